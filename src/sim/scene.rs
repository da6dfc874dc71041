//! Scene files: parsing.
//!
//! The format is specified in the crate's scene-format contract; in short,
//! one command per line, `#` comment lines, blank-separated tokens:
//!
//! ```text
//! size W H
//! clear #RRGGBB
//! rect X Y W H #RRGGBB
//! tri X0 Y0 X1 Y1 X2 Y2 #RRGGBB
//! gtri X0 Y0 #C0 X1 Y1 #C1 X2 Y2 #C2
//! line X0 Y0 X1 Y1 #RRGGBB
//! polyline #RRGGBB X0 Y0 X1 Y1 ...
//! ```

use core::fmt;
use std::format;
use std::prelude::rust_2021::*;

use embedded_graphics_core::{
    geometry::{Point, Size},
    pixelcolor::Rgb888,
    primitives::Rectangle,
};

use crate::{
    line::Line, polygon::FillRule, polygon::Polygon, triangle::Triangle,
    vertex::ParseCoordinateError, vertex::Vertex,
};

/// Largest width and height a scene may have.
pub const MAX_SCENE_SIDE: u32 = 4096;

/// A parsed scene: its framebuffer size and its drawing commands, in order.
///
/// Made by [`parse_scene`], which guarantees `1 <= width, height <= 4096`.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{geometry::Size, pixelcolor::Rgb888};
/// use embedded_raster::sim::{parse_scene, Command};
///
/// let scene = parse_scene("size 32 16\nclear #102030\n")?;
/// assert_eq!(scene.size(), Size::new(32, 16));
/// assert_eq!(scene.commands(), &[Command::Clear(Rgb888::new(0x10, 0x20, 0x30))]);
/// # Ok::<(), embedded_raster::sim::SceneError>(())
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Scene {
    size: Size,
    commands: Vec<Command>,
}

impl Scene {
    /// The framebuffer size given by the scene's `size` command.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::geometry::Size;
    /// use embedded_raster::sim::parse_scene;
    ///
    /// assert_eq!(parse_scene("size 1 4096")?.size(), Size::new(1, 4096));
    /// # Ok::<(), embedded_raster::sim::SceneError>(())
    /// ```
    pub fn size(&self) -> Size {
        self.size
    }

    /// The drawing commands after `size`, in file order.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_raster::sim::parse_scene;
    ///
    /// let scene = parse_scene("size 8 8\n# nothing else\n")?;
    /// assert!(scene.commands().is_empty());
    /// # Ok::<(), embedded_raster::sim::SceneError>(())
    /// ```
    pub fn commands(&self) -> &[Command] {
        &self.commands
    }
}

/// One drawing command of a [`Scene`].
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::Rgb888, prelude::*, primitives::Rectangle};
/// use embedded_raster::sim::{parse_scene, Command};
///
/// let scene = parse_scene("size 8 8\nrect -2 3 4 0 #FF0000")?;
/// assert_eq!(
///     scene.commands(),
///     &[Command::Rect(Rectangle::new(Point::new(-2, 3), Size::new(4, 0)), Rgb888::RED)],
/// );
/// # Ok::<(), embedded_raster::sim::SceneError>(())
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum Command {
    /// `clear #RRGGBB`: fill the whole framebuffer.
    Clear(Rgb888),
    /// `rect X Y W H #RRGGBB`: fill a pixel rectangle, clipped.
    Rect(Rectangle, Rgb888),
    /// `tri X0 Y0 X1 Y1 X2 Y2 #RRGGBB`: fill a triangle.
    Tri(Triangle, Rgb888),
    /// `gtri X0 Y0 #C0 X1 Y1 #C1 X2 Y2 #C2`: a Gouraud triangle, one colour
    /// per vertex.
    Gtri(Triangle, [Rgb888; 3]),
    /// `line X0 Y0 X1 Y1 #RRGGBB`: a 1-pixel line between two pixels.
    Line(Line, Rgb888),
    /// `polyline #RRGGBB X0 Y0 X1 Y1 ...`: connected 1-pixel lines through
    /// two or more pixels, each joint lit once.
    Polyline(Vec<Point>, Rgb888),
    /// `poly evenodd|nonzero #RRGGBB X0 Y0 X1 Y1 ...`: a filled polygon of
    /// 3 to [`SCENE_POLYGON_CAPACITY`] vertices, closed implicitly.
    Poly(Vec<Vertex>, FillRule, Rgb888),
}

