//! Thick polylines with joins, and stroked triangles and polygons, against
//! an independent reference: the stroke as the union of its segments'
//! rectangles and its join regions, tested at each pixel centre in `f64`
//! (pixels within `EPS` of the union's boundary are skipped), written
//! from the definition without calling the code under test. Every pixel
//! must be written at most once, none outside the display. Drawn into a
//! sink on which overdraw is invisible (as a framebuffer is), where the
//! pieces are written whole and overlap, the same pixels must be lit.
//!
//! Case counts follow `PROPTEST_CASES` (proptest's default, 256, when
//! unset).
#![cfg(feature = "sim")]

use core::convert::Infallible;

use embedded_graphics_core::{pixelcolor::Gray8, prelude::*, primitives::Rectangle};
use embedded_raster::{
    sim::SimDisplay, Join, Line, Polygon, Polyline, Span, SpanDrawable, SpanSink, Triangle, Vertex,
};
use proptest::prelude::*;

/// Pixels whose centre is within this many px of the reference's
/// boundary are not checked: the code rounds corners to 1/4096 px and a
/// miter tip (up to 8 times the offsets' rounding) to the nearest unit.
const EPS: f64 = 0.01;

/// Display size; strokes may reach outside it (clipping is exercised).
const SIZE: u32 = 72;

type V = (f64, f64);

fn sub(a: V, b: V) -> V {
    (a.0 - b.0, a.1 - b.1)
}
fn dot(a: V, b: V) -> f64 {
    a.0 * b.0 + a.1 * b.1
}
fn cross(a: V, b: V) -> f64 {
    a.0 * b.1 - a.1 * b.0
}
fn norm(a: V) -> V {
    let l = dot(a, a).sqrt();
    (a.0 / l, a.1 / l)
}

/// Signed distance of `q` inside the convex polygon `v` (either winding):
/// positive inside.
fn convex_margin(v: &[V], q: V) -> f64 {
    let area: f64 = (0..v.len())
        .map(|i| cross(v[i], v[(i + 1) % v.len()]))
        .sum();
    if area.abs() < 1e-12 {
        return f64::NEG_INFINITY;
    }
    let o = area.signum();
    (0..v.len())
        .map(|i| {
            let (a, b) = (v[i], v[(i + 1) % v.len()]);
            let d = sub(b, a);
            let l = dot(d, d).sqrt();
            if l == 0.0 {
                f64::INFINITY
            } else {
                o * cross(d, sub(q, a)) / l
            }
        })
        .fold(f64::INFINITY, f64::min)
}

/// The reference: a stroke through points given in raw 20.12 units.
struct Reference {
    /// Raw coordinates (exact integer directions for the turn's sign).
    pts: Vec<(i64, i64)>,
    closed: bool,
    width: f64,
    join: Join,
}

impl Reference {
    fn polyline(points: &[Point], width: u32, join: Join) -> Self {
        let closed = points.len() >= 3
            && points.first() == points.last()
            && points.iter().any(|p| p != &points[0]);
        let mut pts: Vec<_> = points
            .iter()
            .map(|p| (p.x as i64 * 4096 + 2048, p.y as i64 * 4096 + 2048))
            .collect();
        if closed {
            pts.pop();
        }
        Self {
            pts,
            closed,
            width: width as f64,
            join,
        }
    }

    fn ring(vertices: &[Vertex], width: u32, join: Join) -> Self {
        Self {
            pts: vertices
                .iter()
                .map(|v| (v.raw().0 as i64, v.raw().1 as i64))
                .collect(),
            closed: true,
            width: width as f64,
            join,
        }
    }

    fn px(p: (i64, i64)) -> V {
        (p.0 as f64 / 4096.0, p.1 as f64 / 4096.0)
    }

