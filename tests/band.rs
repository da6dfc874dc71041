//! Band rendering against the whole frame: for random display lists of
//! every command (including depth), any band height gives the same pixels
//! and the same write count per pixel as drawing the list on one
//! whole-screen target, at every band boundary. A `Band` alone takes
//! every kind of write (each `DrawTarget` and `SpanSink` method, and
//! shapes by `draw` and `draw_spans`) as the screen does, in its rows.
#![cfg(feature = "sim")]

#[path = "common/rng.rs"]
mod rng;
#[path = "common/view.rs"]
mod view;
#[path = "common/writes.rs"]
mod writes;

use embedded_graphics::{
    pixelcolor::{Rgb888, RgbColor},
    prelude::*,
    primitives::Rectangle,
};
use embedded_raster::{
    band::{render_in_bands, Command, DisplayList, RenderError},
    shade::DepthBuffer,
    sim::SimDisplay,
    FillRule, Line, Polygon, Polyline, Triangle, Vertex,
};
use proptest::prelude::*;
use rng::Rng;
use view::View;

const W: u32 = 37;
const H: u32 = 29;

/// A y coordinate (raw 20.12) that is often exactly on a band boundary
/// for the tested heights, or a pixel centre next to one.
fn boundary_y(rng: &mut Rng) -> i32 {
    let row = [0, 1, 2, 3, 4, 6, 7, 8, 14, 15, 16, 21, 28, 29][rng.below(14) as usize];
    let offset = [0, 2048, -2048, 1, -1][rng.below(5) as usize];
    row * 4096 + offset
}

fn coordinate(rng: &mut Rng, side: u32) -> i32 {
    // Mostly on screen, some far off it, fractional.
    match rng.below(8) {
        0 => rng.below(1 << 24) as i32 - (1 << 23),
        _ => rng.below(u64::from(side + 8) * 4096) as i32 - 4 * 4096,
    }
}

fn vertex(rng: &mut Rng) -> Vertex {
    let x = coordinate(rng, W);
    let y = if rng.below(2) == 0 {
        boundary_y(rng)
    } else {
        coordinate(rng, H)
    };
    Vertex::from_raw(x, y)
}

fn point(rng: &mut Rng) -> Point {
    let x = rng.below(u64::from(W) + 10) as i32 - 5;
    let y = match rng.below(3) {
        0 => boundary_y(rng) >> 12,
        _ => rng.below(u64::from(H) + 10) as i32 - 5,
    };
    Point::new(x, y)
}

/// A 1-pixel line's end: mostly near the screen, sometimes anywhere in
/// `i32` (lines whose visible part is a sliver of their length, kept
/// from band to band).
fn line_end(rng: &mut Rng) -> Point {
    match rng.below(4) {
        0 => Point::new(rng.next() as i32, rng.next() as i32),
        _ => point(rng),
    }
}

fn color(rng: &mut Rng) -> Rgb888 {
    let c = rng.next();
    Rgb888::new(c as u8, (c >> 8) as u8, (c >> 16) as u8)
}

/// Storage the borrowed commands point into.
struct Shapes {
    polylines: Vec<Vec<Point>>,
    polygons: Vec<Vec<Vertex>>,
}

fn shapes(rng: &mut Rng) -> Shapes {
    let polylines = (0..3)
        .map(|_| (0..2 + rng.below(5)).map(|_| point(rng)).collect())
        .collect();
    let polygons = (0..2)
        .map(|_| (0..3 + rng.below(6)).map(|_| vertex(rng)).collect())
        .collect();
    Shapes {
        polylines,
        polygons,
    }
}

