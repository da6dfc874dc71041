//! Shading against exact references: the vertex-colour average, Gouraud
//! blends (within 1 unit per channel of the exact rational value, and
//! exactly rounded unless within 2^-12 of a half), the pixel set, depth.
//!
//! Case counts follow `PROPTEST_CASES` (proptest's default, 256, when
//! unset); CI's deep run raises it.
#![cfg(feature = "sim")]

use core::convert::Infallible;

use embedded_graphics::draw_target::DrawTargetExt;
use embedded_graphics_core::{
    geometry::{Point, Size},
    pixelcolor::{
        Bgr555, Bgr565, Bgr666, Bgr888, BinaryColor, Gray2, Gray4, Gray8, Rgb555, Rgb565, Rgb666,
        Rgb888,
    },
    prelude::*,
    primitives::Rectangle,
};
use embedded_raster::{
    shade::{average_color, DepthBuffer, ShadeColor},
    sim::SimDisplay,
    Span, Triangle, Vertex,
};
use proptest::prelude::*;

mod common;

use common::{
    blend::{check_rounded, exact_at},
    shapes::{any_scale, focus, sliver, v, MAX, MIN},
};

/// Every span and pixel colour of the Gouraud triangle inside `clip`.
fn shaded<C: ShadeColor>(t: &Triangle, colors: [C; 3], clip: &Rectangle) -> Vec<(Span, Vec<C>)> {
    let mut out = Vec::new();
    t.gouraud(colors)
        .for_each_span(clip, |span, it| {
            out.push((span, it.collect()));
            Ok::<(), Infallible>(())
        })
        .unwrap();
    out
}

fn flat_spans(t: &Triangle, clip: &Rectangle) -> Vec<Span> {
    let mut out = Vec::new();
    t.for_each_span(clip, |s| {
        out.push(s);
        Ok::<(), Infallible>(())
    })
    .unwrap();
    out
}

/// Checks every pixel of the Gouraud triangle inside `clip` against the
/// exact blend, and that its pixels are the flat triangle's.
fn assert_blend<C: ShadeColor + core::fmt::Debug>(
    t: &Triangle,
    colors: [C; 3],
    clip: &Rectangle,
) -> Result<(), TestCaseError> {
    assert_blend_read(t, colors, clip, C::CHANNELS, ShadeColor::channels)
}

/// [`assert_blend`] with the first `channels` channels of each colour read
/// by `read`: the colour's own accessors, for the colours whose
/// `ShadeColor` is checked here rather than trusted.
fn assert_blend_read<C: ShadeColor + core::fmt::Debug>(
    t: &Triangle,
    colors: [C; 3],
    clip: &Rectangle,
    channels: usize,
    read: impl Fn(C) -> [u8; 3],
) -> Result<(), TestCaseError> {
    let spans = shaded(t, colors, clip);
    let flat = flat_spans(t, clip);
    prop_assert_eq!(spans.iter().map(|s| s.0).collect::<Vec<_>>(), flat);
    let ch = colors.map(&read);
    for (span, pixels) in &spans {
        prop_assert_eq!(pixels.len(), span.len() as usize);
        for (x, c) in (span.x_start..).zip(pixels) {
            let got = read(*c);
            for k in 0..channels {
                let a = ch.map(|c| i128::from(c[k]));
                let e = exact_at(t, a, i64::from(x), i64::from(span.y));
                if let Err(msg) = check_rounded(i128::from(got[k]), e) {
                    return Err(TestCaseError::fail(format!(
                        "{t:?} {colors:?} pixel ({x}, {}), channel {k}: {msg}",
                        span.y
                    )));
                }
            }
        }
    }
    Ok(())
}

fn window(cx: i64, cy: i64, w: u32, h: u32) -> Rectangle {
    let x = ((cx >> 12) - i64::from(w / 2)) as i32;
    let y = ((cy >> 12) - i64::from(h / 2)) as i32;
    Rectangle::new(Point::new(x, y), Size::new(w, h))
}

fn rgb888() -> impl Strategy<Value = [Rgb888; 3]> {
    prop::array::uniform3(any::<[u8; 3]>().prop_map(|[r, g, b]| Rgb888::new(r, g, b)))
}

fn rgb565() -> impl Strategy<Value = [Rgb565; 3]> {
    prop::array::uniform3((0u8..32, 0u8..64, 0u8..32).prop_map(|(r, g, b)| Rgb565::new(r, g, b)))
}

