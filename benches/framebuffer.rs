//! embedded-graphics drawing on this crate's `Framebuffer` against
//! embedded-graphics 0.8's own `Framebuffer`, both 320 x 240 little-endian
//! Rgb565, in one run: transparent text (every glyph pixel through
//! `draw_iter`), text on a background (`fill_contiguous`), filled circles
//! (`fill_solid` spans) and single pixels scattered over the screen
//! (`draw_iter`).
//!
//! `cargo bench --bench framebuffer`; `python3 benches/report.py framebuffer`
//! turns the medians into the table in BENCHMARKS.md.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use embedded_graphics::{
    framebuffer::{buffer_size as eg_buffer_size, Framebuffer as EgFramebuffer},
    mono_font::{ascii::FONT_6X10, MonoTextStyle, MonoTextStyleBuilder},
    pixelcolor::{
        raw::{LittleEndian, RawU16},
        Rgb565,
    },
    prelude::*,
    primitives::{Circle, PrimitiveStyle},
    text::{Baseline, Text},
};
use embedded_raster::{
    framebuffer::{buffer_size, Rgb565Le},
    Framebuffer,
};

type Fb = Framebuffer<Rgb565Le, 320, 240, { buffer_size::<Rgb565Le>(320, 240) }>;
type EgFb =
    EgFramebuffer<Rgb565, RawU16, LittleEndian, 320, 240, { eg_buffer_size::<Rgb565>(320, 240) }>;

/// Twenty-four lines of 54 characters (the last one cut by the screen's
/// right edge): the screen full of text.
const LINE: &str = "The quick brown fox jumps over the lazy dog 0123456789";

/// Draws the screen full of text in `style`.
fn text<D: DrawTarget<Color = Rgb565>>(target: &mut D, style: MonoTextStyle<'_, Rgb565>) {
    for row in 0..24 {
        let origin = Point::new(0, row * 10);
        let _ = Text::with_baseline(LINE, origin, style, Baseline::Top).draw(target);
    }
}

/// 48 filled circles of diameter 40, overlapping across the screen.
fn circles<D: DrawTarget<Color = Rgb565>>(target: &mut D) {
    let style = PrimitiveStyle::with_fill(Rgb565::GREEN);
    for i in 0..48 {
        let top_left = Point::new((i % 8) * 40, (i / 8) * 40);
        let _ = Circle::new(top_left, 40).into_styled(style).draw(target);
    }
}

/// 4096 pixels in a fixed scatter over the screen (and a few outside).
fn scatter() -> Vec<Pixel<Rgb565>> {
    let mut state = 0x2545_f491u32;
    (0..4096)
        .map(|_| {
            state ^= state << 13;
            state ^= state >> 17;
            state ^= state << 5;
            let x = (state % 336) as i32 - 8;
            let y = ((state >> 16) % 256) as i32 - 8;
            Pixel(Point::new(x, y), Rgb565::CSS_ORANGE)
        })
        .collect()
}

/// Counts pixels and stores nothing: the cost of the iterators alone.
struct Null(u32);
impl OriginDimensions for Null {
    fn size(&self) -> Size {
        Size::new(320, 240)
    }
}
impl DrawTarget for Null {
    type Color = Rgb565;
    type Error = core::convert::Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Self::Error> {
        pixels.into_iter().for_each(|p| {
            self.0 = self.0.wrapping_add(black_box(p).0.x as u32);
        });
        Ok(())
    }
}

fn framebuffers(c: &mut Criterion) {
    let mut ours = Box::new(Fb::new());
    let mut theirs = Box::new(EgFb::new());
    let transparent = MonoTextStyle::new(&FONT_6X10, Rgb565::WHITE);
    let opaque = MonoTextStyleBuilder::new()
        .font(&FONT_6X10)
        .text_color(Rgb565::WHITE)
        .background_color(Rgb565::BLUE)
        .build();
    let pixels = scatter();

    // One group per drawing: both framebuffers, and for the `draw_iter`
    // cases a target that stores nothing (what the iterators alone cost).
    let mut group = c.benchmark_group("framebuffer text transparent");
    group.bench_function("embedded-raster", |b| {
        b.iter(|| text(black_box(&mut *ours), transparent))
    });
    group.bench_function("embedded-graphics", |b| {
        b.iter(|| text(black_box(&mut *theirs), transparent))
    });
    group.bench_function("null", |b| {
        b.iter(|| text(black_box(&mut Null(0)), transparent))
    });
    group.finish();

    let mut group = c.benchmark_group("framebuffer text on a background");
    group.bench_function("embedded-raster", |b| {
        b.iter(|| text(black_box(&mut *ours), opaque))
    });
    group.bench_function("embedded-graphics", |b| {
        b.iter(|| text(black_box(&mut *theirs), opaque))
    });
    group.finish();

    let mut group = c.benchmark_group("framebuffer filled circles");
    group.bench_function("embedded-raster", |b| {
        b.iter(|| circles(black_box(&mut *ours)))
    });
    group.bench_function("embedded-graphics", |b| {
        b.iter(|| circles(black_box(&mut *theirs)))
    });
    group.finish();

    let mut group = c.benchmark_group("framebuffer scattered pixels");
    group.bench_function("embedded-raster", |b| {
        b.iter(|| ours.draw_iter(black_box(pixels.iter().copied())))
    });
    group.bench_function("embedded-graphics", |b| {
        b.iter(|| theirs.draw_iter(black_box(pixels.iter().copied())))
    });
    group.bench_function("null", |b| {
        b.iter(|| Null(0).draw_iter(black_box(pixels.iter().copied())))
    });
    group.finish();
}

criterion_group!(benches, framebuffers);
criterion_main!(benches);
