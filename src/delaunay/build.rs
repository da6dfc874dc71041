//! Incremental construction: faces, point location, splits and Lawson
//! flips.
//!
//! # The mesh
//!
//! Faces are triangles of vertex indices plus, for each vertex, the face
//! across the edge opposite it. A vertex [`GHOST`] at infinity closes the
//! mesh: every hull edge `a -> b` also belongs to a *ghost face*
//! `(b, a, GHOST)`, so every face has three neighbours and points outside
//! the hull are inserted like any other.
//!
//! ```text
//!            v[0]
//!            /  \
//!   n[2] -- /    \ -- n[1]      n[k]: the face across the edge
//!          /      \                   opposite v[k]
//!       v[1] ---- v[2]
//!              |
//!             n[0]
//! ```
//!
//! Finite faces are stored with [`orientation`] `Greater`. A ghost face
//! `(a, b, GHOST)` stands for the open half-plane right of `a -> b`
//! ([`orientation`]`(a, b, p)` `Greater`): its "circumcircle" in the limit.
//!
//! # Storage
//!
//! `n` points (at least 3 not collinear) make `2n - 2` faces, finite and
//! ghost: the first triangle and its three ghosts are 4 faces for 3
//! points, and each insertion adds 2 (one face split in 3, or two faces
//! split in 4). The legalization stack holds faces around the new point,
//! one per edge of its star: at most `n` (the other points and the ghost).

use core::cmp::Ordering;

use super::predicates::{in_circle, orientation};
use crate::vertex::Vertex;

/// The vertex at infinity.
pub(crate) const GHOST: u16 = u16::MAX;

/// One triangle of the mesh, finite or ghost.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Face {
    /// Vertex indices into the points, or [`GHOST`].
    pub(crate) v: [u16; 3],
    /// `n[k]`: the face across the edge opposite `v[k]`.
    pub(crate) n: [u16; 3],
}

impl Face {
    pub(crate) const EMPTY: Self = Self::new([GHOST; 3], [0; 3]);

    const fn new(v: [u16; 3], n: [u16; 3]) -> Self {
        Self { v, n }
    }

    pub(crate) fn is_ghost(&self) -> bool {
        self.v.contains(&GHOST)
    }
}

/// Where a point lies in the mesh.
#[derive(Debug, Clone, Copy)]
enum Location {
    /// Strictly inside a finite face, or in a ghost face's half-plane.
    Face(u16),
    /// On the edge opposite `v[k]` of a finite face, between its ends.
    Edge(u16, usize),
}

/// The mesh under construction, on borrowed storage.
pub(crate) struct Builder<'a> {
    points: &'a [Vertex],
    faces: &'a mut [Face],
    len: usize,
    stack: &'a mut [u16],
    /// Entries in use on `stack`.
    top: usize,
    /// A face of the last insertion: the next walk starts there.
    last: u16,
}

impl<'a> Builder<'a> {
    /// The first triangle `a, b, c` (not collinear) and its three ghosts.
    ///
    /// `faces` must hold `2n - 2` faces and `stack` `n` entries for the
    /// `n` points that will be inserted.
    pub(crate) fn new(
        points: &'a [Vertex],
        faces: &'a mut [Face],
        stack: &'a mut [u16],
        [a, b, c]: [u16; 3],
    ) -> Self {
        let [a, b] = match orientation(points[a as usize], points[b as usize], points[c as usize]) {
            Ordering::Less => [b, a],
            _ => [a, b],
        };
        // Face 0 is (a, b, c); faces 1, 2, 3 the ghosts across the edges
        // opposite a, b and c.
        faces[..4].copy_from_slice(&[
            Face::new([a, b, c], [1, 2, 3]),
            Face::new([c, b, GHOST], [3, 2, 0]),
            Face::new([a, c, GHOST], [1, 3, 0]),
            Face::new([b, a, GHOST], [2, 1, 0]),
        ]);
        Self {
            points,
            faces,
            len: 4,
            stack,
            top: 0,
            last: 0,
        }
    }

    /// Faces in use, finite and ghost.
    pub(crate) fn len(&self) -> usize {
        self.len
    }

    /// Inserts point `p`, distinct from every point inserted so far.
    pub(crate) fn insert(&mut self, p: u16) {
        let new = match self.locate(self.point(p)) {
            Location::Face(f) => self.split_face(f, p),
            Location::Edge(f, k) => self.split_edge(f, k, p),
        };
        self.last = new;
        self.legalize(p);
    }

    fn point(&self, i: u16) -> Vertex {
        self.points[usize::from(i)]
    }

    fn face(&self, f: u16) -> Face {
        self.faces[usize::from(f)]
    }

