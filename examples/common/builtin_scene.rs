//! The built-in scene the firmware draws, and the checksum it prints.
//!
//! One file, compiled into the Cortex-M firmware (`examples/firmware.rs`,
//! `examples/icount.rs`, `examples/size_triangles.rs`) and into the host
//! test `tests/firmware_scene.rs` through `#[path]`, so both sides run the
//! very same drawing code. Plain `core`: no std, no alloc, no floats; every
//! coordinate is an exact 20.12 value.
//!
//! The scene, drawn in this order on a 320 x 240 `Rgb565` framebuffer:
//!
//! 1. a clear and rectangles, one of them partly and one wholly
//!    off-screen;
//! 2. a huge triangle (corners ~400 000 px away) whose only visible edge
//!    crosses the screen: the 64-bit edge path ([`HUGE`]);
//! 3. a large triangle with fractional corners;
//! 4. a jittered mesh of triangles sharing edges ([`for_each_mesh_triangle`]);
//! 5. a fan of medium triangles around one centre;
//! 6. a grid of small and sub-pixel triangles at fractional offsets;
//! 7. lines: a star of 1-pixel lines in every octant, lines with far
//!    off-screen ends (clipped before stepping), thick lines and a
//!    polyline.
//! 8. polygons: a concave star (non-zero rule) and a self-intersecting
//!    pentagram (even-odd rule, so its centre stays empty).

// The scene is a sequence of display-list commands
// ([`for_each_command`]): `firmware` draws them one after the other on a
// whole framebuffer, `firmware_bands` records them in a display list and
// renders it in bands. Each includer uses a different part of this file.
#![allow(dead_code)]

use embedded_graphics_core::{
    draw_target::DrawTarget,
    geometry::{Point, Size},
    pixelcolor::Rgb565,
    primitives::Rectangle,
    Drawable,
};
use embedded_raster::{
    band::Command,
    framebuffer::{buffer_size, Rgb565Le},
    FillRule, Framebuffer, Line, Polygon, Polyline, Triangle, Vertex,
};

/// Width of the scene in pixels.
pub const WIDTH: usize = 320;
/// Height of the scene in pixels.
pub const HEIGHT: usize = 240;

/// The framebuffer the firmware renders into: 153 600 bytes.
pub type SceneBuffer =
    Framebuffer<Rgb565Le, WIDTH, HEIGHT, { buffer_size::<Rgb565Le>(WIDTH, HEIGHT) }>;

/// The whole screen, the clip every triangle of the scene is drawn with.
pub const SCREEN: Rectangle =
    Rectangle::new(Point::new(0, 0), Size::new(WIDTH as u32, HEIGHT as u32));

/// A vertex at whole pixel coordinates (a pixel corner).
pub const fn px(x: i32, y: i32) -> Vertex {
    Vertex::from_raw(x * 4096, y * 4096)
}

/// The line both [`HUGE`] and [`TWIN`] share as their edge `a -> b`:
/// `(160, 120) + t (20, -7)`.
const fn on_line(t: i32) -> Vertex {
    px(160 + 20 * t, 120 - 7 * t)
}

/// A huge triangle, corners about 400 000 px off-screen; its edge on the
/// line through (160, 120) with direction (20, -7) crosses the screen and
/// it covers everything below that line. Its edge values over the screen
/// do not fit in 32 bits: it takes the 64-bit path.
pub const HUGE: Triangle = Triangle::new(
    on_line(-20_000),
    on_line(20_000),
    px(160 + 7 * 20_000, 120 + 20 * 20_000),
);

/// A triangle lighting exactly the same pixels of the screen as [`HUGE`]
/// (same edge line, the other two edges just off-screen) that takes the
/// 32-bit path.
pub const TWIN: Triangle = Triangle::new(on_line(-12), on_line(12), px(160, 1200));

/// An irregular triangle in the `size` x `size` px cell at `(x, y)`, with
/// corners at 5 %/10 %, 98 %/35 % and 30 %/97 % of the cell (as in the
/// host benchmark).
pub fn irregular(x: i32, y: i32, size: i32) -> Triangle {
    let at = |px: i32, percent: i32| px * 4096 + size * 4096 * percent / 100;
    Triangle::new(
        Vertex::from_raw(at(x, 5), at(y, 10)),
        Vertex::from_raw(at(x, 98), at(y, 35)),
        Vertex::from_raw(at(x, 30), at(y, 97)),
    )
}

