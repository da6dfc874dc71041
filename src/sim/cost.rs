//! The cost model of the `render` tool: how many pixels each command can
//! touch, known before anything is drawn.
//!
//! The model is documented on [`Scene::pixel_work`].

use embedded_graphics_core::{geometry::Point, prelude::*, primitives::Rectangle};

use super::{Command, Scene};
use crate::vertex::Vertex;

impl Scene {
    /// The scene's estimated work: the sum of [`Command::pixel_work`] over
    /// its commands (the `size` command's black costs nothing).
    ///
    /// Rendering time is about the pixels the rasterizers visit, so each
    /// command counts an upper bound on the pixels it can touch inside the
    /// `W x H` target:
    ///
    /// | command | work |
    /// |---|---|
    /// | `clear` | `W H` |
    /// | `rect` | the rectangle's area clipped to the target |
    /// | `tri`, `gtri`, `poly` | the vertices' bounding box grown by half a pixel (whole pixels) clipped to the target |
    /// | `line` | the major-axis extent of the line's bounding box clipped to the target (one pixel per visible step) |
    /// | `polyline` | the sum over its segments, as `line` |
    ///
    /// Every bound is at most `W H <= 2^24` per command, so the sum over
    /// any number of commands a file can hold fits `u64`. Besides pixels,
    /// each command costs a constant plus its vertices, bounded by the
    /// file's length.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::sim::parse_scene;
    ///
    /// let scene = parse_scene(
    ///     "size 100 50\n\
    ///      clear #000000\n\
    ///      rect -10 -10 20 20 #ffffff\n\
    ///      line -1000 0 1000 1 #ffffff\n",
    /// )?;
    /// assert_eq!(scene.pixel_work(), 5000 + 100 + 100);
    /// # Ok::<(), embedded_raster::sim::SceneError>(())
    /// ```
    pub fn pixel_work(&self) -> u64 {
        let size = self.size();
        self.commands().iter().map(|c| c.pixel_work(size)).sum()
    }
}

impl Command {
    /// An upper bound on the pixels this command can touch on a target of
    /// `size`: the cost model of [`Scene::pixel_work`]. At most `width * height`.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::prelude::*;
    /// use embedded_raster::sim::parse_scene;
    ///
    /// let scene = parse_scene("size 64 64\ntri 0.5 0.5 10 0.5 0.5 -524288 #ffffff\n")?;
    /// // The box from (0.5, -524288) to (10, 0.5), grown by half a pixel:
    /// // columns 0..=10 and rows 0..=1 once clipped to the target.
    /// assert_eq!(scene.commands()[0].pixel_work(Size::new(64, 64)), 22);
    /// # Ok::<(), embedded_raster::sim::SceneError>(())
    /// ```
    pub fn pixel_work(&self, size: Size) -> u64 {
        match self {
            Command::Clear(_) => u64::from(size.width) * u64::from(size.height),
            Command::Rect(r, _) => rect_work(r, size),
            Command::Tri(t, _) | Command::Gtri(t, _) => box_work(&t.vertices, size),
            Command::Poly(vertices, ..) => box_work(vertices, size),
            Command::Line(l, _) => line_work(l.start, l.end, size),
            Command::Polyline(points, _) => {
                points.windows(2).map(|p| line_work(p[0], p[1], size)).sum()
            }
        }
    }
}

/// The rectangle's area clipped to the target, in `i64` (a rectangle may
/// reach past `i32::MAX`, where `Rectangle::intersection` would overflow).
fn rect_work(r: &Rectangle, size: Size) -> u64 {
    let (x, y) = (i64::from(r.top_left.x), i64::from(r.top_left.y));
    let w = clipped(x, x + i64::from(r.size.width), size.width);
    let h = clipped(y, y + i64::from(r.size.height), size.height);
    w * h
}

/// `[lo, hi)` clipped to `[0, side)`, as a length.
fn clipped(lo: i64, hi: i64, side: u32) -> u64 {
    let (lo, hi) = (lo.max(0), hi.min(i64::from(side)));
    u64::try_from(hi - lo).unwrap_or(0)
}

/// The whole pixels of the vertices' bounding box grown by half a pixel,
/// clipped: columns `floor(min x - 1/2)..=floor(max x + 1/2)`. They hold
/// every pixel centre inside the box (all the exact rasterizer can
/// light) and, as `render --algo` and `--bits` need, every pixel holding a
/// vertex snapped to a coarser precision (by at most half a pixel), which
/// the Bresenham walk lights.
fn box_work(vertices: &[Vertex], size: Size) -> u64 {
    let raw = |f: fn((i32, i32)) -> i32| vertices.iter().map(move |v| i64::from(f(v.raw())));
    let (Some(x0), Some(x1)) = (raw(|r| r.0).min(), raw(|r| r.0).max()) else {
        return 0;
    };
    let (Some(y0), Some(y1)) = (raw(|r| r.1).min(), raw(|r| r.1).max()) else {
        return 0;
    };
    // 20.12: floor is `>> 12`, half a pixel 2048, exact in i64.
    let w = clipped((x0 - 2048) >> 12, ((x1 + 2048) >> 12) + 1, size.width);
    let h = clipped((y0 - 2048) >> 12, ((y1 + 2048) >> 12) + 1, size.height);
    w * h
}

/// A 1-pixel line lights one pixel per step along its major axis, so at
/// most the major extent of its bounding box clipped to the target, and
/// nothing if that box misses the target.
fn line_work(a: Point, b: Point, size: Size) -> u64 {
    let (ax, ay, bx, by) = (
        i64::from(a.x),
        i64::from(a.y),
        i64::from(b.x),
        i64::from(b.y),
    );
    let w = clipped(ax.min(bx), ax.max(bx) + 1, size.width);
    let h = clipped(ay.min(by), ay.max(by) + 1, size.height);
    match (w, h) {
        (0, _) | (_, 0) => 0,
        _ if (bx - ax).abs() >= (by - ay).abs() => w,
        _ => h,
    }
}