    /// The segments of non-zero length, in order.
    fn segments(&self) -> Vec<((i64, i64), (i64, i64))> {
        let n = self.pts.len();
        let count = if self.closed { n } else { n.saturating_sub(1) };
        (0..count)
            .map(|k| (self.pts[k], self.pts[(k + 1) % n]))
            .filter(|(a, b)| a != b)
            .collect()
    }

    /// The largest signed margin over the pieces, as a range: where a turn
    /// is too close to the miter limit to tell miter from bevel, the
    /// smaller and the larger of the two.
    fn margin(&self, q: V) -> (f64, f64) {
        let mut best = (f64::NEG_INFINITY, f64::NEG_INFINITY);
        for (lo, hi) in self.pieces(q) {
            best = (best.0.max(lo), best.1.max(hi));
        }
        best
    }

    /// The signed margin of `q` in each piece (a range, see `margin`).
    fn pieces(&self, q: V) -> Vec<(f64, f64)> {
        let mut out = vec![];
        let h = self.width / 2.0;
        let segs = self.segments();
        if segs.is_empty() {
            if let Some(&p) = self.pts.first() {
                let p = Self::px(p);
                let m = h - (q.0 - p.0).abs().max((q.1 - p.1).abs());
                out.push((m, m));
            }
            return out;
        }
        for (k, &(a, b)) in segs.iter().enumerate() {
            let (pa, pb) = (Self::px(a), Self::px(b));
            let t = norm(sub(pb, pa));
            let len = dot(sub(pb, pa), sub(pb, pa)).sqrt();
            let ext_a = if !self.closed && k == 0 { 0.5 } else { 0.0 };
            let ext_b = if !self.closed && k + 1 == segs.len() {
                0.5
            } else {
                0.0
            };
            let u = dot(sub(q, pa), t);
            let v = cross(t, sub(q, pa));
            let m = (u + ext_a).min(len + ext_b - u).min(h - v.abs());
            out.push((m, m));
        }
        let joints = if self.closed {
            segs.len()
        } else {
            segs.len() - 1
        };
        for k in 0..joints {
            let (s0, s1) = (segs[k], segs[(k + 1) % segs.len()]);
            let d0 = (s0.1 .0 - s0.0 .0, s0.1 .1 - s0.0 .1);
            let d1 = (s1.1 .0 - s1.0 .0, s1.1 .1 - s1.0 .1);
            let turn = (d0.0 as i128 * d1.1 as i128 - d0.1 as i128 * d1.0 as i128).signum();
            let p = Self::px(s1.0);
            let (t0, t1) = (
                norm((d0.0 as f64, d0.1 as f64)),
                norm((d1.0 as f64, d1.1 as f64)),
            );
            let r = sub(q, p);
            let disk = h - dot(r, r).sqrt();
            let m = match turn {
                0 if dot(t0, t1) > 0.0 => continue,
                0 => match self.join {
                    Join::Round => disk.min(dot(r, t0)),
                    _ => continue,
                },
                _ => {
                    // The outer side is opposite the turn: left normal (-y, x).
                    let s = -(turn as f64) * h;
                    let o0 = (-t0.1 * s, t0.0 * s);
                    let o1 = (-t1.1 * s, t1.0 * s);
                    let (c0, c1) = ((p.0 + o0.0, p.1 + o0.1), (p.0 + o1.0, p.1 + o1.1));
                    let bevel = convex_margin(&[p, c0, c1], q);
                    let cos = dot(t0, t1);
                    let miter = || {
                        let f = 1.0 / (1.0 + cos);
                        let tip = (p.0 + (o0.0 + o1.0) * f, p.1 + (o0.1 + o1.1) * f);
                        convex_margin(&[p, c0, tip, c1], q)
                    };
                    match self.join {
                        Join::Bevel => bevel,
                        Join::Miter if (cos + 7.0 / 8.0).abs() < 1e-3 => {
                            let (a, b) = (bevel, miter());
                            out.push((a.min(b), a.max(b)));
                            continue;
                        }
                        Join::Miter if cos >= -7.0 / 8.0 => miter(),
                        Join::Miter => bevel,
                        Join::Round => {
                            // The cone between o0 and o1 (under 180 degrees).
                            let c = cross(o0, o1).signum();
                            let side0 = c * cross(norm(o0), r);
                            let side1 = -c * cross(norm(o1), r);
                            disk.min(side0).min(side1)
                        }
                    }
                }
            };
            out.push((m, m));
        }
        out
    }
}

