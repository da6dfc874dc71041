//! One random write to a sink, through any of its ways in: the
//! `DrawTarget` methods (`fill_solid`, `draw_iter`, `fill_contiguous`,
//! `clear`), the `SpanSink` methods (`fill_span` inside the screen,
//! `fill_column` and `fill_rect` anywhere) and shapes drawn by `draw` and
//! `draw_spans` (lines, triangles, polygons, axis-aligned ones included,
//! and thick polylines, whose pieces overlap). The parameters depend on
//! the generator alone, so that two sinks given the same generator state
//! receive the same writes, in screen coordinates.

use core::convert::Infallible;

use embedded_graphics::{pixelcolor::Gray8, prelude::*, primitives::Rectangle};
use embedded_raster::{Line, Polygon, Polyline, Span, SpanDrawable, SpanSink, Triangle, Vertex};

use super::rng::Rng;

/// Writes once to `sink`, a view of a `screen`-sized area at the origin
/// (a sink may cover a part of it: a span outside its bounds is not
/// given to it). Returns what was written, for messages.
pub fn random_write<S>(rng: &mut Rng, sink: &mut S, screen: Size) -> String
where
    S: SpanSink<Gray8, Error = Infallible> + DrawTarget<Color = Gray8, Error = Infallible>,
{
    let (w, h) = (screen.width as i64, screen.height as i64);
    let point = |rng: &mut Rng| {
        Point::new(
            (rng.below(w as u64 + 20) - 10) as i32,
            (rng.below(h as u64 + 20) - 10) as i32,
        )
    };
    let luma = Gray8::new(1 + rng.below(255) as u8);
    let size = |rng: &mut Rng| Size::new(rng.below(14) as u32, rng.below(14) as u32);
    let vertex = |rng: &mut Rng| {
        Vertex::from_raw(
            (rng.below((w as u64 + 8) * 4096) - 4 * 4096) as i32,
            (rng.below((h as u64 + 8) * 4096) - 4 * 4096) as i32,
        )
    };
    match rng.below(13) {
        0 => {
            let area = Rectangle::new(point(rng), size(rng));
            let Ok(()) = sink.fill_solid(&area, luma);
            format!("fill_solid {area:?}")
        }
        1 => {
            let pixels: Vec<_> = (0..5).map(|_| Pixel(point(rng), luma)).collect();
            let Ok(()) = sink.draw_iter(pixels.iter().copied());
            format!("draw_iter {pixels:?}")
        }
        2 => {
            // A colour per pixel, so that a skipped or shifted one shows.
            let area = Rectangle::new(point(rng), size(rng));
            let first = rng.below(256) as u8;
            let colors = (0..).map(move |k: u32| Gray8::new(first.wrapping_add(k as u8) | 1));
            let Ok(()) = sink.fill_contiguous(&area, colors);
            format!("fill_contiguous {area:?} from {first}")
        }
        3 if rng.below(8) == 0 => {
            let Ok(()) = sink.clear(luma);
            format!("clear {luma:?}")
        }
        3 | 4 => {
            let y = rng.below(h as u64) as i32;
            let a = rng.below(w as u64) as i32;
            let b = a + 1 + rng.below((w - i64::from(a)) as u64) as i32;
            let span = Span {
                y,
                x_start: a,
                x_end: b,
            };
            // The sink's contract: spans inside its bounds.
            if sink.bounds().contains(Point::new(a, y)) {
                let Ok(()) = sink.fill_span(span, luma);
            }
            format!("fill_span {span:?}")
        }
        5 => {
            let top = point(rng);
            let len = rng.below(h as u64 + 20) as u32;
            let Ok(()) = sink.fill_column(top, len, luma);
            format!("fill_column {top:?} {len}")
        }
        6 => {
            let area = Rectangle::new(point(rng), size(rng));
            let Ok(()) = sink.fill_rect(&area, luma);
            format!("fill_rect {area:?}")
        }
        7 | 8 => {
            let line = Line::new(point(rng), point(rng));
            let stroke = line
                .stroke(luma)
                .stroke_width(1 + 3 * (rng.below(3) == 0) as u32);
            let Ok(()) = match rng.below(2) {
                0 => stroke.draw(sink),
                _ => stroke.draw_spans(sink),
            };
            format!("line {line:?}")
        }
        9 => {
            let t = Triangle::new(vertex(rng), vertex(rng), vertex(rng));
            let Ok(()) = match rng.below(2) {
                0 => t.fill(luma).draw(sink),
                _ => t.fill(luma).draw_spans(sink),
            };
            format!("triangle {t:?}")
        }
        10 => {
            let n = 3 + rng.below(4) as usize;
            let v: Vec<Vertex> = match rng.below(2) {
                // Axis-aligned: a rectangle of whole pixels.
                0 => {
                    let (a, b) = (point(rng), point(rng));
                    [(a.x, a.y), (b.x, a.y), (b.x, b.y), (a.x, b.y)]
                        .map(|(x, y)| Vertex::from_raw(x * 4096, y * 4096))
                        .to_vec()
                }
                _ => (0..n).map(|_| vertex(rng)).collect(),
            };
            let poly = Polygon::<8>::new(&v).unwrap().fill(luma);
            let Ok(()) = match rng.below(2) {
                0 => poly.draw(sink),
                _ => poly.draw_spans(sink),
            };
            format!("polygon {v:?}")
        }
        _ => {
            let points: Vec<Point> = (0..2 + rng.below(4)).map(|_| point(rng)).collect();
            let width = 1 + rng.below(6) as u32;
            let stroke = Polyline::new(&points).stroke(luma).stroke_width(width);
            let Ok(()) = match rng.below(2) {
                0 => stroke.draw(sink),
                _ => stroke.draw_spans(sink),
            };
            format!("polyline {points:?} width {width}")
        }
    }
}
