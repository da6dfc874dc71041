//! Polylines: connected lines over a borrowed list of points.

use embedded_graphics_core::{geometry::Point, pixelcolor::PixelColor, primitives::Rectangle};

use super::{draw_segment, Exact, Line, LineAlgorithm, Run, RunSource};
use crate::{
    raster::sink::{drawable_through_spans, SpanDrawable, SpanSink},
    stroke::{Join, Outline, Stroke},
};

/// Connected lines through `points`, in order, each joint pixel lit once.
///
/// Each segment is the [`Line`] between consecutive points, drawn without
/// its last pixel except for the final segment, so a joint pixel (the end
/// of one segment, the start of the next) is written once: a polyline that
/// does not overlap itself writes every pixel once. A closed polyline (at
/// least 3 points, the last equal to the first, not all equal) also leaves
/// out the final segment's last pixel, which the first segment lit. One
/// point draws that pixel; no points draw nothing.
///
/// Thick polylines ([`StyledPolyline::stroke_width`] above 1) are one
/// filled stroke: each segment's rectangle (as a thick [`Line`]'s, butt
/// ends half a pixel beyond the end pixels' centres at the polyline's two
/// ends) and, where segments meet, a [`Join`] filling the outside of the
/// turn ([`Join::Miter`] by default, see [`StyledPolyline::join`]). The
/// union is filled under the crate's sampling rule, so every pixel of it
/// is written exactly once, on the inside of turns and where the polyline
/// crosses itself too, and there is no gap at any joint. A closed polyline
/// joins at its first point as well. Exact for any `i32` points;
/// [`Join`] has the details and the cost.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
/// use embedded_raster::{framebuffer::{buffer_size, Gray8Bytes}, Framebuffer, Polyline};
///
/// let mut fb = Framebuffer::<Gray8Bytes, 16, 16, { buffer_size::<Gray8Bytes>(16, 16) }>::new();
/// let points = [Point::new(1, 1), Point::new(12, 1), Point::new(12, 9), Point::new(3, 14)];
/// Polyline::new(&points).stroke(Gray8::WHITE).draw(&mut fb)?;
/// assert_eq!(fb.pixel(Point::new(12, 1)), Some(Gray8::WHITE));
/// assert_eq!(fb.pixel(Point::new(3, 14)), Some(Gray8::WHITE));
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Polyline<'a> {
    /// The vertices, in drawing order.
    pub points: &'a [Point],
}

impl<'a> Polyline<'a> {
    /// Creates a polyline through `points`.
    ///
    /// Any number of points (one is a single pixel, none draws nothing),
    /// with any `i32` coordinates, as for [`Line::new`](crate::Line::new).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::geometry::Point;
    /// use embedded_raster::Polyline;
    ///
    /// let points = [Point::new(0, 0), Point::new(5, 5)];
    /// assert_eq!(Polyline::new(&points).points.len(), 2);
    /// ```
    pub const fn new(points: &'a [Point]) -> Self {
        Self { points }
    }

