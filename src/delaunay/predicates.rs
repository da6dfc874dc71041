//! Exact orientation and in-circle tests on 20.12 vertices.
//!
//! # Widths
//!
//! A raw coordinate is an `i32`, so `|x| <= 2^31`, and a difference of two
//! coordinates has `|dx| < 2^32` (an `i64`).
//!
//! - **Orientation** `dx1 * dy2 - dy1 * dx2`: each product is below `2^64`
//!   in magnitude, the difference below `2^65`: `i128` with room to spare;
//!   `i64` when both differences are below `2^31` (products below `2^62`).
//! - **In-circle**, with every coordinate taken relative to `d`
//!   (`a' = a - d`, and so on):
//!
//!   ```text
//!   | a'x  a'y  a'x² + a'y² |
//!   | b'x  b'y  b'x² + b'y² |  =  lift(a') det(b', c') + lift(b') det(c', a') + lift(c') det(a', b')
//!   | c'x  c'y  c'x² + c'y² |
//!   ```
//!
//!   A lift `x² + y²` is below `2 * 2^64 = 2^65`, a 2 x 2 determinant below
//!   `2^65` in magnitude, each product below `2^130` and the sum of three
//!   below `3 * 2^130 < 2^132`: 133 signed bits, more than `i128` holds.
//!   When every difference is below `2^30` (points within 262,144 px of
//!   `d`, so every drawing on a screen), lifts and determinants are below
//!   `2^61` (`i64`), products below `2^122` and the sum below `2^124`
//!   (`i128`).
//!   Otherwise the three products are formed exactly as 256-bit magnitudes
//!   ([`U256`], from 64 x 64-bit partial products), summed separately for
//!   positive and negative terms (each sum below `2^132`, so no carry
//!   leaves the high limb) and compared. Both paths are exact for every
//!   pair of [`Vertex`] values; nothing wraps and nothing rounds.

use core::cmp::Ordering;

use crate::raster::wide;
use crate::vertex::Vertex;

/// Which way `a -> b -> c` turns, exactly: [`Ordering::Greater`] when the
/// signed area `(b - a) x (c - a)` is positive (clockwise on the screen,
/// whose y axis points down; counter-clockwise in y-up coordinates),
/// [`Ordering::Less`] when it is negative, [`Ordering::Equal`] when the
/// three points are collinear (or two coincide).
///
/// Exact for all vertices: the area is computed in `i128` (below `2^65`).
///
/// # Examples
///
/// ```
/// use core::cmp::Ordering;
/// use embedded_raster::{delaunay::orientation, Vertex};
///
/// let v = |x, y| Vertex::try_from_num(x, y).unwrap();
/// // Right, then down the screen: clockwise as seen on the display.
/// assert_eq!(orientation(v(0, 0), v(10, 0), v(10, 10)), Ordering::Greater);
/// assert_eq!(orientation(v(0, 0), v(10, 10), v(10, 0)), Ordering::Less);
/// assert_eq!(orientation(v(0, 0), v(5, 5), v(-7, -7)), Ordering::Equal);
/// ```
pub fn orientation(a: Vertex, b: Vertex, c: Vertex) -> Ordering {
    // The raster core's orientation, on coordinates far below 2^62.
    let p = |v: Vertex| {
        let (x, y) = v.raw();
        (i64::from(x), i64::from(y))
    };
    wide::orientation(p(a), p(b), p(c)).cmp(&0)
}

/// Where `d` lies relative to the circle through `a`, `b` and `c`, exactly,
/// for `a, b, c` with [`orientation`] `Greater`: [`Ordering::Greater`]
/// when `d` is strictly inside, [`Ordering::Equal`] on the circle,
/// [`Ordering::Less`] strictly outside. For `a, b, c` the other way round
/// the answer is reversed; for collinear `a, b, c` (no circle) it is the
/// side of the line `d` is on, or `Equal` on it.
///
/// Exact for all vertices, over the whole 20.12 range: `i128` when the
/// points are within 262,144 px of `d`, 256-bit products otherwise (the
/// proof is in the source).
///
/// # Examples
///
/// ```
/// use core::cmp::Ordering;
/// use embedded_raster::{delaunay::in_circle, Vertex};
///
/// let v = |x, y| Vertex::try_from_num(x, y).unwrap();
/// let (a, b, c) = (v(0, 0), v(10, 0), v(10, 10)); // clockwise on screen
/// assert_eq!(in_circle(a, b, c, v(5, 5)), Ordering::Greater);
/// assert_eq!(in_circle(a, b, c, v(0, 10)), Ordering::Equal); // a square's fourth corner
/// assert_eq!(in_circle(a, b, c, v(20, 20)), Ordering::Less);
/// // Far apart: still exact.
/// let (a, b, c) = (v(-500000, -500000), v(500000, -500000), v(500000, 500000));
/// assert_eq!(in_circle(a, b, c, v(-500000, 500000)), Ordering::Equal);
/// ```
pub fn in_circle(a: Vertex, b: Vertex, c: Vertex, d: Vertex) -> Ordering {
    let [a, b, c] = [a, b, c].map(|v| relative(v, d));
    let near = |p: Delta| p.0.unsigned_abs() < 1 << 30 && p.1.unsigned_abs() < 1 << 30;
    if near(a) && near(b) && near(c) {
        in_circle_near(a, b, c).cmp(&0)
    } else {
        in_circle_wide(a, b, c)
    }
}

/// A coordinate difference, `|x|, |y| < 2^32`.
type Delta = (i64, i64);

