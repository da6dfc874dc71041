//! Edge walking with a flat-bottom/flat-top split and 16.16 fixed-point
//! edges.
//!
//! Rows are decided exactly from the raw y coordinates: row `j` (centre
//! `yc = 4096 j + 2048` raw) is scanned iff `y_top <= yc < y_bottom`, the
//! upper part (`yc < y_mid`) between the long edge and the edge top→mid,
//! the lower part between the long edge and mid→bottom. Each edge is
//! walked from its upper end: its x at its first row is computed exactly
//! and rounded down to 1/65536 px, and every further row adds the slope,
//! `dx / dy` per row rounded down to 1/65536 px. The x at any row is
//! `start + n * slope`, so clipping rows away does not change it.
//!
//! Values: x is at most `2^19` px (`2^35` units), the start's product
//! `dx (yc - y_a)` and the slope's `4096 dx` are below `2^48`, and
//! `n * slope` is at most `|dx| + n` units, so `i64` holds every value
//! (the orientation test alone needs `i128`, for differences over `2^31`
//! raw units).

use embedded_graphics_core::primitives::Rectangle;

use crate::{clip::Bounds, span::Span, vertex::Vertex};

/// Fractional bits of x positions and slopes.
const FRAC: u32 = 16;

/// The first row whose centre is at or below raw `y`.
fn row_of(y: i64) -> i64 {
    (y - 2048 + 4095) >> 12
}

/// One edge, walked down from its upper end.
#[derive(Clone, Copy)]
struct Edge {
    /// Its first row, and x there in 16.16.
    first: i64,
    start: i64,
    /// x change per row in 16.16, rounded down.
    slope: i64,
    /// Its ends' x range in 16.16, where its walked positions are kept.
    low: i64,
    high: i64,
}

impl Edge {
    /// The edge from `a` to `b` (raw, `a.1 < b.1`).
    fn new(a: (i64, i64), b: (i64, i64)) -> Self {
        let first = row_of(a.1);
        let dy = (b.1 - a.1).max(1);
        // |dx| < 2^36 units and 0 <= yc - a.1 < 4096: products below 2^48.
        let dx = (b.0 - a.0) << (FRAC - 12);
        let yc = first * 4096 + 2048;
        let (xa, xb) = (a.0 << (FRAC - 12), b.0 << (FRAC - 12));
        Self {
            first,
            start: xa + (dx * (yc - a.1)).div_euclid(dy),
            slope: (dx * 4096).div_euclid(dy),
            low: xa.min(xb),
            high: xa.max(xb),
        }
    }

    /// A walked position `x` kept within the edge's x range: the drift
    /// (whole pixels on edges taller than 65,536 px) never carries it
    /// past the edge's ends, and so never past the triangle's bounding
    /// box. It depends on the edge alone: two triangles sharing the edge
    /// keep the same positions, and stay watertight.
    #[inline(always)]
    fn kept(&self, x: i64) -> i64 {
        x.max(self.low).min(self.high)
    }

    /// x at row `j >= first`.
    fn at(&self, j: i64) -> i64 {
        self.start + (j - self.first) * self.slope
    }
}

/// Calls `emit` with each row's span of the snapped `v` inside `clip`.
pub(super) fn edge_walk_spans<E>(
    v: &[Vertex; 3],
    clip: &Rectangle,
    emit: &mut impl FnMut(Span) -> Result<(), E>,
) -> Result<(), E> {
    let Some(([top, mid, bot], cross)) = super::sorted_with_turn(v, 0) else {
        return Ok(());
    };
    let long_left = cross > 0;
    let c = Bounds::of(clip);
    let long = Edge::new(top, bot);
    let halves = [
        (row_of(top.1), row_of(mid.1), (top, mid)),
        (row_of(mid.1), row_of(bot.1), (mid, bot)),
    ];
    let half_px = 1i64 << (FRAC - 1);
    let one = 1i64 << FRAC;
    for (j0, j1, (a, b)) in halves {
        let (j0, j1) = (j0.max(c.y0), j1.min(c.y1));
        if j0 >= j1 {
            continue;
        }
        let short = Edge::new(a, b);
        let (left, right) = match long_left {
            true => (long, short),
            false => (short, long),
        };
        let (mut xl, mut xr) = (left.at(j0), right.at(j0));
        // The positions move linearly: if both ends of this part's rows
        // lie within the edges' ranges, every row does, and the rows are
        // not clamped (the test is loop-invariant).
        let within =
            |e: &Edge| e.kept(e.at(j0)) == e.at(j0) && e.kept(e.at(j1 - 1)) == e.at(j1 - 1);
        let keep = !(within(&left) && within(&right));
        for j in j0..j1 {
            if j > j0 {
                xl += left.slope;
                xr += right.slope;
            }
            let (xl, xr) = match keep {
                true => (left.kept(xl), right.kept(xr)),
                false => (xl, xr),
            };
            // Pixels whose centre i + 1/2 lies in [xl, xr).
            let i0 = ((xl - half_px + one - 1) >> FRAC).max(c.x0);
            let i1 = ((xr - half_px + one - 1) >> FRAC).min(c.x1);
            if let Some(span) = Span::from_wide(j, i0, i1) {
                emit(span)?;
            }
        }
    }
    Ok(())
}
