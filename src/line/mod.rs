//! Lines and polylines between pixels.
//!
//! # Which pixels a line lights
//!
//! A [`Line`] runs from the centre of pixel `A` to the centre of pixel `B`
//! (any `i32` coordinates). It is *x-major* when `|dx| >= |dy|`, else
//! *y-major*. An x-major line lights exactly one pixel in every column
//! from `A.x` to `B.x`: the pixel whose row is the ideal line's y at that
//! column rounded to the nearest integer. A y-major line lights one pixel
//! per row, its column rounded likewise. So both end pixels are lit and
//! every pixel is within half a pixel of the ideal line along the minor
//! axis.
//!
//! **Tie rule.** When the ideal line passes exactly through the midpoint
//! between two pixels (the rounded value is an integer plus one half), the
//! pixel with the *smaller* coordinate wins: the smaller y for x-major
//! lines, the smaller x for y-major lines, whatever the sign of the slope.
//! The rule names coordinates, not directions, so the line from `A` to `B`
//! lights exactly the pixels of the line from `B` to `A`.
//!
//! # How
//!
//! The integer midpoint algorithm (Bresenham): after setup, one add and
//! one compare per pixel, no multiply, divide or float. The line is
//! clipped to the target's bounding box *before* stepping: the first and
//! last visible step and the exact decision variable at the first are
//! computed exactly in 64 bits, so a line from `i32::MIN` to `i32::MAX` costs no
//! more than its visible pixels, and lights exactly the pixels the
//! unclipped line would light inside the target.
//!
//! Pixels come out as [`Run`]s: horizontal runs of x-major lines and
//! vertical runs of y-major lines, each one
//! [`fill_solid`](embedded_graphics_core::draw_target::DrawTarget::fill_solid) call.
//!
//! # Variants
//!
//! [`LineAlgorithm`] selects the classic approximations for comparison: a
//! DDA with 32.32 fixed-point increments and the naive per-pixel
//! multiply-and-round in `f32`. See its docs for how often they differ
//! from the exact line.
//!
//! # Thick lines
//!
//! [`StyledLine::stroke_width`] above 1 draws the line as a filled
//! rectangle of that width, walked as a convex polygon: the rectangle
//! around the centre line from `A`'s centre to `B`'s centre, extended by
//! half a pixel at each end, corners rounded to 1/4096 px. It follows the
//! crate's sampling rule, so it shares edges with adjacent filled shapes
//! without gaps or overdraw. A line whose corners leave the 20.12 range
//! is found row by row instead, with the same corners in `i64`: thick
//! lines are exact over the whole `i32` plane.
//!
//! A thick [`Polyline`] is one stroke: its segments' rectangles (the same
//! corners) joined by a [`Join`](crate::Join) (miter by default, bevel
//! past [`MITER_LIMIT`](crate::MITER_LIMIT), or round), filled as one
//! union, so each pixel is written once (into a sink on which overdraw is
//! invisible, such as the framebuffer through `draw_spans`, the pieces are
//! written whole instead, their overlaps twice) and no joint has a gap. A
//! two-point thick polyline is the thick line.

mod bresenham;
mod clip;
mod polyline;
mod thick;
mod variants;

pub use bresenham::LinePixels;
pub use polyline::{Polyline, StyledPolyline, StyledPolylineVariant};
pub use variants::StyledLineVariant;

use embedded_graphics_core::{
    geometry::{Point, Size},
    pixelcolor::PixelColor,
    primitives::Rectangle,
};

use crate::{
    polygon::monotone::{fill_monotone, Shape},
    raster::sink::{drawable_through_spans, SpanDrawable, SpanSink},
    span::Span,
    stroke::fill_far_convex,
    triangle::Triangle,
};
use clip::Canonical;

