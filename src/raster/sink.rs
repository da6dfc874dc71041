//! Span sinks: where rasterized shapes write their pixels.
//!
//! Shapes never touch pixels themselves. They compute which pixels they
//! light as spans (and, for lines, columns) already clipped to the sink's
//! [`bounds`](SpanSink::bounds), and hand them to a [`SpanSink`], which
//! writes them: the crate's [`Framebuffer`](crate::Framebuffer) straight
//! into its rows of bytes, any other `DrawTarget` through
//! [`DrawTargetSink`] and `fill_solid`.

use embedded_graphics_core::{
    draw_target::DrawTarget,
    geometry::{Dimensions, Point, Size},
    primitives::Rectangle,
    Pixel,
};

use crate::{
    clip::Bounds,
    line::{fill_run, LinePixels},
    span::Span,
};

/// Receives the pixels a shape lights, already clipped: the one place
/// where rasterized shapes meet memory or a display.
///
/// Every span, column and rectangle passed to a sink lies inside its
/// [`bounds`](Self::bounds) and is not empty; implementations may rely on
/// it for speed, but must still never write outside their storage or
/// panic if a caller breaks it.
///
/// Ranges: coordinates are any `i32` and lengths any `u32`; the provided
/// methods clip columns and rectangles to the bounds and never overflow.
/// A span's end is exclusive and an `i32`, so no span holds column
/// `i32::MAX`: the provided [`fill_column`](Self::fill_column),
/// [`fill_rect`](Self::fill_rect) and [`fill_line`](Self::fill_line)
/// leave it out, and a sink whose bounds reach it gets nothing there
/// unless it implements them itself (a `DrawTarget` drawn through `draw`
/// gets those pixels).
/// The crate's implementations, given pixels outside their bounds, write
/// none of them and change no other pixel: a
/// [`Framebuffer`](crate::Framebuffer) drops a span that is not wholly
/// inside one row, clips columns and rectangles, and draws a line whose
/// pixels it cannot show to lie inside (listed in a larger clip) pixel by
/// pixel, clipped, at the cost of every pixel; a
/// [`Band`](crate::band::Band)
/// keeps to its rows; a [`DrawTargetSink`] passes them on to the
/// `DrawTarget`, which clips.
///
/// # Examples
///
/// Count the pixels of a triangle, without drawing it anywhere:
///
/// ```
/// use core::convert::Infallible;
/// use embedded_graphics::{geometry::{Point, Size}, pixelcolor::BinaryColor, primitives::Rectangle};
/// use embedded_raster::{Span, SpanDrawable, SpanSink, Triangle};
///
/// struct Counter(u32);
///
/// impl SpanSink<BinaryColor> for Counter {
///     type Error = Infallible;
///     fn bounds(&self) -> Rectangle {
///         Rectangle::new(Point::zero(), Size::new(64, 64))
///     }
///     fn fill_span(&mut self, span: Span, _: BinaryColor) -> Result<(), Infallible> {
///         self.0 += span.len();
///         Ok(())
///     }
/// }
///
/// let t = Triangle::from_points(Point::new(0, 0), Point::new(9, 0), Point::new(0, 9)).unwrap();
/// let mut counter = Counter(0);
/// t.fill(BinaryColor::On).draw_spans(&mut counter)?;
/// assert_eq!(counter.0, 45);
/// # Ok::<(), Infallible>(())
/// ```
pub trait SpanSink<C> {
    /// What writing can fail with.
    type Error;

    /// The rectangle all spans, columns and rectangles given to this sink
    /// lie in.
    fn bounds(&self) -> Rectangle;

