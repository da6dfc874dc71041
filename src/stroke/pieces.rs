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
    raster::wide::{isqrt_u64, round_div, short_product, OverLength, Wide},
    vertex::Vertex,
};

/// A point (or an offset) in raw 20.12 units. A stroke's points,
/// corners and offsets all lie below `2^46` in magnitude (module `row`),
/// so their sums and differences fit `i64`; products that can reach past
/// it are taken in `i128`.
pub(crate) type Pt = (i64, i64);

/// `cross(u, v)`, exact for any two points.
fn cross(u: Pt, v: Pt) -> i128 {
    let w = i128::from;
    w(u.0) * w(v.1) - w(u.1) * w(v.0)
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

/// The lowest and highest `y` (raw) of the segment from `a` to `a + d`
/// (coordinates below `2^47` in magnitude) where its `x` lies in `xs`
/// (`xs.0 <= xs.1`), rounded outwards; `None` if it has no such point.
/// They lie at its ends inside the band or where it crosses the band's
/// lines, `y = a.y + (x - a.x) d.y / d.x` (products below `2^96`, in
/// `i128`; divided in 32 or 64 bits when the operands fit, see
/// [`Wide::div_rem_floor`]).
pub(crate) fn ys_within(a: Pt, d: Pt, xs: (i64, i64)) -> Option<(i64, i64)> {
    let wide = i128::from;
    let (a, d) = ((wide(a.0), wide(a.1)), (wide(d.0), wide(d.1)));
    let b = (a.0 + d.0, a.1 + d.1);
    let band = wide(xs.0)..=wide(xs.1);
    let mut ys: Option<(i128, i128)> = None;
    let mut take = |y: i128| {
        ys = Some(ys.map_or((y, y), |(lo, hi)| (lo.min(y), hi.max(y))));
    };
    for end in [a, b] {
        if band.contains(&end.0) {
            take(end.1);
        }
    }
    if d.0 != 0 {
        let span = a.0.min(b.0)..=a.0.max(b.0);
        for &x in [band.start(), band.end()] {
            if span.contains(&x) {
                // y = a.y + n / m, m > 0: its floor and its ceiling.
                let (n, m) = ((x - a.0) * d.1, d.0);
                let (n, m) = if m < 0 { (-n, -m) } else { (n, m) };
                let (floor, rest) = n.div_rem_floor(m)?;
                take(a.1 + floor);
                take(a.1 + floor + i128::from(rest > 0));
            }
        }
    }
    let (lo, hi) = ys?;
    Some((i64::try_from(lo).ok()?, i64::try_from(hi).ok()?))
}

/// The first row from `from` on where a stroke can light a pixel of the
/// columns `x0..x1`: where the parallelogram of a segment
/// (`segment(k)` for `k` from `ends.0` to `ends.1`, the segments with
/// length; its corners `corners(k, segment)`) crosses them
/// ([`convex_ys_within`]), or within `reach` (raw, in `y`) of a
/// segment's end, where its joins lie, when that end lies within `reach`
/// of them; with no `ends`, within `reach` of the `lone` point. No row
/// between `from` and it has a pixel of those columns lit. `None` if
/// there is none. Columns below `2^32`, points below `2^46`, reaches
/// below `2^30`: no overflow.
///
/// A segment's parallelogram lies within `side` of it on each axis: its
/// corners are set up only for a segment whose own part within `side` of
/// the columns could come before the row found so far. So a tile below
/// the stroke costs a few divisions a segment, and a segment running
/// alongside the columns without lighting them is skipped at once.
///
/// Out of line: a masked stroke calls it only after a tile with nothing
/// lit. Written here rather than in `Stroke`, the Cortex-M4 build of the
/// shading's span starts (another module, unchanged) stayed as it was
/// when it was measured: `.ci/itrace`'s 16 px Gouraud window 10,894
/// instructions, where the same code as a method of `Stroke` gave
/// 11,385.
#[inline(never)]
pub(crate) fn first_row_near(
    ends: Option<(usize, usize)>,
    segment: &dyn Fn(usize) -> Option<Segment>,
    corners: &mut dyn FnMut(usize, &Segment) -> [Pt; 4],
    lone: Pt,
    (x0, x1): (i64, i64),
    from: i64,
    (side, reach): (i64, i64),
) -> Option<i64> {
    let centres = (x0 * 4096 + 2048, (x1 - 1) * 4096 + 2048);
    let near = |r: i64| (centres.0 - r, centres.1 + r);
    // The first row from `from` on whose centre 4096 j + 2048 lies in lo
    // - margin ..= hi + margin, if any.
    let first_row = |ys: Option<(i64, i64)>, margin: i64| {
        let (lo, hi) = ys?;
        let first = -((-(lo - margin - 2048)).div_euclid(4096));
        let last = (hi + margin - 2048).div_euclid(4096);
        (last >= from).then_some(first.max(from))
    };
    let Some((first, last)) = ends else {
        return first_row(ys_within(lone, (0, 0), near(reach)), reach);
    };
    // The earlier of two rows, if any.
    let earlier = |a: Option<i64>, b: Option<i64>| match (a, b) {
        (Some(a), Some(b)) => Some(a.min(b)),
        (a, b) => a.or(b),
    };
    let mut next: Option<i64> = None;
    for k in first..=last {
        let Some(seg) = segment(k) else {
            continue;
        };
        for end in [seg.a, seg.b] {
            next = earlier(next, first_row(ys_within(end, (0, 0), near(reach)), reach));
        }
        let coarse = first_row(ys_within(seg.a, sub(seg.b, seg.a), near(side)), side);
        if coarse.is_some_and(|row| next.is_none_or(|n| row < n)) {
            let exact = first_row(convex_ys_within(&corners(k, &seg), centres), 0);
            next = earlier(next, exact);
        }
    }
    next
}

/// The lowest and highest `y` (raw) of the convex polygon `corners` (in
/// order round it, below `2^46`) where its `x` lies in `xs`: its corners
/// lie on its sides' parts in the band. `None` if it has no such point.
fn convex_ys_within(corners: &[Pt; 4], xs: (i64, i64)) -> Option<(i64, i64)> {
    let sides = (0..4).map(|i| (corners[i], sub(corners[(i + 1) % 4], corners[i])));
    sides_ys_within(sides, xs)
}

/// The lowest and highest `y` (raw) of the parts of the segments `a -> a
/// + d` (`sides`) whose `x` lies in `xs` ([`ys_within`]); `None` if none
/// has such a point. A convex polygon's part in the band is convex, so
/// with its sides as `sides` these are its own.
fn sides_ys_within(sides: impl Iterator<Item = (Pt, Pt)>, xs: (i64, i64)) -> Option<(i64, i64)> {
    sides
        .filter_map(|(a, d)| ys_within(a, d, xs))
        .reduce(|(lo, hi), (l, h)| (lo.min(l), hi.max(h)))
}

/// A convex piece of a stroke: a polygon (a segment's parallelogram, a
/// bevel or a miter's tip) or a round join's disk sector.
///
/// Built in every tile that it can reach, and most are walked by the
/// raster core from their corners alone: a piece holds only what defines
/// it, and the half-planes that the row-by-row fallback reads are derived
/// when it is taken ([`region`](Self::region)). On a Cortex-M4 (`.ci/itrace`'s
/// zigzag through `draw`) the pieces built with their half-planes took
/// 1,061,064 instructions, and 993,702 built this way (856,843 after
/// later changes).
#[derive(Debug, Clone, Copy)]
pub(crate) enum Piece {
    /// A convex polygon through `corners[..count]` (3 or 4, in order,
    /// either winding); one of no area lights nothing.
    Polygon { corners: [Pt; 4], count: usize },
    /// The disk of centre `centre` and squared radius `r2` (`r2 < 2^55`)
    /// cut by the half-planes through the centre along `cuts[..count]`'s
    /// directions, on their sides.
    Sector {
        centre: Pt,
        r2: i64,
        cuts: [(Pt, i8); 2],
        count: usize,
    },
}

/// A piece as the row-by-row fallback reads it ([`RowWalk`](super::row::RowWalk)):
/// up to four half-planes and, for a sector, its disk.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Region {
    planes: [Plane; 4],
    count: usize,
    /// Centre and squared radius.
    pub disk: Option<(Pt, i64)>,
    /// The lowest and highest `y` (raw) of the piece, or beyond.
    pub ys: (i64, i64),
}

