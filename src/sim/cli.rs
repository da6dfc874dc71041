//! The command line of the `render` example, as a library function so that
//! it can be tested without spawning a process.
//!
//! ```text
//! render SCENE -o OUT.png [--counts COUNTS.pgm] [--stats] [--algo NAME] [--bits N]
//!        [--max-pixels N]
//! ```
//!
//! # Examples
//!
//! ```
//! use embedded_raster::sim::cli;
//!
//! let (mut out, mut err) = (Vec::new(), Vec::new());
//! assert_eq!(cli::run(["--help"], &mut out, &mut err), cli::EXIT_OK);
//! assert!(String::from_utf8(out)?.starts_with("usage: render SCENE"));
//! # Ok::<(), std::string::FromUtf8Error>(())
//! ```

use std::ffi::OsString;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::prelude::rust_2021::*;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::{format, vec, writeln};

use embedded_graphics_core::geometry::OriginDimensions;

use super::{parse_scene, render_scene_in_bands, render_scene_with, BandStats};
use crate::{triangle::SubpixelPrecision, triangle::TriangleAlgorithm};

/// Exit code of a successful run (and of `--help`).
///
/// # Examples
///
/// ```
/// assert_eq!(embedded_raster::sim::cli::EXIT_OK, 0);
/// ```
pub const EXIT_OK: i32 = 0;

/// Exit code when the scene is bad or a file cannot be read or written.
///
/// # Examples
///
/// ```
/// assert_eq!(embedded_raster::sim::cli::EXIT_FAILURE, 1);
/// ```
pub const EXIT_FAILURE: i32 = 1;

/// Exit code for a bad command line.
///
/// # Examples
///
/// ```
/// assert_eq!(embedded_raster::sim::cli::EXIT_USAGE, 2);
/// ```
pub const EXIT_USAGE: i32 = 2;

/// The help text, printed by `--help` (on stdout) and after a usage error
/// (on stderr).
///
/// # Examples
///
/// ```
/// assert!(embedded_raster::sim::cli::USAGE.contains("--counts"));
/// ```
pub const USAGE: &str = "\
usage: render SCENE -o OUT.png [--counts COUNTS.pgm] [--stats] [--algo NAME] [--bits N]
              [--max-pixels N] [--band N]

Renders a scene file to an 8-bit RGB PNG.

options:
  -o, --output OUT.png     where to write the image (required)
  --counts COUNTS.pgm      also write per-pixel write counts as a binary PGM
                           (P5, maxval 255, saturating)
  --stats                  print {\"primitives\":N,\"pixels_written\":N,\"raster_seconds\":S,
                           \"bands\":N,\"buffer_bytes\":N} on stdout (bands drawn and
                           bytes of pixel buffer used: 1 and the whole frame
                           without `--band`)
  --algo NAME              triangle algorithm for `tri` (default exact):
                             exact        exact edge equations, top-left rule
                             barycentric  exact, every pixel of the bounding box
                             walk         edge walking, 16.16 fixed-point slopes
                             bresenham    Bresenham edge walking, whole pixels,
                                          closed triangle (overdraws shared edges)
  --bits N                 subpixel bits vertices snap to: 0, 4, 8 or 12
                           (default 12)
  --max-pixels N           refuse a scene whose estimated work is over N
                           pixels (the sum over its commands of the pixels
                           each can touch, clipped; default: no limit)
  --band N                 render through the band renderer, N rows (>= 1) at a
                           time, in one band buffer: the same image and counts
  -h, --help               print this help

On a bad scene, prints `SCENE:LINE: what is wrong` on stderr, writes no
file and exits with 1; likewise for a scene over `--max-pixels`, an output
naming the scene file (or both outputs the same file, or something other
than a regular file: outputs are renamed into place, symbolic links
followed) and a file that cannot be written. On a bad command line, exits
with 2.
";

/// What the command line asks for.
#[derive(Debug)]
struct Options {
    scene: PathBuf,
    output: PathBuf,
    counts: Option<PathBuf>,
    stats: bool,
    algorithm: TriangleAlgorithm,
    precision: SubpixelPrecision,
    max_pixels: Option<u64>,
    band: Option<u32>,
}

