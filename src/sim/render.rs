//! Scene rendering and its statistics.

use std::format;
use std::prelude::rust_2021::*;
use std::time::{Duration, Instant};
use std::{boxed::Box, vec};

use embedded_graphics_core::{
    draw_target::DrawTarget,
    pixelcolor::{Rgb888, RgbColor},
    primitives::Rectangle,
    Drawable,
};

use super::{scene::SCENE_POLYGON_CAPACITY, Command, Scene, SimDisplay};
use crate::band::{self, render_in_bands, DisplayList};
use crate::clip::clip_rect;
use crate::{
    line::Polyline, polygon::Polygon, triangle::SubpixelPrecision, triangle::TriangleAlgorithm,
};

impl Command {
    /// Draws the command on `target`: `clear` with [`DrawTarget::clear`],
    /// `rect` clipped to the target's bounding box (without overflow, for
    /// any position and size) and then, unless nothing is left, with one
    /// [`DrawTarget::fill_solid`] call, `tri` as a
    /// [`FilledTriangle`](crate::FilledTriangle), `gtri` as a
    /// [`GouraudTriangle`](crate::GouraudTriangle), `line` and `polyline` as
    /// 1-pixel Bresenham [`Line`](crate::Line) and
    /// [`Polyline`] strokes, `poly` as a [`Polygon`] filled under its rule
    /// (a hand-made command with too few or too many vertices draws
    /// nothing). Nothing is drawn outside the target.
    ///
    /// # Errors
    ///
    /// Any error of `target`.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Rgb888, prelude::*};
    /// use embedded_raster::sim::{parse_scene, SimDisplay};
    ///
    /// let scene = parse_scene("size 4 4\nrect 1 1 100 100 #00ff00")?;
    /// let mut display = SimDisplay::new(4, 4, Rgb888::BLACK);
    /// let Ok(()) = scene.commands()[0].draw(&mut display);
    /// assert_eq!(display.pixel(Point::new(3, 3)), Some(Rgb888::GREEN));
    /// assert_eq!(display.pixels_written(), 9);
    /// assert_eq!(display.out_of_bounds_writes(), 0);
    /// # Ok::<(), embedded_raster::sim::SceneError>(())
    /// ```
    pub fn draw<D: DrawTarget<Color = Rgb888>>(&self, target: &mut D) -> Result<(), D::Error> {
        match self {
            Self::Clear(color) => target.clear(*color),
            Self::Rect(rect, color) => match clip_rect(rect, &target.bounding_box()) {
                Some(visible) => target.fill_solid(&visible, *color),
                None => Ok(()),
            },
            Self::Tri(triangle, color) => triangle.fill(*color).draw(target),
            Self::Gtri(triangle, colors) => triangle.gouraud(*colors).draw(target),
            Self::Line(line, color) => line.stroke(*color).draw(target),
            Self::Polyline(points, color) => Polyline::new(points).stroke(*color).draw(target),
            Self::Poly(vertices, rule, color) => {
                match Polygon::<SCENE_POLYGON_CAPACITY>::new(vertices) {
                    Ok(polygon) => polygon.fill(*color).with_rule(*rule).draw(target),
                    // The parser checked the vertex count; a hand-made
                    // command with too few or too many draws nothing.
                    Err(_) => Ok(()),
                }
            }
        }
    }
}

