//! Delaunay triangulation of point sets: allocation-free, with exact
//! predicates.
//!
//! [`Delaunay<N>`](Delaunay) triangulates up to `N` [`Vertex`]es in its own
//! fixed storage (no heap): every triangle's circumcircle holds no input
//! point strictly inside, which among all triangulations of the points
//! maximises the smallest angle. The triangles come out as indices into the
//! caller's points and as [`Triangle`]s that the rasterizer draws with no
//! gaps and no overdraw.
//!
//! ```
//! use embedded_raster::{delaunay::Delaunay, Vertex};
//!
//! let points = [(0, 0), (40, 0), (40, 30), (0, 30), (20, 15)]
//!     .map(|(x, y)| Vertex::try_from_num(x, y).unwrap());
//! let mut delaunay = Delaunay::<8>::new();
//! let mesh = delaunay.triangulate(&points)?;
//! assert_eq!(mesh.len(), 4); // 2n - h - 2 = 10 - 4 - 2
//! assert!(mesh.indices().all(|t| t.contains(&4))); // all around the centre
//! # Ok::<(), embedded_raster::delaunay::DelaunayError>(())
//! ```
//!
//! # Algorithm and cost
//!
//! Incremental insertion with Lawson flips. The points are sorted along a
//! Morton (Z-order) curve of their coordinates, so that consecutive points
//! are close; each point is located by a visibility walk from the previous
//! one, splits the triangle (or edge) it falls in, and edges around it are
//! flipped while the far vertex lies strictly inside a circumcircle. A
//! vertex at infinity closes the mesh, so points outside the current hull
//! need no special case.
//!
//! Cost: `O(n log n)` for the sort plus, per point, the walk and the flips.
//! For points spread over an area, walks are short and a point flips a
//! handful of edges on average (measured on 1,000 random points: 3.7 walk
//! steps and 4 flips a point), so the whole is close to `O(n log n)`:
//! `BENCHMARKS.md` has 0.32 ms for 1,000 random points on the build host
//! and 5.8 million instructions (5,800 a point) on a Cortex-M4. The worst
//! case is `O(n²)`: inputs where every insertion re-flips much of the mesh
//! or walks across it. Storage: `28 N` bytes (`2N` faces of 12
//! bytes, a `u16` insertion order and a `u16` flip stack per point).
//!
//! # Exactness
//!
//! [`orientation`] and [`in_circle`] decide every branch exactly, in
//! integers, for all 20.12 coordinates (`i64` and `i128`, and 256-bit
//! products for in-circle tests on points more than 262,144 px apart; the
//! widths are proved in the source). No floating point, no wrapping
//! arithmetic.
//!
//! # Degenerate input, deterministically
//!
//! - **Duplicates** are kept once: the lowest index among equal points is
//!   the vertex, the others appear in no triangle.
//! - **Fewer than 3 distinct points, or all collinear**: `Ok` with no
//!   triangles (no triangle of the points has area).
//! - **Collinear runs** elsewhere: every point is a vertex; points in the
//!   middle of a hull side are vertices on it, and no triangle has zero
//!   area.
//! - **Cocircular points** (grids, regular polygons): an edge flips only
//!   when the far point is *strictly* inside, so four points on a circle
//!   keep the diagonal that insertion made. The insertion order depends
//!   only on the coordinates (Morton order; for duplicates, the lowest
//!   index), so the same point set gives the same triangles (as
//!   coordinates) whatever its order, and every circumcircle is empty in
//!   the closed sense: points on it are allowed, none strictly inside.
//!
//! The triangle count is `2n - h - 2` for `n` distinct points, not all
//! collinear, of which `h` lie on the hull's boundary.
//!
//! # No panics
//!
//! `triangulate` never panics, never loops without bound and never
//! allocates, for any points; the only error is a point count over the
//! capacity, checked before anything is written.

mod build;
mod predicates;

use core::cmp::Ordering;
use core::fmt;

use crate::{triangle::Triangle, vertex::Vertex};
use build::{Builder, Face};
pub use predicates::{in_circle, orientation};

