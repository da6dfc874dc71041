//! The triangle rasterizer against the exact reference in `common`.
//!
//! Case counts follow `PROPTEST_CASES` (proptest's default, 256, when
//! unset); CI's deep run raises it.

mod common;

use common::shapes::{any_scale, focus, sliver, v, MAX, MIN};
use common::{add_spans, assert_exact, reference_polygon, Grid};
use embedded_graphics_core::{
    geometry::{Point, Size},
    pixelcolor::Rgb565,
    prelude::*,
    primitives::Rectangle,
};
use embedded_raster::{Triangle, Vertex};
use proptest::prelude::*;

/// Pixel containing the raw point `p` (floor division by 4096).
fn pixel_of(p: i64) -> i64 {
    p >> 12
}

/// A window of `w x h` pixels centred on the raw point `(cx, cy)`.
fn window_around(cx: i64, cy: i64, w: usize, h: usize) -> (i64, i64, usize, usize) {
    (
        pixel_of(cx) - w as i64 / 2,
        pixel_of(cy) - h as i64 / 2,
        w,
        h,
    )
}

prop_compose! {
    /// Vertices on pixel centres and corners (multiples of half a pixel):
    /// many pixel centres lie exactly on edges and vertices.
    fn on_grid()(c in prop::array::uniform6(-24i64..=24)) -> Triangle {
        Triangle::new(v(c[0] * 2048, c[1] * 2048), v(c[2] * 2048, c[3] * 2048), v(c[4] * 2048, c[5] * 2048))
    }
}

prop_compose! {
    /// Vertices at and next to the ends of the range.
    fn extreme()(k in prop::array::uniform6(0usize..7)) -> Triangle {
        const E: [i64; 7] = [MIN, MIN + 1, -1, 0, 1, MAX - 1, MAX];
        Triangle::new(v(E[k[0]], E[k[1]]), v(E[k[2]], E[k[3]]), v(E[k[4]], E[k[5]]))
    }
}

proptest! {
    #[test]
    fn exact_at_every_scale(t in any_scale(), which in 0usize..4, f in (any::<u16>(), any::<u16>()), w in 1usize..48, h in 1usize..48) {
        let (cx, cy) = focus(&t, which, f.0, f.1);
        let (x0, y0, w, h) = window_around(cx, cy, w, h);
        assert_exact(&t, x0, y0, w, h);
    }

    #[test]
    fn exact_on_pixel_centres_and_corners(t in on_grid()) {
        // The window holds the whole triangle and a margin.
        assert_exact(&t, -14, -14, 28, 28);
    }

    #[test]
    fn exact_for_slivers(t in sliver(1 << 22, 1 << 20), which in 0usize..4, f in (any::<u16>(), any::<u16>())) {
        let (cx, cy) = focus(&t, which, f.0, f.1);
        let (x0, y0, w, h) = window_around(cx, cy, 40, 40);
        assert_exact(&t, x0, y0, w, h);
    }

    #[test]
    fn exact_far_off_screen(t in any_scale(), w in 1usize..64, h in 1usize..64) {
        // A screen-like window at the origin, wherever the triangle is.
        assert_exact(&t, 0, 0, w, h);
    }

    #[test]
    fn exact_at_the_ends_of_the_range(t in extreme(), corner in 0usize..5) {
        const LO: i64 = -(1 << 19);
        const HI: i64 = (1 << 19) - 16;
        let (x0, y0) = [(LO, LO), (HI, LO), (LO, HI), (HI, HI), (-8, -8)][corner];
        assert_exact(&t, x0, y0, 16, 16);
    }

    /// Both windings light the same pixels.
    #[test]
    fn winding_does_not_matter(t in on_grid()) {
        let [a, b, c] = t.vertices;
        let g1 = common::rasterized(&t, -14, -14, 28, 28);
        let g2 = common::rasterized(&Triangle::new(a, c, b), -14, -14, 28, 28);
        prop_assert_eq!(g1, g2);
    }
}

