//! What the fuzz targets share: the checks of `tests/fuzz.rs`
//! (`tests/common/fuzz_cases.rs`, with the references and helpers it
//! uses), driven by [`rng::Rng`], a reader of the fuzzer's bytes.

// The shared test files hold more than the targets call.
#![allow(dead_code)]

#[path = "../../tests/common/mod.rs"]
mod common;
#[path = "../../tests/common/fuzz_cases.rs"]
pub mod fuzz_cases;
#[path = "../../tests/common/line_ref.rs"]
mod line_ref;
#[path = "tape.rs"]
pub mod rng;
#[path = "../../tests/common/view.rs"]
mod view;
