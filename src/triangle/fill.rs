//! The exact triangle fill: two active edges, split at the middle vertex.
//!
//! The vertices are sorted by `y` into `v0` (top), `v1`, `v2` (bottom).
//! Every row between `v0` and `v2` is crossed by the long edge `v0 v2` and
//! by one short edge: `v0 v1` above the middle vertex, `v1 v2` from it on
//! (a horizontal edge crosses no row, see [`Edge`]). The short edges lie
//! left of the long one iff `v0 -> v1 -> v2` turns counter-clockwise, so
//! each row's span is `threshold(left)..threshold(right)`, clipped to the
//! frame: exactly the pixels whose nudged centres are inside, the crate's
//! sampling rule. Each edge steps in O(1) per row; nothing is searched,
//! and nothing per pixel is done here at all: the sink fills the span.
//! Except on 32-bit ARM, a small triangle under 24 rows tall is walked
//! in one loop that takes each span between the lesser and the greater
//! threshold, with no orientation ([`walk_short`]).
//!
//! Widths: the whole setup and the stepping run in `i32` when the
//! vertices lie within `2^29` raw units (131,072 px) of the frame's
//! origin, which holds for every triangle whose bounding box spans under
//! 2^29 raw units a side; products are taken in `i64` and divided in 32 bits
//! when they fit. The common on-screen triangle, under 2^19 raw units
//! (128 px) a side with its top-left corner's first pixel centres inside
//! the clip, takes a shorter setup: its frame is found from those centres
//! alone ([`Frame::of_small_triangle`]), its relative coordinates need no
//! check, and every product fits `i32`, so its edges are set up unchecked
//! ([`Edge::new_small`]). Otherwise everything runs in `i64` (the edges'
//! setup products in `i64` too, which their bounds keep below 2^55; the
//! orientation's in `i128`), exact over the whole 20.12 range. A triangle outside the clip
//! costs its bounding-box tests (the small frame's, then the checked
//! one's), and nothing is set up.

use embedded_graphics_core::primitives::Rectangle;

use crate::{
    raster::{
        edge::Edge,
        frame::Frame,
        walk::{by_numbers_ref, emit_columns, rows_out_of_line},
        wide::{orientation, Narrow, Wide},
    },
    span::Span,
    vertex::Vertex,
};

#[cfg(not(target_arch = "arm"))]
use crate::raster::walk::by_numbers;

/// Calls `emit` with each row's span of the triangle `vertices` inside
/// `clip`, top to bottom, stopping at the first error.
pub(crate) fn triangle_spans<E>(
    vertices: &[Vertex; 3],
    clip: &Rectangle,
    emit: impl FnMut(Span) -> Result<(), E>,
) -> Result<(), E> {
    // Hosts hold the sink's closure, 32-bit ARM a reference to it (see
    // `by_numbers`).
    #[cfg(not(target_arch = "arm"))]
    let mut emit = by_numbers(emit);
    #[cfg(target_arch = "arm")]
    let mut emit = emit;
    #[cfg(target_arch = "arm")]
    let mut emit = by_numbers_ref(&mut emit);
    let mut v = *vertices;
    sort_by_y(&mut v);
    let placed = match cfg!(target_arch = "arm") {
        true => place(&v, clip),
        false => match Frame::of_small_triangle(&v, clip) {
            // Relative coordinates within -4096..SMALL: no overflow.
            Some((frame, p)) if p[2].1 - p[0].1 < SHORT => return walk_short(&frame, p, &mut emit),
            Some((frame, p)) => Some(Placed::Narrow(frame, p, true)),
            None => place_checked(&v, clip),
        },
    };
    match placed {
        Some(Placed::Narrow(frame, p, small)) => {
            // The small frame's relative coordinates are all over -4096
            // (its origin is the first centre at or after the box's left
            // side), so every crossing rounds up to column 0 or right of
            // it: hosts skip the left clamp there (see `rows`). 32-bit ARM
            // and builds for size keep one copy of the row loop
            // ([`ONE_ROW_LOOP`]).
            let left_clamp = ONE_ROW_LOOP || !small;
            walk(&frame, p, narrow_edges(small), left_clamp, &mut emit)
        }
        Some(Placed::Wide(frame)) => match relative::<i64>(&frame, &v) {
            Some(p) => walk(&frame, p, |a, b| Edge::new(a, b, 0), true, &mut emit),
            // Unreachable: every coordinate fits i64.
            None => Ok(()),
        },
        None => Ok(()),
    }
}

