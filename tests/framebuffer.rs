//! `Framebuffer` of every format against an independent pixel-by-pixel
//! model, byte layouts written out by hand, and clipping of extreme
//! rectangles.

use core::fmt::Debug;

use embedded_graphics_core::{
    pixelcolor::{
        Bgr565, BinaryColor, Gray2, Gray4, Gray8, GrayColor, Rgb565, Rgb666, Rgb888, RgbColor,
    },
    prelude::*,
    primitives::Rectangle,
    Pixel,
};
use embedded_raster::{
    framebuffer::{
        buffer_size, row_size, Bgr565Be, Bgr565Le, BinaryMsb, Gray2Lsb, Gray2Msb, Gray4Lsb,
        Gray4Msb, Gray8Bytes, PixelFormat, Rgb565Be, Rgb565Le, Rgb666Bytes, Rgb888Bytes,
    },
    Framebuffer, Span, SpanSink,
};
use proptest::prelude::*;

// ---------------------------------------------------------------------------
// What the tests know about each format, independently of the crate.

/// A format's colours and, from its definition, its expected bytes.
trait Spec: PixelFormat<Color: Copy + PartialEq + Debug + Default> {
    /// Any colour, often one whose bytes are all equal.
    fn arb_color() -> BoxedStrategy<Self::Color>;
    /// A colour picked by `bits`.
    fn color_from(bits: u64) -> Self::Color;
    /// The bytes of one row holding `px`.
    fn encode_row(px: &[Self::Color]) -> Vec<u8>;
}

/// A [`Spec`] for a format of whole-byte pixels, given the bytes of one.
macro_rules! byte_spec {
    ($f:ty, $color:ty, $arb:expr, $from:expr, $bytes:expr) => {
        impl Spec for $f {
            fn arb_color() -> BoxedStrategy<$color> {
                $arb.boxed()
            }
            fn color_from(bits: u64) -> $color {
                $from(bits)
            }
            fn encode_row(px: &[$color]) -> Vec<u8> {
                px.iter().flat_map(|&c| $bytes(c)).collect()
            }
        }
    };
}

/// Rgb565 packed by hand: red in bits 15..11, green 10..5, blue 4..0.
fn rgb565_raw(c: Rgb565) -> u16 {
    (u16::from(c.r()) << 11) | (u16::from(c.g()) << 5) | u16::from(c.b())
}

fn arb_rgb565() -> impl Strategy<Value = Rgb565> {
    prop_oneof![
        4 => (0u8..32, 0u8..64, 0u8..32).prop_map(|(r, g, b)| Rgb565::new(r, g, b)),
        1 => Just(Rgb565::BLACK),
        1 => Just(Rgb565::WHITE),
        1 => Just(Rgb565::new(1, 0, 8)), // 0x0808: both bytes equal
    ]
}

fn rgb565_from(bits: u64) -> Rgb565 {
    Rgb565::new(bits as u8, (bits >> 5) as u8, (bits >> 11) as u8) // masked by `new`
}

byte_spec!(Rgb565Le, Rgb565, arb_rgb565(), rgb565_from, |c| {
    let raw = rgb565_raw(c);
    [(raw & 0xFF) as u8, (raw >> 8) as u8]
});
byte_spec!(Rgb565Be, Rgb565, arb_rgb565(), rgb565_from, |c| {
    let raw = rgb565_raw(c);
    [(raw >> 8) as u8, (raw & 0xFF) as u8]
});
byte_spec!(
    Rgb888Bytes,
    Rgb888,
    prop_oneof![
        3 => any::<[u8; 3]>().prop_map(|[r, g, b]| Rgb888::new(r, g, b)),
        1 => any::<u8>().prop_map(|v| Rgb888::new(v, v, v)),
    ],
    |bits: u64| Rgb888::new(bits as u8, (bits >> 8) as u8, (bits >> 16) as u8),
    |c: Rgb888| [c.r(), c.g(), c.b()]
);
byte_spec!(
    Gray8Bytes,
    Gray8,
    any::<u8>().prop_map(Gray8::new),
    |bits: u64| Gray8::new(bits as u8),
    |c: Gray8| [c.luma()]
);

impl Spec for BinaryMsb {
    fn arb_color() -> BoxedStrategy<BinaryColor> {
        any::<bool>().prop_map(BinaryColor::from).boxed()
    }
    fn color_from(bits: u64) -> BinaryColor {
        BinaryColor::from(bits & 1 == 1)
    }
    /// `ceil(w / 8)` bytes; pixel `x` in bit `7 - x % 8` of byte `x / 8`;
    /// padding bits 0.
    fn encode_row(px: &[BinaryColor]) -> Vec<u8> {
        let mut bytes = vec![0u8; px.len().div_ceil(8)];
        for (x, c) in px.iter().enumerate() {
            if c.is_on() {
                bytes[x / 8] |= 1 << (7 - x % 8);
            }
        }
        bytes
    }
}

