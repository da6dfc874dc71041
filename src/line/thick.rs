//! Thick lines as filled parallelograms of the exact rasterizer.
//!
//! A line of width `w` from pixel `A` to pixel `B` is the rectangle whose
//! centre line runs from the centre of `A` to the centre of `B`, extended
//! by half a pixel beyond each (so a horizontal or vertical thick line
//! covers its end pixels whole), `w` pixels across. Its corners are
//!
//! ```text
//! A - e + n,  B + e + n,  B + e - n,  A - e - n
//! e = (dx, dy) / (2 len),   n = (-dy, dx) w / (2 len),   len = sqrt(dx^2 + dy^2)
//! ```
//!
//! rounded to the nearest 1/4096 px (exactly, in integers: one integer
//! square root and one reciprocal a line, then a few products for each
//! component, in 64 bits while the squared length stays under 2^62, any
//! line on a screen, through a division and a square root in 128 bits
//! past that), and it is filled as a convex polygon under the crate's sampling rule:
//! two chains of edges from its top corner to its bottom one, one span a
//! row (the two triangles sharing its diagonal light the same pixels, in
//! two spans a row). A zero-length thick line is the `w x w` square
//! around its pixel's centre.
//!
//! When a corner would leave the 20.12 range (a line with an end past
//! it, or within about `w / 2 + 1` px of its ends), the parallelogram is
//! filled as a stroke's pieces past that range are
//! ([`fill_far_convex`](crate::stroke::fill_far_convex)): the same
//! corners, in `i64`, each side an edge set up once in 128 bits and
//! stepped in 64. So a thick line is exact over the whole `i32` plane, as
//! a 1-pixel line is, and lights its pixels past the 20.12 range too.

use embedded_graphics_core::geometry::Point;

use crate::{stroke::pieces::Segment, vertex::Vertex};

/// Widths above this are drawn as this width.
pub(crate) const MAX_WIDTH: u32 = 65535;

/// The corners of the thick line, in order round it (a parallelogram:
/// `c[0] + c[2] = c[1] + c[3]`): as vertices, or, if one lies outside the
/// 20.12 range, in raw units (below `2^44` in magnitude).
///
/// The offsets are a stroke segment's ([`Segment::offsets`]), so a
/// thick line and a two-point stroke of the same width have the same
/// corners.
pub(crate) fn corners(
    start: Point,
    end: Point,
    width: u32,
) -> Result<[Vertex; 4], [(i64, i64); 4]> {
    // In i64: centres within 2^43 raw units, offsets within 2^27.
    let w = i64::from(width.min(MAX_WIDTH));
    let centre = |p: Point| (i64::from(p.x) * 4096 + 2048, i64::from(p.y) * 4096 + 2048);
    let segment = Segment {
        a: centre(start),
        b: centre(end),
    };
    let (e, n) = if segment.a == segment.b {
        ((w * 2048, 0), (0, w * 2048))
    } else {
        segment.offsets(w)
    };
    let corners = segment.corners(n, e, e);
    let vertex = |(x, y): (i64, i64)| {
        Some(Vertex::from_raw(
            i32::try_from(x).ok()?,
            i32::try_from(y).ok()?,
        ))
    };
    match corners.map(vertex) {
        [Some(a), Some(b), Some(c), Some(d)] => Ok([a, b, c, d]),
        _ => Err(corners),
    }
}
