//! The approximate line variants: a fixed-point DDA and the naive
//! per-pixel multiply-and-round line.
//!
//! Both use the canonical form of [`clip`](super::clip) (so each lights one
//! pixel per step along the major axis, and a line and its reverse light
//! the same pixels) and its exact major-axis clipping; the minor coordinate
//! is approximated per pixel and pixels outside the clip rectangle's minor
//! range are dropped. Ties of the offset round up (away from the canonical
//! start), so the tie rule depends on the slope's sign.
//!
//! Both offsets are non-decreasing in the step `k` (the DDA's is a floor
//! of an increasing affine function; every `f32` operation of the naive
//! line rounds monotonically), so the steps whose pixel lies inside the
//! clip rectangle form one interval. It is found by binary search on the
//! variant's own offset (about 2 log2(steps) evaluations) before stepping:
//! the work is the visible pixels, not the line's extent inside the clip's
//! major range.
//!
//! The DDA's accumulator starts at the first visible pixel (its value
//! there computed exactly from the unclipped start) and carries its
//! integer part into an `i64`, so it never wraps; the naive line's `f32`
//! product of at most `2^32` is exact to convert. Neither can panic or
//! write outside the clip.

use embedded_graphics_core::{pixelcolor::PixelColor, primitives::Rectangle};

use super::{clip::Canonical, draw_segment, fill_run, Line, LineAlgorithm, Run, RunSource};
use crate::raster::sink::{SpanDrawable, SpanSink};

/// A [`StyledLine`](super::StyledLine) whose 1-pixel pixels come from a
/// chosen [`LineAlgorithm`], made by
/// [`StyledLine::algorithm`](super::StyledLine::algorithm): a
/// [`Drawable`](embedded_graphics_core::Drawable). Thick lines are the
/// same rectangles whatever the algorithm.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::BinaryColor, prelude::*};
/// use embedded_raster::{framebuffer::{buffer_size, BinaryMsb}, Framebuffer, Line, LineAlgorithm};
///
/// let mut fb = Framebuffer::<BinaryMsb, 16, 16, { buffer_size::<BinaryMsb>(16, 16) }>::new();
/// Line::new(Point::new(0, 0), Point::new(15, 6))
///     .stroke(BinaryColor::On)
///     .algorithm(LineAlgorithm::Dda)
///     .draw(&mut fb)?;
/// assert_eq!(fb.pixel(Point::new(15, 6)), Some(BinaryColor::On));
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct StyledLineVariant<C> {
    /// The geometry.
    pub line: Line,
    /// The stroke colour.
    pub color: C,
    /// The stroke width in pixels.
    pub width: u32,
    /// How 1-pixel lines choose their pixels.
    pub algorithm: LineAlgorithm,
}

impl<C> StyledLineVariant<C> {
    /// Sets the stroke width in pixels.
    ///
    /// Any `u32`: 0 draws nothing; 1 is the 1-pixel line; 2 and more is a
    /// filled rectangle that wide ([module docs](super#thick-lines)),
    /// widths over 65535 drawn as 65535.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{geometry::Point, pixelcolor::BinaryColor};
    /// use embedded_raster::{Line, LineAlgorithm};
    ///
    /// let s = Line::new(Point::zero(), Point::new(5, 5)).stroke(BinaryColor::On).algorithm(LineAlgorithm::Naive).stroke_width(3);
    /// assert_eq!(s.width, 3);
    /// ```
    pub const fn stroke_width(mut self, width: u32) -> Self {
        self.width = width;
        self
    }

    /// Sets the algorithm of 1-pixel lines.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{geometry::Point, pixelcolor::BinaryColor};
    /// use embedded_raster::{Line, LineAlgorithm};
    ///
    /// let s = Line::new(Point::zero(), Point::new(5, 2)).stroke(BinaryColor::On).algorithm(LineAlgorithm::Naive).algorithm(LineAlgorithm::Dda);
    /// assert_eq!(s.algorithm, LineAlgorithm::Dda);
    /// ```
    pub const fn algorithm(mut self, algorithm: LineAlgorithm) -> Self {
        self.algorithm = algorithm;
        self
    }
}

impl<C: PixelColor> SpanDrawable for StyledLineVariant<C> {
    type Color = C;

    fn draw_spans<S: SpanSink<C>>(&self, sink: &mut S) -> Result<(), S::Error> {
        draw_segment(
            self.line,
            self.width,
            self.algorithm,
            false,
            self.color,
            sink,
        )
    }
}

