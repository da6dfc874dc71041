//! Filled triangles.

pub(crate) mod fill;
mod variants;

pub use variants::{SubpixelPrecision, TriangleAlgorithm};

use embedded_graphics_core::{geometry::Point, pixelcolor::PixelColor, primitives::Rectangle};

use crate::{
    error::CoordinateOutOfRange,
    raster::sink::{drawable_through_spans, SpanDrawable, SpanSink},
    span::Span,
    stroke::{Join, Outline, Stroke},
    vertex::Vertex,
};

/// A triangle on the continuous plane, with 20.12 fixed-point vertices in
/// either winding.
///
/// It lights pixel `(i, j)` iff the centre `(i + 1/2, j + 1/2)` is inside,
/// a centre exactly on an edge counting as inside only on a left edge or a
/// top edge (the top-left rule; see the [crate docs](crate)). Triangles that
/// share an edge therefore light every pixel along it exactly once, and a
/// triangle with zero area lights nothing.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
/// use embedded_raster::{Triangle, Vertex};
/// # use embedded_graphics::{primitives::Rectangle, Pixel};
/// # struct Display;
/// # impl OriginDimensions for Display { fn size(&self) -> Size { Size::new(64, 64) } }
/// # impl DrawTarget for Display {
/// #     type Color = Rgb565;
/// #     type Error = core::convert::Infallible;
/// #     fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(&mut self, _: I) -> Result<(), Self::Error> { Ok(()) }
/// # }
/// # let mut display = Display;
///
/// let v = |x: f32, y: f32| Vertex::try_from_num(x, y).unwrap();
/// Triangle::new(v(2.0, 1.5), v(60.25, 8.0), v(20.0, 50.75))
///     .fill(Rgb565::RED)
///     .draw(&mut display)?;
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Triangle {
    /// The three corners.
    pub vertices: [Vertex; 3],
}

impl Triangle {
    /// Creates a triangle from its corners: any [`Vertex`]es (all are in
    /// range), drawn exactly on any clip rectangle, degenerate ones
    /// (collinear corners) lighting nothing.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::{Triangle, Vertex};
    ///
    /// let t = Triangle::new(Vertex::from_raw(0, 0), Vertex::from_raw(4096, 0), Vertex::from_raw(0, 4096));
    /// assert_eq!(t.vertices[1].raw(), (4096, 0));
    /// ```
    pub const fn new(a: Vertex, b: Vertex, c: Vertex) -> Self {
        Self {
            vertices: [a, b, c],
        }
    }

    /// Creates a triangle whose corners are the centres of three pixels.
    ///
    /// # Errors
    ///
    /// [`CoordinateOutOfRange`] if a coordinate is outside
    /// `-524288..=524287`.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::geometry::Point;
    /// use embedded_raster::Triangle;
    ///
    /// let t = Triangle::from_points(Point::new(0, 0), Point::new(9, 0), Point::new(0, 9))?;
    /// assert_eq!(t.vertices[0].raw(), (2048, 2048));
    /// assert!(Triangle::from_points(Point::new(i32::MAX, 0), Point::zero(), Point::zero()).is_err());
    /// # Ok::<(), embedded_raster::CoordinateOutOfRange>(())
    /// ```
    pub fn from_points(a: Point, b: Point, c: Point) -> Result<Self, CoordinateOutOfRange> {
        Ok(Self::new(a.try_into()?, b.try_into()?, c.try_into()?))
    }

    /// Styles the triangle as filled with `color`, ready to draw.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use embedded_raster::Triangle;
    ///
    /// let filled = Triangle::default().fill(BinaryColor::On);
    /// assert_eq!(filled.color, BinaryColor::On);
    /// ```
    pub const fn fill<C: PixelColor>(self, color: C) -> FilledTriangle<C> {
        FilledTriangle {
            triangle: self,
            color,
        }
    }

    /// Styles the triangle's outline as a stroke of `color`, 1 px wide
    /// with [`Join::Miter`] corners; change them with
    /// [`StrokedTriangle::stroke_width`] and [`StrokedTriangle::join`].
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use embedded_raster::{Join, Triangle};
    ///
    /// let stroked = Triangle::default().stroke(BinaryColor::On);
    /// assert_eq!((stroked.width, stroked.join), (1, Join::Miter));
    /// ```
    pub const fn stroke<C: PixelColor>(self, color: C) -> StrokedTriangle<C> {
        StrokedTriangle {
            triangle: self,
            color,
            width: 1,
            join: Join::Miter,
        }
    }

