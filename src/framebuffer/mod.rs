//! Owned, const-sized framebuffers.
//!
//! A [`Framebuffer`] is an array of bytes in a display's own format,
//! drawn on through embedded-graphics' [`DrawTarget`] and sent to the
//! display with [`as_bytes`](Framebuffer::as_bytes). Its size and format
//! are type parameters, so it needs no allocation and can live in a
//! `static`.
//!
//! # Formats
//!
//! Rows are stored top to bottom, each row left to right, with nothing
//! between rows; a row of `width` pixels takes [`row_size`]`(width)` bytes
//! and the whole buffer [`buffer_size`]`(width, height)`. Every byte is 0
//! in a new framebuffer: black, or `Off`.
//!
//! | format | colour | bytes per pixel | layout |
//! |---|---|---|---|
//! | [`Rgb565Le`] | `Rgb565` | 2 | low byte first |
//! | [`Rgb565Be`] | `Rgb565` | 2 | high byte first (SPI panels: ST7789, ILI9341, ...) |
//! | [`Bgr565Le`] | `Bgr565` | 2 | low byte first |
//! | [`Bgr565Be`] | `Bgr565` | 2 | high byte first (SPI panels in BGR order) |
//! | [`Rgb888Bytes`] | `Rgb888` | 3 | red, green, blue |
//! | [`Rgb666Bytes`] | `Rgb666` | 3 | red, green, blue, 6 bits each in the high bits of its byte (18-bit SPI: ILI9341, ST7796, ...) |
//! | [`Gray8Bytes`] | `Gray8` | 1 | luma |
//! | [`Gray4Msb`] | `Gray4` | 1/2 | 2 per byte, leftmost in the high nibble (SSD1322), rows padded to whole bytes |
//! | [`Gray4Lsb`] | `Gray4` | 1/2 | 2 per byte, leftmost in the low nibble (SSD1327), rows padded to whole bytes |
//! | [`Gray2Msb`] | `Gray2` | 1/4 | 4 per byte, leftmost in bits 7-6, rows padded to whole bytes |
//! | [`Gray2Lsb`] | `Gray2` | 1/4 | 4 per byte, leftmost in bits 1-0, rows padded to whole bytes |
//! | [`BinaryMsb`] | `BinaryColor` | 1/8 | 8 per byte, leftmost in bit 7, rows padded to whole bytes |
//!
//! Colours become bits through embedded-graphics' own raw values
//! ([`IntoStorage`](embedded_graphics_core::pixelcolor::IntoStorage)), so
//! every format but [`Rgb666Bytes`] and the `Lsb` ones stores the bytes
//! of embedded-graphics' `Framebuffer` of the same colour and byte order.
//!
//! An Rgb565 pixel is 16 bits, red in the top 5, then green in 6, then
//! blue in 5. Pixel `x` of a row takes bytes `2x` and `2x + 1`:
//!
//! ```text
//!            bit 15                                 bit 0
//! Rgb565     R4 R3 R2 R1 R0 G5 G4 G3 G2 G1 G0 B4 B3 B2 B1 B0
//!            '----- high byte -----' '----- low byte ------'
//!
//!            byte 2x                   byte 2x + 1
//! Rgb565Be   R4 R3 R2 R1 R0 G5 G4 G3   G2 G1 G0 B4 B3 B2 B1 B0
//! Rgb565Le   G2 G1 G0 B4 B3 B2 B1 B0   R4 R3 R2 R1 R0 G5 G4 G3
//!
//! e.g. Rgb565::RED = 0xF800:  Be [0xF8, 0x00],  Le [0x00, 0xF8]
//! ```
//!
//! Bgr565 is the same with red and blue swapped: blue in the top 5 bits
//! (`Bgr565::BLUE` = 0xF800). An [`Rgb666Bytes`] pixel takes bytes `3x`
//! to `3x + 2`, the low 2 bits of each 0 (and ignored when read):
//!
//! ```text
//!              byte 3x                  byte 3x + 1              byte 3x + 2
//! Rgb666Bytes  R5 R4 R3 R2 R1 R0 0 0    G5 G4 G3 G2 G1 G0 0 0    B5 B4 B3 B2 B1 B0 0 0
//! ```
//!
//! [`BinaryMsb`] packs pixel `x` of a row into bit `7 - x % 8` of the
//! row's byte `x / 8`, `On` as 1. A row of 10 pixels takes 2 bytes; the
//! low 6 bits of its second byte are padding, which drawing never changes:
//!
//! ```text
//!            byte 0                    byte 1
//! bit        7  6  5  4  3  2  1  0    7  6  5  4  3  2  1  0
//! pixel x    0  1  2  3  4  5  6  7    8  9  -  -  -  -  -  -
//! ```
//!
//! The grey formats pack the same way in 4-bit slots (2 pixels a byte) or
//! 2-bit slots (4 a byte), the pixel's luma as the slot's value, filling
//! each byte from its most significant end (`Msb`) or its least (`Lsb`).
//! A row of 3 pixels `a`, `b`, `c`, then padding `-`:
//!
//! ```text
//!            byte 0                    byte 1
//! bit        7  6  5  4  3  2  1  0    7  6  5  4  3  2  1  0
//! Gray4Msb   a3 a2 a1 a0 b3 b2 b1 b0   c3 c2 c1 c0 -  -  -  -
//! Gray4Lsb   b3 b2 b1 b0 a3 a2 a1 a0   -  -  -  -  c3 c2 c1 c0
//! Gray2Msb   a1 a0 b1 b0 c1 c0 -  -
//! Gray2Lsb   -  -  c1 c0 b1 b0 a1 a0
//! ```
//!
//! Other layouts can be added by implementing [`PixelFormat`].
//!
//! # Speed and clipping
//!
//! [`fill_solid`](DrawTarget::fill_solid),
//! [`fill_contiguous`](DrawTarget::fill_contiguous) and
//! [`clear`](DrawTarget::clear) clip the area once and then fill whole
//! byte slices per row (one slice for all rows when the area spans whole
//! rows without padding). Packed (1-, 2- and 4-bit) pixels: masked end
//! bytes and a `memset` of the repeated byte between; byte pixels: a
//! `memset`. 2- and 4-byte pixels: on a host (x86, x86-64, AArch64)
//! overlapping 16-byte blocks of the repeated pattern (8- or 4-byte ones
//! under 16 bytes); on a core that stores unaligned words (Cortex-M3,
//! M4, M7, M33) a few overlapping words around aligned runs of `strd`;
//! elsewhere (ARMv6-M, RISC-V) pixel by pixel under 16 pixels (2-byte
//! ones 4 to 15 as blocks of four halfwords) and aligned 32-bit words, 8
//! a step, from 16. 3-byte pixels: a `memset` when their
//! bytes are equal, else the pixel loop (which hosts vectorize) and, from
//! 16 pixels on the other cores, aligned words of the repeated pattern.
//! See the README, "Framebuffer formats". The bytes start on a 4-byte
//! boundary.
//! [`draw_iter`](DrawTarget::draw_iter) checks each pixel.
//! Whatever the coordinates and sizes, everything outside the framebuffer
//! is ignored, without overflow or panic.
//!
//! A framebuffer is also a [`SpanSink`]: shapes drawn with
//! [`SpanDrawable::draw_spans`](crate::SpanDrawable::draw_spans) write
//! their spans straight into the rows, already clipped, and 1-pixel lines
//! are walked through the bytes ([`PixelFormat::fill_line`]). A one-row
//! [`fill_solid`](DrawTarget::fill_solid), what
//! [`DrawTargetSink`](crate::DrawTargetSink) sends, takes the same path.
//!
//! # Examples
//!
//! ```
//! use embedded_graphics::{pixelcolor::{Rgb565, RgbColor}, prelude::*, primitives::Rectangle};
//! use embedded_raster::framebuffer::{buffer_size, Framebuffer, Rgb565Be};
//!
//! let mut fb = Framebuffer::<Rgb565Be, 320, 240, { buffer_size::<Rgb565Be>(320, 240) }>::new();
//! fb.clear(Rgb565::BLUE)?;
//! fb.fill_solid(&Rectangle::new(Point::new(-10, 100), Size::new(50, 20)), Rgb565::RED)?;
//! assert_eq!(fb.pixel(Point::new(39, 119)), Some(Rgb565::RED));
//! assert_eq!(fb.pixel(Point::new(40, 119)), Some(Rgb565::BLUE));
//! let bytes: &[u8] = fb.as_bytes(); // 153600 bytes, ready for the panel
//! assert_eq!(bytes.len(), 320 * 240 * 2);
//! # Ok::<(), core::convert::Infallible>(())
//! ```

