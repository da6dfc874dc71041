//! Scene files as any text: parsed, and when they parse rendered whole,
//! in an inexact variant and in bands, with the checks of
//! `tests/common/fuzz_cases.rs`. The first 4 bytes choose the variant and
//! the band height; the rest is the scene (bytes that are not UTF-8
//! replaced). Scenes over 256 x 256 px are only parsed, so that each input
//! stays fast.
#![no_main]

use embedded_raster::sim::parse_scene;
use embedded_raster_fuzz::{fuzz_cases, rng};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let (choices, text) = data.split_at(data.len().min(4));
    let text = String::from_utf8_lossy(text);
    let Ok(scene) = parse_scene(&text) else {
        return;
    };
    let size = scene.size();
    if u64::from(size.width) * u64::from(size.height) > 256 * 256 {
        return;
    }
    fuzz_cases::scene(&text, &mut rng::Rng::new(choices));
});