/// A run of pixels of a line: `len` pixels from `start`, going right
/// (horizontal) or down (vertical).
///
/// Unlike a [`Span`], a run can end at `i32::MAX`. Any field values are
/// valid: [`rect`](Self::rect) is exact and [`last`](Self::last)
/// saturates at `i32::MAX`.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{geometry::{Point, Size}, primitives::Rectangle};
/// use embedded_raster::Run;
///
/// let run = Run { start: Point::new(2, 5), len: 3, vertical: true };
/// assert_eq!(run.rect(), Rectangle::new(Point::new(2, 5), Size::new(1, 3)));
/// assert_eq!(run.last(), Point::new(2, 7));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Run {
    /// The first pixel (leftmost or topmost).
    pub start: Point,
    /// Number of pixels, at least 1.
    pub len: u32,
    /// Whether the run goes down a column rather than along a row.
    pub vertical: bool,
}

impl Run {
    /// A run from major coordinate `first` to `last` (inclusive, growing)
    /// at minor coordinate `minor`.
    #[inline(always)]
    fn along(x_major: bool, first: i32, last: i32, minor: i32) -> Self {
        let len = last.abs_diff(first).saturating_add(1);
        if x_major {
            Self {
                start: Point::new(first, minor),
                len,
                vertical: false,
            }
        } else {
            Self {
                start: Point::new(minor, first),
                len,
                vertical: true,
            }
        }
    }

    /// The run as a one-pixel-wide rectangle, for
    /// [`fill_solid`](embedded_graphics_core::draw_target::DrawTarget::fill_solid).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::geometry::{Point, Size};
    /// use embedded_raster::Run;
    ///
    /// let r = Run { start: Point::new(-1, 0), len: 4, vertical: false }.rect();
    /// assert_eq!(r.size, Size::new(4, 1));
    /// ```
    pub fn rect(&self) -> Rectangle {
        let size = if self.vertical {
            Size::new(1, self.len)
        } else {
            Size::new(self.len, 1)
        };
        Rectangle::new(self.start, size)
    }

    /// The last pixel of the run (saturating at `i32::MAX`).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::geometry::Point;
    /// use embedded_raster::Run;
    ///
    /// let run = Run { start: Point::new(7, 1), len: 1, vertical: false };
    /// assert_eq!(run.last(), run.start);
    /// ```
    pub fn last(&self) -> Point {
        let step = i32::try_from(self.len.saturating_sub(1)).unwrap_or(i32::MAX);
        if self.vertical {
            Point::new(self.start.x, self.start.y.saturating_add(step))
        } else {
            Point::new(self.start.x.saturating_add(step), self.start.y)
        }
    }

    /// A horizontal run as a [`Span`]; `None` for a vertical run or one
    /// that ends at `i32::MAX` (a span's end is exclusive).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::geometry::Point;
    /// use embedded_raster::{Run, Span};
    ///
    /// let run = Run { start: Point::new(3, 9), len: 2, vertical: false };
    /// assert_eq!(run.span(), Some(Span { y: 9, x_start: 3, x_end: 5 }));
    /// ```
    pub fn span(&self) -> Option<Span> {
        if self.vertical {
            return None;
        }
        let end = i64::from(self.start.x) + i64::from(self.len);
        Some(Span {
            y: self.start.y,
            x_start: self.start.x,
            x_end: i32::try_from(end).ok()?,
        })
    }
}