/// Bgr565 packed by hand: blue in bits 15..11, green 10..5, red 4..0.
fn bgr565_raw(c: Bgr565) -> u16 {
    (u16::from(c.b()) << 11) | (u16::from(c.g()) << 5) | u16::from(c.r())
}

fn arb_bgr565() -> impl Strategy<Value = Bgr565> {
    arb_rgb565().prop_map(|c| Bgr565::new(c.r(), c.g(), c.b()))
}

byte_spec!(
    Bgr565Le,
    Bgr565,
    arb_bgr565(),
    |bits: u64| Bgr565::new(bits as u8, (bits >> 5) as u8, (bits >> 11) as u8),
    |c| {
        let raw = bgr565_raw(c);
        [(raw & 0xFF) as u8, (raw >> 8) as u8]
    }
);
byte_spec!(
    Bgr565Be,
    Bgr565,
    arb_bgr565(),
    |bits: u64| Bgr565::new(bits as u8, (bits >> 5) as u8, (bits >> 11) as u8),
    |c| {
        let raw = bgr565_raw(c);
        [(raw >> 8) as u8, (raw & 0xFF) as u8]
    }
);
byte_spec!(
    Rgb666Bytes,
    Rgb666,
    prop_oneof![
        3 => (0u8..64, 0u8..64, 0u8..64).prop_map(|(r, g, b)| Rgb666::new(r, g, b)),
        1 => (0u8..64).prop_map(|v| Rgb666::new(v, v, v)),
    ],
    |bits: u64| Rgb666::new(bits as u8, (bits >> 6) as u8, (bits >> 12) as u8),
    // Each channel times 4: its 6 bits at the top of the byte.
    |c: Rgb666| [c.r() * 4, c.g() * 4, c.b() * 4]
);

/// `values` (each under `2^bits`) packed `8 / bits` to a byte, the first
/// of each byte at the top (`msb_first`) or at the bottom; padding 0.
fn pack(values: &[u8], bits: usize, msb_first: bool) -> Vec<u8> {
    let per_byte = 8 / bits;
    let mut bytes = vec![0u8; values.len().div_ceil(per_byte)];
    for (x, &v) in values.iter().enumerate() {
        let slot = x % per_byte;
        let shift = if msb_first {
            8 - bits * (slot + 1)
        } else {
            bits * slot
        };
        bytes[x / per_byte] |= v << shift;
    }
    bytes
}

/// A [`Spec`] for a packed grey format of `$bits` bits.
macro_rules! gray_spec {
    ($f:ty, $color:ident, $bits:literal, $msb_first:literal) => {
        impl Spec for $f {
            fn arb_color() -> BoxedStrategy<$color> {
                (0u8..1 << $bits).prop_map($color::new).boxed()
            }
            fn color_from(bits: u64) -> $color {
                $color::new(bits as u8 % (1 << $bits))
            }
            fn encode_row(px: &[$color]) -> Vec<u8> {
                let values: Vec<u8> = px.iter().map(|c| c.luma()).collect();
                pack(&values, $bits, $msb_first)
            }
        }
    };
}

gray_spec!(Gray4Msb, Gray4, 4, true);
gray_spec!(Gray4Lsb, Gray4, 4, false);
gray_spec!(Gray2Msb, Gray2, 2, true);
gray_spec!(Gray2Lsb, Gray2, 2, false);

/// The expected bytes of a framebuffer `w` pixels wide holding `px`.
fn encode<F: Spec>(w: usize, px: &[F::Color]) -> Vec<u8> {
    px.chunks(w.max(1)).flat_map(F::encode_row).collect()
}

// ---------------------------------------------------------------------------
// The model: one colour per pixel, written with plain bounds checks.

#[derive(Debug, Clone)]
struct Model<C> {
    w: i64,
    h: i64,
    px: Vec<C>,
}

impl<C: Copy + Default> Model<C> {
    fn new(w: usize, h: usize) -> Self {
        Self {
            w: w as i64,
            h: h as i64,
            px: vec![C::default(); w * h],
        }
    }

    fn set(&mut self, x: i64, y: i64, c: C) {
        if 0 <= x && x < self.w && 0 <= y && y < self.h {
            self.px[(y * self.w + x) as usize] = c;
        }
    }

    /// Every pixel of the model inside `r`, with its index in `r`'s
    /// row-major order.
    fn inside(&self, r: &Rectangle) -> Vec<(i64, i64, u128)> {
        let (x0, y0) = (i64::from(r.top_left.x), i64::from(r.top_left.y));
        let (w, h) = (i64::from(r.size.width), i64::from(r.size.height));
        let mut v = Vec::new();
        for y in 0..self.h {
            for x in 0..self.w {
                if x0 <= x && x < x0 + w && y0 <= y && y < y0 + h {
                    let index = (y - y0) as u128 * w as u128 + (x - x0) as u128;
                    v.push((x, y, index));
                }
            }
        }
        v
    }

