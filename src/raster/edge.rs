//! The exact incremental edge: where an edge crosses each pixel row.
//!
//! # Which pixels an edge separates
//!
//! Coordinates here are raw 20.12 units relative to the centre of a frame's
//! top-left pixel (see [`Frame`](super::frame::Frame)), so row `k` samples
//! `y = 4096 k` and column `i` has its centre at `x = 4096 i`. The sampling
//! rule nudges a centre to `(x + e, y + e^2)`, so an edge from `(x0, y0)`
//! down to `(x1, y1)` (`y0 < y1`) crosses the sample line of row `k` iff
//! `y0 <= 4096 k < y1`: a horizontal edge crosses none. On such a row the
//! nudged centre of column `i` lies right of the edge iff `4096 i >= x(y)`,
//! the edge's exact crossing (the `e` outweighs the `e^2` term whatever
//! the slope). So the edge splits the row at the *threshold*
//!
//! ```text
//! X = ceil(x(y) / 4096) = ceil(ceil(x(y)) / 4096),   x(y) = x0 + (y - y0) dx / dy
//! ```
//!
//! and columns `X..` lie right of it. A triangle's span is `X_left..X_right`;
//! a polygon sums the windings of the edges whose threshold is at or left
//! of a column.
//!
//! # Stepping in O(1), without division
//!
//! The edge keeps `x = ceil(x(y))`, the crossing rounded up to a raw unit,
//! and the remainder `s = x dy - (x0 dy + (y - y0) dx)`, `0 <= s < dy`. One
//! row down adds `4096 dx = q dy + r` (`0 <= r < dy`, divided once at
//! setup) to the numerator, so
//!
//! ```text
//! wrap = s < r;   x += q + wrap;   s += (wrap ? dy : 0) - r
//! ```
//!
//! one compare and two adds per row, exact. The edge stores `x + 4095`
//! rather than `x`, so that the row's threshold is one shift.
//!
//! # Widths
//!
//! The setup divides twice (`q` and the first crossing, see
//! [`Edge::new`]), in 32 bits when the operands fit (a single hardware
//! division on a Cortex-M), else in 64; a triangle's or a polygon's edge
//! never divides wider. (An edge along a line far past the 20.12 range,
//! [`Edge::along_line`], and [`threshold_on_row`] divide in 128 bits.)
//! The state steps in `T`: with every relative
//! coordinate below `2^29` in magnitude, `x`, `q`, `s`, `dy` and
//! `x + 4095` all stay below `2^31` (`|q| <= |dx| + 1` once the edge spans
//! two rows, since then `dy > 4096`), so `i32` is exact; `i64` always is.

use super::wide::{Narrow, Wide};

/// Raw units per pixel, and its logarithm.
const ONE: i32 = 1 << SHIFT;
const SHIFT: u32 = 12;

/// The first row whose sample line `4096 k` is at or below `y` (relative
/// raw units below `2^29` in magnitude for `i32`, so no overflow).
#[inline(always)]
fn first_row_at_or_below<T: Wide>(y: T) -> T {
    (y + bias()) >> SHIFT
}

/// An edge's crossing of consecutive rows, stepped exactly in `T`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Edge<T> {
    /// First and last row the edge crosses (the first is no higher than
    /// the row it was started on).
    pub first_row: i32,
    pub last_row: i32,
    /// `ceil(x(y)) + 4095` on the current row: the crossing rounded up
    /// to a raw unit and biased so that the threshold column is this
    /// shifted right by 12 (one shift a row, not an add and a shift).
    biased: T,
    /// `ceil(x(y)) dy` minus the exact numerator, in `0..dy`.
    s: T,
    /// `4096 dx = q dy + r`.
    q: T,
    r: T,
    dy: T,
}

