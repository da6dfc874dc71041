//! Bresenham edge walking on whole-pixel vertices.
//!
//! Each vertex moves to the pixel containing it (`floor` of its
//! coordinates). An edge from `(x0, y0)` to `(x1, y1)` with `y0 < y1` has,
//! on row `y0 + n`, the x `x0 + floor((2 n dx + dy) / (2 dy))` (nearest,
//! ties up), stepped row by row with Bresenham's error term: one add, one
//! compare and at most one correction per row. The walk starts at the
//! first visible row with one division, so clipping costs nothing per
//! skipped row. Values stay below `2^42`, so `i64` never overflows.

use embedded_graphics_core::primitives::Rectangle;

use crate::{clip::Bounds, span::Span, vertex::Vertex};

/// Bresenham state of one non-horizontal edge.
struct Edge {
    /// Rows `y0..=y1`.
    y0: i64,
    y1: i64,
    /// Current x and error term `e` in `0..2 dy`.
    x: i64,
    e: i64,
    /// Whole and fractional x step per row: `2 dx = q 2 dy + r`.
    q: i64,
    r: i64,
    two_dy: i64,
}

impl Edge {
    /// The edge between pixels `a` and `b` (`a.1 < b.1`), positioned at
    /// row `start >= a.1`.
    fn new(a: (i64, i64), b: (i64, i64), start: i64) -> Self {
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        let two_dy = 2 * dy;
        let num = 2 * (start - a.1) * dx + dy;
        Self {
            y0: a.1,
            y1: b.1,
            x: a.0 + num.div_euclid(two_dy),
            e: num.rem_euclid(two_dy),
            q: (2 * dx).div_euclid(two_dy),
            r: (2 * dx).rem_euclid(two_dy),
            two_dy,
        }
    }

    fn step(&mut self) {
        self.x += self.q;
        self.e += self.r;
        if self.e >= self.two_dy {
            self.e -= self.two_dy;
            self.x += 1;
        }
    }
}

/// Calls `emit` with each row's span of the snapped `v` inside `clip`.
pub(super) fn bresenham_walk_spans<E>(
    v: &[Vertex; 3],
    clip: &Rectangle,
    emit: &mut impl FnMut(Span) -> Result<(), E>,
) -> Result<(), E> {
    // Collinear pixels (also a triangle inside one pixel): nothing.
    let Some(([top, mid, bot], _)) = super::sorted_with_turn(v, 12) else {
        return Ok(());
    };
    let c = Bounds::of(clip);
    let (j0, j1) = (top.1.max(c.y0), bot.1.min(c.y1 - 1));
    if j0 > j1 {
        return Ok(());
    }
    let mut edges = [(top, mid), (mid, bot), (top, bot)]
        .map(|(a, b)| (a.1 < b.1).then(|| Edge::new(a, b, j0.clamp(a.1, b.1))));
    for j in j0..=j1 {
        let (mut lo, mut hi) = (i64::MAX, i64::MIN);
        for (k, (a, b)) in [(top, mid), (mid, bot), (top, bot)].into_iter().enumerate() {
            match &mut edges[k] {
                Some(e) if (e.y0..=e.y1).contains(&j) => {
                    if j > j0.max(e.y0) {
                        e.step();
                    }
                    lo = lo.min(e.x);
                    hi = hi.max(e.x);
                }
                None if a.1 == j => {
                    lo = lo.min(a.0.min(b.0));
                    hi = hi.max(a.0.max(b.0));
                }
                _ => {}
            }
        }
        let (i0, i1) = (lo.max(c.x0), (hi + 1).min(c.x1));
        if let Some(span) = Span::from_wide(j, i0, i1) {
            emit(span)?;
        }
    }
    Ok(())
}
