//! Filled polygons on a 320 x 240 Rgb565 framebuffer: the crate's fill
//! (`Polygon::fill(..).draw(..)`: convex polygons as two chains of edges,
//! the others by the active edge table) beside triangulating and filling
//! the triangles (per draw, and with the triangles computed once), and
//! tiny-skia's non-anti-aliased `fill_path` on its own RGBA pixmap.
//!
//! `cargo bench --bench polygons`; `benches/report.py polygons` prints the
//! table in BENCHMARKS.md.

use std::f64::consts::TAU;
use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use embedded_graphics::{pixelcolor::Rgb565, prelude::*, primitives::Rectangle};
use embedded_raster::{
    framebuffer::{buffer_size, Rgb565Le},
    FillRule, Framebuffer, Polygon, Triangle, Vertex,
};
use tiny_skia::{FillRule as SkFillRule, Paint, PathBuilder, Pixmap, Transform};

const W: usize = 320;
const H: usize = 240;
const CAP: usize = 64;
type Fb = Framebuffer<Rgb565Le, W, H, { buffer_size::<Rgb565Le>(W, H) }>;

struct Set {
    name: &'static str,
    polygons: Vec<Vec<(f64, f64)>>,
    simple: bool,
}

/// A star-shaped polygon of `n` vertices around `(cx, cy)`, radius `r`
/// scaled per vertex by `radii` (cycled).
fn ring(n: usize, cx: f64, cy: f64, r: f64, radii: &[f64]) -> Vec<(f64, f64)> {
    (0..n)
        .map(|k| {
            let a = TAU * k as f64 / n as f64;
            let rk = r * radii[k % radii.len()];
            (cx + rk * a.cos(), cy + rk * a.sin())
        })
        .collect()
}

fn sets() -> Vec<Set> {
    let hexagons = (0..60)
        .map(|k| {
            ring(
                6,
                12.0 + (k % 12) as f64 * 25.0,
                14.0 + (k / 12) as f64 * 45.0,
                9.0,
                &[1.0],
            )
        })
        .collect();
    // Random octagons as `.ci/icount` has them: vertices at fractional
    // positions, by angle round a centre (so simple), radii 40 % to 100 %
    // of 13 px (so often concave).
    let mut state = 0x2545_F491_4F6C_DD1Du64;
    let mut random = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let octagons = (0..60)
        .map(|k| {
            let (cx, cy) = (
                16.0 + (k % 10) as f64 * 30.0 + random(),
                16.0 + (k / 10) as f64 * 36.0 + random(),
            );
            (0..8)
                .map(|j| {
                    let a = TAU * (j as f64 + 0.8 * random() - 0.4) / 8.0;
                    let r = 13.0 * (0.4 + 0.6 * random());
                    (cx + r * a.cos(), cy + r * a.sin())
                })
                .collect()
        })
        .collect();
    vec![
        Set {
            name: "hexagons 18 px (x60)",
            polygons: hexagons,
            simple: true,
        },
        Set {
            name: "random octagons 26 px (x60)",
            polygons: octagons,
            simple: true,
        },
        Set {
            name: "convex 24-gon 200 px",
            polygons: vec![ring(24, 160.0, 120.0, 100.0, &[1.0])],
            simple: true,
        },
        Set {
            name: "concave star 24 vertices 200 px",
            polygons: vec![ring(24, 160.0, 120.0, 100.0, &[1.0, 0.45, 0.8, 0.6])],
            simple: true,
        },
        Set {
            name: "pentagram 200 px (self-intersecting)",
            polygons: vec![(0..5)
                .map(|k| {
                    let a = TAU * (2 * k) as f64 / 5.0 - TAU / 4.0;
                    (160.0 + 110.0 * a.cos(), 125.0 + 110.0 * a.sin())
                })
                .collect()],
            simple: false,
        },
    ]
}

fn vertices(p: &[(f64, f64)]) -> Vec<Vertex> {
    p.iter()
        .map(|&(x, y)| Vertex::try_from_num(x, y).unwrap())
        .collect()
}

fn bench_set(c: &mut Criterion, set: &Set) {
    let polys: Vec<Vec<Vertex>> = set.polygons.iter().map(|p| vertices(p)).collect();
    let clip = Rectangle::new(Point::zero(), Size::new(W as u32, H as u32));
    let mut pixels = 0u64;
    for p in &polys {
        Polygon::<CAP>::new(p)
            .unwrap()
            .for_each_span(FillRule::NonZero, &clip, |s| {
                pixels += u64::from(s.len());
                Ok::<(), ()>(())
            })
            .unwrap();
    }

    let mut g = c.benchmark_group(set.name);
    g.throughput(Throughput::Elements(pixels));
    let mut fb = Box::new(Fb::new());

    g.bench_function("fill", |b| {
        b.iter(|| {
            for p in &polys {
                Polygon::<CAP>::new(p)
                    .unwrap()
                    .fill(Rgb565::RED)
                    .draw(&mut *fb)
                    .unwrap();
            }
            black_box(&fb);
        })
    });

    if set.simple {
        g.bench_function("triangulate and fill", |b| {
            b.iter(|| {
                for p in &polys {
                    Polygon::<CAP>::new(p)
                        .unwrap()
                        .triangulate(|t| t.fill(Rgb565::GREEN).draw(&mut *fb).unwrap())
                        .unwrap();
                }
                black_box(&fb);
            })
        });
        let mut tris: Vec<Triangle> = vec![];
        for p in &polys {
            Polygon::<CAP>::new(p)
                .unwrap()
                .triangulate(|t| tris.push(t))
                .unwrap();
        }
        g.bench_function("fill triangulated once", |b| {
            b.iter(|| {
                for t in &tris {
                    t.fill(Rgb565::BLUE).draw(&mut *fb).unwrap();
                }
                black_box(&fb);
            })
        });
    }

    let mut pixmap = Pixmap::new(W as u32, H as u32).unwrap();
    let mut paint = Paint::default();
    paint.set_color_rgba8(255, 0, 0, 255);
    paint.anti_alias = false;
    let paths: Vec<_> = set
        .polygons
        .iter()
        .map(|p| {
            let mut pb = PathBuilder::new();
            pb.move_to(p[0].0 as f32, p[0].1 as f32);
            for &(x, y) in &p[1..] {
                pb.line_to(x as f32, y as f32);
            }
            pb.close();
            pb.finish().unwrap()
        })
        .collect();
    g.bench_function("tiny-skia", |b| {
        b.iter(|| {
            for p in &paths {
                pixmap.fill_path(p, &paint, SkFillRule::Winding, Transform::identity(), None);
            }
            black_box(&pixmap);
        })
    });
    g.finish();
}

fn polygons(c: &mut Criterion) {
    for set in sets() {
        bench_set(c, &set);
    }
}

criterion_group!(benches, polygons);
criterion_main!(benches);