impl<T: Narrow> Edge<T> {
    /// The edge from `top` to `bottom` (relative raw units within the
    /// bound of [`Wide::difference`], `top.1 < bottom.1`), started on its
    /// first row at or below row `from_row`. `None` if it crosses no row
    /// from there.
    ///
    /// With `4096 dx = q dy + r`, the edge's first row `k0` at `e0 = 4096
    /// k0 - y0` below its top (`0 <= e0 < 4096`) and `n` rows skipped by
    /// `from_row`, the crossing is `x0 + n q + ceil((e0 dx + n r) / dy)`.
    /// Both products are small: `e0 |dx| < 2^12 |dx|` and `n r < n dy <=
    /// dy^2 / 4096`, below `2^49` for `i32` coordinates (below `2^29`) and
    /// `2^55` for `i64` ones (below `2^33`): the numerator fits 64 bits,
    /// and 32 when the edge is short.
    ///
    /// Not inlined on 32-bit ARM, nor on any target built for size
    /// (`optimize_for_size`): a triangle sets up three edges, and one
    /// copy of this code per width is smaller, at the price of a call (see
    /// the triangle walk's `ONE_ROW_LOOP` for RISC-V's figures). Hosts
    /// inline it (the returned record read back right after its
    /// field-wise stores stalls store forwarding on x86-64).
    #[cfg_attr(any(target_arch = "arm", optimize_for_size), inline(never))]
    #[cfg_attr(not(any(target_arch = "arm", optimize_for_size)), inline(always))]
    pub(crate) fn new(top: (T, T), bottom: (T, T), from_row: i32) -> Option<Self> {
        // Differences of coordinates within the bound fit T.
        let (dx, dy) = (bottom.0 - top.0, bottom.1 - top.1);
        let start = first_row_at_or_below(top.1);
        let first = start.max(T::narrow(from_row.into())?);
        let last = first_row_at_or_below(bottom.1) - T::ONE;
        if first > last {
            return None;
        }
        let one = T::narrow(ONE.into())?;
        let wide = |v: T| T::Product::from(v);
        let (e0, n) = (start * one - top.1, first - start);
        // q and r only when the edge is stepped or started below its top:
        // an edge of one row costs one division.
        let (q, r) = if first < last || n > T::ZERO {
            T::div_rem_wide(wide(dx) * wide(one), dy)?
        } else {
            (T::ZERO, T::ZERO)
        };
        // ceil(m / dy) = -floor(-m / dy); the remainder of -m is c dy - m.
        let minus = -(wide(e0) * wide(dx) + wide(n) * wide(r));
        let (f, s) = T::div_rem_wide(minus, dy)?;
        Some(Self {
            first_row: first.to_i32()?,
            last_row: last.to_i32()?,
            // n q + c is the crossing's move from x0 within the edge.
            biased: top.0 + n * q - f + bias(),
            s,
            q,
            r,
            dy,
        })
    }
}

