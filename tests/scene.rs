//! The scene-file contract (`shared/scene-format.md`), the simulator display
//! and the `render` command line.
#![cfg(feature = "sim")]

#[path = "scene/cli.rs"]
mod cli;
#[path = "scene/display.rs"]
mod display;
#[path = "scene/gtri.rs"]
mod gtri;
#[path = "scene/line.rs"]
mod line;

use embedded_graphics_core::{
    pixelcolor::{Rgb888, RgbColor},
    prelude::*,
    primitives::Rectangle,
};
use embedded_raster::sim::{parse_scene, render_scene, Command, SceneError};
use embedded_raster::Vertex;

/// Decodes an 8-bit RGB PNG into `(width, height, bytes)`.
fn decode_png(bytes: &[u8]) -> (u32, u32, Vec<u8>) {
    let mut reader = png::Decoder::new(bytes).read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buf).unwrap();
    assert_eq!(info.color_type, png::ColorType::Rgb);
    assert_eq!(info.bit_depth, png::BitDepth::Eight);
    buf.truncate(info.buffer_size());
    (info.width, info.height, buf)
}
// ---------------------------------------------------------------------------
// Parsing: errors

/// The error of `text`, as `(line, message)`.
fn error(text: &str) -> (usize, String) {
    let e: SceneError = parse_scene(text).expect_err(text);
    assert_eq!(e.to_string(), e.message, "displays as the message alone");
    (e.line, e.message)
}

fn err(line: usize, message: &str) -> (usize, String) {
    (line, message.to_string())
}

#[test]
fn unknown_commands() {
    assert_eq!(
        error("size 8 8\n\n# c\nfoo 1 2\n"),
        err(4, "unknown command `foo`")
    );
    // Words that are not commands (case matters) are unknown, whatever
    // their arguments.
    for (word, args) in [
        ("circle", "4 4 3 #ff0000"),
        ("GTRI", "0 0 #ff0000 8 0 #00ff00 0 8 #0000ff"),
        ("TRI", "0 0 1 0 0 1 #ffffff"),
        ("Size", "8 8"),
    ] {
        let text = format!("size 8 8\nclear #000000\n{word} {args}\n");
        assert_eq!(
            error(&text),
            err(3, &format!("unknown command `{word}`")),
            "{text}"
        );
    }
}

#[test]
fn argument_counts() {
    let cases = [
        ("size 8", 1, "`size` takes 2 arguments, got 1"),
        ("size 8 8 8", 1, "`size` takes 2 arguments, got 3"),
        ("size", 1, "`size` takes 2 arguments, got 0"),
        ("size 8 8\nclear", 2, "`clear` takes 1 argument, got 0"),
        (
            "size 8 8\nclear #000000 #ffffff",
            2,
            "`clear` takes 1 argument, got 2",
        ),
        (
            "size 8 8\nrect 0 0 1 #ffffff",
            2,
            "`rect` takes 5 arguments, got 4",
        ),
        (
            "size 8 8\nrect 0 0 1 1 1 #ffffff",
            2,
            "`rect` takes 5 arguments, got 6",
        ),
        (
            "size 8 8\ntri 0 0 1 1 2 #ffffff",
            2,
            "`tri` takes 7 arguments, got 6",
        ),
        (
            "size 8 8\n\ntri 0 0 1 1 2 2 2 #ffffff",
            3,
            "`tri` takes 7 arguments, got 8",
        ),
        // A trailing comment is not a comment: it is more arguments.
        (
            "size 8 8\nclear #000000 # black",
            2,
            "`clear` takes 1 argument, got 3",
        ),
    ];
    for (text, line, message) in cases {
        assert_eq!(error(text), err(line, message), "{text}");
    }
}

