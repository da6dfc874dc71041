//! A black-box audit of the shapes' public API (everything but the
//! framebuffer, band and `SpanSink`-adapter API) against references
//! written from the crate's documentation only: README ("The sampling
//! rule", "Exactness and ranges", "Lines", "Polygons", "Shading",
//! "Delaunay triangulation", "Choosing a triangle algorithm"), the crate
//! docs and the rustdoc comments. Every reference here is exact integer
//! arithmetic (`i128`, with a small base-2^33 accumulator where 133 bits
//! are needed); none of it reads the crate's sources or `tests/common`.

#[path = "common/rng.rs"]
mod rng;

use core::cmp::Ordering;
use core::convert::Infallible;
use std::collections::{BTreeMap, BTreeSet};

use embedded_graphics::{
    pixelcolor::{BinaryColor, Gray8, Rgb565, Rgb888},
    prelude::*,
    primitives::Rectangle,
    Pixel,
};
use embedded_raster::{
    delaunay::{in_circle, orientation, Delaunay, DelaunayError},
    mesh::{sin_cos, Camera, Rotation, Vec3, ONE},
    prelude::*,
    shade::{average_color, DepthBuffer, ShadeColor, FAR},
    CoordinateOutOfRange, FillRule, Line, LineAlgorithm, ParseCoordinateError, Polygon,
    PolygonError, Polyline, Run, Span, SpanSink, SubpixelPrecision, Triangle, TriangleAlgorithm,
    Vertex, I20F12,
};
use rng::Rng;

// ---------------------------------------------------------------------------
// A recording target: a small window anywhere in the i32 plane.
// ---------------------------------------------------------------------------

#[derive(Clone)]
struct Window<C> {
    area: Rectangle,
    w: i64,
    h: i64,
    x0: i64,
    y0: i64,
    px: Vec<Option<C>>,
    count: Vec<u32>,
    /// Calls or pixels that reached outside the bounding box.
    outside: u32,
    fill_solid: u32,
    fill_contiguous: u32,
    draw_iter: u32,
    spans: u32,
}

impl<C: PixelColor> Window<C> {
    fn new(x0: i32, y0: i32, w: u32, h: u32) -> Self {
        Window {
            area: Rectangle::new(Point::new(x0, y0), Size::new(w, h)),
            w: w as i64,
            h: h as i64,
            x0: x0 as i64,
            y0: y0 as i64,
            px: vec![None; (w * h) as usize],
            count: vec![0; (w * h) as usize],
            outside: 0,
            fill_solid: 0,
            fill_contiguous: 0,
            draw_iter: 0,
            spans: 0,
        }
    }
    fn idx(&self, x: i64, y: i64) -> Option<usize> {
        let (dx, dy) = (x - self.x0, y - self.y0);
        (dx >= 0 && dy >= 0 && dx < self.w && dy < self.h).then(|| (dy * self.w + dx) as usize)
    }
    fn put(&mut self, x: i64, y: i64, c: C) {
        match self.idx(x, y) {
            Some(i) => {
                self.px[i] = Some(c);
                self.count[i] += 1;
            }
            None => self.outside += 1,
        }
    }
    fn get(&self, x: i64, y: i64) -> Option<C> {
        self.idx(x, y).and_then(|i| self.px[i])
    }
    fn cnt(&self, x: i64, y: i64) -> u32 {
        self.idx(x, y).map_or(0, |i| self.count[i])
    }
    fn pixels(&self) -> impl Iterator<Item = (i64, i64)> + '_ {
        let (x0, y0, w, h) = (self.x0, self.y0, self.w, self.h);
        (0..h).flat_map(move |j| (0..w).map(move |i| (x0 + i, y0 + j)))
    }
    fn rect_points(&self, area: &Rectangle) -> Vec<(i64, i64)> {
        let mut v = Vec::new();
        for j in 0..area.size.height as i64 {
            for i in 0..area.size.width as i64 {
                v.push((area.top_left.x as i64 + i, area.top_left.y as i64 + j));
            }
        }
        v
    }
}

impl<C: PixelColor> Dimensions for Window<C> {
    fn bounding_box(&self) -> Rectangle {
        self.area
    }
}

impl<C: PixelColor> DrawTarget for Window<C> {
    type Color = C;
    type Error = Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<C>>>(&mut self, pixels: I) -> Result<(), Infallible> {
        self.draw_iter += 1;
        for Pixel(p, c) in pixels {
            self.put(p.x as i64, p.y as i64, c);
        }
        Ok(())
    }
    fn fill_solid(&mut self, area: &Rectangle, color: C) -> Result<(), Infallible> {
        self.fill_solid += 1;
        for (x, y) in self.rect_points(area) {
            self.put(x, y, color);
        }
        Ok(())
    }
    fn fill_contiguous<I: IntoIterator<Item = C>>(
        &mut self,
        area: &Rectangle,
        colors: I,
    ) -> Result<(), Infallible> {
        self.fill_contiguous += 1;
        let pts = self.rect_points(area);
        let mut it = colors.into_iter();
        for (x, y) in pts {
            let c = it
                .next()
                .expect("fill_contiguous: colours ran out before the area");
            self.put(x, y, c);
        }
        Ok(())
    }
}

impl<C: PixelColor> SpanSink<C> for Window<C> {
    type Error = Infallible;
    fn bounds(&self) -> Rectangle {
        self.area
    }
    fn fill_span(&mut self, span: Span, color: C) -> Result<(), Infallible> {
        self.spans += 1;
        for x in span.x_start as i64..span.x_end as i64 {
            self.put(x, span.y as i64, color);
        }
        Ok(())
    }
}

// ---------------------------------------------------------------------------
// References from the docs.
// ---------------------------------------------------------------------------

type P = (i128, i128);

fn raw(v: Vertex) -> P {
    let (x, y) = v.raw();
    (x as i128, y as i128)
}

fn cross(o: P, a: P, b: P) -> i128 {
    (a.0 - o.0) * (b.1 - o.1) - (a.1 - o.1) * (b.0 - o.0)
}

/// Sign of `cross(b - a, q - a)` at `q` = the centre of pixel (i, j) nudged by (e, e^2).
fn nudged_side(a: P, b: P, i: i64, j: i64) -> i128 {
    let q = (4096 * i as i128 + 2048, 4096 * j as i128 + 2048);
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let e0 = dx * (q.1 - a.1) - dy * (q.0 - a.0);
    if e0 != 0 {
        e0.signum()
    } else if dy != 0 {
        (-dy).signum()
    } else {
        dx.signum()
    }
}

/// The winding number of the closed polygon around the nudged centre of pixel (i, j).
fn winding(v: &[P], i: i64, j: i64) -> i32 {
    let cy = 4096 * j as i128 + 2048;
    let mut w = 0;
    for k in 0..v.len() {
        let (a, b) = (v[k], v[(k + 1) % v.len()]);
        let (a_below, b_below) = (a.1 <= cy, b.1 <= cy);
        if a_below && !b_below {
            if nudged_side(a, b, i, j) > 0 {
                w += 1;
            }
        } else if !a_below && b_below && nudged_side(a, b, i, j) < 0 {
            w -= 1;
        }
    }
    w
}

fn fills(rule: FillRule, w: i32) -> bool {
    match rule {
        FillRule::NonZero => w != 0,
        _ => w % 2 != 0,
    }
}

fn tri_lit(t: &Triangle, i: i64, j: i64) -> bool {
    let v = t.vertices.map(raw);
    winding(&v, i, j) != 0
}

fn poly_lit(v: &[Vertex], rule: FillRule, i: i64, j: i64) -> bool {
    let v: Vec<P> = v.iter().map(|&p| raw(p)).collect();
    fills(rule, winding(&v, i, j))
}

fn pixel_of_raw(r: i128) -> i64 {
    r.div_euclid(4096) as i64
}

/// A window of `w` x `h` pixels around the pixel holding raw point `p`, jittered, kept in i32.
fn window_at<C: PixelColor>(rng: &mut Rng, p: P, w: u32, h: u32) -> Window<C> {
    let cx = pixel_of_raw(p.0) - rng.below(w as u64);
    let cy = pixel_of_raw(p.1) - rng.below(h as u64);
    let cx = cx.clamp(i32::MIN as i64, i32::MAX as i64 - w as i64 + 1);
    let cy = cy.clamp(i32::MIN as i64, i32::MAX as i64 - h as i64 + 1);
    Window::new(cx as i32, cy as i32, w, h)
}

fn rand_raw(rng: &mut Rng, centre: i64, scale_bits: u32) -> i32 {
    let span = 1i64 << scale_bits;
    let v = centre + rng.below(2 * span as u64 + 1) - span;
    v.clamp(i32::MIN as i64, i32::MAX as i64) as i32
}

fn rand_triangle(rng: &mut Rng) -> Triangle {
    let bits = 1 + rng.below(32) as u32; // 2^-11 px .. 2^20 px
    let cx = rng.next() as i32 as i64;
    let cy = rng.next() as i32 as i64;
    let grid = match rng.below(4) {
        0 => 2048,
        1 => 4096,
        _ => 1,
    };
    let mut v = || {
        let x = rand_raw(rng, cx, bits) as i64 / grid * grid;
        let y = rand_raw(rng, cy, bits) as i64 / grid * grid;
        Vertex::from_raw(x as i32, y as i32)
    };
    Triangle::new(v(), v(), v())
}

/// Spans from `for_each_span`-like callbacks, checked for shape: non-empty,
/// inside `clip`, at most one per row, rows growing.
fn check_spans(spans: &[Span], clip: &Rectangle, what: &str) -> BTreeSet<(i64, i64)> {
    let mut set = BTreeSet::new();
    let mut last_row: Option<i32> = None;
    for s in spans {
        assert!(s.x_start < s.x_end, "{what}: empty span {s:?}");
        if let Some(r) = last_row {
            assert!(s.y > r, "{what}: rows not growing ({r} then {})", s.y);
        }
        last_row = Some(s.y);
        let (x0, y0) = (clip.top_left.x as i64, clip.top_left.y as i64);
        let (x1, y1) = (x0 + clip.size.width as i64, y0 + clip.size.height as i64);
        assert!(
            (s.y as i64) >= y0
                && (s.y as i64) < y1
                && s.x_start as i64 >= x0
                && s.x_end as i64 <= x1,
            "{what}: span {s:?} outside clip {clip:?}"
        );
        for x in s.x_start..s.x_end {
            set.insert((x as i64, s.y as i64));
        }
    }
    set
}

// ---------------------------------------------------------------------------
// Vertex.
// ---------------------------------------------------------------------------

const RAW_MIN: i128 = i32::MIN as i128;
const RAW_MAX: i128 = i32::MAX as i128;

/// round(n / d) ties to even, d > 0.
fn round_half_even(n: i128, d: i128) -> i128 {
    let q = n.div_euclid(d);
    let r = n.rem_euclid(d);
    match (2 * r).cmp(&d) {
        Ordering::Less => q,
        Ordering::Greater => q + 1,
        Ordering::Equal => {
            if q % 2 == 0 {
                q
            } else {
                q + 1
            }
        }
    }
}

#[test]
fn vertex_from_numbers_rounds_to_nearest_ties_to_even() {
    let mut rng = Rng(0x5eed_0001);
    let check_f64 = |x: f64| {
        let got = Vertex::try_from_num(x, 0.5f64);
        // x * 4096 is exact in f64 (a power of two) for every finite x in reach.
        let want = if x.is_finite() {
            let s = x * 4096.0;
            let r = s.round_ties_even();
            if r >= RAW_MIN as f64 && r <= RAW_MAX as f64 {
                Ok(r as i32)
            } else {
                Err(CoordinateOutOfRange)
            }
        } else {
            Err(CoordinateOutOfRange)
        };
        match want {
            Ok(r) => assert_eq!(got.map(|v| v.raw()), Ok((r, 2048)), "try_from_num({x:?})"),
            Err(e) => assert_eq!(got, Err(e), "try_from_num({x:?})"),
        }
        // the same through f32 where it is exact, and the y coordinate
        let got_y = Vertex::try_from_num(0, x);
        assert_eq!(got_y.map(|v| v.raw().1), got.map(|v| v.raw().0), "y: {x:?}");
    };
    for _ in 0..20000 {
        let x = match rng.below(4) {
            0 => (rng.unit() - 0.5) * 2.1e6,
            1 => (rng.below(1 << 33) as f64 - (1u64 << 32) as f64) / 8192.0, // ties and half-steps
            2 => f64::from_bits(rng.next()),
            _ => {
                ((rng.below(1 << 20) as f64) - (1 << 19) as f64)
                    + (rng.below(3) as f64 - 1.0) / 8192.0
            }
        };
        check_f64(x);
    }
    for x in [
        0.0,
        -0.0,
        1.0 / 8192.0,
        3.0 / 8192.0,
        -1.0 / 8192.0,
        -3.0 / 8192.0,
        524_287.999_755_859_4,
        524_287.999_877_929_7, // tie above the top: to even = 2^31, out
        524_287.999_877_929_7, // just below the tie
        -524288.0,
        -524_288.000_122_070_3, // tie below the bottom: to even = -2^31, in
        -524_288.000_244_140_6,
        524288.0,
        f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::MAX,
        f64::MIN_POSITIVE,
    ] {
        check_f64(x);
    }
    // Integers.
    for _ in 0..2000 {
        let i = (rng.next() as i64) >> rng.below(64);
        let got = Vertex::try_from_num(i, 0);
        if (-524288..=524287).contains(&i) {
            assert_eq!(got.map(|v| v.raw().0), Ok(i as i32 * 4096), "{i}");
        } else {
            assert_eq!(got, Err(CoordinateOutOfRange), "{i}");
        }
    }
    // f32: exact scaling too.
    for _ in 0..5000 {
        let x = f32::from_bits(rng.next() as u32);
        let got = Vertex::try_from_num(x, 0);
        let want = if x.is_finite() {
            let r = (x as f64 * 4096.0).round_ties_even();
            (r >= RAW_MIN as f64 && r <= RAW_MAX as f64).then_some(r as i32)
        } else {
            None
        };
        assert_eq!(got.ok().map(|v| v.raw().0), want, "f32 {x:?}");
    }
}