fn gray8() -> impl Strategy<Value = [Gray8; 3]> {
    prop::array::uniform3(any::<u8>().prop_map(Gray8::new))
}

proptest! {
    /// The average against an independent formula: the channel sum over
    /// three, rounded to nearest in floating point.
    #[test]
    fn average_is_the_rounded_mean(c in rgb888(), g in rgb565(), l in gray8()) {
        let mean = |s: u32| (f64::from(s) / 3.0).round() as u8;
        let sum = |k: usize, ch: [[u8; 3]; 3]| ch.iter().map(|c| u32::from(c[k])).sum::<u32>();
        let a = average_color(c).channels();
        let ch = c.map(ShadeColor::channels);
        prop_assert_eq!(a, [mean(sum(0, ch)), mean(sum(1, ch)), mean(sum(2, ch))]);
        let a = average_color(g).channels();
        let ch = g.map(ShadeColor::channels);
        prop_assert_eq!(a, [mean(sum(0, ch)), mean(sum(1, ch)), mean(sum(2, ch))]);
        let a = average_color(l).channels();
        let ch = l.map(ShadeColor::channels);
        prop_assert_eq!(a[0], mean(sum(0, ch)));
    }

    #[test]
    fn rgb888_blend_at_every_scale(t in any_scale(), c in rgb888(), which in 0usize..4, f in any::<(u16, u16)>(), w in 1u32..48, h in 1u32..48) {
        let (cx, cy) = focus(&t, which, f.0, f.1);
        assert_blend(&t, c, &window(cx, cy, w, h))?;
    }

    #[test]
    fn rgb565_blend_at_every_scale(t in any_scale(), c in rgb565(), which in 0usize..4, f in any::<(u16, u16)>()) {
        let (cx, cy) = focus(&t, which, f.0, f.1);
        assert_blend(&t, c, &window(cx, cy, 40, 40))?;
    }

    #[test]
    fn gray8_blend_at_every_scale(t in any_scale(), c in gray8(), which in 0usize..4, f in any::<(u16, u16)>()) {
        let (cx, cy) = focus(&t, which, f.0, f.1);
        assert_blend(&t, c, &window(cx, cy, 40, 40))?;
    }

    /// The other colours of embedded-graphics (those of the framebuffer's
    /// formats and the rest of its RGB and BGR ones), each channel read
    /// by the colour's own accessors (`r`, `g`, `b`, `luma`), so that a
    /// channel put in the wrong place or cut short fails.
    #[test]
    fn every_other_colour_blends_at_every_scale(t in any_scale(), raw in any::<[[u8; 3]; 3]>(), which in 0usize..4, f in any::<(u16, u16)>()) {
        let (cx, cy) = focus(&t, which, f.0, f.1);
        let clip = window(cx, cy, 24, 24);
        macro_rules! rgb {
            ($($color:ident),*) => {$(
                // `new` keeps each channel's low bits: any byte is a colour.
                let colors = raw.map(|[r, g, b]| $color::new(r, g, b));
                assert_blend_read(&t, colors, &clip, 3, |c: $color| [c.r(), c.g(), c.b()])?;
            )*};
        }
        rgb!(Rgb555, Bgr555, Bgr565, Rgb666, Bgr666, Bgr888);
        macro_rules! gray {
            ($($color:ident),*) => {$(
                let colors = raw.map(|[l, _, _]| $color::new(l));
                assert_blend_read(&t, colors, &clip, 1, |c: $color| [c.luma(), 0, 0])?;
            )*};
        }
        gray!(Gray2, Gray4);
    }

    #[test]
    fn blend_for_slivers(t in sliver(1 << 30, 1 << 28), c in rgb888(), which in 0usize..4, f in any::<(u16, u16)>()) {
        let (cx, cy) = focus(&t, which, f.0, f.1);
        assert_blend(&t, c, &window(cx, cy, 40, 40))?;
    }

    #[test]
    fn blend_far_off_screen(t in any_scale(), c in rgb888(), w in 1u32..64, h in 1u32..64) {
        assert_blend(&t, c, &Rectangle::new(Point::zero(), Size::new(w, h)))?;
    }

    /// Vertices on pixel centres: a lit vertex pixel has exactly that
    /// vertex's colour.
    #[test]
    fn vertex_colours_at_vertices(p in prop::array::uniform6(-30i32..30), c in rgb888()) {
        let t = Triangle::from_points(Point::new(p[0], p[1]), Point::new(p[2], p[3]), Point::new(p[4], p[5])).unwrap();
        let clip = Rectangle::new(Point::new(-40, -40), Size::new(80, 80));
        for (span, pixels) in shaded(&t, c, &clip) {
            for (x, color) in (span.x_start..).zip(pixels) {
                for k in 0..3 {
                    if Point::new(x, span.y) == Point::new(p[2 * k], p[2 * k + 1]) {
                        prop_assert_eq!(color, c[k]);
                    }
                }
            }
        }
    }

    /// Along a horizontal top edge on pixel centres, the colours run
    /// monotonically from one end's to the other's, per channel.
    #[test]
    fn monotonic_along_an_edge(x0 in -50i32..50, len in 1i32..400, below in (-500i32..500, 1i32..300), c in rgb888()) {
        let t = Triangle::from_points(Point::new(x0, 0), Point::new(x0 + len, 0), Point::new(below.0, below.1)).unwrap();
        let clip = Rectangle::new(Point::new(-1000, 0), Size::new(2000, 1));
        let rows = shaded(&t, c, &clip);
        prop_assert_eq!(rows.len(), 1);
        let (span, pixels) = &rows[0];
        prop_assert_eq!(span.x_start, x0);
        prop_assert_eq!(pixels[0], c[0]);
        for k in 0..3 {
            let (a, b) = (c[0].channels()[k], c[1].channels()[k]);
            let ch: Vec<u8> = pixels.iter().map(|p| p.channels()[k]).collect();
            prop_assert!(ch.windows(2).all(|w| if a <= b { w[0] <= w[1] } else { w[0] >= w[1] }), "{:?}", ch);
            prop_assert!(ch.iter().all(|&x| x >= a.min(b) && x <= a.max(b)));
        }
    }

    /// Drawing on a display: one fill_contiguous per span, the same pixels
    /// and colours as `for_each_span`, nothing else written.
    #[test]
    fn draws_one_fill_contiguous_per_span(t in any_scale(), c in rgb888(), f in any::<(u16, u16)>()) {
        let (cx, cy) = focus(&t, 3, f.0, f.1);
        let clip = window(cx, cy, 32, 24);
        let spans = shaded(&t, c, &clip);
        let mut display = SimDisplay::new(32, 24, Rgb888::BLACK);
        // The display sits at the window: draw through a translated target.
        let mut target = display.translated(-clip.top_left);
        let Ok(()) = t.gouraud(c).draw(&mut target);
        let stats = display.write_stats();
        prop_assert_eq!(stats.fill_contiguous_calls, spans.len() as u64);
        prop_assert_eq!(stats.fill_solid_calls + stats.draw_iter_pixels, 0);
        for (span, pixels) in &spans {
            for (x, color) in (span.x_start..).zip(pixels) {
                let p = Point::new(x, span.y) - clip.top_left;
                prop_assert_eq!(display.pixel(p), Some(*color));
            }
        }
    }

    /// A mesh of triangles in disjoint depth bands, drawn with depth in a
    /// shuffled order, gives the painter's-algorithm image (far to near,
    /// no depth test), whatever the order.
    #[test]
    fn depth_order_independence(
        tris in prop::collection::vec((prop::array::uniform6(0i64..(48 << 12)), rgb888(), prop::array::uniform3(0u16..1000), any::<bool>()), 1..12),
        order in any::<u64>(),
    ) {
        let mesh: Vec<_> = tris.iter().enumerate().map(|(i, (p, c, z, gouraud))| {
            let t = Triangle::new(v(p[0], p[1]), v(p[2], p[3]), v(p[4], p[5]));
            // Band i: depths 1000 i .. 1000 i + 999, nearer for larger i.
            let band = 60_000 - 1000 * i as u16;
            (t, *c, z.map(|z| band - z), *gouraud)
        }).collect();
        let draw = |display: &mut SimDisplay<Rgb888>, t: &Triangle, c: [Rgb888; 3], g: bool, depth: Option<(DepthBuffer<'_>, [u16; 3])>| {
            let Ok(()) = match (g, depth) {
                (true, Some((d, z))) => t.gouraud(c).with_depth(z, d).draw(display),
                (false, Some((d, z))) => t.fill(c[0]).with_depth(z, d).draw(display),
                (true, None) => t.gouraud(c).draw(display),
                (false, None) => t.fill(c[0]).draw(display),
            };
        };
        let mut painter = SimDisplay::new(48, 48, Rgb888::BLACK);
        for (t, c, _, g) in &mesh {
            draw(&mut painter, t, *c, *g, None);
        }
        // A few shuffles of the drawing order.
        let mut seed = order;
        for _ in 0..3 {
            let mut idx: Vec<usize> = (0..mesh.len()).collect();
            for i in (1..idx.len()).rev() {
                seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
                idx.swap(i, (seed >> 33) as usize % (i + 1));
            }
            let mut storage = vec![0u16; 48 * 48];
            let depth = DepthBuffer::new(&mut storage, 48);
            depth.clear();
            let mut display = SimDisplay::new(48, 48, Rgb888::BLACK);
            for &i in &idx {
                let (t, c, z, g) = &mesh[i];
                draw(&mut display, t, *c, *g, Some((depth, *z)));
            }
            prop_assert!(display.pixels() == painter.pixels(), "order {:?}", idx);
        }
    }

    /// With a cleared depth buffer, Gouraud + depth draws exactly what
    /// Gouraud alone does, and stores the interpolated depth (within 1).
    #[test]
    fn depth_alone_changes_nothing(p in prop::array::uniform6(-(8i64 << 12)..(40 << 12)), c in rgb565(), z in prop::array::uniform3(0u16..u16::MAX)) {
        let t = Triangle::new(v(p[0], p[1]), v(p[2], p[3]), v(p[4], p[5]));
        let mut plain = SimDisplay::new(32, 32, Rgb565::BLACK);
        let Ok(()) = t.gouraud(c).draw(&mut plain);
        let mut storage = [0u16; 32 * 32];
        let depth = DepthBuffer::new(&mut storage, 32);
        depth.clear();
        let mut tested = SimDisplay::new(32, 32, Rgb565::BLACK);
        let Ok(()) = t.gouraud(c).with_depth(z, depth).draw(&mut tested);
        prop_assert!(plain.pixels() == tested.pixels());
        prop_assert_eq!(plain.counts(), tested.counts());
        for y in 0..32u32 {
            for x in 0..32u32 {
                let d = depth.get(x, y).unwrap();
                if plain.write_count(Point::new(x as i32, y as i32)) == Some(1) {
                    let e = exact_at(&t, z.map(i128::from), i64::from(x), i64::from(y));
                    prop_assert!(check_rounded(i128::from(d), e).is_ok(), "{} vs {:?}", d, e);
                } else {
                    prop_assert_eq!(d, u16::MAX);
                }
            }
        }
    }
}

