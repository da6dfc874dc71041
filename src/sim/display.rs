//! [`SimDisplay`]: an in-memory display that counts every write.

use std::io::{self, Write};
use std::path::Path;
use std::prelude::rust_2021::*;
use std::vec;

use embedded_graphics_core::{
    draw_target::DrawTarget,
    geometry::{Dimensions, OriginDimensions, Point, Size},
    image::GetPixel,
    pixelcolor::{PixelColor, Rgb888, RgbColor},
    primitives::Rectangle,
    Pixel,
};

use crate::clip::{advance, clip_to, Bounds};
use crate::raster::sink::SpanSink;
use crate::span::Span;

/// An in-memory [`DrawTarget`] of any size and colour type that records how
/// it was drawn on.
///
/// Besides the pixels themselves it keeps
///
/// - a write count per pixel (saturating at `u32::MAX`), to check for
///   overdraw and gaps: [`write_count`](Self::write_count);
/// - the number of writes that fell outside the display, which are counted
///   and dropped: [`out_of_bounds_writes`](Self::out_of_bounds_writes). A
///   rasterizer that clips before it draws never makes one;
/// - how the pixels arrived, per [`DrawTarget`] method: [`WriteStats`].
///
/// A new display starts with every pixel set to its background colour and
/// every count at zero: the background is not a write. [`clear`] is a
/// write of every pixel.
///
/// [`clear`]: DrawTarget::clear
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::Rgb888, prelude::*, primitives::Rectangle};
/// use embedded_raster::sim::SimDisplay;
///
/// let mut display = SimDisplay::new(8, 4, Rgb888::BLACK);
/// let area = Rectangle::new(Point::new(6, 1), Size::new(4, 2));
/// display.fill_solid(&area, Rgb888::RED)?;
///
/// assert_eq!(display.pixel(Point::new(7, 2)), Some(Rgb888::RED));
/// assert_eq!(display.write_count(Point::new(7, 2)), Some(1));
/// assert_eq!(display.pixels_written(), 4); // columns 6 and 7 of rows 1 and 2
/// assert_eq!(display.out_of_bounds_writes(), 4); // columns 8 and 9
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SimDisplay<C> {
    size: Size,
    pixels: Vec<C>,
    counts: Vec<u32>,
    stats: WriteStats,
    out_of_bounds: u64,
}

/// How the pixels sent to a [`SimDisplay`] arrived, since it was made or
/// last [reset](SimDisplay::reset_counts).
///
/// The `*_pixels` fields count every pixel a method was asked to write,
/// inside the display or not, saturating at `u64::MAX`.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::Gray8, prelude::*, primitives::Rectangle};
/// use embedded_raster::sim::SimDisplay;
///
/// let mut display = SimDisplay::new(4, 4, Gray8::BLACK);
/// display.fill_solid(&Rectangle::new(Point::zero(), Size::new(3, 1)), Gray8::WHITE)?;
/// display.draw_iter([Pixel(Point::new(0, 3), Gray8::WHITE)])?;
///
/// let stats = display.write_stats();
/// assert_eq!((stats.fill_solid_calls, stats.fill_solid_pixels), (1, 3));
/// assert_eq!(stats.draw_iter_pixels, 1);
/// assert_eq!(stats.fill_contiguous_pixels, 0);
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct WriteStats {
    /// Pixels passed to [`DrawTarget::draw_iter`].
    pub draw_iter_pixels: u64,
    /// Calls to [`DrawTarget::fill_solid`], including empty rectangles.
    pub fill_solid_calls: u64,
    /// Pixels in the rectangles passed to [`DrawTarget::fill_solid`].
    pub fill_solid_pixels: u64,
    /// Calls to [`DrawTarget::fill_contiguous`].
    pub fill_contiguous_calls: u64,
    /// Pixels in the rectangles passed to [`DrawTarget::fill_contiguous`].
    pub fill_contiguous_pixels: u64,
    /// Calls to [`DrawTarget::clear`]; each writes every pixel once and is
    /// not counted as a `fill_solid` call.
    pub clear_calls: u64,
}

