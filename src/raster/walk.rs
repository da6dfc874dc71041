//! The two-edge walk: the rows between a left and a right edge.
//!
//! Every filled shape whose rows are each crossed by exactly two edges is
//! walked here: a triangle (its long edge on one side, its two short
//! edges in turn on the other), a thick line's parallelogram and any
//! y-monotone polygon (a chain of edges from the top vertex to the bottom
//! one each way round, see [`walk_chains`]). Each row's span runs from the
//! left edge's threshold to the right one's (for a polygon, the lesser to
//! the greater), clipped to the frame; the edges step in O(1) a row
//! ([`Edge`]), and the span goes to the sink as three numbers.

use super::{edge::Edge, frame::Frame, wide::Narrow};
use crate::span::Span;

/// `emit` taking a span's three numbers (`y`, `x_start`, `x_end`), as the
/// walks call it: to a sink's closure that is not inlined into the row
/// loop they go in registers, where a `Span` went through the stack (a
/// 16 px triangle on a Cortex-M4, `.ci/icount`: 1,781 instructions with a
/// `Span`, 1,568 with its numbers).
///
/// This one holds a reference to `emit`: what the band walk, the chain
/// walk and 32-bit ARM use. See [`by_numbers`] for hosts. Always
/// inlined, and so is its closure: left to the compiler, the chain walk
/// on a Cortex-M4 called the closure, with the sink's fill in it, once a
/// row.
#[inline(always)]
pub(crate) fn by_numbers_ref<E>(
    emit: &mut impl FnMut(Span) -> Result<(), E>,
) -> impl FnMut(i32, i32, i32) -> Result<(), E> + '_ {
    #[inline(always)]
    move |y, x_start, x_end| emit(Span { y, x_start, x_end })
}

/// [`by_numbers_ref`] holding `emit` itself, as hosts walk a whole
/// triangle: the row loop then receives the sink's closure behind its own
/// `&mut`, which nothing else writes, and keeps the closure's state (the
/// sink, the colour) in registers across the bytes a span stores; through
/// the second reference it reloaded them after every span (x86-64, random
/// triangles drawn on the framebuffer, instructions counted by callgrind:
/// medium 5,435 a triangle with the reference, 5,211 without; large
/// 16,619 and 15,968). The closure is always inlined, as are the sink
/// calls behind it on hosts (the framebuffer's `fill_span` and
/// `fill_solid`, `DrawTargetSink::fill_span`): left to the compiler, any
/// growth of the fill made it call the sink once a row instead, for about
/// 15 instructions more a row.
///
/// Not on 32-bit ARM: there the sink's fill is then inlined into the row
/// loop, whose registers are already taken by the two edges, and it
/// spills. A Cortex-M4 (`.ci/icount`) drew the 240 px triangle in 1.36
/// instructions a pixel instead of 1.48, but the 16 px one in 1,661
/// instead of 1,568, the built-in scene in 630,311 instead of 624,578,
/// and a single 16 px triangle (`.ci/itrace`) in 2,120 instead of 1,588:
/// its spans under 16 px were filled at 6 instructions a pixel instead of
/// 2.5, with the colour and a loop value reloaded for every pixel.
#[cfg(not(target_arch = "arm"))]
#[inline(always)]
pub(crate) fn by_numbers<E>(
    mut emit: impl FnMut(Span) -> Result<(), E>,
) -> impl FnMut(i32, i32, i32) -> Result<(), E> {
    #[inline(always)]
    move |y, x_start, x_end| emit(Span { y, x_start, x_end })
}

/// Emits columns `x0..x1` (relative to `frame`, within `0..=width`) of
/// the frame's row `row`, if there are any.
#[inline(always)]
pub(crate) fn emit_columns<E>(
    frame: &Frame,
    row: i32,
    x0: i32,
    x1: i32,
    emit: &mut impl FnMut(i32, i32, i32) -> Result<(), E>,
) -> Result<(), E> {
    if x0 < x1 {
        // Inside the frame, which lies inside the clip: no overflow.
        emit(
            frame.origin.y + row,
            frame.origin.x + x0,
            frame.origin.x + x1,
        )?;
    }
    Ok(())
}

