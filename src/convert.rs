//! Conversions from embedded-graphics' shapes (feature `embedded-graphics`).
//!
//! The same corner points give this crate's shapes, which light pixels by
//! the crate's sampling rule rather than embedded-graphics' own: see the
//! crate docs, "Using it with embedded-graphics", for exactly which pixels
//! differ.

use embedded_graphics::primitives::{
    Line as EgLine, Polyline as EgPolyline, Triangle as EgTriangle,
};

use crate::{
    error::CoordinateOutOfRange,
    line::{Line, Polyline},
    triangle::Triangle,
};

/// The triangle whose vertices are the centres of the embedded-graphics
/// triangle's vertex pixels ([`Triangle::from_points`]).
///
/// # Errors
///
/// [`CoordinateOutOfRange`] if a vertex is outside `-524288..=524287`.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{geometry::Point, primitives::Triangle as EgTriangle};
/// use embedded_raster::Triangle;
///
/// let eg = EgTriangle::new(Point::new(0, 0), Point::new(9, 0), Point::new(0, 9));
/// let t = Triangle::try_from(eg)?;
/// assert_eq!(t, Triangle::from_points(Point::new(0, 0), Point::new(9, 0), Point::new(0, 9))?);
/// # Ok::<(), embedded_raster::CoordinateOutOfRange>(())
/// ```
impl TryFrom<EgTriangle> for Triangle {
    type Error = CoordinateOutOfRange;

    fn try_from(t: EgTriangle) -> Result<Self, CoordinateOutOfRange> {
        let [a, b, c] = t.vertices;
        Triangle::from_points(a, b, c)
    }
}

/// The line between the same two pixels.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{geometry::Point, primitives::Line as EgLine};
/// use embedded_raster::Line;
///
/// let line = Line::from(EgLine::new(Point::new(1, 2), Point::new(30, -4)));
/// assert_eq!((line.start, line.end), (Point::new(1, 2), Point::new(30, -4)));
/// ```
impl From<EgLine> for Line {
    fn from(line: EgLine) -> Self {
        Line::new(line.start, line.end)
    }
}

/// The polyline through the same points.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{geometry::Point, primitives::Polyline as EgPolyline};
/// use embedded_raster::Polyline;
///
/// let points = [Point::new(0, 0), Point::new(5, 5), Point::new(9, 0)];
/// let polyline = Polyline::from(EgPolyline::new(&points));
/// assert_eq!(polyline.points, points);
/// ```
impl<'a> From<EgPolyline<'a>> for Polyline<'a> {
    fn from(polyline: EgPolyline<'a>) -> Self {
        Polyline::new(polyline.vertices)
    }
}
