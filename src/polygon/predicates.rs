//! Exact geometric predicates on 20.12 vertices, in `i128` (coordinate
//! differences reach 2^32, their products 2^64).

use core::cmp::Ordering;

use crate::vertex::Vertex;

pub(crate) type P = (i128, i128);

pub(crate) fn pt(v: Vertex) -> P {
    let (x, y) = v.raw();
    (i128::from(x), i128::from(y))
}

/// Twice the signed area of `o, a, b`; positive when `o -> a -> b` turns
/// clockwise on screen (y down).
pub(crate) fn cross(o: P, a: P, b: P) -> i128 {
    (a.0 - o.0) * (b.1 - o.1) - (a.1 - o.1) * (b.0 - o.0)
}

fn dot(o: P, a: P, b: P) -> i128 {
    (a.0 - o.0) * (b.0 - a.0) + (a.1 - o.1) * (b.1 - a.1)
}

/// Twice the signed area of the closed polygon.
pub(crate) fn area2(v: &[Vertex]) -> i128 {
    let n = v.len();
    (0..n)
        .map(|k| {
            let (a, b) = (pt(v[k]), pt(v[(k + 1) % n]));
            a.0 * b.1 - b.0 * a.1
        })
        .sum()
}

/// `p`, known to be on the line through `a` and `b`, lies on the segment.
fn within(p: P, a: P, b: P) -> bool {
    a.0.min(b.0) <= p.0 && p.0 <= a.0.max(b.0) && a.1.min(b.1) <= p.1 && p.1 <= a.1.max(b.1)
}

/// The closed segments `ab` and `cd` share at least one point.
pub(crate) fn segments_touch(a: P, b: P, c: P, d: P) -> bool {
    let (d1, d2) = (cross(c, d, a), cross(c, d, b));
    let (d3, d4) = (cross(a, b, c), cross(a, b, d));
    if d1.signum() * d2.signum() < 0 && d3.signum() * d4.signum() < 0 {
        return true;
    }
    (d1 == 0 && within(a, c, d))
        || (d2 == 0 && within(b, c, d))
        || (d3 == 0 && within(c, a, b))
        || (d4 == 0 && within(d, a, b))
}

/// No two non-adjacent edges share a point, adjacent edges share only
/// their common vertex, and no edge has zero length.
pub(crate) fn is_simple(v: &[Vertex]) -> bool {
    let n = v.len();
    if n < 3 {
        return false;
    }
    let p = |k: usize| pt(v[k % n]);
    for i in 0..n {
        let (a, b, c) = (p(i), p(i + 1), p(i + 2));
        // Zero length, or the next edge folds back over this one.
        if a == b || (cross(a, b, c) == 0 && dot(a, b, c) < 0) {
            return false;
        }
        // Edges i and j, not adjacent (j = i + 1 and, for i = 0, j = n - 1).
        let last = if i == 0 { n - 1 } else { n };
        for j in i + 2..last {
            if segments_touch(a, b, p(j), p(j + 1)) {
                return false;
            }
        }
    }
    true
}

/// Every corner turns the same way or goes straight, the turns add up to
/// one full turn, and no edge has zero length: a convex, simple polygon with
/// non-zero area.
pub(crate) fn is_convex(v: &[Vertex]) -> bool {
    let n = v.len();
    if n < 3 {
        return false;
    }
    let p = |k: usize| pt(v[k % n]);
    let mut turn = 0;
    // Sign changes of the edges' x direction, cyclically: two for one turn.
    let mut dx_changes = 0;
    let mut last_dx = 0;
    for i in 0..n {
        let (a, b, c) = (p(i), p(i + 1), p(i + 2));
        if a == b {
            return false;
        }
        let t = cross(a, b, c).signum();
        if t == 0 && dot(a, b, c) < 0 {
            return false;
        }
        if t != 0 {
            if turn != 0 && t != turn {
                return false;
            }
            turn = t;
        }
        let dx = (b.0 - a.0).signum();
        if dx != 0 {
            if last_dx != 0 && dx != last_dx {
                dx_changes += 1;
            }
            last_dx = dx;
        }
    }
    // Close the cycle: compare the first non-zero dx with the last.
    if let Some(first) = (0..n)
        .map(|i| (p(i + 1).0 - p(i).0).signum())
        .find(|&d| d != 0)
    {
        if first != last_dx {
            dx_changes += 1;
        }
    }
    turn != 0 && dx_changes == 2
}

