//! Firmware for the shading code-size row in `BENCHMARKS.md`: the same
//! triangles as `size_triangles`, drawn flat, Gouraud-shaded and
//! Gouraud-shaded with depth on the 320 x 240 Rgb565 framebuffer (the depth
//! buffer is a `static` of 320 x 240 `u16`), then the checksum over
//! semihosting. `size_triangles` links none of the shading code:
//! `bash .ci/codesize_shading`.

#![cfg_attr(target_arch = "arm", no_std, no_main)]

#[path = "common/builtin_scene.rs"]
mod builtin_scene;

#[cfg(target_arch = "arm")]
#[path = "common/semihosting.rs"]
mod semihosting;

use embedded_graphics_core::{pixelcolor::Rgb565, prelude::*};
use embedded_raster::shade::DepthBuffer;

/// Draws the triangles; returns the checksum.
fn draw(fb: &mut builtin_scene::SceneBuffer, storage: &mut [u16]) -> u32 {
    let Ok(()) = fb.clear(Rgb565::new(2, 5, 8));
    let depth = DepthBuffer::new(storage, builtin_scene::WIDTH as u32);
    depth.clear();
    for (k, size) in [4, 16, 64, 240].into_iter().enumerate() {
        let k8 = 8 * k as u8;
        let colors = [
            Rgb565::new(k8, 16, 31 - k8),
            Rgb565::new(31, k8, 0),
            Rgb565::new(0, 63, k8),
        ];
        let t = builtin_scene::irregular(5 * k as i32, 3 * k as i32, size);
        let Ok(()) = t.fill(colors[0]).draw(fb);
        let Ok(()) = t.gouraud(colors).draw(fb);
        let z = [100 * k as u16, 40_000, 9_000];
        let Ok(()) = t.gouraud(colors).with_depth(z, depth).draw(fb);
    }
    let Ok(()) = builtin_scene::draw_mesh(fb);
    builtin_scene::fnv1a32(fb.as_bytes())
}

#[cfg(target_arch = "arm")]
mod target {
    use cortex_m_rt::entry;
    use cortex_m_semihosting::hprintln;

    use super::builtin_scene::{SceneBuffer, HEIGHT, WIDTH};

    #[entry]
    fn main() -> ! {
        static mut FB: SceneBuffer = SceneBuffer::new();
        static mut DEPTH: [u16; WIDTH * HEIGHT] = [0; WIDTH * HEIGHT];
        hprintln!("shading fnv1a32=0x{:08x}", super::draw(FB, DEPTH));
        super::semihosting::exit_success()
    }
}

#[cfg(not(target_arch = "arm"))]
fn main() {
    let mut fb = Box::new(builtin_scene::SceneBuffer::new());
    let mut depth = vec![0u16; builtin_scene::WIDTH * builtin_scene::HEIGHT];
    println!("shading fnv1a32=0x{:08x}", draw(&mut fb, &mut depth));
}
