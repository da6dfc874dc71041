//! Accuracy measurement of the triangle variants, shared by the `tradeoff`
//! example (the report) and `tests/variants.rs` (the assertions).
//!
//! Everything is deterministic: the scene sets come from a fixed-seed
//! generator. The exact baseline is the default rasterizer
//! (`TriangleAlgorithm::EdgeExact` at 12 bits) on the unsnapped triangles;
//! `tests/triangle.rs` checks it pixel for pixel against the independent
//! winding-number reference of `tests/common`.
//!
//! It also holds `seed000`, the float-setup rasterizer of seed 000 taken
//! literally, as a reference point. It is deliberately not in the library.

#![allow(dead_code)]

use embedded_graphics_core::{
    geometry::{Point, Size},
    primitives::Rectangle,
};
use embedded_raster::{Span, SubpixelPrecision, Triangle, TriangleAlgorithm, Vertex};

/// A library variant, or the seed's float setup.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Variant {
    Lib(TriangleAlgorithm),
    Seed000,
}

impl Variant {
    pub const ALL: [Variant; 5] = [
        Variant::Lib(TriangleAlgorithm::EdgeExact),
        Variant::Lib(TriangleAlgorithm::Barycentric),
        Variant::Lib(TriangleAlgorithm::EdgeWalk),
        Variant::Lib(TriangleAlgorithm::BresenhamWalk),
        Variant::Seed000,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Variant::Lib(a) => a.name(),
            Variant::Seed000 => "seed000-float",
        }
    }

    /// Calls `f` with each span of `t` snapped to `p`, inside `clip`.
    pub fn spans(self, p: SubpixelPrecision, t: &Triangle, clip: &Rectangle, f: impl FnMut(Span)) {
        let mut f = f;
        match self {
            Variant::Lib(a) => {
                // Inlined like the caller's closure (see `draw_variant`).
                let _ = t.for_each_span_with(
                    a,
                    p,
                    clip,
                    #[inline(always)]
                    |s| {
                        f(s);
                        Ok::<(), ()>(())
                    },
                );
            }
            Variant::Seed000 => seed000(&t.snapped(p), clip, f),
        }
    }
}

/// Seed 000's `EdgeEqn` and `FlatTri.Draw`, literally: `double`
/// coefficients scaled by 2^12 and truncated to `int` (Java's saturating
/// cast, which Rust's `as` matches), 32-bit wrapping integer evaluation at
/// the integer pixel coordinates (the pixel's corner, not its centre),
/// `>= 0` on every edge (no tie rule), the bounding box truncated from the
/// vertices, the `xflag` early exit. The vertex-sorting table of the seed
/// only selects the extreme vertices; min and max do the same here.
pub fn seed000(t: &Triangle, clip: &Rectangle, mut f: impl FnMut(Span)) {
    const FRACBITS: i32 = 12;
    let v: Vec<(f64, f64)> = t
        .vertices
        .iter()
        .map(|v| {
            let (x, y) = v.raw();
            (f64::from(x) / 4096.0, f64::from(y) / 4096.0)
        })
        .collect();
    let scale = f64::from(1 << FRACBITS);
    let edge = |v0: (f64, f64), v1: (f64, f64)| {
        let a = v0.1 - v1.1;
        let b = v1.0 - v0.0;
        let c = -0.5 * (a * (v0.0 + v1.0) + b * (v0.1 + v1.1));
        [(a * scale) as i32, (b * scale) as i32, (c * scale) as i32]
    };
    let mut e = [edge(v[0], v[1]), edge(v[1], v[2]), edge(v[2], v[0])];
    let area = e[0][2].wrapping_add(e[1][2]).wrapping_add(e[2][2]);
    if area == 0 {
        return;
    }
    if area < 0 {
        for k in &mut e {
            *k = k.map(i32::wrapping_neg);
        }
    }
    let min = |g: fn(&(f64, f64)) -> f64| v.iter().map(g).fold(f64::INFINITY, f64::min);
    let max = |g: fn(&(f64, f64)) -> f64| v.iter().map(g).fold(f64::NEG_INFINITY, f64::max);
    let mut x_min = min(|p| p.0) as i32;
    let mut x_max = (max(|p| p.0) + 1.0) as i32;
    let mut y_min = min(|p| p.1) as i32;
    let mut y_max = (max(|p| p.1) + 1.0) as i32;
    let (cx0, cy0) = (clip.top_left.x, clip.top_left.y);
    let cx1 = cx0 + clip.size.width as i32 - 1;
    let cy1 = cy0 + clip.size.height as i32 - 1;
    x_min = x_min.max(cx0);
    x_max = x_max.min(cx1);
    y_min = y_min.max(cy0);
    y_max = y_max.min(cy1);
    let eval = |k: usize, x: i32, y: i32| {
        e[k][0]
            .wrapping_mul(x)
            .wrapping_add(e[k][1].wrapping_mul(y))
            .wrapping_add(e[k][2])
    };
    let mut t = [
        eval(0, x_min, y_min),
        eval(1, x_min, y_min),
        eval(2, x_min, y_min),
    ];
    let mut y = y_min;
    while y <= y_max {
        let mut ev = t;
        let mut start = None;
        let mut x = x_min;
        while x <= x_max {
            if (ev[0] | ev[1] | ev[2]) >= 0 {
                start.get_or_insert(x);
            } else if start.is_some() {
                break;
            }
            for (v, e) in ev.iter_mut().zip(&e) {
                *v = v.wrapping_add(e[0]);
            }
            x += 1;
        }
        if let Some(s) = start {
            f(Span {
                y,
                x_start: s,
                x_end: x,
            });
        }
        for (v, e) in t.iter_mut().zip(&e) {
            *v = v.wrapping_add(e[1]);
        }
        y += 1;
    }
}

