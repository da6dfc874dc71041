//! Thick lines: their rectangle, shared edges, the whole range.

use embedded_graphics_core::{pixelcolor::Gray8, prelude::*};
use embedded_raster::{sim::SimDisplay, Line, Polyline};
use proptest::prelude::*;

use super::{any_line, extreme_line, p, view::View, window_on};

/// Draws `line` with `width` on a fresh `size x size` display.
fn thick(line: Line, width: u32, size: u32) -> SimDisplay<Gray8> {
    thick_at(line, width, size, Point::zero())
}

/// [`thick`], on a display whose top-left pixel is `origin`.
fn thick_at(line: Line, width: u32, size: u32, origin: Point) -> SimDisplay<Gray8> {
    let mut d = SimDisplay::new(size, size, Gray8::BLACK);
    line.stroke(Gray8::WHITE)
        .stroke_width(width)
        .draw(&mut View {
            inner: &mut d,
            origin,
        })
        .unwrap();
    assert_eq!(d.out_of_bounds_writes(), 0);
    assert_eq!(d.write_stats().draw_iter_pixels, 0);
    d
}

/// Where the centre of pixel `(x, y)` lies relative to the rectangle of a
/// thick line, in `f64` (independent of the crate's integer corners):
/// positive inside, negative outside, the distance to the nearest side.
fn rect_margin(line: Line, width: u32, x: i64, y: i64) -> f64 {
    let (ax, ay) = (line.start.x as f64, line.start.y as f64);
    let (dx, dy) = (line.end.x as f64 - ax, line.end.y as f64 - ay);
    let (px, py) = (x as f64 - ax, y as f64 - ay);
    let len = (dx * dx + dy * dy).sqrt();
    let w = width as f64 / 2.0;
    if len == 0.0 {
        return w - px.abs().max(py.abs());
    }
    let u = (px * dx + py * dy) / len;
    let v = (px * dy - py * dx) / len;
    (u + 0.5).min(len + 0.5 - u).min(w - v.abs())
}

/// Asserts that the `size x size` window at `origin` shows the pixels of
/// the line's rectangle (those whose centre is inside it by more than
/// 1/1000 px lit, those outside by as much unlit), each at most once,
/// wherever the window is in the `i32` plane: past the 20.12 range too.
fn assert_thick(line: Line, width: u32, size: u32, origin: Point) {
    let d = thick_at(line, width, size, origin);
    for j in 0..size as i64 {
        for i in 0..size as i64 {
            let c = d.write_count(Point::new(i as i32, j as i32)).unwrap();
            let (x, y) = (i64::from(origin.x) + i, i64::from(origin.y) + j);
            assert!(c <= 1, "{line:?} w {width}: ({x}, {y}) written {c} times");
            let m = rect_margin(line, width, x, y);
            if m > 1e-3 {
                assert_eq!(
                    c, 1,
                    "{line:?} w {width}: ({x}, {y}) inside by {m} but unlit"
                );
            } else if m < -1e-3 {
                assert_eq!(
                    c, 0,
                    "{line:?} w {width}: ({x}, {y}) outside by {m} but lit"
                );
            }
        }
    }
}