#[test]
fn bad_numbers_and_out_of_range_coordinates() {
    let tri = |coords: [&str; 6]| format!("size 8 8\ntri {} #ffffff\n", coords.join(" "));
    for bad in [
        "1x", "nan", "NaN", "inf", "-inf", "1e3", "0x10", "1,5", ".", "-", "+", "--1", "1.2.3",
    ] {
        for slot in 0..6 {
            let mut coords = ["1", "2", "3", "4", "5", "6"];
            coords[slot] = bad;
            assert_eq!(
                error(&tri(coords)),
                err(2, &format!("bad number `{bad}`")),
                "{bad} in slot {slot}"
            );
        }
    }
    for out in [
        "524288",
        "-524288.0002",
        "600000",
        "1000000000000000000000000",
        // Exactly halfway between the largest coordinate and 524288: ties to
        // even round up, out of range.
        "524287.9998779296875",
    ] {
        for slot in 0..6 {
            let mut coords = ["1", "2", "3", "4", "5", "6"];
            coords[slot] = out;
            assert_eq!(
                error(&tri(coords)),
                err(2, &format!("coordinate out of range: `{out}`")),
                "{out} in slot {slot}"
            );
        }
    }
    // The first bad token of the line is the one reported.
    assert_eq!(
        error(&tri(["1", "600000", "1x", "4", "5", "6"])),
        err(2, "coordinate out of range: `600000`")
    );
}

#[test]
fn coordinates_at_the_limits_parse_exactly() {
    let scene = parse_scene(
        "size 8 8\n\
         tri -524288 0 100.000244140625 0 524287.999755859375 -0.5 #ffffff\n\
         tri 524287.99987792968 +3 .5 5. 1.00006103515625 -0 #ffffff\n\
         tri -524288.0001220703125 0 0 0 0 0 #ffffff\n",
    )
    .unwrap();
    let Command::Tri(a, _) = scene.commands()[0] else {
        panic!("not a triangle")
    };
    assert_eq!(
        a.vertices.map(Vertex::raw),
        [(-524288 * 4096, 0), (100 * 4096 + 1, 0), (i32::MAX, -2048)]
    );
    let Command::Tri(b, _) = scene.commands()[1] else {
        panic!("not a triangle")
    };
    // 1.00006103515625 = 1 + 1/16384 rounds down to 1; just under the tie
    // rounds down to the largest coordinate.
    assert_eq!(
        b.vertices.map(Vertex::raw),
        [(i32::MAX, 3 * 4096), (2048, 5 * 4096), (4096, 0)]
    );
    // Halfway between -524288 (even) and the next step down: rounds to even.
    let Command::Tri(c, _) = scene.commands()[2] else {
        panic!("not a triangle")
    };
    assert_eq!(c.vertices[0].raw(), (i32::MIN, 0));
}

#[test]
fn bad_colours() {
    for bad in [
        "#12345",
        "#1234567",
        "123456",
        "#12345g",
        "#",
        "##123456",
        "#-12345",
        "#+12345",
        "#１２３",
    ] {
        for text in [
            format!("size 8 8\nclear {bad}"),
            format!("size 8 8\nrect 0 0 1 1 {bad}"),
            format!("size 8 8\ntri 0 0 1 0 0 1 {bad}"),
        ] {
            // Shown as in the file, but for the characters outside
            // printable ASCII (the full-width digits), escaped.
            let shown = bad.replace("１２３", "\\u{ff11}\\u{ff12}\\u{ff13}");
            assert_eq!(
                error(&text),
                err(2, &format!("bad colour `{shown}`")),
                "{text}"
            );
        }
    }
}

#[test]
fn hex_colours_either_case() {
    for (text, colour) in [
        ("#abcdef", Rgb888::new(0xab, 0xcd, 0xef)),
        ("#ABCDEF", Rgb888::new(0xab, 0xcd, 0xef)),
        ("#aBcDeF", Rgb888::new(0xab, 0xcd, 0xef)),
        ("#000000", Rgb888::new(0, 0, 0)),
        ("#FFffFF", Rgb888::new(255, 255, 255)),
        ("#0a0B0c", Rgb888::new(10, 11, 12)),
    ] {
        let scene = parse_scene(&format!("size 2 2\nclear {text}")).unwrap();
        assert_eq!(scene.commands(), &[Command::Clear(colour)], "{text}");
        let rendered = render_scene(&scene);
        assert!(rendered.display.pixels().iter().all(|&c| c == colour));
    }
}