/// The most vertices a scene's `poly` may have; more is an error.
pub const SCENE_POLYGON_CAPACITY: usize = 1024;

/// Why a scene could not be parsed: a 1-based line number and a one-line,
/// lowercase message.
///
/// It displays as the message alone; a caller reporting it on a file
/// prefixes `FILE:LINE: `.
///
/// # Examples
///
/// ```
/// use embedded_raster::sim::parse_scene;
///
/// let err = parse_scene("size 8 8\n\ncircle 4 4 3 #ffffff\n").unwrap_err();
/// assert_eq!(err.line, 3);
/// assert_eq!(err.to_string(), "unknown command `circle`");
/// ```
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct SceneError {
    /// The line the problem is on, counting from 1. A missing `size`
    /// command is reported on the last line (1 for an empty scene).
    pub line: usize,
    /// What is wrong.
    pub message: String,
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for SceneError {}

/// Parses a scene file.
///
/// Every line is checked before anything is drawn, so a scene that parses
/// renders without error.
///
/// # Errors
///
/// [`SceneError`] with the line of the first problem: a first command
/// other than `size`, a second `size`, an unknown command, a wrong number
/// of arguments (or an odd number of `polyline` coordinates), a bad
/// integer, number or colour, a size outside
/// `1..=4096`, a negative rectangle size, a coordinate out of range, or no
/// `size` at all.
///
/// # Examples
///
/// ```
/// use embedded_raster::sim::parse_scene;
///
/// let scene = parse_scene(
///     "# a red triangle on blue\n\
///      size 64 48\n\
///      clear #0000ff\n\
///      \ttri 4 4  60.5 10.25  20 44 #FF0000\n",
/// )?;
/// assert_eq!(scene.commands().len(), 2);
///
/// let err = parse_scene("size 8 8\ntri 0 0 1 1 2 #fff").unwrap_err();
/// assert_eq!((err.line, err.message.as_str()), (2, "`tri` takes 7 arguments, got 6"));
/// # Ok::<(), embedded_raster::sim::SceneError>(())
/// ```
pub fn parse_scene(text: &str) -> Result<Scene, SceneError> {
    let mut size: Option<(usize, Size)> = None;
    let mut commands = Vec::new();
    let mut last_line = 1;
    for (index, line) in text.lines().enumerate() {
        let line_no = index + 1;
        last_line = line_no;
        let mut tokens = line.split([' ', '\t']).filter(|t| !t.is_empty());
        let Some(word) = tokens.next() else {
            continue;
        };
        if word.starts_with('#') {
            continue;
        }
        let args: Vec<&str> = tokens.collect();
        let err = |message: String| SceneError {
            line: line_no,
            message,
        };
        match (word, size) {
            ("size", None) => size = Some((line_no, parse_size(&args).map_err(err)?)),
            ("size", Some((first, _))) => {
                return Err(err(format!("duplicate `size` (first on line {first})")))
            }
            (_, None) if COMMANDS.contains(&word) => {
                return Err(err("`size` must come first".into()))
            }
            (_, None) => return Err(err(format!("unknown command `{}`", Shown(word)))),
            (_, Some(_)) => commands.push(parse_command(word, &args).map_err(err)?),
        }
    }
    match size {
        Some((_, size)) => Ok(Scene { size, commands }),
        None => Err(SceneError {
            line: last_line,
            message: "missing `size` command".into(),
        }),
    }
}

/// The drawing commands' words (those of [`parse_command`]).
const COMMANDS: [&str; 7] = ["clear", "rect", "tri", "gtri", "line", "polyline", "poly"];

/// Parses one drawing command: one match arm per command word.
fn parse_command(word: &str, args: &[&str]) -> Result<Command, String> {
    match word {
        "clear" => {
            let [c] = arity::<1>(word, args)?;
            Ok(Command::Clear(colour(c)?))
        }
        "rect" => {
            let [x, y, w, h, c] = arity::<5>(word, args)?;
            let top_left = Point::new(integer(x)?, integer(y)?);
            let size = Size::new(extent(w, "width")?, extent(h, "height")?);
            Ok(Command::Rect(Rectangle::new(top_left, size), colour(c)?))
        }
        "tri" => {
            let [x0, y0, x1, y1, x2, y2, c] = arity::<7>(word, args)?;
            let triangle = Triangle::new(vertex(x0, y0)?, vertex(x1, y1)?, vertex(x2, y2)?);
            Ok(Command::Tri(triangle, colour(c)?))
        }
        "gtri" => {
            let [x0, y0, c0, x1, y1, c1, x2, y2, c2] = arity::<9>(word, args)?;
            // Left to right, so the first bad token is the one reported.
            let (v0, c0) = (vertex(x0, y0)?, colour(c0)?);
            let (v1, c1) = (vertex(x1, y1)?, colour(c1)?);
            let (v2, c2) = (vertex(x2, y2)?, colour(c2)?);
            Ok(Command::Gtri(Triangle::new(v0, v1, v2), [c0, c1, c2]))
        }
        "line" => {
            let [x0, y0, x1, y1, c] = arity::<5>(word, args)?;
            let start = Point::new(integer(x0)?, integer(y0)?);
            let end = Point::new(integer(x1)?, integer(y1)?);
            Ok(Command::Line(Line::new(start, end), colour(c)?))
        }
        "polyline" => {
            let (c, coordinates) = match args {
                [c, rest @ ..] if rest.len() >= 4 => (c, rest),
                _ => {
                    return Err(format!(
                        "`polyline` takes a colour and at least 2 points, got {} arguments",
                        args.len()
                    ))
                }
            };
            if coordinates.len() % 2 != 0 {
                return Err(format!(
                    "`polyline` takes x y pairs, got {} coordinates",
                    coordinates.len()
                ));
            }
            let color = colour(c)?;
            let points = coordinates
                .chunks_exact(2)
                .map(|p| Ok(Point::new(integer(p[0])?, integer(p[1])?)))
                .collect::<Result<Vec<_>, String>>()?;
            Ok(Command::Polyline(points, color))
        }
        "poly" => {
            let [rule, c, coordinates @ ..] = args else {
                return Err(format!(
                    "`poly` takes a fill rule, a colour and at least 3 points, got {} arguments",
                    args.len()
                ));
            };
            let rule = match *rule {
                "evenodd" => FillRule::EvenOdd,
                "nonzero" => FillRule::NonZero,
                _ => {
                    return Err(format!(
                        "bad fill rule `{}` (evenodd or nonzero)",
                        Shown(rule)
                    ))
                }
            };
            let color = colour(c)?;
            if coordinates.len() % 2 != 0 {
                return Err(format!(
                    "`poly` takes x y pairs, got {} coordinates",
                    coordinates.len()
                ));
            }
            let vertices = coordinates
                .chunks_exact(2)
                .map(|p| vertex(p[0], p[1]))
                .collect::<Result<Vec<_>, String>>()?;
            Polygon::<SCENE_POLYGON_CAPACITY>::new(&vertices).map_err(|e| e.to_string())?;
            Ok(Command::Poly(vertices, rule, color))
        }
        _ => Err(format!("unknown command `{}`", Shown(word))),
    }
}

fn parse_size(args: &[&str]) -> Result<Size, String> {
    let [w, h] = arity::<2>("size", args)?;
    let side = |t: &str| match t.parse::<u32>() {
        Ok(v) if (1..=MAX_SCENE_SIDE).contains(&v) => Ok(v),
        _ if is_integer(t) => Err(format!(
            "size out of range: `{}` (must be 1 to {MAX_SCENE_SIDE})",
            Shown(t)
        )),
        _ => Err(format!("bad integer `{}`", Shown(t))),
    };
    Ok(Size::new(side(w)?, side(h)?))
}

/// The arguments as an array of exactly `N`, or the wrong-count error.
fn arity<'a, const N: usize>(word: &str, args: &[&'a str]) -> Result<[&'a str; N], String> {
    <[&str; N]>::try_from(args).map_err(|_| {
        let plural = if N == 1 { "" } else { "s" };
        format!("`{word}` takes {N} argument{plural}, got {}", args.len())
    })
}

