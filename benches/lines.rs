//! 1-pixel lines on a 320 x 240 Rgb565 framebuffer: this crate's exact
//! Bresenham line, its DDA and naive variants, and embedded-graphics 0.8's
//! `Line` with a 1-pixel stroke on the same framebuffer, on short lines,
//! long lines and random lines that the screen's edges cut. Thick polylines
//! 8 px wide: joined strokes (miter, round), the same segments as
//! separate thick lines (overlapping, no joins), and embedded-graphics'
//! `Polyline` with an 8 px stroke. Random thick lines (widths 2 to 12,
//! ends anywhere on the screen, short and long): this crate's through
//! `draw` and `draw_spans`, `slice::fill` of their exact spans (the
//! limit), tiny-skia 0.12's non-anti-aliased `stroke_path` (butt caps)
//! and embedded-graphics' `Line` with the same stroke width.
//!
//! `cargo bench --bench lines`; `benches/report_lines.py` turns the
//! medians into the table in BENCHMARKS.md.

use std::hint::black_box;

use criterion::{
    criterion_group, criterion_main, measurement::WallTime, BenchmarkGroup, BenchmarkId, Criterion,
    Throughput,
};
use embedded_graphics::{
    pixelcolor::Rgb565,
    prelude::*,
    primitives::{Line as EgLine, Polyline as EgPolyline, PrimitiveStyle, Rectangle},
};
use embedded_raster::{
    framebuffer::{buffer_size, Rgb565Le},
    Framebuffer, Join, Line, LineAlgorithm, Polyline, Span, SpanDrawable, SpanSink,
};
use tiny_skia::{Paint, PathBuilder, Pixmap, Stroke, Transform};

const W: i32 = 320;
const H: i32 = 240;
type Fb = Framebuffer<Rgb565Le, 320, 240, { buffer_size::<Rgb565Le>(320, 240) }>;

/// A deterministic pseudo-random sequence (xorshift64*).
struct Rng(u64);

impl Rng {
    fn below(&mut self, n: i32) -> i32 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) % n as u64) as i32
    }
}

/// 256 lines of 8 px (7 steps along the major axis) in every direction,
/// anywhere on the screen.
fn short() -> Vec<(Point, Point)> {
    let mut rng = Rng(7);
    (0..256)
        .map(|i| {
            let minor = rng.below(8);
            let (mut dx, mut dy) = if i % 2 == 0 { (7, minor) } else { (minor, 7) };
            if i & 2 != 0 {
                dx = -dx;
            }
            if i & 4 != 0 {
                dy = -dy;
            }
            let a = Point::new(8 + rng.below(W - 16), 8 + rng.below(H - 16));
            (a, a + Point::new(dx, dy))
        })
        .collect()
}

/// 64 lines of 300 px across the screen (x-major, every slope from -0.8
/// to 0.8, both directions).
fn long() -> Vec<(Point, Point)> {
    let mut rng = Rng(11);
    (0..64)
        .map(|i| {
            let dy = rng.below(2 * 230 + 1) - 230;
            let y0 = if dy >= 0 {
                rng.below(H - dy)
            } else {
                -dy + rng.below(H + dy)
            };
            let a = Point::new(10, y0);
            let b = Point::new(309, y0 + dy);
            if i % 2 == 0 {
                (a, b)
            } else {
                (b, a)
            }
        })
        .collect()
}

/// 256 lines with ends anywhere in a box of three screens by three
/// around the screen, each with at least one end off the screen and
/// some pixels on it: lines the clip cuts, at every slope and length.
fn cut() -> Vec<(Point, Point)> {
    let mut rng = Rng(13);
    let screen = Rectangle::new(Point::zero(), Size::new(W as u32, H as u32));
    let mut lines = Vec::new();
    while lines.len() < 256 {
        let mut end = || Point::new(rng.below(3 * W) - W, rng.below(3 * H) - H);
        let (a, b) = (end(), end());
        if screen.contains(a) && screen.contains(b) {
            continue;
        }
        let mut lit = false;
        Line::new(a, b)
            .for_each_run(&screen, |_| {
                lit = true;
                Ok::<(), ()>(())
            })
            .unwrap();
        if lit {
            lines.push((a, b));
        }
    }
    lines
}