/// Long spans: huge triangles on a one-row clip as wide as the range, every
/// pixel checked, so the error of the per-pixel increment accumulates over
/// up to 2^20 steps.
#[test]
fn blend_over_the_longest_spans() {
    let clip = Rectangle::new(Point::new(-(1 << 19), 0), Size::new(1 << 20, 1));
    let colors = [
        [
            Rgb888::new(0, 255, 7),
            Rgb888::new(255, 0, 200),
            Rgb888::new(3, 128, 255),
        ],
        [
            Rgb888::new(0, 0, 0),
            Rgb888::new(255, 255, 255),
            Rgb888::new(1, 254, 128),
        ],
    ];
    let mut seed = 0x1234_5678_9abc_def0u64;
    let mut next = |r: i64| {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((seed >> 16) as i64).rem_euclid(2 * r + 1) - r
    };
    for case in 0..24 {
        // Two vertices far left and right, the third above or below row 0.
        let t = Triangle::new(
            v(MIN + next(1 << 20).abs(), next(1 << 30)),
            v(MAX - next(1 << 20).abs(), next(1 << 30)),
            v(next(MAX), if case % 2 == 0 { MIN + 5 } else { MAX - 5 }),
        );
        let spans = shaded(&t, colors[case % 2], &clip);
        let longest = spans.iter().map(|s| s.0.len()).max().unwrap_or(0);
        assert_blend(&t, colors[case % 2], &clip).unwrap();
        assert!(
            case > 3 || longest > 1 << 18,
            "{t:?}: longest span {longest}"
        );
    }
}