#[test]
fn vertex_raw_new_and_points() {
    let mut rng = Rng(7);
    for _ in 0..2000 {
        let (x, y) = (rng.next() as i32, rng.next() as i32);
        let v = Vertex::from_raw(x, y);
        assert_eq!(v.raw(), (x, y));
        assert_eq!(Vertex::new(I20F12::from_bits(x), I20F12::from_bits(y)), v);
        let p = Point::new(x >> rng.below(32), y >> rng.below(32));
        let got = Vertex::try_from(p);
        let ok = |c: i32| (-524288..=524287).contains(&c);
        if ok(p.x) && ok(p.y) {
            assert_eq!(
                got.map(|v| v.raw()),
                Ok((p.x * 4096 + 2048, p.y * 4096 + 2048)),
                "{p:?}"
            );
            let t = Triangle::from_points(p, p, p).unwrap();
            assert_eq!(t.vertices[2], got.unwrap());
        } else {
            assert_eq!(got, Err(CoordinateOutOfRange), "{p:?}");
            assert_eq!(
                Triangle::from_points(Point::zero(), p, Point::zero()),
                Err(CoordinateOutOfRange)
            );
        }
    }
    for c in [-524288, 524287, -524289, 524288, i32::MIN, i32::MAX] {
        let ok = (-524288..=524287).contains(&c);
        assert_eq!(Vertex::try_from(Point::new(0, c)).is_ok(), ok, "{c}");
    }
}

/// Decimal text -> raw, exactly: n / 10^k rounded to 1/4096, ties to even.
fn parse_ref(s: &str) -> Result<i32, ParseCoordinateError> {
    let (neg, body) = match s.strip_prefix('-') {
        Some(b) => (true, b),
        None => (false, s),
    };
    let (int, frac) = body.split_once('.').unwrap_or((body, ""));
    let digits: String = format!("{int}{frac}");
    let n: i128 = digits.parse().unwrap();
    let d = 10i128.pow(frac.len() as u32);
    let r = round_half_even(n * 4096, d);
    let r = if neg { -r } else { r };
    if (RAW_MIN..=RAW_MAX).contains(&r) {
        Ok(r as i32)
    } else {
        Err(ParseCoordinateError::OutOfRange)
    }
}

#[test]
fn vertex_parse_is_exact() {
    let mut rng = Rng(0xdec);
    let mut cases: Vec<String> = vec![
        "0".into(),
        "-0".into(),
        "30.5".into(),
        "100.000244140625".into(),
        "524287.999755859375".into(),
        "524287.9998779296875".into(),
        "524287.9998779296874999999".into(),
        "-524288".into(),
        "-524288.0001220703125".into(),
        "-524288.0001220703125000001".into(),
        "-524288.00012207031249999".into(),
        "524288".into(),
        "0.0001220703125".into(),
        "0.0003662109375".into(),
        "0.00036621093750000000000001".into(),
        "0.00036621093749999999999999".into(),
        "-0.0001220703125".into(),
        "000012.50".into(),
    ];
    for _ in 0..4000 {
        let int = rng.below(600_000);
        let k = rng.below(26) as usize;
        let frac: String = match rng.below(3) {
            // a tie (odd multiple of 1/8192: 13 decimals), maybe perturbed in the last place
            0 => {
                let m = 2 * rng.below(4096) + 1;
                let t = m as i128 * 10i128.pow(13) / 8192;
                let mut s = format!("{t:013}");
                match rng.below(3) {
                    0 => s.push_str(&"0".repeat(rng.below(10) as usize)),
                    1 => {
                        s.push_str(&"0".repeat(rng.below(10) as usize));
                        s.push('1')
                    }
                    _ => {
                        // one unit below the tie in the 30th place
                        let t2 = t - 1;
                        s = format!("{t2:013}{}", "9".repeat(10));
                    }
                }
                s
            }
            _ => (0..k)
                .map(|_| char::from(b'0' + rng.below(10) as u8))
                .collect(),
        };
        let neg = rng.below(2) == 0;
        let s = if frac.is_empty() {
            format!("{}{int}", if neg { "-" } else { "" })
        } else {
            format!("{}{int}.{frac}", if neg { "-" } else { "" })
        };
        cases.push(s);
    }
    for s in &cases {
        let want = parse_ref(s);
        let got = Vertex::parse(s, "1.5").map(|v| v.raw());
        assert_eq!(got, want.map(|r| (r, 6144)), "parse({s:?})");
        let got_y = Vertex::parse("0", s).map(|v| v.raw().1);
        assert_eq!(got_y, want, "parse y ({s:?})");
    }
    for bad in [
        "", "nan", "NaN", "inf", "-inf", "infinity", "1e3", "1E3", "0x10", "1.2.3", "abc", "-",
        " 1", "1 ", "--1", "1-",
    ] {
        assert_eq!(
            Vertex::parse(bad, "0"),
            Err(ParseCoordinateError::Invalid),
            "parse({bad:?})"
        );
        assert_eq!(
            Vertex::parse("0", bad),
            Err(ParseCoordinateError::Invalid),
            "parse y ({bad:?})"
        );
    }
    // a very long number: no overflow
    let long = format!("{}.{}", "9".repeat(40), "1".repeat(200));
    assert_eq!(
        Vertex::parse(&long, "0"),
        Err(ParseCoordinateError::OutOfRange)
    );
    let long_small = format!("0.{}", "0".repeat(300));
    assert_eq!(Vertex::parse(&long_small, "0").map(|v| v.raw()), Ok((0, 0)));
}

// ---------------------------------------------------------------------------
// Triangles: the sampling rule.
// ---------------------------------------------------------------------------

fn check_triangle_in_window(t: &Triangle, win: &Window<BinaryColor>, what: &str) {
    // draw (DrawTarget), draw_spans (SpanSink), for_each_span
    let mut a = win.clone();
    t.fill(BinaryColor::On).draw(&mut a).unwrap();
    let mut b = win.clone();
    t.fill(BinaryColor::On).draw_spans(&mut b).unwrap();
    let mut spans = Vec::new();
    t.for_each_span(&win.area, |s| {
        spans.push(s);
        Ok::<(), Infallible>(())
    })
    .unwrap();
    let set = check_spans(&spans, &win.area, what);
    assert_eq!(a.outside + b.outside, 0, "{what}: write outside the target");
    for (x, y) in win.pixels() {
        let want = tri_lit(t, x, y);
        assert_eq!(
            a.cnt(x, y),
            want as u32,
            "{what}: draw at ({x}, {y}) of {t:?}"
        );
        assert_eq!(
            b.cnt(x, y),
            want as u32,
            "{what}: draw_spans at ({x}, {y}) of {t:?}"
        );
        assert_eq!(
            set.contains(&(x, y)),
            want,
            "{what}: for_each_span at ({x}, {y}) of {t:?}"
        );
    }
    assert!(
        a.draw_iter == 0 && a.fill_contiguous == 0,
        "{what}: draw used other calls than fill_solid"
    );
    assert_eq!(
        a.fill_solid as usize,
        spans.len(),
        "{what}: one fill_solid per span"
    );
}

#[test]
fn triangles_follow_the_sampling_rule() {
    let mut rng = Rng(0x7a1);
    for case in 0..3000 {
        let t = rand_triangle(&mut rng);
        let v = t.vertices.map(raw);
        // window near a vertex, an edge midpoint, the centroid, or anywhere in the box
        let p = match rng.below(4) {
            0 => v[rng.below(3) as usize],
            1 => {
                let k = rng.below(3) as usize;
                (
                    (v[k].0 + v[(k + 1) % 3].0) / 2,
                    (v[k].1 + v[(k + 1) % 3].1) / 2,
                )
            }
            2 => (
                (v[0].0 + v[1].0 + v[2].0) / 3,
                (v[0].1 + v[1].1 + v[2].1) / 3,
            ),
            _ => {
                let (x0, x1) = (
                    v.iter().map(|p| p.0).min().unwrap(),
                    v.iter().map(|p| p.0).max().unwrap(),
                );
                let (y0, y1) = (
                    v.iter().map(|p| p.1).min().unwrap(),
                    v.iter().map(|p| p.1).max().unwrap(),
                );
                (
                    x0 + (rng.unit() * (x1 - x0) as f64) as i128,
                    y0 + (rng.unit() * (y1 - y0) as f64) as i128,
                )
            }
        };
        let win = window_rand(&mut rng, p, 24);
        check_triangle_in_window(&t, &win, &format!("case {case}"));
        // both windings, and every vertex order, light the same pixels
        let [a, b, c] = t.vertices;
        check_triangle_in_window(
            &Triangle::new(c, b, a),
            &win,
            &format!("case {case} reversed"),
        );
    }
}

#[test]
fn triangles_at_the_ends_of_the_range_and_tiny_ones() {
    let mut rng = Rng(0xe4d);
    let ends = [
        i32::MIN,
        i32::MIN + 1,
        i32::MIN + 2047,
        i32::MIN + 2048,
        i32::MAX,
        i32::MAX - 2048,
        i32::MAX - 4095,
        0,
        2048,
    ];
    for case in 0..1500 {
        let mut v = || {
            let pick = |rng: &mut Rng| {
                if rng.below(2) == 0 {
                    ends[rng.below(ends.len() as u64) as usize]
                } else {
                    rng.next() as i32
                }
            };
            Vertex::from_raw(pick(&mut rng), pick(&mut rng))
        };
        let t = Triangle::new(v(), v(), v());
        let k = rng.below(3) as usize;
        let win = window_at(&mut rng, raw(t.vertices[k]), 16, 16);
        check_triangle_in_window(&t, &win, &format!("ends {case}"));
    }
    // Tiny triangles (a few raw units) around pixel centres: most light nothing or one pixel.
    for case in 0..3000 {
        let c = (rng.below(8) as i32 * 2048, rng.below(8) as i32 * 2048);
        let mut v =
            || Vertex::from_raw(c.0 + rng.below(9) as i32 - 4, c.1 + rng.below(9) as i32 - 4);
        let t = Triangle::new(v(), v(), v());
        let win = Window::new(-1, -1, 8, 8);
        check_triangle_in_window(&t, &win, &format!("tiny {case}"));
    }
}

#[test]
fn doc_example_right_triangle_and_zero_area() {
    // for_each_span's example generalised: legs of n px on pixel corners
    for n in 1..20 {
        let v = |x: i32, y: i32| Vertex::try_from_num(x, y).unwrap();
        let t = Triangle::new(v(0, 0), v(n, 0), v(0, n));
        let clip = Rectangle::new(Point::zero(), Size::new(32, 32));
        let mut lens = vec![0u32; n as usize];
        t.for_each_span(&clip, |s| {
            lens[s.y as usize] = s.len();
            Ok::<(), Infallible>(())
        })
        .unwrap();
        let want: Vec<u32> = (0..n as u32).map(|j| n as u32 - 1 - j).collect();
        assert_eq!(lens, want, "legs {n}");
        // from_points: the pixels with x + y < n (README's 45 pixels for n = 9)
        let t =
            Triangle::from_points(Point::new(0, 0), Point::new(n, 0), Point::new(0, n)).unwrap();
        let mut count = 0;
        t.for_each_span(&clip, |s| {
            count += s.len();
            Ok::<(), Infallible>(())
        })
        .unwrap();
        assert_eq!(count, (n * (n + 1) / 2) as u32, "from_points legs {n}");
    }
    // zero area: collinear corners, repeated corners, at any scale, never anything
    let mut rng = Rng(0x2e0);
    for _ in 0..3000 {
        let a = (
            rng.next() as i32 as i64 >> rng.below(20),
            rng.next() as i32 as i64 >> rng.below(20),
        );
        let d = (rng.below(2001) - 1000, rng.below(2001) - 1000);
        let pick = |k: i64| {
            let x = (a.0 + k * d.0).clamp(i32::MIN as i64, i32::MAX as i64) as i32;
            let y = (a.1 + k * d.1).clamp(i32::MIN as i64, i32::MAX as i64) as i32;
            Vertex::from_raw(x, y)
        };
        let (k1, k2) = (rng.below(2000) - 1000, rng.below(2000) - 1000);
        let t = Triangle::new(pick(0), pick(k1), pick(k2));
        if orientation(t.vertices[0], t.vertices[1], t.vertices[2]) != Ordering::Equal {
            continue; // clamped off the line
        }
        let clip = Rectangle::new(
            Point::new(i32::MIN, i32::MIN),
            Size::new(u32::MAX, u32::MAX),
        );
        let mut n = 0;
        t.for_each_span(&clip, |_| {
            n += 1;
            Ok::<(), Infallible>(())
        })
        .unwrap();
        assert_eq!(n, 0, "zero-area {t:?}");
        let mut w = window_at::<BinaryColor>(&mut rng, raw(t.vertices[0]), 8, 8);
        t.fill(BinaryColor::On).draw(&mut w).unwrap();
        assert_eq!(w.count.iter().sum::<u32>() + w.outside, 0);
    }
}