fn bench_set(c: &mut Criterion, name: &str, lines: &[(Point, Point)]) {
    let ours: Vec<Line> = lines.iter().map(|&(a, b)| Line::new(a, b)).collect();
    let clip = Rectangle::new(Point::zero(), Size::new(W as u32, H as u32));
    let mut pixels = 0u64;
    for l in &ours {
        l.for_each_run(&clip, |r| {
            pixels += u64::from(r.len);
            Ok::<(), ()>(())
        })
        .unwrap();
    }
    let mut g = c.benchmark_group(name);
    // Per set; divide by the line count for ns/line.
    g.throughput(Throughput::Elements(pixels));
    let mut fb = Box::new(Fb::new());
    for (id, algorithm) in [
        ("bresenham", LineAlgorithm::Bresenham),
        ("dda", LineAlgorithm::Dda),
        ("naive", LineAlgorithm::Naive),
    ] {
        g.bench_function(BenchmarkId::new(id, ours.len()), |b| {
            b.iter(|| {
                for l in &ours {
                    l.stroke(Rgb565::RED)
                        .algorithm(algorithm)
                        .draw(&mut *fb)
                        .unwrap();
                }
                black_box(&fb);
            })
        });
    }
    bench_eg_lines(&mut g, &mut fb, lines.iter().map(|&(a, b)| (a, b, 1)));
    g.finish();
}

/// embedded-graphics' `Line`s, each with its stroke width, drawn on `fb`.
fn bench_eg_lines(
    g: &mut BenchmarkGroup<'_, WallTime>,
    fb: &mut Fb,
    lines: impl Iterator<Item = (Point, Point, u32)>,
) {
    let eg: Vec<_> = lines
        .map(|(a, b, w)| {
            EgLine::new(a, b).into_styled(PrimitiveStyle::with_stroke(Rgb565::GREEN, w))
        })
        .collect();
    g.bench_function(BenchmarkId::new("embedded-graphics", eg.len()), |b| {
        b.iter(|| {
            for l in &eg {
                l.draw(fb).unwrap();
            }
            black_box(&fb);
        })
    });
}

