//! The framebuffer as an embedded-graphics image (`ImageDrawable`) and as
//! a PNG file, checked pixel by pixel against the framebuffer's contents.

// The simulator's display and its PNG export.
#![cfg(feature = "sim")]

use embedded_graphics::{image::Image, pixelcolor::Gray8, prelude::*, primitives::Rectangle};
use embedded_raster::{
    framebuffer::{buffer_size, Gray8Bytes},
    sim::SimDisplay,
    Framebuffer,
};
use proptest::prelude::*;

type Source = Framebuffer<Gray8Bytes, 13, 7, { buffer_size::<Gray8Bytes>(13, 7) }>;

/// A source whose pixel `(x, y)` has luma `1 + x + 13 y` (never 0).
fn numbered() -> Source {
    let mut fb = Source::new();
    for y in 0..7 {
        for x in 0..13 {
            let luma = (1 + x + 13 * y) as u8;
            Pixel(Point::new(x, y), Gray8::new(luma))
                .draw(&mut fb)
                .unwrap();
        }
    }
    fb
}

/// The luma the reference expects at target pixel `q` after drawing
/// `area` of [`numbered`] at the target's origin, or `None` if `q` is not
/// drawn: `q + area.top_left` must lie in `area` and in the source.
fn expected(q: Point, area: &Rectangle) -> Option<u8> {
    let (sx, sy) = (
        i64::from(q.x) + i64::from(area.top_left.x),
        i64::from(q.y) + i64::from(area.top_left.y),
    );
    let in_area = q.x >= 0
        && q.y >= 0
        && i64::from(q.x) < i64::from(area.size.width)
        && i64::from(q.y) < i64::from(area.size.height);
    let in_source = (0..13).contains(&sx) && (0..7).contains(&sy);
    (in_area && in_source).then(|| (1 + sx + 13 * sy) as u8)
}

fn check_sub_image(area: Rectangle) {
    let source = numbered();
    let mut target = SimDisplay::new(20, 12, Gray8::BLACK);
    source.draw_sub_image(&mut target, &area).unwrap();
    for y in 0..12 {
        for x in 0..20 {
            let q = Point::new(x, y);
            let want = expected(q, &area);
            let got = target.pixel(q).unwrap().luma();
            assert_eq!(got, want.unwrap_or(0), "{q:?} of {area:?}");
            let writes = u32::from(want.is_some());
            assert_eq!(target.write_count(q), Some(writes), "{q:?} of {area:?}");
        }
    }
}

#[test]
fn whole_image_lands_at_the_image_position() {
    let source = numbered();
    let mut target = SimDisplay::new(20, 12, Gray8::BLACK);
    Image::new(&source, Point::new(5, 3))
        .draw(&mut target)
        .unwrap();
    for y in 0..12 {
        for x in 0..20 {
            let (sx, sy) = (x - 5, y - 3);
            let want = if (0..13).contains(&sx) && (0..7).contains(&sy) {
                (1 + sx + 13 * sy) as u8
            } else {
                0
            };
            assert_eq!(target.pixel(Point::new(x, y)).unwrap().luma(), want);
        }
    }
    assert_eq!(target.out_of_bounds_writes(), 0);
}

#[test]
fn sub_images_partly_outside_and_at_the_extremes() {
    for area in [
        Rectangle::new(Point::new(2, 1), Size::new(4, 3)),
        Rectangle::new(Point::new(-3, -2), Size::new(8, 5)),
        Rectangle::new(Point::new(10, 5), Size::new(100, 100)),
        Rectangle::new(Point::new(13, 0), Size::new(5, 5)),
        Rectangle::new(Point::new(0, 0), Size::zero()),
        Rectangle::new(
            Point::new(i32::MIN, i32::MIN),
            Size::new(u32::MAX, u32::MAX),
        ),
        Rectangle::new(Point::new(i32::MAX, 3), Size::new(u32::MAX, 2)),
        Rectangle::new(Point::new(-5, i32::MIN + 4), Size::new(9, u32::MAX)),
    ] {
        check_sub_image(area);
    }
}

proptest! {
    #[test]
    fn sub_images_match_the_reference(
        x in -20i32..20, y in -12i32..12, w in 0u32..30, h in 0u32..20,
    ) {
        check_sub_image(Rectangle::new(Point::new(x, y), Size::new(w, h)));
    }
}

#[test]
fn png_holds_every_pixel() {
    let source = numbered();
    let mut png = Vec::new();
    source.write_png(&mut png).unwrap();
    let mut reader = png::Decoder::new(&png[..]).read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buf).unwrap();
    assert_eq!((info.width, info.height), (13, 7));
    assert_eq!(info.color_type, png::ColorType::Rgb);
    for (i, rgb) in buf[..info.buffer_size()].chunks(3).enumerate() {
        let luma = (1 + i) as u8; // the numbering is row-major
        assert_eq!(rgb, [luma; 3], "pixel {i}");
    }
}
