//! Per-pixel edge-function evaluation over the clipped bounding box.
//!
//! Coordinates are snapped vertices in units of `2^-u` px
//! (`u = max(bits, 1)`), so pixel `i`'s centre is `i 2^u + 2^(u-1)`, an
//! integer. The edge functions carry the crate's top-left bias (the
//! sampling rule the default rasterizer's edges apply as thresholds, see
//! `raster::edge`) and are reduced by the pixel step `2^u` (`F =
//! floor((E + bias) / 2^u)`, exact because the centres are `2^u` apart);
//! `F_k` is then stepped over every pixel of the scanned rectangle, with
//! no span tracking or early exit.
//!
//! `|F_k| <= 2^u W H + 1` over a `W x H` px box, and `|A_k| <= 2^u H`,
//! `|B_k| <= 2^u W`: the exact per-triangle check below picks `i32` when
//! the corner values fit, which they always do when `W H < 2^(31 - u)`.

use embedded_graphics_core::primitives::Rectangle;

use super::SubpixelPrecision;
use crate::{clip::Bounds, raster::wide::orientation, span::Span, vertex::Vertex};

/// Oriented, reduced edge functions over the scanned rectangle.
struct Setup {
    origin: (i32, i32),
    size: (i32, i32),
    a: [i64; 3],
    b: [i64; 3],
    q: [i64; 3],
}

fn setup(v: &[Vertex; 3], precision: SubpixelPrecision, clip: &Rectangle) -> Option<Setup> {
    let u = precision.unit_bits();
    let shift = 12 - u;
    let p = v.map(|v| {
        let (x, y) = v.raw();
        (i64::from(x) >> shift, i64::from(y) >> shift)
    });
    let (pixel, half) = (1i64 << u, 1i64 << (u - 1));
    let min_x = p[0].0.min(p[1].0).min(p[2].0);
    let max_x = p[0].0.max(p[1].0).max(p[2].0);
    let min_y = p[0].1.min(p[1].1).min(p[2].1);
    let max_y = p[0].1.max(p[1].1).max(p[2].1);
    // Pixels whose centres lie in [min, max], clipped.
    let candidates = Bounds {
        x0: (min_x - half + pixel - 1) >> u,
        y0: (min_y - half + pixel - 1) >> u,
        x1: ((max_x - half) >> u) + 1,
        y1: ((max_y - half) >> u) + 1,
    };
    let scan = candidates.intersect(Bounds::of(clip))?;
    let origin = (i32::try_from(scan.x0).ok()?, i32::try_from(scan.y0).ok()?);
    let size = (
        i32::try_from(scan.x1 - scan.x0).ok()?,
        i32::try_from(scan.y1 - scan.y0).ok()?,
    );
    let centre = (
        i128::from(scan.x0 * pixel + half),
        i128::from(scan.y0 * pixel + half),
    );
    // Setup products in i128: differences reach 2^33 units.
    let area2 = orientation(p[0], p[1], p[2]);
    let w = |t: (i64, i64)| (i128::from(t.0), i128::from(t.1));
    let [p0, mut p1, mut p2] = p.map(w);
    if area2 == 0 {
        return None;
    }
    if area2 < 0 {
        core::mem::swap(&mut p1, &mut p2);
    }
    let pts = [p0, p1, p2];
    let (mut a, mut b, mut q) = ([0i64; 3], [0i64; 3], [0i64; 3]);
    for k in 0..3 {
        let (from, to) = (pts[k], pts[(k + 1) % 3]);
        let (ak, bk) = (from.1 - to.1, to.0 - from.0);
        let e = ak * (centre.0 - from.0) + bk * (centre.1 - from.1);
        let top_left = ak > 0 || (ak == 0 && bk > 0);
        let g = if top_left { e } else { e - 1 };
        a[k] = i64::try_from(ak).ok()?;
        b[k] = i64::try_from(bk).ok()?;
        q[k] = i64::try_from(g >> u).ok()?;
    }
    Some(Setup {
        origin,
        size,
        a,
        b,
        q,
    })
}

/// An integer the loop steps in.
trait Step:
    Copy + Ord + core::ops::Add<Output = Self> + core::ops::BitOr<Output = Self> + TryFrom<i64>
{
    const ZERO: Self;
}

impl Step for i32 {
    const ZERO: Self = 0;
}

impl Step for i64 {
    const ZERO: Self = 0;
}

/// The coefficients in `T`, or `None` if a value `F_k` takes over the
/// rectangle (extremes at the corners) or a step does not fit.
#[allow(clippy::type_complexity)]
fn narrow<T: Step>(s: &Setup) -> Option<([T; 3], [T; 3], [T; 3])> {
    let (dx, dy) = (i64::from(s.size.0 - 1), i64::from(s.size.1 - 1));
    let mut out = ([T::ZERO; 3], [T::ZERO; 3], [T::ZERO; 3]);
    for (k, ((&a, &b), &q)) in s.a.iter().zip(&s.b).zip(&s.q).enumerate() {
        let (ax, by) = (a * dx, b * dy);
        T::try_from(q + ax.min(0) + by.min(0)).ok()?;
        T::try_from(q + ax.max(0) + by.max(0)).ok()?;
        out.0[k] = T::try_from(a).ok()?;
        out.1[k] = T::try_from(b).ok()?;
        out.2[k] = T::try_from(q).ok()?;
    }
    Some(out)
}

fn run<T: Step, E>(
    s: &Setup,
    (a, b, mut row): ([T; 3], [T; 3], [T; 3]),
    emit: &mut impl FnMut(Span) -> Result<(), E>,
) -> Result<(), E> {
    let (w, h) = s.size;
    for j in 0..h {
        if j > 0 {
            row = [row[0] + b[0], row[1] + b[1], row[2] + b[2]];
        }
        let mut f = row;
        let (mut first, mut last) = (-1, -1);
        for i in 0..w {
            if (f[0] | f[1] | f[2]) >= T::ZERO {
                if first < 0 {
                    first = i;
                }
                last = i;
            }
            if i + 1 < w {
                f = [f[0] + a[0], f[1] + a[1], f[2] + a[2]];
            }
        }
        if first >= 0 {
            emit(Span {
                y: s.origin.1 + j,
                x_start: s.origin.0 + first,
                x_end: s.origin.0 + last + 1,
            })?;
        }
    }
    Ok(())
}

/// Calls `emit` with each row's span of the snapped `v` inside `clip`.
pub(super) fn barycentric_spans<E>(
    v: &[Vertex; 3],
    precision: SubpixelPrecision,
    clip: &Rectangle,
    emit: &mut impl FnMut(Span) -> Result<(), E>,
) -> Result<(), E> {
    let Some(s) = setup(v, precision, clip) else {
        return Ok(());
    };
    if let Some(c) = narrow::<i32>(&s) {
        run(&s, c, emit)
    } else if let Some(c) = narrow::<i64>(&s) {
        run(&s, c, emit)
    } else {
        // Unreachable: every value fits in i64 (module docs).
        Ok(())
    }
}
