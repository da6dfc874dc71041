//! Polygons against the exact reference in `common`, triangulation against
//! the scanline fill, and the simplicity and convexity tests against
//! brute-force checks written here with a different method.

mod common;

use common::{add_spans_from, assert_same, reference_fill, Grid};
use embedded_graphics_core::{
    geometry::{Point, Size},
    pixelcolor::Rgb565,
    prelude::*,
    primitives::Rectangle,
};
use embedded_raster::{FillRule, Polygon, PolygonError, Vertex};
use proptest::prelude::*;

const CAP: usize = 24;
const MIN: i64 = i32::MIN as i64;
const MAX: i64 = i32::MAX as i64;

fn v(x: i64, y: i64) -> Vertex {
    Vertex::from_raw(x.clamp(MIN, MAX) as i32, y.clamp(MIN, MAX) as i32)
}

fn rule(even_odd: bool) -> FillRule {
    if even_odd {
        FillRule::EvenOdd
    } else {
        FillRule::NonZero
    }
}

/// The scanline fill of `poly` on a window.
fn scanline(poly: &[Vertex], even_odd: bool, x0: i64, y0: i64, w: usize, h: usize) -> Grid {
    let mut g = Grid::new(x0, y0, w, h);
    let p = Polygon::<CAP>::new(poly).unwrap();
    add_spans_from::<core::convert::Infallible>(&mut g, |clip, f| {
        p.for_each_span(rule(even_odd), clip, f)
    });
    g
}

/// The triangulated fill: every triangle's spans added up.
fn triangulated(poly: &[Vertex], x0: i64, y0: i64, w: usize, h: usize) -> Grid {
    let mut g = Grid::new(x0, y0, w, h);
    Polygon::<CAP>::new(poly)
        .unwrap()
        .triangulate(|t| common::add_spans(&t, &mut g))
        .unwrap();
    g
}

prop_compose! {
    /// Any polygon (mostly self-intersecting) of 3 to 12 vertices, at a
    /// scale from a few pixels to the whole range, and a window on it.
    fn any_polygon()(
        n in 3usize..=12,
        scale in 0usize..5,
        c in (any::<i32>(), any::<i32>()),
        d in prop::collection::vec((any::<i64>(), any::<i64>()), 12),
        focus in 0usize..12,
    ) -> (Vec<Vertex>, (i64, i64)) {
        let r = [1i64 << 15, 1 << 17, 1 << 20, 1 << 26, 1 << 32][scale];
        let (cx, cy) = if scale == 4 { (0, 0) } else { (i64::from(c.0), i64::from(c.1)) };
        let poly: Vec<Vertex> = d[..n]
            .iter()
            .map(|&(x, y)| v(cx + x.rem_euclid(2 * r + 1) - r, cy + y.rem_euclid(2 * r + 1) - r))
            .collect();
        let (fx, fy) = poly[focus % n].raw();
        (poly, (i64::from(fx) >> 12, i64::from(fy) >> 12))
    }
}

prop_compose! {
    /// Vertices on a half-pixel grid: edges through pixel centres, many
    /// horizontal and vertical edges, repeated vertices.
    fn grid_polygon()(n in 3usize..=10, c in prop::collection::vec((-12i64..=12, -12i64..=12), 10)) -> Vec<Vertex> {
        c[..n].iter().map(|&(x, y)| v(x * 2048, y * 2048)).collect()
    }
}

prop_compose! {
    /// A simple polygon: star-shaped around a centre, vertices by angle
    /// with random radii (so usually concave), optionally snapped to a
    /// half-pixel grid (ties).
    fn simple_polygon()(
        n in 3usize..=16,
        centre in (-(1i64 << 17)..(1 << 17), -(1i64 << 17)..(1 << 17)),
        radius in (3i64 << 12)..(30i64 << 12),
        jitter in prop::collection::vec((-30i32..=30, 15i32..=100), 16),
        snap in any::<bool>(),
    ) -> Vec<Vertex> {
        let snap_to = |p: i64| if snap { (p + 1024).div_euclid(2048) * 2048 } else { p };
        let poly: Vec<Vertex> = (0..n)
            .map(|k| {
                let step = std::f64::consts::TAU / n as f64;
                let angle = step * (k as f64 + f64::from(jitter[k].0) / 100.0);
                let r = radius as f64 * f64::from(jitter[k].1) / 100.0;
                v(snap_to(centre.0 + (r * angle.cos()) as i64), snap_to(centre.1 + (r * angle.sin()) as i64))
            })
            .collect();
        poly
    }
}