#[test]
fn binary_color_is_the_majority_and_blends_at_the_midline() {
    use BinaryColor::{Off, On};
    assert_eq!(average_color([On, On, Off]), On);
    assert_eq!(average_color([On, Off, Off]), Off);
    let t = Triangle::from_points(Point::new(0, 0), Point::new(10, 0), Point::new(0, 10)).unwrap();
    let clip = Rectangle::new(Point::zero(), Size::new(16, 16));
    for (span, pixels) in shaded(&t, [Off, On, Off], &clip) {
        for (x, c) in (span.x_start..).zip(pixels) {
            assert_eq!(c.is_on(), x >= 5, "pixel ({x}, {})", span.y);
        }
    }
}

/// Each colour's channel maxima are those of its `WHITE`, read by the
/// colour's own accessors, and its channel count is 3 for the RGB and BGR
/// colours, 1 for the greys and `BinaryColor`.
#[test]
fn channel_maxima_are_white() {
    // The channels in the order of the raw bits: blue first for BGR.
    macro_rules! rgb {
        ([$first:ident, $second:ident, $third:ident] $($color:ident),*) => {$(
            let white = $color::WHITE;
            assert_eq!($color::MAX, [white.$first(), white.$second(), white.$third()], stringify!($color));
            assert_eq!($color::CHANNELS, 3, stringify!($color));
        )*};
    }
    rgb!([r, g, b] Rgb555, Rgb565, Rgb666, Rgb888);
    rgb!([b, g, r] Bgr555, Bgr565, Bgr666, Bgr888);
    macro_rules! gray {
        ($($color:ident),*) => {$(
            assert_eq!($color::MAX, [$color::WHITE.luma(), 0, 0], stringify!($color));
            assert_eq!($color::CHANNELS, 1, stringify!($color));
        )*};
    }
    gray!(Gray2, Gray4, Gray8);
    assert_eq!(BinaryColor::MAX, [1, 0, 0]);
}

