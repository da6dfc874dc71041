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
