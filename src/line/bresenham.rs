//! The integer midpoint (Bresenham) stepping loop, emitting runs.
//!
//! Starting from the exactly clipped first pixel and decision variable (see
//! [`clip`](super::clip)), each step adds `2 dminor` to the decision
//! variable and, when it is not negative, ends the current run, moves one
//! pixel along the minor axis and subtracts `2 dmajor`. One add per pixel,
//! one compare, no multiply or divide. The variable stays within
//! `[-2 dmajor, 2 dmajor]`, so the loop runs in `i32` for lines shorter
//! than `2^30` pixels along their major axis and in `i64` otherwise.

use super::{
    clip::{Canonical, Visible},
    Run,
};
use crate::raster::wide::Wide;
use embedded_graphics_core::geometry::Point;

/// Calls `emit` with the runs of the visible part `v` of `c`, in order of
/// growing major coordinate.
pub(crate) fn runs<E>(
    c: &Canonical,
    v: &Visible,
    emit: &mut impl FnMut(Run) -> Result<(), E>,
) -> Result<(), E> {
    match (c.x_major, c.dmajor < 1 << 30) {
        (true, true) => step::<i32, true, E>(c, v, emit),
        (true, false) => step::<i64, true, E>(c, v, emit),
        (false, true) => step::<i32, false, E>(c, v, emit),
        (false, false) => step::<i64, false, E>(c, v, emit),
    }
}

#[inline(always)]
fn step<T: Wide, const X_MAJOR: bool, E>(
    c: &Canonical,
    v: &Visible,
    emit: &mut impl FnMut(Run) -> Result<(), E>,
) -> Result<(), E> {
    // Within [-2 dmajor, 2 dmajor]: `runs` picks a width that holds them.
    let (Some(two_minor), Some(two_major), Some(mut d)) = (
        T::narrow(2 * c.dminor),
        T::narrow(2 * c.dmajor),
        T::narrow(v.decision),
    ) else {
        return Ok(());
    };
    let s: i32 = if c.minor_step > 0 { 1 } else { -1 };
    let (mut major, last, mut minor) = (v.first_major, v.last_major, v.first_minor);
    let mut start = major;
    loop {
        if major == last {
            return emit(Run::along(X_MAJOR, start, major, minor));
        }
        if d >= T::ZERO {
            emit(Run::along(X_MAJOR, start, major, minor))?;
            d = d - two_major;
            // The next pixel is a pixel of the line: no overflow.
            minor += s;
            start = major + 1;
        }
        d = d + two_minor;
        major += 1;
    }
}

/// The pixels a 1-pixel [`Line`](super::Line) lights inside a sink's
/// bounds, in order of growing major coordinate: what
/// [`SpanSink::fill_line`](crate::SpanSink::fill_line) receives.
///
/// It iterates over the pixels as [`Point`]s and, with
/// [`for_each_run`](Self::for_each_run), over the same pixels as
/// [`Run`]s. A sink that knows its memory (the crate's
/// [`Framebuffer`](crate::Framebuffer)) walks the pixels itself, one add
/// and one compare of the Bresenham decision per pixel.
///
/// # Examples
///
/// ```
/// use core::convert::Infallible;
/// use embedded_graphics_core::{geometry::{Point, Size}, pixelcolor::BinaryColor, primitives::Rectangle};
/// use embedded_raster::{line::LinePixels, Line, Span, SpanDrawable, SpanSink};
///
/// /// Records the pixels of the lines drawn into it.
/// struct Pixels(Vec<Point>);
///
/// impl SpanSink<BinaryColor> for Pixels {
///     type Error = Infallible;
///     fn bounds(&self) -> Rectangle {
///         Rectangle::new(Point::zero(), Size::new(8, 8))
///     }
///     fn fill_span(&mut self, _: Span, _: BinaryColor) -> Result<(), Infallible> {
///         Ok(())
///     }
///     fn fill_line(&mut self, pixels: LinePixels, _: BinaryColor) -> Result<(), Infallible> {
///         self.0.extend(pixels);
///         Ok(())
///     }
/// }
///
/// let mut sink = Pixels(Vec::new());
/// Line::new(Point::new(0, 0), Point::new(4, 2)).stroke(BinaryColor::On).draw_spans(&mut sink)?;
/// let want = [(0, 0), (1, 0), (2, 1), (3, 1), (4, 2)].map(|(x, y)| Point::new(x, y));
/// assert_eq!(sink.0, want);
/// # Ok::<(), Infallible>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LinePixels {
    pub(crate) c: Canonical,
    pub(crate) v: Visible,
}

