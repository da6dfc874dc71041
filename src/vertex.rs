//! Subpixel vertices: 20.12 fixed-point positions.

use embedded_graphics_core::geometry::Point;
use fixed::{traits::ToFixed, types::I20F12};

use crate::error::CoordinateOutOfRange;

/// Number of fractional bits in a vertex coordinate.
pub const SUBPIXEL_BITS: u32 = 12;

/// One pixel in raw subpixel units (`1 << SUBPIXEL_BITS`).
pub(crate) const ONE: i64 = 1 << SUBPIXEL_BITS;

/// A position on the continuous drawing plane, in pixels, with 12 fractional
/// bits: each coordinate is an [`I20F12`], a signed 20.12 fixed-point number
/// (a multiple of 1/4096 in `[-524288, 524288 - 1/4096]`).
///
/// The plane's y axis points down. Pixel `(i, j)` covers the square
/// `[i, i + 1) x [j, j + 1)`; its centre is `(i + 1/2, j + 1/2)`. So the
/// vertex `(0, 0)` is the top-left *corner* of pixel `(0, 0)`, while the
/// [`Point`] `(0, 0)` (a pixel) converts to the vertex `(0.5, 0.5)`.
///
/// Every value of this type is in range, so everything built from vertices
/// (triangles, meshes) can be drawn without a range error.
///
/// # Examples
///
/// ```
/// use embedded_graphics::geometry::Point;
/// use embedded_raster::Vertex;
///
/// // From numbers: rounded to the nearest 1/4096, ties to even.
/// let v = Vertex::try_from_num(10.25, -3.0).unwrap();
/// assert_eq!(v.raw(), (10 * 4096 + 1024, -3 * 4096));
///
/// // From a pixel: its centre.
/// let c = Vertex::try_from(Point::new(2, 5)).unwrap();
/// assert_eq!(c, Vertex::try_from_num(2.5, 5.5).unwrap());
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Vertex {
    /// Horizontal position in pixels, growing to the right.
    pub x: I20F12,
    /// Vertical position in pixels, growing downwards.
    pub y: I20F12,
}

impl Vertex {
    /// Creates a vertex from two fixed-point coordinates. Infallible: every
    /// [`I20F12`] is in range.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::{I20F12, Vertex};
    ///
    /// let v = Vertex::new(I20F12::from_num(3), I20F12::from_bits(2048));
    /// assert_eq!(v.raw(), (3 * 4096, 2048));
    /// ```
    pub const fn new(x: I20F12, y: I20F12) -> Self {
        Self { x, y }
    }

    /// Creates a vertex from raw subpixel units (multiples of 1/4096 pixel).
    /// Infallible: every `i32` is a coordinate of the 20.12 range.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::Vertex;
    ///
    /// let v = Vertex::from_raw(4096 + 2048, 0);
    /// assert_eq!(v, Vertex::try_from_num(1.5, 0).unwrap());
    /// ```
    pub const fn from_raw(x: i32, y: i32) -> Self {
        Self {
            x: I20F12::from_bits(x),
            y: I20F12::from_bits(y),
        }
    }

    /// The raw subpixel coordinates `(x * 4096, y * 4096)`.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::Vertex;
    ///
    /// assert_eq!(Vertex::from_raw(-7, 9).raw(), (-7, 9));
    /// ```
    #[inline(always)]
    pub const fn raw(self) -> (i32, i32) {
        (self.x.to_bits(), self.y.to_bits())
    }

    /// Creates a vertex from any numbers `fixed` can convert (integers,
    /// floats, other fixed-point types), rounding to the nearest multiple of
    /// 1/4096 with ties to even.
    ///
    /// # Errors
    ///
    /// [`CoordinateOutOfRange`] if a rounded coordinate lies outside
    /// `[-524288, 524288 - 1/4096]`, or is NaN or infinite.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::Vertex;
    ///
    /// // 1/8192 is half a step: a tie, rounded to the even neighbour 0.
    /// assert_eq!(Vertex::try_from_num(1.0 / 8192.0, 0).unwrap().raw(), (0, 0));
    /// // 3/8192 lies between 1/4096 and 2/4096: a tie, rounded to 2/4096.
    /// assert_eq!(Vertex::try_from_num(3.0 / 8192.0, 0).unwrap().raw(), (2, 0));
    /// assert!(Vertex::try_from_num(524288, 0).is_err());
    /// ```
    pub fn try_from_num<X: ToFixed, Y: ToFixed>(x: X, y: Y) -> Result<Self, CoordinateOutOfRange> {
        Ok(Self {
            x: coordinate_from_num(x)?,
            y: coordinate_from_num(y)?,
        })
    }