prop_compose! {
    /// A convex polygon: vertices at increasing angles on an ellipse
    /// (clockwise or counter-clockwise on screen), from 4 px to 2^16 px
    /// across anywhere in the range; optionally snapped to the half-pixel
    /// grid (ties, level and upright edges, and sometimes a corner that no
    /// longer turns the right way) or with edges split at their midpoints
    /// (corners that go straight). Returns the polygon and whether it is
    /// convex by construction (not snapped).
    fn convex_polygon()(
        n in 3usize..=12,
        centre in (-(1i64 << 30)..(1 << 30), -(1i64 << 30)..(1 << 30)),
        scale in 0usize..4,
        cuts in prop::collection::vec(100u32..1000, 12),
        start in 0.0f64..1.0,
        squash in 1.0f64..2.0,
        clockwise in any::<bool>(),
        snap in any::<bool>(),
        split in any::<bool>(),
    ) -> (Vec<Vertex>, bool) {
        let r = [4.0 * 4096.0, 20.0 * 4096.0, 300.0 * 4096.0, 65536.0 * 4096.0][scale];
        let total: u32 = cuts[..n].iter().sum();
        let mut angle = start * std::f64::consts::TAU;
        let mut corners: Vec<(i64, i64)> = cuts[..n]
            .iter()
            .map(|&c| {
                angle += std::f64::consts::TAU * f64::from(c) / f64::from(total);
                let turn = if clockwise { angle } else { -angle };
                (centre.0 + (r * turn.cos()) as i64, centre.1 + (r * turn.sin() / squash) as i64)
            })
            .collect();
        if snap {
            for c in &mut corners {
                *c = ((c.0 + 1024).div_euclid(2048) * 2048, (c.1 + 1024).div_euclid(2048) * 2048);
            }
        }
        if split {
            let mut with = Vec::new();
            for k in 0..corners.len() {
                let (a, b) = (corners[k], corners[(k + 1) % corners.len()]);
                with.push(a);
                if (a.0 + b.0) % 2 == 0 && (a.1 + b.1) % 2 == 0 {
                    with.push(((a.0 + b.0) / 2, (a.1 + b.1) / 2));
                }
            }
            corners = with;
        }
        (corners.iter().map(|&(x, y)| v(x, y)).collect(), !snap)
    }
}

prop_compose! {
    /// A y-monotone polygon, usually concave and often self-intersecting:
    /// down one chain of random x at increasing y, back up another (the
    /// chains may cross), at a scale from a few pixels to 2^16 px, with
    /// level steps and shared heights.
    fn monotone_polygon()(
        down in prop::collection::vec((-64i64..64, 0i64..6), 1..6),
        up in prop::collection::vec((-64i64..64, 0i64..6), 1..6),
        top in (-64i64..64, -64i64..64),
        unit in prop_oneof![Just(1i64 << 10), Just(1i64 << 12), Just(3001i64), Just(1i64 << 24)],
        centre in (-(1i64 << 28)..(1 << 28), -(1i64 << 28)..(1 << 28)),
    ) -> Vec<Vertex> {
        let at = |x: i64, y: i64| v(centre.0 + x * unit / 4, centre.1 + y * unit / 4);
        let mut poly = vec![at(top.0, top.1)];
        let (mut y, mut bottom) = (top.1, top.1);
        for &(x, dy) in &down {
            y += dy;
            poly.push(at(x, y));
            bottom = y;
        }
        // Up the other chain, from its own bottom at or above this one.
        let mut ys: Vec<i64> = up.iter().scan(top.1, |y, &(_, dy)| { *y += dy; Some((*y).min(bottom)) }).collect();
        ys.reverse();
        for (&(x, _), y) in up.iter().zip(ys) {
            poly.push(at(x, y));
        }
        poly
    }
}

