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
    raster::{
        edge::Edge,
        frame::Frame,
        walk::{by_numbers_ref, emit_columns},
        wide::Narrow,
    },
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
///
/// The table is one array of edge records in three parts: the active
/// edges, sorted by their crossing of the current row; the slots of
/// edges that have ended; the edges still to come, sorted by their first
/// row. An edge is activated by swapping it into the first ended slot
/// (it stays where it is if none has ended), and on a row where edges
/// end, the edges that go on are swapped forward over them. Records move
/// by value rather than through a list of indices: a row reads each
/// active edge once, with no second lookup.
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
    let mut emit = by_numbers_ref(&mut emit);
    let emit = &mut |y: i32, x0: i32, x1: i32| match cfg!(target_pointer_width = "32") {
        true => fill_out_of_line(&mut emit, y, x0, x1),
        false => emit(y, x0, x1),
    };
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
    let edges = edges.as_mut_slice();
    sort_by_first_row(edges);

    // Edges `..active` are active; `next..` are still to come.
    let (mut active, mut next) = (0, 0);
    let Some(mut row) = edges.first().map(|e| e.edge.first_row) else {
        return Ok(());
    };
    while row < frame.height {
        // Activate the edges starting on this row.
        while edges.get(next).is_some_and(|e| e.edge.first_row <= row) {
            // `active <= next`: the slot is free, or the edge's own (no
            // edge has ended yet).
            if active < next {
                swap_apart(edges, active, next);
            }
            active += 1;
            next += 1;
        }
        let Some(current) = edges.get_mut(..active).filter(|a| !a.is_empty()) else {
            // Jump to the next edge, if any.
            match edges.get(next) {
                Some(e) => row = e.edge.first_row,
                None => break,
            }
            continue;
        };
        sort_by_crossing(current);
        emit_row(row, current, rule, frame, emit)?;
        // Step the edges that go on, in place (an edge never steps past
        // its last row); on the few rows where some end, close their gaps.
        let mut ended = false;
        for e in current.iter_mut() {
            match e.edge.last_row > row {
                true => e.edge.step(),
                false => ended = true,
            }
        }
        let mut kept = current.len();
        if ended {
            kept = 0;
            for k in 0..current.len() {
                if current[k].edge.last_row > row {
                    if kept < k {
                        swap_apart(current, kept, k);
                    }
                    kept += 1;
                }
            }
        }
        active = kept;
        row += 1;
    }
    Ok(())
}

/// `emit(y, x0, x1)`, out of line: on 32-bit cores, the sweep calls the
/// sink's fill for each span rather than have it inlined.
///
/// Inlined into [`emit_row`], the framebuffer's fill took the registers
/// of the sweep's own state, which it then kept on the stack, and part of
/// the fill's setup ran at each row's start as well as after each span
/// (519 times for the pentagram's 320 spans). Called, on
/// a Cortex-M4 (`.ci/icount`): the concave star 75,523 → 68,312
/// instructions, the pentagram 77,629 → 69,762, random octagons 6,275 →
/// 5,993, the built-in scene 479,405 → 472,680 (in 16-row bands, where
/// the band's writer is a call already, 778,445 → 779,056); ARMv6-M the
/// star 104,331 → 102,075 and the scene 962,269 → 960,703; RISC-V the
/// star 74,937 → 72,750 and the scene 535,156 → 533,161. On x86-64 the
/// polygons bench could not tell the two apart (its noise is about 10 %
/// there), so hosts keep the fill inlined.
#[inline(never)]
fn fill_out_of_line<E>(
    emit: &mut impl FnMut(i32, i32, i32) -> Result<(), E>,
    y: i32,
    x0: i32,
    x1: i32,
) -> Result<(), E> {
    emit(y, x0, x1)
}

