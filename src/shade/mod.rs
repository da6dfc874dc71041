//! Shading: flat colour from vertex colours, Gouraud interpolation and the
//! depth test.
//!
//! # Interpolation without per-pixel division
//!
//! For a triangle `v0 v1 v2` with doubled signed area `D = (v1 - v0) x (v2 -
//! v0)` (raw 20.12 units, `|D| < 2^65`), the weight of vertex `k` at a point
//! `p` is `w_k(p) = (v_(k+1) - p) x (v_(k+2) - p)`; `w_0 + w_1 + w_2 = D`,
//! and `w_k / D` are the barycentric coordinates, all in `[0, 1]` at any
//! pixel centre the rasterizer lights (the top-left nudge only decides
//! centres with some `w_k = 0`). The exact value of an attribute with
//! vertex values `a_k` at `p` is
//!
//! ```text
//! a(p) = (a_0 w_0 + a_1 w_1 + a_2 w_2) / D = a_0 + (a_1 - a_0) l_1 + (a_2 - a_0) l_2,   l_k = w_k / D
//! ```
//!
//! Values are carried in 32.32 fixed point (`i64`). The rasterizer's spans
//! (the very same spans as the flat triangle: [`Triangle::for_each_span`])
//! are shaded as follows:
//!
//! - per triangle that crosses two rows of pixel centres or more, the
//!   steps of `L_k = 2^60 w_k / D` (below) a column right and a row
//!   down, rounded: four `i128` divisions shared by every attribute;
//!   from them, each attribute's
//!   steps a column right and a row down in 20.44 fixed point (`2^44` times
//!   `(a_1 - a_0) dL_1 + (a_2 - a_0) dL_2`, rounded), and its step per
//!   pixel `d` in 32.32, the column step rounded to `2^-32`. A triangle
//!   that crosses one row has one span: its `d = round(2^32 * 4096 *
//!   sum(a_k (y_(k+1) - y_(k+2))) / D)`, one `i128` division per
//!   attribute;
//! - per span, the value at its first pixel centre `p`, from `2^44 (a(p) -
//!   a_0)` in 20.44 fixed point. The span is the row's whole span, not
//!   cut by any clip, and a triangle under a clip is walked from a row
//!   that is a multiple of 32 at or above the clip's top, so that its
//!   values do not depend on the clip: the same pixels whole, in bands or
//!   in any window (the part of a span inside the clip is drawn from its
//!   offset into the whole span, the value that many single steps
//!   reach). At a triangle's first span (and at any span more than a row
//!   below the last, or on a row that is a multiple of 32), from
//!   `L_k = round(2^60 w_k(p) / D)` for `k = 1, 2`, two `i128` divisions
//!   shared by every attribute, as `round(((a_1 - a_0) L_1 + (a_2 - a_0)
//!   L_2) / 2^16)`; at the next span's first pixel, a
//!   row down and `dx` columns across, by adding the attribute's row step
//!   and `dx` times its column step (up to 8 columns by adds, farther by
//!   one product), with no division and no product of coordinates
//!   (`SpanStarts` in the source). Then `v = 2^32 a_0 +
//!   round(2^-12 * that) + 2^31`: the value in 32.32, plus the `1/2` of
//!   its rounding, added once a span;
//! - per pixel, one add `v += d` per attribute, and the output is `floor(v
//!   / 2^32)`, the integer part (the value rounded). On 32-bit targets
//!   not built for size (Cortex-M, RISC-V, i686) a Gouraud span carries
//!   its channels' integer parts packed into one word, as the colour
//!   packs them (`ShadeColor` gives them in its raw bits' order), and
//!   their fractions apart: the same adds and the same integer parts, in
//!   fewer registers (`PackedChannels` in the source).
//!
//! # The error bound
//!
//! Attribute values are integers in `0..=65535` (colour channels, `u16`
//! depth). In units of the attribute:
//!
//! - the start value is off by less than `2^-20 + 2^-33`: `2^-43` for
//!   the division (the two `L_k`, each within `2^-61` of exact, scaled by
//!   `|a_k - a_0| <= 65535`, and the rounding to `2^-44`) and as much for
//!   each unit step after it, over fewer than `3 * 2^20` of them, and
//!   `2^-33` for the rounding to 32.32 (`SpanStarts`' docs);
//! - the step is off by less than `2^-33 + 2^-43` (the column step in
//!   20.44 within `2^-43`, like a span start's unit step, then rounded to
//!   `2^-32`);
//! - lit pixels of a row lie in the vertices' bounding box, whose width is
//!   at most `2^20` px, so a span has at most `2^20` pixels and the last one
//!   is reached after `n <= 2^20 - 1` steps.
//!
//! So the carried value is within `2^-20 + 2^-33 + (2^20 - 1) (2^-33 +
//! 2^-43) < 2^-12` of the exact `a(p)` at every lit pixel, and the rounded output is
//! within `1/2 + 2^-12 < 1` of it: **within 1 unit per channel**, for every
//! triangle in range (huge, far off-screen or sliver alike). It equals the
//! exactly rounded value unless `a(p)` lies within `2^-12` of a half
//! integer. Because `a(p)` lies between the smallest and largest `a_k`
//! (the `l_k` are in `[0, 1]`), the output does too, so it always fits the
//! channel and a pixel centre on a vertex gets exactly that vertex's value.
//!
//! Intermediate sizes: `|w_k(p)| <= |D| < 2^65` at lit pixels, so `2^60
//! w_k` and the rounding `2 n + D` stay below `2^127`; the step numerator
//! is below `3 * 2^16 * 2^45 * 2^32 < 2^95`. A step too large for `i64`
//! (over `2^48`, i.e. more than `65535` units per pixel) cannot occur on a
//! span of two or more pixels, where `|d| <= 65535 * 2^32` since both ends
//! lie in range; it is then never used and is stored as 0.

mod color;
mod depth;

pub use color::{average_color, ShadeColor};
pub use depth::{DepthBuffer, DepthTriangle, FAR};

use core::{marker::PhantomData, num::NonZeroU128};

use embedded_graphics_core::{draw_target::DrawTarget, Drawable};

use crate::{
    raster::wide::{orientation, Divisor},
    span::Span,
    triangle::FilledTriangle,
    triangle::Triangle,
};

/// `1/2` in 32.32 fixed point, for rounding: added to a span's start
/// values ([`SpanStarts::at`]).
const HALF: i64 = 1 << 31;

/// The barycentric frame of a triangle: its raw vertices and doubled signed
/// area (module docs).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Frame {
    p: [(i64, i64); 3],
    area2: i128,
    /// `m = 2 |D|`, which every value of the triangle's shading is divided
    /// by (`SpanStarts`, `Linear`), prepared once.
    divisor: Divisor,
    /// The steps of `L_1, L_2` a column right and a row down, for a
    /// triangle that crosses two rows of pixel centres or more
    /// ([`lambda_steps_by_division`](Self::lambda_steps_by_division)):
    /// every attribute's steps are made from them.
    lambda_steps: Option<[[i64; 2]; 2]>,
}

