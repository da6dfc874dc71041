//! The convex pieces a stroke is the union of: one parallelogram per
//! segment and, at each joint, the join's triangles or disk sector.
//!
//! A right turn at `P` (y down), the join on the outer side:
//!
//! ```text
//!                   c0 +-----+ M      bevel: P, c0, c1
//!                      |  \  |        tip:   c0, M, c1 (Join::Miter)
//!   seg 0 ---------> P +-----+ c1     c0 = P + s n0, c1 = P + s n1
//!                      |
//!                      v seg 1
//! ```
//!
//! A segment from `a` to `b` with direction `d` has the offsets
//!
//! ```text
//! n = (-d.y, d.x) w / (2 |d|),   e = d / (2 |d|)   (half a pixel along d)
//! ```
//!
//! each component rounded to the nearest raw unit (exactly, with an
//! integer square root, as thick lines do), and its piece is the
//! parallelogram `a + n, b + n, b - n, a - n`; the ends of an open
//! stroke are moved out by `e` (butt caps half a pixel beyond the end
//! pixels' centres). Consecutive pieces share the corners `P + n` and
//! `P - n` exactly, so they meet along the line through the joint `P`.
//!
//! **Which side is outside.** Near `P`, segment 0's piece is the half-plane
//! behind the line through `P` along `n0` and segment 1's the half-plane
//! ahead of the line along `n1`; what they leave uncovered is the cone
//! between the rays `s n0` and `s n1` with `s = -sign(cross(n0, n1))`
//! (since `cross(n, d) < 0` for every segment, rounding included). It is
//! decided on the rounded offsets themselves, so the join fills exactly
//! the cone the pieces leave, however close to straight or to a reversal
//! the turn is. Parallel offsets leave nothing (a straight joint) or, in
//! the opposite direction (a full reversal), the half-plane ahead.

use super::{Join, MITER_LIMIT};
use crate::{
    raster::wide::{div_sqrt, round_div, Wide},
    vertex::Vertex,
};

/// A point in raw 20.12 units.
pub(crate) type Pt = (i128, i128);

fn cross(u: Pt, v: Pt) -> i128 {
    u.0 * v.1 - u.1 * v.0
}

fn add(u: Pt, v: Pt) -> Pt {
    (u.0 + v.0, u.1 + v.1)
}

fn sub(u: Pt, v: Pt) -> Pt {
    (u.0 - v.0, u.1 - v.1)
}

/// The open half-plane `o cross(d, p - a) > 0` (`o` is 1 or -1, `d` not
/// zero), in raw units: every piece's coordinates lie below `2^46` in
/// magnitude (module `row`), so they are stored in `i64`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Plane {
    pub a: (i64, i64),
    pub d: (i64, i64),
    pub o: i8,
}

/// A convex piece: the intersection of up to four half-planes and, for a
/// round join, a disk (centre, squared radius). A polygon also keeps its
/// corners, which the raster core walks when they are 20.12 vertices.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Piece {
    planes: [Plane; 4],
    count: usize,
    pub disk: Option<((i64, i64), i64)>,
    /// A polygon's corners in order (`corner_count` of them), `None`
    /// unless every one fits `i32` raw units.
    corners: Option<[Vertex; 4]>,
    corner_count: usize,
    /// The lowest and highest `y` (raw) of the piece, or beyond.
    pub ys: (i64, i64),
}

/// `p` in `i64`; `None` never happens for a stroke's points (below
/// `2^46`).
fn narrow(p: Pt) -> Option<(i64, i64)> {
    Some((i64::try_from(p.0).ok()?, i64::try_from(p.1).ok()?))
}

impl Piece {
    /// The half-planes.
    pub fn planes(&self) -> &[Plane] {
        &self.planes[..self.count]
    }

    /// A polygon's corners as vertices, if they all fit the 20.12 range.
    pub fn vertices(&self) -> Option<&[Vertex]> {
        self.corners.as_ref()?.get(..self.corner_count)
    }

    /// Calls `f` with the convex polygon through `v` (3 or 4 vertices in
    /// order, either winding), unless it has no area. (Built in place and
    /// lent: a piece is 264 bytes on a 64-bit host, not worth copying.)
    #[inline(always)]
    pub fn polygon(v: &[Pt], f: &mut dyn FnMut(&Piece)) {
        let mut piece = Self::empty();
        if piece.set_polygon(v).is_some() {
            f(&piece);
        }
    }