/// As runs.
impl RunSource for LineAlgorithm {
    fn draw_thin<C: PixelColor, S: SpanSink<C>>(
        self,
        line: &Line,
        skip_end: bool,
        color: C,
        sink: &mut S,
    ) -> Result<(), S::Error> {
        let clip = sink.bounds();
        line.runs(self, &clip, skip_end, &mut |r: Run| {
            fill_run(sink, r, color)
        })
    }
}

/// A variant's minor offset as a function of the step.
#[derive(Debug, Clone, Copy)]
enum Offset {
    /// The slope `dminor / dmajor` in 32.32, rounded to nearest, in
    /// `0..=2^32`.
    Dda(i64),
    /// The slope in `f32`, in `0.0..=1.0`.
    Naive(f32),
}

impl Offset {
    fn new(algorithm: LineAlgorithm, c: &Canonical) -> Option<Self> {
        match algorithm {
            LineAlgorithm::Dda if c.dmajor == 0 => Some(Self::Dda(0)),
            LineAlgorithm::Dda => {
                let num = i128::from(c.dminor) << 32;
                let den = i128::from(c.dmajor);
                Some(Self::Dda(i64::try_from((2 * num + den) / (2 * den)).ok()?))
            }
            LineAlgorithm::Naive if c.dmajor == 0 => Some(Self::Naive(0.0)),
            LineAlgorithm::Naive => Some(Self::Naive(c.dminor as f32 / c.dmajor as f32)),
            LineAlgorithm::Bresenham => None,
        }
    }

    /// The DDA's accumulator after `k` increments, plus 1/2 for rounding:
    /// below 2^65, exact in i128.
    fn acc(slope: i64, k: i64) -> i128 {
        (1i128 << 31) + i128::from(k) * i128::from(slope)
    }

    /// The offset at step `k` (`0 <= k < 2^32`).
    fn at(self, k: i64) -> i64 {
        match self {
            Self::Dda(slope) => i64::try_from(Self::acc(slope, k) >> 32).unwrap_or_default(),
            // Non-negative and at most 2^32 + 1/2, so `as` (truncation)
            // rounds, exactly.
            Self::Naive(slope) => (slope * k as f32 + 0.5) as i64,
        }
    }
}

/// The steps `algorithm` (not Bresenham) lights inside `clip`, and its
/// offset function; `None` if it lights none.
fn steps(
    algorithm: LineAlgorithm,
    c: &Canonical,
    clip: &Rectangle,
    skip_end: bool,
) -> Option<(Offset, i64, i64)> {
    let offset = Offset::new(algorithm, c)?;
    let (lo, hi) = c.major_steps(clip, skip_end)?;
    let (m_lo, m_hi) = c.minor_offsets(clip);
    let (lo, hi) = visible(lo, hi, m_lo, m_hi, |k| offset.at(k))?;
    Some((offset, lo, hi))
}

/// Calls `emit` with the runs `algorithm` (not Bresenham) lights inside
/// `clip`.
pub(crate) fn runs<E>(
    algorithm: LineAlgorithm,
    c: &Canonical,
    clip: &Rectangle,
    skip_end: bool,
    emit: &mut impl FnMut(Run) -> Result<(), E>,
) -> Result<(), E> {
    let Some((offset, lo, hi)) = steps(algorithm, c, clip, skip_end) else {
        return Ok(());
    };
    let (_, (min0, min1)) = c.clip_ranges(clip);
    let mut out = Runs {
        x_major: c.x_major,
        open: None,
    };
    // Inside the major clip range, so every major coordinate fits in i32.
    let major = |k: i64| i32::try_from(c.major0 + k).unwrap_or_default();
    // Every visible step's pixel is inside the clip; checked anyway.
    let mut put = |k: i64, off: i64| {
        let minor = c.minor0 + c.minor_step * off;
        match i32::try_from(minor) {
            Ok(m) if (min0..=min1).contains(&minor) => out.push(major(k), m, emit),
            _ => out.close(emit),
        }
    };
    match offset {
        Offset::Dda(slope) => {
            let mut base = offset.at(lo);
            // The fraction, below 2^32; adding a slope of at most 2^32
            // carries at most 1 into `base`.
            let mut frac = u64::try_from(Offset::acc(slope, lo) & 0xffff_ffff).unwrap_or_default();
            let step = u64::try_from(slope).unwrap_or_default();
            for k in lo..=hi {
                put(k, base)?;
                frac += step;
                base += i64::from(frac >= 1 << 32);
                frac &= 0xffff_ffff;
            }
        }
        Offset::Naive(_) => {
            for k in lo..=hi {
                put(k, offset.at(k))?;
            }
        }
    }
    out.close(emit)
}