#[test]
fn shared_edges_fans_and_errors_stop_early() {
    let mut rng = Rng(0xfa4);
    for case in 0..300 {
        // a fan around a centre, rim on the half-pixel grid (many centres on edges)
        let k = 3 + rng.below(14) as usize;
        let scale = [2.0, 6.0, 20.0, 300.0][rng.below(4) as usize];
        let c = (
            rng.below(9) as f64 * 0.5 + 10.0,
            rng.below(9) as f64 * 0.5 + 10.0,
        );
        let off = rng.unit();
        let rim: Vec<Vertex> = (0..k)
            .map(|i| {
                let a = (i as f64 + off) * core::f64::consts::TAU / k as f64;
                let snap = |v: f64| (v * 2.0).round() / 2.0;
                Vertex::try_from_num(snap(c.0 + scale * a.cos()), snap(c.1 + scale * a.sin()))
                    .unwrap()
            })
            .collect();
        let centre = Vertex::try_from_num(c.0, c.1).unwrap();
        let mut win = Window::<BinaryColor>::new(c.0 as i32 - 12, c.1 as i32 - 12, 24, 24);
        for i in 0..k {
            Triangle::new(centre, rim[i], rim[(i + 1) % k])
                .fill(BinaryColor::On)
                .draw(&mut win)
                .unwrap();
        }
        let poly: Vec<P> = rim.iter().map(|&v| raw(v)).collect();
        // the rim may be non-convex after snapping; the fan is then a star around the centre:
        // the winding of the rim is still the count of triangles covering each point.
        for (x, y) in win.pixels() {
            let w = winding(&poly, x, y).unsigned_abs();
            let lit_any =
                (0..k).any(|i| tri_lit(&Triangle::new(centre, rim[i], rim[(i + 1) % k]), x, y));
            if lit_any || w > 0 {
                // every triangle of the fan has the same orientation unless degenerate
                let covered = (0..k)
                    .filter(|&i| tri_lit(&Triangle::new(centre, rim[i], rim[(i + 1) % k]), x, y))
                    .count() as u32;
                assert_eq!(win.cnt(x, y), covered, "fan {case} at ({x}, {y})");
            } else {
                assert_eq!(win.cnt(x, y), 0, "fan {case} at ({x}, {y})");
            }
        }
        // a convex fan: each pixel inside written exactly once
        let convex = (0..k).all(|i| cross(poly[i], poly[(i + 1) % k], poly[(i + 2) % k]) > 0);
        if convex {
            for (x, y) in win.pixels() {
                assert_eq!(
                    win.cnt(x, y),
                    (winding(&poly, x, y) != 0) as u32,
                    "convex fan {case} ({x}, {y})"
                );
            }
        }
    }
    // two triangles sharing an edge anywhere: the quad's pixels once each
    for case in 0..2000 {
        let t = rand_triangle(&mut rng);
        let [a, b, c] = t.vertices;
        let (pa, pb, pc) = (raw(a), raw(b), raw(c));
        // reflect c over the midpoint of ab: the other side
        let d = (pa.0 + pb.0 - pc.0, pa.1 + pb.1 - pc.1);
        if d.0 < RAW_MIN || d.0 > RAW_MAX || d.1 < RAW_MIN || d.1 > RAW_MAX {
            continue;
        }
        let d = Vertex::from_raw(d.0 as i32, d.1 as i32);
        let mid = ((pa.0 + pb.0) / 2, (pa.1 + pb.1) / 2);
        let mut win = window_at::<BinaryColor>(&mut rng, mid, 12, 12);
        Triangle::new(a, b, c)
            .fill(BinaryColor::On)
            .draw(&mut win)
            .unwrap();
        Triangle::new(b, a, d)
            .fill(BinaryColor::On)
            .draw(&mut win)
            .unwrap();
        let quad = [pa, pc, pb, raw(d)];
        for (x, y) in win.pixels() {
            let want = (winding(&quad, x, y) != 0) as u32;
            let area = cross(pa, pb, pc);
            let want = if area == 0 { 0 } else { want };
            assert_eq!(win.cnt(x, y), want, "shared edge {case} at ({x}, {y})");
        }
    }
    // for_each_span stops at the first error, which it returns
    let t = Triangle::from_points(Point::new(0, 0), Point::new(30, 2), Point::new(5, 29)).unwrap();
    let clip = Rectangle::new(Point::zero(), Size::new(64, 64));
    for stop in 0..28 {
        let mut calls = 0;
        let r = t.for_each_span(&clip, |s| {
            calls += 1;
            if calls > stop {
                Err(s.y)
            } else {
                Ok(())
            }
        });
        assert_eq!(calls, stop + 1);
        assert!(r.is_err());
    }
}

// ---------------------------------------------------------------------------
// Lines.
// ---------------------------------------------------------------------------

/// The reference pixels of the line a-b whose major coordinate lies in `lo..=hi`.
fn line_ref(a: Point, b: Point, lo: i64, hi: i64) -> Vec<(i64, i64)> {
    let (ax, ay, bx, by) = (a.x as i128, a.y as i128, b.x as i128, b.y as i128);
    let x_major = (bx - ax).abs() >= (by - ay).abs();
    // canonical: major grows
    let (ma, na, mb, nb) = if x_major {
        (ax, ay, bx, by)
    } else {
        (ay, ax, by, bx)
    };
    let (ma, na, mb, nb) = if ma <= mb {
        (ma, na, mb, nb)
    } else {
        (mb, nb, ma, na)
    };
    let dm = mb - ma;
    let mut out = Vec::new();
    let from = (lo as i128).max(ma);
    let to = (hi as i128).min(mb);
    let mut m = from;
    while m <= to {
        let minor = if dm == 0 {
            na
        } else {
            // round(na + (m - ma)(nb - na)/dm), ties to the smaller: ceil((2 num - dm) / (2 dm))
            let num = na * dm + (m - ma) * (nb - na);
            let t = 2 * num - dm;
            let d = 2 * dm;
            -((-t).div_euclid(d))
        };
        out.push(if x_major {
            (m as i64, minor as i64)
        } else {
            (minor as i64, m as i64)
        });
        m += 1;
    }
    out
}

fn line_ref_in(a: Point, b: Point, win: &Rectangle) -> Vec<(i64, i64)> {
    let x_major = (b.x as i64 - a.x as i64).abs() >= (b.y as i64 - a.y as i64).abs();
    let (lo, hi) = if x_major {
        (
            win.top_left.x as i64,
            win.top_left.x as i64 + win.size.width as i64 - 1,
        )
    } else {
        (
            win.top_left.y as i64,
            win.top_left.y as i64 + win.size.height as i64 - 1,
        )
    };
    let inside = |&(x, y): &(i64, i64)| {
        x >= win.top_left.x as i64
            && y >= win.top_left.y as i64
            && x < win.top_left.x as i64 + win.size.width as i64
            && y < win.top_left.y as i64 + win.size.height as i64
    };
    line_ref(a, b, lo, hi).into_iter().filter(inside).collect()
}

fn rand_point(rng: &mut Rng) -> Point {
    let sh = rng.below(33) as u32;
    let c = |rng: &mut Rng| {
        let v = (rng.next() as i32 as i64) >> sh.min(31);
        match rng.below(12) {
            0 => i32::MIN,
            1 => i32::MAX,
            _ => v as i32,
        }
    };
    Point::new(c(rng), c(rng))
}

fn rand_line(rng: &mut Rng) -> Line {
    let a = rand_point(rng);
    let b = match rng.below(5) {
        0 => a,
        1 => {
            let d = rng.below(40) as i32 - 20;
            Point::new(
                a.x.saturating_add(d),
                a.y.saturating_add(d * (rng.below(3) as i32 - 1)),
            )
        }
        2 => {
            let (dx, dy) = (rng.below(4000) as i32 - 2000, rng.below(4000) as i32 - 2000);
            Point::new(a.x.saturating_add(dx), a.y.saturating_add(dy))
        }
        _ => rand_point(rng),
    };
    Line::new(a, b)
}

fn window_on_line(rng: &mut Rng, l: &Line, w: u32, h: u32) -> Rectangle {
    let t = rng.unit();
    let p = (
        l.start.x as f64 + t * (l.end.x as f64 - l.start.x as f64),
        l.start.y as f64 + t * (l.end.y as f64 - l.start.y as f64),
    );
    let jitter = |rng: &mut Rng, v: f64, n: u32| {
        let v = v as i64 - rng.below(n as u64 + 4) + 2;
        v.clamp(i32::MIN as i64, i32::MAX as i64 - n as i64 + 1) as i32
    };
    Rectangle::new(
        Point::new(jitter(rng, p.0, w), jitter(rng, p.1, h)),
        Size::new(w, h),
    )
}

#[test]
fn lines_follow_the_documented_rule_and_clip() {
    let mut rng = Rng(0x11e);
    for case in 0..6000 {
        let l = rand_line(&mut rng);
        let (w, h) = (1 + rng.below(20) as u32, 1 + rng.below(20) as u32);
        let area = window_on_line(&mut rng, &l, w, h);
        let want = line_ref_in(l.start, l.end, &area);
        let what = format!("case {case}: {l:?} in {area:?}");
        // the reverse line: the same pixels
        assert_eq!(
            {
                let mut r = line_ref_in(l.end, l.start, &area);
                r.sort();
                r
            },
            {
                let mut r = want.clone();
                r.sort();
                r
            },
            "reference symmetric"
        );
        let mut win = Window::<BinaryColor>::new(area.top_left.x, area.top_left.y, w, h);
        l.stroke(BinaryColor::On).draw(&mut win).unwrap();
        assert_eq!(win.outside, 0, "{what}: outside");
        assert!(
            win.draw_iter == 0 && win.fill_contiguous == 0,
            "{what}: runs go as fill_solid"
        );
        let set: BTreeSet<_> = want.iter().copied().collect();
        for (x, y) in win.pixels() {
            assert_eq!(
                win.cnt(x, y),
                set.contains(&(x, y)) as u32,
                "{what}: draw at ({x}, {y})"
            );
        }
        let mut rev = Window::<BinaryColor>::new(area.top_left.x, area.top_left.y, w, h);
        Line::new(l.end, l.start)
            .stroke(BinaryColor::On)
            .draw_spans(&mut rev)
            .unwrap();
        assert_eq!(rev.outside, 0);
        // (column i32::MAX cannot be a `Span`: see `span_sink_column_at_i32_max`)
        if area.top_left.x as i64 + w as i64 - 1 < i32::MAX as i64 {
            assert_eq!(rev.count, win.count, "{what}: reversed through draw_spans");
        }

        // for_each_run: ordered runs along the major axis covering exactly the pixels
        let x_major =
            (l.end.x as i64 - l.start.x as i64).abs() >= (l.end.y as i64 - l.start.y as i64).abs();
        let mut runs = Vec::new();
        l.for_each_run(&area, |r| {
            runs.push(r);
            Ok::<(), Infallible>(())
        })
        .unwrap();
        let from_runs = runs_pixels(&runs, x_major, &what);
        assert_eq!(from_runs, want, "{what}: for_each_run");
        // pixels(): iteration, len, partial iteration, for_each_run
        match l.pixels(&area) {
            None => assert!(
                want.is_empty(),
                "{what}: pixels() None but {} pixels",
                want.len()
            ),
            Some(mut it) => {
                assert!(!it.is_empty());
                assert_eq!(it.len() as usize, want.len(), "{what}: len");
                let k = rng.below(want.len() as u64 + 2) as usize;
                let mut got = Vec::new();
                for _ in 0..k {
                    if let Some(p) = it.next() {
                        got.push((p.x as i64, p.y as i64));
                    }
                }
                let left = want.len().saturating_sub(k);
                assert_eq!(it.len() as usize, left, "{what}: len after {k}");
                assert_eq!(it.is_empty(), left == 0);
                let mut rest = Vec::new();
                it.for_each_run(|r| {
                    rest.push(r);
                    Ok::<(), Infallible>(())
                })
                .unwrap();
                let rest_px = runs_pixels(&rest, x_major, &what);
                assert_eq!(
                    rest_px.as_slice(),
                    &want[k.min(want.len())..],
                    "{what}: runs after {k}"
                );
                for p in it.by_ref() {
                    got.push((p.x as i64, p.y as i64));
                }
                assert_eq!(got, want, "{what}: iteration");
                assert_eq!(it.next(), None);
                assert_eq!(it.next(), None);
                assert_eq!(it.len(), 0);
                assert!(it.is_empty());
            }
        }
    }
}