#[test]
fn right_triangle_by_hand() {
    // Legs of 4 px on pixel corners: centres (i + 1/2, j + 1/2) with
    // i + j + 1 < 4 are inside; those on the hypotenuse (i + j + 1 == 4)
    // are on a right/bottom edge and stay dark.
    let t = Triangle::new(v(0, 0), v(4 << 12, 0), v(0, 4 << 12));
    let g = common::rasterized(&t, -2, -2, 8, 8);
    for j in -2..6i64 {
        for i in -2..6i64 {
            let lit = i >= 0 && j >= 0 && i + j < 3;
            assert_eq!(g.get(i, j), u32::from(lit), "pixel ({i}, {j})");
        }
    }
}

#[test]
fn top_left_rule_on_pixel_centres() {
    // A triangle with corners on pixel centres: its top and left edges run
    // through centres, which are lit; its bottom and right edges too, unlit.
    // Square (1.5, 1.5)-(5.5, 5.5) split along the other diagonal.
    let c = |i: i64, j: i64| v(i * 4096 + 2048, j * 4096 + 2048);
    let upper = Triangle::new(c(1, 1), c(5, 1), c(1, 5));
    let lower = Triangle::new(c(5, 1), c(5, 5), c(1, 5));
    let gu = common::rasterized(&upper, 0, 0, 8, 8);
    let gl = common::rasterized(&lower, 0, 0, 8, 8);
    for j in 0..8i64 {
        for i in 0..8i64 {
            // The square's top and left sides are in, bottom and right out;
            // the shared diagonal belongs to exactly one of the two.
            let in_square = (1..5).contains(&i) && (1..5).contains(&j);
            assert_eq!(
                gu.get(i, j) + gl.get(i, j),
                u32::from(in_square),
                "pixel ({i}, {j})"
            );
        }
    }
    // Centre (1.5, 1.5), the upper triangle's top-left corner, is lit.
    assert_eq!(gu.get(1, 1), 1);
    // The diagonal x + y = 7 runs from (5.5, 1.5) to (1.5, 5.5) through the
    // centre (3.5, 3.5): the bottom-right edge of the upper triangle, the
    // top-left edge of the lower one.
    assert_eq!((gu.get(3, 3), gl.get(3, 3)), (0, 1));
    assert_eq!((gu.get(3, 2), gl.get(3, 2)), (1, 0));
}

#[test]
fn zero_area_lights_nothing() {
    let cases = [
        Triangle::new(v(0, 0), v(40960, 40960), v(20480, 20480)),
        Triangle::new(v(2048, 2048), v(2048, 2048), v(2048, 2048)),
        Triangle::new(v(0, 2048), v(40960, 2048), v(8192, 2048)),
        Triangle::new(v(MIN, MIN), v(MAX, MAX), v(0, 0)),
    ];
    for t in cases {
        let g = common::rasterized(&t, -16, -16, 32, 32);
        assert!(g.cells.iter().all(|&c| c == 0), "{t:?} lit something");
    }
}

#[test]
fn widest_triangles_are_exact() {
    let t = Triangle::new(v(MIN, MIN), v(MAX, MIN + 5), v(3, MAX));
    for (x0, y0) in [
        (0, 0),
        (-(1 << 19), -(1 << 19)),
        ((1 << 19) - 20, -(1 << 19)),
        (-2, (1 << 19) - 20),
    ] {
        assert_exact(&t, x0, y0, 20, 20);
    }
}

#[test]
fn triangles_at_the_32_bit_bound_are_exact() {
    // Bounding boxes just under and just over 131,072 px a side: the edges
    // step in i32 and in i64 respectively.
    for side in [131_060i64, 131_080] {
        let px = 4096;
        let t = Triangle::new(v(0, 0), v(side * px - 7, 3), v(5, side * px - 1));
        assert_exact(&t, 0, 0, 24, 24);
        assert_exact(&t, side / 2 - 12, side / 2 - 12, 24, 24);
        assert_exact(&t, 0, side - 24, 24, 24);
    }
}

