//! A line in canonical form, and exact clipping of it before stepping.
//!
//! # Canonical form
//!
//! A line from pixel `P` to pixel `Q` is *x-major* when `|dx| >= |dy|`
//! (45-degree lines included) and *y-major* otherwise. Its end points are
//! ordered so that the major coordinate grows by one per step from
//! `major0`, over `dmajor + 1` pixels, while the minor coordinate moves by
//! `dminor <= dmajor` in total, in direction `minor_step` (+1 or -1).
//! Both directions of a line have the same canonical form, so they light
//! the same pixels by construction.
//!
//! # The pixel at each step
//!
//! At step `k` (`0..=dmajor`) the ideal minor offset is `dminor k / dmajor`
//! and the lit pixel is `minor0 + minor_step * m(k)` with
//!
//! ```text
//! m(k) = floor((2 dminor k + dmajor - b) / (2 dmajor))
//! ```
//!
//! the offset rounded to nearest. At a tie (the offset is an integer plus
//! one half) `b` decides: `b = 1` rounds the offset down, `b = 0` rounds it
//! up. The tie rule is "the smaller coordinate", so `b = 1` when the minor
//! coordinate grows along the canonical direction and `b = 0` when it
//! shrinks.
//!
//! The remainder `r(k) = 2 dminor k + dmajor - b - 2 dmajor m(k)` lies in
//! `[0, 2 dmajor)`, and the next offset is `m(k) + 1` iff
//! `D(k) = r(k) + 2 dminor - 2 dmajor >= 0`: the Bresenham decision
//! variable, updated by `+ 2 dminor` per step and `- 2 dmajor` per minor
//! step. Its values stay in `[-2 dmajor, 2 dmajor]`.
//!
//! # Clipping
//!
//! `m` is non-decreasing in `k`, so the steps whose pixel lies inside the
//! clip rectangle form one interval, found without stepping: the steps
//! whose major coordinate is inside, intersected with the steps whose
//! offset lies in the clip's minor range `[m_lo, m_hi]`,
//!
//! ```text
//! m(k) >= M  <=>  k >= ceil((2 dmajor M - dmajor + b) / (2 dminor))
//! ```
//!
//! (for `dminor > 0`). Then `m` and `D` at the first visible step are
//! computed exactly in `u64` (coordinates are any `i32`, so `dmajor <
//! 2^32`; with the clip's offsets first limited to `0..=dminor` and each
//! quotient split into a whole part and a remainder, no product reaches
//! `2^64`: see `Canonical::entry`).
//! A line whose ends lie inside the clip rectangle takes the textbook
//! start, `D = 2 dminor - dmajor - b`, without any division or clip
//! arithmetic, after a 32-bit test of its ends against the clip.

use core::num::NonZeroU64;

use crate::raster::wide::div_rem_u64;

use embedded_graphics_core::{geometry::Point, primitives::Rectangle};

use crate::clip::Bounds;

/// A line in the canonical form of the module docs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Canonical {
    /// Whether x is the major axis.
    pub x_major: bool,
    /// Major and minor coordinate of the first pixel.
    pub major0: i64,
    pub minor0: i64,
    /// Number of steps along the major axis (`>= 0`).
    pub dmajor: i64,
    /// Total minor movement, `0..=dmajor`.
    pub dminor: i64,
    /// +1 or -1: the direction of the minor coordinate.
    pub minor_step: i64,
    /// Whether the original line starts at the canonical end, i.e. was
    /// reversed to make the major coordinate grow.
    pub reversed: bool,
}

impl Canonical {
    pub fn new(start: Point, end: Point) -> Self {
        let (dx, dy) = (
            i64::from(end.x) - i64::from(start.x),
            i64::from(end.y) - i64::from(start.y),
        );
        let x_major = dx.abs() >= dy.abs();
        let (dmaj, dmin) = if x_major { (dx, dy) } else { (dy, dx) };
        let reversed = dmaj < 0;
        let (first, dmin) = if reversed {
            (end, -dmin)
        } else {
            (start, dmin)
        };
        let (major0, minor0) = if x_major {
            (first.x, first.y)
        } else {
            (first.y, first.x)
        };
        Self {
            x_major,
            major0: i64::from(major0),
            minor0: i64::from(minor0),
            dmajor: dmaj.abs(),
            dminor: dmin.abs(),
            minor_step: if dmin < 0 { -1 } else { 1 },
            reversed,
        }
    }

