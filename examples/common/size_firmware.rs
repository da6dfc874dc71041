//! The entry point the code-size firmware examples share.

/// Includes the shared scene and semihosting modules and defines `main`
/// for a code-size firmware whose `draw(&mut SceneBuffer) -> u32` renders
/// and returns the checksum: on a Cortex-M, the framebuffer in static RAM
/// and the line `LABEL fnv1a32=0x........` over semihosting; on 32-bit
/// RISC-V the same, the framebuffer on the stack (riscv-rt has no safe
/// `static mut`); on the host, the same line from a boxed framebuffer.
macro_rules! size_firmware {
    ($label:literal, $draw:ident) => {
        #[path = "common/builtin_scene.rs"]
        mod builtin_scene;

        #[cfg(target_os = "none")]
        #[path = "common/semihosting.rs"]
        mod semihosting;

        #[cfg(target_arch = "arm")]
        mod target {
            use cortex_m_rt::entry;
            use cortex_m_semihosting::hprintln;

            use super::builtin_scene::SceneBuffer;

            #[entry]
            fn main() -> ! {
                // cortex-m-rt turns this into a `&'static mut`: no unsafe.
                static mut FB: SceneBuffer = SceneBuffer::new();
                hprintln!(concat!($label, " fnv1a32=0x{:08x}"), super::$draw(FB));
                super::semihosting::exit_success()
            }
        }

        #[cfg(target_arch = "riscv32")]
        mod target {
            use riscv_rt::entry;
            use riscv_semihosting::hprintln;

            use super::builtin_scene::SceneBuffer;

            #[entry]
            fn main() -> ! {
                let mut fb = SceneBuffer::new();
                hprintln!(concat!($label, " fnv1a32=0x{:08x}"), super::$draw(&mut fb));
                super::semihosting::exit_success()
            }
        }

        #[cfg(not(target_os = "none"))]
        fn main() {
            let mut fb = Box::new(builtin_scene::SceneBuffer::new());
            println!(concat!($label, " fnv1a32=0x{:08x}"), $draw(&mut fb));
        }
    };
}