/// Checks `d` (a drawing of `reference`): each pixel written at most once,
/// and lit exactly where the reference says, away from its boundary (most
/// pixels are decided: the check cannot pass by skipping).
fn check(d: &SimDisplay<Gray8>, reference: &Reference, what: &dyn std::fmt::Debug) {
    assert_eq!(d.out_of_bounds_writes(), 0, "{what:?}");
    let count = |x: i64, y: i64| {
        let p = Point::new(x.try_into().unwrap(), y.try_into().unwrap());
        d.write_count(p).unwrap()
    };
    let side = i64::from(SIZE);
    let decided = check_counts(count, 0..side, 0..side, reference, what);
    assert!(decided * 2 >= side * side, "{what:?}: {decided} decided");
}

/// The pixels `xs` by `ys` written `count(x, y)` times: each at most once,
/// and lit exactly where the reference says, away from its boundary. The
/// number of pixels decided.
fn check_counts(
    count: impl Fn(i64, i64) -> u32,
    xs: std::ops::Range<i64>,
    ys: std::ops::Range<i64>,
    reference: &Reference,
    what: &dyn std::fmt::Debug,
) -> i64 {
    let mut decided = 0;
    for y in ys {
        for x in xs.clone() {
            let c = count(x, y);
            assert!(c <= 1, "{what:?}: ({x}, {y}) written {c} times");
            let (m, upper) = reference.margin((x as f64 + 0.5, y as f64 + 0.5));
            if m > EPS {
                assert_eq!(c, 1, "{what:?}: ({x}, {y}) inside by {m} but unlit");
                decided += 1;
            } else if upper < -EPS {
                assert_eq!(c, 0, "{what:?}: ({x}, {y}) outside by {upper} but lit");
                decided += 1;
            }
        }
    }
    decided
}

/// A display as a sink on which overdraw is invisible: strokes write
/// their pieces whole into it, overlapping.
struct Overlapping<'a>(&'a mut SimDisplay<Gray8>);

impl SpanSink<Gray8> for Overlapping<'_> {
    type Error = Infallible;

    fn bounds(&self) -> Rectangle {
        self.0.bounding_box()
    }

    fn overdraw_is_invisible(&self) -> bool {
        true
    }

    fn fill_span(&mut self, span: Span, color: Gray8) -> Result<(), Infallible> {
        self.0.fill_span(span, color)
    }
}

/// `shape` drawn on a display `width` px wide as [`Overlapping`]: lights
/// the pixels of `masked`, its drawing written each once.
fn assert_overlapping_lights_the_same(
    shape: &impl SpanDrawable<Color = Gray8>,
    masked: &SimDisplay<Gray8>,
    what: &dyn std::fmt::Debug,
) {
    let size = masked.bounding_box().size;
    let mut d = SimDisplay::new(size.width, size.height, Gray8::BLACK);
    shape.draw_spans(&mut Overlapping(&mut d)).unwrap();
    assert_eq!(d.out_of_bounds_writes(), 0, "{what:?}");
    assert!(
        d.pixels() == masked.pixels(),
        "{what:?}: overlapping pieces light other pixels"
    );
}

fn draw_polyline(points: &[Point], width: u32, join: Join) -> SimDisplay<Gray8> {
    let mut d = SimDisplay::new(SIZE, SIZE, Gray8::BLACK);
    Polyline::new(points)
        .stroke(Gray8::WHITE)
        .stroke_width(width)
        .join(join)
        .draw(&mut d)
        .unwrap();
    d
}