/// Whether the triangle walk keeps one copy of its row loop, with the
/// left clamp on every row: on 32-bit ARM, and on every target built for
/// size (`optimize_for_size`). Elsewhere a second copy, without the
/// clamp, walks the small frame's triangles.
///
/// On RISC-V (`riscv32imc`) at opt-level "s", with [`Edge::new`] out of
/// line there too: flat triangles' flash 9,816 → 7,320 bytes (`bash
/// .ci/codesize`), for 16 px triangles 1,755 → 1,795 instructions, 4 px
/// 736 → 753, the built-in scene 678,152 → 689,136 and in 16-row bands
/// 1,104,540 → 1,182,112 (`.ci/icount`). The clamp alone: 9,080 bytes,
/// 16 px 1,800, the scene 686,540. Dropping [`walk_short`] as well (then
/// for triangles under 4 rows) would have saved 976 bytes more, but took
/// 4 px triangles to 919.
const ONE_ROW_LOOP: bool = cfg!(target_arch = "arm") || cfg!(optimize_for_size);

/// The height (raw units) under which a small triangle takes
/// [`walk_short`] (not on 32-bit ARM): 24 rows.
const SHORT: i32 = 24 << 12;

/// Where a triangle is walked: its frame, and its vertices relative to it
/// in `i32` if they fit.
enum Placed {
    /// The vertices fit `i32`; `true` if they are those of
    /// [`Frame::of_small_triangle`].
    Narrow(Frame, [(i32, i32); 3], bool),
    /// They need `i64`.
    Wide(Frame),
}

/// Places the triangle `v` (sorted by `y`) inside `clip`; `None` if it
/// lights nothing there.
#[inline(always)]
fn place(v: &[Vertex; 3], clip: &Rectangle) -> Option<Placed> {
    match Frame::of_small_triangle(v, clip) {
        Some((frame, p)) => Some(Placed::Narrow(frame, p, true)),
        None => place_checked(v, clip),
    }
}

/// [`place`] by the checked frame ([`Frame::around`]) alone.
#[inline(always)]
fn place_checked(v: &[Vertex; 3], clip: &Rectangle) -> Option<Placed> {
    let frame = Frame::around(v, clip)?;
    Some(match relative::<i32>(&frame, v) {
        Some(p) => Placed::Narrow(frame, p, false),
        None => Placed::Wide(frame),
    })
}

/// A triangle's rows inside a clip, walked a window of rows at a time:
/// the edges are set up once, and each window continues where the last
/// one stopped, so a triangle drawn band by band costs what it costs
/// drawn whole. The same spans as [`triangle_spans`] (the same edges, the
/// same [`rows`](crate::raster::walk::rows) loop); only triangles on the 32-bit path are kept, the
/// rest are drawn whole in each window by [`triangle_spans`].
#[derive(Debug, Clone, Copy)]
pub(crate) struct TriangleRows {
    frame: Frame,
    long: Edge<i32>,
    /// The short edges still to walk: the upper one first.
    upper: Option<Edge<i32>>,
    lower: Option<Edge<i32>>,
    short_left: bool,
    /// The next row to emit, relative to the frame.
    row: i32,
}

