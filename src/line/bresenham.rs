//! The integer midpoint (Bresenham) stepping loop, emitting runs.
//!
//! Starting from the exactly clipped first pixel and decision variable (see
//! [`clip`](super::clip)), each step adds `2 dminor` to the decision
//! variable and, when it is not negative, ends the current run, moves one
//! pixel along the minor axis and subtracts `2 dmajor`. One add per pixel,
//! one compare, no multiply or divide. The variable stays within
//! `[-2 dmajor, 2 dmajor]`, so the loop runs in `i32` for lines shorter
//! than `2^30` pixels along their major axis and in `i64` otherwise.

use super::{
    clip::{Canonical, Visible},
    Run,
};
use crate::raster::wide::Wide;
use embedded_graphics_core::geometry::Point;

/// Calls `emit` with the runs of the pixels `p` has left to iterate, in
/// order of growing major coordinate.
pub(crate) fn runs<E>(
    p: &LinePixels,
    emit: &mut impl FnMut(Run) -> Result<(), E>,
) -> Result<(), E> {
    // Iterated to its end: no run (the steps below start at a pixel).
    if p.is_empty() {
        return Ok(());
    }
    match (p.x_major, p.dmajor < 1 << 30) {
        (true, true) => step::<i32, true, E>(p, emit),
        (true, false) => step::<i64, true, E>(p, emit),
        (false, true) => step::<i32, false, E>(p, emit),
        (false, false) => step::<i64, false, E>(p, emit),
    }
}

#[inline(always)]
fn step<T: Wide, const X_MAJOR: bool, E>(
    p: &LinePixels,
    emit: &mut impl FnMut(Run) -> Result<(), E>,
) -> Result<(), E> {
    // Within [-2 dmajor, 2 dmajor]: `runs` picks a width that holds them.
    let (Some(two_minor), Some(two_major), Some(mut d)) = (
        T::narrow(2 * p.dminor),
        T::narrow(2 * p.dmajor),
        T::narrow(p.decision),
    ) else {
        return Ok(());
    };
    let s = p.minor_step;
    let (mut major, last, mut minor) = (p.first_major, p.last_major, p.first_minor);
    if p.dminor == 0 {
        // An axis-aligned line never moves along its minor axis (its
        // decision stays below 2 dminor = 0): one run, found without
        // stepping.
        return emit(Run::along(X_MAJOR, major, last, minor));
    }
    let mut start = major;
    loop {
        if major == last {
            return emit(Run::along(X_MAJOR, start, major, minor));
        }
        if d >= T::ZERO {
            emit(Run::along(X_MAJOR, start, major, minor))?;
            d = d - two_major;
            // The next pixel is a pixel of the line: no overflow.
            minor += s;
            start = major + 1;
        }
        d = d + two_minor;
        major += 1;
    }
}

/// The pixels a 1-pixel [`Line`](super::Line) lights inside a sink's
/// bounds, in order of growing major coordinate: what
/// [`SpanSink::fill_line`](crate::SpanSink::fill_line) receives.
///
/// It iterates over the pixels as [`Point`]s and, with
/// [`for_each_run`](Self::for_each_run), over the same pixels as
/// [`Run`]s. A sink that knows its memory (the crate's
/// [`Framebuffer`](crate::Framebuffer)) walks the pixels itself, one add
/// and one compare of the Bresenham decision per pixel.
///
/// Made only by the crate, for lines with any `i32` end points and any
/// clip rectangle: its pixels and its [`len`](Self::len) (at most `2^32`,
/// reported saturated at `u32::MAX`) are in `i32` and the decision
/// variable within `[-2^33, 2^33]`, so iterating never overflows, up to a
/// last pixel at either end of the `i32` range.
///
/// # Examples
///
/// ```
/// use core::convert::Infallible;
/// use embedded_graphics::{geometry::{Point, Size}, pixelcolor::BinaryColor, primitives::Rectangle};
/// use embedded_raster::{line::LinePixels, Line, Span, SpanDrawable, SpanSink};
///
/// /// Records the pixels of the lines drawn into it.
/// struct Pixels(Vec<Point>);
///
/// impl SpanSink<BinaryColor> for Pixels {
///     type Error = Infallible;
///     fn bounds(&self) -> Rectangle {
///         Rectangle::new(Point::zero(), Size::new(8, 8))
///     }
///     fn fill_span(&mut self, _: Span, _: BinaryColor) -> Result<(), Infallible> {
///         Ok(())
///     }
///     fn fill_line(&mut self, pixels: LinePixels, _: BinaryColor) -> Result<(), Infallible> {
///         self.0.extend(pixels);
///         Ok(())
///     }
/// }
///
/// let mut sink = Pixels(Vec::new());
/// Line::new(Point::new(0, 0), Point::new(4, 2)).stroke(BinaryColor::On).draw_spans(&mut sink)?;
/// let want = [(0, 0), (1, 0), (2, 1), (3, 1), (4, 2)].map(|(x, y)| Point::new(x, y));
/// assert_eq!(sink.0, want);
/// # Ok::<(), Infallible>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LinePixels {
    /// Whether x is the major axis.
    x_major: bool,
    /// +1 or -1: how the minor coordinate moves.
    minor_step: i32,
    /// The first and last major coordinate, and the first minor one.
    first_major: i32,
    last_major: i32,
    first_minor: i32,
    /// A minor coordinate inside the clip the pixels were listed in that
    /// none passes: every pixel's lies between `first_minor` and it.
    minor_bound: i32,
    /// The decision variable at the first pixel, and the line's whole
    /// major and minor extents (`0 <= dminor <= dmajor < 2^32`).
    decision: i64,
    dmajor: i64,
    dminor: i64,
}

