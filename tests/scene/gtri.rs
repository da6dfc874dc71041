//! The `gtri` scene command: parsing, errors, rendering.

use embedded_graphics_core::{pixelcolor::Rgb888, prelude::*};
use embedded_raster::sim::{parse_scene, render_scene, Command, SimDisplay};
use embedded_raster::{Triangle, Vertex};

use super::{err, error};

#[test]
fn gtri_parses() {
    let scene =
        parse_scene("size 8 8\ngtri 0 0.5 #FF0000\t8 0 #00ff00  -3.25 8 #0000Ff\n").unwrap();
    let v = |x: f64, y: f64| Vertex::try_from_num(x, y).unwrap();
    assert_eq!(
        scene.commands(),
        &[Command::Gtri(
            Triangle::new(v(0.0, 0.5), v(8.0, 0.0), v(-3.25, 8.0)),
            [Rgb888::RED, Rgb888::GREEN, Rgb888::BLUE]
        )]
    );
}

#[test]
fn gtri_errors() {
    let cases = [
        (
            "gtri 0 0 #ff0000 8 0 #00ff00 0 8",
            "`gtri` takes 9 arguments, got 8",
        ),
        (
            "gtri 0 0 #ff0000 8 0 #00ff00 0 8 #0000ff 1",
            "`gtri` takes 9 arguments, got 10",
        ),
        ("gtri", "`gtri` takes 9 arguments, got 0"),
        (
            "gtri 0 0 #ff0000 8 0 #00ff0 0 8 #0000ff",
            "bad colour `#00ff0`",
        ),
        (
            "gtri 0 0 ff0000 8 0 #00ff00 0 8 #0000ff",
            "bad colour `ff0000`",
        ),
        (
            "gtri 0 0 #ff0000 8 0 #00ff00 0 8x #0000ff",
            "bad number `8x`",
        ),
        (
            "gtri 0 nan #ff0000 8 0 #00ff00 0 8 #0000ff",
            "bad number `nan`",
        ),
        (
            "gtri 0 0 #ff0000 524288 0 #00ff00 0 8 #0000ff",
            "coordinate out of range: `524288`",
        ),
        // Colours in the coordinate places and the other way round.
        ("gtri 0 0 0 #ff0000 8 0 #00ff00 0 8", "bad colour `0`"),
        // The first bad token, left to right.
        (
            "gtri 0 0 #ff000 8 0 #00ff00 0 8 #0000fg",
            "bad colour `#ff000`",
        ),
        (
            "gtri 0 0 #ff0000 8 0 #00ff0g 0 8.x #0000ff",
            "bad colour `#00ff0g`",
        ),
    ];
    for (line, message) in cases {
        let text = format!("size 8 8\n{line}\n");
        assert_eq!(error(&text), err(2, message), "{text}");
    }
}

#[test]
fn gtri_renders_the_flat_pixels_with_blended_colours() {
    let text = "size 24 20\ngtri 1.5 9.5 #ff0000 22.5 0.5 #00ff00 12.5 18.5 #0000ff\n";
    let rendered = render_scene(&parse_scene(text).unwrap());
    let flat =
        render_scene(&parse_scene("size 24 20\ntri 1.5 9.5 22.5 0.5 12.5 18.5 #ffffff\n").unwrap());
    // Same pixels, each written once, as the flat `tri`.
    assert_eq!(rendered.display.counts(), flat.display.counts());
    assert_eq!(rendered.stats.pixels_written, flat.stats.pixels_written);
    // A vertex on a pixel centre, on two left edges: lit, exactly red.
    let d = &rendered.display;
    assert_eq!(d.pixel(Point::new(1, 9)), Some(Rgb888::RED));
    // And the library's Gouraud triangle draws the same image.
    let v = |x: f64, y: f64| Vertex::try_from_num(x, y).unwrap();
    let mut direct = SimDisplay::new(24, 20, Rgb888::BLACK);
    let Ok(()) = Triangle::new(v(1.5, 9.5), v(22.5, 0.5), v(12.5, 18.5))
        .gouraud([Rgb888::RED, Rgb888::GREEN, Rgb888::BLUE])
        .draw(&mut direct);
    assert_eq!(d.pixels(), direct.pixels());
    let blue = d.pixel(Point::new(12, 17)).unwrap();
    assert!(blue.b() > 200 && blue.r() < 40, "{blue:?}");
}
