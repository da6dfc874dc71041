//! How the firmware examples end, over semihosting: success after their
//! work, failure on any panic, so that QEMU's exit code tells CI what
//! happened.

use cortex_m_semihosting::{debug, hprintln};

/// Ends the program with success (QEMU exits with code 0).
pub fn exit_success() -> ! {
    debug::exit(debug::EXIT_SUCCESS);
    loop {
        cortex_m::asm::nop();
    }
}

#[panic_handler]
fn panic(info: &core::panic::PanicInfo) -> ! {
    hprintln!("panicked: {}", info);
    debug::exit(debug::EXIT_FAILURE);
    loop {
        cortex_m::asm::nop();
    }
}
