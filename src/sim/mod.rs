//! The host simulator (feature `sim`): an overdraw-counting display, PNG
//! export and the scene-file renderer behind the `render` example.
//!
//! - [`SimDisplay`] is a [`DrawTarget`] of any size and colour type that
//!   counts writes per pixel, drops and counts writes outside its area, and
//!   records which [`DrawTarget`] methods the pixels arrived through. It
//!   saves PNG images and PGM images of its write counts.
//! - [`parse_scene`] reads a scene file into a [`Scene`]; [`render_scene`]
//!   draws it on a [`SimDisplay`] with this crate's rasterizers.
//! - [`cli::run`] is the whole `render` command line, [`delaunay_cli::run`]
//!   the `delaunay` example's.
//!
//! # Examples
//!
//! ```
//! use embedded_graphics::{pixelcolor::Rgb888, prelude::*};
//! use embedded_raster::sim::{parse_scene, render_scene};
//!
//! // Two triangles sharing the diagonal make a square.
//! let scene = parse_scene(
//!     "size 32 32\n\
//!      clear #202020\n\
//!      tri 4 4 28 4 4 28 #ff8000\n\
//!      tri 28 4 28 28 4 28 #ff8000\n",
//! )?;
//! let rendered = render_scene(&scene);
//! let display = &rendered.display;
//! assert_eq!(display.pixel(Point::new(4, 27)), Some(Rgb888::new(0xff, 0x80, 0)));
//! assert_eq!(display.write_count(Point::new(16, 16)), Some(2)); // clear + one triangle
//! assert_eq!(display.write_stats().draw_iter_pixels, 0); // all spans, no single pixels
//! assert_eq!(display.out_of_bounds_writes(), 0);
//! # Ok::<(), embedded_raster::sim::SceneError>(())
//! ```
//!
//! [`DrawTarget`]: embedded_graphics_core::draw_target::DrawTarget

pub mod cli;
mod cost;
pub mod delaunay_cli;
pub(crate) mod display;
mod render;
mod scene;

pub use display::{SimDisplay, WriteStats};
pub use render::{
    render_scene, render_scene_in_bands, render_scene_with, BandStats, RenderStats, Rendered,
};
pub use scene::{parse_scene, Command, Scene, SceneError, MAX_SCENE_SIDE, SCENE_POLYGON_CAPACITY};
