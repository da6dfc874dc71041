//! [`DisplayList`]: a frame's drawing commands in fixed storage, drawn
//! whole or band by band.

use core::{fmt, ops::Range};

use embedded_graphics_core::{
    draw_target::DrawTarget,
    geometry::{OriginDimensions, Point, Size},
    pixelcolor::PixelColor,
    primitives::Rectangle,
    Drawable,
};

use super::{render_in_bands, Band, BandOutput, RenderError};
use crate::{
    clip::{clip_rect, Bounds},
    line::{StyledLine, StyledPolyline, ThickLine},
    polygon::FilledPolygon,
    raster::sink::{DrawTargetSink, SpanDrawable, SpanSink},
    shade::{DepthBuffer, GouraudTriangle, ShadeColor},
    triangle::{fill::TriangleRows, FilledTriangle, FilledTriangleVariant},
    vertex::Vertex,
};

/// One drawing command of a [`DisplayList`].
///
/// `P` is the vertex capacity of polygons (their edge table, on the stack
/// while one is drawn).
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
/// use embedded_raster::{band::Command, Triangle};
///
/// let t = Triangle::from_points(Point::new(0, 0), Point::new(9, 0), Point::new(0, 9))?;
/// let command: Command<'_, Gray8> = Command::Triangle(t.fill(Gray8::WHITE));
/// assert_eq!(command.rows(), -1..11); // rows 0..=8 lit, a row more each side
/// # Ok::<(), embedded_raster::CoordinateOutOfRange>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Command<'a, C, const P: usize = 32> {
    /// Fill the whole screen.
    Clear(C),
    /// Fill a rectangle of pixels, clipped.
    Rect(Rectangle, C),
    /// A filled triangle.
    Triangle(FilledTriangle<C>),
    /// A filled triangle by a chosen algorithm and precision.
    TriangleVariant(FilledTriangleVariant<C>),
    /// A Gouraud-shaded triangle.
    Gouraud(GouraudTriangle<C>),
    /// A filled triangle with vertex depths, tested against the list's
    /// depth buffer.
    DepthTriangle(FilledTriangle<C>, [u16; 3]),
    /// A Gouraud triangle with vertex depths, tested likewise.
    DepthGouraud(GouraudTriangle<C>, [u16; 3]),
    /// A 1-pixel line.
    Line(StyledLine<C>),
    /// A thick line.
    ThickLine(ThickLine<C>),
    /// A polyline through borrowed points.
    Polyline(StyledPolyline<'a, C>),
    /// A filled polygon of up to `P` borrowed vertices.
    Polygon(FilledPolygon<'a, C, P>),
}

/// Whole pixel rows from raw 20.12 `y` values: a row is lit only if its
/// centre lies between them, so one row more on each side is enough.
fn vertex_rows(vertices: impl Iterator<Item = Vertex>) -> Range<i32> {
    let (mut low, mut high) = (i32::MAX, i32::MIN);
    for v in vertices {
        let y = v.raw().1 >> 12; // floor(y), in -2^19..2^19
        low = low.min(y);
        high = high.max(y);
    }
    match low <= high {
        true => low - 1..high + 2,
        false => 0..0,
    }
}

/// Rows `low..=high` of pixel coordinates grown by `margin` each way.
fn pixel_rows(low: i32, high: i32, margin: u32) -> Range<i32> {
    low.saturating_sub_unsigned(margin)..high.saturating_add_unsigned(margin).saturating_add(1)
}

/// How far a stroke of `width` reaches from its centre line, generously:
/// half the width, a miter of up to 4 half-widths, and 2 px of rounding.
fn stroke_margin(width: u32) -> u32 {
    match width {
        0 | 1 => 0,
        w => w.saturating_mul(4).saturating_add(2),
    }
}

impl<C: Copy, const P: usize> Command<'_, C, P> {
    /// The screen rows the command can write, or more: a band that does
    /// not meet them skips the command before any setup. The end saturates
    /// at `i32::MAX`, so row `i32::MAX`, which no [`Band`] reaches, is left
    /// out.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*, primitives::Rectangle};
    /// use embedded_raster::band::Command;
    ///
    /// let rect = Rectangle::new(Point::new(3, 10), Size::new(5, 4));
    /// assert_eq!(Command::<'_, Gray8>::Rect(rect, Gray8::WHITE).rows(), 10..14);
    /// ```
    pub fn rows(&self) -> Range<i32> {
        match self {
            Self::Clear(_) => i32::MIN..i32::MAX,
            Self::Rect(r, _) => {
                let b = Bounds::of(r);
                let clamp = |v: i64| v.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32;
                match b.x0 < b.x1 {
                    true => clamp(b.y0)..clamp(b.y1),
                    false => 0..0,
                }
            }
            Self::Triangle(t) => vertex_rows(t.triangle.vertices.into_iter()),
            Self::TriangleVariant(t) => vertex_rows(t.triangle.vertices.into_iter()),
            Self::Gouraud(t) | Self::DepthGouraud(t, _) => {
                vertex_rows(t.triangle.vertices.into_iter())
            }
            Self::DepthTriangle(t, _) => vertex_rows(t.triangle.vertices.into_iter()),
            Self::Line(l) => {
                let (a, b) = (l.line.start.y, l.line.end.y);
                pixel_rows(a.min(b), a.max(b), stroke_margin(1))
            }
            Self::ThickLine(l) => {
                let (a, b) = (l.line.start.y, l.line.end.y);
                pixel_rows(a.min(b), a.max(b), stroke_margin(l.width))
            }
            Self::Polyline(p) => {
                let ys = p.polyline.points.iter().map(|p| p.y);
                let (low, high) = (ys.clone().min(), ys.max());
                match (low, high) {
                    (Some(low), Some(high)) => pixel_rows(low, high, stroke_margin(p.width)),
                    _ => 0..0,
                }
            }
            Self::Polygon(p) => vertex_rows(p.polygon.vertices().iter().copied()),
        }
    }
}

