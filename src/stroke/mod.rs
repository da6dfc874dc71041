//! Strokes: thick polylines with joins, and the outlines of triangles and
//! polygons, filled exactly and each pixel once.
//!
//! # What a stroke covers
//!
//! A stroke `w` px wide through points `P0, P1, ...` is the union of
//!
//! - one parallelogram per segment of non-zero length, `w` px across and
//!   centred on the segment (see [`pieces`] for the corners, rounded to
//!   1/4096 px as thick lines' are); an open stroke's two ends reach half a
//!   pixel beyond its end points (butt caps at the end pixels' outer edges,
//!   as a thick [`Line`](crate::Line));
//! - one [`Join`] at every point where two segments meet, filling the
//!   wedge the two parallelograms leave on the outside of the turn: a
//!   bevel triangle, a miter (the bevel plus the tip out to where the outer
//!   edges cross, within [`MITER_LIMIT`]), or an exact disk sector of
//!   radius `w / 2`;
//!
//! and a pixel is lit iff its centre, nudged as the crate's sampling rule
//! says, lies in that union. A closed stroke (a polyline whose last point
//! repeats its first, or a triangle's or polygon's outline) also joins at
//! that point. Repeated points are skipped (segments of no length have no
//! parallelogram and make no joint); a stroke with no length at all is the
//! `w x w` square around its point.
//!
//! # Each pixel once, or each piece whole
//!
//! The pieces overlap (on the inside of every turn, and wherever the
//! outline crosses itself). Into a sink that needs every pixel written
//! once (any `DrawTarget`: it may blend, count writes or send each one to
//! a display), each pixel they light is written by the first piece that
//! reaches it and skipped by the others: the stroke's box inside the clip
//! is cut into tiles of up to 8,192 px across and as many rows as a mask
//! of one bit a pixel holds in 1 KiB, and in each tile every piece that
//! can reach it writes the pixels of its own not yet marked, and marks
//! them. Into a sink on which overdraw is invisible
//! ([`SpanSink::overdraw_is_invisible`]: the framebuffer), the whole box
//! is one tile and each piece is written whole, with no mask: the same
//! pixels, the overlaps written twice.
//!
//! A polygon piece (a segment's
//! parallelogram, a bevel or a miter's tip) whose corners are 20.12
//! vertices is walked by the raster core, as a filled polygon is: two
//! chains of edges from its top corner to its bottom one, stepped a row
//! at a time with no division. A round join's disk sector, and a piece
//! reaching past the 20.12 range, has its columns found row by row
//! instead ([`RowWalk`]: each side an edge of the raster core along its
//! line, set up once in 128 bits and stepped in 64, and an integer
//! square root a row for the disk). Both light
//! exactly the pixels whose nudged centres the piece holds; the pieces
//! share their corner points exactly, and two pieces meeting along a
//! line light each pixel on it once, through the nudge.
//!
//! # Cost and storage
//!
//! No heap and no storage proportional to the number of points: the
//! offsets of up to 64 segments (1 KiB, kept between tiles, so their
//! square roots are taken once) and, for a sink that needs each pixel
//! once, the mask (1 KiB) are on the stack. Each tile walks the points
//! and builds only the pieces that can reach it, so a tile costs `O(n)`
//! for `n` points plus each reaching piece's setup (two divisions an
//! edge) and its rows within the tile. Only the target's rows and
//! columns within reach of the stroke are visited: the tiles span the
//! points' box (widened by the reach) inside the clip, an empty tile
//! skips to the next rows a segment reaches in its columns, and a piece
//! walked row by row takes only the rows where it crosses the tile's
//! columns, so that a stroke from points far off a tall target costs
//! the rows it crosses there. A masked tile is as wide
//! as the stroke's box inside the clip (up to 8,192 px) and as tall as
//! the mask allows: 25 rows for a box 320 px wide, 256 for one under
//! 33 px. Without the mask every piece is set up once, and costs what it
//! would cost filled on its own.
//!
//! # Ranges
//!
//! Any `i32` points (polylines) and any [`Vertex`]es (triangles,
//! polygons), any width up to 65535 px (wider is drawn as 65535), any
//! clip: coordinates are raw units below `2^46`, kept in `i64` (their
//! sums and differences fit it) with the products that can pass it taken
//! in `i128`, so nothing overflows and nothing is cut or lost at the edges
//! of the 20.12 range.