impl Region {
    /// The half-planes.
    pub fn planes(&self) -> &[Plane] {
        self.planes.get(..self.count).unwrap_or_default()
    }

    /// The lowest and highest `y` (raw, or beyond) of the region's part
    /// whose `x` lies in `xs` (raw, `xs.0 <= xs.1`); `None` if it has none.
    ///
    /// A polygon's planes run along its sides, each from `a` to `a + d`
    /// ([`sides_ys_within`]); a sector's extent is its disk's, small. So
    /// that a far piece's rows are walked only where it meets the tile's
    /// columns, not all of a tall target's.
    pub fn ys_within(&self, xs: (i64, i64)) -> Option<(i64, i64)> {
        if self.disk.is_some() {
            return Some(self.ys);
        }
        sides_ys_within(self.planes().iter().map(|h| (h.a, h.d)), xs)
    }

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
            ys: (i64::MIN, i64::MAX),
        }
    }

    fn push(&mut self, plane: Plane) {
        if let Some(slot) = self.planes.get_mut(self.count) {
            *slot = plane;
            self.count += 1;
        }
    }

    /// The polygon through `v` in `T`, which holds `v` and twice its
    /// area; `None` if it has no area.
    fn of_polygon<T: Wide>(v: &[(T, T)]) -> Option<Self> {
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
        let mut region = Self::empty();
        let (lo, hi) = v
            .iter()
            .skip(1)
            .fold((first.1, first.1), |(lo, hi), p| (lo.min(p.1), hi.max(p.1)));
        region.ys = (lo.to_i64()?, hi.to_i64()?);
        let next = v.iter().skip(1).chain(Some(&first));
        for (&from, &to) in v.iter().zip(next) {
            let d = sub(to, from);
            if d != (T::ZERO, T::ZERO) {
                region.push(Plane {
                    a: (from.0.to_i64()?, from.1.to_i64()?),
                    d: (d.0.to_i64()?, d.1.to_i64()?),
                    o,
                });
            }
        }
        Some(region)
    }

    /// [`of_polygon`](Self::of_polygon) in `i128`, out of line: one copy
    /// for the pieces far off any screen.
    #[inline(never)]
    pub fn of_wide_polygon(v: &[Pt]) -> Option<Self> {
        let mut wide = [(0i128, 0i128); 4];
        for (slot, p) in wide.iter_mut().zip(v) {
            *slot = (p.0.into(), p.1.into());
        }
        Self::of_polygon(wide.get(..v.len())?)
    }
}