fn list<'a>(rng: &mut Rng, shapes: &'a Shapes) -> DisplayList<'a, Rgb888, 64, 16> {
    let mut list = DisplayList::new();
    list.push(Command::Clear(color(rng))).unwrap();
    for _ in 0..24 {
        let triangle = Triangle::new(vertex(rng), vertex(rng), vertex(rng));
        let z = [0, 0, 0].map(|_: i32| rng.below(65536) as u16);
        let command = match rng.below(10) {
            0 => {
                let area = Rectangle::new(
                    point(rng),
                    Size::new(rng.below(20) as u32, rng.below(20) as u32),
                );
                Command::Rect(area, color(rng))
            }
            1 => Command::Triangle(triangle.fill(color(rng))),
            2 => Command::Gouraud(triangle.gouraud([color(rng), color(rng), color(rng)])),
            3 => Command::DepthTriangle(triangle.fill(color(rng)), z),
            4 => Command::DepthGouraud(triangle.gouraud([color(rng), color(rng), color(rng)]), z),
            5 => Command::Line(Line::new(line_end(rng), line_end(rng)).stroke(color(rng))),
            6 => {
                let width = rng.below(7) as u32;
                Command::ThickLine(
                    Line::new(point(rng), point(rng))
                        .stroke(color(rng))
                        .stroke_width(width),
                )
            }
            7 => {
                let points = &shapes.polylines[rng.below(3) as usize];
                let width = [1, 1, 2, 5][rng.below(4) as usize];
                Command::Polyline(Polyline::new(points).stroke(color(rng)).stroke_width(width))
            }
            _ => {
                let vertices = &shapes.polygons[rng.below(2) as usize];
                let rule = [FillRule::EvenOdd, FillRule::NonZero][rng.below(2) as usize];
                let polygon = Polygon::<16>::new(vertices).unwrap();
                Command::Polygon(polygon.fill(color(rng)).with_rule(rule))
            }
        };
        list.push(command).unwrap();
    }
    list
}

/// The list drawn on one whole-screen display with a whole-screen depth
/// buffer.
fn whole(list: &DisplayList<'_, Rgb888, 64, 16>) -> SimDisplay<Rgb888> {
    let mut display = SimDisplay::new(W, H, Rgb888::BLACK);
    let mut z = vec![0u16; (W * H) as usize];
    let depth = DepthBuffer::new(&mut z, W);
    depth.clear();
    list.draw_with_depth(&mut display, Some(depth)).unwrap();
    display
}

/// The list rendered in bands of `rows` rows through `buffers` buffers,
/// each band's pixels and write counts copied into a whole-screen image.
/// How a list is rendered in bands.
#[derive(Debug, Clone, Copy)]
enum Mode {
    /// `DisplayList::render_bands`: triangles set up once, continued from
    /// band to band.
    Resuming,
    /// `render_in_bands` with `DisplayList::draw_band`: every command set
    /// up again in each band it meets.
    EachBand,
}

fn banded(
    list: &DisplayList<'_, Rgb888, 64, 16>,
    rows: u32,
    buffers: usize,
) -> (Vec<Rgb888>, Vec<u32>) {
    banded_by(list, rows, buffers, Mode::Resuming)
}

fn banded_by<const N: usize>(
    list: &DisplayList<'_, Rgb888, N, 16>,
    rows: u32,
    buffers: usize,
    mode: Mode,
) -> (Vec<Rgb888>, Vec<u32>) {
    let mut pixels = vec![Rgb888::BLACK; (W * H) as usize];
    let mut counts = vec![0u32; (W * H) as usize];
    let mut bufs: Vec<SimDisplay<Rgb888>> = (0..buffers)
        .map(|_| SimDisplay::new(W, rows, Rgb888::BLACK))
        .collect();
    // Each buffer's counts accumulate over the bands it held: keep the last
    // snapshot of each to take the difference.
    let mut seen: Vec<Vec<u32>> = vec![vec![0; (W * rows) as usize]; buffers];
    let mut next = 0;
    let mut depth = vec![0u16; (W * rows) as usize];
    let mut bands = 0;
    let mut output = |buffer: &SimDisplay<Rgb888>, area: Rectangle| {
        assert_eq!(area.size.width, W);
        for r in 0..area.size.height as i32 {
            for x in 0..W as i32 {
                let local = Point::new(x, r);
                let i = (r as u32 * W + x as u32) as usize;
                let screen = ((area.top_left.y + r) as u32 * W + x as u32) as usize;
                let total = buffer.write_count(local).unwrap();
                counts[screen] = total - seen[next][i];
                seen[next][i] = total;
                pixels[screen] = buffer.pixel(local).unwrap();
            }
        }
        // Rows of the buffer below the screen are never written.
        for r in area.size.height as i32..rows as i32 {
            for x in 0..W as i32 {
                let i = (r as u32 * W + x as u32) as usize;
                assert_eq!(buffer.write_count(Point::new(x, r)).unwrap(), seen[next][i]);
            }
        }
        assert_eq!(buffer.out_of_bounds_writes(), 0);
        next = (next + 1) % buffers;
        bands += 1;
        Ok::<(), ()>(())
    };
    match mode {
        Mode::Resuming => list.render_bands(H, &mut bufs, Some(&mut depth), &mut output),
        Mode::EachBand => render_in_bands(
            H,
            &mut bufs,
            Some(&mut depth),
            |band, depth| list.draw_band(band, depth),
            &mut output,
        ),
    }
    .unwrap();
    assert_eq!(bands, H.div_ceil(rows));
    (pixels, counts)
}

