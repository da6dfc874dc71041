//! Filled polygons: an exact fill with both fill rules, triangulation, and
//! exact simplicity and convexity tests.
//!
//! A polygon that goes down from its top vertex and back up only once
//! (y-monotone: every convex polygon and many concave ones) is walked as
//! two chains of edges, from its top vertex to its bottom one, one span a
//! row, like a triangle; any other polygon (a star, most self-intersecting
//! outlines) by an active-edge-table scanline fill. The test compares the
//! vertices' heights only, one pass. Both light the same pixels.
//!
//! A polygon borrows its vertices and is closed implicitly (the last vertex
//! connects to the first); it may be concave and may cross itself. Its edge
//! table (the active edges kept at its front) lives in `heapless` storage
//! on the stack whose capacity `N` (vertices) the caller picks: a
//! [`Polygon<N>`](Polygon) of more than `N` vertices cannot be made, so
//! drawing never runs out of room. The storage is one edge record per
//! vertex of capacity: 56 bytes for edges stepped in `i64`, 32 for those
//! in `i32`.
//!
//! Pixels follow the crate's sampling rule, as triangles do: a pixel is lit
//! iff its centre nudged by `(e, e^2)` has a non-zero winding number
//! ([`FillRule::NonZero`]) or an odd one ([`FillRule::EvenOdd`]).

pub(crate) mod monotone;
mod predicates;
mod scanline;
mod triangulate;

use core::fmt;

use embedded_graphics_core::{
    geometry::{Point, Size},
    pixelcolor::PixelColor,
    primitives::Rectangle,
};

use crate::{
    clip::Bounds,
    raster::sink::{drawable_through_spans, SpanDrawable, SpanSink},
    span::Span,
    stroke::{Join, Outline, Stroke},
    triangle::Triangle,
    vertex::Vertex,
};
use monotone::{fill_monotone, Shape};

/// Which pixels inside a self-overlapping outline are filled.
///
/// # Examples
///
/// ```
/// use embedded_raster::FillRule;
///
/// // A point wound twice (inside both loops of a pentagram's centre).
/// assert!(FillRule::NonZero.fills(2));
/// assert!(!FillRule::EvenOdd.fills(2));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum FillRule {
    /// Filled where the outline winds around the pixel at all (the rule
    /// triangles use).
    #[default]
    NonZero,
    /// Filled where the outline winds around the pixel an odd number of
    /// times (parity).
    EvenOdd,
}

impl FillRule {
    /// Whether a pixel with winding number `winding` (any `i32`) is filled.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::FillRule;
    ///
    /// assert!(FillRule::EvenOdd.fills(-1));
    /// assert!(!FillRule::NonZero.fills(0));
    /// ```
    pub fn fills(self, winding: i32) -> bool {
        winding & self.winding_mask() != 0
    }

    /// The bits of a winding number that decide [`fills`](Self::fills):
    /// all of them for non-zero, the lowest for even-odd. The edge table
    /// tests a row's windings by it, with no branch on the rule.
    #[inline(always)]
    pub(crate) fn winding_mask(self) -> i32 {
        match self {
            Self::NonZero => -1,
            Self::EvenOdd => 1,
        }
    }
}

/// Why a polygon cannot be made or triangulated.
///
/// # Examples
///
/// ```
/// use embedded_raster::{Polygon, PolygonError, Vertex};
///
/// let v = [Vertex::from_raw(0, 0); 5];
/// assert_eq!(
///     Polygon::<4>::new(&v).unwrap_err(),
///     PolygonError::CapacityExceeded { needed: 5, capacity: 4 }
/// );
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[non_exhaustive]
pub enum PolygonError {
    /// A polygon needs at least three vertices.
    TooFewVertices {
        /// How many it was given.
        count: usize,
    },
    /// More vertices than the polygon's capacity `N`.
    CapacityExceeded {
        /// How many vertices it was given.
        needed: usize,
        /// Its capacity.
        capacity: usize,
    },
    /// Triangulation needs a simple polygon (see [`Polygon::is_simple`]).
    NotSimple,
}

impl fmt::Display for PolygonError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::TooFewVertices { count } => {
                write!(f, "a polygon needs at least 3 vertices, got {count}")
            }
            Self::CapacityExceeded { needed, capacity } => {
                write!(
                    f,
                    "polygon has {needed} vertices, over the capacity of {capacity}"
                )
            }
            Self::NotSimple => f.write_str("polygon is not simple"),
        }
    }
}

