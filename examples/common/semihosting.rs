//! How the firmware examples end, over semihosting: success after their
//! work, failure on any panic, so that QEMU's exit code tells CI what
//! happened. On ARM through `cortex-m-semihosting`, on RISC-V through
//! `riscv-semihosting`.

#[cfg(target_arch = "arm")]
use cortex_m_semihosting::{debug, hprintln};
#[cfg(target_arch = "riscv32")]
use riscv_semihosting::{debug, hprintln};

/// Ends the program with success (QEMU exits with code 0).
pub fn exit_success() -> ! {
    debug::exit(debug::EXIT_SUCCESS);
    idle()
}

/// Waits for ever (after an exit that did not stop the machine).
fn idle() -> ! {
    loop {
        core::hint::spin_loop();
    }
}

#[panic_handler]
fn panic(info: &core::panic::PanicInfo) -> ! {
    hprintln!("panicked: {}", info);
    debug::exit(debug::EXIT_FAILURE);
    idle()
}