/// How a 1-pixel line chooses its pixels: the exact Bresenham line or one
/// of two classic approximations, for measuring the speed/accuracy trade.
///
/// All three light exactly one pixel per step along the major axis, both
/// end columns (rows) included, and the same pixels in both directions, and
/// all are clipped before stepping. They differ in the minor coordinate:
///
/// - [`Bresenham`](Self::Bresenham) is exact (the [module docs'](self) rule).
/// - [`Dda`](Self::Dda) adds a 32.32 fixed-point slope per pixel and rounds
///   (the slope itself rounded to 2^-32). Its ties round away from the
///   start, so it breaks the tie rule on half of them.
/// - [`Naive`](Self::Naive) computes `round(slope * k)` in `f32` per pixel:
///   one multiply per pixel, 24-bit precision; it drifts by many pixels on
///   lines longer than about 2^23 px.
///
/// Measured over 20000 random lines of 1 to 4096 px (6.3 million pixels,
/// `variant_accuracy` in `tests/line.rs`): 0.14 % of the DDA's pixels
/// differ from Bresenham's, every one at an exact tie; 0.13 % of the naive
/// line's, all but 7 at ties. None is more than one pixel off.
///
/// **Largest error on long lines.** The DDA is at most 1 px from the exact
/// line for every line between `i32` pixels: its slope is within `2^-33`
/// of the exact one and a line has fewer than `2^32` steps, so its
/// unrounded offset is within 1/2 of the exact one. The naive line is
/// within 1 px below `2^23` px of major extent, and within `2^(n - 22)` px
/// below `2^n` px for `n >= 23`: measured 2, 5, 9, 17, 33, 68, 134, 260
/// and 580 px at most for extents up to `2^24`, ..., `2^32` px (208
/// million steps sampled on 4 million random lines, `LINE_ERROR_LINES=200000
/// cargo test --test line variant_error_on_long_lines`). Five `f32`
/// roundings of relative error `2^-24` bound it by `1.5 + 6 dminor / 2^24`
/// (1,537 px).
///
/// Both are clipped to their visible steps before stepping (a binary
/// search on their own offset), so like the exact line they cost the
/// pixels they light inside the target, however long the line.
///
/// Pixels an approximation puts outside the target are dropped.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::BinaryColor, prelude::*};
/// use embedded_raster::{Line, LineAlgorithm};
///
/// let styled = Line::new(Point::new(0, 0), Point::new(9, 3))
///     .stroke(BinaryColor::On)
///     .algorithm(LineAlgorithm::Dda);
/// assert_eq!(styled.algorithm, LineAlgorithm::Dda);
/// assert_eq!(LineAlgorithm::default(), LineAlgorithm::Bresenham);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum LineAlgorithm {
    /// The exact integer midpoint line.
    #[default]
    Bresenham,
    /// Digital differential analyzer with 32.32 fixed-point increments.
    Dda,
    /// Per-pixel `f32` multiply and round.
    Naive,
}

/// A line from the pixel `start` to the pixel `end`, both lit.
///
/// See the [module docs](self) for which pixels it lights (and the tie
/// rule).
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
/// use embedded_raster::{framebuffer::{buffer_size, Rgb565Le}, Framebuffer, Line};
///
/// let mut fb = Framebuffer::<Rgb565Le, 64, 64, { buffer_size::<Rgb565Le>(64, 64) }>::new();
/// Line::new(Point::new(1, 2), Point::new(60, 40))
///     .stroke(Rgb565::GREEN)
///     .draw(&mut fb)?;
/// assert_eq!(fb.pixel(Point::new(1, 2)), Some(Rgb565::GREEN));
/// assert_eq!(fb.pixel(Point::new(60, 40)), Some(Rgb565::GREEN));
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Line {
    /// The first end pixel.
    pub start: Point,
    /// The second end pixel.
    pub end: Point,
}

impl Line {
    /// Creates a line between two pixels.
    ///
    /// Any `i32` coordinates: 1-pixel and thick lines are exact over the
    /// whole `i32` plane, clipped to the target. A 1-pixel line costs
    /// work proportional to its visible pixels; a thick line whose
    /// corners leave the 20.12 range (`-524288..=524287`, module docs,
    /// "Thick lines") is set up in 128 bits and stepped in 64 on the rows
    /// where it crosses the target's columns. No input overflows.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::geometry::Point;
    /// use embedded_raster::Line;
    ///
    /// let line = Line::new(Point::new(i32::MIN, 0), Point::new(i32::MAX, 7));
    /// assert_eq!(line.end.y, 7);
    /// ```
    pub const fn new(start: Point, end: Point) -> Self {
        Self { start, end }
    }