impl Piece {
    /// Calls `f` with the convex polygon through `v` (3 or 4 vertices in
    /// order, either winding).
    #[inline(always)]
    pub fn polygon(v: &[Pt], f: &mut dyn FnMut(&Piece)) {
        let mut corners = [(0, 0); 4];
        let count = v.len().min(4);
        corners[..count].copy_from_slice(&v[..count]);
        f(&Self::Polygon { corners, count });
    }

    /// Calls `f` with the disk of centre `c` and squared radius `r2` cut
    /// by the half-planes through `c` along each `d` of `cuts`, on the side
    /// of the sign of its `o`.
    fn sector(c: Pt, r2: i64, cuts: &[(Pt, i128)], f: &mut dyn FnMut(&Piece)) {
        let mut piece = [((0, 0), 0i8); 2];
        let count = cuts.len().min(2);
        for (slot, &(d, o)) in piece.iter_mut().zip(cuts) {
            *slot = (d, o.signum() as i8);
        }
        f(&Self::Sector {
            centre: c,
            r2,
            cuts: piece,
            count,
        });
    }

    /// A polygon's corners as vertices, if they all fit the 20.12 range.
    pub fn vertices(&self) -> Option<([Vertex; 4], usize)> {
        let Self::Polygon { corners, count } = self else {
            return None;
        };
        let mut vertices = [Vertex::default(); 4];
        for (slot, p) in vertices.iter_mut().zip(&corners[..*count]) {
            *slot = Vertex::from_raw(i32::try_from(p.0).ok()?, i32::try_from(p.1).ok()?);
        }
        Some((vertices, *count))
    }

