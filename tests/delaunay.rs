//! Delaunay triangulation against the independent checker in
//! `delaunay/check.rs`: every input point a vertex, the hull covered
//! exactly once (by edges, and by rasterized pixels against the reference
//! fill of the hull), empty circumcircles, `2n - h - 2` triangles.

#[path = "delaunay/check.rs"]
mod check;
// The point-file command line: the simulator's.
#[cfg(feature = "sim")]
#[path = "delaunay/cli.rs"]
mod cli;
mod common;

use check::Pt;
use common::{add_spans, reference_polygon, Grid};
use embedded_raster::delaunay::{Delaunay, DelaunayError};
use embedded_raster::Vertex;
use proptest::prelude::*;

const CAP: usize = 1100;

fn raw(v: Vertex) -> Pt {
    let (x, y) = v.raw();
    (i64::from(x), i64::from(y))
}

fn px(x: f64, y: f64) -> Vertex {
    Vertex::try_from_num(x, y).unwrap()
}

/// Triangulates, checks everything, and returns the index triangles.
fn triangulate_and_check(points: &[Vertex]) -> Vec<[usize; 3]> {
    let mut delaunay = Box::new(Delaunay::<CAP>::new());
    let mesh = delaunay.triangulate(points).unwrap();
    let indices: Vec<[usize; 3]> = mesh.indices().collect();
    assert_eq!(mesh.len(), indices.len());
    let shapes: Vec<_> = mesh.triangles().collect();
    assert_eq!(shapes.len(), indices.len());
    let pts: Vec<Pt> = points.iter().map(|&v| raw(v)).collect();
    let tris: Vec<[Pt; 3]> = indices.iter().map(|t| t.map(|i| pts[i])).collect();
    for (t, shape) in tris.iter().zip(&shapes) {
        assert!(
            check::cross(t[0], t[1], t[2]) > 0,
            "{t:?} is not clockwise on screen"
        );
        assert_eq!(shape.vertices.map(raw), *t);
    }
    // Duplicates: the lowest index is the vertex.
    for t in &indices {
        for &i in t {
            assert!(
                !points[..i].contains(&points[i]),
                "index {i} repeats an earlier point"
            );
        }
    }
    let hull = check::check(&pts, &tris);
    check_pixels(&hull, &shapes);
    indices
}

/// When the hull fits a window of at most 600 x 600 px: the triangles'
/// pixels, counted, equal the reference fill of the hull (1 inside, 0
/// outside): no gap, no overdraw.
fn check_pixels(hull: &[Pt], shapes: &[embedded_raster::Triangle]) {
    if hull.is_empty() {
        return;
    }
    let lo = |f: fn(&Pt) -> i64| hull.iter().map(f).min().unwrap().div_euclid(4096) - 1;
    let hi = |f: fn(&Pt) -> i64| hull.iter().map(f).max().unwrap().div_euclid(4096) + 2;
    let (x0, y0) = (lo(|p| p.0), lo(|p| p.1));
    let (w, h) = ((hi(|p| p.0) - x0) as usize, (hi(|p| p.1) - y0) as usize);
    if w > 600 || h > 600 {
        return;
    }
    let mut got = Grid::new(x0, y0, w, h);
    for t in shapes {
        add_spans(t, &mut got);
    }
    let outline: Vec<Vertex> = hull
        .iter()
        .map(|&(x, y)| Vertex::from_raw(x as i32, y as i32))
        .collect();
    let want = reference_polygon(&outline, x0, y0, w, h);
    let d = got.diff(&want);
    assert!(
        d.is_empty(),
        "{} pixels differ from the hull fill (x, y, got, want): {:?}",
        d.len(),
        &d[..d.len().min(10)]
    );
}

/// A linear congruential generator: `next(m)` is in `0..m`.
fn lcg(mut seed: u64) -> impl FnMut(u64) -> u64 {
    move |m| {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 33) % m
    }
}

fn grid(cols: usize, rows: usize, step: f64) -> Vec<Vertex> {
    (0..rows)
        .flat_map(|j| (0..cols).map(move |i| px(3.0 + i as f64 * step, 3.0 + j as f64 * step)))
        .collect()
}

#[test]
fn fewer_than_three_points_give_no_triangles() {
    for points in [vec![], vec![px(1.0, 1.0)], vec![px(1.0, 1.0), px(5.0, 2.0)]] {
        assert!(triangulate_and_check(&points).is_empty());
    }
}

#[test]
fn one_triangle() {
    let t = triangulate_and_check(&[px(0.0, 0.0), px(10.0, 0.0), px(3.0, 7.0)]);
    assert_eq!(t.len(), 1);
}