fn runs_pixels(runs: &[Run], x_major: bool, what: &str) -> Vec<(i64, i64)> {
    let mut out = Vec::new();
    for r in runs {
        assert!(r.len >= 1, "{what}: empty run");
        let dm = (r.start.x as i64 - r.last().x as i64).abs()
            + (r.start.y as i64 - r.last().y as i64).abs();
        assert_eq!(dm + 1, r.len as i64, "{what}: run {r:?} last()");
        if r.len > 1 {
            assert_eq!(r.vertical, !x_major, "{what}: run direction {r:?}");
        }
        for k in 0..r.len as i64 {
            out.push(if r.vertical {
                (r.start.x as i64, r.start.y as i64 + k)
            } else {
                (r.start.x as i64 + k, r.start.y as i64)
            });
        }
    }
    // ordered by the growing major coordinate
    for w in out.windows(2) {
        let (m0, m1) = if x_major {
            (w[0].0, w[1].0)
        } else {
            (w[0].1, w[1].1)
        };
        assert_eq!(m1, m0 + 1, "{what}: runs not in growing major order");
    }
    out
}

#[test]
fn line_doc_examples_generalised() {
    // LinePixels::len's example and the i32::MIN..i32::MAX line
    let clip = Rectangle::new(Point::zero(), Size::new(8, 8));
    assert_eq!(
        Line::new(Point::new(-5, 1), Point::new(20, 3))
            .pixels(&clip)
            .unwrap()
            .len(),
        8
    );
    let full = Line::new(
        Point::new(i32::MIN, i32::MIN),
        Point::new(i32::MAX, i32::MAX),
    );
    let whole = Rectangle::new(
        Point::new(i32::MIN, i32::MIN),
        Size::new(u32::MAX, u32::MAX),
    );
    let p = full.pixels(&whole).unwrap();
    assert_eq!(p.len(), u32::MAX, "2^32 pixels reported saturated");
    let horiz = Line::new(Point::new(i32::MIN, 0), Point::new(i32::MAX, 0));
    assert_eq!(horiz.pixels(&whole).unwrap().len(), u32::MAX);
    // an empty clip emits nothing
    let empty = Rectangle::new(Point::new(3, 3), Size::new(0, 5));
    assert!(Line::new(Point::new(0, 0), Point::new(9, 9))
        .pixels(&empty)
        .is_none());
    let mut n = 0;
    Line::new(Point::new(0, 0), Point::new(9, 9))
        .for_each_run(&empty, |_| {
            n += 1;
            Ok::<(), Infallible>(())
        })
        .unwrap();
    assert_eq!(n, 0);
    // a clip reaching past i32::MAX (exact pixels at the end)
    let far = Rectangle::new(Point::new(i32::MAX - 3, i32::MAX - 3), Size::new(100, 100));
    let l = Line::new(
        Point::new(i32::MAX - 10, i32::MAX - 10),
        Point::new(i32::MAX, i32::MAX),
    );
    let got: Vec<_> = l.pixels(&far).unwrap().collect();
    assert_eq!(
        got,
        (0..4)
            .map(|k| Point::new(i32::MAX - 3 + k, i32::MAX - 3 + k))
            .collect::<Vec<_>>()
    );
    let l = Line::new(
        Point::new(i32::MIN, i32::MIN + 5),
        Point::new(i32::MIN + 10, i32::MIN),
    );
    let near_min = Rectangle::new(Point::new(i32::MIN, i32::MIN), Size::new(4, 8));
    let got: Vec<(i64, i64)> = l
        .pixels(&near_min)
        .unwrap()
        .map(|p| (p.x as i64, p.y as i64))
        .collect();
    assert_eq!(got, line_ref_in(l.start, l.end, &near_min));
    // for_each_run stops at the first error
    let l = Line::new(Point::new(0, 0), Point::new(30, 11));
    let big = Rectangle::new(Point::zero(), Size::new(64, 64));
    let mut calls = 0;
    let r = l.for_each_run(&big, |_| {
        calls += 1;
        if calls == 3 {
            Err(())
        } else {
            Ok(())
        }
    });
    assert_eq!((r, calls), (Err(()), 3));
}

/// Pixel multiset of a 1-pixel polyline, from the docs.
fn polyline_ref(points: &[Point], area: &Rectangle) -> BTreeMap<(i64, i64), u32> {
    let mut m = BTreeMap::new();
    let inside = |x: i64, y: i64| {
        x >= area.top_left.x as i64
            && y >= area.top_left.y as i64
            && x < area.top_left.x as i64 + area.size.width as i64
            && y < area.top_left.y as i64 + area.size.height as i64
    };
    if points.len() == 1 {
        let p = points[0];
        if inside(p.x as i64, p.y as i64) {
            m.insert((p.x as i64, p.y as i64), 1);
        }
        return m;
    }
    let closed = points.len() >= 3
        && points[0] == points[points.len() - 1]
        && points.iter().any(|&p| p != points[0]);
    let nseg = points.len().saturating_sub(1);
    for s in 0..nseg {
        let (a, b) = (points[s], points[s + 1]);
        let skip_end = s + 1 < nseg || closed;
        let all = line_ref_in(a, b, area);
        for &(x, y) in &all {
            if skip_end && (x, y) == (b.x as i64, b.y as i64) {
                continue;
            }
            if inside(x, y) {
                *m.entry((x, y)).or_insert(0) += 1;
            }
        }
    }
    m
}

#[test]
fn polylines_write_joints_once() {
    let mut rng = Rng(0x9011);
    for case in 0..3000 {
        let n = rng.below(7) as usize;
        let base = Point::new(rng.below(40) as i32 - 20, rng.below(40) as i32 - 20);
        let mut pts: Vec<Point> = (0..n)
            .map(|_| {
                if rng.below(10) == 0 {
                    rand_point(&mut rng)
                } else {
                    Point::new(
                        base.x + rng.below(30) as i32 - 15,
                        base.y + rng.below(30) as i32 - 15,
                    )
                }
            })
            .collect();
        if n >= 3 && rng.below(3) == 0 {
            pts.push(pts[0]); // closed
        }
        if n >= 2 && rng.below(6) == 0 {
            let k = rng.below(n as u64) as usize;
            pts.insert(k, pts[k]); // a repeated point
        }
        let area = Rectangle::new(Point::new(base.x - 14, base.y - 14), Size::new(28, 28));
        let want = polyline_ref(&pts, &area);
        let mut win = Window::<BinaryColor>::new(area.top_left.x, area.top_left.y, 28, 28);
        Polyline::new(&pts)
            .stroke(BinaryColor::On)
            .draw(&mut win)
            .unwrap();
        assert_eq!(win.outside, 0);
        for (x, y) in win.pixels() {
            assert_eq!(
                win.cnt(x, y),
                want.get(&(x, y)).copied().unwrap_or(0),
                "case {case} {pts:?} at ({x}, {y})"
            );
        }
        let mut from_runs = BTreeMap::new();
        Polyline::new(&pts)
            .for_each_run(LineAlgorithm::Bresenham, &area, |r| {
                for k in 0..r.len as i64 {
                    let p = if r.vertical {
                        (r.start.x as i64, r.start.y as i64 + k)
                    } else {
                        (r.start.x as i64 + k, r.start.y as i64)
                    };
                    *from_runs.entry(p).or_insert(0u32) += 1;
                }
                Ok::<(), Infallible>(())
            })
            .unwrap();
        assert_eq!(from_runs, want, "case {case}: for_each_run {pts:?}");
    }
}

#[test]
fn line_variants_one_pixel_per_step_and_within_one() {
    let mut rng = Rng(0xdda);
    for case in 0..3000 {
        let l = rand_line(&mut rng);
        let area = window_on_line(&mut rng, &l, 16, 16);
        let want = line_ref_in(l.start, l.end, &area);
        let x_major =
            (l.end.x as i64 - l.start.x as i64).abs() >= (l.end.y as i64 - l.start.y as i64).abs();
        let ext = (l.end.x as i64 - l.start.x as i64)
            .abs()
            .max((l.end.y as i64 - l.start.y as i64).abs());
        for alg in [
            LineAlgorithm::Bresenham,
            LineAlgorithm::Dda,
            LineAlgorithm::Naive,
        ] {
            let mut runs = Vec::new();
            l.for_each_run_with(alg, &area, |r| {
                runs.push(r);
                Ok::<(), Infallible>(())
            })
            .unwrap();
            let mut px = Vec::new();
            for r in &runs {
                for k in 0..r.len as i64 {
                    px.push(if r.vertical {
                        (r.start.x as i64, r.start.y as i64 + k)
                    } else {
                        (r.start.x as i64 + k, r.start.y as i64)
                    });
                }
            }
            let inside = |&(x, y): &(i64, i64)| {
                x >= area.top_left.x as i64
                    && y >= area.top_left.y as i64
                    && x < area.top_left.x as i64 + 16
                    && y < area.top_left.y as i64 + 16
            };
            assert!(
                px.iter().all(inside),
                "case {case} {alg:?}: pixel outside the clip"
            );
            if alg == LineAlgorithm::Bresenham {
                px.sort_by_key(|&(x, y)| if x_major { x } else { y });
                assert_eq!(px, want, "case {case}: Bresenham variant");
                continue;
            }
            // one pixel per major step; within 1 of the exact minor coordinate (DDA always,
            // naive below 2^23 px of extent)
            let mut seen = BTreeSet::new();
            for &(x, y) in &px {
                let (m, n) = if x_major { (x, y) } else { (y, x) };
                assert!(
                    seen.insert(m),
                    "case {case} {alg:?}: two pixels at major {m}"
                );
                let exact = line_ref(l.start, l.end, m, m);
                assert_eq!(
                    exact.len(),
                    1,
                    "case {case} {alg:?}: pixel past the ends at {m}"
                );
                let en = if x_major { exact[0].1 } else { exact[0].0 };
                if alg == LineAlgorithm::Dda || ext < (1 << 23) {
                    assert!(
                        (n - en).abs() <= 1,
                        "case {case} {alg:?} {l:?}: {n} vs {en} at {m}"
                    );
                }
            }
        }
    }
}

// ---------------------------------------------------------------------------
// Polygons.
// ---------------------------------------------------------------------------

fn rand_polygon(rng: &mut Rng) -> Vec<Vertex> {
    let n = 3 + rng.below(10) as usize;
    let bits = 3 + rng.below(30) as u32;
    let (cx, cy) = (rng.next() as i32 as i64, rng.next() as i32 as i64);
    let grid = [1i64, 2048, 4096, 64][rng.below(4) as usize];
    (0..n)
        .map(|_| {
            let x = rand_raw(rng, cx, bits) as i64 / grid * grid;
            let y = rand_raw(rng, cy, bits) as i64 / grid * grid;
            Vertex::from_raw(x as i32, y as i32)
        })
        .collect()
}