impl<C: ShadeColor, const P: usize> Command<'_, C, P> {
    /// Draws the command on `target`, with `depth` for a depth-tested one
    /// (skipped without).
    fn draw_on<T>(
        &self,
        target: &mut T,
        depth: Option<DepthBuffer<'_>>,
    ) -> Result<(), <T as DrawTarget>::Error>
    where
        T: DrawTarget<Color = C> + SpanSink<C, Error = <T as DrawTarget>::Error>,
    {
        match self {
            Command::Clear(color) => DrawTarget::clear(target, *color),
            Command::Rect(area, color) => match clip_rect(area, &SpanSink::bounds(target)) {
                Some(visible) => target.fill_rect(&visible, *color),
                None => Ok(()),
            },
            Command::Triangle(t) => t.draw_spans(target),
            Command::TriangleVariant(t) => t.draw_spans(target),
            Command::Gouraud(t) => t.draw(target),
            Command::DepthTriangle(t, z) => match depth {
                Some(depth) => t.with_depth(*z, depth).draw(target),
                None => Ok(()),
            },
            Command::DepthGouraud(t, z) => match depth {
                Some(depth) => t.with_depth(*z, depth).draw(target),
                None => Ok(()),
            },
            Command::Line(l) => l.draw_spans(target),
            Command::ThickLine(l) => l.draw_spans(target),
            Command::Polyline(p) => p.draw_spans(target),
            Command::Polygon(p) => p.draw_spans(target),
        }
    }
}

