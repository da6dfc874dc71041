//! Formats of whole-byte pixels, one or more bytes each: how each
//! encodes a colour. How their bytes are stored is in
//! [`stores`](super::stores).

use core::ops::Range;

use embedded_graphics_core::pixelcolor::{
    raw::RawU16, Bgr565, Gray8, GrayColor, IntoStorage, Rgb565, Rgb666, Rgb888, RgbColor,
};

use super::{
    fill_line_by_pixels,
    stores::{
        byte_span, fill_bytes, fill_rows_bytes, read_bytes, walk_line, walks_by_index, write_bytes,
    },
    PixelFormat,
};
use crate::line::LinePixels;

/// Rgb565 in two bytes per pixel, low byte first (`u16::to_le_bytes`).
///
/// # Examples
///
/// ```
/// use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
/// use embedded_raster::framebuffer::{buffer_size, Framebuffer, Rgb565Le};
/// use embedded_graphics::prelude::*;
///
/// let mut fb = Framebuffer::<Rgb565Le, 2, 1, { buffer_size::<Rgb565Le>(2, 1) }>::new();
/// fb.clear(Rgb565::RED)?; // 0xF800
/// assert_eq!(fb.as_bytes(), [0x00, 0xF8, 0x00, 0xF8]);
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Rgb565Le;

/// Rgb565 in two bytes per pixel, high byte first (`u16::to_be_bytes`):
/// what SPI panels such as the ST7789 and ILI9341 take.
///
/// # Examples
///
/// ```
/// use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
/// use embedded_raster::framebuffer::{buffer_size, Framebuffer, Rgb565Be};
/// use embedded_graphics::prelude::*;
///
/// let mut fb = Framebuffer::<Rgb565Be, 2, 1, { buffer_size::<Rgb565Be>(2, 1) }>::new();
/// fb.clear(Rgb565::RED)?; // 0xF800
/// assert_eq!(fb.as_bytes(), [0xF8, 0x00, 0xF8, 0x00]);
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Rgb565Be;

/// [`Bgr565`] in two bytes per pixel, low byte first (`u16::to_le_bytes`
/// of embedded-graphics' raw value, blue in the top 5 bits): the bytes of
/// embedded-graphics' `Framebuffer<Bgr565, RawU16, LittleEndian, ..>`.
///
/// # Examples
///
/// ```
/// use embedded_graphics::pixelcolor::{Bgr565, RgbColor};
/// use embedded_raster::framebuffer::{buffer_size, Bgr565Le, Framebuffer};
/// use embedded_graphics::prelude::*;
///
/// let mut fb = Framebuffer::<Bgr565Le, 2, 1, { buffer_size::<Bgr565Le>(2, 1) }>::new();
/// fb.clear(Bgr565::BLUE)?; // 0xF800
/// assert_eq!(fb.as_bytes(), [0x00, 0xF8, 0x00, 0xF8]);
/// assert_eq!(fb.pixel(Point::new(1, 0)), Some(Bgr565::BLUE));
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Bgr565Le;

/// [`Bgr565`] in two bytes per pixel, high byte first (`u16::to_be_bytes`
/// of embedded-graphics' raw value, blue in the top 5 bits): for panels
/// wired or configured for BGR order (`MADCTL` BGR bit) on SPI; the bytes
/// of embedded-graphics' `Framebuffer<Bgr565, RawU16, BigEndian, ..>`.
///
/// # Examples
///
/// ```
/// use embedded_graphics::pixelcolor::{Bgr565, RgbColor};
/// use embedded_raster::framebuffer::{buffer_size, Bgr565Be, Framebuffer};
/// use embedded_graphics::prelude::*;
///
/// let mut fb = Framebuffer::<Bgr565Be, 2, 1, { buffer_size::<Bgr565Be>(2, 1) }>::new();
/// fb.clear(Bgr565::RED)?; // 0x001F
/// assert_eq!(fb.as_bytes(), [0x00, 0x1F, 0x00, 0x1F]);
/// assert_eq!(fb.pixel(Point::new(0, 0)), Some(Bgr565::RED));
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Bgr565Be;

/// Rgb888 in three bytes per pixel: red, green, blue.
///
/// # Examples
///
/// ```
/// use embedded_graphics::pixelcolor::Rgb888;
/// use embedded_raster::framebuffer::{buffer_size, Framebuffer, Rgb888Bytes};
/// use embedded_graphics::prelude::*;
///
/// let mut fb = Framebuffer::<Rgb888Bytes, 2, 1, { buffer_size::<Rgb888Bytes>(2, 1) }>::new();
/// fb.clear(Rgb888::new(1, 2, 3))?;
/// assert_eq!(fb.as_bytes(), [1, 2, 3, 1, 2, 3]);
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Rgb888Bytes;