mod format;
#[cfg(feature = "sim")]
mod png;

pub use format::{
    Bgr565Be, Bgr565Le, BinaryMsb, Gray2Lsb, Gray2Msb, Gray4Lsb, Gray4Msb, Gray8Bytes, PixelFormat,
    Rgb565Be, Rgb565Le, Rgb666Bytes, Rgb888Bytes,
};

use core::{convert::Infallible, fmt, marker::PhantomData, ops::Range};

use embedded_graphics_core::{
    draw_target::DrawTarget,
    geometry::{Dimensions, OriginDimensions, Point, Size},
    image::{GetPixel, ImageDrawable},
    primitives::Rectangle,
    Pixel,
};

use crate::{
    clip::{advance, clip_to, row_major_skips},
    line::LinePixels,
    raster::sink::SpanSink,
    span::Span,
};

/// Bytes a row of `width` pixels takes in format `F`:
/// `ceil(width * F::BITS_PER_PIXEL / 8)`.
///
/// # Panics
///
/// If the number of bits overflows `usize` (at compile time when used as a
/// const).
///
/// # Examples
///
/// ```
/// use embedded_raster::framebuffer::{row_size, BinaryMsb, Rgb888Bytes};
///
/// assert_eq!(row_size::<Rgb888Bytes>(10), 30);
/// assert_eq!(row_size::<BinaryMsb>(10), 2);
/// assert_eq!(row_size::<BinaryMsb>(16), 2);
/// ```
pub const fn row_size<F: PixelFormat>(width: usize) -> usize {
    match width.checked_mul(F::BITS_PER_PIXEL) {
        Some(bits) => bits.div_ceil(8),
        None => panic!("framebuffer row size overflows usize"),
    }
}