    /// Styles the line as a 1-pixel Bresenham stroke of `color`; make it
    /// wider with [`StyledLine::stroke_width`].
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{geometry::Point, pixelcolor::BinaryColor};
    /// use embedded_raster::Line;
    ///
    /// let styled = Line::new(Point::zero(), Point::new(5, 5)).stroke(BinaryColor::On);
    /// assert_eq!(styled.color, BinaryColor::On);
    /// ```
    pub const fn stroke<C: PixelColor>(self, color: C) -> StyledLine<C> {
        StyledLine { line: self, color }
    }

    /// Calls `f` with the runs of the exact 1-pixel line inside `clip`, in
    /// order of growing x (x-major) or y (y-major), and stops at the first
    /// error `f` returns. No allocation, no panic, work proportional to
    /// the visible pixels. Any `i32` end points and any `clip`, including
    /// ones reaching past `i32::MAX` (an empty one emits nothing).
    ///
    /// # Examples
    ///
    /// ```
    /// use core::convert::Infallible;
    /// use embedded_graphics::{geometry::{Point, Size}, primitives::Rectangle};
    /// use embedded_raster::{Line, Run};
    ///
    /// // Slope 1/2: the ideal line crosses midpoints at odd x, where the
    /// // tie rule picks the smaller y.
    /// let clip = Rectangle::new(Point::zero(), Size::new(16, 16));
    /// let mut runs = [Run { start: Point::zero(), len: 0, vertical: false }; 3];
    /// let mut n = 0;
    /// Line::new(Point::new(0, 0), Point::new(4, 2)).for_each_run(&clip, |r| {
    ///     runs[n] = r;
    ///     n += 1;
    ///     Ok::<(), Infallible>(())
    /// })?;
    /// let pixels = runs.map(|r| (r.start.x, r.start.y, r.len));
    /// assert_eq!(pixels, [(0, 0, 2), (2, 1, 2), (4, 2, 1)]);
    /// # Ok::<(), Infallible>(())
    /// ```
    pub fn for_each_run<E>(
        &self,
        clip: &Rectangle,
        mut f: impl FnMut(Run) -> Result<(), E>,
    ) -> Result<(), E> {
        self.exact_runs(clip, false, &mut f)
    }

    /// Like [`for_each_run`](Self::for_each_run), with the pixels chosen by
    /// `algorithm`.
    ///
    /// # Examples
    ///
    /// ```
    /// use core::convert::Infallible;
    /// use embedded_graphics::{geometry::{Point, Size}, primitives::Rectangle};
    /// use embedded_raster::{Line, LineAlgorithm};
    ///
    /// let clip = Rectangle::new(Point::zero(), Size::new(16, 16));
    /// let mut lit = 0;
    /// Line::new(Point::new(0, 0), Point::new(4, 2)).for_each_run_with(LineAlgorithm::Naive, &clip, |r| {
    ///     lit += r.len;
    ///     Ok::<(), Infallible>(())
    /// })?;
    /// assert_eq!(lit, 5); // one per column
    /// # Ok::<(), Infallible>(())
    /// ```
    pub fn for_each_run_with<E>(
        &self,
        algorithm: LineAlgorithm,
        clip: &Rectangle,
        mut f: impl FnMut(Run) -> Result<(), E>,
    ) -> Result<(), E> {
        self.runs(algorithm, clip, false, &mut f)
    }

    /// The runs, without the pixel at `end` if `skip_end`.
    fn runs<E>(
        &self,
        algorithm: LineAlgorithm,
        clip: &Rectangle,
        skip_end: bool,
        f: &mut impl FnMut(Run) -> Result<(), E>,
    ) -> Result<(), E> {
        match algorithm {
            LineAlgorithm::Bresenham => self.exact_runs(clip, skip_end, f),
            other => variants::runs(
                other,
                &Canonical::new(self.start, self.end),
                clip,
                skip_end,
                f,
            ),
        }
    }