/// The most points a [`Delaunay`] can hold: vertex and face indices are
/// `u16`, and `2N` faces must stay below `u16::MAX`.
///
/// # Examples
///
/// ```
/// assert_eq!(embedded_raster::delaunay::MAX_POINTS, 32_767);
/// ```
pub const MAX_POINTS: usize = 32_767;

/// Why a point set could not be triangulated.
///
/// # Examples
///
/// ```
/// use embedded_raster::{delaunay::{Delaunay, DelaunayError}, Vertex};
///
/// let points = [Vertex::from_raw(0, 0); 5];
/// let err = Delaunay::<4>::new().triangulate(&points).unwrap_err();
/// assert_eq!(err, DelaunayError::CapacityExceeded { needed: 5, capacity: 4 });
/// assert_eq!(err.to_string(), "5 points, over the capacity of 4");
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[non_exhaustive]
pub enum DelaunayError {
    /// More points (counting duplicates) than the capacity `N`.
    CapacityExceeded {
        /// How many points were given.
        needed: usize,
        /// The capacity.
        capacity: usize,
    },
}

impl fmt::Display for DelaunayError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::CapacityExceeded { needed, capacity } => {
                write!(f, "{needed} points, over the capacity of {capacity}")
            }
        }
    }
}

impl core::error::Error for DelaunayError {}

/// Storage for the Delaunay triangulation of up to `N` points
/// (`N <= 32767`, checked at compile time), and the last triangulation
/// made in it.
///
/// It takes `28 N` bytes and is meant to live where the caller puts it: on
/// the stack for small `N`, in a `static` on a microcontroller, in a `Box`
/// on a host. [`triangulate`](Self::triangulate) fills it; a failed call
/// leaves the previous triangulation in place.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
/// use embedded_raster::{delaunay::Delaunay, framebuffer::{buffer_size, Rgb565Le}, Framebuffer, Vertex};
///
/// let points = [(2, 2), (60, 4), (30, 30), (5, 60), (58, 61), (33, 10)]
///     .map(|(x, y)| Vertex::try_from_num(x, y).unwrap());
/// let mut delaunay = Delaunay::<16>::new();
/// let mut fb = Framebuffer::<Rgb565Le, 64, 64, { buffer_size::<Rgb565Le>(64, 64) }>::new();
/// for (k, triangle) in delaunay.triangulate(&points)?.triangles().enumerate() {
///     let colour = Rgb565::new(8 * k as u8, 63 - 8 * k as u8, 16);
///     triangle.fill(colour).draw(&mut fb).unwrap();
/// }
/// assert_ne!(fb.pixel(Point::new(30, 20)), Some(Rgb565::BLACK));
/// # Ok::<(), embedded_raster::delaunay::DelaunayError>(())
/// ```
pub struct Delaunay<const N: usize> {
    /// `2N` faces, finite and ghost, as pairs (a const generic cannot be
    /// doubled in an array length).
    faces: [[Face; 2]; N],
    /// The insertion order: indices of the distinct points.
    order: [u16; N],
    /// The flip stack.
    stack: [u16; N],
    /// Faces of the last triangulation, finite and ghost.
    face_count: usize,
    /// Finite faces of the last triangulation.
    triangle_count: usize,
}

impl<const N: usize> Delaunay<N> {
    /// Empty storage for up to `N` points, holding no triangles.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::delaunay::Delaunay;
    ///
    /// let delaunay = Delaunay::<100>::new();
    /// assert!(delaunay.is_empty());
    /// ```
    pub const fn new() -> Self {
        const { assert!(N <= MAX_POINTS, "Delaunay<N>: N is at most 32767") };
        Self {
            faces: [[Face::EMPTY; 2]; N],
            order: [0; N],
            stack: [0; N],
            face_count: 0,
            triangle_count: 0,
        }
    }