/// Bytes a framebuffer of `width` x `height` pixels takes in format `F`:
/// `height` rows of [`row_size`]`(width)` bytes. The `N` parameter of
/// [`Framebuffer`].
///
/// # Panics
///
/// If the size overflows `usize` (at compile time when used as a const).
///
/// # Examples
///
/// ```
/// use embedded_raster::framebuffer::{buffer_size, BinaryMsb, Gray4Msb, Gray8Bytes, Rgb565Be};
///
/// assert_eq!(buffer_size::<Rgb565Be>(320, 240), 153_600);
/// assert_eq!(buffer_size::<Gray8Bytes>(3, 2), 6);
/// assert_eq!(buffer_size::<BinaryMsb>(10, 3), 6); // each row padded to 2 bytes
/// assert_eq!(buffer_size::<Gray4Msb>(3, 2), 4); // each row padded to 2 bytes
/// assert_eq!(buffer_size::<Gray4Msb>(256, 64), 8192); // an SSD1322
/// ```
pub const fn buffer_size<F: PixelFormat>(width: usize, height: usize) -> usize {
    match row_size::<F>(width).checked_mul(height) {
        Some(size) => size,
        None => panic!("framebuffer size overflows usize"),
    }
}

/// An owned `W` x `H` framebuffer of `N` bytes in pixel format `F`, and a
/// [`DrawTarget`] for `F::Color`.
///
/// `N` must be [`buffer_size::<F>(W, H)`](buffer_size), which
/// [`new`](Self::new) checks at compile time. The byte layout is described
/// in the [module docs](self). Drawing outside the framebuffer is ignored;
/// see [Speed and clipping](self#speed-and-clipping).
///
/// `Debug` shows the format and dimensions, not the pixels; `==` compares
/// the bytes.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::BinaryColor, prelude::*, primitives::Rectangle};
/// use embedded_raster::{framebuffer::{buffer_size, BinaryMsb}, Framebuffer};
///
/// type Epaper = Framebuffer<BinaryMsb, 200, 200, { buffer_size::<BinaryMsb>(200, 200) }>;
///
/// let mut fb = Epaper::new();
/// fb.fill_solid(&Rectangle::new(Point::new(4, 0), Size::new(8, 2)), BinaryColor::On)?;
/// assert_eq!(fb.as_bytes()[..3], [0b0000_1111, 0b1111_0000, 0]);
/// assert_eq!(fb.size(), Size::new(200, 200));
/// # Ok::<(), core::convert::Infallible>(())
/// ```
pub struct Framebuffer<F, const W: usize, const H: usize, const N: usize> {
    data: Aligned<N>,
    format: PhantomData<F>,
}

/// The pixel bytes, starting on a 4-byte boundary so that rows of a
/// whole number of words can be filled with aligned word stores.
#[derive(Clone, Copy, PartialEq, Eq)]
#[repr(C, align(4))]
struct Aligned<const N: usize>([u8; N]);

impl<F: PixelFormat, const W: usize, const H: usize, const N: usize> Framebuffer<F, W, H, N> {
    /// Bytes per row.
    const STRIDE: usize = row_size::<F>(W);

    /// Whether rows have no padding bits, so that consecutive whole rows
    /// form one longer row.
    const UNPADDED: bool = match W.checked_mul(F::BITS_PER_PIXEL) {
        Some(bits) => bits % 8 == 0,
        None => false,
    };

    /// A framebuffer with every byte 0 (black, or `Off`, in the built-in
    /// formats). A `const fn`, so the framebuffer can be a `static`.
    ///
    /// It fails to compile unless `N` is
    /// [`buffer_size::<F>(W, H)`](buffer_size), and unless `W` and `H`
    /// are at most `i32::MAX` (embedded-graphics addresses pixels by `i32`
    /// coordinates: columns and rows past it could not be drawn).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
    /// use embedded_raster::{framebuffer::{buffer_size, Rgb565Le}, Framebuffer};
    ///
    /// static BLANK: Framebuffer<Rgb565Le, 8, 8, { buffer_size::<Rgb565Le>(8, 8) }> =
    ///     Framebuffer::new();
    /// assert_eq!(BLANK.pixel(Point::new(7, 7)), Some(Rgb565::BLACK));
    /// ```
    ///
    /// A wrong `N` is a compile error:
    ///
    /// ```compile_fail
    /// use embedded_raster::{framebuffer::Rgb565Le, Framebuffer};
    ///
    /// let fb = Framebuffer::<Rgb565Le, 8, 8, 64>::new(); // needs 128 bytes
    /// ```
    ///
    /// So is a side past `i32::MAX`, even with no pixels at all:
    ///
    /// ```compile_fail
    /// use embedded_raster::{framebuffer::Gray8Bytes, Framebuffer};
    ///
    /// let fb = Framebuffer::<Gray8Bytes, { 1 << 31 }, 0, 0>::new();
    /// ```
    pub const fn new() -> Self {
        const {
            assert!(
                F::BITS_PER_PIXEL > 0 && N == buffer_size::<F>(W, H),
                "Framebuffer<F, W, H, N> needs N == buffer_size::<F>(W, H)"
            );
            assert!(
                W as u64 <= i32::MAX as u64 && H as u64 <= i32::MAX as u64,
                "Framebuffer<F, W, H, N> needs W and H at most i32::MAX"
            );
        }
        Self {
            data: Aligned([0; N]),
            format: PhantomData,
        }
    }

    /// The pixel bytes, rows top to bottom, ready to send to a display.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
    /// use embedded_raster::{framebuffer::{buffer_size, Gray8Bytes}, Framebuffer};
    ///
    /// let mut fb = Framebuffer::<Gray8Bytes, 2, 2, { buffer_size::<Gray8Bytes>(2, 2) }>::new();
    /// Pixel(Point::new(1, 0), Gray8::new(7)).draw(&mut fb)?;
    /// assert_eq!(fb.as_bytes(), [0, 7, 0, 0]);
    /// # Ok::<(), core::convert::Infallible>(())
    /// ```
    pub const fn as_bytes(&self) -> &[u8] {
        &self.data.0
    }

