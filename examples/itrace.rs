//! Firmware for `.ci/itrace`: a few shapes drawn between two marker
//! calls, for an instruction-by-instruction trace under QEMU. The script
//! counts the instructions run between each `begin` and the next `end`,
//! in all and per function: where a triangle's setup and rows go on a
//! Cortex-M4, which the totals of `.ci/icount` do not show.
//!
//! The windows, in order (the triangles of `.ci/icount`'s "flat
//! triangles" rows, `builtin_scene::irregular`):
//! 1. the setup of a 16 px triangle: `for_each_span` stopped at its first
//!    span, as `.ci/icount` measures it;
//! 2. the same triangle drawn through the framebuffer's span sink;
//! 3. a 64 px triangle, the same way;
//! 4. the 16 px triangle Gouraud-shaded, through `draw`;
//! 5. the same triangle flat, depth-tested;
//! 6. the same triangle Gouraud-shaded and depth-tested;
//! 7. a line 3 px wide and 100 px long at a slope of 1/2 (the second of
//!    `.ci/icount`'s "3 px wide" lines): its corners, then its rows;
//! 8. a line 3 px wide with ends 10^6 px off-screen (`.ci/icount`'s):
//!    its rows found by edges set up in 128 bits;
//! 9. an 18 px hexagon (`.ci/icount`'s hexagons): the monotone test and
//!    the two chains of edges;
//! 10. `.ci/icount`'s pentagram, 220 px, even-odd: the active edge table;
//! 11. a polyline of 21 points in a zigzag, 8 px wide with mitred joins
//!     (the host bench's, `benches/lines.rs`), through the framebuffer's
//!     span sink: its pieces written whole, overlapping;
//! 12. the same polyline through `draw` (the framebuffer as a
//!     `DrawTarget`): each pixel once, its pieces walked in masked tiles;
//! 13. the same polyline with round joins, through the span sink: each
//!     join a disk sector, walked row by row with a square root a row;
//! 14. the same 20 segments drawn as separate thick lines;
//! 15. `.ci/icount`'s 64 lines 1 px wide and 16 px long, in a star;
//! 16. the same star across the screen's right edge (`.ci/icount`'s
//!     "across the screen's edge" row): lines cut by the clip;
//! 17. 64 random lines 1 px wide that the screen's edges cut
//!     (`builtin_scene::cut_line`): every slope and length, cut on any
//!     side, as the host bench's "lines cut";
//! 18. and 19. 64 random thick lines 2 to 12 px wide, short then long
//!     (`builtin_scene::random_thick_line`, the host bench's two sets);
//! 20. the built-in scene (`builtin_scene::for_each_command`) from a
//!     display list, drawn whole into the framebuffer, as `.ci/icount`'s
//!     "whole frame" row;
//! 21. the same list rendered in bands of 16 rows, as its "bands of 16"
//!     row: where the bands' extra instructions go;
//! 22. and 23. the 16 px and 64 px triangles of windows 2 and 3 through
//!     `draw` (the framebuffer as a `DrawTarget`: a one-row `fill_solid`
//!     a span), as embedded-graphics' own shapes draw;
//! 24. to 27. a line of embedded-graphics' 6 x 10 text (54 characters),
//!     transparent (`draw_iter`) on this crate's framebuffer, then on
//!     embedded-graphics 0.8's of the same size and format, then the same
//!     two on a background (`fill_contiguous`).
//!
//! Built for the host, it does nothing.

#![cfg_attr(target_arch = "arm", no_std, no_main)]

#[cfg(target_arch = "arm")]
#[path = "common/builtin_scene.rs"]
mod builtin_scene;

#[cfg(target_arch = "arm")]
#[path = "common/semihosting.rs"]
mod semihosting;

#[cfg(target_arch = "arm")]
mod target {
    use core::hint::black_box;

    use cortex_m_rt::entry;
    use embedded_graphics::{
        framebuffer::{buffer_size as eg_buffer_size, Framebuffer as EgFramebuffer},
        mono_font::{ascii::FONT_6X10, MonoTextStyle, MonoTextStyleBuilder},
        pixelcolor::raw::{LittleEndian, RawU16},
        text::{Baseline, Text},
    };
    use embedded_graphics_core::pixelcolor::{Rgb565, RgbColor};
    use embedded_graphics_core::primitives::Rectangle;
    use embedded_graphics_core::{draw_target::DrawTarget, geometry::Point, Drawable};
    use embedded_raster::{
        band::DisplayList,
        framebuffer::{buffer_size, Rgb565Le},
        shade::DepthBuffer,
        Framebuffer, Join, Line, Polyline, Span, SpanDrawable, Triangle,
    };

