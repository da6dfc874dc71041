//! Drawing without a full framebuffer: a screen rendered as horizontal
//! bands of a few rows, each drawn into one small buffer and sent to the
//! display before the next.
//!
//! - [`Band`] makes a buffer of `W x R` pixels stand for rows
//!   `top..top + R` of the screen: every shape drawn on it is clipped to
//!   those rows and lands in the buffer's rows `0..R`. It is a
//!   [`DrawTarget`] and a [`SpanSink`] when its buffer is.
//! - [`DisplayList`] records the drawing commands of a frame in fixed
//!   storage and draws them band after band ([`DisplayList::render_bands`]),
//!   each command only in the bands its rows touch.
//! - [`DirtyRows`] records which pixels of a full framebuffer changed since
//!   the last flush, so only those go to the display.
//!
//! Every shape of the crate is exact under any clip rectangle, so a frame
//! drawn in bands of any height is byte for byte the frame drawn whole,
//! and each pixel is written as many times.

mod dirty;
mod list;

pub use dirty::DirtyRows;
pub use list::{Command, DisplayList, DisplayListFull};

use core::{fmt, ops::Range};

use embedded_graphics_core::{
    draw_target::DrawTarget,
    geometry::{Dimensions, OriginDimensions, Point, Size},
    image::GetPixel,
    primitives::Rectangle,
    Pixel,
};

use crate::{
    clip::{advance, Bounds},
    line::LinePixels,
    raster::sink::SpanSink,
    shade::DepthBuffer,
    span::Span,
};

/// A target of `W x R` pixels standing for rows `top..top + R` of a wider
/// screen: shapes drawn on it in screen coordinates are clipped to those
/// rows and written `top` rows higher, into the target's rows `0..R`.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
/// use embedded_raster::{band::Band, framebuffer::{buffer_size, Gray8Bytes}, Framebuffer, Triangle};
///
/// // Rows 8..12 of a 16 x 16 screen.
/// let mut rows = Framebuffer::<Gray8Bytes, 16, 4, { buffer_size::<Gray8Bytes>(16, 4) }>::new();
/// let mut band = Band::new(&mut rows, 8);
/// assert_eq!(band.bounding_box().top_left, Point::new(0, 8));
///
/// let t = Triangle::from_points(Point::new(0, 0), Point::new(15, 0), Point::new(0, 15))?;
/// t.fill(Gray8::WHITE).draw(&mut band)?;
/// // Screen pixel (6, 8) is the band's (6, 0); (7, 8) is past the edge.
/// assert_eq!(rows.pixel(Point::new(6, 0)), Some(Gray8::WHITE));
/// assert_eq!(rows.pixel(Point::new(7, 0)), Some(Gray8::BLACK));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug)]
pub struct Band<'a, T> {
    target: &'a mut T,
    top: i32,
    /// At most the target's height, and the rows from `top` to `i32::MAX`.
    height: u32,
}

impl<'a, T: OriginDimensions> Band<'a, T> {
    /// Makes `target` stand for the screen's rows from `top` down, as many
    /// as it has.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
    /// use embedded_raster::{band::Band, framebuffer::{buffer_size, Gray8Bytes}, Framebuffer};
    ///
    /// let mut rows = Framebuffer::<Gray8Bytes, 32, 8, { buffer_size::<Gray8Bytes>(32, 8) }>::new();
    /// let band = Band::new(&mut rows, 16);
    /// assert_eq!(band.rows(), 16..24);
    /// ```
    pub fn new(target: &'a mut T, top: i32) -> Self {
        // No more rows than the screen has from `top` to `i32::MAX` (see
        // `rows`): the target's rows below stand for none.
        let height = target.size().height.min(i32::MAX.abs_diff(top));
        Self {
            target,
            top,
            height,
        }
    }