    /// The pixel bytes, for writing directly, e.g. to load an image.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
    /// use embedded_raster::{framebuffer::{buffer_size, Gray8Bytes}, Framebuffer};
    ///
    /// let mut fb = Framebuffer::<Gray8Bytes, 2, 2, { buffer_size::<Gray8Bytes>(2, 2) }>::new();
    /// fb.as_bytes_mut()[3] = 9;
    /// assert_eq!(fb.pixel(Point::new(1, 1)), Some(Gray8::new(9)));
    /// ```
    pub const fn as_bytes_mut(&mut self) -> &mut [u8] {
        &mut self.data.0
    }

    /// The colour of the pixel at `p`, or `None` if `p` is outside.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::BinaryColor, prelude::*};
    /// use embedded_raster::{framebuffer::{buffer_size, BinaryMsb}, Framebuffer};
    ///
    /// let mut fb = Framebuffer::<BinaryMsb, 10, 4, { buffer_size::<BinaryMsb>(10, 4) }>::new();
    /// Pixel(Point::new(9, 3), BinaryColor::On).draw(&mut fb)?;
    /// assert_eq!(fb.pixel(Point::new(9, 3)), Some(BinaryColor::On));
    /// assert_eq!(fb.pixel(Point::new(8, 3)), Some(BinaryColor::Off));
    /// assert_eq!(fb.pixel(Point::new(10, 3)), None);
    /// assert_eq!(fb.pixel(Point::new(-1, 0)), None);
    /// # Ok::<(), core::convert::Infallible>(())
    /// ```
    pub fn pixel(&self, p: Point) -> Option<F::Color> {
        let (x, y) = Self::locate(p)?;
        F::read_pixel(self.row(y)?, x)
    }

    /// The column and row of `p`, if it is inside.
    fn locate(p: Point) -> Option<(usize, usize)> {
        let x = usize::try_from(p.x).ok().filter(|&x| x < W)?;
        let y = usize::try_from(p.y).ok().filter(|&y| y < H)?;
        Some((x, y))
    }

    /// The bytes of row `y`, or `None` if there is no such row.
    fn row(&self, y: usize) -> Option<&[u8]> {
        let start = y.checked_mul(Self::STRIDE)?;
        self.data.0.get(start..start.checked_add(Self::STRIDE)?)
    }

    /// The pixels of `pixels` inside the framebuffer, one by one through
    /// [`draw_iter`](DrawTarget::draw_iter), which drops the others: for
    /// lines not known to lie in the bounds (see
    /// [`SpanSink::fill_line`](SpanSink::fill_line)), which no shape of
    /// the crate sends. Pixel by pixel rather than run by run through the
    /// rectangle fill, which firmware drawing lines would otherwise link
    /// (Cortex-M4 at opt-level "s": 2,588 bytes more for 1-pixel lines,
    /// `bash .ci/codesize`).
    #[inline(never)]
    fn fill_line_clipped(&mut self, pixels: LinePixels, color: F::Color) -> Result<(), Infallible> {
        self.draw_iter(pixels.map(|p| Pixel(p, color)))
    }

    /// [`fill_solid`](DrawTarget::fill_solid) of a rectangle of any
    /// height, clipped.
    #[inline(never)]
    fn fill_rectangle(&mut self, area: &Rectangle, color: F::Color) {
        if let Some((xs, ys)) = clip_to(area, &self.bounding_box()) {
            let (rows, span) = self.rows_mut(xs, ys, true);
            F::fill_rows(rows, span, color);
        }
    }

    /// The bytes of `area`'s row and its columns, if `area` is one row
    /// lying wholly inside the buffer.
    #[inline]
    fn row_inside(&mut self, area: &Rectangle) -> Option<(&mut [u8], Range<usize>)> {
        if area.size.height != 1 {
            return None;
        }
        // A negative coordinate, read as `u32`, is 2^31 or more: past `W`
        // and `H` (at most `i32::MAX`, see `new`), so each is tested once,
        // as in `fill_span`; an end past `usize` saturates, past `W` too.
        let index = |v: u32| usize::try_from(v).unwrap_or(usize::MAX);
        let y = index(area.top_left.y as u32);
        let x = index(area.top_left.x as u32);
        let end = x.saturating_add(index(area.size.width));
        if y >= H || end > W {
            return None;
        }
        // y < H: the row lies within the buffer's H rows of STRIDE bytes.
        let stride = Self::STRIDE;
        let row = self.data.0.get_mut(y * stride..(y + 1) * stride)?;
        Some((row, x..end))
    }

