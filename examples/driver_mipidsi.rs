//! A display list rendered in bands straight into an ST7789 panel through
//! the `mipidsi` driver: two 240 x 16 Rgb565 band buffers (15 KiB)
//! instead of a 150 KiB frame, each finished band sent with one window
//! write (`band::WriteTo`: one `fill_contiguous` over the band's rows).
//! Then a small change drawn into a full framebuffer region and flushed
//! with `band::DirtyRows`, which sends only the rows that changed.
//!
//! The SPI bus, pins and delay are stand-ins that count bytes
//! (`examples/common/stub_hal.rs`): build it for a Cortex-M to check it
//! against the real driver crate, or run it under QEMU:
//!
//! ```sh
//! cargo run --release --target thumbv7em-none-eabihf --example driver_mipidsi --features firmware
//! ```
//!
//! On a board, replace the stand-ins with the HAL's SPI device, DC and
//! reset pins and delay.

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
    use embedded_graphics_core::{pixelcolor::Rgb565, prelude::*};
    use embedded_raster::{
        band::{Command, DirtyRows, DisplayList, WriteTo},
        framebuffer::{buffer_size, Rgb565Be},
        Framebuffer, Line, Triangle, Vertex,
    };
    use mipidsi::{interface::SpiInterface, models::ST7789, Builder};

    use super::stub_hal::{CountingSpi, NoDelay, NoPin};

    /// A band: 240 x 16 pixels, big-endian Rgb565 as the panel takes it.
    type BandBuffer = Framebuffer<Rgb565Be, 240, 16, { buffer_size::<Rgb565Be>(240, 16) }>;
    /// A 64 x 64 region of the screen kept whole, for small updates.
    type Region = Framebuffer<Rgb565Be, 64, 64, { buffer_size::<Rgb565Be>(64, 64) }>;

    #[entry]
    fn main() -> ! {
        // cortex-m-rt makes these `&'static mut` (in .bss): no unsafe.
        static mut BANDS: [BandBuffer; 2] = [BandBuffer::new(), BandBuffer::new()];
        static mut REGION: DirtyRows<Region, 64> = DirtyRows::new(Region::new());
        static mut SPI_BUFFER: [u8; 512] = [0; 512];

        let sent = Cell::new(0u32); // bytes over the SPI bus
        let interface = SpiInterface::new(CountingSpi(&sent), NoPin, SPI_BUFFER);
        let Ok(mut display) = Builder::new(ST7789, interface)
            .reset_pin(NoPin)
            .init(&mut NoDelay)
        else {
            panic!("display init failed");
        };

        // The frame, recorded once.
        let v = |x: i32, y: i32| Vertex::from_raw(x * 4096 + 1000, y * 4096 + 3000);
        let mut list = DisplayList::<Rgb565, 8>::new();
        let commands = [
            Command::Clear(Rgb565::BLACK),
            Command::Triangle(Triangle::new(v(10, 10), v(230, 60), v(60, 310)).fill(Rgb565::RED)),
            Command::Line(Line::new(Point::new(0, 319), Point::new(239, 0)).stroke(Rgb565::WHITE)),
        ];
        for command in commands {
            if list.push(command).is_err() {
                panic!("the list holds 8 commands");
            }
        }

        // 20 bands of 16 rows, alternating between the two buffers.
        if list
            .render_bands(320, BANDS, None, &mut WriteTo(&mut display))
            .is_err()
        {
            panic!("sending a band failed");
        }
        let frame_bytes = sent.get();
        hprintln!("bands: {} bytes sent for 240 x 320 px", frame_bytes);

        // A small update: only the changed rows of the region go out.
        let region = REGION;
        let t = Triangle::new(v(4, 4), v(40, 10), v(12, 30));
        if t.fill(Rgb565::GREEN).draw(region).is_err() {
            panic!("drawing failed");
        }
        let changed = region
            .changed()
            .fold(0, |n, r| n + r.size.width * r.size.height);
        if region.flush(&mut display).is_err() {
            panic!("flush failed");
        }
        let update = sent.get() - frame_bytes;
        hprintln!("dirty rows: {} px changed, {} bytes sent", changed, update);
        super::semihosting::exit_success()
    }
}

/// On the host there is no panel to talk to.
#[cfg(not(target_arch = "arm"))]
fn main() {
    eprintln!(
        "driver_mipidsi is Cortex-M firmware: cargo run --release --target \
         thumbv7em-none-eabihf --example driver_mipidsi --features firmware"
    );
}