impl core::error::Error for PolygonError {}

/// A closed polygon of at most `N` vertices, borrowed.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
/// use embedded_raster::{framebuffer::{buffer_size, Rgb565Le}, FillRule, Framebuffer, Polygon, Vertex};
///
/// let mut fb = Framebuffer::<Rgb565Le, 64, 64, { buffer_size::<Rgb565Le>(64, 64) }>::new();
/// // A pentagram: its centre is wound twice.
/// let star = [(32, 2), (50, 60), (3, 24), (61, 24), (14, 60)]
///     .map(|(x, y)| Vertex::try_from_num(x, y).unwrap());
/// let polygon = Polygon::<8>::new(&star)?;
/// polygon.fill(Rgb565::RED).with_rule(FillRule::EvenOdd).draw(&mut fb).unwrap();
/// assert_eq!(fb.pixel(Point::new(32, 36)), Some(Rgb565::BLACK)); // the hole
/// assert_eq!(fb.pixel(Point::new(32, 10)), Some(Rgb565::RED));
/// # Ok::<(), embedded_raster::PolygonError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Polygon<'a, const N: usize> {
    vertices: &'a [Vertex],
}

impl<'a, const N: usize> Polygon<'a, N> {
    /// Makes a polygon of `vertices`, closed implicitly.
    ///
    /// # Errors
    ///
    /// [`PolygonError::TooFewVertices`] for fewer than 3 vertices,
    /// [`PolygonError::CapacityExceeded`] for more than `N`. Any vertices:
    /// every [`Vertex`] is in range, and a polygon of them is filled
    /// exactly, however large, self-intersecting or degenerate.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::{Polygon, PolygonError, Vertex};
    ///
    /// let v = [Vertex::from_raw(0, 0), Vertex::from_raw(4096, 0)];
    /// assert_eq!(Polygon::<8>::new(&v), Err(PolygonError::TooFewVertices { count: 2 }));
    /// ```
    pub fn new(vertices: &'a [Vertex]) -> Result<Self, PolygonError> {
        match vertices.len() {
            count @ 0..3 => Err(PolygonError::TooFewVertices { count }),
            needed if needed > N => Err(PolygonError::CapacityExceeded {
                needed,
                capacity: N,
            }),
            _ => Ok(Self { vertices }),
        }
    }

