//! Puts `memory.x` on the linker's search path for the firmware examples.
//!
//! Only when building for an ARM target with the `firmware` feature: the
//! library itself needs no linker script, and a crate that depends on this
//! one brings its own `memory.x`.

use std::{env, fs, path::PathBuf};

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-changed=memory.x");
    let arm = env::var("CARGO_CFG_TARGET_ARCH").as_deref() == Ok("arm");
    let firmware = env::var_os("CARGO_FEATURE_FIRMWARE").is_some();
    if arm && firmware {
        let out = PathBuf::from(env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
        fs::copy("memory.x", out.join("memory.x")).expect("copy memory.x to OUT_DIR");
        println!("cargo:rustc-link-search={}", out.display());
    }
}
