//! Error types.

use core::fmt;

/// A coordinate lies outside the 20.12 fixed-point range
/// `[-524288, 524288 - 1/4096]` pixels, or is not a finite number.
///
/// # Examples
///
/// ```
/// use embedded_raster::{CoordinateOutOfRange, Vertex};
///
/// assert_eq!(Vertex::try_from_num(1.0e9, 0.0), Err(CoordinateOutOfRange));
/// assert_eq!(Vertex::try_from_num(f32::NAN, 0.0), Err(CoordinateOutOfRange));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct CoordinateOutOfRange;

impl fmt::Display for CoordinateOutOfRange {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("coordinate out of range [-524288, 524288 - 1/4096]")
    }
}

impl core::error::Error for CoordinateOutOfRange {}
