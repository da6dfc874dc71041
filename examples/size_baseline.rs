//! Firmware for the code-size table in `BENCHMARKS.md`: the baseline. The
//! same runtime, framebuffer, checksum and semihosting output as the other
//! firmware, and the same triangles as `size_triangles` built (handed to
//! `black_box` instead of drawn), so the `.text` the library adds is the
//! difference to `size_triangles` and `firmware`: `bash .ci/codesize`.

#![cfg_attr(target_os = "none", no_std, no_main)]

#[macro_use]
#[path = "common/size_firmware.rs"]
mod size_firmware;

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

size_firmware!("baseline", draw);
