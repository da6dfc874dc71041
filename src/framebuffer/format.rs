//! [`PixelFormat`] and the built-in formats.

use core::ops::Range;

use crate::line::LinePixels;

use embedded_graphics_core::pixelcolor::{
    raw::RawU16, BinaryColor, Gray8, GrayColor, IntoStorage, PixelColor, Rgb565, Rgb888, RgbColor,
};

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
/// You can implement this trait for a layout of your own, e.g. `Bgr565` or a
/// 4-bit grey.
///
/// # Examples
///
/// ```
/// use embedded_graphics_core::pixelcolor::{Rgb565, RgbColor};
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
    /// use embedded_graphics_core::pixelcolor::BinaryColor;
    /// use embedded_raster::framebuffer::{BinaryMsb, PixelFormat};
    ///
    /// let mut row = [0u8; 2]; // up to 16 pixels, leftmost in bit 7
    /// BinaryMsb::fill_span(&mut row, 3..11, BinaryColor::On);
    /// assert_eq!(row, [0b0001_1111, 0b1110_0000]);
    /// ```
    fn fill_span(row: &mut [u8], xs: Range<usize>, color: Self::Color);

    /// Sets pixels `xs` of `row`, left to right, to colours taken from
    /// `colors`, and returns how many it set: `xs.len()`, or fewer if
    /// `colors` ran out first. Takes no colour beyond those it sets.
    ///
    /// The provided implementation calls
    /// [`write_pixel`](Self::write_pixel) for each pixel.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics_core::pixelcolor::Gray8;
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
        colors: &mut I,
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
    /// use embedded_graphics_core::pixelcolor::{Rgb888, RgbColor};
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
    /// use embedded_graphics_core::pixelcolor::{Rgb565, RgbColor};
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
    /// `stride` bytes apart; pixels outside `buffer` (negative, or past its
    /// end at any `stride`) are ignored, without overflow.
    ///
    /// The provided implementation calls [`write_pixel`](Self::write_pixel)
    /// per pixel; the built-in byte formats walk the line through the
    /// buffer instead, one byte offset step per pixel.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics_core::{geometry::{Point, Size}, pixelcolor::Gray8, primitives::Rectangle};
    /// use embedded_raster::{framebuffer::{Gray8Bytes, PixelFormat}, Line};
    ///
    /// let mut buffer = [0u8; 12]; // 4 x 3
    /// let clip = Rectangle::new(Point::zero(), Size::new(4, 3));
    /// let pixels = Line::new(Point::new(0, 0), Point::new(3, 2)).pixels(&clip).unwrap();
    /// Gray8Bytes::fill_line(&mut buffer, 4, pixels, Gray8::new(7));
    /// assert_eq!(buffer, [7, 0, 0, 0, 0, 7, 7, 0, 0, 0, 0, 7]);
    /// ```
    fn fill_line(buffer: &mut [u8], stride: usize, pixels: LinePixels, color: Self::Color) {
        for p in pixels {
            if let (Ok(x), Ok(y)) = (usize::try_from(p.x), usize::try_from(p.y)) {
                let row = y
                    .checked_mul(stride)
                    .and_then(|start| buffer.get_mut(start..start.checked_add(stride)?));
                if let Some(row) = row {
                    Self::write_pixel(row, x, color);
                }
            }
        }
    }
}

/// [`PixelFormat::fill_line`] for `B`-byte pixels: the buffer as an array
/// of pixels, walked by index (one pixel along the major axis, one row or
/// pixel more along the minor axis where the line moves), one
/// bounds-checked store per pixel. Indices stay within the buffer's
/// pixels plus one row, far from overflow.
#[inline(always)]
fn walk_line<const B: usize>(buffer: &mut [u8], stride: usize, pixels: &LinePixels, px: [u8; B]) {
    let (cells, _) = buffer.as_chunks_mut::<B>();
    let first = pixels.first();
    let row = stride / B;
    let (Ok(x), Ok(y), Ok(row)) = (
        isize::try_from(first.x),
        isize::try_from(first.y),
        isize::try_from(row),
    ) else {
        return;
    };
    let Some(start) = y.checked_mul(row).and_then(|r| r.checked_add(x)) else {
        return;
    };
    let s = pixels.minor_step() as isize;
    let (major, minor) = if pixels.x_major() {
        (1, s * row)
    } else {
        (row, s)
    };
    pixels.walk(start, major, minor, move |at| {
        if let Some(cell) = usize::try_from(at).ok().and_then(|at| cells.get_mut(at)) {
            *cell = px;
        }
    });
}

