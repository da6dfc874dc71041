//! [`DirtyRows`]: what changed on a full framebuffer since the last flush.

use embedded_graphics_core::{
    draw_target::DrawTarget,
    geometry::{Dimensions, OriginDimensions, Point, Size},
    image::GetPixel,
    primitives::Rectangle,
    Pixel,
};

use crate::{clip::Bounds, line::LinePixels, raster::sink::SpanSink, span::Span};

/// A target `T` of `H` rows that records, per row, the columns written
/// since the last flush (one range per row, from the leftmost to the
/// rightmost pixel written), and sends only those to the display.
///
/// What is recorded is each write's area on the target, whatever `T`
/// does with it: nothing written is ever left out, and where `T` writes
/// less (a `fill_contiguous` whose colours run out, a span that a
/// [`Framebuffer`](crate::Framebuffer) drops because it is not wholly
/// inside one row), the record is a superset, which a flush sends whole.
///
/// Every write goes through to `T`; the record costs two compares per
/// span and `8 H` bytes. [`flush`](Self::flush) sends the changed region
/// as rectangles, each a run of consecutive changed rows whose column
/// ranges overlap, with one `fill_contiguous` each (the window write that
/// display drivers turn into one transfer), and forgets it.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, prelude::*, primitives::Rectangle};
/// use embedded_raster::{band::DirtyRows, framebuffer::{buffer_size, BinaryMsb}, Framebuffer, Line};
///
/// let fb = Framebuffer::<BinaryMsb, 16, 8, { buffer_size::<BinaryMsb>(16, 8) }>::new();
/// let mut screen = DirtyRows::<_, 8>::new(fb);
/// Line::new(Point::new(2, 1), Point::new(5, 1)).stroke(BinaryColor::On).draw(&mut screen)?;
/// assert_eq!(screen.changed().next(), Some(Rectangle::new(Point::new(2, 1), Size::new(4, 1))));
///
/// let mut display = MockDisplay::new();
/// display.set_allow_overdraw(true);
/// screen.flush(&mut display)?; // sends the 4 changed pixels only
/// display.assert_pattern(&["      ", "  ####"]);
/// assert_eq!(screen.changed().next(), None);
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Debug, Clone)]
pub struct DirtyRows<T, const H: usize> {
    target: T,
    /// Per row, the changed columns `start..end` (empty when `start >= end`).
    rows: [(u32, u32); H],
}

impl<T: OriginDimensions, const H: usize> DirtyRows<T, H> {
    /// Wraps `target`, with nothing changed yet. `H` should be the
    /// target's height: rows from `H` down are not recorded.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::{band::DirtyRows, framebuffer::{buffer_size, Gray8Bytes}, Framebuffer};
    ///
    /// let fb = Framebuffer::<Gray8Bytes, 4, 4, { buffer_size::<Gray8Bytes>(4, 4) }>::new();
    /// let screen = DirtyRows::<_, 4>::new(fb);
    /// assert_eq!(screen.changed().count(), 0);
    /// ```
    pub const fn new(target: T) -> Self {
        Self {
            target,
            rows: [(u32::MAX, 0); H],
        }
    }

    /// The wrapped target.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::{band::DirtyRows, framebuffer::{buffer_size, Gray8Bytes}, Framebuffer};
    ///
    /// let fb = Framebuffer::<Gray8Bytes, 4, 4, { buffer_size::<Gray8Bytes>(4, 4) }>::new();
    /// assert_eq!(DirtyRows::<_, 4>::new(fb).target().as_bytes().len(), 16);
    /// ```
    pub fn target(&self) -> &T {
        &self.target
    }

    /// Marks the part of `area` on the target as changed.
    fn mark(&mut self, area: &Rectangle) {
        mark_rows(&mut self.rows, self.target.size(), area);
    }

    /// The changed region as rectangles: runs of consecutive changed rows
    /// whose column ranges overlap, each the smallest rectangle around its
    /// run.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*, primitives::Rectangle};
    /// use embedded_raster::{band::DirtyRows, framebuffer::{buffer_size, Gray8Bytes}, Framebuffer};
    ///
    /// let fb = Framebuffer::<Gray8Bytes, 16, 16, { buffer_size::<Gray8Bytes>(16, 16) }>::new();
    /// let mut screen = DirtyRows::<_, 16>::new(fb);
    /// screen.fill_solid(&Rectangle::new(Point::new(1, 1), Size::new(3, 2)), Gray8::WHITE)?;
    /// screen.fill_solid(&Rectangle::new(Point::new(2, 3), Size::new(5, 1)), Gray8::WHITE)?;
    /// screen.fill_solid(&Rectangle::new(Point::new(10, 9), Size::new(2, 2)), Gray8::WHITE)?;
    /// let changed: Vec<_> = screen.changed().collect();
    /// assert_eq!(changed, [
    ///     Rectangle::new(Point::new(1, 1), Size::new(6, 3)),
    ///     Rectangle::new(Point::new(10, 9), Size::new(2, 2)),
    /// ]);
    /// # Ok::<(), core::convert::Infallible>(())
    /// ```
    pub fn changed(&self) -> impl Iterator<Item = Rectangle> + '_ {
        let mut y = 0;
        core::iter::from_fn(move || {
            // The next changed row, then the rows that overlap it.
            while y < H && self.rows[y].0 >= self.rows[y].1 {
                y += 1;
            }
            let first = y;
            let (mut start, mut end) = *self.rows.get(first)?;
            y += 1;
            while let Some(&(s, e)) = self.rows.get(y) {
                if s >= e || s >= end || e <= start {
                    break;
                }
                (start, end) = (start.min(s), end.max(e));
                y += 1;
            }
            // Marked rows and columns lie below 2^31 (`mark_rows`): they
            // fit `i32`.
            let top_left = Point::new(start as i32, first as i32);
            Some(Rectangle::new(
                top_left,
                Size::new(end - start, (y - first) as u32),
            ))
        })
    }

    /// Forgets the changes, as after a flush.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
    /// use embedded_raster::{band::DirtyRows, framebuffer::{buffer_size, Gray8Bytes}, Framebuffer};
    ///
    /// let fb = Framebuffer::<Gray8Bytes, 4, 4, { buffer_size::<Gray8Bytes>(4, 4) }>::new();
    /// let mut screen = DirtyRows::<_, 4>::new(fb);
    /// screen.clear(Gray8::WHITE)?;
    /// screen.forget();
    /// assert_eq!(screen.changed().count(), 0);
    /// # Ok::<(), core::convert::Infallible>(())
    /// ```
    pub fn forget(&mut self) {
        self.rows = [(u32::MAX, 0); H];
    }
}

