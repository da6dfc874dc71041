//! Triangles (flat, Gouraud, depth-tested and outlined), polygons (filled
//! and outlined), lines and polylines (every join) at `i32` and 20.12
//! extremes, and the mesh arithmetic, from libFuzzer's bytes: the first byte picks
//! the kind, the rest are its choices (`tests/common/fuzz_cases.rs`). Each
//! is checked against the exact references of `tests/common` on every
//! framebuffer format and on a `SimDisplay`, with overflow checks on.
#![no_main]

use embedded_raster_fuzz::{fuzz_cases, rng};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Some((&kind, choices)) = data.split_first() else {
        return;
    };
    let mut r = rng::Rng::new(choices);
    match kind % 4 {
        0 => fuzz_cases::triangle(&mut r),
        1 => fuzz_cases::polygon(&mut r),
        2 => {
            fuzz_cases::line_and_polyline(&mut r);
        }
        _ => fuzz_cases::mesh(&mut r),
    }
});
