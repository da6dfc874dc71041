#![cfg_attr(target_arch = "arm", no_std, no_main)]
#[cfg(target_arch = "arm")]
#[path = "common/builtin_scene.rs"]
mod builtin_scene;
#[cfg(target_arch = "arm")]
#[path = "common/semihosting.rs"]
mod semihosting;
#[cfg(target_arch = "arm")]
mod target {
    use super::builtin_scene::{self, SceneBuffer};
    use core::hint::black_box;
    use cortex_m_rt::entry;
    use embedded_graphics_core::pixelcolor::Rgb565;
    use embedded_raster::SpanDrawable;
    #[entry]
    fn main() -> ! {
        static mut FB: SceneBuffer = SceneBuffer::new();
        use embedded_graphics_core::prelude::*;
        let l = embedded_raster::Line::new(Point::new(60, 20), Point::new(260, 220));
        let _ = black_box(l).stroke(Rgb565::new(0, 40, 31)).draw_spans(FB);
        super::semihosting::exit_success()
    }
}
#[cfg(not(target_arch = "arm"))]
fn main() {}