impl Edge<i32> {
    /// [`Edge::new`] from the edge's own first row, for an edge less than
    /// [`SMALL`] raw units wide that starts in the frame: `|bottom.0 -
    /// top.0| < SMALL`, every coordinate below `2^29` in magnitude (the
    /// bound of exact `i32` stepping, [`Wide::difference`]), and `-4096 <
    /// top.1 < bottom.1` (the caller shows all of it from the shape's
    /// bounding box and frame).
    ///
    /// Then every product fits `i32` and nothing is checked: `|4096 dx| <
    /// 2^31` and `e0 |dx| <= 4095 (2^19 - 1) < 2^31`, and with no row
    /// skipped (`n = 0`) the crossing is `x0 + ceil(e0 dx / dy)`, which
    /// lies between the ends' `x` (the edge's first row lies within it),
    /// so that it and its bias stay below `2^29 + 4096`. The height is
    /// only a divisor, below `2^30`. Two divisions, one hardware
    /// instruction each on a Cortex-M3 or later.
    ///
    /// ARMv6-M has no divide instruction: a division is a library call of
    /// about 160 instructions there, and an edge that crosses a single
    /// row, never stepped, skips the step's (`q` and `r` are then 0).
    /// `.ci/icount --target thumbv6m-none-eabi`: 4 px triangles 1,856 →
    /// 1,691 instructions, the built-in scene 1,012,516 → 991,953, 16 px
    /// triangles 3,094 → 3,109. Where the division is one instruction the
    /// test costs more than it saves (Cortex-M4, `.ci/icount`: setup
    /// 268 → 270, 16 px triangles 1,247 → 1,255), and the hosts divide
    /// both times too (x86-64: level, measured on 2026-12-05). `.ci/run`
    /// runs the exactness tests with this path on the host as well
    /// (`--cfg software_division`).
    ///
    /// Inlined on 32-bit ARM too, unlike [`new`](Self::new): on a
    /// Cortex-M4 (`.ci/icount`) it saves 26 of a triangle's setup
    /// instructions (298 → 272: the call, and the record written to
    /// memory and read back; 4 px triangles 663 → 616, 16 px 1,297 →
    /// 1,250, the built-in scene 564,739 → 552,932), for 220 bytes of
    /// flash in a firmware that fills flat triangles (4,664 → 4,884 at
    /// "s") and 912 in the crate's whole firmware, a copy per kind of sink.
    #[inline(always)]
    pub(crate) fn new_small(top: (i32, i32), bottom: (i32, i32)) -> Option<Self> {
        let (dx, dy) = (bottom.0 - top.0, bottom.1 - top.1);
        let first = first_row_at_or_below(top.1);
        let last = first_row_at_or_below(bottom.1) - 1;
        if first > last {
            return None;
        }
        let e0 = first * ONE - top.1;
        // Where a division is a library call (`software_division`), an
        // edge of one row skips the step's (see the doc above).
        let (q, r) = match !cfg!(software_division) || first < last {
            true => (dx * ONE).div_rem_floor(dy)?,
            false => (0, 0),
        };
        let (f, s) = (-(e0 * dx)).div_rem_floor(dy)?;
        Some(Self {
            first_row: first,
            last_row: last,
            biased: top.0 - f + (ONE - 1),
            s,
            q,
            r,
            dy,
        })
    }
}

/// The bound of [`Edge::new_small`] on an edge's width: `2^19` raw
/// units, 128 pixels.
pub(crate) const SMALL: i32 = 1 << 19;

impl<T: Wide> Edge<T> {
    /// `ceil(x(y))` on the current row, in raw units, plus a constant
    /// (4095): edges crossing a row are ordered by it, with no
    /// subtraction.
    #[inline(always)]
    pub(crate) fn crossing_key(&self) -> T {
        self.biased
    }

    /// The threshold column on the current row: columns from it on lie
    /// right of the edge.
    #[inline(always)]
    pub(crate) fn threshold(&self) -> T {
        self.biased >> SHIFT
    }

    /// Moves to the next row. Written as selects, not branches: whether
    /// the remainder wraps is data, and a mispredicted branch per row
    /// would cost more than the whole step. Both `s` and `r` lie in
    /// `0..dy`, so they compare as unsigned: x86-64 then adds the
    /// comparison's carry to the crossing (`cmp`, `adc`), where a signed
    /// comparison took a `setl` and an add (random triangles on the
    /// framebuffer, instructions counted by callgrind: small 1,345 a
    /// triangle → 1,304, medium 4,482 → 4,287, large 15,086 → 14,512).
    /// 32-bit ARM compiles both to the same code.
    #[inline(always)]
    pub(crate) fn step(&mut self) {
        let wrap = self.s.below(self.r);
        self.biased = self.biased + self.q + if wrap { T::ONE } else { T::ZERO };
        self.s = self.s - self.r + if wrap { self.dy } else { T::ZERO };
    }
}