/// One command drawn on any `DrawTarget` (a depth-tested one draws
/// nothing: it needs a depth buffer, see
/// [`DisplayList::draw_with_depth`]).
///
/// # Examples
///
/// ```
/// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, prelude::*, primitives::Rectangle};
/// use embedded_raster::band::Command;
///
/// let mut display = MockDisplay::new();
/// let rect = Rectangle::new(Point::new(1, 0), Size::new(2, 1));
/// Command::<'_, BinaryColor>::Rect(rect, BinaryColor::On).draw(&mut display)?;
/// display.assert_pattern(&[" ##"]);
/// # Ok::<(), core::convert::Infallible>(())
/// ```
impl<C: ShadeColor, const P: usize> Drawable for Command<'_, C, P> {
    type Color = C;
    type Output = ();

    fn draw<D: DrawTarget<Color = C>>(&self, target: &mut D) -> Result<(), D::Error> {
        self.draw_on(&mut DrawTargetSink::new(target), None)
    }
}

/// A [`DisplayList`] had no room for another command: nothing was added,
/// and everything already in it stays.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
/// use embedded_raster::band::{Command, DisplayList, DisplayListFull};
///
/// let mut list = DisplayList::<Gray8, 1>::new();
/// list.push(Command::Clear(Gray8::BLACK))?;
/// let full = list.push(Command::Clear(Gray8::WHITE)).unwrap_err();
/// assert_eq!(full.capacity, 1);
/// assert_eq!(list.len(), 1);
/// # Ok::<(), DisplayListFull>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[non_exhaustive]
pub struct DisplayListFull {
    /// The list's capacity, all of it in use.
    pub capacity: usize,
}

impl fmt::Display for DisplayListFull {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "display list full: all {} commands in use",
            self.capacity
        )
    }
}

impl core::error::Error for DisplayListFull {}

/// The drawing commands of a frame, up to `N` of them, in fixed storage:
/// drawn in order on any [`DrawTarget`] (it is a [`Drawable`]), or band
/// by band ([`render_bands`](Self::render_bands)) so that a frame needs
/// only a few rows of pixel memory.
///
/// `P` is the vertex capacity of its polygons. Commands with depth test
/// against a depth buffer given when the list is drawn.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::Rgb565, prelude::*, primitives::Rectangle};
/// use embedded_raster::{
///     band::{Command, DisplayList},
///     framebuffer::{buffer_size, Rgb565Be},
///     Framebuffer, Line, Triangle,
/// };
///
/// let mut list = DisplayList::<Rgb565, 8>::new();
/// list.push(Command::Clear(Rgb565::BLACK))?;
/// let t = Triangle::from_points(Point::new(2, 1), Point::new(60, 12), Point::new(20, 30)).unwrap();
/// list.push(Command::Triangle(t.fill(Rgb565::RED)))?;
/// list.push(Command::Line(Line::new(Point::new(0, 31), Point::new(63, 0)).stroke(Rgb565::WHITE)))?;
///
/// // A 64 x 32 screen in bands of 8 rows: 1 KiB of pixels instead of 4.
/// type Band = Framebuffer<Rgb565Be, 64, 8, { buffer_size::<Rgb565Be>(64, 8) }>;
/// let mut band = [Band::new()];
/// let mut screen = Framebuffer::<Rgb565Be, 64, 32, { buffer_size::<Rgb565Be>(64, 32) }>::new();
/// list.render_bands(32, &mut band, None, &mut |rows: &Band, area: Rectangle| {
///     // Send the band to the display; here, copy it into a whole frame.
///     let start = area.top_left.y as usize * 64 * 2;
///     let bytes = &rows.as_bytes()[..area.size.height as usize * 64 * 2];
///     screen.as_bytes_mut()[start..start + bytes.len()].copy_from_slice(bytes);
///     Ok::<(), core::convert::Infallible>(())
/// })?;
///
/// let mut whole = Framebuffer::<Rgb565Be, 64, 32, { buffer_size::<Rgb565Be>(64, 32) }>::new();
/// list.draw(&mut whole)?;
/// assert_eq!(screen, whole);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct DisplayList<'a, C, const N: usize, const P: usize = 32> {
    commands: heapless::Vec<Command<'a, C, P>, N>,
    /// The rows each command may write, `start..end`, apart from the
    /// commands so that a band's scan for its commands reads 8 bytes each.
    rows: heapless::Vec<(i32, i32), N>,
}

