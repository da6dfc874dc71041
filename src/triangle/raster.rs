//! Exact triangle rasterization by edge equations.
//!
//! # The edge functions
//!
//! Vertices are raw 20.12 integers (units of 1/4096 px). After orienting the
//! triangle so that its doubled signed area is positive (swapping two
//! vertices if needed), edge `k` runs from `v[k]` to `v[k + 1]` and
//!
//! ```text
//! E_k(p) = A_k (p.x - x_k) + B_k (p.y - y_k),   A_k = y_k - y_(k+1),  B_k = x_(k+1) - x_k
//! ```
//!
//! is positive inside. A pixel centre `p` exactly on an edge is decided by
//! the sampling rule's nudge `(e, e^2)`: `E_k(p + (e, e^2)) = E_k(p) + A_k e +
//! B_k e^2`, so the centre counts as inside iff `A_k > 0`, or `A_k == 0` and
//! `B_k > 0` (the top-left rule). With `bias_k = 0` for those edges and `-1`
//! otherwise, a centre is inside edge `k` iff `E_k(p) + bias_k >= 0`.
//!
//! # Stepping in pixels, exactly
//!
//! Pixel centres are `4096 i + 2048`, so from the scan origin `(i0, j0)`
//! `E_k(i0 + di, j0 + dj) + bias_k = G_k + 4096 (A_k di + B_k dj)` with
//! `G_k = E_k(i0, j0) + bias_k`. Writing `G_k = 4096 Q_k + R_k` with
//! `0 <= R_k < 4096` (an arithmetic shift), the test becomes
//!
//! ```text
//! F_k(di, dj) = Q_k + A_k di + B_k dj >= 0
//! ```
//!
//! because `4096 F + R >= 0` iff `F >= 0` when `0 <= R < 4096`. `F_k` is
//! stepped with one add per pixel and the three tests are one comparison,
//! `(F_0 | F_1 | F_2) >= 0`. No rounding happens anywhere: the result is the
//! exact sampling rule.
//!
//! # Integer widths and ranges
//!
//! `|A_k|, |B_k| < 2^32` and `G_k` is twice the area of a triangle inside
//! the bounding box, so `|E| <= 2^64` and `|F| <= 2^52` for any vertices in
//! range: 64-bit stepping is always exact. The setup (`E_k` at the origin
//! and the orientation) needs products of coordinate differences: it runs in
//! `i64` when the bounding box is narrower than 2^31 raw units (524288 px)
//! in both axes, else in `i128`.
//!
//! `F_k` is linear, so over the scanned rectangle its extremes lie at the
//! corners. The per-pixel loop runs in `i32` when those extremes and the
//! steps `A_k`, `B_k` all fit in `i32`, which is checked exactly at setup.
//! Since `|F_k| <= 4096 * W * H + 1` for a bounding box of `W x H` px (twice
//! the area of a triangle inside the box) and `|A_k| <= 4096 H`,
//! `|B_k| <= 4096 W`, every triangle whose bounding box has both sides
//! shorter than 524288 px and covers at most 524287 px^2 (724 x 724,
//! 1024 x 511, 4096 x 127, ...) steps in 32 bits, whatever the clip; larger
//! ones do when the values over their visible part fit, else in 64 bits.
//!
//! # Traversal
//!
//! Rows are scanned top to bottom over the bounding box clipped to the
//! target. A triangle is convex, so each row's lit pixels form one span. The
//! walk starts each row where the previous span started, moves left or right
//! by one pixel at a time to the new span (a failing edge tells which way,
//! and a row is left as soon as it is known to be empty), then walks right
//! to the end of the span and leaves the row there. Walking over lit pixels
//! gallops: because they form one interval, a lit pixel 16 steps away means
//! all 16 are lit, so the walk takes strides of 16 and narrows the last
//! one down with 8, 4, 2 and 1, every probe the same one-comparison test.
//! Work per row is about a sixteenth of the span plus the change of its
//! start, not the width of the bounding box. (Strides are used when
//! `16 A_k` fits the stepping type, which it does except for edges taller
//! than 32768 px in the 32-bit loop.)