impl Frame {
    /// The frame of `t`, made in `slot` and borrowed from there; `None`
    /// (and `slot` left `None`) for a triangle of zero area, which lights
    /// nothing.
    ///
    /// Made in place, as `Option::insert` does. Returned by value, the
    /// frame (144 bytes on a Cortex-M4) was copied by `memcpy` after its
    /// steps were found through a reference to it: 164 instructions of a
    /// 16 px depth-tested triangle's 7,132 (`.ci/itrace`); in a firmware
    /// built with LTO and one codegen unit, four copies in a Gouraud
    /// triangle's setup (592 instructions), and with two colour types 727
    /// instructions of copies. Out of line: inlined into each kind of
    /// shading, it took 644 bytes more flash at opt-level "s"
    /// (`.ci/codesize_shading`).
    #[inline(never)]
    pub(crate) fn new_in<'a>(slot: &'a mut Option<Self>, t: &Triangle) -> Option<&'a Self> {
        let p = t.vertices.map(|v| {
            let (x, y) = v.raw();
            (i64::from(x), i64::from(y))
        });
        // Raw coordinates are far below 2^62: exact (raster::wide).
        let area2 = orientation(p[0], p[1], p[2]);
        let divisor = Divisor::new(NonZeroU128::new(2 * area2.unsigned_abs())?);
        let frame = slot.insert(Self {
            p,
            area2,
            divisor,
            lambda_steps: None,
        });
        // A triangle that crosses one row of pixel centres at most has one
        // span, and nothing to step: its attributes' per-pixel steps take
        // a division each instead of the four here. It crosses the row of
        // centre `4096 k + 2048` iff `low <= 4096 k + 2048 < high`, so its
        // first row is `ceil((low - 2048) / 4096)` and the row after its
        // last `ceil((high - 2048) / 4096)` (raw coordinates are far below
        // 2^62: exact). Two pixels tall or more, it crosses two rows: the
        // rows are only counted below that.
        let ys = p.map(|p| p.1);
        if let (Some(low), Some(high)) = (ys.into_iter().min(), ys.into_iter().max()) {
            let row_at_or_below = |y: i64| (y - 2048 + 4095) >> 12;
            let tall = high - low >= 2 * 4096
                || (high - low >= 4096 && row_at_or_below(high) - row_at_or_below(low) >= 2);
            if tall {
                frame.lambda_steps = frame.lambda_steps_by_division();
            }
        }
        Some(frame)
    }

    /// `round(n / D)`, halves up, as `floor((2 s n + |D|) / m)` for `s` the
    /// sign of `D`; `None` if `2 |n| + |D|` does not fit `i128`.
    fn round(&self, n: i128) -> Option<i128> {
        let n = if self.area2 < 0 { n.checked_neg()? } else { n };
        let t = n
            .checked_mul(2)?
            .checked_add(i128::try_from(self.area2.unsigned_abs()).ok()?)?;
        self.divisor.floor_div_rem(t).map(|(q, _)| q)
    }

    /// `L_1, L_2` at the centre of pixel `(x, y)`: `round(2^60 w_k / D)`,
    /// in `0..=2^60` at a lit pixel (saturated to `i64` elsewhere). Two
    /// `i128` divisions; out of line, as every caller's first span and
    /// far moves share it.
    #[inline(never)]
    fn lambdas_at(&self, x: i32, y: i32) -> [i64; 2] {
        let p = &self.p;
        let c = (i64::from(x) * 4096 + 2048, i64::from(y) * 4096 + 2048);
        core::array::from_fn(|k| {
            // w_(k+1) = (a - c) x (b - c): the orientation of c, a, b, below
            // 2^65 in magnitude at a lit pixel, so that 2^60 w stays inside
            // `i128` there; saturated for a pixel far outside.
            let w = orientation(c, p[(k + 2) % 3], p[k]);
            let positive = (w < 0) == (self.area2 < 0);
            let l = w.checked_mul(1 << 60).and_then(|n| self.round(n));
            match l.and_then(|l| i64::try_from(l).ok()) {
                Some(l) => l,
                None if positive => i64::MAX,
                None => i64::MIN,
            }
        })
    }

    /// The changes of `L_1, L_2` a column right and a row down, rounded
    /// (`round(2^60 4096 (y_(k+1) - y_(k+2)) / D)` and `round(2^60 4096
    /// (x_(k+2) - x_(k+1)) / D)`); `None` unless each is below `2^61` in
    /// magnitude, a change of 2 (only a triangle narrower than a pixel
    /// across a step changes them more). Four `i128` divisions, out of
    /// line.
    #[inline(never)]
    fn lambda_steps_by_division(&self) -> Option<[[i64; 2]; 2]> {
        let p = &self.p;
        // 2^72 d, below 2^105 (d below 2^33).
        let step = |d: i64| {
            self.round(i128::from(d) << 72)
                .filter(|q| q.unsigned_abs() < 1 << 61)
                .and_then(|q| i64::try_from(q).ok())
        };
        let mut steps = [[0; 2]; 2];
        for k in 0..2 {
            // w_(k+1) = (a - c) x (b - c) with a = p_(k+2), b = p_k.
            let (a, b) = (p[(k + 2) % 3], p[k]);
            steps[0][k] = step(a.1 - b.1)?;
            steps[1][k] = step(b.0 - a.0)?;
        }
        Some(steps)
    }
}

/// How many columns a span's first pixel may lie from the one of the
/// span a row above for its values to be stepped to from there by adds;
/// farther, by one product per attribute ([`SpanStarts::step_by`]).
const STEPPED_COLUMNS: u32 = 8;

/// The values of `N` attributes at the first pixel of each span, for
/// spans given top to bottom, in 32.32 fixed point with the `1/2` of
/// their rounding (what [`Ramp`] and the depth test step from): divided
/// for at a triangle's first span, then stepped from one span's first
/// pixel to the next one's, a row down and any number of columns across
/// (by adds up to [`STEPPED_COLUMNS`], farther by a product), with no
/// division and no product of coordinates.
///
/// Each attribute is carried as `2^44 (a(p) - a_0) + 2^11` at the last
/// span's first pixel `p` (its offset from vertex 0's value, in 20.44
/// fixed point, with the `1/2` of the rounding to 32.32 folded in): the
/// value handed out is `2^32 a_0 + 2^31` plus its top 52 bits. A row down
/// and `dx` columns across adds the attribute's row step plus `dx` times
/// its column step, each `da_1 s_1 + da_2 s_2` for the steps `s_k` of
/// `L_k` ([`Frame::lambda_steps_by_division`]), rounded to `2^-44`
/// ([`Linear::offset`]): off by less than `2 * 65535 * 2^-61 + 2^-45 <
/// 2^-43` a unit step. From a division on, the first pixels of a
/// triangle's (whole, uncut) spans go down at most `2^20` rows and, the
/// left side of a triangle being convex, at most `2^21` columns across
/// (its box is at most `2^20` px wide), so the carried value is within
/// `3 * 2^20 * 2^-43 + 2^-43 < 2^-20` of exact; the value handed out,
/// its floor at `2^-32`, within `2^-20 + 2^-33` (module docs: the error
/// bound).
///
/// Sizes: at a lit pixel the carried value is below `2^60 + 2^24` in
/// magnitude (`|a(p) - a_0| <= 65535`); steps are taken only when the
/// row step is within `2^60` and the column step within `2^57`, so a
/// move of up to [`STEPPED_COLUMNS`] adds less than `2^61` and every sum
/// stays below `2^62`; a farther move is one product, checked (it ends
/// at a lit pixel, so it stays in range, but that is not assumed). That
/// test is made for a group of attributes at once, and a group whose
/// steps fail it is divided for at every span: a Gouraud triangle's
/// colours and its depth are two groups (`SPLIT`),
/// so that each gets the values it gets without the other.
///
/// On a Cortex-M4 this replaced `L_1, L_2` stepped exactly (a quotient and
/// a remainder each, a row step and up to eight column steps a span) and
/// the three start values made from them by eight 32 by 32-bit products:
/// about 230 instructions a span (`.ci/itrace`).
#[derive(Debug)]
pub(crate) struct SpanStarts<'a, const N: usize, const SPLIT: usize> {
    frame: &'a Frame,
    linear: &'a Linear<N>,
    /// The last span's first pixel.
    last: Option<(i32, i32)>,
    /// `2^44 (a(p) - a_0) + 2^11` there.
    offset: [i64; N],
    /// The attributes' steps, set up at the first step.
    steps: Steps<N>,
}

/// The steps of [`SpanStarts`], set up when first needed.
#[derive(Debug, Clone, Copy)]
enum Steps<const N: usize> {
    /// Not set up yet.
    Unset,
    /// A row down and a column left, none or a column right (`down`),
    /// and a column right and left, in 20.44 fixed point; 0 for the
    /// attributes of a group whose steps are too large, which are
    /// `divided` for at every span instead.
    Set {
        down: [[i64; N]; 3],
        right: [i64; N],
        left: [i64; N],
        divided: [bool; N],
    },
    /// A step is too large (a sliver): every span's first pixel is divided
    /// for.
    None,
}

impl<'a, const N: usize, const SPLIT: usize> SpanStarts<'a, N, SPLIT> {
    /// The starts of the spans of the triangle `frame` whose attributes
    /// are `linear`, in two groups, `..SPLIT` and `SPLIT..` (one group for
    /// `SPLIT = N`).
    pub(crate) fn new(frame: &'a Frame, linear: &'a Linear<N>) -> Self {
        Self {
            frame,
            linear,
            last: None,
            offset: [0; N],
            steps: Steps::Unset,
        }
    }

    /// The 32.32 values, plus `1/2`, at pixel `(x, y)`: the first pixel of
    /// the next span, a lit pixel.
    #[inline]
    pub(crate) fn at(&mut self, x: i32, y: i32) -> [i64; N] {
        self.move_to(x, y);
        // At a lit pixel the offset's top 52 bits are within 2^-20 of
        // a(p) - a_0, below 2^16 + 1 units: the sum is far inside `i64`.
        core::array::from_fn(|n| self.linear.base[n] + (self.offset[n] >> 12))
    }

    /// Moves to pixel `(x, y)`, by a step from the last span's first pixel
    /// when it lies a row above, else by division; `true` if it stepped.
    #[inline(always)]
    fn move_to(&mut self, x: i32, y: i32) -> bool {
        // Divided for at the rows `shaded_spans` starts from.
        let dx = match self.last {
            Some((lx, ly)) if ly.checked_add(1) == Some(y) && y & (DIVIDED_ROWS - 1) != 0 => {
                x.checked_sub(lx)
            }
            _ => None,
        };
        let stepped = match dx {
            Some(dx) => self.step_by(dx, x, y),
            None => false,
        };
        if !stepped {
            self.divide_at(x, y, [true; N]);
        }
        self.last = Some((x, y));
        stepped
    }

    /// The offsets at `(x, y)` of the attributes `which`, from `L_1, L_2`
    /// found by division.
    #[inline(never)]
    fn divide_at(&mut self, x: i32, y: i32, which: [bool; N]) {
        let l = self.frame.lambdas_at(x, y);
        let fresh = self.linear.offset(l);
        for ((o, fresh), which) in self.offset.iter_mut().zip(fresh).zip(which) {
            if which {
                // Below 2^60 + 2^47 for `l` in `[0, 2^60]` (`Linear::offset`).
                *o = fresh + (1 << 11);
            }
        }
    }

