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

/// Whether the closed polygon with vertices at heights `y(0), .., y(n - 1)`
/// (`y` is called with `0..n` only) goes down and back up only once: the
/// signs of its edges' y steps, level edges left out, change exactly twice
/// round the cycle. Then every row sample line between its top and its
/// bottom crosses exactly two of its edges, one of each chain from the top
/// vertex to the bottom one. Every convex polygon is y-monotone.
pub(crate) fn y_monotone<T: Ord>(n: usize, y: impl Fn(usize) -> T) -> bool {
    let next = |k: usize| if k + 1 == n { 0 } else { k + 1 };
    let step = |k: usize| y(next(k)).cmp(&y(k));
    // The last step that is not level, cyclically before the first edge.
    let Some(mut last) = (0..n).rev().map(step).find(|&s| s != Ordering::Equal) else {
        return false;
    };
    let mut changes = 0u32;
    for k in 0..n {
        let s = step(k);
        if s != Ordering::Equal {
            changes += u32::from(s != last);
            last = s;
        }
    }
    changes == 2
}

/// `q` lies inside or on the triangle `a, b, c` of orientation `orient`.
pub(crate) fn in_closed_triangle(q: P, a: P, b: P, c: P, orient: i128) -> bool {
    cross(a, b, q) * orient >= 0 && cross(b, c, q) * orient >= 0 && cross(c, a, q) * orient >= 0
}
