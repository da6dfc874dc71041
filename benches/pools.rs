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

use std::{hint::black_box, time::Instant};

use embedded_graphics::{
    pixelcolor::{Rgb565, RgbColor},
    prelude::*,
    primitives::{PrimitiveStyle, Triangle as EgTriangle},
};
use embedded_raster::{SpanDrawable, Triangle, TriangleAlgorithm};
use tiny_skia::{FillRule, Pixmap, Transform};

#[path = "common/pools.rs"]
mod pools;
use pools::{fill_u16, raw_triangle, screen, skia_paths, spans_of, Fb, H, POOLS, W};

/// A contender: its name and one pass over the pool.
type Contender<'a> = (&'static str, Box<dyn FnMut() + 'a>);

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
        let pool = pool();
        let tris: Vec<Triangle> = pool.iter().map(raw_triangle).collect();
        let (spans, pixels) = spans_of(&tris);
        let clip = screen();
        let px = |(x, y): (i32, i32)| (x as f32 / 4096.0, y as f32 / 4096.0);
        let (paths, paint) = skia_paths(pool.iter().map(|t| t.map(px)));
        let eg: Vec<_> = pool
            .iter()
            .map(|t| {
                let p = t.map(|(x, y)| Point::new((x + 2048) >> 12, (y + 2048) >> 12));
                EgTriangle::new(p[0], p[1], p[2])
                    .into_styled(PrimitiveStyle::with_fill(Rgb565::GREEN))
            })
            .collect();
        // Each contender draws on a target of its own.
        let (mut frame, mut frame2) = (vec![0u16; W * H], vec![0u16; W * H]);
        let mut fbs: Vec<Box<Fb>> = (0..4).map(|_| Box::new(Fb::new())).collect();
        let [fb_draw, fb_spans, fb_walk, fb_eg] = &mut fbs[..] else {
            unreachable!()
        };
        let mut pixmap = Pixmap::new(W as u32, H as u32).unwrap();
        let mut contenders: Vec<Contender<'_>> = vec![
            (
                "limit",
                Box::new(|| {
                    for &s in &spans {
                        fill_u16(&mut frame, s, 0xF800);
                    }
                    black_box(&frame);
                }),
            ),
            (
                "draw",
                Box::new(|| {
                    for t in &tris {
                        t.fill(Rgb565::RED).draw(&mut **fb_draw).unwrap();
                    }
                    black_box(&fb_draw);
                }),
            ),
            (
                "draw_spans",
                Box::new(|| {
                    for t in &tris {
                        t.fill(Rgb565::RED).draw_spans(&mut **fb_spans).unwrap();
                    }
                    black_box(&fb_spans);
                }),
            ),
            (
                "for_each_span",
                Box::new(|| {
                    for t in &tris {
                        t.for_each_span(&clip, |s| {
                            fill_u16(&mut frame2, s, 0xF800);
                            Ok::<(), ()>(())
                        })
                        .unwrap();
                    }
                    black_box(&frame2);
                }),
            ),
            (
                "EdgeWalk@12",
                Box::new(|| {
                    for t in &tris {
                        t.fill(Rgb565::RED)
                            .algorithm(TriangleAlgorithm::EdgeWalk)
                            .draw_spans(&mut **fb_walk)
                            .unwrap();
                    }
                    black_box(&fb_walk);
                }),
            ),
            (
                "tiny-skia",
                Box::new(|| {
                    for p in &paths {
                        pixmap.fill_path(p, &paint, FillRule::Winding, Transform::identity(), None);
                    }
                    black_box(&pixmap);
                }),
            ),
            (
                "embedded-graphics",
                Box::new(|| {
                    for t in &eg {
                        t.draw(&mut **fb_eg).unwrap();
                    }
                    black_box(&fb_eg);
                }),
            ),
        ];
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
            tris.len(),
            group_thousands((pixels as f64 / tris.len() as f64).round() as u64),
            group_thousands((limit * 1e9 / tris.len() as f64).round() as u64),
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