/// Clip rectangles that reach the ends of `i32`: those that miss the
/// widest triangle (its pixels lie in -524288..524288 both ways) get no
/// span, and those as wide or as tall as `i32` across it get exactly the
/// reference's pixels, every span inside the clip.
#[test]
fn clip_rectangles_at_the_ends_of_i32() {
    let t = Triangle::new(v(MIN, MIN), v(MAX, MIN), v(0, MAX));
    let pts = t.vertices.map(common::raw);
    let lit = |x: i64, y: i64| common::winding(&pts, common::centre(x, y)) != 0;
    let spans = |clip: &Rectangle| {
        let mut rows = std::collections::BTreeMap::new();
        t.for_each_span(clip, |s| {
            let (y, xs, xe) = common::checked_span(clip, s);
            assert!(rows.insert(y, (xs, xe)).is_none(), "row {y} twice");
            Ok::<(), ()>(())
        })
        .unwrap();
        rows
    };
    let missing = [
        Rectangle::new(
            Point::new(i32::MAX, i32::MAX),
            Size::new(u32::MAX, u32::MAX),
        ),
        Rectangle::new(Point::new(i32::MIN, i32::MIN), Size::new(u32::MAX, 3)),
        Rectangle::new(Point::new(i32::MAX - 1, 0), Size::new(2, 2)),
        Rectangle::new(Point::new(0, 0), Size::new(0, 10)),
    ];
    for clip in &missing {
        assert_eq!(spans(clip), Default::default(), "{clip:?}");
    }

    // As wide as `i32`, across the top edge and across the apex: in each
    // row of the clip, the span's ends are the reference's (the triangle
    // is convex, so its pixels in a row are one run).
    for (y0, h) in [(-524_290, 6), (524_283, 8)] {
        let clip = Rectangle::new(Point::new(i32::MIN, y0), Size::new(u32::MAX, h));
        let rows = spans(&clip);
        for y in i64::from(y0)..i64::from(y0) + i64::from(h) {
            match rows.get(&y) {
                Some(&(xs, xe)) => assert!(
                    lit(xs, y) && lit(xe - 1, y) && !lit(xs - 1, y) && !lit(xe, y),
                    "row {y}: {xs}..{xe}"
                ),
                // Above the top edge, or so near the apex (x = 0) that
                // no pixel centre is inside.
                None => assert!(
                    !(-524_288..=524_280).contains(&y) && (-4..4).all(|x| !lit(x, y)),
                    "row {y} has no span"
                ),
            }
        }
    }
    // As tall as `i32`, six columns through the apex: every row of the
    // triangle, each pixel the reference's.
    let clip = Rectangle::new(Point::new(-3, i32::MIN), Size::new(6, u32::MAX));
    let rows = spans(&clip);
    assert!(rows.keys().all(|y| (-524_288..524_288).contains(y)));
    for y in -524_290..524_290 {
        let (xs, xe) = rows.get(&y).copied().unwrap_or((0, 0));
        for x in -3..3 {
            assert_eq!((xs..xe).contains(&x), lit(x, y), "({x}, {y})");
        }
    }
}

/// Small triangles (the shorter setup) slid across every edge of a small
/// window at fractional offsets: whether their top-left corner's first
/// pixel centres fall inside the window, on its edge or outside it, and
/// whether they reach past its right and bottom edges, the pixels are the
/// reference's.
#[test]
fn small_triangles_across_the_clip_edges() {
    let shapes = [
        [(0, 0), (5 * 4096 + 700, 1200), (1500, 4 * 4096 + 3000)],
        [
            (2048, 2048),
            (2048, 6 * 4096 + 2048),
            (-3 * 4096 - 5, 3 * 4096),
        ],
        [(100, 4095), (3 * 4096, 4096), (4096, 2 * 4096 + 1)],
    ];
    for shape in shapes {
        for dy in (-9 * 4096..9 * 4096).step_by(1367) {
            for dx in (-9 * 4096..9 * 4096).step_by(1367) {
                let at = |(x, y): (i64, i64)| v(x + dx, y + dy);
                let t = Triangle::new(at(shape[0]), at(shape[1]), at(shape[2]));
                assert_exact(&t, 0, 0, 6, 5);
            }
        }
    }
}

#[test]
fn stops_at_the_first_error() {
    let t = Triangle::new(v(0, 0), v(40960, 0), v(0, 40960));
    let mut calls = 0;
    let r = t.for_each_span(&Grid::new(0, 0, 10, 10).clip(), |_| {
        calls += 1;
        if calls == 3 {
            Err("full")
        } else {
            Ok(())
        }
    });
    assert_eq!((r, calls), (Err("full"), 3));
}