    /// Parses two decimal coordinates such as `"-3.5"` or
    /// `"100.000244140625"`, exactly: the decimal value (with any number of
    /// digits) is rounded once to the nearest multiple of 1/4096, ties to
    /// even.
    ///
    /// # Errors
    ///
    /// [`ParseCoordinateError::Invalid`] if a string is not a decimal number
    /// (`nan`, `inf`, exponents and empty strings are not),
    /// [`ParseCoordinateError::OutOfRange`] if it rounds outside the 20.12
    /// range.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::{ParseCoordinateError, Vertex};
    ///
    /// let v = Vertex::parse("30.5", "4.25").unwrap();
    /// assert_eq!(v.raw(), (30 * 4096 + 2048, 4 * 4096 + 1024));
    /// assert_eq!(Vertex::parse("nan", "0"), Err(ParseCoordinateError::Invalid));
    /// assert_eq!(Vertex::parse("0", "524288"), Err(ParseCoordinateError::OutOfRange));
    /// ```
    pub fn parse(x: &str, y: &str) -> Result<Self, ParseCoordinateError> {
        Ok(Self {
            x: parse_coordinate(x)?,
            y: parse_coordinate(y)?,
        })
    }
}

/// Shown as raw subpixel units, e.g. `Vertex(10240/4096, -3/4096)`.
#[cfg(feature = "defmt")]
impl defmt::Format for Vertex {
    fn format(&self, f: defmt::Formatter<'_>) {
        let (x, y) = self.raw();
        defmt::write!(f, "Vertex({=i32}/4096, {=i32}/4096)", x, y);
    }
}

/// Converts a pixel to the vertex at its centre, `(x + 1/2, y + 1/2)`.
///
/// # Errors
///
/// [`CoordinateOutOfRange`] unless `-524288 <= x, y <= 524287`.
impl TryFrom<Point> for Vertex {
    type Error = CoordinateOutOfRange;

    fn try_from(p: Point) -> Result<Self, Self::Error> {
        let centre = |c: i32| {
            let raw = i64::from(c) * ONE + ONE / 2;
            i32::try_from(raw)
                .map(I20F12::from_bits)
                .map_err(|_| CoordinateOutOfRange)
        };
        Ok(Self {
            x: centre(p.x)?,
            y: centre(p.y)?,
        })
    }
}

fn coordinate_from_num<T: ToFixed>(v: T) -> Result<I20F12, CoordinateOutOfRange> {
    I20F12::checked_from_num(v).ok_or(CoordinateOutOfRange)
}

/// Why a decimal coordinate could not be parsed.
///
/// # Examples
///
/// ```
/// use embedded_raster::{ParseCoordinateError, Vertex};
///
/// assert_eq!(Vertex::parse("1e3", "0"), Err(ParseCoordinateError::Invalid));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[non_exhaustive]
pub enum ParseCoordinateError {
    /// The text is not a decimal number.
    Invalid,
    /// The number rounds to a value outside `[-524288, 524288 - 1/4096]`.
    OutOfRange,
}

impl core::fmt::Display for ParseCoordinateError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::Invalid => f.write_str("bad number"),
            Self::OutOfRange => CoordinateOutOfRange.fmt(f),
        }
    }
}

impl core::error::Error for ParseCoordinateError {}

fn parse_coordinate(s: &str) -> Result<I20F12, ParseCoordinateError> {
    let (negative, digits) = match s.as_bytes().first() {
        Some(b'-') => (true, &s[1..]),
        Some(b'+') => (false, &s[1..]),
        _ => (false, s),
    };
    let (int, frac) = digits.split_once('.').unwrap_or((digits, ""));
    let all_digits = |t: &str| t.bytes().all(|b| b.is_ascii_digit());
    if int.is_empty() && frac.is_empty() || !all_digits(int) || !all_digits(frac) {
        return Err(ParseCoordinateError::Invalid);
    }
    // Integer part, saturating far above the range (2^20 px).
    let whole = int
        .bytes()
        .fold(0i64, |acc, d| (acc * 10 + i64::from(d - b'0')).min(1 << 40));
    let magnitude = whole * ONE + round_fraction(frac);
    let raw = if negative { -magnitude } else { magnitude };
    i32::try_from(raw)
        .map(I20F12::from_bits)
        .map_err(|_| ParseCoordinateError::OutOfRange)
}

/// Rounds the decimal fraction `0.ddd...` to the nearest multiple of 1/4096,
/// ties to even, exactly: returns the numerator (0..=4096).
///
/// Multiplying the digit string by 8192 from its last digit up gives
/// `floor(f * 8192)` (the number of half-steps) as the final carry, and the
/// digits left behind say whether anything remains below it.
fn round_fraction(frac: &str) -> i64 {
    let mut carry = 0u32;
    let mut rest_nonzero = false;
    for d in frac.bytes().rev() {
        let t = u32::from(d - b'0') * 8192 + carry;
        rest_nonzero |= !t.is_multiple_of(10);
        carry = t / 10;
    }
    let (steps, half) = (i64::from(carry >> 1), carry & 1 == 1);
    let round_up = half && (rest_nonzero || steps % 2 == 1);
    steps + i64::from(round_up)
}