    /// How many colours `fill_contiguous(r, ..)` needs: up to the last
    /// pixel inside, in `r`'s row-major order.
    fn needed(&self, r: &Rectangle) -> u128 {
        self.inside(r)
            .iter()
            .map(|&(_, _, i)| i + 1)
            .max()
            .unwrap_or(0)
    }
}

/// A colour source with O(1) `nth` that counts how far it was read.
struct Gen<F> {
    next: u64,
    seed: u64,
    format: core::marker::PhantomData<F>,
}

fn mix(seed: u64, i: u64) -> u64 {
    let mut z = seed ^ i.wrapping_mul(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 31)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z ^ (z >> 29)
}

impl<F: Spec> Iterator for Gen<F> {
    type Item = F::Color;
    fn next(&mut self) -> Option<F::Color> {
        self.nth(0)
    }
    fn nth(&mut self, n: usize) -> Option<F::Color> {
        let i = self.next.checked_add(n as u64)?;
        self.next = i.checked_add(1)?;
        Some(F::color_from(mix(self.seed, i)))
    }
}

#[derive(Debug, Clone)]
enum Op<C> {
    Solid(Rectangle, C),
    /// `fill_contiguous` with a finite list of colours.
    Contiguous(Rectangle, Vec<C>),
    /// `fill_contiguous` with an endless `repeat`.
    Repeat(Rectangle, C),
    /// `fill_contiguous` with an endless generator seeded so.
    Generated(Rectangle, u64),
    Pixels(Vec<(Point, C)>),
    Clear(C),
    /// `SpanSink::fill_span`, with any coordinates (a span outside the
    /// sink's contract is dropped whole).
    Span(Span, C),
    /// `SpanSink::fill_column`, with any coordinates: clipped.
    Column(Point, u32, C),
    /// `SpanSink::fill_line` with the pixels of a line listed in a clip
    /// (the framebuffer's bounds, or those grown by up to 8 px on each
    /// side, as a caller who did not clip would pass), after the first
    /// few have been iterated: the pixels left inside are drawn, no
    /// other (padding included).
    Line(Point, Point, Rectangle, usize, C),
}

/// A span coordinate for a framebuffer `limit` pixels long: mostly near
/// it, sometimes negative or at the ends of the `i32` range.
fn span_coordinate(limit: usize) -> impl Strategy<Value = i32> {
    let limit = limit as i32;
    prop_oneof![
        8 => -3..limit + 3,
        1 => Just(i32::MIN),
        1 => Just(i32::MAX),
        1 => Just(-1 - limit),
        1 => any::<i32>(),
    ]
}

/// A start and length along one axis of a framebuffer `limit` pixels
/// long: mostly near it, sometimes at the ends of the `i32`/`u32` ranges.
fn axis(limit: i64) -> impl Strategy<Value = (i32, u32)> {
    let near = -20..limit + 20;
    let far = prop_oneof![
        Just(i64::from(i32::MIN)),
        Just(i64::from(i32::MAX)),
        Just(i64::from(i32::MAX) - 1),
        any::<i32>().prop_map(i64::from),
    ];
    let clamp =
        |start: i64, end: i64| (start as i32, (end - start).clamp(0, u32::MAX.into()) as u32);
    let inside = (0..=limit).prop_flat_map(move |s| (Just(s as i32), 0..=(limit - s) as u32));
    prop_oneof![
        6 => (near.clone(), 0u32..40).prop_map(|(s, l)| (s as i32, l)),
        2 => inside,
        1 => Just((0, limit as u32)),
        1 => (far.clone(), near.clone()).prop_map(move |(s, e)| clamp(s, e)),
        1 => (near, prop_oneof![Just(u32::MAX), any::<u32>()]).prop_map(|(s, l)| (s as i32, l)),
        1 => (far, prop_oneof![Just(u32::MAX), Just(u32::MAX - 1), any::<u32>()])
            .prop_map(|(s, l)| (s as i32, l)),
    ]
}

fn arb_rect(w: usize, h: usize) -> impl Strategy<Value = Rectangle> {
    let any = (axis(w as i64), axis(h as i64))
        .prop_map(|((x, wd), (y, ht))| Rectangle::new(Point::new(x, y), Size::new(wd, ht)));
    // One row, as the shaded triangles' spans come to `fill_contiguous`:
    // inside, or across an edge.
    let row = (axis(w as i64), -2..h as i32 + 2)
        .prop_map(|((x, wd), y)| Rectangle::new(Point::new(x, y), Size::new(wd, 1)));
    prop_oneof![3 => any, 1 => row]
}

fn arb_point(w: usize, h: usize) -> impl Strategy<Value = Point> {
    let c = |limit: usize| {
        prop_oneof![
            4 => -3..limit as i32 + 3,
            1 => prop_oneof![Just(i32::MIN), Just(i32::MAX), any::<i32>()],
        ]
    };
    (c(w), c(h)).prop_map(|(x, y)| Point::new(x, y))
}