proptest! {
    #[test]
    fn thick_lines_are_their_rectangle(
        c in prop::array::uniform4(-8i64..40),
        width in 2u32..12,
    ) {
        assert_thick(Line::new(p(c[0], c[1]), p(c[2], c[3])), width, 32, Point::zero());
    }

    #[test]
    fn thick_lines_far_away(
        line in prop_oneof![extreme_line(), any_line()],
        f in any::<u16>(),
        width in 2u32..9,
    ) {
        // The display placed on the part of the line near fraction f,
        // wherever it is in the `i32` plane: mostly past the 20.12 range.
        let win = window_on(line, f, (0, 0), (24, 24));
        let origin = Point::new(win.x0 as i32, win.y0 as i32);
        assert_thick(line, width, 24, origin);
        // A two-point thick polyline (a stroke, whose pieces past the
        // 20.12 range have their own exact path) is the same line.
        let ends = [line.start, line.end];
        let mut stroke = SimDisplay::new(24, 24, Gray8::BLACK);
        Polyline::new(&ends)
            .stroke(Gray8::WHITE)
            .stroke_width(width)
            .draw(&mut View { inner: &mut stroke, origin })
            .unwrap();
        let thick = thick_at(line, width, 24, origin);
        prop_assert_eq!(thick.pixels(), stroke.pixels());
        // And the line moved so that this part is at the origin, well
        // inside the range, where the move keeps both ends in `i32`.
        let shift = |q: Point| {
            let moved = (i64::from(q.x) - win.x0, i64::from(q.y) - win.y0);
            Some(Point::new(i32::try_from(moved.0).ok()?, i32::try_from(moved.1).ok()?))
        };
        if let (Some(a), Some(b)) = (shift(line.start), shift(line.end)) {
            assert_thick(Line::new(a, b), width, 24, Point::zero());
        }
    }
}

#[test]
fn thick_line_widths_and_caps() {
    let l = |a: (i32, i32), b: (i32, i32)| Line::new(Point::new(a.0, a.1), Point::new(b.0, b.1));
    let rows = |d: &SimDisplay<Gray8>, x: i32| {
        (0..32)
            .filter(|&y| d.write_count(Point::new(x, y)) == Some(1))
            .collect::<Vec<_>>()
    };
    // Odd widths centre on the line's row, even ones extend one more row up.
    assert_eq!(rows(&thick(l((2, 10), (20, 10)), 3, 32), 2), [9, 10, 11]);
    assert_eq!(
        rows(&thick(l((2, 10), (20, 10)), 4, 32), 20),
        [8, 9, 10, 11]
    );
    // Both end pixels covered whole, nothing beyond.
    let d = thick(l((20, 10), (2, 10)), 2, 32);
    assert_eq!(d.pixels_written(), 2 * 19);
    // Width 0 draws nothing, width 1 is the Bresenham line.
    assert_eq!(thick(l((2, 10), (20, 17)), 0, 32).pixels_written(), 0);
    assert_eq!(thick(l((2, 10), (20, 17)), 1, 32).pixels_written(), 19);
    // A zero-length thick line is a w x w square.
    assert_eq!(thick(l((9, 9), (9, 9)), 5, 32).pixels_written(), 25);
    // Across the whole i32 range, clipped before the triangles are built.
    let d = thick(l((i32::MIN, 5), (i32::MAX, 5)), 3, 32);
    assert_eq!((rows(&d, 0), rows(&d, 31)), (vec![4, 5, 6], vec![4, 5, 6]));
    assert_eq!(d.pixels_written(), 3 * 32);
}

#[test]
fn thick_lines_share_edges() {
    // Two parallel lines of width 10 whose rectangles touch along a side
    // through pixel centres: direction (3, 4) * 10, normal (-0.8, 0.6),
    // offset (-8, 6) = 10 normals.
    let a = Line::new(Point::new(12, 2), Point::new(42, 42));
    let b = Line::new(Point::new(4, 8), Point::new(34, 48));
    let mut d = SimDisplay::new(56, 56, Gray8::BLACK);
    for line in [a, b] {
        line.stroke(Gray8::WHITE)
            .stroke_width(10)
            .draw(&mut d)
            .unwrap();
    }
    // The union is the rectangle of width 10 around the shared side.
    let both = |x: i64, y: i64| {
        let (ma, mb) = (rect_margin(a, 10, x, y), rect_margin(b, 10, x, y));
        ma.max(mb)
    };
    let mut shared = 0;
    for y in 0..56 {
        for x in 0..56 {
            let c = d.write_count(Point::new(x as i32, y as i32)).unwrap();
            assert!(c <= 1, "({x}, {y}) written {c} times");
            let (ma, mb) = (rect_margin(a, 10, x, y), rect_margin(b, 10, x, y));
            if ma.abs() < 1e-9 && mb.abs() < 1e-9 {
                shared += 1; // a centre on the shared side: exactly one of them
                assert_eq!(c, 1);
            } else if both(x, y) > 1e-3 || (ma > -1e-3 && mb > -1e-3) {
                assert_eq!(c, 1, "gap at ({x}, {y})");
            }
        }
    }
    assert!(shared > 0, "the test should hit centres on the shared side");
}