/// Line `k` of a star of 1-pixel lines `len` px long through the screen's
/// centre, in 8 directions (horizontal, 2:1, diagonal, 1:2, vertical and
/// their mirrors), moved right by `k / 8` px.
pub fn star_line(k: i32, len: i32) -> Line {
    const DIRECTIONS: [(i32, i32); 8] = [
        (2, 0),
        (2, 1),
        (2, 2),
        (1, 2),
        (0, 2),
        (-1, 2),
        (-2, 2),
        (-2, 1),
    ];
    let (dx, dy) = DIRECTIONS[k.rem_euclid(8) as usize];
    let half = Point::new(dx * len / 4, dy * len / 4);
    let centre = Point::new(160 + k / 8, 120);
    Line::new(centre - half, centre + half)
}

/// [`star_line`] moved right so that its centre lies 2 px inside the
/// screen's right edge (column 318): all but the vertical lines are cut
/// by the clip.
pub fn edge_star_line(k: i32, len: i32) -> Line {
    let line = star_line(k, len);
    let right = Point::new(158 - k / 8, 0);
    Line::new(line.start + right, line.end + right)
}

/// A random line the screen's edges cut: ends anywhere in a box of three
/// screens by three centred on the screen, at least one of them off it,
/// and some pixel on it (lines that miss the screen are drawn again from
/// `rng`). Every slope and length, cut on any side.
pub fn cut_line(rng: &mut Rng) -> Line {
    let (w, h) = (WIDTH as i32, HEIGHT as i32);
    loop {
        let mut end = || Point::new(w / 2 + rng.signed(3 * w / 2), h / 2 + rng.signed(3 * h / 2));
        let line = Line::new(end(), end());
        let lit = line.for_each_run(&SCREEN, |_| Err(())).is_err();
        if lit && !(SCREEN.contains(line.start) && SCREEN.contains(line.end)) {
            return line;
        }
    }
}

/// A random thick line as in the host bench's sets (`benches/lines.rs`):
/// 2 to 12 px wide, both ends at least 8 px inside the screen; a `short`
/// one ends within 24 px of its start along each axis.
pub fn random_thick_line(rng: &mut Rng, short: bool) -> (Line, u32) {
    let (w, h) = (WIDTH as i32, HEIGHT as i32);
    let end =
        |rng: &mut Rng| Point::new(w / 2 + rng.signed(w / 2 - 8), h / 2 + rng.signed(h / 2 - 8));
    let a = end(rng);
    let b = match short {
        true => {
            let d = Point::new(rng.signed(24), rng.signed(24));
            (a + d)
                .component_max(Point::new(8, 8))
                .component_min(Point::new(w - 9, h - 9))
        }
        false => end(rng),
    };
    (Line::new(a, b), 2 + rng.next_u32() % 11)
}

/// A small deterministic generator (xorshift32).
#[derive(Debug, Clone)]
pub struct Rng(u32);

impl Rng {
    /// A generator from a non-zero seed.
    pub const fn new(seed: u32) -> Self {
        Self(seed)
    }

    /// The next 32 random bits.
    pub fn next_u32(&mut self) -> u32 {
        let mut x = self.0;
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        self.0 = x;
        x
    }

    /// A value in `-range..=range`.
    pub fn signed(&mut self, range: i32) -> i32 {
        (self.next_u32() % (2 * range as u32 + 1)) as i32 - range
    }

    /// A colour.
    pub fn color(&mut self) -> Rgb565 {
        let v = self.next_u32();
        Rgb565::new(
            (v & 31) as u8,
            ((v >> 5) & 63) as u8,
            ((v >> 11) & 31) as u8,
        )
    }
}

