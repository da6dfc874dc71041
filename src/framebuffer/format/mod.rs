//! [`PixelFormat`] and the built-in formats: whole-byte pixels in
//! `bytes`, several pixels to a byte in `packed`.

mod bytes;
mod packed;
mod stores;

pub use bytes::{Bgr565Be, Bgr565Le, Gray8Bytes, Rgb565Be, Rgb565Le, Rgb666Bytes, Rgb888Bytes};
pub use packed::{BinaryMsb, Gray2Lsb, Gray2Msb, Gray4Lsb, Gray4Msb};

use core::ops::Range;

use crate::line::LinePixels;

use embedded_graphics_core::pixelcolor::PixelColor;

/// How one colour type is laid out in the bytes of a
/// [`Framebuffer`](super::Framebuffer).
///
/// A row of `width` pixels takes
/// [`row_size::<F>(width)`](super::row_size) bytes,
/// `ceil(width * BITS_PER_PIXEL / 8)`; rows follow each other top to
/// bottom with nothing in between. A format must be *positional*: pixel `x`
/// lives in the `x`-th `BITS_PER_PIXEL`-bit slot of its row (how the bits
/// are arranged inside a slot, and which end of a byte comes first, is the
/// format's choice). The built-in formats are described in the
/// [module docs](super).
///
/// The methods work on one row at a time, given as the row's bytes and a
/// range of pixel columns. When rows have no padding bits (`width *
/// BITS_PER_PIXEL` a multiple of 8), the framebuffer may pass several
/// consecutive whole rows as one longer row, which positional formats store
/// identically. The framebuffer only asks for pixels inside `row`;
/// implementations should ignore any others rather than panic, as the
/// built-in ones do.
///
/// You can implement this trait for a layout of your own, e.g. `Rgb555` or a
/// panel's own packing.
///
/// # Examples
///
/// ```
/// use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
/// use embedded_raster::framebuffer::{PixelFormat, Rgb565Be};
///
/// let mut row = [0u8; 8]; // 4 pixels
/// Rgb565Be::fill_span(&mut row, 1..3, Rgb565::RED);
/// assert_eq!(row, [0, 0, 0xF8, 0x00, 0xF8, 0x00, 0, 0]);
/// assert_eq!(Rgb565Be::read_pixel(&row, 2), Some(Rgb565::RED));
/// assert_eq!(Rgb565Be::read_pixel(&row, 4), None);
/// ```
pub trait PixelFormat {
    /// The colour type stored.
    type Color: PixelColor;

    /// Bits each pixel takes, at least 1.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::framebuffer::{BinaryMsb, PixelFormat, Rgb888Bytes};
    ///
    /// assert_eq!(Rgb888Bytes::BITS_PER_PIXEL, 24);
    /// assert_eq!(BinaryMsb::BITS_PER_PIXEL, 1);
    /// ```
    const BITS_PER_PIXEL: usize;

    /// Sets pixels `xs` of `row` to `color`.
    ///
    /// Any range: an empty or reversed one writes nothing, and the
    /// built-in formats write nothing unless all of `xs` lies in `row`.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use embedded_raster::framebuffer::{BinaryMsb, PixelFormat};
    ///
    /// let mut row = [0u8; 2]; // up to 16 pixels, leftmost in bit 7
    /// BinaryMsb::fill_span(&mut row, 3..11, BinaryColor::On);
    /// assert_eq!(row, [0b0001_1111, 0b1110_0000]);
    /// ```
    fn fill_span(row: &mut [u8], xs: Range<usize>, color: Self::Color);

