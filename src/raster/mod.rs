//! The raster core every shape uses.
//!
//! - [`wide`]: the one wide-integer abstraction (`i32`, `i64`, `i128`
//!   chosen from a shape's bounds), exact orientation, and division in
//!   the narrowest width the operands fit.
//! - [`frame`]: the pixels of the clip a shape can light, and coordinates
//!   relative to them.
//! - [`edge`]: the exact incremental edge, the threshold column where an
//!   edge crosses each row, stepped in O(1) per row without division (or,
//!   for a line met on one row, found directly by one division).
//! - [`walk`]: the rows between a left and a right edge, for every shape
//!   whose rows two edges cross (triangles, thick lines, y-monotone
//!   polygons).
//! - [`sink`]: where spans go; only sinks touch pixels.

pub(crate) mod edge;
pub(crate) mod frame;
pub(crate) mod sink;
pub(crate) mod walk;
pub(crate) mod wide;

/// A deterministic spread of `u64`s (xorshift64) from `seed`, for the
/// unit tests' random inputs.
#[cfg(test)]
pub(crate) fn xorshift(seed: u64) -> impl Iterator<Item = u64> {
    core::iter::successors(Some(seed), |&x| {
        let x = x ^ (x << 13);
        let x = x ^ (x >> 7);
        Some(x ^ (x << 17))
    })
    .skip(1)
}
