//! Flat triangles on a 320 x 240 Rgb565 framebuffer, in two sets.
//!
//! **Regular shapes** (`4 px` ... `mesh 320x240` groups): this crate beside a
//! plain span fill of the same pixels (the memory limit), embedded-graphics
//! 0.8's filled `Triangle` on the same framebuffer, and tiny-skia's
//! non-anti-aliased `fill_path` on its own RGBA pixmap.
//!
//! **Random pools** (`pool ...` groups): random fat triangles with
//! fractional (1/4096 px) vertices, each pool drawn by every contender in
//! one run, beside the memory limit: `slice::fill` of the same exact spans
//! into a plain `[u16]` frame.
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
//! `cargo bench --bench triangles`; `python3 benches/report.py triangles`
//! and `python3 benches/report.py pools` turn the medians into the tables
//! in BENCHMARKS.md.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use embedded_graphics::{
    pixelcolor::{Rgb565, RgbColor},
    prelude::*,
    primitives::{PrimitiveStyle, Triangle as EgTriangle},
};
use embedded_raster::Triangle;

use tiny_skia::{FillRule, Pixmap, Transform};

#[path = "common/pools.rs"]
mod pools;
use pools::{contenders, skia_paths, spans_of, Fb, Prepared, Targets, H, POOLS, W};

/// A scene: triangles as pixel-centre corners (this crate and tiny-skia
/// place them at `p + 1/2`; embedded-graphics takes the pixels).
struct Scene {
    name: &'static str,
    tris: Vec<[Point; 3]>,
}

/// An irregular triangle `size` px across, repeated over the screen so
/// that each iteration touches fresh rows.
fn sized(name: &'static str, size: i32) -> Scene {
    let shape = [(0.05, 0.1), (0.98, 0.35), (0.3, 0.97)];
    let mut tris = vec![];
    let step = size.max(8);
    let mut y = 0;
    while y + size <= H as i32 && tris.len() < 64 {
        let mut x = 0;
        while x + size <= W as i32 && tris.len() < 64 {
            tris.push(shape.map(|(u, v)| {
                Point::new(x + (u * size as f64) as i32, y + (v * size as f64) as i32)
            }));
            x += step;
        }
        y += step;
    }
    Scene { name, tris }
}

/// The whole screen as a 16 x 12 grid of 20 px cells, two triangles each,
/// with jittered inner vertices: every pixel is covered once.
fn mesh() -> Scene {
    let (nx, ny) = (16, 12);
    let point = |i: i32, j: i32| {
        let jitter = |k: i32| {
            if k > 0 && k < 12 {
                ((i * 7 + j * 13) % 9) - 4
            } else {
                0
            }
        };
        Point::new(
            i * 20 + if i < nx { jitter(i) } else { 0 },
            j * 20 + if j < ny { jitter(j) } else { 0 },
        )
    };
    let mut tris = vec![];
    for j in 0..ny {
        for i in 0..nx {
            let (a, b, c, d) = (
                point(i, j),
                point(i + 1, j),
                point(i + 1, j + 1),
                point(i, j + 1),
            );
            tris.push([a, b, c]);
            tris.push([a, c, d]);
        }
    }
    Scene {
        name: "mesh 320x240",
        tris,
    }
}

fn ours(t: &[Point; 3]) -> Triangle {
    Triangle::from_points(t[0], t[1], t[2]).unwrap()
}

fn bench_scene(c: &mut Criterion, scene: &Scene) {
    let tris: Vec<Triangle> = scene.tris.iter().map(ours).collect();
    let (spans, pixels) = spans_of(&tris);

    let mut g = c.benchmark_group(scene.name);
    // Per scene; divide by the triangle count for ns/triangle.
    g.throughput(Throughput::Elements(pixels));
    let mut fb = Box::new(Fb::new());

    g.bench_function(BenchmarkId::new("embedded-raster", tris.len()), |b| {
        b.iter(|| {
            for t in &tris {
                t.fill(Rgb565::RED).draw(&mut *fb).unwrap();
            }
            black_box(&fb);
        })
    });

    g.bench_function(BenchmarkId::new("span fill", tris.len()), |b| {
        b.iter(|| {
            for s in &spans {
                fb.fill_solid(&s.rect(), Rgb565::BLUE).unwrap();
            }
            black_box(&fb);
        })
    });

    let eg: Vec<_> = scene
        .tris
        .iter()
        .map(|t| {
            EgTriangle::new(t[0], t[1], t[2]).into_styled(PrimitiveStyle::with_fill(Rgb565::GREEN))
        })
        .collect();
    g.bench_function(BenchmarkId::new("embedded-graphics", tris.len()), |b| {
        b.iter(|| {
            for t in &eg {
                t.draw(&mut *fb).unwrap();
            }
            black_box(&fb);
        })
    });

    let mut pixmap = Pixmap::new(W as u32, H as u32).unwrap();
    let centre = |p: Point| (p.x as f32 + 0.5, p.y as f32 + 0.5);
    let (paths, paint) = skia_paths(scene.tris.iter().map(|t| t.map(centre)));
    g.bench_function(BenchmarkId::new("tiny-skia", tris.len()), |b| {
        b.iter(|| {
            for p in &paths {
                pixmap.fill_path(p, &paint, FillRule::Winding, Transform::identity(), None);
            }
            black_box(&pixmap);
        })
    });
    g.finish();
}

fn triangles(c: &mut Criterion) {
    for scene in [
        sized("4 px", 4),
        sized("16 px", 16),
        sized("64 px", 64),
        sized("240 px", 240),
        mesh(),
    ] {
        bench_scene(c, &scene);
    }
}

fn bench_pool(c: &mut Criterion, name: &str, pool: &[[(i32, i32); 3]]) {
    let pool = Prepared::new(pool);
    let mut targets = Targets::new();
    let mut g = c.benchmark_group(name);
    g.throughput(Throughput::Elements(pool.pixels));
    for (label, mut pass) in contenders(&pool, &mut targets) {
        g.bench_function(BenchmarkId::new(label, pool.tris.len()), |b| {
            b.iter(&mut pass)
        });
    }
    g.finish();
}

fn pools(c: &mut Criterion) {
    for (name, pool) in POOLS {
        bench_pool(c, &format!("pool {name}"), &pool());
    }
}

criterion_group!(benches, triangles, pools);
criterion_main!(benches);