use core::ops::{Add, BitOr, Mul, Shr, Sub};

use embedded_graphics_core::primitives::Rectangle;

use crate::{clip::Bounds, vertex::ONE, Span, Vertex};

/// The integer width of a triangle's per-pixel edge stepping, chosen per
/// triangle (and per clip rectangle) by [`Triangle::step_width`].
///
/// [`Triangle::step_width`]: crate::Triangle::step_width
///
/// # Examples
///
/// ```
/// use embedded_graphics_core::{geometry::{Point, Size}, primitives::Rectangle};
/// use embedded_raster::{StepWidth, Triangle, Vertex};
///
/// let clip = Rectangle::new(Point::zero(), Size::new(320, 240));
/// let v = |x: i32, y: i32| Vertex::try_from_num(x, y).unwrap();
/// let small = Triangle::new(v(0, 0), v(300, 10), v(20, 230));
/// assert_eq!(small.step_width(&clip), Some(StepWidth::Bits32));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum StepWidth {
    /// Edge values and steps fit in `i32` over the whole scanned region.
    Bits32,
    /// The region needs `i64` (always sufficient in range).
    Bits64,
}

/// Orientation, per-edge coefficients and the scan rectangle of a triangle
/// that lights at least one candidate pixel.
#[derive(Debug, Clone, Copy)]
struct Setup {
    /// Top-left pixel of the scanned rectangle.
    origin_x: i32,
    origin_y: i32,
    /// Size of the scanned rectangle in pixels (both >= 1).
    width: i32,
    height: i32,
    /// `A_k`, `B_k` and `F_k(0, 0)` of the module docs.
    a: [i64; 3],
    b: [i64; 3],
    q: [i64; 3],
}

/// Calls `emit` with each row's span of `vertices` inside `clip`, top to
/// bottom, stopping at the first error.
pub(crate) fn rasterize<E>(
    vertices: &[Vertex; 3],
    clip: &Rectangle,
    mut emit: impl FnMut(Span) -> Result<(), E>,
) -> Result<(), E> {
    let Some(s) = setup(vertices, clip) else {
        return Ok(());
    };
    match Stepper::<i32>::new(&s) {
        Some(narrow) => narrow.run(&s, &mut emit),
        None => match Stepper::<i64>::new(&s) {
            Some(wide) => wide.run(&s, &mut emit),
            // Unreachable: every value fits in i64 (module docs).
            None => Ok(()),
        },
    }
}

/// The stepping width [`rasterize`] uses, `None` if nothing is lit.
pub(crate) fn step_width(vertices: &[Vertex; 3], clip: &Rectangle) -> Option<StepWidth> {
    let s = setup(vertices, clip)?;
    Some(match Stepper::<i32>::new(&s) {
        Some(_) => StepWidth::Bits32,
        None => StepWidth::Bits64,
    })
}

fn setup(vertices: &[Vertex; 3], clip: &Rectangle) -> Option<Setup> {
    let raw = vertices.map(|v| {
        let (x, y) = v.raw();
        (i64::from(x), i64::from(y))
    });
    let min_x = raw.iter().map(|v| v.0).min()?;
    let max_x = raw.iter().map(|v| v.0).max()?;
    let min_y = raw.iter().map(|v| v.1).min()?;
    let max_y = raw.iter().map(|v| v.1).max()?;

    // Pixels whose centres 4096 i + 2048 lie in [min, max], clipped.
    let half = ONE / 2;
    let candidates = Bounds {
        x0: (min_x + half - 1) >> 12,
        y0: (min_y + half - 1) >> 12,
        x1: ((max_x - half) >> 12) + 1,
        y1: ((max_y - half) >> 12) + 1,
    };
    let scan = candidates.intersect(Bounds::of(clip))?;
    // The scan rectangle lies within the vertex range (|i| <= 2^19 + 1).
    let origin = (i32::try_from(scan.x0).ok()?, i32::try_from(scan.y0).ok()?);
    let size = (
        i32::try_from(scan.x1 - scan.x0).ok()?,
        i32::try_from(scan.y1 - scan.y0).ok()?,
    );
    let centre = (scan.x0 * ONE + half, scan.y0 * ONE + half);

    let narrow = max_x - min_x < 1 << 31 && max_y - min_y < 1 << 31;
    let (a, b, q) = if narrow {
        edges::<i64>(raw, centre)?
    } else {
        edges::<i128>(raw, centre)?
    };
    Some(Setup {
        origin_x: origin.0,
        origin_y: origin.1,
        width: size.0,
        height: size.1,
        a,
        b,
        q,
    })
}