proptest! {
    #[test]
    fn scanline_is_exact_for_any_polygon((poly, (fx, fy)) in any_polygon(), even_odd in any::<bool>(), w in 1usize..40, h in 1usize..40) {
        let (x0, y0) = (fx - w as i64 / 2, fy - h as i64 / 2);
        assert_same(&scanline(&poly, even_odd, x0, y0, w, h), &reference_fill(&poly, even_odd, x0, y0, w, h), &format!("{poly:?}"));
    }

    /// Convex polygons, which take the two-chain walk rather than the edge
    /// table, against the reference, in a window on one of their corners
    /// (cut by it) and one around the whole polygon when it is small.
    #[test]
    fn convex_polygons_are_exact((poly, convex) in convex_polygon(), even_odd in any::<bool>(), corner in 0usize..24, w in 1usize..40, h in 1usize..40) {
        let p = Polygon::<CAP>::new(&poly).unwrap();
        if convex {
            prop_assert!(p.is_convex(), "{:?}", poly);
        }
        let (fx, fy) = poly[corner % poly.len()].raw();
        let (x0, y0) = ((i64::from(fx) >> 12) - w as i64 / 2, (i64::from(fy) >> 12) - h as i64 / 2);
        assert_same(&scanline(&poly, even_odd, x0, y0, w, h), &reference_fill(&poly, even_odd, x0, y0, w, h), &format!("{poly:?}"));
        let (lo, hi) = poly.iter().map(|c| c.raw()).fold(((i32::MAX, i32::MAX), (i32::MIN, i32::MIN)), |(lo, hi), (x, y)| ((lo.0.min(x), lo.1.min(y)), (hi.0.max(x), hi.1.max(y))));
        let (x0, y0) = (i64::from(lo.0 >> 12) - 1, i64::from(lo.1 >> 12) - 1);
        let (w, h) = ((i64::from(hi.0 >> 12) - x0 + 2) as usize, (i64::from(hi.1 >> 12) - y0 + 2) as usize);
        if w.checked_mul(h).is_some_and(|area| area <= 4096) {
            assert_same(&scanline(&poly, even_odd, x0, y0, w, h), &reference_fill(&poly, even_odd, x0, y0, w, h), &format!("whole {poly:?}"));
        }
    }

    /// Y-monotone polygons (two-chain walk with unordered sides) against
    /// the reference, in a window on one of their corners.
    #[test]
    fn monotone_polygons_are_exact(poly in monotone_polygon(), even_odd in any::<bool>(), corner in 0usize..12, w in 1usize..48, h in 1usize..48) {
        let (fx, fy) = poly[corner % poly.len()].raw();
        let (x0, y0) = ((i64::from(fx) >> 12) - w as i64 / 2, (i64::from(fy) >> 12) - h as i64 / 2);
        assert_same(&scanline(&poly, even_odd, x0, y0, w, h), &reference_fill(&poly, even_odd, x0, y0, w, h), &format!("{poly:?}"));
    }

    #[test]
    fn scanline_is_exact_far_off_screen((poly, _) in any_polygon(), even_odd in any::<bool>()) {
        assert_same(&scanline(&poly, even_odd, 0, 0, 32, 24), &reference_fill(&poly, even_odd, 0, 0, 32, 24), &format!("{poly:?}"));
    }

    #[test]
    fn scanline_is_exact_on_the_half_pixel_grid(poly in grid_polygon(), even_odd in any::<bool>()) {
        assert_same(&scanline(&poly, even_odd, -8, -8, 16, 16), &reference_fill(&poly, even_odd, -8, -8, 16, 16), &format!("{poly:?}"));
    }

    #[test]
    fn scanline_is_exact_at_the_ends_of_the_range(k in prop::collection::vec((0usize..5, 0usize..5), 3..8), even_odd in any::<bool>(), corner in 0usize..5) {
        const E: [i64; 5] = [MIN, MIN + 1, 0, MAX - 1, MAX];
        let poly: Vec<Vertex> = k.iter().map(|&(i, j)| v(E[i], E[j])).collect();
        let (x0, y0) = [(-(1 << 19), -(1 << 19)), ((1 << 19) - 12, -(1 << 19)), (-(1 << 19), (1 << 19) - 12), ((1 << 19) - 12, (1 << 19) - 12), (-6, -6)][corner];
        assert_same(&scanline(&poly, even_odd, x0, y0, 12, 12), &reference_fill(&poly, even_odd, x0, y0, 12, 12), &format!("{poly:?}"));
    }

    /// For a simple polygon, the triangulated fill lights exactly the
    /// scanline fill's pixels, each once, under either rule.
    #[test]
    fn triangulation_matches_the_scanline_fill(poly in simple_polygon()) {
        prop_assume!(Polygon::<CAP>::new(&poly).unwrap().is_simple());
        let (cx, cy) = poly[0].raw();
        let (x0, y0) = ((i64::from(cx) >> 12) - 40, (i64::from(cy) >> 12) - 40);
        let tri = triangulated(&poly, x0, y0, 80, 80);
        assert_same(&tri, &scanline(&poly, false, x0, y0, 80, 80), &"non-zero");
        assert_same(&tri, &scanline(&poly, true, x0, y0, 80, 80), &"even-odd");
        assert_same(&tri, &reference_fill(&poly, false, x0, y0, 80, 80), &"reference");
    }

    #[test]
    fn simplicity_and_convexity_match_brute_force(poly in prop_oneof![grid_polygon(), simple_polygon()]) {
        let p = Polygon::<CAP>::new(&poly).unwrap();
        let simple = brute::is_simple(&poly);
        prop_assert_eq!(p.is_simple(), simple, "{:?}", poly);
        prop_assert_eq!(p.is_convex(), simple && brute::is_convex(&poly), "{:?}", poly);
    }

    /// Triangulation refuses exactly the polygons that are not simple, and
    /// cuts the simple ones (on a half-pixel grid: collinear vertices,
    /// horizontal and vertical edges, ties) into at most `n - 2` triangles
    /// that light the reference's pixels, each once.
    #[test]
    fn triangulation_needs_a_simple_polygon(poly in grid_polygon()) {
        let p = Polygon::<CAP>::new(&poly).unwrap();
        let mut calls = 0;
        let r = p.triangulate(|_| calls += 1);
        if brute::is_simple(&poly) {
            prop_assert!(r.is_ok());
            prop_assert!(calls <= poly.len() - 2, "{} triangles for {:?}", calls, poly);
            // The grid spans -6..=6 px: the window holds it all.
            let tri = triangulated(&poly, -8, -8, 16, 16);
            assert_same(&tri, &reference_fill(&poly, false, -8, -8, 16, 16), &format!("{poly:?}"));
        } else {
            prop_assert_eq!((r, calls), (Err(PolygonError::NotSimple), 0));
        }
    }
}