pub(crate) mod pieces;
mod row;

use core::convert::Infallible;

use embedded_graphics_core::{
    geometry::{Point, Size},
    primitives::Rectangle,
};

use crate::{
    clip::Bounds,
    polygon::monotone::{monotone_spans, Shape},
    raster::sink::SpanSink,
    span::Span,
    vertex::Vertex,
};
use pieces::{Piece, Pt, Region, Segment};
use row::{Mask, RowWalk, Tile, MASK_BITS, MASK_WORDS};

/// How a thick stroke turns a corner: the shape filling the wedge the two
/// segments leave on the outside of the turn.
///
/// Used by thick polylines ([`StyledPolyline::join`](crate::StyledPolyline::join))
/// and by the outlines of triangles ([`StrokedTriangle`](crate::StrokedTriangle))
/// and polygons ([`StrokedPolygon`](crate::StrokedPolygon)).
///
/// # What a stroke covers
///
/// A stroke `w` px wide is the union of one rectangle per segment of
/// non-zero length (`w` px across, centred on the segment, corners rounded
/// to 1/4096 px as a thick [`Line`](crate::Line)'s are; at the two ends of
/// an open stroke it reaches half a pixel beyond the end point, a butt
/// cap) and one join at every point where two segments meet. Repeated
/// points are skipped; a stroke of no length is the `w x w` square around
/// its point. A closed stroke (a polyline whose last point repeats its
/// first, or an outline) joins at that point too. A pixel is lit iff its
/// centre, nudged as the [crate's sampling rule](crate#the-sampling-rule)
/// says, is in the union.
///
/// # Each pixel once, no gaps
///
/// The pieces overlap on the inside of every turn and wherever the
/// stroke crosses itself, so they mark the pixels they light in a mask
/// (1 KiB, for a tile of the target at a time), and each run of marked
/// pixels is then written once: every lit pixel is written exactly once.
/// A sink on which overdraw is invisible
/// ([`SpanSink::overdraw_is_invisible`](crate::SpanSink::overdraw_is_invisible):
/// the crate's `Framebuffer`, through `draw_spans`) takes each piece
/// whole instead, the overlaps twice: the same pixels, with no mask.
/// The polygon pieces are walked by the same exact edges as filled
/// polygons; a round join's disk is found row by row, with an integer
/// square root. Neighbouring pieces share their corner points exactly
/// and the join fills exactly the wedge the rounded rectangles leave
/// (decided on the rounded corners, so even turns within a hair of
/// straight or of a full reversal leave no gap).
///
/// # Cost and storage
///
/// No heap, no storage proportional to the number of points (about 2 KiB
/// of stack: the mask and the offsets of up to 64 segments; 1 KiB with no
/// mask). A masked tile (25 rows of a stroke 320 px wide) walks the
/// points and builds only the pieces within reach of it; only the
/// target's rows and columns within reach of the stroke are visited (a
/// stroke from points far off a tall target, the rows it crosses
/// there).
///
/// Measured on the host, 8 px wide on a 320 x 240 framebuffer (`cargo
/// bench --bench lines -- "thick polyline"`, one run on the build machine
/// of 2026-12-06, seventh session), mitred: a 21-point zigzag takes 19 µs
/// through `draw_spans` (no mask) and 53 µs through `draw` (each pixel
/// once), a noisy 320-point trace (each row crossed by about a hundred
/// segments) 0.16 ms and 0.39 ms. The same segments drawn as separate
/// thick lines, which overlap and leave notches, take 20 µs and 0.14 ms,
/// and embedded-graphics 0.8's `Polyline` with the same stroke 1.4 ms and
/// 16.4 ms, in the same run. On a Cortex-M4 (`.ci/itrace`) the zigzag
/// takes 0.39 million instructions through `draw_spans` and 0.85 million
/// through `draw`, its separate thick lines 0.29 million.
///
/// # Ranges
///
/// Any `i32` points, any [`Vertex`]es, any width (over 65535 px drawn as
/// 65535), any clip: coordinates are raw units below `2^46`, with
/// products taken in `i128`, so nothing overflows and nothing is cut at
/// the edges of the 20.12 range.
///
/// # Examples
///
/// A right angle 7 px wide (the mock display fails on any pixel written
/// twice):
///
/// ```
/// use embedded_graphics::mock_display::MockDisplay;
/// use embedded_graphics::{pixelcolor::BinaryColor, prelude::*};
/// use embedded_raster::{Join, Polyline};
///
/// let points = [Point::new(0, 3), Point::new(7, 3), Point::new(7, 10)];
/// let draw = |join| {
///     let mut display = MockDisplay::new();
///     Polyline::new(&points).stroke(BinaryColor::On).stroke_width(7).join(join).draw(&mut display)?;
///     Ok::<_, core::convert::Infallible>(display)
/// };
/// draw(Join::Miter)?.assert_pattern(&[
///     "###########",
///     "###########",
///     "###########",
///     "###########",
///     "###########",
///     "###########",
///     "###########",
///     "    #######",
///     "    #######",
///     "    #######",
///     "    #######",
/// ]);
/// draw(Join::Bevel)?.assert_pattern(&[
///     "########   ",
///     "#########  ",
///     "########## ",
///     "###########",
///     "###########",
///     "###########",
///     "###########",
///     "    #######",
///     "    #######",
///     "    #######",
///     "    #######",
/// ]);
/// draw(Join::Round)?.assert_pattern(&[
///     "#########  ",
///     "########## ",
///     "###########",
///     "###########",
///     "###########",
///     "###########",
///     "###########",
///     "    #######",
///     "    #######",
///     "    #######",
///     "    #######",
/// ]);
/// assert_eq!(Join::default(), Join::Miter);
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Join {
    /// The outer edges extended until they meet, while the tip is within
    /// [`MITER_LIMIT`]; a bevel past it. The default, as in
    /// embedded-graphics.
    #[default]
    Miter,
    /// The outer corners of the two segments joined by a straight edge.
    Bevel,
    /// An exact circular arc of radius `w / 2` around the joint (the
    /// pixels whose centres lie within `w / 2` of it, on the outer side).
    Round,
}