impl LinePixels {
    /// The number of pixels.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics_core::{geometry::{Point, Size}, primitives::Rectangle};
    /// use embedded_raster::Line;
    ///
    /// let clip = Rectangle::new(Point::zero(), Size::new(8, 8));
    /// let pixels = Line::new(Point::new(-5, 1), Point::new(20, 3)).pixels(&clip).unwrap();
    /// assert_eq!(pixels.len(), 8);
    /// ```
    pub fn len(&self) -> u32 {
        self.v
            .last_major
            .abs_diff(self.v.first_major)
            .saturating_add(1)
    }

    /// Always `false`: an empty line has no `LinePixels`.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics_core::{geometry::{Point, Size}, primitives::Rectangle};
    /// use embedded_raster::Line;
    ///
    /// let clip = Rectangle::new(Point::zero(), Size::new(8, 8));
    /// assert!(!Line::new(Point::zero(), Point::zero()).pixels(&clip).unwrap().is_empty());
    /// ```
    pub fn is_empty(&self) -> bool {
        false
    }

    /// Calls `f` with the same pixels as horizontal runs (an x-major line)
    /// or vertical runs (a y-major one), in order, stopping at the first
    /// error.
    ///
    /// # Examples
    ///
    /// ```
    /// use core::convert::Infallible;
    /// use embedded_graphics_core::{geometry::{Point, Size}, primitives::Rectangle};
    /// use embedded_raster::Line;
    ///
    /// let clip = Rectangle::new(Point::zero(), Size::new(8, 8));
    /// let pixels = Line::new(Point::new(0, 0), Point::new(4, 2)).pixels(&clip).unwrap();
    /// let mut lens = Vec::new();
    /// pixels.for_each_run(|r| {
    ///     lens.push(r.len);
    ///     Ok::<(), Infallible>(())
    /// })?;
    /// assert_eq!(lens, [2, 2, 1]);
    /// # Ok::<(), Infallible>(())
    /// ```
    pub fn for_each_run<E>(&self, mut f: impl FnMut(Run) -> Result<(), E>) -> Result<(), E> {
        runs(&self.c, &self.v, &mut f)
    }

    /// Whether the line is x-major and moves along its minor axis less
    /// than once per four pixels, so that its runs are long spans.
    pub(crate) fn has_long_spans(&self) -> bool {
        self.c.x_major && self.c.dminor.saturating_mul(4) < self.c.dmajor
    }

    /// Whether the line is x-major (one pixel per column).
    pub(crate) fn x_major(&self) -> bool {
        self.c.x_major
    }

    /// Walks the pixels with an index that moves by `major` per pixel and
    /// by `minor` more where the line moves along its minor axis, starting
    /// at `first`, calling `plot` with each index: for sinks that address
    /// their memory themselves. The decision variable is kept in the
    /// narrowest width that holds it.
    #[inline(always)]
    pub(crate) fn walk(&self, first: isize, major: isize, minor: isize, plot: impl FnMut(isize)) {
        if self.c.dmajor < 1 << 30 {
            self.walk_in::<i32>(first, major, minor, plot);
        } else {
            self.walk_in::<i64>(first, major, minor, plot);
        }
    }

    #[inline(always)]
    fn walk_in<T: Wide>(
        &self,
        first: isize,
        major: isize,
        minor: isize,
        mut plot: impl FnMut(isize),
    ) {
        // Within [-2 dmajor, 2 dmajor]: `walk` picks a width that holds them.
        let (Some(two_minor), Some(two_major), Some(mut d)) = (
            T::narrow(2 * self.c.dminor),
            T::narrow(2 * self.c.dmajor),
            T::narrow(self.v.decision),
        ) else {
            return;
        };
        let mut at = first;
        plot(at);
        for _ in 1..self.len() {
            if d >= T::ZERO {
                d = d - two_major;
                at += minor;
            }
            d = d + two_minor;
            at += major;
            plot(at);
        }
    }

    /// The first pixel.
    pub(crate) fn first(&self) -> Point {
        if self.c.x_major {
            Point::new(self.v.first_major, self.v.first_minor)
        } else {
            Point::new(self.v.first_minor, self.v.first_major)
        }
    }

    /// +1 or -1: how the minor coordinate moves.
    pub(crate) fn minor_step(&self) -> i32 {
        if self.c.minor_step > 0 {
            1
        } else {
            -1
        }
    }
}

/// The pixels one by one.
impl Iterator for LinePixels {
    type Item = Point;

    fn next(&mut self) -> Option<Point> {
        if self.v.first_major > self.v.last_major {
            return None;
        }
        let p = self.first();
        if self.v.first_major < self.v.last_major {
            let d = self.v.decision;
            let moves = d >= 0;
            // |d| <= 2 dmajor < 2^33 throughout.
            self.v.decision = d + 2 * self.c.dminor - if moves { 2 * self.c.dmajor } else { 0 };
            if moves {
                self.v.first_minor += self.minor_step();
            }
            self.v.first_major += 1;
        } else {
            // Past the end, without stepping beyond i32.
            self.v.last_major -= 1;
        }
        Some(p)
    }
}