/// SplitMix64: a small fixed-seed generator.
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }

    pub fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in `lo..=hi`.
    pub fn range(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next() % (hi - lo + 1) as u64) as i64
    }
}

pub fn raw(x: i64, y: i64) -> Vertex {
    Vertex::from_raw(x as i32, y as i32)
}

/// A named, fixed set of triangles over one clip rectangle; `mesh` sets
/// tile a region with shared edges.
pub struct SceneSet {
    pub name: &'static str,
    pub clip: Rectangle,
    pub tris: Vec<Triangle>,
    pub mesh: bool,
}

const PX: i64 = 4096;

fn window(side: u32) -> Rectangle {
    Rectangle::new(Point::zero(), Size::new(side, side))
}

/// The fixed scene sets; `scale` (1 for the report, smaller in quick
/// tests) multiplies the number of triangles.
pub fn scene_sets(scale: usize) -> Vec<SceneSet> {
    let mut rng = Rng::new(0x7a11_0c47);
    let n = 60 * scale;
    let mut sets = vec![];

    let mut random = vec![];
    for _ in 0..n {
        let mut c = || rng.range(-8 * PX, 136 * PX);
        random.push(Triangle::new(raw(c(), c()), raw(c(), c()), raw(c(), c())));
    }
    sets.push(SceneSet {
        name: "random",
        clip: window(128),
        tris: random,
        mesh: false,
    });

    // Vertices on pixel corners and centres: every tie of the sampling rule.
    let mut ties = vec![];
    for _ in 0..n {
        let mut c = || rng.range(-2, 64) * (PX / 2);
        ties.push(Triangle::new(raw(c(), c()), raw(c(), c()), raw(c(), c())));
    }
    sets.push(SceneSet {
        name: "ties",
        clip: window(32),
        tris: ties,
        mesh: false,
    });

    // Long edges with the third vertex within a pixel of them.
    let mut slivers = vec![];
    for _ in 0..n {
        let (ax, ay) = (rng.range(0, 128 * PX), rng.range(0, 128 * PX));
        let (bx, by) = (rng.range(0, 128 * PX), rng.range(0, 128 * PX));
        let t = rng.range(0, 4096);
        let (mx, my) = (ax + (bx - ax) * t / 4096, ay + (by - ay) * t / 4096);
        let (ox, oy) = (rng.range(-PX, PX), rng.range(-PX, PX));
        slivers.push(Triangle::new(
            raw(ax, ay),
            raw(bx, by),
            raw(mx + ox, my + oy),
        ));
    }
    sets.push(SceneSet {
        name: "slivers",
        clip: window(128),
        tris: slivers,
        mesh: false,
    });

    // One vertex near the window, two far off-screen (up to the range).
    let mut far = vec![];
    for _ in 0..n {
        let far_c = |r: &mut Rng| r.range(-(1i64 << 31) + 1, (1i64 << 31) - 1);
        let (ax, ay) = (rng.range(0, 64 * PX), rng.range(0, 64 * PX));
        let (bx, by, cx, cy) = (
            far_c(&mut rng),
            far_c(&mut rng),
            far_c(&mut rng),
            far_c(&mut rng),
        );
        far.push(Triangle::new(raw(ax, ay), raw(bx, by), raw(cx, cy)));
    }
    sets.push(SceneSet {
        name: "far",
        clip: window(64),
        tris: far,
        mesh: false,
    });

    // Jittered grid meshes: 8 x 8 cells of 12 px, inner vertices moved by
    // up to 4 px at full subpixel precision, each cell split on a random
    // diagonal.
    for m in 0..scale.max(1) {
        let cells = 8i64;
        let cell = 12 * PX;
        let mut grid = vec![];
        for j in 0..=cells {
            for i in 0..=cells {
                let inner = i > 0 && j > 0 && i < cells && j < cells;
                let mut jit = || if inner { rng.range(-4 * PX, 4 * PX) } else { 0 };
                let (jx, jy) = (jit(), jit());
                grid.push((2 * PX + i * cell + jx + m as i64, 2 * PX + j * cell + jy));
            }
        }
        let at = |i: i64, j: i64| {
            let (x, y) = grid[(j * (cells + 1) + i) as usize];
            raw(x, y)
        };
        let mut tris = vec![];
        for j in 0..cells {
            for i in 0..cells {
                let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
                if rng.next() & 1 == 0 {
                    tris.push(Triangle::new(a, b, c));
                    tris.push(Triangle::new(a, c, d));
                } else {
                    tris.push(Triangle::new(a, b, d));
                    tris.push(Triangle::new(b, c, d));
                }
            }
        }
        sets.push(SceneSet {
            name: "mesh",
            clip: window(104),
            tris,
            mesh: true,
        });
    }

    // Fans: 24 ring vertices around a centre, alternating windings.
    for _ in 0..scale.max(1) {
        let (cx, cy) = (rng.range(40 * PX, 60 * PX), rng.range(40 * PX, 60 * PX));
        let k = 24;
        let ring: Vec<(i64, i64)> = (0..k)
            .map(|i| {
                let a = i as f64 * std::f64::consts::TAU / k as f64;
                let r = rng.range(20 * PX, 38 * PX) as f64;
                (cx + (r * a.cos()) as i64, cy + (r * a.sin()) as i64)
            })
            .collect();
        let tris = (0..k)
            .map(|i| {
                let (a, b) = (ring[i], ring[(i + 1) % k]);
                if i.is_multiple_of(2) {
                    Triangle::new(raw(cx, cy), raw(a.0, a.1), raw(b.0, b.1))
                } else {
                    Triangle::new(raw(b.0, b.1), raw(a.0, a.1), raw(cx, cy))
                }
            })
            .collect();
        sets.push(SceneSet {
            name: "fan",
            clip: window(100),
            tris,
            mesh: true,
        });
    }
    sets
}

