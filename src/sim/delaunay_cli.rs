//! The command line of the `delaunay` example: triangulates a point file
//! and writes a scene that `render` draws. A library function, like
//! [`cli::run`](super::cli::run), so that it can be tested in-process.
//!
//! ```text
//! delaunay POINTS -o OUT.scene [--size WxH] [--gouraud]
//! ```
//!
//! A point file holds one `x y` pair per line, decimal numbers as in scene
//! files (snapped to 1/4096, ties to even); blank lines and lines whose
//! first non-blank character is `#` are ignored.
//!
//! # Examples
//!
//! ```
//! use embedded_raster::sim::{cli, delaunay_cli};
//!
//! let (mut out, mut err) = (Vec::new(), Vec::new());
//! assert_eq!(delaunay_cli::run(["--help"], &mut out, &mut err), cli::EXIT_OK);
//! assert!(String::from_utf8(out)?.starts_with("usage: delaunay POINTS"));
//! # Ok::<(), std::string::FromUtf8Error>(())
//! ```

use std::ffi::OsString;
use std::fmt::Write as _;
use std::format;
use std::io::Write;
use std::path::PathBuf;
use std::prelude::rust_2021::*;

use super::cli::{run_parsed, OneLine};
#[cfg(doc)]
use super::cli::{EXIT_FAILURE, EXIT_OK, EXIT_USAGE};
use super::scene::vertex;
use super::SceneError;
use crate::delaunay::{Delaunay, MAX_POINTS};
use crate::vertex::Vertex;

/// The help text, printed by `--help` (on stdout) and after a usage error
/// (on stderr).
///
/// # Examples
///
/// ```
/// assert!(embedded_raster::sim::delaunay_cli::USAGE.contains("--size WxH"));
/// ```
pub const USAGE: &str = "\
usage: delaunay POINTS -o OUT.scene [--size WxH] [--gouraud]

Triangulates the points (Delaunay, exact) and writes a scene file for
`render`: `size W H`, then one `tri` per triangle, coloured by its index.

POINTS holds one `x y` pair per line (decimal, as in scene files); blank
lines and lines starting with `#` are ignored.

options:
  -o, --output OUT.scene   where to write the scene (required)
  --size WxH               the scene's size (default 320x240, 1 to 4096 each)
  --gouraud                write `gtri` lines instead, each vertex coloured
                           from its index
  -h, --help               print this help

On a bad point file, prints `POINTS:LINE: what is wrong` on stderr, writes
no file and exits with 1; on a bad command line, exits with 2.
";

/// What the command line asks for.
#[derive(Debug)]
struct Options {
    points: PathBuf,
    output: PathBuf,
    size: (u32, u32),
    gouraud: bool,
}

/// Runs the `delaunay` command line on `args` (without the program name),
/// writing to `stdout` and `stderr`; returns the exit code
/// ([`EXIT_OK`], [`EXIT_FAILURE`] or [`EXIT_USAGE`]).
///
/// The whole point file is read and triangulated before the scene is
/// written: a bad file leaves no output.
///
/// # Examples
///
/// ```
/// use embedded_raster::sim::{cli, delaunay_cli, parse_scene};
///
/// let dir = std::env::temp_dir();
/// let points = dir.join(format!("delaunay-doc-{}.txt", std::process::id()));
/// let scene = dir.join(format!("delaunay-doc-{}.scene", std::process::id()));
/// std::fs::write(&points, "# a square\n10 10\n60 10\n\n60 60\n10 60\n")?;
///
/// let (mut out, mut err) = (Vec::new(), Vec::new());
/// let args = [points.as_os_str(), "-o".as_ref(), scene.as_os_str(), "--size".as_ref(), "64x64".as_ref()];
/// assert_eq!(delaunay_cli::run(args, &mut out, &mut err), cli::EXIT_OK);
/// let parsed = parse_scene(&std::fs::read_to_string(&scene)?).unwrap();
/// assert_eq!(parsed.commands().len(), 2); // two triangles
///
/// std::fs::write(&points, "10 10\n60 ten\n")?;
/// assert_eq!(delaunay_cli::run(args, &mut out, &mut err), cli::EXIT_FAILURE);
/// assert!(String::from_utf8_lossy(&err).ends_with(":2: bad number `ten`\n"));
/// # std::fs::remove_file(&points)?;
/// # std::fs::remove_file(&scene)?;
/// # Ok::<(), std::io::Error>(())
/// ```
pub fn run<I, S>(args: I, stdout: impl Write, stderr: impl Write) -> i32
where
    I: IntoIterator<Item = S>,
    S: Into<OsString>,
{
    let parsed = parse_args(args.into_iter().map(Into::into));
    let act = |options: &Options, _: &mut _| triangulate_file(options);
    run_parsed(("delaunay", USAGE), parsed, act, stdout, stderr)
}

