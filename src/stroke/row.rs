//! One row of a stroke: the columns a convex piece lights, exactly, found
//! directly (for a round join's disk sector, or a piece out of the 20.12
//! range: each straight side's threshold by the raster core's
//! [`threshold_on_row`]), and the mask that lets each pixel covered by
//! several pieces be written once.
//!
//! Coordinates are raw 20.12 units (absolute, not relative to a frame): a
//! stroke's pieces lie within `2^46` raw units of the origin (any `i32`
//! pixel, `4096 x + 2048`, plus at most `2^29` for a miter tip of the
//! widest stroke), stored in `i64`, within the bound of
//! [`threshold_on_row`] (`2^62`), which works in `i64` for any stroke on
//! a screen and in `i128` beyond.

use embedded_graphics_core::primitives::Rectangle;

use super::pieces::Region;
use crate::{clip::Bounds, raster::edge::threshold_on_row};

/// Raw units per pixel, and half of it (a pixel centre's offset).
const ONE: i64 = 4096;
const HALF: i64 = 2048;

/// `ceil(n / d)` for `d > 0`, `None` only for `n = i64::MIN`.
fn ceil_div(n: i64, d: i64) -> Option<i64> {
    Some(-(n.checked_neg()?.div_euclid(d)))
}

/// The columns `lo..hi` of row sample `py` (raw) whose nudged centres lie
/// inside the piece of `region`; `None` if none do. Unbounded sides stay at `i64::MIN`
/// or `i64::MAX` (the caller clips).
///
/// A half-plane is `o cross(d, p' - a) > 0` at the nudged centre `p' = p +
/// (e, e^2)`. Writing `X` for the line's crossing of the row, a centre `cx`
/// is inside iff `cx < X` when `o dy > 0` (on the line, the nudge takes it
/// out) and iff `cx >= X` when `o dy < 0`; a horizontal line keeps the
/// whole row or none of it, by the `e^2` term when the row is on it. With
/// `cx = 4096 i + 2048`, both bounds are the column `ceil((X - 2048) /
/// 4096)`.
pub(crate) fn interval(region: &Region, py: i64) -> Option<(i64, i64)> {
    let (mut lo, mut hi) = (i64::MIN, i64::MAX);
    for h in region.planes() {
        let (a, d, o) = (h.a, h.d, i64::from(h.o));
        if d.1 == 0 {
            let s = o * d.0.signum();
            let side = (py - a.1).signum();
            if !(s * side > 0 || (side == 0 && s > 0)) {
                return None;
            }
            continue;
        }
        // Centres at 4096 i + 2048: the core's threshold of the line
        // shifted by half a pixel (every operand below 2^48).
        let c = threshold_on_row((a.0 - HALF, a.1), d, py)?;
        if o * d.1.signum() > 0 {
            hi = hi.min(c);
        } else {
            lo = lo.max(c);
        }
    }
    if let Some((c, r2)) = region.disk {
        let (dlo, dhi) = disk_interval(c, r2, py)?;
        lo = lo.max(dlo);
        hi = hi.min(dhi);
    }
    (lo < hi).then_some((lo, hi))
}