impl<T: OriginDimensions + GetPixel, const H: usize> DirtyRows<T, H> {
    /// Sends the changed region to `display`, one `fill_contiguous` per
    /// rectangle of [`changed`](Self::changed), and forgets it.
    ///
    /// # Errors
    ///
    /// The first error of `display`; the changes are kept then, so a
    /// later flush sends them again.
    ///
    /// # Examples
    ///
    /// See [`DirtyRows`].
    pub fn flush<D>(&mut self, display: &mut D) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = <T as GetPixel>::Color>,
    {
        for area in self.changed() {
            let target = &self.target;
            let colors = area.rows().flat_map(move |y| {
                area.columns()
                    .filter_map(move |x| target.pixel(Point::new(x, y)))
            });
            display.fill_contiguous(&area, colors)?;
        }
        self.forget();
        Ok(())
    }
}

/// Marks the part of `area` on a target of `size` as changed in `rows`
/// (one column range per row; rows from `H` down are not recorded).
fn mark_rows<const H: usize>(rows: &mut [(u32, u32); H], size: Size, area: &Rectangle) {
    // The target's pixels a `Point` can name (coordinates below 2^31):
    // the rectangles `changed` reports start at `i32` coordinates.
    let addressable = Bounds {
        x0: 0,
        y0: 0,
        x1: 1 << 31,
        y1: 1 << 31,
    };
    let own = Bounds::of(&Rectangle::new(Point::zero(), size)).intersect(addressable);
    let Some(b) = own.and_then(|own| Bounds::of(area).intersect(own)) else {
        return;
    };
    // Within 0..=2^31: every value fits `u32` and `usize`.
    let (x0, x1) = (b.x0 as u32, b.x1 as u32);
    let ys = b.y0 as usize..(b.y1 as usize).min(H);
    for (start, end) in rows.get_mut(ys).unwrap_or_default() {
        *start = (*start).min(x0);
        *end = (*end).max(x1);
    }
}

impl<T: OriginDimensions, const H: usize> Dimensions for DirtyRows<T, H> {
    fn bounding_box(&self) -> Rectangle {
        Rectangle::new(Point::zero(), self.target.size())
    }
}

impl<T: DrawTarget + OriginDimensions, const H: usize> DrawTarget for DirtyRows<T, H> {
    type Color = T::Color;
    type Error = T::Error;

    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = Pixel<Self::Color>>,
    {
        // One call to the target, marking each pixel on its way there.
        let (rows, size) = (&mut self.rows, self.target.size());
        let marked = pixels.into_iter().inspect(move |Pixel(p, _)| {
            mark_rows(rows, size, &Rectangle::new(*p, Size::new(1, 1)));
        });
        self.target.draw_iter(marked)
    }

    fn fill_contiguous<I>(&mut self, area: &Rectangle, colors: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = Self::Color>,
    {
        self.mark(area);
        self.target.fill_contiguous(area, colors)
    }

    fn fill_solid(&mut self, area: &Rectangle, color: Self::Color) -> Result<(), Self::Error> {
        self.mark(area);
        self.target.fill_solid(area, color)
    }

    fn clear(&mut self, color: Self::Color) -> Result<(), Self::Error> {
        self.mark(&self.bounding_box());
        self.target.clear(color)
    }
}

impl<C: Copy, T: SpanSink<C> + OriginDimensions, const H: usize> SpanSink<C> for DirtyRows<T, H> {
    type Error = T::Error;

    fn bounds(&self) -> Rectangle {
        self.target.bounds()
    }

    /// The target's: a row written twice is marked dirty once.
    #[inline(always)]
    fn overdraw_is_invisible(&self) -> bool {
        self.target.overdraw_is_invisible()
    }

    fn fill_span(&mut self, span: Span, color: C) -> Result<(), Self::Error> {
        self.mark(&span.rect());
        self.target.fill_span(span, color)
    }

    fn fill_column(&mut self, top: Point, len: u32, color: C) -> Result<(), Self::Error> {
        self.mark(&Rectangle::new(top, Size::new(1, len)));
        self.target.fill_column(top, len, color)
    }

    fn fill_rect(&mut self, area: &Rectangle, color: C) -> Result<(), Self::Error> {
        self.mark(area);
        self.target.fill_rect(area, color)
    }

    /// Marks the line's runs (a row's pixels of an x-major line at once, a
    /// column's of a y-major one), then passes the line on whole.
    fn fill_line(&mut self, pixels: LinePixels, color: C) -> Result<(), Self::Error> {
        let Ok(()) = pixels.for_each_run(|run| {
            self.mark(&run.rect());
            Ok::<(), core::convert::Infallible>(())
        });
        self.target.fill_line(pixels, color)
    }
}