    /// The major range `[lo, hi]` and minor range of `clip`, inclusive.
    pub fn clip_ranges(&self, clip: &Rectangle) -> ((i64, i64), (i64, i64)) {
        let b = Bounds::of(clip);
        let (x, y) = ((b.x0, b.x1 - 1), (b.y0, b.y1 - 1));
        if self.x_major {
            (x, y)
        } else {
            (y, x)
        }
    }

    /// Steps `k` whose major coordinate lies inside `clip`, within
    /// `0..=dmajor` and without the pixel at the original end if
    /// `skip_end`. `None` if there are none.
    pub fn major_steps(&self, clip: &Rectangle, skip_end: bool) -> Option<(i64, i64)> {
        let ((c0, c1), _) = self.clip_ranges(clip);
        let mut lo = (c0 - self.major0).max(0);
        let mut hi = (c1 - self.major0).min(self.dmajor);
        if skip_end {
            if self.reversed {
                lo = lo.max(1);
            } else {
                hi = hi.min(self.dmajor - 1);
            }
        }
        (lo <= hi).then_some((lo, hi))
    }

    /// The clip's minor range as offsets from `minor0` along
    /// `minor_step`, inclusive.
    pub fn minor_offsets(&self, clip: &Rectangle) -> (i64, i64) {
        let (_, (c0, c1)) = self.clip_ranges(clip);
        if self.minor_step > 0 {
            (c0 - self.minor0, c1 - self.minor0)
        } else {
            (self.minor0 - c1, self.minor0 - c0)
        }
    }

    /// The canonical form of the line from `start` to `end` and all of it
    /// (without the pixel at `end` if `skip_end`), if both ends lie inside
    /// `clip`: the clip is convex and the line monotonic, so no pixel is
    /// cut. The ends are tested against the clip in 32 bits (their
    /// distances from its corner taken as `u32`), and the visible part is
    /// the textbook start `D = 2 dminor - dmajor - b`, without division or
    /// clip arithmetic, moved on by one Bresenham step when the skipped end
    /// is the first. All of it in `i32`: a clip at most `2^30` px a side
    /// keeps the ends less than `2^30` apart, so that `2 dminor`, `2
    /// dmajor` and the decision fit. `None` if an end lies outside `clip`,
    /// the clip is larger, or no pixel is left: [`visible`](Self::visible)
    /// then clips.
    #[inline]
    pub fn inside(
        start: Point,
        end: Point,
        clip: &Rectangle,
        skip_end: bool,
    ) -> Option<(Self, Visible)> {
        const LARGEST: u32 = 1 << 30;
        let corner = clip.top_left;
        let within = |p: Point| {
            p.x >= corner.x
                && p.y >= corner.y
                && p.x.abs_diff(corner.x) < clip.size.width
                && p.y.abs_diff(corner.y) < clip.size.height
        };
        if clip.size.width > LARGEST || clip.size.height > LARGEST {
            return None;
        }
        if !(within(start) && within(end)) {
            return None;
        }
        // Both ends in the clip: |dx|, |dy| < 2^30. The canonical form is
        // taken here in `i32` rather than from `new` (in `i64`): `new`
        // rewritten in `u32` by `abs_diff` and called from here cost each
        // line inside the clip 13 more instructions on a Cortex-M4
        // (`.ci/itrace`, 64 lines of 16 px: 28,896 → 29,712).
        let (dx, dy) = (end.x - start.x, end.y - start.y);
        let x_major = dx.abs() >= dy.abs();
        let (dmaj, dmin) = if x_major { (dx, dy) } else { (dy, dx) };
        // Drawn from the end with the smaller major coordinate.
        let reversed = dmaj < 0;
        let (first, far, dmin) = match reversed {
            true => (end, start, -dmin),
            false => (start, end, dmin),
        };
        let (major0, minor0, far_minor) = match x_major {
            true => (first.x, first.y, far.y),
            false => (first.y, first.x, far.x),
        };
        let (dmajor, dminor) = (dmaj.abs(), dmin.abs());
        let minor_step = if dmin < 0 { -1 } else { 1 };
        let (two_minor, two_major) = (2 * dminor, 2 * dmajor);
        // Under 2^31 - 2^30: 2 dminor - dmajor <= dminor.
        let mut d = two_minor - dmajor - i32::from(minor_step > 0);
        // The far end's major coordinate: a point of the clip.
        let last = major0 + dmajor;
        if skip_end && dmajor == 0 {
            return None;
        }
        let mut visible = Visible {
            first_major: major0,
            last_major: last,
            first_minor: minor0,
            // The far end's: no pixel passes it.
            minor_bound: far_minor,
            decision: 0,
        };
        // Pixels of the line lie in the clip: neither step leaves i32, nor
        // does the decision (a move takes 2 dmajor from a decision >= 0,
        // and 2 dminor is added to one below 2^30).
        if skip_end && reversed {
            visible.first_major += 1;
            if d >= 0 {
                visible.first_minor += minor_step;
                d -= two_major;
            }
            d += two_minor;
        } else if skip_end {
            visible.last_major -= 1;
        }
        visible.decision = d.into();
        let line = Self {
            x_major,
            major0: major0.into(),
            minor0: minor0.into(),
            dmajor: dmajor.into(),
            dminor: dminor.into(),
            minor_step: minor_step.into(),
            reversed,
        };
        Some((line, visible))
    }