#[test]
fn polygons_fill_under_both_rules() {
    let mut rng = Rng(0x9019);
    for case in 0..2500 {
        let v = if rng.below(5) == 0 {
            // convex on an ellipse
            let n = 3 + rng.below(12) as usize;
            let (rx, ry) = (1.0 + rng.unit() * 200.0, 1.0 + rng.unit() * 200.0);
            let c = (
                rng.below(2000) as f64 - 1000.0,
                rng.below(2000) as f64 - 1000.0,
            );
            let dir = if rng.below(2) == 0 { 1.0 } else { -1.0 };
            (0..n)
                .map(|i| {
                    let a = dir * i as f64 * core::f64::consts::TAU / n as f64;
                    Vertex::try_from_num(c.0 + rx * a.cos(), c.1 + ry * a.sin()).unwrap()
                })
                .collect()
        } else {
            rand_polygon(&mut rng)
        };
        let poly = Polygon::<16>::new(&v).unwrap();
        let p = raw(v[rng.below(v.len() as u64) as usize]);
        let mid = if rng.below(2) == 0 {
            p
        } else {
            let q = raw(v[rng.below(v.len() as u64) as usize]);
            ((p.0 + q.0) / 2, (p.1 + q.1) / 2)
        };
        let win0 = window_rand::<BinaryColor>(&mut rng, mid, 24);
        for rule in [FillRule::NonZero, FillRule::EvenOdd] {
            let what = format!("case {case} {rule:?} {v:?}");
            let mut spans = Vec::new();
            poly.for_each_span(rule, &win0.area, |s| {
                spans.push(s);
                Ok::<(), Infallible>(())
            })
            .unwrap();
            // left to right, row by row from the top; non-empty; inside the clip
            for w in spans.windows(2) {
                assert!(
                    w[1].y > w[0].y || (w[1].y == w[0].y && w[1].x_start > w[0].x_end),
                    "{what}: spans out of order {w:?}"
                );
            }
            let mut set = BTreeSet::new();
            for s in &spans {
                assert!(s.x_start < s.x_end);
                let r = Rectangle::new(Point::new(s.x_start, s.y), Size::new(s.len(), 1));
                assert!(win0.area.intersection(&r) == r, "{what}: span outside clip");
                for x in s.x_start..s.x_end {
                    set.insert((x as i64, s.y as i64));
                }
            }
            let mut win = win0.clone();
            poly.fill(BinaryColor::On)
                .with_rule(rule)
                .draw(&mut win)
                .unwrap();
            assert_eq!(win.outside, 0, "{what}: outside");
            for (x, y) in win0.pixels() {
                let want = poly_lit(&v, rule, x, y);
                assert_eq!(
                    set.contains(&(x, y)),
                    want,
                    "{what}: for_each_span at ({x}, {y})"
                );
                assert_eq!(win.cnt(x, y), want as u32, "{what}: draw at ({x}, {y})");
            }
        }
    }
}

#[test]
fn polygon_construction_errors_and_rectangles() {
    let v = [Vertex::from_raw(0, 0); 40];
    for n in 0..40 {
        let r3 = Polygon::<3>::new(&v[..n]).map(|_| ());
        let r16 = Polygon::<16>::new(&v[..n]).map(|_| ());
        if n < 3 {
            assert_eq!(r3, Err(PolygonError::TooFewVertices { count: n }));
            assert_eq!(r16, Err(PolygonError::TooFewVertices { count: n }));
        } else {
            let expected = |capacity: usize| match n > capacity {
                true => Err(PolygonError::CapacityExceeded {
                    needed: n,
                    capacity,
                }),
                false => Ok(()),
            };
            assert_eq!(r3, expected(3));
            assert_eq!(r16, expected(16));
        }
    }
    // An axis-aligned rectangle is one fill_solid, with the sampling rule's pixels.
    let mut rng = Rng(0x4ec7);
    for case in 0..500 {
        let x0 = rng.below(40) as i32 * 1024 - 4096;
        let y0 = rng.below(40) as i32 * 1024 - 4096;
        let x1 = x0 + rng.below(30) as i32 * 1024 + 1024;
        let y1 = y0 + rng.below(30) as i32 * 1024 + 1024;
        let mut v = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)].map(|(x, y)| Vertex::from_raw(x, y));
        if rng.below(2) == 0 {
            v.reverse();
        }
        v.rotate_left(rng.below(4) as usize);
        let poly = Polygon::<4>::new(&v).unwrap();
        let mut win = Window::<BinaryColor>::new(-3, -3, 14, 14);
        poly.fill(BinaryColor::On).draw(&mut win).unwrap();
        let any = win
            .pixels()
            .any(|(x, y)| poly_lit(&v, FillRule::NonZero, x, y));
        for (x, y) in win.pixels() {
            assert_eq!(
                win.cnt(x, y),
                poly_lit(&v, FillRule::NonZero, x, y) as u32,
                "rect {case} ({x}, {y})"
            );
        }
        if any {
            assert_eq!(
                (win.fill_solid, win.draw_iter, win.fill_contiguous),
                (1, 0, 0),
                "rect {case}: one fill_solid"
            );
        }
    }
}

fn seg_touch(a: P, b: P, c: P, d: P) -> bool {
    let on = |p: P, q: P, r: P| {
        // r on segment pq, given collinear
        r.0 >= p.0.min(q.0) && r.0 <= p.0.max(q.0) && r.1 >= p.1.min(q.1) && r.1 <= p.1.max(q.1)
    };
    let (d1, d2, d3, d4) = (
        cross(a, b, c),
        cross(a, b, d),
        cross(c, d, a),
        cross(c, d, b),
    );
    if ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)) {
        return true;
    }
    (d1 == 0 && on(a, b, c))
        || (d2 == 0 && on(a, b, d))
        || (d3 == 0 && on(c, d, a))
        || (d4 == 0 && on(c, d, b))
}

fn simple_ref(v: &[P]) -> bool {
    let n = v.len();
    let e = |i: usize| (v[i], v[(i + 1) % n]);
    for i in 0..n {
        if v[i] == v[(i + 1) % n] {
            return false;
        }
    }
    for i in 0..n {
        for j in i + 1..n {
            let (a, b) = e(i);
            let (c, d) = e(j);
            let adjacent = j == i + 1 || (i == 0 && j == n - 1);
            if !adjacent {
                if seg_touch(a, b, c, d) {
                    return false;
                }
            } else {
                // share only the common vertex: the shared vertex s, others o1 (of edge i), o2
                let (s, o1, o2) = if j == i + 1 { (b, a, d) } else { (a, b, c) };
                // they overlap beyond s iff collinear and pointing the same way from s
                if cross(s, o1, o2) == 0 {
                    let dot = (o1.0 - s.0) * (o2.0 - s.0) + (o1.1 - s.1) * (o2.1 - s.1);
                    if dot > 0 {
                        return false;
                    }
                }
                if n == 3 {
                    // with three edges every pair is adjacent; nothing more to check
                }
            }
        }
    }
    true
}

fn convex_ref(v: &[P]) -> bool {
    let n = v.len();
    if !simple_ref(v) {
        return false;
    }
    let area: i128 = (0..n)
        .map(|i| v[i].0 * v[(i + 1) % n].1 - v[(i + 1) % n].0 * v[i].1)
        .sum();
    if area == 0 {
        return false;
    }
    let mut pos = false;
    let mut neg = false;
    for i in 0..n {
        let c = cross(v[i], v[(i + 1) % n], v[(i + 2) % n]);
        pos |= c > 0;
        neg |= c < 0;
    }
    !(pos && neg)
}

#[test]
fn polygon_predicates_against_brute_force_and_triangulation() {
    let mut rng = Rng(0x51e);
    let mut counts = [0u32; 3];
    for case in 0..20000 {
        let n = 3 + rng.below(5) as usize;
        let g = [3i64, 4, 6][rng.below(3) as usize];
        let unit = [4096i64, 2048, 1, 1 << 30][rng.below(4) as usize];
        let v: Vec<Vertex> = (0..n)
            .map(|_| {
                Vertex::from_raw(
                    (rng.below(g as u64) * unit - unit) as i32,
                    (rng.below(g as u64) * unit - unit) as i32,
                )
            })
            .collect();
        let p: Vec<P> = v.iter().map(|&q| raw(q)).collect();
        let poly = Polygon::<8>::new(&v).unwrap();
        let (s, c) = (simple_ref(&p), convex_ref(&p));
        assert_eq!(poly.is_simple(), s, "case {case}: is_simple {p:?}");
        assert_eq!(poly.is_convex(), c, "case {case}: is_convex {p:?}");
        counts[s as usize + c as usize] += 1;
        // triangulate: NotSimple without calling f; else the fill's pixels once each
        let mut tris = Vec::new();
        let r = poly.triangulate(|t| tris.push(t));
        if !s {
            assert_eq!(r, Err(PolygonError::NotSimple), "case {case}");
            assert!(tris.is_empty(), "case {case}: f called on error");
        } else if unit <= 4096 {
            assert_eq!(r, Ok(()));
            let mut win = Window::<BinaryColor>::new(
                -2,
                -2,
                (g * unit / 4096 + 4) as u32,
                (g * unit / 4096 + 4) as u32,
            );
            for t in &tris {
                t.fill(BinaryColor::On).draw(&mut win).unwrap();
            }
            for (x, y) in win.pixels() {
                for rule in [FillRule::NonZero, FillRule::EvenOdd] {
                    assert_eq!(
                        win.cnt(x, y),
                        poly_lit(&v, rule, x, y) as u32,
                        "case {case}: triangulation {p:?} at ({x}, {y})"
                    );
                }
            }
        } else {
            assert_eq!(r, Ok(()));
        }
    }
    assert!(
        counts.iter().all(|&c| c > 500),
        "predicate classes poorly covered: {counts:?}"
    );
    // the docs' examples
    let v = |p: &[(i32, i32)]| {
        p.iter()
            .map(|&(x, y)| Vertex::try_from_num(x, y).unwrap())
            .collect::<Vec<_>>()
    };
    assert!(
        Polygon::<8>::new(&v(&[(0, 0), (2, 0), (4, 0), (4, 4), (0, 4)]))
            .unwrap()
            .is_simple()
    );
    assert!(!Polygon::<8>::new(&v(&[(0, 0), (4, 4), (4, 0), (0, 4)]))
        .unwrap()
        .is_simple());
}

// ---------------------------------------------------------------------------
// Shading.
// ---------------------------------------------------------------------------

/// The exact blend at the centre of pixel (i, j) as num / den (den > 0).
fn blend(t: &Triangle, a: [i64; 3], i: i64, j: i64) -> (i128, i128) {
    let v = t.vertices.map(raw);
    let p = (4096 * i as i128 + 2048, 4096 * j as i128 + 2048);
    let w = |k: usize| cross(p, v[(k + 1) % 3], v[(k + 2) % 3]);
    let (w0, w1, w2) = (w(0), w(1), w(2));
    let d = w0 + w1 + w2;
    let num = a[0] as i128 * w0 + a[1] as i128 * w1 + a[2] as i128 * w2;
    if d < 0 {
        (-num, -d)
    } else {
        (num, d)
    }
}

/// Whether `got` is a documented result for the exact value num/den: within 1 (strictly),
/// and the exactly rounded value unless within 2^-12 of a half.
fn blend_ok(got: i64, num: i128, den: i128) -> bool {
    let g = got as i128;
    if (g * den - num).abs() >= den {
        return false;
    }
    // nearest half-integer k + 1/2 to num/den: distance |2 num - (2k+1) den| / (2 den)
    let k = (2 * num).div_euclid(2 * den); // floor(num/den)
    let dist_half = (2 * num - (2 * k + 1) * den).abs(); // over 2 den
    let near_half = dist_half * 4096 <= 2 * den;
    if near_half {
        return true;
    }
    let rounded = (2 * num + den).div_euclid(2 * den);
    g == rounded
}

fn rand_shade_triangle(rng: &mut Rng) -> Triangle {
    let bits = 4 + rng.below(29) as u32;
    let (cx, cy) = (
        (rng.next() as i32 as i64) >> rng.below(12),
        (rng.next() as i32 as i64) >> rng.below(12),
    );
    let grid = [1i64, 2048, 4096][rng.below(3) as usize];
    let mut v = || {
        Vertex::from_raw(
            (rand_raw(rng, cx, bits) as i64 / grid * grid) as i32,
            (rand_raw(rng, cy, bits) as i64 / grid * grid) as i32,
        )
    };
    Triangle::new(v(), v(), v())
}

fn check_gouraud<C: ShadeColor + core::fmt::Debug>(rng: &mut Rng, colors: [C; 3], case: usize) {
    let t = rand_shade_triangle(rng);
    let v = t.vertices.map(raw);
    let k = rng.below(3) as usize;
    let p = if rng.below(2) == 0 {
        v[k]
    } else {
        (
            (v[0].0 + v[1].0 + v[2].0) / 3,
            (v[0].1 + v[1].1 + v[2].1) / 3,
        )
    };
    let win0 = window_rand::<C>(rng, p, 20);
    let mut win = win0.clone();
    let g = t.gouraud(colors);
    g.draw(&mut win).unwrap();
    assert_eq!(win.outside, 0);
    assert!(
        win.fill_solid == 0 && win.draw_iter == 0,
        "Gouraud spans go as fill_contiguous"
    );
    let mut spans = 0u32;
    let mut other = win0.clone();
    g.for_each_span(&win0.area, |s, colors| {
        spans += 1;
        let mut n = 0;
        for (x, c) in (s.x_start..).zip(colors) {
            other.put(x as i64, s.y as i64, c);
            n += 1;
        }
        assert_eq!(n, s.len(), "colours per span");
        Ok::<(), Infallible>(())
    })
    .unwrap();
    assert_eq!(win.fill_contiguous, spans, "one fill_contiguous per span");
    for (x, y) in win0.pixels() {
        let lit = tri_lit(&t, x, y);
        assert_eq!(
            win.cnt(x, y),
            lit as u32,
            "case {case}: Gouraud pixel set at ({x}, {y}) {t:?}"
        );
        assert_eq!(
            other.get(x, y),
            win.get(x, y),
            "case {case}: for_each_span colours"
        );
        if let Some(c) = win.get(x, y) {
            for ch in 0..C::CHANNELS {
                let a = colors.map(|c| c.channels()[ch] as i64);
                let (num, den) = blend(&t, a, x, y);
                let got = c.channels()[ch] as i64;
                assert!(
                    blend_ok(got, num, den),
                    "case {case}: channel {ch} at ({x}, {y}) = {got}, exact {num}/{den} ({}) for {t:?} {colors:?}",
                    num as f64 / den as f64
                );
            }
        }
    }
}