/// Emits rows `from..=end` between `left` and `right`, both positioned on
/// row `from`; leaves both on `end` (never steps past it, so values stay
/// within the edges' bounds). The side is data here, not a type, and the
/// loop does not depend on it. With `ORDERED` false, the two edges may be
/// on either side, and cross: each row's span runs between the lesser
/// and the greater threshold (two more selects a row).
///
/// With `LEFT_CLAMP` false, the caller shows that no threshold is
/// negative (the frame starts at the shape's first column, as
/// [`Frame::of_small_triangle`] does), and the spans are not clamped on
/// the left. On x86-64 that is 2 instructions a row fewer (random
/// triangles drawn by `draw_spans`, instructions counted by callgrind:
/// small 1,220 a triangle → 1,180, medium 3,989 → 3,857, the mesh 1,090
/// → 1,056); 32-bit ARM clamps in one instruction and keeps a single copy
/// of the loop.
///
/// Always inlined, into one out-of-line function per shape, defined in
/// the shape's own module (`triangle_rows`, `chain_rows`): out of line,
/// the loop has its own registers for the edges and the sink (left to the
/// compiler, it was inlined into the one-shot triangle walk once the band
/// walk also called it, and the flat-triangle rows of `.ci/icount` took
/// 8 % more instructions on a Cortex-M4: 240 px 1.54 instructions a pixel
/// against 1.49 then). In the caller's module, the out-of-line copy lands
/// in the caller's codegen unit, where the compiler can fit the call to
/// it: called from another module's copy, a 16 px triangle took 1,286
/// instructions instead of 1,250 (`.ci/icount`), the same code compiled
/// into other registers.
#[inline(always)]
pub(crate) fn rows<const ORDERED: bool, const LEFT_CLAMP: bool, T: Narrow, E>(
    frame: &Frame,
    left: &mut Edge<T>,
    right: &mut Edge<T>,
    from: i32,
    end: i32,
    emit: &mut impl FnMut(i32, i32, i32) -> Result<(), E>,
) -> Result<(), E> {
    let Some(width) = T::narrow(frame.width.into()) else {
        return Ok(());
    };
    // Stepped in locals, which stay in registers across `emit`, and
    // written back at the end.
    let (mut l, mut r) = (*left, *right);
    let mut row = from;
    while row <= end {
        let (tl, tr) = (l.threshold(), r.threshold());
        let (x0, x1) = match ORDERED {
            true => (tl, tr),
            false => (tl.min(tr), tl.max(tr)),
        };
        let x0 = match LEFT_CLAMP {
            true => x0.max(T::ZERO),
            false => {
                debug_assert!(x0 >= T::ZERO);
                x0
            }
        };
        let x1 = x1.min(width);
        if x0 < x1 {
            if let (Some(x0), Some(x1)) = (x0.to_i32(), x1.to_i32()) {
                emit_columns(frame, row, x0, x1, emit)?;
            }
        }
        if row == end {
            break;
        }
        l.step();
        r.step();
        row += 1;
    }
    (*left, *right) = (l, r);
    Ok(())
}

/// Defines `$name`, [`rows`] out of line, in the module that invokes it:
/// one copy per shape, in the shape's own codegen unit (see [`rows`]).
macro_rules! rows_out_of_line {
    ($(#[$doc:meta])* $name:ident) => {
        $(#[$doc])*
        #[inline(never)]
        fn $name<const ORDERED: bool, const LEFT_CLAMP: bool, T: $crate::raster::wide::Narrow, E>(
            frame: &$crate::raster::frame::Frame,
            left: &mut $crate::raster::edge::Edge<T>,
            right: &mut $crate::raster::edge::Edge<T>,
            from: i32,
            end: i32,
            emit: &mut impl FnMut(i32, i32, i32) -> Result<(), E>,
        ) -> Result<(), E> {
            $crate::raster::walk::rows::<ORDERED, LEFT_CLAMP, T, E>(frame, left, right, from, end, emit)
        }
    };
}
pub(crate) use rows_out_of_line;

/// Walks the rows of a shape outlined by two chains of edges that run from
/// its top to its bottom, `left` on the left and `right` on the right
/// (with `ORDERED` false, on either side, crossing or not: see [`rows`]),
/// each edge set up on its first row in the frame (as `Edge::new(top,
/// bottom, 0)` does) and the edges that cross no row left out. Down each
/// chain, every row of the shape is crossed by exactly one edge (the next
/// edge starts on the row after the last one's end), and both chains
/// start on the same row; a pair of chains breaking this (which no
/// y-monotone outline does) ends the walk there.
///
/// Each stretch of rows between two changes of edge is one call of
/// [`rows`], as a triangle's halves are.
pub(crate) fn walk_chains<const ORDERED: bool, T: Narrow, E>(
    frame: &Frame,
    mut left: impl Iterator<Item = Edge<T>>,
    mut right: impl Iterator<Item = Edge<T>>,
    emit: &mut impl FnMut(i32, i32, i32) -> Result<(), E>,
) -> Result<(), E> {
    let last = frame.height - 1;
    let (Some(mut l), Some(mut r)) = (left.next(), right.next()) else {
        return Ok(());
    };
    let mut row = l.first_row;
    if r.first_row != row {
        return Ok(());
    }
    loop {
        let end = l.last_row.min(r.last_row).min(last);
        chain_rows::<ORDERED, true, T, E>(frame, &mut l, &mut r, row, end, emit)?;
        if end >= last {
            return Ok(());
        }
        row = end + 1;
        if !(move_on(&mut l, &mut left, end) && move_on(&mut r, &mut right, end)) {
            return Ok(());
        }
    }
}

rows_out_of_line!(
    /// [`rows`] out of line, for [`walk_chains`].
    chain_rows
);

/// Moves `edge`, positioned on row `end`, on to the next row: to the next
/// edge of its `chain` if it ends at `end`, else one step. `false` if the
/// chain has no edge starting there.
#[inline(always)]
fn move_on<T: Narrow>(
    edge: &mut Edge<T>,
    chain: &mut impl Iterator<Item = Edge<T>>,
    end: i32,
) -> bool {
    if edge.last_row != end {
        // It crosses the next row: its last row is past `end`.
        edge.step();
        return true;
    }
    match chain.next() {
        Some(next) if next.first_row == end + 1 => {
            *edge = next;
            true
        }
        _ => false,
    }
}
