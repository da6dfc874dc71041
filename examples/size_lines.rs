//! Firmware for the code-size table in `BENCHMARKS.md`: 1-pixel lines only
//! (the star of the instruction-count firmware and a line with ends far
//! off-screen), drawn through the span sink (`draw_spans`) of the
//! 320 x 240 Rgb565 framebuffer, then the checksum over semihosting.
//! Compare its `.text` with `size_baseline`: `bash .ci/codesize`.

#![cfg_attr(target_os = "none", no_std, no_main)]

#[macro_use]
#[path = "common/size_firmware.rs"]
mod size_firmware;

use embedded_graphics_core::{pixelcolor::Rgb565, prelude::*};
use embedded_raster::SpanDrawable;

/// Draws the lines through the framebuffer's span sink; returns the
/// checksum.
fn draw(fb: &mut builtin_scene::SceneBuffer) -> u32 {
    let Ok(()) = fb.clear(Rgb565::new(2, 5, 8));
    for k in 0..16 {
        let color = Rgb565::new(31, 4 * k as u8, 0);
        let Ok(()) = builtin_scene::star_line(k, 200)
            .stroke(color)
            .draw_spans(fb);
    }
    let Ok(()) = builtin_scene::FAR_LINE
        .stroke(Rgb565::new(0, 63, 0))
        .draw_spans(fb);
    builtin_scene::fnv1a32(fb.as_bytes())
}

size_firmware!("lines", draw);