/// The miter limit: a [`Join::Miter`] whose miter length (from the inner
/// to the outer corner, `w / cos(turn / 2)`) would be over `MITER_LIMIT`
/// times the stroke width is drawn as a [`Join::Bevel`].
///
/// 4 is SVG's default `stroke-miterlimit`, and embedded-graphics' rule
/// (the tip at most twice the width from the joint): turns up to about
/// 151 degrees (interior angles down to about 29) keep their miter. The
/// test is exact on the rounded offsets, `16 n0.n1 >= -14 (w / 2)^2`.
///
/// # Examples
///
/// ```
/// use embedded_raster::MITER_LIMIT;
///
/// // cos(turn) >= 2 / L^2 - 1: a right angle keeps its miter.
/// let l = MITER_LIMIT as f64;
/// assert!(90f64.to_radians().cos() >= 2.0 / (l * l) - 1.0);
/// assert!(160f64.to_radians().cos() < 2.0 / (l * l) - 1.0);
/// ```
pub const MITER_LIMIT: u32 = 4;

/// Widths above this are drawn as this width.
const MAX_WIDTH: u32 = 65535;

/// The points a stroke goes through, in raw units.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Outline<'a> {
    /// Pixel centres.
    Points(&'a [Point]),
    /// Subpixel vertices.
    Vertices(&'a [Vertex]),
}

impl Outline<'_> {
    fn len(&self) -> usize {
        match self {
            Self::Points(p) => p.len(),
            Self::Vertices(v) => v.len(),
        }
    }

    /// Point `k` (`k < len`) in raw units.
    fn at(&self, k: usize) -> Pt {
        match self {
            Self::Points(p) => p.get(k).map_or((0, 0), |p| {
                (i64::from(p.x) * 4096 + 2048, i64::from(p.y) * 4096 + 2048)
            }),
            Self::Vertices(v) => v.get(k).map_or((0, 0), |v| {
                let (x, y) = v.raw();
                (i64::from(x), i64::from(y))
            }),
        }
    }
}

