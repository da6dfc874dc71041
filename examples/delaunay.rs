//! Triangulates a point file (Delaunay, exact) and writes a scene file.
//!
//! ```text
//! cargo run --release --features sim --example delaunay -- POINTS -o OUT.scene [--size WxH] [--gouraud]
//! cargo run --release --features sim --bin render -- OUT.scene -o OUT.png
//! ```
//!
//! `POINTS` holds one `x y` pair per line; run with `--help` for details.

use std::process::ExitCode;

fn main() -> ExitCode {
    let code = embedded_raster::sim::delaunay_cli::run(
        std::env::args_os().skip(1),
        std::io::stdout().lock(),
        std::io::stderr().lock(),
    );
    ExitCode::from(u8::try_from(code).unwrap_or(1))
}