    /// Rows `ys` (within `0..=H`, else none) as byte slices, and the
    /// pixels `xs` of each to draw.
    ///
    /// With `merge`, if `xs` is every column and rows have no padding, all
    /// rows come as one slice holding one long row, and the pixel range
    /// covers them all.
    ///
    /// The byte offsets are not checked multiplications: every framebuffer
    /// holds `N = H * STRIDE` bytes (see [`new`](Self::new)), so `ys.end *
    /// STRIDE <= N` cannot overflow. On ARMv6-M a checked `usize`
    /// multiplication is a call to the library's 64-bit multiply (the
    /// core has no 32 x 32 -> 64-bit one); and there the rows are split off
    /// one by one ([`rows_of`]). Measured with `.ci/icount`: on the
    /// Cortex-M4, 200 x 200 rectangles 22,840 → 22,822 instructions, 16 x
    /// 16 ones 56,462 → 55,310 for the batch of 64; on ARMv6-M, 4 x 4 ones
    /// 41,682 → 32,214.
    fn rows_mut(
        &mut self,
        xs: Range<usize>,
        ys: Range<usize>,
        merge: bool,
    ) -> (RowsOf<'_>, Range<usize>) {
        let stride = Self::STRIDE;
        let bytes = match ys.start <= ys.end && ys.end <= H {
            true => self
                .data
                .0
                .get_mut(ys.start * stride..ys.end * stride)
                .unwrap_or_default(),
            false => Default::default(),
        };
        let whole_rows = merge && Self::UNPADDED && xs.start == 0 && xs.end == W;
        if whole_rows && !bytes.is_empty() {
            // `ys.len() * W` pixels in `ys.len() * STRIDE` whole bytes: no
            // more pixels than bytes for pixels of a byte or more, so the
            // product is at most `N` then; checked for smaller pixels.
            let pixels = match F::BITS_PER_PIXEL >= 8 {
                true => Some(ys.len() * W),
                false => ys.len().checked_mul(W),
            };
            if let Some(pixels) = pixels {
                let len = bytes.len();
                return (rows_of(bytes, len), 0..pixels);
            }
        }
        (rows_of(bytes, stride), xs)
    }
}

/// The iterator of [`rows_of`].
#[cfg(software_division)]
type RowsOf<'a> = Rows<'a>;
#[cfg(not(software_division))]
type RowsOf<'a> = core::slice::ChunksExactMut<'a, u8>;

/// The rows of `len` bytes of `bytes`, top to bottom (a last piece
/// shorter than `len` is not a row).
///
/// `chunks_exact_mut`, except on cores that divide in software
/// (`software_division`, set by the build script for ARMv6-M), where it
/// would divide the slice's length by `len` in a library call: there
/// [`Rows`] splits the rows off one by one, with no division (`.ci/icount`
/// on ARMv6-M: 4 x 4 rectangles 32,214 → 26,842 instructions for the
/// batch of 64). On the Cortex-M4 the split rows cost instructions
/// instead (200 x 200 rectangles 22,822 → 23,831, 16 x 16 ones 55,310 →
/// 59,982).
#[inline(always)]
fn rows_of(bytes: &mut [u8], len: usize) -> RowsOf<'_> {
    #[cfg(software_division)]
    return Rows { rest: bytes, len };
    #[cfg(not(software_division))]
    bytes.chunks_exact_mut(len.max(1))
}

/// Consecutive `len`-byte rows of a slice, top to bottom (a last piece
/// shorter than `len` is not a row): `chunks_exact_mut` without its
/// division of the slice's length by `len`.
#[cfg_attr(not(software_division), allow(dead_code))]
struct Rows<'a> {
    rest: &'a mut [u8],
    len: usize,
}

impl<'a> Iterator for Rows<'a> {
    type Item = &'a mut [u8];

    #[inline]
    fn next(&mut self) -> Option<&'a mut [u8]> {
        if self.len == 0 {
            return None;
        }
        let (row, rest) = core::mem::take(&mut self.rest).split_at_mut_checked(self.len)?;
        self.rest = rest;
        Some(row)
    }
}

