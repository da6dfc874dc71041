//! Firmware: renders the built-in scene (`examples/common/builtin_scene.rs`)
//! into a 320 x 240 Rgb565 framebuffer in static RAM on a Cortex-M, prints
//! its checksum over semihosting and exits with success. A panic prints its
//! message and exits with failure.
//!
//! Run it on QEMU's Cortex-M4 board (`.cargo/config.toml` is the runner):
//!
//! ```sh
//! cargo run --release --target thumbv7em-none-eabihf --example firmware --features firmware
//! ```
//!
//! or on its `virt` board, for 32-bit RISC-V (`qemu-system-riscv32`, in
//! Debian's `qemu-system-misc`):
//!
//! ```sh
//! cargo run --release --target riscv32imc-unknown-none-elf --example firmware --features firmware
//! ```
//!
//! Built for the host, it renders the same scene with the same code and
//! prints the same line, for comparison.

#![cfg_attr(target_os = "none", no_std, no_main)]

#[path = "common/builtin_scene.rs"]
mod builtin_scene;

#[cfg(target_os = "none")]
#[path = "common/semihosting.rs"]
mod semihosting;

/// The line both sides print; CI compares the firmware's with the host's.
#[cfg_attr(not(target_os = "none"), allow(dead_code))]
const REPORT: &str = "scene 320x240 rgb565le fnv1a32=";

#[cfg(target_arch = "arm")]
mod target {
    use cortex_m_rt::entry;
    use cortex_m_semihosting::hprintln;

    use super::builtin_scene::{self, SceneBuffer};

    #[entry]
    fn main() -> ! {
        // cortex-m-rt turns this into a `&'static mut` (in .bss): no unsafe.
        static mut FB: SceneBuffer = SceneBuffer::new();
        let checksum = builtin_scene::render(FB);
        hprintln!("{}0x{:08x}", super::REPORT, checksum);
        super::semihosting::exit_success()
    }
}

/// The same on 32-bit RISC-V (QEMU's `virt` board, `.cargo/config.toml`
/// is the runner).
#[cfg(target_arch = "riscv32")]
mod target {
    use riscv_rt::entry;
    use riscv_semihosting::hprintln;

    use super::builtin_scene::{self, SceneBuffer};

    #[entry]
    fn main() -> ! {
        // riscv-rt has no safe `static mut`: the 150 KiB framebuffer lives
        // on the stack, which has the board's RAM.
        let mut fb = SceneBuffer::new();
        let checksum = builtin_scene::render(&mut fb);
        hprintln!("{}0x{:08x}", super::REPORT, checksum);
        super::semihosting::exit_success()
    }
}

/// On the host: the same rendering, the same line.
#[cfg(not(target_os = "none"))]
fn main() {
    let mut fb = Box::new(builtin_scene::SceneBuffer::new());
    let checksum = builtin_scene::render(&mut fb);
    println!("{REPORT}0x{checksum:08x}");
    eprintln!(
        "(host build; the firmware runs with: cargo run --release --target \
         thumbv7em-none-eabihf --example firmware --features firmware)"
    );
}