impl LinePixels {
    /// The visible part `v` of the canonical line `c`.
    pub(crate) fn new(c: &Canonical, v: Visible) -> Self {
        Self {
            x_major: c.x_major,
            minor_step: if c.minor_step > 0 { 1 } else { -1 },
            first_major: v.first_major,
            last_major: v.last_major,
            first_minor: v.first_minor,
            minor_bound: v.minor_bound,
            decision: v.decision,
            dmajor: c.dmajor,
            dminor: c.dminor,
        }
    }

    /// The same pixels moved down by `dy` rows, or `None` if a coordinate
    /// would leave `i32`.
    pub(crate) fn moved_down(self, dy: i32) -> Option<Self> {
        let mut moved = self;
        if self.x_major {
            moved.first_minor = self.first_minor.checked_add(dy)?;
            moved.minor_bound = self.minor_bound.checked_add(dy)?;
        } else {
            moved.first_major = self.first_major.checked_add(dy)?;
            moved.last_major = self.last_major.checked_add(dy)?;
        }
        Some(moved)
    }

    /// The number of pixels (left to iterate).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{geometry::{Point, Size}, primitives::Rectangle};
    /// use embedded_raster::Line;
    ///
    /// let clip = Rectangle::new(Point::zero(), Size::new(8, 8));
    /// let pixels = Line::new(Point::new(-5, 1), Point::new(20, 3)).pixels(&clip).unwrap();
    /// assert_eq!(pixels.len(), 8);
    /// ```
    pub fn len(&self) -> u32 {
        // `abs_diff` of two `i32`s fits `u32`; `+ 1` saturates.
        if self.first_major > self.last_major {
            return 0;
        }
        self.last_major.abs_diff(self.first_major).saturating_add(1)
    }

    /// Whether no pixel is left (never for a line just made: an empty
    /// line has no `LinePixels`).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{geometry::{Point, Size}, primitives::Rectangle};
    /// use embedded_raster::Line;
    ///
    /// let clip = Rectangle::new(Point::zero(), Size::new(8, 8));
    /// let mut pixels = Line::new(Point::zero(), Point::zero()).pixels(&clip).unwrap();
    /// assert!(!pixels.is_empty());
    /// assert_eq!(pixels.next(), Some(Point::zero()));
    /// assert!(pixels.is_empty());
    /// ```
    pub fn is_empty(&self) -> bool {
        self.first_major > self.last_major
    }

    /// Calls `f` with the same pixels as horizontal runs (an x-major line)
    /// or vertical runs (a y-major one), in order, stopping at the first
    /// error.
    ///
    /// # Examples
    ///
    /// ```
    /// use core::convert::Infallible;
    /// use embedded_graphics::{geometry::{Point, Size}, primitives::Rectangle};
    /// use embedded_raster::Line;
    ///
    /// let clip = Rectangle::new(Point::zero(), Size::new(8, 8));
    /// let pixels = Line::new(Point::new(0, 0), Point::new(4, 2)).pixels(&clip).unwrap();
    /// let mut lens = Vec::new();
    /// pixels.for_each_run(|r| {
    ///     lens.push(r.len);
    ///     Ok::<(), Infallible>(())
    /// })?;
    /// assert_eq!(lens, [2, 2, 1]);
    /// # Ok::<(), Infallible>(())
    /// ```
    pub fn for_each_run<E>(&self, mut f: impl FnMut(Run) -> Result<(), E>) -> Result<(), E> {
        runs(self, &mut f)
    }