/// Cells of the mesh, across and down.
pub const MESH_COLS: i32 = 8;
/// Cells of the mesh, across and down.
pub const MESH_ROWS: i32 = 6;
/// Side of a mesh cell in pixels.
pub const MESH_CELL: i32 = 18;
/// The pixels the mesh covers: every one exactly once.
pub const MESH_AREA: Rectangle = Rectangle::new(
    Point::new(168, 8),
    Size::new(
        (MESH_COLS * MESH_CELL) as u32,
        (MESH_ROWS * MESH_CELL) as u32,
    ),
);

/// Calls `f` with each triangle of a jittered grid mesh over
/// [`MESH_AREA`] and its colour. Border vertices sit on pixel corners of
/// the area's outline; inner ones are moved by up to ±1.46 px in raw 1/4096
/// steps. Neighbouring triangles share their edges exactly, so the mesh
/// lights each pixel of the area once.
pub fn for_each_mesh_triangle<E>(
    mut f: impl FnMut(Triangle, Rgb565) -> Result<(), E>,
) -> Result<(), E> {
    const STRIDE: usize = (MESH_COLS + 1) as usize;
    let mut grid = [[Vertex::from_raw(0, 0); STRIDE]; (MESH_ROWS + 1) as usize];
    let mut rng = Rng::new(0x2545_f491);
    // Iterators rather than indices: no bounds check, so no panic path is
    // linked into the code-size firmware.
    for (j, row) in (0..).zip(grid.iter_mut()) {
        for (i, vertex) in (0..).zip(row.iter_mut()) {
            let x = (MESH_AREA.top_left.x + i * MESH_CELL) * 4096;
            let y = (MESH_AREA.top_left.y + j * MESH_CELL) * 4096;
            let inner = i > 0 && i < MESH_COLS && j > 0 && j < MESH_ROWS;
            let (dx, dy) = if inner {
                (rng.signed(6000), rng.signed(6000))
            } else {
                (0, 0)
            };
            *vertex = Vertex::from_raw(x + dx, y + dy);
        }
    }
    for (j, (upper, lower)) in grid.iter().zip(grid.iter().skip(1)).enumerate() {
        let cells = upper.windows(2).zip(lower.windows(2));
        for (i, (top, bottom)) in cells.enumerate() {
            let (&[a, b], &[c, d]) = (top, bottom) else {
                continue;
            };
            // Alternate the diagonal, so both orientations of shared edges occur.
            let (t0, t1) = if (i + j) % 2 == 0 {
                (Triangle::new(a, b, d), Triangle::new(a, d, c))
            } else {
                (Triangle::new(a, b, c), Triangle::new(b, d, c))
            };
            f(t0, rng.color())?;
            f(t1, rng.color())?;
        }
    }
    Ok(())
}

/// Draws the mesh of [`for_each_mesh_triangle`].
pub fn draw_mesh<D: DrawTarget<Color = Rgb565>>(target: &mut D) -> Result<(), D::Error> {
    for_each_mesh_triangle(|t, color| t.fill(color).draw(target))
}

/// A command of the scene; polygons hold up to 12 vertices.
pub type SceneCommand<'a> = Command<'a, Rgb565, 12>;

/// The vertex and point arrays the scene's polygons and polyline borrow.
pub struct SceneShapes {
    star: [Vertex; 12],
    pentagram: [Vertex; 5],
    polyline: [Point; 5],
}

impl SceneShapes {
    /// The scene's shapes.
    pub fn new() -> Self {
        Self {
            star: star((60, 60), 50, 22),
            pentagram: pentagram((250, 185), 45),
            polyline: [
                Point::new(5, 235),
                Point::new(60, 190),
                Point::new(90, 232),
                Point::new(140, 200),
                Point::new(160, 236),
            ],
        }
    }
}