/// The channels are the colour's raw bits, highest field first, each
/// field as wide as its maximum: put back together, they give
/// embedded-graphics' own storage value (`IntoStorage`). A BGR colour's
/// channels in red-first order fail it.
#[test]
fn channels_follow_the_raw_bits() {
    macro_rules! check {
        ($($color:ident),*) => {$(
            let width = $color::MAX.map(|m| u8::BITS - m.leading_zeros());
            for [r, g, b] in [[1u8, 2, 3], [31, 0, 17], [5, 63, 1], [200, 100, 50], [255; 3]] {
                // `new` keeps each channel's low bits.
                let c = $color::new(r, g, b);
                let ch = c.channels().map(u32::from);
                let packed = (ch[0] << (width[1] + width[2])) | (ch[1] << width[2]) | ch[2];
                let raw = u32::from(c.into_storage());
                assert_eq!(packed, raw, "{} {c:?}", stringify!($color));
                assert_eq!($color::from_channels(c.channels()), c, "{}", stringify!($color));
            }
        )*};
    }
    check!(Rgb555, Bgr555, Rgb565, Bgr565, Rgb666, Bgr666, Rgb888, Bgr888);
    macro_rules! gray {
        ($($color:ident),*) => {$(
            for l in [0u8, 1, 2, 3, 9, 15, 128, 255] {
                let c = $color::new(l);
                assert_eq!(u32::from(c.channels()[0]), u32::from(c.into_storage()), "{c:?}");
            }
        )*};
    }
    gray!(Gray2, Gray4, Gray8);
}