    /// Calls `f` with the span of lit pixels on each row inside `clip`, top
    /// to bottom, and stops at the first error `f` returns.
    ///
    /// This is the rasterizer itself: exact for every triangle in range, no
    /// allocation, no panic.
    ///
    /// `f` is called from several row loops (one per integer width and
    /// size of triangle), so a closure of more than a few instructions,
    /// such as one calling `fill_solid`, may be called out of line on
    /// every row: mark it `#[inline(always)]` (x86-64, 32 px triangles,
    /// each span sent to a framebuffer's `fill_solid`: 2,534 instructions
    /// a triangle without the mark, 2,197 with it). Drawing through
    /// [`Drawable::draw`](embedded_graphics_core::Drawable::draw) or
    /// [`draw_spans`](crate::SpanDrawable::draw_spans)
    /// needs no mark.
    ///
    /// # Examples
    ///
    /// ```
    /// use core::convert::Infallible;
    /// use embedded_graphics::{geometry::{Point, Size}, primitives::Rectangle};
    /// use embedded_raster::{Span, Triangle, Vertex};
    ///
    /// // A right triangle with legs of 4 px, corners on pixel corners. The
    /// // centres on its hypotenuse (x + y = 4) lie on a right edge: unlit.
    /// let v = |x: i32, y: i32| Vertex::try_from_num(x, y).unwrap();
    /// let t = Triangle::new(v(0, 0), v(4, 0), v(0, 4));
    /// let clip = Rectangle::new(Point::zero(), Size::new(8, 8));
    /// let mut lens = [0; 4];
    /// t.for_each_span(&clip, |s: Span| {
    ///     lens[s.y as usize] = s.len();
    ///     Ok::<(), Infallible>(())
    /// })
    /// .unwrap();
    /// assert_eq!(lens, [3, 2, 1, 0]);
    /// ```
    pub fn for_each_span<E>(
        &self,
        clip: &Rectangle,
        f: impl FnMut(Span) -> Result<(), E>,
    ) -> Result<(), E> {
        fill::triangle_spans(&self.vertices, clip, f)
    }

    /// Like [`for_each_span`](Self::for_each_span), with the vertices
    /// snapped to `precision` and the spans found by `algorithm` (see
    /// [`TriangleAlgorithm`] for the pixels each lights). With
    /// [`TriangleAlgorithm::EdgeExact`] and [`SubpixelPrecision::Bits12`]
    /// it is `for_each_span`.
    ///
    /// # Examples
    ///
    /// ```
    /// use core::convert::Infallible;
    /// use embedded_graphics::{geometry::{Point, Size}, primitives::Rectangle};
    /// use embedded_raster::{Span, SubpixelPrecision, Triangle, TriangleAlgorithm, Vertex};
    ///
    /// let v = |x: i32, y: i32| Vertex::try_from_num(x, y).unwrap();
    /// let t = Triangle::new(v(0, 0), v(4, 0), v(0, 4));
    /// let clip = Rectangle::new(Point::zero(), Size::new(8, 8));
    /// let mut lit = 0;
    /// t.for_each_span_with(TriangleAlgorithm::BresenhamWalk, SubpixelPrecision::Bits12, &clip, |s: Span| {
    ///     lit += s.len();
    ///     Ok::<(), Infallible>(())
    /// })
    /// .unwrap();
    /// // The closed triangle of pixels (0, 0), (4, 0), (0, 4): 5 + 4 + 3 + 2 + 1.
    /// assert_eq!(lit, 15);
    /// ```
    pub fn for_each_span_with<E>(
        &self,
        algorithm: TriangleAlgorithm,
        precision: SubpixelPrecision,
        clip: &Rectangle,
        f: impl FnMut(Span) -> Result<(), E>,
    ) -> Result<(), E> {
        if algorithm == TriangleAlgorithm::EdgeExact && precision == SubpixelPrecision::Bits12 {
            return fill::triangle_spans(&self.vertices, clip, f);
        }
        variants::variant_spans(algorithm, precision, &self.vertices, clip, f)
    }

    /// This triangle with its vertices snapped to `precision` (see
    /// [`SubpixelPrecision::snap`]).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::{SubpixelPrecision, Triangle, Vertex};
    ///
    /// let v = |x: f32, y: f32| Vertex::try_from_num(x, y).unwrap();
    /// let t = Triangle::new(v(0.3, 0.0), v(4.0, 0.75), v(0.0, 4.0));
    /// let s = t.snapped(SubpixelPrecision::Bits0);
    /// assert_eq!(s, Triangle::new(v(0.0, 0.0), v(4.0, 1.0), v(0.0, 4.0)));
    /// ```
    pub fn snapped(&self, precision: SubpixelPrecision) -> Self {
        Self {
            vertices: self.vertices.map(|v| precision.snap(v)),
        }
    }
}