/// The steps of `lo..=hi` whose offset, non-decreasing in the step, lies
/// in `m_lo..=m_hi`, by binary search; `None` if there are none.
fn visible(
    lo: i64,
    hi: i64,
    m_lo: i64,
    m_hi: i64,
    offset: impl Fn(i64) -> i64,
) -> Option<(i64, i64)> {
    if offset(lo) >= m_lo && offset(hi) <= m_hi {
        return Some((lo, hi));
    }
    // The first step in `lo..=hi + 1` where `past` holds.
    let first = |past: &dyn Fn(i64) -> bool| {
        let (mut a, mut b) = (lo, hi + 1);
        while a < b {
            let mid = a + (b - a) / 2;
            if past(offset(mid)) {
                b = mid;
            } else {
                a = mid + 1;
            }
        }
        a
    };
    let start = first(&|m| m >= m_lo);
    let end = first(&|m| m > m_hi) - 1;
    (start <= end).then_some((start, end))
}

/// Merges pixels of growing major coordinate into runs.
struct Runs {
    x_major: bool,
    /// The open run: first and last major coordinate, minor coordinate.
    open: Option<(i32, i32, i32)>,
}

impl Runs {
    fn push<E>(
        &mut self,
        major: i32,
        minor: i32,
        emit: &mut impl FnMut(Run) -> Result<(), E>,
    ) -> Result<(), E> {
        match self.open {
            Some((first, _, m)) if m == minor => self.open = Some((first, major, m)),
            _ => {
                self.close(emit)?;
                self.open = Some((major, major, minor));
            }
        }
        Ok(())
    }

    fn close<E>(&mut self, emit: &mut impl FnMut(Run) -> Result<(), E>) -> Result<(), E> {
        match self.open.take() {
            Some((first, last, minor)) => emit(Run::along(self.x_major, first, last, minor)),
            None => Ok(()),
        }
    }
}

#[cfg(test)]
mod tests {
    use embedded_graphics_core::geometry::{Point, Size};
    use std::format;

    use super::*;

    /// Issue 12, item 4: the variants stepped through the whole major
    /// extent inside the clip (2^32 steps for a line across a
    /// `u32::MAX`-wide target, about 20 s) rather than the visible pixels.
    #[test]
    fn issue_12_variants_step_only_the_visible_pixels() {
        let (min, max) = (i32::MIN, i32::MAX);
        let row = |y: i32| Rectangle::new(Point::new(min, y), Size::new(u32::MAX, 1));
        let huge = Rectangle::new(Point::new(min, min), Size::new(u32::MAX, u32::MAX));
        let cases = [
            // The diagonal crosses one row in one pixel.
            ((min, min), (max, max), row(0), 1),
            ((max, min), (min, max), row(-7), 1),
            // Slope about 1/4: four pixels per row.
            ((min, 0), (max, i32::MAX / 2), row(5), 4),
            // A shallow line through the largest target: every step but
            // the last column (the target ends at `i32::MAX - 1`).
            ((min, 0), (max, 1), huge, (1 << 32) - 1),
            // Outside the target's minor range: nothing.
            ((min, 10), (max, 20), row(0), 0),
        ];
        for algorithm in [LineAlgorithm::Dda, LineAlgorithm::Naive] {
            for (a, b, clip, want) in cases {
                for (a, b) in [(a, b), (b, a)] {
                    let c = Canonical::new(Point::new(a.0, a.1), Point::new(b.0, b.1));
                    let n = steps(algorithm, &c, &clip, false).map_or(0, |(_, lo, hi)| hi - lo + 1);
                    let case = format!("{algorithm:?} {a:?} {b:?} {clip:?}");
                    if algorithm == LineAlgorithm::Dda || want == 0 || want > 4 {
                        assert_eq!(n, want, "{case}");
                    } else {
                        // Past 2^24 steps the naive line's `f32` step index
                        // moves in units of up to 256, so its pixels come
                        // in flat runs of up to 256 per minor coordinate,
                        // and some minor coordinates get none.
                        assert!(n <= 256 * want, "{case}: {n}");
                    }
                    if n > 1024 {
                        continue;
                    }
                    // The pixels drawn are exactly those steps.
                    let mut pixels = 0;
                    runs(algorithm, &c, &clip, false, &mut |r| {
                        pixels += i64::from(r.len);
                        Ok::<(), ()>(())
                    })
                    .unwrap();
                    assert_eq!(pixels, n, "{case}");
                }
            }
        }
    }
}