impl<C, const N: usize, const P: usize> Default for DisplayList<'_, C, N, P> {
    fn default() -> Self {
        Self {
            commands: heapless::Vec::new(),
            rows: heapless::Vec::new(),
        }
    }
}

impl<'a, C: PixelColor, const N: usize, const P: usize> DisplayList<'a, C, N, P> {
    /// An empty list.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use embedded_raster::band::DisplayList;
    ///
    /// let list = DisplayList::<BinaryColor, 16>::new();
    /// assert!(list.is_empty());
    /// ```
    pub const fn new() -> Self {
        Self {
            commands: heapless::Vec::new(),
            rows: heapless::Vec::new(),
        }
    }

    /// Appends `command`, to be drawn after those already in the list.
    ///
    /// # Errors
    ///
    /// [`DisplayListFull`] if the list holds `N` commands already: nothing
    /// is added or lost.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use embedded_raster::band::{Command, DisplayList};
    ///
    /// let mut list = DisplayList::<BinaryColor, 2>::new();
    /// list.push(Command::Clear(BinaryColor::Off))?;
    /// assert_eq!(list.len(), 1);
    /// # Ok::<(), embedded_raster::band::DisplayListFull>(())
    /// ```
    pub fn push(&mut self, command: Command<'a, C, P>) -> Result<(), DisplayListFull> {
        let rows = command.rows();
        if self.commands.is_full() {
            return Err(DisplayListFull { capacity: N });
        }
        // Both vectors have the same length: both have room.
        let _ = self.commands.push(command);
        let _ = self.rows.push((rows.start, rows.end));
        Ok(())
    }

    /// The number of commands in the list.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use embedded_raster::{band::{Command, DisplayList}, FillRule, Polygon, Vertex};
    ///
    /// let v = [(0, 0), (8, 0), (4, 8)].map(|(x, y)| Vertex::try_from_num(x, y).unwrap());
    /// let mut list = DisplayList::<BinaryColor, 4, 8>::new();
    /// let polygon = Polygon::<8>::new(&v)?.fill(BinaryColor::On).with_rule(FillRule::EvenOdd);
    /// list.push(Command::Polygon(polygon))?;
    /// assert_eq!(list.len(), 1);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn len(&self) -> usize {
        self.commands.len()
    }

    /// Whether the list has no command.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use embedded_raster::band::DisplayList;
    ///
    /// assert!(DisplayList::<BinaryColor, 1>::new().is_empty());
    /// ```
    pub fn is_empty(&self) -> bool {
        self.commands.is_empty()
    }

    /// Removes every command.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use embedded_raster::band::{Command, DisplayList};
    ///
    /// let mut list = DisplayList::<BinaryColor, 1>::new();
    /// list.push(Command::Clear(BinaryColor::On))?;
    /// list.clear();
    /// assert!(list.is_empty());
    /// # Ok::<(), embedded_raster::band::DisplayListFull>(())
    /// ```
    pub fn clear(&mut self) {
        self.commands.clear();
        self.rows.clear();
    }

    /// The commands, in drawing order.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use embedded_raster::band::{Command, DisplayList};
    ///
    /// let mut list = DisplayList::<BinaryColor, 1>::new();
    /// list.push(Command::Clear(BinaryColor::On))?;
    /// assert_eq!(list.commands().next(), Some(&Command::Clear(BinaryColor::On)));
    /// # Ok::<(), embedded_raster::band::DisplayListFull>(())
    /// ```
    pub fn commands(&self) -> impl Iterator<Item = &Command<'a, C, P>> {
        self.commands.iter()
    }
}