/// Per-row spans of one triangle, indexed by `y - clip.y`.
fn rows(v: Variant, p: SubpixelPrecision, t: &Triangle, clip: &Rectangle) -> Vec<Vec<(i32, i32)>> {
    let mut r = vec![vec![]; clip.size.height as usize];
    v.spans(p, t, clip, |s| {
        let i = (s.y - clip.top_left.y) as usize;
        assert!(
            s.x_start < s.x_end
                && s.x_start >= clip.top_left.x
                && s.x_end <= clip.top_left.x + clip.size.width as i32
                && i < r.len(),
            "{} emitted {s:?} outside {clip:?} for {t:?}",
            v.name()
        );
        r[i].push((s.x_start, s.x_end));
    });
    r
}

/// Pixels in exactly one of two span lists of a row.
fn row_xor(a: &[(i32, i32)], b: &[(i32, i32)]) -> u64 {
    let len = |s: &[(i32, i32)]| {
        s.iter()
            .map(|&(x0, x1)| u64::from(x0.abs_diff(x1)))
            .sum::<u64>()
    };
    let mut both = 0;
    for &(a0, a1) in a {
        for &(b0, b1) in b {
            let (lo, hi) = (a0.max(b0), a1.min(b1));
            if lo < hi {
                both += u64::from(lo.abs_diff(hi));
            }
        }
    }
    len(a) + len(b) - 2 * both
}

/// Accuracy of one variant at one precision over one set.
#[derive(Debug, Clone, Copy, Default)]
pub struct Accuracy {
    /// Pixels lit by the exact baseline, summed over triangles.
    pub reference_px: u64,
    /// Pixels lit by exactly one of the variant and the baseline.
    pub differing_px: u64,
    /// Mesh sets: pixels the exact rasterizer covers exactly once with the
    /// vertices snapped to the same precision (the mesh's interior, at
    /// that precision) that the variant writes 0 (gaps) or 2+ times
    /// (overdraw).
    pub gaps: u64,
    pub overdraw: u64,
}

pub fn accuracy(v: Variant, p: SubpixelPrecision, set: &SceneSet) -> Accuracy {
    accuracy_vs(v, p, set, SubpixelPrecision::Bits12)
}