/// A stroke ready to rasterize.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Stroke<'a> {
    outline: Outline<'a>,
    /// Whether the last point joins the first (through a segment from it
    /// to the first, unless they are equal).
    closed: bool,
    width: i64,
    join: Join,
}

impl<'a> Stroke<'a> {
    /// A stroke of `width` (at least 1; over 65535 drawn as 65535).
    pub fn new(outline: Outline<'a>, closed: bool, width: u32, join: Join) -> Self {
        Self {
            outline,
            closed,
            width: i64::from(width.clamp(1, MAX_WIDTH)),
            join,
        }
    }

    /// The segments `k -> k + 1` (wrapping when closed) that have length.
    fn segment(&self, k: usize) -> Option<Segment> {
        let n = self.outline.len();
        let next = if k + 1 == n { 0 } else { k + 1 };
        let (a, b) = (self.outline.at(k), self.outline.at(next));
        (a != b).then_some(Segment { a, b })
    }

    fn segment_count(&self) -> usize {
        let n = self.outline.len();
        if self.closed {
            n
        } else {
            n.saturating_sub(1)
        }
    }

    /// Writes the stroke's pixels into `sink`: each once, unless the sink
    /// says overdraw is invisible ([`SpanSink::overdraw_is_invisible`]).
    ///
    /// Each piece that can reach the stroke's box inside the clip writes
    /// its pixels: a polygon piece whose corners are 20.12 vertices walked
    /// by the raster core (two chains of edges, stepped a row at a time),
    /// a round join's disk sector, or a piece out of that range, found row
    /// by row ([`RowWalk`]). Written each once, the box is cut into
    /// tiles of at most [`MASK_WORDS`] 32-pixel words; in each the pieces
    /// mark their pixels in the tile's mask, and the mask's runs are
    /// written, each as long as it goes ([`Mask::for_each_run`]). Else
    /// the whole box is one tile, with no mask, and the pieces overlap
    /// ([`draw_overlapping`](Self::draw_overlapping)).
    pub fn draw<C: Copy, S: SpanSink<C>>(&self, color: C, sink: &mut S) -> Result<(), S::Error> {
        if sink.overdraw_is_invisible() {
            return self.draw_overlapping(color, sink);
        }
        let Some((columns, rows)) = self.reach_in(&sink.bounds()) else {
            return Ok(());
        };
        let ends = self.ends();
        let mut offsets = Offsets::new();
        let mut mask = Mask::new();
        let mut x0 = columns.start;
        while x0 < columns.end {
            let x1 = columns.end.min(x0 + MASK_BITS);
            // Words a row of the tile: 1..=MASK_WORDS.
            let stride = usize::try_from((x1 - x0 + 31) / 32).unwrap_or(MASK_WORDS);
            let tall = i64::try_from(MASK_WORDS / stride.max(1)).unwrap_or(1);
            let mut y0 = rows.start;
            while y0 < rows.end {
                let y1 = rows.end.min(y0 + tall);
                let tile = Tile::new(x0, x1, y0, y1);
                let tile_rows = usize::try_from(y1 - y0).unwrap_or(MASK_WORDS);
                mask.clear(stride, tile_rows);
                let origin = tile.rectangle.top_left;
                let marked = self.draw_tile(
                    &tile,
                    ends,
                    &mut offsets,
                    &mut marked_runs(&mut mask, origin),
                );
                // Marking cannot fail.
                let Ok(()) = marked;
                let lit = mask.for_each_run(tile_rows, |row, s, e| {
                    // A run of the tile's rows and columns (below 2^13):
                    // from its top-left pixel, a `Point`, to at most the
                    // tile's right side, which fits `u32`.
                    let (y, x) = (origin.y + row as i32, origin.x + s as i32);
                    write_run(sink, y, x, (e - s) as u32, color)
                })?;
                y0 = match lit {
                    true => y1,
                    // Nothing here: on to the next rows the stroke
                    // reaches in these columns (a stroke with points far
                    // off a tall target crosses it in a few rows).
                    false => match self.next_row_near((x0, x1), y1, ends, &mut offsets) {
                        Some(next) => next,
                        None => break,
                    },
                };
            }
            x0 = x1;
        }
        Ok(())
    }