impl Edge<i64> {
    /// The edge along the line through `p` with direction `d` (`d.1 !=
    /// 0`, either sign), on rows `0..=last`: `p` and `d` in an `Edge`'s
    /// coordinates (column `i`'s centre at `x = 4096 i`, row `k` sampled
    /// at `y = 4096 k`), each below `2^62` in magnitude, as
    /// [`threshold_on_row`] takes them. Set up on row 0 in `i128` (two
    /// divisions), then stepped in `i64` like any edge.
    ///
    /// For the lines that bound a shape far past the range an
    /// [`Edge::new`] is set up in (a stroke's pieces beyond the 20.12
    /// range), whose thresholds [`threshold_on_row`] would otherwise find
    /// with a 128-bit division on every row. `None` if `d.1 = 0`, an
    /// operand is out of bound, `last < 0`, or `|c_0| + last (|q| + 1) +
    /// 4096` (a bound on every crossing the walk reaches, `c_0` row 0's,
    /// `q` the step) is `2^62` or more: the caller then finds each row's
    /// threshold directly. The edge may be stepped once past row `last`
    /// (a walk steps after each row): that crossing stays below `2^62 +
    /// 2^62`, within `i64`.
    ///
    /// The crossing of row `k` is `ceil(m_k / dy)` with `m_k = p.0 dy + (4096
    /// k - p.1) dx` (`d` reversed if need be so that `dy > 0`); each product
    /// is below `2^62 2^63 = 2^125`, and their sum `2^126`. The step `4096
    /// dx = q dy + r` is below `2^74`. From row 0 on the crossing moves by
    /// `q` or `q + 1` a row, so it stays within `|c_0| + last (|q| + 1)`,
    /// which is checked; then every value the edge steps through fits
    /// `i64` (module docs).
    pub(crate) fn along_line(p: (i64, i64), d: (i64, i64), last: i32) -> Option<Self> {
        const BOUND: i128 = 1 << 62;
        let wide = i128::from;
        if d.1 == 0 || [p.0, p.1, d.0, d.1].iter().any(|&v| wide(v).abs() >= BOUND) || last < 0 {
            return None;
        }
        let (dx, dy) = match d.1 < 0 {
            true => (-wide(d.0), -wide(d.1)),
            false => (wide(d.0), wide(d.1)),
        };
        let one = wide(ONE.into());
        let (q, r) = (dx * one).div_rem_floor(dy)?;
        // ceil(m / dy) = -floor(-m / dy); the remainder of -m is c dy - m.
        let m = wide(p.0) * dy - wide(p.1) * dx;
        let (f, s) = (-m).div_rem_floor(dy)?;
        let reach = f.abs() + wide(last.into()) * (q.abs() + 1) + one;
        if reach >= BOUND || q.abs() >= BOUND {
            return None;
        }
        let narrow = |v: i128| i64::try_from(v).ok();
        Some(Self {
            first_row: 0,
            last_row: last,
            biased: narrow(-f)? + bias::<i64>(),
            s: narrow(s)?,
            q: narrow(q)?,
            r: narrow(r)?,
            dy: narrow(dy)?,
        })
    }

    /// The least and the greatest threshold on rows `0..=last_row` of an
    /// edge from [`along_line`](Self::along_line) not yet stepped: from
    /// row 0 the crossing moves by `q` or `q + 1` a row, always the same
    /// way, so row `last_row`'s lies between `last_row q` and `last_row
    /// (q + 1)` from row 0's (all below `2^62`, as `along_line` checked).
    pub(crate) fn threshold_bounds(&self) -> (i64, i64) {
        let rows = i64::from(self.last_row);
        let (least, most) = (
            self.biased + rows * self.q,
            self.biased + rows * (self.q + 1),
        );
        (
            (least >> SHIFT).min(self.threshold()),
            (most >> SHIFT).max(self.threshold()),
        )
    }
}