#[test]
fn size_rules() {
    for (text, w, h) in [
        ("size 1 1", 1, 1),
        ("size 4096 4096", 4096, 4096),
        ("size 1 4096", 1, 4096),
        ("size +7 007", 7, 7),
    ] {
        assert_eq!(parse_scene(text).unwrap().size(), Size::new(w, h), "{text}");
    }
    let range = |t: &str| format!("size out of range: `{t}` (must be 1 to 4096)");
    for (text, message) in [
        ("size 0 8", range("0")),
        ("size 8 0", range("0")),
        ("size 4097 8", range("4097")),
        ("size 8 4097", range("4097")),
        ("size -1 8", range("-1")),
        ("size 99999999999999999999 8", range("99999999999999999999")),
        ("size 8.0 8", "bad integer `8.0`".into()),
        ("size 8 x", "bad integer `x`".into()),
    ] {
        assert_eq!(error(text), (1, message), "{text}");
    }
    assert_eq!(
        error("# comment\n\nclear #000000\nsize 8 8\n"),
        err(3, "`size` must come first")
    );
    assert_eq!(
        error("rect 0 0 1 1 #000000\n"),
        err(1, "`size` must come first")
    );
    assert_eq!(
        error("\n size 8 8\nclear #000000\nsize 8 8\n"),
        err(4, "duplicate `size` (first on line 2)")
    );
    assert_eq!(error(""), err(1, "missing `size` command"));
    assert_eq!(
        error("# only\n\n# comments"),
        err(3, "missing `size` command")
    );
}

#[test]
fn rect_arguments() {
    for (text, message) in [
        ("rect 0 0 -1 1 #ffffff", "negative width `-1`"),
        ("rect 0 0 1 -2 #ffffff", "negative height `-2`"),
        ("rect 1.5 0 1 1 #ffffff", "bad integer `1.5`"),
        ("rect 0 0 1 1x #ffffff", "bad integer `1x`"),
        (
            "rect 2147483648 0 1 1 #ffffff",
            "integer out of range: `2147483648`",
        ),
        (
            "rect 0 -2147483649 1 1 #ffffff",
            "integer out of range: `-2147483649`",
        ),
        (
            "rect 0 0 2147483648 1 #ffffff",
            "integer out of range: `2147483648`",
        ),
    ] {
        assert_eq!(
            error(&format!("size 8 8\n{text}")),
            err(2, message),
            "{text}"
        );
    }
}

#[test]
fn comments_blanks_and_separators() {
    let text = "# heading\r\n\
                \r\n\
                \t  \n\
                   # indented comment\n\
                #no space after the hash\n\
                \tsize\t4  3 \n\
                clear\t\t#102030\r\n\
                \n\
                  rect  1 1\t2 1   #FFFFFF  \n\
                #tri 0 0 4 0 0 4 #ff0000\n";
    let scene = parse_scene(text).unwrap();
    assert_eq!(scene.size(), Size::new(4, 3));
    assert_eq!(
        scene.commands(),
        &[
            Command::Clear(Rgb888::new(0x10, 0x20, 0x30)),
            Command::Rect(
                Rectangle::new(Point::new(1, 1), Size::new(2, 1)),
                Rgb888::WHITE
            ),
        ]
    );
    // Line numbers count comment and blank lines, and CRLF line ends.
    assert_eq!(
        error("# a\r\n\r\nsize 4 4\r\n  # b\r\nbogus\r\n"),
        err(5, "unknown command `bogus`")
    );
    // Control characters in a quoted token are escaped: one line.
    assert_eq!(
        error("size 4 4\nclear #123456\rfoo\n"),
        err(2, "bad colour `#123456\\rfoo`")
    );
    assert_eq!(
        error("size 4 4\nfoo\x0bbar 1\n"),
        err(2, "unknown command `foo\\u{b}bar`")
    );
    // The first error wins.
    assert_eq!(
        error("size 4 4\nclear #fff\nfoo\n"),
        err(2, "bad colour `#fff`")
    );
    // Characters outside printable ASCII are shown escaped, such as a
    // byte-order mark before the first command (which is then unknown,
    // not a command before `size`) or a no-break space.
    assert_eq!(
        error("\u{feff}size 4 4\n"),
        err(1, "unknown command `\\u{feff}size`")
    );
    assert_eq!(
        error("size 4 4\nclear\u{a0}#ffffff\n"),
        err(2, "unknown command `clear\\u{a0}#ffffff`")
    );
    assert_eq!(error("clear #ffffff\n"), err(1, "`size` must come first"));
    // A long token is cut after 40 characters.
    let long = "x".repeat(5000);
    assert_eq!(
        error(&format!("size 4 4\nclear #{long}\n")),
        err(2, &format!("bad colour `#{}...`", "x".repeat(39)))
    );
}