/// Runs the `render` command line on `args` (without the program name),
/// writing to `stdout` and `stderr`, and returns the process exit code:
/// [`EXIT_OK`], [`EXIT_FAILURE`] or [`EXIT_USAGE`].
///
/// The scene is read, parsed and rendered, and both images are encoded,
/// before any file is written: a bad scene, a scene over `--max-pixels` or
/// an output path naming the scene file leaves no output file. The files
/// are written under temporary names beside their targets and renamed
/// only when both are complete, so a failure to write either leaves
/// neither (nor any temporary file). Every
/// error is reported as one line on `stderr` (followed by [`USAGE`] for a
/// bad command line): `SCENE:LINE: message` for a bad scene,
/// `PATH: message` for an I/O error. On success, one summary line goes to
/// `stderr`: `render: wrote OUT.png: WxH, N primitives, N pixels written,
/// rasterized in T ms`.
///
/// # Examples
///
/// ```
/// use embedded_raster::sim::cli;
///
/// let dir = std::env::temp_dir();
/// let scene = dir.join(format!("cli-doc-{}.scene", std::process::id()));
/// let png = dir.join(format!("cli-doc-{}.png", std::process::id()));
/// std::fs::write(&scene, "size 4 4\nclear #ff0000\n")?;
///
/// let (mut out, mut err) = (Vec::new(), Vec::new());
/// let args = [scene.as_os_str(), "-o".as_ref(), png.as_os_str(), "--stats".as_ref()];
/// assert_eq!(cli::run(args, &mut out, &mut err), cli::EXIT_OK);
/// assert!(String::from_utf8_lossy(&out).starts_with(r#"{"primitives":1,"pixels_written":16,"#));
/// // One summary line on stderr.
/// assert!(String::from_utf8_lossy(&err).starts_with("render: wrote "));
/// assert!(png.exists());
/// # std::fs::remove_file(&scene)?;
/// # std::fs::remove_file(&png)?;
/// # Ok::<(), std::io::Error>(())
/// ```
pub fn run<I, S>(args: I, stdout: impl Write, stderr: impl Write) -> i32
where
    I: IntoIterator<Item = S>,
    S: Into<OsString>,
{
    let parsed = parse_args(args.into_iter().map(Into::into));
    run_parsed(("render", USAGE), parsed, render, stdout, stderr)
}

/// What every command line does with its parsed arguments: `Ok(None)`
/// (`--help`) prints the usage on stdout; a usage error prints
/// `NAME: message`, a blank line and the usage on stderr ([`EXIT_USAGE`]);
/// otherwise `act` runs: its summary of what it did is one line on stderr
/// (stdout stays for requested output such as `--stats`), its error is one
/// line on stderr ([`EXIT_FAILURE`]).
pub(super) fn run_parsed<O, W: Write>(
    (name, usage): (&str, &str),
    parsed: Result<Option<O>, String>,
    act: impl FnOnce(&O, &mut W) -> Result<String, String>,
    mut stdout: W,
    mut stderr: impl Write,
) -> i32 {
    // Failing to report on stdout or stderr leaves nothing better to do.
    let options = match parsed {
        Ok(Some(options)) => options,
        Ok(None) => {
            return match stdout.write_all(usage.as_bytes()) {
                Ok(()) => EXIT_OK,
                Err(_) => EXIT_FAILURE,
            };
        }
        Err(message) => {
            let _ = write!(stderr, "{name}: {message}\n\n{usage}");
            return EXIT_USAGE;
        }
    };
    match act(&options, &mut stdout) {
        Ok(summary) => {
            let _ = writeln!(stderr, "{name}: {summary}");
            EXIT_OK
        }
        Err(message) => {
            let _ = writeln!(stderr, "{message}");
            EXIT_FAILURE
        }
    }
}

/// The options that take a value (each may be given once).
const VALUE_OPTIONS: [&str; 7] = [
    "--algo",
    "--bits",
    "--max-pixels",
    "--band",
    "-o",
    "--output",
    "--counts",
];

