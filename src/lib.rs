//! Exact, allocation-free rasterization for microcontroller displays.
//!
//! `embedded-raster` fills shapes pixel-exactly in integer arithmetic and
//! draws them on any [`embedded-graphics`] [`DrawTarget`], fastest on its
//! own [`Framebuffer`]. The same code runs on a Cortex-M and, with the `sim`
//! feature, in a host simulator that renders scene files to PNG.
//!
//! ```toml
//! [dependencies]
//! embedded-raster = "0.1"
//! embedded-graphics = "0.8"
//! ```
//!
//! # Example
//!
//! A triangle with fractional vertices, drawn into a 320 x 240 Rgb565
//! framebuffer whose bytes go to the display as they are:
//!
//! ```
//! use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
//! use embedded_raster::{
//!     framebuffer::{buffer_size, Rgb565Be},
//!     prelude::*,
//!     Framebuffer, Vertex,
//! };
//!
//! let mut fb = Framebuffer::<Rgb565Be, 320, 240, { buffer_size::<Rgb565Be>(320, 240) }>::new();
//! fb.clear(Rgb565::BLACK)?;
//!
//! let v = |x: f32, y: f32| Vertex::try_from_num(x, y);
//! embedded_raster::Triangle::new(v(10.0, 12.5)?, v(300.25, 40.0)?, v(120.0, 230.75)?)
//!     .fill(Rgb565::RED)
//!     .draw_spans(&mut fb)?; // straight into the rows; `.draw(&mut fb)` works too
//!
//! assert_eq!(fb.pixel(Point::new(120, 200)), Some(Rgb565::RED));
//! let bytes: &[u8] = fb.as_bytes(); // big-endian Rgb565, as SPI panels take it
//! assert_eq!(bytes.len(), 320 * 240 * 2);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # Map
//!
//! | module | what it holds |
//! |---|---|
//! | [`Vertex`] | 20.12 fixed-point positions (12 fractional bits) |
//! | [`Triangle`], [`FilledTriangle`] | the exact triangle rasterizer (the long edge and one short edge per row, split at the middle vertex) and its [`Drawable`] |
//! | [`Span`] | the horizontal runs every filled shape is rasterized into |
//! | [`SpanSink`], [`SpanDrawable`], [`DrawTargetSink`] | where shapes write their pixels, already clipped: [`Framebuffer`] straight into its rows, any [`DrawTarget`] through [`DrawTargetSink`] |
//! | `raster` (private) | the one raster core: the wide-integer abstraction and exact orientation, the scan frame, the exact incremental edge (O(1) per row, quotient and remainder), the sink traits |
//! | [`TriangleAlgorithm`], [`SubpixelPrecision`] | selectable triangle variants (exact edge equations, barycentric bounding-box test, fixed-point edge walking, Bresenham edge walking) and vertex snapping to 0, 4, 8 or 12 subpixel bits, for trading accuracy for speed (measured in `BENCHMARKS.md`) |
//! | [`line`](mod@line) | [`Line`], [`Polyline`] and their styles: exact Bresenham lines between any `i32` pixels, clipped before stepping (tie rule: the smaller coordinate), emitted as [`Run`]s; [`LineAlgorithm`] variants (DDA, naive); thick lines as filled rectangles |
//! | [`Join`], [`MITER_LIMIT`], [`StrokedTriangle`], [`StrokedPolygon`] | strokes (`stroke` private): thick polylines and the outlines of triangles and polygons as one exact union of segment rectangles and miter, bevel or round joins, filled row by row with each pixel written once, no heap |
//! | [`Polygon`], [`FilledPolygon`], [`FillRule`] | the exact active-edge-table fill (even-odd and non-zero) with `heapless` storage of a chosen capacity, ear-clipping and fan triangulation, exact simple and convex tests |
//! | [`shade`], [`GouraudTriangle`] | shading: the rounded average of vertex colours, Gouraud blends within 1 unit per channel (no per-pixel division), interpolated `u16` depth tested against a caller's [`DepthBuffer`](shade::DepthBuffer), each a separate type so flat-only code links none of it |
//! | [`delaunay`] | Delaunay triangulation of up to `N` points in fixed storage ([`Delaunay`](delaunay::Delaunay)), incremental with Lawson flips, exact integer orientation and in-circle tests over the whole 20.12 range, deterministic on duplicates, collinear and cocircular points |
//! | [`mesh`] | fixed-point 3D without floats: table sine/cosine, rotation, perspective projection to vertices and depths, an allocation-free latitude/longitude sphere |
//! | [`framebuffer`] | [`Framebuffer`], an owned const-sized [`DrawTarget`] and [`SpanSink`] for Rgb565 and Bgr565 (both byte orders), Rgb888, 18-bit Rgb666, Gray8, Gray4 and Gray2 (both packing orders) and 1-bit, filled with `memset` and aligned word stores |
//! | `sim` (feature `sim`) | the host simulator: an overdraw-counting display, PNG export, the scene-file renderer |
//! | [`band`] | drawing without a full framebuffer: [`DisplayList`](band::DisplayList) rendered band by band into a buffer of a few rows (flat triangles continued from band to band), [`Band`](band::Band), [`WriteTo`](band::WriteTo) a display driver, [`DirtyRows`](band::DirtyRows) for partial updates |
//! | [`prelude`] | the crate's traits, to glob-import beside embedded-graphics' prelude without name clashes |
//! | `convert` (feature `embedded-graphics`, private) | [`Triangle`], [`Line`] and [`Polyline`] from embedded-graphics' shapes of the same name |
//!
//! # The sampling rule
//!
//! The plane is continuous with y pointing down; pixel `(i, j)` covers
//! `[i, i + 1) x [j, j + 1)` and its centre is `(i + 1/2, j + 1/2)`. A filled
//! shape lights a pixel iff its centre, nudged by `(e, e^2)` for an
//! infinitesimal `e > 0`, is inside. For a triangle this is the Direct3D
//! top-left rule: a centre exactly on a left edge, or on a horizontal edge
//! with the interior below it, is lit; on a right or bottom edge it is not.
//! Shapes that share an edge light each pixel along it exactly once, so a
//! mesh has no gaps and no overdraw.
//!
//! # Ranges
//!
//! Vertex coordinates are 20.12 fixed point: multiples of 1/4096 in
//! `[-524288, 524288 - 1/4096]`. Every [`Vertex`] is in range; conversions
//! from numbers, strings and [`Point`]s are checked and report
//! [`CoordinateOutOfRange`]. Any triangle of in-range vertices is
//! rasterized exactly, on any clip rectangle. Per triangle, the edges
//! step in 32 bits when the triangle's bounding box spans under 2^29 raw
//! units (131,072 px) a side and in 64 bits otherwise; their setup divides
//! in 32 bits when the operands fit and in 64 bits only when they do not
//! (never wider).
//!
//! Every numeric input, its range, and what happens outside it (each
//! function's docs say the same; arithmetic inside these ranges is proven
//! not to overflow in comments, with no reliance on wraparound, and the
//! tests run with overflow checks):
//!
//! | Input | Valid range | Outside it |
//! |---|---|---|
//! | [`Vertex`] coordinates (triangles, polygons, Gouraud, depth, [`delaunay`]) | 20.12: `[-524288, 524288 - 1/4096]`; every `Vertex` and every raw `i32` ([`Vertex::from_raw`]) | conversions return [`CoordinateOutOfRange`], parsing [`ParseCoordinateError`] |
//! | [`Point`] to `Vertex` ([`Triangle::from_points`]) | `-524288..=524287` | [`CoordinateOutOfRange`] |
//! | [`Line`] and [`Polyline`] points | any `i32` | none: 1-pixel and thick lines and polylines exact everywhere, clipped |
//! | stroke width | any `u32` | 0 draws nothing, over 65535 drawn as 65535 |
//! | clip rectangles, target bounds | any `Rectangle`, even past `i32::MAX` | clipped; empty ones draw nothing |
//! | [`Span`], [`Run`], [`SpanSink`] coordinates and lengths | any `i32` / `u32` | empty spans draw nothing; sums saturate at `i32::MAX` |
//! | [`Polygon`] vertex count | `3..=N` | [`PolygonError`] |
//! | [`delaunay::Delaunay`] points | up to `N <= 32767` | `N` checked at compile time; more points: [`delaunay::DelaunayError`] |
//! | colours ([`shade::ShadeColor`]) | each channel `0..=MAX` (`Rgb565` and `Bgr565` 31/63/31, `Rgb555`, `Bgr555` 31, `Rgb666`, `Bgr666` 63, `Rgb888`, `Bgr888`, `Gray8` 255, `Gray4` 15, `Gray2` 3, `BinaryColor` 1) | high bits dropped as the colours' `new` does |
//! | depths ([`shade::DepthBuffer`]) | any `u16` (`FAR` never passes); any width and storage | width 0: no rows, nothing passes |
//! | [`framebuffer`] sizes `W`, `H` | [`framebuffer::buffer_size`] fits `usize` | compile-time error |
//! | [`band::DisplayList`] commands | up to its capacity `N` | [`band::DisplayListFull`], nothing added or lost |
//! | band rendering: screen height, buffers, depth storage | any `u32` height (rows past `i32::MAX` are not drawn); buffers as wide as the screen; depth storage for one buffer's pixels | no buffer or rows: nothing drawn; depth storage short of a band: depth-tested pixels of its missing rows are not drawn |
//! | `PixelFormat` pixel indices | any `usize` | pixels outside the row are not written |
//! | [`mesh`] vectors, angles, camera | any `i32` / `u16` (module docs) | results saturate, or `None` from `checked_*` and `Camera::project` |
//!
//! # No panics
//!
//! No input to this crate's drawing functions panics, loops without bound
//! or writes outside the target: shapes are clipped to the target's
//! bounding box, whatever their coordinates.
//!
//! # Building for size
//!
//! Built at `opt-level = "s"` or `"z"` (for the whole profile, or for this
//! crate alone under `[profile.release.package.embedded-raster]`), the
//! crate takes its compact code paths: its build script reads Cargo's
//! `OPT_LEVEL`. They light the same pixels; on a Cortex-M4 at `"s"`, flat
//! triangles add about 4.5 KiB of flash (`BENCHMARKS.md` has the counts).
//!
//! [`embedded-graphics`]: https://docs.rs/embedded-graphics
//! [`DrawTarget`]: embedded_graphics_core::draw_target::DrawTarget
//! [`Drawable`]: embedded_graphics_core::Drawable
//! [`Point`]: embedded_graphics_core::geometry::Point

