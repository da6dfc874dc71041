//! Packed formats: several pixels to a byte, rows padded to whole bytes.

use core::ops::Range;

use embedded_graphics_core::pixelcolor::{
    raw::{RawU1, RawU2, RawU4},
    BinaryColor, Gray2, Gray4, IntoStorage,
};

use super::PixelFormat;

/// [`BinaryColor`] packed 8 pixels per byte, the leftmost pixel in the
/// most significant bit, `On` as 1; each row starts on a new byte, the
/// unused low bits of its last byte being padding that drawing never
/// changes. The layout of e-paper panels and embedded-graphics'
/// `Framebuffer<BinaryColor, RawU1, BigEndian, ..>`.
///
/// # Examples
///
/// ```
/// use embedded_graphics::pixelcolor::BinaryColor;
/// use embedded_raster::framebuffer::{buffer_size, BinaryMsb, Framebuffer};
/// use embedded_graphics::prelude::*;
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

/// [`Gray4`] packed 2 pixels per byte, the leftmost pixel in the high
/// nibble; each row starts on a new byte, the low nibble of an odd-width
/// row's last byte being padding that drawing never changes. The layout of
/// SSD1322 OLEDs and of embedded-graphics' `Framebuffer<Gray4, RawU4, ..>`.
///
/// # Examples
///
/// ```
/// use embedded_graphics::pixelcolor::Gray4;
/// use embedded_raster::framebuffer::{buffer_size, Framebuffer, Gray4Msb};
/// use embedded_graphics::prelude::*;
///
/// // 3 pixels per row: 2 bytes, the last nibble padding.
/// let mut fb = Framebuffer::<Gray4Msb, 3, 1, { buffer_size::<Gray4Msb>(3, 1) }>::new();
/// Pixel(Point::new(0, 0), Gray4::new(0xA)).draw(&mut fb)?;
/// Pixel(Point::new(2, 0), Gray4::new(0x5)).draw(&mut fb)?;
/// assert_eq!(fb.as_bytes(), [0xA0, 0x50]);
/// assert_eq!(fb.pixel(Point::new(2, 0)), Some(Gray4::new(0x5)));
/// # Ok::<(), core::convert::Infallible>(())
/// ```
///
/// The padding counts in the size, checked at compile time:
///
/// ```compile_fail
/// use embedded_raster::{framebuffer::Gray4Msb, Framebuffer};
///
/// let fb = Framebuffer::<Gray4Msb, 3, 2, 3>::new(); // needs 2 x 2 bytes
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Gray4Msb;

/// [`Gray4`] packed 2 pixels per byte, the leftmost pixel in the low
/// nibble; each row starts on a new byte, the high nibble of an odd-width
/// row's last byte being padding that drawing never changes. The layout of
/// SSD1327 OLEDs without nibble remapping.
///
/// # Examples
///
/// ```
/// use embedded_graphics::pixelcolor::Gray4;
/// use embedded_raster::framebuffer::{buffer_size, Framebuffer, Gray4Lsb};
/// use embedded_graphics::prelude::*;
///
/// let mut fb = Framebuffer::<Gray4Lsb, 3, 1, { buffer_size::<Gray4Lsb>(3, 1) }>::new();
/// Pixel(Point::new(0, 0), Gray4::new(0xA)).draw(&mut fb)?;
/// Pixel(Point::new(2, 0), Gray4::new(0x5)).draw(&mut fb)?;
/// assert_eq!(fb.as_bytes(), [0x0A, 0x05]);
/// assert_eq!(fb.pixel(Point::new(0, 0)), Some(Gray4::new(0xA)));
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Gray4Lsb;

/// [`Gray2`] packed 4 pixels per byte, the leftmost pixel in the top two
/// bits (7 and 6); each row starts on a new byte, the unused low bits of
/// its last byte being padding that drawing never changes. The layout of
/// embedded-graphics' `Framebuffer<Gray2, RawU2, ..>`.
///
/// # Examples
///
/// ```
/// use embedded_graphics::pixelcolor::Gray2;
/// use embedded_raster::framebuffer::{buffer_size, Framebuffer, Gray2Msb};
/// use embedded_graphics::prelude::*;
///
/// // 5 pixels per row: 2 bytes, the last 6 bits padding.
/// let mut fb = Framebuffer::<Gray2Msb, 5, 1, { buffer_size::<Gray2Msb>(5, 1) }>::new();
/// fb.clear(Gray2::new(0b10))?;
/// assert_eq!(fb.as_bytes(), [0b10_10_10_10, 0b10_00_00_00]);
/// assert_eq!(fb.pixel(Point::new(4, 0)), Some(Gray2::new(0b10)));
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Gray2Msb;