fn assert_polyline(points: &[Point], width: u32, join: Join) {
    let d = draw_polyline(points, width, join);
    let what = (points, width, join);
    check(&d, &Reference::polyline(points, width, join), &what);
    let stroke = Polyline::new(points)
        .stroke(Gray8::WHITE)
        .stroke_width(width)
        .join(join);
    assert_overlapping_lights_the_same(&stroke, &d, &what);
}

fn any_join() -> impl Strategy<Value = Join> {
    prop_oneof![Just(Join::Miter), Just(Join::Bevel), Just(Join::Round)]
}

/// A polyline walked by turns: segment lengths short (0 to 3 px, repeated
/// points included) or long, turns anywhere or within 2 degrees of a full
/// reversal, rounded to pixels.
fn walked() -> impl Strategy<Value = Vec<Point>> {
    (
        (8i32..64, 8i32..64),
        0.0f64..360.0,
        prop::collection::vec(
            (
                prop_oneof![0.0f64..3.0, 3.0f64..40.0],
                prop_oneof![-180.0f64..180.0, 178.0f64..182.0],
            ),
            1..6,
        ),
    )
        .prop_map(|(start, heading, steps)| {
            let mut pts = vec![Point::new(start.0, start.1)];
            let (mut x, mut y, mut h) = (start.0 as f64, start.1 as f64, heading);
            for (len, turn) in steps {
                x += len * h.to_radians().cos();
                y += len * h.to_radians().sin();
                pts.push(Point::new(x.round() as i32, y.round() as i32));
                h += turn;
            }
            pts
        })
}

proptest! {
    #[test]
    fn random_polylines_exact_and_once(
        points in prop::collection::vec((-8i32..80, -8i32..80).prop_map(|(x, y)| Point::new(x, y)), 1..7),
        width in 2u32..=40,
        join in any_join(),
        closed in any::<bool>(),
    ) {
        let mut points = points;
        if closed {
            points.push(points[0]);
        }
        assert_polyline(&points, width, join);
    }

    #[test]
    fn walked_polylines_with_near_reversals(
        points in walked(),
        width in 2u32..=40,
        join in any_join(),
        closed in any::<bool>(),
    ) {
        let mut points = points;
        if closed {
            points.push(points[0]);
        }
        assert_polyline(&points, width, join);
    }

    /// Many short segments in a small area, crossing themselves.
    #[test]
    fn crowded_polylines(
        points in prop::collection::vec((20i32..52, 20i32..52).prop_map(|(x, y)| Point::new(x, y)), 20..80),
        width in 2u32..=12,
        join in any_join(),
    ) {
        assert_polyline(&points, width, join);
    }

    /// Triangle outlines at subpixel vertices, every width from 1.
    #[test]
    fn stroked_triangles(
        raw in prop::array::uniform6(0i32..72 * 4096),
        width in 1u32..=16,
        join in any_join(),
    ) {
        let v = [0, 2, 4].map(|k| Vertex::from_raw(raw[k], raw[k + 1]));
        let mut d = SimDisplay::new(SIZE, SIZE, Gray8::BLACK);
        let stroke = Triangle::new(v[0], v[1], v[2]).stroke(Gray8::WHITE).stroke_width(width).join(join);
        stroke.draw(&mut d).unwrap();
        check(&d, &Reference::ring(&v, width, join), &(v, width, join));
        assert_overlapping_lights_the_same(&stroke, &d, &(v, width, join));
    }

    /// Polygon outlines, self-crossing ones too, every pixel once.
    #[test]
    fn stroked_polygons(
        raw in prop::collection::vec((0i32..72 * 4096, 0i32..72 * 4096), 3..9),
        width in 1u32..=24,
        join in any_join(),
    ) {
        let v: Vec<Vertex> = raw.iter().map(|&(x, y)| Vertex::from_raw(x, y)).collect();
        let mut d = SimDisplay::new(SIZE, SIZE, Gray8::BLACK);
        let polygon = Polygon::<8>::new(&v).unwrap();
        let stroke = polygon.stroke(Gray8::WHITE).stroke_width(width).join(join);
        stroke.draw(&mut d).unwrap();
        check(&d, &Reference::ring(&v, width, join), &(&v, width, join));
        assert_overlapping_lights_the_same(&stroke, &d, &(&v, width, join));
    }

    /// Segments from far outside (up to the ends of `i32`) through the
    /// display, with joins inside it: the 128-bit paths, exact.
    #[test]
    fn far_points_through_the_display(
        inner in prop::collection::vec((8i32..64, 8i32..64), 2..4),
        far in prop::array::uniform2((-1i64 << 31..1i64 << 31, -1i64 << 31..1i64 << 31)),
        width in 2u32..=24,
        join in any_join(),
    ) {
        let mut points: Vec<Point> = inner.iter().map(|&(x, y)| Point::new(x, y)).collect();
        let c = |v: i64| v.clamp(i32::MIN.into(), i32::MAX.into()) as i32;
        points.insert(0, Point::new(c(far[0].0), c(far[0].1)));
        points.push(Point::new(c(far[1].0), c(far[1].1)));
        assert_polyline(&points, width, join);
    }

    /// A two-point thick polyline is the thick line, pixel for pixel.
    #[test]
    fn two_points_are_the_thick_line(
        c in prop::array::uniform4(-10i32..82),
        width in 2u32..=30,
        join in any_join(),
    ) {
        let points = [Point::new(c[0], c[1]), Point::new(c[2], c[3])];
        let d = draw_polyline(&points, width, join);
        let mut l = SimDisplay::new(SIZE, SIZE, Gray8::BLACK);
        Line::new(points[0], points[1]).stroke(Gray8::WHITE).stroke_width(width).draw(&mut l).unwrap();
        prop_assert_eq!(d.pixels(), l.pixels());
        let stroke = Polyline::new(&points).stroke(Gray8::WHITE).stroke_width(width).join(join);
        assert_overlapping_lights_the_same(&stroke, &d, &(points, width, join));
    }
}

