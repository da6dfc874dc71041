//! Rows of a stroke: the columns a convex piece lights on each row,
//! exactly, for the pieces the raster core's polygon walk does not take
//! (a round join's disk sector, a piece out of the 20.12 range, and a
//! thick line's rectangle out of it): each straight side an [`Edge`]
//! along its line, set up once and stepped ([`RowWalk`]); and the mask
//! that lets each pixel covered by several pieces be written once.
//!
//! Coordinates are raw 20.12 units (absolute, not relative to a frame): a
//! stroke's pieces lie within `2^46` raw units of the origin (any `i32`
//! pixel, `4096 x + 2048`, plus at most `2^29` for a miter tip of the
//! widest stroke), stored in `i64`, within the bound of
//! [`Edge::along_line`] and [`threshold_on_row`] (`2^62`).

use embedded_graphics_core::primitives::Rectangle;

use super::pieces::Region;
use crate::{
    clip::Bounds,
    raster::{
        edge::{threshold_on_row, Edge},
        wide::isqrt_u64,
    },
};

/// Raw units per pixel, and half of it (a pixel centre's offset).
const ONE: i64 = 4096;
const HALF: i64 = 2048;

/// `ceil(n / d)` for `d > 0`, `None` only for `n = i64::MIN`.
fn ceil_div(n: i64, d: i64) -> Option<i64> {
    Some(-(n.checked_neg()?.div_euclid(d)))
}

/// The columns a piece lights on each row of a tile, top to bottom: each
/// straight side of its [`Region`] stepped from row to row by the raster
/// core's [`Edge`] (set up once, in `i128`), or, where an edge would
/// leave its range, found on each row by [`threshold_on_row`].
///
/// A half-plane is `o cross(d, p' - a) > 0` at the nudged centre `p' = p +
/// (e, e^2)`. Writing `X` for the line's crossing of the row, a centre `cx`
/// is inside iff `cx < X` when `o dy > 0` (on the line, the nudge takes it
/// out) and iff `cx >= X` when `o dy < 0`; a horizontal line keeps the
/// whole row or none of it, by the `e^2` term when the row is on it. With
/// `cx = 4096 i + 2048`, both bounds are the column `ceil((X - 2048) /
/// 4096)`: the threshold of an `Edge` whose column `i` is centred at
/// `4096 (i - x0)` and whose row `k` is row `y0 + k` of the tile.
///
/// On a Cortex-M4 (`.ci/icount`), a 3 px line with ends 10^6 px
/// off-screen (one such piece, across about 110 of the screen's 240
/// rows) took 581,494 instructions with each row's four thresholds
/// divided in 128 bits on all 240 rows, 133,808 with them stepped,
/// 76,868 with the two ends' sides, which bound no row inside the
/// screen, left out, and takes 46,514 with only the rows where the piece
/// crosses the screen's columns walked ([`Region::ys_within`]).
pub(crate) struct RowWalk {
    /// The sides that can bound a row inside the tile, `count` of them.
    sides: [Side; 4],
    count: usize,
    /// The disk of a round join's sector: centre and squared radius.
    disk: Option<((i64, i64), i64)>,
    /// The tile's first column.
    x0: i64,
    /// The next row (absolute).
    row: i64,
    /// Whether a side leaves every row of the tile outside.
    empty: bool,
}

/// How a [`RowWalk`] finds a straight side's threshold, and which bound
/// of the row it is.
#[derive(Debug, Clone, Copy)]
enum Side {
    /// A horizontal side through `y`: the rows below it (`below`) or
    /// above it are kept whole, and a row sampled on it goes with those
    /// below (the nudge moves its centres down).
    Level { y: i64, below: bool },
    /// Stepped, in the walk's columns and rows; columns from its threshold
    /// on are outside (`upper`) or inside.
    Stepped { edge: Edge<i64>, upper: bool },
    /// Found directly on each row, for the line through `a` along `d`.
    Direct {
        a: (i64, i64),
        d: (i64, i64),
        upper: bool,
    },
}