    /// Writes each piece's pixels into `sink` whole, with no mask: where
    /// pieces overlap, their pixels are written once by each.
    fn draw_overlapping<C: Copy, S: SpanSink<C>>(
        &self,
        color: C,
        sink: &mut S,
    ) -> Result<(), S::Error> {
        let Some((columns, rows)) = self.reach_in(&sink.bounds()) else {
            return Ok(());
        };
        if columns.is_empty() || rows.is_empty() {
            return Ok(());
        }
        let tile = Tile::new(columns.start, columns.end, rows.start, rows.end);
        let mut offsets = Offsets::new();
        self.draw_tile(
            &tile,
            self.ends(),
            &mut offsets,
            &mut whole_runs(sink, color),
        )
    }

    /// The columns and rows of `clip` the stroke can light, each ending at
    /// `2^31` at most: a tile from column or row `2^31` on (of a clip that
    /// reaches there) holds no pixel a `Point` can name, and each tile's
    /// top-left pixel is a `Point`.
    fn reach_in(&self, clip: &Rectangle) -> Option<(core::ops::Range<i64>, core::ops::Range<i64>)> {
        let clip = Bounds::of(clip);
        let rows = self.reach_of(1, clip.y0, clip.y1)?;
        let columns = self.reach_of(0, clip.x0, clip.x1)?;
        Some((
            columns.start..columns.end.min(1 << 31),
            rows.start..rows.end.min(1 << 31),
        ))
    }

    /// Calls `write` with each run of `tile` pixels the pieces light.
    #[inline(always)]
    fn draw_tile<E>(
        &self,
        tile: &Tile,
        ends: Option<(usize, usize)>,
        offsets: &mut Offsets,
        write: &mut impl FnMut(i32, i32, u32) -> Result<(), E>,
    ) -> Result<(), E> {
        let window = Window::of(tile);
        let mut result = Ok(());
        self.for_each_piece(&window, ends, offsets, &mut |piece: &Piece| {
            if result.is_ok() {
                result = piece_spans(piece, tile, write);
            }
        });
        result
    }

    /// The first row from `from` on that the stroke can light in columns
    /// `x0..x1` ([`pieces::first_row_near`]): no row between `from` and it
    /// has a pixel of those columns lit. `None` if there is none. `O(n)`
    /// for `n` points: each segment's parallelogram (its offsets kept in
    /// `offsets`), with two divisions for each of its sides that crosses
    /// a side of the band.
    fn next_row_near(
        &self,
        (x0, x1): (i64, i64),
        from: i64,
        ends: Option<(usize, usize)>,
        offsets: &mut Offsets,
    ) -> Option<i64> {
        let segment = |k| self.segment(k);
        let mut corners = |k, seg: &Segment| {
            let ends = ends.unwrap_or((k, k));
            self.segment_corners(k, seg, ends, offsets)
        };
        let lone = self.outline.at(0);
        let reaches = (self.side(), self.reach());
        pieces::first_row_near(ends, &segment, &mut corners, lone, (x0, x1), from, reaches)
    }

    /// The corners of segment `k`'s parallelogram (`seg`), of a stroke
    /// whose first and last segments with length are `ends`: the ends of
    /// an open stroke reach half a pixel further (butt caps).
    fn segment_corners(
        &self,
        k: usize,
        seg: &Segment,
        (first, last): (usize, usize),
        offsets: &mut Offsets,
    ) -> [Pt; 4] {
        let n = offsets.get(k, seg, self.width);
        let extend = |end: usize| match !self.closed && k == end {
            true => seg.extension(),
            false => (0, 0),
        };
        seg.corners(n, extend(first), extend(last))
    }