    /// The exactly clipped visible part, or `None` if no pixel of the line
    /// lies inside `clip`; for any line, but lines inside the clip are
    /// found faster by [`inside`](Self::inside). Out of line: its frame
    /// is large.
    #[inline(never)]
    pub fn visible(&self, clip: &Rectangle, skip_end: bool) -> Option<Visible> {
        let (lo, hi) = self.major_steps(clip, skip_end)?;
        // The clip's minor range as offsets m, limited to the line's own
        // offsets 0..=dminor (which changes no step range: m(0) = 0 and
        // m(dmajor) = dminor), so that products stay small.
        let (m_lo, m_hi) = self.minor_offsets(clip);
        if m_lo > self.dminor || m_hi < 0 {
            return None;
        }
        let (m_lo, m_hi) = (m_lo.max(0), m_hi.min(self.dminor));
        let (lo, hi, m, d) = self.entry(lo, hi, m_lo, m_hi)?;
        self.steps(lo, hi, m, m_hi, d)
    }

    /// The visible steps `lo..=hi`, with offset `m` and decision `d` at
    /// `lo`, and no offset past `m_hi`.
    fn steps(&self, lo: i64, hi: i64, m: i64, m_hi: i64, d: i64) -> Option<Visible> {
        // Every visible pixel is a pixel of the line, and the offset
        // `m_hi` one inside the clip (within the line's own offsets): all
        // fit in i32.
        let minor = |m: i64| i32::try_from(self.minor0 + self.minor_step * m).ok();
        Some(Visible {
            first_major: i32::try_from(self.major0 + lo).ok()?,
            last_major: i32::try_from(self.major0 + hi).ok()?,
            first_minor: minor(m)?,
            minor_bound: minor(m_hi)?,
            decision: d,
        })
    }

