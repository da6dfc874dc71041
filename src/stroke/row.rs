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

/// Intervals of one row kept on the stack in one pass.
const BUFFERED: usize = 64;

/// Emits the union of the intervals `visit` reports (each `lo..hi`, any
/// order, empty ones ignored) as disjoint spans from left to right.
///
/// Each pass over the pieces keeps, sorted, the [`BUFFERED`] intervals
/// (1 KiB) that start first at or after `cur`, clipped to start there,
/// and notes `lim`, the first start it had to leave out. Every interval
/// starting before `lim` was kept, so the union is exact on `cur..lim`:
/// that part is emitted and the next pass starts at `lim`. A row crossed
/// by at most `BUFFERED` pieces takes one pass; more take about one pass
/// per `BUFFERED` of them (a span may then be emitted in touching parts).
/// If every kept interval starts at `lim` (more than `BUFFERED` start
/// there), the pass emits from `lim` up to the nearest of their ends
/// instead. `cur` grows every pass, so the passes end.
pub(crate) fn union<E>(
    mut visit: impl FnMut(&mut dyn FnMut(i64, i64)),
    mut emit: impl FnMut(i64, i64) -> Result<(), E>,
) -> Result<(), E> {
    let mut buf = [(0i64, 0i64); BUFFERED];
    let mut cur = i64::MIN;
    loop {
        let (mut n, mut lim) = (0usize, i64::MAX);
        visit(&mut |a, b| {
            if b <= cur || a >= b {
                return;
            }
            let a = a.max(cur);
            if n == BUFFERED {
                let last = buf[n - 1].0;
                if a >= last {
                    lim = lim.min(a);
                    return;
                }
                lim = lim.min(last);
                n -= 1;
            }
            let mut i = n;
            while i > 0 && buf[i - 1].0 > a {
                buf[i] = buf[i - 1];
                i -= 1;
            }
            buf[i] = (a, b);
            n += 1;
        });
        let kept = &buf[..n];
        let Some(&(first, _)) = kept.first() else {
            return Ok(());
        };
        if first >= lim {
            // Every kept interval starts at `first = lim`, and none before:
            // emit up to the nearest end.
            let end = kept.iter().map(|&(_, b)| b).min().unwrap_or(first);
            emit(first, end)?;
            cur = end;
            continue;
        }
        let mut span: Option<(i64, i64)> = None;
        for &(a, b) in kept.iter().filter(|&&(a, _)| a < lim) {
            span = match span {
                Some((s, e)) if a <= e => Some((s, e.max(b))),
                Some((s, e)) => {
                    emit(s, e)?;
                    Some((a, b))
                }
                None => Some((a, b)),
            };
        }
        if let Some((s, e)) = span {
            emit(s, e.min(lim))?;
        }
        if lim == i64::MAX {
            return Ok(());
        }
        cur = lim;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The pixels of `0..128` the union emits, checking that no pixel is
    /// emitted twice.
    fn pixels(visit: impl FnMut(&mut dyn FnMut(i64, i64))) -> u128 {
        let mut set = 0u128;
        union(visit, |a, b| {
            for x in a..b {
                assert!(set & (1 << x) == 0, "pixel {x} twice");
                set |= 1 << x;
            }
            Ok::<(), ()>(())
        })
        .unwrap();
        set
    }

    /// The union over many passes (copies and shifted copies past the
    /// buffer) equals the plain union.
    #[test]
    fn passes_match_the_plain_union() {
        let sets: [&[(i64, i64)]; 4] = [
            &[(0, 3), (2, 5), (7, 9), (9, 10), (12, 12), (4, 6)],
            &[(5, 6), (0, 1), (1, 2), (40, 63)],
            &[(3, 60)],
            &[],
        ];
        for set in sets {
            let want = set
                .iter()
                .flat_map(|&(a, b)| a..b)
                .fold(0u128, |m, x| m | 1 << x);
            assert_eq!(pixels(|f| set.iter().for_each(|&(a, b)| f(a, b))), want);
            // 3 x BUFFERED copies: all start together, the nearest-end rule.
            let many = |f: &mut dyn FnMut(i64, i64)| {
                for _ in 0..3 * BUFFERED {
                    set.iter().for_each(|&(a, b)| f(a, b));
                }
            };
            assert_eq!(pixels(many), want);
            // Shifted and shortened copies: many distinct starts.
            let shifted = |f: &mut dyn FnMut(i64, i64)| {
                for k in 0..3 * BUFFERED as i64 {
                    set.iter().for_each(|&(a, b)| f(a + k % 3, b - k % 2));
                }
            };
            let want = (0..3 * BUFFERED as i64)
                .flat_map(|k| set.iter().map(move |&(a, b)| (a + k % 3, b - k % 2)))
                .flat_map(|(a, b)| a..b)
                .fold(0u128, |m, x| m | 1 << x);
            assert_eq!(pixels(shifted), want);
        }
    }
}