/// Found by `thick_lines_far_away` in a CI run, when a thick line whose
/// corners left the 20.12 range had its centre line cut `w + 4` px short
/// of the range's ends: a thick line from near the origin to the far
/// corner of the `i32` plane, seen at the corner of the 20.12 range and
/// past it, where its pixels are its rectangle's as anywhere else.
#[test]
fn thick_line_at_the_range_corner() {
    let line = Line::new(
        Point::new(-1, 0),
        Point::new(-2_147_483_647, -2_147_483_646),
    );
    for corner in [-524_290, -524_280, -524_300] {
        assert_thick(line, 3, 24, Point::new(corner, corner));
    }
    assert_thick(line, 9, 24, Point::new(-2_147_483_000, -2_147_483_000));
}

/// The thick line's corners as its definition gives them (module docs of
/// `line`): `A - e + n, B + e + n, B + e - n, A - e - n` around the end
/// pixels' centres, with `e = d / (2 |d|)` and `n = (-d.y, d.x) w / (2
/// |d|)` each rounded to the nearest 1/4096 px (half away from zero), in
/// raw units. Written from the definition in exact integers.
fn exact_corners(line: Line, width: u32) -> [(i128, i128); 4] {
    let (dx, dy) = (
        i128::from(line.end.x) - i128::from(line.start.x),
        i128::from(line.end.y) - i128::from(line.start.y),
    );
    let w = i128::from(width);
    // round(c f / |d|) for f > 0, exactly: k = floor(|c| f / |d|), then up
    // iff |c| f / |d| >= k + 1/2, that is 4 (c f)^2 >= (2k + 1)^2 |d|^2.
    let len2 = (dx * dx + dy * dy) as u128;
    let scaled = |c: i128, f: i128| {
        let a = (c.unsigned_abs()) * f as u128;
        let k = (a * a / len2).isqrt();
        let k = if 4 * a * a >= (2 * k + 1) * (2 * k + 1) * len2 {
            k + 1
        } else {
            k
        };
        c.signum() * k as i128
    };
    let (e, n) = if len2 == 0 {
        ((2048 * w, 0), (0, 2048 * w))
    } else {
        (
            (scaled(dx, 2048), scaled(dy, 2048)),
            (-scaled(dy, 2048 * w), scaled(dx, 2048 * w)),
        )
    };
    let centre = |p: Point| (i128::from(p.x) * 4096 + 2048, i128::from(p.y) * 4096 + 2048);
    let (a, b) = (centre(line.start), centre(line.end));
    [
        (a.0 - e.0 + n.0, a.1 - e.1 + n.1),
        (b.0 + e.0 + n.0, b.1 + e.1 + n.1),
        (b.0 + e.0 - n.0, b.1 + e.1 - n.1),
        (a.0 - e.0 - n.0, a.1 - e.1 - n.1),
    ]
}

/// Whether the centre of pixel `(x, y)`, nudged by `(e, e^2)`, lies inside
/// the convex polygon `v` (the crate's sampling rule), exactly: on each
/// side, the sign of the cross product, or of its derivatives along the
/// nudge when the centre is on the side's line.
fn exact_lit(v: &[(i128, i128); 4], x: i64, y: i64) -> bool {
    let p = (i128::from(x) * 4096 + 2048, i128::from(y) * 4096 + 2048);
    let area: i128 = (0..4)
        .map(|i| {
            let (a, b) = (v[i], v[(i + 1) % 4]);
            a.0 * b.1 - a.1 * b.0
        })
        .sum();
    let o = area.signum();
    o != 0
        && (0..4).all(|i| {
            let (a, b) = (v[i], v[(i + 1) % 4]);
            let d = (b.0 - a.0, b.1 - a.1);
            // o cross(d, p + (e, e^2) - a) = f + e (-o d.y) + e^2 (o d.x).
            let f = o * (d.0 * (p.1 - a.1) - d.1 * (p.0 - a.0));
            match (f, -o * d.1, o * d.0) {
                (0, 0, g) => g > 0,
                (0, g, _) => g > 0,
                (f, _, _) => f > 0,
            }
        })
}

