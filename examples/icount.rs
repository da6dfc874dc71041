//! Firmware: instruction counts per primitive on the Cortex-M4, printed
//! over semihosting as tab-separated rows; `.ci/icount` runs it (twice,
//! to check the numbers repeat) and turns them into the Markdown table in
//! `BENCHMARKS.md`. Built for `thumbv6m-none-eabi` (`.ci/icount --target
//! thumbv6m-none-eabi`), it counts the ARMv6-M build on `mps2-an385`,
//! whose SysTick also counts a 25 MHz clock; built for
//! `riscv32imc-unknown-none-elf`, the RISC-V build on QEMU's `virt` board.
//!
//! # The counter
//!
//! On ARM, QEMU runs with `-icount shift=7`: every instruction advances
//! virtual time by exactly 2^7 = 128 ns, whatever the host does. SysTick
//! counts the board's 25 MHz core clock in virtual time (40 ns a tick), so
//! `n` instructions take `3.2 n` ticks, rounded to a whole tick; because a
//! tick is shorter than an instruction, `round(ticks / 3.2)` recovers `n`
//! exactly. On RISC-V, QEMU runs with `-icount shift=0`, under which the
//! `minstret` counter reads the instructions run, exactly. Before
//! measuring, the firmware checks its counter on a loop of a known number
//! of instructions (`delay`) and stops with a failure if the count is not
//! exact. These are instructions, not cycles: QEMU does not model
//! pipeline stalls, wait states or the cost of a taken branch.
//!
//! Run: `.ci/icount` (or by hand: `cargo build --release --target
//! thumbv7em-none-eabihf --example icount --features firmware`, then the
//! runner of `.cargo/config.toml` with `-icount shift=7` added; the RISC-V
//! runner has its `-icount shift=0` already).

#![cfg_attr(target_os = "none", no_std, no_main)]

#[cfg(target_os = "none")]
#[path = "common/builtin_scene.rs"]
mod builtin_scene;

#[cfg(target_os = "none")]
#[path = "common/semihosting.rs"]
mod semihosting;

#[cfg(target_os = "none")]
mod target {
    use core::hint::black_box;

    #[cfg(target_arch = "arm")]
    use cortex_m::peripheral::{syst::SystClkSource, SYST};
    #[cfg(target_arch = "arm")]
    use cortex_m_semihosting::hprintln;
    use embedded_graphics_core::{
        draw_target::DrawTarget,
        geometry::{Dimensions, OriginDimensions, Point, Size},
        pixelcolor::Rgb565,
        primitives::Rectangle,
        Drawable, Pixel,
    };
    use embedded_raster::{
        band::DisplayList,
        framebuffer::{buffer_size, Rgb565Le},
        shade::GouraudTriangle,
        FillRule, Framebuffer, Line, Polygon, Span, SpanDrawable, StyledLine, ThickLine, Triangle,
        TriangleAlgorithm, Vertex,
    };
    #[cfg(target_arch = "riscv32")]
    use riscv_semihosting::hprintln;

    use super::builtin_scene::{self, SceneBuffer, HUGE, SCREEN, TWIN};

    /// QEMU's `-icount shift`: 2^SHIFT ns of virtual time per instruction.
    #[cfg(target_arch = "arm")]
    const SHIFT: u32 = 7;
    /// SysTick's clock on mps2-an386: the 25 MHz core clock.
    #[cfg(target_arch = "arm")]
    const SYSTICK_HZ: u64 = 25_000_000;

    /// Instructions in `ticks` SysTick ticks: `ticks / (2^SHIFT ns * 25 MHz)`,
    /// rounded to the nearest integer.
    #[cfg(target_arch = "arm")]
    fn instructions(ticks: u32) -> u32 {
        let den = (1u64 << SHIFT) * SYSTICK_HZ;
        ((u64::from(ticks) * 1_000_000_000 + den / 2) / den) as u32
    }

    /// Counts the instructions a closure runs, less the measurement's own:
    /// by SysTick on ARM, by the `minstret` counter on RISC-V (QEMU counts
    /// it exactly with `-icount shift=0`).
    struct Counter {
        #[cfg(target_arch = "arm")]
        syst: SYST,
        overhead: u32,
    }