prop_compose! {
    /// A rectangle split into a jittered grid of cells, two triangles each:
    /// (corner, raw cell size, vertices, cells, diagonal per cell).
    fn mesh()(
        nx in 1usize..6, ny in 1usize..6,
        corner in (-(1i64 << 16)..(1 << 16), -(1i64 << 16)..(1 << 16)),
        cell in (4096i64..(24 << 12), 4096i64..(24 << 12)),
        jitter in prop::collection::vec((-20i64..=20, -20i64..=20), 36),
        diagonals in prop::collection::vec(any::<bool>(), 25),
    ) -> (Vec<Triangle>, (i64, i64, i64, i64)) {
        let point = |i: usize, j: usize| {
            let (mut x, mut y) = (corner.0 + i as i64 * cell.0, corner.1 + j as i64 * cell.1);
            let (jx, jy) = jitter[j * 6 + i];
            // Boundary vertices slide along the boundary only.
            if i > 0 && i < nx { x += cell.0 * jx / 100; }
            if j > 0 && j < ny { y += cell.1 * jy / 100; }
            v(x, y)
        };
        let mut tris = vec![];
        for j in 0..ny {
            for i in 0..nx {
                let (a, b, c, d) = (point(i, j), point(i + 1, j), point(i + 1, j + 1), point(i, j + 1));
                if diagonals[j * 5 + i] {
                    tris.push(Triangle::new(a, b, c));
                    tris.push(Triangle::new(a, c, d));
                } else {
                    tris.push(Triangle::new(a, b, d));
                    tris.push(Triangle::new(b, c, d));
                }
            }
        }
        let bounds = (corner.0, corner.1, corner.0 + nx as i64 * cell.0, corner.1 + ny as i64 * cell.1);
        (tris, bounds)
    }
}

prop_compose! {
    /// A fan around a centre: a star-shaped polygon and its triangles.
    fn fan()(
        n in 4usize..12,
        centre in (-(1i64 << 16)..(1 << 16), -(1i64 << 16)..(1 << 16)),
        radius in (2i64 << 12)..(40i64 << 12),
        jitter in prop::collection::vec((-40i32..=40, 50i32..=100), 12),
        snap in any::<bool>(),
    ) -> (Vec<Triangle>, Vec<Vertex>) {
        // Snapped fans put every vertex on a half-pixel grid: many ties.
        let snap_to = |p: i64| if snap { (p + 1024).div_euclid(2048) * 2048 } else { p };
        let c = v(snap_to(centre.0), snap_to(centre.1));
        let ring: Vec<Vertex> = (0..n)
            .map(|k| {
                let step = std::f64::consts::TAU / n as f64;
                let angle = step * (k as f64 + f64::from(jitter[k].0) / 100.0);
                let r = radius as f64 * f64::from(jitter[k].1) / 100.0;
                v(snap_to(centre.0 + (r * angle.cos()) as i64), snap_to(centre.1 + (r * angle.sin()) as i64))
            })
            .collect();
        let tris = (0..n).map(|k| Triangle::new(c, ring[k], ring[(k + 1) % n])).collect();
        (tris, ring)
    }
}

proptest! {
    /// Every pixel of a jittered grid mesh is written exactly once, and
    /// exactly the pixels whose centres are in the outer rectangle.
    #[test]
    fn meshes_have_no_gaps_and_no_overdraw((tris, (x0, y0, x1, y1)) in mesh()) {
        let mut g = Grid::new((x0 >> 12) - 2, (y0 >> 12) - 2, ((x1 - x0) >> 12) as usize + 5, ((y1 - y0) >> 12) as usize + 5);
        for t in &tris {
            add_spans(t, &mut g);
        }
        for j in 0..g.h as i64 {
            for i in 0..g.w as i64 {
                let (px, py) = ((g.x0 + i) * 4096 + 2048, (g.y0 + j) * 4096 + 2048);
                // Nudged by (e, e^2): a centre on the left or top side is in.
                let inside = x0 <= px && px < x1 && y0 <= py && py < y1;
                prop_assert_eq!(g.get(g.x0 + i, g.y0 + j), u32::from(inside), "pixel ({}, {})", g.x0 + i, g.y0 + j);
            }
        }
    }

    /// A fan lights each pixel of its outline exactly once.
    #[test]
    fn fans_have_no_gaps_and_no_overdraw((tris, ring) in fan()) {
        // Snapping a small ring to the half-pixel grid can reorder its
        // points around the centre; then the fan is not a partition of the
        // ring (found by a 400,000-case run: a triangle turned over).
        prop_assume!(turns_one_way(&tris));
        let (cx, cy) = tris[0].vertices[0].raw();
        let (x0, y0) = ((i64::from(cx) >> 12) - 44, (i64::from(cy) >> 12) - 44);
        let mut g = Grid::new(x0, y0, 88, 88);
        for t in &tris {
            add_spans(t, &mut g);
        }
        let want = reference_polygon(&ring, x0, y0, 88, 88);
        let d = g.diff(&want);
        prop_assert!(d.is_empty(), "{} pixels differ: {:?}", d.len(), &d[..d.len().min(8)]);
    }
}