    /// The pixels the line lights inside `clip`, in order; `None` if none
    /// is inside.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{geometry::{Point, Size}, primitives::Rectangle};
    /// use embedded_raster::Line;
    ///
    /// let clip = Rectangle::new(Point::zero(), Size::new(8, 8));
    /// let pixels: Vec<Point> = Line::new(Point::new(-2, 0), Point::new(1, 3)).pixels(&clip).unwrap().collect();
    /// assert_eq!(pixels, [Point::new(0, 2), Point::new(1, 3)]);
    /// assert!(Line::new(Point::new(-9, 0), Point::new(-1, 3)).pixels(&clip).is_none());
    /// ```
    pub fn pixels(&self, clip: &Rectangle) -> Option<LinePixels> {
        self.exact_pixels(clip, false)
    }

    /// The exact (Bresenham) pixels, without the pixel at `end` if
    /// `skip_end`.
    fn exact_pixels(&self, clip: &Rectangle, skip_end: bool) -> Option<LinePixels> {
        let (c, v) = match Canonical::inside(self.start, self.end, clip, skip_end) {
            Some(inside) => inside,
            None => {
                let c = Canonical::new(self.start, self.end);
                (c, c.visible(clip, skip_end)?)
            }
        };
        Some(LinePixels::new(&c, v))
    }

    /// The exact (Bresenham) runs, without the pixel at `end` if `skip_end`.
    fn exact_runs<E>(
        &self,
        clip: &Rectangle,
        skip_end: bool,
        f: &mut impl FnMut(Run) -> Result<(), E>,
    ) -> Result<(), E> {
        match self.exact_pixels(clip, skip_end) {
            Some(pixels) => bresenham::runs(&pixels, f),
            None => Ok(()),
        }
    }
}

/// How a 1-pixel segment is drawn: the exact line, or a
/// [`LineAlgorithm`]. A type rather than a value, so that code drawing only
/// exact lines links none of the variants.
trait RunSource: Copy {
    /// Draws the segment into `sink`, without its last pixel if
    /// `skip_end`.
    fn draw_thin<C: PixelColor, S: SpanSink<C>>(
        self,
        line: &Line,
        skip_end: bool,
        color: C,
        sink: &mut S,
    ) -> Result<(), S::Error>;
}

/// The exact line.
#[derive(Debug, Clone, Copy)]
struct Exact;

/// As [`LinePixels`], which a framebuffer walks itself.
impl RunSource for Exact {
    fn draw_thin<C: PixelColor, S: SpanSink<C>>(
        self,
        line: &Line,
        skip_end: bool,
        color: C,
        sink: &mut S,
    ) -> Result<(), S::Error> {
        match line.exact_pixels(&sink.bounds(), skip_end) {
            Some(pixels) => sink.fill_line(pixels, color),
            None => Ok(()),
        }
    }
}

/// A [`Line`] with a colour: the exact 1-pixel line, a
/// [`Drawable`](embedded_graphics_core::Drawable).
///
/// On a `DrawTarget` it is one
/// [`fill_solid`](embedded_graphics_core::draw_target::DrawTarget::fill_solid)
/// per [`Run`]; through a [`SpanSink`] the sink gets the whole line (but
/// for column `i32::MAX` with the provided methods: see [`SpanSink`]).
/// [`stroke_width`](Self::stroke_width) makes a [`ThickLine`] and
/// [`algorithm`](Self::algorithm) a [`StyledLineVariant`]: separate types,
/// so that firmware drawing only exact 1-pixel lines links neither the
/// thick lines (their polygon fill, 64-bit edge setup and integer square
/// root) nor the variants.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
/// use embedded_raster::{framebuffer::{buffer_size, Gray8Bytes}, Framebuffer, Line};
///
/// let mut fb = Framebuffer::<Gray8Bytes, 32, 32, { buffer_size::<Gray8Bytes>(32, 32) }>::new();
/// Line::new(Point::new(2, 10), Point::new(20, 13)).stroke(Gray8::WHITE).draw(&mut fb)?;
/// let lit = |x, y| fb.pixel(Point::new(x, y)) == Some(Gray8::WHITE);
/// assert!(lit(2, 10) && lit(20, 13) && !lit(2, 11) && !lit(21, 13));
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct StyledLine<C> {
    /// The geometry.
    pub line: Line,
    /// The stroke colour.
    pub color: C,
}