/// Thick lines from the screen to anywhere in the `i32` plane (most with
/// their corners past the 20.12 range), pixel for pixel against the exact
/// reference in a 40 x 40 display. Until 2026-12-06 a line whose corners
/// left the range had its centre line cut short and its corners worked
/// out again from the cut points, rounded: its sides moved by up to 1/8192
/// px, and about one such line in 300 had a pixel wrong on the screen.
#[test]
fn thick_lines_to_far_points_are_exact() {
    let mut rng = super::Rng(0x7F4A_7C15_9E37_79B9);
    let mut far = 0;
    for case in 0..3000 {
        let near = Point::new(rng.below(40) as i32, rng.below(40) as i32);
        let bits = 4 + rng.below(28) as u32;
        let mut coordinate = || (rng.next() >> (64 - bits)) as i32 - (1 << (bits - 1));
        let other = Point::new(coordinate(), coordinate());
        let line = if case % 2 == 0 {
            Line::new(near, other)
        } else {
            Line::new(other, near)
        };
        let width = 2 + rng.below(19) as u32;
        let corners = exact_corners(line, width);
        far += usize::from(
            corners
                .iter()
                .any(|c| i32::try_from(c.0).is_err() || i32::try_from(c.1).is_err()),
        );
        let d = thick(line, width, 40);
        for y in 0..40 {
            for x in 0..40 {
                let lit = d.write_count(Point::new(x as i32, y as i32)) == Some(1);
                assert_eq!(
                    lit,
                    exact_lit(&corners, x, y),
                    "{line:?} w {width}: ({x}, {y})"
                );
            }
        }
    }
    assert!(far > 1000, "{far} of 3000 past the 20.12 range");
}

/// A sink as tall as `Rectangle` allows (every `i32` row) and 64 px wide,
/// which keeps the pixels it is given (each at most once).
struct TallSink {
    lit: std::collections::BTreeMap<(i32, i32), u32>,
}

impl embedded_raster::SpanSink<Gray8> for TallSink {
    type Error = core::convert::Infallible;

    fn bounds(&self) -> embedded_graphics_core::primitives::Rectangle {
        embedded_graphics_core::primitives::Rectangle::new(
            Point::new(0, i32::MIN),
            Size::new(64, u32::MAX),
        )
    }

    fn fill_span(&mut self, span: embedded_raster::Span, _: Gray8) -> Result<(), Self::Error> {
        for x in span.x_start..span.x_end {
            *self.lit.entry((x, span.y)).or_default() += 1;
        }
        Ok(())
    }
}

/// Thick lines and thick polylines with ends far past the 20.12 range,
/// through a target 64 px wide and 2^32 rows tall: only the rows where
/// their pieces cross the target's columns are visited. Visiting all
/// 2^32 took minutes (before 2026-12-06: the thick lines' rows, and the
/// strokes' masked tiles; then, with tiles skipped only by the strokes'
/// whole reach, 55 s for four strokes running alongside the columns), so
/// the check runs under a watchdog of 30 s, against a few milliseconds.
/// The pixels are the exact reference's in each column, on the rows
/// around where the exact rectangle crosses it (found independently, in
/// `f64`), each written once, and none elsewhere.
#[test]
fn far_thick_lines_in_a_tall_target_visit_their_rows() {
    let (done, finished) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        far_thick_lines_in_a_tall_target();
        done.send(()).unwrap();
    });
    let waited = finished.recv_timeout(std::time::Duration::from_secs(30));
    assert!(
        !matches!(waited, Err(std::sync::mpsc::RecvTimeoutError::Timeout)),
        "not done in 30 s: rows visited beyond the lines' own"
    );
    // A panic in the check drops the sender: fail with it.
    waited.expect("the check panicked (see its message above)");
}

