//! The `line` and `polyline` scene commands.

use embedded_graphics_core::{pixelcolor::Rgb888, prelude::*};
use embedded_raster::sim::{parse_scene, render_scene, Command};
use embedded_raster::Line;

use super::{err, error};

#[test]
fn line_and_polyline_parse() {
    let scene = parse_scene(
        "size 8 8\n\
         line -2147483648 0 2147483647 -7 #FF0000\n\
         polyline #00ff00 0 0 7 7 3 +5\n",
    )
    .unwrap();
    assert_eq!(
        scene.commands(),
        &[
            Command::Line(
                Line::new(Point::new(i32::MIN, 0), Point::new(i32::MAX, -7)),
                Rgb888::RED
            ),
            Command::Polyline(
                vec![Point::new(0, 0), Point::new(7, 7), Point::new(3, 5)],
                Rgb888::GREEN
            ),
        ]
    );
}

#[test]
fn line_and_polyline_errors() {
    let cases = [
        ("line 0 0 7 #ffffff", "`line` takes 5 arguments, got 4"),
        ("line 0 0 7 7 7 #ffffff", "`line` takes 5 arguments, got 6"),
        ("line", "`line` takes 5 arguments, got 0"),
        ("line 0 0 7 7.5 #ffffff", "bad integer `7.5`"),
        (
            "line 0 0 2147483648 7 #ffffff",
            "integer out of range: `2147483648`",
        ),
        ("line 0 0 7 7 #fffff", "bad colour `#fffff`"),
        (
            "polyline",
            "`polyline` takes a colour and at least 2 points, got 0 arguments",
        ),
        (
            "polyline #ffffff 0 0",
            "`polyline` takes a colour and at least 2 points, got 3 arguments",
        ),
        (
            "polyline #ffffff 0 0 1",
            "`polyline` takes a colour and at least 2 points, got 4 arguments",
        ),
        (
            "polyline #ffffff 0 0 1 1 2",
            "`polyline` takes x y pairs, got 5 coordinates",
        ),
        ("polyline 0 0 1 1 #ffffff", "bad colour `0`"),
        ("polyline #ffffff 0 0 1 x", "bad integer `x`"),
        (
            "polyline #ffffff 0 0 1 -2147483649",
            "integer out of range: `-2147483649`",
        ),
    ];
    for (line, message) in cases {
        let text = format!("size 8 8\nclear #000000\n{line}\n");
        assert_eq!(error(&text), err(3, message), "{line}");
    }
}

#[test]
fn lines_render_clipped_with_joints_once() {
    let scene = parse_scene(
        "size 16 16\n\
         line -2147483648 -2147483648 2147483647 2147483647 #ff0000\n\
         polyline #00ff00 1 14 7 2 13 14 1 14\n\
         line 3 0 3 0 #0000ff\n",
    )
    .unwrap();
    let rendered = render_scene(&scene);
    let d = &rendered.display;
    // The corner-to-corner line is the diagonal of the screen (the
    // outline drawn after it crosses it).
    for i in 0..16 {
        assert!(d.write_count(Point::new(i, i)) >= Some(1), "{i}");
    }
    assert_eq!(d.pixel(Point::new(15, 15)), Some(Rgb888::RED));
    // The closed triangle outline: every pixel once except where it
    // crosses the diagonal.
    let green = Rgb888::GREEN;
    assert_eq!(d.pixel(Point::new(7, 2)), Some(green));
    assert_eq!(d.pixel(Point::new(1, 14)), Some(green));
    let twice = d.counts().iter().filter(|&&c| c == 2).count();
    assert!(twice <= 3, "{twice}");
    assert_eq!(d.pixel(Point::new(3, 0)), Some(Rgb888::BLUE));
    assert_eq!(d.out_of_bounds_writes(), 0);
    assert_eq!(d.write_stats().draw_iter_pixels, 0);
    assert_eq!(rendered.stats.primitives, 3);
}