    /// Triangulates `points`, replacing the previous triangulation.
    ///
    /// The result borrows `points` and this storage; it lists each
    /// triangle once, with its vertices clockwise on the screen
    /// ([`orientation`] `Greater`). Degenerate input is described in the
    /// [module docs](self): duplicates count once, and fewer than three
    /// distinct points or all collinear give no triangles.
    ///
    /// # Errors
    ///
    /// [`DelaunayError::CapacityExceeded`] if `points` has more than `N`
    /// entries (duplicates included). Any vertices: every [`Vertex`] is in
    /// range and the predicates are exact on all of them. It is checked first: on error the
    /// storage still holds the previous triangulation.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::{delaunay::Delaunay, Vertex};
    ///
    /// let v = |x, y| Vertex::try_from_num(x, y).unwrap();
    /// let mut delaunay = Delaunay::<8>::new();
    /// // A square: two triangles, either diagonal being Delaunay.
    /// let square = [v(0, 0), v(8, 0), v(8, 8), v(0, 8)];
    /// assert_eq!(delaunay.triangulate(&square)?.len(), 2);
    /// // Collinear: no triangles.
    /// assert!(delaunay.triangulate(&[v(0, 0), v(1, 1), v(2, 2)])?.is_empty());
    /// # Ok::<(), embedded_raster::delaunay::DelaunayError>(())
    /// ```
    pub fn triangulate<'a>(
        &'a mut self,
        points: &'a [Vertex],
    ) -> Result<Triangulation<'a>, DelaunayError> {
        if points.len() > N {
            return Err(DelaunayError::CapacityExceeded {
                needed: points.len(),
                capacity: N,
            });
        }
        let order = &mut self.order[..points.len()];
        let distinct = sort_distinct(points, order);
        self.face_count = match first_triangle(points, &mut order[..distinct]) {
            Some(first) => {
                let faces = self.faces.as_flattened_mut();
                let mut builder = Builder::new(points, faces, &mut self.stack, first);
                for &p in &order[3..distinct] {
                    builder.insert(p);
                }
                builder.len()
            }
            None => 0,
        };
        let faces = &self.faces.as_flattened()[..self.face_count];
        self.triangle_count = faces.iter().filter(|f| !f.is_ghost()).count();
        Ok(self.triangulation(points))
    }

    /// The last triangulation, over the points it was made from.
    ///
    /// Pass the slice given to the last successful
    /// [`triangulate`](Self::triangulate): triangles with an index outside
    /// `points` are left out of [`Triangulation::triangles`].
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::{delaunay::Delaunay, Vertex};
    ///
    /// let points = [(0, 0), (9, 0), (0, 9)].map(|(x, y)| Vertex::try_from_num(x, y).unwrap());
    /// let mut delaunay = Delaunay::<4>::new();
    /// delaunay.triangulate(&points)?;
    /// // Too many points: an error, and the triangle is still there.
    /// assert!(delaunay.triangulate(&[points[0]; 5]).is_err());
    /// assert_eq!(delaunay.triangulation(&points).len(), 1);
    /// # Ok::<(), embedded_raster::delaunay::DelaunayError>(())
    /// ```
    pub fn triangulation<'a>(&'a self, points: &'a [Vertex]) -> Triangulation<'a> {
        Triangulation {
            faces: &self.faces.as_flattened()[..self.face_count],
            points,
            len: self.triangle_count,
        }
    }

    /// Triangles in the last triangulation.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::{delaunay::Delaunay, Vertex};
    ///
    /// let points = [(0, 0), (9, 0), (0, 9), (9, 9)].map(|(x, y)| Vertex::try_from_num(x, y).unwrap());
    /// let mut delaunay = Delaunay::<4>::new();
    /// delaunay.triangulate(&points)?;
    /// assert_eq!(delaunay.len(), 2);
    /// # Ok::<(), embedded_raster::delaunay::DelaunayError>(())
    /// ```
    pub fn len(&self) -> usize {
        self.triangle_count
    }

    /// Whether the last triangulation has no triangles (or there was none).
    ///
    /// # Examples
    ///
    /// ```
    /// assert!(embedded_raster::delaunay::Delaunay::<4>::new().is_empty());
    /// ```
    pub fn is_empty(&self) -> bool {
        self.triangle_count == 0
    }
}