impl<C: PixelColor> SimDisplay<C> {
    /// Creates a `width` x `height` display with every pixel set to
    /// `background` and every write count at zero.
    ///
    /// # Panics
    ///
    /// If `width * height` pixels do not fit in memory (allocation failure
    /// may abort instead).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::BinaryColor, prelude::*};
    /// use embedded_raster::sim::SimDisplay;
    ///
    /// let display = SimDisplay::new(128, 64, BinaryColor::Off);
    /// assert_eq!(display.size(), Size::new(128, 64));
    /// assert_eq!(display.pixel(Point::new(127, 63)), Some(BinaryColor::Off));
    /// assert_eq!(display.pixels_written(), 0);
    /// ```
    pub fn new(width: u32, height: u32, background: C) -> Self {
        let len = usize::try_from(u64::from(width) * u64::from(height))
            .expect("SimDisplay: width * height does not fit in memory");
        Self {
            size: Size::new(width, height),
            pixels: vec![background; len],
            counts: vec![0; len],
            stats: WriteStats::default(),
            out_of_bounds: 0,
        }
    }

    /// The colour of pixel `p`, or `None` if `p` is outside the display.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
    /// use embedded_raster::sim::SimDisplay;
    ///
    /// let mut display = SimDisplay::new(2, 2, Rgb565::BLACK);
    /// display.draw_iter([Pixel(Point::new(1, 0), Rgb565::GREEN)])?;
    /// assert_eq!(display.pixel(Point::new(1, 0)), Some(Rgb565::GREEN));
    /// assert_eq!(display.pixel(Point::new(2, 0)), None);
    /// # Ok::<(), core::convert::Infallible>(())
    /// ```
    pub fn pixel(&self, p: Point) -> Option<C> {
        self.index(p).map(|i| self.pixels[i])
    }

    /// How many times pixel `p` was written (saturating at `u32::MAX`), or
    /// `None` if `p` is outside the display.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
    /// use embedded_raster::sim::SimDisplay;
    ///
    /// let mut display = SimDisplay::new(3, 3, Gray8::BLACK);
    /// display.clear(Gray8::WHITE)?;
    /// display.draw_iter([Pixel(Point::new(1, 1), Gray8::BLACK)])?;
    /// assert_eq!(display.write_count(Point::new(1, 1)), Some(2));
    /// assert_eq!(display.write_count(Point::new(0, 0)), Some(1));
    /// assert_eq!(display.write_count(Point::new(-1, 0)), None);
    /// # Ok::<(), core::convert::Infallible>(())
    /// ```
    pub fn write_count(&self, p: Point) -> Option<u32> {
        self.index(p).map(|i| self.counts[i])
    }

    /// Every pixel, row by row from the top left.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use embedded_raster::sim::SimDisplay;
    ///
    /// let display = SimDisplay::new(3, 2, BinaryColor::On);
    /// assert_eq!(display.pixels(), &[BinaryColor::On; 6]);
    /// ```
    pub fn pixels(&self) -> &[C] {
        &self.pixels
    }

    /// Every pixel's write count, row by row from the top left.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::BinaryColor, prelude::*};
    /// use embedded_raster::sim::SimDisplay;
    ///
    /// let mut display = SimDisplay::new(2, 2, BinaryColor::Off);
    /// display.draw_iter([Pixel(Point::new(1, 1), BinaryColor::On)])?;
    /// assert_eq!(display.counts(), &[0, 0, 0, 1]);
    /// # Ok::<(), core::convert::Infallible>(())
    /// ```
    pub fn counts(&self) -> &[u32] {
        &self.counts
    }

    /// Total number of pixel writes inside the display (the sum of all write
    /// counts, without saturation).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
    /// use embedded_raster::sim::SimDisplay;
    ///
    /// let mut display = SimDisplay::new(4, 4, Gray8::BLACK);
    /// display.clear(Gray8::WHITE)?;
    /// display.clear(Gray8::BLACK)?;
    /// assert_eq!(display.pixels_written(), 32);
    /// # Ok::<(), core::convert::Infallible>(())
    /// ```
    pub fn pixels_written(&self) -> u64 {
        self.counts.iter().map(|&c| u64::from(c)).sum()
    }

    /// Number of pixel writes that fell outside the display and were
    /// dropped (saturating at `u64::MAX`).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
    /// use embedded_raster::sim::SimDisplay;
    ///
    /// let mut display = SimDisplay::new(4, 4, Gray8::BLACK);
    /// display.draw_iter([Pixel(Point::new(4, 0), Gray8::WHITE)])?;
    /// assert_eq!(display.out_of_bounds_writes(), 1);
    /// assert_eq!(display.pixels_written(), 0);
    /// # Ok::<(), core::convert::Infallible>(())
    /// ```
    pub fn out_of_bounds_writes(&self) -> u64 {
        self.out_of_bounds
    }