fn arb_op<F: Spec>(w: usize, h: usize) -> impl Strategy<Value = Op<F::Color>> {
    let color = F::arb_color;
    prop_oneof![
        4 => (arb_rect(w, h), color()).prop_map(|(r, c)| Op::Solid(r, c)),
        3 => (arb_rect(w, h), prop::collection::vec(color(), 0..120))
            .prop_map(|(r, cs)| Op::Contiguous(r, cs)),
        1 => (arb_rect(w, h), color()).prop_map(|(r, c)| Op::Repeat(r, c)),
        2 => (arb_rect(w, h), any::<u64>()).prop_map(|(r, s)| Op::Generated(r, s)),
        2 => prop::collection::vec((arb_point(w, h), color()), 0..20).prop_map(Op::Pixels),
        1 => color().prop_map(Op::Clear),
        3 => (span_coordinate(h), span_coordinate(w), span_coordinate(w), color())
            .prop_map(|(y, x_start, x_end, c)| Op::Span(Span { y, x_start, x_end }, c)),
        2 => (arb_point(w, h), prop_oneof![0..h as u32 + 4, any::<u32>()], color())
            .prop_map(|(top, len, c)| Op::Column(top, len, c)),
        3 => (arb_point(w, h), arb_point(w, h), 0usize..4, color()).prop_map(move |(a, b, k, c)| {
            Op::Line(a, b, Rectangle::new(Point::zero(), Size::new(w as u32, h as u32)), k, c)
        }),
        3 => (near(w, h), near(w, h), 0i32..=8, 0usize..4, color()).prop_map(move |(a, b, g, k, c)| {
            let grown = Size::new(w as u32 + 2 * g as u32, h as u32 + 2 * g as u32);
            Op::Line(a, b, Rectangle::new(Point::new(-g, -g), grown), k, c)
        }),
    ]
}

/// A point within 12 px of a `w` x `h` framebuffer.
fn near(w: usize, h: usize) -> impl Strategy<Value = Point> {
    (-12..w as i32 + 12, -12..h as i32 + 12).prop_map(|(x, y)| Point::new(x, y))
}

/// Applies `ops` to a framebuffer and to the model, comparing bytes, every
/// pixel and the colours `fill_contiguous` consumed after each.
fn run<F: Spec, const W: usize, const H: usize, const N: usize>(
    ops: &[Op<F::Color>],
) -> Result<(), TestCaseError> {
    let mut fb = Framebuffer::<F, W, H, N>::new();
    let mut model = Model::<F::Color>::new(W, H);
    for op in ops {
        match op {
            Op::Solid(r, c) | Op::Repeat(r, c) => {
                match op {
                    Op::Solid(..) => fb.fill_solid(r, *c),
                    _ => fb.fill_contiguous(r, core::iter::repeat(*c)),
                }
                .unwrap();
                for (x, y, _) in model.inside(r) {
                    model.set(x, y, *c);
                }
            }
            Op::Contiguous(r, cs) => {
                let mut taken = 0u128;
                fb.fill_contiguous(r, cs.iter().copied().inspect(|_| taken += 1))
                    .unwrap();
                let (x0, y0) = (i64::from(r.top_left.x), i64::from(r.top_left.y));
                let width = u128::from(r.size.width);
                let area = width * u128::from(r.size.height);
                for (i, &c) in cs.iter().enumerate() {
                    let i = i as u128;
                    if i >= area {
                        break;
                    }
                    model.set(x0 + (i % width) as i64, y0 + (i / width) as i64, c);
                }
                prop_assert_eq!(taken, model.needed(r).min(cs.len() as u128), "{:?}", op);
            }
            Op::Generated(r, seed) => {
                let mut colors = Gen::<F> {
                    next: 0,
                    seed: *seed,
                    format: core::marker::PhantomData,
                };
                fb.fill_contiguous(r, &mut colors).unwrap();
                prop_assert_eq!(u128::from(colors.next), model.needed(r), "{:?}", op);
                for (x, y, i) in model.inside(r) {
                    model.set(x, y, F::color_from(mix(*seed, i as u64)));
                }
            }
            Op::Pixels(ps) => {
                fb.draw_iter(ps.iter().map(|&(p, c)| Pixel(p, c))).unwrap();
                for &(p, c) in ps {
                    model.set(p.x.into(), p.y.into(), c);
                }
            }
            Op::Clear(c) => {
                fb.clear(*c).unwrap();
                model.px.fill(*c);
            }
            Op::Span(span, c) => {
                fb.fill_span(*span, *c).unwrap();
                let (y, x0, x1) = (
                    i64::from(span.y),
                    i64::from(span.x_start),
                    i64::from(span.x_end),
                );
                // Within the contract: a row of the framebuffer, columns
                // `x0..x1` inside it; anything else changes nothing.
                if (0..model.h).contains(&y) && 0 <= x0 && x0 <= x1 && x1 <= model.w {
                    for x in x0..x1 {
                        model.set(x, y, *c);
                    }
                }
            }
            Op::Column(top, len, c) => {
                fb.fill_column(*top, *len, *c).unwrap();
                let (x, y) = (i64::from(top.x), i64::from(top.y));
                // Only the rows that can hold a pixel.
                for y in y.max(-1)..(y + i64::from(*len)).min(model.h) {
                    model.set(x, y, *c);
                }
            }
            Op::Line(a, b, clip, k, c) => {
                let Some(mut pixels) = embedded_raster::Line::new(*a, *b).pixels(clip) else {
                    continue;
                };
                for _ in 0..*k {
                    pixels.next();
                }
                fb.fill_line(pixels, *c).unwrap();
                for p in pixels {
                    model.set(p.x.into(), p.y.into(), *c);
                }
            }
        }
        let bytes = encode::<F>(W, &model.px);
        prop_assert_eq!(fb.as_bytes(), &bytes[..], "after {:?}", op);
        for y in 0..H {
            for x in 0..W {
                let p = Point::new(x as i32, y as i32);
                prop_assert_eq!(
                    fb.pixel(p),
                    Some(model.px[y * W + x]),
                    "{:?} after {:?}",
                    p,
                    op
                );
            }
        }
    }
    Ok(())
}