    /// Styles the polyline as a 1-pixel Bresenham stroke of `color`.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{geometry::Point, pixelcolor::BinaryColor};
    /// use embedded_raster::Polyline;
    ///
    /// let points = [Point::zero(), Point::new(3, 1)];
    /// let styled = Polyline::new(&points).stroke(BinaryColor::On);
    /// assert_eq!(styled.width, 1);
    /// ```
    pub const fn stroke<C: PixelColor>(self, color: C) -> StyledPolyline<'a, C> {
        StyledPolyline {
            polyline: self,
            color,
            width: 1,
            join: Join::Miter,
        }
    }

    /// Calls `f` with the runs of the 1-pixel polyline by `algorithm`
    /// inside `clip`, segment by segment (each in its own run order), and
    /// stops at the first error `f` returns.
    ///
    /// # Examples
    ///
    /// ```
    /// use core::convert::Infallible;
    /// use embedded_graphics::{geometry::{Point, Size}, primitives::Rectangle};
    /// use embedded_raster::{LineAlgorithm, Polyline};
    ///
    /// // An L: 5 pixels across, 4 more down; the corner is lit once.
    /// let points = [Point::new(0, 0), Point::new(4, 0), Point::new(4, 4)];
    /// let clip = Rectangle::new(Point::zero(), Size::new(8, 8));
    /// let mut lit = 0;
    /// Polyline::new(&points).for_each_run(LineAlgorithm::Bresenham, &clip, |r| {
    ///     lit += r.len;
    ///     Ok::<(), Infallible>(())
    /// })?;
    /// assert_eq!(lit, 9);
    /// # Ok::<(), Infallible>(())
    /// ```
    pub fn for_each_run<E>(
        &self,
        algorithm: LineAlgorithm,
        clip: &Rectangle,
        mut f: impl FnMut(Run) -> Result<(), E>,
    ) -> Result<(), E> {
        self.segments()
            .try_for_each(|(line, skip_end)| line.runs(algorithm, clip, skip_end, &mut f))
    }

    /// Whether the polyline is closed: at least 3 points, the last equal
    /// to the first, not all equal.
    fn is_closed(&self) -> bool {
        let points = self.points;
        points.len() >= 3
            && points.first() == points.last()
            && points.iter().any(|p| Some(p) != points.first())
    }

    /// The thick stroke of `width` (at least 2) with `join`: a closed
    /// polyline is the ring of its points without the repeated last one.
    fn thick(&self, width: u32, join: Join) -> Stroke<'a> {
        let closed = self.is_closed();
        let points = match self.points.split_last() {
            Some((_, ring)) if closed => ring,
            _ => self.points,
        };
        Stroke::new(Outline::Points(points), closed, width, join)
    }

    /// Each segment and whether its last pixel is left out.
    fn segments(&self) -> impl Iterator<Item = (Line, bool)> + 'a {
        let points = self.points;
        let n = points.len();
        let closed = self.is_closed();
        let single = points
            .first()
            .filter(|_| n == 1)
            .map(|&p| (Line::new(p, p), false));
        let pairs = points.windows(2).enumerate().map(move |(i, w)| {
            let final_segment = i + 2 == n;
            (Line::new(w[0], w[1]), !final_segment || closed)
        });
        single.into_iter().chain(pairs)
    }
}

/// A [`Polyline`] with a colour and a width: a [`Drawable`](embedded_graphics_core::Drawable) of exact
/// segments ([`algorithm`](Self::algorithm) gives a [`StyledPolylineVariant`]).
/// Width 0 draws nothing; see [`Polyline`] for the other widths.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::BinaryColor, prelude::*};
/// use embedded_raster::{framebuffer::{buffer_size, BinaryMsb}, Framebuffer, Polyline};
///
/// let mut fb = Framebuffer::<BinaryMsb, 32, 32, { buffer_size::<BinaryMsb>(32, 32) }>::new();
/// let zigzag = [Point::new(0, 0), Point::new(10, 20), Point::new(20, 0), Point::new(31, 31)];
/// Polyline::new(&zigzag).stroke(BinaryColor::On).stroke_width(3).draw(&mut fb)?;
/// assert_eq!(fb.pixel(Point::new(10, 20)), Some(BinaryColor::On));
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct StyledPolyline<'a, C> {
    /// The geometry.
    pub polyline: Polyline<'a>,
    /// The stroke colour.
    pub color: C,
    /// The stroke width in pixels.
    pub width: u32,
    /// How thick segments meet ([`Join::Miter`] unless set).
    pub join: Join,
}

impl<'a, C> StyledPolyline<'a, C> {
    /// Sets the stroke width in pixels.
    ///
    /// Any `u32`: 0 draws nothing; 1 is the 1-pixel polyline; 2 and more is
    /// a thick stroke that wide, its segments meeting in [`join`](Self::join)s
    /// and each pixel written once (see [`Polyline`]; see
    /// [`Join`](crate::Join) for sinks on which overdraw is invisible),
    /// widths over 65535 drawn as 65535.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{geometry::Point, pixelcolor::BinaryColor};
    /// use embedded_raster::Polyline;
    ///
    /// let points = [Point::zero(), Point::new(3, 1)];
    /// let p = Polyline::new(&points).stroke(BinaryColor::On).stroke_width(2);
    /// assert_eq!(p.width, 2);
    /// ```
    pub const fn stroke_width(mut self, width: u32) -> Self {
        self.width = width;
        self
    }