    /// The vertices, in order.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::{Polygon, Vertex};
    ///
    /// let v = [Vertex::from_raw(0, 0), Vertex::from_raw(9, 0), Vertex::from_raw(0, 9)];
    /// assert_eq!(Polygon::<3>::new(&v)?.vertices().len(), 3);
    /// # Ok::<(), embedded_raster::PolygonError>(())
    /// ```
    pub fn vertices(&self) -> &'a [Vertex] {
        self.vertices
    }

    /// Whether the outline never touches itself: no two non-adjacent edges
    /// share a point, adjacent edges share only their common vertex (no
    /// fold-backs), and no edge has zero length (so no vertex repeats
    /// consecutively). Collinear neighbouring edges are allowed. Exact.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::{Polygon, Vertex};
    ///
    /// let v = |p: &[(i32, i32)]| p.iter().map(|&(x, y)| Vertex::try_from_num(x, y).unwrap()).collect::<Vec<_>>();
    /// let square_with_midpoint = v(&[(0, 0), (2, 0), (4, 0), (4, 4), (0, 4)]);
    /// let bow_tie = v(&[(0, 0), (4, 4), (4, 0), (0, 4)]);
    /// assert!(Polygon::<8>::new(&square_with_midpoint)?.is_simple());
    /// assert!(!Polygon::<8>::new(&bow_tie)?.is_simple());
    /// # Ok::<(), embedded_raster::PolygonError>(())
    /// ```
    pub fn is_simple(&self) -> bool {
        predicates::is_simple(self.vertices)
    }

    /// Whether the polygon is convex: simple, with non-zero area, every
    /// corner turning the same way or going straight. Exact, in one pass.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::{Polygon, Vertex};
    ///
    /// let v = |p: &[(i32, i32)]| p.iter().map(|&(x, y)| Vertex::try_from_num(x, y).unwrap()).collect::<Vec<_>>();
    /// assert!(Polygon::<8>::new(&v(&[(0, 0), (4, 0), (4, 4), (0, 4)]))?.is_convex());
    /// assert!(!Polygon::<8>::new(&v(&[(0, 0), (4, 0), (1, 1), (0, 4)]))?.is_convex());
    /// # Ok::<(), embedded_raster::PolygonError>(())
    /// ```
    pub fn is_convex(&self) -> bool {
        predicates::is_convex(self.vertices)
    }

    /// Calls `f` with the spans of lit pixels inside `clip` under `rule`,
    /// row by row from the top, left to right, stopping at the first error.
    ///
    /// # Examples
    ///
    /// ```
    /// use core::convert::Infallible;
    /// use embedded_graphics::{geometry::{Point, Size}, primitives::Rectangle};
    /// use embedded_raster::{FillRule, Polygon, Vertex};
    ///
    /// // A 4 x 2 px rectangle with a corner on a pixel corner.
    /// let v = [(0, 0), (4, 0), (4, 2), (0, 2)].map(|(x, y)| Vertex::try_from_num(x, y).unwrap());
    /// let clip = Rectangle::new(Point::zero(), Size::new(10, 10));
    /// let mut pixels = 0;
    /// Polygon::<4>::new(&v)?
    ///     .for_each_span(FillRule::NonZero, &clip, |s| {
    ///         pixels += s.len();
    ///         Ok::<(), Infallible>(())
    ///     })
    ///     .unwrap();
    /// assert_eq!(pixels, 8);
    /// # Ok::<(), embedded_raster::PolygonError>(())
    /// ```
    pub fn for_each_span<E>(
        &self,
        rule: FillRule,
        clip: &Rectangle,
        f: impl FnMut(Span) -> Result<(), E>,
    ) -> Result<(), E> {
        let mut f = f;
        match monotone::monotone_spans(self.vertices, Shape::Polygon, clip, &mut f) {
            Some(done) => done,
            None => scanline::polygon_spans::<N, E>(self.vertices, rule, clip, f),
        }
    }

    /// Cuts the polygon into triangles and calls `f` with each: a fan for a
    /// convex polygon, ear clipping for a simple one. The triangles share
    /// their cut edges, so drawn with the triangle rasterizer they light
    /// exactly the pixels of [`for_each_span`](Self::for_each_span), each
    /// once (either fill rule: a simple polygon winds once).
    ///
    /// # Errors
    ///
    /// [`PolygonError::NotSimple`] if the polygon is not simple; `f` has
    /// not been called then.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::{Polygon, Vertex};
    ///
    /// // An L shape: six vertices, four triangles.
    /// let v = [(0, 0), (2, 0), (2, 3), (5, 3), (5, 5), (0, 5)]
    ///     .map(|(x, y)| Vertex::try_from_num(x, y).unwrap());
    /// let mut count = 0;
    /// Polygon::<6>::new(&v)?.triangulate(|_| count += 1)?;
    /// assert_eq!(count, 4);
    /// # Ok::<(), embedded_raster::PolygonError>(())
    /// ```
    pub fn triangulate(&self, f: impl FnMut(Triangle)) -> Result<(), PolygonError> {
        triangulate::triangulate::<N>(self.vertices, f).map_err(|_| PolygonError::NotSimple)
    }

    /// Styles the polygon as filled with `color` under the non-zero rule
    /// (change it with [`FilledPolygon::with_rule`]).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use embedded_raster::{FillRule, Polygon, Vertex};
    ///
    /// let v = [Vertex::from_raw(0, 0), Vertex::from_raw(4096, 0), Vertex::from_raw(0, 4096)];
    /// let filled = Polygon::<3>::new(&v)?.fill(BinaryColor::On);
    /// assert_eq!(filled.rule, FillRule::NonZero);
    /// # Ok::<(), embedded_raster::PolygonError>(())
    /// ```
    pub fn fill<C: PixelColor>(self, color: C) -> FilledPolygon<'a, C, N> {
        FilledPolygon {
            polygon: self,
            color,
            rule: FillRule::NonZero,
        }
    }

    /// Styles the polygon's outline as a stroke of `color`, 1 px wide with
    /// [`Join::Miter`] corners; change them with
    /// [`StrokedPolygon::stroke_width`] and [`StrokedPolygon::join`].
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use embedded_raster::{Join, Polygon, Vertex};
    ///
    /// let v = [Vertex::from_raw(0, 0), Vertex::from_raw(4096, 0), Vertex::from_raw(0, 4096)];
    /// let stroked = Polygon::<3>::new(&v)?.stroke(BinaryColor::On);
    /// assert_eq!((stroked.width, stroked.join), (1, Join::Miter));
    /// # Ok::<(), embedded_raster::PolygonError>(())
    /// ```
    pub fn stroke<C: PixelColor>(self, color: C) -> StrokedPolygon<'a, C, N> {
        StrokedPolygon {
            polygon: self,
            color,
            width: 1,
            join: Join::Miter,
        }
    }

    /// The pixels of an axis-aligned rectangle, if the polygon is one.
    fn as_pixel_rect(&self) -> Option<Bounds> {
        let &[a, b, c, d] = self.vertices else {
            return None;
        };
        let [a, b, c, d] = [a, b, c, d].map(Vertex::raw);
        let along_x = a.1 == b.1 && b.0 == c.0 && c.1 == d.1 && d.0 == a.0;
        let along_y = a.0 == b.0 && b.1 == c.1 && c.0 == d.0 && d.1 == a.1;
        if !(along_x || along_y) {
            return None;
        }
        // Pixels whose centres 4096 i + 2048 lie in [min, max).
        let first = |lo: i32| (i64::from(lo) + 2047) >> 12;
        let (x0, x1) = (a.0.min(c.0), a.0.max(c.0));
        let (y0, y1) = (a.1.min(c.1), a.1.max(c.1));
        Some(Bounds {
            x0: first(x0),
            y0: first(y0),
            x1: first(x1),
            y1: first(y1),
        })
    }
}