    /// Walks from the last insertion towards `p`, crossing any edge with
    /// `p` strictly beyond it, until a face holds `p`. In a Delaunay mesh
    /// this walk cannot cycle; it is bounded by the face count all the
    /// same, and falls back to trying every face.
    fn locate(&self, p: Vertex) -> Location {
        let mut f = self.last;
        if let Some(k) = self.face(f).v.iter().position(|&v| v == GHOST) {
            f = self.face(f).n[k];
        }
        for step in 0..self.len {
            match self.step(f, p, step % 3) {
                Ok(location) => return location,
                Err(next) => f = next,
            }
        }
        self.scan(p)
    }

    /// One walk step from finite face `f`, testing its edges from `first`
    /// on: where `p` is, or the neighbour to walk to.
    fn step(&self, f: u16, p: Vertex, first: usize) -> Result<Location, u16> {
        let face = self.face(f);
        let mut on_edge = None;
        for k in (first..first + 3).map(|k| k % 3) {
            let (a, b) = (face.v[(k + 1) % 3], face.v[(k + 2) % 3]);
            match orientation(self.point(a), self.point(b), p) {
                Ordering::Less => {
                    let next = face.n[k];
                    return match self.face(next).is_ghost() {
                        true => Ok(Location::Face(next)),
                        false => Err(next),
                    };
                }
                Ordering::Equal => on_edge = Some(k),
                Ordering::Greater => {}
            }
        }
        Ok(match on_edge {
            Some(k) => Location::Edge(f, k),
            None => Location::Face(f),
        })
    }

    /// Every face in turn: the fallback for a walk that ran too long.
    fn scan(&self, p: Vertex) -> Location {
        let mut outside = 0;
        // At most `2 MAX_POINTS - 2 < u16::MAX` faces: the cast is exact.
        for f in 0..self.len as u16 {
            let face = self.face(f);
            if let Some(k) = face.v.iter().position(|&v| v == GHOST) {
                let (a, b) = (face.v[(k + 1) % 3], face.v[(k + 2) % 3]);
                if orientation(self.point(a), self.point(b), p) == Ordering::Greater {
                    outside = f;
                }
            } else if let Ok(location) = self.contains(f, p) {
                return location;
            }
        }
        Location::Face(outside)
    }

    /// Whether finite face `f` holds `p` in its closed interior.
    fn contains(&self, f: u16, p: Vertex) -> Result<Location, ()> {
        match self.step(f, p, 0) {
            Ok(Location::Face(g)) if g != f => Err(()),
            Ok(location) => Ok(location),
            Err(_) => Err(()),
        }
    }

    /// Splits face `f` (finite with `p` inside, or ghost with `p` in its
    /// half-plane) into three faces around `p`; returns one of them.
    fn split_face(&mut self, f: u16, p: u16) -> u16 {
        let Face {
            v: [a, b, c],
            n: [na, nb, nc],
        } = self.face(f);
        let ids = [f, self.allocate(), self.allocate()];
        self.fan(p, [b, c, a], [(na, f), (nb, f), (nc, f)], ids);
        f
    }

    /// Splits finite face `f` and its neighbour across the edge opposite
    /// `v[k]`, which holds `p` between its ends, into four faces around
    /// `p`; returns one of them.
    fn split_edge(&mut self, f: u16, k: usize, p: u16) -> u16 {
        let face = self.face(f);
        let at = |i: usize| face.v[(k + i) % 3];
        let outer = |i: usize| face.n[(k + i) % 3];
        let (a, b, c) = (at(0), at(1), at(2));
        let g = outer(0);
        let other = self.face(g);
        let j = opposite_slot(&other, b, c);
        let d = other.v[j];
        // Across (b, d) lies the face opposite c in g; across (d, c), b's.
        let g_outer = |v: u16| other.n[other.v.iter().position(|&x| x == v).unwrap_or(j)];
        let ids = [f, self.allocate(), g, self.allocate()];
        let outers = [
            (outer(1), f),
            (outer(2), f),
            (g_outer(c), g),
            (g_outer(b), g),
        ];
        self.fan(p, [c, a, b, d], outers, ids);
        f
    }

    /// Writes faces `ids[i] = (p, ring[i], ring[i + 1])` around `p`, each
    /// seeing `outer[i].0` across its edge opposite `p` (which saw face
    /// `outer[i].1` there before), and pushes them for legalization.
    fn fan<const M: usize>(
        &mut self,
        p: u16,
        ring: [u16; M],
        outer: [(u16, u16); M],
        ids: [u16; M],
    ) {
        for i in 0..M {
            let next = (i + 1) % M;
            let prev = (i + M - 1) % M;
            self.faces[usize::from(ids[i])] = Face {
                v: [p, ring[i], ring[next]],
                n: [outer[i].0, ids[next], ids[prev]],
            };
            self.relink(outer[i].0, outer[i].1, ids[i]);
            self.push(ids[i]);
        }
    }

    /// A new face slot. The storage holds `2n - 2` faces (module docs).
    fn allocate(&mut self) -> u16 {
        // Below `2 MAX_POINTS - 2 < u16::MAX` (the storage's size): exact.
        let f = self.len as u16;
        self.len += 1;
        f
    }

