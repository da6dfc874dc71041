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

/// Calls `emit` with the runs of the visible part `v` of `c`, in order of
/// growing major coordinate.
pub(crate) fn runs<E>(
    c: &Canonical,
    v: &Visible,
    emit: &mut impl FnMut(Run) -> Result<(), E>,
) -> Result<(), E> {
    match (c.x_major, c.dmajor < 1 << 30) {
        (true, true) => step::<i32, true, E>(c, v, emit),
        (true, false) => step::<i64, true, E>(c, v, emit),
        (false, true) => step::<i32, false, E>(c, v, emit),
        (false, false) => step::<i64, false, E>(c, v, emit),
    }
}

#[inline(always)]
fn step<T: Wide, const X_MAJOR: bool, E>(
    c: &Canonical,
    v: &Visible,
    emit: &mut impl FnMut(Run) -> Result<(), E>,
) -> Result<(), E> {
    // Within [-2 dmajor, 2 dmajor]: `runs` picks a width that holds them.
    let (Some(two_minor), Some(two_major), Some(mut d)) = (
        T::narrow(2 * c.dminor),
        T::narrow(2 * c.dmajor),
        T::narrow(v.decision),
    ) else {
        return Ok(());
    };
    let s: i32 = if c.minor_step > 0 { 1 } else { -1 };
    let (mut major, last, mut minor) = (v.first_major, v.last_major, v.first_minor);
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
