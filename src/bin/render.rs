//! Renders a scene file to a PNG image: the `render` tool of the scene
//! contract, a binary target so that it builds without the dev-dependencies.
//!
//! ```text
//! cargo run --release --features sim --bin render -- SCENE -o OUT.png [--counts COUNTS.pgm] [--stats]
//! ```
//!
//! The scene format is described in `embedded_raster::sim`; run with
//! `--help` for the options.

use std::process::ExitCode;

fn main() -> ExitCode {
    let code = embedded_raster::sim::cli::run(
        std::env::args_os().skip(1),
        std::io::stdout().lock(),
        std::io::stderr().lock(),
    );
    ExitCode::from(u8::try_from(code).unwrap_or(1))
}