    /// The same band, covering at most `rows` rows (the last band of a
    /// screen whose height the buffer's does not divide): shapes are
    /// clipped to them, and the target's rows below stay untouched.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::{band::Band, framebuffer::{buffer_size, Gray8Bytes}, Framebuffer};
    ///
    /// let mut rows = Framebuffer::<Gray8Bytes, 4, 16, { buffer_size::<Gray8Bytes>(4, 16) }>::new();
    /// assert_eq!(Band::new(&mut rows, 32).limited_to(8).rows(), 32..40);
    /// ```
    pub fn limited_to(self, rows: u32) -> Self {
        Self {
            height: self.height.min(rows),
            ..self
        }
    }

    /// The screen rows this band covers (ends at `i32::MAX` at most).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::{band::Band, framebuffer::{buffer_size, Gray8Bytes}, Framebuffer};
    ///
    /// let mut rows = Framebuffer::<Gray8Bytes, 4, 2, { buffer_size::<Gray8Bytes>(4, 2) }>::new();
    /// assert_eq!(Band::new(&mut rows, -1).rows(), -1..1);
    /// ```
    pub fn rows(&self) -> Range<i32> {
        self.top..self.top.saturating_add_unsigned(self.height)
    }

    /// The screen area this band covers.
    fn area(&self) -> Rectangle {
        let rows = self.rows();
        let height = rows.end.abs_diff(rows.start);
        let width = self.target.size().width;
        Rectangle::new(Point::new(0, self.top), Size::new(width, height))
    }

    /// `area`'s rows inside the band, moved to the target's coordinates,
    /// and how many of `area`'s pixels (row-major) come before them.
    fn to_target(&self, area: &Rectangle) -> Option<(Rectangle, u64)> {
        let band = Bounds::of(&self.area());
        let a = Bounds::of(area);
        // Rows only: columns are the target's to clip.
        let (y0, y1) = (a.y0.max(band.y0), a.y1.min(band.y1));
        if y0 >= y1 || a.x0 >= a.x1 {
            return None;
        }
        // `y0 - top` is in `0..height`, so it fits `i32`, and the skipped
        // rows times the width fit `u64` (both below 2^32).
        let top = i32::try_from(y0 - band.y0).ok()?;
        let height = u32::try_from(y1 - y0).ok()?;
        let skipped = u64::try_from(y0 - a.y0).ok()? * u64::from(area.size.width);
        let moved = Rectangle::new(
            Point::new(area.top_left.x, top),
            Size::new(area.size.width, height),
        );
        Some((moved, skipped))
    }
}

impl<T> Band<'_, T> {
    /// Writes spans of `color` into the target, each moved up by `top`
    /// and dropped unless it is in the band's rows: `fill_span` with the
    /// band's fields copied into the closure, so that a span loop keeps
    /// them in registers across the target's stores.
    pub(crate) fn span_writer<'s, C: Copy + 's>(
        &'s mut self,
        color: C,
    ) -> impl FnMut(Span) -> Result<(), <T as SpanSink<C>>::Error> + 's
    where
        T: SpanSink<C>,
    {
        let (top, height, target) = (self.top, self.height, &mut *self.target);
        move |span: Span| match span.y.checked_sub(top) {
            // In the band's rows, `span.y - top` is in `0..height`.
            Some(y) if y >= 0 && y.unsigned_abs() < height => {
                target.fill_span(Span { y, ..span }, color)
            }
            _ => Ok(()),
        }
    }

    /// Like [`span_writer`](Self::span_writer), for spans known to lie in
    /// the band's rows (a walk stopped at the band's end, started at or
    /// below its top): moved up by `top` only, without the row test. The
    /// target still clips to its own rows, which for a limited band
    /// include rows below it: callers must keep to the band.
    #[inline]
    pub(crate) fn row_span_writer<'s, C: Copy + 's>(
        &'s mut self,
        color: C,
    ) -> impl FnMut(Span) -> Result<(), <T as SpanSink<C>>::Error> + 's
    where
        T: SpanSink<C>,
    {
        let (top, target) = (self.top, &mut *self.target);
        move |span: Span| match span.y.checked_sub(top) {
            Some(y) => target.fill_span(Span { y, ..span }, color),
            None => Ok(()),
        }
    }
}