/// Whether `t` is an optionally signed run of ASCII digits.
fn is_integer(t: &str) -> bool {
    let digits = t.strip_prefix(['-', '+']).unwrap_or(t);
    !digits.is_empty() && digits.bytes().all(|b| b.is_ascii_digit())
}

fn integer(t: &str) -> Result<i32, String> {
    match t.parse::<i32>() {
        Ok(v) => Ok(v),
        Err(_) if is_integer(t) => Err(format!("integer out of range: `{}`", Shown(t))),
        _ => Err(format!("bad integer `{}`", Shown(t))),
    }
}

/// A rectangle width or height: an `i32` that is not negative.
fn extent(t: &str, what: &str) -> Result<u32, String> {
    let v = integer(t)?;
    u32::try_from(v).map_err(|_| format!("negative {what} `{}`", Shown(t)))
}

pub(super) fn vertex(x: &str, y: &str) -> Result<Vertex, String> {
    Vertex::parse(x, y).map_err(|e| {
        // Name the offending token: `x` if it fails on its own, else `y`.
        let (e, t) = match Vertex::parse(x, "0") {
            Err(ex) => (ex, x),
            Ok(_) => (e, y),
        };
        match e {
            ParseCoordinateError::OutOfRange => format!("coordinate out of range: `{}`", Shown(t)),
            _ => format!("bad number `{}`", Shown(t)),
        }
    })
}

