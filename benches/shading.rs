//! Shading cost per pixel on the 320 x 240 Rgb565 framebuffer: the same
//! triangles drawn flat, flat with depth, Gouraud and Gouraud with depth.
//!
//! `cargo bench --bench shading`; the medians (criterion's `thrpt` is
//! pixels per second) go into the "Shading" table in BENCHMARKS.md.
//!
//! With depth, every iteration draws 1 nearer than the last (so every
//! pixel passes and is written, as in a first draw on a cleared buffer);
//! the buffer is cleared only when the depths run out, once in ~60 000
//! iterations.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use embedded_graphics::{pixelcolor::Rgb565, prelude::*, primitives::Rectangle};
use embedded_raster::{
    framebuffer::{buffer_size, Rgb565Le},
    shade::DepthBuffer,
    Framebuffer, Triangle, Vertex,
};

const W: usize = 320;
const H: usize = 240;
type Fb = Framebuffer<Rgb565Le, W, H, { buffer_size::<Rgb565Le>(W, H) }>;

/// Irregular triangles `size` px across with fractional corners, repeated
/// over the screen (at most 64).
fn sized(size: i32) -> Vec<Triangle> {
    let shape = [(0.05, 0.1), (0.98, 0.35), (0.3, 0.97)];
    let step = size.max(8);
    let mut tris = vec![];
    let mut y = 0;
    while y + size <= H as i32 && tris.len() < 64 {
        let mut x = 0;
        while x + size <= W as i32 && tris.len() < 64 {
            let [a, b, c] = shape.map(|(u, v)| {
                Vertex::try_from_num(
                    f64::from(x) + u * f64::from(size),
                    f64::from(y) + v * f64::from(size),
                )
                .unwrap()
            });
            tris.push(Triangle::new(a, b, c));
            x += step;
        }
        y += step;
    }
    tris
}

/// The whole screen as 16 x 12 cells of two triangles: every pixel once.
fn mesh() -> Vec<Triangle> {
    let p = |i: i32, j: i32| {
        Triangle::from_points(Point::new(i * 20, j * 20), Point::zero(), Point::zero())
            .unwrap()
            .vertices[0]
    };
    let mut tris = vec![];
    for j in 0..12 {
        for i in 0..16 {
            let (a, b, c, d) = (p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1));
            tris.push(Triangle::new(a, b, c));
            tris.push(Triangle::new(a, c, d));
        }
    }
    tris
}

const COLORS: [Rgb565; 3] = [
    Rgb565::new(31, 10, 0),
    Rgb565::new(0, 63, 8),
    Rgb565::new(4, 20, 31),
];

fn bench_scene(c: &mut Criterion, name: &str, tris: &[Triangle]) {
    let clip = Rectangle::new(Point::zero(), Size::new(W as u32, H as u32));
    let mut pixels = 0u64;
    for t in tris {
        t.for_each_span(&clip, |s| {
            pixels += u64::from(s.len());
            Ok::<(), ()>(())
        })
        .unwrap();
    }
    let mut g = c.benchmark_group(format!("shading {name}"));
    g.throughput(Throughput::Elements(pixels));
    let mut fb = Box::new(Fb::new());
    let mut storage = vec![0u16; W * H];
    let depth = DepthBuffer::new(&mut storage, W as u32);
    depth.clear();
    // The next depth offset: decreasing, so every draw passes.
    let mut k = 60_000u16;
    let mut nearer = move || {
        if k < 2 {
            depth.clear();
            k = 60_000;
        }
        k -= 1;
        // All three 1 nearer than last time: every pixel's depth is too.
        [k, k + 2000, k + 5000]
    };

    g.bench_function(BenchmarkId::new("flat", tris.len()), |b| {
        b.iter(|| {
            for t in tris {
                t.fill(COLORS[0]).draw(&mut *fb).unwrap();
            }
            black_box(&fb);
        })
    });
    g.bench_function(BenchmarkId::new("flat+depth", tris.len()), |b| {
        b.iter(|| {
            let z = nearer();
            for t in tris {
                t.fill(COLORS[0])
                    .with_depth(z, depth)
                    .draw(&mut *fb)
                    .unwrap();
            }
            black_box(&fb);
        })
    });
    g.bench_function(BenchmarkId::new("gouraud", tris.len()), |b| {
        b.iter(|| {
            for t in tris {
                t.gouraud(COLORS).draw(&mut *fb).unwrap();
            }
            black_box(&fb);
        })
    });
    g.bench_function(BenchmarkId::new("gouraud+depth", tris.len()), |b| {
        b.iter(|| {
            let z = nearer();
            for t in tris {
                t.gouraud(COLORS)
                    .with_depth(z, depth)
                    .draw(&mut *fb)
                    .unwrap();
            }
            black_box(&fb);
        })
    });
    g.finish();
}

fn shading(c: &mut Criterion) {
    bench_scene(c, "16 px", &sized(16));
    bench_scene(c, "64 px", &sized(64));
    bench_scene(c, "240 px", &sized(240));
    bench_scene(c, "mesh 320x240", &mesh());
}

criterion_group!(benches, shading);
criterion_main!(benches);
