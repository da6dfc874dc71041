//! Pools of random fat triangles with fractional (1/4096 px) vertices on a
//! 320 x 240 Rgb565 target, each pool drawn by every contender in one run,
//! beside the memory limit: `slice::fill` of the same exact spans into a
//! plain `[u16]` frame.
//!
//! | contender | what it does |
//! |---|---|
//! | `limit` | the exact spans, precomputed, each one `slice::fill` on `[u16]` |
//! | `draw` | this crate's default `FilledTriangle::draw` on its `Framebuffer<Rgb565Le>` (the `DrawTarget` path) |
//! | `draw_spans` | the same through the span sink, straight into the framebuffer's rows |
//! | `for_each_span` | the exact rasterizer alone, each span `slice::fill` on `[u16]` |
//! | `EdgeWalk@12` | the inexact 16.16 edge-walking variant, `draw_spans` on the framebuffer |
//! | `tiny-skia` | tiny-skia 0.12 `fill_path`, no anti-aliasing, on its RGBA pixmap |
//! | `embedded-graphics` | embedded-graphics 0.8 filled `Triangle` (vertices rounded to pixels) on the framebuffer |
//!
//! `cargo bench --bench pools`, then `python3 benches/report.py pools`
//! prints each contender's time as a fraction of the limit's.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use embedded_graphics::{
    pixelcolor::{Rgb565, RgbColor},
    prelude::*,
    primitives::{PrimitiveStyle, Rectangle, Triangle as EgTriangle},
};
use embedded_raster::{
    framebuffer::{buffer_size, Rgb565Le},
    Framebuffer, Span, SpanDrawable, Triangle, TriangleAlgorithm, Vertex,
};
use tiny_skia::{FillRule, Paint, PathBuilder, Pixmap, Transform};

const W: usize = 320;
const H: usize = 240;
type Fb = Framebuffer<Rgb565Le, W, H, { buffer_size::<Rgb565Le>(W, H) }>;

/// xorshift64*: a fixed, dependency-free sequence.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    /// Uniform in `[0, 1)`.
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// A raw 20.12 coordinate from pixels, at 1/4096 px.
fn raw(px: f64) -> i32 {
    (px * 4096.0).round() as i32
}

/// `count` fat triangles `size` px across: corners on a circle of diameter
/// `size` around a random centre, 120 degrees apart give or take 30, at
/// fractional positions. With `margin`, centres keep the whole triangle on
/// screen; without, they may lie anywhere on it (partly clipped).
fn fat_pool(seed: u64, count: usize, size: f64, on_screen: bool) -> Vec<[(i32, i32); 3]> {
    let mut rng = Rng(seed);
    let r = size / 2.0;
    let margin = if on_screen { r + 1.0 } else { 0.0 };
    (0..count)
        .map(|_| {
            let cx = margin + rng.unit() * (W as f64 - 2.0 * margin);
            let cy = margin + rng.unit() * (H as f64 - 2.0 * margin);
            let a0 = rng.unit() * std::f64::consts::TAU;
            [0.0, 1.0, 2.0].map(|k: f64| {
                let a = a0 + k * std::f64::consts::TAU / 3.0 + (rng.unit() - 0.5) * 1.0;
                (raw(cx + r * a.cos()), raw(cy + r * a.sin()))
            })
        })
        .collect()
}

/// A 32 x 24 grid of 10 x 10 px cells over the screen, two triangles a
/// cell, inner grid points jittered by up to 3 px at 1/4096 px: a mesh
/// that covers every pixel once.
fn mesh_pool(seed: u64) -> Vec<[(i32, i32); 3]> {
    let mut rng = Rng(seed);
    let (nx, ny) = (32usize, 24usize);
    let mut grid = vec![(0i32, 0i32); (nx + 1) * (ny + 1)];
    for j in 0..=ny {
        for i in 0..=nx {
            let inner = i > 0 && i < nx && j > 0 && j < ny;
            let jitter = |rng: &mut Rng| if inner { (rng.unit() - 0.5) * 6.0 } else { 0.0 };
            let x = i as f64 * 10.0 + jitter(&mut rng);
            let y = j as f64 * 10.0 + jitter(&mut rng);
            grid[j * (nx + 1) + i] = (raw(x), raw(y));
        }
    }
    let at = |i: usize, j: usize| grid[j * (nx + 1) + i];
    let mut tris = vec![];
    for j in 0..ny {
        for i in 0..nx {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            tris.push([a, b, c]);
            tris.push([a, c, d]);
        }
    }
    tris
}

fn ours(t: &[(i32, i32); 3]) -> Triangle {
    let v = t.map(|(x, y)| Vertex::from_raw(x, y));
    Triangle::new(v[0], v[1], v[2])
}