/// Whether every triangle has a non-zero area of the same sign: the fan
/// of a ring star-shaped around its centre.
fn turns_one_way(tris: &[Triangle]) -> bool {
    let sign = |t: &Triangle| {
        let p = t.vertices.map(|v| {
            let (x, y) = v.raw();
            (i128::from(x), i128::from(y))
        });
        ((p[1].0 - p[0].0) * (p[2].1 - p[0].1) - (p[1].1 - p[0].1) * (p[2].0 - p[0].0)).signum()
    };
    let first = tris.first().map_or(0, sign);
    first != 0 && tris.iter().all(|t| sign(t) == first)
}

/// A display that accepts only `fill_solid`, to prove flat fills never go
/// pixel by pixel.
struct SpansOnly {
    fills: usize,
}

impl OriginDimensions for SpansOnly {
    fn size(&self) -> Size {
        Size::new(64, 64)
    }
}

impl DrawTarget for SpansOnly {
    type Color = Rgb565;
    type Error = core::convert::Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(
        &mut self,
        _: I,
    ) -> Result<(), Self::Error> {
        panic!("a flat triangle was drawn pixel by pixel");
    }

    fn fill_contiguous<I: IntoIterator<Item = Rgb565>>(
        &mut self,
        _: &Rectangle,
        _: I,
    ) -> Result<(), Self::Error> {
        panic!("a flat triangle was drawn through fill_contiguous");
    }

    fn fill_solid(&mut self, area: &Rectangle, _: Rgb565) -> Result<(), Self::Error> {
        assert_eq!(area.size.height, 1);
        assert!(area.size.width > 0);
        assert!(self.bounding_box().contains(area.top_left));
        assert!(self
            .bounding_box()
            .contains(area.top_left + Point::new(area.size.width as i32 - 1, 0)));
        self.fills += 1;
        Ok(())
    }
}

#[test]
fn drawable_sends_one_clipped_fill_solid_per_row() {
    let mut d = SpansOnly { fills: 0 };
    // Reaches far outside the 64 x 64 target on three sides.
    let t = Triangle::from_points(
        Point::new(-100, 10),
        Point::new(300, 20),
        Point::new(30, 500),
    )
    .unwrap();
    t.fill(Rgb565::GREEN).draw(&mut d).unwrap();
    // The top edge runs from centre (-99.5, 10.5) to (300.5, 20.5): at the
    // first column's centre x = 0.5 it is at y = 13.0, so rows 13..=63 of
    // the target have pixels, one span each.
    assert_eq!(d.fills, 64 - 13);
}

/// embedded-graphics' own mock display panics on overdraw and on writes
/// outside its 64 x 64 area. A mesh covering more than that area draws on it
/// cleanly and lights every pixel.
#[test]
fn draws_on_embedded_graphics_mock_display() {
    use embedded_graphics::mock_display::MockDisplay;

    let mut display = MockDisplay::<Rgb565>::new();
    // An 8 x 8 grid of sheared cells spanning (-9.3, -7.1) to (89.3, 85.9).
    let p = |i: i32, j: i32| {
        Vertex::try_from_num(
            f64::from(i) * 12.33 - 9.3 + f64::from(j) * 0.7,
            f64::from(j) * 11.61 - 7.1,
        )
        .unwrap()
    };
    for j in 0..8 {
        for i in 0..8 {
            let (a, b, c, d) = (p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1));
            Triangle::new(a, b, c)
                .fill(Rgb565::CSS_ORANGE)
                .draw(&mut display)
                .unwrap();
            Triangle::new(a, c, d)
                .fill(Rgb565::CSS_TEAL)
                .draw(&mut display)
                .unwrap();
        }
    }
    for y in 0..64 {
        for x in 0..64 {
            assert!(
                display.get_pixel(Point::new(x, y)).is_some(),
                "pixel ({x}, {y}) is a gap"
            );
        }
    }
}