/// `Ok(None)` for `--help`.
fn parse_args(mut args: impl Iterator<Item = OsString>) -> Result<Option<Options>, String> {
    let mut scene = None;
    let mut output = None;
    let mut counts = None;
    let mut stats = false;
    let mut algorithm = TriangleAlgorithm::EdgeExact;
    let mut precision = SubpixelPrecision::Bits12;
    let mut max_pixels = None;
    let mut band = None;
    let mut given: Vec<String> = Vec::new();
    while let Some(arg) = args.next() {
        // Every option takes one value, given once (`--stats` is a flag).
        if let Some(name) = arg.to_str().filter(|a| VALUE_OPTIONS.contains(a)) {
            if given.iter().any(|g| g == name) {
                return Err(format!("`{name}` given twice"));
            }
            given.push(name.to_string());
        }
        match arg.to_str() {
            Some("--algo") => {
                let v = args.next().ok_or("`--algo` needs a name")?;
                let name = v.to_string_lossy();
                algorithm = TriangleAlgorithm::from_name(&name).ok_or_else(|| {
                    format!("unknown algorithm `{name}` (exact, barycentric, walk, bresenham)")
                })?;
                continue;
            }
            Some("--bits") => {
                let v = args.next().ok_or("`--bits` needs a number")?;
                let text = v.to_string_lossy();
                precision = text
                    .parse()
                    .ok()
                    .and_then(SubpixelPrecision::from_bits)
                    .ok_or_else(|| format!("`--bits` must be 0, 4, 8 or 12, got `{text}`"))?;
                continue;
            }
            Some("--max-pixels") => {
                let v = args.next().ok_or("`--max-pixels` needs a number")?;
                let text = v.to_string_lossy();
                let n = text.parse::<u64>().map_err(|_| {
                    format!("`--max-pixels` must be a non-negative integer, got `{text}`")
                })?;
                max_pixels = Some(n);
                continue;
            }
            Some("--band") => {
                let v = args.next().ok_or("`--band` needs a number of rows")?;
                let text = v.to_string_lossy();
                let rows = text.parse::<u32>().ok().filter(|&n| n >= 1);
                band = Some(rows.ok_or_else(|| {
                    format!(
                        "`--band` must be a number of rows from 1 to {}, got `{text}`",
                        u32::MAX
                    )
                })?);
                continue;
            }
            _ => {}
        }
        let mut value = |slot: &mut Option<PathBuf>, name: &str| {
            let v = args
                .next()
                .ok_or_else(|| format!("`{name}` needs a file name"))?;
            match slot.replace(v.into()) {
                Some(_) => Err(format!("`{name}` given twice")),
                None => Ok(()),
            }
        };
        match arg.to_str() {
            Some("-h" | "--help") => return Ok(None),
            Some(name @ ("-o" | "--output")) => value(&mut output, name)?,
            Some("--counts") => value(&mut counts, "--counts")?,
            Some("--stats") => stats = true,
            Some(a) if a.starts_with('-') && a != "-" => {
                return Err(format!("unknown option `{a}`"))
            }
            _ if scene.is_some() => {
                return Err(format!(
                    "unexpected argument `{}`: one scene file at a time",
                    arg.to_string_lossy()
                ))
            }
            _ => scene = Some(PathBuf::from(arg)),
        }
    }
    Ok(Some(Options {
        scene: scene.ok_or("missing SCENE file")?,
        output: output.ok_or("missing `-o OUT.png`")?,
        counts,
        stats,
        algorithm,
        precision,
        max_pixels,
        band,
    }))
}

/// A path as part of a one-line message: its control characters (a line
/// break is legal in a Unix file name) escaped as in a Rust string, and
/// what is not UTF-8 replaced by U+FFFD.
pub(crate) struct OneLine<'a>(pub &'a Path);

impl core::fmt::Display for OneLine<'_> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        use core::fmt::Write as _;
        for c in self.0.to_string_lossy().chars() {
            match c.is_control() {
                true => write!(f, "{}", c.escape_default())?,
                false => f.write_char(c)?,
            }
        }
        Ok(())
    }
}

