//! Filled triangles.

mod raster;

pub use raster::StepWidth;

use embedded_graphics_core::{
    draw_target::DrawTarget, geometry::Point, pixelcolor::PixelColor, primitives::Rectangle,
    Drawable,
};

use crate::{CoordinateOutOfRange, Span, Vertex};

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
/// use embedded_graphics_core::{pixelcolor::Rgb565, prelude::*};
/// use embedded_raster::{Triangle, Vertex};
/// # use embedded_graphics_core::{primitives::Rectangle, Pixel};
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
    /// Creates a triangle from its corners.
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
    /// use embedded_graphics_core::geometry::Point;
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
    /// use embedded_graphics_core::pixelcolor::BinaryColor;
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

    /// Calls `f` with the span of lit pixels on each row inside `clip`, top
    /// to bottom, and stops at the first error `f` returns.
    ///
    /// This is the rasterizer itself: exact for every triangle in range, no
    /// allocation, no panic.
    ///
    /// # Examples
    ///
    /// ```
    /// use core::convert::Infallible;
    /// use embedded_graphics_core::{geometry::{Point, Size}, primitives::Rectangle};
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
        raster::rasterize(&self.vertices, clip, f)
    }

    /// The integer width [`for_each_span`](Self::for_each_span) steps the
    /// edge functions in for this triangle inside `clip`, or `None` if it
    /// has zero area or no candidate pixel inside `clip`. See
    /// [`StepWidth`].
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics_core::{geometry::{Point, Size}, primitives::Rectangle};
    /// use embedded_raster::{StepWidth, Triangle, Vertex};
    ///
    /// let clip = Rectangle::new(Point::new(-400_000, -400_000), Size::new(800_000, 800_000));
    /// let v = |x: i32, y: i32| Vertex::try_from_num(x, y).unwrap();
    /// let huge = Triangle::new(v(-300_000, -300_000), v(300_000, -300_000), v(0, 300_000));
    /// assert_eq!(huge.step_width(&clip), Some(StepWidth::Bits64));
    /// ```
    pub fn step_width(&self, clip: &Rectangle) -> Option<StepWidth> {
        raster::step_width(&self.vertices, clip)
    }
}

/// A [`Triangle`] filled with one colour: a [`Drawable`] for any
/// [`DrawTarget`]. Each row's span goes to the target as one
/// [`fill_solid`](DrawTarget::fill_solid) call, clipped to the target's
/// bounding box first.
///
/// # Examples
///
/// ```
/// use embedded_graphics_core::{pixelcolor::Gray8, prelude::*};
/// use embedded_raster::{Triangle, Vertex};
/// # use embedded_graphics_core::{primitives::Rectangle, Pixel};
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

impl<C: PixelColor> Drawable for FilledTriangle<C> {
    type Color = C;
    type Output = ();

    fn draw<D>(&self, target: &mut D) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = C>,
    {
        let clip = target.bounding_box();
        self.triangle
            .for_each_span(&clip, |span| target.fill_solid(&span.rect(), self.color))
    }
}
