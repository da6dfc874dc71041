//! Triangulation: a fan for convex polygons, ear clipping for simple ones.

use heapless::Vec;

use super::predicates::{area2, cross, in_closed_triangle, is_convex, is_simple, pt};
use crate::{triangle::Triangle, vertex::Vertex};

/// Why a polygon could not be triangulated.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct NotSimple;

/// Calls `f` with triangles that tile the polygon exactly: their shared
/// edges are diagonals, so the triangles together light each pixel of the
/// polygon once. At most `N` vertices (checked by the caller).
pub(crate) fn triangulate<const N: usize>(
    v: &[Vertex],
    mut f: impl FnMut(Triangle),
) -> Result<(), NotSimple> {
    if is_convex(v) {
        for k in 1..v.len() - 1 {
            f(Triangle::new(v[0], v[k], v[k + 1]));
        }
        return Ok(());
    }
    if !is_simple(v) {
        return Err(NotSimple);
    }
    let orient = area2(v).signum();
    let mut ring: Vec<usize, N> = Vec::new();
    for k in 0..v.len() {
        // The caller checked that there are at most N vertices.
        ring.push(k).map_err(|_| NotSimple)?;
    }
    while ring.len() > 3 {
        let ear = find_ear(v, &ring, orient).ok_or(NotSimple)?;
        let n = ring.len();
        let (p, i, q) = (ring[(ear + n - 1) % n], ring[ear], ring[(ear + 1) % n]);
        if cross(pt(v[p]), pt(v[i]), pt(v[q])) != 0 {
            f(Triangle::new(v[p], v[i], v[q]));
        }
        ring.remove(ear);
    }
    f(Triangle::new(v[ring[0]], v[ring[1]], v[ring[2]]));
    Ok(())
}

/// A corner of the ring that can be cut off: it turns the polygon's way
/// (or goes straight) and no other vertex lies in its triangle.
fn find_ear(v: &[Vertex], ring: &[usize], orient: i128) -> Option<usize> {
    let n = ring.len();
    (0..n).find(|&k| {
        let (p, i, q) = (ring[(k + n - 1) % n], ring[k], ring[(k + 1) % n]);
        let (a, b, c) = (pt(v[p]), pt(v[i]), pt(v[q]));
        let turn = cross(a, b, c) * orient;
        if turn == 0 {
            // A straight corner: dropping it changes nothing.
            return true;
        }
        turn > 0
            && ring
                .iter()
                .filter(|&&r| r != p && r != i && r != q)
                .all(|&r| !in_closed_triangle(pt(v[r]), a, b, c, orient))
    })
}
