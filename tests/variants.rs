//! The triangle variants keep their documented properties: the exact ones
//! light the independent reference's pixels (`tests/common`) at every size
//! and precision, the watertight ones have no gap and no overdraw in
//! meshes and fans at every precision (where the reference covers a pixel
//! once), and every variant is safe (overflow checks on) at the ends of
//! the range.

mod common;
#[path = "../examples/tradeoff/measure.rs"]
mod measure;
#[path = "common/rng.rs"]
mod rng;

use embedded_graphics_core::{
    geometry::{Point, Size},
    primitives::Rectangle,
};
use embedded_raster::{SubpixelPrecision, Triangle, TriangleAlgorithm, Vertex};
use measure::{accuracy, largest_ok, scene_sets, size_probe, Variant, SIZES};

use common::Grid;

const EXACT: Variant = Variant::Lib(TriangleAlgorithm::EdgeExact);

/// The pixels `a` lights of `t` at precision `p` inside `clip`, one count
/// a pixel (spans checked: in order, inside the clip, not overlapping).
fn drawn(a: TriangleAlgorithm, p: SubpixelPrecision, t: &Triangle, clip: &Rectangle) -> Grid {
    let mut g = grid(clip);
    common::add_spans_from::<()>(&mut g, |clip, f| t.for_each_span_with(a, p, clip, f));
    g
}

/// The independent reference (`tests/common`) for `t` snapped to `p`.
fn reference(p: SubpixelPrecision, t: &Triangle, clip: &Rectangle) -> Grid {
    let g = grid(clip);
    common::reference_triangle(&t.snapped(p), g.x0, g.y0, g.w, g.h)
}

fn grid(clip: &Rectangle) -> Grid {
    Grid::new(
        clip.top_left.x.into(),
        clip.top_left.y.into(),
        clip.size.width as usize,
        clip.size.height as usize,
    )
}

const EXACT_ONES: [TriangleAlgorithm; 2] =
    [TriangleAlgorithm::EdgeExact, TriangleAlgorithm::Barycentric];

#[test]
fn exact_variants_match_the_reference() {
    assert!(TriangleAlgorithm::ALL
        .into_iter()
        .all(|a| a.is_exact() == EXACT_ONES.contains(&a)));
    let mut lit = 0;
    for set in &scene_sets(1) {
        for t in &set.tris {
            let want = reference(SubpixelPrecision::Bits12, t, &set.clip);
            lit += want.cells.iter().sum::<u32>();
            for a in EXACT_ONES {
                let got = drawn(a, SubpixelPrecision::Bits12, t, &set.clip);
                assert!(
                    got == want,
                    "{a} on {}, {t:?}: {:?}",
                    set.name,
                    want.diff(&got)
                );
            }
        }
    }
    // The sets light something, or the check above is empty.
    assert!(lit > 10_000, "{lit}");
}

/// The exact variants at every precision, on the irregular triangles of
/// every size the speed/accuracy report tries (`largest_ok`, up to legs of
/// 524,287 px), in the report's windows at the corners and the centroid.
#[test]
fn exact_variants_match_the_reference_at_every_size() {
    let mut lit = 0;
    for l in SIZES {
        let (t, clips) = size_probe(l);
        for p in SubpixelPrecision::ALL {
            for clip in &clips {
                let want = reference(p, &t, clip);
                lit += want.cells.iter().sum::<u32>();
                for a in EXACT_ONES {
                    let got = drawn(a, p, &t, clip);
                    assert!(
                        got == want,
                        "{a} at {p} bits, legs {l} px, {clip:?}: {:?}",
                        want.diff(&got)
                    );
                }
            }
        }
    }
    assert!(lit > 10_000, "{lit}");
}

#[test]
fn barycentric_matches_the_exact_rasterizer_at_every_precision() {
    for set in &scene_sets(1) {
        for p in SubpixelPrecision::ALL {
            for t in &set.tris {
                let mut want = vec![];
                let mut got = vec![];
                EXACT.spans(p, t, &set.clip, |s| want.push(s));
                Variant::Lib(TriangleAlgorithm::Barycentric)
                    .spans(p, t, &set.clip, |s| got.push(s));
                assert_eq!(got, want, "{t:?} at {p} bits on {}", set.name);
            }
        }
    }
}