proptest! {
    /// The stroke is drawn in tiles of at most 8,192 px across, as many
    /// rows a tile as a 1 KiB mask holds. On a display 8,300 px wide, a
    /// polyline from x = -100 has tiles 8,192 px wide and one row tall
    /// from x = 0, then 108 px wide and 75 rows tall: the same polyline,
    /// moved by whole pixels so that its turns straddle x = 8,192,
    /// lights the same pixels there, each once, as on the small display
    /// (one tile).
    #[test]
    fn tiles_change_nothing(
        points in prop::collection::vec((-8i32..80, -8i32..80).prop_map(|(x, y)| Point::new(x, y)), 1..6),
        far_y in -20i32..100,
        width in 2u32..=30,
        join in any_join(),
    ) {
        let shift = Point::new(8192 - 36, 0);
        let far = Point::new(-100, far_y);
        let small: Vec<Point> = Some(far - shift).into_iter().chain(points.iter().copied()).collect();
        let moved: Vec<Point> = small.iter().map(|&p| p + shift).collect();
        let small = draw_polyline(&small, width, join);
        let mut wide = SimDisplay::new(8300, SIZE, Gray8::BLACK);
        let stroke = Polyline::new(&moved).stroke(Gray8::WHITE).stroke_width(width).join(join);
        stroke.draw(&mut wide).unwrap();
        // Overlapping, the whole display is one tile.
        assert_overlapping_lights_the_same(&stroke, &wide, &(&moved, width, join));
        for y in 0..SIZE as i32 {
            for x in 0..SIZE as i32 {
                let p = Point::new(x, y);
                prop_assert_eq!(wide.write_count(p + shift), small.write_count(p), "{:?}", p);
            }
        }
        for y in 0..SIZE as i32 {
            for x in 0..8300 {
                prop_assert!(wide.write_count(Point::new(x, y)).unwrap() <= 1, "({}, {})", x, y);
            }
        }
    }
}

