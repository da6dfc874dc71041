//! Band rendering against the whole frame, in one run: the demo scene and
//! the mesh scene (`scenes/`) as display lists on a 320 x 240 Rgb565
//! target, drawn whole into a full framebuffer and rendered in bands of
//! 1, 8, 16 and 32 rows through one band buffer (the finished bands go
//! nowhere: sending them costs the same either way).
//!
//! `cargo bench --bench bands`; `python3 benches/report.py bands` prints
//! the table in BENCHMARKS.md and the README.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use embedded_graphics::{
    pixelcolor::{Rgb565, Rgb888},
    primitives::Rectangle,
};
use embedded_raster::{
    band::{Command, DisplayList},
    framebuffer::{buffer_size, Rgb565Le},
    sim::{self, parse_scene},
    Framebuffer, Polygon, Polyline,
};

type List<'a> = DisplayList<'a, Rgb565, 512, 1024>;

/// The scene's commands in Rgb565 (its colours converted as
/// embedded-graphics converts them).
fn list(scene: &sim::Scene) -> Box<List<'_>> {
    let c = |c: &Rgb888| Rgb565::from(*c);
    let mut list = Box::new(List::new());
    for command in scene.commands() {
        let command = match command {
            sim::Command::Clear(color) => Command::Clear(c(color)),
            sim::Command::Rect(r, color) => Command::Rect(*r, c(color)),
            sim::Command::Tri(t, color) => Command::Triangle(t.fill(c(color))),
            sim::Command::Gtri(t, colors) => Command::Gouraud(t.gouraud(colors.each_ref().map(c))),
            sim::Command::Line(l, color) => Command::Line(l.stroke(c(color))),
            sim::Command::Polyline(points, color) => {
                Command::Polyline(Polyline::new(points).stroke(c(color)))
            }
            sim::Command::Poly(vertices, rule, color) => Command::Polygon(
                Polygon::new(vertices)
                    .unwrap()
                    .fill(c(color))
                    .with_rule(*rule),
            ),
            other => panic!("no display-list command for {other:?}"),
        };
        list.push(command).unwrap();
    }
    list
}

/// Renders `list` in bands of `R` rows; returns a byte of the last band.
fn banded<const R: usize, const N: usize>(
    list: &List<'_>,
    height: u32,
    buffer: &mut [Framebuffer<Rgb565Le, 320, R, N>; 1],
) -> u8 {
    let mut nowhere = |b: &Framebuffer<Rgb565Le, 320, R, N>, _: Rectangle| {
        black_box(b.as_bytes()[0]);
        Ok::<(), ()>(())
    };
    let _ = list.render_bands(height, buffer, None, &mut nowhere);
    buffer[0].as_bytes()[0]
}

fn bands(c: &mut Criterion) {
    let root = env!("CARGO_MANIFEST_DIR");
    for name in ["demo", "mesh"] {
        let text = std::fs::read_to_string(format!("{root}/scenes/{name}.scene")).unwrap();
        let scene = parse_scene(&text).unwrap();
        // Scenes up to 320 x 240 (the mesh is 256 x 192): the same work on
        // a 320-wide target, clipped alike.
        let size = scene.size();
        assert!(size.width <= 320 && size.height <= 240);
        let height = size.height;
        let list = list(&scene);
        let mut group = c.benchmark_group(format!("bands {name}"));
        let mut whole = Box::new(Framebuffer::<
            Rgb565Le,
            320,
            240,
            { buffer_size::<Rgb565Le>(320, 240) },
        >::new());
        group.bench_function(BenchmarkId::new("whole frame", 240), |b| {
            b.iter(|| list.draw_with_depth(black_box(&mut *whole), None))
        });
        let mut b1 = Box::new([Framebuffer::<
            Rgb565Le,
            320,
            1,
            { buffer_size::<Rgb565Le>(320, 1) },
        >::new()]);
        group.bench_function(BenchmarkId::new("bands", 1), |b| {
            b.iter(|| banded(&list, height, &mut b1))
        });
        let mut b8 = Box::new([Framebuffer::<
            Rgb565Le,
            320,
            8,
            { buffer_size::<Rgb565Le>(320, 8) },
        >::new()]);
        group.bench_function(BenchmarkId::new("bands", 8), |b| {
            b.iter(|| banded(&list, height, &mut b8))
        });
        let mut b16 = Box::new([Framebuffer::<
            Rgb565Le,
            320,
            16,
            { buffer_size::<Rgb565Le>(320, 16) },
        >::new()]);
        group.bench_function(BenchmarkId::new("bands", 16), |b| {
            b.iter(|| banded(&list, height, &mut b16))
        });
        let mut b32 = Box::new([Framebuffer::<
            Rgb565Le,
            320,
            32,
            { buffer_size::<Rgb565Le>(320, 32) },
        >::new()]);
        group.bench_function(BenchmarkId::new("bands", 32), |b| {
            b.iter(|| banded(&list, height, &mut b32))
        });
        let mut b240 = Box::new([Framebuffer::<
            Rgb565Le,
            320,
            240,
            { buffer_size::<Rgb565Le>(320, 240) },
        >::new()]);
        group.bench_function(BenchmarkId::new("bands", 240), |b| {
            b.iter(|| banded(&list, height, &mut b240))
        });
        group.finish();
    }
}

criterion_group!(benches, bands);
criterion_main!(benches);