/// [`Gray2`] packed 4 pixels per byte, the leftmost pixel in the bottom
/// two bits (1 and 0); each row starts on a new byte, the unused high bits
/// of its last byte being padding that drawing never changes.
///
/// # Examples
///
/// ```
/// use embedded_graphics::pixelcolor::Gray2;
/// use embedded_raster::framebuffer::{buffer_size, Framebuffer, Gray2Lsb};
/// use embedded_graphics::prelude::*;
///
/// let mut fb = Framebuffer::<Gray2Lsb, 5, 1, { buffer_size::<Gray2Lsb>(5, 1) }>::new();
/// Pixel(Point::new(1, 0), Gray2::new(0b11)).draw(&mut fb)?;
/// Pixel(Point::new(4, 0), Gray2::new(0b01)).draw(&mut fb)?;
/// assert_eq!(fb.as_bytes(), [0b00_00_11_00, 0b00_00_00_01]);
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Gray2Lsb;

/// The row layout of `BITS`-bit pixels (1, 2 or 4), `8 / BITS` to a byte:
/// pixel `x` in slot `x % PER_BYTE` of byte `x / PER_BYTE`, slot 0 in the
/// most significant bits if `MSB_FIRST`, else in the least.
///
/// ```text
/// BITS 4, MSB_FIRST:   byte = [ slot 0 | slot 1 ]            bits 7..4, 3..0
/// BITS 4, LSB first:   byte = [ slot 1 | slot 0 ]
/// BITS 2, MSB_FIRST:   byte = [ slot 0 | slot 1 | slot 2 | slot 3 ]
/// ```
struct Packed<const BITS: u32, const MSB_FIRST: bool>;

impl<const BITS: u32, const MSB_FIRST: bool> Packed<BITS, MSB_FIRST> {
    /// Pixels per byte; `BITS` must be 1, 2 or 4 (checked at compile time).
    const PER_BYTE: usize = {
        assert!(BITS == 1 || BITS == 2 || BITS == 4);
        8 / BITS as usize
    };

    /// The largest pixel value, and the mask of slot bits at shift 0.
    const MAX: u8 = (1 << BITS) - 1;

    /// How far slot `k < PER_BYTE` is shifted up in its byte (at most 7).
    const fn shift(k: usize) -> u32 {
        // `k < 8 / BITS`, so `(k + 1) * BITS <= 8`.
        if MSB_FIRST {
            8 - (k as u32 + 1) * BITS
        } else {
            k as u32 * BITS
        }
    }

    /// The bits of slot `k` and of every later slot (pixels to its right).
    const fn from_slot(k: usize) -> u8 {
        if MSB_FIRST {
            0xFF >> (k as u32 * BITS)
        } else {
            0xFF << (k as u32 * BITS)
        }
    }

    /// The bits of slot `k` and of every earlier slot (pixels to its left).
    const fn to_slot(k: usize) -> u8 {
        if MSB_FIRST {
            0xFF << Self::shift(k)
        } else {
            0xFF >> (8 - (k as u32 + 1) * BITS)
        }
    }

    /// `value`'s low `BITS` in every slot of a byte: the byte of a run of
    /// pixels of one value.
    const fn splat(value: u8) -> u8 {
        (value & Self::MAX) * (0xFF / Self::MAX)
    }

    /// Sets pixels `xs` of `row` to `value`: masks the partial bytes at
    /// both ends and fills the whole bytes in between (`memset`). Writes
    /// nothing unless every pixel is in `row`.
    #[inline]
    fn fill_span(row: &mut [u8], xs: Range<usize>, value: u8) {
        let Some(last) = xs.end.checked_sub(1) else {
            return;
        };
        if xs.start > last {
            return;
        }
        let head = Self::from_slot(xs.start % Self::PER_BYTE);
        let tail = Self::to_slot(last % Self::PER_BYTE);
        let fill = Self::splat(value);
        match row.get_mut(xs.start / Self::PER_BYTE..=last / Self::PER_BYTE) {
            Some([only]) => set(only, head & tail, fill),
            Some([first, middle @ .., end]) => {
                set(first, head, fill);
                middle.fill(fill);
                set(end, tail, fill);
            }
            _ => {}
        }
    }

