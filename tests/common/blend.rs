//! The exact reference for interpolated attributes (Gouraud channels,
//! depths): the value at a pixel centre as a fraction of signed areas,
//! and the tolerance the docs promise. Written independently of the
//! library, in `i128` on raw 20.12 coordinates.

use embedded_raster::Triangle;

use super::raw;

/// The exact value of an attribute at the centre of pixel `(i, j)` as
/// `(n, d)` with `d > 0`: `sum(a_k w_k) / area2`, where `w_k` is the
/// signed area of the sub-triangle opposite vertex `k`. `t` must not be
/// degenerate.
pub fn exact_at(t: &Triangle, a: [i128; 3], i: i64, j: i64) -> (i128, i128) {
    let p = t.vertices.map(raw);
    let c = (i128::from(i) * 4096 + 2048, i128::from(j) * 4096 + 2048);
    let cross = |o: (i128, i128), u: (i128, i128), w: (i128, i128)| {
        (u.0 - o.0) * (w.1 - o.1) - (u.1 - o.1) * (w.0 - o.0)
    };
    let d = cross(p[0], p[1], p[2]);
    // Weight of vertex k: the area of the triangle (c, v_(k+1), v_(k+2)).
    let n = a[0] * cross(c, p[1], p[2]) + a[1] * cross(c, p[2], p[0]) + a[2] * cross(c, p[0], p[1]);
    if d < 0 {
        (-n, -d)
    } else {
        (n, d)
    }
}

/// Checks output `o` against the exact `n / d`: within 1, and equal to the
/// rounding (halves up) unless `n / d` is within 2^-12 of a half integer.
pub fn check_rounded(o: i128, (n, d): (i128, i128)) -> Result<(), String> {
    if (o * d - n).abs() >= d {
        return Err(format!("{o} is 1 or more away from {n}/{d}"));
    }
    let rounded = (2 * n + d).div_euclid(2 * d);
    if o != rounded && (2 * n - (o + rounded) * d).abs() * 4096 > 2 * d {
        return Err(format!("{o} is not {n}/{d} rounded ({rounded})"));
    }
    Ok(())
}