/// Rgb565 in two bytes per pixel, low byte first (`u16::to_le_bytes`).
///
/// # Examples
///
/// ```
/// use embedded_graphics_core::pixelcolor::{Rgb565, RgbColor};
/// use embedded_raster::framebuffer::{buffer_size, Framebuffer, Rgb565Le};
/// use embedded_graphics_core::prelude::*;
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
/// use embedded_graphics_core::pixelcolor::{Rgb565, RgbColor};
/// use embedded_raster::framebuffer::{buffer_size, Framebuffer, Rgb565Be};
/// use embedded_graphics_core::prelude::*;
///
/// let mut fb = Framebuffer::<Rgb565Be, 2, 1, { buffer_size::<Rgb565Be>(2, 1) }>::new();
/// fb.clear(Rgb565::RED)?; // 0xF800
/// assert_eq!(fb.as_bytes(), [0xF8, 0x00, 0xF8, 0x00]);
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Rgb565Be;

/// Rgb888 in three bytes per pixel: red, green, blue.
///
/// # Examples
///
/// ```
/// use embedded_graphics_core::pixelcolor::Rgb888;
/// use embedded_raster::framebuffer::{buffer_size, Framebuffer, Rgb888Bytes};
/// use embedded_graphics_core::prelude::*;
///
/// let mut fb = Framebuffer::<Rgb888Bytes, 2, 1, { buffer_size::<Rgb888Bytes>(2, 1) }>::new();
/// fb.clear(Rgb888::new(1, 2, 3))?;
/// assert_eq!(fb.as_bytes(), [1, 2, 3, 1, 2, 3]);
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Rgb888Bytes;

/// Gray8 in one byte per pixel, the luma.
///
/// # Examples
///
/// ```
/// use embedded_graphics_core::pixelcolor::Gray8;
/// use embedded_raster::framebuffer::{buffer_size, Framebuffer, Gray8Bytes};
/// use embedded_graphics_core::prelude::*;
///
/// let mut fb = Framebuffer::<Gray8Bytes, 3, 1, { buffer_size::<Gray8Bytes>(3, 1) }>::new();
/// fb.clear(Gray8::new(0x80))?;
/// assert_eq!(fb.as_bytes(), [0x80; 3]);
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Gray8Bytes;

/// [`BinaryColor`] packed 8 pixels per byte, the leftmost pixel in the
/// most significant bit, `On` as 1; each row starts on a new byte, the
/// unused low bits of its last byte being padding that drawing never
/// changes. The layout of e-paper panels and embedded-graphics'
/// `Framebuffer<BinaryColor, RawU1, BigEndian, ..>`.
///
/// # Examples
///
/// ```
/// use embedded_graphics_core::pixelcolor::BinaryColor;
/// use embedded_raster::framebuffer::{buffer_size, BinaryMsb, Framebuffer};
/// use embedded_graphics_core::prelude::*;
///
/// // 10 pixels per row: 2 bytes, the last 6 bits padding.
/// let mut fb = Framebuffer::<BinaryMsb, 10, 2, { buffer_size::<BinaryMsb>(10, 2) }>::new();
/// fb.clear(BinaryColor::On)?;
/// assert_eq!(fb.as_bytes(), [0xFF, 0b1100_0000, 0xFF, 0b1100_0000]);
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct BinaryMsb;

