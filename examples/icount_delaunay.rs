//! Firmware: instructions to triangulate 100 and 1,000 points (and two
//! grids) on the Cortex-M4, the point sets of `benches/delaunay.rs`.
//!
//! Run: `bash .ci/icount_delaunay`. It builds this example for
//! `thumbv7em-none-eabihf`, runs it twice under QEMU (`mps2-an386`) with
//! `-icount shift=7`, checks that both runs agree and that every
//! triangulation matches the host's (the same example run on the host
//! prints the same rows without counts), and prints a Markdown table.
//!
//! # The counter
//!
//! Under `-icount shift=7` each instruction takes 128 ns of virtual time
//! and SysTick counts the 25 MHz clock: 3.2 ticks an instruction, so
//! `round(ticks / 3.2)` is the instruction count (`examples/icount.rs`
//! validates this on a loop of known length). A triangulation can outlast
//! SysTick's 24 bits (5.2 M instructions), so the SysTick exception counts
//! wraps; its handler's few instructions per wrap (one wrap per 5.2 M) are
//! included in the counts.

#![cfg_attr(target_arch = "arm", no_std, no_main)]

#[cfg(target_arch = "arm")]
#[path = "common/semihosting.rs"]
mod semihosting;

#[path = "common/delaunay_sets.rs"]
mod sets;

#[cfg(target_arch = "arm")]
mod target {
    use core::hint::black_box;
    use core::sync::atomic::{AtomicU32, Ordering::Relaxed};

    use cortex_m::peripheral::{syst::SystClkSource, SYST};
    use cortex_m_rt::{entry, exception};
    use cortex_m_semihosting::hprintln;
    use embedded_raster::{delaunay::Delaunay, Vertex};

    use super::sets::{self, MAX, SETS};

    /// SysTick wraps since the measurement started.
    static WRAPS: AtomicU32 = AtomicU32::new(0);

    #[exception]
    fn SysTick() {
        // Load and store: ARMv6-M has no atomic read-modify-write.
        WRAPS.store(WRAPS.load(Relaxed) + 1, Relaxed);
    }

    /// SysTick ticks spent in `f`, wraps included.
    fn ticks(syst: &mut SYST, f: &mut dyn FnMut()) -> u64 {
        // Restart from the reload value: no wrap for 2^24 ticks.
        syst.clear_current();
        cortex_m::asm::delay(4);
        WRAPS.store(0, Relaxed);
        let t0 = SYST::get_current();
        f();
        // The wrap count and the counter, read without a wrap between.
        let (wraps, t1) = loop {
            let wraps = WRAPS.load(Relaxed);
            let t1 = SYST::get_current();
            if WRAPS.load(Relaxed) == wraps {
                break (u64::from(wraps), t1);
            }
        };
        (wraps << 24) + u64::from(t0) - u64::from(t1)
    }

    /// `round(ticks / 3.2)`.
    fn instructions(ticks: u64) -> u64 {
        (ticks * 10 + 16) / 32
    }

    #[entry]
    fn main() -> ! {
        static mut DELAUNAY: Delaunay<MAX> = Delaunay::new();
        static mut POINTS: [Vertex; MAX] = [Vertex::from_raw(0, 0); MAX];
        let mut syst = cortex_m::Peripherals::take().expect("peripherals").SYST;
        syst.set_clock_source(SystClkSource::Core);
        syst.set_reload(0x00FF_FFFF);
        syst.clear_current();
        syst.enable_interrupt();
        syst.enable_counter();
        let overhead = ticks(&mut syst, &mut || {});
        // Check the wrap counting on a loop of known length, longer than
        // one wrap: delay(n) runs n + 1 iterations of two instructions.
        let looped = ticks(&mut syst, &mut || {
            cortex_m::asm::delay(black_box(3_000_000))
        });
        let looped = instructions(looped - overhead);
        hprintln!(
            "validate\tdelay(3000000)={}\texpected={}",
            looped,
            6_000_002
        );
        assert!(
            (6_000_002..6_000_002 + 64).contains(&looped),
            "counter is off"
        );
        for set in SETS {
            let n = sets::fill(set, POINTS);
            let points = &POINTS[..n];
            let spent = ticks(&mut syst, &mut || {
                black_box(DELAUNAY.triangulate(black_box(points)).map(|m| m.len())).ok();
            });
            let mesh = DELAUNAY.triangulation(points);
            hprintln!(
                "row\t{}\t{}\t{}\t{:#010x}\t{}",
                set.0,
                n,
                mesh.len(),
                sets::fnv1a(mesh.indices()),
                instructions(spent - overhead)
            );
        }
        hprintln!("done");
        super::semihosting::exit_success()
    }
}

#[cfg(not(target_arch = "arm"))]
fn main() {
    use embedded_raster::{delaunay::Delaunay, Vertex};
    use sets::{MAX, SETS};

    // The same rows as the firmware, without instruction counts.
    let mut delaunay = Box::new(Delaunay::<MAX>::new());
    let mut points = Box::new([Vertex::from_raw(0, 0); MAX]);
    for set in SETS {
        let n = sets::fill(set, &mut points);
        let mesh = delaunay.triangulate(&points[..n]).expect("within capacity");
        let hash = sets::fnv1a(mesh.indices());
        println!("row\t{}\t{n}\t{}\t{hash:#010x}", set.0, mesh.len());
    }
}