fn relative(v: Vertex, origin: Vertex) -> Delta {
    let ((x, y), (ox, oy)) = (v.raw(), origin.raw());
    (i64::from(x) - i64::from(ox), i64::from(y) - i64::from(oy))
}

/// `x² + y²`, below `2^65`.
fn lift(p: Delta) -> i128 {
    let (x, y) = (i128::from(p.0), i128::from(p.1));
    x * x + y * y
}

/// `p.x q.y - p.y q.x`, below `2^65` in magnitude.
fn det2(p: Delta, q: Delta) -> i128 {
    i128::from(p.0) * i128::from(q.1) - i128::from(p.1) * i128::from(q.0)
}

/// The determinant for differences below `2^30`: lifts and 2 x 2
/// determinants below `2^61` in `i64`, their products below `2^122` and the
/// sum below `2^124` in `i128`.
fn in_circle_near(a: Delta, b: Delta, c: Delta) -> i128 {
    let lift = |p: Delta| p.0 * p.0 + p.1 * p.1;
    let det2 = |p: Delta, q: Delta| p.0 * q.1 - p.1 * q.0;
    let term = |l: i64, d: i64| i128::from(l) * i128::from(d);
    term(lift(a), det2(b, c)) + term(lift(b), det2(c, a)) + term(lift(c), det2(a, b))
}

/// The determinant's sign from 256-bit products, for any differences.
fn in_circle_wide(a: Delta, b: Delta, c: Delta) -> Ordering {
    let terms = [
        (lift(a), det2(b, c)),
        (lift(b), det2(c, a)),
        (lift(c), det2(a, b)),
    ];
    let (mut positive, mut negative) = (U256::ZERO, U256::ZERO);
    for (l, det) in terms {
        // A lift is never negative.
        let product = U256::product(l.unsigned_abs(), det.unsigned_abs());
        if det > 0 {
            positive = positive.add(product);
        } else {
            negative = negative.add(product);
        }
    }
    positive.cmp(&negative)
}

/// An unsigned 256-bit integer `hi * 2^128 + lo`, just wide enough for
/// the in-circle sums (below `2^132`). Ordered by value: the derived
/// comparison looks at `hi` first.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) struct U256 {
    hi: u128,
    lo: u128,
}

impl U256 {
    const ZERO: Self = Self { hi: 0, lo: 0 };

    /// `a * b`, exactly, from four 64 x 64-bit partial products.
    pub(crate) fn product(a: u128, b: u128) -> Self {
        const LOW: u128 = u64::MAX as u128;
        let (a1, a0) = (a >> 64, a & LOW);
        let (b1, b0) = (b >> 64, b & LOW);
        // Each partial product of two values below 2^64 is below 2^128.
        let (p00, p01, p10, p11) = (a0 * b0, a0 * b1, a1 * b0, a1 * b1);
        // Bits 64..: three terms below 2^64 each, so below 3 * 2^64.
        let middle = (p00 >> 64) + (p01 & LOW) + (p10 & LOW);
        let lo = ((middle & LOW) << 64) | (p00 & LOW);
        // The whole product is below 2^256, so this sum is below 2^128.
        let hi = p11 + (p01 >> 64) + (p10 >> 64) + (middle >> 64);
        Self { hi, lo }
    }

    /// `self + other`; the caller keeps the sum below `2^256`.
    pub(crate) fn add(self, other: Self) -> Self {
        let (lo, carry) = self.lo.overflowing_add(other.lo);
        Self {
            hi: self.hi + other.hi + u128::from(carry),
            lo,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn product_matches_u128_when_small() {
        for (a, b) in [
            (0, 7),
            (3, 5),
            (u64::MAX as u128, u64::MAX as u128),
            (1 << 100, 1 << 27),
        ] {
            assert_eq!(U256::product(a, b), U256 { hi: 0, lo: a * b });
        }
    }

    #[test]
    fn product_carries_into_the_high_limb() {
        // (2^128 - 1)^2 = 2^256 - 2^129 + 1.
        let m = u128::MAX;
        assert_eq!(U256::product(m, m), U256 { hi: m - 1, lo: 1 });
        // 2^127 * 4 = 2^129.
        assert_eq!(U256::product(1 << 127, 4), U256 { hi: 2, lo: 0 });
        // (2^64 + 1)^2 = 2^128 + 2^65 + 1.
        let p = (1u128 << 64) + 1;
        assert_eq!(
            U256::product(p, p),
            U256 {
                hi: 1,
                lo: (1 << 65) + 1
            }
        );
    }

    #[test]
    fn add_carries() {
        let a = U256 {
            hi: 1,
            lo: u128::MAX,
        };
        assert_eq!(a.add(U256 { hi: 0, lo: 1 }), U256 { hi: 2, lo: 0 });
    }

    #[test]
    fn wide_path_agrees_with_i128_where_both_apply() {
        let cases: [[Delta; 3]; 4] = [
            [(5, 0), (0, 5), (-5, 0)],
            [(1 << 29, 3), (-7, 1 << 29), (-(1 << 29), -(1 << 29))],
            [(100, 200), (300, -400), (-500, 600)],
            [(1, 1), (2, 2), (3, 3)],
        ];
        for [a, b, c] in cases {
            assert_eq!(in_circle_wide(a, b, c), in_circle_near(a, b, c).cmp(&0));
            assert_eq!(in_circle_wide(b, a, c), in_circle_near(b, a, c).cmp(&0));
        }
    }
}
