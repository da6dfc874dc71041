//! Thick lines: their rectangle, shared edges, the whole range.

use embedded_graphics_core::{pixelcolor::Gray8, prelude::*};
use embedded_raster::{sim::SimDisplay, Line};
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

/// The 20.12 range of pixels, outside which thick lines light nothing
/// (`Line::new`).
const THICK_RANGE: core::ops::RangeInclusive<i64> = -524_288..=524_287;

/// Asserts that the `size x size` window at `origin` shows the pixels of
/// the line's rectangle (those whose centre is inside it by more than
/// 1/1000 px lit, those outside by as much unlit), none outside the 20.12
/// range, each at most once. A line with an end within `w + 4` px of the
/// range's ends or past them may have its centre line cut short there
/// (`Line::new`'s documented limit): its pixels that close to the range's
/// ends need not be lit, and are only checked to be unlit outside the
/// rectangle.
fn assert_thick(line: Line, width: u32, size: u32, origin: Point) {
    let d = thick_at(line, width, size, origin);
    let margin = i64::from(width) + 4;
    let (near_lo, near_hi) = (THICK_RANGE.start() + margin, THICK_RANGE.end() - margin);
    let near_end = |v: i64| v < near_lo || v > near_hi;
    let cut = [line.start, line.end]
        .iter()
        .any(|q| near_end(q.x.into()) || near_end(q.y.into()));
    for j in 0..size as i64 {
        for i in 0..size as i64 {
            let c = d.write_count(Point::new(i as i32, j as i32)).unwrap();
            let (x, y) = (i64::from(origin.x) + i, i64::from(origin.y) + j);
            assert!(c <= 1, "{line:?} w {width}: ({x}, {y}) written {c} times");
            if !THICK_RANGE.contains(&x) || !THICK_RANGE.contains(&y) {
                assert_eq!(
                    c, 0,
                    "{line:?} w {width}: ({x}, {y}) lit past the 20.12 range"
                );
                continue;
            }
            let m = rect_margin(line, width, x, y);
            if m > 1e-3 && !(cut && (near_end(x) || near_end(y))) {
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
        // wherever it is in the `i32` plane: mostly past the 20.12 range,
        // where nothing may be lit.
        let win = window_on(line, f, (0, 0), (24, 24));
        assert_thick(line, width, 24, Point::new(win.x0 as i32, win.y0 as i32));
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

/// Found by `thick_lines_far_away` in a CI run: a thick line from near the
/// origin to the far corner of the `i32` plane, seen at the corner of the
/// 20.12 range. Its centre line is cut `w + 4` px short of the range's
/// ends (the documented limit), and its pixels there are unlit; past that
/// margin, along the same line, they are its rectangle's.
#[test]
fn thick_line_cut_at_the_range_corner() {
    let line = Line::new(
        Point::new(-1, 0),
        Point::new(-2_147_483_647, -2_147_483_646),
    );
    assert_thick(line, 3, 24, Point::new(-524_290, -524_290));
    assert_thick(line, 3, 24, Point::new(-524_280, -524_280));
}