/// `Ok(None)` for `--help`.
fn parse_args(mut args: impl Iterator<Item = OsString>) -> Result<Option<Options>, String> {
    let (mut points, mut output, mut size, mut gouraud) = (None, None, (320, 240), false);
    while let Some(arg) = args.next() {
        match arg.to_str() {
            Some("-h" | "--help") => return Ok(None),
            Some(name @ ("-o" | "--output")) => {
                let path = args
                    .next()
                    .ok_or_else(|| format!("`{name}` needs a file name"))?;
                if output.replace(PathBuf::from(path)).is_some() {
                    return Err(format!("`{name}` given twice"));
                }
            }
            Some("--size") => {
                let text = args.next().ok_or("`--size` needs WxH")?;
                let text = text.to_string_lossy();
                size = parse_size(&text).ok_or_else(|| {
                    format!("`--size` takes WxH with 1 to 4096 each, got `{text}`")
                })?;
            }
            Some("--gouraud") => gouraud = true,
            Some(a) if a.starts_with('-') && a != "-" => {
                return Err(format!("unknown option `{a}`"))
            }
            _ if points.is_some() => {
                return Err(format!(
                    "unexpected argument `{}`: one point file at a time",
                    arg.to_string_lossy()
                ))
            }
            _ => points = Some(PathBuf::from(arg)),
        }
    }
    Ok(Some(Options {
        points: points.ok_or("missing POINTS file")?,
        output: output.ok_or("missing `-o OUT.scene`")?,
        size,
        gouraud,
    }))
}

fn parse_size(text: &str) -> Option<(u32, u32)> {
    let (w, h) = text.split_once('x')?;
    let side = |t: &str| t.parse::<u32>().ok().filter(|v| (1..=4096).contains(v));
    Some((side(w)?, side(h)?))
}

/// Everything after the command line; the error is the one stderr line.
fn triangulate_file(options: &Options) -> Result<String, String> {
    let path = OneLine(&options.points);
    let text = std::fs::read(&options.points).map_err(|e| format!("{path}: cannot read: {e}"))?;
    let text = String::from_utf8(text).map_err(|_| format!("{path}: not valid UTF-8"))?;
    let points = parse_points(&text).map_err(|e| format!("{path}:{}: {e}", e.line))?;
    let mut delaunay = Box::new(Delaunay::<MAX_POINTS>::new());
    let mesh = delaunay
        .triangulate(&points)
        .map_err(|e| format!("{path}: {e}"))?;
    let scene = scene_text(&points, mesh.indices(), options.size, options.gouraud);
    std::fs::write(&options.output, scene)
        .map_err(|e| format!("{}: cannot write: {e}", OneLine(&options.output)))?;
    Ok(format!(
        "wrote {}: {} points, {} triangles",
        OneLine(&options.output),
        points.len(),
        mesh.indices().count()
    ))
}

/// Parses a point file: one `x y` pair per line; blank lines and `#`
/// comment lines are skipped.
///
/// # Errors
///
/// [`SceneError`] with the line of the first problem: not two values, a
/// bad number, a coordinate out of range, or more than 32767 points.
///
/// # Examples
///
/// ```
/// use embedded_raster::{sim::delaunay_cli::parse_points, Vertex};
///
/// let points = parse_points("# corners\n0 0\n\n  2.5 -1\n").unwrap();
/// assert_eq!(points, [Vertex::from_raw(0, 0), Vertex::from_raw(10240, -4096)]);
/// let err = parse_points("0 0\n1 2 3\n").unwrap_err();
/// assert_eq!((err.line, err.message.as_str()), (2, "expected `x y`, got 3 values"));
/// ```
pub fn parse_points(text: &str) -> Result<Vec<Vertex>, SceneError> {
    let mut points = Vec::new();
    for (index, line) in text.lines().enumerate() {
        let err = |message: String| SceneError {
            line: index + 1,
            message,
        };
        let tokens: Vec<&str> = line.split([' ', '\t']).filter(|t| !t.is_empty()).collect();
        match tokens.as_slice() {
            [] => continue,
            [first, ..] if first.starts_with('#') => continue,
            [x, y] => points.push(vertex(x, y).map_err(err)?),
            other => return Err(err(format!("expected `x y`, got {} values", other.len()))),
        }
        if points.len() > MAX_POINTS {
            return Err(err(format!("more than {MAX_POINTS} points")));
        }
    }
    Ok(points)
}