impl<T: OriginDimensions> Dimensions for Band<'_, T> {
    fn bounding_box(&self) -> Rectangle {
        self.area()
    }
}

impl<T: DrawTarget + OriginDimensions> DrawTarget for Band<'_, T> {
    type Color = T::Color;
    type Error = T::Error;

    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = Pixel<Self::Color>>,
    {
        let rows = self.rows();
        let top = self.top;
        self.target.draw_iter(
            pixels
                .into_iter()
                .filter(move |Pixel(p, _)| rows.contains(&p.y))
                // In the band's rows, so `p.y - top` is in `0..height`.
                .map(move |Pixel(p, c)| Pixel(Point::new(p.x, p.y - top), c)),
        )
    }

    fn fill_contiguous<I>(&mut self, area: &Rectangle, colors: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = Self::Color>,
    {
        let Some((moved, skipped)) = self.to_target(area) else {
            return Ok(());
        };
        let mut colors = colors.into_iter();
        if !advance(&mut colors, skipped) {
            return Ok(());
        }
        self.target.fill_contiguous(&moved, colors)
    }

    fn fill_solid(&mut self, area: &Rectangle, color: Self::Color) -> Result<(), Self::Error> {
        match self.to_target(area) {
            Some((moved, _)) => self.target.fill_solid(&moved, color),
            None => Ok(()),
        }
    }

    /// Fills the whole band: its part of the screen (and no buffer row
    /// below a limited band).
    fn clear(&mut self, color: Self::Color) -> Result<(), Self::Error> {
        let width = self.target.size().width;
        let rows = Rectangle::new(Point::zero(), Size::new(width, self.height));
        self.target.fill_solid(&rows, color)
    }
}

impl<C: Copy, T: SpanSink<C> + OriginDimensions> SpanSink<C> for Band<'_, T> {
    type Error = T::Error;

    /// The band's area: the target must take spans anywhere in its size
    /// (as every sink whose bounds are its size does).
    fn bounds(&self) -> Rectangle {
        self.area()
    }

    /// The target's.
    #[inline(always)]
    fn overdraw_is_invisible(&self) -> bool {
        self.target.overdraw_is_invisible()
    }

    fn fill_span(&mut self, span: Span, color: C) -> Result<(), Self::Error> {
        self.span_writer(color)(span)
    }

    fn fill_column(&mut self, top: Point, len: u32, color: C) -> Result<(), Self::Error> {
        let column = Rectangle::new(top, Size::new(1, len));
        match self.to_target(&column) {
            Some((moved, _)) => self
                .target
                .fill_column(moved.top_left, moved.size.height, color),
            None => Ok(()),
        }
    }

    fn fill_rect(&mut self, area: &Rectangle, color: C) -> Result<(), Self::Error> {
        match self.to_target(area) {
            Some((moved, _)) => self.target.fill_rect(&moved, color),
            None => Ok(()),
        }
    }

    /// A line known to lie in the band's area (as the shapes clip it)
    /// goes to the target whole, moved up by `top`; any other, run by run
    /// through [`fill_rect`](Self::fill_rect), which keeps to the band's
    /// rows and leaves the columns to the target's clipping.
    fn fill_line(&mut self, pixels: LinePixels, color: C) -> Result<(), Self::Error> {
        // The band's columns and rows, inclusive (its rows end before
        // i32::MAX, see `new`). Inside them, moving the line up by `top`
        // keeps it in `i32`.
        let columns = (
            0,
            i32::try_from(self.target.size().width).unwrap_or(i32::MAX) - 1,
        );
        let rows = self.rows();
        // A band of no rows at i32::MIN: an empty range.
        let rows = rows
            .end
            .checked_sub(1)
            .map_or((0, -1), |last| (rows.start, last));
        let moved = match pixels.known_inside(columns, rows) {
            true => self.top.checked_neg().and_then(|up| pixels.moved_down(up)),
            false => None,
        };
        match moved {
            Some(moved) => self.target.fill_line(moved, color),
            None => pixels.for_each_run(|run| self.fill_rect(&run.rect(), color)),
        }
    }
}