/// The columns of row sample `py` whose nudged centres lie inside the disk
/// of centre `c` and squared radius `r2` (`r2 < 2^55`).
///
/// With `u = cx - c.x` and `D = r2 - (py - c.y)^2`, a centre is inside iff
/// `u^2 < D`, or `u^2 = D` and the nudge moves it inwards: the derivative
/// of `|p' - c|^2` along `(e, e^2)` is `2 u e + (1 + 2 (py - c.y)) e^2`, so
/// inwards iff `u < 0`, or `u = 0` and `py < c.y`.
fn disk_interval(c: (i64, i64), r2: i64, py: i64) -> Option<(i64, i64)> {
    let dy = py - c.1;
    // Past i64, dy^2 is beyond any r2.
    let d = r2 - dy.checked_mul(dy)?;
    if d < 0 {
        return None;
    }
    let s = d.isqrt();
    let (ul, uh) = if s * s < d {
        (-s, s)
    } else if s > 0 {
        (-s, s - 1)
    } else if dy < 0 {
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

    /// Calls `write` with each run of columns of `c..end` in row `row` of
    /// the tile (counted from its top-left pixel, all inside it) not
    /// written yet, left to right, and marks them written.
    ///
    /// The tile's own columns and rows, in `usize`: on a 32-bit core this
    /// is the stroke's inner loop, and the absolute coordinates were
    /// 64-bit arithmetic there.
    pub fn write_unset<E>(
        &mut self,
        row: usize,
        mut c: usize,
        end: usize,
        mut write: impl FnMut(usize, usize) -> Result<(), E>,
    ) -> Result<(), E> {
        let stride = self.stride;
        // Inside the tile: its rows' words lie within the mask, and its
        // columns within a row's words.
        debug_assert!((row + 1) * stride <= MASK_WORDS && end <= 32 * stride);
        let start = row * stride;
        let Some(row) = self.words.get_mut(start..start + stride) else {
            return Ok(());
        };
        // Word by word: mark the span's bits, and carry the unwritten run
        // that reaches the word's end into the next word.
        let mut open: Option<usize> = None;
        while c < end {
            let (k, lo) = (c / 32, c % 32);
            let hi = (end - 32 * k).min(32);
            let Some(word) = row.get_mut(k) else {
                break;
            };
            // Bits lo..hi: 1..=32 of them.
            let span = u32::MAX >> (32 - (hi - lo)) << lo;
            let free = !*word & span;
            *word |= span;
            if free != span {
                // Runs start where a free bit follows a written one, end
                // where a written bit follows a free one.
                let written = !free & span;
                let mut pos = lo;
                loop {
                    if let Some(s) = open {
                        let ahead = written >> pos << pos;
                        if ahead == 0 {
                            break;
                        }
                        let e = ahead.trailing_zeros() as usize;
                        write(s, 32 * k + e)?;
                        open = None;
                        pos = e;
                    }
                    let ahead = free >> pos << pos;
                    if ahead == 0 {
                        break;
                    }
                    let s = ahead.trailing_zeros() as usize;
                    open = Some(32 * k + s);
                    pos = s;
                }
            } else if open.is_none() {
                open = Some(c);
            }
            c = 32 * k + hi;
        }
        if let Some(s) = open {
            write(s, end)?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `write_unset` against a plain array of flags: random runs in a
    /// tile 3 words (90 px) wide and 2 rows tall, across word boundaries,
    /// each pixel written once and exactly the runs' union written.
    #[test]
    fn masked_runs_write_each_pixel_once() {
        let mut random = crate::raster::xorshift(0x9E37_79B9_7F4A_7C15);
        for _ in 0..200 {
            let mut mask = Mask::new();
            mask.clear(3, 2);
            let mut written = [[0u8; 90]; 2];
            let mut want = [[false; 90]; 2];
            for _ in 0..12 {
                let x = random.next().unwrap_or_default();
                let row = (x % 2) as usize;
                let (a, b) = (((x >> 8) % 91) as usize, ((x >> 20) % 91) as usize);
                let (a, b) = (a.min(b), a.max(b));
                want[row][a..b].fill(true);
                let mut last = None;
                mask.write_unset(row, a, b, |s, e| {
                    assert!(
                        a <= s && s < e && e <= b && last.is_none_or(|l| s > l),
                        "{s}..{e} in {a}..{b}"
                    );
                    last = Some(e);
                    for n in &mut written[row][s..e] {
                        *n += 1;
                    }
                    Ok::<(), ()>(())
                })
                .unwrap();
            }
            for (w, r) in written.iter().zip(&want) {
                for (&n, &lit) in w.iter().zip(r) {
                    assert_eq!(n, u8::from(lit));
                }
            }
        }
    }
}