    /// The steps `lo..=hi` (within `0..=dmajor`) narrowed to offsets
    /// `m_lo..=m_hi` (within `0..=dminor`), the offset and the decision
    /// variable at the first: `(lo, hi, m, D)`.
    ///
    /// In `u64` for every line of `i32` ends (`dmajor < 2^32`), with no
    /// product past `2^64`: the quotients of the module docs are split
    /// into whole parts and remainders first. With `dmajor = Q dminor + R`
    /// (`R < dminor`),
    ///
    /// ```text
    /// first(m) = ceil((2 dmajor m - dmajor + b) / (2 dminor))
    ///          = Q m + ceil((2 R m - dmajor + b) / (2 dminor))
    /// ```
    ///
    /// and with `R m = Q2 dminor + R2` (`R m < 2^64` for `m <= dminor`),
    /// `first(m) = Q m + Q2 - floor((Q dminor + R - 2 R2 - b) / (2
    /// dminor))`. That last quotient needs no division: with `Q = 2 H + P`
    /// (`P` in `0..=1`) it is `H + floor((P dminor + R - 2 R2 - b) / (2
    /// dminor))`, whose numerator lies strictly between `-2 dminor` and `2
    /// dminor`, so it is `H - 1` if the numerator is negative, else `H`.
    /// Likewise, with
    /// `dminor lo = Q3 dmajor + R3`, `m(lo) = Q3 + floor(U / (2 dmajor))`
    /// and its remainder `U mod 2 dmajor` for `U = 2 R3 + dmajor - b`,
    /// which lies within `0..3 dmajor`.
    fn entry(&self, lo: i64, hi: i64, m_lo: i64, m_hi: i64) -> Option<(i64, i64, i64, i64)> {
        let u = |v: i64| u64::try_from(v).ok();
        let (dmaj, dmin, b) = (
            u(self.dmajor)?,
            u(self.dminor)?,
            u64::from(self.minor_step > 0),
        );
        let (mut lo, mut hi) = (u(lo)?, u(hi)?);
        // A line the clip's minor range does not cut needs no quotient.
        let cut = m_lo > 0 || m_hi < self.dminor;
        if let Some(nonzero) = NonZeroU64::new(dmin).filter(|_| cut) {
            // Q, R below 2^32.
            let (q, r) = div_rem_u64(dmaj, nonzero);
            // The first step whose offset is at least m, for 1 <= m <=
            // dminor (offset 0 is reached at step 0).
            let first = |m: u64| {
                let (q2, r2) = div_rem_u64(r * m, nonzero);
                // Q m + Q2 - H, plus 1 if P dminor + R < 2 R2 + b (both
                // sides below 2 dminor): at least 1, as first(m) is.
                let late = (q & 1) * dmin + r < 2 * r2 + b;
                Some((q * m + q2).checked_sub(q >> 1)? + u64::from(late))
            };
            if m_lo > 0 {
                lo = lo.max(first(u(m_lo)?)?);
            }
            if m_hi < self.dminor {
                hi = hi.min(first(u(m_hi)? + 1)? - 1);
            }
        }
        if lo > hi {
            return None;
        }
        let (m, d) = match NonZeroU64::new(dmaj) {
            // A single pixel: lo = hi = 0 and dminor = 0.
            None => (0, 0),
            // The first pixel: the textbook start, U = dmajor - b.
            Some(_) if lo == 0 => (
                0,
                2 * self.dminor - self.dmajor - i64::from(self.minor_step > 0),
            ),
            Some(nonzero) => {
                let (q3, r3) = div_rem_u64(dmin * lo, nonzero);
                let t = 2 * r3 + dmaj - b;
                let (m, r) = match t.checked_sub(2 * dmaj) {
                    Some(r) => (q3 + 1, r),
                    None => (q3, t),
                };
                let i = |v: u64| i64::try_from(v).ok();
                (i(m)?, i(r)? + 2 * self.dminor - 2 * self.dmajor)
            }
        };
        let i = |v: u64| i64::try_from(v).ok();
        Some((i(lo)?, i(hi)?, m, d))
    }
}

/// The visible part of a line: its first and last major coordinate, the
/// minor coordinate of its first pixel and the decision variable `D` there.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Visible {
    pub first_major: i32,
    pub last_major: i32,
    pub first_minor: i32,
    /// A minor coordinate inside the clip that no visible pixel passes:
    /// each lies between `first_minor` and this one.
    pub minor_bound: i32,
    pub decision: i64,
}

#[cfg(test)]
mod tests {
    use embedded_graphics_core::{
        geometry::{Point, Size},
        primitives::Rectangle,
    };

    use super::{Canonical, Visible};