#[test]
fn collinear_sets_give_no_triangles() {
    let diagonal: Vec<_> = (0..50)
        .map(|k| px(k as f64 * 1.5, k as f64 * 0.75))
        .collect();
    assert!(triangulate_and_check(&diagonal).is_empty());
    let vertical: Vec<_> = (0..20).rev().map(|k| px(7.0, k as f64)).collect();
    assert!(triangulate_and_check(&vertical).is_empty());
    let with_duplicates = [px(0.0, 0.0), px(1.0, 1.0), px(0.0, 0.0), px(2.0, 2.0)];
    assert!(triangulate_and_check(&with_duplicates).is_empty());
}

#[test]
fn collinear_run_plus_one_point() {
    let mut points: Vec<_> = (0..40).map(|k| px(5.0 + k as f64 * 7.0, 100.0)).collect();
    points.push(px(140.0, 20.0));
    // Every point of the run is on the hull: 2n - h - 2 = n - 2.
    assert_eq!(triangulate_and_check(&points).len(), 39);
    points.push(px(140.0, 180.0));
    triangulate_and_check(&points);
}

#[test]
fn collinear_runs_inside_and_on_the_hull() {
    let mut points = vec![];
    for k in 0..30 {
        let t = k as f64 * 10.0;
        points.push(px(t, 0.0)); // a hull side
        points.push(px(t, t)); // a diagonal through the interior
        points.push(px(150.0, t)); // a vertical line through the middle
    }
    points.push(px(0.0, 290.0));
    triangulate_and_check(&points);
}

#[test]
fn square_grids_are_cocircular_everywhere() {
    for (cols, rows) in [(2, 2), (3, 3), (10, 7), (32, 32)] {
        let t = triangulate_and_check(&grid(cols, rows, 8.0));
        assert_eq!(t.len(), 2 * (cols - 1) * (rows - 1));
    }
}

#[test]
fn grid_result_does_not_depend_on_point_order() {
    let points = grid(9, 9, 5.0);
    let mut reversed = points.clone();
    reversed.reverse();
    let shape = |p: &[Vertex]| {
        let mut d = Box::new(Delaunay::<CAP>::new());
        let mut ts: Vec<Vec<Pt>> = d
            .triangulate(p)
            .unwrap()
            .indices()
            .map(|t| {
                let mut v: Vec<Pt> = t.iter().map(|&i| raw(p[i])).collect();
                v.sort();
                v
            })
            .collect();
        ts.sort();
        ts
    };
    assert_eq!(shape(&points), shape(&reversed));
}

#[test]
fn points_on_a_circle_and_its_centre() {
    for n in [3, 4, 5, 8, 12, 64, 200] {
        let mut points: Vec<_> = (0..n)
            .map(|k| {
                let a = std::f64::consts::TAU * k as f64 / n as f64;
                px(200.0 + 150.0 * a.cos(), 200.0 + 150.0 * a.sin())
            })
            .collect();
        triangulate_and_check(&points);
        points.push(px(200.0, 200.0));
        triangulate_and_check(&points);
    }
    // Exactly cocircular: the 12 lattice points on the circle of radius 5.
    let ring: Vec<_> = (-5..=5i32)
        .flat_map(|x| (-5..=5i32).map(move |y| (x, y)))
        .filter(|(x, y)| x * x + y * y == 25)
        .map(|(x, y)| px(50.0 + 8.0 * x as f64, 50.0 + 8.0 * y as f64))
        .collect();
    assert_eq!(ring.len(), 12);
    assert_eq!(triangulate_and_check(&ring).len(), 10);
}

#[test]
fn clusters_far_apart() {
    let mut points = vec![];
    let mut lcg = lcg(12345);
    let mut next = || lcg(1 << 31) as f64 / (1u64 << 31) as f64;
    for (cx, cy) in [
        (10.0, 10.0),
        (500.0, 20.0),
        (250.0, 450.0),
        (-300000.0, 400000.0),
    ] {
        for _ in 0..40 {
            points.push(px(cx + next() * 0.01, cy + next() * 0.01));
        }
    }
    triangulate_and_check(&points);
}

