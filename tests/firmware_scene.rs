//! The firmware's built-in scene on the host: the same file the Cortex-M
//! firmware compiles (`examples/common/builtin_scene.rs`), drawn on the
//! crate's framebuffer and on the simulator.
//!
//! `.ci/run` runs the firmware under QEMU and then this test with
//! `FIRMWARE_CHECKSUM` set to the checksum the firmware printed:
//! `firmware_checksum_matches_host` fails unless the target drew the same
//! bytes as the host.

#[path = "../examples/common/builtin_scene.rs"]
mod builtin_scene;

use builtin_scene::{SceneBuffer, HUGE, TWIN};
use embedded_graphics_core::{pixelcolor::Rgb565, prelude::*};

fn host_render() -> (Box<SceneBuffer>, u32) {
    let mut fb = Box::new(SceneBuffer::new());
    let checksum = builtin_scene::render(&mut fb);
    (fb, checksum)
}

#[test]
fn huge_and_twin_light_the_same_pixels() {
    let lit = |t: embedded_raster::Triangle| {
        let mut fb = Box::new(SceneBuffer::new());
        t.fill(Rgb565::WHITE).draw(&mut *fb).unwrap();
        fb
    };
    let (huge, twin) = (lit(HUGE), lit(TWIN));
    assert!(huge == twin, "HUGE and TWIN differ on screen");
    let count = huge.as_bytes().chunks(2).filter(|p| p != &[0, 0]).count();
    assert!(count > 30_000, "{count} px lit");
}

#[test]
fn firmware_checksum_matches_host() {
    let (_, checksum) = host_render();
    // The same line the firmware prints.
    println!("scene 320x240 rgb565le fnv1a32=0x{checksum:08x}");
    assert_eq!(host_render().1, checksum, "rendering is not deterministic");
    if let Ok(firmware) = std::env::var("FIRMWARE_CHECKSUM") {
        let firmware = firmware.trim();
        let parsed = u32::from_str_radix(firmware.trim_start_matches("0x"), 16)
            .unwrap_or_else(|_| panic!("FIRMWARE_CHECKSUM={firmware:?} is not a hex u32"));
        assert_eq!(
            parsed, checksum,
            "the firmware drew 0x{parsed:08x}, the host 0x{checksum:08x}"
        );
    }
}

#[test]
fn checksum_is_fnv1a32() {
    // Test vectors of the reference FNV-1a.
    assert_eq!(builtin_scene::fnv1a32(b""), 0x811c_9dc5);
    assert_eq!(builtin_scene::fnv1a32(b"a"), 0xe40c_292c);
    assert_eq!(builtin_scene::fnv1a32(b"foobar"), 0xbf9c_f968);
}

#[cfg(feature = "sim")]
mod sim {
    use super::*;
    use embedded_raster::sim::SimDisplay;

    #[test]
    fn framebuffer_and_simulator_agree_pixel_for_pixel() {
        let (fb, checksum) = host_render();
        let mut display = SimDisplay::new(320, 240, Rgb565::BLACK);
        builtin_scene::draw_scene(&mut display).unwrap();
        let mut bytes = Vec::with_capacity(fb.as_bytes().len());
        for y in 0..240 {
            for x in 0..320 {
                let p = Point::new(x, y);
                let (sim, ours) = (display.pixel(p), fb.pixel(p));
                assert_eq!(sim, ours, "pixel {p:?}");
                let raw = sim.unwrap().into_storage();
                bytes.extend_from_slice(&raw.to_le_bytes());
            }
        }
        assert_eq!(builtin_scene::fnv1a32(&bytes), checksum);
        // `FIRMWARE_SCENE_PNG=path` saves the picture.
        if let Some(path) = std::env::var_os("FIRMWARE_SCENE_PNG") {
            display.save_png(path).unwrap();
        }
        // Filled shapes reach the display as spans only.
        assert_eq!(display.write_stats().draw_iter_pixels, 0);
    }

    #[test]
    fn mesh_lights_every_pixel_of_its_area_once() {
        let mut display = SimDisplay::new(320, 240, Rgb565::BLACK);
        builtin_scene::draw_mesh(&mut display).unwrap();
        let area = builtin_scene::MESH_AREA;
        for y in 0..240 {
            for x in 0..320 {
                let p = Point::new(x, y);
                let expected = u32::from(area.contains(p));
                assert_eq!(display.write_count(p), Some(expected), "pixel {p:?}");
            }
        }
    }
}