    /// The piece's half-planes, disk and extent in `y`; `None` if it has
    /// no area.
    ///
    /// A polygon's in `i64` when every coordinate lies below `2^29` in
    /// magnitude (any stroke on a screen: differences below `2^30`, twice
    /// the area below `2^62`), else in `i128`.
    pub fn region(&self) -> Option<Region> {
        match *self {
            Self::Polygon { corners, count } => {
                let v = corners.get(..count)?;
                const NEAR: i64 = 1 << 29;
                let near = |c: i64| -NEAR < c && c < NEAR;
                match v.iter().all(|p| near(p.0) && near(p.1)) {
                    true => Region::of_polygon(v),
                    false => Region::of_wide_polygon(v),
                }
            }
            Self::Sector {
                centre,
                r2,
                cuts,
                count,
            } => {
                let mut region = Region::empty();
                for &(d, o) in cuts.get(..count)? {
                    region.push(Plane { a: centre, d, o });
                }
                region.disk = Some((centre, r2));
                // Rows beyond the disk's top and bottom cross nothing.
                // r2 >= 0, and a root of 64 bits has 32: the cast is exact.
                let r = isqrt_u64(r2.unsigned_abs()) as i64 + 1;
                region.ys = (centre.1 - r, centre.1 + r);
                Some(region)
            }
        }
    }
}

/// A segment `a -> b` (raw units, `a != b`) of a stroke `w` px wide or of
/// a thick line: its ends are the centres of `i32` pixels or [`Vertex`]
/// coordinates, so that its direction, reduced, lies below `2^32`
/// ([`offsets`](Self::offsets)).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Segment {
    pub a: Pt,
    pub b: Pt,
}

impl Segment {
    /// The offset `n` (module docs) for width `w <= 65535`.
    pub fn normal(&self, w: i64) -> Pt {
        let scaled = self.scaler();
        (-scaled(1, 2048 * w), scaled(0, 2048 * w))
    }

    /// The offset `e`, half a pixel along the segment.
    pub fn extension(&self) -> Pt {
        let scaled = self.scaler();
        (scaled(0, 2048), scaled(1, 2048))
    }

    /// The offsets `e` and `n` for width `w <= 65535`, with one setup of
    /// the direction's length.
    #[inline]
    pub fn offsets(&self, w: i64) -> (Pt, Pt) {
        let scaled = self.scaler();
        (
            (scaled(0, 2048), scaled(1, 2048)),
            (-scaled(1, 2048 * w), scaled(0, 2048 * w)),
        )
    }