    /// Whether the line's runs are long: it is axis-aligned (one run), or
    /// x-major and moves along its minor axis less than once per four
    /// pixels (spans of four pixels or more).
    pub(crate) fn has_long_runs(&self) -> bool {
        // dminor < 2^32: four times it fits i64.
        self.dminor == 0 || (self.x_major && 4 * self.dminor < self.dmajor)
    }

    /// Whether every pixel left is known to lie in columns `xs` and rows
    /// `ys` (inclusive `(first, last)` ranges, empty if `last < first`),
    /// without iterating: the first pixel, the last major coordinate and
    /// the minor bound (a coordinate inside the clip the pixels were
    /// listed in, which no pixel passes) all do, as the pixels move one
    /// way along each axis. Always true for pixels listed in a clip
    /// inside those ranges (as the crate's shapes list them, in the
    /// sink's own bounds); possibly false for others even if they lie
    /// inside. A line iterated to its end may answer either: it lights
    /// nothing. 32-bit compares only (ranges given as constants fold): for
    /// sinks that must not trust their callers to have clipped.
    #[inline(always)]
    pub(crate) fn known_inside(&self, xs: (i32, i32), ys: (i32, i32)) -> bool {
        let (major, minor) = match self.x_major {
            true => (xs, ys),
            false => (ys, xs),
        };
        let within = |v: i32, (first, last): (i32, i32)| first <= v && v <= last;
        within(self.first_major, major)
            && within(self.last_major, major)
            && within(self.first_minor, minor)
            && within(self.minor_bound, minor)
    }

    /// Whether the line is x-major (one pixel per column).
    pub(crate) fn x_major(&self) -> bool {
        self.x_major
    }

    /// Walks the pixels with an index that moves by `major` per pixel and
    /// by `minor` more where the line moves along its minor axis, starting
    /// at `first`, calling `plot` with each index: for sinks that address
    /// their memory themselves. The decision variable is kept in the
    /// narrowest width that holds it. At least one pixel must be left: the
    /// first is plotted unconditionally. The caller checks it (in
    /// `walks_by_index`): checked here, before the loop, it changed how
    /// the loop compiled, and a 200 px line on a Cortex-M4 took 2,349 or
    /// 2,501 instructions (two ways of writing it) instead of 2,199
    /// (`.ci/icount`).
    #[inline(always)]
    pub(crate) fn walk(&self, first: isize, major: isize, minor: isize, plot: impl FnMut(isize)) {
        debug_assert!(!self.is_empty());
        if self.dmajor < 1 << 30 {
            self.walk_in::<i32>(first, major, minor, plot);
        } else {
            self.walk_in::<i64>(first, major, minor, plot);
        }
    }

    #[inline(always)]
    fn walk_in<T: Wide>(
        &self,
        first: isize,
        major: isize,
        minor: isize,
        mut plot: impl FnMut(isize),
    ) {
        // Within [-2 dmajor, 2 dmajor]: `walk` picks a width that holds them.
        let (Some(two_minor), Some(two_major), Some(mut d)) = (
            T::narrow(2 * self.dminor),
            T::narrow(2 * self.dmajor),
            T::narrow(self.decision),
        ) else {
            return;
        };
        // One step along both axes where the line moves, else along the
        // major one: one select per pixel.
        let diagonal = major + minor;
        let mut at = first;
        plot(at);
        for _ in 1..self.len() {
            let moves = d >= T::ZERO;
            d = d + (two_minor - if moves { two_major } else { T::ZERO });
            at += if moves { diagonal } else { major };
            plot(at);
        }
    }

    /// The first pixel.
    pub(crate) fn first(&self) -> Point {
        if self.x_major {
            Point::new(self.first_major, self.first_minor)
        } else {
            Point::new(self.first_minor, self.first_major)
        }
    }

    /// +1 or -1: how the minor coordinate moves.
    pub(crate) fn minor_step(&self) -> i32 {
        self.minor_step
    }
}

