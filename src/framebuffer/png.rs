//! PNG output of a [`Framebuffer`] (feature `sim`), to look at what was
//! drawn or compare it in tests.

use std::io::{self, Write};
use std::path::Path;

use embedded_graphics_core::{
    geometry::{OriginDimensions, Point},
    pixelcolor::Rgb888,
};

use super::{Framebuffer, PixelFormat};
use crate::sim::display::{save_to, write_rgb_png};

impl<F: PixelFormat, const W: usize, const H: usize, const N: usize> Framebuffer<F, W, H, N>
where
    F::Color: Into<Rgb888>,
{
    /// Writes the framebuffer as an 8-bit RGB PNG, each pixel converted to
    /// [`Rgb888`] as embedded-graphics converts colours.
    ///
    /// # Errors
    ///
    /// Errors of `w`, and encoder errors as [`io::ErrorKind::Other`].
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
    /// use embedded_raster::{framebuffer::{buffer_size, Rgb565Le}, Framebuffer};
    ///
    /// let mut fb = Framebuffer::<Rgb565Le, 8, 4, { buffer_size::<Rgb565Le>(8, 4) }>::new();
    /// fb.clear(Rgb565::BLUE)?;
    /// let mut png = Vec::new();
    /// fb.write_png(&mut png)?;
    /// assert_eq!(&png[1..4], b"PNG");
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn write_png<Out: Write>(&self, w: Out) -> io::Result<()> {
        let size = self.size();
        let pixels = (0..H).flat_map(|y| (0..W).map(move |x| (x, y)));
        let colors = pixels.map(|(x, y)| {
            let at = |n: usize| i32::try_from(n).unwrap_or(i32::MAX);
            // Every (x, y) is inside: `pixel` is `Some`.
            self.pixel(Point::new(at(x), at(y)))
                .map_or(Rgb888::new(0, 0, 0), Into::into)
        });
        write_rgb_png(w, size, colors)
    }

    /// Saves the framebuffer as an 8-bit RGB PNG file at `path`; see
    /// [`write_png`](Self::write_png).
    ///
    /// # Errors
    ///
    /// If the file cannot be created or written.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::BinaryColor, prelude::*};
    /// use embedded_raster::{framebuffer::{buffer_size, BinaryMsb}, Framebuffer};
    ///
    /// let mut fb = Framebuffer::<BinaryMsb, 16, 8, { buffer_size::<BinaryMsb>(16, 8) }>::new();
    /// fb.clear(BinaryColor::On)?;
    /// let path = std::env::temp_dir().join(format!("fb-doc-{}.png", std::process::id()));
    /// fb.save_png(&path)?;
    /// assert!(std::fs::metadata(&path)?.len() > 0);
    /// std::fs::remove_file(&path)?;
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn save_png<P: AsRef<Path>>(&self, path: P) -> io::Result<()> {
        save_to(path.as_ref(), |w| self.write_png(w))
    }
}
