//! The exact reference the tests compare against, written independently of
//! the rasterizer: the scene contract's sampling rule taken literally.
//!
//! A pixel `(i, j)` is lit iff the winding number of the shape around its
//! centre, nudged by `(e, e^2)` for an infinitesimal `e > 0`, is non-zero.
//! Everything is computed in `i128` on raw 20.12 coordinates, so nothing can
//! overflow or round.

#![allow(dead_code)]

pub mod blend;
pub mod shapes;

use embedded_graphics_core::{
    geometry::{Point, Size},
    primitives::Rectangle,
};
use embedded_raster::{Span, Triangle, Vertex};

/// Raw 20.12 coordinates of a vertex as `i128`.
pub fn raw(v: Vertex) -> (i128, i128) {
    let (x, y) = v.raw();
    (i128::from(x), i128::from(y))
}

/// Sign (-1 or 1) of `cross(b - a, p' - a)` where `p' = p + (e, e^2)`.
/// Never 0 when `a != b`: on the line, the nudge decides.
fn nudged_side(a: (i128, i128), b: (i128, i128), p: (i128, i128)) -> i128 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let s = dx * (p.1 - a.1) - dy * (p.0 - a.0);
    if s != 0 {
        return s.signum();
    }
    // cross((dx, dy), (e, e^2)) = dx e^2 - dy e: the e term dominates.
    if dy != 0 {
        -dy.signum()
    } else {
        dx.signum()
    }
}

/// Winding number of the closed polygon `poly` around the nudged point
/// `p + (e, e^2)`, with `p` in raw units.
pub fn winding(poly: &[(i128, i128)], p: (i128, i128)) -> i32 {
    let mut wn = 0;
    for k in 0..poly.len() {
        let (a, b) = (poly[k], poly[(k + 1) % poly.len()]);
        // p'.y = p.y + e^2 lies strictly between rows of the grid, so an
        // edge straddles it iff exactly one end has y <= p.y.
        let (a_below, b_below) = (a.1 <= p.1, b.1 <= p.1);
        if a_below && !b_below && nudged_side(a, b, p) > 0 {
            wn += 1;
        } else if !a_below && b_below && nudged_side(a, b, p) < 0 {
            wn -= 1;
        }
    }
    wn
}

/// Panics, naming `what` and the first pixels that differ, unless `got`
/// and `want` are the same grid.
pub fn assert_same(got: &Grid, want: &Grid, what: &dyn core::fmt::Debug) {
    let d = got.diff(want);
    assert!(
        d.is_empty(),
        "{what:?}: {} pixels differ (x, y, got, want): {:?}",
        d.len(),
        &d[..d.len().min(10)]
    );
}

/// Raw coordinates of the centre of pixel `(i, j)`.
pub fn centre(i: i64, j: i64) -> (i128, i128) {
    (i128::from(i) * 4096 + 2048, i128::from(j) * 4096 + 2048)
}

/// A window of pixels with one cell per pixel.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Grid {
    pub x0: i64,
    pub y0: i64,
    pub w: usize,
    pub h: usize,
    pub cells: Vec<u32>,
}

impl Grid {
    pub fn new(x0: i64, y0: i64, w: usize, h: usize) -> Self {
        Self {
            x0,
            y0,
            w,
            h,
            cells: vec![0; w * h],
        }
    }

    pub fn clip(&self) -> Rectangle {
        Rectangle::new(
            Point::new(self.x0 as i32, self.y0 as i32),
            Size::new(self.w as u32, self.h as u32),
        )
    }

    pub fn get(&self, i: i64, j: i64) -> u32 {
        self.cells[(j - self.y0) as usize * self.w + (i - self.x0) as usize]
    }

    pub fn bump(&mut self, i: i64, j: i64) {
        assert!(
            i >= self.x0
                && j >= self.y0
                && i < self.x0 + self.w as i64
                && j < self.y0 + self.h as i64,
            "write outside the clip rectangle at ({i}, {j})"
        );
        self.cells[(j - self.y0) as usize * self.w + (i - self.x0) as usize] += 1;
    }

    /// Positions of cells whose values differ, for failure messages.
    pub fn diff(&self, other: &Grid) -> Vec<(i64, i64, u32, u32)> {
        let mut d = vec![];
        for j in 0..self.h {
            for i in 0..self.w {
                let (a, b) = (self.cells[j * self.w + i], other.cells[j * self.w + i]);
                if a != b {
                    d.push((self.x0 + i as i64, self.y0 + j as i64, a, b));
                }
            }
        }
        d
    }
}