/// Whether the closed polygon `vertices` goes down and back up only
/// once: the signs of its edges' y steps, level edges left out, change
/// exactly twice round the cycle. Then every row sample line between its
/// top and its bottom crosses exactly two of its edges, one of each chain
/// from the top vertex to the bottom one. Every convex polygon is
/// y-monotone; one of no height is not.
///
/// One pass, each height read once: the steps are taken from the last
/// vertex to the first, then along the slice, which is the same cycle
/// started elsewhere. Written to read each step's two heights through
/// an index, after a first pass backwards for the last step, it took 238
/// of an 18 px hexagon's 2,674 instructions on a Cortex-M4
/// (`.ci/itrace`); this form, inlined, left the hexagon at 2,563.
pub(crate) fn y_monotone(vertices: &[Vertex]) -> bool {
    let Some(last) = vertices.last() else {
        return false;
    };
    let mut before = last.raw().1;
    // The first and the latest step that is not level, and the changes
    // of sign between consecutive ones.
    let (mut first, mut latest) = (Ordering::Equal, Ordering::Equal);
    let mut changes = 0u32;
    for v in vertices {
        let y = v.raw().1;
        let step = y.cmp(&before);
        before = y;
        if step != Ordering::Equal {
            if latest == Ordering::Equal {
                first = step;
            } else {
                changes += u32::from(step != latest);
            }
            latest = step;
        }
    }
    // Close the cycle: from the latest step back to the first.
    first != Ordering::Equal && changes + u32::from(first != latest) == 2
}

/// `q` lies inside or on the triangle `a, b, c` of orientation `orient`.
pub(crate) fn in_closed_triangle(q: P, a: P, b: P, c: P, orient: i128) -> bool {
    cross(a, b, q) * orient >= 0 && cross(b, c, q) * orient >= 0 && cross(c, a, q) * orient >= 0
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The definition by crossings, independent of the signs of the
    /// steps: the polygon has some height, and every horizontal line
    /// strictly between two consecutive heights of its vertices crosses
    /// exactly two of its edges.
    fn crosses_each_line_twice(ys: &[i32]) -> bool {
        let mut heights = ys.to_vec();
        heights.sort_unstable();
        heights.dedup();
        heights.len() >= 2
            && heights.windows(2).all(|h| {
                // Doubled, so that the line between them is an integer.
                let line = i64::from(h[0]) + i64::from(h[1]);
                let crossings = (0..ys.len())
                    .filter(|&k| {
                        let (a, b) = (ys[k], ys[(k + 1) % ys.len()]);
                        2 * i64::from(a.min(b)) < line && line < 2 * i64::from(a.max(b))
                    })
                    .count();
                crossings == 2
            })
    }

    fn monotone(ys: &[i32]) -> bool {
        let vertices: std::vec::Vec<_> = ys
            .iter()
            .enumerate()
            .map(|(k, &y)| Vertex::from_raw(k as i32, y))
            .collect();
        y_monotone(&vertices)
    }

    #[test]
    fn monotone_by_steps_as_by_crossings() {
        for ys in [
            &[][..],
            &[5],
            &[5, 5, 5],
            &[0, 1],
            &[0, 4, 2],
            &[0, 4, 4, 0],
            &[0, 4, 1, 4],
            &[3, 0, 3, 0, 3],
            &[i32::MIN, i32::MAX, 0],
        ] {
            assert_eq!(monotone(ys), crosses_each_line_twice(ys), "{ys:?}");
        }
        // Random outlines of up to 9 vertices on few heights: level
        // edges, repeated heights and plateaus at the top and bottom.
        let mut random = crate::raster::xorshift(0xD1B5_4A32_D192_ED03);
        let (mut yes, mut no) = (0, 0);
        for _ in 0..20_000 {
            let x = random.next().unwrap_or_default();
            let n = (x % 10) as usize;
            let ys: std::vec::Vec<i32> = (0..n).map(|k| ((x >> (8 + 5 * k)) % 5) as i32).collect();
            let want = crosses_each_line_twice(&ys);
            assert_eq!(monotone(&ys), want, "{ys:?}");
            if want {
                yes += 1;
            } else {
                no += 1;
            }
        }
        assert!(yes > 3_000 && no > 3_000, "{yes} {no}");
    }
}
