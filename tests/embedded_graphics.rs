//! What the README's "Using it with embedded-graphics" says about the
//! pixels each crate lights, checked on random shapes: embedded-graphics
//! 0.8 drawing onto the simulator beside this crate's shapes converted
//! from the same embedded-graphics shapes (feature `embedded-graphics`).
#![cfg(all(feature = "sim", feature = "embedded-graphics"))]

use std::collections::BTreeSet;

use embedded_graphics::{
    pixelcolor::BinaryColor,
    prelude::*,
    primitives::{Line as EgLine, PrimitiveStyle, Triangle as EgTriangle},
};
use embedded_raster::{sim::SimDisplay, Line, Triangle};

#[path = "common/rng.rs"]
mod rng;
use rng::Rng;

const SIDE: i32 = 48;

/// The lit pixels of a display, and whether any was written twice.
fn lit(d: &SimDisplay<BinaryColor>) -> (BTreeSet<(i32, i32)>, bool) {
    let mut set = BTreeSet::new();
    let mut twice = false;
    for y in 0..SIDE {
        for x in 0..SIDE {
            let p = Point::new(x, y);
            if d.pixel(p) == Some(BinaryColor::On) {
                set.insert((x, y));
            }
            twice |= d.write_count(p).unwrap() > 1;
        }
    }
    (set, twice)
}

fn display() -> SimDisplay<BinaryColor> {
    SimDisplay::new(SIDE as u32, SIDE as u32, BinaryColor::Off)
}

fn eg_line(a: Point, b: Point) -> BTreeSet<(i32, i32)> {
    let mut d = display();
    let style = PrimitiveStyle::with_stroke(BinaryColor::On, 1);
    EgLine::new(a, b).into_styled(style).draw(&mut d).unwrap();
    lit(&d).0
}

fn our_line(a: Point, b: Point) -> BTreeSet<(i32, i32)> {
    let mut d = display();
    Line::from(EgLine::new(a, b))
        .stroke(BinaryColor::On)
        .draw(&mut d)
        .unwrap();
    lit(&d).0
}

/// Whether the ideal line from `a` to `b` passes exactly midway between
/// two pixels at some column (x-major) or row (y-major): `2 k minor`
/// is an odd multiple of `major` for a step `k` strictly inside.
fn has_tie(a: Point, b: Point) -> bool {
    let (dx, dy) = (i64::from((b.x - a.x).abs()), i64::from((b.y - a.y).abs()));
    let (major, minor) = if dx >= dy { (dx, dy) } else { (dy, dx) };
    (1..major).any(|k| (2 * k * minor) % (2 * major) == major)
}

/// Lines differ only at ties, and embedded-graphics breaks a tie towards
/// the start's minor-axis coordinate: drawn from the end with the smaller
/// minor-axis coordinate, it lights exactly this crate's pixels.
#[test]
fn lines_differ_only_at_ties_and_match_from_the_smaller_end() {
    let mut rng = Rng(0x5eed_0001);
    let mut differing = 0;
    for _ in 0..2000 {
        let mut point = || Point::new(rng.below(SIDE as u64) as i32, rng.below(SIDE as u64) as i32);
        let (a, b) = (point(), point());
        let ours = our_line(a, b);
        assert_eq!(ours, our_line(b, a), "ours is symmetric");
        let x_major = (b.x - a.x).abs() >= (b.y - a.y).abs();
        let (from, to) = match x_major {
            true if a.y <= b.y => (a, b),
            false if a.x <= b.x => (a, b),
            _ => (b, a),
        };
        assert_eq!(eg_line(from, to), ours, "{from:?} -> {to:?}");
        let reverse = eg_line(to, from);
        if reverse != ours {
            differing += 1;
            assert!(has_tie(a, b), "{a:?} {b:?} differ without a tie");
        }
    }
    // A quarter to a third of random lines have a tie: the claim is not
    // vacuous.
    assert!(differing > 300, "{differing}");
}

/// Triangles with integer vertices: every pixel this crate lights,
/// embedded-graphics lights too; it adds pixels on the right and bottom
/// edges, so two triangles sharing an edge write pixels twice, which this
/// crate never does.
#[test]
fn triangles_are_a_subset_and_tile_without_overdraw() {
    let mut rng = Rng(0x5eed_0002);
    let mut extra = 0usize;
    let mut eg_overdraws = 0;
    for _ in 0..500 {
        let mut point = || Point::new(rng.below(SIDE as u64) as i32, rng.below(SIDE as u64) as i32);
        let [a, b, c, d] = [point(), point(), point(), point()];
        let (first, second) = (EgTriangle::new(a, b, c), EgTriangle::new(a, c, d));

        let mut theirs = display();
        first
            .into_styled(PrimitiveStyle::with_fill(BinaryColor::On))
            .draw(&mut theirs)
            .unwrap();
        let (eg_first, _) = lit(&theirs);
        second
            .into_styled(PrimitiveStyle::with_fill(BinaryColor::On))
            .draw(&mut theirs)
            .unwrap();
        eg_overdraws += usize::from(lit(&theirs).1);

        let mut ours = display();
        Triangle::try_from(first)
            .unwrap()
            .fill(BinaryColor::On)
            .draw(&mut ours)
            .unwrap();
        let (our_first, _) = lit(&ours);
        assert!(our_first.is_subset(&eg_first), "{first:?}");
        extra += eg_first.len() - our_first.len();
        // The second triangle shares the edge a-c; when the quadrilateral is
        // convex with b and d on opposite sides, the two tile it.
        let cross = |p: Point| {
            i64::from(c.x - a.x) * i64::from(p.y - a.y)
                - i64::from(c.y - a.y) * i64::from(p.x - a.x)
        };
        if cross(b).signum() * cross(d).signum() < 0 {
            Triangle::try_from(second)
                .unwrap()
                .fill(BinaryColor::On)
                .draw(&mut ours)
                .unwrap();
            assert!(
                !lit(&ours).1,
                "overdraw on the shared edge of {first:?} {second:?}"
            );
        }
    }
    assert!(extra > 0 && eg_overdraws > 100, "{extra} {eg_overdraws}");
}

/// The README's example triangle: 45 pixels here, 55 there.
#[test]
fn the_readme_triangle() {
    let eg = EgTriangle::new(Point::new(0, 0), Point::new(9, 0), Point::new(0, 9));
    let mut theirs = display();
    eg.into_styled(PrimitiveStyle::with_fill(BinaryColor::On))
        .draw(&mut theirs)
        .unwrap();
    let mut ours = display();
    Triangle::try_from(eg)
        .unwrap()
        .fill(BinaryColor::On)
        .draw(&mut ours)
        .unwrap();
    // Ours: centres with x + y < 9 (the hypotenuse is a right edge): 45.
    // Theirs: x + y <= 9: 55.
    let count = |f: fn(i32) -> bool| {
        (0..10)
            .flat_map(|y| (0..10).map(move |x| x + y))
            .filter(|&s| f(s))
            .count()
    };
    assert_eq!(lit(&ours).0.len(), count(|s| s < 9));
    assert_eq!(lit(&theirs).0.len(), count(|s| s <= 9));
}
