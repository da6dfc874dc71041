//! The `delaunay` example's command line, through
//! `embedded_raster::sim::delaunay_cli::run`: its scenes pass the
//! independent checks, and `render` draws every pixel of the hull once.

use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};

use embedded_graphics_core::geometry::Point;
use embedded_raster::sim::{cli, delaunay_cli, parse_scene, render_scene, Command};
use embedded_raster::Vertex;
use proptest::prelude::*;

use super::check::{self, Pt};
use super::common::reference_polygon;

/// A fresh path in the temp directory; removed on drop.
struct TempFile(PathBuf);

impl TempFile {
    fn new(name: &str) -> Self {
        static NEXT: AtomicUsize = AtomicUsize::new(0);
        let n = NEXT.fetch_add(1, Ordering::Relaxed);
        let file = format!("embedded-raster-delaunay-{}-{n}-{name}", std::process::id());
        let path = std::env::temp_dir().join(file);
        let _ = std::fs::remove_file(&path);
        Self(path)
    }

    fn arg(&self) -> String {
        self.0.to_str().unwrap().to_string()
    }
}

impl Drop for TempFile {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.0);
    }
}

/// Runs the command line; returns the exit code, stderr and the scene.
fn run(points: &str, extra: &[&str]) -> (i32, String, Option<String>) {
    let (input, output) = (TempFile::new("points.txt"), TempFile::new("out.scene"));
    std::fs::write(&input.0, points).unwrap();
    let mut args = vec![input.arg(), "-o".into(), output.arg()];
    args.extend(extra.iter().map(|s| s.to_string()));
    let (mut out, mut err) = (vec![], vec![]);
    let code = delaunay_cli::run(args, &mut out, &mut err);
    let err = String::from_utf8(err)
        .unwrap()
        .replace(&input.arg(), "POINTS");
    (code, err, std::fs::read_to_string(&output.0).ok())
}

/// The points of a point file, read here rather than by the code under
/// test: a point a line (`x y`, decimals), blank lines and `#` comments
/// skipped, each coordinate in raw 1/4096 px, rounded to the nearest, ties
/// to even (the scene format's rule).
fn points_of(text: &str) -> Vec<Pt> {
    let raw = |s: &str| -> i64 {
        let (neg, s) = s.strip_prefix('-').map_or((false, s), |s| (true, s));
        let (whole, frac) = s.split_once('.').unwrap_or((s, ""));
        let scale = 10i128.pow(frac.len() as u32);
        let q = format!("{whole}{frac}").parse::<i128>().unwrap() * 4096;
        let (down, rest) = (q / scale, q % scale);
        let up = 2 * rest > scale || (2 * rest == scale && down % 2 == 1);
        let r = (down + i128::from(up)) as i64;
        if neg {
            -r
        } else {
            r
        }
    };
    text.lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .map(|l| {
            let xy: Vec<&str> = l.split_whitespace().collect();
            assert_eq!(xy.len(), 2, "{l}");
            (raw(xy[0]), raw(xy[1]))
        })
        .collect()
}

/// Triangulates a point file with the example, checks the scene's
/// triangles with the checker and its rendering against the hull; returns
/// the triangle count.
fn check_point_file(text: &str, size: (u32, u32)) -> usize {
    let (code, err, scene) = run(text, &["--size", &format!("{}x{}", size.0, size.1)]);
    assert_eq!(code, cli::EXIT_OK, "{err}");
    let scene = parse_scene(&scene.unwrap()).expect("render accepts the scene");
    // The summary line counts the scene's triangles.
    let count = format!(", {} triangles\n", scene.commands().len());
    assert!(
        err.starts_with("delaunay: wrote ") && err.ends_with(&count),
        "{err}"
    );
    let points = points_of(text);
    let triangles: Vec<[Pt; 3]> = scene
        .commands()
        .iter()
        .map(|c| match c {
            Command::Tri(t, _) => t.vertices.map(|v| {
                let (x, y) = v.raw();
                (i64::from(x), i64::from(y))
            }),
            other => panic!("unexpected command {other:?}"),
        })
        .collect();
    let hull = check::check(&points, &triangles);
    check_counts(&scene, &hull, size);
    triangles.len()
}

/// `render --counts`: 1 inside the hull, 0 outside, per the sampling rule.
fn check_counts(scene: &embedded_raster::sim::Scene, hull: &[Pt], (w, h): (u32, u32)) {
    let display = render_scene(scene).display;
    let outline: Vec<Vertex> = hull
        .iter()
        .map(|&(x, y)| Vertex::from_raw(x as i32, y as i32))
        .collect();
    let want = reference_polygon(&outline, 0, 0, w as usize, h as usize);
    for j in 0..h as i64 {
        for i in 0..w as i64 {
            let got = display.write_count(Point::new(i as i32, j as i32)).unwrap();
            assert_eq!(got, want.get(i, j), "pixel ({i}, {j}) written {got} times");
        }
    }
}