impl<F: PixelFormat, const W: usize, const H: usize, const N: usize> DrawTarget
    for Framebuffer<F, W, H, N>
{
    type Color = F::Color;
    type Error = Infallible;

    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), Infallible>
    where
        I: IntoIterator<Item = Pixel<F::Color>>,
    {
        // One bounds test per coordinate and one store: the bytes from the
        // pixel's row on, so the format's own check is on the same slice.
        let data = &mut self.data.0[..];
        for Pixel(p, color) in pixels {
            if let Some((x, y)) = Self::locate(p) {
                // `y < H`, so `y * STRIDE < N`: the product cannot overflow.
                if let Some(row) = data.get_mut(y * Self::STRIDE..) {
                    F::write_pixel(row, x, color);
                }
            }
        }
        Ok(())
    }

    /// Writes the colours that fall inside, row by row, skipping the others
    /// with [`Iterator::nth`], and stops after the last pixel inside.
    fn fill_contiguous<I>(&mut self, area: &Rectangle, colors: I) -> Result<(), Infallible>
    where
        I: IntoIterator<Item = F::Color>,
    {
        // One row inside the buffer, as the shaded triangles' spans come:
        // written into it with no clipping.
        if let Some((row, xs)) = self.row_inside(area) {
            F::write_span(row, xs, colors.into_iter());
            return Ok(());
        }
        let bounds = self.bounding_box();
        let (Some((xs, ys)), Some((skip, gap))) =
            (clip_to(area, &bounds), row_major_skips(area, &bounds))
        else {
            return Ok(());
        };
        let mut colors = colors.into_iter();
        let (rows, span) = self.rows_mut(xs, ys, gap == 0);
        let mut pending = skip;
        for row in rows {
            if !advance(&mut colors, pending)
                || F::write_span(row, span.clone(), &mut colors) < span.len()
            {
                break;
            }
            pending = gap;
        }
        Ok(())
    }

    /// Inlined, so that a span from [`DrawTargetSink`](crate::DrawTargetSink) (one row) is
    /// filled where it is made, as through the framebuffer's own
    /// [`SpanSink`]; taller rectangles go to an out-of-line fill.
    // Inlined on hosts into the triangle walks' row loop, as
    // `fill_span` (see `raster::walk::by_numbers`).
    #[cfg_attr(not(target_arch = "arm"), inline(always))]
    #[cfg_attr(target_arch = "arm", inline)]
    fn fill_solid(&mut self, area: &Rectangle, color: F::Color) -> Result<(), Infallible> {
        // One row inside the buffer, as `DrawTargetSink` sends spans (it
        // has clipped them to the bounds): filled with no clipping. x86-64,
        // random triangles through `draw`, instructions counted by
        // callgrind: small 1,223 a triangle → 1,177, medium 4,153 →
        // 3,807, large 14,777 → 13,540 (against clamping the row first
        // and handing it to `fill_span`, as the other rows still are
        // below). On 64-bit targets only: inlined wherever a span reaches
        // `fill_solid`, it took 1.2 KB more of the framebuffer's code in
        // `.ci/codesize`'s whole Cortex-M4 firmware at "s" (3.8 KB on
        // ARMv6-M; 1.5 KB and 6.5 KB at opt-level 3).
        if cfg!(target_pointer_width = "64") {
            if let Some((row, xs)) = self.row_inside(area) {
                F::fill_span(row, xs, color);
                return Ok(());
            }
        }
        if area.size.height == 1 {
            // One row, as `DrawTargetSink` sends spans: clipped as a span.
            // The row's columns inside `0..W`: both ends lie within
            // `i32::MIN..=W`, so they fit `i32` (`W <= i32::MAX`); the span
            // sink drops the row if it is outside or empty.
            let (x, width) = (i64::from(area.top_left.x), i64::from(area.size.width));
            let x0 = x.max(0);
            let x1 = (x + width).min(i64::try_from(W).unwrap_or(i64::MAX));
            let y = area.top_left.y;
            if let (Ok(x_start), Ok(x_end)) = (i32::try_from(x0), i32::try_from(x1)) {
                SpanSink::fill_span(self, Span { y, x_start, x_end }, color)?;
            }
            return Ok(());
        }
        self.fill_rectangle(area, color);
        Ok(())
    }

    fn clear(&mut self, color: F::Color) -> Result<(), Infallible> {
        // Unpadded rows come as one long row: one span.
        let (rows, span) = self.rows_mut(0..W, 0..H, true);
        for row in rows {
            F::fill_span(row, span.clone(), color);
        }
        Ok(())
    }
}

/// Spans go straight into the rows: no clipping (the rasterizers have
/// clipped to [`bounds`](SpanSink::bounds)) and no conversion beyond the
/// byte offsets, each checked, so a span outside is ignored, never a
/// panic.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
/// use embedded_raster::{framebuffer::{buffer_size, Gray8Bytes}, Framebuffer, Span, SpanSink};
///
/// let mut fb = Framebuffer::<Gray8Bytes, 4, 2, { buffer_size::<Gray8Bytes>(4, 2) }>::new();
/// fb.fill_span(Span { y: 1, x_start: 1, x_end: 3 }, Gray8::new(9))?;
/// fb.fill_column(Point::new(0, 0), 2, Gray8::new(5))?;
/// assert_eq!(fb.as_bytes(), [5, 0, 0, 0, 5, 9, 9, 0]);
/// # Ok::<(), core::convert::Infallible>(())
/// ```
impl<F: PixelFormat, const W: usize, const H: usize, const N: usize> SpanSink<F::Color>
    for Framebuffer<F, W, H, N>
{
    type Error = Infallible;

    fn bounds(&self) -> Rectangle {
        Rectangle::new(Point::zero(), self.size())
    }

    /// `true`: a pixel holds the last colour written to it.
    #[inline(always)]
    fn overdraw_is_invisible(&self) -> bool {
        true
    }

    // Inlined on hosts into the triangle walks' row loop (see
    // `raster::walk::by_numbers`).
    #[cfg_attr(not(target_arch = "arm"), inline(always))]
    #[cfg_attr(target_arch = "arm", inline)]
    fn fill_span(&mut self, span: Span, color: F::Color) -> Result<(), Infallible> {
        // A negative coordinate, read as `u32`, is 2^31 or more: past every
        // bound below (`W` and `H` are at most `i32::MAX`, see `new`), so
        // each coordinate is tested once, not for its sign apart. x86-64,
        // random triangles drawn by `draw_spans`, instructions counted by
        // callgrind: small 1,304 a triangle → 1,229, medium 4,287 → 3,998,
        // large 14,512 → 13,800 against `usize::try_from` with no test of
        // `x1` against `W` (the cast alone, without that test: small
        // 1,266; `u32::try_from(v).unwrap_or(u32::MAX)` in its place: small
        // 1,390). Cortex-M4 (`.ci/icount`): 240 px 1.48 → 1.42
        // instructions a pixel.
        let index = |v: i32| usize::try_from(v as u32).unwrap_or(usize::MAX);
        let (y, x0, x1) = (index(span.y), index(span.x_start), index(span.x_end));
        // On 32-bit ARM the columns' order is tested here as well (the
        // format's slice test rejects a reversed span either way): the byte
        // offsets then cannot overflow and their sign test goes (Cortex-M4,
        // `.ci/icount`: 16 px triangles 1,529 → 1,476 instructions, the
        // built-in scene 610,426 → 601,066). On x86-64 the same test cost
        // instructions (callgrind, small 1,229 → 1,266).
        let ordered = !cfg!(target_arch = "arm") || x0 <= x1;
        // Its own row only: a span past the row's last pixel (a caller
        // breaking the sink's contract) is dropped, neither wrapped into the
        // next row nor written into the row's padding bits. `y < H`, so `y *
        // STRIDE + STRIDE <= N`: no overflow.
        let row = (y < H && ordered && x1 <= W).then(|| y * Self::STRIDE);
        if let Some(row) = row.and_then(|start| self.data.0.get_mut(start..start + Self::STRIDE)) {
            F::fill_span(row, x0..x1, color);
        }
        Ok(())
    }

    /// Clipped to the bounds: rows above the first are skipped, and a
    /// column left or right of the pixels (in a packed format's padding
    /// bits, say) is not drawn.
    fn fill_column(&mut self, top: Point, len: u32, color: F::Color) -> Result<(), Infallible> {
        // `W` and `H` are at most `i32::MAX` (see `new`).
        let (x, y) = (i64::from(top.x), i64::from(top.y));
        let (from, to) = (y.max(0), (y + i64::from(len)).min(H as i64));
        if let (true, Ok(x), Ok(from), Ok(rows)) = (
            x < W as i64,
            usize::try_from(x),
            usize::try_from(from),
            usize::try_from(to - from),
        ) {
            let stride = Self::STRIDE.max(1);
            for row in self.data.0.chunks_exact_mut(stride).skip(from).take(rows) {
                F::write_pixel(row, x, color);
            }
        }
        Ok(())
    }

    fn fill_rect(&mut self, area: &Rectangle, color: F::Color) -> Result<(), Infallible> {
        self.fill_solid(area, color)
    }

    /// Lines with long runs (axis-aligned ones, and shallow ones under one
    /// step down per four pixels) go as spans and columns; the others are
    /// walked pixel by pixel through the bytes
    /// ([`PixelFormat::fill_line`]).
    ///
    /// A line listed in a clip larger than the bounds (by a caller who did
    /// not clip it to them) goes pixel by pixel, each outside the bounds
    /// dropped: nothing is written outside the pixels, in a packed
    /// format's padding or the next row, at the cost of every pixel of the
    /// line.
    fn fill_line(&mut self, pixels: LinePixels, color: F::Color) -> Result<(), Infallible> {
        // `W` and `H` are at most `i32::MAX` (see `new`).
        let last = |n: usize| i32::try_from(n).unwrap_or(i32::MAX) - 1;
        if !pixels.known_inside((0, last(W)), (0, last(H))) {
            return self.fill_line_clipped(pixels, color);
        }
        if pixels.has_long_runs() {
            return pixels.for_each_run(|run| {
                if run.vertical {
                    return self.fill_column(run.start, run.len, color);
                }
                // Always a span: a row run inside the bounds ends by
                // column `W <= i32::MAX` (see `new`). Not sent to
                // `fill_rect` otherwise, as `fill_run` does for other
                // sinks: that would link the rectangle fill (1,250 bytes
                // on a Cortex-M4 at opt-level "s") into every firmware
                // that draws lines.
                match run.span() {
                    Some(span) => self.fill_span(span, color),
                    None => Ok(()),
                }
            });
        }
        F::fill_line(&mut self.data.0, Self::STRIDE, pixels, color);
        Ok(())
    }
}