    /// The first and last segments with length; `None` if there are none.
    fn ends(&self) -> Option<(usize, usize)> {
        let count = self.segment_count();
        let first = (0..count).find(|&k| self.segment(k).is_some())?;
        let last = (0..count).rev().find(|&k| self.segment(k).is_some())?;
        Some((first, last))
    }

    /// How far (raw units, on each axis) a segment's parallelogram
    /// reaches from the segment: `|n| + |e| <= w / 2 + 1/2` px, rounding
    /// included.
    fn side(&self) -> i64 {
        2048 * self.width + 4096
    }

    /// How far (raw units) any piece reaches from the points: a miter tip
    /// is within `2 w` of its joint (within [`MITER_LIMIT`]), a corner
    /// within `w / 2 + 1/2`, a square's corner within `w / sqrt(2)`.
    fn reach(&self) -> i64 {
        4096 * 2 * self.width + 8192
    }

    /// The rows (`axis` 1) or columns (`axis` 0) of `clip`, `lo..hi`, the
    /// stroke can light: those whose centres lie within its reach of a
    /// point.
    fn reach_of(&self, axis: usize, lo: i64, hi: i64) -> Option<core::ops::Range<i64>> {
        let coordinate = |p: Pt| if axis == 0 { p.0 } else { p.1 };
        let (min, max) = (0..self.outline.len())
            .map(|k| coordinate(self.outline.at(k)))
            .fold((i64::MAX, i64::MIN), |(a, b), v| (a.min(v), b.max(v)));
        if min > max {
            return None;
        }
        // Points below 2^46, a reach below 2^30: no overflow.
        let first = -((-(min - self.reach() - 2048)).div_euclid(4096));
        let last = (max + self.reach() - 2048).div_euclid(4096);
        let (first, end) = (first.max(lo), (last + 1).min(hi));
        (first < end).then_some(first..end)
    }

    /// Calls `f` with every piece that can reach a pixel centre of
    /// `window`.
    fn for_each_piece(
        &self,
        window: &Window,
        ends: Option<(usize, usize)>,
        offsets: &mut Offsets,
        f: &mut dyn FnMut(&Piece),
    ) {
        let w = self.width;
        let Some((first, last)) = ends else {
            let p = self.outline.at(0);
            if window.near(p, p, self.reach()) {
                pieces::square(p, w, f);
            }
            return;
        };
        let side = self.side();
        let mut prev: Option<(usize, Segment)> = None;
        for k in first..=last {
            let Some(seg) = self.segment(k) else {
                continue;
            };
            if window.near(seg.a, seg.b, side) {
                Piece::polygon(&self.segment_corners(k, &seg, (first, last), offsets), f);
            }
            if let Some((k0, s0)) = &prev {
                self.join_at(window, (*k0, s0), (k, &seg), offsets, f);
            }
            prev = Some((k, seg));
        }
        if self.closed {
            if let (Some((k0, s0)), Some(s)) = (&prev, self.segment(first)) {
                self.join_at(window, (*k0, s0), (first, &s), offsets, f);
            }
        }
    }

    /// The join where segment `s0` ends and `s1` starts (with their
    /// indices), if it can reach a pixel centre of `window`.
    fn join_at(
        &self,
        window: &Window,
        (k0, s0): (usize, &Segment),
        (k1, s1): (usize, &Segment),
        offsets: &mut Offsets,
        f: &mut dyn FnMut(&Piece),
    ) {
        let p = s1.a;
        if !window.near(p, p, self.reach()) {
            return;
        }
        let n0 = offsets.get(k0, s0, self.width);
        let n1 = offsets.get(k1, s1, self.width);
        let d0 = (s0.b.0 - s0.a.0, s0.b.1 - s0.a.1);
        pieces::join(p, n0, d0, n1, self.width, self.join, f);
    }
}

/// The pixel centres of a tile, raw: `x` and `y` from the first to the
/// last.
#[derive(Debug, Clone, Copy)]
struct Window {
    x: (i64, i64),
    y: (i64, i64),
}