#[test]
fn readme_point_file() {
    let text = std::fs::read_to_string("scenes/delaunay.points").unwrap();
    check_point_file(&text, (320, 240));
}

#[test]
fn comments_blank_lines_and_decimals() {
    let text = "# a pentagon and its centre\n\n  10 10\n\t60.5 12.25\n# more\n70 50\n35.000244140625 70\n5 45\n\n36 40\n";
    assert_eq!(check_point_file(text, (80, 80)), 5);
}

#[test]
fn grid_file() {
    let text: String = (0..100)
        .map(|k| format!("{} {}\n", 5 + 10 * (k % 10), 5 + 10 * (k / 10)))
        .collect();
    assert_eq!(check_point_file(&text, (100, 100)), 162);
}

#[test]
fn collinear_file_gives_an_empty_scene() {
    let text: String = (0..20).map(|k| format!("{k} {}\n", 2 * k)).collect();
    assert_eq!(check_point_file(&text, (64, 64)), 0);
    assert_eq!(check_point_file("", (8, 8)), 0);
}

#[test]
fn default_size_and_gouraud() {
    let (code, _, scene) = run("0 0\n100 0\n0 100\n", &[]);
    assert_eq!(code, cli::EXIT_OK);
    let scene = scene.unwrap();
    assert!(scene.contains("\nsize 320 240\n"), "{scene}");
    let (code, _, scene) = run("0 0\n100 0\n0 100\n", &["--gouraud"]);
    assert_eq!(code, cli::EXIT_OK);
    let scene = parse_scene(&scene.unwrap()).unwrap();
    assert!(matches!(scene.commands(), [Command::Gtri(..)]));
}

#[test]
fn bad_point_files_report_the_line_and_write_nothing() {
    for (text, message) in [
        ("0 0\n1\n", "POINTS:2: expected `x y`, got 1 values"),
        ("0 0\n\n1 2 3\n", "POINTS:3: expected `x y`, got 3 values"),
        ("# x\n0 nan\n", "POINTS:2: bad number `nan`"),
        ("1e3 0\n", "POINTS:1: bad number `1e3`"),
        (
            "0 0\n524288 1\n",
            "POINTS:2: coordinate out of range: `524288`",
        ),
    ] {
        let (code, err, scene) = run(text, &[]);
        assert_eq!(code, cli::EXIT_FAILURE, "{text:?}");
        assert_eq!(err, format!("{message}\n"));
        assert!(scene.is_none(), "a scene was written for {text:?}");
    }
}

#[test]
fn too_many_points_is_an_error_on_the_line_that_overflows() {
    let text: String = (0..32_768)
        .map(|k| format!("{} {}\n", k % 200, k / 200))
        .collect();
    let (code, err, scene) = run(&text, &[]);
    assert_eq!(
        (code, err.as_str()),
        (cli::EXIT_FAILURE, "POINTS:32768: more than 32767 points\n")
    );
    assert!(scene.is_none());
}

#[test]
fn bad_command_lines() {
    for extra in [
        &["--size", "0x10"][..],
        &["--size", "10"],
        &["--size"],
        &["--bogus"],
        &["second-file"],
    ] {
        let (code, err, scene) = run("0 0\n", extra);
        assert_eq!(code, cli::EXIT_USAGE, "{extra:?}");
        assert!(err.starts_with("delaunay: "), "{err}");
        assert!(scene.is_none());
    }
    let (mut out, mut err) = (vec![], vec![]);
    assert_eq!(
        delaunay_cli::run(["points.txt"], &mut out, &mut err),
        cli::EXIT_USAGE
    );
    assert!(String::from_utf8(err)
        .unwrap()
        .contains("missing `-o OUT.scene`"));
}

fn any_point_file() -> impl Strategy<Value = String> {
    let coordinate = (0u32..160 * 16).prop_map(|c| format!("{}", c as f64 / 16.0));
    prop::collection::vec((coordinate.clone(), coordinate), 0..60)
        .prop_map(|v| v.iter().map(|(x, y)| format!("{x} {y}\n")).collect())
}

/// A quarter of `PROPTEST_CASES` (proptest's default, 256, when unset),
/// so that the deep run deepens this test too: each case runs the whole
/// command line, files included.
fn a_quarter_of_the_cases() -> u32 {
    let cases = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok());
    (cases.unwrap_or(256u32) / 4).max(1)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(a_quarter_of_the_cases()))]

    #[test]
    fn any_point_file_gives_a_checked_scene(text in any_point_file()) {
        check_point_file(&text, (161, 161));
    }
}