    /// Makes this empty piece the polygon through `v`; `None` if it has
    /// no area.
    ///
    /// In `i64` when every coordinate lies below `2^29` in magnitude (any
    /// stroke on a screen: differences below `2^30`, twice the area below
    /// `2^62`), else in `i128`. On a Cortex-M4 the `i128` set-up was
    /// about 30 % of the tiles' piece building (`.ci/itrace`'s zigzag:
    /// `for_each_piece` 236,474 instructions all in `i128`, 165,772 now).
    #[inline(always)]
    fn set_polygon(&mut self, v: &[Pt]) -> Option<()> {
        const NEAR: i128 = 1 << 29;
        let mut near = [(0i64, 0i64); 4];
        let all_near = v.len() <= near.len()
            && v.iter().zip(&mut near).all(|(p, slot)| {
                // Tested in i128 first: the conversion is then exact.
                let inside = |c: i128| match -NEAR < c && c < NEAR {
                    true => i64::try_from(c).ok(),
                    false => None,
                };
                match (inside(p.0), inside(p.1)) {
                    (Some(x), Some(y)) => {
                        *slot = (x, y);
                        true
                    }
                    _ => false,
                }
            });
        match all_near {
            true => self.set_outline(near.get(..v.len())?),
            false => self.set_outline_wide(v),
        }
    }

    /// [`set_outline`](Self::set_outline) in `i128`, out of line: one
    /// copy for the pieces far off any screen, not one in every kind of
    /// piece (flash).
    #[inline(never)]
    fn set_outline_wide(&mut self, v: &[Pt]) -> Option<()> {
        self.set_outline(v)
    }

    /// [`set_polygon`](Self::set_polygon) in `T`, which holds `v` and
    /// twice its area.
    #[inline(always)]
    fn set_outline<T: Wide>(&mut self, v: &[(T, T)]) -> Option<()> {
        let first = *v.first()?;
        let sub = |u: (T, T), w: (T, T)| (u.0 - w.0, u.1 - w.1);
        // Twice the area, from the first vertex.
        let area = v.windows(2).skip(1).fold(T::ZERO, |sum, w| {
            let (u, w) = (sub(w[0], first), sub(w[1], first));
            sum + (u.0 * w.1 - u.1 * w.0)
        });
        let o: i8 = match area.cmp(&T::ZERO) {
            core::cmp::Ordering::Less => -1,
            core::cmp::Ordering::Equal => return None,
            core::cmp::Ordering::Greater => 1,
        };
        let (lo, hi) = v
            .iter()
            .skip(1)
            .fold((first.1, first.1), |(lo, hi), p| (lo.min(p.1), hi.max(p.1)));
        self.ys = (lo.to_i64()?, hi.to_i64()?);
        // The corners as vertices, if each fits the 20.12 range.
        let vertex = |p: &(T, T)| Some(Vertex::from_raw(p.0.to_i32()?, p.1.to_i32()?));
        let mut corners = Some([Vertex::default(); 4]);
        for (k, p) in v.iter().enumerate() {
            match (corners.as_mut().and_then(|c| c.get_mut(k)), vertex(p)) {
                (Some(slot), Some(p)) => *slot = p,
                _ => corners = None,
            }
        }
        self.corners = corners;
        self.corner_count = v.len();
        let next = v.iter().skip(1).chain(Some(&first));
        for (&from, &to) in v.iter().zip(next) {
            let d = sub(to, from);
            if d != (T::ZERO, T::ZERO) {
                self.push(Plane {
                    a: (from.0.to_i64()?, from.1.to_i64()?),
                    d: (d.0.to_i64()?, d.1.to_i64()?),
                    o,
                });
            }
        }
        Some(())
    }

    /// The disk of centre `c` and squared radius `r2` cut by the
    /// half-planes through `c` along `d` with sides `o`.
    fn sector(c: Pt, r2: i128, planes: &[(Pt, i128)], f: &mut dyn FnMut(&Piece)) {
        let mut piece = Self::empty();
        if piece.set_sector(c, r2, planes).is_some() {
            f(&piece);
        }
    }

    fn set_sector(&mut self, c: Pt, r2: i128, planes: &[(Pt, i128)]) -> Option<()> {
        let c = narrow(c)?;
        for &(d, o) in planes {
            self.push(Plane {
                a: c,
                d: narrow(d)?,
                o: o.signum() as i8,
            });
        }
        let r2 = i64::try_from(r2).ok()?;
        self.disk = Some((c, r2));
        // Rows beyond the disk's top and bottom cross nothing.
        let r = r2.isqrt() + 1;
        self.ys = (c.1 - r, c.1 + r);
        Some(())
    }

    #[inline(always)]
    fn empty() -> Self {
        let none = Plane {
            a: (0, 0),
            d: (1, 0),
            o: 1,
        };
        Self {
            planes: [none; 4],
            count: 0,
            disk: None,
            corners: None,
            corner_count: 0,
            ys: (i64::MIN, i64::MAX),
        }
    }

    #[inline(always)]
    fn push(&mut self, plane: Plane) {
        if let Some(slot) = self.planes.get_mut(self.count) {
            *slot = plane;
            self.count += 1;
        }
    }
}

/// A segment `a -> b` (raw units, `a != b`) of a stroke `w` px wide.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Segment {
    pub a: Pt,
    pub b: Pt,
}

