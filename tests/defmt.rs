//! With the `defmt` feature, the public value types implement
//! `defmt::Format` (checked at compile time; `.ci/run` also builds the
//! library for thumbv7em-none-eabihf with `--features defmt`).

#![cfg(feature = "defmt")]

use embedded_graphics_core::pixelcolor::{BinaryColor, Rgb565};
use embedded_raster::{
    framebuffer::{
        buffer_size, Bgr565Be, Bgr565Le, BinaryMsb, Gray2Lsb, Gray2Msb, Gray4Lsb, Gray4Msb,
        Gray8Bytes, Rgb565Be, Rgb565Le, Rgb666Bytes, Rgb888Bytes,
    },
    CoordinateOutOfRange, FilledTriangle, Framebuffer, Join, ParseCoordinateError, Span,
    StrokedTriangle, Triangle, Vertex,
};

fn implements_format<T: defmt::Format + ?Sized>() {}

#[test]
fn value_types_implement_format() {
    implements_format::<Vertex>();
    implements_format::<Triangle>();
    implements_format::<FilledTriangle<Rgb565>>();
    implements_format::<FilledTriangle<BinaryColor>>();
    implements_format::<StrokedTriangle<Rgb565>>();
    implements_format::<Join>();
    implements_format::<Span>();
    implements_format::<CoordinateOutOfRange>();
    implements_format::<ParseCoordinateError>();
    implements_format::<Rgb565Le>();
    implements_format::<Rgb565Be>();
    implements_format::<Rgb888Bytes>();
    implements_format::<Gray8Bytes>();
    implements_format::<BinaryMsb>();
    implements_format::<Bgr565Le>();
    implements_format::<Bgr565Be>();
    implements_format::<Rgb666Bytes>();
    implements_format::<Gray4Msb>();
    implements_format::<Gray4Lsb>();
    implements_format::<Gray2Msb>();
    implements_format::<Gray2Lsb>();
    implements_format::<Framebuffer<Rgb565Le, 4, 4, { buffer_size::<Rgb565Le>(4, 4) }>>();
}