    /// How the pixels arrived, per [`DrawTarget`] method.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*, primitives::Rectangle};
    /// use embedded_raster::sim::SimDisplay;
    ///
    /// let mut display = SimDisplay::new(4, 4, Gray8::BLACK);
    /// let area = Rectangle::new(Point::zero(), Size::new(2, 2));
    /// display.fill_contiguous(&area, [Gray8::WHITE; 4])?;
    /// assert_eq!(display.write_stats().fill_contiguous_pixels, 4);
    /// assert_eq!(display.write_stats().fill_solid_calls, 0);
    /// # Ok::<(), core::convert::Infallible>(())
    /// ```
    pub fn write_stats(&self) -> WriteStats {
        self.stats
    }

    /// Sets every write count, the out-of-bounds count and the
    /// [`WriteStats`] back to zero, keeping the pixels.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
    /// use embedded_raster::sim::SimDisplay;
    ///
    /// let mut display = SimDisplay::new(4, 4, Gray8::BLACK);
    /// display.clear(Gray8::WHITE)?;
    /// display.reset_counts();
    /// assert_eq!(display.pixels_written(), 0);
    /// assert_eq!(display.write_stats().clear_calls, 0);
    /// assert_eq!(display.pixel(Point::zero()), Some(Gray8::WHITE));
    /// # Ok::<(), core::convert::Infallible>(())
    /// ```
    pub fn reset_counts(&mut self) {
        self.counts.fill(0);
        self.stats = WriteStats::default();
        self.out_of_bounds = 0;
    }

    /// Copies `rows` rows of `band` into this display's rows from `top`
    /// down, counting as writes the growth of `band`'s counts since `seen`
    /// (its counts when last pasted, updated here) and taking `background`
    /// for pixels not written since: so one band buffer can be reused for
    /// every band without clearing it. Rows outside either display are
    /// skipped. How a band renderer's output is assembled.
    pub(crate) fn paste_rows(
        &mut self,
        band: &SimDisplay<C>,
        (top, rows): (i32, u32),
        seen: &mut [u32],
        background: C,
    ) where
        C: Copy,
    {
        let width = self.size.width.min(band.size.width) as usize;
        for r in 0..rows.min(band.size.height) {
            let Some(y) = top
                .checked_add_unsigned(r)
                .and_then(|y| u32::try_from(y).ok())
            else {
                continue;
            };
            if y >= self.size.height {
                break;
            }
            // Both rows exist: the indices are in the vectors.
            let from = r as usize * band.size.width as usize;
            let to = y as usize * self.size.width as usize;
            let source = band.pixels[from..from + width].iter();
            let totals = band.counts[from..from + width].iter();
            let before = seen.iter_mut().skip(from);
            let pixels = self.pixels[to..to + width].iter_mut();
            let counts = self.counts[to..to + width].iter_mut();
            for ((((pixel, count), &color), &total), before) in
                pixels.zip(counts).zip(source).zip(totals).zip(before)
            {
                // Counts only grow (saturating), so the difference is >= 0.
                *count = total.saturating_sub(*before);
                *pixel = if *count > 0 { color } else { background };
                *before = total;
            }
        }
    }

    /// Writes the write counts as a binary PGM image (`P5`, maxval 255):
    /// the header `P5\nW H\n255\n`, then one byte per pixel, row by row,
    /// each count saturating at 255.
    ///
    /// # Errors
    ///
    /// Any error of `w`.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
    /// use embedded_raster::sim::SimDisplay;
    ///
    /// let mut display = SimDisplay::new(3, 1, Gray8::BLACK);
    /// display.draw_iter([Pixel(Point::new(2, 0), Gray8::WHITE)])?;
    /// let mut pgm = Vec::new();
    /// display.write_counts_pgm(&mut pgm)?;
    /// assert_eq!(pgm, b"P5\n3 1\n255\n\x00\x00\x01");
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn write_counts_pgm<W: Write>(&self, mut w: W) -> io::Result<()> {
        let header = std::format!("P5\n{} {}\n255\n", self.size.width, self.size.height);
        let bytes: Vec<u8> = header
            .into_bytes()
            .into_iter()
            .chain(self.counts.iter().map(|&c| c.min(255) as u8))
            .collect();
        w.write_all(&bytes)?;
        w.flush()
    }