/// A [`Polygon`] filled with one colour under a [`FillRule`]: a
/// [`Drawable`](embedded_graphics_core::Drawable) for any
/// [`DrawTarget`](embedded_graphics_core::draw_target::DrawTarget). Spans
/// go to the target as
/// [`fill_solid`](embedded_graphics_core::draw_target::DrawTarget::fill_solid)
/// calls; an axis-aligned rectangle is a single `fill_solid`.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
/// use embedded_raster::{framebuffer::{buffer_size, Gray8Bytes}, FillRule, Framebuffer, Polygon, Vertex};
///
/// let mut fb = Framebuffer::<Gray8Bytes, 16, 16, { buffer_size::<Gray8Bytes>(16, 16) }>::new();
/// let v = [(1, 1), (15, 2), (8, 15)].map(|(x, y)| Vertex::try_from_num(x, y).unwrap());
/// Polygon::<3>::new(&v)?.fill(Gray8::WHITE).with_rule(FillRule::EvenOdd).draw(&mut fb).unwrap();
/// assert_eq!(fb.pixel(Point::new(8, 6)), Some(Gray8::WHITE));
/// # Ok::<(), embedded_raster::PolygonError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct FilledPolygon<'a, C, const N: usize> {
    /// The shape.
    pub polygon: Polygon<'a, N>,
    /// The fill colour.
    pub color: C,
    /// The fill rule.
    pub rule: FillRule,
}

impl<'a, C, const N: usize> FilledPolygon<'a, C, N> {
    /// The same, filled under `rule`.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use embedded_raster::{FillRule, Polygon, Vertex};
    ///
    /// let v = [Vertex::from_raw(0, 0), Vertex::from_raw(4096, 0), Vertex::from_raw(0, 4096)];
    /// let p = Polygon::<3>::new(&v)?.fill(BinaryColor::On).with_rule(FillRule::EvenOdd);
    /// assert_eq!(p.rule, FillRule::EvenOdd);
    /// # Ok::<(), embedded_raster::PolygonError>(())
    /// ```
    pub fn with_rule(self, rule: FillRule) -> Self {
        Self { rule, ..self }
    }
}

impl<C: PixelColor, const N: usize> SpanDrawable for FilledPolygon<'_, C, N> {
    type Color = C;

    fn draw_spans<S: SpanSink<C>>(&self, sink: &mut S) -> Result<(), S::Error> {
        let clip = sink.bounds();
        if let Some(rect) = self.polygon.as_pixel_rect() {
            let Some(b) = rect.intersect(Bounds::of(&clip)) else {
                return Ok(());
            };
            // Inside the clip rectangle: all of it fits i32 and u32.
            let (Ok(x), Ok(y), Ok(w), Ok(h)) = (
                i32::try_from(b.x0),
                i32::try_from(b.y0),
                u32::try_from(b.x1 - b.x0),
                u32::try_from(b.y1 - b.y0),
            ) else {
                return Ok(());
            };
            return sink.fill_rect(
                &Rectangle::new(Point::new(x, y), Size::new(w, h)),
                self.color,
            );
        }
        if let Some(done) = fill_monotone(self.polygon.vertices, Shape::Polygon, sink, self.color) {
            return done;
        }
        scanline::polygon_spans::<N, _>(self.polygon.vertices, self.rule, &clip, |span| {
            sink.fill_span(span, self.color)
        })
    }
}