    /// `scaled(i, f)`: component `i` of the direction times `f / |d|`,
    /// rounded to the nearest raw unit (half away from zero).
    ///
    /// A ratio of the direction, so it is first divided by the largest
    /// power of two dividing both components: a direction between pixel
    /// centres (a multiple of 4096) becomes one between `i32` pixels,
    /// below `2^32` a component, as is any difference of `Vertex`
    /// coordinates. Then the squares lie below `2^64`, `|d| f < 2^32 *
    /// 2048 * 65535 < 2^59`, and the result is at most `f` in magnitude:
    /// the products are taken in `u64`, not `u128` (on a Cortex-M4,
    /// `.ci/itrace`'s mitred zigzag 398,864 → 395,805 instructions through
    /// `draw_spans`).
    fn scaler(&self) -> impl Fn(usize, i64) -> i64 {
        let d = sub(self.b, self.a);
        let shift = (d.0 | d.1).trailing_zeros().min(63);
        let d = [d.0 >> shift, d.1 >> shift];
        let square = |c: i64| u128::from(short_product(c.unsigned_abs(), c.unsigned_abs()));
        let over_length = OverLength::new(square(d[0]) + square(d[1]));
        move |i, f| {
            let c = d[i & 1];
            // f below 2^27 (2048 w, w <= 65535).
            let scaled = over_length.rounded(short_product(c.unsigned_abs(), f.unsigned_abs()));
            // At most |f|: it fits.
            let scaled = i64::try_from(scaled).unwrap_or_default();
            if c < 0 {
                -scaled
            } else {
                scaled
            }
        }
    }

    /// The corners of the segment's parallelogram with offset `n`, its
    /// start moved back by `start` and its end forward by `end` (each `e`
    /// or zero), in order round it.
    #[inline(always)]
    pub fn corners(&self, n: Pt, start: Pt, end: Pt) -> [Pt; 4] {
        let (a, b) = (sub(self.a, start), add(self.b, end));
        [add(a, n), add(b, n), sub(b, n), sub(a, n)]
    }
}

/// The `w x w` square around `p` that a stroke of no length draws, as a
/// zero-length thick line does.
pub(crate) fn square(p: Pt, w: i64, f: &mut dyn FnMut(&Piece)) {
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
///   crossing for exact offsets, each component rounded to the nearest
///   raw unit, halves up (towards `+inf`). Two triangles rather than one
///   quadrilateral: the tip's rounding can never dent the bevel.
/// - Round: the disk of radius `r` around `P`, exactly, cut to the cone
///   between the rays `s n0` and `s n1` (after a full reversal, to the
///   half-plane ahead of the first segment).
pub(crate) fn join(p: Pt, n0: Pt, d0: Pt, n1: Pt, w: i64, kind: Join, f: &mut dyn FnMut(&Piece)) {
    // The offsets are below 2048 w <= 2^27 a component: r^2, n0.n1 and
    // 16 of either fit i64.
    let r2 = (2048 * w) * (2048 * w);
    let c = cross(n0, n1);
    let dot = n0.0 * n1.0 + n0.1 * n1.1;
    if c == 0 {
        if dot < 0 && kind == Join::Round {
            Piece::sector(p, r2, &[(n0, cross(n0, d0))], f);
        }
        return;
    }
    let s = -c.signum() as i64;
    let (u0, u1) = ((s * n0.0, s * n0.1), (s * n1.0, s * n1.1));
    let (c0, c1) = (add(p, u0), add(p, u1));
    if kind == Join::Round {
        // cross(u0, u1) = c: the cone is on u1's side of u0 and u0's of u1.
        Piece::sector(p, r2, &[(u0, c), (u1, -c)], f);
        return;
    }
    Piece::polygon(&[p, c0, c1], f);
    let l2 = i64::from(MITER_LIMIT) * i64::from(MITER_LIMIT);
    if kind == Join::Miter && l2 * dot >= (2 - l2) * r2 {
        // r^2 + n0.n1 >= 2 r^2 / L^2 > 0, and the tip lies within the
        // miter limit, 2^29 of the joint: it fits.
        let den = i128::from(r2 + dot);
        let tip = |u: i64| {
            let t = round_div(i128::from(u) * i128::from(r2), den);
            i64::try_from(t).unwrap_or_default()
        };
        let m = (p.0 + tip(u0.0 + u1.0), p.1 + tip(u0.1 + u1.1));
        Piece::polygon(&[c0, m, c1], f);
    }
}
