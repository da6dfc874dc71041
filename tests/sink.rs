//! The provided methods of `SpanSink`, on a sink that implements only
//! `fill_span` and records what it is given: a column or a rectangle,
//! clipped or not by the caller, reaches `fill_span` as one span per row
//! of its part inside the sink's bounds, each exactly that part's
//! columns, and nothing of it outside (so an unclipped area costs only
//! its visible rows). The expected pixels are the intersection computed
//! here in `i64`; a span cannot end past `i32::MAX`, so the last column
//! of the range is out of reach (the documented limit).
//!
//! `DrawTargetSink` passes every kind of write on to its target: the same
//! pixels as the framebuffer's own `SpanSink` and `DrawTarget` give.
//!
//! Case counts follow `PROPTEST_CASES` (proptest's default, 256, when
//! unset).

#[path = "common/rng.rs"]
mod rng;
#[path = "common/writes.rs"]
mod writes;

use std::convert::Infallible;

use embedded_graphics_core::{
    geometry::{Point, Size},
    pixelcolor::BinaryColor,
    primitives::Rectangle,
};
use embedded_raster::{Span, SpanSink};
use proptest::prelude::*;

/// Records every span it is given.
struct Spans {
    bounds: Rectangle,
    spans: Vec<Span>,
}

impl SpanSink<BinaryColor> for Spans {
    type Error = Infallible;

    fn bounds(&self) -> Rectangle {
        self.bounds
    }

    fn fill_span(&mut self, span: Span, _: BinaryColor) -> Result<(), Infallible> {
        self.spans.push(span);
        Ok(())
    }
}

/// `(x0, x1, y0, y1)`, half-open, of a rectangle in `i64`.
fn edges(r: &Rectangle) -> (i64, i64, i64, i64) {
    let (x, y) = (i64::from(r.top_left.x), i64::from(r.top_left.y));
    (
        x,
        x + i64::from(r.size.width),
        y,
        y + i64::from(r.size.height),
    )
}

/// The spans the provided methods should produce for `area` in `bounds`,
/// from the two rectangles' edges.
fn expected(area: &Rectangle, bounds: &Rectangle) -> Vec<(i64, i64, i64)> {
    let (a, b) = (edges(area), edges(bounds));
    let (x0, x1) = (a.0.max(b.0), a.1.min(b.1).min(i64::from(i32::MAX)));
    let (y0, y1) = (a.2.max(b.2), a.3.min(b.3).min(i64::from(i32::MAX) + 1));
    if x0 >= x1 || y0 >= y1 {
        return vec![];
    }
    (y0..y1).map(|y| (y, x0, x1)).collect()
}

fn got(sink: &Spans) -> Vec<(i64, i64, i64)> {
    sink.spans
        .iter()
        .map(|s| (i64::from(s.y), i64::from(s.x_start), i64::from(s.x_end)))
        .collect()
}

/// A coordinate near one of a few places: the origin, or either end of
/// the `i32` range.
fn coordinate() -> impl Strategy<Value = i32> {
    (0usize..3, -40i64..40).prop_map(|(at, d)| {
        let base = [0, i64::from(i32::MIN), i64::from(i32::MAX)][at];
        (base + d).clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32
    })
}

/// A side: short, or anything up to `u32::MAX`.
fn side() -> impl Strategy<Value = u32> {
    prop_oneof![0u32..60, any::<u32>(), Just(u32::MAX)]
}

proptest! {
    #[test]
    fn provided_fills_cover_the_visible_rows_only(
        bounds_at in (coordinate(), coordinate()),
        bounds_size in (1u32..48, 1u32..48),
        at in (coordinate(), coordinate()),
        size in (side(), side()),
    ) {
        let bounds = Rectangle::new(Point::new(bounds_at.0, bounds_at.1), Size::new(bounds_size.0, bounds_size.1));
        let area = Rectangle::new(Point::new(at.0, at.1), Size::new(size.0, size.1));
        let mut sink = Spans { bounds, spans: vec![] };
        sink.fill_rect(&area, BinaryColor::On).unwrap();
        prop_assert_eq!(got(&sink), expected(&area, &bounds), "rectangle {:?} in {:?}", area, bounds);

        let column = Rectangle::new(area.top_left, Size::new(1, size.1));
        let mut sink = Spans { bounds, spans: vec![] };
        sink.fill_column(column.top_left, size.1, BinaryColor::On).unwrap();
        prop_assert_eq!(got(&sink), expected(&column, &bounds), "column {:?} in {:?}", column, bounds);
    }
}

/// By hand: a column from the row after `i32::MIN`, `u32::MAX` long (to
/// row `i32::MAX`), in 3 x 4 bounds at the bottom of the range, lights
/// their four rows.
#[test]
fn a_whole_range_column_lights_the_rows_of_the_bounds() {
    let bounds = Rectangle::new(Point::new(5, i32::MAX - 3), Size::new(3, 4));
    let mut sink = Spans {
        bounds,
        spans: vec![],
    };
    sink.fill_column(Point::new(6, i32::MIN + 1), u32::MAX, BinaryColor::On)
        .unwrap();
    let rows: Vec<i32> = sink.spans.iter().map(|s| s.y).collect();
    assert_eq!(rows, [i32::MAX - 3, i32::MAX - 2, i32::MAX - 1, i32::MAX]);
    assert!(sink.spans.iter().all(|s| (s.x_start, s.x_end) == (6, 7)));
}

/// Random writes of every kind (`tests/common/writes.rs`) through a
/// `DrawTargetSink` on a framebuffer, which turns spans, columns and
/// rectangles into `fill_solid` and passes the `DrawTarget` methods on,
/// leave the same pixels as the same writes on the framebuffer itself,
/// whose `SpanSink` writes its bytes directly.
#[test]
fn a_draw_target_sink_passes_every_write_on() {
    use embedded_raster::{
        framebuffer::{buffer_size, Gray8Bytes},
        DrawTargetSink, Framebuffer,
    };
    type Fb = Framebuffer<Gray8Bytes, 40, 30, { buffer_size::<Gray8Bytes>(40, 30) }>;
    let size = Size::new(40, 30);
    let mut rng = rng::Rng(0x5151_0000_0000_0001);
    for case in 0..1000 {
        let (mut direct, mut wrapped) = (Fb::new(), Fb::new());
        let mut done = vec![];
        for _ in 0..1 + rng.below(6) {
            let mut twin = rng::Rng(rng.0);
            done.push(writes::random_write(&mut rng, &mut direct, size));
            writes::random_write(&mut twin, &mut DrawTargetSink::new(&mut wrapped), size);
        }
        for y in 0..30 {
            for x in 0..40 {
                let p = Point::new(x, y);
                assert_eq!(
                    wrapped.pixel(p),
                    direct.pixel(p),
                    "case {case}: {p:?}: {done:#?}"
                );
            }
        }
    }
}
