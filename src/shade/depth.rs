//! The depth test: interpolated `u16` depth against a caller's buffer.

use core::cell::Cell;

use embedded_graphics_core::{
    draw_target::DrawTarget,
    geometry::{Point, Size},
    primitives::Rectangle,
    Drawable,
};

use super::{
    offset, shaded_spans, whole, Frame, GouraudSetup, GouraudTriangle, Linear, ShadeColor,
    SpanStarts, Window,
};
use crate::{clip::Bounds, span::Span, triangle::FilledTriangle};

/// The depth a cleared [`DepthBuffer`] holds: farther than anything drawn
/// (a pixel at depth `FAR` never passes the test).
pub const FAR: u16 = u16::MAX;

/// A depth buffer on caller-provided storage: one `u16` per pixel, row
/// major, for the pixels `(0, 0)..(width, height)`. Smaller is nearer.
///
/// It is a shared handle (`Copy`): every triangle drawn with
/// [`with_depth`](FilledTriangle::with_depth) on it reads and updates the
/// same storage, through [`Cell`]s, so [`Drawable::draw`] can take `&self`.
///
/// # Examples
///
/// ```
/// use embedded_raster::shade::{DepthBuffer, FAR};
///
/// let mut storage = [0u16; 8 * 4]; // or a `static`, or a slice of a larger buffer
/// let depth = DepthBuffer::new(&mut storage, 8);
/// depth.clear();
/// assert_eq!(depth.get(7, 3), Some(FAR));
/// assert_eq!(depth.get(8, 0), None);
/// ```
#[derive(Debug, Clone, Copy)]
pub struct DepthBuffer<'a> {
    cells: &'a [Cell<u16>],
    width: u32,
    height: u32,
    /// The screen row of the first stored row.
    top: i32,
}

impl<'a> DepthBuffer<'a> {
    /// A buffer `width` pixels wide on `storage`, as many rows tall as fit
    /// (`storage.len() / width`; a trailing partial row is unused). The
    /// content is kept: call [`clear`](Self::clear) before a frame.
    ///
    /// Any `width` and storage: width 0 (or wider than the storage) gives
    /// a buffer of no rows, which nothing passes; a height over `u32::MAX`
    /// rows is cut there. Triangles drawn with it are clipped to both the
    /// target and the buffer.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::geometry::Size;
    /// use embedded_raster::shade::DepthBuffer;
    ///
    /// let mut storage = [0u16; 100];
    /// assert_eq!(DepthBuffer::new(&mut storage, 30).size(), Size::new(30, 3));
    /// assert_eq!(DepthBuffer::new(&mut storage, 0).size(), Size::new(0, 0));
    /// ```
    pub fn new(storage: &'a mut [u16], width: u32) -> Self {
        let cells = Cell::from_mut(storage).as_slice_of_cells();
        let (w, rows) = match usize::try_from(width) {
            Ok(w) if w > 0 => (w, cells.len() / w),
            // Width 0, or wider than any slice: no rows.
            _ => (0, 0),
        };
        let height = u32::try_from(rows).unwrap_or(u32::MAX);
        // `height <= rows = len / w`, so `w * height <= len`: no overflow,
        // and `height` (at most `rows`, a `usize`) converts exactly.
        let used = w * height as usize;
        Self {
            cells: &cells[..used],
            width,
            height,
            top: 0,
        }
    }

    /// A depth buffer for the screen rows from `top` down (as many as
    /// `storage` holds), as a band renderer needs: a pixel `(x, y)` of the
    /// screen is stored at row `y - top`.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::shade::DepthBuffer;
    ///
    /// let mut storage = [0u16; 8 * 2];
    /// let band = DepthBuffer::for_rows(&mut storage, 8, 40); // rows 40 and 41
    /// band.clear();
    /// assert_eq!(band.size().height, 2);
    /// ```
    pub fn for_rows(storage: &'a mut [u16], width: u32, top: i32) -> Self {
        Self {
            top,
            ..Self::new(storage, width)
        }
    }

    /// Width and height in pixels.
    pub fn size(&self) -> Size {
        Size::new(self.width, self.height)
    }

    /// Sets every pixel to [`FAR`].
    pub fn clear(&self) {
        self.cells.iter().for_each(|c| c.set(FAR));
    }

    /// The depth at pixel `(x, y)`, `None` outside the buffer (any `x`,
    /// `y`).
    pub fn get(&self, x: u32, y: u32) -> Option<u16> {
        // `x < width`, `y < height`: the index is below `width * height`,
        // the cells' length, so every conversion and sum is exact.
        (x < self.width && y < self.height)
            .then(|| self.cells[y as usize * self.width as usize + x as usize].get())
    }

