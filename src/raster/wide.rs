//! The one wide-integer abstraction of the raster core.
//!
//! Every exact computation of the raster core (edge setup, orientation)
//! is written once, generic over [`Wide`], and run in the narrowest of
//! `i32`, `i64` and `i128` that the shape's own bounds allow; line
//! clipping splits its quotients so that `u64` holds them all, and
//! divides with [`div_rem_u64`], the same division as the 64-bit `Wide`.
//! Many values divided by one number (a shaded triangle's doubled area)
//! go through a [`Divisor`] prepared once.
//! Callers pick the width from a stated bound, never by trying and
//! wrapping: nothing here relies on wraparound, and every conversion down
//! is checked.

use core::ops::{Add, Mul, Neg, Shr, Sub};
use core::{
    fmt::Debug,
    num::{NonZeroU128, NonZeroU32, NonZeroU64},
};

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
    /// `a - b` in this width, for coordinates relative to a frame (see
    /// [`Frame`](super::frame::Frame)). `within_2_29` tells that the
    /// caller has shown `|a - b| < 2^29`, the bound under which edges step
    /// exactly in `i32`; without it, `i32` gives `None`. Wider types
    /// always hold the difference.
    fn difference(a: i32, b: i32, within_2_29: bool) -> Option<Self>;
    /// 0.
    const ZERO: Self;
    /// 1.
    const ONE: Self;
    /// `v` in this width, if it fits.
    fn narrow(v: i64) -> Option<Self>;
    /// The value as `i64`, if it fits.
    fn to_i64(self) -> Option<i64>;
    /// The value as `i32`, if it fits.
    fn to_i32(self) -> Option<i32>;
    /// `floor(self / d)` and `self - d floor(self / d)` (in `0..d`), for
    /// `d > 0`; `None` for `d <= 0`.
    fn div_rem_floor(self, d: Self) -> Option<(Self, Self)>;
    /// `self < other` for two values the caller has shown non-negative,
    /// compared as unsigned (x86-64 then adds the result as a carry).
    fn below(self, other: Self) -> bool;
}

macro_rules! impl_wide {
    ($t:ty, $u:ty, $difference:expr) => {
        impl_wide!($t, $u, $difference, |n: $t, d: $t| (
            n.div_euclid(d),
            n.rem_euclid(d)
        ));
    };
    ($t:ty, $u:ty, $difference:expr, $floor:expr) => {
        impl Wide for $t {
            #[inline(always)]
            fn difference(a: i32, b: i32, within_2_29: bool) -> Option<Self> {
                $difference(a, b, within_2_29)
            }
            const ZERO: Self = 0;
            const ONE: Self = 1;
            #[inline]
            fn narrow(v: i64) -> Option<Self> {
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
                (d > 0).then(|| $floor(self, d))
            }
            #[inline(always)]
            fn below(self, other: Self) -> bool {
                debug_assert!(self >= 0 && other >= 0);
                (self as $u) < (other as $u)
            }
        }
    };
}

// With `within_2_29`, `a - b` does not overflow `i32`.
impl_wide!(i32, u32, |a: i32, b: i32, within: bool| within
    .then(|| a - b));
impl_wide!(
    i64,
    u64,
    |a: i32, b: i32, _| Some(i64::from(a) - i64::from(b)),
    |n: i64, d: i64| match cfg!(target_pointer_width = "32") {
        true => floor_div_rem_by_shifts(n, d),
        false => (n.div_euclid(d), n.rem_euclid(d)),
    }
);

/// Restoring shift-and-subtract division of the unsigned `$n` by `$d >
/// 0`, one step per bit of the quotient: `(quotient, remainder)` in their
/// type. The divisor's top bit is first aligned with the dividend's (when
/// `n >= d`, so the shift loses nothing); `r < 2 step` throughout.
macro_rules! shift_subtract {
    ($n:expr, $d:expr) => {{
        let (n, d) = ($n, $d);
        let shift = d.leading_zeros().saturating_sub(n.leading_zeros());
        let (mut step, mut r, mut q) = (d << shift, n, 0);
        let mut bits = shift + 1;
        while bits > 0 {
            q <<= 1;
            if r >= step {
                r -= step;
                q |= 1;
            }
            step >>= 1;
            bits -= 1;
        }
        (q, r)
    }};
}

/// `floor(n / d)` and `n - d floor(n / d)` for `d > 0`, for 32-bit
/// targets: the magnitudes divided by `divide_u64` (inlined here; the
/// division [`div_rem_u64`] makes out of line), the signs applied after.
///
/// The library routine a 64-bit division links there takes about 1 KB of
/// flash (864 + 136 bytes on a Cortex-M4 at opt-level "s"); this took
/// 372 when measured (364 in BENCHMARKS.md's later count). Only shapes
/// off the 32-bit path divide in 64 bits (a triangle over 128 px a side,
/// an edge reaching far off the screen, a line clipped to the screen),
/// once or twice per edge, where
/// the quotient's bits (about 14 instructions each) are small beside the
/// pixels they light: on the Cortex-M4, when this was chosen, a line
/// with ends 10^6 px off the screen cost 13 % more than with the library
/// routine (lines have clipped in `u64` since), the 64-bit triangle
/// `HUGE` under 1 % more. Long division in 16-bit digits on the
/// hardware divider (Knuth's algorithm D) came within 3 % of the
/// library's speed (that line 2.4 % slower, `HUGE` 0.2 % faster) and took
/// 768 bytes.
#[inline(never)]
fn floor_div_rem_by_shifts(n: i64, d: i64) -> (i64, i64) {
    let (m, dd) = (n.unsigned_abs(), d.unsigned_abs());
    let (q, r) = divide_u64(m, dd);
    // n = -m: floor(-m / d) = -ceil(m / d) = -(q + [r > 0]), remainder
    // d - r. Both fit i64: q + [r > 0] <= 2^63, and r < d.
    let ceil = q + u64::from(n < 0 && r > 0);
    let (q, r) = match n < 0 {
        true => (
            0i64.checked_sub_unsigned(ceil),
            if r > 0 { dd - r } else { 0 },
        ),
        false => (i64::try_from(q).ok(), r),
    };
    (q.unwrap_or(i64::MIN), i64::try_from(r).unwrap_or(0))
}