impl Command {
    /// Like [`draw`](Self::draw), but a `tri` is filled by `algorithm` at
    /// `precision` (see [`TriangleAlgorithm`]); other commands draw as
    /// with `draw`.
    ///
    /// # Errors
    ///
    /// Any error of `target`.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Rgb888, prelude::*};
    /// use embedded_raster::sim::{parse_scene, SimDisplay};
    /// use embedded_raster::{SubpixelPrecision, TriangleAlgorithm};
    ///
    /// let scene = parse_scene("size 8 8\ntri 0 0 4 0 0 4 #00ff00")?;
    /// let mut display = SimDisplay::new(8, 8, Rgb888::BLACK);
    /// let Ok(()) = scene.commands()[0].draw_with(&mut display, TriangleAlgorithm::BresenhamWalk, SubpixelPrecision::Bits12);
    /// assert_eq!(display.pixels_written(), 15);
    /// # Ok::<(), embedded_raster::sim::SceneError>(())
    /// ```
    pub fn draw_with<D: DrawTarget<Color = Rgb888>>(
        &self,
        target: &mut D,
        algorithm: TriangleAlgorithm,
        precision: SubpixelPrecision,
    ) -> Result<(), D::Error> {
        match self {
            Self::Tri(triangle, color) => triangle
                .fill(*color)
                .algorithm(algorithm)
                .precision(precision)
                .draw(target),
            other => other.draw(target),
        }
    }
}

/// A rendered scene: the final framebuffer, whose write counts cover the
/// whole scene, and the statistics of the run.
///
/// # Examples
///
/// ```
/// use embedded_raster::sim::{parse_scene, render_scene};
///
/// let rendered = render_scene(&parse_scene("size 8 8\nclear #ffffff")?);
/// assert_eq!(rendered.display.pixels_written(), 64);
/// assert_eq!(rendered.stats.primitives, 1);
/// # Ok::<(), embedded_raster::sim::SceneError>(())
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Rendered {
    /// The framebuffer after the last command.
    pub display: SimDisplay<Rgb888>,
    /// What it took.
    pub stats: RenderStats,
}

/// Statistics of a [`render_scene`] run.
///
/// # Examples
///
/// ```
/// use embedded_raster::sim::{parse_scene, render_scene};
///
/// let scene = parse_scene("size 10 10\nrect 0 0 5 2 #ff0000\ntri 0 0 10 0 0 10 #00ff00")?;
/// let stats = render_scene(&scene).stats;
/// assert_eq!((stats.primitives, stats.pixels_written), (2, 10 + 45));
/// # Ok::<(), embedded_raster::sim::SceneError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct RenderStats {
    /// Commands drawn: every command after `size`.
    pub primitives: u64,
    /// Pixel writes inside the framebuffer, summed over all commands
    /// (`clear` writes every pixel; the initial black is not a write).
    pub pixels_written: u64,
    /// Wall-clock time spent drawing the commands (not parsing, not
    /// allocating the framebuffer, not encoding images).
    pub raster_time: Duration,
}

impl RenderStats {
    /// The statistics as one line of JSON, with the fields `primitives`,
    /// `pixels_written` (integers) and `raster_seconds` (a decimal number).
    ///
    /// # Examples
    ///
    /// ```
    /// use std::time::Duration;
    /// use embedded_raster::sim::RenderStats;
    ///
    /// let stats = RenderStats {
    ///     primitives: 3,
    ///     pixels_written: 1234,
    ///     raster_time: Duration::from_micros(125),
    /// };
    /// assert_eq!(
    ///     stats.to_json(),
    ///     r#"{"primitives":3,"pixels_written":1234,"raster_seconds":0.000125}"#,
    /// );
    /// ```
    pub fn to_json(&self) -> String {
        format!(
            r#"{{"primitives":{},"pixels_written":{},"raster_seconds":{}}}"#,
            self.primitives,
            self.pixels_written,
            self.raster_time.as_secs_f64()
        )
    }
}

/// Renders `scene` on a new black [`SimDisplay`] of the scene's size.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::Rgb888, prelude::*};
/// use embedded_raster::sim::{parse_scene, render_scene};
///
/// let scene = parse_scene("size 16 16\ntri 0 0 16 0 0 16 #FF0000\ntri 16 0 16 16 0 16 #0000ff")?;
/// let rendered = render_scene(&scene);
/// let display = &rendered.display;
/// assert_eq!(display.pixel(Point::new(0, 0)), Some(Rgb888::RED));
/// assert_eq!(display.pixel(Point::new(15, 15)), Some(Rgb888::BLUE));
/// // The two halves share their diagonal: every pixel is written once.
/// assert!(display.counts().iter().all(|&c| c == 1));
/// # Ok::<(), embedded_raster::sim::SceneError>(())
/// ```
pub fn render_scene(scene: &Scene) -> Rendered {
    render_scene_with(
        scene,
        TriangleAlgorithm::EdgeExact,
        SubpixelPrecision::Bits12,
    )
}

