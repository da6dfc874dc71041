//! The speed-for-accuracy report of the triangle variants.
//!
//! ```sh
//! cargo run --release --features sim --example tradeoff
//! ```
//!
//! Measures, in one run, every [`TriangleAlgorithm`] at every
//! [`SubpixelPrecision`] (and seed 000's float setup as a reference
//! point): accuracy over the fixed scene sets of `measure.rs`, host time
//! per triangle on a 320 x 240 Rgb565 framebuffer as medians of repeated
//! runs, beside the exact default and a plain span fill. It writes the
//! tables into `BENCHMARKS.md` between the `tradeoff` marker comments
//! (re-runs replace them) and draws `docs/tradeoff.png` with the crate's
//! own rasterizer.

mod measure;

use std::fmt::Write as _;
use std::hint::black_box;
use std::time::Instant;

use embedded_graphics::{
    mono_font::{ascii::FONT_6X10, MonoTextStyle},
    pixelcolor::{Rgb565, Rgb888},
    prelude::*,
    text::{Alignment, Text},
};
use embedded_raster::{
    framebuffer::{buffer_size, Rgb565Le},
    sim::SimDisplay,
    Framebuffer, Line, Span, SubpixelPrecision, Triangle, TriangleAlgorithm, Vertex,
};
use measure::{accuracy, largest_ok, scene_sets, Accuracy, Rng, Variant};

const W: usize = 320;
const H: usize = 240;
type Fb = Framebuffer<Rgb565Le, W, H, { buffer_size::<Rgb565Le>(W, H) }>;

/// Size classes for timing: (name, size in px, triangles).
const CLASSES: [(&str, i64, usize); 3] = [("8 px", 8, 64), ("32 px", 32, 64), ("128 px", 128, 16)];
/// Timed repetitions; the median is reported.
const REPEATS: usize = 41;

/// Irregular triangles `size` px across at random subpixel positions.
fn timing_set(size: i64, n: usize, seed: u64) -> Vec<Triangle> {
    let mut rng = Rng::new(seed);
    let s = size * 4096;
    (0..n)
        .map(|_| {
            let ox = rng.range(0, (W as i64 - size - 1) * 4096);
            let oy = rng.range(0, (H as i64 - size - 1) * 4096);
            let p = |u: i64, v: i64| {
                Vertex::from_raw((ox + s * u / 100) as i32, (oy + s * v / 100) as i32)
            };
            Triangle::new(p(5, 10), p(98, 35), p(30, 97))
        })
        .collect()
}

/// Median ns per triangle of `draw` over the set, and pixels lit per run.
fn time(mut draw: impl FnMut(&mut Fb) -> u64, tris: usize) -> (f64, u64) {
    let mut fb = Fb::new();
    let px = draw(&mut fb);
    let mut samples: Vec<f64> = (0..REPEATS)
        .map(|_| {
            let start = Instant::now();
            black_box(draw(black_box(&mut fb)));
            start.elapsed().as_nanos() as f64 / tris as f64
        })
        .collect();
    samples.sort_by(f64::total_cmp);
    (samples[REPEATS / 2], px)
}

/// Each span goes to `fill_solid` from a closure marked `#[inline(always)]`,
/// so that every variant's row loop has it inlined: without the mark, the
/// compiler inlined it into `walk`'s single loop but called it out of
/// line from the exact walk's four (its 32-bit, checked, 64-bit and tiny
/// paths), and the table measured that call, about 12 instructions a
/// row (callgrind: 2,534 against 2,197 a 32 px triangle of about 28
/// rows), rather than the algorithms (BENCHMARKS.md, "Speed for
/// accuracy").
fn draw_variant(v: Variant, p: SubpixelPrecision, tris: &[Triangle], fb: &mut Fb) -> u64 {
    let clip = fb.bounding_box();
    let mut px = 0u64;
    for t in tris {
        v.spans(
            p,
            t,
            &clip,
            #[inline(always)]
            |s: Span| {
                px += u64::from(s.len());
                let _ = fb.fill_solid(&s.rect(), Rgb565::RED);
            },
        );
    }
    px
}

struct Row {
    v: Variant,
    p: SubpixelPrecision,
    sets: Vec<(&'static str, Accuracy)>,
    largest: i64,
    /// ns per triangle and px per run, per size class.
    speed: Vec<(f64, u64)>,
}

impl Row {
    fn total(&self) -> Accuracy {
        let mut t = Accuracy::default();
        for (_, a) in &self.sets {
            t.reference_px += a.reference_px;
            t.differing_px += a.differing_px;
            t.gaps += a.gaps;
            t.overdraw += a.overdraw;
        }
        t
    }