/// The pixels one by one.
impl Iterator for LinePixels {
    type Item = Point;

    fn next(&mut self) -> Option<Point> {
        if self.first_major > self.last_major {
            return None;
        }
        let p = self.first();
        if self.first_major < self.last_major {
            let d = self.decision;
            let moves = d >= 0;
            // |d| <= 2 dmajor < 2^33 throughout.
            self.decision = d + 2 * self.dminor - if moves { 2 * self.dmajor } else { 0 };
            if moves {
                self.first_minor += self.minor_step;
            }
            self.first_major += 1;
        } else {
            // Past the end: an empty range, without stepping beyond `i32`
            // (the last pixel may sit at `i32::MIN` or `i32::MAX`).
            (self.first_major, self.last_major) = (i32::MAX, i32::MIN);
        }
        Some(p)
    }
}

#[cfg(test)]
mod tests {
    use embedded_graphics_core::{
        geometry::{Point, Size},
        primitives::Rectangle,
    };

    use crate::{clip::Bounds, line::Line};

    /// A rectangle's columns and rows as inclusive ranges (both within 40
    /// px of the origin here).
    fn ranges(r: &Rectangle) -> ((i32, i32), (i32, i32)) {
        let (x, y) = (r.top_left.x, r.top_left.y);
        let (w, h) = (r.size.width as i32, r.size.height as i32);
        ((x, x + w - 1), (y, y + h - 1))
    }

    /// [`LinePixels::known_inside`] against its pixels, iterated: random
    /// short lines listed in a clip, partly iterated. Sound: never true
    /// when a pixel left lies outside the bounds tested (random bounds at,
    /// just inside and just outside the pixels' bounding box). Complete
    /// where it must be: true in any bounds holding the clip.
    #[test]
    fn known_inside_only_when_every_pixel_left_is() {
        let mut random = crate::raster::xorshift(0x2545_F491_4F6C_DD1D);
        let mut next = |n: u64| (random.next().unwrap_or(0) % n) as i32;
        let (mut inside, mut outside) = (0, 0);
        for _ in 0..20_000 {
            let clip = Rectangle::new(
                Point::new(next(41) - 20, next(41) - 20),
                Size::new(next(40) as u32, next(40) as u32),
            );
            let mut at = || Point::new(next(81) - 40, next(81) - 40);
            let line = Line::new(at(), at());
            let Some(mut pixels) = line.pixels(&clip) else {
                continue;
            };
            for _ in 0..next(4) {
                pixels.next();
            }
            if pixels.is_empty() {
                continue;
            }
            // In the clip, and in anything holding it.
            let (grow, shift) = (next(3) as u32, next(3) - 1);
            let around = Rectangle::new(
                clip.top_left - Point::new(grow as i32 + shift, grow as i32),
                clip.size + Size::new(2 * grow + 1, 2 * grow),
            );
            if Bounds::of(&around).intersect(Bounds::of(&clip)) == Some(Bounds::of(&clip)) {
                assert!(
                    pixels.known_inside(ranges(&around).0, ranges(&around).1),
                    "{line:?} in {clip:?}"
                );
            }
            // The pixels' bounding box, each side moved by -1, 0 or 1.
            let (lo, hi) = { pixels }.fold(
                (
                    Point::new(i32::MAX, i32::MAX),
                    Point::new(i32::MIN, i32::MIN),
                ),
                |(lo, hi), p| (lo.component_min(p), hi.component_max(p)),
            );
            let mut jitter = || next(3) - 1;
            let (x0, y0) = (lo.x + jitter(), lo.y + jitter());
            let (x1, y1) = (hi.x + 1 + jitter(), hi.y + 1 + jitter());
            let size = |a: i32, b: i32| (b - a).max(0) as u32;
            let area = Rectangle::new(Point::new(x0, y0), Size::new(size(x0, x1), size(y0, y1)));
            let every = { pixels }.all(|p| area.contains(p));
            if pixels.known_inside(ranges(&area).0, ranges(&area).1) {
                assert!(every, "{line:?} from {:?} in {area:?}", pixels.first());
                inside += 1;
            } else if !every {
                outside += 1;
            }
        }
        // Both answers occur often (a minor bound on the clip's edge is
        // outside most of these tight boxes, so true is the rarer).
        assert!(inside > 300 && outside > 2_000, "{inside} {outside}");
    }
}