/// The reference: 1 where `poly` covers the pixel under the sampling rule.
pub fn reference_polygon(poly: &[Vertex], x0: i64, y0: i64, w: usize, h: usize) -> Grid {
    let pts: Vec<_> = poly.iter().map(|&v| raw(v)).collect();
    let mut g = Grid::new(x0, y0, w, h);
    for j in 0..h as i64 {
        for i in 0..w as i64 {
            if winding(&pts, centre(x0 + i, y0 + j)) != 0 {
                g.bump(x0 + i, y0 + j);
            }
        }
    }
    g
}

/// The reference under a fill rule: lit where the winding number is odd
/// (`even_odd`) or non-zero.
pub fn reference_fill(
    poly: &[Vertex],
    even_odd: bool,
    x0: i64,
    y0: i64,
    w: usize,
    h: usize,
) -> Grid {
    let pts: Vec<_> = poly.iter().map(|&v| raw(v)).collect();
    let mut g = Grid::new(x0, y0, w, h);
    for j in 0..h as i64 {
        for i in 0..w as i64 {
            let wn = winding(&pts, centre(x0 + i, y0 + j));
            if (even_odd && wn % 2 != 0) || (!even_odd && wn != 0) {
                g.bump(x0 + i, y0 + j);
            }
        }
    }
    g
}

/// The row and columns of a span in `i64`, checked: not empty, and inside
/// `clip` (which may reach the ends of `i32`).
pub fn checked_span(clip: &Rectangle, s: Span) -> (i64, i64, i64) {
    let (x0, y0) = (i64::from(clip.top_left.x), i64::from(clip.top_left.y));
    let (w, h) = (i64::from(clip.size.width), i64::from(clip.size.height));
    let (xs, xe, y) = (i64::from(s.x_start), i64::from(s.x_end), i64::from(s.y));
    assert!(
        x0 <= xs && xs < xe && xe <= x0 + w,
        "{s:?} outside {clip:?}"
    );
    assert!(y0 <= y && y < y0 + h, "{s:?} outside {clip:?}");
    (y, xs, xe)
}

/// Adds one to every pixel of every span `for_each_span` yields, checking
/// that spans are non-empty, inside the window, in row order and, within a
/// row, left to right without overlap.
pub fn add_spans_from<E: core::fmt::Debug>(
    g: &mut Grid,
    for_each_span: impl FnOnce(&Rectangle, &mut dyn FnMut(Span) -> Result<(), E>) -> Result<(), E>,
) {
    let mut last: Option<(i32, i32)> = None;
    let clip = g.clip();
    for_each_span(&clip, &mut |s: Span| {
        assert!(s.x_start < s.x_end, "empty span {s:?}");
        if let Some((y, x_end)) = last {
            assert!(
                s.y > y || (s.y == y && s.x_start > x_end),
                "spans out of order at {s:?}"
            );
        }
        last = Some((s.y, s.x_end));
        for x in s.x_start..s.x_end {
            g.bump(i64::from(x), i64::from(s.y));
        }
        Ok(())
    })
    .unwrap();
}

pub fn reference_triangle(t: &Triangle, x0: i64, y0: i64, w: usize, h: usize) -> Grid {
    reference_polygon(&t.vertices, x0, y0, w, h)
}

/// The rasterizer's spans inside the window, checked for well-formedness:
/// rows strictly increasing, one non-empty span per row, inside the clip.
pub fn rasterized(t: &Triangle, x0: i64, y0: i64, w: usize, h: usize) -> Grid {
    let mut g = Grid::new(x0, y0, w, h);
    add_spans(t, &mut g);
    g
}

/// Adds one to every pixel of every span of `t` in the window of `g`.
pub fn add_spans(t: &Triangle, g: &mut Grid) {
    let mut last_row = None;
    t.for_each_span(&g.clip(), |s: Span| {
        assert!(s.x_start < s.x_end, "empty span {s:?}");
        assert!(
            last_row.is_none_or(|r| s.y > r),
            "rows out of order at {s:?}"
        );
        last_row = Some(s.y);
        for x in s.x_start..s.x_end {
            g.bump(i64::from(x), i64::from(s.y));
        }
        Ok::<(), core::convert::Infallible>(())
    })
    .unwrap();
}

/// Asserts that the rasterizer and the reference agree on the window.
pub fn assert_exact(t: &Triangle, x0: i64, y0: i64, w: usize, h: usize) {
    let got = rasterized(t, x0, y0, w, h);
    let want = reference_triangle(t, x0, y0, w, h);
    let d = got.diff(&want);
    assert!(
        d.is_empty(),
        "{t:?} in window ({x0}, {y0}) {w}x{h}: {} pixels differ (x, y, got, want): {:?}",
        d.len(),
        &d[..d.len().min(10)]
    );
}