impl<C: Copy> StyledLine<C> {
    /// This line `width` pixels wide, a [`ThickLine`].
    ///
    /// Any `u32`: 0 draws nothing; 1 is the same 1-pixel line; 2 and more
    /// is a filled rectangle that wide (module docs, "Thick lines"),
    /// widths over 65535 drawn as 65535.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{geometry::Point, pixelcolor::BinaryColor};
    /// use embedded_raster::Line;
    ///
    /// let thick = Line::new(Point::zero(), Point::new(5, 5)).stroke(BinaryColor::On).stroke_width(4);
    /// assert_eq!(thick.width, 4);
    /// ```
    pub const fn stroke_width(self, width: u32) -> ThickLine<C> {
        ThickLine {
            line: self.line,
            color: self.color,
            width,
        }
    }

    /// Sets the algorithm of 1-pixel lines.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{geometry::Point, pixelcolor::BinaryColor};
    /// use embedded_raster::{Line, LineAlgorithm};
    ///
    /// let styled = Line::new(Point::zero(), Point::new(5, 2)).stroke(BinaryColor::On).algorithm(LineAlgorithm::Naive);
    /// assert_eq!((styled.algorithm, styled.width), (LineAlgorithm::Naive, 1));
    /// ```
    pub fn algorithm(self, algorithm: LineAlgorithm) -> StyledLineVariant<C> {
        StyledLineVariant {
            line: self.line,
            color: self.color,
            width: 1,
            algorithm,
        }
    }
}

impl<C: PixelColor> SpanDrawable for StyledLine<C> {
    type Color = C;

    fn draw_spans<S: SpanSink<C>>(&self, sink: &mut S) -> Result<(), S::Error> {
        Exact.draw_thin(&self.line, false, self.color, sink)
    }
}

/// A [`Line`] with a colour and a width, made by
/// [`StyledLine::stroke_width`]: a [`Drawable`](embedded_graphics_core::Drawable).
///
/// Width 1 draws the exact 1-pixel line and width 0 nothing. Wider lines
/// are filled rectangles (see the [module docs](self#thick-lines)), walked
/// as convex polygons, one span per row. Widths above 65535 px
/// draw as 65535 px.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
/// use embedded_raster::{framebuffer::{buffer_size, Gray8Bytes}, Framebuffer, Line};
///
/// let mut fb = Framebuffer::<Gray8Bytes, 32, 32, { buffer_size::<Gray8Bytes>(32, 32) }>::new();
/// // A horizontal line 3 px wide covers rows 9, 10 and 11, x from 2 to 20.
/// Line::new(Point::new(2, 10), Point::new(20, 10))
///     .stroke(Gray8::WHITE)
///     .stroke_width(3)
///     .draw(&mut fb)?;
/// let lit = |x, y| fb.pixel(Point::new(x, y)) == Some(Gray8::WHITE);
/// assert!(lit(2, 9) && lit(20, 11) && !lit(1, 10) && !lit(21, 10) && !lit(10, 12));
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct ThickLine<C> {
    /// The geometry.
    pub line: Line,
    /// The stroke colour.
    pub color: C,
    /// The stroke width in pixels.
    pub width: u32,
}