#[test]
fn gouraud_blends_within_one_and_exactly_rounded() {
    let mut rng = Rng(0x6a0);
    let c888 = |rng: &mut Rng| {
        Rgb888::new(
            rng.below(256) as u8,
            rng.below(256) as u8,
            rng.below(256) as u8,
        )
    };
    for case in 0..1500 {
        let c = [c888(&mut rng), c888(&mut rng), c888(&mut rng)];
        check_gouraud(&mut rng, c, case);
        let c565 = |rng: &mut Rng| {
            Rgb565::new(
                rng.below(32) as u8,
                rng.below(64) as u8,
                rng.below(32) as u8,
            )
        };
        let c = [c565(&mut rng), c565(&mut rng), c565(&mut rng)];
        check_gouraud(&mut rng, c, case);
        let g = |rng: &mut Rng| Gray8::new(rng.below(256) as u8);
        let c = [g(&mut rng), g(&mut rng), g(&mut rng)];
        check_gouraud(&mut rng, c, case);
        let b = |rng: &mut Rng| {
            if rng.below(2) == 0 {
                BinaryColor::On
            } else {
                BinaryColor::Off
            }
        };
        let c = [b(&mut rng), b(&mut rng), b(&mut rng)];
        check_gouraud(&mut rng, c, case);
    }
}

#[test]
fn average_color_and_shade_color() {
    for s0 in 0..=255u16 {
        for s1 in [0u16, 1, 2, 127, 128, 254, 255] {
            for s2 in [0u16, 1, 85, 170, 255] {
                let c = [
                    Gray8::new(s0 as u8),
                    Gray8::new(s1 as u8),
                    Gray8::new(s2 as u8),
                ];
                let s = s0 + s1 + s2;
                assert_eq!(
                    average_color(c),
                    Gray8::new(((s + 1) / 3) as u8),
                    "{s0} {s1} {s2}"
                );
                let t = Triangle::default().gouraud(c);
                assert_eq!(t.flat().color, average_color(c));
                assert_eq!(t.flat().triangle, t.triangle);
            }
        }
    }
    let mut rng = Rng(0xa7);
    for _ in 0..5000 {
        let c = [0, 1, 2].map(|_| {
            Rgb565::new(
                rng.below(32) as u8,
                rng.below(64) as u8,
                rng.below(32) as u8,
            )
        });
        let avg = average_color(c);
        for ch in 0..3 {
            let s: u32 = c.iter().map(|c| c.channels()[ch] as u32).sum();
            assert_eq!(avg.channels()[ch] as u32, (s + 1) / 3);
        }
        let b = [0, 1, 2].map(|_| {
            if rng.below(2) == 0 {
                BinaryColor::On
            } else {
                BinaryColor::Off
            }
        });
        let ons = b.iter().filter(|&&c| c == BinaryColor::On).count();
        assert_eq!(
            average_color(b),
            if ons >= 2 {
                BinaryColor::On
            } else {
                BinaryColor::Off
            }
        );
        let raw3 = [
            rng.below(256) as u8,
            rng.below(256) as u8,
            rng.below(256) as u8,
        ];
        assert_eq!(Rgb888::from_channels(raw3).channels(), raw3);
        assert_eq!(
            Rgb565::from_channels(raw3),
            Rgb565::new(raw3[0], raw3[1], raw3[2])
        );
        assert_eq!(Gray8::from_channels(raw3).channels()[0], raw3[0]);
        assert_eq!(
            BinaryColor::from_channels(raw3),
            if raw3[0] != 0 {
                BinaryColor::On
            } else {
                BinaryColor::Off
            }
        );
    }
    assert_eq!(
        (Rgb565::MAX, Rgb888::MAX, Gray8::MAX, BinaryColor::MAX[0]),
        ([31, 63, 31], [255; 3], [255, 0, 0], 1)
    );
    assert_eq!(
        (
            Rgb565::CHANNELS,
            Rgb888::CHANNELS,
            Gray8::CHANNELS,
            BinaryColor::CHANNELS
        ),
        (3, 3, 1, 1)
    );
}

#[test]
fn depth_test_strictly_nearer_stores_interpolated_depth() {
    let mut rng = Rng(0xde9);
    for case in 0..1500 {
        let t = {
            let mut v = || {
                Vertex::from_raw(
                    rng.below(30 * 4096) as i32 - 4 * 4096,
                    rng.below(30 * 4096) as i32 - 4 * 4096,
                )
            };
            Triangle::new(v(), v(), v())
        };
        let z = [0, 1, 2].map(|_| match rng.below(4) {
            0 => FAR,
            1 => rng.below(4) as u16,
            _ => rng.below(65536) as u16,
        });
        // buffer: any width, maybe a band of rows, with random old depths
        let bw = 1 + rng.below(26) as u32;
        let bh = rng.below(26) as usize;
        let top = rng.below(10) as i32 - 5;
        let mut storage: Vec<u16> = (0..bw as usize * bh + rng.below(3) as usize)
            .map(|_| match rng.below(3) {
                0 => FAR,
                _ => rng.below(65536) as u16,
            })
            .collect();
        let old = storage.clone();
        let bh = storage.len() / bw as usize; // as many rows as fit
        let win0 = Window::<Rgb888>::new(rng.below(6) as i32 - 3, rng.below(6) as i32 - 3, 22, 22);
        let mut win = win0.clone();
        let gouraud = rng.below(2) == 0;
        let cols = [Rgb888::RED, Rgb888::GREEN, Rgb888::BLUE];
        {
            let depth = if top == 0 && rng.below(2) == 0 {
                DepthBuffer::new(&mut storage, bw)
            } else {
                DepthBuffer::for_rows(&mut storage, bw, top)
            };
            if gouraud {
                t.gouraud(cols).with_depth(z, depth).draw(&mut win).unwrap();
            } else {
                t.fill(Rgb888::WHITE)
                    .with_depth(z, depth)
                    .draw(&mut win)
                    .unwrap();
            }
        }
        assert_eq!(win.outside, 0, "case {case}: outside");
        let zi = z.map(|z| z as i64);
        // every pixel of the target and of the buffer
        for (x, y) in win0.pixels() {
            let in_buf =
                x >= 0 && (x as u32) < bw && y >= top as i64 && ((y - top as i64) as usize) < bh;
            let lit = tri_lit(&t, x, y);
            let drawn = win.cnt(x, y);
            assert!(drawn <= 1);
            if !lit || !in_buf {
                assert_eq!(
                    drawn, 0,
                    "case {case}: drawn at ({x}, {y}) lit {lit} in buffer {in_buf}"
                );
                continue;
            }
            let i = (y - top as i64) as usize * bw as usize + x as usize;
            let (num, den) = blend(&t, zi, x, y);
            let before = old[i] as i64;
            let after = storage[i] as i64;
            if drawn == 1 {
                assert!(
                    after < before,
                    "case {case}: ({x}, {y}) drawn but stored {after} not < old {before}"
                );
                assert!(
                    blend_ok(after, num, den),
                    "case {case}: stored depth {after} vs exact {num}/{den}"
                );
                if !gouraud {
                    assert_eq!(win.get(x, y), Some(Rgb888::WHITE));
                } else {
                    let c = win.get(x, y).unwrap();
                    for ch in 0..3 {
                        let (n2, d2) = blend(&t, cols.map(|c| c.channels()[ch] as i64), x, y);
                        assert!(
                            blend_ok(c.channels()[ch] as i64, n2, d2),
                            "case {case}: colour under depth"
                        );
                    }
                }
            } else {
                assert_eq!(
                    after, before,
                    "case {case}: ({x}, {y}) not drawn but depth changed"
                );
                // the interpolated depth could not have been smaller: every allowed value >= before
                let lo = (num.div_euclid(den) as i64).max(0); // the smallest candidate is floor or round
                let mut candidates = Vec::new();
                for c in lo - 1..=lo + 2 {
                    if (0..=65535).contains(&c) && blend_ok(c, num, den) {
                        candidates.push(c);
                    }
                }
                assert!(!candidates.is_empty());
                assert!(
                    candidates.iter().any(|&c| c >= before),
                    "case {case}: ({x}, {y}) not drawn though depth {candidates:?} < stored {before}"
                );
                if candidates.iter().all(|&c| c < before) {
                    unreachable!();
                }
            }
        }
        // depth cells outside the target or the triangle are untouched
        for (k, (&a, &b)) in old.iter().zip(&storage).enumerate() {
            if a != b {
                let (x, y) = (
                    (k % bw as usize) as i64,
                    (k / bw as usize) as i64 + top as i64,
                );
                assert!(
                    win0.idx(x, y).is_some() && win.cnt(x, y) == 1,
                    "case {case}: depth cell {k} changed, pixel not drawn"
                );
            }
        }
    }
    // FAR never passes; equal depths keep the first drawn
    let mut storage = [0u16; 16 * 16];
    let depth = DepthBuffer::new(&mut storage, 16);
    depth.clear();
    assert!((0..16).all(|y| (0..16).all(|x| depth.get(x, y) == Some(FAR))));
    assert_eq!(
        (
            depth.get(16, 0),
            depth.get(0, 16),
            depth.get(u32::MAX, u32::MAX)
        ),
        (None, None, None)
    );
    let t = Triangle::from_points(Point::new(0, 0), Point::new(15, 1), Point::new(2, 15)).unwrap();
    let mut win = Window::<Gray8>::new(0, 0, 16, 16);
    t.fill(Gray8::WHITE)
        .with_depth([FAR; 3], depth)
        .draw(&mut win)
        .unwrap();
    assert_eq!(win.count.iter().sum::<u32>(), 0, "FAR passed");
    t.fill(Gray8::new(1))
        .with_depth([700; 3], depth)
        .draw(&mut win)
        .unwrap();
    t.fill(Gray8::new(2))
        .with_depth([700; 3], depth)
        .draw(&mut win)
        .unwrap();
    assert!(
        win.px
            .iter()
            .all(|c| c.is_none() || *c == Some(Gray8::new(1))),
        "a tie replaced the first"
    );
    assert_eq!(depth.get(5, 5), Some(700));
    // sizes
    let mut s = [0u16; 100];
    assert_eq!(DepthBuffer::new(&mut s, 30).size(), Size::new(30, 3));
    assert_eq!(DepthBuffer::new(&mut s, 0).size().height, 0);
    assert_eq!(DepthBuffer::new(&mut s, 101).size().height, 0);
    let d = DepthBuffer::new(&mut s, 0);
    d.clear();
    let mut win = Window::<Gray8>::new(0, 0, 8, 8);
    Triangle::from_points(Point::new(0, 0), Point::new(7, 0), Point::new(0, 7))
        .unwrap()
        .fill(Gray8::WHITE)
        .with_depth([0; 3], d)
        .draw(&mut win)
        .unwrap();
    assert_eq!(win.count.iter().sum::<u32>(), 0, "width 0: nothing passes");
}

// ---------------------------------------------------------------------------
// Mesh arithmetic.
// ---------------------------------------------------------------------------

#[test]
fn sin_cos_within_two_units_everywhere() {
    for a in 0..=u16::MAX {
        let (s, c) = sin_cos(a);
        let t = a as f64 * core::f64::consts::TAU / 65536.0;
        let (es, ec) = (32768.0 * t.sin(), 32768.0 * t.cos());
        assert!(
            (s as f64 - es).abs() <= 2.0 + 1e-9,
            "sin({a}) = {s}, exact {es}"
        );
        assert!(
            (c as f64 - ec).abs() <= 2.0 + 1e-9,
            "cos({a}) = {c}, exact {ec}"
        );
        assert!(s.abs() <= ONE && c.abs() <= ONE);
    }
}

fn q15_round(n: i128) -> i128 {
    (n + (1 << 14)).div_euclid(1 << 15) // ties up
}

/// A position inside the 20.12 range whose centre or offset from it lies
/// outside: `Camera::project` returned `None` until 2026-12-06 (it
/// checked each part into `i32`); the docs promise the position.
#[test]
fn camera_project_in_range_position_with_far_parts() {
    // 1. The offset focal * y / z = 600000 px is out of range, the position
    //    100000 - 600000 = -500000 px is in it.
    let cam = Camera {
        focal: 1,
        centre: (0, 100_000),
        near: 1,
        far: 2,
    };
    let got = cam.project(Vec3::new(0, 600_000, 1));
    assert_eq!(
        got.map(|(v, _)| v.raw()),
        Some((0, -500_000 * 4096)),
        "offset out of range"
    );
    // 2. The centre (754896 px) is out of range, the position (-280707.6 px) is in it.
    let cam = Camera {
        focal: -115,
        centre: (-32768, 754_896),
        near: -15,
        far: -381,
    };
    let got = cam.project(Vec3::new(-9754, -110_781_315, 12302));
    assert!(got.is_some(), "centre out of range: observed None");
}