/// Like [`render_scene`], with `tri` commands drawn by `algorithm` at
/// `precision` (see [`Command::draw_with`]).
///
/// # Examples
///
/// ```
/// use embedded_raster::sim::{parse_scene, render_scene_with};
/// use embedded_raster::{SubpixelPrecision, TriangleAlgorithm};
///
/// let scene = parse_scene("size 16 16\ntri 0 0 16 0 0 16 #FF0000\ntri 16 0 16 16 0 16 #0000ff")?;
/// let closed = render_scene_with(&scene, TriangleAlgorithm::BresenhamWalk, SubpixelPrecision::Bits12);
/// // Both triangles light their shared diagonal.
/// assert!(closed.display.counts().iter().any(|&c| c == 2));
/// # Ok::<(), embedded_raster::sim::SceneError>(())
/// ```
pub fn render_scene_with(
    scene: &Scene,
    algorithm: TriangleAlgorithm,
    precision: SubpixelPrecision,
) -> Rendered {
    let size = scene.size();
    let mut display = SimDisplay::new(size.width, size.height, Rgb888::BLACK);
    let start = Instant::now();
    for command in scene.commands() {
        let Ok(()) = command.draw_with(&mut display, algorithm, precision);
    }
    let raster_time = start.elapsed();
    let stats = RenderStats {
        primitives: scene.commands().len() as u64,
        pixels_written: display.pixels_written(),
        raster_time,
    };
    Rendered { display, stats }
}

/// Commands per display list when a scene is rendered in bands (a scene
/// of more is several lists, drawn in order in each band).
const LIST_CAPACITY: usize = 256;

/// A scene's commands as display lists, in order.
type SceneLists<'a> = Vec<Box<DisplayList<'a, Rgb888, LIST_CAPACITY, SCENE_POLYGON_CAPACITY>>>;

/// The display-list command drawing `command` as
/// [`Command::draw_with`] does.
fn list_command(
    command: &Command,
    algorithm: TriangleAlgorithm,
    precision: SubpixelPrecision,
) -> Option<band::Command<'_, Rgb888, SCENE_POLYGON_CAPACITY>> {
    let exact = algorithm == TriangleAlgorithm::EdgeExact && precision == SubpixelPrecision::Bits12;
    Some(match command {
        Command::Clear(color) => band::Command::Clear(*color),
        Command::Rect(rect, color) => band::Command::Rect(*rect, *color),
        Command::Tri(t, color) if exact => band::Command::Triangle(t.fill(*color)),
        Command::Tri(t, color) => {
            band::Command::TriangleVariant(t.fill(*color).algorithm(algorithm).precision(precision))
        }
        Command::Gtri(t, colors) => band::Command::Gouraud(t.gouraud(*colors)),
        Command::Line(line, color) => band::Command::Line(line.stroke(*color)),
        Command::Polyline(points, color) => {
            band::Command::Polyline(Polyline::new(points).stroke(*color))
        }
        Command::Poly(vertices, rule, color) => {
            // The parser checked the count; a hand-made command that does
            // not fit draws nothing, as with `draw`.
            let polygon = Polygon::<SCENE_POLYGON_CAPACITY>::new(vertices).ok()?;
            band::Command::Polygon(polygon.fill(*color).with_rule(*rule))
        }
    })
}