impl Window {
    fn of(tile: &Tile) -> Self {
        // Pixels within 2^33 of the origin: no overflow.
        let centre = |v: i64| v * 4096 + 2048;
        Self {
            x: (centre(tile.x0), centre(tile.x1 - 1)),
            y: (centre(tile.y0), centre(tile.y1 - 1)),
        }
    }

    /// Whether a centre lies within `reach` (raw, on each axis) of the
    /// box of `a` and `b`: a piece built there that reaches no further
    /// cannot light one.
    #[inline(always)]
    fn near(&self, a: Pt, b: Pt, reach: i64) -> bool {
        let overlaps =
            |(lo, hi): (i64, i64), u: i64, v: i64| hi >= u.min(v) - reach && lo <= u.max(v) + reach;
        overlaps(self.x, a.0, b.0) && overlaps(self.y, a.1, b.1)
    }
}

/// Segments whose offsets are kept between tiles.
const CACHED: usize = 64;

/// The offsets `n` of recently used segments, by index modulo [`CACHED`],
/// so that a segment crossing many rows takes its square roots once (for
/// up to `CACHED` segments). 1 KiB on the stack: the components fit `i32`
/// (`|n| <= 2048 * 65535 < 2^27`).
#[derive(Debug)]
struct Offsets {
    entries: [(usize, [i32; 2]); CACHED],
}

impl Offsets {
    fn new() -> Self {
        Self {
            entries: [(usize::MAX, [0; 2]); CACHED],
        }
    }

    /// The offset `n` of segment `k`.
    fn get(&mut self, k: usize, seg: &Segment, w: i64) -> Pt {
        let slot = &mut self.entries[k % CACHED];
        if slot.0 != k {
            let n = seg.normal(w);
            let c = |v: i64| i32::try_from(v).unwrap_or_default();
            *slot = (k, [c(n.0), c(n.1)]);
        }
        (i64::from(slot.1[0]), i64::from(slot.1[1]))
    }
}

/// Calls `emit` with the row, the first column and the length of each
/// run of `tile` pixels `piece` lights (a run may end at column `2^31`,
/// past what a `Span` holds): a polygon of 20.12 corners walked by the
/// raster core ([`monotone_spans`]: a convex piece is y-monotone),
/// anything else row by row ([`RowWalk`]).
fn piece_spans<E>(
    piece: &Piece,
    tile: &Tile,
    emit: &mut impl FnMut(i32, i32, u32) -> Result<(), E>,
) -> Result<(), E> {
    if let Some((vertices, count)) = piece.vertices() {
        // Convex: no y-monotone test. The walk's spans are not reversed.
        let vertices = vertices.get(..count).unwrap_or_default();
        let walked = monotone_spans(vertices, Shape::Convex, &tile.rectangle, &mut as_runs(emit));
        if let Some(result) = walked {
            return result;
        }
    }
    // With no area, it lights nothing.
    let Some(region) = piece.region() else {
        return Ok(());
    };
    region_spans(&region, tile, emit)
}

/// Calls `emit` with the row, the first column and the length of each
/// run of `tile` pixels `region` lights, row by row ([`RowWalk`]).
fn region_spans<E>(
    region: &Region,
    tile: &Tile,
    emit: &mut impl FnMut(i32, i32, u32) -> Result<(), E>,
) -> Result<(), E> {
    // The rows whose samples 4096 j + 2048 lie in the extent of the
    // region's part over the tile's columns (centres 4096 i + 2048).
    let columns = (tile.x0 * 4096 + 2048, (tile.x1 - 1) * 4096 + 2048);
    let Some((lo, hi)) = region.ys_within(columns) else {
        return Ok(());
    };
    let first = (lo.saturating_sub(2048) / 4096 - 1).max(tile.y0);
    let end = (hi.saturating_sub(2048) / 4096 + 2).min(tile.y1);
    let mut walk = RowWalk::new(region, (tile.x0, tile.x1), first, end);
    if walk.is_empty() {
        return Ok(());
    }
    for j in first..end {
        if let Some((a, b)) = walk.next_row() {
            let (a, b) = (a.clamp(tile.x0, tile.x1), b.clamp(tile.x0, tile.x1));
            // The tile's rows and columns before its far sides are
            // `Point` coordinates, and its sides fit `u32`.
            let run = (i32::try_from(j), i32::try_from(a), u32::try_from(b - a));
            if let (Ok(y), Ok(x), Ok(len @ 1..)) = run {
                emit(y, x, len)?;
            }
        }
    }
    Ok(())
}