/// Checks written independently of the crate's predicates: segment
/// intersection by solving for both parameters as exact fractions.
mod brute {
    use embedded_raster::Vertex;

    type P = (i128, i128);

    fn p(v: Vertex) -> P {
        let (x, y) = v.raw();
        (i128::from(x), i128::from(y))
    }

    fn sub(a: P, b: P) -> P {
        (a.0 - b.0, a.1 - b.1)
    }

    fn cross(a: P, b: P) -> i128 {
        a.0 * b.1 - a.1 * b.0
    }

    fn dot(a: P, b: P) -> i128 {
        a.0 * b.0 + a.1 * b.1
    }

    /// t = num / den lies in [0, 1].
    fn unit(num: i128, den: i128) -> bool {
        let (num, den) = if den < 0 { (-num, -den) } else { (num, den) };
        0 <= num && num <= den
    }

    /// Do closed segments a0-a1 and b0-b1 share a point? Parametric:
    /// a0 + t r = b0 + u s.
    pub fn meet(a0: P, a1: P, b0: P, b1: P) -> bool {
        let (r, s, q) = (sub(a1, a0), sub(b1, b0), sub(b0, a0));
        let den = cross(r, s);
        if den != 0 {
            return unit(cross(q, s), den) && unit(cross(q, r), den);
        }
        if cross(q, r) != 0 || cross(q, s) != 0 {
            return false; // parallel and apart (either may be a point)
        }
        // Collinear (or points): project on the longer direction.
        let dir = if dot(r, r) >= dot(s, s) { r } else { s };
        if dir == (0, 0) {
            return a0 == b0;
        }
        let (a_lo, a_hi) = minmax(0, dot(r, dir));
        let (b_lo, b_hi) = minmax(dot(q, dir), dot(sub(b1, a0), dir));
        a_lo <= b_hi && b_lo <= a_hi
    }

    fn minmax(a: i128, b: i128) -> (i128, i128) {
        (a.min(b), a.max(b))
    }

