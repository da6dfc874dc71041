//! The inputs and checks of the fuzz targets, one input at a time: drawn
//! from [`Rng`], which is the seeded generator of `tests/fuzz.rs` there
//! and, in the coverage-guided targets of `fuzz/`, a reader of libFuzzer's
//! bytes. The includer declares the sibling modules `common`, `line_ref`,
//! `rng` and `view`.

use embedded_graphics::draw_target::DrawTargetExt;
use embedded_graphics_core::{
    pixelcolor::{Bgr565, BinaryColor, Gray2, Gray4, Gray8, Rgb565, Rgb666, Rgb888, RgbColor},
    prelude::*,
    primitives::Rectangle,
};
use embedded_raster::{
    framebuffer::{
        buffer_size, Bgr565Be, Bgr565Le, BinaryMsb, Gray2Lsb, Gray2Msb, Gray4Lsb, Gray4Msb,
        Gray8Bytes, PixelFormat, Rgb565Be, Rgb565Le, Rgb666Bytes, Rgb888Bytes,
    },
    mesh::{Camera, Rotation, Vec3},
    shade::{DepthBuffer, ShadeColor, FAR},
    sim::{parse_scene, render_scene, render_scene_in_bands, render_scene_with, SimDisplay},
    FillRule, Framebuffer, Join, Line, LineAlgorithm, Polygon, Polyline, SpanDrawable, SpanSink,
    SubpixelPrecision, Triangle, TriangleAlgorithm, Vertex,
};

use super::common::{
    add_spans_from, assert_same,
    blend::{check_rounded, exact_at},
    rasterized, reference_fill, reference_triangle, Grid,
};
use super::line_ref::{ideal_minor, reference, Window};
use super::rng::Rng;
use super::view::View;

/// One of `choices`, or `other` one time in `choices.len() + 1`.
fn pick<T: Copy>(r: &mut Rng, choices: &[T], other: impl FnOnce(&mut Rng) -> T) -> T {
    match usize::try_from(r.below(choices.len() as u64 + 1)).unwrap() {
        i if i < choices.len() => choices[i],
        _ => other(r),
    }
}

/// A raw 20.12 coordinate: the range's ends, zero, tiny values, values
/// near `near` (pixels), or anything.
fn raw(r: &mut Rng, near: i64) -> i32 {
    let c = [
        i32::MIN,
        i32::MIN + 1,
        i32::MAX,
        i32::MAX - 1,
        0,
        1,
        -1,
        2048,
        4095,
    ];
    match r.below(3) {
        0 => pick(r, &c, |r| r.next() as i32),
        _ => (near * 4096 + r.below(40 * 4096) - 20 * 4096).clamp(i32::MIN.into(), i32::MAX.into())
            as i32,
    }
}

/// A pixel coordinate: `i32` ends, zero, or near `near`.
fn pixel(r: &mut Rng, near: i64) -> i32 {
    let c = [i32::MIN, i32::MIN + 1, i32::MAX, i32::MAX - 1, 0, -1];
    match r.below(3) {
        0 => pick(r, &c, |r| r.next() as i32),
        _ => (near + r.below(40) - 20).clamp(i32::MIN.into(), i32::MAX.into()) as i32,
    }
}

/// Where to look: near the origin, at the edges of the 20.12 range, or at
/// the `i32` ends (pixels).
fn focus(r: &mut Rng) -> i64 {
    pick(r, &[0, 4, -524288, 524280, -524292], |r| {
        r.below(1 << 20) - (1 << 19)
    })
}

fn vertex(r: &mut Rng, fx: i64, fy: i64) -> Vertex {
    Vertex::from_raw(raw(r, fx), raw(r, fy))
}

/// Any of the joins.
fn join(r: &mut Rng) -> Join {
    pick(r, &[Join::Miter, Join::Bevel], |_| Join::Round)
}