/// Where finished bands go: a display's window write, a DMA transfer, a
/// copy. Any `FnMut(&T, Rectangle) -> Result<(), E>` closure is one.
///
/// # Examples
///
/// ```
/// use embedded_graphics::primitives::Rectangle;
/// use embedded_raster::band::BandOutput;
///
/// /// Counts the rows it is sent.
/// struct Rows(u32);
/// impl<T> BandOutput<T> for Rows {
///     type Error = core::convert::Infallible;
///     fn send(&mut self, _band: &T, area: Rectangle) -> Result<(), Self::Error> {
///         self.0 += area.size.height;
///         Ok(())
///     }
/// }
/// ```
pub trait BandOutput<T> {
    /// What sending can fail with.
    type Error;

    /// Takes the finished `band`, whose first `area.size.height` rows are
    /// the screen's `area`. It may start a transfer from `band` and return
    /// before it ends: the renderer draws into that buffer again only
    /// after [`wait`](Self::wait) for it.
    ///
    /// # Examples
    ///
    /// A closure is an output: here it records the screen rows of each
    /// band of a 10-row screen drawn in bands of 4 rows.
    ///
    /// ```
    /// use core::convert::Infallible;
    /// use embedded_graphics::{pixelcolor::BinaryColor, prelude::*, primitives::Rectangle};
    /// use embedded_raster::{band::{render_in_bands, BandOutput}, framebuffer::{buffer_size, BinaryMsb}, Framebuffer};
    ///
    /// type Rows = Framebuffer<BinaryMsb, 8, 4, { buffer_size::<BinaryMsb>(8, 4) }>;
    /// let (mut sent, mut count) = ([(0, 0); 4], 0);
    /// let mut output = |_: &Rows, area: Rectangle| {
    ///     sent[count] = (area.top_left.y, area.size.height);
    ///     count += 1;
    ///     Ok::<(), Infallible>(())
    /// };
    /// output.send(&Rows::new(), Rectangle::new(Point::zero(), Size::new(8, 1)))?;
    /// render_in_bands(10, &mut [Rows::new()], None, |band, _| band.clear(BinaryColor::On), &mut output)?;
    /// assert_eq!(sent, [(0, 1), (0, 4), (4, 4), (8, 2)]);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    fn send(&mut self, band: &T, area: Rectangle) -> Result<(), Self::Error>;

    /// Returns once nothing is being read from `band` any more. The
    /// provided implementation returns at once (for a `send` that is done
    /// when it returns).
    ///
    /// # Examples
    ///
    /// An output that counts the transfers still running: `send` starts
    /// one, `wait` ends it. With two buffers, the renderer waits for each
    /// before drawing into it again, and for both at the end.
    ///
    /// ```
    /// use core::convert::Infallible;
    /// use embedded_graphics::{pixelcolor::BinaryColor, prelude::*, primitives::Rectangle};
    /// use embedded_raster::{band::{render_in_bands, BandOutput}, framebuffer::{buffer_size, BinaryMsb}, Framebuffer};
    ///
    /// type Rows = Framebuffer<BinaryMsb, 8, 2, { buffer_size::<BinaryMsb>(8, 2) }>;
    /// #[derive(Default)]
    /// struct Transfers { running: u32, most: u32, waits: u32 }
    /// impl BandOutput<Rows> for Transfers {
    ///     type Error = Infallible;
    ///     fn send(&mut self, _: &Rows, _: Rectangle) -> Result<(), Infallible> {
    ///         self.running += 1;
    ///         self.most = self.most.max(self.running);
    ///         Ok(())
    ///     }
    ///     fn wait(&mut self, _: &Rows) -> Result<(), Infallible> {
    ///         self.running = self.running.saturating_sub(1);
    ///         self.waits += 1;
    ///         Ok(())
    ///     }
    /// }
    ///
    /// let mut output = Transfers::default();
    /// let mut buffers = [Rows::new(), Rows::new()];
    /// render_in_bands(8, &mut buffers, None, |band, _| band.clear(BinaryColor::On), &mut output)?;
    /// // Four bands: two waits before buffers are reused, two at the end.
    /// assert_eq!((output.running, output.most, output.waits), (0, 2, 4));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    fn wait(&mut self, band: &T) -> Result<(), Self::Error> {
        let _ = band;
        Ok(())
    }
}