impl<C: ShadeColor, const N: usize, const P: usize> DisplayList<'_, C, N, P> {
    /// Draws the commands that can touch rows `rows` on `target`, in order,
    /// with `depth` for the depth-tested ones (without one, they are
    /// skipped).
    fn draw_rows<T>(
        &self,
        target: &mut T,
        rows: Range<i32>,
        depth: Option<DepthBuffer<'_>>,
    ) -> Result<(), <T as DrawTarget>::Error>
    where
        T: DrawTarget<Color = C> + SpanSink<C, Error = <T as DrawTarget>::Error>,
    {
        for (&(start, end), command) in self.rows.iter().zip(&self.commands) {
            if start < rows.end && rows.start < end {
                command.draw_on(target, depth)?;
            }
        }
        Ok(())
    }

    /// Draws the list on `target`, a [`DrawTarget`] that is also a
    /// [`SpanSink`] (a [`Framebuffer`](crate::Framebuffer), a [`Band`] of
    /// one), with `depth` for the depth-tested commands (skipped without
    /// one). [`Drawable::draw`] draws on any `DrawTarget`, without depth.
    ///
    /// # Errors
    ///
    /// The first error of `target`.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
    /// use embedded_raster::{
    ///     band::{Command, DisplayList},
    ///     framebuffer::{buffer_size, Gray8Bytes},
    ///     shade::DepthBuffer,
    ///     Framebuffer, Triangle,
    /// };
    ///
    /// let near = Triangle::from_points(Point::new(0, 0), Point::new(15, 0), Point::new(0, 15))?;
    /// let mut list = DisplayList::<Gray8, 4>::new();
    /// list.push(Command::DepthTriangle(near.fill(Gray8::WHITE), [10, 10, 10]))?;
    /// list.push(Command::DepthTriangle(near.fill(Gray8::new(7)), [20, 20, 20]))?; // behind
    ///
    /// let mut fb = Framebuffer::<Gray8Bytes, 16, 16, { buffer_size::<Gray8Bytes>(16, 16) }>::new();
    /// let mut z = [0u16; 16 * 16];
    /// let depth = DepthBuffer::new(&mut z, 16);
    /// depth.clear();
    /// list.draw_with_depth(&mut fb, Some(depth))?;
    /// assert_eq!(fb.pixel(Point::new(1, 1)), Some(Gray8::WHITE));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn draw_with_depth<T>(
        &self,
        target: &mut T,
        depth: Option<DepthBuffer<'_>>,
    ) -> Result<(), <T as DrawTarget>::Error>
    where
        T: DrawTarget<Color = C> + SpanSink<C, Error = <T as DrawTarget>::Error>,
    {
        // Every command: culling by rows could only skip the empty ones,
        // and would skip those on row `i32::MAX`, which no `Range<i32>`
        // of rows holds.
        self.commands
            .iter()
            .try_for_each(|command| command.draw_on(target, depth))
    }

    /// Draws the commands whose rows meet `band`'s on it, in order, with
    /// `depth` (for the band's rows) for the depth-tested ones.
    ///
    /// # Errors
    ///
    /// The first error of the band's buffer.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
    /// use embedded_raster::{band::{Band, Command, DisplayList}, framebuffer::{buffer_size, Gray8Bytes}, Framebuffer, Line};
    ///
    /// let mut list = DisplayList::<Gray8, 2>::new();
    /// list.push(Command::Line(Line::new(Point::new(0, 9), Point::new(7, 9)).stroke(Gray8::WHITE)))?;
    /// let mut rows = Framebuffer::<Gray8Bytes, 8, 4, { buffer_size::<Gray8Bytes>(8, 4) }>::new();
    /// list.draw_band(&mut Band::new(&mut rows, 8), None)?; // rows 8..12
    /// assert_eq!(rows.pixel(Point::new(3, 1)), Some(Gray8::WHITE));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn draw_band<T>(
        &self,
        band: &mut Band<'_, T>,
        depth: Option<DepthBuffer<'_>>,
    ) -> Result<(), <T as DrawTarget>::Error>
    where
        T: DrawTarget<Color = C> + SpanSink<C, Error = <T as DrawTarget>::Error> + OriginDimensions,
    {
        let rows = band.rows();
        self.draw_rows(band, rows, depth)
    }

    /// Renders the list on a screen of `height` rows, band by band: each
    /// band is drawn into the next of `buffers` (as wide as the screen; as
    /// many rows as a buffer has make a band; one buffer, or two to
    /// alternate so that one can be sent while the other is drawn) and
    /// handed to `output` ([`render_in_bands`] has the details).
    ///
    /// The image is exactly the one drawn on a whole-screen target, byte
    /// for byte, whatever the band height. A command is set up only in the
    /// bands its rows meet; a flat triangle is set up once and continued
    /// from band to band (up to 24 at a time).
    ///
    /// Stack: the kept triangle walks, about 3 KiB, and one byte per
    /// command of capacity (`N`), besides what the commands' drawing uses.
    ///
    /// # Errors
    ///
    /// The first error of a buffer or of `output`, as [`RenderError`];
    /// before anything is drawn, if the screen has rows,
    /// [`RenderError::NoRows`] if `buffers` is empty or a buffer has none,
    /// and [`RenderError::WidthsDiffer`] if the buffers are not all as
    /// wide as the first.
    ///
    /// # Examples
    ///
    /// See [`DisplayList`].
    pub fn render_bands<T, O>(
        &self,
        height: u32,
        buffers: &mut [T],
        depth: Option<&mut [u16]>,
        output: &mut O,
    ) -> Result<(), RenderError<<T as DrawTarget>::Error, O::Error>>
    where
        T: DrawTarget<Color = C> + SpanSink<C, Error = <T as DrawTarget>::Error> + OriginDimensions,
        O: BandOutput<T>,
    {
        let width = buffers.first().map_or(0, |b| b.size().width);
        // The kept walks are clipped to one width, the screen's.
        if height > 0 && buffers.iter().any(|b| b.size().width != width) {
            return Err(RenderError::WidthsDiffer);
        }
        let screen = Rectangle::new(Point::zero(), Size::new(width, height));
        // Built in place: a walk table is a few KiB of stack.
        let mut walks = Walks::<N> {
            slot_of: [0; N],
            slots: [None; WALKS],
            free: heapless::Vec::new(),
            live: 0,
        };
        walks.free_all();
        render_in_bands(
            height,
            buffers,
            depth,
            |band, depth| self.draw_band_resuming(band, depth, &screen, &mut walks),
            output,
        )
    }

    /// Draws the commands meeting `band`'s rows, like
    /// [`draw_band`](Self::draw_band), but continues the triangles set up
    /// in an earlier band from where they stopped and keeps the walks of
    /// those set up here that go on below, while there is room (else later
    /// bands draw them whole, clipped to their rows). Bands must come top
    /// to bottom.
    fn draw_band_resuming<T>(
        &self,
        band: &mut Band<'_, T>,
        depth: Option<DepthBuffer<'_>>,
        screen: &Rectangle,
        walks: &mut Walks<N>,
    ) -> Result<(), <T as DrawTarget>::Error>
    where
        T: DrawTarget<Color = C> + SpanSink<C, Error = <T as DrawTarget>::Error> + OriginDimensions,
    {
        let rows = band.rows();
        // Skip the commands that ended in earlier bands (a list drawn top
        // to bottom has many).
        let ended = self.rows.get(walks.live..).unwrap_or_default();
        walks.live += ended
            .iter()
            .take_while(|&&(_, end)| end <= rows.start)
            .count();
        let live = walks.live;
        let rows_left = self.rows.get(live..).unwrap_or_default();
        let commands_left = self.commands.get(live..).unwrap_or_default();
        for (offset, (&(start, end), command)) in rows_left.iter().zip(commands_left).enumerate() {
            let index = live + offset;
            if start >= rows.end || rows.start >= end {
                continue;
            }
            let Command::Triangle(t) = command else {
                command.draw_on(band, depth)?;
                continue;
            };
            if let Some(walk) = walks.of(index) {
                // Set up in an earlier band: continue.
                if walk.emit_until(rows.end, &mut band.row_span_writer(t.color))? {
                    walks.finish(index);
                }
                continue;
            }
            // The first band the command meets sets it up, and keeps the
            // walk only if the triangle goes on below the band.
            let first = start >= rows.start || rows.start == 0;
            if first && end <= rows.end {
                t.draw_spans(band)?;
                continue;
            }
            // Set up in a free slot, where it stays (walks are not moved).
            let slot = if first {
                walks.start(index, t, screen)
            } else {
                None
            };
            match slot {
                Some(walk) => {
                    if walk.emit_until(rows.end, &mut band.row_span_writer(t.color))? {
                        walks.finish(index);
                    }
                }
                // No free slot, nothing to light, or on the 64-bit path.
                None => t.draw_spans(band)?,
            }
        }
        Ok(())
    }
}