/// A stroke's width (thin, thick, huge, or anything up to 64) and join.
fn stroke_style(r: &mut Rng) -> (u32, Join) {
    let width = pick(r, &[1, 2, 3, 8, 1000, u32::MAX], |r| r.below(64) as u32);
    (width, join(r))
}

/// A 16 x 16 window near pixel `(fx, fy)` (within the 20.12 range).
fn window_near(r: &mut Rng, fx: i64, fy: i64) -> Point {
    let near = |f: i64, r: &mut Rng| (f + r.below(48) - 24) as i32;
    Point::new(near(fx, r), near(fy, r))
}

/// Draws `target` on a `SimDisplay` and on a `Framebuffer` of every
/// format, 16 x 16 at `origin` (through a [`View`]), and checks that they
/// agree, that nothing lands outside and, for a shape that promises it,
/// that no pixel is written twice. At the origin, also through the
/// framebuffers' own `SpanSink` (`draw_spans`: spans and lines written
/// straight into their bytes). Returns the display's lit grid (write
/// count > 0).
fn on_every_target(target: &Target, origin: Point) -> Grid {
    let mut display = SimDisplay::new(16, 16, Rgb888::BLACK);
    target.draw(
        &mut View {
            inner: &mut display,
            origin,
        },
        Rgb888::WHITE,
    );
    assert_eq!(display.out_of_bounds_writes(), 0);
    let mut lit = Grid::new(origin.x.into(), origin.y.into(), 16, 16);
    for j in 0..16 {
        for i in 0..16 {
            let count = display.write_count(Point::new(i, j));
            if target.each_pixel_once() {
                assert!(
                    count <= Some(1),
                    "written twice at ({i}, {j}) of {origin:?}"
                );
            }
            if count != Some(0) {
                lit.bump(i64::from(origin.x + i), i64::from(origin.y + j));
            }
        }
    }
    macro_rules! check {
        ($f:ty, $c:ty, $on:expr) => {{
            let mut fb = Framebuffer::<$f, 16, 16, { buffer_size::<$f>(16, 16) }>::new();
            let background: $c = fb.pixel(Point::zero()).unwrap();
            let mut sim = SimDisplay::new(16, 16, background);
            target.draw(
                &mut View {
                    inner: &mut fb,
                    origin,
                },
                $on,
            );
            target.draw(
                &mut View {
                    inner: &mut sim,
                    origin,
                },
                $on,
            );
            assert_eq!(sim.out_of_bounds_writes(), 0);
            let mut direct = Framebuffer::<$f, 16, 16, { buffer_size::<$f>(16, 16) }>::new();
            if origin == Point::zero() {
                target.draw_spans(&mut direct, $on);
            }
            for j in 0..16 {
                for i in 0..16 {
                    let p = Point::new(i, j);
                    assert_eq!(fb.pixel(p), sim.pixel(p), "{} at {p:?}", stringify!($f));
                    if origin == Point::zero() {
                        assert_eq!(
                            direct.pixel(p),
                            sim.pixel(p),
                            "{} spans at {p:?}",
                            stringify!($f)
                        );
                    }
                }
            }
        }};
    }
    check!(Rgb565Le, Rgb565, Rgb565::new(31, 7, 3));
    check!(Rgb565Be, Rgb565, Rgb565::new(1, 60, 30));
    check!(Rgb888Bytes, Rgb888, Rgb888::new(1, 2, 3));
    check!(Gray8Bytes, Gray8, Gray8::new(0x81));
    check!(BinaryMsb, BinaryColor, BinaryColor::On);
    check!(Bgr565Le, Bgr565, Bgr565::new(31, 7, 3));
    check!(Bgr565Be, Bgr565, Bgr565::new(1, 60, 30));
    check!(Rgb666Bytes, Rgb666, Rgb666::new(63, 1, 40));
    check!(Gray4Msb, Gray4, Gray4::new(0xB));
    check!(Gray4Lsb, Gray4, Gray4::new(0x6));
    check!(Gray2Msb, Gray2, Gray2::new(2));
    check!(Gray2Lsb, Gray2, Gray2::new(1));
    lit
}