    /// Whether writing a pixel again with the colour it was just given
    /// changes nothing, and costs less than avoiding it: `true` for pixels
    /// in memory, such as the crate's [`Framebuffer`](crate::Framebuffer).
    ///
    /// Shapes made of overlapping pieces (thick polylines and outlines,
    /// whose segments and joins overlap on the inside of every turn) then
    /// write each piece whole, and the overlaps twice, instead of keeping a
    /// mask of the pixels already written: the same pixels in the same
    /// colour, in less time and with 1 KiB less stack. The provided
    /// implementation returns `false`, so that every pixel is written once:
    /// a `DrawTarget` may blend, count writes, or send each one to a
    /// display over a bus.
    ///
    /// # Examples
    ///
    /// A sink that counts the writes to each pixel, and so keeps the
    /// default: a thick polyline turning back on itself still writes each
    /// pixel once.
    ///
    /// ```
    /// use core::convert::Infallible;
    /// use embedded_graphics::{pixelcolor::BinaryColor, prelude::*, primitives::Rectangle};
    /// use embedded_raster::{framebuffer::{buffer_size, BinaryMsb}, Framebuffer, Polyline, Span, SpanDrawable, SpanSink};
    ///
    /// struct Writes([[u8; 32]; 32]);
    ///
    /// impl SpanSink<BinaryColor> for Writes {
    ///     type Error = Infallible;
    ///     fn bounds(&self) -> Rectangle {
    ///         Rectangle::new(Point::zero(), Size::new(32, 32))
    ///     }
    ///     fn fill_span(&mut self, span: Span, _: BinaryColor) -> Result<(), Infallible> {
    ///         for x in span.x_start..span.x_end {
    ///             self.0[span.y as usize][x as usize] += 1;
    ///         }
    ///         Ok(())
    ///     }
    /// }
    ///
    /// let points = [Point::new(4, 4), Point::new(28, 16), Point::new(4, 28)];
    /// let stroke = Polyline::new(&points).stroke(BinaryColor::On).stroke_width(6);
    /// let mut writes = Writes([[0; 32]; 32]);
    /// stroke.draw_spans(&mut writes)?;
    /// assert!(writes.0.iter().flatten().all(|&n| n <= 1));
    ///
    /// // A framebuffer takes the overlaps twice, with the same pixels lit.
    /// let mut fb = Framebuffer::<BinaryMsb, 32, 32, { buffer_size::<BinaryMsb>(32, 32) }>::new();
    /// assert!(fb.overdraw_is_invisible());
    /// stroke.draw_spans(&mut fb)?;
    /// for (y, row) in writes.0.iter().enumerate() {
    ///     for (x, &n) in row.iter().enumerate() {
    ///         let on = fb.pixel(Point::new(x as i32, y as i32)) == Some(BinaryColor::On);
    ///         assert_eq!(on, n == 1);
    ///     }
    /// }
    /// # Ok::<(), Infallible>(())
    /// ```
    fn overdraw_is_invisible(&self) -> bool {
        false
    }

    /// Sets the pixels of `span` to `color`.
    fn fill_span(&mut self, span: Span, color: C) -> Result<(), Self::Error>;

    /// Sets `len` pixels from `top` downwards to `color` (a run of a steep
    /// line). The provided implementation calls
    /// [`fill_span`](Self::fill_span) per pixel inside
    /// [`bounds`](Self::bounds).
    fn fill_column(&mut self, top: Point, len: u32, color: C) -> Result<(), Self::Error>
    where
        C: Copy,
    {
        fill_rows(self, &Rectangle::new(top, Size::new(1, len)), color)
    }

    /// Sets the pixels of a 1-pixel line to `color`. The provided
    /// implementation writes them as runs:
    /// [`fill_span`](Self::fill_span) for an x-major line,
    /// [`fill_column`](Self::fill_column) for a y-major one.
    fn fill_line(&mut self, pixels: LinePixels, color: C) -> Result<(), Self::Error>
    where
        C: Copy,
    {
        pixels.for_each_run(|run| fill_run(self, run, color))
    }

    /// Sets every pixel of `area` to `color`. The provided implementation
    /// calls [`fill_span`](Self::fill_span) per row inside
    /// [`bounds`](Self::bounds).
    fn fill_rect(&mut self, area: &Rectangle, color: C) -> Result<(), Self::Error>
    where
        C: Copy,
    {
        fill_rows(self, area, color)
    }
}

