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
//! rounded to the nearest 1/4096 px (exactly, in integers: a division and
//! an integer square root for each of the four, in 64 bits while `dx w`
//! and `dy w` stay under 2^20, any line on a screen, in 128 bits past
//! that), and it is filled as a convex polygon under the crate's sampling rule:
//! two chains of edges from its top corner to its bottom one, one span a
//! row (the two triangles sharing its diagonal light the same pixels, in
//! two spans a row). A zero-length thick line is the `w x w` square
//! around its pixel's centre.
//!
//! Corners must be [`Vertex`]es. When one would leave the 20.12 range, the
//! centre line is first cut to the target's bounding box grown by
//! `w / 2 + 2` px (parametrically, in exact rational arithmetic, the cut
//! points rounded to the nearest 1/4096 px); nothing cut away can light a
//! pixel of the target. Pixels beyond the 20.12 range are never lit, as
//! for every filled shape, and when the cut is needed, neither are those
//! within `w + 4` px of the range's ends.

use embedded_graphics_core::{geometry::Point, primitives::Rectangle};

use crate::{
    clip::Bounds,
    raster::wide::{div_sqrt, round_div},
    vertex::{Vertex, ONE},
};

/// Widths above this are drawn as this width.
pub(crate) const MAX_WIDTH: u32 = 65535;

/// The corners of the thick line, in order round it (a parallelogram:
/// `c[0] + c[2] = c[1] + c[3]`), or `None` if nothing of it can be visible
/// in `clip`.
pub(crate) fn corners(
    start: Point,
    end: Point,
    width: u32,
    clip: &Rectangle,
) -> Option<[Vertex; 4]> {
    // In i64: centres within 2^43 raw units, offsets within 2^27, every
    // difference of two `i32` points within 2^32.
    let w = i64::from(width.min(MAX_WIDTH));
    let centre = |p: Point| (i64::from(p.x) * 4096 + 2048, i64::from(p.y) * 4096 + 2048);
    // In pixels: the ratios below do not depend on the unit.
    let (dx, dy) = (
        i64::from(end.x) - i64::from(start.x),
        i64::from(end.y) - i64::from(start.y),
    );
    let (e, n) = if dx == 0 && dy == 0 {
        ((w * 2048, 0), (0, w * 2048))
    } else {
        // |dx|, |dy| <= 2^32 - 1: each square fits u64, their sum u128.
        let (ax, ay) = (dx.unsigned_abs(), dy.unsigned_abs());
        let len2 = u128::from(ax * ax) + u128::from(ay * ay);
        // round(|d| f / len), with the sign of d; |d| f < 2^32 2^27 = 2^59,
        // and so is the result.
        let scaled = |d: i64, f: i64| {
            let a = u128::from(d.unsigned_abs() * f.unsigned_abs());
            d.signum() * i64::try_from(div_sqrt(a, len2)).unwrap_or_default()
        };
        // e = (dx, dy) * 2048 / len and n = (-dy, dx) * w * 2048 / len, raw.
        (
            (scaled(dx, 2048), scaled(dy, 2048)),
            (-scaled(dy, 2048 * w), scaled(dx, 2048 * w)),
        )
    };
    let corners = |p0: (i64, i64), p1: (i64, i64)| {
        [
            (p0.0 - e.0 + n.0, p0.1 - e.1 + n.1),
            (p1.0 + e.0 + n.0, p1.1 + e.1 + n.1),
            (p1.0 + e.0 - n.0, p1.1 + e.1 - n.1),
            (p0.0 - e.0 - n.0, p0.1 - e.1 - n.1),
        ]
    };
    let vertex = |(x, y): (i64, i64)| {
        Some(Vertex::from_raw(
            i32::try_from(x).ok()?,
            i32::try_from(y).ok()?,
        ))
    };
    let (p0, p1) = (centre(start), centre(end));
    let mut v = corners(p0, p1).map(vertex);
    if v.iter().any(Option::is_none) {
        let wide = |p: (i64, i64)| (i128::from(p.0), i128::from(p.1));
        // The cut points lie within the 20.12 range: they fit i64.
        let narrow = |p: (i128, i128)| Some((i64::try_from(p.0).ok()?, i64::try_from(p.1).ok()?));
        let (c0, c1) = cut(wide(p0), wide(p1), i128::from(w), clip)?;
        v = corners(narrow(c0)?, narrow(c1)?).map(vertex);
    }
    let [Some(a), Some(b), Some(c), Some(d)] = v else {
        return None;
    };
    Some([a, b, c, d])
}

/// The part of the centre line `p0 -> p1` (raw units) inside `clip` grown
/// by `w / 2 + 2` px, within the range where the corners stay 20.12.
fn cut(
    p0: (i128, i128),
    p1: (i128, i128),
    w: i128,
    clip: &Rectangle,
) -> Option<((i128, i128), (i128, i128))> {
    let b = Bounds::of(clip);
    let margin = (w / 2 + 2) * ONE as i128;
    let (lo, hi) = (
        i128::from(i32::MIN) + margin * 2,
        i128::from(i32::MAX) - margin * 2,
    );
    let range = |a: i64, z: i64| {
        let a = (i128::from(a) * 4096 - margin).max(lo);
        let z = (i128::from(z) * 4096 + margin).min(hi);
        (a <= z).then_some((a, z))
    };
    let (bx, by) = (range(b.x0, b.x1)?, range(b.y0, b.y1)?);
    // Liang-Barsky with t = num / den, den > 0.
    let (mut t0, mut t1) = ((0i128, 1i128), (1i128, 1i128));
    let less = |a: (i128, i128), b: (i128, i128)| a.0 * b.1 < b.0 * a.1;
    for (from, to, (a, z)) in [(p0.0, p1.0, bx), (p0.1, p1.1, by)] {
        let d = to - from;
        if d == 0 {
            if from < a || from > z {
                return None;
            }
            continue;
        }
        let frac = |v: i128| if d > 0 { (v - from, d) } else { (from - v, -d) };
        let (enter, exit) = if d > 0 {
            (frac(a), frac(z))
        } else {
            (frac(z), frac(a))
        };
        if less(t0, enter) {
            t0 = enter;
        }
        if less(exit, t1) {
            t1 = exit;
        }
    }
    if less(t1, t0) {
        return None;
    }
    let at = |t: (i128, i128)| {
        // a + round((z - a) t), halves up (t.1 > 0).
        let lerp = |a: i128, z: i128| a + round_div((z - a) * t.0, t.1);
        (lerp(p0.0, p1.0), lerp(p0.1, p1.1))
    };
    Some((at(t0), at(t1)))
}