/// A [`Triangle`] filled with one colour: a [`Drawable`](embedded_graphics_core::Drawable) for any
/// [`DrawTarget`](embedded_graphics_core::draw_target::DrawTarget), and a [`SpanDrawable`] for any [`SpanSink`] (the fast
/// way onto a [`Framebuffer`](crate::Framebuffer)). Each row's span from
/// the exact rasterizer is clipped to the target's bounding box and goes to
/// the target as one [`fill_solid`](embedded_graphics_core::draw_target::DrawTarget::fill_solid) call (or one
/// [`SpanSink::fill_span`]).
///
/// [`algorithm`](Self::algorithm) and [`precision`](Self::precision) turn it
/// into a [`FilledTriangleVariant`]: the choice is a type, so firmware that
/// never asks for a variant links none of them.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
/// use embedded_raster::{Triangle, Vertex};
/// # use embedded_graphics::{primitives::Rectangle, Pixel};
/// # struct Display;
/// # impl OriginDimensions for Display { fn size(&self) -> Size { Size::new(16, 16) } }
/// # impl DrawTarget for Display {
/// #     type Color = Gray8;
/// #     type Error = core::convert::Infallible;
/// #     fn draw_iter<I: IntoIterator<Item = Pixel<Gray8>>>(&mut self, _: I) -> Result<(), Self::Error> { Ok(()) }
/// # }
/// # let mut display = Display;
///
/// let t = Triangle::from_points(Point::new(1, 1), Point::new(14, 3), Point::new(5, 12)).unwrap();
/// t.fill(Gray8::WHITE).draw(&mut display)?;
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct FilledTriangle<C> {
    /// The shape.
    pub triangle: Triangle,
    /// The fill colour.
    pub color: C,
}

impl<C> FilledTriangle<C> {
    /// Draws with `algorithm` (at full precision) instead of the exact
    /// default.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use embedded_raster::{Triangle, TriangleAlgorithm};
    ///
    /// let t = Triangle::default().fill(BinaryColor::On).algorithm(TriangleAlgorithm::EdgeWalk);
    /// assert_eq!(t.algorithm, TriangleAlgorithm::EdgeWalk);
    /// ```
    pub fn algorithm(self, algorithm: TriangleAlgorithm) -> FilledTriangleVariant<C> {
        FilledTriangleVariant {
            triangle: self.triangle,
            color: self.color,
            algorithm,
            precision: SubpixelPrecision::Bits12,
        }
    }

    /// Snaps the vertices to `precision` before drawing (with the exact
    /// algorithm).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use embedded_raster::{SubpixelPrecision, Triangle};
    ///
    /// let t = Triangle::default().fill(BinaryColor::On).precision(SubpixelPrecision::Bits4);
    /// assert_eq!(t.precision.bits(), 4);
    /// ```
    pub fn precision(self, precision: SubpixelPrecision) -> FilledTriangleVariant<C> {
        FilledTriangleVariant {
            triangle: self.triangle,
            color: self.color,
            algorithm: TriangleAlgorithm::EdgeExact,
            precision,
        }
    }
}

impl<C: PixelColor> SpanDrawable for FilledTriangle<C> {
    type Color = C;

    fn draw_spans<S: SpanSink<C>>(&self, sink: &mut S) -> Result<(), S::Error> {
        let clip = sink.bounds();
        self.triangle.for_each_span(
            &clip,
            // Into the row loop on hosts (see `raster::walk::by_numbers`).
            #[cfg_attr(not(target_arch = "arm"), inline(always))]
            |span| sink.fill_span(span, self.color),
        )
    }
}

/// The outline of a [`Triangle`] as a stroke: a [`Drawable`](embedded_graphics_core::Drawable).
///
/// The stroke is the closed thick polyline through the three vertices
/// (subpixel positions, not pixel centres): a band `width` px wide centred
/// on each edge, the corners filled by the [`Join`], every pixel of it
/// written exactly once under the crate's sampling rule (the same code as
/// a thick [`Polyline`](crate::Polyline), see there; into a sink on which
/// overdraw is invisible, such as the framebuffer through `draw_spans`,
/// the pieces are written whole and their overlaps twice). Width 0 draws
/// nothing, widths over 65535 draw as 65535; a triangle with all three
/// vertices equal is the `width x width` square around them.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
/// use embedded_raster::{framebuffer::{buffer_size, Gray8Bytes}, Framebuffer, Join, Triangle};
///
/// let mut fb = Framebuffer::<Gray8Bytes, 32, 32, { buffer_size::<Gray8Bytes>(32, 32) }>::new();
/// let t = Triangle::from_points(Point::new(4, 4), Point::new(27, 4), Point::new(4, 27)).unwrap();
/// t.stroke(Gray8::WHITE).stroke_width(3).join(Join::Round).draw(&mut fb)?;
/// let lit = |x, y| fb.pixel(Point::new(x, y)) == Some(Gray8::WHITE);
/// assert!(lit(15, 4) && lit(4, 15) && lit(15, 16) && !lit(10, 10));
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct StrokedTriangle<C> {
    /// The shape.
    pub triangle: Triangle,
    /// The stroke colour.
    pub color: C,
    /// The stroke width in pixels.
    pub width: u32,
    /// How the edges meet at the corners.
    pub join: Join,
}