/// Gouraud triangles on the framebuffer formats whose colours are not
/// `Rgb565`, `Rgb888`, `Gray8` or `BinaryColor`: every pixel of the
/// framebuffer holds the colour `for_each_span` gives it, the rest the
/// background.
#[test]
fn gouraud_on_every_framebuffer_format() {
    use embedded_raster::framebuffer::{
        buffer_size, Bgr565Be, Bgr565Le, Gray2Lsb, Gray2Msb, Gray4Lsb, Gray4Msb, PixelFormat,
        Rgb666Bytes,
    };
    use embedded_raster::Framebuffer;
    fn check<F: PixelFormat, const N: usize>(colors: [F::Color; 3])
    where
        F::Color: ShadeColor + core::fmt::Debug,
    {
        let t = Triangle::new(
            Vertex::from_raw(1 << 11, 3 << 11),
            Vertex::from_raw(77 << 12, 9 << 12),
            Vertex::from_raw(20 << 12, (47 << 12) + 1234),
        )
        .gouraud(colors);
        let mut fb = Framebuffer::<F, 80, 48, N>::new();
        let screen = fb.bounding_box();
        let mut want = std::collections::HashMap::new();
        t.for_each_span(&screen, |span, it| {
            for (x, c) in (span.x_start..).zip(it) {
                want.insert(Point::new(x, span.y), c);
            }
            Ok::<(), Infallible>(())
        })
        .unwrap();
        assert!(want.len() > 1000, "{}", want.len());
        let background = F::Color::from_channels([0; 3]);
        t.draw(&mut fb).unwrap();
        for p in screen.points() {
            let got = fb.pixel(p).unwrap();
            assert_eq!(got, want.get(&p).copied().unwrap_or(background), "{p:?}");
        }
    }
    let rgb = [[31, 0, 5], [2, 63, 17], [9, 30, 31]];
    check::<Bgr565Le, { buffer_size::<Bgr565Le>(80, 48) }>(
        rgb.map(|[r, g, b]| Bgr565::new(r, g, b)),
    );
    check::<Bgr565Be, { buffer_size::<Bgr565Be>(80, 48) }>(
        rgb.map(|[r, g, b]| Bgr565::new(r, g, b)),
    );
    let rgb = [[63, 0, 5], [2, 63, 40], [9, 30, 63]];
    check::<Rgb666Bytes, { buffer_size::<Rgb666Bytes>(80, 48) }>(
        rgb.map(|[r, g, b]| Rgb666::new(r, g, b)),
    );
    let gray = [15, 0, 9];
    check::<Gray4Msb, { buffer_size::<Gray4Msb>(80, 48) }>(gray.map(Gray4::new));
    check::<Gray4Lsb, { buffer_size::<Gray4Lsb>(80, 48) }>(gray.map(Gray4::new));
    let gray = [3, 0, 2];
    check::<Gray2Msb, { buffer_size::<Gray2Msb>(80, 48) }>(gray.map(Gray2::new));
    check::<Gray2Lsb, { buffer_size::<Gray2Lsb>(80, 48) }>(gray.map(Gray2::new));
}

#[test]
fn gray8_ramp_by_hand() {
    // 0 at x = 0.5 and 100 at x = 10.5 on every row: 10 per pixel.
    let f = |x: f32, y: f32| Vertex::try_from_num(x, y).unwrap();
    let t = Triangle::new(f(0.5, -100.0), f(10.5, 0.0), f(0.5, 100.0));
    let clip = Rectangle::new(Point::new(0, -3), Size::new(20, 7));
    for (span, pixels) in shaded(&t, [Gray8::new(0), Gray8::new(100), Gray8::new(0)], &clip) {
        // The weight of the right vertex is the distance from the left
        // edge over 10 px: exactly 10 x at pixel x, whatever the row.
        assert_eq!(span.x_start, 0);
        for (x, c) in (0..).zip(&pixels) {
            assert_eq!(i32::from(c.luma()), 10 * x, "({x}, {})", span.y);
        }
    }
}

#[test]
fn equal_depth_keeps_the_first_and_far_is_never_drawn() {
    let t = Triangle::from_points(Point::new(0, 0), Point::new(15, 0), Point::new(0, 15)).unwrap();
    let mut storage = [0u16; 16 * 16];
    let depth = DepthBuffer::new(&mut storage, 16);
    depth.clear();
    let mut display = SimDisplay::new(16, 16, Rgb888::BLACK);
    let z = [10, 500, 20];
    let Ok(()) = t.fill(Rgb888::RED).with_depth(z, depth).draw(&mut display);
    let written = display.pixels_written();
    assert!(written > 0);
    // The same depths again: nothing passes, nothing is written.
    let Ok(()) = t
        .gouraud([Rgb888::GREEN; 3])
        .with_depth(z, depth)
        .draw(&mut display);
    let Ok(()) = t.fill(Rgb888::BLUE).with_depth(z, depth).draw(&mut display);
    assert_eq!(display.pixels_written(), written);
    // One nearer: everything passes.
    let Ok(()) = t
        .fill(Rgb888::BLUE)
        .with_depth(z.map(|z| z - 1), depth)
        .draw(&mut display);
    assert_eq!(display.pixels_written(), 2 * written);
    assert_eq!(display.pixel(Point::new(1, 1)), Some(Rgb888::BLUE));
    // At FAR on a cleared buffer: nothing.
    depth.clear();
    let Ok(()) = t
        .fill(Rgb888::RED)
        .with_depth([u16::MAX; 3], depth)
        .draw(&mut display);
    assert_eq!(display.pixels_written(), 2 * written);
}