/// Swaps records `i < j` of `edges` (nothing if `j` is out of bounds).
/// Two distinct records, so the swap moves them through registers: the
/// slice's own `swap`, which allows `i == j`, called `memmove` for them
/// on a Cortex-M4.
#[inline(always)]
fn swap_apart<T: Copy>(edges: &mut [Directed<T>], i: usize, j: usize) {
    let (head, tail) = edges.split_at_mut(j.min(edges.len()));
    if let (Some(a), Some(b)) = (head.get_mut(i), tail.first_mut()) {
        core::mem::swap(a, b);
    }
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
            swap_apart(edges, root, child);
            root = child;
        }
    };
    let n = edges.len();
    for root in (0..n / 2).rev() {
        sift(edges, root, n);
    }
    for end in (1..n).rev() {
        swap_apart(edges, 0, end);
        sift(edges, 0, end);
    }
}

/// Insertion sort by crossing: from one row to the next the order barely
/// changes, so this is one comparison an edge on most rows.
fn sort_by_crossing<T: Narrow>(active: &mut [Directed<T>]) {
    for i in 1..active.len() {
        let mut j = i;
        while j > 0 && active[j - 1].edge.crossing_key() > active[j].edge.crossing_key() {
            swap_apart(active, j - 1, j);
            j -= 1;
        }
    }
}

/// Sweeps the sorted thresholds of `row`, emitting each maximal run of
/// pixels the rule fills, clipped to the frame. Edges sharing a threshold
/// are applied together, so a run never splits where one edge ends and
/// another begins. Each edge's threshold is found once, and the rule is
/// a mask of the winding number ([`FillRule::winding_mask`]), not a
/// branch.
fn emit_row<T: Narrow, E>(
    row: i32,
    active: &[Directed<T>],
    rule: FillRule,
    frame: &Frame,
    emit: &mut impl FnMut(i32, i32, i32) -> Result<(), E>,
) -> Result<(), E> {
    let Some(width) = T::narrow(frame.width.into()) else {
        return Ok(());
    };
    let mask = rule.winding_mask();
    // A sum of at most `N` edge directions of +-1, and the `N` edge records
    // (56 bytes each) live on the stack, so `|winding| <= N < 2^31`: the
    // sum cannot overflow.
    let mut winding: i32 = 0;
    // Whether the pixels before the current threshold are filled, and
    // where their run started.
    let (mut inside, mut start) = (false, T::ZERO);
    let mut edges = active.iter();
    let Some(mut edge) = edges.next() else {
        return Ok(());
    };
    let mut x = edge.edge.threshold();
    loop {
        winding += i32::from(edge.winding);
        let next = edges.next().map(|e| (e, e.edge.threshold()));
        if next.is_none_or(|(_, nx)| nx != x) {
            // The last edge at `x`: the pixels from `x` on have `winding`.
            let filled = winding & mask != 0;
            if filled && !inside {
                start = x;
            } else if inside && !filled {
                let (from, to) = (start.max(T::ZERO), x.min(width));
                // Inside the frame, so inside the clip: fits i32.
                if let (true, Some(from), Some(to)) = (from < to, from.to_i32(), to.to_i32()) {
                    emit_columns(frame, row, from, to, emit)?;
                }
            }
            inside = filled;
        }
        match next {
            Some((e, nx)) => (edge, x) = (e, nx),
            None => return Ok(()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The storage figure in the docs: 56 bytes per edge record in `i64`
    /// (five 64-bit fields, the row range and the winding: 52 bytes,
    /// rounded up to the 8-byte alignment of `i64` on Cortex-M and
    /// x86-64; 52 where `i64` is 4-byte aligned, as on i686), the larger
    /// of the two widths; 32 in `i32`.
    #[test]
    fn edge_records_are_56_and_32_bytes() {
        let wide = match core::mem::align_of::<i64>() {
            8 => 56,
            _ => 52,
        };
        assert_eq!(core::mem::size_of::<Directed<i64>>(), wide);
        assert_eq!(core::mem::size_of::<Directed<i32>>(), 32);
    }
}