    fn mismatch(&self) -> f64 {
        let t = self.total();
        100.0 * t.differing_px as f64 / t.reference_px.max(1) as f64
    }

    fn label(&self) -> String {
        format!("{} @{}", self.v.name(), self.p.bits())
    }
}

fn main() {
    let sets = scene_sets(4);
    let timing: Vec<Vec<Triangle>> = CLASSES
        .iter()
        .enumerate()
        .map(|(k, &(_, size, n))| timing_set(size, n, 100 + k as u64))
        .collect();

    // The memory limit: the exact spans, precomputed, filled.
    let fill: Vec<(f64, u64)> = timing
        .iter()
        .map(|tris| {
            let clip = Fb::new().bounding_box();
            let mut spans = vec![];
            for t in tris {
                let _ = t.for_each_span(&clip, |s| {
                    spans.push(s);
                    Ok::<(), ()>(())
                });
            }
            time(
                |fb| {
                    spans.iter().for_each(|s| {
                        let _ = fb.fill_solid(&s.rect(), Rgb565::RED);
                    });
                    spans.iter().map(|s| u64::from(s.len())).sum()
                },
                tris.len(),
            )
        })
        .collect();

    let mut rows = vec![];
    for v in Variant::ALL {
        for p in SubpixelPrecision::ALL {
            let sets_acc = sets.iter().map(|s| (s.name, accuracy(v, p, s))).collect();
            let speed = timing
                .iter()
                .map(|tris| time(|fb| draw_variant(v, p, tris, fb), tris.len()))
                .collect();
            rows.push(Row {
                v,
                p,
                sets: sets_acc,
                largest: largest_ok(v, p),
                speed,
            });
        }
    }
    let exact = rows
        .iter()
        .position(|r| {
            r.v == Variant::Lib(TriangleAlgorithm::EdgeExact) && r.p == SubpixelPrecision::Bits12
        })
        .unwrap_or(0);
    let base: Vec<f64> = rows[exact].speed.iter().map(|s| s.0).collect();

    // Pareto front on (mismatch, time at 32 px) over the library variants.
    // Times within 5 % count as equal: closer than that is noise here.
    let lib: Vec<usize> = (0..rows.len())
        .filter(|&i| matches!(rows[i].v, Variant::Lib(_)))
        .collect();
    let pareto: Vec<usize> = lib
        .iter()
        .copied()
        .filter(|&i| {
            let (m, t) = (rows[i].mismatch(), rows[i].speed[1].0);
            !lib.iter().any(|&j| {
                let (mj, tj) = (rows[j].mismatch(), rows[j].speed[1].0);
                j != i && mj <= m && tj <= t * 1.05 && (mj < m || tj < t * 0.95)
            })
        })
        .collect();

    let md = report(&rows, &base, &fill, &pareto);
    print!("{md}");
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/BENCHMARKS.md");
    match std::fs::read_to_string(path) {
        Ok(text) => {
            let (begin, end) = ("<!-- tradeoff:begin -->", "<!-- tradeoff:end -->");
            let new = match (text.find(begin), text.find(end)) {
                (Some(b), Some(e)) if b < e => {
                    format!("{}{begin}\n{md}{}", &text[..b], &text[e..])
                }
                _ => format!("{text}\n{begin}\n{md}{end}\n"),
            };
            if let Err(e) = std::fs::write(path, new) {
                eprintln!("{path}: {e}");
            }
        }
        Err(e) => eprintln!("{path}: {e}"),
    }
    let png = concat!(env!("CARGO_MANIFEST_DIR"), "/docs/tradeoff.png");
    if let Err(e) = chart(&rows, &pareto).save_png(png) {
        eprintln!("{png}: {e}");
    } else {
        eprintln!("wrote {path} and {png}");
    }
}

fn report(rows: &[Row], base: &[f64], fill: &[(f64, u64)], pareto: &[usize]) -> String {
    let mut md = String::new();
    let names: Vec<&str> = rows[0].sets.iter().map(|s| s.0).collect();
    let mut set_names: Vec<&str> = vec![];
    for n in &names {
        if !set_names.contains(n) {
            set_names.push(n);
        }
    }
    let _ = writeln!(md, "### Accuracy (fixed scene sets)\n");
    let _ = writeln!(
        md,
        "Pixels differing from the exact rasterizer on the unsnapped triangles, as a percentage of the pixels it lights; \
         gaps and overdraw over the meshes and fans; largest triangle (px) within 1 % of exact.\n"
    );
    let _ = write!(md, "| variant | bits | all sets |");
    for n in &set_names {
        let _ = write!(md, " {n} |");
    }
    let _ = writeln!(md, " mesh gaps | mesh overdraw | largest ok |");
    let _ = writeln!(
        md,
        "|---|---|---|{}---|---|---|",
        "---|".repeat(set_names.len())
    );
    for r in rows {
        let t = r.total();
        let _ = write!(
            md,
            "| {} | {} | {:.3} % |",
            r.v.name(),
            r.p.bits(),
            r.mismatch()
        );
        for n in &set_names {
            let (mut d, mut re) = (0, 0);
            for (m, a) in &r.sets {
                if m == n {
                    d += a.differing_px;
                    re += a.reference_px;
                }
            }
            let _ = write!(md, " {:.3} % |", 100.0 * d as f64 / re.max(1) as f64);
        }
        let _ = writeln!(md, " {} | {} | {} |", t.gaps, t.overdraw, r.largest);
    }
    let _ = writeln!(
        md,
        "\n### Speed (host, medians of {REPEATS} runs, Rgb565 320 x 240)\n"
    );
    let _ = write!(md, "| variant | bits |");
    for (name, _, n) in CLASSES {
        let _ = write!(md, " {name} (x{n}) ns/tri | Mpx/s | ÷ exact | ÷ fill |");
    }
    let _ = writeln!(md);
    let _ = writeln!(md, "|---|---|{}", "---|---|---|---|".repeat(CLASSES.len()));
    let _ = write!(md, "| span fill | - |");
    for (k, (ns, px)) in fill.iter().enumerate() {
        let n = CLASSES[k].2 as f64;
        let _ = write!(
            md,
            " {:.0} | {:.0} | {:.2}x | 1.00x |",
            ns,
            *px as f64 / n / ns * 1e3,
            ns / base[k]
        );
    }
    let _ = writeln!(md);
    for r in rows {
        let _ = write!(md, "| {} | {} |", r.v.name(), r.p.bits());
        for (k, (ns, px)) in r.speed.iter().enumerate() {
            let n = CLASSES[k].2 as f64;
            let _ = write!(
                md,
                " {:.0} | {:.0} | {:.2}x | {:.2}x |",
                ns,
                *px as f64 / n / ns * 1e3,
                ns / base[k],
                ns / fill[k].0
            );
        }
        let _ = writeln!(md);
    }
    let _ = writeln!(
        md,
        "\nPareto-optimal at 32 px (no other library variant is at least as accurate and at least as fast, times within 5 % counting as equal): {}.\n",
        pareto.iter().map(|&i| format!("`{}`", rows[i].label())).collect::<Vec<_>>().join(", ")
    );
    md
}

fn colour(v: Variant) -> Rgb888 {
    match v {
        Variant::Lib(TriangleAlgorithm::EdgeExact) => Rgb888::new(0x1f, 0x77, 0xb4),
        Variant::Lib(TriangleAlgorithm::Barycentric) => Rgb888::new(0x2c, 0xa0, 0x2c),
        Variant::Lib(TriangleAlgorithm::EdgeWalk) => Rgb888::new(0xff, 0x7f, 0x0e),
        Variant::Lib(TriangleAlgorithm::BresenhamWalk) => Rgb888::new(0xd6, 0x27, 0x28),
        Variant::Seed000 => Rgb888::new(0x94, 0x67, 0xbd),
    }
}

/// Speed (x: exact time / variant time at 32 px) against accuracy (y: %
/// of pixels differing, log scale, exact at the bottom).
fn chart(rows: &[Row], pareto: &[usize]) -> SimDisplay<Rgb888> {
    let (w, h) = (720i32, 460i32);
    let mut d = SimDisplay::new(w as u32, h as u32, Rgb888::WHITE);
    let (x0, x1, y0, y1) = (70, w - 170, 30, h - 50);
    let grey = Rgb888::new(0xc0, 0xc0, 0xc0);
    let black = Rgb888::BLACK;
    let text = |d: &mut SimDisplay<Rgb888>, s: &str, p: Point, a: Alignment, c: Rgb888| {
        let _ = Text::with_alignment(s, p, MonoTextStyle::new(&FONT_6X10, c), a).draw(d);
    };
    let line = |d: &mut SimDisplay<Rgb888>, a: Point, b: Point, c: Rgb888| {
        let _ = Line::new(a, b).stroke(c).draw(d);
    };
    let exact_t = rows
        .iter()
        .find(|r| {
            r.v == Variant::Lib(TriangleAlgorithm::EdgeExact) && r.p == SubpixelPrecision::Bits12
        })
        .map_or(1.0, |r| r.speed[1].0);
    let speed = |r: &Row| exact_t / r.speed[1].0;
    let max_speed = rows.iter().map(speed).fold(1.0, f64::max) * 1.1;
    // y: 0 % at the bottom band, then 0.001 % .. 100 % on a log scale.
    let (lo, hi) = (-3.0f64, 2.0f64);
    let zero_y = y1 - 10;
    let ypos = |m: f64| -> i32 {
        if m <= 0.0 {
            zero_y
        } else {
            let f = ((m.log10() - lo) / (hi - lo)).clamp(0.0, 1.0);
            (f64::from(zero_y - 30) - f * f64::from(zero_y - 30 - y0)) as i32
        }
    };
    let xpos = |s: f64| x0 + (s / max_speed * f64::from(x1 - x0)) as i32;
    for k in 0..=((hi - lo) as i32) {
        let m = 10f64.powi(lo as i32 + k);
        let y = ypos(m);
        line(&mut d, Point::new(x0, y), Point::new(x1, y), grey);
        text(
            &mut d,
            &format!("{m}%"),
            Point::new(x0 - 4, y + 3),
            Alignment::Right,
            black,
        );
    }
    text(
        &mut d,
        "exact",
        Point::new(x0 - 4, zero_y + 3),
        Alignment::Right,
        black,
    );
    let mut s = 0.0;
    while s <= max_speed {
        let x = xpos(s);
        line(&mut d, Point::new(x, y0), Point::new(x, y1), grey);
        text(
            &mut d,
            &format!("{s:.1}x"),
            Point::new(x, y1 + 14),
            Alignment::Center,
            black,
        );
        s += 0.5;
    }
    line(&mut d, Point::new(x0, y1), Point::new(x1, y1), black);
    line(&mut d, Point::new(x0, y0), Point::new(x0, y1), black);
    text(
        &mut d,
        "speed vs the exact default (32 px triangles, host) ->",
        Point::new((x0 + x1) / 2, y1 + 30),
        Alignment::Center,
        black,
    );
    text(
        &mut d,
        "pixels differing from exact (log)",
        Point::new(x0 - 60, y0 - 14),
        Alignment::Left,
        black,
    );
    // Pareto front, in speed order.
    let mut front: Vec<Point> = pareto
        .iter()
        .map(|&i| Point::new(xpos(speed(&rows[i])), ypos(rows[i].mismatch())))
        .collect();
    front.sort_by_key(|p| p.x);
    for pair in front.windows(2) {
        line(&mut d, pair[0], pair[1], Rgb888::new(0x60, 0x60, 0x60));
    }
    // Points: a triangle per variant and precision, bigger for more bits.
    for r in rows {
        let c = Point::new(xpos(speed(r)), ypos(r.mismatch()));
        let s = 3 + r.p.bits() as i32 / 3;
        let v = |dx: i32, dy: i32| Vertex::try_from(c + Point::new(dx, dy)).unwrap_or_default();
        let _ = Triangle::new(v(0, -s), v(s, s), v(-s, s))
            .fill(colour(r.v))
            .draw(&mut d);
    }
    // Legend.
    let lx = x1 + 16;
    for (k, v) in Variant::ALL.into_iter().enumerate() {
        let y = y0 + 10 + 16 * k as i32;
        let p =
            |dx: i32, dy: i32| Vertex::try_from(Point::new(lx + dx, y + dy)).unwrap_or_default();
        let _ = Triangle::new(p(0, -5), p(5, 5), p(-5, 5))
            .fill(colour(v))
            .draw(&mut d);
        text(
            &mut d,
            v.name(),
            Point::new(lx + 10, y + 4),
            Alignment::Left,
            black,
        );
    }
    let ly = y0 + 10 + 16 * 5 + 8;
    text(
        &mut d,
        "size = subpixel bits",
        Point::new(lx - 5, ly),
        Alignment::Left,
        black,
    );
    text(
        &mut d,
        "(0, 4, 8, 12)",
        Point::new(lx - 5, ly + 12),
        Alignment::Left,
        black,
    );
    text(
        &mut d,
        "line = Pareto front",
        Point::new(lx - 5, ly + 28),
        Alignment::Left,
        black,
    );
    d
}