    /// Steps a row down and `dx` columns across, to `(x, y)`; `false` if
    /// the triangle's steps are too large, or a move of more than
    /// [`STEPPED_COLUMNS`] leaves `i64` (it does not between two lit
    /// pixels, but it is checked, not assumed).
    #[inline(always)]
    fn step_by(&mut self, dx: i32, x: i32, y: i32) -> bool {
        if let Steps::Unset = self.steps {
            self.set_up_steps();
        }
        let Steps::Set {
            down,
            right,
            left,
            divided,
        } = &self.steps
        else {
            return false;
        };
        let (first, column) = match dx {
            ..0 => (&down[0], left),
            0 => (&down[1], right),
            1.. => (&down[2], right),
        };
        let columns = dx.unsigned_abs();
        if columns > STEPPED_COLUMNS {
            // The diagonal step and `|dx| - 1` column steps more, as one
            // product each: the same sum as that many adds, exactly.
            let more = i64::from(columns - 1);
            let mut moved = self.offset;
            for ((o, diagonal), step) in moved.iter_mut().zip(first).zip(column) {
                let sum = step
                    .checked_mul(more)
                    .and_then(|m| m.checked_add(*diagonal))
                    .and_then(|m| o.checked_add(m));
                match sum {
                    Some(sum) => *o = sum,
                    None => return false,
                }
            }
            self.offset = moved;
        } else {
            // |o| < 2^60 + 2^24 at the last lit pixel, |row| <= 2^60 and
            // |dx| column steps at most 8 2^57 (struct docs): below 2^62
            // all the way.
            for (o, step) in self.offset.iter_mut().zip(first) {
                *o += step;
            }
            // Adds, not a product: on ARMv6-M a 64-bit product is a
            // library call, and the first pixels of a triangle's spans
            // mostly move by a column or none, which the diagonal steps of
            // `down` take at once.
            for _ in 1..columns {
                for (o, step) in self.offset.iter_mut().zip(column) {
                    *o += step;
                }
            }
        }
        // A group whose steps are too large (stepped by 0 above); none
        // with one group.
        let divided = *divided;
        if SPLIT < N && divided.contains(&true) {
            self.divide_at(x, y, divided);
        }
        true
    }

    /// Sets up the attributes' steps ([`Steps`]), or none if they are
    /// outside the bounds of the struct's docs. Written in place: returned,
    /// the steps were copied by `memcpy` on a Cortex-M4.
    #[inline(never)]
    fn set_up_steps(&mut self) {
        self.steps = Steps::None;
        let Some([mut column, mut row]) = self.linear.moves else {
            return;
        };
        // Each group's steps within 2^57 and 2^60, or the group divided
        // for (an empty group is not stepped).
        let stepped = |group: core::ops::Range<usize>| {
            !group.is_empty()
                && group.clone().all(|n| {
                    column[n].unsigned_abs() <= 1 << 57 && row[n].unsigned_abs() <= 1 << 60
                })
        };
        let (first, second) = (stepped(0..SPLIT), stepped(SPLIT..N));
        if !first && !second {
            return;
        }
        let divided: [bool; N] = core::array::from_fn(|n| match n < SPLIT {
            true => !first,
            false => !second,
        });
        for n in 0..N {
            if divided[n] {
                (column[n], row[n]) = (0, 0);
            }
        }
        // Within 2^57 and 2^60: the negation and sums are exact.
        let left = column.map(|c| -c);
        let diagonal = |column: &[i64; N]| core::array::from_fn(|n| row[n] + column[n]);
        self.steps = Steps::Set {
            down: [diagonal(&left), row, diagonal(&column)],
            right: column,
            left,
            divided,
        };
    }
}

/// `N` attributes linear over a triangle, with their per-pixel steps.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Linear<const N: usize> {
    /// `2^32 a_0 + 2^31`: the value at vertex 0 in 32.32, with the `1/2`
    /// of the rounding ([`SpanStarts::at`]).
    base: [i64; N],
    /// `a_1 - a_0`, `a_2 - a_0` (values in `0..=65535`): in `i32`, so that
    /// [`offset`](Self::offset) multiplies 32 by 32 bits.
    da: [[i32; N]; 2],
    /// The step a pixel right in 32.32 fixed point.
    step: [i64; N],
    /// The steps a column right and a row down in 20.44, `[column, row]`,
    /// made from the frame's steps of `L_1, L_2` ([`Linear::offset`]), if
    /// it has them.
    moves: Option<[[i64; N]; 2]>,
}

impl<const N: usize> Linear<N> {
    #[inline]
    pub(crate) fn new(frame: &Frame, values: [[i64; N]; 3]) -> Self {
        let p = &frame.p;
        let mut base = [0; N];
        let mut da = [[0; N]; 2];
        for n in 0..N {
            let a = [values[0][n], values[1][n], values[2][n]];
            // Values in 0..=65535 (`u8` channels, `u16` depths): every
            // difference, product and sum here fits `i64`, the differences
            // `i32`.
            base[n] = (a[0] << 32) + HALF;
            da[0][n] = i32::try_from(a[1] - a[0]).unwrap_or_default();
            da[1][n] = i32::try_from(a[2] - a[0]).unwrap_or_default();
        }
        let mut linear = Self {
            base,
            da,
            step: [0; N],
            moves: None,
        };
        linear.moves = frame
            .lambda_steps
            .map(|[column, row]| [linear.offset(column), linear.offset(row)]);
        for n in 0..N {
            let d = match linear.moves {
                // Rounded from 20.44 (below 2^62 + 2^32 in magnitude):
                // within 2^-33 + 2^-43 of exact (module docs).
                Some([column, _]) => Some((column[n] + (1 << 11)) >> 12),
                None => {
                    let a = [values[0][n], values[1][n], values[2][n]];
                    // d w_k / dx per pixel: 4096 (y_(k+1) - y_(k+2)); the
                    // raw `y` differences are below 2^33, so the sum is
                    // below 3 2^49.
                    let num: i64 = (0..3)
                        .map(|k| a[k] * (p[(k + 1) % 3].1 - p[(k + 2) % 3].1))
                        .sum();
                    frame
                        .round(i128::from(num) << 44)
                        .and_then(|d| i64::try_from(d).ok())
                }
            };
            // A step over `2^48` (65536 units per pixel) cannot occur on a
            // span of two or more pixels (module docs): it is never used,
            // and is stored as 0 so that every sum below stays far inside
            // `i64`.
            linear.step[n] = d.filter(|d| d.unsigned_abs() <= 1 << 48).unwrap_or(0);
        }
        linear
    }

    /// `da_1 l_1 + da_2 l_2` for `l` in `2^-60` units, in `2^-44` units
    /// rounded (halves up): `floor((da_1 l_1 + da_2 l_2 + 2^15) / 2^16)`.
    /// For a lit pixel's `L_1, L_2` (in `[0, 2^60]`) it is `2^44 (a(p) -
    /// a_0)` within `2 * 65535 * 2^-61 + 2^-45 < 2^-43` units; for the
    /// steps of `L_1, L_2` (`|l| < 2^61`) the step of `2^44 a`.
    ///
    /// In `i64`, exactly, with each `l = 2^30 h + b` (`0 <= b < 2^30`, and
    /// `-2^31 <= h < 2^31` for `|l| < 2^61`; for another `l`, `h` is taken as
    /// 0): the products of the `h` are whole multiples of `2^16`, so the
    /// quotient is `2^14 (da_1 h_1 + da_2 h_2)` plus that of the `b`
    /// terms. Every product is of two `i32` (one multiplication on a
    /// Cortex-M4) and below `2^47` in magnitude (`|da| <= 65535`), `2^14
    /// (da_1 h_1 + da_2 h_2)` at most `2^62`, and the result below `2^62
    /// + 2^32`: no overflow for any `l`.
    fn offset(&self, l: [i64; 2]) -> [i64; N] {
        core::array::from_fn(|n| blend_offset([self.da[0][n], self.da[1][n]], l))
    }
}

/// One attribute's [`Linear::offset`], for its differences `[a_1 - a_0,
/// a_2 - a_0]`. Taken only where a span's start is divided for and where
/// the steps are set up, a few times a triangle: out of line in builds
/// for size. Out of line at opt-level 3 as well, the firmware of
/// `.ci/codesize` was 2.2 KB smaller on a Cortex-M4, but `.ci/itrace`'s
/// 16 px Gouraud triangle took 4 % more instructions (8,814 → 9,168).
#[cfg_attr(optimize_for_size, inline(never))]
fn blend_offset([d1, d2]: [i32; 2], l: [i64; 2]) -> i64 {
    let split = |l: i64| {
        (
            i32::try_from(l >> 30).unwrap_or(0),
            // Below 2^30: the cast is exact.
            (l & ((1 << 30) - 1)) as i32,
        )
    };
    let ((h1, b1), (h2, b2)) = (split(l[0]), split(l[1]));
    // On ARMv6-M a library call each, as they stay: with the 16-bit
    // quarters of `raster::wide::product_u32` in their place, the Gouraud
    // window of `.ci/itrace` took 507 instructions fewer (when every span's
    // start took these products), but the compiler then laid out the band
    // loop of `.ci/icount`'s scene otherwise (bands of 16 rows 1.0 %
    // slower).
    let product = |a: i32, b: i32| i64::from(a) * i64::from(b);
    let high = product(d1, h1) + product(d2, h2);
    let low = product(d1, b1) + product(d2, b2);
    high * (1 << 14) + ((low + (1 << 15)) >> 16)
}

