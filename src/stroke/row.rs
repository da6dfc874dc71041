//! One row of a stroke: the columns each convex piece lights, exactly, and
//! their union, so that a pixel covered by several pieces is written once.
//!
//! Coordinates are raw 20.12 units (absolute, not relative to a frame): a
//! stroke's pieces lie within `2^46` raw units of the origin (any `i32`
//! pixel, `4096 x + 2048`, plus at most `2^29` for a miter tip of the
//! widest stroke), stored in `i64`; a product that does not fit 64 bits
//! is taken in 128, where every one stays below `2^94`.

use super::pieces::Piece;

/// Raw units per pixel, and half of it (a pixel centre's offset).
const ONE: i64 = 4096;
const HALF: i64 = 2048;

/// `ceil(n / d)` for `d > 0`, `None` only for `n = i64::MIN`.
fn ceil_div(n: i64, d: i64) -> Option<i64> {
    Some(-(n.checked_neg()?.div_euclid(d)))
}

/// `i128` to `i64`, saturating: bounds past the `i64` range act as
/// unbounded.
fn saturate(v: i128) -> i64 {
    i64::try_from(v).unwrap_or(if v < 0 { i64::MIN } else { i64::MAX })
}

/// The column `ceil(((a.x - 2048) d.y + d.x (py - a.y)) / (4096 d.y))`
/// (`d.y != 0`), in 64 bits when the products fit (any stroke on a
/// screen), else in 128 (every operand below `2^47`, so products below
/// `2^94`).
fn column(a: (i64, i64), d: (i64, i64), py: i64) -> i64 {
    let fast = || {
        let num = (a.0 - HALF)
            .checked_mul(d.1)?
            .checked_add(d.0.checked_mul(py - a.1)?)?;
        let den = d.1.checked_mul(ONE)?;
        if den < 0 {
            ceil_div(num.checked_neg()?, den.checked_neg()?)
        } else {
            ceil_div(num, den)
        }
    };
    fast().unwrap_or_else(|| {
        let w = i128::from;
        let (mut num, mut den) = (
            (w(a.0) - w(HALF)) * w(d.1) + w(d.0) * (w(py) - w(a.1)),
            w(ONE) * w(d.1),
        );
        if den < 0 {
            (num, den) = (-num, -den);
        }
        saturate(-((-num).div_euclid(den)))
    })
}

/// The columns `lo..hi` of row sample `py` (raw) whose nudged centres lie
/// inside `piece`; `None` if none do. Unbounded sides stay at `i64::MIN`
/// or `i64::MAX` (the caller clips).
///
/// A half-plane is `o cross(d, p' - a) > 0` at the nudged centre `p' = p +
/// (e, e^2)`. Writing `X` for the line's crossing of the row, a centre `cx`
/// is inside iff `cx < X` when `o dy > 0` (on the line, the nudge takes it
/// out) and iff `cx >= X` when `o dy < 0`; a horizontal line keeps the
/// whole row or none of it, by the `e^2` term when the row is on it. With
/// `cx = 4096 i + 2048`, both bounds are the column `ceil((X - 2048) /
/// 4096)`.
pub(crate) fn interval(piece: &Piece, py: i64) -> Option<(i64, i64)> {
    let (mut lo, mut hi) = (i64::MIN, i64::MAX);
    for h in piece.planes() {
        let (a, d, o) = (h.a, h.d, i64::from(h.o));
        if d.1 == 0 {
            let s = o * d.0.signum();
            let side = (py - a.1).signum();
            if !(s * side > 0 || (side == 0 && s > 0)) {
                return None;
            }
            continue;
        }
        let c = column(a, d, py);
        if o * d.1.signum() > 0 {
            hi = hi.min(c);
        } else {
            lo = lo.max(c);
        }
    }
    if let Some((c, r2)) = piece.disk {
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

/// Intervals of one row kept before falling back to repeated passes.
const BUFFERED: usize = 64;

/// Emits the union of the intervals `visit` reports (each `lo..hi`, any
/// order, empty ones ignored) as disjoint, non-touching spans from left to
/// right.
///
/// Up to [`BUFFERED`] intervals (1 KiB) are sorted and merged on the stack. A row
/// crossed by more pieces than that is merged without storage, by passes
/// over the pieces: each pass extends the current span by every interval
/// starting inside it and finds where the next one starts, so a row costs
/// `O(k)` passes of `k` intervals at most (each pass but one per span moves
/// the span's end to a new interval's end).
pub(crate) fn union<E>(
    mut visit: impl FnMut(&mut dyn FnMut(i64, i64)),
    mut emit: impl FnMut(i64, i64) -> Result<(), E>,
) -> Result<(), E> {
    let mut buf = [(0i64, 0i64); BUFFERED];
    let (mut n, mut overflow) = (0, false);
    visit(&mut |a, b| {
        if a < b {
            match buf.get_mut(n) {
                Some(slot) => {
                    *slot = (a, b);
                    n += 1;
                }
                None => overflow = true,
            }
        }
    });
    if !overflow {
        let buf = &mut buf[..n];
        buf.sort_unstable_by_key(|&(a, _)| a);
        let mut current: Option<(i64, i64)> = None;
        for &(a, b) in buf.iter() {
            current = match current {
                Some((s, e)) if a <= e => Some((s, e.max(b))),
                Some((s, e)) => {
                    emit(s, e)?;
                    Some((a, b))
                }
                None => Some((a, b)),
            };
        }
        return match current {
            Some((s, e)) => emit(s, e),
            None => Ok(()),
        };
    }
    let mut start: Option<i64> = None;
    visit(&mut |a, b| {
        if a < b {
            start = Some(start.map_or(a, |s| s.min(a)));
        }
    });
    while let Some(s) = start {
        let mut end = s;
        loop {
            let (mut grown, mut next) = (end, None::<i64>);
            visit(&mut |a, b| {
                if a >= b {
                } else if a <= end {
                    grown = grown.max(b);
                } else {
                    next = Some(next.map_or(a, |x| x.min(a)));
                }
            });
            if grown == end {
                start = next;
                break;
            }
            end = grown;
        }
        emit(s, end)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The union by passes equals the buffered one.
    #[test]
    fn passes_match_the_buffer() {
        let sets: [&[(i64, i64)]; 3] = [
            &[(0, 3), (2, 5), (7, 9), (9, 10), (12, 12), (4, 6)],
            &[(5, 6), (-3, 0), (0, 1)],
            &[],
        ];
        for set in sets {
            // 17 copies overflow the buffer.
            let many = |f: &mut dyn FnMut(i64, i64)| {
                for _ in 0..=BUFFERED {
                    set.iter().for_each(|&(a, b)| f(a, b));
                }
            };
            let once = |f: &mut dyn FnMut(i64, i64)| set.iter().for_each(|&(a, b)| f(a, b));
            let (mut x, mut y) = (heapless::Vec::<_, 8>::new(), heapless::Vec::<_, 8>::new());
            union(many, |a, b| x.push((a, b)).map_err(|_| ())).unwrap();
            union(once, |a, b| y.push((a, b)).map_err(|_| ())).unwrap();
            assert_eq!(x, y);
        }
    }
}