// ---------------------------------------------------------------------------
// Rendering

/// What `rect x y w h` lights on a `width` x `height` display, by brute force.
fn expected_rect(width: u32, height: u32, x: i32, y: i32, w: i32, h: i32) -> Vec<bool> {
    let mut lit = vec![false; (width * height) as usize];
    for j in 0..height {
        for i in 0..width {
            let (i64i, i64j) = (i64::from(i), i64::from(j));
            let in_x = i64::from(x) <= i64i && i64i < i64::from(x) + i64::from(w);
            let in_y = i64::from(y) <= i64j && i64j < i64::from(y) + i64::from(h);
            lit[(j * width + i) as usize] = in_x && in_y;
        }
    }
    lit
}

#[test]
fn rect_clipping_with_extreme_values() {
    const MIN: i32 = i32::MIN;
    const MAX: i32 = i32::MAX;
    let (width, height) = (13, 9);
    let cases = [
        (2, 3, 4, 5),
        (0, 0, 13, 9),
        (-5, -5, 8, 7),
        (10, 6, 100, 100),
        (-1, 4, MAX, 1),
        (MIN, MIN, MAX, MAX),
        (MIN, 0, MAX, MAX),
        (MAX, MAX, MAX, MAX),
        (MAX, 0, MAX, 9),
        (0, MAX, 5, MAX),
        (MIN, 2, 0, 3),
        (-2147483000, -2147483000, MAX, MAX),
        (3, 3, 0, 0),
        (3, 3, 5, 0),
        (12, 8, 1, 1),
        (13, 9, 1, 1),
        (-1, -1, 1, 1),
    ];
    for (x, y, w, h) in cases {
        let text = format!("size {width} {height}\nrect {x} {y} {w} {h} #FF8000\n");
        let rendered = render_scene(&parse_scene(&text).unwrap());
        let display = &rendered.display;
        let expected = expected_rect(width, height, x, y, w, h);
        for (k, &lit) in expected.iter().enumerate() {
            let colour = if lit {
                Rgb888::new(0xff, 0x80, 0)
            } else {
                Rgb888::BLACK
            };
            assert_eq!(display.pixels()[k], colour, "{text} pixel {k}");
            assert_eq!(display.counts()[k], u32::from(lit), "{text} pixel {k}");
        }
        let n = expected.iter().filter(|&&l| l).count() as u64;
        assert_eq!(rendered.stats.pixels_written, n, "{text}");
        assert_eq!(rendered.stats.primitives, 1);
        assert_eq!(display.out_of_bounds_writes(), 0, "{text}: clipped first");
        assert_eq!(display.write_stats().draw_iter_pixels, 0);
    }
}