#[cfg(feature = "sim")]
proptest! {
    /// The same meshes drawn as `Drawable`s on the simulator's display:
    /// one write per covered pixel, nothing outside the display, every
    /// pixel through `fill_solid`.
    #[test]
    fn meshes_on_the_simulator_write_each_pixel_once((tris, (x0, y0, x1, y1)) in mesh()) {
        use embedded_graphics_core::pixelcolor::Rgb888;
        use embedded_raster::sim::SimDisplay;

        // The mesh starts within 16 px of the origin and may begin left of
        // or above it: the display clips that part.
        let mut display = SimDisplay::new(140, 140, Rgb888::BLACK);
        for t in &tris {
            t.fill(Rgb888::WHITE).draw(&mut display).unwrap();
        }
        prop_assert_eq!(display.out_of_bounds_writes(), 0);
        let stats = display.write_stats();
        prop_assert_eq!((stats.draw_iter_pixels, stats.fill_contiguous_pixels), (0, 0));
        prop_assert_eq!(stats.fill_solid_pixels, display.pixels_written());
        for y in 0..140i64 {
            for x in 0..140i64 {
                let (px, py) = (x * 4096 + 2048, y * 4096 + 2048);
                let inside = x0 <= px && px < x1 && y0 <= py && py < y1;
                let count = display.write_count(Point::new(x as i32, y as i32));
                prop_assert_eq!(count, Some(u32::from(inside)), "pixel ({}, {})", x, y);
            }
        }
    }
}

proptest! {
    /// Through the span sink, on the crate's framebuffer (`draw_spans`)
    /// and through its `DrawTarget` (`draw`), triangles at every scale
    /// light exactly the reference's pixels in the screen-like window at
    /// the origin, the colour written once per pixel of the fill.
    #[test]
    fn framebuffer_paths_match_the_reference(t in any_scale(), on_screen in any::<bool>(), f in (any::<u16>(), any::<u16>())) {
        use embedded_graphics_core::pixelcolor::Gray8;
        use embedded_raster::{framebuffer::{buffer_size, Gray8Bytes}, Framebuffer, SpanDrawable};
        type Fb = Framebuffer<Gray8Bytes, 40, 30, { buffer_size::<Gray8Bytes>(40, 30) }>;
        // Half the cases: the triangle moved so that a corner or a point
        // of its bounding box (`focus`, in 20.12 units) lands on pixel
        // (20, 15), the window's middle; a vertex moved past the range is
        // clamped into it, which keeps that point in the bounding box.
        let t = if on_screen {
            let (cx, cy) = focus(&t, usize::from(f.0 % 4), f.0, f.1);
            let (dx, dy) = (20 * 4096 - cx, 15 * 4096 - cy);
            let [a, b, c] = t.vertices.map(|p| {
                let (x, y) = p.raw();
                v(i64::from(x) + dx, i64::from(y) + dy)
            });
            Triangle::new(a, b, c)
        } else {
            t
        };
        let want = common::reference_triangle(&t, 0, 0, 40, 30);
        let mut direct = Fb::new();
        t.fill(Gray8::WHITE).draw_spans(&mut direct).unwrap();
        let mut through = Fb::new();
        t.fill(Gray8::WHITE).draw(&mut through).unwrap();
        let lit = |fb: &Fb| -> Vec<u32> {
            (0..30)
                .flat_map(|y| (0..40).map(move |x| (x, y)))
                .map(|(x, y)| u32::from(fb.pixel(Point::new(x, y)) == Some(Gray8::WHITE)))
                .collect()
        };
        prop_assert_eq!(&lit(&direct), &want.cells, "{:?}", t);
        prop_assert_eq!(&lit(&through), &want.cells, "{:?}", t);
    }
}