#[test]
fn a_run_stops_at_an_equal_depth() {
    // A (right part) at depth 100, then B over the whole row at depth 100:
    // B's pixels pass until they reach A's, which stay A's.
    let f = |x: f32, y: f32| Vertex::try_from_num(x, y).unwrap();
    let a = Triangle::new(f(8.0, -50.0), f(16.0, -50.0), f(8.0, 50.0));
    let b = Triangle::new(f(0.0, -50.0), f(32.0, -50.0), f(0.0, 50.0));
    let mut storage = [0u16; 32];
    let depth = DepthBuffer::new(&mut storage, 32);
    depth.clear();
    let mut display = SimDisplay::new(32, 1, Rgb888::BLACK);
    let Ok(()) = a
        .fill(Rgb888::RED)
        .with_depth([100; 3], depth)
        .draw(&mut display);
    let Ok(()) = b
        .gouraud([Rgb888::BLUE; 3])
        .with_depth([100; 3], depth)
        .draw(&mut display);
    let row: Vec<Rgb888> = (0..32)
        .map(|x| display.pixel(Point::new(x, 0)).unwrap())
        .collect();
    for (x, c) in row.iter().enumerate() {
        let lit_by_b = (x as f32 + 0.5) < 32.0 - 32.0 * 50.5 / 100.0;
        let lit_by_a = x >= 8 && (x as f32 + 0.5) < 8.0 + 8.0 * 49.5 / 100.0;
        let want = if lit_by_a {
            Rgb888::RED
        } else if lit_by_b {
            Rgb888::BLUE
        } else {
            Rgb888::BLACK
        };
        assert_eq!(*c, want, "pixel {x}: {row:?}");
    }
    assert!(row.contains(&Rgb888::RED) && row.contains(&Rgb888::BLUE));
}

/// The documented ranges of the depth buffer and of shading (issue 12):
/// any width, any depths, and slivers whose steps per pixel are huge (each
/// row one pixel wide), under overflow checks.
#[test]
fn depth_and_shading_ranges() {
    use embedded_raster::shade::{DepthBuffer, FAR};
    let mut storage = [0u16; 16];
    for (width, size) in [
        (0, Size::new(0, 0)),
        (1, Size::new(1, 16)),
        (5, Size::new(5, 3)),
        (17, Size::new(17, 0)),
        (u32::MAX, Size::new(u32::MAX, 0)),
    ] {
        let depth = DepthBuffer::new(&mut storage, width);
        assert_eq!(depth.size(), size);
        depth.clear();
        assert_eq!(depth.get(u32::MAX, u32::MAX), None);
        assert_eq!(depth.get(0, 0), (size.height > 0).then_some(FAR));
    }
    // Slivers one raw unit wide and up to the whole range tall: per-pixel
    // steps from 2^44 to past i64, colour and depth at their extremes. The
    // colours and depths are the exact values', within 1.
    let clip = Rectangle::new(Point::zero(), Size::new(8, 8));
    let mut lit = 0;
    for height in [100i64, 1 << 15, 1 << 19, (1 << 31) - 1] {
        for (x0, x1) in [(0, 1), (2048, 2049), (4095, 4096)] {
            let t = Triangle::new(v(x0, 0), v(x1, height), v(x0, height));
            let colors = [Rgb888::WHITE, Rgb888::BLACK, Rgb888::new(255, 0, 255)];
            assert_blend(&t, colors, &clip).unwrap();
            let mut d = SimDisplay::new(8, 8, Rgb888::BLACK);
            let mut storage = [0u16; 64];
            let depth = DepthBuffer::new(&mut storage, 8);
            depth.clear();
            let z = [0, u16::MAX - 1, 1];
            t.gouraud([Rgb888::WHITE, Rgb888::BLACK, Rgb888::RED])
                .with_depth(z, depth)
                .draw(&mut d)
                .unwrap();
            assert_eq!(d.out_of_bounds_writes(), 0);
            for y in 0..8u32 {
                for x in 0..8u32 {
                    let stored = depth.get(x, y).unwrap();
                    if d.write_count(Point::new(x as i32, y as i32)) == Some(1) {
                        let e = exact_at(&t, z.map(i128::from), i64::from(x), i64::from(y));
                        check_rounded(i128::from(stored), e).unwrap();
                        lit += 1;
                    } else {
                        assert_eq!(stored, FAR, "({x}, {y}) of {t:?}");
                    }
                }
            }
        }
    }
    // The slivers whose left edge runs through the pixel centres
    // (x0 = 2048) light that column's 8 rows in the clip, but the one 100
    // raw units tall, which reaches no centre; the others light nothing.
    assert_eq!(lit, 3 * 8);
}