/// The threshold column of one row for the line through `p` with
/// direction `d` (`d.1 != 0`, either sign), found directly by one
/// division instead of stepped: what an [`Edge`] along that line holds on
/// the row sampled at `y`, `ceil(x(y) / 4096)` with `x(y) = p.0 + (y -
/// p.1) d.0 / d.1`, columns from it on lying right of the line.
/// Coordinates are an `Edge`'s (column `i`'s centre at `x = 4096 i`: a
/// caller whose centres lie at `4096 i + 2048` passes `p.0 - 2048`).
///
/// For shapes that meet a line on a single row, or lie beyond the range
/// an `Edge` steps in (a stroke's round joins, and its pieces far off the
/// 20.12 range). In `i64` when every operand lies below `2^30` in
/// magnitude (then `|y - p.1| < 2^31`, each product below `2^61`), else in
/// `i128`, exact for operands below `2^62` (products below `2^125`);
/// `None` past that bound or for `d.1 = 0`. A threshold past the `i64`
/// range saturates: it lies beyond every pixel either way.
pub(crate) fn threshold_on_row(p: (i64, i64), d: (i64, i64), y: i64) -> Option<i64> {
    let below = |bound: u32| {
        [p.0, p.1, d.0, d.1, y]
            .iter()
            .all(|v| v.unsigned_abs() < 1 << bound)
    };
    if below(30) {
        threshold_in::<i64>(p, d, y)
    } else if below(62) {
        let t = threshold_in::<i128>(p, d, y)?;
        Some(i64::try_from(t).unwrap_or(if t < 0 { i64::MIN } else { i64::MAX }))
    } else {
        None
    }
}

/// [`threshold_on_row`] in `T`, whose bound the caller has checked.
fn threshold_in<T: Wide>(p: (i64, i64), d: (i64, i64), y: i64) -> Option<T> {
    let (x, x_step, y_step, rise) = (
        T::narrow(p.0)?,
        T::narrow(d.0)?,
        T::narrow(d.1)?,
        T::narrow(y)? - T::narrow(p.1)?,
    );
    // The same line with `d` reversed: the divisor positive.
    let (x_step, y_step) = match y_step < T::ZERO {
        true => (-x_step, -y_step),
        false => (x_step, y_step),
    };
    // x(y) / 4096 = (x dy + rise dx) / (4096 dy); ceil(m / n) = -floor(-m / n).
    let m = x * y_step + rise * x_step;
    let (f, _) = (-m).div_rem_floor(y_step * T::narrow(ONE.into())?)?;
    Some(-f)
}

