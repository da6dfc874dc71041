//! Horizontal spans: what every filled shape is rasterized into.

use embedded_graphics_core::{
    geometry::{Point, Size},
    primitives::Rectangle,
};

/// A run of pixels `x_start..x_end` on row `y` (half-open: `x_end` is not
/// lit). Rasterizers only produce non-empty spans (`x_start < x_end`).
///
/// Any `i32` values are valid: a span with `x_end <= x_start` is empty,
/// and [`len`](Self::len) (at most `2^32 - 1`) cannot overflow.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{geometry::{Point, Size}, primitives::Rectangle};
/// use embedded_raster::Span;
///
/// let span = Span { y: 3, x_start: 2, x_end: 6 };
/// assert_eq!(span.len(), 4);
/// assert_eq!(span.rect(), Rectangle::new(Point::new(2, 3), Size::new(4, 1)));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Span {
    /// Row.
    pub y: i32,
    /// First lit column.
    pub x_start: i32,
    /// One past the last lit column.
    pub x_end: i32,
}

impl Span {
    /// Number of pixels in the span (0 if `x_end <= x_start`).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::Span;
    ///
    /// assert_eq!(Span { y: 0, x_start: -2, x_end: 3 }.len(), 5);
    /// ```
    pub fn len(&self) -> u32 {
        // `abs_diff` of two `i32`s fits `u32`; times 0 or 1: no overflow.
        self.x_end.abs_diff(self.x_start) * u32::from(self.x_end > self.x_start)
    }

    /// Whether the span lights no pixel.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::Span;
    ///
    /// assert!(Span { y: 0, x_start: 4, x_end: 4 }.is_empty());
    /// ```
    pub fn is_empty(&self) -> bool {
        self.x_end <= self.x_start
    }

    /// The span `x_start..x_end` on row `y`, from the wide integers a
    /// rasterizer clips in: `None` if it is empty or does not fit `i32`
    /// (which a span inside a clip rectangle always does).
    pub(crate) fn from_wide(y: i64, x_start: i64, x_end: i64) -> Option<Self> {
        if x_start >= x_end {
            return None;
        }
        Some(Self {
            y: i32::try_from(y).ok()?,
            x_start: i32::try_from(x_start).ok()?,
            x_end: i32::try_from(x_end).ok()?,
        })
    }

    /// The span as a one-row rectangle, ready for `DrawTarget::fill_solid`.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::geometry::{Point, Size};
    /// use embedded_raster::Span;
    ///
    /// let r = Span { y: 1, x_start: 0, x_end: 2 }.rect();
    /// assert_eq!((r.top_left, r.size), (Point::new(0, 1), Size::new(2, 1)));
    /// ```
    pub fn rect(&self) -> Rectangle {
        Rectangle::new(Point::new(self.x_start, self.y), Size::new(self.len(), 1))
    }
}