impl Segment {
    /// The offset `n` (module docs) for width `w <= 65535`.
    pub fn normal(&self, w: i128) -> Pt {
        let scaled = self.scaler();
        (-scaled(1, 2048 * w), scaled(0, 2048 * w))
    }

    /// The offset `e`, half a pixel along the segment.
    pub fn extension(&self) -> Pt {
        let scaled = self.scaler();
        (scaled(0, 2048), scaled(1, 2048))
    }

    /// `scaled(i, f)`: component `i` of the direction times `f / |d|`,
    /// rounded to the nearest raw unit (half away from zero).
    ///
    /// A ratio of the direction, so it is first divided by the largest
    /// power of two dividing both components: a direction between pixel
    /// centres (a multiple of 4096) becomes one between `i32` pixels,
    /// below `2^32` a component, as is any difference of `Vertex`
    /// coordinates. Then `|d| f < 2^32 * 2048 * 65535 < 2^59`.
    fn scaler(&self) -> impl Fn(usize, i128) -> i128 {
        let d = sub(self.b, self.a);
        let shift = (d.0 | d.1).trailing_zeros().min(127);
        let d = [d.0 >> shift, d.1 >> shift];
        let len2 = (d[0] * d[0] + d[1] * d[1]).unsigned_abs();
        move |i, f| {
            let c = d[i & 1];
            c.signum() * div_sqrt(c.unsigned_abs() * f.unsigned_abs(), len2)
        }
    }

    /// The segment's parallelogram with offset `n`, its start moved back
    /// by `start` and its end forward by `end` (each `e` or zero).
    #[inline(always)]
    pub fn piece(&self, n: Pt, start: Pt, end: Pt, f: &mut dyn FnMut(&Piece)) {
        let (a, b) = (sub(self.a, start), add(self.b, end));
        Piece::polygon(&[add(a, n), add(b, n), sub(b, n), sub(a, n)], f);
    }
}

/// The `w x w` square around `p` that a stroke of no length draws, as a
/// zero-length thick line does.
pub(crate) fn square(p: Pt, w: i128, f: &mut dyn FnMut(&Piece)) {
    let r = 2048 * w;
    let corners = [
        (p.0 - r, p.1 + r),
        (p.0 + r, p.1 + r),
        (p.0 + r, p.1 - r),
        (p.0 - r, p.1 - r),
    ];
    Piece::polygon(&corners, f);
}

/// Calls `f` with the pieces of the join at `p` between a segment with
/// offset `n0` and direction `d0` and the next one, with offset `n1`, for
/// a stroke `w` px wide.
///
/// - Bevel: the triangle `P, P + s n0, P + s n1`.
/// - Miter: the bevel and the tip triangle `P + s n0, M, P + s n1`, while
///   `cos(turn) >= 2 / L^2 - 1` for `L =` [`MITER_LIMIT`] (tested on the
///   offsets: `L^2 n0.n1 >= (2 - L^2) r^2`, `r = w / 2`), else the bevel
///   alone. `M = P + s (n0 + n1) r^2 / (r^2 + n0.n1)`, the offset lines'
///   crossing for exact offsets, rounded to a raw unit. Two triangles
///   rather than one quadrilateral: the tip's rounding can never dent the
///   bevel.
/// - Round: the disk of radius `r` around `P`, exactly, cut to the cone
///   between the rays `s n0` and `s n1` (after a full reversal, to the
///   half-plane ahead of the first segment).
pub(crate) fn join(p: Pt, n0: Pt, d0: Pt, n1: Pt, w: i128, kind: Join, f: &mut dyn FnMut(&Piece)) {
    let r2 = (2048 * w) * (2048 * w);
    let c = cross(n0, n1);
    let dot = n0.0 * n1.0 + n0.1 * n1.1;
    if c == 0 {
        if dot < 0 && kind == Join::Round {
            Piece::sector(p, r2, &[(n0, cross(n0, d0))], f);
        }
        return;
    }
    let s = -c.signum();
    let (u0, u1) = ((s * n0.0, s * n0.1), (s * n1.0, s * n1.1));
    let (c0, c1) = (add(p, u0), add(p, u1));
    if kind == Join::Round {
        // cross(u0, u1) = c: the cone is on u1's side of u0 and u0's of u1.
        Piece::sector(p, r2, &[(u0, c), (u1, -c)], f);
        return;
    }
    Piece::polygon(&[p, c0, c1], f);
    let l2 = i128::from(MITER_LIMIT) * i128::from(MITER_LIMIT);
    if kind == Join::Miter && l2 * dot >= (2 - l2) * r2 {
        // r^2 + n0.n1 >= 2 r^2 / L^2 > 0.
        let den = r2 + dot;
        let m = (
            p.0 + round_div((u0.0 + u1.0) * r2, den),
            p.1 + round_div((u0.1 + u1.1) * r2, den),
        );
        Piece::polygon(&[c0, m, c1], f);
    }
}