    use super::builtin_scene::{irregular, SceneBuffer, SCREEN};

    /// The start of a traced window.
    #[inline(never)]
    fn begin() {
        cortex_m::asm::nop();
    }

    /// Its end (a body of its own, so that the two are not merged).
    #[inline(never)]
    fn end() {
        cortex_m::asm::nop();
        cortex_m::asm::nop();
    }

    /// One triangle drawn through the framebuffer's span sink, traced.
    #[inline(never)]
    fn draw(t: &Triangle, fb: &mut SceneBuffer) {
        begin();
        let Ok(()) = black_box(t).fill(Rgb565::RED).draw_spans(black_box(fb));
        end();
    }

    /// One triangle drawn through `Drawable::draw`, the framebuffer as a
    /// `DrawTarget`, traced.
    #[inline(never)]
    fn draw_as_target(t: &Triangle, fb: &mut SceneBuffer) {
        begin();
        let Ok(()) = black_box(t).fill(Rgb565::RED).draw(black_box(fb));
        end();
    }

    /// embedded-graphics 0.8's own framebuffer, the same size and format
    /// as the scene's, for its text beside this crate's.
    type EgScreen = EgFramebuffer<
        Rgb565,
        RawU16,
        LittleEndian,
        320,
        240,
        { eg_buffer_size::<Rgb565>(320, 240) },
    >;

    /// A line of 54 characters of embedded-graphics' 6 x 10 font (the last
    /// one cut by the screen's right edge), white, drawn on `target`,
    /// traced: without a background (each glyph pixel through `draw_iter`)
    /// or on a black one (each glyph's cell through `fill_contiguous`).
    #[inline(never)]
    fn text<D: DrawTarget<Color = Rgb565>>(target: &mut D, background: bool) {
        let style = match background {
            true => MonoTextStyleBuilder::new()
                .font(&FONT_6X10)
                .text_color(Rgb565::WHITE)
                .background_color(Rgb565::BLACK)
                .build(),
            false => MonoTextStyle::new(&FONT_6X10, Rgb565::WHITE),
        };
        let line = "The quick brown fox jumps over the lazy dog 0123456789";
        let origin = Point::new(0, 100);
        begin();
        let _ = Text::with_baseline(black_box(line), origin, style, Baseline::Top)
            .draw(black_box(target));
        end();
    }

    /// The built-in scene's display list, as `.ci/icount` builds it.
    type SceneList<'a> = DisplayList<'a, Rgb565, 288, 12>;

    /// A band of 16 rows of the screen.
    type Band16 = Framebuffer<Rgb565Le, 320, 16, { buffer_size::<Rgb565Le>(320, 16) }>;