/// Everything after the command line; the error is the one stderr line.
fn render(options: &Options, stdout: &mut impl Write) -> Result<String, String> {
    let scene_path = OneLine(&options.scene);
    let (output_target, counts_target) = output_targets(options)?;
    let bytes =
        std::fs::read(&options.scene).map_err(|e| format!("{scene_path}: cannot read: {e}"))?;
    let text = std::str::from_utf8(&bytes).map_err(|e| {
        let line = 1 + bytes[..e.valid_up_to()]
            .iter()
            .filter(|&&b| b == b'\n')
            .count();
        format!("{scene_path}:{line}: not valid UTF-8")
    })?;
    let scene = parse_scene(text).map_err(|e| format!("{scene_path}:{}: {e}", e.line))?;
    if let Some(limit) = options.max_pixels {
        let work = scene.pixel_work();
        if work > limit {
            return Err(format!(
                "{scene_path}: too much work: {work} pixels, over `--max-pixels {limit}`"
            ));
        }
    }
    let size = scene.size();
    let (rendered, bands) = match options.band {
        Some(rows) => render_scene_in_bands(&scene, rows, options.algorithm, options.precision),
        None => {
            let whole = BandStats {
                bands: 1,
                buffer_bytes: u64::from(size.width) * u64::from(size.height) * 3,
            };
            let rendered = render_scene_with(&scene, options.algorithm, options.precision);
            (rendered, whole)
        }
    };

    let mut png = Vec::new();
    rendered
        .display
        .write_png(&mut png)
        .map_err(|e| format!("{}: cannot encode PNG: {e}", OneLine(&options.output)))?;
    let mut files = vec![Output {
        path: &options.output,
        option: "-o",
        target: &output_target,
        bytes: png,
    }];
    if let (Some(path), Some(target)) = (&options.counts, &counts_target) {
        let mut pgm = Vec::new();
        rendered
            .display
            .write_counts_pgm(&mut pgm)
            .map_err(|e| format!("{}: cannot encode PGM: {e}", OneLine(path)))?;
        files.push(Output {
            path,
            option: "--counts",
            target,
            bytes: pgm,
        });
    }

    write_all_or_nothing(&files)?;
    if options.stats {
        let json = rendered.stats.to_json();
        let fields = format!(
            r#","bands":{},"buffer_bytes":{}}}"#,
            bands.bands, bands.buffer_bytes
        );
        // `to_json` is one object: its closing brace makes way for more.
        let json = format!("{}{fields}", json.trim_end_matches('}'));
        writeln!(stdout, "{json}").map_err(|e| format!("cannot write to stdout: {e}"))?;
    }
    let size = rendered.display.size();
    let stats = rendered.stats;
    Ok(format!(
        "wrote {}: {}x{}, {} primitives, {} pixels written, rasterized in {:.3} ms",
        OneLine(&options.output),
        size.width,
        size.height,
        stats.primitives,
        stats.pixels_written,
        stats.raster_time.as_secs_f64() * 1e3
    ))
}

/// The files the outputs go to (`-o`'s and `--counts`'), their symbolic
/// links followed; refuses a target that exists and is not a regular file
/// (a device, a FIFO, a directory: renaming over it would replace it), an
/// output that is the scene file, and two outputs that are one file,
/// comparing canonical paths (a target that does not exist yet is its
/// canonical directory and its name).
fn output_targets(options: &Options) -> Result<(PathBuf, Option<PathBuf>), String> {
    let scene = std::fs::canonicalize(&options.scene).ok();
    let output = output_target(&options.output, "-o")?;
    let counts = match &options.counts {
        Some(path) => Some(output_target(path, "--counts")?),
        None => None,
    };
    for (path, name, target) in [(&options.output, "-o", Some(&output))].into_iter().chain(
        options
            .counts
            .as_ref()
            .map(|p| (p, "--counts", counts.as_ref())),
    ) {
        if target.is_some() && target.cloned() == scene {
            return Err(format!(
                "{}: `{name}` names the scene file; refusing to overwrite it",
                OneLine(path)
            ));
        }
    }
    match (&options.counts, &counts) {
        (Some(path), Some(c)) if *c == output => Err(format!(
            "{}: `-o` and `--counts` name the same file",
            OneLine(path)
        )),
        _ => Ok((output, counts)),
    }
}

/// Where `path` (the option `name`'s) is written: the file its symbolic
/// links lead to, which may not exist yet, canonical where it resolves.
/// Refuses a path (or link) ending in a separator, `.` or `..`, which can
/// only name a directory.
fn output_target(path: &Path, name: &str) -> Result<PathBuf, String> {
    let mut target = path.to_path_buf();
    // As many links as Linux follows before giving up (`ELOOP`).
    for _ in 0..40 {
        if !names_a_file(&target) {
            return Err(format!(
                "{}: `{name}` must name a file, not end in `/`, `.` or `..`",
                OneLine(path)
            ));
        }
        let meta = match std::fs::symlink_metadata(&target) {
            Ok(meta) => meta,
            // Not there yet: written where its directory resolves.
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
                return Ok(resolve(&target).unwrap_or(target))
            }
            Err(e) => return Err(format!("{}: cannot write: {e}", OneLine(path))),
        };
        if meta.file_type().is_symlink() {
            let link = std::fs::read_link(&target)
                .map_err(|e| format!("{}: cannot read the link: {e}", OneLine(path)))?;
            target = match target.parent() {
                Some(dir) => dir.join(link),
                None => link,
            };
            continue;
        }
        if !meta.is_file() {
            return Err(format!(
                "{}: `{name}` names something other than a regular file; refusing to replace it",
                OneLine(path)
            ));
        }
        return Ok(resolve(&target).unwrap_or(target));
    }
    Err(format!(
        "{}: too many levels of symbolic links",
        OneLine(path)
    ))
}