/// 4095 in `T`, the bias of [`Edge`]'s crossing: `ceil(x / 4096) = (x +
/// 4095) >> 12`.
#[inline(always)]
fn bias<T: Wide>() -> T {
    T::narrow(i64::from(ONE - 1)).unwrap_or(T::ZERO)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The threshold computed from scratch with exact rationals (u128-free:
    /// i128 numerators), independent of the stepping.
    fn direct(top: (i64, i64), bottom: (i64, i64), row: i64) -> i64 {
        let (dx, dy) = (i128::from(bottom.0 - top.0), i128::from(bottom.1 - top.1));
        // x(y) = x0 + (4096 row - y0) dx / dy; threshold = ceil(x(y) / 4096).
        let num = i128::from(top.0) * dy + (i128::from(row) * 4096 - i128::from(top.1)) * dx;
        let den = 4096 * dy;
        (-((-num).div_euclid(den))) as i64
    }

    fn check(top: (i64, i64), bottom: (i64, i64), from: i32) {
        let Some(mut e) = Edge::<i64>::new(top, bottom, from) else {
            return;
        };
        let small = |v: i64| i32::try_from(v).ok().filter(|v| v.unsigned_abs() < 1 << 29);
        let mut narrow = match (small(top.0), small(top.1), small(bottom.0), small(bottom.1)) {
            (Some(a), Some(b), Some(c), Some(d)) => Edge::<i32>::new((a, b), (c, d), from),
            _ => None,
        };
        // The unchecked constructor, where its bounds hold (coordinates
        // below 2^29, less than SMALL wide, the top less than a row above
        // row 0) and no row is skipped.
        let stepped = |v: i64| i32::try_from(v).ok().filter(|v| v.unsigned_abs() < 1 << 29);
        let mut small = match (
            stepped(top.0),
            stepped(top.1),
            stepped(bottom.0),
            stepped(bottom.1),
        ) {
            (Some(a), Some(b), Some(c), Some(d))
                if (bottom.0 - top.0).unsigned_abs() < SMALL as u64
                    && top.1 > -4096
                    && i64::from(from) <= (top.1 + 4095) >> 12 =>
            {
                let edge = Edge::new_small((a, b), (c, d));
                assert!(edge.is_some(), "{top:?} {bottom:?}");
                edge
            }
            _ => None,
        };
        for row in e.first_row..=e.last_row {
            let want = direct(top, bottom, row.into());
            assert_eq!(e.threshold(), want, "{top:?} {bottom:?} row {row}");
            if let Some(n) = narrow.as_mut() {
                assert_eq!(i64::from(n.threshold()), want, "i32, row {row}");
            }
            if let Some(n) = small.as_mut() {
                assert_eq!((n.first_row, n.last_row), (e.first_row, e.last_row));
                assert_eq!(i64::from(n.threshold()), want, "small, row {row}");
            }
            if row < e.last_row {
                e.step();
                if let Some(n) = narrow.as_mut() {
                    n.step();
                }
                if let Some(n) = small.as_mut() {
                    n.step();
                }
            }
        }
    }

    #[test]
    fn stepping_matches_direct_thresholds() {
        check(
            (3 * 4096 + 1229, -700),
            (-20 * 4096 - 410, 40 * 4096 + 3686),
            i32::MIN,
        );
        check((0, 0), (1, 100 * 4096), -5);
        check((0, -1), (-5_000_000, 7 * 4096 + 1), 2);
        check((17, 4096), (17, 3 * 4096), 0);
        // Small edges: steep, shallow, both directions, at the bound.
        check((-2048, -4095), (30_000, 9_000), i32::MIN);
        check((100_000, 5), (-100_000, 41_000), 0);
        check(
            (-(1 << 18), -(1 << 18)),
            ((1 << 18) - 1, (1 << 18) - 1),
            -64,
        );
        check((3, -1), (-5, 7 * 4096 + 1), 0);
        // Narrow and tall, to the bounds of the unchecked constructor.
        check((-4095, -4095), ((1 << 19) - 4096, (1 << 29) - 1), i32::MIN);
        check(
            ((1 << 29) - 1, 0),
            ((1 << 29) - (1 << 19) + 1, (1 << 29) - 1),
            0,
        );
        check((-(1 << 29) + 1, 17), (-(1 << 29) + 5, 300 * 4096 + 3), 0);
    }

    /// The unchecked constructor on random edges within its bounds:
    /// under 128 px wide, any height below 2^29 raw units, their tops
    /// within a row above the frame's first or anywhere below it.
    #[test]
    fn narrow_edges_of_any_height() {
        let mut random = crate::raster::xorshift(0x3C6E_F372_FE94_F82B);
        let mut next = |n: i64| (random.next().unwrap_or_default() >> 1) as i64 % n;
        for _ in 0..20_000 {
            let top = (next(1 << 30) - (1 << 29), next(1 << 29) - 4095);
            let width = next(2 * SMALL as i64 - 1) - (SMALL as i64 - 1);
            let x = (top.0 + width).clamp(-(1 << 29) + 1, (1 << 29) - 1);
            let bits = 1 + next(29);
            let height = 1 + next(1i64 << bits);
            let bottom = (x, (top.1 + height).min((1 << 29) - 1));
            if top.1 < bottom.1 {
                check(top, bottom, i32::MIN);
            }
        }
    }

    /// Edges along lines far from their frame ([`Edge::along_line`])
    /// against the exact reference, row by row: random lines of every
    /// size up to the bound, in both directions. Refused only where a
    /// crossing on the first or last row, or the step, lies past `2^60`.
    #[test]
    fn lines_stepped_from_afar_match_the_reference() {
        let mut next = signed_bits(0x6A09_E667_F3BC_C909);
        // ceil(x / 4096) of the crossing of row k, and the crossing ceil(x).
        let reference = |p: (i64, i64), d: (i64, i64), k: i64| {
            let (dx, dy) = (i128::from(d.0), i128::from(d.1));
            let (dx, dy) = if dy < 0 { (-dx, -dy) } else { (dx, dy) };
            let num = i128::from(p.0) * dy + (i128::from(k) * 4096 - i128::from(p.1)) * dx;
            let ceil = |n: i128, d: i128| -((-n).div_euclid(d));
            (ceil(num, 4096 * dy), ceil(num, dy))
        };
        let (mut stepped, mut refused) = (0, 0);
        for bits in [14, 20, 31, 46, 61, 63] {
            for _ in 0..3000 {
                let p = (next(bits), next(bits));
                // Steep and shallow: dy from 1 bit to 48.
                let dy_bits = 1 + next(7).unsigned_abs() as u32 % 48;
                let d = (next(bits.min(48)), next(dy_bits));
                let last = next(8).abs() as i32;
                let edge = Edge::along_line(p, d, last);
                let within = [p.0, p.1, d.0, d.1]
                    .iter()
                    .all(|v| v.unsigned_abs() < 1 << 62);
                if d.1 == 0 || !within {
                    assert!(edge.is_none(), "{p:?} {d:?}");
                    continue;
                }
                let Some(mut edge) = edge else {
                    let ends = [reference(p, d, 0).1, reference(p, d, last.into()).1];
                    let q = 4096 * i128::from(d.0) / i128::from(d.1);
                    let far = ends.iter().chain([&q]).any(|v| v.abs() >= 1 << 60);
                    assert!(far, "{p:?} {d:?} rows 0..={last} refused");
                    refused += 1;
                    continue;
                };
                assert_eq!((edge.first_row, edge.last_row), (0, last));
                let (least, most) = edge.threshold_bounds();
                for k in 0..=last {
                    let want = reference(p, d, k.into()).0;
                    assert_eq!(i128::from(edge.threshold()), want, "{p:?} {d:?} row {k}");
                    assert!(
                        (least..=most).contains(&edge.threshold()),
                        "{p:?} {d:?} row {k}"
                    );
                    edge.step();
                }
                stepped += 1;
            }
        }
        assert!(stepped > 9_000 && refused > 100, "{stepped} {refused}");
        // A step of 2^59 raw units a row from the origin: the crossing of
        // row 7 is below 2^62 and that of row 8 is not, so that stepping
        // there would overflow.
        let shallow = (1 << 47, 1);
        let mut edge = Edge::along_line((0, 0), shallow, 7).expect("rows 0..=7");
        for k in 0..=7 {
            assert_eq!(
                i128::from(edge.threshold()),
                reference((0, 0), shallow, k).0
            );
            edge.step();
        }
        assert!(Edge::along_line((0, 0), shallow, 8).is_none());
        assert!(Edge::along_line((0, 0), (-1 << 47, -1), 8).is_none());
        // Walks as tall as a tile can be (up to 2^31 - 1 rows), not
        // stepped through: the bounds hold the reference's thresholds on
        // the first and the last row.
        let mut tall = 0;
        for _ in 0..3000 {
            let p = (next(44), next(44));
            let dy_bits = 1 + next(7).unsigned_abs() as u32 % 44;
            let d = (next(44), next(dy_bits));
            let last = next(32).unsigned_abs().min(i32::MAX as u64) as i32;
            if d.1 == 0 {
                continue;
            }
            if let Some(edge) = Edge::along_line(p, d, last) {
                let (least, most) = edge.threshold_bounds();
                for k in [0, i64::from(last)] {
                    let want = reference(p, d, k).0;
                    let within = (i128::from(least)..=i128::from(most)).contains(&want);
                    assert!(within, "{p:?} {d:?} row {k} of {last}");
                }
                tall += 1;
            }
        }
        assert!(tall > 300, "{tall}");
    }

    /// Random values of `bits` bits, signed (`-2^(bits-1)..2^(bits-1)`),
    /// from the generator seeded `seed`.
    fn signed_bits(seed: u64) -> impl FnMut(u32) -> i64 {
        let mut random = crate::raster::xorshift(seed);
        move |bits| {
            let x = random.next().unwrap_or_default();
            ((x >> 1) % (1 << bits)) as i64 - (1 << (bits - 1))
        }
    }

    /// The direct threshold against the exact reference: the lines of
    /// random edges in both directions, on rows inside and outside them,
    /// in both widths and at the bound of each.
    #[test]
    fn direct_thresholds_match_the_reference() {
        let mut next = signed_bits(0x2545_F491_4F6C_DD1D);
        let mut lines = 0;
        for bits in [14, 20, 31, 48, 63] {
            for _ in 0..4000 {
                let (top, bottom) = ((next(bits), next(bits)), (next(bits), next(bits)));
                if top.1 == bottom.1 {
                    continue;
                }
                let row = (top.1 >> 12) + next(6);
                let y = row * 4096;
                // `direct` takes the edge downwards; its line is the same
                // either way, and so is the threshold.
                let (hi, lo) = if top.1 < bottom.1 {
                    (top, bottom)
                } else {
                    (bottom, top)
                };
                let (Some(dx), Some(dy)) =
                    (bottom.0.checked_sub(top.0), bottom.1.checked_sub(top.1))
                else {
                    continue;
                };
                let got = threshold_on_row(top, (dx, dy), y);
                let within = [top.0, top.1, dx, dy, y]
                    .iter()
                    .all(|v| v.unsigned_abs() < 1 << 62);
                // Past the bound: refused, never wrong.
                assert_eq!(got.is_some(), within, "{top:?} {bottom:?} row {row}");
                if let Some(got) = got {
                    assert_eq!(got, direct(hi, lo, row), "{top:?} {bottom:?} row {row}");
                    lines += 1;
                }
            }
        }
        assert!(lines > 15_000, "{lines}");
        // Crossings on a column centre and one raw unit either side of it
        // (ties of the rounding), on both sides of zero.
        for a in [-3i64, 0, 2, 1 << 20] {
            for e in [-1, 0, 1] {
                let p = (4096 * a + e, 4096 * 5);
                for d in [(3, 7), (-3, 7), (3, -7), (0, 1)] {
                    let (hi, lo) = (
                        (p.0 - 4 * d.0, p.1 - 4 * d.1),
                        (p.0 + 4 * d.0, p.1 + 4 * d.1),
                    );
                    let (hi, lo) = if hi.1 < lo.1 { (hi, lo) } else { (lo, hi) };
                    assert_eq!(
                        threshold_on_row(p, d, p.1),
                        Some(direct(hi, lo, 5)),
                        "{p:?} {d:?}"
                    );
                }
            }
        }
        assert_eq!(threshold_on_row((5, 5), (3, 0), 4096), None);
    }

    #[test]
    fn the_whole_range() {
        let (lo, hi) = (-(1i64 << 32), (1i64 << 32) - 1);
        let e = Edge::<i64>::new((lo, lo), (hi, hi), 0).unwrap();
        assert_eq!(e.threshold(), direct((lo, lo), (hi, hi), 0));
        let e = Edge::<i64>::new((hi, lo + 3), (lo, hi), 1 << 19).unwrap();
        assert_eq!(e.threshold(), direct((hi, lo + 3), (lo, hi), 1 << 19));
    }
}