/// The most triangle walks kept from one band to the next.
const WALKS: usize = 24;

/// Triangle walks kept between bands, found by command index: slots
/// that do not move (a walk is 120 to 130 bytes), a slot number per
/// command, and the free slots.
struct Walks<const N: usize> {
    /// Per command, its slot plus one, or 0.
    slot_of: [u8; N],
    slots: [Option<TriangleRows>; WALKS],
    free: heapless::Vec<u8, WALKS>,
    /// Commands before this one end above the current band: bands come
    /// top to bottom, so no later band needs them.
    live: usize,
}

impl<const N: usize> Walks<N> {
    /// Marks every slot free.
    fn free_all(&mut self) {
        self.free.clear();
        // Slots 0..WALKS: `WALKS` fits the vector and `u8`.
        for slot in (0..WALKS as u8).rev() {
            let _ = self.free.push(slot);
        }
    }

    /// The walk of command `index`, if one is kept.
    fn of(&mut self, index: usize) -> Option<&mut TriangleRows> {
        let slot = usize::from(*self.slot_of.get(index)?).checked_sub(1)?;
        self.slots.get_mut(slot)?.as_mut()
    }

    /// Sets up the walk of triangle `t` inside `screen` for command
    /// `index` in a free slot, and returns it; `None` (nothing kept) if no
    /// slot is free or the triangle has no 32-bit walk.
    fn start<C>(
        &mut self,
        index: usize,
        t: &FilledTriangle<C>,
        screen: &Rectangle,
    ) -> Option<&mut TriangleRows> {
        let mark = self.slot_of.get_mut(index)?;
        let &slot = self.free.last()?;
        let place = self.slots.get_mut(usize::from(slot))?;
        *place = TriangleRows::new(&t.triangle.vertices, screen);
        let walk = place.as_mut()?;
        self.free.pop();
        *mark = slot + 1;
        Some(walk)
    }