impl<F, const W: usize, const H: usize, const N: usize> OriginDimensions
    for Framebuffer<F, W, H, N>
{
    fn size(&self) -> Size {
        let side = |n: usize| u32::try_from(n).unwrap_or(u32::MAX);
        Size::new(side(W), side(H))
    }
}

/// The colour of a pixel, as embedded-graphics' image and sprite code asks
/// for it: [`Framebuffer::pixel`].
///
/// # Examples
///
/// ```
/// use embedded_graphics::{image::GetPixel, pixelcolor::Gray8, prelude::*};
/// use embedded_raster::{framebuffer::{buffer_size, Gray8Bytes}, Framebuffer};
///
/// fn brightest<T: GetPixel<Color = Gray8>>(image: &T, points: &[Point]) -> Option<Gray8> {
///     points.iter().filter_map(|&p| image.pixel(p)).max_by_key(|c| c.luma())
/// }
///
/// let mut fb = Framebuffer::<Gray8Bytes, 4, 4, { buffer_size::<Gray8Bytes>(4, 4) }>::new();
/// Pixel(Point::new(2, 1), Gray8::new(200)).draw(&mut fb)?;
/// assert_eq!(brightest(&fb, &[Point::new(0, 0), Point::new(2, 1), Point::new(9, 9)]), Some(Gray8::new(200)));
/// # Ok::<(), core::convert::Infallible>(())
/// ```
impl<F: PixelFormat, const W: usize, const H: usize, const N: usize> GetPixel
    for Framebuffer<F, W, H, N>
{
    type Color = F::Color;

    fn pixel(&self, p: Point) -> Option<F::Color> {
        Framebuffer::pixel(self, p)
    }
}