    impl Counter {
        #[cfg(target_arch = "arm")]
        fn new(mut syst: SYST) -> Self {
            syst.disable_interrupt();
            syst.set_clock_source(SystClkSource::Core);
            syst.set_reload(0x00FF_FFFF);
            syst.clear_current();
            syst.enable_counter();
            let mut counter = Self { syst, overhead: 0 };
            counter.overhead = counter.raw(&mut || {});
            counter
        }

        #[cfg(target_arch = "riscv32")]
        fn new() -> Self {
            let mut counter = Self { overhead: 0 };
            counter.overhead = counter.raw(&mut || {});
            counter
        }

        /// Instructions from one read of the counter to the next around
        /// `f` (a dynamic call, so the overhead is the same for every `f`).
        #[cfg(target_arch = "arm")]
        #[inline(never)]
        fn raw(&mut self, f: &mut dyn FnMut()) -> u32 {
            // Restart from the reload value: 2^24 ticks (5.2 M instructions)
            // before the counter wraps. Reloading sets COUNTFLAG; clear it.
            self.syst.clear_current();
            cortex_m::asm::delay(4);
            let _ = self.syst.has_wrapped();
            let t0 = SYST::get_current();
            f();
            let t1 = SYST::get_current();
            assert!(
                !self.syst.has_wrapped() && t1 <= t0,
                "batch too long for the 24-bit SysTick"
            );
            instructions(t0 - t1)
        }

        #[cfg(target_arch = "riscv32")]
        #[inline(never)]
        fn raw(&mut self, f: &mut dyn FnMut()) -> u32 {
            let t0 = riscv::register::minstret::read64();
            f();
            let t1 = riscv::register::minstret::read64();
            u32::try_from(t1 - t0).expect("batch too long for a u32 count")
        }

        fn count(&mut self, mut f: impl FnMut()) -> u32 {
            self.raw(&mut f) - self.overhead
        }
    }

    /// A busy loop of `n` or so iterations: `cortex_m::asm::delay(n)` runs
    /// `n + 1` iterations of `subs; bne`, `riscv::asm::delay(n)` `1 + n /
    /// 2` of `addi; bne`.
    fn delay(n: u32) {
        #[cfg(target_arch = "arm")]
        cortex_m::asm::delay(n);
        #[cfg(target_arch = "riscv32")]
        riscv::asm::delay(n);
    }

    /// Instructions the loop of [`delay`] runs for `n`, calls aside.
    const fn delay_loop(n: u32) -> u32 {
        match cfg!(target_arch = "arm") {
            true => 2 * (n + 1),
            false => 2 * (1 + n / 2),
        }
    }

    /// Checks the counter on loops of known length; panics (exit failure)
    /// if it is off by even one instruction.
    fn validate(counter: &mut Counter) {
        let delay = |n: u32| move || delay(black_box(n));
        let short = counter.count(delay(1_000));
        let long = counter.count(delay(301_000));
        let again = counter.count(delay(301_000));
        let expected = delay_loop(301_000) - delay_loop(1_000);
        hprintln!(
            "validate\tdelay(1000)={}\tdelay(301000)={}\tdifference={}\texpected={}",
            short,
            long,
            long - short,
            expected
        );
        assert_eq!(long - short, expected, "instruction counter is not exact");
        assert_eq!(long, again, "instruction counter does not repeat");
        // The loop plus a few instructions of call and setup.
        let loop_only = delay_loop(1_000);
        assert!(
            (loop_only..=loop_only + 16).contains(&short),
            "delay(1000) = {short}"
        );
    }

