//! The Delaunay point sets of `benches/delaunay.rs` and
//! `examples/icount_delaunay.rs`, shared so that host and Cortex-M4
//! figures are for the same points.

#![allow(dead_code)] // each user takes what it needs

use embedded_raster::Vertex;

/// The most points in a set.
pub const MAX: usize = 1024;

/// Set labels and sizes: random points over 320 x 240, or grids.
pub const SETS: [(&str, usize); 4] = [
    ("random 100", 100),
    ("random 1000", 1000),
    ("grid 10x10", 10),
    ("grid 32x32", 32),
];

/// Fills `out` with the set `(label, n)` of [`SETS`]; returns its
/// length.
pub fn fill((label, n): (&str, usize), out: &mut [Vertex; MAX]) -> usize {
    if label.starts_with("random") {
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let mut next = |m: u64| {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed % m) as i32
        };
        for v in &mut out[..n] {
            *v = Vertex::from_raw(next(320 * 4096), next(240 * 4096));
        }
        n
    } else {
        for (k, v) in out[..n * n].iter_mut().enumerate() {
            let (i, j) = ((k % n) as i32, (k / n) as i32);
            *v = Vertex::from_raw((4 + 7 * i) * 4096, (4 + 7 * j) * 4096);
        }
        n * n
    }
}

/// FNV-1a over the triangles' vertex indices, to compare with the host.
pub fn fnv1a(triangles: impl Iterator<Item = [usize; 3]>) -> u32 {
    let mut h = 0x811c_9dc5u32;
    for i in triangles.flatten() {
        for b in (i as u16).to_le_bytes() {
            h = (h ^ u32::from(b)).wrapping_mul(0x0100_0193);
        }
    }
    h
}
