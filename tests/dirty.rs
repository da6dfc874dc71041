//! `DirtyRows`: after random writes of every kind (each `DrawTarget` and
//! `SpanSink` method, and shapes by `draw` and `draw_spans`), a flush sends every pixel that
//! changed (the display ends equal to the framebuffer), sends nothing
//! outside the region it reports, and leaves nothing to send.
#![cfg(feature = "sim")]

#[path = "common/rng.rs"]
mod rng;
#[path = "common/writes.rs"]
mod writes;

use embedded_graphics::{pixelcolor::Gray8, prelude::*, primitives::Rectangle};
use embedded_raster::{
    band::DirtyRows,
    framebuffer::{buffer_size, Gray8Bytes},
    sim::SimDisplay,
    Framebuffer,
};
use rng::Rng;

type Fb = Framebuffer<Gray8Bytes, 40, 30, { buffer_size::<Gray8Bytes>(40, 30) }>;

#[test]
fn flush_sends_exactly_the_changed_region() {
    let mut rng = Rng(0xd1e7_0001);
    let mut screen = DirtyRows::<_, 30>::new(Fb::new());
    let mut display = SimDisplay::new(40, 30, Gray8::BLACK);
    for round in 0..300 {
        let before = screen.target().clone();
        for _ in 0..1 + rng.below(4) {
            writes::random_write(&mut rng, &mut screen, Size::new(40, 30));
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