/// Whether `path` ends in a file's name: not in a separator, `.` or `..`
/// (`Path::components` drops a trailing `/` and `/.`, so the text is
/// read).
fn names_a_file(path: &Path) -> bool {
    let text = path.as_os_str().as_encoded_bytes();
    let dot_last = |suffix: &[u8]| {
        text.ends_with(suffix)
            && (text.len() == suffix.len()
                || std::path::is_separator(char::from(text[text.len() - suffix.len() - 1])))
    };
    let ends_in_separator = text
        .last()
        .is_some_and(|&b| std::path::is_separator(char::from(b)));
    !text.is_empty() && !ends_in_separator && !dot_last(b".") && !dot_last(b"..")
}

/// The canonical form of `path`, or of its parent joined with its name if
/// it does not exist; `None` if neither resolves.
fn resolve(path: &Path) -> Option<PathBuf> {
    if let Ok(p) = std::fs::canonicalize(path) {
        return Some(p);
    }
    let name = path.file_name()?;
    let parent = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    Some(std::fs::canonicalize(parent).ok()?.join(name))
}

/// One output file: the path the user named with its option, the file it
/// goes to ([`output_target`]) and its bytes.
struct Output<'a> {
    path: &'a Path,
    option: &'static str,
    target: &'a Path,
    bytes: Vec<u8>,
}

/// Writes every file under a new temporary name beside its target, then
/// renames them all into place; on any failure removes what it wrote.
/// Just before the renames, each path must still lead to its target (a
/// link or special file put there while the scene rendered is refused).
fn write_all_or_nothing(files: &[Output<'_>]) -> Result<(), String> {
    let mut temps: Vec<PathBuf> = Vec::new();
    let cleanup = |temps: &[PathBuf]| {
        for temp in temps {
            let _ = std::fs::remove_file(temp);
        }
    };
    for file in files {
        match write_new_temp(file.target, &file.bytes) {
            Ok(temp) => temps.push(temp),
            Err(e) => {
                cleanup(&temps);
                return Err(format!("{}: cannot write: {e}", OneLine(file.path)));
            }
        }
    }
    for file in files {
        match output_target(file.path, file.option) {
            Ok(target) if target == file.target => {}
            Ok(_) => {
                cleanup(&temps);
                return Err(format!("{}: changed while rendering", OneLine(file.path)));
            }
            Err(e) => {
                cleanup(&temps);
                return Err(e);
            }
        }
    }
    for (i, (temp, file)) in temps.iter().zip(files).enumerate() {
        if let Err(e) = std::fs::rename(temp, file.target) {
            // The files already renamed hold this run's output: remove them
            // too, so that nothing of a failed run is left.
            for done in &files[..i] {
                let _ = std::fs::remove_file(done.target);
            }
            cleanup(&temps[i..]);
            return Err(format!("{}: cannot write: {e}", OneLine(file.path)));
        }
    }
    Ok(())
}

/// Writes `bytes` to a file of a new name beside `target` ([`temp_name`]),
/// created only if no file (or link) has that name: one that exists is
/// never followed, truncated or removed.
fn write_new_temp(target: &Path, bytes: &[u8]) -> std::io::Result<PathBuf> {
    for _ in 0..100 {
        let temp = temp_name(target).ok_or(std::io::ErrorKind::InvalidInput)?;
        let created = std::fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&temp);
        match created {
            Ok(mut file) => {
                return match file.write_all(bytes) {
                    Ok(()) => Ok(temp),
                    Err(e) => {
                        drop(file);
                        let _ = std::fs::remove_file(&temp);
                        Err(e)
                    }
                };
            }
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
            Err(e) => return Err(e),
        }
    }
    Err(std::io::ErrorKind::AlreadyExists.into())
}

/// `DIR/.NAME.render-PID-N.tmp` for `DIR/NAME`, `N` counting the calls in
/// this process (so that runs in threads of one process never share one).
fn temp_name(path: &Path) -> Option<PathBuf> {
    static NEXT: AtomicUsize = AtomicUsize::new(0);
    let name = path.file_name()?.to_string_lossy();
    let n = NEXT.fetch_add(1, Ordering::Relaxed);
    Some(path.with_file_name(format!(".{name}.render-{}-{n}.tmp", std::process::id())))
}