impl<const N: usize> Linear<N> {
    /// Attribute `n`'s 32.32 `value` at a span's pixel, moved `pixels`
    /// pixels right along the span: exactly the value that many single
    /// steps reach. A move of 1 or more is inside a span of two or more
    /// pixels, whose ends both lie within `2^-12` of `0..=65535`, so the
    /// product is at most about `65536 * 2^32 < 2^49`: no overflow.
    #[inline(always)]
    pub(crate) fn advanced(&self, value: i64, n: usize, pixels: u32) -> i64 {
        // No product for the common move of none (a span not cut on the
        // left): a library call on ARMv6-M, three instructions on a
        // Cortex-M4.
        match pixels {
            0 => value,
            _ => value + self.step[n] * i64::from(pixels),
        }
    }
}

impl Linear<3> {
    /// These three attributes followed by the depth `z`: a Gouraud
    /// triangle with depth takes its span starts for both at once, from
    /// one set of divisions ([`SpanStarts`]).
    pub(crate) fn and_depth(&self, z: &Linear<1>) -> Linear<4> {
        let [b0, b1, b2] = self.base;
        let [[d0, d1, d2], [e0, e1, e2]] = self.da;
        let [s0, s1, s2] = self.step;
        // Both from the same frame: both or neither have moves.
        let moves = match (self.moves, z.moves) {
            (Some([[c0, c1, c2], [r0, r1, r2]]), Some([[zc], [zr]])) => {
                Some([[c0, c1, c2, zc], [r0, r1, r2, zr]])
            }
            _ => None,
        };
        Linear {
            base: [b0, b1, b2, z.base[0]],
            da: [[d0, d1, d2, z.da[0][0]], [e0, e1, e2, z.da[1][0]]],
            step: [s0, s1, s2, z.step[0]],
            moves,
        }
    }
}

/// The integer part of a carried 32.32 value, which holds the `1/2` of
/// its rounding ([`SpanStarts::at`]): the attribute rounded. Folding the `1/2`
/// in once a span saved an add with carry per channel and pixel (on a
/// Cortex-M4, two instructions each). The values carried are below `2^49 +
/// 2^31` in magnitude (module docs: within `2^-12` of `0..=65535` at lit
/// pixels, plus at most one step of at most `2^48` past the last one).
#[inline(always)]
fn whole(v: i64) -> i64 {
    v >> 32
}

/// The colours of a span's pixels, stepped in 32.32 fixed point: the
/// iterator a Gouraud span hands to [`DrawTarget::fill_contiguous`].
#[derive(Debug, Clone)]
struct Ramp<C> {
    value: Carried,
    /// The triangle's step a pixel right, in the same form.
    step: Carried,
    left: u32,
    color: PhantomData<C>,
}

impl<C: ShadeColor> Iterator for Ramp<C> {
    type Item = C;

    #[inline(always)]
    fn next(&mut self) -> Option<C> {
        if self.left == 0 {
            return None;
        }
        self.left -= 1;
        Some(self.value.color_then_advance::<C>(&self.step))
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let n = self.left as usize;
        (n, Some(n))
    }
}

/// How [`Ramp`] carries a span's channel values: packed integer parts
/// and 32-bit fractions on 32-bit targets ([`PackedChannels`]), three 64-bit
/// integers on 64-bit ones and in builds for size ([`Channels64`]). The same
/// colours either way (the unit test
/// `packed_channels_step_as_64_bit_values`).
#[cfg(not(all(target_pointer_width = "32", not(optimize_for_size))))]
type Carried = Channels64;
#[cfg(all(target_pointer_width = "32", not(optimize_for_size)))]
type Carried = PackedChannels;

/// A colour's channel values (or their step) in 32.32 fixed point, each an
/// `i64`, stepped by three 64-bit adds: what [`Ramp`] carries on 64-bit
/// targets and in builds for size ([`Carried`]). [`PackedChannels`] took more
/// there: on x86-64, 1.6x the instructions on large random triangles
/// (callgrind, a 200 px Gouraud triangle 196,787 → 311,771; 16 px ones,
/// mostly span starts, 7,984 → 7,336) and up to twice the time (`cargo
/// bench --bench shading`, 240 px 12.7 → 26.2 us, on a loaded machine),
/// and at opt-level "s", where the
/// compiler keeps its per-channel loops as loops and its layout as a table in
/// memory, the Cortex-M4's 64 px Gouraud triangles (`.ci/icount`) took 1.75x
/// the instructions.
// One of `Channels64` and `PackedChannels` is unused on each target
// (`Carried`).
#[allow(dead_code)]
#[derive(Debug, Clone, Copy)]
struct Channels64([i64; 3]);

// The signatures of `PackedChannels`'s, which needs the colour's layout; one
// of the two is unused on each target (`Carried`).
#[allow(clippy::extra_unused_type_parameters, dead_code)]
impl Channels64 {
    /// No step: what a setup holds until its step is read (`GouraudSetup`).
    const ZERO: Self = Self([0; 3]);

    /// Values `v` at a lit pixel, with the `1/2` of their rounding.
    #[inline(always)]
    fn value<C: ShadeColor>(v: [i64; 3]) -> Self {
        Self(v)
    }

    /// The per-pixel steps `d` ([`Linear`]'s).
    fn step<C: ShadeColor>(d: [i64; 3]) -> Self {
        Self(d)
    }

    /// The colour: each channel's integer part. Then adds `step`.
    #[inline(always)]
    fn color_then_advance<C: ShadeColor>(&mut self, step: &Self) -> C {
        let mut ch = [0u8; 3];
        let steps = ch.iter_mut().zip(&mut self.0).zip(&step.0);
        for ((c, v), d) in steps.take(C::CHANNELS) {
            // In 0..=channel max by the module's bound: the cast is exact.
            *c = whole(*v) as u8;
            // |v| < 2^48 + 1 and |d| <= 2^48 (`Linear::new`): no overflow.
            *v += *d;
        }
        C::from_channels(ch)
    }
}

/// A colour's channel values (or their step) in 32.32 fixed point, as
/// each value's integer part and fraction (`2^-32` units, its two
/// halves), with the integer parts packed into one `i32`, each channel in
/// a field of its own width (`whole = sum_c whole_c << shift_c`,
/// [`layout`]): what [`Ramp`] carries on 32-bit targets ([`Carried`]).
///
/// A step adds the fractions, and adds the packed integer parts of the
/// step and each fraction's carry at its channel's field: the integer
/// parts of three 64-bit adds, exactly. These are sums of integers, not of
/// fields apart, so they hold whatever the signs; and at every lit pixel
/// each integer part lies in `0..=MAX` (module docs), inside its field,
/// so the packed value unpacks into exactly the channels of the 64-bit
/// adds. The colours' raw values are packed the same way, since
/// [`ShadeColor`] gives the channels in the order of the raw bits
/// (`Rgb565` 5/6/5 bits red highest, `Bgr565` blue highest, `Rgb888`
/// 8/8/8, the greys' and `BinaryColor`'s single channel), and the
/// compiler folds the unpacking and the colour's own packing into one
/// mask. With a BGR colour's channels red first, a `Bgr565` pixel took
/// about 5 instructions more on a Cortex-M4 to move its fields (the 16 px
/// triangle Gouraud-shaded, `.ci/itrace` with a `Bgr565` window added:
/// 9,551 instructions against `Rgb565`'s 9,057; now 9,037).
///
/// On a Cortex-M4 a pixel took 22 instructions as three `i64`, 5 of them
/// loads of steps that did not fit the registers, and takes 17: three
/// adds for the fractions, each carry folded into the packed value by an
/// add with carry or a conditional add, and one halfword store of the
/// packed value itself (the `Rgb565` colour). Gouraud triangles through
/// `draw` (`.ci/icount`), 16 px and 64 px: Cortex-M4 10,903 → 10,278
/// and 59,172 → 50,651 instructions each, ARMv6-M 29,023 → 28,219 and
/// 132,323 → 123,570, RISC-V 14,746 → 14,106 and 78,760 → 72,488. The
/// flash of a firmware that shades (`.ci/codesize_shading`, opt-level 3)
/// grew 1.5 KB (Cortex-M4 27,088 → 28,612 bytes); builds for size keep
/// [`Channels64`], and their size. On i686, whose seven registers do not hold
/// it, long spans cost more (callgrind, instructions a Gouraud triangle
/// against [`Channels64`]: 16 px 14,125 → 12,657, 64 px 62,738 → 63,670, 200
/// px 290,944 → 421,627); it is kept there all the same, as the 32-bit
/// host whose tests run the 32-bit cores' code.
// One of `Channels64` and `PackedChannels` is unused on each target
// (`Carried`).
#[allow(dead_code)]
#[derive(Debug, Clone, Copy)]
struct PackedChannels {
    whole: i32,
    fraction: [u32; 3],
}