impl<C> ThickLine<C> {
    /// Sets the stroke width in pixels (any `u32`, as
    /// [`StyledLine::stroke_width`]).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{geometry::Point, pixelcolor::BinaryColor};
    /// use embedded_raster::Line;
    ///
    /// let thick = Line::new(Point::zero(), Point::new(5, 5)).stroke(BinaryColor::On).stroke_width(4).stroke_width(2);
    /// assert_eq!(thick.width, 2);
    /// ```
    pub const fn stroke_width(mut self, width: u32) -> Self {
        self.width = width;
        self
    }

    /// Sets the algorithm of the line where it is 1 pixel wide; wider
    /// lines are the same rectangles whatever the algorithm.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{geometry::Point, pixelcolor::BinaryColor};
    /// use embedded_raster::{Line, LineAlgorithm};
    ///
    /// let s = Line::new(Point::zero(), Point::new(5, 2)).stroke(BinaryColor::On).stroke_width(3).algorithm(LineAlgorithm::Dda);
    /// assert_eq!((s.algorithm, s.width), (LineAlgorithm::Dda, 3));
    /// ```
    pub fn algorithm(self, algorithm: LineAlgorithm) -> StyledLineVariant<C> {
        StyledLineVariant {
            line: self.line,
            color: self.color,
            width: self.width,
            algorithm,
        }
    }
}

impl<C: PixelColor> SpanDrawable for ThickLine<C> {
    type Color = C;

    fn draw_spans<S: SpanSink<C>>(&self, sink: &mut S) -> Result<(), S::Error> {
        draw_segment(self.line, self.width, Exact, false, self.color, sink)
    }
}

drawable_through_spans!(StyledLine, ThickLine, StyledLineVariant);

/// Draws one line (or polyline segment) into `sink`.
fn draw_segment<C: PixelColor, S: SpanSink<C>>(
    line: Line,
    width: u32,
    source: impl RunSource,
    skip_end: bool,
    color: C,
    sink: &mut S,
) -> Result<(), S::Error> {
    match width {
        0 => Ok(()),
        1 => source.draw_thin(&line, skip_end, color, sink),
        w => match thick::corners(line.start, line.end, w) {
            Ok(c) => match fill_monotone(&c, Shape::Parallelogram, sink, color) {
                Some(done) => done,
                // Over 131,072 px a side: the two triangles sharing its
                // diagonal, which light the same pixels, in 64 bits (the
                // triangles' own copy for the sink).
                None => [[c[0], c[1], c[2]], [c[0], c[2], c[3]]]
                    .into_iter()
                    .try_for_each(|[a, b, d]| Triangle::new(a, b, d).fill(color).draw_spans(sink)),
            },
            // A corner past the 20.12 range.
            Err(c) => fill_far_convex(&c, color, sink),
        },
    }
}

/// Writes a run (inside the sink's bounds) into `sink`.
#[inline(always)]
pub(crate) fn fill_run<C: Copy, S: SpanSink<C> + ?Sized>(
    sink: &mut S,
    run: Run,
    color: C,
) -> Result<(), S::Error> {
    if run.vertical {
        return sink.fill_column(run.start, run.len, color);
    }
    match run.span() {
        Some(span) => sink.fill_span(span, color),
        // A run ending at i32::MAX, which a span cannot hold.
        None => sink.fill_rect(&run.rect(), color),
    }
}

// `Point` has no `defmt::Format` here, so these are written out.
#[cfg(feature = "defmt")]
impl defmt::Format for Run {
    fn format(&self, f: defmt::Formatter<'_>) {
        defmt::write!(
            f,
            "Run {{ start: ({=i32}, {=i32}), len: {=u32}, vertical: {=bool} }}",
            self.start.x,
            self.start.y,
            self.len,
            self.vertical
        );
    }
}

#[cfg(feature = "defmt")]
impl defmt::Format for Line {
    fn format(&self, f: defmt::Formatter<'_>) {
        defmt::write!(
            f,
            "Line {{ start: ({=i32}, {=i32}), end: ({=i32}, {=i32}) }}",
            self.start.x,
            self.start.y,
            self.end.x,
            self.end.y
        );
    }
}