/// A proptest of [`run`] for format `$f` at `$w` x `$h`.
macro_rules! model_test {
    ($name:ident, $f:ty, $w:literal, $h:literal) => {
        proptest! {
            #[test]
            fn $name(ops in prop::collection::vec(arb_op::<$f>($w, $h), 1..12)) {
                run::<$f, $w, $h, { buffer_size::<$f>($w, $h) }>(&ops)?;
            }
        }
    };
}

model_test!(model_rgb565le_10x4, Rgb565Le, 10, 4);
model_test!(model_rgb565le_37x2, Rgb565Le, 37, 2);
model_test!(model_rgb565be_10x4, Rgb565Be, 10, 4);
model_test!(model_rgb565be_16x3, Rgb565Be, 16, 3);
model_test!(model_rgb888_10x4, Rgb888Bytes, 10, 4);
model_test!(model_rgb888_37x2, Rgb888Bytes, 37, 2);
model_test!(model_gray8_10x4, Gray8Bytes, 10, 4);
model_test!(model_gray8_1x5, Gray8Bytes, 1, 5);
model_test!(model_binary_10x4, BinaryMsb, 10, 4);
model_test!(model_binary_16x3, BinaryMsb, 16, 3);
model_test!(model_binary_3x5, BinaryMsb, 3, 5);
model_test!(model_binary_37x2, BinaryMsb, 37, 2);
model_test!(model_bgr565le_10x4, Bgr565Le, 10, 4);
model_test!(model_bgr565be_37x2, Bgr565Be, 37, 2);
model_test!(model_rgb666_10x4, Rgb666Bytes, 10, 4);
model_test!(model_rgb666_37x2, Rgb666Bytes, 37, 2);
model_test!(model_gray4msb_10x4, Gray4Msb, 10, 4);
model_test!(model_gray4msb_7x3, Gray4Msb, 7, 3);
model_test!(model_gray4lsb_10x4, Gray4Lsb, 10, 4);
model_test!(model_gray4lsb_37x2, Gray4Lsb, 37, 2);
model_test!(model_gray2msb_10x4, Gray2Msb, 10, 4);
model_test!(model_gray2msb_16x3, Gray2Msb, 16, 3);
model_test!(model_gray2lsb_7x3, Gray2Lsb, 7, 3);
model_test!(model_gray2lsb_37x2, Gray2Lsb, 37, 2);

/// Every colour survives a round trip through each pixel.
fn round_trip<F: Spec, const W: usize, const H: usize, const N: usize>(
    c: F::Color,
) -> Result<(), TestCaseError> {
    let mut fb = Framebuffer::<F, W, H, N>::new();
    for y in 0..H as i32 {
        for x in 0..W as i32 {
            let p = Point::new(x, y);
            Pixel(p, c).draw(&mut fb).unwrap();
            prop_assert_eq!(fb.pixel(p), Some(c));
        }
    }
    Ok(())
}