// One of `Channels64` and `PackedChannels` is unused on each target
// (`Carried`).
#[allow(dead_code)]
impl PackedChannels {
    /// No step: what a setup holds until its step is read (`GouraudSetup`).
    const ZERO: Self = Self {
        whole: 0,
        fraction: [0; 3],
    };

    /// Values `v` at a lit pixel, with the `1/2` of their rounding: each
    /// integer part in `0..=MAX` (module docs), below `2^8`.
    #[inline(always)]
    fn value<C: ShadeColor>(v: [i64; 3]) -> Self {
        let (shift, _) = const { layout(C::MAX) };
        let mut whole = 0;
        let mut fraction = [0; 3];
        for c in 0..C::CHANNELS {
            whole += ((v[c] >> 32) as i32) << shift[c];
            fraction[c] = (v[c] & i64::from(u32::MAX)) as u32;
        }
        Self { whole, fraction }
    }

    /// The per-pixel steps `d` ([`Linear`]'s). A step moves between the
    /// values of two lit pixels of a span, each in `0..=MAX` before
    /// rounding (module docs), so its integer part lies in `-255..=255`
    /// where it is used, and the packed one below `2^25` in magnitude. A
    /// triangle with a larger step has no span of two pixels, and its step
    /// never leads to a pixel (only past a span's last one): it is taken
    /// as 0, so that no sum leaves `i32`.
    fn step<C: ShadeColor>(d: [i64; 3]) -> Self {
        let (shift, _) = const { layout(C::MAX) };
        let mut whole = 0;
        let mut fraction = [0; 3];
        for c in 0..C::CHANNELS {
            match i32::try_from(d[c] >> 32) {
                Ok(w) if w.abs() <= 255 => whole += w << shift[c],
                _ => {
                    return Self {
                        whole: 0,
                        fraction: [0; 3],
                    }
                }
            }
            fraction[c] = (d[c] & i64::from(u32::MAX)) as u32;
        }
        Self { whole, fraction }
    }

    /// The colour: each channel's field. Then adds `step`.
    #[inline(always)]
    fn color_then_advance<C: ShadeColor>(&mut self, step: &Self) -> C {
        let (shift, mask) = const { layout(C::MAX) };
        let whole = self.whole;
        // Each field holds its channel's integer part, in 0..=MAX (see
        // above): the masked value fits `u8`.
        let color = C::from_channels(core::array::from_fn(|c| {
            ((whole >> shift[c]) & mask[c]) as u8
        }));
        // |whole| < 2^24, |step.whole| < 2^25 and the carries below 2^17:
        // no overflow.
        let mut whole = whole + step.whole;
        let fractions = self.fraction.iter_mut().zip(step.fraction).zip(shift);
        for ((f, d), shift) in fractions.take(C::CHANNELS) {
            // The low halves of 64-bit adds: each carry goes to its field.
            let (sum, carry) = f.overflowing_add(d);
            *f = sum;
            whole += i32::from(carry) << shift;
        }
        self.whole = whole;
        color
    }
}

/// Where each channel of a colour with channel maxima `max` lies in
/// [`PackedChannels`]'s integer parts: its shift, and the mask of its field
/// (as wide as its largest value), the first channel in the highest bits; 24
/// bits at most.
const fn layout(max: [u8; 3]) -> ([u32; 3], [i32; 3]) {
    let width = [
        u8::BITS - max[0].leading_zeros(),
        u8::BITS - max[1].leading_zeros(),
        u8::BITS - max[2].leading_zeros(),
    ];
    (
        [width[1] + width[2], width[2], 0],
        [
            (1 << width[0]) - 1,
            (1 << width[1]) - 1,
            (1 << width[2]) - 1,
        ],
    )
}

/// Per-triangle Gouraud state over a triangle's [`Frame`]: the three
/// channels.
///
/// The frame is not part of it: each caller keeps the frame where
/// [`Frame::new_in`] made it, borrowed. With the frame inside, a setup
/// built out of line (as in a firmware with LTO and one codegen unit, or
/// with two colour types) copied the frame up to four times by `memcpy`
/// on a Cortex-M4.
#[derive(Debug, Clone, Copy)]
pub(crate) struct GouraudSetup<C> {
    linear: Linear<3>,
    /// The linear step a pixel right, as [`Ramp`] carries it.
    step: Carried,
    color: PhantomData<C>,
}

impl<C: ShadeColor> GouraudSetup<C> {
    fn new(frame: &Frame, colors: &[C; 3]) -> Self {
        let values = colors.map(|c| c.channels().map(i64::from));
        // The channels made where they stay, and the step read from there:
        // made apart and moved in, they were copied by `memcpy` (128
        // bytes) in a firmware with two colour types on a Cortex-M4.
        let mut setup = Self {
            linear: Linear::new(frame, values),
            step: Carried::ZERO,
            color: PhantomData,
        };
        setup.step = Carried::step::<C>(setup.linear.step);
        setup
    }

    /// The colours of `len` pixels starting `offset` pixels into a span
    /// whose first pixel has the values `start` ([`SpanStarts::at`]).
    fn ramp(&self, start: [i64; 3], offset: u32, len: u32) -> Ramp<C> {
        let v = core::array::from_fn(|k| self.linear.advanced(start[k], k, offset));
        Ramp {
            value: Carried::value::<C>(v),
            step: self.step,
            left: len,
            color: PhantomData,
        }
    }
}

impl Triangle {
    /// Styles the triangle with one colour per vertex, blended across it
    /// (Gouraud shading), ready to draw.
    ///
    /// Any colours and any triangle in the 20.12 range: each channel is
    /// interpolated in its own range ([`ShadeColor`]) to within 1 unit of
    /// the exact value and never outside the vertices' values (module
    /// docs: the error bound and the sizes of the intermediates).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Rgb888, RgbColor};
    /// use embedded_raster::Triangle;
    ///
    /// let shaded = Triangle::default().gouraud([Rgb888::RED, Rgb888::GREEN, Rgb888::BLUE]);
    /// assert_eq!(shaded.colors[1], Rgb888::GREEN);
    /// ```
    pub const fn gouraud<C: ShadeColor>(self, colors: [C; 3]) -> GouraudTriangle<C> {
        GouraudTriangle {
            triangle: self,
            colors,
        }
    }
}

/// A [`Triangle`] with a colour per vertex (in the order of
/// [`Triangle::vertices`]): a [`Drawable`] that lights the same pixels as
/// the flat triangle and gives each the barycentric blend of the vertex
/// colours at its centre, per channel in the colour's own range (5/6/5 bits
/// for `Rgb565`), within 1 unit of the exact value (see the module source
/// for the proof). Each span goes to the target as one
/// [`fill_contiguous`](DrawTarget::fill_contiguous) call.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
/// use embedded_raster::{framebuffer::{buffer_size, Framebuffer, Rgb565Le}, Triangle};
///
/// let mut fb = Framebuffer::<Rgb565Le, 16, 16, { buffer_size::<Rgb565Le>(16, 16) }>::new();
/// // Corners on pixel centres: those pixels get exactly the vertex colours.
/// let t = Triangle::from_points(Point::new(0, 0), Point::new(15, 0), Point::new(0, 15)).unwrap();
/// t.gouraud([Rgb565::RED, Rgb565::GREEN, Rgb565::BLUE]).draw(&mut fb)?;
/// assert_eq!(fb.pixel(Point::new(0, 0)), Some(Rgb565::RED));
/// assert_eq!(fb.pixel(Point::new(14, 0)), Some(Rgb565::new(2, 59, 0)));
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct GouraudTriangle<C> {
    /// The shape.
    pub triangle: Triangle,
    /// The colour at each vertex.
    pub colors: [C; 3],
}

impl<C: ShadeColor> GouraudTriangle<C> {
    /// The same triangle filled with one colour, the rounded per-channel
    /// average of the vertex colours ([`average_color`]).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Gray8;
    /// use embedded_raster::Triangle;
    ///
    /// let t = Triangle::default().gouraud([Gray8::new(0), Gray8::new(1), Gray8::new(1)]);
    /// assert_eq!(t.flat().color, Gray8::new(1)); // 2/3 rounds to 1
    /// ```
    pub fn flat(&self) -> FilledTriangle<C> {
        self.triangle.fill(average_color(self.colors))
    }

