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
        use embedded_graphics_core::{prelude::*, primitives::Rectangle};
        let r = Rectangle::new(Point::new(3, 5), Size::new(200, 200));
        let _ = FB.fill_solid(black_box(&r), Rgb565::new(0, 40, 31));
        super::semihosting::exit_success()
    }
}
#[cfg(not(target_arch = "arm"))]
fn main() {}
