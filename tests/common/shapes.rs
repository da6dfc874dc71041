//! Triangle generators and helpers shared by the property tests.

use embedded_raster::{Triangle, Vertex};
use proptest::prelude::*;

pub const MIN: i64 = i32::MIN as i64;
pub const MAX: i64 = i32::MAX as i64;

/// A vertex from raw 20.12 units, clamped into the range.
pub fn v(x: i64, y: i64) -> Vertex {
    Vertex::from_raw(x.clamp(MIN, MAX) as i32, y.clamp(MIN, MAX) as i32)
}

/// Picks a window centre: one of the vertices, or a point of the bounding
/// box given by two fractions.
pub fn focus(t: &Triangle, which: usize, fx: u16, fy: u16) -> (i64, i64) {
    let r = t.vertices.map(|v| {
        let (x, y) = v.raw();
        (i64::from(x), i64::from(y))
    });
    if which < 3 {
        return r[which];
    }
    let (min_x, max_x) = (
        r.iter().map(|p| p.0).min().unwrap(),
        r.iter().map(|p| p.0).max().unwrap(),
    );
    let (min_y, max_y) = (
        r.iter().map(|p| p.1).min().unwrap(),
        r.iter().map(|p| p.1).max().unwrap(),
    );
    let lerp = |a: i64, b: i64, f: u16| a + ((b - a) as i128 * i128::from(f) / 65535) as i64;
    (lerp(min_x, max_x, fx), lerp(min_y, max_y, fy))
}

/// Half-extents in raw units, from a 4 px triangle to the whole range.
pub const SCALES: [i64; 6] = [1 << 13, 1 << 15, 1 << 18, 1 << 22, 1 << 27, 1 << 32];

prop_compose! {
    /// Triangles at every scale, anywhere in the range.
    pub fn any_scale()(
        scale in 0..SCALES.len(),
        c in (any::<i32>(), any::<i32>()),
        d in prop::array::uniform6(any::<i64>()),
    ) -> Triangle {
        let r = SCALES[scale];
        let (cx, cy) = if scale == SCALES.len() - 1 { (0, 0) } else { (i64::from(c.0), i64::from(c.1)) };
        let off = |k: usize| d[k].rem_euclid(2 * r + 1) - r;
        Triangle::new(v(cx + off(0), cy + off(1)), v(cx + off(2), cy + off(3)), v(cx + off(4), cy + off(5)))
    }
}

prop_compose! {
    /// Slivers: the first vertex within `corner` raw units of the origin,
    /// the second within `reach` of it, and the third close to the line
    /// through the two (up to 3000 raw units off it, one raw unit off it,
    /// or exactly on it: a third of the cases each).
    pub fn sliver(corner: i64, reach: i64)(
        p0 in (-corner..corner, -corner..corner),
        d in (-reach..reach, -reach..reach),
        t in -2048i64..=6144,
        off in (-3000i64..=3000, -3000i64..=3000),
        kind in 0u8..3,
    ) -> Triangle {
        let (d, (ox, oy)) = match kind {
            0 => (d, off),
            1 => (d, (off.0.signum(), off.1.signum())),
            // Whole pixels apart, so that `d t / 4096` is exact: collinear.
            _ => ((d.0 / 4096 * 4096, d.1 / 4096 * 4096), (0, 0)),
        };
        Triangle::new(
            v(p0.0, p0.1),
            v(p0.0 + d.0, p0.1 + d.1),
            v(p0.0 + d.0 * t / 4096 + ox, p0.1 + d.1 * t / 4096 + oy),
        )
    }
}
