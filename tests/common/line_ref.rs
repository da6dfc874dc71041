//! The exact line reference, shared by `tests/line.rs` and `tests/fuzz.rs`.
//!
//! It takes the stated rule literally: for each major-axis coordinate, the
//! ideal minor coordinate as an exact `i128` fraction, rounded to the
//! nearest integer with ties to the smaller one. It shares nothing with the
//! stepping code (no decision variable, no clipping algebra): it simply
//! evaluates every column (row) of a window.

#![allow(dead_code)]

use embedded_graphics_core::{
    geometry::{Point, Size},
    primitives::Rectangle,
};

const MIN: i64 = i32::MIN as i64;
const MAX: i64 = i32::MAX as i64;

/// A window of pixels `x0..x0 + w`, `y0..y0 + h`, clamped into `i32`.
#[derive(Debug, Clone, Copy)]
pub struct Window {
    pub x0: i64,
    pub y0: i64,
    pub w: i64,
    pub h: i64,
}

impl Window {
    pub fn around(x: i64, y: i64, w: i64, h: i64) -> Self {
        let x0 = (x - w / 2).clamp(MIN, MAX - w + 1);
        let y0 = (y - h / 2).clamp(MIN, MAX - h + 1);
        Self { x0, y0, w, h }
    }

    pub fn rect(&self) -> Rectangle {
        Rectangle::new(
            Point::new(self.x0 as i32, self.y0 as i32),
            Size::new(self.w as u32, self.h as u32),
        )
    }

    pub fn contains(&self, x: i64, y: i64) -> bool {
        (self.x0..self.x0 + self.w).contains(&x) && (self.y0..self.y0 + self.h).contains(&y)
    }
}

/// The nearest integer to `num / den` (`den > 0`), ties to the smaller:
/// the smallest integer `n` with `n >= num / den - 1/2`, i.e.
/// `ceil((2 num - den) / (2 den))`.
pub fn round_ties_down(num: i128, den: i128) -> i128 {
    TIE.with(|t| t.set((2 * num - den).rem_euclid(2 * den) == 0));
    let (n, d) = (2 * num - den, 2 * den);
    -((-n).div_euclid(d))
}

thread_local! {
    /// Whether the last rounding by `round_ties_down` was a tie.
    pub static TIE: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// The reference minor coordinate at major coordinate `t` of the line, or
/// `None` if `t` is outside its major range. Returns `(x_major, minor)`.
pub fn ideal_minor(a: Point, b: Point, t: i64) -> (bool, Option<i64>) {
    let (ax, ay, bx, by) = (a.x as i128, a.y as i128, b.x as i128, b.y as i128);
    let x_major = (bx - ax).abs() >= (by - ay).abs();
    let (a_maj, a_min, b_maj, b_min) = if x_major {
        (ax, ay, bx, by)
    } else {
        (ay, ax, by, bx)
    };
    let t = t as i128;
    if t < a_maj.min(b_maj) || t > a_maj.max(b_maj) {
        return (x_major, None);
    }
    if a_maj == b_maj {
        return (x_major, Some(a_min as i64));
    }
    // minor = a_min + (b_min - a_min) (t - a_maj) / (b_maj - a_maj)
    let (mut num, mut den) = (
        a_min * (b_maj - a_maj) + (b_min - a_min) * (t - a_maj),
        b_maj - a_maj,
    );
    if den < 0 {
        (num, den) = (-num, -den);
    }
    (x_major, Some(round_ties_down(num, den) as i64))
}

/// The reference pixels inside `win`, as (x, y) in order.
pub fn reference(a: Point, b: Point, win: Window) -> Vec<(i64, i64)> {
    let (x_major, _) = ideal_minor(a, b, 0);
    let (lo, len) = if x_major {
        (win.x0, win.w)
    } else {
        (win.y0, win.h)
    };
    let mut out = vec![];
    for t in lo..lo + len {
        if let (_, Some(m)) = ideal_minor(a, b, t) {
            let (x, y) = if x_major { (t, m) } else { (m, t) };
            if win.contains(x, y) {
                out.push((x, y));
            }
        }
    }
    out.sort();
    out
}