fn check(seed: u64) {
    let mut rng = Rng(seed | 1);
    let shapes = shapes(&mut rng);
    let list = list(&mut rng, &shapes);
    let reference = whole(&list);
    let want_pixels = reference.pixels().to_vec();
    let want_counts: Vec<u32> = (0..H as i32)
        .flat_map(|y| (0..W as i32).map(move |x| Point::new(x, y)))
        .map(|p| reference.write_count(p).unwrap())
        .collect();
    for rows in [1, 2, 3, 7, 8, 16, 28, 29, 240] {
        for (buffers, mode) in [
            (1, Mode::Resuming),
            (2, Mode::Resuming),
            (1, Mode::EachBand),
        ] {
            let (pixels, counts) = banded_by(&list, rows, buffers, mode);
            let what = format!("bands of {rows}, {buffers} buffers, {mode:?}, seed {seed}");
            assert!(pixels == want_pixels, "pixels differ: {what}");
            assert!(counts == want_counts, "counts differ: {what}");
        }
    }
}

proptest! {
    #[test]
    fn bands_equal_the_whole_frame(seed in any::<u64>()) {
        check(seed);
    }
}

/// A triangle whose vertices and a polyline whose joints lie exactly on
/// band boundaries, and a line along a boundary row.
#[test]
fn shapes_on_band_boundaries() {
    let shapes = Shapes {
        polylines: vec![vec![
            Point::new(1, 7),
            Point::new(20, 8),
            Point::new(5, 16),
            Point::new(30, 16),
        ]],
        polygons: vec![vec![
            Vertex::from_raw(0, 8 * 4096),
            Vertex::from_raw(36 * 4096, 16 * 4096),
            Vertex::from_raw(3 * 4096, 28 * 4096 + 2048),
        ]],
    };
    let mut list = DisplayList::<Rgb888, 64, 16>::new();
    list.push(Command::Clear(Rgb888::BLACK)).unwrap();
    let t = Triangle::new(
        Vertex::from_raw(2048, 7 * 4096 + 2048),
        Vertex::from_raw(30 * 4096, 8 * 4096),
        Vertex::from_raw(10 * 4096, 16 * 4096 + 2048),
    );
    list.push(Command::Triangle(t.fill(Rgb888::RED))).unwrap();
    list.push(Command::Polyline(
        Polyline::new(&shapes.polylines[0]).stroke(Rgb888::GREEN),
    ))
    .unwrap();
    list.push(Command::Polyline(
        Polyline::new(&shapes.polylines[0])
            .stroke(Rgb888::WHITE)
            .stroke_width(3),
    ))
    .unwrap();
    let polygon = Polygon::<16>::new(&shapes.polygons[0]).unwrap();
    list.push(Command::Polygon(polygon.fill(Rgb888::BLUE)))
        .unwrap();
    list.push(Command::Line(
        Line::new(Point::new(0, 8), Point::new(36, 8)).stroke(Rgb888::CYAN),
    ))
    .unwrap();
    let reference = whole(&list);
    for rows in [1, 4, 7, 8, 16] {
        let (pixels, counts) = banded(&list, rows, 2);
        assert_eq!(pixels, reference.pixels(), "bands of {rows}");
        let want: Vec<u32> = (0..H as i32)
            .flat_map(|y| (0..W as i32).map(move |x| Point::new(x, y)))
            .map(|p| reference.write_count(p).unwrap())
            .collect();
        assert_eq!(counts, want, "bands of {rows}");
    }
}