/// The provided [`SpanSink::fill_column`] and [`SpanSink::fill_rect`]: a
/// span per row of the part of `area` inside the sink's bounds, so that
/// an area a caller failed to clip costs only its visible rows (a column
/// `u32::MAX` pixels long was that many calls). A span cannot end past
/// `i32::MAX`, so the last column of the `i32` range is left out, as a
/// span would leave it.
fn fill_rows<C: Copy, S: SpanSink<C> + ?Sized>(
    sink: &mut S,
    area: &Rectangle,
    color: C,
) -> Result<(), S::Error> {
    let Some(b) = Bounds::of(area).intersect(Bounds::of(&sink.bounds())) else {
        return Ok(());
    };
    // Inside `bounds`: x0 and y0 fit `i32`; x1, a span's exclusive end,
    // is clamped to i32::MAX; and no row lies past i32::MAX.
    let narrow = |v: i64| i32::try_from(v).unwrap_or(i32::MAX);
    let (x_start, x_end) = (narrow(b.x0), narrow(b.x1));
    if x_start == x_end {
        // Only column i32::MAX: no span holds it.
        return Ok(());
    }
    for y in b.y0..b.y1 {
        let Ok(y) = i32::try_from(y) else {
            break;
        };
        sink.fill_span(Span { y, x_start, x_end }, color)?;
    }
    Ok(())
}

/// A shape that rasterizes into any [`SpanSink`]: each of the crate's
/// filled and stroked drawables. Its [`Drawable`] implementation is
/// `draw_spans` on a [`DrawTargetSink`].
///
/// [`Drawable`]: embedded_graphics_core::Drawable
///
/// # Examples
///
/// The direct way onto a [`Framebuffer`](crate::Framebuffer): spans go
/// straight into its rows.
///
/// ```
/// use embedded_graphics::{pixelcolor::{Rgb565, RgbColor}, prelude::*};
/// use embedded_raster::{framebuffer::{buffer_size, Rgb565Le}, Framebuffer, SpanDrawable, Triangle};
///
/// let mut fb = Framebuffer::<Rgb565Le, 16, 16, { buffer_size::<Rgb565Le>(16, 16) }>::new();
/// let t = Triangle::from_points(Point::new(1, 1), Point::new(14, 3), Point::new(5, 12)).unwrap();
/// t.fill(Rgb565::RED).draw_spans(&mut fb)?;
/// assert_eq!(fb.pixel(Point::new(6, 5)), Some(Rgb565::RED));
/// # Ok::<(), core::convert::Infallible>(())
/// ```
pub trait SpanDrawable {
    /// The colour it draws in.
    type Color;

    /// Writes the shape's pixels into `sink`, clipped to its bounds, and
    /// stops at the first error.
    fn draw_spans<S: SpanSink<Self::Color>>(&self, sink: &mut S) -> Result<(), S::Error>;
}

/// Any [`DrawTarget`] as a [`SpanSink`]: each span, column and rectangle
/// becomes one [`fill_solid`](DrawTarget::fill_solid) call.
///
/// # Examples
///
/// ```
/// use embedded_graphics::mock_display::MockDisplay;
/// use embedded_graphics::{pixelcolor::BinaryColor, prelude::*};
/// use embedded_raster::{DrawTargetSink, SpanSink, Span};
///
/// let mut display = MockDisplay::<BinaryColor>::new();
/// let mut sink = DrawTargetSink::new(&mut display);
/// sink.fill_span(Span { y: 1, x_start: 0, x_end: 3 }, BinaryColor::On)?;
/// display.assert_pattern(&[
///     "   ",
///     "###",
/// ]);
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Debug)]
pub struct DrawTargetSink<'a, D> {
    target: &'a mut D,
    bounds: Rectangle,
}