impl TriangleRows {
    /// Sets up the walk of `vertices` inside `clip`, or `None` if the
    /// triangle lights nothing there or needs the 64-bit path.
    #[inline(always)]
    pub(crate) fn new(vertices: &[Vertex; 3], clip: &Rectangle) -> Option<Self> {
        let mut v = *vertices;
        sort_by_y(&mut v);
        let Placed::Narrow(frame, p, small) = place(&v, clip)? else {
            return None;
        };
        let turn = orientation(p[0], p[1], p[2]);
        if turn == 0 {
            return None;
        }
        let edge = narrow_edges(small);
        Some(Self {
            long: edge(p[0], p[2])?,
            upper: edge(p[0], p[1]),
            lower: edge(p[1], p[2]),
            short_left: turn < 0,
            row: 0,
            frame,
        })
    }

    /// Emits the triangle's spans on the rows above `until` (absolute)
    /// not emitted yet, top to bottom; `true` once every row is done.
    pub(crate) fn emit_until<E>(
        &mut self,
        until: i32,
        emit: &mut impl FnMut(Span) -> Result<(), E>,
    ) -> Result<bool, E> {
        let emit = &mut by_numbers_ref(emit);
        let frame = &self.frame;
        let last = frame.height - 1;
        // The last row of this window, relative to the frame.
        // Clamped into `i32` (`last` is one): the cast below is exact.
        let stop = (i64::from(until) - i64::from(frame.origin.y) - 1)
            .clamp(i64::from(i32::MIN), i64::from(last)) as i32;
        loop {
            let (short, upper) = match (&mut self.upper, &mut self.lower) {
                (Some(short), _) => (short, true),
                (None, Some(short)) => (short, false),
                (None, None) => return Ok(true),
            };
            let from = self.row.max(short.first_row);
            let half_end = short.last_row.min(last);
            let end = half_end.min(stop);
            if from > end {
                return Ok(false);
            }
            match self.short_left {
                true => triangle_rows::<true, true, _, _>(
                    frame,
                    short,
                    &mut self.long,
                    from,
                    end,
                    emit,
                )?,
                false => triangle_rows::<true, true, _, _>(
                    frame,
                    &mut self.long,
                    short,
                    from,
                    end,
                    emit,
                )?,
            }
            self.row = end + 1;
            if end < half_end {
                // Both edges move on to the window's next row.
                short.step();
                self.long.step();
                return Ok(false);
            }
            // This half is done; the other starts on the next row.
            match upper {
                true => self.upper = None,
                false => self.lower = None,
            }
            if end == last {
                (self.upper, self.lower) = (None, None);
                return Ok(true);
            }
            self.long.step();
        }
    }
}

/// How the 32-bit edges of a triangle are set up: unchecked
/// ([`Edge::new_small`]) for the frame and coordinates of
/// [`Frame::of_small_triangle`], else checked ([`Edge::new`]).
#[inline(always)]
fn narrow_edges(small: bool) -> impl Fn((i32, i32), (i32, i32)) -> Option<Edge<i32>> {
    #[inline(always)]
    move |a, b| match small {
        true => Edge::new_small(a, b),
        false => Edge::new(a, b, 0),
    }
}