    pub fn is_simple(v: &[Vertex]) -> bool {
        let n = v.len();
        let e = |k: usize| (p(v[k % n]), p(v[(k + 1) % n]));
        for i in 0..n {
            let (a0, a1) = e(i);
            if a0 == a1 {
                return false;
            }
            for j in i + 1..n {
                let (b0, b1) = e(j);
                let adjacent = j == i + 1 || (i == 0 && j == n - 1);
                if adjacent {
                    // Only the shared vertex in common: the far ends must
                    // not lie on the other edge.
                    let (shared, far_a, far_b) = if j == i + 1 {
                        (a1, a0, b1)
                    } else {
                        (a0, a1, b0)
                    };
                    let on = |x: P, s0: P, s1: P| meet(x, x, s0, s1);
                    if n == 3 && cross(sub(a1, a0), sub(b1, b0)) == 0 {
                        return false;
                    }
                    if on(far_a, shared, far_b) || on(far_b, shared, far_a) {
                        return false;
                    }
                } else if meet(a0, a1, b0, b1) {
                    return false;
                }
            }
        }
        true
    }

    /// Given a simple polygon: convex iff every vertex is on one side of
    /// (or on) every edge's line, with non-zero area.
    pub fn is_convex(v: &[Vertex]) -> bool {
        let n = v.len();
        let area: i128 = (0..n).map(|k| cross(p(v[k]), p(v[(k + 1) % n]))).sum();
        if area == 0 {
            return false;
        }
        (0..n).all(|k| {
            let (a, b) = (p(v[k]), p(v[(k + 1) % n]));
            v.iter()
                .all(|&q| cross(sub(b, a), sub(p(q), a)) * area.signum() >= 0)
        })
    }
}

fn poly(points: &[(f64, f64)]) -> Vec<Vertex> {
    points
        .iter()
        .map(|&(x, y)| Vertex::try_from_num(x, y).unwrap())
        .collect()
}

#[test]
fn pentagram_even_odd_leaves_the_centre_empty() {
    let star = poly(&[
        (16.0, 1.0),
        (25.4, 29.9),
        (0.8, 12.0),
        (31.2, 12.0),
        (6.6, 29.9),
    ]);
    let (nz, eo) = (
        scanline(&star, false, 0, 0, 32, 32),
        scanline(&star, true, 0, 0, 32, 32),
    );
    // The centre pentagon is wound twice: filled only under non-zero.
    assert_eq!((nz.get(16, 18), eo.get(16, 18)), (1, 0));
    // A point of the star is wound once: filled under both.
    assert_eq!((nz.get(16, 5), eo.get(16, 5)), (1, 1));
    assert_same(
        &nz,
        &reference_fill(&star, false, 0, 0, 32, 32),
        &"non-zero",
    );
    assert_same(&eo, &reference_fill(&star, true, 0, 0, 32, 32), &"even-odd");
}

#[test]
fn rectangle_pixels_by_hand() {
    // Corners on pixel centres and a pixel corner: centres on the left and
    // top sides are in, on the right and bottom sides out.
    let r = poly(&[(1.5, 2.0), (5.5, 2.0), (5.5, 4.5), (1.5, 4.5)]);
    let g = scanline(&r, false, 0, 0, 8, 8);
    for j in 0..8 {
        for i in 0..8 {
            let lit = (1..5).contains(&i) && (2..4).contains(&j);
            assert_eq!(g.get(i, j), u32::from(lit), "pixel ({i}, {j})");
        }
    }
}