/// The scene: a comment, `size W H`, then one `tri` (or `gtri`) line per
/// triangle.
fn scene_text(
    points: &[Vertex],
    triangles: impl Iterator<Item = [usize; 3]>,
    (w, h): (u32, u32),
    gouraud: bool,
) -> String {
    let mut out = format!(
        "# Delaunay triangulation of {} points\nsize {w} {h}\n",
        points.len()
    );
    for (k, t) in triangles.enumerate() {
        let [a, b, c] = t.map(|i| {
            let (x, y) = points[i].raw();
            (decimal(x), decimal(y), vertex_colour(points[i], i, (w, h)))
        });
        // Writing to a String cannot fail.
        let _ = if gouraud {
            writeln!(
                out,
                "gtri {} {} {} {} {} {} {} {} {}",
                a.0, a.1, a.2, b.0, b.1, b.2, c.0, c.1, c.2
            )
        } else {
            writeln!(
                out,
                "tri {} {} {} {} {} {} {}",
                a.0,
                a.1,
                b.0,
                b.1,
                c.0,
                c.1,
                colour(k)
            )
        };
    }
    out
}

/// A raw 20.12 coordinate as an exact decimal (`-3.5`, `100.000244140625`).
fn decimal(raw: i32) -> String {
    let magnitude = i64::from(raw).unsigned_abs();
    let sign = if raw < 0 { "-" } else { "" };
    let (whole, fraction) = (magnitude >> 12, magnitude & 4095);
    if fraction == 0 {
        return format!("{sign}{whole}");
    }
    // 1/4096 = 0.000244140625 exactly: twelve decimal places.
    let digits = format!("{:012}", fraction * 244_140_625);
    format!("{sign}{whole}.{}", digits.trim_end_matches('0'))
}

/// A bright colour from an index, spread by a multiplicative hash.
fn colour(index: usize) -> String {
    let h = hash(index);
    let channel = |shift: u32| 64 + ((h >> shift) & 0xff) * 3 / 4;
    format!("#{:02x}{:02x}{:02x}", channel(24), channel(16), channel(8))
}

/// A `gtri` vertex colour: a gradient over the scene (red grows to the
/// right, blue downwards), darkened by 0 to 50 % by a hash of the index so
/// that the facets show.
fn vertex_colour(v: Vertex, index: usize, (w, h): (u32, u32)) -> String {
    let (x, y) = v.raw();
    let fraction = |c: i32, side: u32| (i64::from(c) / i64::from(side)).clamp(0, 4095);
    let (fx, fy) = (fraction(x, w), fraction(y, h));
    let shade = 128 + i64::from(hash(index) >> 25); // 128..=255
    let channel = |c: i64| (c * shade / 255).clamp(0, 255);
    let (r, g, b) = (
        40 + fx * 215 / 4095,
        90 + (4095 - fy) * 80 / 4095,
        60 + fy * 195 / 4095,
    );
    format!("#{:02x}{:02x}{:02x}", channel(r), channel(g), channel(b))
}

fn hash(index: usize) -> u32 {
    (index as u32 ^ 0x5bd1_e995).wrapping_mul(0x9e37_79b1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decimals_are_exact() {
        for (raw, text) in [
            (0, "0"),
            (4096, "1"),
            (-2048, "-0.5"),
            (100 * 4096 + 1, "100.000244140625"),
            (i32::MIN, "-524288"),
            (i32::MAX, "524287.999755859375"),
        ] {
            assert_eq!(decimal(raw), text);
            assert_eq!(Vertex::parse(text, "0").unwrap().raw().0, raw);
        }
    }

    #[test]
    fn sizes() {
        assert_eq!(parse_size("320x240"), Some((320, 240)));
        assert_eq!(parse_size("0x5"), None);
        assert_eq!(parse_size("4097x5"), None);
        assert_eq!(parse_size("12"), None);
    }
}
