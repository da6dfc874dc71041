//! This crate's exact shapes on an SSD1306 128 x 64 OLED through the
//! `ssd1306` driver (I2C, buffered graphics mode): drawn straight into the
//! driver's own page buffer, which it is a `DrawTarget` of, and a 1-bit
//! `Framebuffer` of this crate drawn onto it as an image, then flushed.
//!
//! The I2C bus is a stand-in that counts bytes
//! (`examples/common/stub_hal.rs`): build it for a Cortex-M to check it
//! against the real driver crate, or run it under QEMU:
//!
//! ```sh
//! cargo run --release --target thumbv7em-none-eabihf --example driver_ssd1306 --features firmware
//! ```

#![cfg_attr(target_arch = "arm", no_std, no_main)]

#[cfg(target_arch = "arm")]
#[path = "common/semihosting.rs"]
mod semihosting;
#[cfg(target_arch = "arm")]
#[path = "common/stub_hal.rs"]
mod stub_hal;

#[cfg(target_arch = "arm")]
mod target {
    use core::cell::Cell;

    use cortex_m_rt::entry;
    use cortex_m_semihosting::hprintln;
    use embedded_graphics::{image::Image, pixelcolor::BinaryColor, prelude::*};
    use embedded_raster::{
        framebuffer::{buffer_size, BinaryMsb},
        Framebuffer, Polyline, Triangle, Vertex,
    };
    use ssd1306::{prelude::*, I2CDisplayInterface, Ssd1306};

    use super::stub_hal::CountingI2c;

    /// A 48 x 32 sprite, 1 bit a pixel (192 bytes).
    type Sprite = Framebuffer<BinaryMsb, 48, 32, { buffer_size::<BinaryMsb>(48, 32) }>;

    #[entry]
    fn main() -> ! {
        let sent = Cell::new(0u32); // bytes over the I2C bus
        let interface = I2CDisplayInterface::new(CountingI2c(&sent));
        let mut display = Ssd1306::new(interface, DisplaySize128x64, DisplayRotation::Rotate0)
            .into_buffered_graphics_mode();
        if display.init().is_err() {
            panic!("display init failed");
        }
        let init_bytes = sent.get();

        // Exact shapes straight into the driver's buffer.
        let v = |x: i32, y: i32| Vertex::from_raw(x * 4096 + 2048, y * 4096 + 1024);
        // (Drawing into the driver's buffer cannot fail; its error type is
        // the bus's.)
        let triangle = Triangle::new(v(2, 2), v(60, 20), v(10, 60));
        let _ = triangle.fill(BinaryColor::On).draw(&mut display);
        let zigzag = [
            Point::new(64, 60),
            Point::new(80, 4),
            Point::new(96, 60),
            Point::new(127, 4),
        ];
        let _ = Polyline::new(&zigzag)
            .stroke(BinaryColor::On)
            .draw(&mut display);

        // A sprite drawn in this crate's 1-bit framebuffer, then placed.
        let mut sprite = Sprite::new();
        let Ok(()) = Triangle::new(v(0, 0), v(47, 16), v(0, 31))
            .fill(BinaryColor::On)
            .draw(&mut sprite);
        let _ = Image::new(&sprite, Point::new(70, 30)).draw(&mut display);

        if display.flush().is_err() {
            panic!("flush failed");
        }
        hprintln!(
            "ssd1306: {} bytes sent for a 128 x 64 frame",
            sent.get() - init_bytes
        );
        super::semihosting::exit_success()
    }
}

/// On the host there is no panel to talk to.
#[cfg(not(target_arch = "arm"))]
fn main() {
    eprintln!(
        "driver_ssd1306 is Cortex-M firmware: cargo run --release --target \
         thumbv7em-none-eabihf --example driver_ssd1306 --features firmware"
    );
}
