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
pub use list::{Command, DisplayList, DisplayListFull, RenderError};

use core::ops::Range;

use embedded_graphics_core::{
    draw_target::DrawTarget,
    geometry::{Dimensions, OriginDimensions, Point, Size},
    primitives::Rectangle,
    Pixel,
};

use crate::{
    clip::{advance, Bounds},
    line::LinePixels,
    raster::sink::SpanSink,
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
        Self { target, top }
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
        let height = self.target.size().height;
        self.top..self.top.saturating_add_unsigned(height)
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

    /// `p` in the target's coordinates, if it is in the band's rows.
    fn point_to_target(&self, p: Point) -> Option<Point> {
        self.rows()
            .contains(&p.y)
            .then(|| Point::new(p.x, p.y - self.top))
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

    /// Fills the whole band: its part of the screen.
    fn clear(&mut self, color: Self::Color) -> Result<(), Self::Error> {
        self.target.clear(color)
    }
}

impl<C: Copy, T: SpanSink<C> + OriginDimensions> SpanSink<C> for Band<'_, T> {
    type Error = T::Error;

    fn bounds(&self) -> Rectangle {
        // Only what the target has: shapes clip to it before they step.
        let own = self.target.bounds();
        let top_left = Point::new(own.top_left.x, own.top_left.y.saturating_add(self.top));
        Rectangle::new(top_left, own.size)
    }

    fn fill_span(&mut self, span: Span, color: C) -> Result<(), Self::Error> {
        match self.point_to_target(Point::new(span.x_start, span.y)) {
            Some(p) => self.target.fill_span(Span { y: p.y, ..span }, color),
            None => Ok(()),
        }
    }

    fn fill_column(&mut self, top: Point, len: u32, color: C) -> Result<(), Self::Error> {
        let column = Rectangle::new(top, Size::new(1, len));
        match self.to_target(&column) {
            Some((moved, _)) => {
                self.target
                    .fill_column(moved.top_left, moved.size.height, color)
            }
            None => Ok(()),
        }
    }

    fn fill_rect(&mut self, area: &Rectangle, color: C) -> Result<(), Self::Error> {
        match self.to_target(area) {
            Some((moved, _)) => self.target.fill_rect(&moved, color),
            None => Ok(()),
        }
    }

    fn fill_line(&mut self, pixels: LinePixels, color: C) -> Result<(), Self::Error> {
        // The shapes clipped the line to `bounds`, inside the band's rows,
        // so moving it up by `top` keeps it in `i32`.
        match self.top.checked_neg().and_then(|up| pixels.moved_down(up)) {
            Some(moved) => self.target.fill_line(moved, color),
            None => pixels.for_each_run(|run| crate::line::fill_run(self, run, color)),
        }
    }
}
