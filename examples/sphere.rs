//! A lit sphere with a moon passing through it, built by latitude and
//! longitude with the library's fixed-point mesh tools, rotated, projected
//! in perspective and drawn with a depth buffer, flat-shaded (each face the
//! rounded average of its vertex colours) and Gouraud-shaded.
//!
//!     cargo run --release --features sim --example sphere -- [OUT_DIR] [--strip STRIP.png]
//!
//! Writes `OUT_DIR/flat_NN.png` and `OUT_DIR/gouraud_NN.png` (default
//! `target/sphere`) for 12 frames, and with `--strip` one PNG of 6 frames:
//! flat on the top row, Gouraud below (the README's `docs/sphere.png`).
//! No floating point is used for the geometry or the shading.

use std::path::PathBuf;

use embedded_graphics_core::{
    pixelcolor::{Rgb888, RgbColor},
    prelude::*,
    primitives::Rectangle,
};
use embedded_raster::{
    mesh::{sphere, sphere_size, Camera, Rotation, Vec3, ONE},
    shade::{average_color, DepthBuffer},
    sim::SimDisplay,
    Triangle,
};

const SIZE: u32 = 160;
const FRAMES: u16 = 12;
const RINGS: u16 = 12;
const SEGMENTS: u16 = 20;
const VERTICES: usize = sphere_size(RINGS, SEGMENTS).0;
const TRIANGLES: usize = sphere_size(RINGS, SEGMENTS).1;

/// One sphere of the scene: the unit mesh placed at `centre` with `radius`
/// (Q15 fractions of the unit), in colour `base`.
struct Body {
    centre: Vec3,
    radius: i32,
    base: [u8; 3],
}

/// Lambert lighting plus ambient, all integer: `base * (ambient + diffuse)`.
fn lit(base: [u8; 3], normal: Vec3) -> Rgb888 {
    // Towards the light: up, left, towards the viewer (normalised, Q15).
    let light = Vec3::new(-15000, 18000, -22000);
    let diffuse = normal.dot(light).max(0); // Q15
    let k = i64::from(ONE / 6) + i64::from(diffuse) * 5 / 6; // Q15, <= 1
    let c = base.map(|b| ((i64::from(b) * k) >> 15) as u8);
    Rgb888::new(c[0], c[1], c[2])
}

fn scale(v: Vec3, s: i32) -> Vec3 {
    let m = |a: i32| ((i64::from(a) * i64::from(s)) >> 15) as i32;
    Vec3::new(m(v.x), m(v.y), m(v.z))
}

/// Draws frame `f` on a fresh display, flat (`gouraud == false`) or
/// Gouraud-shaded, with depth.
fn frame(
    f: u16,
    gouraud: bool,
    mesh: &([Vec3; VERTICES], [[u16; 3]; TRIANGLES]),
) -> SimDisplay<Rgb888> {
    let mut display = SimDisplay::new(SIZE, SIZE, Rgb888::new(12, 14, 24));
    let mut storage = vec![0u16; (SIZE * SIZE) as usize];
    let depth = DepthBuffer::new(&mut storage, SIZE);
    depth.clear();
    let camera = Camera {
        focal: 190,
        centre: (SIZE as i32 / 2, SIZE as i32 / 2),
        near: 2 * ONE,
        far: 5 * ONE,
    };
    let turn = (u32::from(f) * 65536 / u32::from(FRAMES)) as u16;
    // The moon orbits through the planet's surface.
    let (s, c) = embedded_raster::mesh::sin_cos(turn);
    let bodies = [
        Body {
            centre: Vec3::new(0, 0, 0),
            radius: ONE,
            base: [70, 140, 255],
        },
        Body {
            centre: Vec3::new(c * 7 / 8, ONE / 4, s * 7 / 8),
            radius: 2 * ONE / 5,
            base: [255, 170, 60],
        },
    ];
    let spin = Rotation::new(turn, 0);
    let tilt = Rotation::new(0, 65535 - 3000);
    let (vertices, triangles) = mesh;
    for body in &bodies {
        let mut screen = [(embedded_raster::Vertex::default(), 0u16); VERTICES];
        let mut colors = [Rgb888::BLACK; VERTICES];
        for (k, v) in vertices.iter().enumerate() {
            // The unit sphere's vertices are their own normals. The spin
            // is visible through the facets of the flat-shaded sphere.
            let normal = tilt.apply(spin.apply(*v));
            let on = scale(spin.apply(*v), body.radius);
            let p = tilt.apply(Vec3::new(
                on.x + body.centre.x,
                on.y + body.centre.y,
                on.z + body.centre.z,
            ));
            let p = Vec3::new(p.x, p.y, p.z + 7 * ONE / 2);
            screen[k] = camera.project(p).expect("in front of the camera");
            colors[k] = lit(body.base, normal);
        }
        for tri in triangles {
            let [a, b, c] = tri.map(usize::from);
            let t = Triangle::new(screen[a].0, screen[b].0, screen[c].0);
            let z = [screen[a].1, screen[b].1, screen[c].1];
            let vc = [colors[a], colors[b], colors[c]];
            let Ok(()) = if gouraud {
                t.gouraud(vc).with_depth(z, depth).draw(&mut display)
            } else {
                t.fill(average_color(vc))
                    .with_depth(z, depth)
                    .draw(&mut display)
            };
        }
    }
    display
}

fn main() -> std::io::Result<()> {
    let mut out = PathBuf::from("target/sphere");
    let mut strip_path = None;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--strip" => strip_path = args.next().map(PathBuf::from),
            _ => out = PathBuf::from(a),
        }
    }
    std::fs::create_dir_all(&out)?;

    let mut vertices = [Vec3::default(); VERTICES];
    let mut triangles = [[0u16; 3]; TRIANGLES];
    sphere(RINGS, SEGMENTS, &mut vertices, &mut triangles).expect("storage sized by sphere_size");
    let mesh = (vertices, triangles);

    const STRIP: u16 = 6;
    let mut strip = SimDisplay::new(SIZE * u32::from(STRIP), 2 * SIZE, Rgb888::BLACK);
    for f in 0..FRAMES {
        for (row, gouraud) in [(0, false), (1, true)] {
            let d = frame(f, gouraud, &mesh);
            let name = if gouraud { "gouraud" } else { "flat" };
            d.save_png(out.join(format!("{name}_{f:02}.png")))?;
            if f % (FRAMES / STRIP) == 0 {
                let column = i32::from(f / (FRAMES / STRIP));
                let at = Point::new(column * SIZE as i32, row * SIZE as i32);
                let Ok(()) = strip.fill_contiguous(
                    &Rectangle::new(at, Size::new(SIZE, SIZE)),
                    d.pixels().iter().copied(),
                );
            }
        }
    }
    if let Some(path) = strip_path {
        strip.save_png(&path)?;
        println!("wrote {}", path.display());
    }
    println!("wrote {} frames to {}", 2 * FRAMES, out.display());
    Ok(())
}