#[test]
fn extremes_of_the_range() {
    let (lo, hi) = (i32::MIN, i32::MAX);
    let v = Vertex::from_raw;
    let corners = [v(lo, lo), v(hi, lo), v(hi, hi), v(lo, hi)];
    assert_eq!(triangulate_and_check(&corners).len(), 2);
    let mut points = corners.to_vec();
    points.extend([
        v(0, 0),
        v(1, 0),
        v(0, 1),
        v(hi, 0),
        v(lo, 7),
        v(hi - 1, hi),
        v(lo + 1, lo),
    ]);
    triangulate_and_check(&points);
    // Nearly collinear across the whole range.
    triangulate_and_check(&[v(lo, lo), v(hi, hi), v(hi, hi - 1), v(0, 0), v(1, 0)]);
}

#[test]
fn duplicates_are_kept_once() {
    let mut points = grid(5, 5, 10.0);
    points.extend(grid(5, 5, 10.0));
    points.extend(grid(3, 3, 10.0));
    let t = triangulate_and_check(&points);
    assert_eq!(t.len(), 32);
    assert!(t.iter().flatten().all(|&i| i < 25));
}

#[test]
fn thousand_random_points() {
    let mut next = lcg(7);
    let points: Vec<_> = (0..1000)
        .map(|_| Vertex::from_raw(next(320 * 4096) as i32, next(240 * 4096) as i32))
        .collect();
    triangulate_and_check(&points);
}

#[test]
fn the_most_points_a_triangulation_holds() {
    use embedded_raster::delaunay::MAX_POINTS;
    let mut next = lcg(99);
    // 2000 x 2000 px on a 1/16 px lattice: some duplicates.
    let points: Vec<_> = (0..MAX_POINTS)
        .map(|_| Vertex::from_raw(next(32000) as i32 * 256, next(32000) as i32 * 256))
        .collect();
    let mut delaunay = Box::new(Delaunay::<MAX_POINTS>::new());
    let mesh = delaunay.triangulate(&points).unwrap();
    let pts: Vec<Pt> = points.iter().map(|&v| raw(v)).collect();
    let tris: Vec<[Pt; 3]> = mesh.indices().map(|t| t.map(|i| pts[i])).collect();
    check::check(&pts, &tris);
}

#[test]
fn capacity_error_leaves_the_previous_triangulation() {
    let points = grid(3, 3, 10.0);
    let mut delaunay = Delaunay::<9>::new();
    let before: Vec<_> = delaunay.triangulate(&points).unwrap().indices().collect();
    let too_many = grid(4, 3, 10.0);
    assert_eq!(
        delaunay.triangulate(&too_many).unwrap_err(),
        DelaunayError::CapacityExceeded {
            needed: 12,
            capacity: 9
        }
    );
    let after: Vec<_> = delaunay.triangulation(&points).indices().collect();
    assert_eq!(before, after);
    assert_eq!(delaunay.len(), 8);
}

#[test]
fn capacity_counts_duplicates_and_exact_fit_works() {
    let mut delaunay = Delaunay::<4>::new();
    let four = [px(0.0, 0.0), px(4.0, 0.0), px(0.0, 4.0), px(4.0, 4.0)];
    assert_eq!(delaunay.triangulate(&four).unwrap().len(), 2);
    let five_with_duplicate = [four[0], four[1], four[2], four[3], four[0]];
    assert!(delaunay.triangulate(&five_with_duplicate).is_err());
}

fn any_points(range: i64, max_len: usize) -> impl Strategy<Value = Vec<Vertex>> {
    prop::collection::vec((0..range, 0..range), 0..max_len).prop_map(|v| {
        v.into_iter()
            .map(|(x, y)| Vertex::from_raw(x as i32, y as i32))
            .collect()
    })
}

fn any_extreme_points() -> impl Strategy<Value = Vec<Vertex>> {
    let coordinate = prop_oneof![
        Just(i32::MIN),
        Just(i32::MAX),
        Just(0),
        any::<i32>(),
        -3..3i32
    ];
    prop::collection::vec((coordinate.clone(), coordinate), 0..24)
        .prop_map(|v| v.into_iter().map(|(x, y)| Vertex::from_raw(x, y)).collect())
}

proptest! {
    #[test]
    fn random_points_in_a_screen(points in any_points(300 * 4096, 80)) {
        triangulate_and_check(&points);
    }

    #[test]
    fn random_points_on_a_small_lattice(points in any_points(6, 40).prop_map(|v| v.into_iter().map(|p| { let (x, y) = p.raw(); Vertex::from_raw(x * 4096, y * 4096) }).collect::<Vec<_>>())) {
        // Many duplicates, collinear runs and cocircular quadruples.
        triangulate_and_check(&points);
    }

    #[test]
    fn random_points_anywhere_in_the_range(points in any_extreme_points()) {
        triangulate_and_check(&points);
    }
}
