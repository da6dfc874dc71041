//! Overflow-free rectangle clipping, shared by every target in the crate.

use embedded_graphics_core::primitives::Rectangle;

/// Half-open pixel bounds `x0..x1`, `y0..y1` of a rectangle, in `i64` so
/// that any `Rectangle` (top-left near `i32::MAX`, size up to `u32::MAX`)
/// is represented without overflow.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Bounds {
    pub x0: i64,
    pub y0: i64,
    pub x1: i64,
    pub y1: i64,
}

impl Bounds {
    /// The pixels of `r`; empty (`x0 == x1` or `y0 == y1`) for a zero size.
    pub fn of(r: &Rectangle) -> Self {
        let x0 = i64::from(r.top_left.x);
        let y0 = i64::from(r.top_left.y);
        Self {
            x0,
            y0,
            x1: x0 + i64::from(r.size.width),
            y1: y0 + i64::from(r.size.height),
        }
    }

    /// The rectangle of these bounds, which must lie in `i32` coordinates
    /// with `u32` sides (they do when inside a `Rectangle`); anything
    /// else saturates.
    pub fn to_rectangle(self) -> Rectangle {
        let at = |v: i64| v.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32;
        let side = |a: i64, b: i64| b.saturating_sub(a).clamp(0, i64::from(u32::MAX)) as u32;
        Rectangle::new(
            embedded_graphics_core::geometry::Point::new(at(self.x0), at(self.y0)),
            embedded_graphics_core::geometry::Size::new(
                side(self.x0, self.x1),
                side(self.y0, self.y1),
            ),
        )
    }

    /// The pixels in both `self` and `other`, or `None` if there are none.
    pub fn intersect(self, other: Self) -> Option<Self> {
        let b = Self {
            x0: self.x0.max(other.x0),
            y0: self.y0.max(other.y0),
            x1: self.x1.min(other.x1),
            y1: self.y1.min(other.y1),
        };
        (b.x0 < b.x1 && b.y0 < b.y1).then_some(b)
    }
}

/// The part of `area` inside `bounds`, as pixel ranges relative to the
/// top-left of `bounds`: `(x_range, y_range)`, both non-empty. `None` if
/// nothing of `area` is inside.
pub(crate) fn clip_to(
    area: &Rectangle,
    bounds: &Rectangle,
) -> Option<(core::ops::Range<usize>, core::ops::Range<usize>)> {
    let outer = Bounds::of(bounds);
    let b = Bounds::of(area).intersect(outer)?;
    // Both differences lie in 0..=u32::MAX because `b` is inside `outer`.
    let rel = |v: i64, o: i64| usize::try_from(v - o).ok();
    Some((
        rel(b.x0, outer.x0)?..rel(b.x1, outer.x0)?,
        rel(b.y0, outer.y0)?..rel(b.y1, outer.y0)?,
    ))
}

/// Where the part of `area` inside `bounds` lies among `area`'s pixels in
/// row-major order: `(skip, gap)`, the number of `area`'s pixels before
/// the first one inside, and between the last one inside on a row and the
/// first one inside on the next. `None` if nothing of `area` is inside.
pub(crate) fn row_major_skips(area: &Rectangle, bounds: &Rectangle) -> Option<(u64, u64)> {
    let a = Bounds::of(area);
    let b = a.intersect(Bounds::of(bounds))?;
    // Each difference lies in 0..=u32::MAX because `b` is inside `a`, so
    // `skip` is at most (2^32 - 1) * (2^32 - 1) + 2^32 - 1 < 2^64.
    let diff = |v: i64, o: i64| u64::try_from(v - o).ok();
    let width = u64::from(area.size.width);
    let skip = diff(b.y0, a.y0)?
        .checked_mul(width)?
        .checked_add(diff(b.x0, a.x0)?)?;
    Some((skip, width.checked_sub(diff(b.x1, b.x0)?)?))
}

/// Advances `iter` by `n` items; `false` if it ended first.
pub(crate) fn advance<I: Iterator>(iter: &mut I, mut n: u64) -> bool {
    while n > 0 {
        // `nth` skips in O(1) on many iterators, e.g. `repeat` and slices.
        let step = usize::try_from(n).unwrap_or(usize::MAX);
        if iter.nth(step - 1).is_none() {
            return false;
        }
        n -= step as u64; // `step <= n`, and `usize` has at most 64 bits.
    }
    true
}

/// The part of `area` inside `bounds`, or `None` if there is none.
pub(crate) fn clip_rect(area: &Rectangle, bounds: &Rectangle) -> Option<Rectangle> {
    Some(
        Bounds::of(area)
            .intersect(Bounds::of(bounds))?
            .to_rectangle(),
    )
}