/// [`Rgb666`] in three bytes per pixel, as 18-bit SPI panels (ILI9341,
/// ST7796, ILI9488 in 18-bit mode) take it: red, green, blue, each
/// channel's 6 bits in the high bits of its byte, the low 2 bits 0
/// (`RRRRRR00 GGGGGG00 BBBBBB00`). Reading a pixel ignores the low 2 bits.
///
/// embedded-graphics' `Framebuffer<Rgb666, RawU24, ..>` stores the 18-bit
/// raw value in 3 bytes instead (`000000RR RRRRGGGG GGBBBBBB`, big-endian),
/// which these panels do not take.
///
/// # Examples
///
/// ```
/// use embedded_graphics::pixelcolor::Rgb666;
/// use embedded_raster::framebuffer::{buffer_size, Framebuffer, Rgb666Bytes};
/// use embedded_graphics::prelude::*;
///
/// let mut fb = Framebuffer::<Rgb666Bytes, 2, 1, { buffer_size::<Rgb666Bytes>(2, 1) }>::new();
/// fb.clear(Rgb666::new(63, 1, 32))?;
/// assert_eq!(fb.as_bytes(), [0xFC, 0x04, 0x80, 0xFC, 0x04, 0x80]);
/// assert_eq!(fb.pixel(Point::new(1, 0)), Some(Rgb666::new(63, 1, 32)));
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Rgb666Bytes;

/// Gray8 in one byte per pixel, the luma.
///
/// # Examples
///
/// ```
/// use embedded_graphics::pixelcolor::Gray8;
/// use embedded_raster::framebuffer::{buffer_size, Framebuffer, Gray8Bytes};
/// use embedded_graphics::prelude::*;
///
/// let mut fb = Framebuffer::<Gray8Bytes, 3, 1, { buffer_size::<Gray8Bytes>(3, 1) }>::new();
/// fb.clear(Gray8::new(0x80))?;
/// assert_eq!(fb.as_bytes(), [0x80; 3]);
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Gray8Bytes;

/// Implements [`PixelFormat`] for a format of `$bytes`-byte pixels, given
/// how to encode and decode a colour.
macro_rules! byte_format {
    ($format:ty, $color:ty, $bytes:literal, $encode:expr, $decode:expr) => {
        impl PixelFormat for $format {
            type Color = $color;
            const BITS_PER_PIXEL: usize = 8 * $bytes;

            #[inline(always)]
            fn fill_span(row: &mut [u8], xs: Range<usize>, color: $color) {
                if let Some(bytes) = byte_span::<$bytes>(row, xs) {
                    fill_bytes(bytes, $encode(color));
                }
            }

            #[inline]
            fn fill_rows<'a>(
                rows: impl Iterator<Item = &'a mut [u8]>,
                xs: Range<usize>,
                color: $color,
            ) {
                fill_rows_bytes::<$bytes>(rows, xs, $encode(color));
            }

            fn write_span<I: Iterator<Item = $color>>(
                row: &mut [u8],
                xs: Range<usize>,
                colors: I,
            ) -> usize {
                write_bytes(row, xs, colors, $encode)
            }

            fn read_pixel(row: &[u8], x: usize) -> Option<$color> {
                read_bytes::<$bytes>(row, x).map($decode)
            }

            #[inline]
            fn write_pixel(row: &mut [u8], x: usize, color: $color) {
                if let Some(px) = byte_span::<$bytes>(row, x..x.saturating_add(1)) {
                    for (dst, src) in px.iter_mut().zip($encode(color)) {
                        *dst = src;
                    }
                }
            }

            // Inlined into the framebuffer's `fill_line`, after its test
            // that the line lies inside; `walks_by_index` still runs, and
            // the pixel-by-pixel path is still linked (Cortex-M4, `.ci/icount`: 16 px lines 481 → 472
            // instructions; the lines-only firmware at opt-level "s" 3,840
            // → 3,744 bytes, `.ci/codesize`).
            #[inline]
            fn fill_line(buffer: &mut [u8], stride: usize, pixels: LinePixels, color: $color) {
                // By offset where that is safe (always, for a
                // framebuffer's own lines), else pixel by pixel.
                if walks_by_index::<$bytes>(stride, &pixels) {
                    walk_line(buffer, stride, &pixels, $encode(color));
                } else {
                    fill_line_by_pixels::<Self>(buffer, stride, pixels, color);
                }
            }
        }
    };
}

byte_format!(
    Rgb565Le,
    Rgb565,
    2,
    |c: Rgb565| c.into_storage().to_le_bytes(),
    |b| Rgb565::from(RawU16::new(u16::from_le_bytes(b)))
);
byte_format!(
    Rgb565Be,
    Rgb565,
    2,
    |c: Rgb565| c.into_storage().to_be_bytes(),
    |b| Rgb565::from(RawU16::new(u16::from_be_bytes(b)))
);
byte_format!(
    Bgr565Le,
    Bgr565,
    2,
    |c: Bgr565| c.into_storage().to_le_bytes(),
    |b| Bgr565::from(RawU16::new(u16::from_le_bytes(b)))
);
byte_format!(
    Bgr565Be,
    Bgr565,
    2,
    |c: Bgr565| c.into_storage().to_be_bytes(),
    |b| Bgr565::from(RawU16::new(u16::from_be_bytes(b)))
);
byte_format!(
    Rgb888Bytes,
    Rgb888,
    3,
    |c: Rgb888| [c.r(), c.g(), c.b()],
    |[r, g, b]: [u8; 3]| Rgb888::new(r, g, b)
);
// Each 6-bit channel in the high bits of its byte.
byte_format!(
    Rgb666Bytes,
    Rgb666,
    3,
    |c: Rgb666| [c.r() << 2, c.g() << 2, c.b() << 2],
    |[r, g, b]: [u8; 3]| Rgb666::new(r >> 2, g >> 2, b >> 2)
);
byte_format!(
    Gray8Bytes,
    Gray8,
    1,
    |c: Gray8| [c.luma()],
    |[luma]: [u8; 1]| Gray8::new(luma)
);