/// The bytes of pixels `xs` in a row of `B`-byte pixels, if all are in
/// `row`.
#[inline]
fn byte_span<const B: usize>(row: &mut [u8], xs: Range<usize>) -> Option<&mut [u8]> {
    row.get_mut(xs.start.checked_mul(B)?..xs.end.checked_mul(B)?)
}

/// Fills `bytes`, whole pixels, with copies of `pixel`.
///
/// One `memset` if all bytes of `pixel` are equal (black, white, any
/// grey). Otherwise, on 32-bit ARM and for spans of 16 pixels or more, the
/// widest safe stores ([`fill_words`]): aligned 32-bit words of the
/// repeating pattern, which the compiler turns into runs of `strd` on a
/// Cortex-M4. Shorter spans, and every span on other architectures, are a
/// plain pixel loop: the word setup costs more than it saves on short
/// spans, and hosts' compilers vectorize the loop themselves (measured
/// faster on x86-64 than the word path).
#[inline(always)]
fn fill_bytes<const B: usize>(bytes: &mut [u8], pixel: [u8; B]) {
    let Some(&first) = pixel.first() else { return };
    if pixel.iter().all(|&b| b == first) {
        bytes.fill(first);
    } else if bytes.len() < 16 * B || !cfg!(target_arch = "arm") {
        // Whole pixels only: `bytes` is a span of them. Hosts vectorize
        // this loop themselves, better than the word path below.
        bytes.as_chunks_mut::<B>().0.fill(pixel);
    } else {
        fill_words(bytes, pixel);
    }
}

/// [`fill_bytes`] through aligned words.
#[inline]
fn fill_words<const B: usize>(bytes: &mut [u8], pixel: [u8; B]) {
    // Byte `i` of the span is byte `i % B` of the pixel.
    let at = |i: usize| pixel[i % B];
    let (head, words, tail) = bytemuck::pod_align_to_mut::<u8, u32>(bytes);
    let offset = head.len();
    if offset % B == 0 && 4 % B == 0 {
        // Whole pixels up to the boundary (for 2-byte pixels in a
        // word-aligned buffer: none or one), then one repeated word.
        for px in head.as_chunks_mut::<B>().0 {
            *px = pixel;
        }
        fill_u32(words, u32::from_ne_bytes([at(0), at(1), at(2), at(3)]));
        // The tail is whole pixels too: the span and the head are.
        for px in tail.as_chunks_mut::<B>().0 {
            *px = pixel;
        }
        return;
    }
    for (i, b) in head.iter_mut().enumerate() {
        *b = at(i);
    }
    // Four pixels are B whole words; this block starts where `words` does.
    let mut block = [0u32; B];
    for (k, w) in block.iter_mut().enumerate() {
        let i = offset + 4 * k;
        *w = u32::from_ne_bytes([at(i), at(i + 1), at(i + 2), at(i + 3)]);
    }
    let (blocks, rest) = words.as_chunks_mut::<B>();
    for chunk in blocks {
        *chunk = block;
    }
    for (w, b) in rest.iter_mut().zip(block) {
        *w = b;
    }
    let offset = offset + 4 * words.len();
    for (i, b) in tail.iter_mut().enumerate() {
        *b = at(offset + i);
    }
}

/// `words.fill(word)`, 8 words (32 bytes) a step: on a Cortex-M4 each
/// step is a few multi-register stores (`strd`/`stm`) and one loop test,
/// about 0.4 instructions per 2-byte pixel, where a plain `fill` is
/// unrolled only 4 times.
#[inline(always)]
fn fill_u32(words: &mut [u32], word: u32) {
    let (blocks, rest) = words.as_chunks_mut::<8>();
    for block in blocks {
        *block = [word; 8];
    }
    rest.fill(word);
}

/// [`PixelFormat::write_span`] for `B`-byte pixels.
fn write_bytes<const B: usize, C, I: Iterator<Item = C>>(
    row: &mut [u8],
    xs: Range<usize>,
    colors: &mut I,
    encode: impl Fn(C) -> [u8; B],
) -> usize {
    let Some(bytes) = byte_span::<B>(row, xs) else {
        return 0;
    };
    let mut written = 0;
    for px in bytes.as_chunks_mut::<B>().0 {
        let Some(color) = colors.next() else { break };
        *px = encode(color);
        written += 1;
    }
    written
}