/// One drawable, drawable on any of the targets in one colour.
#[derive(Clone)]
enum Target {
    Tri(Triangle),
    Poly(Vec<Vertex>, FillRule),
    Line(Line, LineAlgorithm, u32),
    Polyline(Vec<Point>, LineAlgorithm, u32, Join),
    /// A triangle's outline: width and join.
    StrokedTri(Triangle, u32, Join),
    /// A polygon's outline: width and join.
    StrokedPoly(Vec<Vertex>, u32, Join),
}

/// `$target` styled in `$c`, written by `$method` (`draw` or `draw_spans`)
/// into `$d`.
macro_rules! draw_with {
    ($target:expr, $c:expr, $method:ident, $d:expr) => {{
        let Ok(()) = match $target {
            Target::Tri(t) => t.fill($c).$method($d),
            Target::Poly(v, rule) => Polygon::<8>::new(v)
                .unwrap()
                .fill($c)
                .with_rule(*rule)
                .$method($d),
            Target::Line(l, a, w) => l.stroke($c).stroke_width(*w).algorithm(*a).$method($d),
            Target::Polyline(p, a, w, j) => Polyline::new(p)
                .stroke($c)
                .stroke_width(*w)
                .algorithm(*a)
                .join(*j)
                .$method($d),
            Target::StrokedTri(t, w, j) => t.stroke($c).stroke_width(*w).join(*j).$method($d),
            Target::StrokedPoly(v, w, j) => Polygon::<8>::new(v)
                .unwrap()
                .stroke($c)
                .stroke_width(*w)
                .join(*j)
                .$method($d),
        };
    }};
}

impl Target {
    /// Whether the drawable writes each pixel at most once through a
    /// `DrawTarget`, as the docs promise: filled shapes, thick lines, and
    /// strokes over 1 px wide (1-pixel polylines and outlines may cross
    /// themselves).
    fn each_pixel_once(&self) -> bool {
        match self {
            Target::Tri(_) | Target::Poly(..) => true,
            Target::Line(_, _, w)
            | Target::Polyline(_, _, w, _)
            | Target::StrokedTri(_, w, _)
            | Target::StrokedPoly(_, w, _) => *w >= 2,
        }
    }

    /// Through `Drawable::draw`.
    fn draw<D: DrawTarget<Color = C, Error = core::convert::Infallible>, C: PixelColor>(
        &self,
        d: &mut D,
        c: C,
    ) {
        draw_with!(self, c, draw, d)
    }

    /// Through `SpanDrawable::draw_spans`.
    fn draw_spans<S: SpanSink<C, Error = core::convert::Infallible>, C: PixelColor>(
        &self,
        s: &mut S,
        c: C,
    ) {
        draw_with!(self, c, draw_spans, s)
    }
}