    /// [`Canonical::inside`], in `i32`, against the general clip
    /// [`Canonical::visible`] (checked against the line reference in
    /// `tests/line.rs`): the same line and the same visible part, field
    /// for field, for lines with both ends in clips anywhere in `i32` of
    /// every size up to `2^30` px a side (the largest it takes), with and
    /// without the end pixel. Larger clips are left to `visible`.
    #[test]
    fn inside_matches_the_general_clip() {
        let mut random = crate::raster::xorshift(0x6A09_E667_F3BC_C909);
        let mut next = |n: u64| random.next().unwrap_or(0) % n;
        let mut taken = 0;
        for case in 0..50_000u64 {
            let side = |bits: u64| match bits {
                0 => 1 << 30,
                1 => (1 << 30) - 1,
                2 => (1 << 30) + 1,
                b => 1 + (1u64 << (b % 31)) as u32 / 2,
            };
            let size = Size::new(side(next(34)), side(next(34)));
            let corner = |len: u32, r: u64| {
                let room = (1u64 << 32) - u64::from(len);
                (i64::from(i32::MIN) + (r % room) as i64) as i32
            };
            let clip = Rectangle::new(
                Point::new(
                    corner(size.width, next(1 << 40)),
                    corner(size.height, next(1 << 40)),
                ),
                size,
            );
            let mut at = || {
                let mut offset = |len: u32| match next(4) {
                    0 => 0,
                    1 => len - 1,
                    _ => next(u64::from(len)) as u32,
                };
                let (dx, dy) = (offset(size.width), offset(size.height));
                Point::new(
                    clip.top_left.x.wrapping_add_unsigned(dx),
                    clip.top_left.y.wrapping_add_unsigned(dy),
                )
            };
            let (start, end) = (at(), at());
            let skip_end = case % 2 == 0;
            let general = Canonical::new(start, end);
            // A single pixel is never stepped: its decision does not
            // matter (and the two differ).
            let one = |(c, mut v): (Canonical, Visible)| {
                if v.first_major == v.last_major {
                    v.decision = 0;
                }
                (c, v)
            };
            let want = general.visible(&clip, skip_end).map(|v| one((general, v)));
            let got = Canonical::inside(start, end, &clip, skip_end).map(one);
            let large = size.width > 1 << 30 || size.height > 1 << 30;
            match large {
                true => assert_eq!(got, None),
                false => assert_eq!(got, want, "{start:?} to {end:?} in {clip:?}"),
            }
            taken += usize::from(got.is_some());
        }
        assert!(taken > 30_000, "{taken}");
    }

    /// The visible part by the formulas of the module docs evaluated
    /// directly in `i128`: the canonical form from the ends, `m(k)` and
    /// `D(k)` at each step, and the visible steps found by binary search
    /// over `m`, which is non-decreasing (no closed form). Returns the
    /// first and last major coordinate, the first minor coordinate, the
    /// decision there (`None` for a single pixel, which is never stepped)
    /// and the minor bound.
    fn reference(
        start: Point,
        end: Point,
        clip: &Rectangle,
        skip_end: bool,
    ) -> Option<(i128, i128, i128, Option<i128>, i128)> {
        let (sx, sy, ex, ey) = (
            i128::from(start.x),
            i128::from(start.y),
            i128::from(end.x),
            i128::from(end.y),
        );
        let x_major = (ex - sx).abs() >= (ey - sy).abs();
        let ((a0, a1), (n0, n1)) = match x_major {
            true => ((sx, ex), (sy, ey)),
            false => ((sy, ey), (sx, ex)),
        };
        // From the end with the smaller major coordinate.
        let ((major0, minor0), (major1, minor1)) = match a1 < a0 {
            true => ((a1, n1), (a0, n0)),
            false => ((a0, n0), (a1, n1)),
        };
        let (dmaj, step) = (major1 - major0, if minor1 < minor0 { -1 } else { 1 });
        let dmin = (minor1 - minor0) * step;
        let b = i128::from(step > 0);
        let m = |k: i128| match dmaj {
            0 => 0,
            _ => (2 * dmin * k + dmaj - b).div_euclid(2 * dmaj),
        };
        let bounds =
            |first: i32, len: u32| (i128::from(first), i128::from(first) + i128::from(len) - 1);
        let (bx, by) = (
            bounds(clip.top_left.x, clip.size.width),
            bounds(clip.top_left.y, clip.size.height),
        );
        let ((c0, c1), (d0, d1)) = if x_major { (bx, by) } else { (by, bx) };
        // Steps inside the clip's major range, and the end skipped.
        let mut lo = (c0 - major0).max(0);
        let mut hi = (c1 - major0).min(dmaj);
        if skip_end {
            match a1 < a0 {
                true => lo = lo.max(1),
                false => hi = hi.min(dmaj - 1),
            }
        }
        // The clip's minor range as offsets along the minor direction.
        let (o0, o1) = match step > 0 {
            true => (d0 - minor0, d1 - minor0),
            false => (minor0 - d1, minor0 - d0),
        };
        // The first step of lo..=hi + 1 where `past` holds (m rises).
        let first = |past: &dyn Fn(i128) -> bool| {
            let (mut x, mut y) = (lo, hi + 1);
            while x < y {
                let mid = x + (y - x) / 2;
                if past(mid) {
                    y = mid;
                } else {
                    x = mid + 1;
                }
            }
            x
        };
        if lo > hi {
            return None;
        }
        let (lo2, hi2) = (first(&|k| m(k) >= o0), first(&|k| m(k) > o1) - 1);
        if lo2 > hi2 {
            return None;
        }
        let decision =
            (dmaj > 0).then(|| 2 * dmin * lo2 + dmaj - b - 2 * dmaj * m(lo2) + 2 * dmin - 2 * dmaj);
        Some((
            major0 + lo2,
            major0 + hi2,
            minor0 + step * m(lo2),
            decision,
            minor0 + step * o1.min(dmin),
        ))
    }

