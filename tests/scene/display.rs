//! The simulator display: clipping, counting, PGM and PNG export.

use embedded_graphics_core::{
    pixelcolor::{BinaryColor, Gray8, Rgb565, Rgb888},
    prelude::*,
    primitives::Rectangle,
};
use embedded_raster::sim::SimDisplay;

use super::decode_png;

#[test]
fn sim_display_fill_solid_extremes_never_overflow() {
    let mut d = SimDisplay::new(5, 4, Gray8::BLACK);
    let max = u32::MAX;
    let cases = [
        (i32::MAX, i32::MAX, max, max, 0),
        (i32::MIN, i32::MIN, max, max, 20),
        (-1, -1, max, max, 20),
        (i32::MIN, 1, max, 2, 10),
        (3, 2, max, max, 4),
        (0, 0, 0, max, 0),
        (4, 3, 1, 1, 1),
    ];
    for (x, y, w, h, inside) in cases {
        d.reset_counts();
        let area = Rectangle::new(Point::new(x, y), Size::new(w, h));
        d.fill_solid(&area, Gray8::WHITE).unwrap();
        let total = u64::from(w) * u64::from(h);
        assert_eq!(d.pixels_written(), inside, "{area:?}");
        assert_eq!(d.out_of_bounds_writes(), total - inside, "{area:?}");
        assert_eq!(d.write_stats().fill_solid_calls, 1);
        assert_eq!(d.write_stats().fill_solid_pixels, total);
    }
    // The out-of-bounds count saturates instead of overflowing.
    d.reset_counts();
    let huge = Rectangle::new(Point::new(i32::MAX, 0), Size::new(max, max));
    for _ in 0..3 {
        d.fill_solid(&huge, Gray8::WHITE).unwrap();
    }
    assert_eq!(d.out_of_bounds_writes(), u64::MAX);
}

#[test]
fn sim_display_fill_contiguous_and_draw_iter() {
    let (w, h) = (6, 5);
    let mut d = SimDisplay::new(w, h, Gray8::BLACK);
    let area = Rectangle::new(Point::new(-2, -1), Size::new(5, 4));
    // Colour = the index in `area`, row by row.
    d.fill_contiguous(&area, (0..20u8).map(Gray8::new)).unwrap();
    for j in 0..h as i32 {
        for i in 0..w as i32 {
            let (ax, ay) = (i + 2, j + 1);
            let expected = if (0..5).contains(&ax) && (0..4).contains(&ay) {
                Gray8::new((ay * 5 + ax) as u8)
            } else {
                Gray8::BLACK
            };
            assert_eq!(d.pixel(Point::new(i, j)), Some(expected), "({i}, {j})");
        }
    }
    assert_eq!(d.pixels_written(), 9);
    assert_eq!(d.out_of_bounds_writes(), 11);
    assert_eq!(d.write_stats().fill_contiguous_pixels, 20);
    assert_eq!(d.write_stats().fill_contiguous_calls, 1);

    // A huge area with an endless colour stream terminates.
    let huge = Rectangle::new(Point::new(i32::MIN, -3), Size::new(u32::MAX, 5));
    d.fill_contiguous(&huge, std::iter::repeat(Gray8::WHITE))
        .unwrap();
    assert_eq!(d.pixel(Point::new(5, 1)), Some(Gray8::WHITE));

    d.reset_counts();
    d.draw_iter([
        Pixel(Point::new(0, 0), Gray8::WHITE),
        Pixel(Point::new(0, 0), Gray8::WHITE),
        Pixel(Point::new(-1, 0), Gray8::WHITE),
        Pixel(Point::new(6, 0), Gray8::WHITE),
        Pixel(Point::new(0, 5), Gray8::WHITE),
        Pixel(Point::new(i32::MIN, i32::MAX), Gray8::WHITE),
    ])
    .unwrap();
    assert_eq!(d.write_count(Point::new(0, 0)), Some(2));
    assert_eq!(d.pixels_written(), 2);
    assert_eq!(d.out_of_bounds_writes(), 4);
    assert_eq!(d.write_stats().draw_iter_pixels, 6);
    assert_eq!(d.write_stats().fill_solid_calls, 0);

    d.reset_counts();
    d.clear(Gray8::new(7)).unwrap();
    assert!(d.counts().iter().all(|&c| c == 1));
    assert_eq!(d.write_stats().clear_calls, 1);
    assert_eq!(d.write_stats().fill_solid_calls, 0);
}

#[test]
fn pgm_counts_saturate_at_255() {
    let mut d = SimDisplay::new(3, 2, BinaryColor::Off);
    for _ in 0..300 {
        d.draw_iter([Pixel(Point::new(0, 0), BinaryColor::On)])
            .unwrap();
    }
    for _ in 0..7 {
        d.draw_iter([Pixel(Point::new(2, 1), BinaryColor::On)])
            .unwrap();
    }
    assert_eq!(d.write_count(Point::new(0, 0)), Some(300));
    let mut pgm = Vec::new();
    d.write_counts_pgm(&mut pgm).unwrap();
    assert_eq!(pgm, b"P5\n3 2\n255\n\xff\x00\x00\x00\x00\x07");
}

#[test]
fn png_export_converts_colours() {
    let mut rgb = SimDisplay::new(2, 1, Rgb565::BLACK);
    rgb.draw_iter([Pixel(Point::new(1, 0), Rgb565::new(31, 0, 15))])
        .unwrap();
    let mut bytes = Vec::new();
    rgb.write_png(&mut bytes).unwrap();
    let expected = Rgb888::from(Rgb565::new(31, 0, 15));
    assert_eq!(
        decode_png(&bytes),
        (2, 1, vec![0, 0, 0, 255, 0, expected.b()])
    );

    let mut gray = SimDisplay::new(1, 2, Gray8::new(0x40));
    gray.draw_iter([Pixel(Point::new(0, 1), Gray8::new(0xc0))])
        .unwrap();
    bytes.clear();
    gray.write_png(&mut bytes).unwrap();
    assert_eq!(
        decode_png(&bytes),
        (1, 2, vec![0x40, 0x40, 0x40, 0xc0, 0xc0, 0xc0])
    );

    let bin = SimDisplay::new(1, 1, BinaryColor::On);
    bytes.clear();
    bin.write_png(&mut bytes).unwrap();
    assert_eq!(decode_png(&bytes), (1, 1, vec![255, 255, 255]));
}