#![no_std]
#![forbid(unsafe_code)]
#![deny(
    missing_docs,
    missing_debug_implementations,
    rustdoc::broken_intra_doc_links
)]

#[cfg(any(test, feature = "std"))]
extern crate std;

pub mod band;
mod clip;
#[cfg(feature = "embedded-graphics")]
mod convert;
pub mod delaunay;
mod error;
pub mod framebuffer;
pub mod line;
pub mod mesh;
mod polygon;
pub mod prelude;
mod raster;
pub mod shade;
#[cfg(feature = "sim")]
pub mod sim;
mod span;
mod stroke;
mod triangle;
mod vertex;

/// The README's examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

/// The `embedded-graphics-core` this crate is built on (its `DrawTarget`,
/// `Drawable`, colours and geometry), for crates that do not depend on it
/// or on `embedded-graphics` themselves.
pub use embedded_graphics_core;
pub use error::CoordinateOutOfRange;
pub use fixed::types::I20F12;
pub use framebuffer::Framebuffer;
pub use line::{
    Line, LineAlgorithm, Polyline, Run, StyledLine, StyledLineVariant, StyledPolyline,
    StyledPolylineVariant, ThickLine,
};
pub use polygon::{FillRule, FilledPolygon, Polygon, PolygonError, StrokedPolygon};
pub use raster::sink::{DrawTargetSink, SpanDrawable, SpanSink};
pub use shade::GouraudTriangle;
pub use span::Span;
pub use stroke::{Join, MITER_LIMIT};
pub use triangle::{
    FilledTriangle, FilledTriangleVariant, StrokedTriangle, SubpixelPrecision, Triangle,
    TriangleAlgorithm,
};
pub use vertex::{ParseCoordinateError, Vertex, SUBPIXEL_BITS};