fn colour(t: &str) -> Result<Rgb888, String> {
    let bad = || format!("bad colour `{}`", Shown(t));
    let hex = t.strip_prefix('#').ok_or_else(bad)?;
    if hex.len() != 6 || !hex.bytes().all(|b| b.is_ascii_hexdigit()) {
        return Err(bad());
    }
    let channel = |i: usize| u8::from_str_radix(&hex[i..i + 2], 16).map_err(|_| bad());
    Ok(Rgb888::new(channel(0)?, channel(2)?, channel(4)?))
}

/// A token quoted in an error message: every character but printable
/// ASCII, and the backslash, escaped (`\u{feff}` for a byte-order mark, `\u{a0}` for a
/// no-break space: a scene's words are all ASCII, so these are what makes
/// the token wrong), so that the message stays on one line and shows it,
/// and cut after [`Shown::MAX_CHARS`] characters.
struct Shown<'a>(&'a str);

impl Shown<'_> {
    /// The characters of a token shown before `...`.
    const MAX_CHARS: usize = 40;
}

impl fmt::Display for Shown<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use fmt::Write;
        for (i, c) in self.0.chars().enumerate() {
            if i == Self::MAX_CHARS {
                return f.write_str("...");
            }
            // A backslash escaped too, so that `\u{a0}` in the file reads
            // apart from a no-break space.
            if c.is_ascii_graphic() && c != '\\' {
                f.write_char(c)?;
            } else {
                write!(f, "{}", c.escape_default())?;
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `COMMANDS` lists exactly the words `parse_command` knows.
    #[test]
    fn commands_are_the_parsed_words() {
        for word in COMMANDS {
            let e = parse_command(word, &[]).unwrap_err();
            assert!(!e.starts_with("unknown command"), "{word}: {e}");
        }
        assert!(parse_command("circle", &[])
            .unwrap_err()
            .starts_with("unknown command"));
    }
}