    /// Drops the walk of command `index`, freeing its slot.
    fn finish(&mut self, index: usize) {
        let Some(mark) = self.slot_of.get_mut(index) else {
            return;
        };
        if let Some(slot) = mark.checked_sub(1) {
            if let Some(place) = self.slots.get_mut(usize::from(slot)) {
                *place = None;
                // A slot taken from `free` goes back: there is room.
                let _ = self.free.push(slot);
            }
        }
        *mark = 0;
    }
}

/// Draws the list in order on any `DrawTarget`, without depth (the
/// depth-tested commands are skipped: use
/// [`draw_with_depth`](DisplayList::draw_with_depth)).
///
/// # Examples
///
/// ```
/// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, prelude::*};
/// use embedded_raster::{band::{Command, DisplayList}, Line};
///
/// let mut list = DisplayList::<BinaryColor, 2>::new();
/// list.push(Command::Line(Line::new(Point::new(0, 0), Point::new(2, 0)).stroke(BinaryColor::On)))?;
/// let mut display = MockDisplay::new();
/// list.draw(&mut display)?;
/// display.assert_pattern(&["###"]);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
impl<C: ShadeColor, const N: usize, const P: usize> Drawable for DisplayList<'_, C, N, P> {
    type Color = C;
    type Output = ();

    fn draw<D: DrawTarget<Color = C>>(&self, target: &mut D) -> Result<(), D::Error> {
        self.draw_with_depth(&mut DrawTargetSink::new(target), None)
    }
}
