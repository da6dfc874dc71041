//! Band firmware: the built-in scene of `firmware` (the same commands,
//! `examples/common/builtin_scene.rs`) recorded in a display list and
//! rendered at 320 x 240 Rgb565 in bands of 16 rows through one 10 KiB
//! band buffer, on a Cortex-M whose memory map gives it 32 KiB of RAM in
//! all (`memory-32k.x`). It prints the FNV-1a checksum of the bands'
//! bytes in order, which is the checksum of the whole frame: the same
//! line as `firmware`. It also reports how deep its stack went, sampled
//! on every write the shapes make.
//!
//! ```sh
//! cargo run --release --target thumbv7em-none-eabihf --example firmware_bands --features firmware-32k
//! ```

#![cfg_attr(target_arch = "arm", no_std, no_main)]

#[path = "common/builtin_scene.rs"]
mod builtin_scene;

#[cfg(target_arch = "arm")]
#[path = "common/semihosting.rs"]
mod semihosting;

use embedded_graphics_core::{
    draw_target::DrawTarget,
    geometry::{Dimensions, OriginDimensions, Point, Size},
    pixelcolor::Rgb565,
    primitives::Rectangle,
    Pixel,
};
use embedded_raster::{
    band::{DisplayList, RenderError},
    framebuffer::{buffer_size, Rgb565Le},
    line::LinePixels,
    Framebuffer, Span, SpanSink,
};

use builtin_scene::{SceneShapes, HEIGHT, WIDTH};

/// The line both `firmware` and this print.
#[cfg_attr(not(target_arch = "arm"), allow(dead_code))]
const REPORT: &str = "scene 320x240 rgb565le fnv1a32=";

/// Rows per band.
const ROWS: usize = 16;

/// The band buffer: 320 x 16 Rgb565, 10 240 bytes.
type BandBuffer = Framebuffer<Rgb565Le, WIDTH, ROWS, { buffer_size::<Rgb565Le>(WIDTH, ROWS) }>;

/// Room for the scene's 284 commands.
type SceneList<'a> = DisplayList<'a, Rgb565, 288, 12>;

/// The lowest stack pointer seen: the stack's deepest point.
#[cfg(target_arch = "arm")]
fn stack_pointer() -> u32 {
    cortex_m::register::msp::read()
}

#[cfg(not(target_arch = "arm"))]
fn stack_pointer() -> u32 {
    u32::MAX
}

/// The band buffer, sampling the stack pointer on every write: the
/// shapes write from their innermost loops, so the lowest sample is
/// (within one call) the deepest the drawing goes.
struct Probe {
    buffer: BandBuffer,
    lowest: u32,
}

impl Probe {
    fn sample(&mut self) {
        self.lowest = self.lowest.min(stack_pointer());
    }
}

impl OriginDimensions for Probe {
    fn size(&self) -> Size {
        self.buffer.size()
    }
}

impl DrawTarget for Probe {
    type Color = Rgb565;
    type Error = core::convert::Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Self::Error> {
        self.sample();
        self.buffer.draw_iter(pixels)
    }

    fn fill_contiguous<I: IntoIterator<Item = Rgb565>>(
        &mut self,
        area: &Rectangle,
        colors: I,
    ) -> Result<(), Self::Error> {
        self.sample();
        self.buffer.fill_contiguous(area, colors)
    }

    fn fill_solid(&mut self, area: &Rectangle, color: Rgb565) -> Result<(), Self::Error> {
        self.sample();
        self.buffer.fill_solid(area, color)
    }
}

impl SpanSink<Rgb565> for Probe {
    type Error = core::convert::Infallible;

    fn bounds(&self) -> Rectangle {
        self.buffer.bounding_box()
    }

    fn fill_span(&mut self, span: Span, color: Rgb565) -> Result<(), Self::Error> {
        self.sample();
        self.buffer.fill_span(span, color)
    }

    fn fill_column(&mut self, top: Point, len: u32, color: Rgb565) -> Result<(), Self::Error> {
        self.sample();
        self.buffer.fill_column(top, len, color)
    }

    fn fill_rect(&mut self, area: &Rectangle, color: Rgb565) -> Result<(), Self::Error> {
        self.sample();
        self.buffer.fill_rect(area, color)
    }

    fn fill_line(&mut self, pixels: LinePixels, color: Rgb565) -> Result<(), Self::Error> {
        self.sample();
        self.buffer.fill_line(pixels, color)
    }
}

/// Records the scene in `list` and renders it in bands through `probe`,
/// each finished band hashed; returns the frame's checksum, or `None` if
/// the scene did not fit the list.
fn render<'a>(shapes: &'a SceneShapes, list: &mut SceneList<'a>, probe: &mut Probe) -> Option<u32> {
    list.clear();
    builtin_scene::for_each_command(shapes, |command| list.push(command)).ok()?;
    let mut hash = builtin_scene::FNV1A32_START;
    let row_bytes = probe.buffer.as_bytes().len() / ROWS;
    let mut output = |band: &Probe, area: Rectangle| {
        // The band's rows, in screen order: the frame's bytes in turn.
        let used = row_bytes * area.size.height as usize;
        hash = builtin_scene::fnv1a32_more(hash, &band.buffer.as_bytes()[..used]);
        Ok::<(), core::convert::Infallible>(())
    };
    let buffers = core::slice::from_mut(probe);
    match list.render_bands(HEIGHT as u32, buffers, None, &mut output) {
        Ok(()) => Some(hash),
        // One buffer of `ROWS` rows: never.
        Err(RenderError::NoRows | RenderError::WidthsDiffer) => None,
        Err(RenderError::Draw(e) | RenderError::Flush(e)) => match e {},
    }
}

#[cfg(target_arch = "arm")]
mod target {
    use cortex_m_rt::entry;
    use cortex_m_semihosting::hprintln;

    use super::{BandBuffer, Probe, SceneList, SceneShapes};

    #[entry]
    fn main() -> ! {
        // cortex-m-rt makes these `&'static mut` (in .bss): no unsafe.
        static mut BAND: Probe = Probe {
            buffer: BandBuffer::new(),
            lowest: 0, // all zero: in .bss, not copied from flash
        };
        static mut LIST: SceneList<'static> = SceneList::new();
        static mut SHAPES: Option<SceneShapes> = None;
        BAND.lowest = u32::MAX;
        let top = super::stack_pointer();
        let shapes: &'static SceneShapes = SHAPES.insert(SceneShapes::new());
        match super::render(shapes, LIST, BAND) {
            Some(checksum) => hprintln!("{}0x{:08x}", super::REPORT, checksum),
            None => panic!("the scene does not fit the display list"),
        }
        // `main`'s own frame is above `top`: a few words more.
        hprintln!(
            "stack used below main: {} bytes",
            top.saturating_sub(BAND.lowest)
        );
        super::semihosting::exit_success()
    }
}

/// On the host: the same rendering, the same line.
#[cfg(not(target_arch = "arm"))]
fn main() {
    let shapes = SceneShapes::new();
    let mut list = Box::new(SceneList::new());
    let mut probe = Box::new(Probe {
        buffer: BandBuffer::new(),
        lowest: u32::MAX,
    });
    let checksum = render(&shapes, &mut list, &mut probe).expect("the scene fits the list");
    println!("{REPORT}0x{checksum:08x}");
}