/// More triangles going on below a band than there are slots to keep
/// their walks in (24): 40 triangles across the whole screen, between 40
/// lines in every direction, some with ends far off it. The triangles
/// without a slot are clipped again in each band; the frame is the same.
#[test]
fn more_walks_than_slots() {
    let mut rng = Rng(0x5DEE_CE66_D1CE_4E5B);
    let mut list = DisplayList::<Rgb888, 96, 16>::new();
    list.push(Command::Clear(Rgb888::BLACK)).unwrap();
    for k in 0..80 {
        let (top, bottom) = (rng.below(3) as i32 - 2, H as i32 + rng.below(3) as i32);
        let (a, b) = (point(&mut rng), point(&mut rng));
        let far = k % 5 == 0;
        let x = |p: Point| if far { p.x * 100_000 } else { p.x };
        let (start, end) = match k % 4 {
            0 | 1 => (Point::new(x(a), top), Point::new(x(b), bottom)),
            _ => (Point::new(x(a), bottom), Point::new(x(b), top)),
        };
        let command = match k % 2 {
            0 => Command::Line(Line::new(start, end).stroke(color(&mut rng))),
            _ => {
                let v = |p: Point| Vertex::from_raw(p.x.clamp(-100, 100) * 4096, p.y * 4096);
                let apex = Vertex::from_raw(rng.below(u64::from(W) * 4096) as i32, 0);
                Command::Triangle(Triangle::new(v(start), v(end), apex).fill(color(&mut rng)))
            }
        };
        list.push(command).unwrap();
    }
    let mut display = SimDisplay::new(W, H, Rgb888::BLACK);
    list.draw(&mut display).unwrap();
    let want: Vec<u32> = (0..H as i32)
        .flat_map(|y| (0..W as i32).map(move |x| Point::new(x, y)))
        .map(|p| display.write_count(p).unwrap())
        .collect();
    for rows in [1, 3, 8] {
        let (pixels, counts) = banded_by(&list, rows, 1, Mode::Resuming);
        assert_eq!(pixels, display.pixels(), "bands of {rows}");
        assert_eq!(counts, want, "bands of {rows}");
    }
}

/// A command below the screen lights nothing in any band: no band maps
/// its rows onto its own (whether the band culls the command by rows or
/// clips it, which this cannot tell apart; the culling's effect on the
/// pixels is the band-against-whole-frame tests' to check).
#[test]
fn commands_below_every_band_write_nothing() {
    let mut list = DisplayList::<Rgb888, 64, 16>::new();
    list.push(Command::Line(
        Line::new(Point::new(0, 100), Point::new(30, 120)).stroke(Rgb888::RED),
    ))
    .unwrap();
    let (_, counts) = banded(&list, 8, 1);
    assert!(counts.iter().all(|&c| c == 0));
}

/// A list drawn on a target at the bottom of the `i32` plane drew nothing
/// on row `i32::MAX` (found by a robustness audit): `draw` culled the
/// commands by rows `i32::MIN..i32::MAX`, which leaves that row out, and
/// a command on it alone has an empty range of rows. Drawn through the
/// list or one by one, the same pixels are written.
#[test]
fn a_list_draws_on_the_last_row_of_i32() {
    let last = Point::new(1, i32::MAX);
    let line = Line::new(last, last + Point::new(2, 0)).stroke(Rgb888::RED);
    let rect = Rectangle::new(Point::new(0, i32::MAX), Size::new(1, 1));
    let mut list = DisplayList::<Rgb888, 4>::new();
    list.push(Command::Line(line)).unwrap();
    list.push(Command::Rect(rect, Rgb888::GREEN)).unwrap();
    // 4 x 2 pixels whose bottom row is row `i32::MAX`.
    let origin = Point::new(0, i32::MAX - 1);
    let mut through_list = SimDisplay::new(4, 2, Rgb888::BLACK);
    list.draw(&mut View {
        inner: &mut through_list,
        origin,
    })
    .unwrap();
    let mut one_by_one = SimDisplay::new(4, 2, Rgb888::BLACK);
    let mut view = View {
        inner: &mut one_by_one,
        origin,
    };
    line.draw(&mut view).unwrap();
    view.fill_solid(&rect, Rgb888::GREEN).unwrap();
    assert_eq!(through_list.pixels(), one_by_one.pixels());
    assert_eq!(through_list.counts(), one_by_one.counts());
    assert_eq!(through_list.pixels_written(), 4);
}