/// A triangle found by a probe of 5,000,000 random Gouraud triangles
/// under random clips: cut on the left by a clip from column 21, its
/// pixel (22, 48) lay so near a half in red that the span start found at
/// the clip's first column and the one stepped to at the row's own first
/// pixel (the triangle drawn whole) rounded apart, one unit of red. Span
/// starts are now found at each row's whole span whatever the clip, so
/// every clip gives the whole triangle's pixels inside it, with and
/// without depth (whose colours are those without it).
#[test]
fn clipped_gouraud_as_whole_near_a_half() {
    let t = Triangle::new(
        Vertex::from_raw(78_088, 222_570),
        Vertex::from_raw(67_872, 145_586),
        Vertex::from_raw(192_707, 105_954),
    );
    let c = [
        Rgb888::new(217, 176, 155),
        Rgb888::new(248, 167, 90),
        Rgb888::new(180, 5, 111),
    ];
    let render = |clip: &Rectangle, depth: bool| {
        let mut display = SimDisplay::new(64, 64, Rgb888::BLACK);
        let mut storage = vec![0u16; 64 * 64];
        let buffer = DepthBuffer::new(&mut storage, 64);
        buffer.clear();
        let Ok(()) = match depth {
            true => t
                .gouraud(c)
                .with_depth([100, 30_000, 65_000], buffer)
                .draw(&mut display.clipped(clip)),
            false => t.gouraud(c).draw(&mut display.clipped(clip)),
        };
        display
    };
    for depth in [false, true] {
        let whole = render(&Rectangle::new(Point::zero(), Size::new(64, 64)), depth);
        for left in 0..50u32 {
            for width in 1..=(64 - left) {
                let clip = Rectangle::new(Point::new(left as i32, 0), Size::new(width, 64));
                let part = render(&clip, depth);
                for p in clip.points() {
                    assert_eq!(
                        part.pixel(p),
                        whole.pixel(p),
                        "{clip:?} at {p:?}, depth {depth}"
                    );
                }
            }
        }
    }
}

proptest! {
    /// A Gouraud triangle, with or without depth, drawn through a window
    /// that cuts it anywhere (embedded-graphics' `Clipped`) writes inside
    /// the window exactly the pixels, values and counts it writes drawn
    /// whole, and nothing outside it.
    #[test]
    fn any_window_gives_the_whole_triangle_inside_it(
        p in prop::array::uniform6(-(8i64 << 12)..(56 << 12)),
        c in rgb888(),
        z in prop::array::uniform3(0u16..u16::MAX),
        win in (-4i32..52, -4i32..52, 0u32..56, 0u32..56),
        depth in any::<bool>(),
    ) {
        let t = Triangle::new(v(p[0], p[1]), v(p[2], p[3]), v(p[4], p[5]));
        let window = Rectangle::new(Point::new(win.0, win.1), Size::new(win.2, win.3));
        let render = |clip: &Rectangle| {
            let mut display = SimDisplay::new(48, 48, Rgb888::BLACK);
            let mut storage = [0u16; 48 * 48];
            let buffer = DepthBuffer::new(&mut storage, 48);
            buffer.clear();
            let Ok(()) = match depth {
                true => t.gouraud(c).with_depth(z, buffer).draw(&mut display.clipped(clip)),
                false => t.gouraud(c).draw(&mut display.clipped(clip)),
            };
            display
        };
        let whole = render(&Rectangle::new(Point::zero(), Size::new(48, 48)));
        let part = render(&window);
        for q in Rectangle::new(Point::zero(), Size::new(48, 48)).points() {
            if window.contains(q) {
                prop_assert_eq!(part.pixel(q), whole.pixel(q), "at {:?}", q);
                prop_assert_eq!(part.write_count(q), whole.write_count(q), "at {:?}", q);
            } else {
                prop_assert_eq!(part.write_count(q), Some(0), "at {:?}", q);
            }
        }
    }
}
