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
//! Edges step in `i32` when every vertex lies within `2^29` raw units of
//! the frame's origin (the polygon's box spans under 131,072 px a side),
//! as a triangle's do, and in `i64` otherwise, exact for any vertices in
//! range (their setup divides in 32 bits when the operands fit, and takes
//! its products in `i64`, which the edge's bounds keep below `2^55`).

use core::cmp::Ordering;

use embedded_graphics_core::primitives::Rectangle;
use heapless::Vec;

use crate::{
    raster::{edge::Edge, frame::Frame, wide::Narrow},
    span::Span,
    vertex::Vertex,
};

use super::FillRule;

/// An edge of the polygon with its direction, stepped in `T`.
#[derive(Debug, Clone, Copy)]
struct Directed<T> {
    edge: Edge<T>,
    /// +1 if the edge runs down (y growing), -1 if up.
    winding: i8,
}

impl<T: Narrow> Directed<T> {
    /// The edge `from -> to`, `None` if it is horizontal, crosses no row
    /// of the frame, or its ends do not fit `T` relative to the frame.
    fn new(frame: &Frame, from: Vertex, to: Vertex) -> Option<Self> {
        let (a, b) = (frame.relative::<T>(from)?, frame.relative::<T>(to)?);
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
    emit: impl FnMut(Span) -> Result<(), E>,
) -> Result<(), E> {
    let Some(frame) = Frame::around(vertices, clip) else {
        return Ok(());
    };
    match frame.fits_i32() {
        true => scan::<i32, N, E>(&frame, vertices, rule, emit),
        false => scan::<i64, N, E>(&frame, vertices, rule, emit),
    }
}

/// [`polygon_spans`] with edges stepped in `T`, for a frame whose
/// relative coordinates fit it. Out of line, so that the two widths'
/// edge tables never share the stack: the larger, `i64`'s, bounds it.
#[inline(never)]
fn scan<T: Narrow, const N: usize, E>(
    frame: &Frame,
    vertices: &[Vertex],
    rule: FillRule,
    mut emit: impl FnMut(Span) -> Result<(), E>,
) -> Result<(), E> {
    // A copy of its own, which no store through `emit` can alias: read
    // through the reference instead, the Cortex-M4 took 5,854
    // instructions an 18 px hexagon rather than 5,808 (`.ci/icount`).
    let frame = &{ *frame };
    let mut edges: Vec<Directed<T>, N> = Vec::new();
    for (k, &from) in vertices.iter().enumerate() {
        let to = vertices[(k + 1) % vertices.len()];
        if let Some(e) = Directed::new(frame, from, to) {
            // Cannot fail: at most one edge per vertex.
            if edges.push(e).is_err() {
                return Ok(());
            }
        }
    }
    sort_by_first_row(&mut edges);

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
        emit_row(row, &active, &edges, rule, frame, &mut emit)?;
        active.retain(|&k| edges[k].edge.last_row > row);
        for &k in active.iter() {
            edges[k].edge.step();
        }
        row += 1;
    }
    Ok(())
}

/// Sorts `edges` by their first row: a heapsort, in place and in
/// `O(n log n)`, whose code is a few hundred bytes in each edge width.
/// The standard library's sort, once per width, took 4.4 KB more flash
/// in the whole firmware (`.ci/codesize` at "s": 84,492 bytes against
/// 80,124).
fn sort_by_first_row<T: Copy>(edges: &mut [Directed<T>]) {
    let key = |edges: &[Directed<T>], i: usize| edges.get(i).map(|e| e.edge.first_row);
    // Moves `root` down the heap `..end` to where its children's first
    // rows are no later than its own.
    let sift = |edges: &mut [Directed<T>], mut root: usize, end: usize| {
        // `root < end <= len`, so `2 root + 2` cannot overflow.
        while 2 * root + 1 < end {
            let mut child = 2 * root + 1;
            if child + 1 < end && key(edges, child) < key(edges, child + 1) {
                child += 1;
            }
            if key(edges, root) >= key(edges, child) {
                break;
            }
            edges.swap(root, child);
            root = child;
        }
    };
    let n = edges.len();
    for root in (0..n / 2).rev() {
        sift(edges, root, n);
    }
    for end in (1..n).rev() {
        edges.swap(0, end);
        sift(edges, 0, end);
    }
}

/// Insertion sort: from one row to the next the order barely changes.
fn sort_by_crossing<T: Narrow>(active: &mut [usize], edges: &[Directed<T>]) {
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
fn emit_row<T: Narrow, E>(
    row: i32,
    active: &[usize],
    edges: &[Directed<T>],
    rule: FillRule,
    frame: &Frame,
    emit: &mut impl FnMut(Span) -> Result<(), E>,
) -> Result<(), E> {
    let Some(width) = T::narrow(frame.width.into()) else {
        return Ok(());
    };
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
                let start = run_start.take().unwrap_or(x).max(T::ZERO);
                let end = x.min(width);
                // Inside the frame, so inside the clip: fits i32.
                if let (true, Some(start), Some(end)) = (start < end, start.to_i32(), end.to_i32())
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

    /// The storage figure in the docs: 56 bytes per edge record in `i64`
    /// (five 64-bit fields, the row range and the winding, 8-byte
    /// aligned), the larger of the two widths; 32 in `i32`.
    #[test]
    fn edge_records_are_56_and_32_bytes() {
        assert_eq!(core::mem::size_of::<Directed<i64>>(), 56);
        assert_eq!(core::mem::size_of::<Directed<i32>>(), 32);
    }
}
