//! Delaunay triangulation of 100 and 1,000 points on the host: uniformly
//! random points over a 320 x 240 screen (a fixed seed), and square grids
//! (every cell cocircular); the sets `examples/icount_delaunay.rs` counts
//! instructions for on the Cortex-M4.
//!
//! `cargo bench --bench delaunay -- --warm-up-time 1 --measurement-time 4`

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use embedded_raster::{delaunay::Delaunay, Vertex};

#[path = "../examples/common/delaunay_sets.rs"]
mod sets;

fn delaunay(c: &mut Criterion) {
    let mut storage = Box::new(Delaunay::<{ sets::MAX }>::new());
    let mut buffer = Box::new([Vertex::from_raw(0, 0); sets::MAX]);
    let mut g = c.benchmark_group("delaunay");
    for set in sets::SETS {
        let n = sets::fill(set, &mut buffer);
        let points = &buffer[..n];
        g.throughput(Throughput::Elements(points.len() as u64));
        g.bench_function(set.0, |b| {
            b.iter(|| black_box(storage.triangulate(black_box(points)).unwrap().len()))
        });
    }
    g.finish();
}

criterion_group!(benches, delaunay);
criterion_main!(benches);
