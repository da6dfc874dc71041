//! The frame a shape is scanned in: the clip's pixels that can be lit,
//! and coordinates relative to the first of them.

use embedded_graphics_core::{geometry::Point, primitives::Rectangle};

use super::{edge::SMALL, wide::Wide};
use crate::vertex::Vertex;

/// The pixels of a clip rectangle whose centres lie in a shape's bounding
/// box (the only ones the sampling rule can light), with the shape's raw
/// coordinates measured from the centre of the top-left one.
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
/// `ceil((raw - 2048) / 4096)`, without overflow for any `i32`.
#[inline(always)]
const fn first_centre_at_or_after(raw: i32) -> i32 {
    (raw >> 12) + (((raw & 4095) + 2047) >> 12)
}

/// The last pixel whose centre is at or left of `raw`: `floor((raw -
/// 2048) / 4096)`, without overflow for any `i32`.
#[inline(always)]
const fn last_centre_at_or_before(raw: i32) -> i32 {
    (raw >> 12) + (((raw & 4095) - 2048) >> 12)
}

impl Frame {
    /// The frame of the shape with these vertices inside `clip`; `None` if
    /// no pixel centre of `clip` lies in their bounding box.
    #[inline]
    pub(crate) fn around(vertices: &[Vertex], clip: &Rectangle) -> Option<Self> {
        let (mut lo, mut hi) = ((i32::MAX, i32::MAX), (i32::MIN, i32::MIN));
        for v in vertices {
            let (x, y) = v.raw();
            lo = (lo.0.min(x), lo.1.min(y));
            hi = (hi.0.max(x), hi.1.max(y));
        }
        Self::of_box(lo, hi, clip)
    }

    /// [`around`](Self::around) a triangle whose vertices are sorted by
    /// `y` (the first and last give the box's top and bottom), and
    /// whether its bounding box spans under [`SMALL`] raw units a side.
    #[inline(always)]
    pub(crate) fn around_sorted_triangle(
        v: &[Vertex; 3],
        clip: &Rectangle,
    ) -> Option<(Self, bool)> {
        let x = v.map(|v| v.raw().0);
        let lo = (x[0].min(x[1]).min(x[2]), v[0].raw().1);
        let hi = (x[0].max(x[1]).max(x[2]), v[2].raw().1);
        let small = hi.0.abs_diff(lo.0) < SMALL as u32 && hi.1.abs_diff(lo.1) < SMALL as u32;
        Some((Self::of_box(lo, hi, clip)?, small))
    }

    /// The frame of the box `lo..=hi` (raw) inside `clip`.
    #[inline(always)]
    fn of_box(lo: (i32, i32), hi: (i32, i32), clip: &Rectangle) -> Option<Self> {
        // Pixels lie within +-(2^19 + 1): saturating the clip's far edge at
        // i32::MAX changes nothing.
        let end = |start: i32, len: u32| start.saturating_add_unsigned(len);
        let x0 = first_centre_at_or_after(lo.0).max(clip.top_left.x);
        let y0 = first_centre_at_or_after(lo.1).max(clip.top_left.y);
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
        Some(Self {
            origin: Point::new(x0, y0),
            width: x1 - x0,
            height: y1 - y0,
            centre: (centre(x0), centre(y0)),
            near: within(lo.0, hi.0, 1 << 29) && within(lo.1, hi.1, 1 << 29),
        })
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