/// A comb whose middle rows cross over 64 pieces, overlapping at every
/// joint: still exact and once.
#[test]
fn comb_crossing_every_row_64_times() {
    let points: Vec<Point> = (0..90)
        .map(|k| Point::new(-10 + k, if k % 2 == 0 { 10 } else { 60 }))
        .collect();
    for (width, join) in [(2, Join::Miter), (3, Join::Round), (5, Join::Bevel)] {
        assert_polyline(&points, width, join);
    }
}

/// The corner pixels of a right angle 9 px wide, turning at (30, 30): the
/// outer corner of the miter is (34, 26), which the bevel cuts off.
fn right_angle(join: Join) -> SimDisplay<Gray8> {
    let points = [Point::new(10, 30), Point::new(30, 30), Point::new(30, 50)];
    draw_polyline(&points, 9, join)
}

fn lit(d: &SimDisplay<Gray8>, x: i32, y: i32) -> bool {
    d.pixel(Point::new(x, y)) == Some(Gray8::WHITE)
}

#[test]
fn right_angle_miter_fills_the_outer_corner() {
    let d = right_angle(Join::Miter);
    // The whole 9 x 9 corner square, the outermost pixel included.
    for y in 26..=34 {
        for x in 26..=34 {
            assert!(lit(&d, x, y), "({x}, {y})");
        }
    }
    assert!(!lit(&d, 35, 25) && !lit(&d, 35, 30) && !lit(&d, 30, 25));
    assert_eq!(d.counts().iter().max(), Some(&1));
}

#[test]
fn right_angle_bevel_cuts_the_corner() {
    let d = right_angle(Join::Bevel);
    // The bevel runs from (30, 25.5) to (34.5, 30) in pixel-index
    // coordinates: centres with x - y > 4.5 are cut off.
    assert!(!lit(&d, 34, 26) && !lit(&d, 33, 26) && !lit(&d, 34, 27));
    assert!(lit(&d, 30, 26) && lit(&d, 34, 30) && lit(&d, 32, 28));
    assert_eq!(d.counts().iter().max(), Some(&1));
}

#[test]
fn right_angle_round_lies_between() {
    let (m, b, r) = (
        right_angle(Join::Miter),
        right_angle(Join::Bevel),
        right_angle(Join::Round),
    );
    let count = |d: &SimDisplay<Gray8>| d.counts().iter().filter(|&&c| c > 0).count();
    assert!(count(&b) < count(&r) && count(&r) < count(&m));
    for (i, &c) in r.counts().iter().enumerate() {
        assert!(c <= 1);
        // Bevel inside round inside miter.
        assert!(b.counts()[i] <= c && c <= m.counts()[i], "pixel {i}");
    }
    // The corner pixel is out, (33, 27) at distance sqrt(18) < 4.5 is in.
    assert!(!lit(&r, 34, 26) && lit(&r, 33, 27));
}

/// Past the miter limit (a turn of about 173 degrees) the miter is the
/// bevel.
#[test]
fn sharp_turn_past_the_limit_is_bevelled() {
    let points = [Point::new(5, 40), Point::new(60, 40), Point::new(5, 33)];
    let (m, b) = (
        draw_polyline(&points, 7, Join::Miter),
        draw_polyline(&points, 7, Join::Bevel),
    );
    assert_eq!(m.pixels(), b.pixels());
    // A turn of 120 degrees keeps a longer tip than its bevel.
    let points = [Point::new(5, 40), Point::new(40, 40), Point::new(20, 5)];
    let (m, b) = (
        draw_polyline(&points, 7, Join::Miter),
        draw_polyline(&points, 7, Join::Bevel),
    );
    assert_ne!(m.pixels(), b.pixels());
}

