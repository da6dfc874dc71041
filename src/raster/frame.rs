//! The frame a shape is scanned in: the clip's pixels that can be lit,
//! and coordinates relative to the first of them.

use embedded_graphics_core::{geometry::Point, primitives::Rectangle};

use super::{edge::SMALL, wide::Wide};
use crate::vertex::Vertex;

/// A rectangle of a clip's pixels holding every pixel whose centre lies
/// in a shape's bounding box (the only ones the sampling rule can light),
/// with the shape's raw coordinates measured from the centre of its
/// top-left pixel. [`around`](Self::around) gives exactly those pixels;
/// [`of_small_triangle`](Self::of_small_triangle) reaches on to the
/// clip's right and bottom edges.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Frame {
    /// Top-left pixel.
    pub origin: Point,
    /// Columns and rows, both at least 1.
    pub width: i32,
    pub height: i32,
    /// Raw coordinates of the origin's centre.
    centre: (i32, i32),
    /// Whether every vertex lies within `2^29` raw units of the centre.
    near: bool,
}

/// The first pixel whose centre `4096 i + 2048` is at or right of `raw`:
/// `ceil((raw - 2048) / 4096) = floor((raw + 2047) / 4096)`, without
/// overflow for any `i32` (the result lies within `-2^19..=2^19`).
///
/// On 64-bit targets the sum is taken in `i64`, an add and a shift; on
/// narrower ones the whole units and the remainder apart, all in `i32`,
/// since an `i64` sum takes a register pair there. Measured: random tiny
/// triangles on x86-64 took 505 instructions a triangle with the split
/// form, 495 with `i64` (callgrind, `benches/pools_callgrind.py`); on a
/// Cortex-M4 (`.ci/icount`) the `i64` form put 13 instructions on a
/// triangle's setup (272 → 285).
#[inline(always)]
const fn first_centre_at_or_after(raw: i32) -> i32 {
    match cfg!(target_pointer_width = "64") {
        true => centre_index_wide(raw, 2047),
        false => centre_index_split(raw, 2047),
    }
}

/// The last pixel whose centre is at or left of `raw`: `floor((raw -
/// 2048) / 4096)`, without overflow for any `i32`; in `i64` on 64-bit
/// targets, as [`first_centre_at_or_after`].
#[inline(always)]
const fn last_centre_at_or_before(raw: i32) -> i32 {
    match cfg!(target_pointer_width = "64") {
        true => centre_index_wide(raw, -2048),
        false => centre_index_split(raw, -2048),
    }
}

/// `floor((raw + offset) / 4096)` for `offset` within `-2048..=2047`,
/// in `i64`. The cast back is exact: the quotient lies within
/// `-2^19..=2^19`.
#[inline(always)]
const fn centre_index_wide(raw: i32, offset: i32) -> i32 {
    ((raw as i64 + offset as i64) >> 12) as i32
}

/// [`centre_index_wide`] in `i32`: whole units and remainder apart, so
/// that nothing overflows.
#[inline(always)]
const fn centre_index_split(raw: i32, offset: i32) -> i32 {
    (raw >> 12) + (((raw & 4095) + offset) >> 12)
}

impl Frame {
    /// The frame of the shape with these vertices inside `clip`; `None` if
    /// no pixel centre of `clip` lies in their bounding box.
    #[inline]
    pub(crate) fn around(vertices: &[Vertex], clip: &Rectangle) -> Option<Self> {
        Self::around_and_whether_small(vertices, clip).map(|(frame, _)| frame)
    }

