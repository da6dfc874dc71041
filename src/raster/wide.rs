//! The one wide-integer abstraction of the raster core.
//!
//! Every exact computation in the crate (edge setup, orientation, line
//! clipping) is written once, generic over [`Wide`], and run in the
//! narrowest of `i32`, `i64` and `i128` that the shape's own bounds allow.
//! Callers pick the width from a stated bound, never by trying and
//! wrapping: nothing here relies on wraparound, and every conversion down
//! is checked.

use core::fmt::Debug;
use core::ops::{Add, Mul, Neg, Shr, Sub};

/// A signed integer the raster core computes in: `i32`, `i64` or `i128`.
pub(crate) trait Wide:
    Copy
    + Debug
    + Ord
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Neg<Output = Self>
    + Shr<u32, Output = Self>
{
    /// 0.
    const ZERO: Self;
    /// 1.
    const ONE: Self;
    /// `v` in this width, if it fits.
    fn narrow(v: i64) -> Option<Self>;
    /// `v` in this width, if it fits.
    fn narrow_from_i128(v: i128) -> Option<Self>;
    /// The value as `i64`, if it fits.
    fn to_i64(self) -> Option<i64>;
    /// The value as `i32`, if it fits.
    fn to_i32(self) -> Option<i32>;
    /// `floor(self / d)` and `self - d floor(self / d)` (in `0..d`), for
    /// `d > 0`; `None` for `d <= 0`.
    fn div_rem_floor(self, d: Self) -> Option<(Self, Self)>;
}

macro_rules! impl_wide {
    ($t:ty) => {
        impl Wide for $t {
            const ZERO: Self = 0;
            const ONE: Self = 1;
            #[inline]
            fn narrow(v: i64) -> Option<Self> {
                <$t>::try_from(v).ok()
            }
            #[inline]
            fn narrow_from_i128(v: i128) -> Option<Self> {
                <$t>::try_from(v).ok()
            }
            #[inline]
            fn to_i64(self) -> Option<i64> {
                i64::try_from(self).ok()
            }
            #[inline]
            fn to_i32(self) -> Option<i32> {
                i32::try_from(self).ok()
            }
            #[inline]
            fn div_rem_floor(self, d: Self) -> Option<(Self, Self)> {
                // With d > 0, Euclidean division is floor division, and it
                // cannot overflow (only `MIN / -1` does).
                (d > 0).then(|| (self.div_euclid(d), self.rem_euclid(d)))
            }
        }
    };
}

impl_wide!(i32);
impl_wide!(i64);
impl_wide!(i128);

/// `floor(n / d)` and the remainder in `0..d`, for `d > 0`, in 32 bits when
/// both operands fit (one hardware division on a 32-bit core) and in 64
/// bits otherwise. `None` for `d <= 0`.
#[inline]
pub(crate) fn div_rem_floor(n: i64, d: i64) -> Option<(i64, i64)> {
    match (i32::try_from(n), i32::try_from(d)) {
        (Ok(n), Ok(d)) => n
            .div_rem_floor(d)
            .map(|(q, r)| (i64::from(q), i64::from(r))),
        _ => n.div_rem_floor(d),
    }
}

/// `n1 * n2` divided by `d > 0`, rounded up, and the remainder
/// `ceil(n1 n2 / d) d - n1 n2` (in `0..d`): in 32 or 64 bits when the
/// product fits `i64`, in `i128` otherwise. `None` if `d <= 0` or the
/// quotient does not fit `i64`.
pub(crate) fn mul_div_ceil(n1: i64, n2: i64, d: i64) -> Option<(i64, i64)> {
    match n1.checked_mul(n2).and_then(i64::checked_neg) {
        // ceil(n / d) = -floor(-n / d), and the remainder of -n is c d - n.
        Some(minus_n) => div_rem_floor(minus_n, d).map(|(f, r)| (-f, r)),
        None => {
            let minus_n = -(i128::from(n1) * i128::from(n2));
            let (f, r) = minus_n.div_rem_floor(i128::from(d))?;
            Some((i64::narrow_from_i128(-f)?, i64::narrow_from_i128(r)?))
        }
    }
}

/// The doubled signed area of `a, b, c` (raw 20.12 units): positive when
/// `a -> b -> c` turns clockwise on screen (y down). Exact for any
/// coordinates in `i32`: differences reach `2^32` and their products
/// `2^64`, so it is computed in `i64` when every difference fits 31 bits
/// (products below `2^62`) and in `i128` otherwise.
pub(crate) fn orientation(a: (i32, i32), b: (i32, i32), c: (i32, i32)) -> i128 {
    let d = |p: (i32, i32), o: (i32, i32)| {
        (
            i64::from(p.0) - i64::from(o.0),
            i64::from(p.1) - i64::from(o.1),
        )
    };
    let (u, v) = (d(b, a), d(c, a));
    let small = |x: i64| x.unsigned_abs() < 1 << 31;
    if small(u.0) && small(u.1) && small(v.0) && small(v.1) {
        i128::from(u.0 * v.1 - u.1 * v.0)
    } else {
        i128::from(u.0) * i128::from(v.1) - i128::from(u.1) * i128::from(v.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn floor_division_of_negatives() {
        assert_eq!(div_rem_floor(-7, 2), Some((-4, 1)));
        assert_eq!(div_rem_floor(i64::MIN, 3), Some((-3074457345618258603, 1)));
        assert_eq!(div_rem_floor(5, 0), None);
    }

    #[test]
    fn ceiling_of_products_beyond_i64() {
        // (2^40)(2^40) / (2^33 + 1), rounded up, checked against u128.
        let (n, d) = (1i64 << 40, (1i64 << 33) + 1);
        let exact = (1u128 << 80).div_ceil(d as u128);
        let (c, r) = mul_div_ceil(n, n, d).unwrap();
        assert_eq!(c as u128, exact);
        assert_eq!(r as u128, exact * d as u128 - (1u128 << 80));
        assert_eq!(mul_div_ceil(-3, 5, 4), Some((-3, 3)));
    }

    #[test]
    fn orientation_at_the_extremes() {
        let (lo, hi) = (i32::MIN, i32::MAX);
        // Counter-clockwise on screen: negative; the magnitude needs 65 bits.
        let area = orientation((lo, lo), (lo, hi), (hi, lo));
        assert_eq!(area, -((1i128 << 32) - 1) * ((1i128 << 32) - 1));
        assert_eq!(orientation((0, 0), (4, 0), (0, 4)), 16);
        assert_eq!(orientation((0, 0), (1, 1), (2, 2)), 0);
    }
}
