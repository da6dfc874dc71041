//! Polygons whose rows two edges cross, walked like a triangle.
//!
//! A polygon that goes down from its top vertex and back up only once
//! (y-monotone: every convex polygon, and many concave ones) has an
//! outline of two chains of edges from its top vertex down to its bottom
//! one, and every row sample line between them crosses each chain exactly
//! once. Each row then has two crossings, the polygon winds once (either
//! way) between them and not at all outside, so under either fill rule a
//! row's span runs from the lesser threshold to the greater, as a
//! triangle's does between its long and its short edge. No edge table, no
//! sort, no windings: two active edges at a time, each stepped in O(1) a
//! row and handed over to the next edge of its chain at a vertex
//! ([`walk_chains`]). The pixels are the scanline fill's; only the work
//! differs.
//!
//! Whether a polygon is y-monotone is decided by the signs of its edges'
//! y steps alone ([`y_monotone`]), no products; one that is not (a star,
//! most self-intersecting outlines) gets `None` and takes the edge table.
//! A parallelogram (a thick line's rectangle) is convex by construction:
//! its sides are fixed by one orientation and its rows skip the two
//! selects.

use embedded_graphics_core::primitives::Rectangle;

use super::predicates::y_monotone;
use crate::{
    raster::{
        edge::Edge,
        frame::Frame,
        sink::SpanSink,
        walk::{by_numbers_ref, walk_chains},
        wide::orientation,
    },
    span::Span,
    vertex::Vertex,
};

/// What the two-chain walk knows of its polygon.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Shape {
    /// Nothing: it may not be y-monotone.
    Polygon,
    /// Convex by construction (a stroke's piece), so y-monotone: walked
    /// as a [`Polygon`](Self::Polygon) that passed the test, with no
    /// test.
    Convex,
    /// It is a parallelogram (its corners in order round it, `c[0] + c[2]
    /// = c[1] + c[3]`), so convex, or of no area: a thick line's
    /// rectangle, whose rows are one span each, where its two triangles
    /// gave two.
    Parallelogram,
}

/// Fills the polygon `vertices` with `color` in `sink` if it is
/// y-monotone; `None`, with nothing drawn, if it is not. One copy per sink
/// for polygons and thick lines alike.
pub(crate) fn fill_monotone<C: Copy, S: SpanSink<C>>(
    vertices: &[Vertex],
    shape: Shape,
    sink: &mut S,
    color: C,
) -> Option<Result<(), S::Error>> {
    let clip = sink.bounds();
    monotone_spans(vertices, shape, &clip, &mut |s| sink.fill_span(s, color))
}

/// Calls `emit` with the spans of the polygon `vertices` inside `clip`,
/// top to bottom, if it is y-monotone; `None`, with nothing emitted, if it
/// is not.
pub(crate) fn monotone_spans<E>(
    vertices: &[Vertex],
    shape: Shape,
    clip: &Rectangle,
    emit: &mut impl FnMut(Span) -> Result<(), E>,
) -> Option<Result<(), E>> {
    // Tested on the vertices' own heights, before any frame: a polygon
    // that takes the edge table sets its frame up only there.
    if let Shape::Polygon = shape {
        if !y_monotone(vertices) {
            return None;
        }
    }
    let Some((frame, small)) = Frame::around_and_whether_small(vertices, clip) else {
        return Some(Ok(()));
    };
    // A polygon reaching 2^29 raw units (131,072 px) from its frame's
    // origin takes the edge table or the triangles, which step in `i64`
    // too: this walk has one width, one copy per sink.
    if !frame.fits_i32() {
        return None;
    }
    walk_monotone(&frame, small, vertices, shape, &mut by_numbers_ref(emit))
}

/// [`monotone_spans`] in `i32`, for a y-monotone polygon (or a
/// parallelogram) whose relative coordinates fit the frame; `None` only if
/// a parallelogram does not have four corners.
fn walk_monotone<E>(
    frame: &Frame,
    small: bool,
    vertices: &[Vertex],
    shape: Shape,
    emit: &mut impl FnMut(i32, i32, i32) -> Result<(), E>,
) -> Option<Result<(), E>> {
    // Vertex `k` relative to the frame. The frame fits `i32` for every
    // vertex (`Frame::fits_i32`), so the default is never taken.
    let p = |k: usize| frame.relative::<i32>(vertices[k]).unwrap_or_default();
    let n = vertices.len();
    // The first vertex at the least y: both chains start there.
    let top = (0..n).min_by_key(|&k| p(k).1)?;
    let chain = |forwards| Chain {
        p,
        n,
        at: top,
        left: n,
        forwards,
        small,
    };
    Some(match shape {
        // Either chain on either side: the lesser threshold and the greater
        // bound each row.
        Shape::Polygon | Shape::Convex => {
            walk_chains::<false, _, _>(frame, chain(true), chain(false), emit)
        }
        // Coordinates within the bound: the orientation is exact. Of no
        // area, it lights nothing. Clockwise on screen, the forward chain
        // runs down the right side.
        Shape::Parallelogram if n == 4 => match orientation(p(0), p(1), p(2)) {
            0 => Ok(()),
            t if t > 0 => walk_chains::<true, _, _>(frame, chain(false), chain(true), emit),
            _ => walk_chains::<true, _, _>(frame, chain(true), chain(false), emit),
        },
        Shape::Parallelogram => return None,
    })
}