    /// Sets how the segments of a thick polyline meet: [`Join::Miter`]
    /// (the default, a bevel past [`MITER_LIMIT`](crate::MITER_LIMIT)),
    /// [`Join::Bevel`] or [`Join::Round`]. 1-pixel polylines have no joins.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::BinaryColor, prelude::*};
    /// use embedded_raster::{framebuffer::{buffer_size, BinaryMsb}, Framebuffer, Join, Polyline};
    ///
    /// let mut fb = Framebuffer::<BinaryMsb, 16, 16, { buffer_size::<BinaryMsb>(16, 16) }>::new();
    /// // A right angle 5 px wide: the bevel cuts off the outer corner.
    /// let points = [Point::new(2, 4), Point::new(10, 4), Point::new(10, 14)];
    /// Polyline::new(&points).stroke(BinaryColor::On).stroke_width(5).join(Join::Bevel).draw(&mut fb)?;
    /// assert_eq!(fb.pixel(Point::new(12, 2)), Some(BinaryColor::Off));
    /// assert_eq!(fb.pixel(Point::new(11, 3)), Some(BinaryColor::On));
    /// # Ok::<(), core::convert::Infallible>(())
    /// ```
    pub const fn join(mut self, join: Join) -> Self {
        self.join = join;
        self
    }

    /// Sets the algorithm of 1-pixel segments.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{geometry::Point, pixelcolor::BinaryColor};
    /// use embedded_raster::{LineAlgorithm, Polyline};
    ///
    /// let points = [Point::zero(), Point::new(3, 1)];
    /// let p = Polyline::new(&points).stroke(BinaryColor::On).algorithm(LineAlgorithm::Dda);
    /// assert_eq!(p.algorithm, LineAlgorithm::Dda);
    /// ```
    pub fn algorithm(self, algorithm: LineAlgorithm) -> StyledPolylineVariant<'a, C> {
        StyledPolylineVariant {
            polyline: self.polyline,
            color: self.color,
            width: self.width,
            join: self.join,
            algorithm,
        }
    }
}

impl<C: PixelColor> SpanDrawable for StyledPolyline<'_, C> {
    type Color = C;

    fn draw_spans<S: SpanSink<C>>(&self, sink: &mut S) -> Result<(), S::Error> {
        draw_polyline(
            &self.polyline,
            self.width,
            self.join,
            Exact,
            self.color,
            sink,
        )
    }
}

/// A [`StyledPolyline`] whose 1-pixel segments come from a chosen
/// [`LineAlgorithm`], made by [`StyledPolyline::algorithm`]: a
/// [`Drawable`](embedded_graphics_core::Drawable).
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::BinaryColor, prelude::*};
/// use embedded_raster::{framebuffer::{buffer_size, BinaryMsb}, Framebuffer, LineAlgorithm, Polyline};
///
/// let mut fb = Framebuffer::<BinaryMsb, 16, 16, { buffer_size::<BinaryMsb>(16, 16) }>::new();
/// let points = [Point::new(0, 0), Point::new(15, 6), Point::new(3, 15)];
/// Polyline::new(&points).stroke(BinaryColor::On).algorithm(LineAlgorithm::Naive).draw(&mut fb)?;
/// assert_eq!(fb.pixel(Point::new(3, 15)), Some(BinaryColor::On));
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct StyledPolylineVariant<'a, C> {
    /// The geometry.
    pub polyline: Polyline<'a>,
    /// The stroke colour.
    pub color: C,
    /// The stroke width in pixels.
    pub width: u32,
    /// How thick segments meet ([`Join::Miter`] unless set).
    pub join: Join,
    /// How 1-pixel segments choose their pixels.
    pub algorithm: LineAlgorithm,
}