#[test]
fn quad_sharing_a_diagonal_is_written_exactly_once() {
    // Corners on fractional coordinates: centres on the left (x = 2.5) and
    // top (y = 3.5) edges are in, on the right (12.5) and bottom (9.5) out.
    for (a, b) in [
        ("2.5 3.5 12.5 3.5 12.5 9.5", "2.5 3.5 12.5 9.5 2.5 9.5"),
        ("2.5 3.5 12.5 9.5 12.5 3.5", "12.5 9.5 2.5 3.5 2.5 9.5"),
        ("12.5 3.5 2.5 9.5 2.5 3.5", "12.5 3.5 12.5 9.5 2.5 9.5"),
    ] {
        let text = format!("size 16 12\ntri {a} #ff0000\ntri {b} #00ff00\n");
        let display = render_scene(&parse_scene(&text).unwrap()).display;
        for j in 0..12 {
            for i in 0..16 {
                let inside = (2..12).contains(&i) && (3..9).contains(&j);
                assert_eq!(
                    display.write_count(Point::new(i, j)),
                    Some(u32::from(inside)),
                    "{text} ({i}, {j})"
                );
            }
        }
        assert_eq!(display.out_of_bounds_writes(), 0);
    }

    // A skewed quad: the two halves never overlap and light exactly what
    // each lights alone.
    let (a, b) = ("1.3 2.7 27.9 0.2 30.1 19.6", "1.3 2.7 30.1 19.6 3.05 22.85");
    let both = render_scene(
        &parse_scene(&format!("size 32 24\ntri {a} #ff0000\ntri {b} #00ff00\n")).unwrap(),
    )
    .display;
    let alone = |t: &str| {
        render_scene(&parse_scene(&format!("size 32 24\ntri {t} #ffffff\n")).unwrap()).display
    };
    let (da, db) = (alone(a), alone(b));
    for k in 0..32 * 24 {
        assert!(da.counts()[k] + db.counts()[k] <= 1, "overlap at {k}");
        assert_eq!(both.counts()[k], da.counts()[k] + db.counts()[k]);
    }
    // Area 543.47 px²: the lit count is close to it.
    let lit = both.pixels_written();
    assert!((520..=570).contains(&lit), "{lit}");
}

#[test]
fn triangles_arrive_as_fill_solid_spans() {
    let text = "size 40 30\ntri 1.5 1.5 38.25 7 12 28.75 #ffffff\n";
    let display = render_scene(&parse_scene(text).unwrap()).display;
    let stats = display.write_stats();
    assert_eq!(stats.draw_iter_pixels, 0);
    assert_eq!(stats.fill_contiguous_pixels, 0);
    assert_eq!(stats.fill_solid_pixels, display.pixels_written());
    // One call per lit row.
    let rows = (0..30)
        .filter(|&j| (0..40).any(|i| display.write_count(Point::new(i, j)) == Some(1)))
        .count() as u64;
    assert_eq!(stats.fill_solid_calls, rows);
    assert_eq!(display.out_of_bounds_writes(), 0);
}