/// An integer wide enough for the setup products.
trait SetupInt:
    Copy
    + Ord
    + From<i64>
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Shr<u32, Output = Self>
{
    const ZERO: Self;
    fn to_i64(self) -> Option<i64>;
}

impl SetupInt for i64 {
    const ZERO: Self = 0;
    fn to_i64(self) -> Option<i64> {
        Some(self)
    }
}

impl SetupInt for i128 {
    const ZERO: Self = 0;
    fn to_i64(self) -> Option<i64> {
        i64::try_from(self).ok()
    }
}

type Coefficients = ([i64; 3], [i64; 3], [i64; 3]);

/// Orients the triangle and returns `(A, B, Q)` per edge, with `Q = F(0, 0)`
/// at the scan origin whose pixel centre is `centre`. `None` for zero area.
fn edges<W: SetupInt>(raw: [(i64, i64); 3], centre: (i64, i64)) -> Option<Coefficients> {
    let w = |v: i64| W::from(v);
    let [p0, mut p1, mut p2] = raw;
    let area2 = w(p1.0 - p0.0) * w(p2.1 - p0.1) - w(p1.1 - p0.1) * w(p2.0 - p0.0);
    if area2 == W::ZERO {
        return None;
    }
    if area2 < W::ZERO {
        core::mem::swap(&mut p1, &mut p2);
    }
    let p = [p0, p1, p2];
    let mut a = [0; 3];
    let mut b = [0; 3];
    let mut q = [0; 3];
    for k in 0..3 {
        let (from, to) = (p[k], p[(k + 1) % 3]);
        a[k] = from.1 - to.1;
        b[k] = to.0 - from.0;
        let e = w(a[k]) * w(centre.0 - from.0) + w(b[k]) * w(centre.1 - from.1);
        let top_left = a[k] > 0 || (a[k] == 0 && b[k] > 0);
        let g = if top_left { e } else { e - w(1) };
        q[k] = (g >> 12).to_i64()?;
    }
    Some((a, b, q))
}

/// An integer the per-pixel loop steps in.
trait Step: Copy + Ord + Add<Output = Self> + Sub<Output = Self> + BitOr<Output = Self> {
    const ZERO: Self;
    fn from_i64(v: i64) -> Option<Self>;
}

impl Step for i32 {
    const ZERO: Self = 0;
    fn from_i64(v: i64) -> Option<Self> {
        i32::try_from(v).ok()
    }
}

impl Step for i64 {
    const ZERO: Self = 0;
    fn from_i64(v: i64) -> Option<Self> {
        Some(v)
    }
}

/// Edge stepping state in integers of type `T`.
struct Stepper<T> {
    a: [T; 3],
    b: [T; 3],
    /// `F_k` at the current column `x` of the current row.
    f: [T; 3],
    /// Edges with `A_k > 0`: failing, the span lies to the right.
    bound_left: u8,
    /// Edges with `A_k < 0`: failing, the span lies to the left.
    bound_right: u8,
    /// `[16, 8, 4, 2] * A_k`, when they fit in `T`, for galloping.
    strides: Option<[[T; 3]; 4]>,
}

/// Galloping strides in pixels, largest first, for [`Stepper::strides`].
const STRIDES: [i32; 4] = [16, 8, 4, 2];

