//! The frame a shape is scanned in: the clip's pixels that can be lit,
//! and coordinates relative to the first of them.

use embedded_graphics_core::{geometry::Point, primitives::Rectangle};

use super::wide::Wide;
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
        // |x0|, |y0| <= 2^19, so the centres lie within +-(2^31 - 2048).
        let centre = |p: i32| p.checked_mul(4096)?.checked_add(2048);
        let centre = (centre(x0)?, centre(y0)?);
        // The origin's centre lies in the box [lo, hi] (x0 and y0 are
        // candidates: clipping only moves them inwards), so every vertex
        // lies within the box's extent of it.
        let small = |lo: i32, hi: i32| hi.checked_sub(lo).is_some_and(|e| e < 1 << 29);
        Some(Self {
            origin: Point::new(x0, y0),
            width: x1 - x0,
            height: y1 - y0,
            centre,
            near: small(lo.0, hi.0) && small(lo.1, hi.1),
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