impl<const N: usize> Default for Delaunay<N> {
    fn default() -> Self {
        Self::new()
    }
}

impl<const N: usize> fmt::Debug for Delaunay<N> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Delaunay")
            .field("capacity", &N)
            .field("triangles", &self.triangle_count)
            .finish_non_exhaustive()
    }
}

/// A Delaunay triangulation: its triangles as vertex indices and as
/// [`Triangle`]s, borrowed from a [`Delaunay`] and the points.
///
/// # Examples
///
/// ```
/// use embedded_raster::{delaunay::Delaunay, Triangle, Vertex};
///
/// let points = [(0, 0), (9, 0), (0, 9)].map(|(x, y)| Vertex::try_from_num(x, y).unwrap());
/// let mut delaunay = Delaunay::<4>::new();
/// let mesh = delaunay.triangulate(&points)?;
/// let [a, b, c] = mesh.indices().next().unwrap();
/// assert_eq!(mesh.triangles().next(), Some(Triangle::new(points[a], points[b], points[c])));
/// # Ok::<(), embedded_raster::delaunay::DelaunayError>(())
/// ```
#[derive(Debug, Clone, Copy)]
pub struct Triangulation<'a> {
    faces: &'a [Face],
    points: &'a [Vertex],
    len: usize,
}

impl<'a> Triangulation<'a> {
    /// The number of triangles.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::{delaunay::Delaunay, Vertex};
    ///
    /// let points = [(0, 0), (9, 0), (0, 9)].map(|(x, y)| Vertex::try_from_num(x, y).unwrap());
    /// assert_eq!(Delaunay::<3>::new().triangulate(&points)?.len(), 1);
    /// # Ok::<(), embedded_raster::delaunay::DelaunayError>(())
    /// ```
    pub fn len(&self) -> usize {
        self.len
    }

    /// Whether there are no triangles.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::{delaunay::Delaunay, Vertex};
    ///
    /// let twice = [Vertex::from_raw(5, 5); 2];
    /// assert!(Delaunay::<2>::new().triangulate(&twice)?.is_empty());
    /// # Ok::<(), embedded_raster::delaunay::DelaunayError>(())
    /// ```
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Each triangle's vertices as indices into the points, clockwise on
    /// the screen.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::{delaunay::Delaunay, Vertex};
    ///
    /// // The duplicate (index 3) is not a vertex; index 0 is.
    /// let points = [(0, 0), (9, 0), (0, 9), (0, 0)].map(|(x, y)| Vertex::try_from_num(x, y).unwrap());
    /// let mut delaunay = Delaunay::<4>::new();
    /// let mut triangle = delaunay.triangulate(&points)?.indices().next().unwrap();
    /// triangle.sort();
    /// assert_eq!(triangle, [0, 1, 2]);
    /// # Ok::<(), embedded_raster::delaunay::DelaunayError>(())
    /// ```
    pub fn indices(&self) -> impl Iterator<Item = [usize; 3]> + 'a {
        self.faces
            .iter()
            .filter(|f| !f.is_ghost())
            .map(|f| f.v.map(usize::from))
    }

    /// Each triangle, ready to fill.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::{delaunay::Delaunay, Vertex};
    ///
    /// let points = [(0, 0), (9, 0), (0, 9), (9, 9)].map(|(x, y)| Vertex::try_from_num(x, y).unwrap());
    /// let mut delaunay = Delaunay::<4>::new();
    /// let area2: i64 = delaunay
    ///     .triangulate(&points)?
    ///     .triangles()
    ///     .map(|t| {
    ///         let [a, b, c] = t.vertices.map(|v| v.raw()).map(|(x, y)| (i64::from(x), i64::from(y)));
    ///         (b.0 - a.0) * (c.1 - a.1) - (b.1 - a.1) * (c.0 - a.0)
    ///     })
    ///     .sum();
    /// assert_eq!(area2, 2 * 81 * 4096 * 4096); // the square, covered once
    /// # Ok::<(), embedded_raster::delaunay::DelaunayError>(())
    /// ```
    pub fn triangles(&self) -> impl Iterator<Item = Triangle> + 'a {
        let points = self.points;
        self.indices().filter_map(move |[a, b, c]| {
            Some(Triangle::new(
                *points.get(a)?,
                *points.get(b)?,
                *points.get(c)?,
            ))
        })
    }
}