#[test]
fn render_stats_and_counts() {
    let text = "size 10 10\n\
                clear #ffffff\n\
                rect 0 0 5 2 #ff0000\n\
                tri 0 0 10 0 0 10 #00ff00\n\
                rect 100 100 5 5 #0000ff\n";
    let rendered = render_scene(&parse_scene(text).unwrap());
    // Every command after `size` is a primitive, even one that lights nothing.
    assert_eq!(rendered.stats.primitives, 4);
    // clear 100 + rect 10 + triangle 45 (i + j < 9).
    assert_eq!(rendered.stats.pixels_written, 100 + 10 + 45);
    let d = &rendered.display;
    assert_eq!(d.write_count(Point::new(0, 0)), Some(3));
    assert_eq!(d.write_count(Point::new(8, 0)), Some(2));
    assert_eq!(d.write_count(Point::new(9, 0)), Some(1));
    assert_eq!(d.pixel(Point::new(9, 0)), Some(Rgb888::WHITE));
    assert_eq!(d.pixel(Point::new(0, 0)), Some(Rgb888::GREEN));
    // `size` alone writes nothing.
    let empty = render_scene(&parse_scene("size 3 3").unwrap());
    assert_eq!((empty.stats.primitives, empty.stats.pixels_written), (0, 0));
    assert!(empty.display.pixels().iter().all(|&c| c == Rgb888::BLACK));
    let json = rendered.stats.to_json();
    assert!(
        json.starts_with(r#"{"primitives":4,"pixels_written":155,"raster_seconds":"#),
        "{json}"
    );
}

#[test]
fn poly_command_errors() {
    let big: String = (0..1025).map(|k| format!(" {k} {}", k % 7)).collect();
    let cases = [
        (
            "poly",
            "`poly` takes a fill rule, a colour and at least 3 points, got 0 arguments".to_string(),
        ),
        (
            "poly nonzero",
            "`poly` takes a fill rule, a colour and at least 3 points, got 1 arguments".to_string(),
        ),
        (
            "poly winding #ffffff 0 0 4 0 0 4",
            "bad fill rule `winding` (evenodd or nonzero)".to_string(),
        ),
        (
            "poly evenodd ffffff 0 0 4 0 0 4",
            "bad colour `ffffff`".to_string(),
        ),
        (
            "poly evenodd #ffffff 0 0 4 0 0",
            "`poly` takes x y pairs, got 5 coordinates".to_string(),
        ),
        (
            "poly nonzero #ffffff 0 0 4 0",
            "a polygon needs at least 3 vertices, got 2".to_string(),
        ),
        (
            "poly nonzero #ffffff 0 0 4 0 0 nan",
            "bad number `nan`".to_string(),
        ),
        (
            "poly nonzero #ffffff 0 0 4 0 0 524288",
            "coordinate out of range: `524288`".to_string(),
        ),
        (
            &*format!("poly nonzero #ffffff{big}"),
            "polygon has 1025 vertices, over the capacity of 1024".to_string(),
        ),
    ];
    for (line, message) in cases {
        let text = format!("size 8 8\n{line}\n");
        assert_eq!(error(&text), err(2, &message), "{line}");
    }
}

#[test]
fn poly_fill_rules() {
    // A pentagram: its centre is wound twice.
    let star = "16 1 25.4 29.9 0.8 12 31.2 12 6.6 29.9";
    for (rule, centre_lit) in [("evenodd", false), ("nonzero", true)] {
        let scene = parse_scene(&format!("size 32 32\npoly {rule} #ff0000 {star}\n")).unwrap();
        let display = render_scene(&scene).display;
        let red = Some(Rgb888::new(255, 0, 0));
        assert_eq!(
            display.pixel(Point::new(16, 18)) == red,
            centre_lit,
            "{rule}"
        );
        assert_eq!(display.pixel(Point::new(16, 5)), red, "{rule}");
        assert_eq!(
            display.pixel(Point::new(1, 1)),
            Some(Rgb888::BLACK),
            "{rule}"
        );
        // Spans never overlap: every pixel is written at most once.
        assert!(display.counts().iter().all(|&c| c <= 1), "{rule}");
        assert_eq!(display.out_of_bounds_writes(), 0);
    }
}

/// A scene the fuzz driver found (`FUZZ_SEED=20261232`): in the second
/// Gouraud triangle, pixel (7, 25) lies so near a half in red that the
/// span start stepped to it from the rows above (the frame drawn whole)
/// and the one divided for at a band's first row rounded apart, and the
/// frame drawn in bands of 1, 2, 3 or 7 rows differed there by one. Span
/// starts now follow the same path whatever the clip's top; the same
/// pixels and counts in bands of every height.
#[test]
fn shaded_triangles_in_bands_as_whole_near_a_half() {
    use embedded_raster::{sim::render_scene_in_bands, SubpixelPrecision, TriangleAlgorithm};
    let text = "size 33 38
rect -2147483648 -16 1 2147483647 #FF8000
polyline #FF8000 -2147483648 -2147483648 42 0
clear #000000
gtri 37 48 #FF8000 41 4 #123abc 524287.999755859375 41 #ffffff
gtri 34 -12 #FF8000 28 36 #FF8000 -16 39 #123abc
poly nonzero #FF8000 11.9447 -1 -3 28 3 31
gtri 42 -12 #123abc 39 -12 #FF8000 6 -0 #123abc
tri 30 59 43 -18 3.8437 35 #ffffff
";
    let scene = parse_scene(text).expect("the scene parses");
    let whole = render_scene(&scene);
    for rows in 1..=38 {
        let exact = (TriangleAlgorithm::EdgeExact, SubpixelPrecision::Bits12);
        let (banded, _) = render_scene_in_bands(&scene, rows, exact.0, exact.1);
        let (a, b) = (&banded.display, &whole.display);
        assert!(a.pixels() == b.pixels(), "bands of {rows}: pixels");
        assert!(a.counts() == b.counts(), "bands of {rows}: counts");
    }
}
