//! Firmware for the code-size table in `BENCHMARKS.md`: the baseline. The
//! same runtime, framebuffer, checksum and semihosting output as the other
//! firmware, and the same triangles as `size_triangles` built (handed to
//! `black_box` instead of drawn), so the `.text` the library adds is the
//! difference to `size_triangles` and `firmware`: `bash .ci/codesize`.

#![cfg_attr(target_arch = "arm", no_std, no_main)]

#[path = "common/builtin_scene.rs"]
mod builtin_scene;

#[cfg(target_arch = "arm")]
#[path = "common/semihosting.rs"]
mod semihosting;

/// Builds `size_triangles`' triangles without drawing them, and checksums
/// the untouched (black) framebuffer.
fn draw(fb: &mut builtin_scene::SceneBuffer) -> u32 {
    use core::hint::black_box;
    for (k, size) in [4, 16, 64, 240].into_iter().enumerate() {
        black_box(builtin_scene::irregular(5 * k as i32, 3 * k as i32, size));
    }
    let Ok(()) = builtin_scene::for_each_mesh_triangle(|t, c| {
        black_box((t, c));
        Ok::<(), core::convert::Infallible>(())
    });
    builtin_scene::fnv1a32(black_box(fb).as_bytes())
}

#[cfg(target_arch = "arm")]
mod target {
    use cortex_m_rt::entry;
    use cortex_m_semihosting::hprintln;

    use super::builtin_scene::SceneBuffer;

    #[entry]
    fn main() -> ! {
        static mut FB: SceneBuffer = SceneBuffer::new();
        hprintln!("baseline fnv1a32=0x{:08x}", super::draw(FB));
        super::semihosting::exit_success()
    }
}

#[cfg(not(target_arch = "arm"))]
fn main() {
    let mut fb = Box::new(builtin_scene::SceneBuffer::new());
    println!("baseline fnv1a32=0x{:08x}", draw(&mut fb));
}