#[test]
fn vec3_dot_rotation_apply_and_camera() {
    let mut rng = Rng(0x3d);
    let comp = |rng: &mut Rng| -> i32 {
        match rng.below(5) {
            0 => [i32::MIN, i32::MAX, 0, -1, 1, ONE, -ONE][rng.below(7) as usize],
            _ => (rng.next() as i32) >> rng.below(32),
        }
    };
    for _ in 0..30000 {
        let a = Vec3::new(comp(&mut rng), comp(&mut rng), comp(&mut rng));
        let b = Vec3::new(comp(&mut rng), comp(&mut rng), comp(&mut rng));
        let s = a.x as i128 * b.x as i128 + a.y as i128 * b.y as i128 + a.z as i128 * b.z as i128;
        let r = q15_round(s);
        let fits = (i32::MIN as i128..=i32::MAX as i128).contains(&r);
        assert_eq!(a.checked_dot(b), fits.then_some(r as i32), "{a:?}.{b:?}");
        assert_eq!(
            a.dot(b) as i128,
            r.clamp(i32::MIN as i128, i32::MAX as i128),
            "{a:?}.{b:?}"
        );
        let m = Rotation {
            m: [
                [comp(&mut rng), comp(&mut rng), comp(&mut rng)],
                [comp(&mut rng), comp(&mut rng), comp(&mut rng)],
                [comp(&mut rng), comp(&mut rng), comp(&mut rng)],
            ],
        };
        let rows = m.m.map(|row| Vec3::new(row[0], row[1], row[2]).dot(a));
        assert_eq!(m.apply(a), Vec3::new(rows[0], rows[1], rows[2]));
        let checked =
            m.m.map(|row| Vec3::new(row[0], row[1], row[2]).checked_dot(a));
        let want = match checked {
            [Some(x), Some(y), Some(z)] => Some(Vec3::new(x, y, z)),
            _ => None,
        };
        assert_eq!(m.checked_apply(a), want);
        // rotations made by new: exact within ±2^30, rows of length ONE
        let r = Rotation::new(rng.next() as u16, rng.next() as u16);
        for row in r.m {
            assert!(row.iter().all(|e| e.abs() <= ONE));
            let len2: i64 = row.iter().map(|&e| e as i64 * e as i64).sum();
            assert!(
                (len2 as f64).sqrt() - ONE as f64 <= 8.0
                    && ONE as f64 - (len2 as f64).sqrt() <= 8.0,
                "row {row:?}"
            );
        }
        let small = Vec3::new(
            comp(&mut rng) >> 1,
            comp(&mut rng) >> 1,
            comp(&mut rng) >> 1,
        );
        assert!(
            r.checked_apply(small).is_some(),
            "saturated within ±2^30: {r:?} {small:?}"
        );
    }
    // yaw: a quarter turn as in the docs; orthogonality of new's rows
    for _ in 0..2000 {
        let r = Rotation::new(rng.next() as u16, rng.next() as u16);
        for i in 0..3 {
            for j in i + 1..3 {
                let d: i64 = (0..3).map(|k| r.m[i][k] as i64 * r.m[j][k] as i64).sum();
                assert!(
                    d.abs() <= 16 * ONE as i64,
                    "rows {i} {j} not orthogonal: {r:?}"
                );
            }
        }
    }
    // Camera::project
    for case in 0..30000 {
        let small = rng.below(2) == 0;
        let f = |rng: &mut Rng| {
            if small {
                (rng.below(2001) as i32) - 1000
            } else {
                comp(rng)
            }
        };
        let cam = Camera {
            focal: f(&mut rng),
            centre: (f(&mut rng), f(&mut rng)),
            near: if small {
                rng.below(4 * ONE as u64) as i32
            } else {
                comp(&mut rng)
            },
            far: if small {
                rng.below(16 * ONE as u64) as i32
            } else {
                comp(&mut rng)
            },
        };
        let p = if small {
            Vec3::new(
                rng.below(8 * ONE as u64) as i32 - 4 * ONE,
                rng.below(8 * ONE as u64) as i32 - 4 * ONE,
                rng.below(16 * ONE as u64) as i32 - ONE,
            )
        } else {
            Vec3::new(comp(&mut rng), comp(&mut rng), comp(&mut rng))
        };
        let got = cam.project(p);
        if p.z <= 0 {
            assert_eq!(got, None, "case {case}: z <= 0");
            continue;
        }
        let z = p.z as i128;
        // exact raw positions: 4096 (cx + focal x / z), 4096 (cy - focal y / z), as num / z
        let nx = 4096 * (cam.centre.0 as i128 * z + cam.focal as i128 * p.x as i128);
        let ny = 4096 * (cam.centre.1 as i128 * z - cam.focal as i128 * p.y as i128);
        let clearly_in = |n: i128| n > (RAW_MIN + 1) * z && n < (RAW_MAX - 1) * z;
        let clearly_out = |n: i128| n < (RAW_MIN - 1) * z || n > (RAW_MAX + 1) * z;
        match got {
            Some((v, depth)) => {
                let (rx, ry) = raw(v);
                assert!(
                    (rx * z - nx).abs() < z,
                    "case {case}: x raw {rx} vs {}/{z}",
                    nx
                );
                assert!(
                    (ry * z - ny).abs() < z,
                    "case {case}: y raw {ry} vs {}/{z}",
                    ny
                );
                if 0 < cam.near && cam.near < cam.far {
                    let num = 65534 * cam.far as i128 * (z - cam.near as i128);
                    let den = z * (cam.far as i128 - cam.near as i128);
                    let d = depth as i128;
                    let exact_clamped_ok = if num <= 0 {
                        d == 0 || (d * den - num).abs() < den
                    } else if num >= 65534 * den {
                        d == 65534 || (d * den - num).abs() < den
                    } else {
                        (d * den - num).abs() < den
                    };
                    assert!(
                        exact_clamped_ok,
                        "case {case}: depth {depth} vs {num}/{den} {cam:?} {p:?}"
                    );
                    assert!(depth <= 65534);
                } else {
                    assert_eq!(depth, 0, "case {case}: depth without 0 < near < far");
                }
            }
            None => {
                assert!(
                    !(clearly_in(nx) && clearly_in(ny)),
                    "case {case}: None though in range {cam:?} {p:?}"
                );
            }
        }
        if clearly_out(nx) || clearly_out(ny) {
            assert_eq!(got, None, "case {case}: out of range gives None");
        }
    }
}

// ---------------------------------------------------------------------------
// Delaunay.
// ---------------------------------------------------------------------------

/// Sign of the in-circle determinant (relative to d) from the module docs, exactly, with a
/// base-2^33 accumulator for the 133-bit sum.
fn in_circle_ref(a: Vertex, b: Vertex, c: Vertex, d: Vertex) -> Ordering {
    let d0 = raw(d);
    let rel = |p: Vertex| {
        let p = raw(p);
        (p.0 - d0.0, p.1 - d0.1)
    };
    let (a, b, c) = (rel(a), rel(b), rel(c));
    let lift = |p: P| p.0 * p.0 + p.1 * p.1;
    let det = |p: P, q: P| p.0 * q.1 - p.1 * q.0;
    let terms = [
        (lift(a), det(b, c)),
        (lift(b), det(c, a)),
        (lift(c), det(a, b)),
    ];
    const B: i128 = 1 << 33;
    let mut limbs = [0i128; 8];
    for (x, y) in terms {
        let split = |v: i128| (v.div_euclid(B), v.rem_euclid(B)); // v = hi B + lo
        let (x1, x0) = split(x);
        let (y1, y0) = split(y);
        // x1, y1 < 2^33 in magnitude: every product below 2^66
        limbs[0] += x0 * y0;
        limbs[1] += x1 * y0 + x0 * y1;
        limbs[2] += x1 * y1;
    }
    for i in 0..7 {
        let carry = limbs[i].div_euclid(B);
        limbs[i] -= carry * B;
        limbs[i + 1] += carry;
    }
    for i in (0..8).rev() {
        if limbs[i] != 0 {
            // lower limbs are in [0, B): the sign is the top non-zero limb's
            return limbs[i].cmp(&0);
        }
    }
    Ordering::Equal
}

#[test]
fn delaunay_predicates_are_exact() {
    let mut rng = Rng(0xde1);
    let pick = |rng: &mut Rng| -> i32 {
        match rng.below(4) {
            0 => [i32::MIN, i32::MAX, 0, i32::MIN + 1, i32::MAX - 1][rng.below(5) as usize],
            1 => rng.below(64) as i32 * 4096,
            _ => (rng.next() as i32) >> rng.below(32),
        }
    };
    for _ in 0..40000 {
        let mut v = || Vertex::from_raw(pick(&mut rng), pick(&mut rng));
        let (a, b, c, d) = (v(), v(), v(), v());
        assert_eq!(
            orientation(a, b, c),
            cross(raw(a), raw(b), raw(c)).cmp(&0),
            "{a:?} {b:?} {c:?}"
        );
        assert_eq!(
            in_circle(a, b, c, d),
            in_circle_ref(a, b, c, d),
            "{a:?} {b:?} {c:?} {d:?}"
        );
    }
    // cocircular: rectangles' corners anywhere in range (Equal), and one unit off
    for _ in 0..20000 {
        let (x0, y0) = (pick(&mut rng), pick(&mut rng));
        let (x1, y1) = (pick(&mut rng), pick(&mut rng));
        let (a, b, c, d) = (
            Vertex::from_raw(x0, y0),
            Vertex::from_raw(x1, y0),
            Vertex::from_raw(x1, y1),
            Vertex::from_raw(x0, y1),
        );
        assert_eq!(in_circle(a, b, c, d), in_circle_ref(a, b, c, d));
        if orientation(a, b, c) != Ordering::Equal {
            assert_eq!(
                in_circle(a, b, c, d),
                Ordering::Equal,
                "rectangle corners {x0} {y0} {x1} {y1}"
            );
        }
        let e = Vertex::from_raw(x0.saturating_add(1), y1);
        assert_eq!(in_circle(a, b, c, e), in_circle_ref(a, b, c, e));
    }
}

fn hull_boundary_count(p: &[P]) -> usize {
    // distinct points on the boundary of the convex hull
    let mut pts: Vec<P> = p.to_vec();
    pts.sort();
    pts.dedup();
    let mut hull: Vec<P> = Vec::new();
    for pass in 0..2 {
        let start = hull.len();
        let iter: Box<dyn Iterator<Item = &P>> = if pass == 0 {
            Box::new(pts.iter())
        } else {
            Box::new(pts.iter().rev())
        };
        for &q in iter {
            while hull.len() >= start + 2
                && cross(hull[hull.len() - 2], hull[hull.len() - 1], q) <= 0
            {
                hull.pop();
            }
            hull.push(q);
        }
        hull.pop();
    }
    let m = hull.len();
    pts.iter()
        .filter(|&&q| {
            (0..m).any(|i| {
                let (a, b) = (hull[i], hull[(i + 1) % m]);
                cross(a, b, q) == 0
                    && q.0 >= a.0.min(b.0)
                    && q.0 <= a.0.max(b.0)
                    && q.1 >= a.1.min(b.1)
                    && q.1 <= a.1.max(b.1)
            })
        })
        .count()
}