impl<T, E, F: FnMut(&T, Rectangle) -> Result<(), E>> BandOutput<T> for F {
    type Error = E;

    fn send(&mut self, band: &T, area: Rectangle) -> Result<(), E> {
        self(band, area)
    }
}

/// A [`BandOutput`] that writes each band to a [`DrawTarget`] (a display
/// driver) with one `fill_contiguous` over the band's screen area: the
/// window write that drivers such as `mipidsi` turn into one transfer.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, prelude::*};
/// use embedded_raster::{band::{Command, DisplayList, WriteTo}, framebuffer::{buffer_size, BinaryMsb}, Framebuffer, Line};
///
/// let mut list = DisplayList::<BinaryColor, 2>::new();
/// list.push(Command::Clear(BinaryColor::Off))?;
/// list.push(Command::Line(Line::new(Point::new(0, 0), Point::new(3, 3)).stroke(BinaryColor::On)))?;
/// let mut display = MockDisplay::new();
/// let mut bands = [Framebuffer::<BinaryMsb, 4, 2, { buffer_size::<BinaryMsb>(4, 2) }>::new()];
/// list.render_bands(4, &mut bands, None, &mut WriteTo(&mut display))?;
/// display.assert_pattern(&["#...", ".#..", "..#.", "...#"]);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug)]
pub struct WriteTo<'a, D>(pub &'a mut D);

impl<T, D> BandOutput<T> for WriteTo<'_, D>
where
    T: GetPixel<Color = D::Color>,
    D: DrawTarget,
{
    type Error = D::Error;

    fn send(&mut self, band: &T, area: Rectangle) -> Result<(), D::Error> {
        let (width, height) = (area.size.width, area.size.height);
        // Band rows and columns: small enough for `i32`.
        let colors = (0..height).flat_map(move |y| {
            (0..width).filter_map(move |x| band.pixel(Point::new(x as i32, y as i32)))
        });
        self.0.fill_contiguous(&area, colors)
    }
}