    /// Sets pixels `xs` of every row of `rows` to `color`: a rectangle.
    ///
    /// The provided implementation calls [`fill_span`](Self::fill_span)
    /// on each row. The built-in whole-byte formats work out their word
    /// stores once for all the rows, where rows start on a 4-byte
    /// boundary (the rows of a [`Framebuffer`](super::Framebuffer) whose
    /// rows are a whole number of words long).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Gray8;
    /// use embedded_raster::framebuffer::{Gray8Bytes, PixelFormat};
    ///
    /// let mut buffer = [0u8; 12]; // 4 x 3
    /// Gray8Bytes::fill_rows(buffer.chunks_exact_mut(4).skip(1), 1..3, Gray8::new(5));
    /// assert_eq!(buffer, [0, 0, 0, 0, 0, 5, 5, 0, 0, 5, 5, 0]);
    /// ```
    fn fill_rows<'a>(
        rows: impl Iterator<Item = &'a mut [u8]>,
        xs: Range<usize>,
        color: Self::Color,
    ) {
        for row in rows {
            Self::fill_span(row, xs.clone(), color);
        }
    }

    /// Sets pixels `xs` of `row`, left to right, to colours taken from
    /// `colors`, and returns how many it set: `xs.len()`, or fewer if
    /// `colors` ran out first. Takes no colour beyond those it sets, so
    /// that a `&mut` iterator goes on with the next pixel in the next call;
    /// one passed by value can be held in registers as it is stepped.
    ///
    /// The provided implementation calls
    /// [`write_pixel`](Self::write_pixel) for each pixel.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Gray8;
    /// use embedded_raster::framebuffer::{Gray8Bytes, PixelFormat};
    ///
    /// let mut row = [0u8; 4];
    /// let mut colors = [10, 20, 30].into_iter().map(Gray8::new);
    /// assert_eq!(Gray8Bytes::write_span(&mut row, 0..2, &mut colors), 2);
    /// assert_eq!(Gray8Bytes::write_span(&mut row, 3..4, &mut colors), 1);
    /// assert_eq!(Gray8Bytes::write_span(&mut row, 2..3, &mut colors), 0);
    /// assert_eq!(row, [10, 20, 0, 30]);
    /// ```
    fn write_span<I: Iterator<Item = Self::Color>>(
        row: &mut [u8],
        xs: Range<usize>,
        mut colors: I,
    ) -> usize {
        let mut written = 0;
        for x in xs {
            let Some(color) = colors.next() else { break };
            Self::write_pixel(row, x, color);
            written += 1;
        }
        written
    }

    /// The colour of pixel `x` of `row`, or `None` if it is not inside
    /// `row` (any `x`).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Rgb888, RgbColor};
    /// use embedded_raster::framebuffer::{PixelFormat, Rgb888Bytes};
    ///
    /// let row = [0, 0, 0, 1, 2, 3];
    /// assert_eq!(Rgb888Bytes::read_pixel(&row, 1), Some(Rgb888::new(1, 2, 3)));
    /// assert_eq!(Rgb888Bytes::read_pixel(&row, 2), None);
    /// ```
    fn read_pixel(row: &[u8], x: usize) -> Option<Self::Color>;

    /// Sets pixel `x` of `row` to `color`; any `x`, nothing written
    /// outside `row`.
    ///
    /// The provided implementation calls [`fill_span`](Self::fill_span)
    /// with `x..x + 1` (saturating: `usize::MAX` is an empty range).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
    /// use embedded_raster::framebuffer::{PixelFormat, Rgb565Le};
    ///
    /// let mut row = [0u8; 4];
    /// Rgb565Le::write_pixel(&mut row, 1, Rgb565::BLUE);
    /// assert_eq!(row, [0, 0, 0x1F, 0x00]);
    /// ```
    fn write_pixel(row: &mut [u8], x: usize, color: Self::Color) {
        Self::fill_span(row, x..x.saturating_add(1), color);
    }

    /// Sets the pixels of a 1-pixel line in `buffer`, whose rows are
    /// `stride` bytes apart; pixels outside `buffer` (at a negative offset,
    /// or past its end at any `stride`) are ignored, without overflow.
    /// Clip the line to the rows' width first (as the
    /// [`Framebuffer`](super::Framebuffer) does): a pixel past its row's
    /// end is ignored by the provided implementation and the packed
    /// formats, but lands in the next row (and one at a negative `x` at the
    /// end of the row before) with the byte formats, which walk the buffer
    /// by offset when `stride` is a whole number of pixels (at other
    /// strides they set the pixels one by one, as the provided
    /// implementation does, and ignore it).
    ///
    /// The provided implementation calls [`write_pixel`](Self::write_pixel)
    /// per pixel; the built-in byte formats walk the line through the
    /// buffer instead, one byte offset step per pixel.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{geometry::{Point, Size}, pixelcolor::Gray8, primitives::Rectangle};
    /// use embedded_raster::{framebuffer::{Gray8Bytes, PixelFormat}, Line};
    ///
    /// let mut buffer = [0u8; 12]; // 4 x 3
    /// let clip = Rectangle::new(Point::zero(), Size::new(4, 3));
    /// let pixels = Line::new(Point::new(0, 0), Point::new(3, 2)).pixels(&clip).unwrap();
    /// Gray8Bytes::fill_line(&mut buffer, 4, pixels, Gray8::new(7));
    /// assert_eq!(buffer, [7, 0, 0, 0, 0, 7, 7, 0, 0, 0, 0, 7]);
    /// ```
    fn fill_line(buffer: &mut [u8], stride: usize, pixels: LinePixels, color: Self::Color) {
        fill_line_by_pixels::<Self>(buffer, stride, pixels, color);
    }
}

/// [`PixelFormat::fill_line`] pixel by pixel, each through
/// [`write_pixel`](PixelFormat::write_pixel) on its row cut at the
/// buffer's end (a stride may be any size): the provided implementation,
/// and the byte formats' for the lines they cannot walk by offset.
pub(super) fn fill_line_by_pixels<F: PixelFormat + ?Sized>(
    buffer: &mut [u8],
    stride: usize,
    pixels: LinePixels,
    color: F::Color,
) {
    let len = buffer.len();
    for p in pixels {
        if let (Ok(x), Ok(y)) = (usize::try_from(p.x), usize::try_from(p.y)) {
            let row = y
                .checked_mul(stride)
                .and_then(|start| buffer.get_mut(start..start.saturating_add(stride).min(len)));
            if let Some(row) = row {
                F::write_pixel(row, x, color);
            }
        }
    }
}