/// Fills `span` of a plain row-major `[u16]` frame.
#[inline(always)]
fn fill_u16(frame: &mut [u16], s: Span, color: u16) {
    let row = s.y as usize * W;
    frame[row + s.x_start as usize..row + s.x_end as usize].fill(color);
}

fn bench_pool(c: &mut Criterion, name: &str, pool: &[[(i32, i32); 3]]) {
    let tris: Vec<Triangle> = pool.iter().map(ours).collect();
    let clip = Rectangle::new(Point::zero(), Size::new(W as u32, H as u32));
    let mut spans: Vec<Span> = vec![];
    for t in &tris {
        t.for_each_span(&clip, |s| {
            spans.push(s);
            Ok::<(), ()>(())
        })
        .unwrap();
    }
    let pixels: u64 = spans.iter().map(|s| u64::from(s.len())).sum();
    let n = tris.len();

    let mut g = c.benchmark_group(name);
    g.throughput(Throughput::Elements(pixels));
    let mut fb = Box::new(Fb::new());
    let mut frame = vec![0u16; W * H];

    g.bench_function(BenchmarkId::new("limit", n), |b| {
        b.iter(|| {
            for &s in &spans {
                fill_u16(&mut frame, s, 0xF800);
            }
            black_box(&frame);
        })
    });
    g.bench_function(BenchmarkId::new("draw", n), |b| {
        b.iter(|| {
            for t in &tris {
                t.fill(Rgb565::RED).draw(&mut *fb).unwrap();
            }
            black_box(&fb);
        })
    });
    g.bench_function(BenchmarkId::new("draw_spans", n), |b| {
        b.iter(|| {
            for t in &tris {
                t.fill(Rgb565::RED).draw_spans(&mut *fb).unwrap();
            }
            black_box(&fb);
        })
    });
    g.bench_function(BenchmarkId::new("for_each_span", n), |b| {
        b.iter(|| {
            for t in &tris {
                t.for_each_span(&clip, |s| {
                    fill_u16(&mut frame, s, 0xF800);
                    Ok::<(), ()>(())
                })
                .unwrap();
            }
            black_box(&frame);
        })
    });
    g.bench_function(BenchmarkId::new("EdgeWalk@12", n), |b| {
        b.iter(|| {
            for t in &tris {
                t.fill(Rgb565::RED)
                    .algorithm(TriangleAlgorithm::EdgeWalk)
                    .draw_spans(&mut *fb)
                    .unwrap();
            }
            black_box(&fb);
        })
    });

    let mut pixmap = Pixmap::new(W as u32, H as u32).unwrap();
    let mut paint = Paint::default();
    paint.set_color_rgba8(255, 0, 0, 255);
    paint.anti_alias = false;
    let paths: Vec<_> = pool
        .iter()
        .map(|t| {
            let f = |(x, y): (i32, i32)| (x as f32 / 4096.0, y as f32 / 4096.0);
            let mut pb = PathBuilder::new();
            pb.move_to(f(t[0]).0, f(t[0]).1);
            pb.line_to(f(t[1]).0, f(t[1]).1);
            pb.line_to(f(t[2]).0, f(t[2]).1);
            pb.close();
            pb.finish().unwrap()
        })
        .collect();
    g.bench_function(BenchmarkId::new("tiny-skia", n), |b| {
        b.iter(|| {
            for p in &paths {
                pixmap.fill_path(p, &paint, FillRule::Winding, Transform::identity(), None);
            }
            black_box(&pixmap);
        })
    });

    let eg: Vec<_> = pool
        .iter()
        .map(|t| {
            let p = t.map(|(x, y)| Point::new((x + 2048) >> 12, (y + 2048) >> 12));
            EgTriangle::new(p[0], p[1], p[2]).into_styled(PrimitiveStyle::with_fill(Rgb565::GREEN))
        })
        .collect();
    g.bench_function(BenchmarkId::new("embedded-graphics", n), |b| {
        b.iter(|| {
            for t in &eg {
                t.draw(&mut *fb).unwrap();
            }
            black_box(&fb);
        })
    });
    g.finish();
}

fn pools(c: &mut Criterion) {
    bench_pool(c, "pool tiny 4 px", &fat_pool(1, 512, 4.0, true));
    bench_pool(c, "pool small 16 px", &fat_pool(2, 256, 16.0, true));
    bench_pool(c, "pool medium 64 px", &fat_pool(3, 64, 64.0, true));
    bench_pool(c, "pool large 240 px", &fat_pool(4, 16, 240.0, false));
    bench_pool(c, "pool mesh 32x24 of 10 px", &mesh_pool(5));
}

criterion_group!(benches, pools);
criterion_main!(benches);