    /// Calls `f` with each lit span and the colours of its pixels, left to
    /// right: the spans of [`Triangle::for_each_span`] inside `clip`.
    ///
    /// # Examples
    ///
    /// ```
    /// use core::convert::Infallible;
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*, primitives::Rectangle};
    /// use embedded_raster::{Triangle, Vertex};
    ///
    /// let v = |x: f32, y: f32| Vertex::try_from_num(x, y).unwrap();
    /// // A ramp from 0 at x = 0.5 to 100 at x = 10.5, the same on every row.
    /// let t = Triangle::new(v(0.5, -100.0), v(10.5, 0.0), v(0.5, 100.0))
    ///     .gouraud([Gray8::new(0), Gray8::new(100), Gray8::new(0)]);
    /// let clip = Rectangle::new(Point::new(0, 0), Size::new(20, 1));
    /// let mut row = [0u8; 10];
    /// t.for_each_span(&clip, |span, colors| {
    ///     for (x, c) in (span.x_start..).zip(colors) {
    ///         row[x as usize] = c.luma();
    ///     }
    ///     Ok::<(), Infallible>(())
    /// })
    /// .unwrap();
    /// assert_eq!(row, [0, 10, 20, 30, 40, 50, 60, 70, 80, 90]);
    /// ```
    pub fn for_each_span<E>(
        &self,
        clip: &embedded_graphics_core::primitives::Rectangle,
        mut f: impl FnMut(Span, &mut dyn Iterator<Item = C>) -> Result<(), E>,
    ) -> Result<(), E> {
        let mut slot = None;
        let Some(frame) = Frame::new_in(&mut slot, &self.triangle) else {
            return Ok(());
        };
        let setup = GouraudSetup::new(frame, &self.colors);
        let mut starts = SpanStarts::<3, 3>::new(frame, &setup.linear);
        // Every row's values start at its whole span (`shaded_spans`).
        let window = Window::of(clip);
        shaded_spans(&self.triangle, clip, &mut |whole| {
            let start = starts.at(whole.x_start, whole.y);
            let visible = window.visible(whole);
            match visible.is_empty() {
                true => Ok(()),
                false => f(
                    visible,
                    &mut setup.ramp(start, offset(whole, visible), visible.len()),
                ),
            }
        })
    }
}

/// Calls `f` with the whole span of each row of `triangle` that
/// [`SpanStarts`] must see for the rows inside `clip`: not cut by any
/// clip, where the row's values start, from the last row at or above the
/// clip's top that [`SpanStarts`] divides at ([`DIVIDED_ROWS`]) down to
/// the clip's bottom. The caller draws the part inside the clip
/// ([`Window::visible`], empty for a row above the clip or beside it)
/// from its offset into the whole span ([`GouraudSetup::ramp`]). So the
/// span starts are found at the same pixels along the same path whatever
/// the clip, and each pixel's value is the same as in the triangle drawn
/// under any other clip: a frame drawn in bands, or in windows, is the
/// frame drawn whole, byte for byte (a start stepped to and one divided
/// for, or one found at another pixel, may round apart within `2^-12` of
/// a half).
///
/// Nothing is walked for a triangle whose columns miss the clip's.
///
/// Through one copy of the triangle walk for every kind of shading (one
/// per error type), not one per caller's closure: a shaded span costs far
/// more than the call through the `dyn` reference, while each copy of the
/// walk (`triangle_spans` and its rows' loops) took about 2.2 KB of flash
/// on a Cortex-M4.
#[inline(never)]
pub(crate) fn shaded_spans<E>(
    triangle: &Triangle,
    clip: &embedded_graphics_core::primitives::Rectangle,
    f: &mut dyn FnMut(Span) -> Result<(), E>,
) -> Result<(), E> {
    use embedded_graphics_core::{
        geometry::{Point, Size},
        primitives::Rectangle,
    };
    if clip.is_zero_sized() {
        return Ok(());
    }
    // The columns any lit pixel of the triangle can have: centres `4096 i
    // + 2048` within its corners' `x`, with a column to spare each side.
    // Raw coordinates are `i32`, so these lie within +-2^19 + 2.
    let xs = triangle.vertices.map(|v| v.raw().0);
    let (Some(low), Some(high)) = (xs.into_iter().min(), xs.into_iter().max()) else {
        return Ok(());
    };
    let (left, right) = ((low >> 12) - 1, (high >> 12) + 2);
    let window = Window::of(clip);
    if window.right <= left || window.left >= right {
        return Ok(());
    }
    let top = clip.top_left.y;
    // At most `DIVIDED_ROWS - 1` rows above `top`: no overflow.
    let from = top & !(DIVIDED_ROWS - 1);
    let lead = (top - from).unsigned_abs();
    let size = Size::new(
        (right - left).unsigned_abs(),
        clip.size.height.saturating_add(lead),
    );
    triangle.for_each_span(&Rectangle::new(Point::new(left, from), size), f)
}

/// The rows and columns of a clip, as the callers of [`shaded_spans`]
/// cut each whole span to it.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Window {
    top: i32,
    left: i32,
    /// The column after the last, at most `i32::MAX` (every span ends
    /// there or before).
    right: i32,
}

impl Window {
    /// `clip`'s window.
    #[inline(always)]
    pub(crate) fn of(clip: &embedded_graphics_core::primitives::Rectangle) -> Self {
        let left = clip.top_left.x;
        // Clamped into `i32`: the cast is exact. (Through `clip::Bounds`,
        // whose `of` is not inlined at opt-level "s", shading took 100
        // bytes more flash on a Cortex-M4.)
        let right = (i64::from(left) + i64::from(clip.size.width)).min(i64::from(i32::MAX)) as i32;
        Self {
            top: clip.top_left.y,
            left,
            right,
        }
    }

    /// The part of the row's `whole` span (from [`shaded_spans`]) inside
    /// the window, starting at or after its first pixel: empty above the
    /// window's top or beside it (its rows end at the clip's bottom).
    #[inline(always)]
    pub(crate) fn visible(&self, whole: Span) -> Span {
        let x_start = self.left.max(whole.x_start);
        let x_end = match whole.y < self.top {
            true => x_start,
            false => self.right.min(whole.x_end).max(x_start),
        };
        Span {
            y: whole.y,
            x_start,
            x_end,
        }
    }
}

/// The rows `y` (multiples of this) at which [`SpanStarts`] divides for
/// the start of a span rather than stepping to it, and from which
/// [`shaded_spans`] walks. A power of two: both find its multiples by a
/// mask.
const DIVIDED_ROWS: i32 = 32;
const _: () = assert!(DIVIDED_ROWS > 0 && DIVIDED_ROWS & (DIVIDED_ROWS - 1) == 0);

/// How many pixels into a row's `whole` span (from [`shaded_spans`]) its
/// `visible` part ([`Window::visible`]) starts.
#[inline(always)]
fn offset(whole: Span, visible: Span) -> u32 {
    visible.x_start.abs_diff(whole.x_start)
}

impl<C: ShadeColor> Drawable for GouraudTriangle<C> {
    type Color = C;
    type Output = ();