impl<C> StrokedTriangle<C> {
    /// Sets the stroke width in pixels: any `u32`, 0 draws nothing, over
    /// 65535 drawn as 65535.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use embedded_raster::Triangle;
    ///
    /// assert_eq!(Triangle::default().stroke(BinaryColor::On).stroke_width(4).width, 4);
    /// ```
    pub const fn stroke_width(mut self, width: u32) -> Self {
        self.width = width;
        self
    }

    /// Sets how the edges meet at the corners.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use embedded_raster::{Join, Triangle};
    ///
    /// let t = Triangle::default().stroke(BinaryColor::On).join(Join::Bevel);
    /// assert_eq!(t.join, Join::Bevel);
    /// ```
    pub const fn join(mut self, join: Join) -> Self {
        self.join = join;
        self
    }
}

impl<C: PixelColor> SpanDrawable for StrokedTriangle<C> {
    type Color = C;

    fn draw_spans<S: SpanSink<C>>(&self, sink: &mut S) -> Result<(), S::Error> {
        if self.width == 0 {
            return Ok(());
        }
        let outline = Outline::Vertices(&self.triangle.vertices);
        Stroke::new(outline, true, self.width, self.join).draw(self.color, sink)
    }
}

/// A filled triangle drawn with a chosen [`TriangleAlgorithm`] at a chosen
/// [`SubpixelPrecision`], made by [`FilledTriangle::algorithm`] or
/// [`FilledTriangle::precision`]. Spans go to the target as
/// [`fill_solid`](embedded_graphics_core::draw_target::DrawTarget::fill_solid) calls, as for [`FilledTriangle`].
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
/// use embedded_raster::{
///     framebuffer::{buffer_size, Gray8Bytes}, Framebuffer, SubpixelPrecision, Triangle,
///     TriangleAlgorithm,
/// };
///
/// let mut fb = Framebuffer::<Gray8Bytes, 16, 16, { buffer_size::<Gray8Bytes>(16, 16) }>::new();
/// let t = Triangle::from_points(Point::new(1, 1), Point::new(14, 3), Point::new(5, 12)).unwrap();
/// t.fill(Gray8::WHITE)
///     .algorithm(TriangleAlgorithm::EdgeWalk)
///     .precision(SubpixelPrecision::Bits8)
///     .draw(&mut fb)
///     .unwrap();
/// assert_eq!(fb.pixel(Point::new(6, 5)), Some(Gray8::WHITE));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct FilledTriangleVariant<C> {
    /// The shape.
    pub triangle: Triangle,
    /// The fill colour.
    pub color: C,
    /// The rasterization algorithm.
    pub algorithm: TriangleAlgorithm,
    /// The subpixel precision vertices are snapped to.
    pub precision: SubpixelPrecision,
}

impl<C> FilledTriangleVariant<C> {
    /// The same, drawn with `algorithm`.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use embedded_raster::{SubpixelPrecision, Triangle, TriangleAlgorithm};
    ///
    /// let t = Triangle::default()
    ///     .fill(BinaryColor::On)
    ///     .precision(SubpixelPrecision::Bits4)
    ///     .algorithm(TriangleAlgorithm::Barycentric);
    /// assert_eq!((t.algorithm, t.precision.bits()), (TriangleAlgorithm::Barycentric, 4));
    /// ```
    pub const fn algorithm(mut self, algorithm: TriangleAlgorithm) -> Self {
        self.algorithm = algorithm;
        self
    }

    /// The same, with vertices snapped to `precision`.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use embedded_raster::{SubpixelPrecision, Triangle, TriangleAlgorithm};
    ///
    /// let t = Triangle::default()
    ///     .fill(BinaryColor::On)
    ///     .algorithm(TriangleAlgorithm::EdgeWalk)
    ///     .precision(SubpixelPrecision::Bits0);
    /// assert_eq!(t.precision.bits(), 0);
    /// ```
    pub const fn precision(mut self, precision: SubpixelPrecision) -> Self {
        self.precision = precision;
        self
    }
}

drawable_through_spans!(FilledTriangle, StrokedTriangle);

impl<C: PixelColor> SpanDrawable for FilledTriangleVariant<C> {
    type Color = C;

    fn draw_spans<S: SpanSink<C>>(&self, sink: &mut S) -> Result<(), S::Error> {
        let clip = sink.bounds();
        self.triangle
            .for_each_span_with(self.algorithm, self.precision, &clip, |span| {
                sink.fill_span(span, self.color)
            })
    }
}

drawable_through_spans!(FilledTriangleVariant);