/// `$name(n, d)`, `n / d` and `n % d` in `$t` for a nonzero `d`: the
/// operators on 64-bit targets; on 32-bit ones `$core`, out of line.
/// `$core(n, d)` (for `d > 0`) divides in the half width `$half` by
/// `$half_div` when both operands fit it, else by `$wide_div`.
macro_rules! unsigned_division {
    ($(#[$doc:meta])* $name:ident, $core:ident, $t:ty, $nonzero:ty, $half:ty, $half_nonzero:ty, $half_div:expr, $wide_div:expr) => {
        $(#[$doc])*
        #[cfg_attr(target_pointer_width = "32", inline(never))]
        #[cfg_attr(not(target_pointer_width = "32"), inline(always))]
        pub(crate) fn $name(n: $t, d: $nonzero) -> ($t, $t) {
            match cfg!(target_pointer_width = "32") {
                true => $core(n, d.get()),
                false => (n / d, n % d),
            }
        }

        /// The division of 32-bit targets: in the half width when both
        /// operands fit it, else the wide way.
        #[inline(always)]
        fn $core(n: $t, d: $t) -> ($t, $t) {
            debug_assert!(d > 0);
            match (
                <$half>::try_from(n),
                <$half>::try_from(d).ok().and_then(<$half_nonzero>::new),
            ) {
                (Ok(n), Some(d)) => {
                    let (q, r): ($half, $half) = $half_div(n, d);
                    (q.into(), r.into())
                }
                _ => $wide_div(n, d),
            }
        }
    };
}

unsigned_division!(
    /// `n / d` and `n % d` in `u64`. On 32-bit targets one hardware
    /// division when both fit 32 bits; out of line there, it has the flash
    /// of [`floor_div_rem_by_shifts`] (which inlines `divide_u64`): a
    /// firmware that links both has the loop twice, one that links one of
    /// them, as a firmware of flat triangles does, has it once, with no
    /// call between.
    div_rem_u64,
    divide_u64,
    u64,
    NonZeroU64,
    u32,
    NonZeroU32,
    |n: u32, d: NonZeroU32| (n / d, n % d),
    |n: u64, d: u64| shift_subtract!(n, d)
);

unsigned_division!(
    /// `n / d` and `n % d` in `u128`. A 32-bit target has no 128-bit
    /// division routine: the compiler expands each `u128` or `i128`
    /// division in place, about 1 KB of flash a site on a Cortex-M4; this
    /// one is out of line there, through [`div_rem_u64`] when both fit 64
    /// bits, else [`divide_by_estimates`].
    div_rem_u128,
    divide_u128,
    u128,
    NonZeroU128,
    u64,
    NonZeroU64,
    div_rem_u64,
    divide_by_estimates
);

/// `n / d` and `n % d` in `u128` for `d > 0`, a run of quotient bits at a
/// time on a 32-bit divider: each round divides the remainder's top 32
/// bits by the divisor's top 16, rounded up, which never gives more than
/// the quotient left (and gives about 15 bits of it, where
/// shift-and-subtract gives one), and takes that many divisors off.
///
/// With `head` the remainder's top 32 bits (`r >= head 2^rs`) and `top`
/// the divisor's top 16 rounded up (`d <= top 2^ds`), `e = floor(head /
/// top)` divisors shifted by `rs - ds` come to at most `e top 2^rs <= r`
/// (for `rs < ds`, `e` is shifted down instead, and `r` has at most 16
/// bits more than `d`). `top` is at most `2^16 (1 + 2^-15)` times
/// `d`'s leading bits, so a round leaves about `2^-15` of the quotient,
/// and the last rounds take the few divisors left; one divisor at least,
/// since `r >= d`.
///
/// On a Cortex-M4 (`.ci/itrace`): a Gouraud-shaded 16 px triangle's nine
/// divisions (quotients of about 60 bits) took 14,245 instructions by
/// shifts and subtractions, and 5,614 by estimates, about four rounds
/// each. The shading now divides by a prepared [`Divisor`] instead
/// (1,955 for the same nine); this serves the other `u128` divisions.
fn divide_by_estimates(n: u128, d: u128) -> (u128, u128) {
    let d_shift = (128 - d.leading_zeros()).saturating_sub(16);
    // Below 2^16, plus 1 when bits were dropped: at most 2^16.
    let top = u32::try_from(d >> d_shift).unwrap_or(u32::MAX) + u32::from(d_shift > 0);
    let (mut q, mut r) = (0u128, n);
    while r >= d {
        let r_shift = (128 - r.leading_zeros()).saturating_sub(32);
        let head = u32::try_from(r >> r_shift).unwrap_or(u32::MAX);
        let (e, shift) = match r_shift.checked_sub(d_shift) {
            Some(shift) => (head / top, shift),
            // r_shift >= d_shift - 16, since r >= d.
            None => ((head / top) >> (d_shift - r_shift), 0),
        };
        // An estimate of 0 has no shift (r_shift > 0 makes head at least
        // 2^31, over top): one divisor, which r holds.
        let (e, shift) = if e == 0 { (1, 0) } else { (e, shift) };
        r -= times_u32(d, e) << shift;
        q += u128::from(e) << shift;
    }
    (q, r)
}

/// `d e` for a product that fits `u128`: four 32-bit multiplications
/// with carries, where a `u128` product is sixteen.
#[inline(always)]
fn times_u32(d: u128, e: u32) -> u128 {
    let (mut product, mut carry) = (0u128, 0u64);
    for k in 0..4 {
        let limb = u64::from((d >> (32 * k)) as u32);
        // (2^32 - 1)^2 + 2^32 - 1 < 2^64.
        let p = limb * u64::from(e) + carry;
        product |= u128::from(p as u32) << (32 * k);
        carry = p >> 32;
    }
    product
}

/// `floor(n / d)` and `n - d floor(n / d)` for `d > 0`, through
/// [`div_rem_u128`] (`None` for `d <= 0`): the 128-bit `Wide`'s division,
/// so that 32-bit targets divide in one place.
fn floor_div_rem_i128(n: i128, d: i128) -> Option<(i128, i128)> {
    let d = NonZeroU128::new(u128::try_from(d).ok()?)?;
    floor_of(n, d.get(), div_rem_u128(n.unsigned_abs(), d))
}

/// The floor quotient and remainder of `n` by `d > 0` from those of `|n|`,
/// `(q, r)`.
#[inline(always)]
fn floor_of(n: i128, d: u128, (q, r): (u128, u128)) -> Option<(i128, i128)> {
    // For n >= 0, q <= n < 2^127 and r < d. For n = -m, floor(-m / d) =
    // -(q + [r > 0]) >= -2^127, and the remainder d - r (or 0) < d.
    Some(match n < 0 {
        true => (
            0i128.checked_sub_unsigned(q + u128::from(r > 0))?,
            i128::try_from(if r > 0 { d - r } else { 0 }).ok()?,
        ),
        false => (i128::try_from(q).ok()?, i128::try_from(r).ok()?),
    })
}

/// A divisor that many numbers are divided by, as a triangle's doubled
/// area is by its shading (`shade`): on a 32-bit target, one below `2^64`
/// is prepared once, shifted left until its top bit is set and with the
/// reciprocal of that, and each division is then two 64 by 64-bit
/// multiplications and a few subtractions ([`divide_by_reciprocal`]),
/// where a 128-bit division by estimates ([`div_rem_u128`]) took about
/// 620 instructions on a Cortex-M4. Larger divisors, and 64-bit targets,
/// divide as [`div_rem_u128`] does.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Divisor {
    d: NonZeroU128,
    /// On 32-bit targets, for `d < 2^64`: the shift `s` that sets the top
    /// bit of `d 2^s`, that `u64`, and `min(floor(2^127 / (d 2^s)), 2^64 -
    /// 1)`.
    reciprocal: Option<(u32, u64, u64)>,
}

impl Divisor {
    /// `d`, prepared (its reciprocal found on a 32-bit target).
    pub(crate) fn new(d: NonZeroU128) -> Self {
        let reciprocal = match (cfg!(target_pointer_width = "32"), u64::try_from(d.get())) {
            (true, Ok(d)) => reciprocal_of(d),
            _ => None,
        };
        Self { d, reciprocal }
    }

    /// The divisor.
    pub(crate) fn get(&self) -> u128 {
        self.d.get()
    }

    /// `n / d` and `n % d`.
    pub(crate) fn div_rem(&self, n: u128) -> (u128, u128) {
        match self.reciprocal {
            Some((shift, normal, reciprocal)) => divide_by_reciprocal(n, shift, normal, reciprocal),
            None => div_rem_u128(n, self.d),
        }
    }

    /// `floor(n / d)` and `n - d floor(n / d)`; `None` only if `d` is
    /// above `2^127` and they do not fit.
    pub(crate) fn floor_div_rem(&self, n: i128) -> Option<(i128, i128)> {
        floor_of(n, self.get(), self.div_rem(n.unsigned_abs()))
    }
}

/// The shift, normalized divisor and reciprocal of [`Divisor`] for `d`
/// (`None` for 0).
fn reciprocal_of(d: u64) -> Option<(u32, u64, u64)> {
    let shift = d.leading_zeros();
    let normal = d.checked_shl(shift)?;
    Some((shift, normal, reciprocal_of_normal(normal)))
}

/// `floor((2^127 - 1) / d)` for `d` in `2^63..2^64`, which is
/// `min(floor(2^127 / d), 2^64 - 1)`: [`reciprocal_estimate`], then the
/// divisors it falls short by (at most 5) added one at a time. On a
/// Cortex-M4 (`.ci/itrace`) `Divisor::new` takes 156 instructions in all;
/// the 128-bit division ([`div_rem_u128`]) it replaces took 895 alone.
fn reciprocal_of_normal(d: u64) -> u64 {
    debug_assert!(d >> 63 == 1);
    let mut x = reciprocal_estimate(d);
    // x <= floor((2^127 - 1) / d), so d x <= 2^127 - 1 and the loop
    // stops at that floor, which is below 2^64.
    let mut r = (u128::MAX >> 1) - product_u64(d, x);
    while r >= u128::from(d) {
        r -= u128::from(d);
        x += 1;
    }
    x
}

/// An estimate of `f = 2^127 / d` for `d` in `2^63..2^64`, at most
/// `floor((2^127 - 1) / d)` and at most 5 below it, by Newton's iteration
/// for a reciprocal, `z' = z (2 - d z)`, which never exceeds `1 / d`
/// (`z' = (1 - (1 - d z)^2) / d`) and squares the relative error `1 - d
/// z`. Every rounding below is down, so each estimate stays at most its
/// exact value, and every subtraction is of a smaller number.
///
/// - 16 bits from the 32-bit divider: with `u = floor(d / 2^32) + 1` (so
///   `d < 2^32 u`, `u` in `2^31 + 1..=2^32`) and `a = floor(d / 2^48) +
///   1` (`u <= 2^16 a`, `a` in `2^15 + 1..=2^16`), `x0 =
///   floor((2^32 - 1) / a)` has `u x0 < 2^48`, and `e0 = 2^48 - u x0 <
///   3 2^32` (relative error below `2^-15 + 2^-16`).
/// - Two steps for `1 / u` in 64-bit words: `x1 <= 2^63 / u` falls short
///   by less than `2^32 (3 2^-16)^2 + 1 = 10`, so `e1 = 2^63 - u x1 < 10
///   u` and `e1 / 16 < 2^32`; then `x2 <= 2^95 / u < f` (since `2^32 u >
///   d`) falls short of `2^95 / u` by less than `2^64 (10 2^-31)^2 + 33`
///   (the step's error, then the 4 bits of `e1` dropped and the floor).
/// - One step for `1 / d` in 128 bits: `e2 = 2^127 - d x2` is `2^95
///   (2^32 u - d) / u + d (2^95 / u - x2) < 2^96 + 2^73`, so `e2 / 2^33 <
///   2^64`, and `x3` falls short of `f` by less than `e2^2 / (2^127 d) +
///   1`, that is below 5.001 (the Newton step's error, then the bits of
///   `e2` dropped and the floor). It is below `f` (`x2 < f` makes the
///   step's error nonzero), so at most `floor((2^127 - 1) / d)`, also for
///   `d = 2^63`.
fn reciprocal_estimate(d: u64) -> u64 {
    let u = (d >> 32) + 1;
    // Below 2^16 + 1 (`d >> 48 < 2^16`): no division by 0.
    let a = (d >> 48) as u32 + 1;
    let x0 = u64::from(u32::MAX / a);
    let e0 = (1 << 48) - u * x0;
    let x1 = (x0 << 15) + ((x0 * e0) >> 33);
    let e1 = (1 << 63) - u * x1;
    let x2 = (x1 << 32) + ((x1 * (e1 >> 4)) >> 27);
    let e2 = (1 << 127) - product_u64(d, x2);
    // Below 2^34.
    let correction = (product_u64(x2, (e2 >> 33) as u64) >> 94) as u64;
    // `x3` of the doc.
    x2 + correction
}

/// `n / d` and `n % d` for `d = normal 2^-shift`, by [`Divisor`]'s
/// reciprocal: `n 2^shift`, up to 192 bits, is divided by `normal` as
/// three 64-bit digits, one quotient digit at a time
/// ([`quotient_digit`]).
fn divide_by_reciprocal(n: u128, shift: u32, normal: u64, reciprocal: u64) -> (u128, u128) {
    let (high, low) = ((n >> 64) as u64, n as u64);
    // The bits shifted out of each digit into the one above; `>> 1 >>`
    // keeps the shift below 64 for shift = 0.
    let out = |v: u64| v >> 1 >> (63 - shift);
    let (n2, n1, n0) = (out(high), high << shift | out(low), low << shift);
    // n2 < 2^shift <= 2^63 <= normal: the first digit's condition.
    let (q1, r1) = match n2 == 0 && n1 < normal {
        true => (0, n1),
        false => quotient_digit(n2, n1, normal, reciprocal),
    };
    let (q0, r0) = quotient_digit(r1, n0, normal, reciprocal);
    (
        u128::from(q1) << 64 | u128::from(q0),
        u128::from(r0 >> shift),
    )
}

/// `floor((high 2^64 + low) / d)` and the remainder, for `high < d` and
/// `d >= 2^63`, with `reciprocal = min(floor(2^127 / d), 2^64 - 1)`.
///
/// The estimate `e = floor(high reciprocal / 2^63)` is at most `high 2^64
/// / d`, so at most the quotient `q`, and since `reciprocal > 2^127 / d -
/// 1` and `high < d < 2^64`, more than `high 2^64 / d - 3`, while `q <
/// high 2^64 / d + 2` (`low < 2^64 <= 2 d`): `q - e` is at most 4, taken
/// by subtracting `d` from the remainder while it is at least `d`. Both
/// `e` and `q` are below `2^64` (`high < d`).
#[inline(always)]
fn quotient_digit(high: u64, low: u64, d: u64, reciprocal: u64) -> (u64, u64) {
    let n = u128::from(high) << 64 | u128::from(low);
    let mut q = (product_u64(high, reciprocal) >> 63) as u64;
    let mut r = n - product_u64(q, d);
    while r >= u128::from(d) {
        r -= u128::from(d);
        q += 1;
    }
    (q, r as u64)
}

/// `a b` in full: on a 32-bit target, which multiplies `u128`s through a
/// library call, [`product_by_halves`].
#[inline(always)]
fn product_u64(a: u64, b: u64) -> u128 {
    match cfg!(target_pointer_width = "32") {
        true => product_by_halves(a, b),
        false => u128::from(a) * u128::from(b),
    }
}

/// `a b` from four 32 by 32-bit products ([`product_u32`]).
#[inline(always)]
fn product_by_halves(a: u64, b: u64) -> u128 {
    let (a1, a0) = ((a >> 32) as u32, a as u32);
    let (b1, b0) = ((b >> 32) as u32, b as u32);
    // Each product below 2^64; the middle ones' sum below 2^65, and the
    // total is a b < 2^128.
    let middle = u128::from(product_u32(a1, b0)) + u128::from(product_u32(a0, b1));
    (u128::from(product_u32(a1, b1)) << 64) + (middle << 32) + u128::from(product_u32(a0, b0))
}

/// `a b` for factors the caller shows below `2^32` (checked in debug
/// builds): where a 64-bit product is a library call
/// (`narrow_multiplier`), four 16 by 16-bit products ([`product_u32`]);
/// elsewhere the plain product.
///
/// Only there: on a Cortex-M4 (`.ci/itrace`) one `umull` in place of the
/// plain product's three multiplies saved nothing once the factors were
/// tested for size (the 3 px line 5,268 → 5,276 instructions, 64 random
/// short thick lines 183,429 → 183,941).
#[inline(always)]
pub(crate) fn short_product(a: u64, b: u64) -> u64 {
    debug_assert!(a >> 32 == 0 && b >> 32 == 0, "{a} {b}");
    match cfg!(narrow_multiplier) {
        // Within u32 (the caller's bound): the saturation never acts.
        true => product_u32(
            u32::try_from(a).unwrap_or(u32::MAX),
            u32::try_from(b).unwrap_or(u32::MAX),
        ),
        false => a * b,
    }
}

/// `a b` in full: one `umull` on a core that has it.
#[cfg(not(narrow_multiplier))]
#[inline(always)]
fn product_u32(a: u32, b: u32) -> u64 {
    u64::from(a) * u64::from(b)
}

/// `a b` in full, where a 64-bit product is a library call
/// (`narrow_multiplier`: ARMv6-M, whose `muls` keeps the low 32 bits):
/// four 16 by 16-bit products. In the ARMv6-M build (`.ci/itrace --target
/// thumbv6m-none-eabi`) 23 instructions a call, where `__aeabi_lmul`, a
/// 64 by 64-bit product, takes 37: the Gouraud window 30,555 → 29,081.
/// Inlined, 28,937, with 1,052 bytes more flash.
#[cfg(narrow_multiplier)]
#[inline(never)]
fn product_u32(a: u32, b: u32) -> u64 {
    product_by_quarters(a, b)
}

/// `a b` from four 16 by 16-bit products, each below `2^32`.
#[cfg_attr(not(narrow_multiplier), allow(dead_code))]
#[inline(always)]
fn product_by_quarters(a: u32, b: u32) -> u64 {
    let (a1, a0) = (a >> 16, a & 0xFFFF);
    let (b1, b0) = (b >> 16, b & 0xFFFF);
    // The middle ones' sum below 2^33, and the total a b < 2^64.
    let middle = u64::from(a1 * b0) + u64::from(a0 * b1);
    (u64::from(a1 * b1) << 32) + (middle << 16) + u64::from(a0 * b0)
}

impl_wide!(
    i128,
    u128,
    |a: i32, b: i32, _| Some(i128::from(a) - i128::from(b)),
    |n: i128, d: i128| floor_div_rem_i128(n, d).unwrap_or((0, 0))
);

/// A [`Wide`] with a type twice as wide, which holds the product of any
/// two of its values: `i32` (products in `i64`) and `i64` (in `i128`).
pub(crate) trait Narrow: Wide {
    /// The double width.
    type Double: Wide + From<Self>;
    /// The width of an edge setup's products ([`Edge::new`]): `i64` for
    /// both, which the edge's bounds keep them within (below `2^49` for
    /// `i32` coordinates, `2^55` for `i64` ones), so that no 128-bit
    /// product is ever taken there.
    ///
    /// [`Edge::new`]: super::edge::Edge::new
    type Product: Wide + From<Self>;

    /// `floor(n / d)` and the remainder in `0..d`, for `d > 0`: in `i32`
    /// when `n` fits (one hardware division on a 32-bit core), else in
    /// `i64`. `None` if `d <= 0` or a value does not fit.
    fn div_rem_wide(n: Self::Product, d: Self) -> Option<(Self, Self)>;
}

impl Narrow for i32 {
    type Double = i64;
    type Product = i64;

    #[inline]
    fn div_rem_wide(n: i64, d: i32) -> Option<(i32, i32)> {
        match i32::try_from(n) {
            Ok(n) => n.div_rem_floor(d),
            Err(_) => {
                let (q, r) = n.div_rem_floor(d.into())?;
                Some((i32::try_from(q).ok()?, i32::try_from(r).ok()?))
            }
        }
    }
}

impl Narrow for i64 {
    type Double = i128;
    type Product = i64;

    #[inline]
    fn div_rem_wide(n: i64, d: i64) -> Option<(i64, i64)> {
        n.div_rem_floor(d)
    }
}

/// The doubled signed area of `a, b, c` (raw 20.12 units): positive when
/// `a -> b -> c` turns clockwise on screen (y down). Exact in the double
/// width when every coordinate is below `2^(k-2)` in magnitude for `k`-bit
/// `T`: the differences then fit `T`, each product has at most `2k - 2`
/// bits and their difference `2k - 1`.
#[inline]
pub(crate) fn orientation<T: Narrow>(a: (T, T), b: (T, T), c: (T, T)) -> T::Double {
    let d = |v: T| T::Double::from(v);
    let (ux, uy) = (d(b.0 - a.0), d(b.1 - a.1));
    let (vx, vy) = (d(c.0 - a.0), d(c.1 - a.1));
    ux * vy - uy * vx
}

/// Rounds `n / d` to the nearest integer, halves up; `d != 0`. The
/// callers keep `2 |n| + |d|` within `i128`.
pub(crate) fn round_div(n: i128, d: i128) -> i128 {
    let (n, d) = if d < 0 { (-n, -d) } else { (n, d) };
    // Unreachable with d = 0 (the callers' bound); no pixel depends on it.
    floor_div_rem_i128(2 * n + d, 2 * d).map_or(0, |(q, _)| q)
}

/// `floor(sqrt(n))`: the library's on 64-bit targets; on 32-bit ones
/// digit by digit (two bits of `n` a step), whose loop is a few dozen
/// instructions where the library's, inlined with the 64-bit one it
/// calls, took about 1 KB of flash on a Cortex-M4 (the whole firmware
/// 77,088 → 76,036 bytes at opt-level "s").
fn isqrt_u128(n: u128) -> u128 {
    match cfg!(target_pointer_width = "32") {
        true => isqrt_by_digits(n),
        false => n.isqrt(),
    }
}

/// `floor(sqrt(n))` digit by digit, for 32-bit targets ([`isqrt_u128`]).
fn isqrt_by_digits(n: u128) -> u128 {
    // The highest power of 4 at or below n (none for n = 0).
    let mut bit = match n.checked_ilog2() {
        Some(log) => 1u128 << (log & !1),
        None => 0,
    };
    let (mut rem, mut root) = (n, 0u128);
    while bit != 0 {
        // root holds the digits so far, shifted up by the bits to come.
        if rem >= root + bit {
            rem -= root + bit;
            root = (root >> 1) + bit;
        } else {
            root >>= 1;
        }
        bit >>= 2;
    }
    root
}

/// `round(a / sqrt(len2))` (`len2 > 0`, halves up), exactly: with `t =
/// floor(2 a / sqrt(len2)) = isqrt(floor(4 a^2 / len2))`, the nearest
/// integer is `ceil(t / 2)`. The callers keep `a < 2^59`, so `4 a^2 <
/// 2^120`. In 128 bits: the segments on and near a screen take
/// [`OverLength`], and only the rest (a length of `2^31` or more, a
/// quotient over about `2^26`) comes here.
pub(crate) fn div_sqrt(a: u128, len2: u128) -> i128 {
    let t = match NonZeroU128::new(len2) {
        Some(len2) => isqrt_u128(div_rem_u128(4 * a * a, len2).0),
        // Unreachable (`len2 > 0`).
        None => 0,
    };
    i128::try_from(t.div_ceil(2)).unwrap_or_default()
}

/// `floor(sqrt(n))`, every 64-bit square root of the crate (128-bit ones
/// go through [`isqrt_u128`]): the library's on 64-bit targets, which
/// divide 64 bits in one instruction; on 32-bit ones [`isqrt_by_steps`],
/// where the library's `u64::isqrt` divides 64 bits in software (and was
/// inlined into each of its callers once it had few). On x86-64,
/// `isqrt_by_steps` in its place took 39 instructions more a thick line
/// (callgrind).
#[inline]
pub(crate) fn isqrt_u64(n: u64) -> u64 {
    match cfg!(target_pointer_width = "32") {
        true => isqrt_by_steps(n),
        false => n.isqrt(),
    }
}

/// `floor(sqrt(n))` for any `n`: below `2^32` the library's `u32::isqrt`
/// (a round join's rows, whose square roots are of a few pixels squared:
/// taking them through [`isqrt_62_by_step`] as well cost 2 % more on
/// `.ci/itrace`'s round-joined zigzag); above, through
/// [`isqrt_62_by_step`]: `n` times the power of 4 that brings it into
/// `[2^60, 2^62)`, the root then divided by its square root
/// (`floor(floor(2^k x) / 2^k) = floor(x)`); over `2^62`, `2
/// isqrt(floor(n / 4))` or one more, one exact test deciding
/// (`floor(sqrt(floor(n / 4))) = floor(sqrt(n) / 2)`).
#[inline(never)]
fn isqrt_by_steps(n: u64) -> u64 {
    if let Ok(n) = u32::try_from(n) {
        return u64::from(n.isqrt());
    }
    match n.leading_zeros() {
        0 | 1 => {
            let s = 2 * isqrt_62_by_step(n >> 2);
            // s + 1 < 2^32: its square fits.
            match (s + 1) * (s + 1) <= n {
                true => s + 1,
                false => s,
            }
        }
        zeros => {
            let k = (zeros - 2) / 2;
            isqrt_62_by_step(n << (2 * k)) >> k
        }
    }
}

/// `floor(sqrt(n))` for `n` in `[2^60, 2^62)`: [`isqrt_62_by_step`] on
/// 32-bit targets, the library's on 64-bit ones ([`isqrt_u64`]). For
/// [`OverLength`], whose `n` is already in that range: no scaling.
#[inline(always)]
fn isqrt_62(n: u64) -> u64 {
    match cfg!(target_pointer_width = "32") {
        true => isqrt_62_by_step(n),
        false => n.isqrt(),
    }
}

/// `floor(sqrt(n))` for `n` in `[2^60, 2^62)` (so in `[2^30, 2^31)`), by
/// one step of the digit-pair square root over `u32::isqrt`, with one
/// 32-bit division where `u64::isqrt` divides 64 bits (in software on a
/// 32-bit core: on a Cortex-M4, `.ci/itrace`'s thick lines, about 160
/// instructions a square root, 52 of them the library's division; 90
/// this way).
///
/// With `a = isqrt(floor(n / 2^30))` in `[2^15, 2^16)`, `A = 2^15 a` and
/// `r = n - A^2`, in `[0, (2 a + 1) 2^30)` (below `2^47`): `sqrt(n) - A =
/// r / (sqrt(n) + A)`, which `r / 2A` exceeds by at most `r^2 / 8 A^3 <
/// (2 a + 1)^2 2^15 / 8 a^3 < 0.51` (with `a >= 2^15`). So `A + floor(r /
/// 2A)` is the root or one more, and one exact test decides. `floor(r /
/// 2A) = floor(floor(r / 2^16) / a)`, a 32-bit division (`r / 2^16 <
/// 2^31`); every square is below `2^62 + 2^32`.
fn isqrt_62_by_step(n: u64) -> u64 {
    let top = u32::try_from(n >> 30).unwrap_or(u32::MAX);
    let a = top.isqrt();
    let r = n - (u64::from(a * a) << 30);
    let q = u32::try_from(r >> 16).unwrap_or(u32::MAX) / a.max(1);
    let s = (u64::from(a) << 15) + u64::from(q);
    // s below 2^32: 2^15 a below 2^31, q at most 2^16 (r below (2 a + 1)
    // 2^30).
    match short_product(s, s) > n {
        true => s - 1,
        false => s,
    }
}

/// `floor((2^62 - 1) / s)` for `s` in `[2^30, 2^31)` (below `2^32`),
/// without a 64-bit division, which a 32-bit core makes in software (a
/// library call of about 330 instructions for this quotient on a
/// Cortex-M4): a 15-bit estimate from one 32-bit division, two Newton
/// steps, then the last units by the remainder.
///
/// The estimate `y0 = floor((2^32 - 1) / (floor(s / 2^15) + 1)) 2^15` is
/// below `2^62 / s` by less than `2^-14` of it. A step `y + floor(y
/// floor(e / 2^18) / 2^44)`, with `e = 2^62 - s y`, stays below `2^62 /
/// s` (as `y (2 - s y / 2^62)` does) and squares the relative error,
/// then loses at most 2 to the floors: after two, `y` is within 3 of
/// `2^62 / s`, and at most three increments remain (over every `s` of
/// the range, checked one by one: at most one). Every product is below
/// `2^63`.
fn reciprocal_62(s: u64) -> u64 {
    let top = u32::try_from(s >> 15).unwrap_or(u32::MAX - 1) + 1;
    // Every factor below 2^32: s below 2^31, y at most 2^62 / s < 2^32,
    // e below 2^48 (y within 2^-14 of 2^62 / s, so e < 2^62 2^-14), so e
    // / 2^18 below 2^30.
    let mut y = u64::from(u32::MAX / top) << 15;
    for _ in 0..2 {
        let e = (1 << 62) - short_product(s, y);
        y += short_product(y, e >> 18) >> 44;
    }
    let mut rem = ((1 << 62) - 1) - short_product(s, y);
    while rem >= s {
        y += 1;
        rem -= s;
    }
    y
}

/// `round(a / sqrt(len2))` (halves up, exactly: [`div_sqrt`]'s values)
/// for many `a` and one `len2 > 0`, the components of a segment's offsets:
/// where `len2 < 2^62`, with one square root and one division set up
/// once, then a few multiplications for each `a`, in `u64`.
///
/// Set up: `s = floor(sqrt(len2) 2^k) = isqrt(len2 4^k)`, with `k` such
/// that `s` lies in `[2^30, 2^31)`, and `inv = floor((2^62 - 1) / s)`,
/// below `2^32`. For `a < 2^(57 - k)` (so `x = 2^k a < 2^57` and `a /
/// sqrt(len2) < 2^27`), `x inv / 2^62` lies within `(-1/32, 1/8)` of `a /
/// sqrt(len2)`: `inv` is short of `2^62 / s` by less than 1 (at most
/// `2^57 / 2^62` on the quotient), and `s` of `sqrt(len2) 2^k` by less
/// than 1 (at most `2^27 / 2^30` more). Taken to 6 fractional bits, less
/// `1/8`, plus `1/2`, its floor `r0` is the rounded quotient `r` or `r -
/// 1`, and one exact test decides: `r = r0 + 1` iff `(2 r0 + 1)^2 len2 <=
/// 4 a^2`. That test is in `u64` when `a < 2^30` and `len2 < 2^60` (both
/// sides are below `(2 a + 2 sqrt(len2))^2 < 2^64`), else in `u128`.
/// Other `a` and `len2` go through [`div_sqrt`].
///
/// Each [`div_sqrt`] divides and takes a square root in 64 bits at least:
/// a thick line's four components took about 840 instructions on a
/// Cortex-M4 that way (`.ci/itrace`).
#[derive(Debug, Clone, Copy)]
pub(crate) struct OverLength {
    len2: u128,
    /// `(len2, k, inv)` where `len2 < 2^62`.
    prepared: Option<(u64, u32, u64)>,
}

impl OverLength {
    /// Prepares the divisions by `sqrt(len2)`, `len2 > 0`.
    #[inline]
    pub(crate) fn new(len2: u128) -> Self {
        let prepared = u64::try_from(len2)
            .ok()
            .filter(|&l| l > 0 && l < 1 << 62)
            .map(|l| {
                // `l` has `64 - lz` bits; `l 4^k` then has 61 or 62, so
                // that `s` is in [2^30, 2^31).
                let k = (l.leading_zeros() - 2) / 2;
                let s = isqrt_62(l << (2 * k));
                (l, k, reciprocal_62(s))
            });
        Self { len2, prepared }
    }

    /// `round(a / sqrt(len2))`, halves up. Out of line: one copy for
    /// every offset.
    #[inline(never)]
    pub(crate) fn rounded(&self, a: u64) -> u64 {
        if let Some((len2, k, inv)) = self.prepared {
            if a < 1 << (57 - k) {
                let x = a << k;
                // x inv / 2^56, floored, from two 32 by 32-bit products
                // (inv below 2^32): below 2^57 and 2^64.
                let hi = short_product(x >> 32, inv);
                let lo = short_product(x & 0xFFFF_FFFF, inv);
                let sixty_fourths = (hi + (lo >> 32)) >> 24;
                let r0 = (sixty_fourths + 24) >> 6;
                let t = 2 * r0 + 1;
                let up = match a < 1 << 30 && len2 < 1 << 60 {
                    // t below 2^29 (r0 at most a / sqrt(len2) < 2^27).
                    true => short_product(t, t) * len2 <= short_product(a, a) << 2,
                    false => {
                        let t = u128::from(t);
                        t * t * u128::from(len2) <= 4 * u128::from(a) * u128::from(a)
                    }
                };
                return r0 + u64::from(up);
            }
        }
        // At most a: it fits.
        u64::try_from(div_sqrt(a.into(), self.len2)).unwrap_or_default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::raster::xorshift;

    #[test]
    fn divisions_in_the_narrowest_width() {
        assert_eq!(i32::div_rem_wide(-7, 2), Some((-4, 1)));
        assert_eq!(i32::div_rem_wide(-(1i64 << 40), 3), None);
        assert_eq!(i32::div_rem_wide(1i64 << 40, 1 << 20), Some((1 << 20, 0)));
        assert_eq!(
            i32::div_rem_wide(-(1i64 << 40) - 1, 1 << 20),
            Some((-(1 << 20) - 1, (1 << 20) - 1))
        );
        assert_eq!(i64::div_rem_wide(5, 0), None);
        assert_eq!(
            i64::div_rem_wide(-(1i64 << 62), 3),
            Some((-(1i64 << 62) / 3 - 1, 2))
        );
    }

    /// The shift-and-subtract division against the native one, at the
    /// ends of the range and on a spread of magnitudes.
    #[test]
    fn shift_division_matches_native() {
        let check = |n: i64, d: i64| {
            assert_eq!(
                floor_div_rem_by_shifts(n, d),
                (n.div_euclid(d), n.rem_euclid(d)),
                "{n} / {d}"
            );
        };
        let edges = [
            i64::MIN,
            i64::MIN + 1,
            -(1 << 32),
            -1,
            0,
            1,
            1 << 32,
            i64::MAX,
        ];
        for &n in &edges {
            for d in [1, 2, 3, (1 << 32) - 1, 1 << 32, (1 << 32) + 1, i64::MAX] {
                check(n, d);
            }
        }
        // A deterministic spread: every magnitude of n and d, both signs.
        for x in xorshift(0x9E37_79B9_7F4A_7C15).take(20_000) {
            let n = (x as i64) >> (x % 64);
            let d = (((x >> 8) | 1) >> ((x >> 20) % 63)).max(1) as i64;
            check(n, d);
        }
    }

    /// The unsigned divisions of 32-bit targets against the native ones:
    /// at the ends of each type, across the 32- and 64-bit boundaries
    /// where they change method, and on a spread of magnitudes.
    #[test]
    fn unsigned_divisions_match_native() {
        let check = |n: u128, d: u128| {
            if d == 0 {
                return;
            }
            assert_eq!(divide_u128(n, d), (n / d, n % d), "{n} / {d}");
            if let (Ok(n), Ok(d)) = (u64::try_from(n), u64::try_from(d)) {
                assert_eq!(divide_u64(n, d), (n / d, n % d), "{n} / {d}");
            }
        };
        let small = [0, 1, 2, 3, (1u128 << 32) - 1, 1 << 32, (1 << 32) + 1];
        let edges = || {
            small
                .into_iter()
                .flat_map(|v| [v, (1 << 64) - 1 - v, (1 << 64) + v, u128::MAX - v])
        };
        for n in edges() {
            for d in edges() {
                check(n, d);
            }
        }
        let mut random = xorshift(0x9E37_79B9_7F4A_7C15);
        for _ in 0..20_000 {
            let (a, b) = (random.next().unwrap_or(1), random.next().unwrap_or(1));
            let wide = (u128::from(a) << 64 | u128::from(b)) >> (b % 128);
            let narrow = u128::from(a >> (b % 64));
            for (n, d) in [
                (wide, narrow),
                (narrow, wide),
                (wide, wide >> (a % 128)),
                (narrow, narrow >> 9),
            ] {
                check(n, d);
            }
        }
        // Divisors of every length, above all around the 16 bits whose
        // rounding the estimates use: quotients of every length, with the
        // remainder at 0, at d - 1 and anywhere between.
        for _ in 0..20_000 {
            let mut next = || random.next().unwrap_or(1);
            let (bits, q_bits) = (next() % 128 + 1, next() % 128);
            let d =
                (u128::from(next()) << 64 | u128::from(next())) >> (128 - bits) | 1 << (bits - 1);
            let q = (u128::from(next()) << 64 | u128::from(next())) >> (127 - q_bits.min(127));
            let Some(base) = d.checked_mul(q) else {
                continue;
            };
            for r in [0, d - 1, u128::from(next()) % d] {
                if let Some(n) = base.checked_add(r) {
                    check(n, d);
                }
            }
        }
    }

    /// Division by a prepared divisor's reciprocal (the 32-bit targets'
    /// path, called directly) against the native one: divisors of every
    /// length up to 64 bits, the powers of two and the ends among them,
    /// and numbers of every length up to `u128::MAX`; and the signed
    /// floor division through [`Divisor`] on this target.
    #[test]
    fn divisions_by_reciprocal_match_native() {
        let check = |n: u128, d: u64| {
            let Some((shift, normal, reciprocal)) = reciprocal_of(d) else {
                return assert_eq!(d, 0);
            };
            let d_wide = u128::from(d);
            assert_eq!(
                divide_by_reciprocal(n, shift, normal, reciprocal),
                (n / d_wide, n % d_wide),
                "{n} / {d}"
            );
            let divisor = Divisor::new(NonZeroU128::new(d_wide).unwrap());
            // Below 2^127, either sign.
            let half = (n >> 1) as i128;
            for n in [half, -half, -half - 1] {
                let native = (n.div_euclid(d_wide as i128), n.rem_euclid(d_wide as i128));
                assert_eq!(divisor.floor_div_rem(n), Some(native), "{n} / {d}");
            }
        };
        let mut random = xorshift(0x5DEE_CE66_D1CE_2026);
        let mut next = move || random.next().unwrap_or(1);
        let divisors = [
            1,
            2,
            3,
            1 << 31,
            (1 << 32) + 1,
            1 << 63,
            (1 << 63) + 1,
            u64::MAX,
        ];
        let numbers = [
            0,
            1,
            u128::from(u64::MAX),
            1 << 64,
            u128::MAX,
            u128::MAX - 1,
            1 << 127,
        ];
        for &d in &divisors {
            for &n in &numbers {
                check(n, d);
                check(n.saturating_sub(u128::from(d)), d);
            }
        }
        for _ in 0..50_000 {
            let d = (next() >> (next() % 64)).max(1);
            let n = (u128::from(next()) << 64 | u128::from(next())) >> (next() % 128);
            check(n, d);
            // A multiple of d and its neighbours: remainders 0 and d - 1.
            let m = (u128::from(d) * u128::from(next() >> (next() % 64))).max(1);
            for n in [m - 1, m, m + 1] {
                check(n, d);
            }
        }
    }

    /// The reciprocal's estimate against the native division: never above
    /// `floor((2^127 - 1) / d)`, at most 5 below it, and corrected to it
    /// exactly. Every value of the 16 top bits that the first estimate
    /// divides by, each with the lowest and highest rest, the same for the
    /// 32 top bits of random divisors, and random divisors.
    #[test]
    fn reciprocal_estimates_fall_short_by_at_most_5() {
        let mut worst = 0;
        let mut check = |d: u64| {
            let exact = u64::try_from((u128::MAX >> 1) / u128::from(d)).unwrap();
            let estimate = reciprocal_estimate(d);
            assert!(estimate <= exact, "{d}: {estimate} over {exact}");
            worst = worst.max(exact - estimate);
            assert!(exact - estimate <= 5, "{d}: {estimate} for {exact}");
            assert_eq!(reciprocal_of_normal(d), exact, "{d}");
        };
        let mut random = xorshift(0x2026_1207_8E3C_1B0F);
        let mut next = move || random.next().unwrap_or(1);
        for top in 1u64 << 15..1 << 16 {
            for rest in [0, 1, (1 << 48) - 1, next() >> 16] {
                check(top << 48 | rest);
            }
        }
        for _ in 0..100_000 {
            let top = next() | 1 << 63;
            check(top);
            check(top >> 32 << 32);
            check(top | 0xFFFF_FFFF);
        }
        // The bound is what occurs: these divisors reach it.
        assert_eq!(worst, 5);
    }

    /// The 32-bit targets' product against the native one.
    #[test]
    fn products_by_halves_match_native() {
        let mut random = xorshift(0x2026_1206_0000_0001);
        let mut next = move || random.next().unwrap_or(1);
        for (a, b) in [
            (u64::MAX, u64::MAX),
            (0, u64::MAX),
            (1 << 32, (1 << 32) - 1),
        ] {
            assert_eq!(product_by_halves(a, b), u128::from(a) * u128::from(b));
        }
        for _ in 0..20_000 {
            let (a, b) = (next() >> (next() % 64), next() >> (next() % 64));
            assert_eq!(
                product_by_halves(a, b),
                u128::from(a) * u128::from(b),
                "{a} {b}"
            );
        }
    }

    /// ARMv6-M's 32 by 32-bit products from 16-bit quarters against the
    /// native ones: the ends, and random factors of every length.
    #[test]
    fn products_by_quarters_match_native() {
        let ends = [0, 1, 0xFFFF, 0x1_0000, 0x7FFF_FFFF, 0x8000_0000, u32::MAX];
        for a in ends {
            for b in ends {
                assert_eq!(product_by_quarters(a, b), u64::from(a) * u64::from(b));
            }
        }
        let mut random = xorshift(0x2026_1206_0000_0016);
        let mut next = move || random.next().unwrap_or(1);
        for _ in 0..50_000 {
            let (a, b) = (
                (next() >> (32 + next() % 32)) as u32,
                (next() >> (32 + next() % 32)) as u32,
            );
            assert_eq!(
                product_by_quarters(a, b),
                u64::from(a) * u64::from(b),
                "{a} {b}"
            );
        }
    }

    /// The digit-by-digit square root against the library's: squares and
    /// their neighbours up to the top of `u128`, and a spread.
    #[test]
    fn square_roots_by_digits_match_native() {
        let check = |n: u128| assert_eq!(isqrt_by_digits(n), n.isqrt(), "sqrt {n}");
        for n in [0, 1, 2, 3, u128::MAX, u128::MAX - 1] {
            check(n);
        }
        let roots = [1u128, 2, 3, 1 << 31, (1 << 32) - 1, 1 << 32, (1 << 63) + 5];
        for k in roots.into_iter().chain([u128::from(u64::MAX)]) {
            for n in [k * k - 1, k * k, k * k + 1] {
                check(n);
            }
        }
        let mut random = xorshift(0x2545_F491_4F6C_DD1D);
        for _ in 0..20_000 {
            let (a, b) = (random.next().unwrap_or(1), random.next().unwrap_or(1));
            check((u128::from(a) << 64 | u128::from(b)) >> (b % 128));
        }
    }

    /// `round_div` against `round(n / d)` taken by the native floor
    /// division, both signs, at the callers' bound and on a spread.
    #[test]
    fn rounded_division_matches_native() {
        let check = |n: i128, d: i128| {
            let (m, e) = if d < 0 { (-n, -d) } else { (n, d) };
            assert_eq!(round_div(n, d), (2 * m + e).div_euclid(2 * e), "{n} / {d}");
        };
        for x in xorshift(0x1234_5678_9ABC_DEF1).take(20_000) {
            let n = i128::from(x as i64) << (x % 60);
            let d =
                i128::from(((x >> 7) as i64) >> (x % 50)).max(1) * if x & 1 == 0 { 1 } else { -1 };
            check(n, d);
            check(-n, d);
        }
        for (n, d) in [
            (0, 1),
            (1, 2),
            (-1, 2),
            (3, 2),
            (-3, 2),
            (1i128 << 122, 3),
            (-(1i128 << 122), -7),
        ] {
            check(n, d);
        }
    }

    #[test]
    fn orientation_at_the_extremes() {
        let (lo, hi) = (-(1i64 << 33), 1i64 << 33);
        // Counter-clockwise on screen: negative; the magnitude needs 69 bits.
        let area = orientation::<i64>((lo, lo), (lo, hi), (hi, lo));
        assert_eq!(area, -(1i128 << 68));
        let (lo, hi) = (-(1i32 << 29) + 1, (1i32 << 29) - 1);
        let area = orientation::<i32>((lo, lo), (lo, hi), (hi, lo));
        assert_eq!(area, -(i64::from(hi - lo) * i64::from(hi - lo)));
        assert_eq!(orientation::<i32>((0, 0), (4, 0), (0, 4)), 16);
        assert_eq!(orientation::<i32>((0, 0), (1, 1), (2, 2)), 0);
    }

    /// `div_sqrt` against the defining inequalities
    /// of `r = round(a / sqrt(len2))`, halves up: `(2 r - 1)^2 len2 <= 4
    /// a^2 < (2 r + 1)^2 len2` (for `r = 0`, only the right one), checked
    /// in `u128` with no square root, from small values up to the
    /// callers' `a < 2^59`.
    #[test]
    fn rounded_quotients_of_square_roots() {
        let check = |a: u64, len2: u64| {
            let r = div_sqrt(a.into(), len2.into());
            let (a, len2) = (u128::from(a), u128::from(len2));
            let r = u128::try_from(r).expect("not negative");
            let four = 4 * a * a;
            assert!(
                four < (2 * r + 1).pow(2) * len2,
                "{a} {len2}: {r} too small"
            );
            if r > 0 {
                assert!(
                    (2 * r - 1).pow(2) * len2 <= four,
                    "{a} {len2}: {r} too large"
                );
            }
        };
        for (a, len2) in [
            (0, 1),
            (1, 4),
            (1, 5),
            (3, 4),
            (2048, 1),
            (2048, 2),
            ((1 << 31) - 1, 3),
            (1 << 31, 3),
            ((1 << 59) - 1, 1),
            ((1 << 59) - 1, (1 << 63) + 12345),
        ] {
            check(a, len2);
        }
        for x in xorshift(0x2545_F491_4F6C_DD1D).take(20_000) {
            let a = x >> (5 + x % 40);
            let len2 = ((x >> 3) >> (x % 61)).max(1);
            check(a, len2);
        }
    }

    /// [`reciprocal_62`] against the division, at both ends of its range
    /// and at random.
    #[test]
    fn reciprocals_are_exact() {
        let check = |s: u64| assert_eq!(reciprocal_62(s), ((1 << 62) - 1) / s, "1 / {s}");
        for s in (1 << 30)..(1 << 30) + 5000 {
            check(s);
        }
        for s in (1 << 31) - 5000..1 << 31 {
            check(s);
        }
        for x in xorshift(0xA076_1D64_78BD_642F).take(1_000_000) {
            check((1 << 30) | (x & ((1 << 30) - 1)));
        }
    }

    /// The 62-bit square root against `u64::isqrt`: both ends of the
    /// range, both sides of every square of the first digit pair (where
    /// the remainder `r` is least and greatest), squares of the result and
    /// their neighbours, and random values.
    #[test]
    fn square_roots_of_62_bits_are_exact() {
        let check = |n: u64| assert_eq!(isqrt_62_by_step(n), n.isqrt(), "sqrt {n}");
        for n in [1 << 60, (1 << 60) + 1, (1 << 62) - 2, (1 << 62) - 1] {
            check(n);
        }
        for a in 1u64 << 15..1 << 16 {
            let low = (a * a) << 30;
            for n in [low, low + 1, (((a + 1) * (a + 1)) << 30) - 1] {
                if (1 << 60..1 << 62).contains(&n) {
                    check(n);
                }
            }
        }
        let mut random = xorshift(0x2545_F491_4F6C_DD1D);
        for _ in 0..200_000 {
            let s = (1 << 30) | (random.next().unwrap_or(0) & ((1 << 31) - 1));
            for n in [s * s - 1, s * s, s * s + 1, s * s + 2 * s] {
                if (1 << 60..1 << 62).contains(&n) {
                    check(n);
                }
            }
            check((1 << 60) + random.next().unwrap_or(0) % (3 << 60));
        }
    }

    /// Every square root against `u64::isqrt`: all `n` below `2^17`, both
    /// sides of every power of two and of squares at every magnitude (the
    /// scalings by powers of 4 and the test over `2^62`), the largest
    /// values and random ones of every length.
    #[test]
    fn square_roots_are_exact() {
        let check = |n: u64| assert_eq!(isqrt_by_steps(n), n.isqrt(), "sqrt {n}");
        for n in 0..1 << 17 {
            check(n);
        }
        for bit in 0..64 {
            let p = 1u64 << bit;
            for n in [p - 1, p, p + 1] {
                check(n);
            }
        }
        for n in [u64::MAX, u64::MAX - 1, u64::MAX - (1 << 32)] {
            check(n);
        }
        let mut random = xorshift(0x94D0_49BB_1331_11EB);
        for _ in 0..200_000 {
            let x = random.next().unwrap_or(0);
            let s = x >> (x % 32 + 32);
            let square = s * s;
            for n in [square.saturating_sub(1), square, square + 1, square + 2 * s] {
                check(n);
            }
            check(x >> (x % 64));
        }
    }

    /// [`OverLength`] against [`div_sqrt`] (itself checked against the
    /// defining inequalities above): every `a` below 600 for every `len2`
    /// up to 300; ties (`2 a = (2 r - 1) m` for `len2 = m^2`); both sides
    /// of its bounds (`a` at `2^30` and `2^(57 - k)`, `len2` at `2^60` and
    /// `2^62`); random `a` and `len2` at every magnitude, up to a stroke's
    /// `a < 2^59` and `len2 < 2^65`.
    #[test]
    fn prepared_quotients_match_div_sqrt() {
        let check = |a: u64, len2: u128| {
            let want = u64::try_from(div_sqrt(a.into(), len2)).expect("fits");
            assert_eq!(OverLength::new(len2).rounded(a), want, "{a} / sqrt({len2})");
        };
        for len2 in 1..=300 {
            for a in 0..600 {
                check(a, len2);
            }
        }
        for m in 1u64..2000 {
            for r in 1..40 {
                let twice = (2 * r - 1) * m;
                if twice % 2 == 0 {
                    for a in [twice / 2 - 1, twice / 2, twice / 2 + 1] {
                        check(a, u128::from(m * m));
                    }
                }
            }
        }
        let near = |v: u64| [v.saturating_sub(1), v, v + 1];
        for len2 in [1u128, 2, 3, 5, (1 << 60) - 1, 1 << 60, (1 << 60) + 1]
            .into_iter()
            .chain([(1 << 62) - 1, 1 << 62, (1 << 62) + 1, (1 << 64) + 3])
        {
            let l = u64::try_from(len2).unwrap_or(u64::MAX);
            let k = (l.leading_zeros().max(2) - 2) / 2;
            for edge in [1 << 30, 1u64 << (57 - k), 2048 * 65535, 1 << 31] {
                for a in near(edge) {
                    check(a, len2);
                }
            }
        }
        for x in xorshift(0x9E37_79B9_7F4A_7C15).take(200_000) {
            let y = x.rotate_left(29) ^ 0xD1B5_4A32_D192_ED03;
            let a = (x >> (5 + x % 59)).min((1 << 59) - 1);
            let len2 = (u128::from(y) << (y % 2)) >> (y % 64);
            check(a, len2.max(1));
        }
        // Segments on a screen: directions below 2^12 a component, the
        // components of `e` and `n` for widths up to 65535.
        for x in xorshift(0x94D0_49BB_1331_11EB).take(200_000) {
            let (dx, dy) = (x & 0xFFF, (x >> 12) & 0xFFF);
            let len2 = u128::from(dx * dx + dy * dy).max(1);
            let w = 1 + (x >> 24) % if x % 4 == 0 { 65535 } else { 16 };
            for c in [dx, dy] {
                check(c * 2048, len2);
                check(c * 2048 * w, len2);
            }
        }
    }
}