/// A triangle anywhere, against the reference in a window on it and on
/// every target at the origin, and its Gouraud version's pixels.
pub fn triangle(r: &mut Rng) {
    let (fx, fy) = (focus(r), focus(r));
    let t = Triangle::new(vertex(r, fx, fy), vertex(r, fx, fy), vertex(r, fx, fy));
    // A window wherever the triangle is, against the reference.
    let (x0, y0) = (fx + r.below(16) - 8, fy + r.below(16) - 8);
    assert_same(
        &rasterized(&t, x0, y0, 8, 8),
        &reference_triangle(&t, x0, y0, 8, 8),
        &t,
    );
    // Every target at the origin.
    let lit = on_every_target(&Target::Tri(t), Point::zero());
    assert_same(&lit, &reference_triangle(&t, 0, 0, 16, 16), &t);
    // Gouraud, in a window near its focus, in a colour of any format.
    let origin = window_near(r, fx, fy);
    let lit_near = reference_triangle(&t, origin.x.into(), origin.y.into(), 16, 16);
    // Colours made and read by the colour's own constructor, constants and
    // accessors, not by `ShadeColor`.
    macro_rules! rgb {
        ($f:ty, $c:ident) => {
            gouraud_in_window::<$f, { buffer_size::<$f>(16, 16) }>(
                &t,
                three(r, [$c::MAX_R, $c::MAX_G, $c::MAX_B]).map(|c| $c::new(c[0], c[1], c[2])),
                origin,
                &lit_near,
                |c| [c.r(), c.g(), c.b()],
            )
        };
    }
    macro_rules! gray {
        ($f:ty, $c:ident) => {
            gouraud_in_window::<$f, { buffer_size::<$f>(16, 16) }>(
                &t,
                three(r, [$c::WHITE.luma(), 0, 0]).map(|c| $c::new(c[0])),
                origin,
                &lit_near,
                |c| [c.luma(), 0, 0],
            )
        };
    }
    match r.below(6) {
        0 => rgb!(Rgb888Bytes, Rgb888),
        1 => rgb!(Rgb565Le, Rgb565),
        2 => rgb!(Bgr565Be, Bgr565),
        3 => rgb!(Rgb666Bytes, Rgb666),
        4 => gray!(Gray4Msb, Gray4),
        _ => gray!(Gray8Bytes, Gray8),
    }
    // Depth-tested against a cleared buffer, at depths nearer than `FAR`:
    // every pixel passes, so exactly the same pixels, each written once,
    // each storing the exact depth (within 1, rounded unless near a half),
    // and the rest still `FAR`.
    let mut z = [0u16; 16 * 16];
    let depth = DepthBuffer::new(&mut z, 16);
    depth.clear();
    let near = |r: &mut Rng| pick(r, &[0, 1, u16::MAX - 1], |r| r.below(65535) as u16);
    let zs = [near(r), near(r), near(r)];
    let mut d = SimDisplay::new(16, 16, Gray8::BLACK);
    let Ok(()) = t.fill(Gray8::WHITE).with_depth(zs, depth).draw(&mut d);
    assert_eq!(d.out_of_bounds_writes(), 0);
    for j in 0..16 {
        for i in 0..16 {
            let count = d.write_count(Point::new(i, j));
            let want = u32::from(lit.get(i64::from(i), i64::from(j)) != 0);
            assert_eq!(count, Some(want), "{t:?} at depths {zs:?}");
            let stored = depth.get(i as u32, j as u32).unwrap();
            if want == 1 {
                let e = exact_at(&t, zs.map(i128::from), i64::from(i), i64::from(j));
                if let Err(msg) = check_rounded(i128::from(stored), e) {
                    panic!("{t:?} at depths {zs:?}, ({i}, {j}): {msg}");
                }
            } else {
                assert_eq!(stored, FAR, "{t:?} at depths {zs:?}, ({i}, {j})");
            }
        }
    }
    // Its outline, in a window near its focus.
    let (width, join) = stroke_style(r);
    on_every_target(&Target::StrokedTri(t, width, join), window_near(r, fx, fy));
}

/// Three colours' channels, each up to `max`: 0, the maximum, or any.
fn three(r: &mut Rng, max: [u8; 3]) -> [[u8; 3]; 3] {
    let mut channel = |m: u8| pick(r, &[0, m], |r| r.below(u64::from(m) + 1) as u8);
    [0; 3].map(|_| max.map(&mut channel))
}

