//! `DirtyRows`: after random drawing, a flush sends every pixel that
//! changed (the display ends equal to the framebuffer), sends nothing
//! outside the region it reports, and leaves nothing to send.
#![cfg(feature = "sim")]

#[path = "common/rng.rs"]
mod rng;

use embedded_graphics::{pixelcolor::Gray8, prelude::*, primitives::Rectangle};
use embedded_raster::{
    band::DirtyRows,
    framebuffer::{buffer_size, Gray8Bytes},
    sim::SimDisplay,
    Framebuffer, Line, SpanDrawable, Triangle, Vertex,
};
use rng::Rng;

type Fb = Framebuffer<Gray8Bytes, 40, 30, { buffer_size::<Gray8Bytes>(40, 30) }>;

fn random_drawing(rng: &mut Rng, screen: &mut DirtyRows<Fb, 30>) {
    let point = |rng: &mut Rng| Point::new(rng.below(60) as i32 - 10, rng.below(50) as i32 - 10);
    let luma = Gray8::new(1 + rng.below(255) as u8);
    match rng.below(4) {
        0 => {
            let area = Rectangle::new(
                point(rng),
                Size::new(rng.below(12) as u32, rng.below(12) as u32),
            );
            screen.fill_solid(&area, luma).unwrap();
        }
        1 => {
            // Through `DrawTarget`, or whole through `SpanSink::fill_line`.
            let (a, b) = (point(rng), point(rng));
            let line = Line::new(a, b).stroke(luma);
            match rng.below(2) {
                0 => line.draw(screen).unwrap(),
                _ => line.draw_spans(screen).unwrap(),
            }
        }
        2 => {
            let v = |rng: &mut Rng| {
                Vertex::from_raw(rng.below(50 * 4096) as i32, rng.below(40 * 4096) as i32)
            };
            Triangle::new(v(rng), v(rng), v(rng))
                .fill(luma)
                .draw(screen)
                .unwrap();
        }
        _ => {
            let pixels: Vec<_> = (0..5).map(|_| Pixel(point(rng), luma)).collect();
            screen.draw_iter(pixels).unwrap();
        }
    }
}

#[test]
fn flush_sends_exactly_the_changed_region() {
    let mut rng = Rng(0xd1e7_0001);
    let mut screen = DirtyRows::<_, 30>::new(Fb::new());
    let mut display = SimDisplay::new(40, 30, Gray8::BLACK);
    for round in 0..300 {
        let before = screen.target().clone();
        for _ in 0..1 + rng.below(4) {
            random_drawing(&mut rng, &mut screen);
        }
        let changed: Vec<Rectangle> = screen.changed().collect();
        // Every pixel that differs from before lies in a reported rectangle.
        for y in 0..30 {
            for x in 0..40 {
                let p = Point::new(x, y);
                if before.pixel(p) != screen.target().pixel(p) {
                    assert!(
                        changed.iter().any(|r| r.contains(p)),
                        "round {round}: {p:?} not reported"
                    );
                }
            }
        }
        display.reset_counts();
        screen.flush(&mut display).unwrap();
        // The display now holds the framebuffer, and only the reported
        // region was sent.
        for y in 0..30 {
            for x in 0..40 {
                let p = Point::new(x, y);
                assert_eq!(
                    display.pixel(p),
                    screen.target().pixel(p),
                    "round {round}: {p:?}"
                );
                let sent = display.write_count(p).unwrap() > 0;
                assert_eq!(
                    sent,
                    changed.iter().any(|r| r.contains(p)),
                    "round {round}: {p:?}"
                );
            }
        }
        assert_eq!(display.out_of_bounds_writes(), 0);
        assert_eq!(
            screen.changed().count(),
            0,
            "round {round}: flushed region forgotten"
        );
    }
}

/// A target wider than a `Point` can address (`u32::MAX` columns) that
/// draws nothing: only the size matters here.
struct Wide;

impl OriginDimensions for Wide {
    fn size(&self) -> Size {
        Size::new(u32::MAX, 4)
    }
}

impl DrawTarget for Wide {
    type Color = Gray8;
    type Error = core::convert::Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<Gray8>>>(&mut self, _: I) -> Result<(), Self::Error> {
        Ok(())
    }
}

/// A fill reaching past column 2^31 is reported only up to it, from a
/// non-negative column: the region names pixels a `Point` can reach.
#[test]
fn regions_stay_within_point_coordinates() {
    let mut screen = DirtyRows::<_, 4>::new(Wide);
    let far = Rectangle::new(Point::new(i32::MAX - 9, 1), Size::new(u32::MAX, 2));
    screen.fill_solid(&far, Gray8::WHITE).unwrap();
    let regions: Vec<Rectangle> = screen.changed().collect();
    let want = Rectangle::new(Point::new(i32::MAX - 9, 1), Size::new(10, 2));
    assert_eq!(regions, [want]);
}