    /// The clip rectangle for drawing on `target` with this buffer.
    fn clip(&self, target: &Rectangle) -> Option<Rectangle> {
        let own = Rectangle::new(Point::new(0, self.top), self.size());
        let b = Bounds::of(target).intersect(Bounds::of(&own))?;
        // Inside `own`, so every value fits.
        Some(Rectangle::new(
            Point::new(i32::try_from(b.x0).ok()?, i32::try_from(b.y0).ok()?),
            Size::new(
                u32::try_from(b.x1 - b.x0).ok()?,
                u32::try_from(b.y1 - b.y0).ok()?,
            ),
        ))
    }

    /// Depth-tests the pixels of `span` (inside the buffer) whose 32.32
    /// depth, plus the `1/2` of its rounding (`SpanStarts::at`), starts at `z`
    /// and steps by `dz`, storing the passing ones, and
    /// calls `run(offset, len)` for each run of passing pixels. `|z| < 2^49`
    /// and `|dz| <= 2^48` (module `shade`: `Linear::new` stores larger steps
    /// as 0), so `z += dz` cannot overflow.
    fn test_span<E>(
        &self,
        span: Span,
        mut z: i64,
        dz: i64,
        mut run: impl FnMut(u32, u32) -> Result<(), E>,
    ) -> Result<(), E> {
        // The span lies in the buffer (clipped to it): the index is below
        // `width * height`, the cells' length, so nothing overflows.
        // `span.y - top` is a stored row: in `0..height`.
        let row = (i64::from(span.y) - i64::from(self.top)) as usize;
        let start = row * self.width as usize + span.x_start as usize;
        let row = &self.cells[start..start + span.len() as usize];
        let mut i = 0;
        while i < row.len() {
            // Skip failing pixels, then store a run of passing ones. The
            // rounded depth is in 0..=65535 by the interpolation bound
            // (module `shade`), so the cast is exact.
            while i < row.len() && whole(z) as u16 >= row[i].get() {
                z += dz;
                i += 1;
            }
            let first = i;
            while i < row.len() {
                let here = whole(z) as u16;
                if here >= row[i].get() {
                    break;
                }
                row[i].set(here);
                z += dz;
                i += 1;
            }
            if first < i {
                run(first as u32, (i - first) as u32)?;
            }
        }
        Ok(())
    }
}

/// A shaded triangle ([`FilledTriangle`] or [`GouraudTriangle`]) with a
/// depth per vertex, drawn with a depth test against a [`DepthBuffer`].
///
/// Each lit pixel (the flat triangle's pixels, inside both the target and
/// the buffer) gets the depth interpolated at its centre, rounded, within 1
/// of exact (the same bound as colours, see [`shade`](crate::shade)). It is
/// drawn, and its depth stored, iff that depth is **smaller** than the
/// stored one (strictly: of two equal depths the first drawn stays). Each
/// run of passing pixels goes to the target as one
/// [`fill_solid`](DrawTarget::fill_solid) (flat) or
/// [`fill_contiguous`](DrawTarget::fill_contiguous) (Gouraud) call. With
/// distinct depths per pixel, a mesh gives the same image in any drawing
/// order.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
/// use embedded_raster::{
///     framebuffer::{buffer_size, Framebuffer, Gray8Bytes},
///     shade::DepthBuffer,
///     Triangle,
/// };
///
/// let mut fb = Framebuffer::<Gray8Bytes, 8, 8, { buffer_size::<Gray8Bytes>(8, 8) }>::new();
/// let mut storage = [0u16; 64];
/// let depth = DepthBuffer::new(&mut storage, 8);
/// depth.clear();
/// let t = Triangle::from_points(Point::new(0, 0), Point::new(7, 0), Point::new(0, 7)).unwrap();
/// // Near first, then far: the far one stays behind.
/// t.fill(Gray8::WHITE).with_depth([100; 3], depth).draw(&mut fb)?;
/// t.fill(Gray8::new(50)).with_depth([200; 3], depth).draw(&mut fb)?;
/// assert_eq!(fb.pixel(Point::new(1, 1)), Some(Gray8::WHITE));
/// assert_eq!(depth.get(1, 1), Some(100));
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Debug, Clone, Copy)]
pub struct DepthTriangle<'a, S> {
    /// The shaded triangle.
    pub shaded: S,
    /// The depth at each vertex (smaller is nearer).
    pub z: [u16; 3],
    /// The buffer tested and updated.
    pub depth: DepthBuffer<'a>,
}

