//! Firmware for the code-size table in `BENCHMARKS.md`: 1-pixel lines only
//! (the star of the instruction-count firmware and a line with ends far
//! off-screen), drawn through the span sink (`draw_spans`) of the
//! 320 x 240 Rgb565 framebuffer, then the checksum over semihosting.
//! Compare its `.text` with `size_baseline`: `bash .ci/codesize`.

#![cfg_attr(target_arch = "arm", no_std, no_main)]

#[path = "common/builtin_scene.rs"]
mod builtin_scene;

#[cfg(target_arch = "arm")]
#[path = "common/semihosting.rs"]
mod semihosting;

use embedded_graphics_core::{pixelcolor::Rgb565, prelude::*};
use embedded_raster::{Line, SpanDrawable};

/// Draws the lines through the framebuffer's span sink; returns the
/// checksum.
fn draw(fb: &mut builtin_scene::SceneBuffer) -> u32 {
    let Ok(()) = fb.clear(Rgb565::new(2, 5, 8));
    for k in 0..16 {
        let (dx, dy) = [(2, 0), (2, 1), (2, 2), (1, 2), (0, 2), (-1, 2), (-2, 2), (-2, 1)][k % 8];
        let half = Point::new(dx * 50, dy * 50);
        let centre = Point::new(160 + k as i32, 120);
        let color = Rgb565::new(31, 4 * k as u8, 0);
        let Ok(()) = Line::new(centre - half, centre + half).stroke(color).draw_spans(fb);
    }
    let Ok(()) = builtin_scene::FAR_LINE.stroke(Rgb565::new(0, 63, 0)).draw_spans(fb);
    builtin_scene::fnv1a32(fb.as_bytes())
}

#[cfg(target_arch = "arm")]
mod target {
    use cortex_m_rt::entry;
    use cortex_m_semihosting::hprintln;

    use super::builtin_scene::SceneBuffer;

    #[entry]
    fn main() -> ! {
        static mut FB: SceneBuffer = SceneBuffer::new();
        hprintln!("lines fnv1a32=0x{:08x}", super::draw(FB));
        super::semihosting::exit_success()
    }
}

#[cfg(not(target_arch = "arm"))]
fn main() {
    let mut fb = Box::new(builtin_scene::SceneBuffer::new());
    println!("lines fnv1a32=0x{:08x}", draw(&mut fb));
}