/// The edges of a y-monotone polygon's chain, top to bottom: from vertex `at`
/// (of `p(0), .., p(n - 1)`) forwards (`at`, `at + 1`, ...) or backwards,
/// while the outline goes down or stays level, leaving out the edges that
/// cross no row of the frame.
struct Chain<F> {
    p: F,
    n: usize,
    at: usize,
    /// Edges not yet looked at: the chain ends after all of them at most.
    left: usize,
    forwards: bool,
    /// Whether the frame is small
    /// ([`Frame::around_and_whether_small`]): the edges are then set up
    /// by [`Edge::new_small`], unchecked.
    small: bool,
}

impl<F: Fn(usize) -> (i32, i32)> Iterator for Chain<F> {
    type Item = Edge<i32>;

    fn next(&mut self) -> Option<Edge<i32>> {
        while self.left > 0 {
            self.left -= 1;
            let next = match self.forwards {
                true if self.at + 1 == self.n => 0,
                true => self.at + 1,
                false if self.at == 0 => self.n - 1,
                false => self.at - 1,
            };
            let (a, b) = ((self.p)(self.at), (self.p)(next));
            self.at = next;
            if b.1 < a.1 {
                // Past the bottom vertex.
                self.left = 0;
            } else if a.1 < b.1 {
                let edge = match self.small {
                    true => Edge::new_small(a, b),
                    false => Edge::new(a, b, 0),
                };
                if let Some(edge) = edge {
                    return Some(edge);
                }
            }
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use std::vec::Vec;

    use embedded_graphics_core::geometry::{Point, Size};

    use super::*;
    use crate::raster::xorshift;

    /// The spans of `corners` walked as `shape` inside `clip`.
    fn spans(corners: &[Vertex], shape: Shape, clip: &Rectangle) -> Option<Vec<Span>> {
        let mut out = Vec::new();
        monotone_spans(corners, shape, clip, &mut |s| {
            out.push(s);
            Ok::<(), ()>(())
        })?
        .ok()?;
        Some(out)
    }

    /// A parallelogram's walk against the general two-chain walk of the
    /// same outline (which `tests/polygon.rs` checks against an exact
    /// reference), in both windings, starting at every corner: random
    /// sides, small and large frames (the two edge setups), horizontal
    /// and vertical sides, clipped on every side. Thick lines, the walk's
    /// only users, all wind one way, so this is where the other is tested.
    #[test]
    fn parallelograms_walk_as_polygons() {
        let clip = Rectangle::new(Point::new(-5, -7), Size::new(70, 50));
        let mut random = xorshift(0x8C6F_1D2B_5E3A_4097);
        let mut next = move |range: u64| random.next().unwrap_or(0) % range;
        let mut lit = 0;
        for case in 0..20_000 {
            // Sides up to 16 px or 400 px (over the small setup's 128),
            // some of them level or upright.
            let reach = if case % 2 == 0 { 1 << 16 } else { 400 << 12 };
            let mut side = |axis: u64| {
                let v = next(2 * reach) as i32 - reach as i32;
                if next(8) == axis {
                    0
                } else {
                    v
                }
            };
            let (u, v) = ((side(0), side(1)), (side(2), side(3)));
            let a = (
                next(100 << 12) as i32 - (20 << 12),
                next(80 << 12) as i32 - (20 << 12),
            );
            let c = [
                a,
                (a.0 + u.0, a.1 + u.1),
                (a.0 + u.0 + v.0, a.1 + u.1 + v.1),
                (a.0 + v.0, a.1 + v.1),
            ];
            let c = c.map(|(x, y)| Vertex::from_raw(x, y));
            for start in 0..4 {
                for reversed in [false, true] {
                    let mut corners: [Vertex; 4] = core::array::from_fn(|k| c[(start + k) % 4]);
                    if reversed {
                        corners.reverse();
                    }
                    // A parallelogram is always walked; the general walk
                    // leaves a level one (no rows) to the edge table.
                    let walked = spans(&corners, Shape::Parallelogram, &clip).expect("walked");
                    let general = spans(&corners, Shape::Polygon, &clip).unwrap_or_default();
                    assert_eq!(walked, general, "{corners:?}");
                    lit += walked.len();
                }
            }
        }
        // Most of them light something inside the clip.
        assert!(lit > 1_000_000, "{lit} spans");
    }
}
