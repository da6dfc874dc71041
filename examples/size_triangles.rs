//! Firmware for the code-size table in `BENCHMARKS.md`: flat triangles
//! only (irregular triangles of four sizes and the scene's mesh), drawn
//! through the span sink (`draw_spans`) of the 320 x 240 Rgb565
//! framebuffer, then the checksum over semihosting. Compare
//! its `.text` with `size_baseline` (no drawing) and `firmware` (every
//! primitive): `bash .ci/codesize`.

#![cfg_attr(target_os = "none", no_std, no_main)]

#[macro_use]
#[path = "common/size_firmware.rs"]
mod size_firmware;

use embedded_graphics_core::{pixelcolor::Rgb565, prelude::*};
use embedded_raster::SpanDrawable;

/// Draws the triangles through the framebuffer's span sink (the direct
/// path); returns the checksum.
fn draw(fb: &mut builtin_scene::SceneBuffer) -> u32 {
    let Ok(()) = fb.clear(Rgb565::new(2, 5, 8));
    for (k, size) in [4, 16, 64, 240].into_iter().enumerate() {
        let color = Rgb565::new(8 * k as u8, 16, 31 - 8 * k as u8);
        let Ok(()) = builtin_scene::irregular(5 * k as i32, 3 * k as i32, size)
            .fill(color)
            .draw_spans(fb);
    }
    let Ok(()) = builtin_scene::for_each_mesh_triangle(|t, c| t.fill(c).draw_spans(fb));
    builtin_scene::fnv1a32(fb.as_bytes())
}

size_firmware!("triangles", draw);