impl<T: Step> Stepper<T> {
    /// `None` if some value `F_k` takes over the scan rectangle (its
    /// extremes are at the corners), or a step, does not fit in `T`.
    fn new(s: &Setup) -> Option<Self> {
        let (dx, dy) = (i64::from(s.width - 1), i64::from(s.height - 1));
        let mut a = [T::ZERO; 3];
        let mut b = [T::ZERO; 3];
        let mut f = [T::ZERO; 3];
        let (mut bound_left, mut bound_right) = (0, 0);
        for k in 0..3 {
            let (ax, by) = (s.a[k] * dx, s.b[k] * dy);
            let lo = s.q[k] + ax.min(0) + by.min(0);
            let hi = s.q[k] + ax.max(0) + by.max(0);
            T::from_i64(lo)?;
            T::from_i64(hi)?;
            a[k] = T::from_i64(s.a[k])?;
            b[k] = T::from_i64(s.b[k])?;
            f[k] = T::from_i64(s.q[k])?;
            bound_left |= u8::from(s.a[k] > 0) << k;
            bound_right |= u8::from(s.a[k] < 0) << k;
        }
        let stride = |n: i32| -> Option<[T; 3]> {
            let d = |k: usize| T::from_i64(s.a[k] * i64::from(n));
            Some([d(0)?, d(1)?, d(2)?])
        };
        let strides = match STRIDES.map(stride) {
            [Some(d16), Some(d8), Some(d4), Some(d2)] => Some([d16, d8, d4, d2]),
            _ => None,
        };
        Some(Self {
            a,
            b,
            f,
            bound_left,
            bound_right,
            strides,
        })
    }

    fn run<E>(mut self, s: &Setup, emit: &mut impl FnMut(Span) -> Result<(), E>) -> Result<(), E> {
        let last = s.width - 1;
        let mut x = 0;
        for row in 0..s.height {
            if row > 0 {
                self.f = add(self.f, self.b);
            }
            if let Some((start, end)) = self.find_span(&mut x, last) {
                emit(Span {
                    y: s.origin_y + row,
                    x_start: s.origin_x + start,
                    x_end: s.origin_x + end + 1,
                })?;
            }
        }
        Ok(())
    }

    /// Finds this row's span `start..=end`, leaving `x` and `self.f` at its
    /// start (or, for an empty row, wherever the search stopped).
    fn find_span(&mut self, x: &mut i32, last: i32) -> Option<(i32, i32)> {
        let failing = negative(self.f);
        if failing == 0 {
            // Inside: back up to the start, then on to the end.
            let (f, back) = self.extend(self.f, *x, true);
            self.f = f;
            *x -= back;
            Some((*x, *x + self.extend(self.f, last - *x, false).1))
        } else if failing & self.bound_left == failing {
            // Every failing edge bounds the span from the left: go right.
            loop {
                if *x == last {
                    return None;
                }
                *x += 1;
                self.f = add(self.f, self.a);
                let failing = negative(self.f);
                if failing == 0 {
                    return Some((*x, *x + self.extend(self.f, last - *x, false).1));
                }
                if failing & self.bound_right != 0 {
                    return None;
                }
            }
        } else if failing & self.bound_right == failing {
            // Every failing edge bounds the span from the right: go left to
            // its end, then on to its start.
            loop {
                if *x == 0 {
                    return None;
                }
                *x -= 1;
                self.f = sub(self.f, self.a);
                let failing = negative(self.f);
                if failing == 0 {
                    break;
                }
                if failing & self.bound_left != 0 {
                    return None;
                }
            }
            let end = *x;
            let (f, back) = self.extend(self.f, *x, true);
            self.f = f;
            *x -= back;
            Some((*x, end))
        } else {
            // A horizontal edge fails, or the span would have to lie on
            // both sides: nothing on this row.
            None
        }
    }