/// The check of [`far_thick_lines_in_a_tall_target_visit_their_rows`].
fn far_thick_lines_in_a_tall_target() {
    let lines = [
        Line::new(
            Point::new(-1_000_000_000, -333_000_000),
            Point::new(2_000_000_000, 666_000_000),
        ),
        Line::new(
            Point::new(i32::MIN, i32::MIN + 7),
            Point::new(i32::MAX, i32::MAX),
        ),
        Line::new(Point::new(-7_000_000, 5), Point::new(9_000_000, 17)),
    ];
    for (k, line) in lines.into_iter().enumerate() {
        let width = 3 + 4 * k as u32;
        let mut sink = TallSink {
            lit: Default::default(),
        };
        embedded_raster::SpanDrawable::draw_spans(
            &line.stroke(Gray8::WHITE).stroke_width(width),
            &mut sink,
        )
        .unwrap();
        assert!(!sink.lit.is_empty(), "{line:?}: nothing lit");
        assert!(
            sink.lit.values().all(|&n| n == 1),
            "{line:?}: a pixel written twice"
        );
        // In each column, the rows around where the exact rectangle
        // crosses the centres' vertical line (in f64, two rows of margin
        // either side) hold every pixel it lights there.
        let corners = exact_corners(line, width);
        let mut expected = 0;
        for x in 0..64i64 {
            let cx = (x * 4096 + 2048) as f64;
            let ys: Vec<f64> = (0..4)
                .filter_map(|i| {
                    let (a, b) = (corners[i], corners[(i + 1) % 4]);
                    let (ax, ay, bx, by) = (a.0 as f64, a.1 as f64, b.0 as f64, b.1 as f64);
                    let spans = ax.min(bx) <= cx && cx <= ax.max(bx) && ax != bx;
                    spans.then(|| ay + (cx - ax) * (by - ay) / (bx - ax))
                })
                .collect();
            let Some(ylo) = ys.iter().copied().reduce(f64::min) else {
                continue;
            };
            let yhi = ys.iter().copied().fold(ylo, f64::max);
            for y in (ylo / 4096.0).floor() as i64 - 2..=(yhi / 4096.0).ceil() as i64 + 2 {
                let lit = sink.lit.contains_key(&(x as i32, y as i32));
                let want = exact_lit(&corners, x, y);
                assert_eq!(lit, want, "{line:?} w {width}: ({x}, {y})");
                expected += usize::from(want);
            }
        }
        assert_eq!(sink.lit.len(), expected, "{line:?}: pixels lit elsewhere");
        // The same line as a two-point thick polyline, a stroke.
        let ends = [line.start, line.end];
        let mut stroke = TallSink {
            lit: Default::default(),
        };
        let polyline = Polyline::new(&ends)
            .stroke(Gray8::WHITE)
            .stroke_width(width);
        embedded_raster::SpanDrawable::draw_spans(&polyline, &mut stroke).unwrap();
        assert_eq!(stroke.lit, sink.lit, "{line:?}: the stroke");
    }
    // Strokes running the target's whole height alongside its columns,
    // reaching within a few pixels of them but lighting none: every tile
    // of theirs is empty.
    for (x, width) in [(-3, 2), (-3, 5), (-40_000, 65535), (70, 8)] {
        let points = [Point::new(x, i32::MIN), Point::new(x, i32::MAX)];
        let polyline = Polyline::new(&points)
            .stroke(Gray8::WHITE)
            .stroke_width(width);
        let mut stroke = TallSink {
            lit: Default::default(),
        };
        embedded_raster::SpanDrawable::draw_spans(&polyline, &mut stroke).unwrap();
        assert!(stroke.lit.is_empty(), "x = {x}, w {width}: lit");
    }
}
