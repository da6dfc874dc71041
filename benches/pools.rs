//! The random triangle pools of `benches/triangles.rs`, each contender
//! timed in turn: one round times every contender once, on a batch that
//! takes about `POOLS_BATCH_MS` (default 2) milliseconds, and each
//! contender keeps its fastest batch over `POOLS_ROUNDS` (default 30)
//! rounds. Prints the pools table of BENCHMARKS.md and the README: each
//! contender's speed as a fraction of the memory limit's (`slice::fill`
//! of the same exact spans).
//!
//! Why not criterion's medians alone: on a shared machine the speed of
//! the whole machine drifts over the minutes a criterion run takes, and
//! criterion measures one contender after another, so the drift lands in
//! the ratios. Two consecutive criterion runs of the same build gave the
//! small pool's `draw_spans` 0.70 and 0.30 of the limit. Interleaved
//! rounds put every contender under the same conditions, and the fastest
//! batch is the one least disturbed.
//!
//! `cargo bench --bench pools` prints one run's table;
//! `python3 benches/pools_median.py | python3 benches/splice.py pools`
//! puts the median of 9 runs into BENCHMARKS.md and the README.

use std::time::Instant;

#[path = "common/pools.rs"]
mod pools;
use pools::{contenders, Prepared, Targets, POOLS};

/// An environment variable as a number, or `default`.
fn setting(name: &str, default: u64) -> u64 {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

/// Seconds taken by `n` passes of `pass`.
fn time(n: u64, pass: &mut dyn FnMut()) -> f64 {
    let start = Instant::now();
    for _ in 0..n {
        pass();
    }
    start.elapsed().as_secs_f64()
}

fn main() {
    // `cargo bench` passes `--bench` (a name filter is not supported);
    // `cargo test --all-targets` runs this once, as a smoke test: one
    // round of single passes.
    let measure = std::env::args().any(|a| a == "--bench");
    let rounds = if measure {
        setting("POOLS_ROUNDS", 30).max(1)
    } else {
        1
    };
    let batch = if measure {
        setting("POOLS_BATCH_MS", 2) as f64 / 1e3
    } else {
        0.0
    };
    if !measure {
        println!("Smoke test (one pass each, not a measurement): `cargo bench --bench pools`.");
    }
    println!(
        "| pool | triangles | px each | limit ns/tri | draw | draw_spans | for_each_span | EdgeWalk@12 | tiny-skia | embedded-graphics |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|");
    for (name, pool) in POOLS {
        let pool = Prepared::new(&pool());
        let mut targets = Targets::new();
        let mut contenders = contenders(&pool, &mut targets);
        // Passes per batch, from one warm pass each.
        let passes: Vec<u64> = contenders
            .iter_mut()
            .map(|(_, pass)| {
                let once = time(1, pass.as_mut()).max(1e-7);
                ((batch / once) as u64).max(1)
            })
            .collect();
        let mut best = vec![f64::MAX; contenders.len()];
        for _ in 0..rounds {
            for ((_, pass), (n, best)) in contenders.iter_mut().zip(passes.iter().zip(&mut best)) {
                *best = best.min(time(*n, pass.as_mut()) / *n as f64);
            }
        }
        let limit = best[0];
        let ratios: Vec<String> = best[1..]
            .iter()
            .map(|&t| format!("{:.2}", limit / t))
            .collect();
        println!(
            "| {name} | {} | {} | {} | {} |",
            pool.tris.len(),
            group_thousands((pool.pixels as f64 / pool.tris.len() as f64).round() as u64),
            group_thousands((limit * 1e9 / pool.tris.len() as f64).round() as u64),
            ratios.join(" | ")
        );
    }
}

/// `n` with commas between thousands.
fn group_thousands(n: u64) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(3) {
            out.push(',');
        }
        out.push(c);
    }
    out
}
