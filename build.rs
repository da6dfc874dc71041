//! Puts `memory.x` on the linker's search path for the firmware examples
//! (`memory-32k.x` in its place with the feature `firmware-32k`, and
//! `memory-riscv.x` for RISC-V), and sets the `cfg`s of target cores that
//! the library's code paths depend on.
//!
//! The memory map only when building for an ARM or 32-bit RISC-V target
//! with the `firmware` feature: the library itself needs no linker script,
//! and a crate that depends on this one brings its own `memory.x`.

use std::{env, fs, path::PathBuf};

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-changed=memory.x");
    println!("cargo:rerun-if-changed=memory-32k.x");
    println!("cargo:rerun-if-changed=memory-riscv.x");
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
    // `narrow_multiplier`: the target's cores multiply 32 by 32 bits into
    // the low 32 bits only (ARMv6-M and ARMv8-M Baseline, no `umull`), so
    // that a 64-bit product is a library call.
    println!("cargo::rustc-check-cfg=cfg(narrow_multiplier)");
    if ["thumbv6m-", "thumbv8m.base-"]
        .iter()
        .any(|arch| target.starts_with(arch))
    {
        println!("cargo:rustc-cfg=narrow_multiplier");
    }
    // `optimize_for_size`: this crate is built at opt-level "s" or "z"
    // (Cargo's `OPT_LEVEL` for the profile being built, per-package
    // overrides included), where a few loops are written out that the
    // compiler then leaves as loops.
    println!("cargo::rustc-check-cfg=cfg(optimize_for_size)");
    if matches!(env::var("OPT_LEVEL").as_deref(), Ok("s" | "z")) {
        println!("cargo:rustc-cfg=optimize_for_size");
    }
    let arch = env::var("CARGO_CFG_TARGET_ARCH").unwrap_or_default();
    let firmware = env::var_os("CARGO_FEATURE_FIRMWARE").is_some();
    // `firmware-32k`: the band firmware's map, 32 KiB of RAM in all.
    let small = env::var_os("CARGO_FEATURE_FIRMWARE_32K").is_some();
    // RISC-V firmware runs from the RAM of QEMU's `virt` board.
    let map = match (arch.as_str(), small) {
        ("arm", false) => Some("memory.x"),
        ("arm", true) => Some("memory-32k.x"),
        ("riscv32", _) => Some("memory-riscv.x"),
        _ => None,
    };
    if let (Some(map), true) = (map, firmware) {
        let out = PathBuf::from(env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
        // cortex-m-rt's `link.x` includes `memory.x`; riscv-rt's map is
        // named on the command line (`.cargo/config.toml`), under its own
        // name, so that the linker cannot take the ARM one from the crate's
        // root for it.
        let name = if arch == "riscv32" { map } else { "memory.x" };
        fs::copy(map, out.join(name)).expect("copy the memory map to OUT_DIR");
        println!("cargo:rustc-link-search={}", out.display());
    }
}