    fn draw<D>(&self, target: &mut D) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = C>,
    {
        let mut slot = None;
        let Some(frame) = Frame::new_in(&mut slot, &self.triangle) else {
            return Ok(());
        };
        let setup = GouraudSetup::new(frame, &self.colors);
        let clip = target.bounding_box();
        let mut starts = SpanStarts::<3, 3>::new(frame, &setup.linear);
        // Every row's values start at its whole span (`shaded_spans`).
        let window = Window::of(&clip);
        shaded_spans(&self.triangle, &clip, &mut |whole| {
            let start = starts.at(whole.x_start, whole.y);
            let visible = window.visible(whole);
            match visible.is_empty() {
                true => Ok(()),
                false => target.fill_contiguous(
                    &visible.rect(),
                    setup.ramp(start, offset(whole, visible), visible.len()),
                ),
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use core::convert::Infallible;

    use embedded_graphics_core::{
        geometry::{Point, Size},
        pixelcolor::{BinaryColor, Gray8, Rgb565, Rgb888},
        primitives::Rectangle,
    };

    use super::*;
    use crate::{raster::xorshift, vertex::Vertex};

    /// `L_1, L_2` at the centre of pixel `(x, y)` from their definition,
    /// `round(2^60 w_k / D)` halves up, with the weights as the signed
    /// areas of the sub-triangles and the host's own division.
    fn reference(t: &Triangle, x: i32, y: i32) -> [i128; 2] {
        let p = t.vertices.map(|v| {
            let (x, y) = v.raw();
            (i128::from(x), i128::from(y))
        });
        let c = (i128::from(x) * 4096 + 2048, i128::from(y) * 4096 + 2048);
        let area = |a: (i128, i128), b: (i128, i128), e: (i128, i128)| {
            (b.0 - a.0) * (e.1 - a.1) - (b.1 - a.1) * (e.0 - a.0)
        };
        let d = area(p[0], p[1], p[2]);
        let round = |n: i128| {
            let (n, d) = if d < 0 { (-n, -d) } else { (n, d) };
            (2 * n + d).div_euclid(2 * d)
        };
        // Weight of vertex k: the triangle (c, p_(k+1), p_(k+2)).
        [
            round(area(c, p[2], p[0]) << 60),
            round(area(c, p[0], p[1]) << 60),
        ]
    }

    /// [`Linear::offset`] against its definition in `i128`, for values
    /// across `0..=65535` and coordinates across `-2^61 < l < 2^61` (a
    /// lit pixel's and the steps'), the ends, the `2^30` boundaries of the
    /// split and the `2^16` ones of the rounding among them.
    #[test]
    fn offsets_split_exactly() {
        let mut random = xorshift(0x5EED_0F5A_1157_A2B3);
        let mut next = move || random.next().unwrap_or_default();
        let ends = [
            0i64,
            1,
            (1 << 15) - 1,
            1 << 15,
            (1 << 16) - 1,
            1 << 16,
            (1 << 16) + 1,
            (1 << 30) - 1,
            1 << 30,
            (1 << 30) + 1,
            (1 << 31) - 1,
            1 << 31,
            (1 << 60) - 1,
            1 << 60,
            (1 << 61) - 1,
        ];
        for case in 0..100_000 {
            let a = [0; 3].map(|_| (next() % 65536) as i64);
            let mut coordinate = || {
                let l = match case % 3 {
                    0 => ends[(next() % ends.len() as u64) as usize],
                    _ => (next() % (1 << 61)) as i64,
                };
                if next() % 2 == 0 {
                    -l
                } else {
                    l
                }
            };
            let l = [coordinate(), coordinate()];
            let linear = Linear::<1> {
                base: [0],
                da: [[(a[1] - a[0]) as i32], [(a[2] - a[0]) as i32]],
                step: [0],
                moves: None,
            };
            let wide = |v: i64| i128::from(v);
            let exact =
                (wide(a[1] - a[0]) * wide(l[0]) + wide(a[2] - a[0]) * wide(l[1]) + (1 << 15)) >> 16;
            assert_eq!(i128::from(linear.offset(l)[0]), exact, "{a:?} {l:?}");
        }
    }

    /// Calls `check` with `cases` random triangles of nonzero area from
    /// `seed` ([`random_triangle`], of scales below `scales`, one in four
    /// a sliver), their frames, and the generator for more.
    fn for_random_triangles(
        seed: u64,
        cases: usize,
        scales: u64,
        mut check: impl FnMut(&Triangle, Frame, &mut dyn FnMut() -> u64),
    ) {
        let mut random = xorshift(seed);
        let mut next = move || random.next().unwrap_or_default();
        for case in 0..cases {
            let scale = (next() % scales) as u32;
            let t = random_triangle(&mut next, scale, case % 4 == 0);
            if let Some(frame) = Frame::new_in(&mut None, &t) {
                check(&t, *frame, &mut next);
            }
        }
    }

    /// A random triangle with corners from 1 px to `2^(1 + scale)` px
    /// around a centre (clamped to the 20.12 range), or a sliver (the
    /// third corner near the others' line).
    fn random_triangle(next: &mut impl FnMut() -> u64, scale: u32, sliver: bool) -> Triangle {
        let centre = ((next() % 200) as i32 * 4096, (next() % 200) as i32 * 4096);
        let mut corner = || {
            let span = 1i64 << (12 + scale);
            let offset = |r: u64| (r % (2 * span as u64 + 1)) as i64 - span;
            let x = i64::from(centre.0) + offset(next());
            let y = i64::from(centre.1) + offset(next());
            // Within the 20.12 range.
            let c = |v: i64| v.clamp(i32::MIN.into(), i32::MAX.into()) as i32;
            Vertex::from_raw(c(x), c(y))
        };
        let (a, b) = (corner(), corner());
        let c = match sliver {
            true => {
                let (a, b) = (a.raw(), b.raw());
                let jitter = (next() % 65) as i64 - 32;
                let mid = |u: i32, v: i32, j: i64| {
                    let m = (i64::from(u) + i64::from(v)) / 2 + j;
                    m.clamp(i32::MIN.into(), i32::MAX.into()) as i32
                };
                Vertex::from_raw(mid(a.0, b.0, jitter), mid(a.1, b.1, -jitter))
            }
            false => corner(),
        };
        Triangle::new(a, b, c)
    }

    /// [`Frame::new_in`] fills its slot only for a triangle with area: a
    /// triangle of zero area leaves it empty; another is in it, with its
    /// raw corners and its doubled signed area worked out here by hand.
    #[test]
    fn frames_are_made_in_their_slot() {
        let v = Vertex::from_raw;
        let mut slot = None;
        let line = Triangle::new(v(0, 0), v(8192, 4096), v(16384, 8192));
        assert!(Frame::new_in(&mut slot, &line).is_none());
        assert!(slot.is_none());
        // (b - a) x (c - a) = 12288 * 20480 - 4096 * (-8192).
        let t = Triangle::new(v(4096, 8192), v(16384, 12288), v(4096 - 8192, 8192 + 20480));
        let made = Frame::new_in(&mut slot, &t).map(|f| (f.p, f.area2));
        let corners = [(4096, 8192), (16384, 12288), (-4096, 28672)];
        let area2 = 12288 * 20480 + 4096 * 8192;
        assert_eq!(made, Some((corners, area2)));
        assert_eq!(slot.map(|f| (f.p, f.area2)), Some((corners, area2)));
    }

    /// [`Frame::lambdas_at`] and [`Frame::lambda_steps_by_division`]
    /// against their definitions ([`reference`], and the difference of
    /// the weights a pixel apart divided by the host's own division), and
    /// each attribute's step a pixel right in 32.32 ([`Linear::new`])
    /// against the exact `2^32 4096 sum(a_k (y_(k+1) - y_(k+2))) / D`:
    /// within `2^-33 + 2^-43` (module docs), whether made from the
    /// frame's steps of `L_1, L_2` or, for a triangle that crosses one
    /// row of pixel centres or none, or a sliver, divided for; on random
    /// triangles of every size and slivers, with random values across
    /// `0..=65535`.
    #[test]
    fn steps_match_their_definitions() {
        let (mut steps, mut refused, mut derived) = (0, 0, 0);
        for_random_triangles(0x1A3B_DA55_7E95_2026, 20_000, 21, |t, frame, next| {
            let (x, y) = ((next() % 300) as i32 - 50, (next() % 300) as i32 - 50);
            let here = reference(t, x, y);
            let fit = |v: i128| v.clamp(i64::MIN.into(), i64::MAX.into()) as i64;
            assert_eq!(frame.lambdas_at(x, y), here.map(fit), "{t:?} at ({x}, {y})");
            // The steps: 2^60 times the weights' change a pixel across or
            // down, over D, rounded (halves up).
            let p = t.vertices.map(|v| {
                let (x, y) = v.raw();
                (i128::from(x), i128::from(y))
            });
            let d = (p[1].0 - p[0].0) * (p[2].1 - p[0].1) - (p[1].1 - p[0].1) * (p[2].0 - p[0].0);
            let round = |n: i128| {
                let (n, d) = if d < 0 { (-n, -d) } else { (n, d) };
                (2 * n + d).div_euclid(2 * d)
            };
            // Weight of vertex k + 1: the edge from p_(k+2) to p_k.
            let exact: [[i128; 2]; 2] = [
                [0, 1].map(|k: usize| round((p[(k + 2) % 3].1 - p[k].1) << 72)),
                [0, 1].map(|k: usize| round((p[k].0 - p[(k + 2) % 3].0) << 72)),
            ];
            let within = exact.iter().flatten().all(|s| s.unsigned_abs() < 1 << 61);
            let values = [0; 3].map(|_| [0; 3].map(|_| (next() % 65536) as i64));
            let linear = Linear::new(&frame, values);
            for n in 0..3 {
                let num: i128 = (0..3)
                    .map(|k| i128::from(values[k][n]) * (p[(k + 1) % 3].1 - p[(k + 2) % 3].1))
                    .sum();
                let step = i128::from(linear.step[n]);
                // Stored as 0 past 2^48 (never used).
                if step == 0 && (num << 44).abs() > d.abs() << 48 {
                    continue;
                }
                // |step - 2^44 num / D| <= 1/2 + 2^-11, times 2^11 |D|.
                let error = (step * d - (num << 44)) * d.signum() * (1 << 11);
                assert!(
                    error.abs() <= ((1 << 10) + 1) * d.abs(),
                    "{t:?} {values:?}, channel {n}: off by {}",
                    error as f64 / d.abs() as f64 / 2048.0,
                );
            }
            derived += usize::from(linear.moves.is_some());
            match frame.lambda_steps_by_division() {
                Some(s) => {
                    assert!(within, "{t:?}");
                    assert_eq!(s.map(|s| s.map(i128::from)), exact, "{t:?}");
                    steps += 1;
                }
                None => {
                    assert!(!within, "{t:?}");
                    refused += 1;
                }
            }
        });
        // Most triangles step, and most of those make their steps a pixel
        // right from the steps of `L_1, L_2`.
        assert!(
            steps > 2 * refused && refused > 0 && derived * 2 > steps,
            "{steps} set up, {refused} refused, {derived} steps a pixel right made from them"
        );
    }

    /// A frame has the steps of `L_1, L_2` exactly when its triangle
    /// crosses two rows of pixel centres or more (and the steps are
    /// within their bound): the rows counted one by one here. On random
    /// triangles up to 16 px across, slivers among them.
    #[test]
    fn steps_only_for_two_rows_or_more() {
        let (mut one, mut more) = (0, 0);
        for_random_triangles(0x5EED_0F20_0005, 20_000, 4, |t, frame, _| {
            let ys = t.vertices.map(|v| i64::from(v.raw().1));
            let (low, high) = (ys.iter().min().unwrap(), ys.iter().max().unwrap());
            let rows = (low.div_euclid(4096) - 1..=high.div_euclid(4096) + 1)
                .filter(|k| (*low..*high).contains(&(4096 * k + 2048)))
                .count();
            let expected = match rows >= 2 {
                true => frame.lambda_steps_by_division(),
                false => None,
            };
            assert_eq!(frame.lambda_steps, expected, "{t:?}: {rows} rows");
            match rows >= 2 {
                true => more += 1,
                false => one += 1,
            }
        });
        assert!(
            one > 1000 && more > 1000,
            "{one} of one row or none, {more} of more"
        );
    }

    /// The values [`SpanStarts`] hands out at every span's first pixel
    /// against the exact blend `2^32 a(p) + 2^31`, for random values in
    /// `0..=65535` and random triangles with corners from 1 px to 2^18 px
    /// around a centre (slivers among them), in clip windows that cut
    /// them anywhere: spans a row apart whose starts move either way by up
    /// to [`STEPPED_COLUMNS`] (adds) and more (a product), rows skipped by
    /// thin triangles,
    /// and the first span of each. Each is within the bound of
    /// [`SpanStarts`]' docs for the unit steps taken since the last
    /// division: `2^-43` a unit step and for the division, and `2^-32`
    /// for the floor. The triangles' doubled areas stay below `2^62`, so
    /// that the check, made over their common denominator, fits `i128`.
    #[test]
    fn span_starts_stay_within_their_bound() {
        let (mut stepped, mut spans, mut near_but_divided, mut longest) = (0, 0, 0, 0);
        for_random_triangles(0x0DDB_1A5E_5EED_2026, 3_000, 18, |t, frame, next| {
            let values = [0; 3].map(|_| [0; 3].map(|_| (next() % 65536) as i64));
            let linear = Linear::new(&frame, values);
            let clip = Rectangle::new(
                Point::new((next() % 240) as i32 - 20, (next() % 240) as i32 - 20),
                Size::new((next() % 300) as u32 + 1, (next() % 300) as u32 + 1),
            );
            let p = t.vertices.map(|v| {
                let (x, y) = v.raw();
                (i128::from(x), i128::from(y))
            });
            let area = |a: (i128, i128), b: (i128, i128), e: (i128, i128)| {
                (b.0 - a.0) * (e.1 - a.1) - (b.1 - a.1) * (e.0 - a.0)
            };
            let d = area(p[0], p[1], p[2]);
            let mut starts = SpanStarts::<3, 3>::new(&frame, &linear);
            // The last span's first pixel, and the unit steps since the
            // last division.
            let (mut last, mut units): (Option<(i32, i32)>, i128) = (None, 0);
            t.for_each_span(&clip, |span| {
                let (x, y) = (span.x_start, span.y);
                let got = starts.at(x, y);
                let near = last.and_then(|(lx, ly)| {
                    (ly + 1 == y).then_some(lx.abs_diff(x))
                });
                let moved = near.filter(|_| matches!(starts.steps, Steps::Set { .. }));
                units = match moved {
                    Some(dx) => units + 1 + i128::from(dx),
                    None => 0,
                };
                longest = longest.max(units);
                let c = (i128::from(x) * 4096 + 2048, i128::from(y) * 4096 + 2048);
                let w = [area(c, p[2], p[0]), area(c, p[0], p[1])];
                for n in 0..3 {
                    // 2^12 (got - 2^32 a_0 - 2^31) against 2^44 (a(p) -
                    // a_0), times |D|.
                    let g = i128::from(got[n] - (values[0][n] << 32) - (1 << 31)) << 12;
                    let da = [values[1][n] - values[0][n], values[2][n] - values[0][n]];
                    let x44 = (i128::from(da[0]) * w[0] + i128::from(da[1]) * w[1]) << 44;
                    let error = g * d.abs() - x44 * d.signum();
                    let bound = ((1 << 11) + 2 * (1 + units)) * d.abs();
                    assert!(
                        error.abs() <= bound,
                        "{t:?} {values:?} at ({x}, {y}), channel {n}: {} units of 2^-44 after {units} unit steps",
                        error as f64 / d.abs() as f64,
                    );
                }
                near_but_divided += usize::from(near.is_some() && moved.is_none());
                stepped += usize::from(moved.is_some());
                last = Some((x, y));
                spans += 1;
                Ok::<(), Infallible>(())
            })
            .unwrap();
        });
        // Most spans were stepped to, and some divided for: some of them
        // near enough to step to, but in a triangle whose steps are too
        // large; runs of many steps among them.
        assert!(
            stepped * 2 > spans && stepped < spans && near_but_divided > 0 && longest > 200,
            "{stepped} of {spans} stepped, {near_but_divided} near but divided, {longest} units at most"
        );
    }

    /// Two groups of attributes (a Gouraud triangle's colours and its
    /// depth) get at every span's first pixel exactly the values each
    /// gets alone, on random triangles whose depth steps are often too
    /// large to step (depths across `0..=65535` on triangles a few pixels
    /// wide) while their colours' are not, and the other way round.
    #[test]
    fn groups_get_the_values_they_get_alone() {
        let (mut spans, mut mixed) = (0, 0);
        for_random_triangles(0x6A0C_5EED_0002_2026, 4_000, 8, |t, frame, next| {
            let colors = [0; 3].map(|_| [0; 3].map(|_| (next() % 256) as i64));
            let z = [0; 3].map(|_| [(next() % 65536) as i64]);
            let (colors, z) = (Linear::new(&frame, colors), Linear::new(&frame, z));
            let both = colors.and_depth(&z);
            let mut alone = (
                SpanStarts::<3, 3>::new(&frame, &colors),
                SpanStarts::<1, 1>::new(&frame, &z),
            );
            let mut grouped = SpanStarts::<4, 3>::new(&frame, &both);
            let clip = Rectangle::new(Point::new(-20, -20), Size::new(300, 300));
            t.for_each_span(&clip, |span| {
                let (x, y) = (span.x_start, span.y);
                let [r, g, b, depth] = grouped.at(x, y);
                assert_eq!([r, g, b], alone.0.at(x, y), "{t:?} at ({x}, {y})");
                assert_eq!([depth], alone.1.at(x, y), "{t:?} at ({x}, {y})");
                if let Steps::Set { divided, .. } = grouped.steps {
                    mixed += usize::from(divided.contains(&true));
                }
                spans += 1;
                Ok::<(), Infallible>(())
            })
            .unwrap();
        });
        assert!(
            mixed > 100 && mixed * 4 < spans,
            "{mixed} of {spans} spans with a group divided"
        );
    }

    /// [`PackedChannels`] against [`Channels64`], the 64-bit adds it stands
    /// for, in every built-in colour: spans of 1 to 600 pixels between two
    /// random values as a span carries them (an exact value in each
    /// channel's `0..=MAX`, in 32.32, plus the `1/2` of its rounding),
    /// rising, falling or flat, so that the fractions carry at every pixel,
    /// at none, or between; the first spans two pixels from one end of the
    /// range to the other, the steepest steps. Stepped pixel by pixel and
    /// once past the last, the colours compared at every pixel. One-pixel
    /// spans take steps of up to `2^48`, which [`PackedChannels`] takes as
    /// 0: their one pixel is the same.
    #[test]
    fn packed_channels_step_as_64_bit_values() {
        fn check<C: ShadeColor + core::fmt::Debug>(random: &mut impl Iterator<Item = u64>) -> u64 {
            let mut next = || random.next().unwrap_or_default();
            let mut pixels = 0;
            for k in 0..4_000 {
                // The first spans are two pixels from one end of each
                // channel's range to the other: the steepest steps.
                let n = match k {
                    0..4 => 2,
                    _ => 1 + (next() % 600) as i64,
                };
                let (mut v, mut d) = ([0i64; 3], [0i64; 3]);
                for c in 0..C::CHANNELS {
                    // A carried value: an exact one in 0..=MAX, plus the
                    // 1/2 of its rounding (`SpanStarts::at`).
                    let max = i64::from(C::MAX[c]) << 32;
                    let mut value = || match k {
                        0..4 => max * (next() % 2) as i64 + (1 << 31),
                        _ => (next() % (max as u64 + 1)) as i64 + (1 << 31),
                    };
                    let (a, b) = (value(), value());
                    v[c] = a;
                    // Truncated: every value of the span lies between a and b.
                    d[c] = match n {
                        1 => (next() % (1 << 49)) as i64 - (1 << 48),
                        _ => (b - a) / (n - 1),
                    };
                }
                let (mut wide, mut packed) =
                    (Channels64::value::<C>(v), PackedChannels::value::<C>(v));
                let (wide_step, packed_step) =
                    (Channels64::step::<C>(d), PackedChannels::step::<C>(d));
                for k in 0..n {
                    let want: C = wide.color_then_advance(&wide_step);
                    let got: C = packed.color_then_advance(&packed_step);
                    assert_eq!(got, want, "pixel {k} of {n} from {v:?} by {d:?}");
                    pixels += 1;
                }
            }
            pixels
        }
        let mut random = xorshift(0x5EED_0FC0_1055);
        let pixels = check::<Rgb565>(&mut random)
            + check::<Rgb888>(&mut random)
            + check::<Gray8>(&mut random)
            + check::<BinaryColor>(&mut random);
        assert!(pixels > 4_000_000, "{pixels}");
    }
}