impl RowWalk {
    /// The walk of `region` over rows `first..end` of a tile whose
    /// columns are `x0..x1` (rows and columns below `2^32` in magnitude).
    ///
    /// A stepped side whose thresholds on those rows all lie past the
    /// tile on its outer side is left out (the caller clips the columns
    /// to the tile); one whose thresholds all lie past the tile on its
    /// inner side leaves nothing to walk. So a piece far past the 20.12
    /// range, whose ends lie far outside the tile, is walked between its
    /// two long sides.
    pub fn new(region: &Region, (x0, x1): (i64, i64), first: i64, end: i64) -> Self {
        // The frame: column x0's centre and row first's sample line. The
        // pieces' coordinates lie below 2^46, the origin's 2^44.
        let origin = (x0 * ONE + HALF, first * ONE + HALF);
        let last = i32::try_from(end - first - 1).unwrap_or(-1);
        let mut walk = Self {
            sides: [Side::Level { y: 0, below: true }; 4],
            count: 0,
            disk: region.disk,
            x0,
            row: first,
            empty: false,
        };
        for h in region.planes() {
            let o = i64::from(h.o);
            let side = if h.d.1 == 0 {
                Side::Level {
                    y: h.a.1,
                    below: o * h.d.0.signum() > 0,
                }
            } else {
                let upper = o * h.d.1.signum() > 0;
                let p = (h.a.0 - origin.0, h.a.1 - origin.1);
                match Edge::along_line(p, h.d, last) {
                    Some(edge) => {
                        // In the tile's columns, relative to x0.
                        let (least, most) = edge.threshold_bounds();
                        let width = x1 - x0;
                        let (outside, nothing) = match upper {
                            true => (least >= width, most <= 0),
                            false => (most <= 0, least >= width),
                        };
                        walk.empty |= nothing;
                        if outside {
                            continue;
                        }
                        Side::Stepped { edge, upper }
                    }
                    None => Side::Direct {
                        a: h.a,
                        d: h.d,
                        upper,
                    },
                }
            };
            if let Some(slot) = walk.sides.get_mut(walk.count) {
                *slot = side;
                walk.count += 1;
            }
        }
        walk
    }

    /// Whether no row has a pixel in the tile.
    pub fn is_empty(&self) -> bool {
        self.empty
    }

    /// The columns `lo..hi` of the next row whose nudged centres lie
    /// inside the piece; `None` if none do. Unbounded sides stay at
    /// `i64::MIN` or `i64::MAX` (the caller clips).
    pub fn next_row(&mut self) -> Option<(i64, i64)> {
        // |row| < 2^32: the sample fits i64.
        let py = self.row * ONE + HALF;
        self.row += 1;
        let (mut lo, mut hi) = (i64::MIN, i64::MAX);
        let mut empty = false;
        let count = self.count;
        for side in self.sides.iter_mut().take(count) {
            let (c, upper) = match side {
                Side::Level { y, below } => {
                    empty |= (py < *y) == *below;
                    continue;
                }
                Side::Stepped { edge, upper } => {
                    let c = edge.threshold() + self.x0;
                    edge.step();
                    (c, *upper)
                }
                // Centres at 4096 i + 2048: the core's threshold of the
                // line shifted by half a pixel (every operand below 2^48).
                Side::Direct { a, d, upper } => match threshold_on_row((a.0 - HALF, a.1), *d, py) {
                    Some(c) => (c, *upper),
                    None => {
                        empty = true;
                        continue;
                    }
                },
            };
            if upper {
                hi = hi.min(c);
            } else {
                lo = lo.max(c);
            }
        }
        if empty {
            return None;
        }
        if let Some((c, r2)) = self.disk {
            let (dlo, dhi) = disk_interval(c, r2, py)?;
            lo = lo.max(dlo);
            hi = hi.min(dhi);
        }
        (lo < hi).then_some((lo, hi))
    }
}

/// The columns of row sample `py` whose nudged centres lie inside the disk
/// of centre `c` and squared radius `r2` (`r2 < 2^55`).
///
/// With `u = cx - c.x` and `D = r2 - (py - c.y)^2`, a centre is inside iff
/// `u^2 < D`, or `u^2 = D` and the nudge moves it inwards. The nudge is
/// `(e, e^2)` in pixels: with `u` and `v = py - c.y` in pixels too,
/// `|p' - c|^2` grows by `2 u e + (1 + 2 v) e^2 + e^4`, so inwards iff `u
/// < 0`, or `u = 0` and `v < -1/2` px (raw: `py - c.y < -2048`). At `v =
/// -1/2` exactly, the top of the disk of a stroke 1 px wide, the `e^4`
/// term leaves it outside. (Until 2026-12-06 that point was taken as
/// inside, the `e^2` term read in raw units: `tests/stroke_exact.rs`,
/// `width_one_round_join_top`.)
fn disk_interval(c: (i64, i64), r2: i64, py: i64) -> Option<(i64, i64)> {
    let dy = py - c.1;
    // Past i64, dy^2 is beyond any r2.
    let d = r2 - dy.checked_mul(dy)?;
    if d < 0 {
        return None;
    }
    // A root of 64 bits has 32: the cast is exact.
    let s = isqrt_u64(d.unsigned_abs()) as i64;
    let (ul, uh) = if s * s < d {
        (-s, s)
    } else if s > 0 {
        (-s, s - 1)
    } else if dy < -HALF {
        (0, 0)
    } else {
        return None;
    };
    // Columns whose centres 4096 i + 2048 lie in [c.x + ul, c.x + uh].
    let lo = ceil_div(c.0 + ul - HALF, ONE)?;
    let hi = (c.0 + uh - HALF).div_euclid(ONE) + 1;
    (lo < hi).then_some((lo, hi))
}