/// Calls `f` with each command of the built-in scene, in drawing order
/// (see the file's docs).
pub fn for_each_command<'a, E>(
    shapes: &'a SceneShapes,
    mut f: impl FnMut(SceneCommand<'a>) -> Result<(), E>,
) -> Result<(), E> {
    // 1. Clear and rectangles.
    f(Command::Clear(Rgb565::new(2, 5, 8)))?;
    let rect = |x: i32, y: i32, w: u32, h: u32| Rectangle::new(Point::new(x, y), Size::new(w, h));
    f(Command::Rect(rect(4, 4, 150, 100), Rgb565::new(6, 12, 20)))?;
    f(Command::Rect(
        rect(-20, 180, 70, 90),
        Rgb565::new(28, 40, 4),
    ))?;
    f(Command::Rect(
        rect(300, 100, 40, 10),
        Rgb565::new(31, 0, 31),
    ))?;
    f(Command::Rect(
        rect(400, 10, 10, 10),
        Rgb565::new(31, 63, 31),
    ))?;

    // 2. The 64-bit path.
    f(Command::Triangle(HUGE.fill(Rgb565::new(4, 20, 10))))?;

    // 3. A large triangle at fractional coordinates (raw 1/4096 units).
    let large = Triangle::new(
        Vertex::from_raw(10 * 4096 + 1234, 20 * 4096 + 77),
        Vertex::from_raw(150 * 4096 + 2048, 60 * 4096 + 3001),
        Vertex::from_raw(40 * 4096 + 5, 230 * 4096 + 4095),
    );
    f(Command::Triangle(large.fill(Rgb565::new(31, 30, 2))))?;

    // 4. The shared-edge mesh.
    for_each_mesh_triangle(|t, color| f(Command::Triangle(t.fill(color))))?;

    // 5. A fan of medium triangles around (80, 170).
    let fan = [
        (0, -40),
        (30, -28),
        (40, 0),
        (28, 30),
        (0, 42),
        (-29, 29),
        (-41, 0),
        (-27, -27),
    ];
    let centre = Vertex::from_raw(80 * 4096 + 1000, 170 * 4096 + 3000);
    let mut rng = Rng::new(0x9e37_79b9);
    for k in 0..fan.len() {
        let (x0, y0) = fan[k];
        let (x1, y1) = fan[(k + 1) % fan.len()];
        let p = |x: i32, y: i32| Vertex::from_raw((80 + x) * 4096, (170 + y) * 4096 + 512);
        f(Command::Triangle(
            Triangle::new(centre, p(x0, y0), p(x1, y1)).fill(rng.color()),
        ))?;
    }

    // 6. Small and sub-pixel triangles: a 14 x 10 grid of 10 px cells, the
    // triangle in each from 1 to 10 px across, at a fractional offset.
    for j in 0..10 {
        for i in 0..14 {
            let size = 1 + (i + j) % 10;
            let mut t = irregular(170 + i * 10, 125 + j * 11, size);
            let (ox, oy) = ((i * 577) % 4096, (j * 1129) % 4096);
            for v in &mut t.vertices {
                let (x, y) = v.raw();
                *v = Vertex::from_raw(x + ox, y + oy);
            }
            f(Command::Triangle(t.fill(rng.color())))?;
        }
    }

    // 7. Lines.
    for_each_line_command(shapes, &mut rng, &mut f)?;

    // 8. Polygons (their vertex counts are within the capacity).
    if let Ok(star) = Polygon::<12>::new(&shapes.star) {
        f(Command::Polygon(star.fill(Rgb565::new(31, 45, 10))))?;
    }
    if let Ok(pentagram) = Polygon::<12>::new(&shapes.pentagram) {
        let filled = pentagram.fill(Rgb565::new(10, 60, 31));
        f(Command::Polygon(filled.with_rule(FillRule::EvenOdd)))?;
    }
    Ok(())
}

/// Draws the whole built-in scene, command by command.
pub fn draw_scene<D: DrawTarget<Color = Rgb565>>(target: &mut D) -> Result<(), D::Error> {
    let shapes = SceneShapes::new();
    for_each_command(&shapes, |command| command.draw(target))
}

/// Unit vectors every 30 degrees, times 4096 (so `r` px along one is `r`
/// times it in raw units), rounded.
const DIRS_30: [(i32, i32); 12] = [
    (4096, 0),
    (3547, 2048),
    (2048, 3547),
    (0, 4096),
    (-2048, 3547),
    (-3547, 2048),
    (-4096, 0),
    (-3547, -2048),
    (-2048, -3547),
    (0, -4096),
    (2048, -3547),
    (3547, -2048),
];