impl<'a, D: DrawTarget> DrawTargetSink<'a, D> {
    /// Wraps `target`; its bounding box is read once, here.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::mock_display::MockDisplay;
    /// use embedded_graphics::{pixelcolor::BinaryColor, prelude::*};
    /// use embedded_raster::{DrawTargetSink, SpanSink};
    ///
    /// let mut display = MockDisplay::<BinaryColor>::new();
    /// let sink = DrawTargetSink::new(&mut display);
    /// assert_eq!(sink.bounds().size, Size::new(64, 64));
    /// ```
    pub fn new(target: &'a mut D) -> Self {
        let bounds = target.bounding_box();
        Self { target, bounds }
    }
}

impl<D: DrawTarget> SpanSink<D::Color> for DrawTargetSink<'_, D> {
    type Error = D::Error;

    fn bounds(&self) -> Rectangle {
        self.bounds
    }

    // Inlined on hosts into the triangle walks' row loop (see
    // `raster::walk::by_numbers`).
    #[cfg_attr(not(target_arch = "arm"), inline(always))]
    #[cfg_attr(target_arch = "arm", inline)]
    fn fill_span(&mut self, span: Span, color: D::Color) -> Result<(), D::Error> {
        self.target.fill_solid(&span.rect(), color)
    }

    #[inline]
    fn fill_column(&mut self, top: Point, len: u32, color: D::Color) -> Result<(), D::Error> {
        self.target
            .fill_solid(&Rectangle::new(top, Size::new(1, len)), color)
    }

    #[inline]
    fn fill_rect(&mut self, area: &Rectangle, color: D::Color) -> Result<(), D::Error> {
        self.target.fill_solid(area, color)
    }
}

impl<D: DrawTarget> Dimensions for DrawTargetSink<'_, D> {
    fn bounding_box(&self) -> Rectangle {
        self.bounds
    }
}

/// The wrapped target itself, for drawing that needs a `DrawTarget`
/// (shading) beside spans.
impl<D: DrawTarget> DrawTarget for DrawTargetSink<'_, D> {
    type Color = D::Color;
    type Error = D::Error;

    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), D::Error>
    where
        I: IntoIterator<Item = Pixel<D::Color>>,
    {
        self.target.draw_iter(pixels)
    }

    fn fill_contiguous<I>(&mut self, area: &Rectangle, colors: I) -> Result<(), D::Error>
    where
        I: IntoIterator<Item = D::Color>,
    {
        self.target.fill_contiguous(area, colors)
    }

    fn fill_solid(&mut self, area: &Rectangle, color: D::Color) -> Result<(), D::Error> {
        self.target.fill_solid(area, color)
    }

    fn clear(&mut self, color: D::Color) -> Result<(), D::Error> {
        self.target.clear(color)
    }
}

/// Implements [`Drawable`](embedded_graphics_core::Drawable) for a
/// [`SpanDrawable`] with a `color` field's type parameter `C` (after a
/// lifetime and before a `const` capacity, where it has them: `Type<'_,
/// const N>`): drawing on a `DrawTarget` is drawing spans on a
/// [`DrawTargetSink`] of it.
macro_rules! drawable_through_spans {
    ($($ty:ident $(<$lt:lifetime $(, const $n:ident)?>)?),* $(,)?) => {$(
        impl<C: embedded_graphics_core::pixelcolor::PixelColor $($(, const $n: usize)?)?>
            embedded_graphics_core::Drawable for $ty<$($lt,)? C $($(, $n)?)?>
        {
            type Color = C;
            type Output = ();

            fn draw<D>(&self, target: &mut D) -> Result<(), D::Error>
            where
                D: embedded_graphics_core::draw_target::DrawTarget<Color = C>,
            {
                $crate::raster::sink::SpanDrawable::draw_spans(
                    self,
                    &mut $crate::raster::sink::DrawTargetSink::new(target),
                )
            }
        }
    )*};
}

pub(crate) use drawable_through_spans;