proptest! {
    #[test]
    fn pixel_round_trips(
        c565 in arb_rgb565(),
        c888 in Rgb888Bytes::arb_color(),
        gray in any::<u8>(),
        on in any::<bool>(),
    ) {
        round_trip::<Rgb565Le, 3, 2, { buffer_size::<Rgb565Le>(3, 2) }>(c565)?;
        round_trip::<Rgb565Be, 3, 2, { buffer_size::<Rgb565Be>(3, 2) }>(c565)?;
        round_trip::<Rgb888Bytes, 3, 2, { buffer_size::<Rgb888Bytes>(3, 2) }>(c888)?;
        round_trip::<Gray8Bytes, 3, 2, { buffer_size::<Gray8Bytes>(3, 2) }>(Gray8::new(gray))?;
        round_trip::<BinaryMsb, 11, 2, { buffer_size::<BinaryMsb>(11, 2) }>(BinaryColor::from(on))?;
        let bgr = Bgr565::new(c565.r(), c565.g(), c565.b());
        round_trip::<Bgr565Le, 3, 2, { buffer_size::<Bgr565Le>(3, 2) }>(bgr)?;
        round_trip::<Bgr565Be, 3, 2, { buffer_size::<Bgr565Be>(3, 2) }>(bgr)?;
        let c666 = Rgb666::new(c888.r(), c888.g(), c888.b()); // high bits dropped
        round_trip::<Rgb666Bytes, 3, 2, { buffer_size::<Rgb666Bytes>(3, 2) }>(c666)?;
        let (g4, g2) = (Gray4::new(gray), Gray2::new(gray)); // high bits dropped
        round_trip::<Gray4Msb, 5, 2, { buffer_size::<Gray4Msb>(5, 2) }>(g4)?;
        round_trip::<Gray4Lsb, 5, 2, { buffer_size::<Gray4Lsb>(5, 2) }>(g4)?;
        round_trip::<Gray2Msb, 7, 2, { buffer_size::<Gray2Msb>(7, 2) }>(g2)?;
        round_trip::<Gray2Lsb, 7, 2, { buffer_size::<Gray2Lsb>(7, 2) }>(g2)?;
    }
}

// ---------------------------------------------------------------------------
// Layouts written out by hand.

/// The rectangle of `w` x `h` pixels from `(x, y)`.
fn rect(x: i32, y: i32, w: u32, h: u32) -> Rectangle {
    Rectangle::new(Point::new(x, y), Size::new(w, h))
}

type Le = Framebuffer<Rgb565Le, 2, 1, 4>;
type Be = Framebuffer<Rgb565Be, 2, 1, 4>;

#[test]
fn rgb565_byte_orders() {
    let cases = [
        (Rgb565::RED, [0x00, 0xF8], [0xF8, 0x00]),   // 0xF800
        (Rgb565::GREEN, [0xE0, 0x07], [0x07, 0xE0]), // 0x07E0
        (Rgb565::BLUE, [0x1F, 0x00], [0x00, 0x1F]),  // 0x001F
        // 10101 110011 01110 = 0xAE6E
        (
            Rgb565::new(0b10101, 0b110011, 0b01110),
            [0x6E, 0xAE],
            [0xAE, 0x6E],
        ),
    ];
    for (color, le, be) in cases {
        let mut fb = Le::new();
        Pixel(Point::new(1, 0), color).draw(&mut fb).unwrap();
        assert_eq!(fb.as_bytes(), [0, 0, le[0], le[1]], "{color:?}");
        let mut fb = Be::new();
        fb.fill_solid(&rect(1, 0, 5, 5), color).unwrap();
        assert_eq!(fb.as_bytes(), [0, 0, be[0], be[1]], "{color:?}");
    }
}

#[test]
fn rgb888_and_gray8_bytes() {
    let mut fb = Framebuffer::<Rgb888Bytes, 2, 2, 12>::new();
    fb.fill_contiguous(
        &rect(0, 0, 2, 2),
        [(1, 2, 3), (4, 5, 6), (7, 8, 9), (10, 11, 12)].map(|(r, g, b)| Rgb888::new(r, g, b)),
    )
    .unwrap();
    assert_eq!(fb.as_bytes(), [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12]);

    let mut fb = Framebuffer::<Gray8Bytes, 3, 2, 6>::new();
    fb.fill_solid(&rect(1, 1, 9, 9), Gray8::new(0x42)).unwrap();
    assert_eq!(fb.as_bytes(), [0, 0, 0, 0, 0x42, 0x42]);
}

type Mono10 = Framebuffer<BinaryMsb, 10, 3, 6>;

#[test]
fn binary_rows_are_padded_msb_first() {
    assert_eq!(row_size::<BinaryMsb>(10), 2);
    assert_eq!(buffer_size::<BinaryMsb>(10, 3), 6);
    let mut fb = Mono10::new();
    // Columns 6..10 of rows 0 and 1: bits 1, 0 of byte 0 and 7, 6 of byte 1.
    fb.fill_solid(&rect(6, 0, 100, 2), BinaryColor::On).unwrap();
    assert_eq!(fb.as_bytes(), [0b11, 0b1100_0000, 0b11, 0b1100_0000, 0, 0]);
    Pixel(Point::new(0, 2), BinaryColor::On)
        .draw(&mut fb)
        .unwrap();
    Pixel(Point::new(9, 2), BinaryColor::On)
        .draw(&mut fb)
        .unwrap();
    assert_eq!(fb.as_bytes()[4..], [0b1000_0000, 0b0100_0000]);
    fb.clear(BinaryColor::On).unwrap();
    assert_eq!(fb.as_bytes(), [0xFF, 0xC0, 0xFF, 0xC0, 0xFF, 0xC0]);
}