/// The walk of a triangle under 24 rows tall framed by
/// [`Frame::of_small_triangle`] (`p` relative to it, sorted by `y`), on
/// every target but 32-bit ARM: the same edges and spans as [`walk`], in
/// one loop of its own.
///
/// Both edges of each row cross it on the triangle's outline, so the
/// span lies between their thresholds whichever side each is on: taken
/// as the lesser and the greater, with no orientation computed (a
/// degenerate triangle's edges cross each row at the same point, and its
/// spans are empty). The lower short edge, set up when the upper one
/// ends, takes over in the same function. This saves the orientation and
/// the two calls into [`rows`](crate::raster::walk::rows) with their
/// edges passed through memory, for two selects a row: random 4 px
/// triangles took about 10 % less time on x86-64 than through [`walk`]
/// (the tiny pool of `benches/pools.rs`, median of 5 runs: 46 ns a
/// triangle against 41). Since the height went from 4 rows to 24, with
/// one loop per short edge (a single test a row), the mesh's 10 px
/// cells take 0.87x the time and small 16 px triangles 0.98x (`python3
/// benches/pools_ab.py` against the commit before, medians of 11
/// alternating runs, `draw_spans`); callgrind, instructions a triangle:
/// tiny 450 → 438, small 1,066 → 972, the mesh 953 → 860. Taller ones
/// keep [`walk`], whose out-of-line row loop has registers to spare:
/// with 80 rows, the 64 px pool took 1.09x the time (this loop holds a
/// third vertex pair for the lower edge). 32-bit ARM keeps [`walk`] for
/// all: there this loop, inlined into the setup, spills (Cortex-M4,
/// `.ci/icount`, with it for every small triangle under 24 rows: setup
/// 268 → 228 instructions, but 16 px triangles 1,247 → 1,300, the mesh
/// 1,566 → 1,679; 4 px 605 → 569). RISC-V (`riscv32imc`, opt-level 3)
/// gains from it (`.ci/icount --target riscv32imc-unknown-none-elf`, 4
/// rows → 24: 16 px triangles 1,229 → 1,087 instructions, random 16 px
/// 1,166 → 1,016, the mesh 1,546 → 1,481, 64 px level).
#[inline(always)]
fn walk_short<E>(
    frame: &Frame,
    [a, b, c]: [(i32, i32); 3],
    emit: &mut impl FnMut(i32, i32, i32) -> Result<(), E>,
) -> Result<(), E> {
    let Some(mut long) = Edge::new_small(a, c) else {
        return Ok(());
    };
    let end = long.last_row.min(frame.height - 1);
    let (mut short, mut switch) = match Edge::new_small(a, b) {
        Some(upper) => (upper, upper.last_row),
        None => match Edge::new_small(b, c) {
            Some(lower) => (lower, i32::MAX),
            None => return Ok(()),
        },
    };
    let mut row = 0;
    loop {
        // The rows of this short edge, to the switch or the end.
        let stop = switch.min(end);
        loop {
            let (ts, tl) = (short.threshold(), long.threshold());
            // No threshold lies left of the small frame (see `rows`
            // without its left clamp).
            let x0 = ts.min(tl);
            debug_assert!(x0 >= 0);
            emit_columns(frame, row, x0, ts.max(tl).min(frame.width), emit)?;
            if row == stop {
                break;
            }
            long.step();
            short.step();
            row += 1;
        }
        if row == end {
            return Ok(());
        }
        long.step();
        short = match Edge::new_small(b, c) {
            Some(lower) => lower,
            None => return Ok(()),
        };
        switch = i32::MAX;
        row += 1;
    }
}

/// The vertices relative to the frame, in `T` if they fit its bound.
#[inline(always)]
fn relative<T: Wide>(frame: &Frame, v: &[Vertex; 3]) -> Option<[(T, T); 3]> {
    Some([
        frame.relative(v[0])?,
        frame.relative(v[1])?,
        frame.relative(v[2])?,
    ])
}

/// Sorts three vertices by `y`.
///
/// On hosts, a network of three compare-exchanges written as selects: the
/// order of random triangles' corners is unpredictable, and a
/// mispredicted branch costs more than the whole exchange. The selects
/// are `select_unpredictable`: written as plain `if`s, the compiler
/// turned the second exchange back into a branch (x86-64, random
/// triangles drawn by `draw_spans`: tiny 450 instructions a triangle →
/// 445, small 1,059 → 1,049, the mesh 945 → 936 by callgrind; mispredicted
/// branches a triangle, in the model of `valgrind --tool=cachegrind
/// --branch-sim=yes`, tiny 4.25 → 3.77, small 13.24 → 12.80). On 32-bit ARM,
/// branches: a Cortex-M predicts nothing and pays a taken branch a few
/// cycles, while each select is an `it` and a move, executed whatever the
/// order. On a Cortex-M4, a 16 px triangle's setup went from 314
/// instructions to 303 (`.ci/icount` when it was measured, corners
/// already in order), the whole triangle only from 1,808 to 1,806; over
/// all six orders of its corners, 256 against 271 on average in a
/// one-off probe.
///
/// Inlined on hosts: called out of line, the sorted array went back
/// through memory, and random 4 px and 16 px triangles took 10 % and 6 %
/// longer. Left out of line on ARM (the compiler's choice, seen in
/// `.ci/itrace`'s listing): inlined there, setup was 291 and the whole
/// 16 px triangle 1,802 (against 303 and 1,806, measured at the same
/// commit), for 68 more bytes of flash at opt-level "s".
#[cfg_attr(not(target_arch = "arm"), inline(always))]
fn sort_by_y(v: &mut [Vertex; 3]) {
    match cfg!(target_arch = "arm") {
        true => sort_by_y_branching(v),
        false => sort_by_y_selecting(v),
    }
}

