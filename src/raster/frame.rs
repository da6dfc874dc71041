//! The frame a shape is scanned in: the clip's pixels that can be lit,
//! and coordinates relative to the first of them.

use embedded_graphics_core::{geometry::Point, primitives::Rectangle};

use crate::{clip::Bounds, Vertex};

/// Raw units per pixel.
const ONE: i64 = 1 << 12;

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
    centre: (i64, i64),
    /// Largest magnitude of a relative coordinate of the shape.
    reach: u64,
}

impl Frame {
    /// The frame of the shape with these vertices inside `clip`; `None` if
    /// no pixel centre of `clip` lies in their bounding box.
    pub(crate) fn around(vertices: &[Vertex], clip: &Rectangle) -> Option<Self> {
        let (mut lo, mut hi) = ((i32::MAX, i32::MAX), (i32::MIN, i32::MIN));
        for v in vertices {
            let (x, y) = v.raw();
            lo = (lo.0.min(x), lo.1.min(y));
            hi = (hi.0.max(x), hi.1.max(y));
        }
        let (lo, hi) = (
            (i64::from(lo.0), i64::from(lo.1)),
            (i64::from(hi.0), i64::from(hi.1)),
        );
        // Pixels whose centres 4096 i + 2048 lie in [lo, hi].
        let half = ONE / 2;
        let candidates = Bounds {
            x0: (lo.0 - half + ONE - 1) >> 12,
            y0: (lo.1 - half + ONE - 1) >> 12,
            x1: ((hi.0 - half) >> 12) + 1,
            y1: ((hi.1 - half) >> 12) + 1,
        };
        let scan = candidates.intersect(Bounds::of(clip))?;
        let centre = (scan.x0 * ONE + half, scan.y0 * ONE + half);
        let reach = [
            lo.0 - centre.0,
            hi.0 - centre.0,
            lo.1 - centre.1,
            hi.1 - centre.1,
        ]
        .into_iter()
        .map(i64::unsigned_abs)
        .max()
        .unwrap_or(0);
        // The scan lies within the vertex range: |i| <= 2^19 + 1.
        Some(Self {
            origin: Point::new(i32::try_from(scan.x0).ok()?, i32::try_from(scan.y0).ok()?),
            width: i32::try_from(scan.x1 - scan.x0).ok()?,
            height: i32::try_from(scan.y1 - scan.y0).ok()?,
            centre,
            reach,
        })
    }

    /// `v` in raw units from the origin's centre: `|x|, |y| < 2^33`.
    #[inline]
    pub(crate) fn relative(&self, v: Vertex) -> (i64, i64) {
        let (x, y) = v.raw();
        (i64::from(x) - self.centre.0, i64::from(y) - self.centre.1)
    }

    /// Whether every relative coordinate is below `2^29` in magnitude, so
    /// that edges step exactly in `i32` (see [`Edge`](super::edge::Edge)):
    /// true for any shape whose bounding box is under 131,070 px a side.
    pub(crate) fn fits_i32(&self) -> bool {
        self.reach < 1 << 29
    }
}