#[test]
fn binary_padding_is_never_drawn() {
    let mut fb = Mono10::new();
    fb.as_bytes_mut().fill(0xFF);
    fb.clear(BinaryColor::Off).unwrap();
    assert_eq!(fb.as_bytes(), [0, 0x3F, 0, 0x3F, 0, 0x3F]);
    fb.fill_solid(&rect(-5, -5, 99, 99), BinaryColor::On)
        .unwrap();
    fb.fill_contiguous(&rect(0, 0, 10, 3), core::iter::repeat(BinaryColor::Off))
        .unwrap();
    assert_eq!(fb.as_bytes(), [0, 0x3F, 0, 0x3F, 0, 0x3F]);
}

#[test]
fn binary_span_within_one_byte_and_across_bytes() {
    let mut fb = Framebuffer::<BinaryMsb, 24, 1, 3>::new();
    fb.fill_solid(&rect(2, 0, 3, 1), BinaryColor::On).unwrap();
    assert_eq!(fb.as_bytes(), [0b0011_1000, 0, 0]);
    fb.fill_solid(&rect(5, 0, 14, 1), BinaryColor::On).unwrap();
    assert_eq!(fb.as_bytes(), [0b0011_1111, 0xFF, 0b1110_0000]);
    fb.fill_solid(&rect(3, 0, 14, 1), BinaryColor::Off).unwrap();
    assert_eq!(fb.as_bytes(), [0b0010_0000, 0, 0b0110_0000]);
}

// ---------------------------------------------------------------------------
// Clipping, sizes and the rest of the API.

type Small = Framebuffer<Rgb565Be, 7, 5, { buffer_size::<Rgb565Be>(7, 5) }>;

#[test]
fn extreme_rectangles_are_clipped() {
    let mut fb = Small::new();
    let far = [
        rect(i32::MAX - 1, 5, u32::MAX, 3),
        rect(i32::MAX, i32::MAX, u32::MAX, u32::MAX),
        rect(i32::MIN, i32::MIN, u32::MAX, 1),
        rect(7, 0, u32::MAX, u32::MAX),
        rect(0, 0, 0, u32::MAX),
    ];
    for r in far {
        fb.fill_solid(&r, Rgb565::RED).unwrap();
        fb.fill_contiguous(&r, core::iter::repeat(Rgb565::RED))
            .unwrap();
        fb.fill_contiguous(&r, [Rgb565::RED; 3]).unwrap();
    }
    assert_eq!(fb, Small::new());

    // Covers everything: from -2^31 to 2^31 - 2 on both axes.
    let all = rect(i32::MIN, i32::MIN, u32::MAX, u32::MAX);
    fb.fill_solid(&all, Rgb565::GREEN).unwrap();
    assert!(fb.as_bytes().chunks(2).all(|px| px == [0x07, 0xE0]));
    // Skips about 2^63 colours with `repeat`'s O(1) `nth`.
    fb.fill_contiguous(&all, core::iter::repeat(Rgb565::BLUE))
        .unwrap();
    assert!(fb.as_bytes().chunks(2).all(|px| px == [0x00, 0x1F]));
}

#[test]
fn fill_contiguous_takes_only_the_colours_it_needs() {
    let mut fb = Small::new();
    let mut colors = (0u8..).map(|i| Rgb565::new(i, 0, 0));
    // A 3 x 3 area whose last visible pixel is (6, 4), index 2 * 3 + 1 = 7.
    fb.fill_contiguous(&rect(5, 2, 3, 3), &mut colors).unwrap();
    assert_eq!(colors.next(), Some(Rgb565::new(8, 0, 0)));
    assert_eq!(fb.pixel(Point::new(6, 4)), Some(Rgb565::new(7, 0, 0)));
    assert_eq!(fb.pixel(Point::new(5, 2)), Some(Rgb565::new(0, 0, 0)));
    assert_eq!(fb.pixel(Point::new(6, 3)), Some(Rgb565::new(4, 0, 0)));

    // Nothing visible: nothing taken.
    let mut colors = (0u8..).map(|i| Rgb565::new(i, 0, 0));
    fb.fill_contiguous(&rect(7, 0, 3, 3), &mut colors).unwrap();
    assert_eq!(colors.next(), Some(Rgb565::new(0, 0, 0)));

    // Too few colours: the rest of the area is left alone.
    let mut fb = Small::new();
    fb.fill_contiguous(&rect(0, 0, 7, 5), [Rgb565::RED; 10])
        .unwrap();
    assert_eq!(fb.pixel(Point::new(2, 1)), Some(Rgb565::RED));
    assert_eq!(fb.pixel(Point::new(3, 1)), Some(Rgb565::BLACK));
}

