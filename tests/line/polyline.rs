//! Polylines: every pixel written once, joints included.

use embedded_graphics_core::{pixelcolor::Gray8, prelude::*};
use embedded_raster::{sim::SimDisplay, Polyline};
use proptest::prelude::*;

use super::{p, reference, Window};

/// Draws `points` on a fresh display and returns it.
fn polyline_display(points: &[Point], size: u32) -> SimDisplay<Gray8> {
    let mut d = SimDisplay::new(size, size, Gray8::BLACK);
    Polyline::new(points)
        .stroke(Gray8::WHITE)
        .draw(&mut d)
        .unwrap();
    assert_eq!(d.out_of_bounds_writes(), 0);
    d
}

/// The union of the exact pixels of every segment, in the display.
fn union_of_segments(points: &[Point], size: i64) -> Vec<(i64, i64)> {
    let win = Window {
        x0: 0,
        y0: 0,
        w: size,
        h: size,
    };
    let mut all: Vec<_> = points
        .windows(2)
        .flat_map(|w| reference(w[0], w[1], win))
        .collect();
    if points.len() == 1 {
        all = reference(points[0], points[0], win);
    }
    all.sort();
    all.dedup();
    all
}

fn lit(d: &SimDisplay<Gray8>, size: i64) -> (Vec<(i64, i64)>, u32) {
    let mut out = vec![];
    let mut max = 0;
    for y in 0..size {
        for x in 0..size {
            let c = d.write_count(Point::new(x as i32, y as i32)).unwrap();
            max = max.max(c);
            if c > 0 {
                out.push((x, y));
            }
        }
    }
    out.sort();
    (out, max)
}

proptest! {
    #[test]
    fn polyline_joints_written_once(
        steps in prop::collection::vec((1i64..12, -11i64..=11), 1..8),
        start in (0i64..8, 20i64..40),
        transpose in any::<bool>(),
    ) {
        // x-major segments with x strictly growing never overlap, so every
        // pixel, joints included, must be written exactly once.
        let mut pts = vec![start];
        for (dx, dy) in steps {
            let last = *pts.last().unwrap();
            let dy = dy.clamp(-dx, dx);
            pts.push((last.0 + dx, last.1 + dy));
        }
        let points: Vec<Point> = pts
            .iter()
            .map(|&(x, y)| if transpose { p(y, x) } else { p(x, y) })
            .collect();
        let d = polyline_display(&points, 100);
        let (got, max) = lit(&d, 100);
        prop_assert_eq!(max, 1, "{:?}", points);
        prop_assert_eq!(got, union_of_segments(&points, 100));
        prop_assert_eq!(d.write_stats().draw_iter_pixels, 0);
    }
}

#[test]
fn closed_and_degenerate_polylines() {
    let pt = |x, y| Point::new(x, y);
    // A closed square outline: 4 * 18 pixels, each once.
    let square = [pt(2, 2), pt(20, 2), pt(20, 20), pt(2, 20), pt(2, 2)];
    let d = polyline_display(&square, 32);
    let (got, max) = lit(&d, 32);
    assert_eq!((got.len(), max), (72, 1));
    assert_eq!(got, union_of_segments(&square, 32));
    // A closed triangle with sloped sides.
    let tri = [pt(3, 3), pt(28, 9), pt(11, 27), pt(3, 3)];
    let (got, max) = lit(&polyline_display(&tri, 32), 32);
    assert_eq!(max, 1);
    assert_eq!(got, union_of_segments(&tri, 32));
    // Repeated points, a single point, all points equal, none.
    let rep = [pt(1, 1), pt(1, 1), pt(9, 4), pt(9, 4), pt(9, 4), pt(15, 30)];
    let (got, max) = lit(&polyline_display(&rep, 32), 32);
    assert_eq!((max, got), (1, union_of_segments(&rep, 32)));
    for pts in [&[pt(5, 6)][..], &[pt(5, 6), pt(5, 6), pt(5, 6)][..]] {
        let (got, max) = lit(&polyline_display(pts, 32), 32);
        assert_eq!((got, max), (vec![(5, 6)], 1));
    }
    assert_eq!(lit(&polyline_display(&[], 32), 32).1, 0);
    // Far off-screen segments at the extremes.
    let far = [
        pt(i32::MIN, i32::MIN),
        pt(i32::MAX, i32::MAX),
        pt(i32::MIN, i32::MAX),
        pt(31, 0),
    ];
    let d = polyline_display(&far, 32);
    assert_eq!(lit(&d, 32).1, 1);
    assert_eq!(lit(&d, 32).0, union_of_segments(&far, 32));
}
