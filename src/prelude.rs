//! The traits whose methods drawing code calls, to glob-import beside
//! embedded-graphics' prelude.
//!
//! It holds traits only, imported as `_` (their methods become callable,
//! their names stay free), so
//!
//! ```
//! use embedded_graphics::prelude::*;
//! use embedded_raster::prelude::*;
//! ```
//!
//! never makes a name ambiguous. The shapes, whose names are also
//! embedded-graphics' (`Triangle`, `Line`, `Polyline`, `Framebuffer`), are
//! left to explicit paths: see the crate docs, "Using it with
//! embedded-graphics".
//!
//! # Examples
//!
//! ```
//! use embedded_graphics::{pixelcolor::Gray8, prelude::*};
//! use embedded_raster::prelude::*;
//! use embedded_raster::{framebuffer::{buffer_size, Gray8Bytes}, Framebuffer, Vertex};
//!
//! let mut fb = Framebuffer::<Gray8Bytes, 8, 8, { buffer_size::<Gray8Bytes>(8, 8) }>::new();
//! let triangle = embedded_raster::Triangle::from_points(
//!     Point::new(0, 0), Point::new(8, 0), Point::new(0, 8),
//! )?;
//! // `draw_spans` comes from the prelude's `SpanDrawable`.
//! triangle.fill(Gray8::WHITE).draw_spans(&mut fb)?;
//! assert_eq!(fb.pixel(Point::new(0, 0)), Some(Gray8::WHITE));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub use crate::framebuffer::PixelFormat as _;
pub use crate::raster::sink::{SpanDrawable as _, SpanSink as _};
pub use crate::shade::ShadeColor as _;