/// Without joins (the old drawing), a right angle's corner was a notch and
/// its inner square was written twice.
#[test]
fn closed_square_ring_once_no_notches() {
    let points = [
        Point::new(10, 10),
        Point::new(50, 10),
        Point::new(50, 50),
        Point::new(10, 50),
        Point::new(10, 10),
    ];
    for join in [Join::Miter, Join::Bevel, Join::Round] {
        let d = draw_polyline(&points, 6, join);
        assert_eq!(d.counts().iter().max(), Some(&1));
        // Miter: all four corners square, the closing one too.
        if join == Join::Miter {
            for (x, y) in [(7, 7), (52, 7), (52, 52), (7, 52)] {
                assert!(lit(&d, x, y), "{join:?} ({x}, {y})");
            }
            let total = d.counts().iter().filter(|&&c| c > 0).count();
            assert_eq!(total, 46 * 46 - 34 * 34);
        }
        assert_polyline(&points, 6, join);
    }
}

/// Full reversals, repeated points, single points, huge coordinates and
/// widths: no panic, nothing outside, each pixel once.
#[test]
fn degenerate_and_extreme_inputs() {
    let cases: Vec<(Vec<Point>, u32)> = vec![
        (
            vec![Point::new(10, 10), Point::new(40, 10), Point::new(10, 10)],
            9,
        ),
        (vec![Point::new(20, 20); 4], 5),
        (vec![Point::new(20, 20)], 6),
        (vec![], 6),
        (
            vec![
                Point::new(5, 5),
                Point::new(5, 5),
                Point::new(30, 30),
                Point::new(30, 30),
                Point::new(60, 5),
            ],
            7,
        ),
        (
            vec![
                Point::new(i32::MIN, i32::MIN),
                Point::new(i32::MAX, i32::MAX),
                Point::new(i32::MIN, 30),
            ],
            40,
        ),
        (
            vec![
                Point::new(i32::MIN, 36),
                Point::new(36, 36),
                Point::new(i32::MAX, 37),
                Point::new(i32::MIN, 36),
            ],
            u32::MAX,
        ),
        (
            vec![
                Point::new(30, 30),
                Point::new(31, 30),
                Point::new(30, 30),
                Point::new(31, 30),
            ],
            40,
        ),
    ];
    for (points, width) in cases {
        for join in [Join::Miter, Join::Bevel, Join::Round] {
            let d = draw_polyline(&points, width, join);
            assert_eq!(d.out_of_bounds_writes(), 0);
            assert!(
                d.counts().iter().all(|&c| c <= 1),
                "{points:?} {width} {join:?}"
            );
            if width <= 40
                && points
                    .iter()
                    .all(|p| p.x.unsigned_abs() < 1000 && p.y.unsigned_abs() < 1000)
            {
                assert_polyline(&points, width, join);
            }
        }
    }
}

/// A full reversal with a round join ends in a half disk; the miter and
/// bevel end flat at the turning point (the closed ring has no caps: its
/// rectangle ends on the centre of (40, 30), a right edge).
#[test]
fn reversal_round_cap() {
    let points = [Point::new(10, 30), Point::new(40, 30), Point::new(10, 30)];
    let r = draw_polyline(&points, 11, Join::Round);
    let b = draw_polyline(&points, 11, Join::Bevel);
    assert!(lit(&r, 44, 30) && !lit(&r, 46, 30) && !lit(&r, 44, 25));
    assert!(lit(&b, 39, 30) && !lit(&b, 40, 30));
}

/// A target whose box reaches past column `i32::MAX`, recording every
/// pixel written (as `i64` columns) and how often.
struct FarTarget {
    bounds: embedded_graphics_core::primitives::Rectangle,
    writes: std::collections::HashMap<(i64, i64), u32>,
}

impl Dimensions for FarTarget {
    fn bounding_box(&self) -> embedded_graphics_core::primitives::Rectangle {
        self.bounds
    }
}

