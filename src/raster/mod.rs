//! The raster core every shape uses.
//!
//! - [`wide`]: the one wide-integer abstraction (`i32`, `i64`, `i128`
//!   chosen from a shape's bounds), exact orientation, and division in
//!   the narrowest width the operands fit.
//! - [`frame`]: the pixels of the clip a shape can light, and coordinates
//!   relative to them.
//! - [`edge`]: the exact incremental edge, the threshold column where an
//!   edge crosses each row, stepped in O(1) per row without division.
//! - [`walk`]: the rows between a left and a right edge, for every shape
//!   whose rows two edges cross (triangles, thick lines, y-monotone
//!   polygons).
//! - [`sink`]: where spans go; only sinks touch pixels.

pub(crate) mod edge;
pub(crate) mod frame;
pub(crate) mod sink;
pub(crate) mod walk;
pub(crate) mod wide;