#[test]
fn draw_iter_ignores_pixels_outside() {
    let mut fb = Small::new();
    let outside = [
        Point::new(-1, 0),
        Point::new(7, 0),
        Point::new(0, 5),
        Point::new(i32::MIN, i32::MIN),
        Point::new(i32::MAX, i32::MAX),
    ];
    fb.draw_iter(outside.map(|p| Pixel(p, Rgb565::WHITE)))
        .unwrap();
    assert_eq!(fb, Small::new());
    for p in outside {
        assert_eq!(fb.pixel(p), None);
    }
    Pixel(Point::new(6, 4), Rgb565::WHITE)
        .draw(&mut fb)
        .unwrap();
    assert_eq!(fb.as_bytes()[68..], [0xFF, 0xFF]);
}

#[test]
fn dimensions() {
    let fb = Small::new();
    assert_eq!(fb.size(), Size::new(7, 5));
    assert_eq!(
        fb.bounding_box(),
        Rectangle::new(Point::zero(), Size::new(7, 5))
    );
    assert_eq!(fb.as_bytes().len(), 70);
    assert_eq!(Mono10::new().size(), Size::new(10, 3));
    assert_eq!(
        Framebuffer::<Rgb888Bytes, 320, 240, { buffer_size::<Rgb888Bytes>(320, 240) }>::new()
            .size(),
        Size::new(320, 240)
    );
}

#[test]
fn empty_framebuffers_ignore_everything() {
    fn exercise<F: Spec, const W: usize, const H: usize, const N: usize>() {
        let mut fb = Framebuffer::<F, W, H, N>::new();
        let c = F::color_from(0xFFFF_FFFF);
        let r = rect(-3, -3, 10, 10);
        fb.clear(c).unwrap();
        fb.fill_solid(&r, c).unwrap();
        fb.fill_contiguous(&r, core::iter::repeat(c)).unwrap();
        Pixel(Point::zero(), c).draw(&mut fb).unwrap();
        assert_eq!(fb.pixel(Point::zero()), None);
        assert_eq!(fb.size(), Size::new(W as u32, H as u32));
        assert!(fb.as_bytes().iter().all(|&b| b == 0));
    }
    exercise::<Rgb565Le, 0, 3, 0>();
    exercise::<Rgb888Bytes, 4, 0, 0>();
    exercise::<BinaryMsb, 0, 0, 0>();
    exercise::<Gray8Bytes, 0, 5, 0>();
    exercise::<Rgb666Bytes, 0, 5, 0>();
    exercise::<Gray4Lsb, 0, 2, 0>();
    exercise::<Gray2Msb, 3, 0, 0>();
}

#[test]
fn new_default_clone_eq_debug() {
    let mut fb = Small::default();
    assert_eq!(fb, Small::new());
    fb.clear(Rgb565::RED).unwrap();
    let copy = fb.clone();
    assert_eq!(copy, fb);
    assert_ne!(copy, Small::new());
    let debug = format!("{fb:?}");
    assert!(debug.starts_with("Framebuffer"), "{debug}");
    assert!(
        debug.contains("Rgb565Be") && debug.contains("width: 7"),
        "{debug}"
    );
}

#[test]
fn as_bytes_mut_writes_pixels() {
    let mut fb = Small::new();
    fb.as_bytes_mut()[2..4].copy_from_slice(&[0xF8, 0x00]);
    assert_eq!(fb.pixel(Point::new(1, 0)), Some(Rgb565::RED));
}

#[test]
fn framebuffer_can_be_static() {
    static FB: Framebuffer<BinaryMsb, 10, 3, { buffer_size::<BinaryMsb>(10, 3) }> =
        Framebuffer::new();
    assert_eq!(FB.pixel(Point::new(9, 2)), Some(BinaryColor::Off));
}

/// A span past the end of its row, which no rasterizer of the crate sends
/// (spans are clipped to the sink's bounds), is not wrapped into the next
/// row: the framebuffer's storage holds the rows back to back.
#[test]
fn sink_span_past_the_row_end_stays_out_of_the_next_row() {
    let mut fb = Small::new();
    fb.fill_span(
        Span {
            y: 1,
            x_start: 5,
            x_end: 9,
        },
        Rgb565::RED,
    )
    .unwrap();
    fb.fill_span(
        Span {
            y: 4,
            x_start: 6,
            x_end: 8,
        },
        Rgb565::RED,
    )
    .unwrap();
    for y in 0..5 {
        assert_eq!(fb.pixel(Point::new(0, y)), Some(Rgb565::BLACK), "row {y}");
        assert_eq!(fb.pixel(Point::new(1, y)), Some(Rgb565::BLACK), "row {y}");
    }
}