/// Fills the convex polygon `corners` (raw units below `2^46` in
/// magnitude, in order round it, either winding) into `sink`, each pixel
/// once, as a stroke's piece past the 20.12 range is: row by row, each
/// side an edge set up once ([`RowWalk`]), only the rows and columns of
/// the sink's bounds that its box reaches. A thick [`Line`](crate::Line)
/// whose corners leave that range.
pub(crate) fn fill_far_convex<C: Copy, S: SpanSink<C>>(
    corners: &[Pt; 4],
    color: C,
    sink: &mut S,
) -> Result<(), S::Error> {
    let Some(tile) = Tile::around(corners, &sink.bounds()) else {
        return Ok(());
    };
    // A corner past the 20.12 range lies past 2^31 raw units: the
    // region's products need `i128`, as `Piece::region` would find. With
    // no area, it lights nothing.
    let Some(region) = Region::of_wide_polygon(corners) else {
        return Ok(());
    };
    region_spans(&region, &tile, &mut whole_runs(sink, color))
}

/// `emit` taking a walk's spans, as runs. Always inlined, and so is its
/// closure: left to the compiler, the walk's row loop called it once a
/// span, and `.ci/itrace`'s zigzag through `draw_spans` took 490,735
/// instructions on a Cortex-M4, 443,956 with it (and the writer behind
/// it) inlined.
#[inline(always)]
fn as_runs<E>(
    emit: &mut impl FnMut(i32, i32, u32) -> Result<(), E>,
) -> impl FnMut(Span) -> Result<(), E> + '_ {
    #[inline(always)]
    move |s: Span| emit(s.y, s.x_start, s.x_end.abs_diff(s.x_start))
}

/// Writes runs into `sink` whole, as [`write_run`]. Always inlined, as
/// is its closure (see [`as_runs`]).
#[inline(always)]
fn whole_runs<'a, C: Copy + 'a, S: SpanSink<C>>(
    sink: &'a mut S,
    color: C,
) -> impl FnMut(i32, i32, u32) -> Result<(), S::Error> + 'a {
    #[inline(always)]
    move |y, x, len| write_run(sink, y, x, len, color)
}

/// Marks runs in the `mask` of the tile whose top-left pixel is
/// `origin`. Always inlined, as is its closure (see [`as_runs`]).
#[inline(always)]
fn marked_runs(
    mask: &mut Mask,
    origin: Point,
) -> impl FnMut(i32, i32, u32) -> Result<(), Infallible> + '_ {
    #[inline(always)]
    move |y, x, len| {
        // The mask counts from the tile's top-left pixel, in its own
        // columns and rows (under 2^13, see `Mask::mark`); the run lies
        // inside the tile: the differences do not overflow and are not
        // negative.
        let (row, c) = ((y - origin.y) as usize, (x - origin.x) as usize);
        mask.mark(row, c, c + len as usize);
        Ok(())
    }
}

/// Writes the `len` pixels from `(x, y)` on (inside the sink's bounds):
/// one span, or a rectangle for a run ending past `i32::MAX`, which a
/// `Span` cannot hold.
#[inline(always)]
fn write_run<C: Copy, S: SpanSink<C>>(
    sink: &mut S,
    y: i32,
    x: i32,
    len: u32,
    color: C,
) -> Result<(), S::Error> {
    match x.checked_add_unsigned(len) {
        Some(x_end) => sink.fill_span(
            Span {
                y,
                x_start: x,
                x_end,
            },
            color,
        ),
        None => sink.fill_rect(&Rectangle::new(Point::new(x, y), Size::new(len, 1)), color),
    }
}