/// [`sort_by_y`] with branches: insertion of the second and the third
/// vertex. Stable, as the selecting network is: the same exchanges.
#[inline(always)]
fn sort_by_y_branching(v: &mut [Vertex; 3]) {
    let y = |v: &Vertex| v.raw().1;
    if y(&v[1]) < y(&v[0]) {
        v.swap(0, 1);
    }
    if y(&v[2]) < y(&v[1]) {
        v.swap(1, 2);
        if y(&v[1]) < y(&v[0]) {
            v.swap(0, 1);
        }
    }
}

/// [`sort_by_y`] as three compare-exchanges written as selects.
#[inline(always)]
fn sort_by_y_selecting(v: &mut [Vertex; 3]) {
    let exchange = |a: Vertex, b: Vertex| {
        let swap = b.raw().1 < a.raw().1;
        (
            core::hint::select_unpredictable(swap, b, a),
            core::hint::select_unpredictable(swap, a, b),
        )
    };
    let (a, b) = exchange(v[0], v[1]);
    let (b, c) = exchange(b, v[2]);
    let (a, b) = exchange(a, b);
    *v = [a, b, c];
}

/// Walks the rows of the frame the triangle `p` (relative, sorted by `y`)
/// crosses; with `left_clamp` false, the caller shows that no threshold
/// lies left of the frame (see [`rows`]).
///
/// [`rows`]: crate::raster::walk::rows
#[inline(always)]
fn walk<T: Narrow, E>(
    frame: &Frame,
    p: [(T, T); 3],
    edge: impl Fn((T, T), (T, T)) -> Option<Edge<T>>,
    left_clamp: bool,
    emit: &mut impl FnMut(i32, i32, i32) -> Result<(), E>,
) -> Result<(), E> {
    // Coordinates within the bound: the orientation is exact.
    let turn = orientation(p[0], p[1], p[2]);
    if turn == T::Double::ZERO {
        return Ok(());
    }
    let short_left = turn < T::Double::ZERO;
    let last = frame.height - 1;
    // Each edge is used where it was returned, inside its `Option`: moved
    // out, it was written field by field and read back whole, which
    // stalls store forwarding on x86-64 (a third of a 4 px triangle's
    // time).
    let mut long = edge(p[0], p[2]);
    let Some(long) = long.as_mut() else {
        return Ok(());
    };
    // Each half: the rows of the short edge, between it and the long edge.
    let mut half = |short: &mut Edge<T>, long: &mut Edge<T>| {
        let (from, end) = (short.first_row, short.last_row.min(last));
        match (short_left, left_clamp) {
            (true, true) => triangle_rows::<true, true, _, _>(frame, short, long, from, end, emit),
            (false, true) => triangle_rows::<true, true, _, _>(frame, long, short, from, end, emit),
            (true, false) => {
                triangle_rows::<true, false, _, _>(frame, short, long, from, end, emit)
            }
            (false, false) => {
                triangle_rows::<true, false, _, _>(frame, long, short, from, end, emit)
            }
        }
        .map(|()| end)
    };
    if let Some(upper) = edge(p[0], p[1]).as_mut() {
        if half(upper, long)? == last {
            return Ok(());
        }
        long.step();
    }
    if let Some(lower) = edge(p[1], p[2]).as_mut() {
        half(lower, long)?;
    }
    Ok(())
}