    /// [`around`](Self::around), and whether every edge of the shape may
    /// be set up by [`Edge::new_small`](super::edge::Edge::new_small) from
    /// its vertices' relative coordinates: the shape's box is under
    /// [`SMALL`] raw units wide, its coordinates fit `i32` relative to the
    /// frame ([`fits_i32`](Self::fits_i32)), and the clip does not cut its
    /// top row.
    ///
    /// Then every difference of two `x` lies within `-SMALL..SMALL`, every
    /// relative coordinate below `2^29` in magnitude, and every vertex
    /// less than a row above the origin's centre (the origin's row is the
    /// first whose centre is at or below the box's top), so that no edge
    /// starts above the frame's first row: what `new_small` needs,
    /// whatever the height. A separate answer, not a field of the frame:
    /// the shapes that do not ask for it store nothing more.
    #[inline(always)]
    pub(crate) fn around_and_whether_small(
        vertices: &[Vertex],
        clip: &Rectangle,
    ) -> Option<(Self, bool)> {
        let (mut lo, mut hi) = ((i32::MAX, i32::MAX), (i32::MIN, i32::MIN));
        for v in vertices {
            let (x, y) = v.raw();
            lo = (lo.0.min(x), lo.1.min(y));
            hi = (hi.0.max(x), hi.1.max(y));
        }
        Self::of_box(lo, hi, clip)
    }

    /// The frame of a small triangle whose vertices are sorted by `y`,
    /// and its vertices relative to the frame, if its bounding box spans
    /// under [`SMALL`] raw units a side and the first pixel centres at or
    /// after its top-left corner lie in `clip`: the common on-screen
    /// triangle, set up without any check beyond these.
    ///
    /// The frame starts at those first centres and reaches to the clip's
    /// right and bottom edges: the triangle's edges end its rows and
    /// columns there, so nothing beyond its box is walked. Its top vertex
    /// lies less than one row above the origin's centre, and every
    /// relative coordinate lies within `-4096..SMALL` (the origin's
    /// centre is at most 4095 raw units past the box's corner): what
    /// [`Edge::new_small`](super::edge::Edge::new_small) needs.
    #[inline(always)]
    pub(crate) fn of_small_triangle(
        v: &[Vertex; 3],
        clip: &Rectangle,
    ) -> Option<(Self, [(i32, i32); 3])> {
        let [a, b, c] = [v[0].raw(), v[1].raw(), v[2].raw()];
        let left = a.0.min(b.0).min(c.0);
        let right = a.0.max(b.0).max(c.0);
        if right.abs_diff(left) >= SMALL as u32 || c.1.abs_diff(a.1) >= SMALL as u32 {
            return None;
        }
        let origin = Point::new(
            first_centre_at_or_after(left),
            first_centre_at_or_after(a.1),
        );
        // A first centre at 2^19 px lies past every raw coordinate (and
        // its centre past i32): the box holds no centre, and nothing is
        // drawn, by the checked path.
        if origin.x < clip.top_left.x
            || origin.y < clip.top_left.y
            || origin.x.max(origin.y) >= 1 << 19
        {
            return None;
        }
        // The clip's columns (rows) from the origin on: its size less the
        // origin's distance past its near edge (exact in u32, the origin
        // being at or past it), held in i32.
        let rest = |at: i32, start: i32, len: u32| {
            let past = at.abs_diff(start);
            if past >= len {
                return None;
            }
            Some(i32::try_from(len - past).unwrap_or(i32::MAX))
        };
        let width = rest(origin.x, clip.top_left.x, clip.size.width)?;
        let height = rest(origin.y, clip.top_left.y, clip.size.height)?;
        // The origin's pixel lies within -2^19..2^19: its centre fits i32, and
        // lies in the box or at most 4095 raw units past its near corner,
        // so each difference below lies within -4096..SMALL.
        let centre = (origin.x * 4096 + 2048, origin.y * 4096 + 2048);
        let relative = |p: (i32, i32)| (p.0 - centre.0, p.1 - centre.1);
        let frame = Self {
            origin,
            width,
            height,
            centre,
            near: true,
        };
        Some((frame, [relative(a), relative(b), relative(c)]))
    }