    fn index(&self, p: Point) -> Option<usize> {
        let x = u32::try_from(p.x).ok().filter(|&x| x < self.size.width)?;
        let y = u32::try_from(p.y).ok().filter(|&y| y < self.size.height)?;
        usize::try_from(u64::from(y) * u64::from(self.size.width) + u64::from(x)).ok()
    }
}

impl<C: PixelColor + Into<Rgb888>> SimDisplay<C> {
    /// Writes the display as an 8-bit RGB PNG image, converting each pixel
    /// to [`Rgb888`] (`Rgb565`, `Gray8`, `BinaryColor` and the other
    /// `embedded-graphics` colour types all convert).
    ///
    /// # Errors
    ///
    /// Any error of `w`; an encoder error becomes an
    /// [`io::ErrorKind::Other`] error.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
    /// use embedded_raster::sim::SimDisplay;
    ///
    /// let display = SimDisplay::new(16, 8, Rgb565::BLUE);
    /// let mut png = Vec::new();
    /// display.write_png(&mut png)?;
    /// assert_eq!(&png[1..4], b"PNG");
    /// # Ok::<(), std::io::Error>(())
    /// ```
    pub fn write_png<W: Write>(&self, w: W) -> io::Result<()> {
        write_rgb_png(w, self.size, self.pixels.iter().map(|&c| c.into()))
    }

    /// Saves the display as an 8-bit RGB PNG file at `path`; see
    /// [`write_png`](Self::write_png).
    ///
    /// # Errors
    ///
    /// If the file cannot be created or written.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
    /// use embedded_raster::sim::SimDisplay;
    ///
    /// let path = std::env::temp_dir().join(format!("sim-doc-{}.png", std::process::id()));
    /// SimDisplay::new(4, 4, Gray8::WHITE).save_png(&path)?;
    /// assert!(std::fs::metadata(&path)?.len() > 0);
    /// std::fs::remove_file(&path)?;
    /// # Ok::<(), std::io::Error>(())
    /// ```
    pub fn save_png<P: AsRef<Path>>(&self, path: P) -> io::Result<()> {
        save_to(path.as_ref(), |w| self.write_png(w))
    }
}

/// Encodes `size.width * size.height` pixels, row by row, as an 8-bit RGB
/// PNG.
pub(crate) fn write_rgb_png<W: Write>(
    w: W,
    size: Size,
    pixels: impl Iterator<Item = Rgb888>,
) -> io::Result<()> {
    let mut encoder = png::Encoder::new(w, size.width, size.height);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    let data: Vec<u8> = pixels.flat_map(|c| [c.r(), c.g(), c.b()]).collect();
    let mut writer = encoder.write_header().map_err(png_error)?;
    writer.write_image_data(&data).map_err(png_error)?;
    writer.finish().map_err(png_error)
}

/// Creates the file at `path` and has `write` fill it through a buffer.
pub(crate) fn save_to(
    path: &Path,
    write: impl FnOnce(&mut io::BufWriter<std::fs::File>) -> io::Result<()>,
) -> io::Result<()> {
    let mut w = io::BufWriter::new(std::fs::File::create(path)?);
    write(&mut w)?;
    w.flush()
}

fn png_error(e: png::EncodingError) -> io::Error {
    match e {
        png::EncodingError::IoError(e) => e,
        other => io::Error::other(other),
    }
}

impl<C> OriginDimensions for SimDisplay<C> {
    fn size(&self) -> Size {
        self.size
    }
}

impl<C: PixelColor> SimDisplay<C> {
    /// Writes `color` to the pixels `x_range` of row `y` (all inside).
    fn write_row(&mut self, y: usize, x_range: core::ops::Range<usize>, color: C) {
        let start = y * self.size.width as usize;
        let range = start + x_range.start..start + x_range.end;
        self.pixels[range.clone()].fill(color);
        for count in &mut self.counts[range] {
            *count = count.saturating_add(1);
        }
    }

    /// Writes `color` to the pixel at index `i` (inside).
    fn put(&mut self, i: usize, color: C) {
        self.pixels[i] = color;
        self.counts[i] = self.counts[i].saturating_add(1);
    }

    fn add_out_of_bounds(&mut self, n: u64) {
        self.out_of_bounds = self.out_of_bounds.saturating_add(n);
    }
}