proptest! {
    /// `Band`'s `SpanSink::fill_line` given pixels listed in a clip wider
    /// than the band (the screen, or the screen grown by up to 8 px), as a
    /// caller who did not clip to the band would pass, partly iterated:
    /// the target gets exactly the pixels left in the band's rows (its
    /// limit included), moved up by `top`, and no other.
    #[test]
    fn band_lines_keep_to_the_band_rows(
        c in prop::array::uniform4(-12i32..24),
        grow in 0i32..=8,
        k in 0usize..4,
        top in -3i32..14,
        limit in 0u32..=5,
    ) {
        use embedded_graphics::pixelcolor::Gray8;
        use embedded_raster::{
            band::Band,
            framebuffer::{buffer_size, Gray8Bytes},
            Framebuffer, SpanSink,
        };
        let clip = Rectangle::new(
            Point::new(-grow, -grow),
            Size::new(8 + 2 * grow as u32, 12 + 2 * grow as u32),
        );
        let Some(mut pixels) = Line::new(Point::new(c[0], c[1]), Point::new(c[2], c[3])).pixels(&clip)
        else {
            return Ok(());
        };
        for _ in 0..k {
            pixels.next();
        }
        let mut fb = Framebuffer::<Gray8Bytes, 8, 4, { buffer_size::<Gray8Bytes>(8, 4) }>::new();
        Band::new(&mut fb, top).limited_to(limit).fill_line(pixels, Gray8::WHITE).unwrap();
        let rows = top..top + limit.min(4) as i32;
        let mut want = [0u8; 32];
        for p in pixels {
            if rows.contains(&p.y) && (0..8).contains(&p.x) {
                want[((p.y - top) * 8 + p.x) as usize] = 255;
            }
        }
        prop_assert_eq!(fb.as_bytes(), &want[..], "rows {:?}", rows);
    }
}

/// A band whose buffer has more rows than the screen has left before
/// `i32::MAX` covers only those (`rows` ends there): a span on row
/// `i32::MAX` and a clear write no buffer row past them.
#[test]
fn a_band_at_the_end_of_i32_has_only_the_rows_before_it() {
    use embedded_graphics::pixelcolor::Gray8;
    use embedded_raster::{
        band::Band,
        framebuffer::{buffer_size, Gray8Bytes},
        Framebuffer, Span, SpanSink,
    };
    let mut fb = Framebuffer::<Gray8Bytes, 8, 4, { buffer_size::<Gray8Bytes>(8, 4) }>::new();
    let mut band = Band::new(&mut fb, i32::MAX - 1);
    assert_eq!(band.rows(), i32::MAX - 1..i32::MAX);
    assert_eq!(band.bounding_box().size, Size::new(8, 1));
    let span = Span {
        y: i32::MAX,
        x_start: 0,
        x_end: 8,
    };
    band.fill_span(span, Gray8::WHITE).unwrap();
    assert!(fb.as_bytes().iter().all(|&b| b == 0), "row i32::MAX drawn");
    let mut band = Band::new(&mut fb, i32::MAX - 1);
    band.clear(Gray8::WHITE).unwrap();
    let (first, rest) = fb.as_bytes().split_at(8);
    assert!(first.iter().all(|&b| b == 255));
    assert!(rest.iter().all(|&b| b == 0), "rows below the band cleared");
}

/// A screen with rows and no buffer, or a buffer without rows, is an
/// error before anything is drawn or sent; a screen without rows needs
/// no buffer.
#[test]
fn buffers_without_rows_are_an_error() {
    use embedded_graphics::pixelcolor::Gray8;
    use embedded_raster::band::RenderError;
    let mut calls = 0;
    let mut sent = 0;
    let mut run = |height: u32, buffers: &mut [SimDisplay<Gray8>]| {
        render_in_bands(
            height,
            buffers,
            None,
            |band, _| {
                calls += 1;
                band.clear(Gray8::WHITE)
            },
            &mut |_: &SimDisplay<Gray8>, _: Rectangle| {
                sent += 1;
                Ok::<(), core::convert::Infallible>(())
            },
        )
    };
    let later_empty = &mut [
        SimDisplay::new(4, 2, Gray8::BLACK),
        SimDisplay::new(4, 0, Gray8::BLACK),
    ];
    assert_eq!(run(8, later_empty), Err(RenderError::NoRows));
    assert_eq!(run(8, &mut []), Err(RenderError::NoRows));
    assert_eq!(run(0, &mut []), Ok(()));
    assert_eq!(run(8, &mut [SimDisplay::new(4, 3, Gray8::BLACK)]), Ok(()));
    assert_eq!((calls, sent), (3, 3), "bands drawn and sent");
}

