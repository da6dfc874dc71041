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
//! The DDA's accumulator starts at the first visible pixel (its value
//! there computed exactly from the unclipped start) and wraps after `2^31`
//! visible pixels, far beyond any display; the naive line's `f32` product
//! saturates when converted. Neither can panic or write outside the clip.

use embedded_graphics_core::primitives::Rectangle;
use fixed::types::I32F32;

use super::{clip::Canonical, LineAlgorithm, Run};

/// Calls `emit` with the runs `algorithm` (not Bresenham) lights inside
/// `clip`.
pub(crate) fn runs<E>(
    algorithm: LineAlgorithm,
    c: &Canonical,
    clip: &Rectangle,
    skip_end: bool,
    emit: &mut impl FnMut(Run) -> Result<(), E>,
) -> Result<(), E> {
    let Some((lo, hi)) = c.major_steps(clip, skip_end) else {
        return Ok(());
    };
    let (_, (min0, min1)) = c.clip_ranges(clip);
    let mut out = Runs {
        x_major: c.x_major,
        open: None,
    };
    // Inside the major clip range, so every major coordinate fits in i32.
    let major = |k: i64| i32::try_from(c.major0 + k).unwrap_or_default();
    let mut put = |k: i64, off: i64| {
        let minor = c.minor0 + c.minor_step * off;
        match i32::try_from(minor) {
            Ok(m) if (min0..=min1).contains(&minor) => out.push(major(k), m, emit),
            _ => out.close(emit),
        }
    };
    match algorithm {
        LineAlgorithm::Dda => {
            // slope = dminor / dmajor in 32.32, rounded to nearest.
            let slope = if c.dmajor == 0 {
                0
            } else {
                let num = i128::from(c.dminor) << 32;
                let den = i128::from(c.dmajor);
                i64::try_from((2 * num + den) / (2 * den)).unwrap_or_default()
            };
            // The accumulator after `lo` increments, plus 1/2 for rounding:
            // its integer part goes to `base`, the rest starts the loop.
            let acc = (1i128 << 31) + i128::from(lo) * i128::from(slope);
            let base = i64::try_from(acc >> 32).unwrap_or_default();
            let mut frac = I32F32::from_bits(i64::try_from(acc & 0xffff_ffff).unwrap_or_default());
            let step = I32F32::from_bits(slope);
            for k in lo..=hi {
                put(k, base + (frac.to_bits() >> 32))?;
                frac = frac.wrapping_add(step);
            }
        }
        LineAlgorithm::Naive => {
            let slope = if c.dmajor == 0 {
                0.0
            } else {
                c.dminor as f32 / c.dmajor as f32
            };
            for k in lo..=hi {
                // Non-negative, so `as` (truncation, saturating) rounds.
                put(k, (slope * k as f32 + 0.5) as i64)?;
            }
        }
        LineAlgorithm::Bresenham => {}
    }
    out.close(emit)
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