impl DrawTarget for FarTarget {
    type Color = Gray8;
    type Error = core::convert::Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<Gray8>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Self::Error> {
        for Pixel(p, _) in pixels {
            *self.writes.entry((p.x.into(), p.y.into())).or_default() += 1;
        }
        Ok(())
    }

    fn fill_solid(
        &mut self,
        area: &embedded_graphics_core::primitives::Rectangle,
        _: Gray8,
    ) -> Result<(), Self::Error> {
        let (x, y) = (i64::from(area.top_left.x), i64::from(area.top_left.y));
        for row in y..y + i64::from(area.size.height) {
            for column in x..x + i64::from(area.size.width) {
                *self.writes.entry((column, row)).or_default() += 1;
            }
        }
        Ok(())
    }
}

/// [`FarTarget`]'s box as a sink on which overdraw is invisible,
/// recording the pixels lit (as `i64` columns).
struct FarOverlapping {
    bounds: Rectangle,
    lit: std::collections::HashSet<(i64, i64)>,
}

impl SpanSink<Gray8> for FarOverlapping {
    type Error = Infallible;

    fn bounds(&self) -> Rectangle {
        self.bounds
    }

    fn overdraw_is_invisible(&self) -> bool {
        true
    }

    fn fill_span(&mut self, span: Span, _: Gray8) -> Result<(), Infallible> {
        let y = i64::from(span.y);
        self.lit
            .extend((i64::from(span.x_start)..i64::from(span.x_end)).map(|x| (x, y)));
        Ok(())
    }

    /// A run ending at column 2^31 comes as a rectangle: its last pixel
    /// is column `i32::MAX`, past what a `Span` holds.
    fn fill_rect(&mut self, area: &Rectangle, _: Gray8) -> Result<(), Infallible> {
        let (x, y) = (i64::from(area.top_left.x), i64::from(area.top_left.y));
        for row in y..y + i64::from(area.size.height) {
            self.lit
                .extend((x..x + i64::from(area.size.width)).map(|c| (c, row)));
        }
        Ok(())
    }
}

/// At the right end of the coordinate space, on a target whose box
/// reaches past it: every pixel a `Point` can name is lit as the
/// reference says and written once; none past column `i32::MAX` (no
/// `Point` names one) is written. Drawn overlapping, with no mask, the
/// same pixels are lit.
#[test]
fn strokes_at_the_last_column() {
    let m = i32::MAX;
    let points = [
        Point::new(m - 40, 1010),
        Point::new(m - 10, 1040),
        Point::new(m, 1005),
        Point::new(m - 25, 1020),
    ];
    let left = i64::from(m) - 47;
    for join in [Join::Miter, Join::Bevel, Join::Round] {
        let mut target = FarTarget {
            bounds: embedded_graphics_core::primitives::Rectangle::new(
                Point::new(m - 47, 1000),
                Size::new(200, 48),
            ),
            writes: Default::default(),
        };
        let stroke = Polyline::new(&points)
            .stroke(Gray8::WHITE)
            .stroke_width(7)
            .join(join);
        stroke.draw(&mut target).unwrap();
        assert!(
            target.writes.keys().all(|&(x, _)| x <= i64::from(m)),
            "{join:?}"
        );
        let reference = Reference::polyline(&points, 7, join);
        let count = |x: i64, y: i64| target.writes.get(&(x, y)).copied().unwrap_or(0);
        let decided = check_counts(count, left..i64::from(m) + 1, 1000..1048, &reference, &join);
        assert!(decided > 2000, "{join:?}: {decided} decided");
        assert!(
            target.writes.contains_key(&(i64::from(m), 1005)),
            "{join:?}"
        );
        let mut overlapping = FarOverlapping {
            bounds: target.bounds,
            lit: Default::default(),
        };
        stroke.draw_spans(&mut overlapping).unwrap();
        let masked: std::collections::HashSet<_> = target.writes.keys().copied().collect();
        assert!(
            overlapping.lit == masked,
            "{join:?}: overlapping pieces light other pixels"
        );
    }
}