    /// The frame of the box `lo..=hi` (raw) inside `clip`, and whether it
    /// is small ([`around_and_whether_small`](Self::around_and_whether_small)).
    #[inline(always)]
    fn of_box(lo: (i32, i32), hi: (i32, i32), clip: &Rectangle) -> Option<(Self, bool)> {
        // Pixels lie within +-(2^19 + 1): saturating the clip's far edge at
        // i32::MAX changes nothing.
        let end = |start: i32, len: u32| start.saturating_add_unsigned(len);
        let x0 = first_centre_at_or_after(lo.0).max(clip.top_left.x);
        let top = first_centre_at_or_after(lo.1);
        let y0 = top.max(clip.top_left.y);
        let x1 = (last_centre_at_or_before(hi.0) + 1).min(end(clip.top_left.x, clip.size.width));
        let y1 = (last_centre_at_or_before(hi.1) + 1).min(end(clip.top_left.y, clip.size.height));
        if x0 >= x1 || y0 >= y1 {
            return None;
        }
        // x0 and y0 are the first centres at or after lo (or clip edges
        // past them) and before the last ones at or before hi, so they lie
        // within -2^19..2^19: 4096 p + 2048 is within +-(2^31 - 2048).
        let centre = |p: i32| p * 4096 + 2048;
        // The origin's centre lies in the box [lo, hi] (x0 and y0 are
        // candidates: clipping only moves them inwards), so every vertex
        // lies within the box's extent of it.
        let within = |lo: i32, hi: i32, bound: u32| hi.abs_diff(lo) < bound;
        let frame = Self {
            origin: Point::new(x0, y0),
            width: x1 - x0,
            height: y1 - y0,
            centre: (centre(x0), centre(y0)),
            near: within(lo.0, hi.0, 1 << 29) && within(lo.1, hi.1, 1 << 29),
        };
        let small = frame.near && within(lo.0, hi.0, SMALL as u32) && top == y0;
        Some((frame, small))
    }

    /// Whether every vertex of the shape lies within `2^29` raw units of
    /// the origin's centre: its relative coordinates fit `i32`
    /// ([`relative`](Self::relative)), and its edges step exactly in it.
    #[inline(always)]
    pub(crate) fn fits_i32(&self) -> bool {
        self.near
    }

    /// `v` in raw units from the origin's centre, in `T` if both
    /// coordinates lie within its bound for exact stepping
    /// ([`Wide::difference`]; always for `i64`: `|x|, |y| < 2^32`).
    #[inline(always)]
    pub(crate) fn relative<T: Wide>(&self, v: Vertex) -> Option<(T, T)> {
        let (x, y) = v.raw();
        Some((
            T::difference(x, self.centre.0, self.near)?,
            T::difference(y, self.centre.1, self.near)?,
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Both forms of the centre indices, whichever the target uses,
    /// against `div_euclid` in `i64`: every raw value near the ends of
    /// `i32` and near 0, and random ones.
    #[test]
    fn centre_indices_are_exact_over_the_i32_range() {
        let near = |c: i64| (c - 9000..=c + 9000).filter_map(|v| i32::try_from(v).ok());
        let mut random = crate::raster::xorshift(0x2545_F491_4F6C_DD1D);
        let values = near(i64::from(i32::MIN))
            .chain(near(0))
            .chain(near(i64::from(i32::MAX)))
            .chain((0..100_000).map(|_| random.next().unwrap_or_default() as i32));
        for raw in values {
            for offset in [2047, -2048] {
                let want = (i64::from(raw) + i64::from(offset)).div_euclid(4096);
                assert_eq!(
                    i64::from(centre_index_wide(raw, offset)),
                    want,
                    "{raw} {offset}"
                );
                assert_eq!(
                    i64::from(centre_index_split(raw, offset)),
                    want,
                    "{raw} {offset}"
                );
            }
            // The first centre at or after `raw` is; the one before it is not.
            let first = i64::from(first_centre_at_or_after(raw));
            assert!(
                first * 4096 + 2048 >= i64::from(raw) && (first - 1) * 4096 + 2048 < i64::from(raw)
            );
            let last = i64::from(last_centre_at_or_before(raw));
            assert!(
                last * 4096 + 2048 <= i64::from(raw) && (last + 1) * 4096 + 2048 > i64::from(raw)
            );
        }
    }
}