/// Found by a robustness audit: `render_bands` with buffers of different
/// widths handed the narrower one spans past its width (the triangles it
/// continues from band to band were clipped to the first buffer's). It
/// now refuses them before drawing; `render_in_bands`, which clips each
/// band to its own buffer, still takes them.
#[test]
fn buffers_of_different_widths_are_an_error() {
    let v = |x: i32, y: i32| Vertex::try_from_num(x, y).unwrap();
    let mut list = DisplayList::<Rgb888, 4, 16>::new();
    let t = Triangle::new(v(0, 0), v(20, 0), v(20, 8));
    list.push(Command::Triangle(t.fill(Rgb888::RED))).unwrap();
    let mut bufs = [
        SimDisplay::new(20, 2, Rgb888::BLACK),
        SimDisplay::new(4, 2, Rgb888::BLACK),
    ];
    let sent = core::cell::Cell::new(0);
    let mut output = |_: &SimDisplay<Rgb888>, _: Rectangle| {
        sent.set(sent.get() + 1);
        Ok::<(), ()>(())
    };
    let result = list.render_bands(8, &mut bufs, None, &mut output);
    assert_eq!(result, Err(RenderError::WidthsDiffer));
    assert_eq!(sent.get(), 0);
    assert!(bufs.iter().all(|b| b.counts().iter().all(|&c| c == 0)));
    // No rows to draw: nothing to refuse.
    assert_eq!(list.render_bands(0, &mut bufs, None, &mut output), Ok(()));
    // Each band clipped to its own buffer.
    let result = render_in_bands(
        8,
        &mut bufs,
        None,
        |band, _| list.draw_band(band, None),
        &mut output,
    );
    assert_eq!(result, Ok(()));
    assert!(bufs.iter().all(|b| b.out_of_bounds_writes() == 0));
    assert_eq!(sent.get(), 4);
}

/// A band of a 40 x 30 screen, `Gray8`, takes random writes of every kind
/// (`tests/common/writes.rs`, in screen coordinates) as the whole screen
/// does: its rows end equal to the screen's rows it stands for, and the
/// target's rows past a `limited_to` band stay untouched. Each case is up
/// to 6 writes to a band of 7 rows anywhere in the screen, limited now
/// and then.
#[test]
fn a_band_takes_every_write_as_the_screen_does() {
    use embedded_graphics::pixelcolor::Gray8;
    use embedded_raster::{
        band::Band,
        framebuffer::{buffer_size, Gray8Bytes},
        Framebuffer,
    };
    type Screen = Framebuffer<Gray8Bytes, 40, 30, { buffer_size::<Gray8Bytes>(40, 30) }>;
    type Rows = Framebuffer<Gray8Bytes, 40, 7, { buffer_size::<Gray8Bytes>(40, 7) }>;
    let size = Size::new(40, 30);
    let mut rng = Rng(0xba4d_5eed_0000_0001);
    for case in 0..2000 {
        let top = rng.below(24) as i32;
        let limit = match rng.below(4) {
            0 => 1 + rng.below(7) as u32,
            _ => 7,
        };
        let (mut screen, mut rows) = (Screen::new(), Rows::new());
        let mut writes = vec![];
        for _ in 0..1 + rng.below(6) {
            let mut twin = Rng(rng.0);
            writes.push(writes::random_write(&mut rng, &mut screen, size));
            let mut band = Band::new(&mut rows, top).limited_to(limit);
            writes::random_write(&mut twin, &mut band, size);
            assert_eq!(twin.0, rng.0, "the same choices");
        }
        for y in 0..7 {
            for x in 0..40 {
                let got = rows.pixel(Point::new(x, y));
                let want = match y < limit as i32 {
                    true => screen.pixel(Point::new(x, top + y)),
                    false => Some(Gray8::BLACK),
                };
                assert_eq!(
                    got, want,
                    "case {case}: band at {top}, {limit} rows, ({x}, {y}): {writes:#?}"
                );
            }
        }
    }
}