impl<C> StyledPolylineVariant<'_, C> {
    /// Sets the stroke width in pixels.
    ///
    /// Any `u32`: 0 draws nothing; 1 is the 1-pixel polyline; 2 and more is
    /// a thick stroke that wide, its segments meeting in [`join`](Self::join)s
    /// and each pixel written once (see [`Polyline`]; see
    /// [`Join`](crate::Join) for sinks on which overdraw is invisible),
    /// widths over 65535 drawn as 65535.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{geometry::Point, pixelcolor::BinaryColor};
    /// use embedded_raster::{LineAlgorithm, Polyline};
    ///
    /// let points = [Point::zero(), Point::new(3, 1)];
    /// let p = Polyline::new(&points).stroke(BinaryColor::On).algorithm(LineAlgorithm::Dda).stroke_width(2);
    /// assert_eq!(p.width, 2);
    /// ```
    pub const fn stroke_width(mut self, width: u32) -> Self {
        self.width = width;
        self
    }

    /// Sets how the segments of a thick polyline meet: [`Join::Miter`]
    /// (the default, a bevel past [`MITER_LIMIT`](crate::MITER_LIMIT)),
    /// [`Join::Bevel`] or [`Join::Round`]. 1-pixel polylines have no joins.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::BinaryColor, prelude::*};
    /// use embedded_raster::{framebuffer::{buffer_size, BinaryMsb}, Framebuffer, Join, Polyline};
    ///
    /// let mut fb = Framebuffer::<BinaryMsb, 16, 16, { buffer_size::<BinaryMsb>(16, 16) }>::new();
    /// // A right angle 5 px wide: the bevel cuts off the outer corner.
    /// let points = [Point::new(2, 4), Point::new(10, 4), Point::new(10, 14)];
    /// Polyline::new(&points).stroke(BinaryColor::On).stroke_width(5).join(Join::Bevel).draw(&mut fb)?;
    /// assert_eq!(fb.pixel(Point::new(12, 2)), Some(BinaryColor::Off));
    /// assert_eq!(fb.pixel(Point::new(11, 3)), Some(BinaryColor::On));
    /// # Ok::<(), core::convert::Infallible>(())
    /// ```
    pub const fn join(mut self, join: Join) -> Self {
        self.join = join;
        self
    }

    /// Sets the algorithm of 1-pixel segments.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{geometry::Point, pixelcolor::BinaryColor};
    /// use embedded_raster::{LineAlgorithm, Polyline};
    ///
    /// let points = [Point::zero(), Point::new(3, 1)];
    /// let p = Polyline::new(&points).stroke(BinaryColor::On).algorithm(LineAlgorithm::Naive).algorithm(LineAlgorithm::Dda);
    /// assert_eq!(p.algorithm, LineAlgorithm::Dda);
    /// ```
    pub const fn algorithm(mut self, algorithm: LineAlgorithm) -> Self {
        self.algorithm = algorithm;
        self
    }
}

impl<C: PixelColor> SpanDrawable for StyledPolylineVariant<'_, C> {
    type Color = C;

    fn draw_spans<S: SpanSink<C>>(&self, sink: &mut S) -> Result<(), S::Error> {
        draw_polyline(
            &self.polyline,
            self.width,
            self.join,
            self.algorithm,
            self.color,
            sink,
        )
    }
}

drawable_through_spans!(StyledPolyline<'_>, StyledPolylineVariant<'_>);

/// Draws every segment into `sink`, each joint pixel once.
fn draw_polyline<C: PixelColor, S: SpanSink<C>>(
    polyline: &Polyline<'_>,
    width: u32,
    join: Join,
    source: impl RunSource,
    color: C,
    sink: &mut S,
) -> Result<(), S::Error> {
    match width {
        0 => Ok(()),
        1 => polyline
            .segments()
            .try_for_each(|(line, skip_end)| draw_segment(line, 1, source, skip_end, color, sink)),
        w => polyline.thick(w, join).draw(color, sink),
    }
}

#[cfg(feature = "defmt")]
impl defmt::Format for Polyline<'_> {
    fn format(&self, f: defmt::Formatter<'_>) {
        defmt::write!(f, "Polyline {{ {=usize} points }}", self.points.len());
    }
}