impl<C> FilledTriangle<C> {
    /// Adds a depth per vertex and the buffer to test against.
    ///
    /// Any `u16` depths (smaller is nearer; [`FAR`] never passes),
    /// interpolated as Gouraud colours are, to within 1 of the exact value
    /// and never outside the vertices' range.
    ///
    /// See [`DepthTriangle`] for an example.
    pub const fn with_depth(self, z: [u16; 3], depth: DepthBuffer<'_>) -> DepthTriangle<'_, Self> {
        DepthTriangle {
            shaded: self,
            z,
            depth,
        }
    }
}

impl<C> GouraudTriangle<C> {
    /// Adds a depth per vertex and the buffer to test against.
    ///
    /// Any `u16` depths (smaller is nearer; [`FAR`] never passes),
    /// interpolated as Gouraud colours are, to within 1 of the exact value
    /// and never outside the vertices' range.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
    /// use embedded_raster::{shade::DepthBuffer, Triangle};
    /// # use embedded_raster::framebuffer::{buffer_size, Framebuffer, Rgb565Le};
    /// # let mut fb = Framebuffer::<Rgb565Le, 8, 8, { buffer_size::<Rgb565Le>(8, 8) }>::new();
    ///
    /// let mut storage = [0u16; 64];
    /// let depth = DepthBuffer::new(&mut storage, 8);
    /// depth.clear();
    /// let t = Triangle::from_points(Point::new(0, 0), Point::new(7, 0), Point::new(0, 7)).unwrap();
    /// t.gouraud([Rgb565::RED, Rgb565::GREEN, Rgb565::BLUE])
    ///     .with_depth([0, 1000, 2000], depth)
    ///     .draw(&mut fb)?;
    /// assert_eq!(depth.get(0, 0), Some(0));
    /// assert_eq!(depth.get(4, 0), Some(571)); // 1000 * 4 / 7 = 571.4
    /// # Ok::<(), core::convert::Infallible>(())
    /// ```
    pub const fn with_depth(self, z: [u16; 3], depth: DepthBuffer<'_>) -> DepthTriangle<'_, Self> {
        DepthTriangle {
            shaded: self,
            z,
            depth,
        }
    }
}

/// The depth plane of `triangle`: its frame and depth stepping.
fn depth_setup(frame: &Frame, z: [u16; 3]) -> Linear<1> {
    Linear::new(frame, z.map(|z| [i64::from(z)]))
}

impl<C: ShadeColor> Drawable for DepthTriangle<'_, FilledTriangle<C>> {
    type Color = C;
    type Output = ();

    fn draw<D>(&self, target: &mut D) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = C>,
    {
        let mut slot = None;
        let frame = Frame::new_in(&mut slot, &self.shaded.triangle);
        let (Some(clip), Some(frame)) = (self.depth.clip(&target.bounding_box()), frame) else {
            return Ok(());
        };
        let z = depth_setup(frame, self.z);
        let color = self.shaded.color;
        let mut starts = SpanStarts::<1, 1>::new(frame, &z);
        // Every row's values start at its whole span (`shaded_spans`).
        let window = Window::of(&clip);
        shaded_spans(&self.shaded.triangle, &clip, &mut |whole| {
            let [z0] = starts.at(whole.x_start, whole.y);
            let span = window.visible(whole);
            if span.is_empty() {
                return Ok(());
            }
            let z0 = z.advanced(z0, 0, offset(whole, span));
            self.depth.test_span(span, z0, z.step[0], |offset, len| {
                let run = Span {
                    y: span.y,
                    x_start: span.x_start + offset as i32,
                    x_end: span.x_start + (offset + len) as i32,
                };
                target.fill_solid(&run.rect(), color)
            })
        })
    }
}

impl<C: ShadeColor> Drawable for DepthTriangle<'_, GouraudTriangle<C>> {
    type Color = C;
    type Output = ();

    fn draw<D>(&self, target: &mut D) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = C>,
    {
        let mut slot = None;
        let frame = Frame::new_in(&mut slot, &self.shaded.triangle);
        let (Some(clip), Some(frame)) = (self.depth.clip(&target.bounding_box()), frame) else {
            return Ok(());
        };
        let setup = GouraudSetup::new(frame, &self.shaded.colors);
        let z = depth_setup(frame, self.z);
        let both = setup.linear.and_depth(&z);
        // The colours and the depth apart: the colours are those of the
        // triangle drawn without depth.
        let mut starts = SpanStarts::<4, 3>::new(frame, &both);
        // Every row's values start at its whole span (`shaded_spans`).
        let window = Window::of(&clip);
        shaded_spans(&self.shaded.triangle, &clip, &mut |whole| {
            let [r, g, b, z0] = starts.at(whole.x_start, whole.y);
            let span = window.visible(whole);
            if span.is_empty() {
                return Ok(());
            }
            let skip = offset(whole, span);
            let (start, z0) = ([r, g, b], z.advanced(z0, 0, skip));
            self.depth.test_span(span, z0, z.step[0], |offset, len| {
                let run = Span {
                    y: span.y,
                    x_start: span.x_start + offset as i32,
                    x_end: span.x_start + (offset + len) as i32,
                };
                target.fill_contiguous(&run.rect(), setup.ramp(start, skip + offset, len))
            })
        })
    }
}