    /// Sets pixels `xs` of `row`, left to right, to values from `values`;
    /// gathers the pixels of each byte and writes the byte once. Returns
    /// how many it set.
    fn write_span(
        row: &mut [u8],
        xs: Range<usize>,
        values: &mut impl Iterator<Item = u8>,
    ) -> usize {
        let mut written = 0;
        let mut x = xs.start;
        while x < xs.end {
            let Some(byte) = row.get_mut(x / Self::PER_BYTE) else {
                break;
            };
            // Up to the end of this byte or of the span.
            let byte_end = (x - x % Self::PER_BYTE).saturating_add(Self::PER_BYTE);
            let end = xs.end.min(byte_end);
            let (mut mask, mut bits, mut ran_out) = (0u8, 0u8, false);
            while x < end {
                let Some(value) = values.next() else {
                    ran_out = true;
                    break;
                };
                let shift = Self::shift(x % Self::PER_BYTE);
                mask |= Self::MAX << shift;
                bits |= (value & Self::MAX) << shift;
                x += 1;
                written += 1;
            }
            set(byte, mask, bits);
            if ran_out {
                break;
            }
        }
        written
    }

    /// The value of pixel `x` of `row`, if it is in `row`.
    fn read_pixel(row: &[u8], x: usize) -> Option<u8> {
        let shift = Self::shift(x % Self::PER_BYTE);
        row.get(x / Self::PER_BYTE)
            .map(|byte| (byte >> shift) & Self::MAX)
    }

    /// Sets pixel `x` of `row` to `value`, if it is in `row`.
    #[inline]
    fn write_pixel(row: &mut [u8], x: usize, value: u8) {
        if let Some(byte) = row.get_mut(x / Self::PER_BYTE) {
            let shift = Self::shift(x % Self::PER_BYTE);
            set(byte, Self::MAX << shift, value << shift);
        }
    }
}

/// Sets the bits `mask` of `byte` to those of `bits`.
#[inline(always)]
fn set(byte: &mut u8, mask: u8, bits: u8) {
    *byte = (*byte & !mask) | (bits & mask);
}

/// Implements [`PixelFormat`] for a packed format through [`Packed`],
/// given how to encode a colour as its `$bits`-bit value and decode it.
macro_rules! packed_format {
    ($format:ty, $color:ty, $bits:literal, $msb_first:literal, $encode:expr, $decode:expr) => {
        impl PixelFormat for $format {
            type Color = $color;
            const BITS_PER_PIXEL: usize = $bits;

            #[inline]
            fn fill_span(row: &mut [u8], xs: Range<usize>, color: $color) {
                Packed::<$bits, $msb_first>::fill_span(row, xs, $encode(color));
            }

            fn write_span<I: Iterator<Item = $color>>(
                row: &mut [u8],
                xs: Range<usize>,
                colors: I,
            ) -> usize {
                Packed::<$bits, $msb_first>::write_span(row, xs, &mut colors.map($encode))
            }

            fn read_pixel(row: &[u8], x: usize) -> Option<$color> {
                Packed::<$bits, $msb_first>::read_pixel(row, x).map($decode)
            }

            #[inline]
            fn write_pixel(row: &mut [u8], x: usize, color: $color) {
                Packed::<$bits, $msb_first>::write_pixel(row, x, $encode(color));
            }
        }
    };
}

// embedded-graphics' raw values: `On` is 1, a grey its luma.
packed_format!(
    BinaryMsb,
    BinaryColor,
    1,
    true,
    |c: BinaryColor| c.into_storage(),
    |v| BinaryColor::from(RawU1::new(v))
);
packed_format!(Gray4Msb, Gray4, 4, true, |c: Gray4| c.into_storage(), |v| {
    Gray4::from(RawU4::new(v))
});
packed_format!(
    Gray4Lsb,
    Gray4,
    4,
    false,
    |c: Gray4| c.into_storage(),
    |v| Gray4::from(RawU4::new(v))
);
packed_format!(Gray2Msb, Gray2, 2, true, |c: Gray2| c.into_storage(), |v| {
    Gray2::from(RawU2::new(v))
});
packed_format!(
    Gray2Lsb,
    Gray2,
    2,
    false,
    |c: Gray2| c.into_storage(),
    |v| Gray2::from(RawU2::new(v))
);