/// Renders a screen of `height` rows band by band: for each band, in
/// order from the top, the next of `buffers` (used in turn; each as wide
/// as the screen, its rows making the band) stands for the band's rows,
/// `draw` draws the frame on it, and `output` is sent the finished band.
///
/// - The last band covers only the rows left; buffer rows below the screen
///   are not drawn.
/// - Buffers are not cleared between bands: the frame's drawing should
///   cover every pixel (start with a clear).
/// - With `depth` (storage for one buffer's pixels, row-major), `draw`
///   gets a depth buffer for the band's rows, cleared to
///   [`FAR`](crate::shade::FAR) before each band.
/// - Before a buffer is drawn into again, `output.wait` is called for it;
///   at the end, for every buffer sent.
///
/// # Errors
///
/// The first error of `draw` ([`RenderError::Draw`]) or of `output`
/// ([`RenderError::Flush`]); no band is sent after it. With `height`
/// above 0, [`RenderError::NoRows`] before anything is drawn if
/// `buffers` is empty or a buffer has no rows.
///
/// # Examples
///
/// Text of embedded-graphics in bands of 4 rows:
///
/// ```
/// use embedded_graphics::{mono_font::{ascii::FONT_6X10, MonoTextStyle}, pixelcolor::BinaryColor, prelude::*, text::Text};
/// use embedded_raster::{band::render_in_bands, framebuffer::{buffer_size, BinaryMsb}, Framebuffer};
///
/// type Rows = Framebuffer<BinaryMsb, 64, 4, { buffer_size::<BinaryMsb>(64, 4) }>;
/// let mut buffers = [Rows::new()];
/// let mut lit = 0;
/// render_in_bands(16, &mut buffers, None, |band, _depth| {
///     band.clear(BinaryColor::Off)?;
///     Text::new("band", Point::new(2, 10), MonoTextStyle::new(&FONT_6X10, BinaryColor::On)).draw(band)?;
///     Ok::<(), core::convert::Infallible>(())
/// }, &mut |rows: &Rows, area: embedded_graphics::primitives::Rectangle| {
///     lit += rows.as_bytes()[..area.size.height as usize * 8].iter().map(|b| b.count_ones()).sum::<u32>();
///     Ok::<(), core::convert::Infallible>(())
/// })?;
/// assert!(lit > 20);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn render_in_bands<T, D, O>(
    height: u32,
    buffers: &mut [T],
    mut depth: Option<&mut [u16]>,
    mut draw: impl FnMut(&mut Band<'_, T>, Option<DepthBuffer<'_>>) -> Result<(), D>,
    output: &mut O,
) -> Result<(), RenderError<D, O::Error>>
where
    T: OriginDimensions,
    O: BandOutput<T>,
{
    let count = buffers.len();
    let mut sent = 0usize; // buffers sent at least once: a prefix
    let screen = i32::try_from(height).unwrap_or(i32::MAX);
    if screen > 0 && (count == 0 || buffers.iter().any(|b| b.size().height == 0)) {
        return Err(RenderError::NoRows);
    }
    let mut top = 0i32;
    let mut next = 0usize;
    while top < screen {
        let Some(buffer) = buffers.get_mut(next) else {
            return Err(RenderError::NoRows); // checked above
        };
        let Size {
            width,
            height: rows,
        } = buffer.size();
        if rows == 0 {
            // Checked above, unless `size` changed since.
            return Err(RenderError::NoRows);
        }
        if next < sent {
            output.wait(buffer).map_err(RenderError::Flush)?;
        }
        let left = screen.abs_diff(top); // `top < screen`
        let mut band = Band::new(buffer, top).limited_to(left);
        let band_rows = band.rows();
        let depth_band = depth.as_deref_mut().map(|storage| {
            let d = DepthBuffer::for_rows(storage, width, top);
            d.clear();
            d
        });
        draw(&mut band, depth_band).map_err(RenderError::Draw)?;
        let area = Rectangle::new(
            Point::new(0, top),
            Size::new(width, band_rows.end.abs_diff(band_rows.start)),
        );
        output.send(buffer, area).map_err(RenderError::Flush)?;
        sent = sent.max(next + 1);
        top = band_rows.end;
        next = (next + 1) % count;
    }
    for buffer in &buffers[..sent] {
        output.wait(buffer).map_err(RenderError::Flush)?;
    }
    Ok(())
}

/// Why [`DisplayList::render_bands`] stopped.
///
/// # Examples
///
/// ```
/// use embedded_raster::band::RenderError;
///
/// let e: RenderError<core::convert::Infallible, &str> = RenderError::Flush("bus error");
/// assert!(matches!(e, RenderError::Flush("bus error")));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum RenderError<D, F> {
    /// Drawing into the band buffer failed.
    Draw(D),
    /// Handing a finished band on failed.
    Flush(F),
    /// The screen has rows, and there is no buffer or a buffer has none:
    /// nothing was drawn.
    NoRows,
    /// The screen has rows, and the buffers given to
    /// [`DisplayList::render_bands`]
    /// differ in width: the first gives the screen's, and the triangles
    /// it continues from band to band are clipped to it. Nothing was
    /// drawn. ([`render_in_bands`] draws each band clipped to its own
    /// buffer, and does not return it.)
    WidthsDiffer,
}

impl<D: fmt::Display, F: fmt::Display> fmt::Display for RenderError<D, F> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Draw(e) => write!(f, "drawing a band failed: {e}"),
            Self::Flush(e) => write!(f, "sending a band failed: {e}"),
            Self::NoRows => f.write_str("no band buffer with rows to draw the screen in"),
            Self::WidthsDiffer => f.write_str("band buffers of different widths"),
        }
    }
}

impl<D: fmt::Debug + fmt::Display, F: fmt::Debug + fmt::Display> core::error::Error
    for RenderError<D, F>
{
}