/// How a scene was rendered in bands.
///
/// # Examples
///
/// ```
/// use embedded_raster::sim::{parse_scene, render_scene_in_bands};
/// use embedded_raster::{SubpixelPrecision, TriangleAlgorithm};
///
/// let scene = parse_scene("size 10 10\nclear #000000")?;
/// let (_, bands) = render_scene_in_bands(&scene, 4, TriangleAlgorithm::EdgeExact, SubpixelPrecision::Bits12);
/// assert_eq!((bands.bands, bands.buffer_bytes), (3, 10 * 4 * 3));
/// # Ok::<(), embedded_raster::sim::SceneError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct BandStats {
    /// Bands drawn.
    pub bands: u32,
    /// Bytes of the one band buffer (3 per `Rgb888` pixel), the pixel
    /// memory the render needed.
    pub buffer_bytes: u64,
}

/// Renders `scene` through the band renderer
/// ([`band::render_in_bands`]), `rows` rows at a time (at least 1), into
/// one `Rgb888` band buffer, and assembles the bands' pixels and write
/// counts into a whole [`SimDisplay`]: the same image and counts as
/// [`render_scene_with`], by the crate's band exactness.
///
/// # Examples
///
/// ```
/// use embedded_raster::sim::{parse_scene, render_scene_in_bands, render_scene_with};
/// use embedded_raster::{SubpixelPrecision, TriangleAlgorithm};
///
/// let scene = parse_scene("size 16 16\ntri 0 0 16 0 0 16 #FF0000\nline 0 15 15 0 #00ff00")?;
/// let (algo, bits) = (TriangleAlgorithm::EdgeExact, SubpixelPrecision::Bits12);
/// let (banded, stats) = render_scene_in_bands(&scene, 3, algo, bits);
/// let whole = render_scene_with(&scene, algo, bits).display;
/// assert_eq!(banded.display.pixels(), whole.pixels());
/// assert_eq!(banded.display.counts(), whole.counts());
/// assert_eq!(stats.bands, 6);
/// # Ok::<(), embedded_raster::sim::SceneError>(())
/// ```
pub fn render_scene_in_bands(
    scene: &Scene,
    rows: u32,
    algorithm: TriangleAlgorithm,
    precision: SubpixelPrecision,
) -> (Rendered, BandStats) {
    let size = scene.size();
    let rows = rows.clamp(1, size.height.max(1));
    let mut lists: SceneLists<'_> = Vec::new();
    for command in scene.commands() {
        let Some(command) = list_command(command, algorithm, precision) else {
            continue;
        };
        if lists.last().is_none_or(|l| l.len() == LIST_CAPACITY) {
            lists.push(Box::new(DisplayList::new()));
        }
        if let Some(list) = lists.last_mut() {
            // Not full: a new list was pushed if the last one was.
            let _ = list.push(command);
        }
    }

    let mut display = SimDisplay::new(size.width, size.height, Rgb888::BLACK);
    let mut buffers = [SimDisplay::new(size.width, rows, Rgb888::BLACK)];
    let mut stats = BandStats {
        bands: 0,
        buffer_bytes: u64::from(size.width) * u64::from(rows) * 3,
    };
    let mut seen = vec![0u32; size.width as usize * rows as usize];
    let start = Instant::now();
    let result = render_in_bands(
        size.height,
        &mut buffers,
        None,
        |target, _| {
            lists
                .iter()
                .try_for_each(|list| list.draw_band(target, None))
        },
        &mut |buffer: &SimDisplay<Rgb888>, area: Rectangle| {
            let rows = (area.top_left.y, area.size.height);
            display.paste_rows(buffer, rows, &mut seen, Rgb888::BLACK);
            stats.bands += 1;
            Ok::<(), core::convert::Infallible>(())
        },
    );
    let raster_time = start.elapsed();
    // A `SimDisplay` cannot fail, the buffer has a row at least, and
    // `render_in_bands` takes buffers of any width.
    match result {
        Ok(()) | Err(band::RenderError::NoRows | band::RenderError::WidthsDiffer) => {}
        Err(band::RenderError::Draw(e) | band::RenderError::Flush(e)) => match e {},
    }
    let stats_all = RenderStats {
        primitives: scene.commands().len() as u64,
        pixels_written: display.pixels_written(),
        raster_time,
    };
    (
        Rendered {
            display,
            stats: stats_all,
        },
        stats,
    )
}