/// Draws `t`'s Gouraud version with `colors` in the 16 x 16 window at
/// `origin`, on a `SimDisplay` and on a `Framebuffer` of format `F`, and
/// checks that the display gets exactly the flat triangle's pixels (`lit`,
/// the reference's), each once, with every channel (read by `read`: the
/// colour's own accessors) within 1 of the exact blend of
/// `tests/common/blend.rs` and rounded unless near a half, and that the
/// framebuffer holds the same.
fn gouraud_in_window<F: PixelFormat, const N: usize>(
    t: &Triangle,
    colors: [F::Color; 3],
    origin: Point,
    lit: &Grid,
    read: impl Fn(F::Color) -> [u8; 3],
) where
    F::Color: ShadeColor + core::fmt::Debug,
{
    let mut fb = Framebuffer::<F, 16, 16, N>::new();
    let background = fb.pixel(Point::zero()).unwrap();
    let mut sim = SimDisplay::new(16, 16, background);
    let shaded = t.gouraud(colors);
    let Ok(()) = shaded.draw(&mut View {
        inner: &mut sim,
        origin,
    });
    let Ok(()) = shaded.draw(&mut View {
        inner: &mut fb,
        origin,
    });
    assert_eq!(sim.out_of_bounds_writes(), 0);
    let at_vertices = colors.map(&read);
    for j in 0..16 {
        for i in 0..16 {
            let p = Point::new(i, j);
            let (x, y) = (
                i64::from(origin.x) + i64::from(i),
                i64::from(origin.y) + i64::from(j),
            );
            assert_eq!(fb.pixel(p), sim.pixel(p), "{t:?} {colors:?} at ({x}, {y})");
            let count = sim.write_count(p);
            assert_eq!(
                count,
                Some(u32::from(lit.get(x, y) != 0)),
                "{t:?} at ({x}, {y})"
            );
            if count == Some(1) {
                let got = read(sim.pixel(p).unwrap());
                for k in 0..<F::Color as ShadeColor>::CHANNELS {
                    let e = exact_at(t, at_vertices.map(|c| i128::from(c[k])), x, y);
                    if let Err(msg) = check_rounded(i128::from(got[k]), e) {
                        panic!("{t:?} {colors:?} at ({x}, {y}), channel {k}: {msg}");
                    }
                }
            }
        }
    }
}

/// A polygon of 3 to 8 vertices under either rule, against the reference.
pub fn polygon(r: &mut Rng) {
    let (fx, fy) = (focus(r), focus(r));
    let len = 3 + r.below(6) as usize;
    let v: Vec<Vertex> = (0..len).map(|_| vertex(r, fx, fy)).collect();
    let rule = if r.below(2) == 0 {
        FillRule::EvenOdd
    } else {
        FillRule::NonZero
    };
    let even_odd = rule == FillRule::EvenOdd;
    let poly = Polygon::<8>::new(&v).unwrap();
    let (x0, y0) = (fx + r.below(16) - 8, fy + r.below(16) - 8);
    let mut got = Grid::new(x0, y0, 8, 8);
    add_spans_from::<core::convert::Infallible>(&mut got, |clip, f| {
        poly.for_each_span(rule, clip, f)
    });
    assert_same(&got, &reference_fill(&v, even_odd, x0, y0, 8, 8), &v);
    let lit = on_every_target(&Target::Poly(v.clone(), rule), Point::zero());
    assert_same(&lit, &reference_fill(&v, even_odd, 0, 0, 16, 16), &v);
    // Its outline, in a window near its focus.
    let (width, join) = stroke_style(r);
    on_every_target(&Target::StrokedPoly(v, width, join), window_near(r, fx, fy));
}

/// The exact pixels of the polyline through `points` (one point: that
/// pixel) in the 16 x 16 window at `origin`, from the independent line
/// reference: the union of its segments' pixels.
fn line_reference(points: &[Point], origin: Point) -> Grid {
    let win = Window {
        x0: origin.x.into(),
        y0: origin.y.into(),
        w: 16,
        h: 16,
    };
    let mut g = Grid::new(win.x0, win.y0, 16, 16);
    let segments: Vec<(Point, Point)> = match points {
        [p] => vec![(*p, *p)],
        _ => points.windows(2).map(|w| (w[0], w[1])).collect(),
    };
    for (a, b) in segments {
        for (x, y) in reference(a, b, win) {
            if g.get(x, y) == 0 {
                g.bump(x, y);
            }
        }
    }
    g
}