    /// A batch of primitives to measure.
    #[derive(Clone, Copy)]
    enum Batch<'a> {
        Triangles(&'a [(Triangle, Rgb565)]),
        /// The same triangles through `draw` (the framebuffer as a
        /// `DrawTarget`: each span a one-row `fill_solid`), as
        /// embedded-graphics' own shapes are drawn.
        Drawn(&'a [(Triangle, Rgb565)]),
        /// Triangles drawn by a chosen [`TriangleAlgorithm`].
        Variants(TriangleAlgorithm, &'a [(Triangle, Rgb565)]),
        Rects(&'a [Rectangle]),
        Lines(&'a [StyledLine<Rgb565>]),
        ThickLines(&'a [ThickLine<Rgb565>]),
        Polygons(&'a [(&'a [Vertex], FillRule)]),
        /// Triangles Gouraud-shaded from their colour to [`GOURAUD`]'s.
        Gouraud(&'a [(Triangle, Rgb565)]),
    }

    impl Batch<'_> {
        fn len(self) -> usize {
            match self {
                Batch::Triangles(ts)
                | Batch::Drawn(ts)
                | Batch::Variants(_, ts)
                | Batch::Gouraud(ts) => ts.len(),
                Batch::Rects(rs) => rs.len(),
                Batch::Lines(ls) => ls.len(),
                Batch::ThickLines(ls) => ls.len(),
                Batch::Polygons(ps) => ps.len(),
            }
        }

        fn draw<D: DrawTarget<Color = Rgb565>>(self, target: &mut D) -> Result<(), D::Error> {
            match self {
                Batch::Triangles(ts) | Batch::Drawn(ts) => {
                    ts.iter().try_for_each(|(t, c)| t.fill(*c).draw(target))
                }
                Batch::Variants(a, ts) => ts
                    .iter()
                    .try_for_each(|(t, c)| t.fill(*c).algorithm(a).draw(target)),
                Batch::Rects(rs) => rs.iter().try_for_each(|r| target.fill_solid(r, BLUE)),
                Batch::Lines(ls) => ls.iter().try_for_each(|l| l.draw(target)),
                Batch::ThickLines(ls) => ls.iter().try_for_each(|l| l.draw(target)),
                Batch::Polygons(ps) => ps.iter().try_for_each(|&(v, rule)| {
                    let polygon = Polygon::<12>::new(v).expect("at most 12 vertices");
                    polygon.fill(BLUE).with_rule(rule).draw(target)
                }),
                Batch::Gouraud(ts) => ts.iter().try_for_each(|&(t, c)| gouraud(t, c).draw(target)),
            }
        }

        /// The same on the framebuffer through its span sink (the direct
        /// path), but [`Batch::Drawn`] through `draw`; rectangles through
        /// `fill_solid`.
        fn draw_spans(self, fb: &mut SceneBuffer) {
            let Ok(()) = match self {
                Batch::Triangles(ts) => ts.iter().try_for_each(|(t, c)| t.fill(*c).draw_spans(fb)),
                Batch::Drawn(ts) => ts.iter().try_for_each(|(t, c)| t.fill(*c).draw(fb)),
                Batch::Variants(a, ts) => ts
                    .iter()
                    .try_for_each(|(t, c)| t.fill(*c).algorithm(a).draw_spans(fb)),
                Batch::Rects(rs) => rs.iter().try_for_each(|r| fb.fill_solid(r, BLUE)),
                Batch::Lines(ls) => ls.iter().try_for_each(|l| l.draw_spans(fb)),
                Batch::ThickLines(ls) => ls.iter().try_for_each(|l| l.draw_spans(fb)),
                Batch::Polygons(ps) => ps.iter().try_for_each(|&(v, rule)| {
                    let polygon = Polygon::<12>::new(v).expect("at most 12 vertices");
                    polygon.fill(BLUE).with_rule(rule).draw_spans(fb)
                }),
                // No span sink: a shaded span is a `fill_contiguous`.
                Batch::Gouraud(ts) => ts.iter().try_for_each(|&(t, c)| gouraud(t, c).draw(fb)),
            };
        }

        /// The triangles' setup: everything up to their first span (sorting,
        /// clipping, orientation, the three edges, the first row), measured
        /// by stopping each triangle's rasterizer at its first span.
        fn setup(self) {
            if let Batch::Triangles(ts) = self {
                for (t, _) in ts {
                    let first = |_: Span| Err(());
                    let _ = black_box(black_box(t).for_each_span(black_box(&SCREEN), first));
                }
            }
        }

        /// The triangles' edge-stepping width: 32 bits when the bounding
        /// box spans under 2^29 raw units (131,072 px) a side, the rule of
        /// the library's frame.
        fn width(self) -> &'static str {
            let Batch::Triangles(ts) = self else {
                return "-";
            };
            let narrow = |t: &Triangle| {
                let (xs, ys) = (t.vertices.map(|v| v.raw().0), t.vertices.map(|v| v.raw().1));
                let side = |c: [i32; 3]| {
                    let (lo, hi) = (c.iter().min().unwrap(), c.iter().max().unwrap());
                    i64::from(*hi) - i64::from(*lo)
                };
                side(xs) < 1 << 29 && side(ys) < 1 << 29
            };
            match (
                ts.iter().all(|(t, _)| narrow(t)),
                ts.iter().any(|(t, _)| narrow(t)),
            ) {
                (true, _) => "32-bit",
                (false, false) => "64-bit",
                _ => "mixed",
            }
        }
    }

    const BLUE: Rgb565 = Rgb565::new(0, 40, 31);

    /// The colours of a Gouraud triangle's second and third corners.
    const GOURAUD: [Rgb565; 2] = [Rgb565::new(31, 8, 0), Rgb565::new(4, 63, 12)];

    /// Triangle `t` shaded from `c` at its first corner to [`GOURAUD`].
    fn gouraud(t: Triangle, c: Rgb565) -> GouraudTriangle<Rgb565> {
        t.gouraud([c, GOURAUD[0], GOURAUD[1]])
    }

    /// A draw target that records the rectangles sent to `fill_solid`
    /// (clipped to the screen, split into rows if `rows`), to replay them
    /// as a plain span fill of the same pixels.
    struct Recorder<'a> {
        rects: &'a mut [Rectangle],
        len: usize,
        pixels: u32,
        rows: bool,
    }

    impl Recorder<'_> {
        fn push(&mut self, r: Rectangle) {
            assert!(self.len < self.rects.len(), "recorder full");
            self.rects[self.len] = r;
            self.len += 1;
        }
    }