/// A 21-point zigzag across the framebuffer and a noisy 320-point trace.
fn polylines() -> [(&'static str, Vec<Point>); 2] {
    let zigzag = (0..21)
        .map(|k| Point::new(10 + k * 14, if k % 2 == 0 { 30 } else { 210 }))
        .collect();
    let mut r = Rng(0x5eed_1234_abcd_0001);
    let trace = (0..W).map(|x| Point::new(x, 20 + r.below(200))).collect();
    [("zigzag 21", zigzag), ("trace 320", trace)]
}

fn thick_polylines(c: &mut Criterion) {
    const WIDTH: u32 = 8;
    let mut fb = Box::new(Fb::new());
    for (name, points) in polylines() {
        let mut g = c.benchmark_group(format!("thick polyline {name}"));
        // Through `draw` (the `DrawTarget` path: each pixel once, masked)
        // and the framebuffer's own span sink (overdraw is invisible
        // there, so the pieces are written whole, with no mask).
        for (id, join, spans) in [
            ("miter", Join::Miter, false),
            ("round", Join::Round, false),
            ("miter, draw_spans", Join::Miter, true),
            ("round, draw_spans", Join::Round, true),
        ] {
            g.bench_function(id, |b| {
                b.iter(|| {
                    let stroke = Polyline::new(&points)
                        .stroke(Rgb565::RED)
                        .stroke_width(WIDTH)
                        .join(join);
                    match spans {
                        true => stroke.draw_spans(&mut *fb).unwrap(),
                        false => stroke.draw(&mut *fb).unwrap(),
                    }
                    black_box(&fb);
                })
            });
        }
        g.bench_function("separate thick lines", |b| {
            b.iter(|| {
                for s in points.windows(2) {
                    Line::new(s[0], s[1])
                        .stroke(Rgb565::RED)
                        .stroke_width(WIDTH)
                        .draw(&mut *fb)
                        .unwrap();
                }
                black_box(&fb);
            })
        });
        let eg =
            EgPolyline::new(&points).into_styled(PrimitiveStyle::with_stroke(Rgb565::GREEN, WIDTH));
        g.bench_function("embedded-graphics", |b| {
            b.iter(|| {
                eg.draw(&mut *fb).unwrap();
                black_box(&fb);
            })
        });
        g.finish();
    }
}

/// 256 thick lines with random widths from 2 to 12 px, each end at
/// least 8 px inside the screen: `short` ones up to 24 px along each
/// axis, or with ends anywhere.
fn thick_random(seed: u64, short: bool) -> Vec<(Point, Point, u32)> {
    let mut rng = Rng(seed);
    (0..256)
        .map(|_| {
            let end = |rng: &mut Rng| Point::new(8 + rng.below(W - 16), 8 + rng.below(H - 16));
            let a = end(&mut rng);
            let b = match short {
                true => {
                    let d = Point::new(rng.below(49) - 24, rng.below(49) - 24);
                    (a + d)
                        .component_max(Point::new(8, 8))
                        .component_min(Point::new(W - 9, H - 9))
                }
                false => end(&mut rng),
            };
            (a, b, 2 + rng.below(11) as u32)
        })
        .collect()
}

/// The spans a sink receives, in order (overlapping spans kept).
struct Recorder(Vec<Span>);

impl SpanSink<Rgb565> for Recorder {
    type Error = core::convert::Infallible;

    fn bounds(&self) -> Rectangle {
        Rectangle::new(Point::zero(), Size::new(W as u32, H as u32))
    }

    fn fill_span(&mut self, span: Span, _: Rgb565) -> Result<(), Self::Error> {
        self.0.push(span);
        Ok(())
    }
}

fn thick_lines(c: &mut Criterion) {
    for (name, lines) in [
        ("thick lines short", thick_random(17, true)),
        ("thick lines long", thick_random(19, false)),
    ] {
        let ours: Vec<_> = lines
            .iter()
            .map(|&(a, b, w)| Line::new(a, b).stroke(Rgb565::RED).stroke_width(w))
            .collect();
        let mut spans = Recorder(vec![]);
        for l in &ours {
            l.draw_spans(&mut spans).unwrap();
        }
        let spans = spans.0;
        let pixels: u64 = spans.iter().map(|s| u64::from(s.len())).sum();
        let mut g = c.benchmark_group(name);
        // Per set; divide by the line count for ns/line.
        g.throughput(Throughput::Elements(pixels));
        let mut frame = vec![0u16; (W * H) as usize];
        g.bench_function(BenchmarkId::new("limit", ours.len()), |b| {
            b.iter(|| {
                for s in &spans {
                    let row = s.y as usize * W as usize;
                    frame[row + s.x_start as usize..row + s.x_end as usize].fill(0xF800);
                }
                black_box(&frame);
            })
        });
        let mut fb = Box::new(Fb::new());
        g.bench_function(BenchmarkId::new("draw", ours.len()), |b| {
            b.iter(|| {
                for l in &ours {
                    l.draw(&mut *fb).unwrap();
                }
                black_box(&fb);
            })
        });
        g.bench_function(BenchmarkId::new("draw_spans", ours.len()), |b| {
            b.iter(|| {
                for l in &ours {
                    l.draw_spans(&mut *fb).unwrap();
                }
                black_box(&fb);
            })
        });
        let mut pixmap = Pixmap::new(W as u32, H as u32).unwrap();
        let mut paint = Paint::default();
        paint.set_color_rgba8(255, 0, 0, 255);
        paint.anti_alias = false;
        let skia: Vec<_> = lines
            .iter()
            .map(|&(a, b, w)| {
                let mut pb = PathBuilder::new();
                pb.move_to(a.x as f32 + 0.5, a.y as f32 + 0.5);
                pb.line_to(b.x as f32 + 0.5, b.y as f32 + 0.5);
                let stroke = Stroke {
                    width: w as f32,
                    ..Stroke::default()
                };
                (pb.finish(), stroke)
            })
            .collect();
        g.bench_function(BenchmarkId::new("tiny-skia", ours.len()), |b| {
            b.iter(|| {
                for (path, stroke) in &skia {
                    // A zero-length line has no path (and no butt-capped
                    // pixels).
                    if let Some(path) = path {
                        pixmap.stroke_path(path, &paint, stroke, Transform::identity(), None);
                    }
                }
                black_box(&pixmap);
            })
        });
        bench_eg_lines(&mut g, &mut fb, lines.iter().copied());
        g.finish();
    }
}

fn lines(c: &mut Criterion) {
    bench_set(c, "lines 8 px", &short());
    bench_set(c, "lines 300 px", &long());
    bench_set(c, "lines cut", &cut());
    thick_polylines(c);
    thick_lines(c);
}

criterion_group!(benches, lines);
criterion_main!(benches);
