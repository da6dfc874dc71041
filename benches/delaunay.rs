//! Delaunay triangulation of 100 and 1,000 points on the host: uniformly
//! random points over a 320 x 240 screen (a fixed seed), and a square grid
//! (every quadrilateral cocircular).
//!
//! `cargo bench --bench delaunay -- --warm-up-time 1 --measurement-time 4`

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use embedded_raster::{delaunay::Delaunay, Vertex};

/// `n` points uniformly over 320 x 240 px, on the 1/4096 grid.
fn random_points(n: usize) -> Vec<Vertex> {
    let mut seed = 0x2545_f491_4f6c_dd1du64;
    let mut next = |m: u64| {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed % m) as i32
    };
    (0..n)
        .map(|_| Vertex::from_raw(next(320 * 4096), next(240 * 4096)))
        .collect()
}

/// A `side` x `side` grid, 7 px apart.
fn grid_points(side: usize) -> Vec<Vertex> {
    (0..side * side)
        .map(|k| {
            let (i, j) = ((k % side) as i32, (k / side) as i32);
            Vertex::from_raw((4 + 7 * i) * 4096, (4 + 7 * j) * 4096)
        })
        .collect()
}

fn delaunay(c: &mut Criterion) {
    let sets = [
        ("random 100", random_points(100)),
        ("random 1000", random_points(1000)),
        ("grid 10x10", grid_points(10)),
        ("grid 32x32", grid_points(32)),
    ];
    let mut storage = Box::new(Delaunay::<1024>::new());
    let mut g = c.benchmark_group("delaunay");
    for (name, points) in &sets {
        g.throughput(Throughput::Elements(points.len() as u64));
        g.bench_function(*name, |b| {
            b.iter(|| black_box(storage.triangulate(black_box(points)).unwrap().len()))
        });
    }
    g.finish();
}

criterion_group!(benches, delaunay);
criterion_main!(benches);