    /// [`Canonical::visible`] against [`reference`]: lines with ends
    /// anywhere in `i32`, near clips of every size (empty ones and ones
    /// reaching past `i32::MAX` included), with and without the end pixel.
    /// (The pixels themselves are checked against the line reference in
    /// `tests/line.rs`.)
    #[test]
    fn visible_matches_the_formulas() {
        let mut random = crate::raster::xorshift(0x6A09_E667_F3BC_C909);
        let mut next = |n: u64| random.next().unwrap_or(0) % n;
        let (mut seen, mut cut) = (0, 0);
        for case in 0..200_000u64 {
            let side = |bits: u64| match bits {
                0 => 0,
                1 => u32::MAX,
                b => (1u64 << (b % 33)).min(u64::from(u32::MAX)) as u32,
            };
            let size = Size::new(side(next(40)), side(next(40)));
            let any = |r: u64| (r as u32) as i32;
            let clip = Rectangle::new(Point::new(any(next(1 << 32)), any(next(1 << 32))), size);
            // Near the clip: within three of its sides of its corner.
            let near = |first: i32, len: u32, r: u64| {
                let span = 3 * u64::from(len.max(2));
                let off =
                    i64::try_from(r % (2 * span)).unwrap_or(0) - i64::try_from(span).unwrap_or(0);
                let v = i64::from(first) + off;
                v.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32
            };
            let at = |next: &mut dyn FnMut(u64) -> u64| match next(5) {
                0 => Point::new(any(next(1 << 32)), any(next(1 << 32))),
                _ => Point::new(
                    near(clip.top_left.x, size.width, next(1 << 40)),
                    near(clip.top_left.y, size.height, next(1 << 40)),
                ),
            };
            let start = at(&mut next);
            let end = match next(3) {
                0 => Point::new(
                    start.x.saturating_add(next(9) as i32 - 4),
                    start.y.saturating_add(next(9) as i32 - 4),
                ),
                _ => at(&mut next),
            };
            let skip_end = case % 2 == 0;
            let c = Canonical::new(start, end);
            let got = c.visible(&clip, skip_end).map(|v| {
                let single = v.first_major == v.last_major && c.dmajor == 0;
                (
                    i128::from(v.first_major),
                    i128::from(v.last_major),
                    i128::from(v.first_minor),
                    (!single).then_some(i128::from(v.decision)),
                    i128::from(v.minor_bound),
                )
            });
            let want = reference(start, end, &clip, skip_end);
            assert_eq!(
                got, want,
                "{start:?} to {end:?} in {clip:?}, skip_end {skip_end}"
            );
            seen += usize::from(got.is_some());
            let whole = (
                i128::from(c.major0),
                i128::from(c.major0) + i128::from(c.dmajor),
            );
            cut += usize::from(got.is_some_and(|g| (g.0, g.1) != whole));
        }
        assert!(seen > 25_000 && cut > 20_000, "{seen} {cut}");
    }
}