/// On meshes and fans, at every precision: where the reference covers a
/// pixel exactly once (the mesh's inside, its vertices snapped to that
/// precision), a watertight variant writes it exactly once too.
#[test]
fn watertight_variants_have_no_gap_or_overdraw() {
    let mut inside = 0;
    for set in scene_sets(2).iter().filter(|s| s.mesh) {
        for p in SubpixelPrecision::ALL {
            let mut once = grid(&set.clip);
            for t in &set.tris {
                let r = reference(p, t, &set.clip);
                once.cells
                    .iter_mut()
                    .zip(&r.cells)
                    .for_each(|(c, r)| *c += r);
            }
            inside += once.cells.iter().filter(|&&c| c == 1).count();
            for a in TriangleAlgorithm::ALL {
                let mut counts = grid(&set.clip);
                for t in &set.tris {
                    let g = drawn(a, p, t, &set.clip);
                    counts
                        .cells
                        .iter_mut()
                        .zip(&g.cells)
                        .for_each(|(c, g)| *c += g);
                }
                let (mut gaps, mut overdraw) = (0, 0);
                for (&r, &c) in once.cells.iter().zip(&counts.cells) {
                    if r == 1 {
                        gaps += usize::from(c == 0);
                        overdraw += usize::from(c >= 2);
                    }
                }
                if a.is_watertight() {
                    assert_eq!((gaps, overdraw), (0, 0), "{a} at {p} bits on {}", set.name);
                } else {
                    // Documented as overdrawing its shared edges.
                    assert!(overdraw > 0, "{a} at {p} bits on {}", set.name);
                }
            }
        }
    }
    assert!(inside > 10_000, "{inside}");
}

#[test]
fn approximate_variants_and_the_seed_differ_measurably() {
    let sets = scene_sets(1);
    for v in [
        Variant::Lib(TriangleAlgorithm::BresenhamWalk),
        Variant::Seed000,
    ] {
        let diff: u64 = sets
            .iter()
            .map(|s| accuracy(v, SubpixelPrecision::Bits12, s).differing_px)
            .sum();
        assert!(diff > 0, "{}", v.name());
    }
    // The seed's 32-bit integers fail on large triangles (the exact
    // variants handle every size: `exact_variants_match_the_reference_at_every_size`).
    assert!(largest_ok(Variant::Seed000, SubpixelPrecision::Bits12) < 4096);
}

fn v(x: i64, y: i64) -> Vertex {
    Vertex::from_raw(x as i32, y as i32)
}

#[test]
fn every_variant_is_safe_at_the_ends_of_the_range() {
    let (lo, hi) = (i64::from(i32::MIN), i64::from(i32::MAX));
    let coords = [lo, lo + 1, -4096, -1, 0, 1, 2048, 4096, hi - 1, hi];
    let clips = [
        Rectangle::new(Point::new(-8, -8), Size::new(16, 16)),
        Rectangle::new(Point::new(-524_300, -524_300), Size::new(40, 40)),
        Rectangle::new(Point::new(524_270, 524_270), Size::new(40, 40)),
        Rectangle::new(Point::new(i32::MIN, i32::MIN), Size::new(u32::MAX, 64)),
        Rectangle::new(Point::new(i32::MAX - 10, 0), Size::new(u32::MAX, 8)),
        Rectangle::new(Point::zero(), Size::zero()),
    ];
    let mut k = 0usize;
    let mut next = || {
        k = k.wrapping_mul(2_654_435_761).wrapping_add(12_345);
        coords[(k >> 7) % coords.len()]
    };
    let mut tris = vec![];
    for _ in 0..200 {
        tris.push(Triangle::new(
            v(next(), next()),
            v(next(), next()),
            v(next(), next()),
        ));
    }
    // Degenerate: a point, a segment, a sliver one raw unit wide.
    tris.push(Triangle::new(v(5, 5), v(5, 5), v(5, 5)));
    tris.push(Triangle::new(v(lo, lo), v(0, 0), v(hi, hi)));
    tris.push(Triangle::new(v(lo, lo), v(hi, hi), v(hi, hi - 1)));
    // Clips as wide and as tall as the whole range, for the first few.
    let long_clips = [
        Rectangle::new(Point::new(-600_000, -1), Size::new(1_200_000, 2)),
        Rectangle::new(Point::new(-1, -600_000), Size::new(2, 1_200_000)),
    ];
    let mut cases: Vec<(&Triangle, &Rectangle)> = tris
        .iter()
        .flat_map(|t| clips.iter().map(move |c| (t, c)))
        .collect();
    cases.extend(
        tris.iter()
            .take(12)
            .flat_map(|t| long_clips.iter().map(move |c| (t, c))),
    );
    for (t, clip) in cases {
        for a in TriangleAlgorithm::ALL {
            for p in SubpixelPrecision::ALL {
                let mut n = 0u64;
                let _ = t.for_each_span_with(a, p, clip, |s| {
                    let inside = s.x_start < s.x_end
                        && i64::from(s.x_start) >= i64::from(clip.top_left.x)
                        && i64::from(s.x_end)
                            <= i64::from(clip.top_left.x) + i64::from(clip.size.width)
                        && i64::from(s.y) >= i64::from(clip.top_left.y)
                        && i64::from(s.y)
                            < i64::from(clip.top_left.y) + i64::from(clip.size.height);
                    assert!(inside, "{a} at {p} bits: {s:?} outside {clip:?} for {t:?}");
                    n += 1;
                    Ok::<(), ()>(())
                });
                assert!(n <= u64::from(clip.size.height));
            }
        }
    }
}