/// 32-bit words of a tile's mask: 1 KiB on the stack, a bit a pixel (a
/// tile is up to 8,192 px wide, and as many rows as fit).
pub(crate) const MASK_WORDS: usize = 256;

/// The widest tile, in pixels.
pub(crate) const MASK_BITS: i64 = 32 * MASK_WORDS as i64;

/// A rectangle of pixels `x0..x1` by `y0..y1` a stroke's pieces are
/// walked in: a tile of the masked walk (at most [`MASK_BITS`] wide), or
/// the stroke's whole reach inside the clip when overdraw is invisible.
/// Its top-left pixel is a `Point` (`x0` and `y0` fit `i32`) and its
/// sides fit `u32` (it lies inside a `Rectangle`).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Tile {
    pub x0: i64,
    pub x1: i64,
    pub y0: i64,
    pub y1: i64,
    /// The same pixels, for the walk's clip: its top-left corner is
    /// `(x0, y0)`, from which the pieces' rows and columns count.
    pub rectangle: Rectangle,
}

impl Tile {
    /// The pixels of `clip` whose centres lie in the box of `points` (raw
    /// units below `2^46` in magnitude), up to column and row `2^31`
    /// (past which no pixel is a `Point`); `None` if there are none (or
    /// no points).
    pub fn around(points: &[(i64, i64)], clip: &Rectangle) -> Option<Self> {
        let clip = Bounds::of(clip);
        let (&start, rest) = points.split_first()?;
        let (lo, hi) = rest.iter().fold((start, start), |(lo, hi), p| {
            (
                (lo.0.min(p.0), lo.1.min(p.1)),
                (hi.0.max(p.0), hi.1.max(p.1)),
            )
        });
        // The first centre 4096 i + 2048 at or after `lo`, the last at or
        // before `hi`, and one past it.
        let first = |v: i64| ceil_div(v - HALF, ONE);
        let end = |v: i64| (v - HALF).div_euclid(ONE) + 1;
        let (x0, y0) = (first(lo.0)?.max(clip.x0), first(lo.1)?.max(clip.y0));
        let (x1, y1) = (end(hi.0).min(clip.x1), end(hi.1).min(clip.y1));
        let (x1, y1) = (x1.min(1 << 31), y1.min(1 << 31));
        (x0 < x1 && y0 < y1).then(|| Self::new(x0, x1, y0, y1))
    }

    /// The pixels `x0..x1` by `y0..y1` (inside a `Rectangle`, see
    /// [`Tile`]).
    pub fn new(x0: i64, x1: i64, y0: i64, y1: i64) -> Self {
        Self {
            x0,
            x1,
            y0,
            y1,
            rectangle: Bounds { x0, y0, x1, y1 }.to_rectangle(),
        }
    }
}

/// The pixels of a tile already written, a bit each, its rows `stride`
/// words apart.
#[derive(Debug)]
pub(crate) struct Mask {
    words: [u32; MASK_WORDS],
    stride: usize,
}

impl Mask {
    pub fn new() -> Self {
        Self {
            words: [0; MASK_WORDS],
            stride: 0,
        }
    }

    /// Starts a tile of `rows` rows `stride` words apart (`stride rows <=
    /// MASK_WORDS`, the tile at most `32 stride` px wide), every pixel
    /// unwritten.
    pub fn clear(&mut self, stride: usize, rows: usize) {
        self.stride = stride;
        let used = stride.saturating_mul(rows);
        if let Some(words) = self.words.get_mut(..used) {
            words.fill(0);
        }
    }