#[test]
fn delaunay_triangulations_against_their_definition() {
    let mut rng = Rng(0xd1a);
    let mut storage = Box::new(Delaunay::<64>::new());
    for case in 0..600 {
        let n = rng.below(40) as usize;
        let kind = rng.below(4);
        let unit: i64 = [4096, 2048, 1, 1 << 24][rng.below(4) as usize];
        let g = if kind == 0 { 4 + rng.below(5) } else { 1 << 12 };
        let mut pts: Vec<Vertex> = (0..n)
            .map(|_| {
                let c = |rng: &mut Rng| {
                    ((rng.below(g as u64) - g / 2) * unit).clamp(i32::MIN as i64, i32::MAX as i64)
                        as i32
                };
                Vertex::from_raw(c(&mut rng), c(&mut rng))
            })
            .collect();
        if kind == 1 && n > 2 {
            // collinear run
            let (a, d) = (
                raw(pts[0]),
                (rng.below(5) as i128 - 2, rng.below(5) as i128 - 2),
            );
            for (k, p) in pts.iter_mut().enumerate().skip(n / 2) {
                *p = Vertex::from_raw(
                    (a.0 + k as i128 * d.0 * 4096) as i32,
                    (a.1 + k as i128 * d.1 * 4096) as i32,
                );
            }
        }
        if kind == 2 && n > 1 {
            for k in 0..n / 3 {
                let j = rng.below(n as u64) as usize;
                pts[k] = pts[j]; // duplicates
            }
        }
        let p: Vec<P> = pts.iter().map(|&v| raw(v)).collect();
        let mesh = storage.triangulate(&pts).unwrap();
        let tris: Vec<[usize; 3]> = mesh.indices().collect();
        let as_tris: Vec<Triangle> = mesh.triangles().collect();
        assert_eq!(tris.len(), mesh.len());
        assert_eq!(as_tris.len(), tris.len());
        let distinct: BTreeSet<P> = p.iter().copied().collect();
        let all_collinear = distinct.len() < 3 || {
            let d: Vec<P> = distinct.iter().copied().collect();
            d.iter().all(|&q| cross(d[0], d[1], q) == 0)
        };
        let what = format!("case {case} ({n} points, kind {kind})");
        if all_collinear {
            assert!(tris.is_empty(), "{what}: collinear gives triangles");
            continue;
        }
        // the lowest index of each distinct point is its vertex; every distinct point is one
        let lowest: BTreeMap<P, usize> = p.iter().enumerate().rev().map(|(i, &q)| (q, i)).collect();
        let mut used = BTreeSet::new();
        for (t, tri) in tris.iter().zip(&as_tris) {
            for &i in t {
                assert!(i < n);
                assert_eq!(lowest[&p[i]], i, "{what}: duplicate index {i} used");
                used.insert(i);
            }
            assert_eq!(*tri, Triangle::new(pts[t[0]], pts[t[1]], pts[t[2]]));
            assert_eq!(
                orientation(pts[t[0]], pts[t[1]], pts[t[2]]),
                Ordering::Greater,
                "{what}: not clockwise"
            );
            for (k, &q) in pts.iter().enumerate() {
                assert_ne!(
                    in_circle_ref(pts[t[0]], pts[t[1]], pts[t[2]], q),
                    Ordering::Greater,
                    "{what}: point {k} inside circumcircle of {t:?}"
                );
            }
        }
        assert_eq!(
            used.len(),
            distinct.len(),
            "{what}: not every point is a vertex"
        );
        let h = hull_boundary_count(&p);
        assert_eq!(
            tris.len(),
            2 * distinct.len() - h - 2,
            "{what}: 2n - h - 2 with n {} h {h}",
            distinct.len()
        );
        // order independence (as coordinates)
        let key = |ts: &[[usize; 3]], pts: &[Vertex]| {
            let mut k: Vec<[P; 3]> = ts
                .iter()
                .map(|t| {
                    let mut c = t.map(|i| raw(pts[i]));
                    // rotate so the least comes first (keeps the winding)
                    let m = (0..3).min_by_key(|&i| c[i]).unwrap();
                    c.rotate_left(m);
                    c
                })
                .collect();
            k.sort();
            k
        };
        let want_key = key(&tris, &pts);
        let mut shuffled = pts.clone();
        for i in (1..shuffled.len()).rev() {
            let j = rng.below(i as u64 + 1) as usize;
            shuffled.swap(i, j);
        }
        let mut other = Box::new(Delaunay::<64>::new());
        let t2: Vec<[usize; 3]> = other.triangulate(&shuffled).unwrap().indices().collect();
        assert_eq!(
            key(&t2, &shuffled),
            want_key,
            "{what}: depends on the order"
        );
        // capacity error keeps the previous triangulation
        let too_many = vec![pts[0]; 65];
        assert_eq!(
            storage.triangulate(&too_many).unwrap_err(),
            DelaunayError::CapacityExceeded {
                needed: 65,
                capacity: 64
            }
        );
        let again: Vec<[usize; 3]> = storage.triangulation(&pts).indices().collect();
        assert_eq!(
            again, tris,
            "{what}: capacity error changed the triangulation"
        );
        assert_eq!(storage.len(), tris.len());
        // rasterized: the hull exactly once (small coordinates only)
        if g * unit <= 64 * 4096 {
            let mut hull: Vec<P> = Vec::new();
            {
                let mut d: Vec<P> = distinct.iter().copied().collect();
                d.sort();
                for pass in 0..2 {
                    let start = hull.len();
                    let it: Vec<P> = if pass == 0 {
                        d.clone()
                    } else {
                        d.iter().rev().copied().collect()
                    };
                    for q in it {
                        while hull.len() >= start + 2
                            && cross(hull[hull.len() - 2], hull[hull.len() - 1], q) <= 0
                        {
                            hull.pop();
                        }
                        hull.push(q);
                    }
                    hull.pop();
                }
            }
            let half = (g * unit / 4096 / 2 + 2) as i32;
            let mut win =
                Window::<BinaryColor>::new(-half, -half, 2 * half as u32, 2 * half as u32);
            for t in &as_tris {
                t.fill(BinaryColor::On).draw(&mut win).unwrap();
            }
            for (x, y) in win.pixels() {
                assert_eq!(
                    win.cnt(x, y),
                    (winding(&hull, x, y) != 0) as u32,
                    "{what}: hull pixel ({x}, {y})"
                );
            }
        }
    }
}

// ---------------------------------------------------------------------------
// Triangle variants.
// ---------------------------------------------------------------------------

fn snap_ref(p: SubpixelPrecision, v: Vertex) -> Vertex {
    let step = 1i128 << (12 - p.bits());
    let s = |c: i32| {
        let r = round_half_even(c as i128, step) * step;
        let r = if r > RAW_MAX {
            RAW_MAX / step * step
        } else {
            r
        };
        r as i32
    };
    let (x, y) = v.raw();
    Vertex::from_raw(s(x), s(y))
}

#[test]
fn variants_snap_and_exact_ones_follow_the_rule() {
    let mut rng = Rng(0x5a9);
    for p in SubpixelPrecision::ALL {
        for c in [
            i32::MIN,
            i32::MIN + 1,
            i32::MAX,
            i32::MAX - 2047,
            i32::MAX - 2048,
            0,
            2048,
            6144,
            -2048,
            -6144,
            128,
            8,
            24,
        ] {
            let v = Vertex::from_raw(c, c.wrapping_neg().max(i32::MIN + 1));
            assert_eq!(p.snap(v), snap_ref(p, v), "{p:?} {v:?}");
        }
        for _ in 0..5000 {
            let v = Vertex::from_raw(
                rng.next() as i32 >> rng.below(32),
                rng.next() as i32 >> rng.below(32),
            );
            assert_eq!(p.snap(v), snap_ref(p, v), "{p:?} {v:?}");
        }
    }
    for case in 0..2500 {
        let t = rand_triangle(&mut rng);
        let p = SubpixelPrecision::ALL[rng.below(4) as usize];
        let snapped = Triangle::new(
            snap_ref(p, t.vertices[0]),
            snap_ref(p, t.vertices[1]),
            snap_ref(p, t.vertices[2]),
        );
        assert_eq!(t.snapped(p), snapped);
        let k = rng.below(3) as usize;
        let win = window_rand::<BinaryColor>(&mut rng, raw(snapped.vertices[k]), 20);
        for alg in TriangleAlgorithm::ALL {
            let mut spans = Vec::new();
            t.for_each_span_with(alg, p, &win.area, |s| {
                spans.push(s);
                Ok::<(), Infallible>(())
            })
            .unwrap();
            let what = format!("case {case} {alg:?} {p:?} {t:?}");
            let set = check_spans(&spans, &win.area, &what);
            let mut drawn = win.clone();
            t.fill(BinaryColor::On)
                .algorithm(alg)
                .precision(p)
                .draw(&mut drawn)
                .unwrap();
            assert_eq!(drawn.outside, 0, "{what}: outside");
            for (x, y) in win.pixels() {
                assert_eq!(
                    drawn.cnt(x, y),
                    set.contains(&(x, y)) as u32,
                    "{what}: draw vs spans at ({x}, {y})"
                );
            }
            if alg.is_exact() {
                for (x, y) in win.pixels() {
                    assert_eq!(
                        set.contains(&(x, y)),
                        tri_lit(&snapped, x, y),
                        "{what}: at ({x}, {y})"
                    );
                }
            }
            if alg == TriangleAlgorithm::EdgeWalk {
                // centres within the bounding box; rows decided exactly
                let v = snapped.vertices.map(raw);
                let (x0, x1) = (
                    v.iter().map(|q| q.0).min().unwrap(),
                    v.iter().map(|q| q.0).max().unwrap(),
                );
                let (y0, y1) = (
                    v.iter().map(|q| q.1).min().unwrap(),
                    v.iter().map(|q| q.1).max().unwrap(),
                );
                for &(x, y) in &set {
                    let (cx, cy) = (4096 * x as i128 + 2048, 4096 * y as i128 + 2048);
                    assert!(
                        cx >= x0 && cx <= x1,
                        "{what}: EdgeWalk centre x {x} outside the box"
                    );
                    assert!(
                        cy >= y0 && cy < y1,
                        "{what}: EdgeWalk row {y} outside [y_top, y_bottom)"
                    );
                }
            }
            if alg == TriangleAlgorithm::BresenhamWalk {
                let want = bresenham_walk_ref(&snapped);
                if let Some(want) = want {
                    for (x, y) in win.pixels() {
                        assert_eq!(
                            set.contains(&(x, y)),
                            want(x, y),
                            "{what}: BresenhamWalk at ({x}, {y})"
                        );
                    }
                }
            }
        }
    }
    // the doc example: the closed triangle of pixels (0,0), (4,0), (0,4): 15 pixels
    let v = |x: i32, y: i32| Vertex::try_from_num(x, y).unwrap();
    let mut lit = 0;
    Triangle::new(v(0, 0), v(4, 0), v(0, 4))
        .for_each_span_with(
            TriangleAlgorithm::BresenhamWalk,
            SubpixelPrecision::Bits12,
            &Rectangle::new(Point::zero(), Size::new(8, 8)),
            |s| {
                lit += s.len();
                Ok::<(), Infallible>(())
            },
        )
        .unwrap();
    assert_eq!(lit, 15);
}

/// BresenhamWalk from its docs: vertices to their pixels; each edge, per row, x rounded to
/// nearest, ties up (to the larger x); each row from the top to the bottom vertex's lights the
/// pixels from the leftmost to the rightmost edge position. `None` for collinear pixel corners
/// (not specified) or huge triangles (the model would be slow).
fn bresenham_walk_ref(t: &Triangle) -> Option<impl Fn(i64, i64) -> bool> {
    let q = t.vertices.map(|v| {
        let (x, y) = v.raw();
        ((x >> 12) as i128, (y >> 12) as i128)
    });
    if cross(q[0], q[1], q[2]) == 0 {
        return None;
    }
    let (ymin, ymax) = (
        q.iter().map(|p| p.1).min().unwrap(),
        q.iter().map(|p| p.1).max().unwrap(),
    );
    if ymax - ymin > 100_000 {
        return None;
    }
    let mut rows: BTreeMap<i64, (i64, i64)> = BTreeMap::new();
    let mut add = |y: i128, x: i128| {
        let e = rows.entry(y as i64).or_insert((x as i64, x as i64));
        e.0 = e.0.min(x as i64);
        e.1 = e.1.max(x as i64);
    };
    for k in 0..3 {
        let (a, b) = (q[k], q[(k + 1) % 3]);
        if a.1 == b.1 {
            add(a.1, a.0);
            add(b.1, b.0);
            continue;
        }
        let (a, b) = if a.1 < b.1 { (a, b) } else { (b, a) };
        let dy = b.1 - a.1;
        for y in a.1..=b.1 {
            // x = a.x + (y - a.y) dx / dy rounded to nearest, ties up
            let num = 2 * (a.0 * dy + (y - a.1) * (b.0 - a.0)) + dy;
            add(y, num.div_euclid(2 * dy));
        }
    }
    Some(move |x: i64, y: i64| rows.get(&y).is_some_and(|&(l, r)| x >= l && x <= r))
}

/// A window of random size (1 to `n` px a side) at `p`.
fn window_rand<C: PixelColor>(rng: &mut Rng, p: P, n: u64) -> Window<C> {
    let (w, h) = (1 + rng.below(n) as u32, 1 + rng.below(n) as u32);
    window_at(rng, p, w, h)
}

/// No span holds column `i32::MAX` (a span's end is exclusive): a sink
/// with only the required methods gets none of a line's pixels there, as
/// `SpanSink`'s docs say, where a `DrawTarget` drawn through `draw` gets
/// them all.
#[test]
fn span_sink_column_at_i32_max() {
    let mut sink = Window::<BinaryColor>::new(i32::MAX - 3, 0, 4, 4);
    Line::new(Point::new(i32::MAX, 0), Point::new(i32::MAX, 3))
        .stroke(BinaryColor::On)
        .draw_spans(&mut sink)
        .unwrap();
    let mut target = Window::<BinaryColor>::new(i32::MAX - 3, 0, 4, 4);
    Line::new(Point::new(i32::MAX, 0), Point::new(i32::MAX, 3))
        .stroke(BinaryColor::On)
        .draw(&mut target)
        .unwrap();
    assert_eq!(target.count.iter().sum::<u32>(), 4);
    assert_eq!(
        sink.count.iter().sum::<u32>(),
        0,
        "draw_spans into a plain SpanSink"
    );
}