#[test]
fn snapping_rounds_to_nearest_ties_to_even_and_stays_in_range() {
    for p in SubpixelPrecision::ALL {
        let step = 1i64 << (12 - p.bits());
        for r in [
            i64::from(i32::MIN),
            -step * 3 / 2,
            -1,
            0,
            1,
            step / 2,
            step * 3 / 2,
            i64::from(i32::MAX),
        ] {
            let (x, _) = p.snap(v(r, 0)).raw();
            let x = i64::from(x);
            assert_eq!(x % step, 0, "{r} at {p} bits");
            let d = (x - r).abs();
            let top = x + step > i64::from(i32::MAX);
            assert!(
                d * 2 < step || top || (d * 2 == step && (x / step) % 2 == 0),
                "{r} -> {x} at {p} bits"
            );
        }
    }
}

/// At the documented end of the barycentric evaluator's 32-bit guarantee
/// (`2^(31 - u) - 1` px² at `u = max(bits, 1)` subpixel bits), where it
/// steps in 32 bits, and 16 times beyond it, where it steps in 64 bits, it
/// lights the reference's pixels.
#[test]
fn barycentric_is_exact_on_both_sides_of_the_32_bit_bound() {
    let mut lit = 0;
    for p in SubpixelPrecision::ALL {
        let max = (1i64 << (31 - p.bits().max(1))) - 1;
        // A right triangle whose box is W x H pixels, W H <= max, with W a
        // power of two: the worst case at the opposite corner.
        let w = 1i64 << ((63 - max.leading_zeros()) / 2);
        let h = max / w;
        assert!(w * h <= max);
        let px = 4096;
        for k in [1, 4] {
            let t = Triangle::new(v(0, 0), v(k * w * px, 0), v(0, k * h * px));
            for (x, y) in [
                (0, 0),
                (k * w - 24, 0),
                (0, k * h - 24),
                (k * w / 2 - 12, k * h / 2 - 12),
            ] {
                let clip = Rectangle::new(Point::new(x as i32, y as i32), Size::new(24, 24));
                let want = reference(p, &t, &clip);
                lit += want.cells.iter().sum::<u32>();
                let got = drawn(TriangleAlgorithm::Barycentric, p, &t, &clip);
                assert!(
                    got == want,
                    "{p} bits, box {}x{} px, {clip:?}: {:?}",
                    k * w,
                    k * h,
                    want.diff(&got)
                );
            }
        }
    }
    assert!(lit > 1000, "{lit}");
}

use proptest::prelude::*;

proptest! {
    /// The barycentric evaluator against the independent winding-number
    /// reference of `tests/common`, on the snapped triangle, at every
    /// scale from a few pixels to the whole range.
    #[test]
    fn barycentric_matches_the_independent_reference(
        scale in 13u32..=32,
        c in (any::<i32>(), any::<i32>()),
        d in prop::array::uniform6(any::<i64>()),
        p in 0usize..4,
        corner in 0usize..4,
    ) {
        let r = 1i64 << scale;
        let (cx, cy) = if scale == 32 { (0, 0) } else { (i64::from(c.0), i64::from(c.1)) };
        let at = |k: usize| (d[k].rem_euclid(2 * r + 1) - r + [cx, cy][k % 2])
            .clamp(i64::from(i32::MIN), i64::from(i32::MAX));
        let t = Triangle::new(v(at(0), at(1)), v(at(2), at(3)), v(at(4), at(5)));
        let p = SubpixelPrecision::ALL[p];
        let snapped = t.snapped(p);
        // A 24 x 24 window at a corner or the centroid.
        let (wx, wy) = if corner < 3 {
            snapped.vertices[corner].raw()
        } else {
            let s = snapped.vertices.map(|v| v.raw());
            (
                ((i64::from(s[0].0) + i64::from(s[1].0) + i64::from(s[2].0)) / 3) as i32,
                ((i64::from(s[0].1) + i64::from(s[1].1) + i64::from(s[2].1)) / 3) as i32,
            )
        };
        let (x0, y0) = (i64::from(wx >> 12) - 12, i64::from(wy >> 12) - 12);
        let want = common::reference_triangle(&snapped, x0, y0, 24, 24);
        let mut got = common::Grid::new(x0, y0, 24, 24);
        let clip = got.clip();
        let _ = t.for_each_span_with(TriangleAlgorithm::Barycentric, p, &clip, |s| {
            for x in s.x_start..s.x_end {
                got.bump(i64::from(x), i64::from(s.y));
            }
            Ok::<(), ()>(())
        });
        prop_assert_eq!(got.diff(&want), vec![]);
    }
}