    /// In face `f`, the neighbour `old` becomes `new`.
    fn relink(&mut self, f: u16, old: u16, new: u16) {
        let face = &mut self.faces[usize::from(f)];
        if let Some(slot) = face.n.iter_mut().find(|n| **n == old) {
            *slot = new;
        }
    }

    fn push(&mut self, f: u16) {
        // At most one entry per face around the new point (module docs).
        self.stack[self.top] = f;
        self.top += 1;
    }

    /// Lawson's flips around the new point `p` (at `v[0]` of every face on
    /// the stack): each edge opposite `p` whose far vertex lies strictly
    /// inside the face's circumcircle is flipped, which adds an edge at `p`
    /// and two new edges opposite it to check. Ties (the far vertex on the
    /// circle) are not flipped.
    fn legalize(&mut self, p: u16) {
        while let Some(f) = self.pop() {
            let Face {
                v: [_, a, b],
                n: [g, fa, fb],
            } = self.face(f);
            let other = self.face(g);
            let j = opposite_slot(&other, a, b);
            let d = other.v[j];
            if !self.flips(p, a, b, d) {
                continue;
            }
            // g is (d, b, a) from slot j: across (a, d) lies gb, across (d, b) ga.
            let ga = other.n[(j + 2) % 3];
            let gb = other.n[(j + 1) % 3];
            self.faces[usize::from(f)] = Face::new([p, a, d], [gb, g, fb]);
            self.faces[usize::from(g)] = Face::new([p, d, b], [ga, fa, f]);
            self.relink(gb, g, f);
            self.relink(fa, f, g);
            self.push(f);
            self.push(g);
        }
    }

    fn pop(&mut self) -> Option<u16> {
        self.top = self.top.checked_sub(1)?;
        Some(self.stack[self.top])
    }

    /// Whether the edge `a b` of face `(p, a, b)` must flip: `d`, across
    /// it, lies strictly inside the face's circumcircle (for a ghost face,
    /// strictly inside its half-plane; the ghost itself never does).
    fn flips(&self, p: u16, a: u16, b: u16, d: u16) -> bool {
        let v = |i| self.point(i);
        let strictly = |o| o == Ordering::Greater;
        match (a, b, d) {
            (_, _, GHOST) => false,
            (GHOST, _, _) => strictly(orientation(v(b), v(p), v(d))),
            (_, GHOST, _) => strictly(orientation(v(p), v(a), v(d))),
            _ => strictly(in_circle(v(p), v(a), v(b), v(d))),
        }
    }
}

/// The slot of the vertex of `face` that is neither `a` nor `b`.
fn opposite_slot(face: &Face, a: u16, b: u16) -> usize {
    face.v.iter().position(|&v| v != a && v != b).unwrap_or(0)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Whether `location` holds `p`, by the definitions.
    fn holds(b: &Builder<'_>, location: Location, p: Vertex) -> bool {
        let edge = |face: &Face, k: usize| {
            let (a, c) = (face.v[(k + 1) % 3], face.v[(k + 2) % 3]);
            orientation(b.point(a), b.point(c), p)
        };
        match location {
            Location::Face(f) => {
                let face = b.face(f);
                match face.v.iter().position(|&v| v == GHOST) {
                    Some(k) => edge(&face, k) == Ordering::Greater,
                    None => (0..3).all(|k| edge(&face, k) == Ordering::Greater),
                }
            }
            Location::Edge(f, k) => {
                let face = b.face(f);
                !face.is_ghost()
                    && edge(&face, k) == Ordering::Equal
                    && (1..3).all(|i| edge(&face, (k + i) % 3) == Ordering::Greater)
            }
        }
    }

    /// The walk and its fallback, the scan of every face, both find a
    /// face that holds each query point: inside, on an edge, or outside.
    #[test]
    fn walk_and_scan_locate_every_point() {
        let v = |x: i32, y: i32| Vertex::from_raw(x * 4096, y * 4096);
        let points: [Vertex; 9] = [
            v(0, 0),
            v(40, 0),
            v(0, 40),
            v(40, 40),
            v(20, 20),
            v(10, 30),
            v(33, 7),
            v(20, 0),
            v(5, 12),
        ];
        let mut faces = [Face::EMPTY; 18];
        let mut stack = [0; 9];
        let mut b = Builder::new(&points, &mut faces, &mut stack, [0, 1, 2]);
        for p in 3..9 {
            b.insert(p);
        }
        for x in -5..46 {
            for y in (-5..46).step_by(3) {
                let p = v(x, y);
                if points.contains(&p) {
                    continue;
                }
                assert!(holds(&b, b.locate(p), p), "walk, {p:?}");
                assert!(holds(&b, b.scan(p), p), "scan, {p:?}");
            }
        }
    }
}