/// The outline of a [`Polygon`] as a stroke: a [`Drawable`](embedded_graphics_core::Drawable).
///
/// The closed thick polyline through the vertices (subpixel positions),
/// `width` px wide, corners filled by the [`Join`], every pixel written
/// exactly once under the crate's sampling rule, where the outline
/// crosses itself too (the same code as a thick
/// [`Polyline`](crate::Polyline); into a sink on which overdraw is
/// invisible, such as the framebuffer through `draw_spans`, the pieces
/// are written whole and their overlaps twice). Repeated vertices are skipped. It needs
/// no storage, whatever `N`. Width 0 draws nothing, widths over 65535 draw
/// as 65535.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::BinaryColor, prelude::*};
/// use embedded_raster::{framebuffer::{buffer_size, BinaryMsb}, Framebuffer, Polygon, Vertex};
///
/// let mut fb = Framebuffer::<BinaryMsb, 32, 32, { buffer_size::<BinaryMsb>(32, 32) }>::new();
/// let square = [(4, 4), (28, 4), (28, 28), (4, 28)].map(|(x, y)| Vertex::try_from_num(x, y).unwrap());
/// Polygon::<4>::new(&square)?.stroke(BinaryColor::On).stroke_width(4).draw(&mut fb).unwrap();
/// // Rows 2 to 5 along the top, the miter corners square.
/// assert_eq!(fb.pixel(Point::new(2, 2)), Some(BinaryColor::On));
/// assert_eq!(fb.pixel(Point::new(16, 5)), Some(BinaryColor::On));
/// assert_eq!(fb.pixel(Point::new(16, 6)), Some(BinaryColor::Off));
/// # Ok::<(), embedded_raster::PolygonError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct StrokedPolygon<'a, C, const N: usize> {
    /// The shape.
    pub polygon: Polygon<'a, N>,
    /// The stroke colour.
    pub color: C,
    /// The stroke width in pixels.
    pub width: u32,
    /// How the edges meet at the corners.
    pub join: Join,
}

impl<C, const N: usize> StrokedPolygon<'_, C, N> {
    /// Sets the stroke width in pixels: any `u32`, 0 draws nothing, over
    /// 65535 drawn as 65535.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use embedded_raster::{Polygon, Vertex};
    ///
    /// let v = [Vertex::from_raw(0, 0), Vertex::from_raw(4096, 0), Vertex::from_raw(0, 4096)];
    /// assert_eq!(Polygon::<3>::new(&v)?.stroke(BinaryColor::On).stroke_width(6).width, 6);
    /// # Ok::<(), embedded_raster::PolygonError>(())
    /// ```
    pub const fn stroke_width(mut self, width: u32) -> Self {
        self.width = width;
        self
    }

    /// Sets how the edges meet at the corners.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use embedded_raster::{Join, Polygon, Vertex};
    ///
    /// let v = [Vertex::from_raw(0, 0), Vertex::from_raw(4096, 0), Vertex::from_raw(0, 4096)];
    /// let p = Polygon::<3>::new(&v)?.stroke(BinaryColor::On).join(Join::Round);
    /// assert_eq!(p.join, Join::Round);
    /// # Ok::<(), embedded_raster::PolygonError>(())
    /// ```
    pub const fn join(mut self, join: Join) -> Self {
        self.join = join;
        self
    }
}

impl<C: PixelColor, const N: usize> SpanDrawable for StrokedPolygon<'_, C, N> {
    type Color = C;

    fn draw_spans<S: SpanSink<C>>(&self, sink: &mut S) -> Result<(), S::Error> {
        if self.width == 0 {
            return Ok(());
        }
        let outline = Outline::Vertices(self.polygon.vertices);
        Stroke::new(outline, true, self.width, self.join).draw(self.color, sink)
    }
}

drawable_through_spans!(FilledPolygon<'_, const N>, StrokedPolygon<'_, const N>);