    impl OriginDimensions for Recorder<'_> {
        fn size(&self) -> Size {
            SCREEN.size
        }
    }

    impl DrawTarget for Recorder<'_> {
        type Color = Rgb565;
        type Error = core::convert::Infallible;

        fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(
            &mut self,
            _: I,
        ) -> Result<(), Self::Error> {
            panic!("recorder: a primitive drew single pixels");
        }

        /// A shaded span: recorded as a fill of its area.
        fn fill_contiguous<I: IntoIterator<Item = Rgb565>>(
            &mut self,
            area: &Rectangle,
            _: I,
        ) -> Result<(), Self::Error> {
            self.fill_solid(area, BLUE)
        }

        fn fill_solid(&mut self, area: &Rectangle, _: Rgb565) -> Result<(), Self::Error> {
            let area = area.intersection(&self.bounding_box());
            let Size { width, height } = area.size;
            if width == 0 || height == 0 {
                return Ok(());
            }
            self.pixels += width * height;
            if self.rows {
                for dy in 0..height as i32 {
                    let top_left = area.top_left + Point::new(0, dy);
                    self.push(Rectangle::new(top_left, Size::new(width, 1)));
                }
            } else {
                self.push(area);
            }
            Ok(())
        }
    }

    /// Measures drawing `batch` on the framebuffer, the triangles' setup,
    /// and a plain `fill_solid` of the same pixels (the primitives' own
    /// fill rectangles, or rows if `rows`); prints one row.
    fn row(
        counter: &mut Counter,
        fb: &mut SceneBuffer,
        rects: &mut [Rectangle],
        group: &str,
        label: &str,
        batch: Batch<'_>,
        rows: bool,
    ) {
        let mut recorder = Recorder {
            rects,
            len: 0,
            pixels: 0,
            rows,
        };
        let Ok(()) = batch.draw(&mut recorder);
        let (len, pixels) = (recorder.len, recorder.pixels);
        let spans = &rects[..len];
        let drawn = counter.count(|| batch.draw_spans(fb));
        let setup = counter.count(|| batch.setup());
        let filled = counter.count(|| {
            for r in spans {
                let Ok(()) = fb.fill_solid(r, BLUE);
            }
        });
        hprintln!(
            "row\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}",
            group,
            label,
            batch.len(),
            pixels,
            len,
            batch.width(),
            drawn,
            setup,
            filled
        );
    }

    /// The built-in scene as a display list.
    type SceneList<'a> = DisplayList<'a, Rgb565, 288, 12>;

    /// A band buffer of `R` rows.
    type Band<const R: usize, const N: usize> = Framebuffer<Rgb565Le, 320, R, N>;

    /// Counts rendering `list` in bands of `buffer`'s rows; prints a row.
    fn bands_row<const R: usize, const N: usize>(
        counter: &mut Counter,
        list: &SceneList<'_>,
        buffer: &mut Band<R, N>,
    ) {
        let buffers = core::slice::from_mut(buffer);
        let instructions = counter.count(|| {
            let mut nowhere = |_: &Band<R, N>, _: Rectangle| Ok::<(), ()>(());
            let _ = list.render_bands(240, &mut *buffers, None, &mut nowhere);
        });
        hprintln!("bands\tbands of {}\t{}\t{}\t{}", R, R, N, instructions);
    }

    /// `count` (at most 64) irregular triangles of `size` px tiled over
    /// the screen, as in the host benchmark.
    fn tiles(size: i32, count: usize, out: &mut [(Triangle, Rgb565); 64]) -> usize {
        let (cols, rows) = (320 / size, 240 / size);
        let mut n = 0;
        for j in 0..rows {
            for i in 0..cols {
                if n < count.min(64) {
                    out[n] = (builtin_scene::irregular(i * size, j * size, size), BLUE);
                    n += 1;
                }
            }
        }
        n
    }

    /// `sin` and `cos` of `a` radians (`|a| <= pi`) by their Taylor
    /// series to the 18th power, within 1e-7: enough to place a corner
    /// (`core` has no `sin`).
    fn sin_cos(a: f64) -> (f64, f64) {
        let (mut sin, mut cos, mut term) = (0.0, 0.0, 1.0);
        for k in 0..19 {
            match k % 4 {
                0 => cos += term,
                1 => sin += term,
                2 => cos -= term,
                _ => sin -= term,
            }
            term *= a / f64::from(k + 1);
        }
        (sin, cos)
    }

    /// A row of `group` for each random pool (4, 16 and 64 px across), its
    /// triangles drawn as `batch` makes them.
    fn random_rows(
        counter: &mut Counter,
        fb: &mut SceneBuffer,
        rects: &mut [Rectangle],
        group: &str,
        batch: fn(&[(Triangle, Rgb565)]) -> Batch<'_>,
    ) {
        let mut ts = [(Triangle::default(), BLUE); 64];
        for (seed, size, count, label) in [
            (1, 4.0, 64, "random, 4 px across"),
            (2, 16.0, 64, "random, 16 px across"),
            (3, 64.0, 16, "random, 64 px across"),
        ] {
            let n = fat_triangles(seed, size, count, &mut ts);
            row(counter, fb, rects, group, label, batch(&ts[..n]), false);
        }
    }

    /// `count` (at most 64) random fat triangles `size` px across, as the
    /// host's pools (`benches/common/pools.rs`): corners on a circle of
    /// diameter `size` around a random centre that keeps them on the
    /// screen, 120 degrees apart give or take 30, at fractional (1/4096
    /// px) positions.
    fn fat_triangles(
        seed: u32,
        size: f64,
        count: usize,
        out: &mut [(Triangle, Rgb565); 64],
    ) -> usize {
        const TAU: f64 = core::f64::consts::TAU;
        let mut rng = builtin_scene::Rng::new(seed);
        let mut unit = || f64::from(rng.next_u32()) / 4_294_967_296.0;
        let (r, n) = (size / 2.0, count.min(64));
        let margin = r + 1.0;
        // On the screen, so positive: truncating `+ 0.5` rounds.
        let raw = |px: f64| (px * 4096.0 + 0.5) as i32;
        for t in &mut out[..n] {
            let cx = margin + unit() * (320.0 - 2.0 * margin);
            let cy = margin + unit() * (240.0 - 2.0 * margin);
            let a0 = unit() * TAU;
            let corner = |k: f64, jitter: f64| {
                let mut a = a0 + k * TAU / 3.0 + (jitter - 0.5);
                while a > core::f64::consts::PI {
                    a -= TAU;
                }
                let (sin, cos) = sin_cos(a);
                Vertex::from_raw(raw(cx + r * cos), raw(cy + r * sin))
            };
            let (j0, j1, j2) = (unit(), unit(), unit());
            *t = (
                Triangle::new(corner(0.0, j0), corner(1.0, j1), corner(2.0, j2)),
                BLUE,
            );
        }
        n
    }

    /// The band buffers of 16 and 8 rows.
    type Band16 = Band<16, { buffer_size::<Rgb565Le>(320, 16) }>;
    type Band8 = Band<8, { buffer_size::<Rgb565Le>(320, 8) }>;

    #[cfg(target_arch = "arm")]
    #[cortex_m_rt::entry]
    fn main() -> ! {
        // cortex-m-rt turns these into `&'static mut` (in .bss): no unsafe.
        static mut FB: SceneBuffer = SceneBuffer::new();
        static mut RECTS: [Rectangle; 8192] = [Rectangle::zero(); 8192];
        static mut LIST: SceneList<'static> = SceneList::new();
        static mut SHAPES: Option<builtin_scene::SceneShapes> = None;
        static mut BAND16: Band16 = Band::new();
        static mut BAND8: Band8 = Band::new();
        let peripherals = cortex_m::Peripherals::take().expect("peripherals");
        let counter = Counter::new(peripherals.SYST);
        measure(counter, FB, RECTS, LIST, SHAPES, BAND16, BAND8)
    }

    #[cfg(target_arch = "riscv32")]
    #[riscv_rt::entry]
    fn main() -> ! {
        // riscv-rt has no safe `static mut`: all of it on the stack, which
        // has the board's RAM.
        let mut fb = SceneBuffer::new();
        let mut rects = [Rectangle::zero(); 8192];
        let mut shapes = None;
        let mut list = SceneList::new();
        let (mut band16, mut band8) = (Band16::new(), Band8::new());
        let counter = Counter::new();
        measure(
            counter,
            &mut fb,
            &mut rects,
            &mut list,
            &mut shapes,
            &mut band16,
            &mut band8,
        )
    }

    /// Checks the counter, then counts every row of the table and prints
    /// it. The parameters keep the names of the ARM entry's statics, which
    /// the body used before RISC-V came.
    #[allow(non_snake_case)]
    fn measure<'a>(
        mut counter: Counter,
        FB: &mut SceneBuffer,
        RECTS: &mut [Rectangle; 8192],
        LIST: &mut SceneList<'a>,
        SHAPES: &'a mut Option<builtin_scene::SceneShapes>,
        BAND16: &mut Band16,
        BAND8: &mut Band8,
    ) -> ! {
        validate(&mut counter);
        hprintln!("overhead\t{}", counter.overhead);

        // Flat triangles of several sizes, and the scene's mesh.
        let mut ts = [(Triangle::default(), BLUE); 64];
        for (size, count, label) in [
            (4, 64, "4 px"),
            (16, 64, "16 px"),
            (64, 15, "64 px"),
            (240, 1, "240 px"),
        ] {
            let n = tiles(size, count, &mut ts);
            let batch = Batch::Triangles(&ts[..n]);
            row(
                &mut counter,
                FB,
                RECTS,
                "flat triangles",
                label,
                batch,
                false,
            );
        }
        let mut mesh = [(Triangle::default(), BLUE); 96];
        let mut n = 0;
        let Ok(()) = builtin_scene::for_each_mesh_triangle(|t, c| {
            mesh[n] = (t, c);
            n += 1;
            Ok::<(), core::convert::Infallible>(())
        });
        let batch = Batch::Triangles(&mesh[..n]);
        let label = "mesh 8x6 cells (18 px)";
        row(
            &mut counter,
            FB,
            RECTS,
            "flat triangles",
            label,
            batch,
            false,
        );
        // Random fat triangles with fractional corners, as the host's pools.
        random_rows(&mut counter, FB, RECTS, "flat triangles", |ts| {
            Batch::Triangles(ts)
        });

        // The same triangles through `draw`, the embedded-graphics way.
        let group = "flat triangles through `draw`";
        for (size, count, label) in [(16, 64, "16 px"), (64, 15, "64 px")] {
            let n = tiles(size, count, &mut ts);
            row(
                &mut counter,
                FB,
                RECTS,
                group,
                label,
                Batch::Drawn(&ts[..n]),
                false,
            );
        }
        random_rows(&mut counter, FB, RECTS, group, |ts| Batch::Drawn(ts));

        // Gouraud-shaded triangles (through `draw`: each span one
        // `fill_contiguous` of its colours), against a flat fill of the
        // same spans.
        for (size, count, label) in [(16, 64, "16 px"), (64, 15, "64 px")] {
            let n = tiles(size, count, &mut ts);
            let (batch, group) = (Batch::Gouraud(&ts[..n]), "Gouraud triangles");
            row(&mut counter, FB, RECTS, group, label, batch, false);
        }
        for (seed, size, count, label) in [
            (2, 16.0, 64, "random, 16 px across"),
            (3, 64.0, 16, "random, 64 px across"),
        ] {
            let n = fat_triangles(seed, size, count, &mut ts);
            let (batch, group) = (Batch::Gouraud(&ts[..n]), "Gouraud triangles");
            row(&mut counter, FB, RECTS, group, label, batch, false);
        }

        // Every triangle algorithm on the same triangles (issue: speed for
        // accuracy); the exact one again, for ratios within the group.
        for algorithm in TriangleAlgorithm::ALL {
            let labels = match algorithm {
                TriangleAlgorithm::EdgeExact => ["exact, 16 px", "exact, 64 px"],
                TriangleAlgorithm::Barycentric => ["barycentric, 16 px", "barycentric, 64 px"],
                TriangleAlgorithm::EdgeWalk => ["walk, 16 px", "walk, 64 px"],
                TriangleAlgorithm::BresenhamWalk => ["bresenham, 16 px", "bresenham, 64 px"],
            };
            for ((size, count), label) in [(16, 64), (64, 15)].into_iter().zip(labels) {
                let n = tiles(size, count, &mut ts);
                let batch = Batch::Variants(algorithm, &ts[..n]);
                let group = "triangle algorithms";
                row(&mut counter, FB, RECTS, group, label, batch, false);
            }
        }

        // The same pixels in 32 and 64 bits.
        for (t, label) in [
            (TWIN, "TWIN: corners < 1200 px away"),
            (HUGE, "HUGE: corners ~400000 px away"),
        ] {
            let batch = Batch::Triangles(&[(t, BLUE)]);
            row(&mut counter, FB, RECTS, "edge paths", label, batch, false);
        }

        // Rectangles through fill_solid, beside one fill_solid per row.
        for (side, count, label) in [
            (4, 64, "4x4"),
            (16, 64, "16x16"),
            (64, 12, "64x64"),
            (200, 1, "200x200"),
        ] {
            let mut rs = [Rectangle::zero(); 64];
            let per_row = 320 / (side + 2);
            for (k, r) in rs.iter_mut().enumerate().take(count) {
                let (i, j) = ((k as i32 % per_row), (k as i32 / per_row));
                let top_left = Point::new(i * (side + 2), j * (side + 2));
                *r = Rectangle::new(top_left, Size::new(side as u32, side as u32));
            }
            let batch = Batch::Rects(&rs[..count]);
            row(&mut counter, FB, RECTS, "rectangles", label, batch, true);
        }

        // Lines: 1 px (short, long, ends far off-screen) and thick.
        let star = builtin_scene::star_line;
        for (count, len, label) in [
            (64, 16, "1 px wide, 16 px long"),
            (16, 200, "1 px wide, 200 px long"),
        ] {
            let mut ls = [Line::default().stroke(BLUE); 64];
            for (k, l) in ls.iter_mut().enumerate().take(count) {
                *l = star(k as i32, len).stroke(BLUE);
            }
            let batch = Batch::Lines(&ls[..count]);
            row(&mut counter, FB, RECTS, "lines", label, batch, false);
        }
        // The same short star centred 2 px inside the screen's right
        // edge: most lines cut by the clip.
        let ls: [_; 64] =
            core::array::from_fn(|k| builtin_scene::edge_star_line(k as i32, 16).stroke(BLUE));
        let label = "1 px wide, 16 px long, across the screen's edge";
        row(
            &mut counter,
            FB,
            RECTS,
            "lines",
            label,
            Batch::Lines(&ls),
            false,
        );
        for (width, label) in [(3, "3 px wide, 100 px long"), (8, "8 px wide, 100 px long")] {
            let mut ls = [Line::default().stroke(BLUE).stroke_width(width); 16];
            for (k, l) in ls.iter_mut().enumerate() {
                *l = star(k as i32, 100).stroke(BLUE).stroke_width(width);
            }
            let batch = Batch::ThickLines(&ls);
            row(&mut counter, FB, RECTS, "lines", label, batch, false);
        }
        let batch = Batch::Lines(&[builtin_scene::FAR_LINE.stroke(BLUE)]);
        let label = "1 px wide, ends 10^6 px off-screen";
        row(&mut counter, FB, RECTS, "lines", label, batch, false);
        // Its corners past the 20.12 range: found row by row.
        let batch = Batch::ThickLines(&[builtin_scene::FAR_LINE.stroke(BLUE).stroke_width(3)]);
        let label = "3 px wide, ends 10^6 px off-screen";
        row(&mut counter, FB, RECTS, "lines", label, batch, false);

        // Polygons (active edge table).
        let mut hexagons = [[Vertex::default(); 6]; 32];
        for (k, h) in hexagons.iter_mut().enumerate() {
            let k = k as i32;
            *h = builtin_scene::hexagon((12 + 20 * (k % 8), 12 + 20 * (k / 8)), 9);
        }
        let hexagons = hexagons.each_ref().map(|h| (&h[..], FillRule::NonZero));
        let batch = Batch::Polygons(&hexagons);
        row(
            &mut counter,
            FB,
            RECTS,
            "polygons",
            "hexagon 18 px",
            batch,
            false,
        );
        let star = builtin_scene::star((160, 120), 110, 50);
        let batch = Batch::Polygons(&[(&star, FillRule::NonZero)]);
        let label = "concave star, 12 vertices, 220 px";
        row(&mut counter, FB, RECTS, "polygons", label, batch, false);
        let pentagram = builtin_scene::pentagram((160, 120), 110);
        let batch = Batch::Polygons(&[(&pentagram, FillRule::EvenOdd)]);
        let label = "pentagram 220 px, even-odd";
        row(&mut counter, FB, RECTS, "polygons", label, batch, false);
        // Random octagons, often concave: corners in 8 directions at a
        // random 6 to 20 px from the centre, each moved by up to 2 px, at
        // fractional (1/4096 px) positions.
        let mut rng = builtin_scene::Rng::new(0x9E37_79B9);
        let mut octagons = [[Vertex::default(); 8]; 16];
        const DIRECTIONS: [(i32, i32); 8] = [
            (10, 0),
            (7, 7),
            (0, 10),
            (-7, 7),
            (-10, 0),
            (-7, -7),
            (0, -10),
            (7, -7),
        ];
        for (k, o) in octagons.iter_mut().enumerate() {
            let k = k as i32;
            let centre = ((24 + 40 * (k % 8)) * 4096, (40 + 80 * (k / 8)) * 4096);
            for (v, (dx, dy)) in o.iter_mut().zip(DIRECTIONS) {
                let r = 13 * 4096 + rng.signed(7 * 4096);
                let (jx, jy) = (rng.signed(2 * 4096), rng.signed(2 * 4096));
                *v = Vertex::from_raw(centre.0 + dx * r / 10 + jx, centre.1 + dy * r / 10 + jy);
            }
        }
        let octagons = octagons.each_ref().map(|o| (&o[..], FillRule::NonZero));
        let batch = Batch::Polygons(&octagons);
        let label = "random octagons, about 26 px";
        row(&mut counter, FB, RECTS, "polygons", label, batch, false);

        // The built-in scene from a display list: the whole frame, then
        // bands of 16 and 8 rows (the finished bands go nowhere).
        let shapes: &'a builtin_scene::SceneShapes =
            SHAPES.insert(builtin_scene::SceneShapes::new());
        if builtin_scene::for_each_command(shapes, |c| LIST.push(c)).is_err() {
            panic!("the scene does not fit the list");
        }
        let list: &SceneList<'a> = LIST;
        let whole = counter.count(|| {
            let Ok(()) = list.draw_with_depth(&mut *FB, None);
        });
        hprintln!("bands\twhole frame\t240\t{}\t{}", 320 * 240 * 2, whole);
        bands_row(&mut counter, list, BAND16);
        bands_row(&mut counter, list, BAND8);

        hprintln!("done");
        super::semihosting::exit_success()
    }
}

#[cfg(not(target_os = "none"))]
fn main() {
    eprintln!(
        "icount is Cortex-M firmware: run .ci/icount, which builds it for \
         thumbv7em-none-eabihf and runs it under QEMU with -icount shift=7"
    );
}