/// The framebuffer as an embedded-graphics image: `Image::new(&fb, at)`
/// draws it onto another target (a display driver, a larger framebuffer)
/// with one `fill_contiguous` of its pixels, or a part of it with
/// `Image::new(&fb.sub_image(&area), at)`.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{image::Image, pixelcolor::Gray8, prelude::*, primitives::Rectangle};
/// use embedded_raster::{framebuffer::{buffer_size, Gray8Bytes}, Framebuffer};
///
/// let mut sprite = Framebuffer::<Gray8Bytes, 4, 2, { buffer_size::<Gray8Bytes>(4, 2) }>::new();
/// Pixel(Point::new(3, 1), Gray8::new(9)).draw(&mut sprite)?;
///
/// let mut screen = Framebuffer::<Gray8Bytes, 8, 8, { buffer_size::<Gray8Bytes>(8, 8) }>::new();
/// Image::new(&sprite, Point::new(2, 5)).draw(&mut screen)?;
/// assert_eq!(screen.pixel(Point::new(5, 6)), Some(Gray8::new(9)));
///
/// let corner = sprite.sub_image(&Rectangle::new(Point::new(2, 1), Size::new(2, 1)));
/// Image::new(&corner, Point::new(0, 0)).draw(&mut screen)?;
/// assert_eq!(screen.pixel(Point::new(1, 0)), Some(Gray8::new(9)));
/// # Ok::<(), core::convert::Infallible>(())
/// ```
impl<F: PixelFormat, const W: usize, const H: usize, const N: usize> ImageDrawable
    for Framebuffer<F, W, H, N>
{
    type Color = F::Color;

    fn draw<D: DrawTarget<Color = F::Color>>(&self, target: &mut D) -> Result<(), D::Error> {
        self.draw_sub_image(target, &self.bounding_box())
    }

    /// Draws the pixels of `area` (in the framebuffer's coordinates) with
    /// `area`'s top-left corner at the target's origin; the part of `area`
    /// outside the framebuffer is not drawn.
    fn draw_sub_image<D: DrawTarget<Color = F::Color>>(
        &self,
        target: &mut D,
        area: &Rectangle,
    ) -> Result<(), D::Error> {
        let Some((xs, ys)) = clip_to(area, &self.bounding_box()) else {
            return Ok(());
        };
        // Where the visible part lands on the target: past `i32` (an area
        // starting more than 2^31 px before the framebuffer) is nowhere.
        let offset = |start: usize, corner: i32| {
            let start = i64::try_from(start).ok()?;
            i32::try_from(start - i64::from(corner)).ok()
        };
        let (Some(x), Some(y)) = (
            offset(xs.start, area.top_left.x),
            offset(ys.start, area.top_left.y),
        ) else {
            return Ok(());
        };
        let side = |n: usize| u32::try_from(n).unwrap_or(u32::MAX);
        let visible = Rectangle::new(Point::new(x, y), Size::new(side(xs.len()), side(ys.len())));
        let rows = ys.filter_map(|y| self.row(y));
        // Every pixel of `xs` is in its row, so no colour is skipped.
        let colors = rows.flat_map(|row| xs.clone().filter_map(move |x| F::read_pixel(row, x)));
        target.fill_contiguous(&visible, colors)
    }
}

/// Same as [`Framebuffer::new`].
///
/// # Examples
///
/// ```
/// use embedded_raster::{framebuffer::{buffer_size, Gray8Bytes}, Framebuffer};
///
/// let fb: Framebuffer<Gray8Bytes, 4, 4, { buffer_size::<Gray8Bytes>(4, 4) }> = Default::default();
/// assert_eq!(fb.as_bytes(), [0; 16]);
/// ```
impl<F: PixelFormat, const W: usize, const H: usize, const N: usize> Default
    for Framebuffer<F, W, H, N>
{
    fn default() -> Self {
        Self::new()
    }
}

impl<F, const W: usize, const H: usize, const N: usize> Clone for Framebuffer<F, W, H, N> {
    fn clone(&self) -> Self {
        Self {
            data: self.data,
            format: PhantomData,
        }
    }
}

impl<F, const W: usize, const H: usize, const N: usize> PartialEq for Framebuffer<F, W, H, N> {
    fn eq(&self, other: &Self) -> bool {
        self.data == other.data
    }
}

impl<F, const W: usize, const H: usize, const N: usize> Eq for Framebuffer<F, W, H, N> {}

/// Like `Debug`: the format and dimensions, not the pixels.
#[cfg(feature = "defmt")]
impl<F: defmt::Format + Default, const W: usize, const H: usize, const N: usize> defmt::Format
    for Framebuffer<F, W, H, N>
{
    fn format(&self, f: defmt::Formatter<'_>) {
        defmt::write!(
            f,
            "Framebuffer {{ format: {}, width: {=usize}, height: {=usize}, bytes: {=usize} }}",
            F::default(),
            W,
            H,
            N
        );
    }
}

impl<F, const W: usize, const H: usize, const N: usize> fmt::Debug for Framebuffer<F, W, H, N> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Framebuffer")
            .field("format", &core::any::type_name::<F>())
            .field("width", &W)
            .field("height", &H)
            .field("bytes", &N)
            .finish_non_exhaustive()
    }
}

#[cfg(test)]
mod tests {
    use std::vec::Vec;

    use super::Rows;

    /// [`Rows`], which ARMv6-M builds iterate in place of
    /// `chunks_exact_mut`, gives the same rows: slices of every length up
    /// to 40 bytes cut into rows of 0 to 9 bytes (none for 0).
    #[test]
    fn rows_are_the_exact_chunks() {
        for n in 0..40u8 {
            for len in 0..10 {
                let mut bytes: Vec<u8> = (0..n).collect();
                let want: Vec<Vec<u8>> = match len {
                    0 => Vec::new(),
                    _ => bytes.chunks_exact(len).map(<[u8]>::to_vec).collect(),
                };
                let rows = Rows {
                    rest: &mut bytes,
                    len,
                };
                let got: Vec<Vec<u8>> = rows.map(|row| row.to_vec()).collect();
                assert_eq!(got, want, "{n} bytes, rows of {len}");
            }
        }
    }
}
