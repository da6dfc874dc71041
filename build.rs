//! Puts `memory.x` on the linker's search path for the firmware examples
//! (`memory-32k.x` in its place with the feature `firmware-32k`).
//!
//! Only when building for an ARM target with the `firmware` feature: the
//! library itself needs no linker script, and a crate that depends on this
//! one brings its own `memory.x`.

use std::{env, fs, path::PathBuf};

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-changed=memory.x");
    println!("cargo:rerun-if-changed=memory-32k.x");
    // `unaligned_words`: the target's cores store 32-bit words at any
    // address (ARMv7-M, ARMv7E-M and ARMv8-M Mainline; not ARMv6-M or
    // ARMv8-M Baseline), which short framebuffer spans use.
    println!("cargo::rustc-check-cfg=cfg(unaligned_words)");
    let target = env::var("TARGET").unwrap_or_default();
    if ["thumbv7m-", "thumbv7em-", "thumbv8m.main-"]
        .iter()
        .any(|arch| target.starts_with(arch))
    {
        println!("cargo:rustc-cfg=unaligned_words");
    }
    // `software_division`: the target's cores have no divide instruction
    // (ARMv6-M), so a division is a library call.
    println!("cargo::rustc-check-cfg=cfg(software_division)");
    if target.starts_with("thumbv6m-") {
        println!("cargo:rustc-cfg=software_division");
    }
    let arm = env::var("CARGO_CFG_TARGET_ARCH").as_deref() == Ok("arm");
    let firmware = env::var_os("CARGO_FEATURE_FIRMWARE").is_some();
    // `firmware-32k`: the band firmware's map, 32 KiB of RAM in all.
    let small = env::var_os("CARGO_FEATURE_FIRMWARE_32K").is_some();
    if arm && firmware {
        let out = PathBuf::from(env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
        let map = if small { "memory-32k.x" } else { "memory.x" };
        fs::copy(map, out.join("memory.x")).expect("copy the memory map to OUT_DIR");
        println!("cargo:rustc-link-search={}", out.display());
    }
}
