//! Flat triangles on a 320 x 240 Rgb565 framebuffer: this crate beside a
//! plain span fill of the same pixels (the memory limit), embedded-graphics
//! 0.8's filled `Triangle` on the same framebuffer, and tiny-skia's
//! non-anti-aliased `fill_path` on its own RGBA pixmap.
//!
//! `cargo bench --bench triangles`; `benches/report.py` turns the medians
//! into the table in BENCHMARKS.md.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use embedded_graphics::{
    pixelcolor::Rgb565,
    prelude::*,
    primitives::{PrimitiveStyle, Rectangle, Triangle as EgTriangle},
};
use embedded_raster::{
    framebuffer::{buffer_size, Rgb565Le},
    Framebuffer, Span, Triangle,
};
use tiny_skia::{FillRule, Paint, PathBuilder, Pixmap, Transform};

const W: usize = 320;
const H: usize = 240;
type Fb = Framebuffer<Rgb565Le, W, H, { buffer_size::<Rgb565Le>(W, H) }>;

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
    let mut paint = Paint::default();
    paint.set_color_rgba8(255, 0, 0, 255);
    paint.anti_alias = false;
    let paths: Vec<_> = scene
        .tris
        .iter()
        .map(|t| {
            let mut pb = PathBuilder::new();
            let f = |p: Point| (p.x as f32 + 0.5, p.y as f32 + 0.5);
            pb.move_to(f(t[0]).0, f(t[0]).1);
            pb.line_to(f(t[1]).0, f(t[1]).1);
            pb.line_to(f(t[2]).0, f(t[2]).1);
            pb.close();
            pb.finish().unwrap()
        })
        .collect();
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

criterion_group!(benches, triangles);
criterion_main!(benches);