/// Number of pixels in `area`, which is at most `(2^32 - 1)^2 < 2^64`.
fn area_pixels(area: &Rectangle) -> u64 {
    u64::from(area.size.width) * u64::from(area.size.height)
}

/// Spans as one `fill_solid` each (counted as such in [`WriteStats`]), so
/// that band renderers can draw on a display.
impl<C: PixelColor> SpanSink<C> for SimDisplay<C> {
    type Error = core::convert::Infallible;

    fn bounds(&self) -> Rectangle {
        self.bounding_box()
    }

    fn fill_span(&mut self, span: Span, color: C) -> Result<(), Self::Error> {
        self.fill_solid(&span.rect(), color)
    }
}

/// [`SimDisplay::pixel`], for code written against embedded-graphics'
/// image traits (such as [`WriteTo`](crate::band::WriteTo)).
impl<C: PixelColor> GetPixel for SimDisplay<C> {
    type Color = C;

    fn pixel(&self, p: Point) -> Option<C> {
        SimDisplay::pixel(self, p)
    }
}

impl<C: PixelColor> DrawTarget for SimDisplay<C> {
    type Color = C;
    type Error = core::convert::Infallible;

    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = Pixel<C>>,
    {
        for Pixel(p, color) in pixels {
            self.stats.draw_iter_pixels = self.stats.draw_iter_pixels.saturating_add(1);
            match self.index(p) {
                Some(i) => self.put(i, color),
                None => self.add_out_of_bounds(1),
            }
        }
        Ok(())
    }

    /// Consumes colours up to the last pixel inside the display only; the
    /// pixels of `area` outside the display count as out-of-bounds writes
    /// whether or not `colors` reaches them.
    fn fill_contiguous<I>(&mut self, area: &Rectangle, colors: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = C>,
    {
        let total = area_pixels(area);
        self.stats.fill_contiguous_calls = self.stats.fill_contiguous_calls.saturating_add(1);
        self.stats.fill_contiguous_pixels = self.stats.fill_contiguous_pixels.saturating_add(total);
        let area_b = Bounds::of(area);
        let Some(visible) = area_b.intersect(Bounds::of(&self.bounding_box())) else {
            self.add_out_of_bounds(total);
            return Ok(());
        };
        let inside = (visible.x1 - visible.x0) as u64 * (visible.y1 - visible.y0) as u64;
        self.add_out_of_bounds(total - inside);

        // `visible` lies inside both `area` and the display (whose top left
        // is the origin): the offsets below are in `0..=u32::MAX` and the
        // coordinates are display indices.
        let width = u64::from(area.size.width);
        let left = (visible.x0 - area_b.x0) as u64;
        let right = (area_b.x1 - visible.x1) as u64;
        let mut colors = colors.into_iter();
        if !advance(&mut colors, (visible.y0 - area_b.y0) as u64 * width) {
            return Ok(());
        }
        for y in visible.y0..visible.y1 {
            if !advance(&mut colors, left) {
                return Ok(());
            }
            // Inside the display: `y * width + x` fits in `usize`.
            let row = y as usize * self.size.width as usize;
            for x in visible.x0..visible.x1 {
                let Some(color) = colors.next() else {
                    return Ok(());
                };
                self.put(row + x as usize, color);
            }
            if y + 1 < visible.y1 && !advance(&mut colors, right) {
                return Ok(());
            }
        }
        Ok(())
    }

    fn fill_solid(&mut self, area: &Rectangle, color: C) -> Result<(), Self::Error> {
        let total = area_pixels(area);
        self.stats.fill_solid_calls = self.stats.fill_solid_calls.saturating_add(1);
        self.stats.fill_solid_pixels = self.stats.fill_solid_pixels.saturating_add(total);
        let Some((xs, ys)) = clip_to(area, &self.bounding_box()) else {
            self.add_out_of_bounds(total);
            return Ok(());
        };
        self.add_out_of_bounds(total - (xs.len() as u64 * ys.len() as u64));
        for y in ys {
            self.write_row(y, xs.clone(), color);
        }
        Ok(())
    }

    fn clear(&mut self, color: C) -> Result<(), Self::Error> {
        self.stats.clear_calls = self.stats.clear_calls.saturating_add(1);
        self.pixels.fill(color);
        for count in &mut self.counts {
            *count = count.saturating_add(1);
        }
        Ok(())
    }
}