/// Where to look at the segment `a`-`b`: the origin, or a 16 x 16 window
/// around one of its exact pixels (anywhere in `i32`, the ends included),
/// shifted by up to 20 px.
fn window_on(r: &mut Rng, a: Point, b: Point) -> Point {
    if r.below(3) == 0 {
        return Point::zero();
    }
    let (x_major, _) = ideal_minor(a, b, 0);
    let (m0, m1) = if x_major {
        (i64::from(a.x), i64::from(b.x))
    } else {
        (i64::from(a.y), i64::from(b.y))
    };
    let t = pick(r, &[m0, m1, m0 + (m1 - m0) / 2], |r| {
        m0 + (((m1 - m0) as i128 * i128::from(r.below(1 << 16))) >> 16) as i64
    });
    let m = ideal_minor(a, b, t).1.unwrap();
    let (x, y) = if x_major { (t, m) } else { (m, t) };
    let at = |c: i64, r: &mut Rng| {
        (c + r.below(41) - 20 - 8).clamp(i32::MIN.into(), i64::from(i32::MAX) - 15) as i32
    };
    Point::new(at(x, r), at(y, r))
}

/// A line and a polyline in any algorithm and width on every target;
/// exact 1-pixel ones against the line reference. Whether they were
/// exact 1-pixel strokes.
pub fn line_and_polyline(r: &mut Rng) -> bool {
    let mut exact = false;
    let f = pick(r, &[0, 8], |r| r.next() as i32 as i64);
    let point = |r: &mut Rng| Point::new(pixel(r, f), pixel(r, f));
    let a = pick(
        r,
        &[
            LineAlgorithm::Bresenham,
            LineAlgorithm::Bresenham,
            LineAlgorithm::Dda,
        ],
        |_| LineAlgorithm::Naive,
    );
    let width = pick(r, &[1, 1, 1, 1, 1, 0, 2, 3, 7, 1000, u32::MAX], |r| {
        r.below(64) as u32
    });
    // Exact 1-pixel strokes light exactly the reference's pixels;
    // width 0 lights nothing.
    let check = |lit: &Grid, points: &[Point], origin: Point| {
        if width == 1 && a == LineAlgorithm::Bresenham {
            assert_same(lit, &line_reference(points, origin), &points);
        } else if width == 0 {
            assert!(lit.cells.iter().all(|&c| c == 0), "{points:?}");
        }
    };
    let line = Line::new(point(r), point(r));
    let origin = window_on(r, line.start, line.end);
    let lit = on_every_target(&Target::Line(line, a, width), origin);
    check(&lit, &[line.start, line.end], origin);
    if width == 1 && a == LineAlgorithm::Bresenham {
        // `Line::pixels` lists the same pixels.
        let mut listed = Grid::new(origin.x.into(), origin.y.into(), 16, 16);
        let clip = Rectangle::new(origin, Size::new(16, 16));
        for q in line.pixels(&clip).into_iter().flatten() {
            listed.bump(q.x.into(), q.y.into());
        }
        assert_same(&listed, &lit, &line);
        exact = true;
        // Partly iterated, or past its end: its runs are the pixels
        // left to iterate.
        if let Some(mut pixels) = line.pixels(&clip) {
            for _ in 0..r.below(20) {
                pixels.next();
            }
            let mut runs = vec![];
            pixels
                .for_each_run(|run| {
                    assert!(run.len <= 16, "{run:?} of {line:?}");
                    for i in 0..run.len as i32 {
                        let (x, y) = (run.start.x, run.start.y);
                        runs.push(match run.vertical {
                            true => Point::new(x, y + i),
                            false => Point::new(x + i, y),
                        });
                    }
                    Ok::<(), ()>(())
                })
                .unwrap();
            assert_eq!(runs, pixels.collect::<Vec<_>>(), "{line:?}");
        }
    }
    let len = 2 + r.below(5) as usize;
    let points: Vec<Point> = (0..len).map(|_| point(r)).collect();
    let k = r.below(len as u64 - 1) as usize;
    let origin = window_on(r, points[k], points[k + 1]);
    let join = join(r);
    let lit = on_every_target(&Target::Polyline(points.clone(), a, width, join), origin);
    check(&lit, &points, origin);
    exact
}