/// The vertex `r` px from pixel corner `centre` along `dir`.
fn polar(centre: (i32, i32), dir: (i32, i32), r: i32) -> Vertex {
    Vertex::from_raw(centre.0 * 4096 + dir.0 * r, centre.1 * 4096 + dir.1 * r)
}

/// A concave star of 12 vertices around `centre`, radii alternating
/// between `outer` and `inner` px.
pub fn star(centre: (i32, i32), outer: i32, inner: i32) -> [Vertex; 12] {
    let mut k = 0;
    DIRS_30.map(|d| {
        k += 1;
        polar(centre, d, if k % 2 == 1 { outer } else { inner })
    })
}

/// A regular hexagon of radius `r` px around `centre`.
pub fn hexagon(centre: (i32, i32), r: i32) -> [Vertex; 6] {
    core::array::from_fn(|k| polar(centre, DIRS_30[2 * k], r))
}

/// A pentagram (a self-intersecting 5-point star) of radius `r` px
/// around `centre`: the corners of a regular pentagon taken every second.
pub fn pentagram(centre: (i32, i32), r: i32) -> [Vertex; 5] {
    // Unit vectors every 72 degrees from straight up, times 4096.
    const DIRS_72: [(i32, i32); 5] = [
        (0, -4096),
        (3895, -1266),
        (2408, 3314),
        (-2408, 3314),
        (-3895, -1266),
    ];
    [0, 2, 4, 1, 3].map(|k| polar(centre, DIRS_72[k], r))
}

/// A line through (160, 120) whose ends are about 10^6 px off-screen.
pub const FAR_LINE: Line = Line::new(
    Point::new(-999_839, -333_213),
    Point::new(2_000_158, 666_787),
);

/// The lines of the scene (step 7 of [`for_each_command`]).
fn for_each_line_command<'a, E>(
    shapes: &'a SceneShapes,
    rng: &mut Rng,
    f: &mut impl FnMut(SceneCommand<'a>) -> Result<(), E>,
) -> Result<(), E> {
    // A star of 1-pixel lines around (250, 180), through every octant.
    let centre = Point::new(250, 180);
    for k in 0..24 {
        let (dx, dy) = (rng.signed(60), rng.signed(55));
        let end = centre + Point::new(dx, dy + k % 3);
        f(Command::Line(Line::new(centre, end).stroke(rng.color())))?;
    }
    // Ends far off-screen: only the visible pixels are stepped.
    f(Command::Line(FAR_LINE.stroke(Rgb565::new(31, 63, 0))))?;
    let across = Line::new(Point::new(i32::MIN, 239), Point::new(i32::MAX, 0));
    f(Command::Line(across.stroke(Rgb565::new(0, 63, 31))))?;
    // Thick lines.
    for (k, width) in [2u32, 3, 5, 8].into_iter().enumerate() {
        let y = 110 + 12 * k as i32;
        let line = Line::new(Point::new(10, y), Point::new(150, y + 25 - 10 * k as i32));
        f(Command::ThickLine(
            line.stroke(rng.color()).stroke_width(width),
        ))?;
    }
    // A polyline.
    let polyline = Polyline::new(&shapes.polyline).stroke(Rgb565::new(31, 20, 0));
    f(Command::Polyline(polyline))
}

/// FNV-1a, 32 bits, of `bytes`.
pub fn fnv1a32(bytes: &[u8]) -> u32 {
    fnv1a32_more(FNV1A32_START, bytes)
}

/// The FNV-1a hash of no bytes.
pub const FNV1A32_START: u32 = 0x811c_9dc5;

/// The FNV-1a hash of the bytes hashed into `hash` followed by `bytes`:
/// a frame's checksum from its bands, in order.
pub fn fnv1a32_more(hash: u32, bytes: &[u8]) -> u32 {
    bytes.iter().fold(hash, |hash, &b| {
        (hash ^ u32::from(b)).wrapping_mul(0x0100_0193)
    })
}

/// Renders the scene into `fb` and returns the checksum of its bytes.
pub fn render(fb: &mut SceneBuffer) -> u32 {
    let Ok(()) = draw_scene(fb);
    fnv1a32(fb.as_bytes())
}