/// The bytes of pixel `x` in a row of `B`-byte pixels.
fn read_bytes<const B: usize>(row: &[u8], x: usize) -> Option<[u8; B]> {
    let start = x.checked_mul(B)?;
    row.get(start..start.checked_add(B)?)?.try_into().ok()
}

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

            fn write_span<I: Iterator<Item = $color>>(
                row: &mut [u8],
                xs: Range<usize>,
                colors: &mut I,
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

            fn fill_line(buffer: &mut [u8], stride: usize, pixels: LinePixels, color: $color) {
                walk_line(buffer, stride, &pixels, $encode(color));
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
    Rgb888Bytes,
    Rgb888,
    3,
    |c: Rgb888| [c.r(), c.g(), c.b()],
    |[r, g, b]: [u8; 3]| Rgb888::new(r, g, b)
);
byte_format!(
    Gray8Bytes,
    Gray8,
    1,
    |c: Gray8| [c.luma()],
    |[luma]: [u8; 1]| Gray8::new(luma)
);

/// The bit of pixel `x` in its byte of a [`BinaryMsb`] row.
const fn msb_bit(x: usize) -> u8 {
    0x80 >> (x % 8)
}

/// Sets (`on`) or clears the bits `mask` of `byte`.
fn apply(byte: &mut u8, mask: u8, on: bool) {
    if on {
        *byte |= mask;
    } else {
        *byte &= !mask;
    }
}

impl PixelFormat for BinaryMsb {
    type Color = BinaryColor;
    const BITS_PER_PIXEL: usize = 1;

    /// Masks the partial bytes at both ends and fills the whole bytes in
    /// between.
    fn fill_span(row: &mut [u8], xs: Range<usize>, color: BinaryColor) {
        let Some(last) = xs.end.checked_sub(1) else {
            return;
        };
        if xs.start > last {
            return;
        }
        // Pixels `start % 8..` of the first byte, `..=last % 8` of the last.
        let head = 0xFF_u8 >> (xs.start % 8);
        let tail = 0xFF_u8 << (7 - last % 8);
        let on = color.is_on();
        match row.get_mut(xs.start / 8..=last / 8) {
            Some([only]) => apply(only, head & tail, on),
            Some([first, middle @ .., end]) => {
                apply(first, head, on);
                middle.fill(if on { 0xFF } else { 0 });
                apply(end, tail, on);
            }
            _ => {}
        }
    }

    /// Gathers up to 8 pixels and writes each byte once.
    fn write_span<I: Iterator<Item = BinaryColor>>(
        row: &mut [u8],
        xs: Range<usize>,
        colors: &mut I,
    ) -> usize {
        let mut written = 0;
        let mut x = xs.start;
        while x < xs.end {
            let Some(byte) = row.get_mut(x / 8) else {
                break;
            };
            // Up to the end of this byte or of the span.
            let end = xs.end.min((x | 7).saturating_add(1));
            let (mut mask, mut bits, mut ran_out) = (0u8, 0u8, false);
            while x < end {
                let Some(color) = colors.next() else {
                    ran_out = true;
                    break;
                };
                mask |= msb_bit(x);
                if color.is_on() {
                    bits |= msb_bit(x);
                }
                x += 1;
                written += 1;
            }
            *byte = (*byte & !mask) | bits;
            if ran_out {
                break;
            }
        }
        written
    }

    fn read_pixel(row: &[u8], x: usize) -> Option<BinaryColor> {
        row.get(x / 8)
            .map(|byte| BinaryColor::from(byte & msb_bit(x) != 0))
    }

    fn write_pixel(row: &mut [u8], x: usize, color: BinaryColor) {
        if let Some(byte) = row.get_mut(x / 8) {
            apply(byte, msb_bit(x), color.is_on());
        }
    }
}