rows_out_of_line!(
    /// [`rows`] out of line, for the triangle walks (see [`rows`] for why
    /// it is defined here).
    ///
    /// [`rows`]: crate::raster::walk::rows
    triangle_rows
);

#[cfg(test)]
mod tests {
    use embedded_graphics_core::geometry::{Point, Size};

    use super::*;

    /// [`walk_short`] against [`walk`] with the same small edges (the one
    /// the hosts use for taller triangles, and 32-bit ARM for all): random
    /// triangles at 1/4096 px, half of them up to 5 rows tall and half up
    /// to 26 (past [`SHORT`]'s 24), in clips that cut them on the right
    /// and at the bottom (a cut on the left or at the top takes the
    /// checked frame, not these walks).
    #[test]
    fn short_walk_matches_the_two_call_walk() {
        let mut random = crate::raster::xorshift(0x9E37_79B9_7F4A_7C15);
        let mut next = |n: i32| (random.next().unwrap_or_default() % n as u64) as i32;
        let (mut lit, mut tall) = (0, 0);
        for i in 0..80_000 {
            let (w, h) = match i % 2 {
                0 => (8, 5),
                _ => (20, 26),
            };
            let corner = |next: &mut dyn FnMut(i32) -> i32| {
                Vertex::from_raw(40_960 + next(w * 4096), 40_960 + next(h * 4096))
            };
            let mut v = [corner(&mut next), corner(&mut next), corner(&mut next)];
            sort_by_y(&mut v);
            let clip = Rectangle::new(
                Point::new(6 + next(6), 6 + next(6)),
                Size::new(next(w + 4) as u32, next(h + 4) as u32),
            );
            let Some((frame, p)) = Frame::of_small_triangle(&v, &clip) else {
                continue;
            };
            let spans = |short: bool| {
                let mut out = heapless::Vec::<Span, 32>::new();
                let mut push = |s: Span| out.push(s).map_err(|_| ());
                let mut push = by_numbers_ref(&mut push);
                let _ = match short {
                    true => walk_short(&frame, p, &mut push),
                    false => walk(&frame, p, narrow_edges(true), false, &mut push),
                };
                drop(push);
                out
            };
            let short = spans(true);
            assert_eq!(short, spans(false), "{v:?} in {clip:?}");
            lit += usize::from(!short.is_empty());
            tall += usize::from(short.len() > 12);
        }
        assert!(lit > 20_000 && tall > 2_000, "{lit} {tall}");
    }

    /// Both sorts, whichever the target uses, against the standard stable
    /// sort: every order of three corners, with and without equal `y`.
    #[test]
    fn both_sorts_are_the_stable_sort_by_y() {
        let corner = |x: i32, y: i32| Vertex::from_raw(x, y);
        let sets = [
            [corner(0, 5), corner(1, -3), corner(2, 9)],
            [corner(0, 4), corner(1, 4), corner(2, -1)],
            [corner(0, 7), corner(1, 7), corner(2, 7)],
            [corner(0, i32::MIN), corner(1, i32::MAX), corner(2, 0)],
        ];
        let orders = [
            [0, 1, 2],
            [0, 2, 1],
            [1, 0, 2],
            [1, 2, 0],
            [2, 0, 1],
            [2, 1, 0],
        ];
        for set in sets {
            for order in orders {
                let v = order.map(|i| set[i]);
                let mut want = v;
                want.sort_by_key(|c| c.raw().1);
                for sort in [sort_by_y_branching, sort_by_y_selecting] {
                    let mut got = v;
                    sort(&mut got);
                    assert_eq!(got, want, "{order:?}");
                }
            }
        }
    }
}