    /// Marks columns `c..end` of row `row` of the tile (counted from its
    /// top-left pixel, all inside it). In the tile's own columns and rows,
    /// in `usize`: on a 32-bit core this is the stroke's inner loop, and
    /// the absolute coordinates were 64-bit arithmetic there.
    #[inline(always)]
    pub fn mark(&mut self, row: usize, c: usize, end: usize) {
        // Inside the tile: its rows' words lie within the mask, and its
        // columns within a row's words.
        debug_assert!((row + 1) * self.stride <= MASK_WORDS && end <= 32 * self.stride);
        if c >= end {
            return;
        }
        let start = row * self.stride;
        let (first, last) = (start + c / 32, start + (end - 1) / 32);
        // Bits c % 32.. of the first word and ..=(end - 1) % 32 of the
        // last; all of those between.
        let (head, tail) = (u32::MAX << (c % 32), u32::MAX >> (31 - (end - 1) % 32));
        match self.words.get_mut(first..=last) {
            Some([word]) => *word |= head & tail,
            Some([first, middle @ .., last]) => {
                *first |= head;
                middle.fill(u32::MAX);
                *last |= tail;
            }
            _ => {}
        }
    }

    /// Calls `write(row, start, end)` with each run of marked pixels of the
    /// tile's first `rows` rows, row by row, left to right: each run as
    /// long as it goes, so that a pixel many pieces mark is written once
    /// and runs that touch are written as one. Whether there was a run.
    pub fn for_each_run<E>(
        &self,
        rows: usize,
        mut write: impl FnMut(usize, usize, usize) -> Result<(), E>,
    ) -> Result<bool, E> {
        let mut any = false;
        let stride = self.stride.max(1);
        let used = self
            .words
            .get(..stride.saturating_mul(rows))
            .unwrap_or_default();
        for (row, words) in used.chunks_exact(stride).enumerate() {
            // The start of a run that reaches the end of the word before.
            let mut open: Option<usize> = None;
            for (k, &word) in words.iter().enumerate() {
                let base = 32 * k;
                // Runs start at a marked bit after an unmarked one and end
                // at an unmarked bit after a marked one; `pos` (below 32)
                // is where the next one is looked for.
                let mut pos = 0;
                loop {
                    match open {
                        Some(s) => {
                            let ahead = !word & u32::MAX << pos;
                            if ahead == 0 {
                                break;
                            }
                            pos = ahead.trailing_zeros();
                            write(row, s, base + pos as usize)?;
                            any = true;
                            open = None;
                        }
                        None => {
                            let ahead = word & u32::MAX << pos;
                            if ahead == 0 {
                                break;
                            }
                            pos = ahead.trailing_zeros();
                            open = Some(base + pos as usize);
                        }
                    }
                }
            }
            if let Some(s) = open {
                write(row, s, 32 * stride)?;
                any = true;
            }
        }
        Ok(any)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Marks and runs against a plain array of flags: random runs in a
    /// tile 3 words (96 px) wide and 2 rows tall, across word boundaries;
    /// the runs written are exactly the marks' union, each pixel once,
    /// left to right with a gap between runs.
    #[test]
    fn runs_are_the_union_of_the_marks() {
        let mut random = crate::raster::xorshift(0x9E37_79B9_7F4A_7C15);
        for case in 0..400 {
            let mut mask = Mask::new();
            mask.clear(3, 2);
            let mut want = [[false; 96]; 2];
            for _ in 0..case % 13 {
                let x = random.next().unwrap_or_default();
                let row = (x % 2) as usize;
                let (a, b) = (((x >> 8) % 97) as usize, ((x >> 20) % 97) as usize);
                let (a, b) = (a.min(b), a.max(b));
                want[row][a..b].fill(true);
                mask.mark(row, a, b);
            }
            let mut written = [[0u8; 96]; 2];
            let mut last: Option<(usize, usize)> = None;
            let any = mask
                .for_each_run(2, |row, s, e| {
                    let after = last.is_none_or(|(r, l)| row > r || (row == r && s > l));
                    assert!(s < e && e <= 96 && after, "{row}: {s}..{e} after {last:?}");
                    last = Some((row, e));
                    for n in &mut written[row][s..e] {
                        *n += 1;
                    }
                    Ok::<(), ()>(())
                })
                .unwrap();
            assert_eq!(any, want.iter().flatten().any(|&w| w), "case {case}");
            assert_eq!(written.map(|r| r.map(|n| n == 1)), want, "case {case}");
            assert!(written.iter().flatten().all(|&n| n <= 1));
        }
    }
}