/// Found by a robustness audit: on triangles hundreds of thousands of
/// pixels tall, the walk's drift lit whole pixels outside the vertices'
/// bounding box (and past `render --max-pixels`' estimate). Each walked
/// edge position is now kept within its edge's x range: random triangles
/// with vertices anywhere in the 20.12 range, through windows on their
/// extreme vertices, light no pixel whose centre lies outside the box of
/// the snapped vertices, at every precision; drifted pixels do occur
/// inside it (the walk is not exact), and the walk stays watertight (a
/// triangle and its neighbour across an edge never both light a pixel).
#[test]
fn the_walk_keeps_to_the_vertices_bounding_box() {
    let mut rng = rng::Rng(0x1F83_D9AB_FB41_BD6B);
    let mut mismatched = 0u32;
    for case in 0..3_000u32 {
        let mut at = || Vertex::from_raw(rng.next() as i32, rng.next() as i32);
        let (a, b, c) = (at(), at(), at());
        let p = [
            SubpixelPrecision::Bits0,
            SubpixelPrecision::Bits4,
            SubpixelPrecision::Bits8,
            SubpixelPrecision::Bits12,
        ][case as usize % 4];
        let t = Triangle::new(a, b, c);
        // Across the edge a-b from c: the mirror image of c.
        let (ra, rb, rc) = (a.raw(), b.raw(), c.raw());
        let mirror = |u: i32, v: i32, w: i32| {
            (i64::from(u) + i64::from(v) - i64::from(w)).clamp(i32::MIN.into(), i32::MAX.into())
                as i32
        };
        let d = Vertex::from_raw(mirror(ra.0, rb.0, rc.0), mirror(ra.1, rb.1, rc.1));
        let n = Triangle::new(a, b, d);
        // Neighbours only if d, snapped, lies strictly on the other side
        // of a-b (the mirror may have been cut to the range).
        let turn = |t: &Triangle| {
            let [u, v, w] = t
                .snapped(p)
                .vertices
                .map(|v| v.raw())
                .map(|(x, y)| (i128::from(x), i128::from(y)));
            ((v.0 - u.0) * (w.1 - u.1) - (v.1 - u.1) * (w.0 - u.0)).signum()
        };
        let neighbours = turn(&t) * turn(&n) < 0;
        let s = t.snapped(p).vertices.map(|v| v.raw());
        let (xs, ys) = (s.map(|v| i64::from(v.0)), s.map(|v| i64::from(v.1)));
        let (x_lo, x_hi) = (*xs.iter().min().unwrap(), *xs.iter().max().unwrap());
        let (y_lo, y_hi) = (*ys.iter().min().unwrap(), *ys.iter().max().unwrap());
        // A 48 x 48 window at each snapped vertex.
        for v in s {
            let corner = Point::new(
                (v.0 >> 12).saturating_sub(24),
                (v.1 >> 12).saturating_sub(24),
            );
            let clip = Rectangle::new(corner, Size::new(48, 48));
            let got = drawn(TriangleAlgorithm::EdgeWalk, p, &t, &clip);
            let other = drawn(TriangleAlgorithm::EdgeWalk, p, &n, &clip);
            let want = reference(p, &t, &clip);
            for (k, (&lit, &also)) in got.cells.iter().zip(&other.cells).enumerate() {
                let (i, j) = (got.x0 + (k % got.w) as i64, got.y0 + (k / got.w) as i64);
                let (cx, cy) = (i * 4096 + 2048, j * 4096 + 2048);
                if lit > 0 {
                    assert!(
                        (x_lo..=x_hi).contains(&cx) && (y_lo..=y_hi).contains(&cy),
                        "{t:?} at {p} bits: pixel ({i}, {j}) outside the box"
                    );
                }
                if neighbours {
                    assert!(
                        lit + also <= 1,
                        "{t:?} and {n:?} at {p} bits: ({i}, {j}) lit twice"
                    );
                }
                mismatched += u32::from(lit != want.cells[k]);
            }
        }
    }
    assert!(
        mismatched > 0,
        "no drift seen: the test would not see it leave the box"
    );
}
