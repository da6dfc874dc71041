//! Exact scanline fill with an active edge table, on the raster core's
//! [`Edge`].
//!
//! Each edge that crosses a row's sample line splits the row at its
//! threshold column (see [`Edge`] for the sampling rule and the exact O(1)
//! stepping); the winding number of a pixel is the sum of the directions
//! (+1 down, -1 up) of the edges whose threshold is at or left of it,
//! exactly the winding number of the nudged centre. Edges are stored
//! pointing down, in the polygon's frame (the clip's pixels inside its
//! bounding box), each started on its first row inside the frame when it
//! is built, so activating it costs nothing.
//!
//! Edges step in `i64`, exact for any vertices in range (their setup
//! divides in 32 bits when the operands fit, in 128 only for products of
//! two 33-bit differences).

use core::cmp::Ordering;

use embedded_graphics_core::primitives::Rectangle;
use heapless::Vec;

use crate::{
    raster::{edge::Edge, frame::Frame},
    span::Span,
    vertex::Vertex,
};

use super::FillRule;

/// An edge of the polygon with its direction.
#[derive(Debug, Clone, Copy)]
struct Directed {
    edge: Edge<i64>,
    /// +1 if the edge runs down (y growing), -1 if up.
    winding: i8,
}

impl Directed {
    fn new(frame: &Frame, from: Vertex, to: Vertex) -> Option<Self> {
        let (a, b) = (frame.relative::<i64>(from)?, frame.relative::<i64>(to)?);
        let (top, bottom, winding) = match a.1.cmp(&b.1) {
            Ordering::Less => (a, b, 1),
            Ordering::Greater => (b, a, -1),
            Ordering::Equal => return None,
        };
        let edge = Edge::new(top, bottom, 0)?;
        (edge.first_row < frame.height).then_some(Self { edge, winding })
    }
}

/// Calls `emit` with the spans of `vertices` (a closed polygon) inside
/// `clip` under `rule`, top to bottom and left to right; the caller has
/// checked that there are at most `N` vertices.
pub(crate) fn polygon_spans<const N: usize, E>(
    vertices: &[Vertex],
    rule: FillRule,
    clip: &Rectangle,
    mut emit: impl FnMut(Span) -> Result<(), E>,
) -> Result<(), E> {
    let Some(frame) = Frame::around(vertices, clip) else {
        return Ok(());
    };
    let mut edges: Vec<Directed, N> = Vec::new();
    for (k, &from) in vertices.iter().enumerate() {
        let to = vertices[(k + 1) % vertices.len()];
        if let Some(e) = Directed::new(&frame, from, to) {
            // Cannot fail: at most one edge per vertex.
            if edges.push(e).is_err() {
                return Ok(());
            }
        }
    }
    edges.sort_unstable_by_key(|e| e.edge.first_row);

    let mut active: Vec<usize, N> = Vec::new();
    let mut next = 0;
    let Some(mut row) = edges.first().map(|e| e.edge.first_row) else {
        return Ok(());
    };
    while row < frame.height {
        // Activate the edges starting on this row.
        while edges.get(next).is_some_and(|e| e.edge.first_row <= row) {
            // Cannot fail: `active` holds distinct edges.
            let _ = active.push(next);
            next += 1;
        }
        if active.is_empty() {
            // Jump to the next edge, if any.
            match edges.get(next) {
                Some(e) => row = e.edge.first_row,
                None => break,
            }
            continue;
        }
        sort_by_crossing(&mut active, &edges);
        emit_row(row, &active, &edges, rule, &frame, &mut emit)?;
        active.retain(|&k| edges[k].edge.last_row > row);
        for &k in active.iter() {
            edges[k].edge.step();
        }
        row += 1;
    }
    Ok(())
}

/// Insertion sort: from one row to the next the order barely changes.
fn sort_by_crossing(active: &mut [usize], edges: &[Directed]) {
    for i in 1..active.len() {
        let mut j = i;
        while j > 0 && edges[active[j - 1]].edge.crossing() > edges[active[j]].edge.crossing() {
            active.swap(j - 1, j);
            j -= 1;
        }
    }
}

/// Sweeps the sorted thresholds of `row`, emitting each maximal run of
/// pixels the rule fills, clipped to the frame. Edges sharing a threshold
/// are applied together, so a run never splits where one edge ends and
/// another begins.
fn emit_row<E>(
    row: i32,
    active: &[usize],
    edges: &[Directed],
    rule: FillRule,
    frame: &Frame,
    emit: &mut impl FnMut(Span) -> Result<(), E>,
) -> Result<(), E> {
    let width = i64::from(frame.width);
    // A sum of at most `N` edge directions of +-1, and the `N` edge records
    // (56 bytes each) live on the stack, so `|winding| <= N < 2^31`: the
    // sum cannot overflow.
    let mut winding: i32 = 0;
    let mut run_start = None;
    let mut k = 0;
    while let Some(&first) = active.get(k) {
        let x = edges[first].edge.threshold();
        let was_in = rule.fills(winding);
        while let Some(e) = active
            .get(k)
            .map(|&i| &edges[i])
            .filter(|e| e.edge.threshold() == x)
        {
            winding += i32::from(e.winding);
            k += 1;
        }
        match (was_in, rule.fills(winding)) {
            (false, true) => run_start = Some(x),
            (true, false) => {
                let start = run_start.take().unwrap_or(x).max(0);
                let end = x.min(width);
                // Inside the frame, so inside the clip: fits i32.
                if let (true, Ok(start), Ok(end)) =
                    (start < end, i32::try_from(start), i32::try_from(end))
                {
                    emit(Span {
                        y: frame.origin.y + row,
                        x_start: frame.origin.x + start,
                        x_end: frame.origin.x + end,
                    })?;
                }
            }
            _ => {}
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The storage figure in the docs: 56 bytes per edge record (five
    /// 64-bit fields, the row range and the winding, 8-byte aligned).
    #[test]
    fn edge_record_is_56_bytes() {
        assert_eq!(core::mem::size_of::<Directed>(), 56);
    }
}