#[test]
fn tricky_simplicity_and_convexity() {
    let check = |pts: &[(f64, f64)], simple: bool, convex: bool| {
        let v = poly(pts);
        let p = Polygon::<CAP>::new(&v).unwrap();
        assert_eq!((p.is_simple(), p.is_convex()), (simple, convex), "{pts:?}");
        assert_eq!(
            brute::is_simple(&v),
            simple,
            "brute force disagrees on {pts:?}"
        );
    };
    check(
        &[(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0)],
        true,
        true,
    );
    // Collinear vertices on a side: still simple and convex.
    check(
        &[(0.0, 0.0), (2.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0)],
        true,
        true,
    );
    // A repeated vertex: a zero-length edge.
    check(
        &[(0.0, 0.0), (4.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0)],
        false,
        false,
    );
    // A spike folding back along itself.
    check(
        &[(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (4.0, 2.0), (0.0, 4.0)],
        false,
        false,
    );
    // A vertex touching a non-adjacent edge.
    check(
        &[(0.0, 0.0), (4.0, 0.0), (2.0, 4.0), (2.0, 0.0), (1.0, 2.0)],
        false,
        false,
    );
    // Two vertices at one point (a figure eight pinched at a vertex).
    check(
        &[
            (0.0, 0.0),
            (2.0, 2.0),
            (4.0, 0.0),
            (4.0, 4.0),
            (2.0, 2.0),
            (0.0, 4.0),
        ],
        false,
        false,
    );
    // Bow tie and pentagram: crossing edges.
    check(
        &[(0.0, 0.0), (4.0, 4.0), (4.0, 0.0), (0.0, 4.0)],
        false,
        false,
    );
    check(
        &[
            (16.0, 1.0),
            (25.4, 29.9),
            (0.8, 12.0),
            (31.2, 12.0),
            (6.6, 29.9),
        ],
        false,
        false,
    );
    // Concave but simple.
    check(
        &[(0.0, 0.0), (4.0, 0.0), (1.0, 1.0), (0.0, 4.0)],
        true,
        false,
    );
    // All on one line: zero area.
    check(&[(0.0, 0.0), (2.0, 0.0), (4.0, 0.0)], false, false);
}

#[test]
fn errors_and_degenerate_polygons() {
    let three = poly(&[(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)]);
    assert_eq!(
        Polygon::<CAP>::new(&three[..2]),
        Err(PolygonError::TooFewVertices { count: 2 })
    );
    assert_eq!(
        Polygon::<CAP>::new(&[]),
        Err(PolygonError::TooFewVertices { count: 0 })
    );
    assert_eq!(
        Polygon::<2>::new(&three),
        Err(PolygonError::CapacityExceeded {
            needed: 3,
            capacity: 2
        })
    );
    // Zero area: nothing lit, under either rule.
    for flat in [
        poly(&[(0.0, 0.5), (9.0, 0.5), (4.0, 0.5)]),
        poly(&[(1.0, 1.0), (5.0, 5.0), (9.0, 9.0), (5.0, 5.0)]),
    ] {
        for even_odd in [false, true] {
            assert!(scanline(&flat, even_odd, -2, -2, 14, 14)
                .cells
                .iter()
                .all(|&c| c == 0));
        }
    }
}

/// A display that counts `fill_solid` calls and rejects everything else.
struct Fills {
    calls: usize,
    pixels: u64,
}

impl OriginDimensions for Fills {
    fn size(&self) -> Size {
        Size::new(40, 30)
    }
}

impl DrawTarget for Fills {
    type Color = Rgb565;
    type Error = core::convert::Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(
        &mut self,
        _: I,
    ) -> Result<(), Self::Error> {
        panic!("a flat polygon was drawn pixel by pixel");
    }

    fn fill_solid(&mut self, area: &Rectangle, _: Rgb565) -> Result<(), Self::Error> {
        assert!(self.bounding_box().contains(area.top_left));
        assert!(area
            .bottom_right()
            .is_some_and(|p| self.bounding_box().contains(p)));
        self.calls += 1;
        self.pixels += u64::from(area.size.width) * u64::from(area.size.height);
        Ok(())
    }
}

#[test]
fn axis_aligned_rectangles_are_one_fill_solid() {
    // Reaching past the left and bottom sides of the 40 x 30 target.
    let r = poly(&[(-10.25, 3.5), (12.5, 3.5), (12.5, 100.0), (-10.25, 100.0)]);
    let mut d = Fills {
        calls: 0,
        pixels: 0,
    };
    Polygon::<4>::new(&r)
        .unwrap()
        .fill(Rgb565::RED)
        .draw(&mut d)
        .unwrap();
    // Columns 0..12 (centres 0.5 ..= 11.5 < 12.5), rows 3..30.
    assert_eq!((d.calls, d.pixels), (1, 12 * 27));
    let want: u32 = reference_fill(&r, false, 0, 0, 40, 30).cells.iter().sum();
    assert_eq!(u64::from(want), d.pixels);
    // A rectangle entirely outside: nothing.
    let far = poly(&[(50.0, 0.0), (60.0, 0.0), (60.0, 10.0), (50.0, 10.0)]);
    let mut d = Fills {
        calls: 0,
        pixels: 0,
    };
    Polygon::<4>::new(&far)
        .unwrap()
        .fill(Rgb565::RED)
        .draw(&mut d)
        .unwrap();
    assert_eq!(d.calls, 0);
}

#[test]
fn concave_polygon_draws_as_clipped_spans() {
    let l = poly(&[
        (-5.0, -5.0),
        (20.0, -5.0),
        (20.0, 10.0),
        (10.0, 10.0),
        (10.0, 50.0),
        (-5.0, 50.0),
    ]);
    let mut d = Fills {
        calls: 0,
        pixels: 0,
    };
    Polygon::<6>::new(&l)
        .unwrap()
        .fill(Rgb565::RED)
        .draw(&mut d)
        .unwrap();
    let want: u32 = reference_fill(&l, false, 0, 0, 40, 30).cells.iter().sum();
    assert_eq!((d.calls, d.pixels), (30, u64::from(want)));
}

/// Clip rectangles that reach the ends of `i32`, on a concave polygon as
/// large as the 20.12 range (its pixels lie in -524288..524288 both
/// ways): those that miss it get no span; one as wide as `i32` across its
/// top edge and one as tall as `i32` through its notch get exactly the
/// reference's pixels, every span inside the clip.
#[test]
fn clip_rectangles_at_the_ends_of_i32() {
    let big = [v(MIN, MIN), v(MAX, MIN), v(MAX, MAX), v(0, 0), v(MIN, MAX)];
    let poly = Polygon::<CAP>::new(&big).unwrap();
    let pts = big.map(common::raw);
    let lit = |x: i64, y: i64| common::winding(&pts, common::centre(x, y)) % 2 != 0;
    let spans = |clip: &Rectangle| {
        let mut runs = std::collections::BTreeSet::new();
        poly.for_each_span(FillRule::EvenOdd, clip, |s| {
            let (y, xs, xe) = common::checked_span(clip, s);
            assert!(runs.insert((y, xs, xe)), "{s:?} twice");
            Ok::<(), ()>(())
        })
        .unwrap();
        runs
    };
    for clip in [
        Rectangle::new(
            Point::new(i32::MAX, i32::MAX),
            Size::new(u32::MAX, u32::MAX),
        ),
        Rectangle::new(Point::new(i32::MIN, i32::MIN), Size::new(u32::MAX, 2)),
        Rectangle::new(Point::new(0, 0), Size::new(0, 7)),
    ] {
        assert_eq!(spans(&clip), Default::default(), "{clip:?}");
    }

    // As wide as `i32`, across the top edge: one run a row, its ends the
    // reference's, and none above the edge.
    let clip = Rectangle::new(Point::new(i32::MIN, -524_290), Size::new(u32::MAX, 5));
    let rows = spans(&clip);
    let ys: Vec<i64> = rows.iter().map(|r| r.0).collect();
    assert_eq!(ys, [-524_288, -524_287, -524_286]);
    for &(y, xs, xe) in &rows {
        assert!(
            lit(xs, y) && lit(xe - 1, y) && !lit(xs - 1, y) && !lit(xe, y),
            "row {y}: {xs}..{xe}"
        );
    }
    assert!((-4..4).all(|x| !lit(x, -524_289)));

    // As tall as `i32`, six columns through the notch at (0, 0): each
    // pixel of every row of the polygon the reference's.
    let clip = Rectangle::new(Point::new(-3, i32::MIN), Size::new(6, u32::MAX));
    let rows = spans(&clip);
    assert!(rows.iter().all(|r| (-524_288..524_288).contains(&r.0)));
    for y in -524_290..524_290 {
        for x in -3..3 {
            let drawn = rows
                .range((y, i64::MIN, i64::MIN)..(y + 1, i64::MIN, i64::MIN))
                .any(|&(_, xs, xe)| (xs..xe).contains(&x));
            assert_eq!(drawn, lit(x, y), "({x}, {y})");
        }
    }
}

/// Issue 12: an edge spanning nearly the whole 20.12 range overflowed the
/// 64-bit threshold setup (`c * d`) in builds with overflow checks. The
/// reproducer scene, on its 8 x 8 target.
#[test]
fn issue_12_edge_across_the_whole_range() {
    // -524285.999755859375, -524288 and 524287.999755859375 px in raw
    // 1/4096 units.
    let (left, min, max) = (-2_147_475_455, -2_147_483_648, 2_147_483_647);
    let poly = [v(left, min), v(max, max), v(left, max)];
    for even_odd in [false, true] {
        assert_same(
            &scanline(&poly, even_odd, 0, 0, 8, 8),
            &reference_fill(&poly, even_odd, 0, 0, 8, 8),
            &"reproducer",
        );
    }
}