/// A random scene: mostly well-formed commands at extreme values, now and
/// then a bad token.
pub fn scene_text(r: &mut Rng) -> String {
    // About one token in 100 is bad (out of range or malformed), so that
    // most scenes parse and a fair share fail somewhere.
    let bad = |r: &mut Rng| r.below(100) == 0;
    let num = |r: &mut Rng| -> String {
        if bad(r) {
            return pick(r, &["524288", "1e3", "nan", "-524288.0001", "0x10"], |_| {
                "inf"
            })
            .to_string();
        }
        match r.below(8) {
            0 => {
                let extreme = [
                    "-524288",
                    "524287.999755859375",
                    "-0.5",
                    "0.000244140625",
                    "-0",
                ];
                match r.below(extreme.len() as u64 + 1) as usize {
                    i if i < extreme.len() => extreme[i].to_string(),
                    _ => format!("{}", r.below(1 << 21) - (1 << 20)),
                }
            }
            1 => format!("{}.{}", r.below(80) - 20, r.below(10000)),
            _ => format!("{}", r.below(80) - 20),
        }
    };
    let int = |r: &mut Rng| -> String {
        if bad(r) {
            return pick(r, &["2147483648", "1.5", "-2147483649"], |_| "x").to_string();
        }
        pick(r, &[i32::MIN as i64, i32::MAX as i64, 0, -1], |r| {
            r.below(80) - 20
        })
        .to_string()
    };
    let colour = |r: &mut Rng| -> String {
        if bad(r) {
            return pick(r, &["#0", "#GGGGGG", "ffffff"], |_| "#1234567").to_string();
        }
        pick(r, &["#ffffff", "#000000", "#FF8000"], |_| "#123abc").to_string()
    };
    let (w, h) = (1 + r.below(40), 1 + r.below(40));
    let mut s = format!("size {w} {h}\n");
    for _ in 0..r.below(12) {
        let line = match r.below(8) {
            0 => format!("clear {}", colour(r)),
            1 => format!(
                "rect {} {} {} {} {}",
                int(r),
                int(r),
                int(r).trim_start_matches('-'),
                int(r).trim_start_matches('-'),
                colour(r)
            ),
            2 => format!(
                "tri {} {} {} {} {} {} {}",
                num(r),
                num(r),
                num(r),
                num(r),
                num(r),
                num(r),
                colour(r)
            ),
            3 => format!(
                "gtri {} {} {} {} {} {} {} {} {}",
                num(r),
                num(r),
                colour(r),
                num(r),
                num(r),
                colour(r),
                num(r),
                num(r),
                colour(r)
            ),
            4 => format!(
                "line {} {} {} {} {}",
                int(r),
                int(r),
                int(r),
                int(r),
                colour(r)
            ),
            5 => {
                let pts: Vec<String> = (0..2 * (2 + r.below(4))).map(|_| int(r)).collect();
                format!("polyline {} {}", colour(r), pts.join(" "))
            }
            6 => {
                let pts: Vec<String> = (0..2 * (3 + r.below(5))).map(|_| num(r)).collect();
                let rule = pick(r, &["evenodd", "nonzero", "winding"], |_| "nonzero");
                format!("poly {rule} {} {}", colour(r), pts.join(" "))
            }
            _ if bad(r) => pick(r, &["circle 1 2 3", "size 4 4", "tri 1 2"], |_| {
                "poly nonzero #ffffff 0 0 1 1"
            })
            .to_string(),
            _ => pick(r, &["# comment", ""], |_| "\t").to_string(),
        };
        s.push_str(&line);
        s.push('\n');
    }
    s
}
/// The scene `text` parsed and, if it parses, rendered whole, in an
/// inexact variant and in bands (of a height drawn from `r`): no write
/// outside, no more pixels than its estimate, the same image in bands.
/// Whether it parsed.
pub fn scene(text: &str, r: &mut Rng) -> bool {
    let Ok(scene) = parse_scene(text) else {
        return false;
    };
    let rendered = render_scene(&scene);
    assert_eq!(rendered.display.out_of_bounds_writes(), 0, "{text}");
    let work = scene.pixel_work();
    assert!(
        rendered.stats.pixels_written <= work,
        "{text}: {} > {work}",
        rendered.stats.pixels_written
    );
    // The estimate bounds the inexact variants too (`render --algo`).
    let algo = [
        TriangleAlgorithm::EdgeWalk,
        TriangleAlgorithm::BresenhamWalk,
    ][r.below(2) as usize];
    let bits = [
        SubpixelPrecision::Bits0,
        SubpixelPrecision::Bits4,
        SubpixelPrecision::Bits12,
    ][r.below(3) as usize];
    let variant = render_scene_with(&scene, algo, bits);
    assert_eq!(variant.display.out_of_bounds_writes(), 0, "{algo:?} {text}");
    assert!(
        variant.stats.pixels_written <= work,
        "{algo:?} at {bits:?}: {text}: {} > {work}",
        variant.stats.pixels_written
    );
    // Through the band renderer, in bands of a random height: the same
    // image and the same write counts.
    let rows = [1, 2, 3, 7, 16, 64][r.below(6) as usize];
    let (algo, bits) = (TriangleAlgorithm::EdgeExact, SubpixelPrecision::Bits12);
    let (banded, _) = render_scene_in_bands(&scene, rows, algo, bits);
    let (a, b) = (&banded.display, &rendered.display);
    assert!(a.pixels() == b.pixels(), "bands of {rows}: {text}");
    assert!(a.counts() == b.counts(), "bands of {rows}: {text}");
    // Through a window that may cut every shape on any side
    // (embedded-graphics' `Clipped`): inside it, the whole image.
    let size = scene.size();
    let (w, h) = (i64::from(size.width), i64::from(size.height));
    let at = |r: &mut Rng, n: i64| (r.below(n as u64 + 8) - 4) as i32;
    let span = |r: &mut Rng, n: i64| r.below(n as u64 + 8) as u32;
    let window = Rectangle::new(
        Point::new(at(r, w), at(r, h)),
        Size::new(span(r, w), span(r, h)),
    );
    let mut display = SimDisplay::new(size.width, size.height, Rgb888::BLACK);
    for command in scene.commands() {
        let Ok(()) = command.draw_with(&mut display.clipped(&window), algo, bits);
    }
    for p in window.points() {
        assert_eq!(
            display.pixel(p),
            b.pixel(p),
            "window {window:?} at {p:?}: {text}"
        );
    }
    true
}

/// The mesh arithmetic at `i32` extremes, against `i128`.
pub fn mesh(r: &mut Rng) {
    let any = |r: &mut Rng| {
        pick(
            r,
            &[i32::MIN, i32::MAX, 0, 1, -1, 1 << 15, 1 << 30, -(1 << 30)],
            |r| r.next() as i32,
        )
    };
    let v = Vec3::new(any(r), any(r), any(r));
    let o = Vec3::new(any(r), any(r), any(r));
    let exact = {
        let p = |a: i32, b: i32| i128::from(a) * i128::from(b);
        (p(v.x, o.x) + p(v.y, o.y) + p(v.z, o.z) + (1 << 14)) >> 15
    };
    assert_eq!(
        i128::from(v.dot(o)),
        exact.clamp(i32::MIN.into(), i32::MAX.into())
    );
    assert_eq!(
        v.checked_dot(o).map(i128::from),
        i32::try_from(exact).ok().map(i128::from)
    );
    let rot = Rotation::new(r.next() as u16, r.next() as u16);
    let _ = (rot.apply(v), rot.checked_apply(v));
    let cam = Camera {
        focal: any(r),
        centre: (any(r), any(r)),
        near: any(r),
        far: any(r),
    };
    let _ = cam.project(v);
}