/// Sorts the indices of `points` into `order` by Morton code of the
/// coordinates (then index), drops all but the first of equal points, and
/// returns how many distinct points lead `order`.
fn sort_distinct(points: &[Vertex], order: &mut [u16]) -> usize {
    for (i, slot) in order.iter_mut().enumerate() {
        // At most MAX_POINTS points, so every index fits.
        *slot = i as u16;
    }
    let at = |i: u16| points[usize::from(i)];
    order.sort_unstable_by(|&i, &j| morton_cmp(at(i), at(j)).then(i.cmp(&j)));
    let mut distinct = 0;
    for k in 0..order.len() {
        let p = order[k];
        let seen =
            distinct > 0 && points[usize::from(order[distinct - 1])] == points[usize::from(p)];
        if !seen {
            order[distinct] = p;
            distinct += 1;
        }
    }
    distinct
}

/// Compares two vertices in Morton (Z-order) order: the order of the
/// codes that interleave the bits of their coordinates (offset to
/// unsigned), y's above x's at each level, without building the codes:
/// the coordinate whose first differing bit is higher decides.
fn morton_cmp(a: Vertex, b: Vertex) -> Ordering {
    let unsigned = |v: Vertex| {
        let (x, y) = v.raw();
        (
            x.cast_unsigned() ^ 0x8000_0000,
            y.cast_unsigned() ^ 0x8000_0000,
        )
    };
    let ((ax, ay), (bx, by)) = (unsigned(a), unsigned(b));
    let (dx, dy) = (ax ^ bx, ay ^ by);
    // dy's highest set bit is below dx's.
    let x_decides = dy < dx && dy < (dx ^ dy);
    match x_decides {
        true => ax.cmp(&bx),
        false => ay.cmp(&by),
    }
}

/// The first triangle: the first two points in `order` and the first
/// point not on their line, moved to the third place. `None` when there
/// are fewer than three points or all are collinear.
fn first_triangle(points: &[Vertex], order: &mut [u16]) -> Option<[u16; 3]> {
    let [a, b, ..] = *order else {
        return None;
    };
    let at = |i: u16| points[usize::from(i)];
    let k = (2..order.len())
        .find(|&k| orientation(at(a), at(b), at(order[k])) != core::cmp::Ordering::Equal)?;
    order[2..=k].rotate_right(1);
    Some([a, b, order[2]])
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Morton code itself: offset coordinates, bits interleaved.
    fn morton(v: Vertex) -> u64 {
        let spread = |c: i32| {
            let u = u64::from(c.cast_unsigned() ^ 0x8000_0000);
            (0..32).map(|k| (u >> k & 1) << (2 * k)).sum::<u64>()
        };
        let (x, y) = v.raw();
        spread(x) | spread(y) << 1
    }

    #[test]
    fn morton_cmp_orders_as_the_codes() {
        let values = [
            i32::MIN,
            -70000,
            -4097,
            -1,
            0,
            1,
            2,
            3,
            4096,
            4097,
            123456,
            i32::MAX,
        ];
        let v = |x, y| Vertex::from_raw(x, y);
        for &ax in &values {
            for &ay in &values {
                for &bx in &values {
                    for &by in &values {
                        let (a, b) = (v(ax, ay), v(bx, by));
                        assert_eq!(morton_cmp(a, b), morton(a).cmp(&morton(b)), "{a:?} {b:?}");
                    }
                }
            }
        }
    }

    #[test]
    fn duplicates_are_dropped_keeping_the_lowest_index() {
        let v = |x, y| Vertex::from_raw(x, y);
        let points = [v(5, 5), v(1, 1), v(5, 5), v(1, 1), v(0, 0)];
        let mut order = [0; 5];
        let n = sort_distinct(&points, &mut order);
        assert_eq!(&order[..n], &[4, 1, 0]);
    }
}
