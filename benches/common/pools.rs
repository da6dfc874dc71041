//! The inputs of the triangle benchmarks' random pools, shared by
//! `benches/triangles.rs` (criterion) and `benches/pools.rs` (interleaved
//! rounds): the pools themselves, the screen, the exact spans (the memory
//! limit's work) and tiny-skia's paths.

// Each benchmark uses what it needs.
#![allow(dead_code)]

use embedded_graphics::{prelude::*, primitives::Rectangle};
use embedded_raster::{
    framebuffer::{buffer_size, Rgb565Le},
    Framebuffer, Span, Triangle, Vertex,
};
use tiny_skia::{Paint, PathBuilder};

#[path = "../../tests/common/rng.rs"]
mod rng;
use rng::Rng;

/// The screen's size, and its framebuffer.
pub const W: usize = 320;
pub const H: usize = 240;
pub type Fb = Framebuffer<Rgb565Le, W, H, { buffer_size::<Rgb565Le>(W, H) }>;

/// A pool: triangles as raw 20.12 corners.
pub type Pool = Vec<[(i32, i32); 3]>;

/// A named pool's generator.
pub type NamedPool = (&'static str, fn() -> Pool);

/// The random pools by name: random fat triangles with fractional
/// vertices, and a jittered mesh.
pub const POOLS: [NamedPool; 5] = [
    ("tiny 4 px", || fat_pool(1, 512, 4.0, true)),
    ("small 16 px", || fat_pool(2, 256, 16.0, true)),
    ("medium 64 px", || fat_pool(3, 64, 64.0, true)),
    ("large 240 px", || fat_pool(4, 16, 240.0, false)),
    ("mesh 32x24 of 10 px", || mesh_pool(5)),
];

/// The screen.
pub fn screen() -> Rectangle {
    Rectangle::new(Point::zero(), Size::new(W as u32, H as u32))
}

/// The exact spans of `tris` on the screen, and their pixel count.
pub fn spans_of(tris: &[Triangle]) -> (Vec<Span>, u64) {
    let mut spans: Vec<Span> = vec![];
    for t in tris {
        t.for_each_span(&screen(), |s| {
            spans.push(s);
            Ok::<(), ()>(())
        })
        .unwrap();
    }
    let pixels = spans.iter().map(|s| u64::from(s.len())).sum();
    (spans, pixels)
}

/// tiny-skia paths of triangles given in pixels, and a solid red paint
/// without anti-aliasing.
pub fn skia_paths(
    tris: impl Iterator<Item = [(f32, f32); 3]>,
) -> (Vec<tiny_skia::Path>, Paint<'static>) {
    let paths = tris
        .map(|t| {
            let mut pb = PathBuilder::new();
            pb.move_to(t[0].0, t[0].1);
            pb.line_to(t[1].0, t[1].1);
            pb.line_to(t[2].0, t[2].1);
            pb.close();
            pb.finish().unwrap()
        })
        .collect();
    let mut paint = Paint::default();
    paint.set_color_rgba8(255, 0, 0, 255);
    paint.anti_alias = false;
    (paths, paint)
}

/// A raw 20.12 coordinate from pixels, at 1/4096 px.
pub fn raw(px: f64) -> i32 {
    (px * 4096.0).round() as i32
}

/// `count` fat triangles `size` px across: corners on a circle of diameter
/// `size` around a random centre, 120 degrees apart give or take 30, at
/// fractional positions. With `margin`, centres keep the whole triangle on
/// screen; without, they may lie anywhere on it (partly clipped).
pub fn fat_pool(seed: u64, count: usize, size: f64, on_screen: bool) -> Vec<[(i32, i32); 3]> {
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
pub fn mesh_pool(seed: u64) -> Vec<[(i32, i32); 3]> {
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

pub fn raw_triangle(t: &[(i32, i32); 3]) -> Triangle {
    let v = t.map(|(x, y)| Vertex::from_raw(x, y));
    Triangle::new(v[0], v[1], v[2])
}

/// Fills `span` of a plain row-major `[u16]` frame.
#[inline(always)]
pub fn fill_u16(frame: &mut [u16], s: Span, color: u16) {
    let row = s.y as usize * W;
    frame[row + s.x_start as usize..row + s.x_end as usize].fill(color);
}
