//! The triangle benchmarks' random pools and their contenders, shared by
//! `benches/triangles.rs` (criterion) and `benches/pools.rs` (interleaved
//! rounds): the pools themselves, the screen, the exact spans (the memory
//! limit's work), tiny-skia's paths and one pass of each contender.

// Each benchmark uses what it needs.
#![allow(dead_code)]

use std::hint::black_box;

use embedded_graphics::{
    pixelcolor::{Rgb565, RgbColor},
    prelude::*,
    primitives::{PrimitiveStyle, Rectangle, Styled, Triangle as EgTriangle},
};
use embedded_raster::{
    framebuffer::{buffer_size, Rgb565Le},
    Framebuffer, Span, SpanDrawable, Triangle, TriangleAlgorithm, Vertex,
};
use tiny_skia::{FillRule, Paint, PathBuilder, Pixmap, Transform};

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

/// A contender: its name and one pass over a pool.
pub type Contender<'a> = (&'static str, Box<dyn FnMut() + 'a>);

/// A pool as each contender takes it.
pub struct Prepared {
    /// This crate's triangles.
    pub tris: Vec<Triangle>,
    /// Their exact spans (the limit's work) and the pixels they light.
    pub spans: Vec<Span>,
    pub pixels: u64,
    paths: Vec<tiny_skia::Path>,
    paint: Paint<'static>,
    /// embedded-graphics' triangles, corners rounded to pixels.
    eg: Vec<Styled<EgTriangle, PrimitiveStyle<Rgb565>>>,
}

impl Prepared {
    pub fn new(pool: &[[(i32, i32); 3]]) -> Self {
        let tris: Vec<Triangle> = pool.iter().map(raw_triangle).collect();
        let (spans, pixels) = spans_of(&tris);
        let px = |(x, y): (i32, i32)| (x as f32 / 4096.0, y as f32 / 4096.0);
        let (paths, paint) = skia_paths(pool.iter().map(|t| t.map(px)));
        let eg = pool
            .iter()
            .map(|t| {
                let p = t.map(|(x, y)| Point::new((x + 2048) >> 12, (y + 2048) >> 12));
                EgTriangle::new(p[0], p[1], p[2])
                    .into_styled(PrimitiveStyle::with_fill(Rgb565::GREEN))
            })
            .collect();
        Self {
            tris,
            spans,
            pixels,
            paths,
            paint,
            eg,
        }
    }
}

/// What the contenders draw on: each a target of its own.
pub struct Targets {
    frames: [Vec<u16>; 2],
    fbs: [Box<Fb>; 4],
    pixmap: Pixmap,
}

impl Targets {
    pub fn new() -> Self {
        Self {
            frames: [vec![0u16; W * H], vec![0u16; W * H]],
            fbs: [(); 4].map(|()| Box::new(Fb::new())),
            pixmap: Pixmap::new(W as u32, H as u32).unwrap(),
        }
    }
}

/// The contenders on `pool`, the limit first: `slice::fill` of the exact
/// spans on a `[u16]` frame; this crate's `draw` and `draw_spans` on its
/// framebuffer; `for_each_span` filling the `[u16]` frame; `EdgeWalk` at
/// 12 bits; tiny-skia's non-anti-aliased `fill_path`; embedded-graphics'
/// filled `Triangle`.
pub fn contenders<'a>(pool: &'a Prepared, targets: &'a mut Targets) -> Vec<Contender<'a>> {
    let Targets {
        frames: [frame, frame2],
        fbs: [fb_draw, fb_spans, fb_walk, fb_eg],
        pixmap,
    } = targets;
    let Prepared {
        tris,
        spans,
        paths,
        paint,
        eg,
        ..
    } = pool;
    let clip = screen();
    vec![
        (
            "limit",
            Box::new(move || {
                for &s in spans {
                    fill_u16(frame, s, 0xF800);
                }
                black_box(&frame);
            }),
        ),
        (
            "draw",
            Box::new(move || {
                for t in tris {
                    t.fill(Rgb565::RED).draw(&mut **fb_draw).unwrap();
                }
                black_box(&fb_draw);
            }),
        ),
        (
            "draw_spans",
            Box::new(move || {
                for t in tris {
                    t.fill(Rgb565::RED).draw_spans(&mut **fb_spans).unwrap();
                }
                black_box(&fb_spans);
            }),
        ),
        (
            "for_each_span",
            Box::new(move || {
                for t in tris {
                    t.for_each_span(&clip, |s| {
                        fill_u16(frame2, s, 0xF800);
                        Ok::<(), ()>(())
                    })
                    .unwrap();
                }
                black_box(&frame2);
            }),
        ),
        (
            "EdgeWalk@12",
            Box::new(move || {
                for t in tris {
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
            Box::new(move || {
                for p in paths {
                    pixmap.fill_path(p, paint, FillRule::Winding, Transform::identity(), None);
                }
                black_box(&pixmap);
            }),
        ),
        (
            "embedded-graphics",
            Box::new(move || {
                for t in eg {
                    t.draw(&mut **fb_eg).unwrap();
                }
                black_box(&fb_eg);
            }),
        ),
    ]
}