    /// From an inside pixel with edge values `g`, moves right (or left if
    /// `back`) while still inside, at most `room` pixels; returns the values
    /// there and the distance moved.
    ///
    /// Lit pixels on a row form one interval, so if the pixel `n` steps
    /// away is inside, so is every pixel in between: after probing one
    /// step, the walk gallops in strides of 16, narrows down with 8, 4 and
    /// 2, and ends with single steps, each a one-comparison test of the
    /// stepped values. It never
    /// steps beyond `room`, so values stay inside the checked range.
    #[inline(always)]
    fn extend(&self, mut g: [T; 3], room: i32, back: bool) -> ([T; 3], i32) {
        let step = |g: [T; 3], d: [T; 3]| if back { sub(g, d) } else { add(g, d) };
        // One probe first: a span's start often moves by 0 or 1 pixel.
        if room == 0 || !inside(step(g, self.a)) {
            return (g, 0);
        }
        let mut n = 0;
        if let Some([d16, d8, d4, d2]) = self.strides {
            while room - n >= STRIDES[0] {
                let t = step(g, d16);
                if !inside(t) {
                    break;
                }
                g = t;
                n += STRIDES[0];
            }
            for (len, d) in [(STRIDES[1], d8), (STRIDES[2], d4), (STRIDES[3], d2)] {
                if room - n >= len {
                    let t = step(g, d);
                    if inside(t) {
                        g = t;
                        n += len;
                    }
                }
            }
        }
        while n < room {
            let t = step(g, self.a);
            if !inside(t) {
                break;
            }
            g = t;
            n += 1;
        }
        (g, n)
    }
}

#[inline(always)]
fn add<T: Step>(f: [T; 3], d: [T; 3]) -> [T; 3] {
    [f[0] + d[0], f[1] + d[1], f[2] + d[2]]
}

#[inline(always)]
fn sub<T: Step>(f: [T; 3], d: [T; 3]) -> [T; 3] {
    [f[0] - d[0], f[1] - d[1], f[2] - d[2]]
}

/// All three edge tests in one comparison: a negative value has its sign
/// bit set, and so does the OR of the three.
#[inline(always)]
fn inside<T: Step>(f: [T; 3]) -> bool {
    (f[0] | f[1] | f[2]) >= T::ZERO
}

/// Bit `k` set iff `F_k < 0`.
#[inline(always)]
fn negative<T: Step>(f: [T; 3]) -> u8 {
    u8::from(f[0] < T::ZERO) | u8::from(f[1] < T::ZERO) << 1 | u8::from(f[2] < T::ZERO) << 2
}

#[cfg(test)]
mod tests {
    use super::*;

    fn setup(q: i64, a: i64, b: i64, width: i32, height: i32) -> Setup {
        Setup {
            origin_x: 0,
            origin_y: 0,
            width,
            height,
            a: [a, 0, 0],
            b: [b, 0, 0],
            q: [q, 0, 0],
        }
    }

    #[test]
    fn narrow_only_when_every_corner_fits() {
        let max = i64::from(i32::MAX);
        let min = i64::from(i32::MIN);
        // F ranges over q + a * (0..w) + b * (0..h).
        assert!(Stepper::<i32>::new(&setup(max - 10, 1, 1, 6, 6)).is_some());
        assert!(Stepper::<i32>::new(&setup(max - 10, 1, 1, 6, 7)).is_none());
        assert!(Stepper::<i32>::new(&setup(min + 10, -1, -1, 6, 6)).is_some());
        assert!(Stepper::<i32>::new(&setup(min + 10, -1, -1, 7, 6)).is_none());
        // Only the lowest corner leaves the range: still too wide.
        assert!(Stepper::<i32>::new(&setup(0, -(1 << 30), 1, 4, 1)).is_none());
        // Steps that do not fit, even when never taken.
        assert!(Stepper::<i32>::new(&setup(0, max + 1, 0, 1, 1)).is_none());
        assert!(Stepper::<i64>::new(&setup(min * 4, 1 << 40, 0, 5, 1)).is_some());
    }
}