    #[entry]
    fn main() -> ! {
        static mut FB: SceneBuffer = SceneBuffer::new();
        static mut LIST: Option<SceneList<'static>> = None;
        static mut SHAPES: Option<super::builtin_scene::SceneShapes> = None;
        static mut BAND16: Band16 = Band16::new();
        static mut DEPTH: [u16; 64 * 64] = [0; 64 * 64];
        static mut EG: EgScreen = EgScreen::new();
        let small = irregular(32, 48, 16);
        begin();
        let first = |_: Span| Err(());
        let _ = black_box(black_box(&small).for_each_span(black_box(&SCREEN), first));
        end();
        // One call each: a loop over an array of triangles could move
        // them with a `memmove` inside the window.
        draw(&small, FB);
        draw(&irregular(64, 64, 64), FB);
        // The 16 px triangle Gouraud-shaded, through `draw` (the shaded
        // spans' colours go to the framebuffer's `fill_contiguous`).
        let shaded = small.gouraud([Rgb565::RED, Rgb565::GREEN, Rgb565::BLUE]);
        begin();
        let Ok(()) = black_box(&shaded).draw(black_box(&mut *FB));
        end();
        // The same triangle flat, depth-tested against a cleared 64 x 64
        // depth buffer that holds it (every pixel passes).
        let depth = DepthBuffer::new(DEPTH, 64);
        depth.clear();
        let tested = small.fill(Rgb565::RED).with_depth([100, 200, 300], depth);
        begin();
        let Ok(()) = black_box(&tested).draw(black_box(&mut *FB));
        end();
        // The same triangle Gouraud-shaded and depth-tested, against the
        // depth buffer cleared again.
        depth.clear();
        let both = shaded.with_depth([100, 200, 300], depth);
        begin();
        let Ok(()) = black_box(&both).draw(black_box(&mut *FB));
        end();
        let line = super::builtin_scene::star_line(1, 100)
            .stroke(Rgb565::RED)
            .stroke_width(3);
        begin();
        let Ok(()) = black_box(&line).draw_spans(black_box(FB));
        end();
        // The same width with ends 10^6 px off-screen: its corners leave
        // the 20.12 range, and its rows are found by edges set up in
        // 128 bits.
        let far = super::builtin_scene::FAR_LINE
            .stroke(Rgb565::RED)
            .stroke_width(3);
        begin();
        let Ok(()) = black_box(&far).draw_spans(black_box(FB));
        end();
        let hex = super::builtin_scene::hexagon((100, 100), 9);
        let poly = embedded_raster::Polygon::<12>::new(&hex)
            .unwrap()
            .fill(Rgb565::RED);
        begin();
        let Ok(()) = black_box(&poly).draw_spans(black_box(FB));
        end();
        let star = super::builtin_scene::pentagram((160, 120), 110);
        let poly = embedded_raster::Polygon::<12>::new(&star)
            .unwrap()
            .fill(Rgb565::RED)
            .with_rule(embedded_raster::FillRule::EvenOdd);
        begin();
        let Ok(()) = black_box(&poly).draw_spans(black_box(FB));
        end();
        // The host bench's zigzag (`benches/lines.rs`): 21 points, 8 px
        // wide, mitred; then its 20 segments as separate thick lines.
        let zigzag: [Point; 21] = core::array::from_fn(|k| {
            let k = k as i32;
            Point::new(10 + k * 14, if k % 2 == 0 { 30 } else { 210 })
        });
        let stroke = Polyline::new(&zigzag)
            .stroke(Rgb565::RED)
            .stroke_width(8)
            .join(Join::Miter);
        begin();
        let Ok(()) = black_box(&stroke).draw_spans(black_box(FB));
        end();
        begin();
        let Ok(()) = black_box(&stroke).draw(black_box(FB));
        end();
        let round = stroke.join(Join::Round);
        begin();
        let Ok(()) = black_box(&round).draw_spans(black_box(FB));
        end();
        let lines: [_; 20] = core::array::from_fn(|k| {
            Line::new(zigzag[k], zigzag[k + 1])
                .stroke(Rgb565::RED)
                .stroke_width(8)
        });
        begin();
        for line in black_box(&lines) {
            let Ok(()) = black_box(line).draw_spans(black_box(FB));
        }
        end();
        // `.ci/icount`'s 64 star lines 1 px wide and 16 px long, then the
        // same star across the screen's right edge (clipped lines): a
        // window each.
        let stars: [fn(i32, i32) -> Line; 2] = [
            super::builtin_scene::star_line,
            super::builtin_scene::edge_star_line,
        ];
        for star in stars {
            let lines: [_; 64] = core::array::from_fn(|k| star(k as i32, 16).stroke(Rgb565::RED));
            begin();
            for line in black_box(&lines) {
                let Ok(()) = black_box(line).draw_spans(black_box(&mut *FB));
            }
            end();
        }
        let mut rng = super::builtin_scene::Rng::new(0x2545_F491);
        let cut: [_; 64] =
            core::array::from_fn(|_| super::builtin_scene::cut_line(&mut rng).stroke(Rgb565::RED));
        begin();
        for line in black_box(&cut) {
            let Ok(()) = black_box(line).draw_spans(black_box(&mut *FB));
        }
        end();
        // Random thick lines, short then long, as the host bench's sets.
        for short in [true, false] {
            let thick: [_; 64] = core::array::from_fn(|_| {
                let (line, width) = super::builtin_scene::random_thick_line(&mut rng, short);
                line.stroke(Rgb565::RED).stroke_width(width)
            });
            begin();
            for line in black_box(&thick) {
                let Ok(()) = black_box(line).draw_spans(black_box(&mut *FB));
            }
            end();
        }
        let shapes: &'static _ = SHAPES.insert(super::builtin_scene::SceneShapes::new());
        let list = LIST.insert(SceneList::new());
        if super::builtin_scene::for_each_command(shapes, |c| list.push(c)).is_err() {
            panic!("the scene does not fit the list");
        }
        let list = &*list;
        begin();
        let Ok(()) = black_box(list).draw_with_depth(black_box(&mut *FB), None);
        end();
        let buffers = core::slice::from_mut(BAND16);
        let mut nowhere = |_: &Band16, _: Rectangle| Ok::<(), ()>(());
        begin();
        let _ = black_box(list).render_bands(240, &mut *buffers, None, &mut nowhere);
        end();
        draw_as_target(&small, FB);
        draw_as_target(&irregular(64, 64, 64), FB);
        for background in [false, true] {
            text(FB, background);
            text(EG, background);
        }
        super::semihosting::exit_success()
    }
}

#[cfg(not(target_arch = "arm"))]
fn main() {}