/// Like [`accuracy`], with the baseline's vertices snapped to `base`.
pub fn accuracy_vs(
    v: Variant,
    p: SubpixelPrecision,
    set: &SceneSet,
    base: SubpixelPrecision,
) -> Accuracy {
    let exact = Variant::Lib(TriangleAlgorithm::EdgeExact);
    let (w, h) = (set.clip.size.width as usize, set.clip.size.height as usize);
    let mut counts_ref = vec![0u32; w * h];
    let mut counts = vec![0u32; w * h];
    let mut acc = Accuracy::default();
    let x0 = set.clip.top_left.x;
    let bump = |c: &mut Vec<u32>, j: usize, spans: &[(i32, i32)]| {
        for &(s, e) in spans {
            for x in s..e {
                c[j * w + (x - x0) as usize] += 1;
            }
        }
    };
    for t in &set.tris {
        let r = rows(exact, base, t, &set.clip);
        let o = rows(v, p, t, &set.clip);
        for (a, b) in r.iter().zip(&o) {
            acc.reference_px += a
                .iter()
                .map(|&(x0, x1)| u64::from(x0.abs_diff(x1)))
                .sum::<u64>();
            acc.differing_px += row_xor(a, b);
        }
        if set.mesh {
            let snapped = rows(exact, p, t, &set.clip);
            for (j, (a, b)) in snapped.iter().zip(&o).enumerate() {
                bump(&mut counts_ref, j, a);
                bump(&mut counts, j, b);
            }
        }
    }
    if set.mesh {
        for (r, c) in counts_ref.iter().zip(&counts) {
            if *r == 1 {
                acc.gaps += u64::from(*c == 0);
                acc.overdraw += u64::from(*c >= 2);
            }
        }
    }
    acc
}

/// The irregular triangle of legs about `l` px that [`largest_ok`] tries,
/// and its four 48 x 48 windows: at its three corners and its centroid.
pub fn size_probe(l: i64) -> (Triangle, [Rectangle; 4]) {
    let f = |a: f64, b: f64| -> i64 { (a * l as f64 * 4096.0) as i64 + (b * 4096.0) as i64 };
    let pts = [
        (f(0.0, 0.3), f(0.0, 0.7)),
        (f(1.0, -0.45), f(0.3, 0.1)),
        (f(0.2, 0.6), f(1.0, -0.3)),
    ];
    let pts = pts.map(|(x, y)| (x.min((1 << 31) - 1), y.min((1 << 31) - 1)));
    let t = Triangle::new(
        raw(pts[0].0, pts[0].1),
        raw(pts[1].0, pts[1].1),
        raw(pts[2].0, pts[2].1),
    );
    let cx = (pts[0].0 + pts[1].0 + pts[2].0) / 3;
    let cy = (pts[0].1 + pts[1].1 + pts[2].1) / 3;
    let [a, b, c] = pts;
    let clips = [a, b, c, (cx, cy)].map(|(x, y)| {
        Rectangle::new(
            Point::new((x >> 12) as i32 - 24, (y >> 12) as i32 - 24),
            Size::new(48, 48),
        )
    });
    (t, clips)
}

/// The legs tried by [`largest_ok`], in px.
pub const SIZES: [i64; 9] = [16, 64, 256, 1024, 4096, 16384, 65536, 262144, 524287];

/// The largest triangle size from [`SIZES`] up to which the variant
/// handles triangles without error: its pixels differing from the exact
/// rasterizer on the same snapped vertices, in 48 x 48 windows at the three
/// corners and the centroid of an irregular triangle of that size, stay
/// within `max(1 %, twice the rate at the smallest size)` of the exact
/// pixels there (so a variant's own rule, such as Bresenham's closed
/// triangle, is not an error, but growing drift or overflow is). 0 if
/// even the smallest size fails.
pub fn largest_ok(v: Variant, p: SubpixelPrecision) -> i64 {
    let mut best = 0;
    let mut limit = None;
    for &l in &SIZES {
        let (t, clips) = size_probe(l);
        let mut acc = Accuracy::default();
        for clip in clips {
            let a = accuracy_vs(
                v,
                p,
                &SceneSet {
                    name: "size",
                    clip,
                    tris: vec![t],
                    mesh: false,
                },
                p,
            );
            acc.reference_px += a.reference_px;
            acc.differing_px += a.differing_px;
        }
        // Rate in parts per million of the exact pixels.
        let rate = acc.differing_px * 1_000_000 / acc.reference_px.max(1);
        let limit = *limit.get_or_insert((2 * rate).max(10_000));
        if rate > limit {
            break;
        }
        best = l;
    }
    best
}
