//! The `render` command line, through `embedded_raster::sim::cli::run`.

use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};

use embedded_raster::sim::cli;

use super::decode_png;

/// A fresh path in the temp directory; removed on drop.
struct Temp(PathBuf);

impl Temp {
    fn new(name: &str) -> Self {
        static NEXT: AtomicUsize = AtomicUsize::new(0);
        let n = NEXT.fetch_add(1, Ordering::Relaxed);
        let path = std::env::temp_dir().join(format!(
            "embedded-raster-scene-test-{}-{n}-{name}",
            std::process::id()
        ));
        let _ = std::fs::remove_file(&path);
        Self(path)
    }

    fn with(name: &str, contents: &str) -> Self {
        let t = Self::new(name);
        std::fs::write(&t.0, contents).unwrap();
        t
    }

    fn arg(&self) -> String {
        self.0.to_str().unwrap().to_string()
    }
}

impl Drop for Temp {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.0);
    }
}

/// Runs the command line: `(exit code, stdout, stderr)`.
fn run(args: &[&str]) -> (i32, String, String) {
    let (mut out, mut err) = (Vec::new(), Vec::new());
    let code = cli::run(args, &mut out, &mut err);
    (
        code,
        String::from_utf8(out).unwrap(),
        String::from_utf8(err).unwrap(),
    )
}

const SCENE: &str = "# test scene\n\
                     size 6 4\n\
                     clear #102030\n\
                     rect 1 1 2 2 #FF0000\n\
                     tri 3 0 6 0 6 3 #00ff00\n";

#[test]
fn cli_writes_png_counts_and_stats() {
    let scene = Temp::with("ok.scene", SCENE);
    let png_file = Temp::new("ok.png");
    let pgm_file = Temp::new("ok.pgm");
    let (code, out, err) = run(&[
        &scene.arg(),
        "-o",
        &png_file.arg(),
        "--counts",
        &pgm_file.arg(),
        "--stats",
    ]);
    assert_eq!(code, 0, "{err}");
    // One summary line on stderr: size, commands, pixel writes (4 clear +
    // 4 rect + 6 triangle... counted below from the counts image), time.
    let summary = format!(
        "render: wrote {}: 6x4, 3 primitives, 34 pixels written, rasterized in ",
        png_file.arg()
    );
    assert!(
        err.starts_with(&summary) && err.ends_with(" ms\n") && err.lines().count() == 1,
        "{err}"
    );

    // The image.
    let (w, h, rgb) = decode_png(&std::fs::read(&png_file.0).unwrap());
    assert_eq!((w, h), (6, 4));
    let at = |x: usize, y: usize| &rgb[(y * 6 + x) * 3..][..3];
    assert_eq!(at(0, 0), [0x10, 0x20, 0x30]);
    assert_eq!(at(1, 1), [0xff, 0, 0]);
    assert_eq!(at(2, 2), [0xff, 0, 0]);
    assert_eq!(at(3, 2), [0x10, 0x20, 0x30]);
    // The triangle lights centres with x - y >= 3: the diagonal is its left
    // edge.
    let green = [0, 0xff, 0];
    assert_eq!(at(3, 0), green);
    assert_eq!(at(5, 0), green);
    assert_eq!(at(4, 1), green);
    assert_eq!(at(5, 2), green);
    assert_eq!(at(3, 1), [0x10, 0x20, 0x30]);
    assert_eq!(at(4, 2), [0x10, 0x20, 0x30]);
    assert_eq!(at(5, 3), [0x10, 0x20, 0x30]);

    // The counts, against the same expectation.
    let pgm = std::fs::read(&pgm_file.0).unwrap();
    let header = b"P5\n6 4\n255\n";
    assert_eq!(&pgm[..header.len()], header);
    #[rustfmt::skip]
    let counts: [u8; 24] = [
        1, 1, 1, 2, 2, 2,
        1, 2, 2, 1, 2, 2,
        1, 2, 2, 1, 1, 2,
        1, 1, 1, 1, 1, 1,
    ];
    assert_eq!(&pgm[header.len()..], counts);

    // The stats: one JSON object on one line.
    assert_eq!(out.lines().count(), 1, "{out}");
    let json = out.trim_end();
    let prefix = r#"{"primitives":3,"pixels_written":34,"raster_seconds":"#;
    let suffix = r#","bands":1,"buffer_bytes":72}"#; // the whole 6 x 4 Rgb888 frame
    assert!(json.starts_with(prefix) && json.ends_with(suffix), "{json}");
    let seconds: f64 = json[prefix.len()..json.len() - suffix.len()]
        .parse()
        .unwrap();
    assert!((0.0..10.0).contains(&seconds), "{json}");
}

#[test]
fn cli_without_options_writes_only_the_png() {
    let scene = Temp::with("plain.scene", "size 3 2\nclear #FFFFFF\n");
    let png_file = Temp::new("plain.png");
    let (code, out, err) = run(&[&scene.arg(), "--output", &png_file.arg()]);
    assert_eq!((code, out.as_str()), (0, ""));
    let summary = format!(
        "render: wrote {}: 3x2, 1 primitives, 6 pixels written",
        png_file.arg()
    );
    assert!(err.starts_with(&summary), "{err}");
    let (w, h, rgb) = decode_png(&std::fs::read(&png_file.0).unwrap());
    assert_eq!((w, h, rgb), (3, 2, vec![255; 18]));
}

#[test]
fn cli_bad_scene_reports_one_line_and_writes_nothing() {
    let cases = [
        (
            "size 8 8\nclear #000000\ngtri 0 0 #ff0000 8 0 #00ff00 0 8\n",
            3,
            "`gtri` takes 9 arguments, got 8",
        ),
        (
            "size 8 8\ntri 0 0 1 1 2 #ffffff\n",
            2,
            "`tri` takes 7 arguments, got 6",
        ),
        (
            "size 8 8\n\n\ntri 0 0 1x 1 2 2 #ffffff\n",
            4,
            "bad number `1x`",
        ),
        (
            "size 8 8\ntri 0 0 600000 1 2 2 #ffffff\n",
            2,
            "coordinate out of range: `600000`",
        ),
        ("size 8 8\nclear #12345\n", 2, "bad colour `#12345`"),
        ("clear #123456\nsize 8 8\n", 1, "`size` must come first"),
        (
            "size 0 8\n",
            1,
            "size out of range: `0` (must be 1 to 4096)",
        ),
        ("# nothing\n", 1, "missing `size` command"),
        // An error after many good lines still writes nothing.
        (
            "size 8 8\nclear #000000\nrect 0 0 4 4 #ffffff\npoly nonzero #ffffff 0 0 4 0\n",
            4,
            "a polygon needs at least 3 vertices, got 2",
        ),
    ];
    for (text, line, message) in cases {
        let scene = Temp::with("bad.scene", text);
        let png_file = Temp::new("bad.png");
        let pgm_file = Temp::new("bad.pgm");
        let (code, out, err) = run(&[
            &scene.arg(),
            "-o",
            &png_file.arg(),
            "--counts",
            &pgm_file.arg(),
            "--stats",
        ]);
        assert_ne!(code, 0, "{text}");
        assert_eq!(out, "", "{text}");
        assert_eq!(
            err,
            format!("{}:{line}: {message}\n", scene.arg()),
            "{text}"
        );
        assert!(!png_file.0.exists(), "{text}");
        assert!(!pgm_file.0.exists(), "{text}");
    }

    // Invalid UTF-8 is reported on its line.
    let scene = Temp::new("utf8.scene");
    std::fs::write(&scene.0, b"size 8 8\nclear #000000\nrect \xff\n").unwrap();
    let png_file = Temp::new("utf8.png");
    let (code, _, err) = run(&[&scene.arg(), "-o", &png_file.arg()]);
    assert_eq!(code, 1);
    assert_eq!(err, format!("{}:3: not valid UTF-8\n", scene.arg()));
    assert!(!png_file.0.exists());
}

#[test]
fn cli_io_errors_are_one_line() {
    let missing = Temp::new("missing.scene");
    let png_file = Temp::new("missing.png");
    let (code, out, err) = run(&[&missing.arg(), "-o", &png_file.arg()]);
    assert_eq!((code, out.as_str()), (1, ""));
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.starts_with(&format!("{}: cannot read: ", missing.arg())),
        "{err}"
    );
    assert!(!png_file.0.exists());

    // An output in a directory that does not exist.
    let scene = Temp::with("io.scene", "size 2 2\n");
    let bad_out = missing.0.join("out.png");
    let (code, _, err) = run(&[&scene.arg(), "-o", bad_out.to_str().unwrap()]);
    assert_eq!(code, 1);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("cannot write"), "{err}");
}

/// A scene path holding a line break (legal on Unix) is shown escaped,
/// so that bad input still gives one line (`scene-format.md`); until
/// 2026-12-06 it was printed raw, over two lines (found by a black-box
/// audit of `render` against that contract).
#[cfg(unix)]
#[test]
fn cli_error_line_escapes_the_path() {
    let scene = Temp::with("two\nlines.scene", "size 4 4\nfoo\n");
    let png_file = Temp::new("two-lines.png");
    let (code, out, err) = run(&[&scene.arg(), "-o", &png_file.arg()]);
    assert_eq!((code, out.as_str()), (1, ""));
    assert_eq!(err.matches('\n').count(), 1, "{err:?}");
    let shown = scene.arg().replace('\n', "\\n");
    assert_eq!(err, format!("{shown}:2: unknown command `foo`\n"));
    assert!(!png_file.0.exists());
}

#[test]
fn cli_usage() {
    let (code, out, err) = run(&["--help"]);
    assert_eq!((code, err.as_str()), (0, ""));
    assert!(out.starts_with("usage: render SCENE -o OUT.png"), "{out}");

    let scene = Temp::with("usage.scene", "size 2 2\n");
    let png_file = Temp::new("usage.png");
    let s = scene.arg();
    let p = png_file.arg();
    for args in [
        vec![],
        vec![s.as_str()],
        vec!["-o", p.as_str()],
        vec![s.as_str(), "-o"],
        vec![s.as_str(), "-o", p.as_str(), "--counts"],
        vec![s.as_str(), "-o", p.as_str(), "--bogus"],
        vec![s.as_str(), "-o", p.as_str(), "-o", p.as_str()],
        vec![s.as_str(), s.as_str(), "-o", p.as_str()],
        // Every option with a value at most once, as `-o`.
        vec![s.as_str(), "-o", p.as_str(), "--band", "4", "--band", "8"],
        vec![s.as_str(), "--bits", "4", "-o", p.as_str(), "--bits", "4"],
        vec![
            s.as_str(),
            "-o",
            p.as_str(),
            "--algo",
            "walk",
            "--algo",
            "exact",
        ],
        vec![
            s.as_str(),
            "-o",
            p.as_str(),
            "--max-pixels",
            "9",
            "--max-pixels",
            "9",
        ],
    ] {
        let (code, out, err) = run(&args);
        assert_eq!(code, 2, "{args:?}");
        assert_eq!(out, "", "{args:?}");
        assert!(err.starts_with("render: "), "{args:?}: {err}");
        assert!(err.contains("usage: render SCENE"), "{args:?}: {err}");
        assert!(!png_file.0.exists(), "{args:?}");
    }
}

/// The entries of `dir` whose names contain `part` (temporary files
/// included).
fn entries_with(dir: &std::path::Path, part: &str) -> Vec<String> {
    std::fs::read_dir(dir)
        .unwrap()
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter(|n| n.contains(part))
        .collect()
}

/// Issue 12, item 3: `--counts` into a directory that does not exist
/// failed but left `OUT.png` written. Now neither file nor any temporary
/// file is left, whichever output fails.
#[test]
fn issue_12_failing_counts_writes_no_file() {
    let scene = Temp::with("counts.scene", SCENE);
    let png_file = Temp::new("counts.png");
    let missing = Temp::new("no-such-dir");
    let bad = missing.0.join("counts.pgm");
    for args in [
        [&png_file.arg(), bad.to_str().unwrap()],
        [bad.to_str().unwrap(), &Temp::new("counts.pgm").arg()],
    ] {
        let (code, out, err) = run(&[&scene.arg(), "-o", args[0], "--counts", args[1]]);
        assert_eq!((code, out.as_str()), (1, ""), "{args:?}");
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(
            err.starts_with(&format!("{}: cannot write: ", bad.display())),
            "{err}"
        );
        for path in args {
            assert!(!std::path::Path::new(path).exists(), "{path} left behind");
        }
        let name = std::format!("embedded-raster-scene-test-{}-", std::process::id());
        let left: Vec<_> = entries_with(&std::env::temp_dir(), &name)
            .into_iter()
            // This test's outputs only: other tests write in parallel.
            .filter(|n| n.ends_with(".tmp") && n.contains("-counts."))
            .collect();
        assert!(left.is_empty(), "temporary files left: {left:?}");
    }
    // A good run leaves no temporary file either.
    let pgm_file = Temp::new("counts-ok.pgm");
    let (code, _, err) = run(&[
        &scene.arg(),
        "-o",
        &png_file.arg(),
        "--counts",
        &pgm_file.arg(),
    ]);
    assert_eq!((code, err.lines().count()), (0, 1), "{err}");
    assert!(png_file.0.exists() && pgm_file.0.exists());
    let tmp = entries_with(&std::env::temp_dir(), ".render-");
    let ours = std::format!(".render-{}-", std::process::id());
    // This test's files only: other tests render in parallel.
    let left = |n: &&String| n.contains(&ours) && n.contains("-counts");
    assert!(!tmp.iter().any(|n| left(&n)), "{tmp:?}");
}

/// Issue 12, item 3: `-o` naming the scene file overwrote the scene. Now it
/// is refused, however the path is spelled, as is `--counts` naming the
/// scene or the PNG.
#[test]
fn issue_12_output_naming_the_scene_is_refused() {
    let scene = Temp::with("self.scene", SCENE);
    let dir = scene.0.parent().unwrap();
    let name = scene.0.file_name().unwrap().to_str().unwrap();
    let respelled = dir.join(".").join(name);
    let respelled = respelled.to_str().unwrap();
    let png_file = Temp::new("self.png");
    let (s, p) = (scene.arg(), png_file.arg());
    let cases = [
        (vec!["-o", s.as_str()], scene.arg(), "-o"),
        (vec!["-o", respelled], respelled.to_string(), "-o"),
        (
            vec!["-o", p.as_str(), "--counts", respelled],
            respelled.to_string(),
            "--counts",
        ),
    ];
    for (options, path, option) in cases {
        let mut args = vec![scene.arg()];
        args.extend(options.iter().map(|s| s.to_string()));
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let (code, out, err) = run(&args);
        assert_eq!((code, out.as_str()), (1, ""), "{args:?}");
        assert_eq!(
            err,
            format!("{path}: `{option}` names the scene file; refusing to overwrite it\n"),
            "{args:?}"
        );
        assert_eq!(std::fs::read_to_string(&scene.0).unwrap(), SCENE);
        assert!(!png_file.0.exists(), "{args:?}");
    }

    let (code, _, err) = run(&[
        &scene.arg(),
        "-o",
        &png_file.arg(),
        "--counts",
        &png_file.arg(),
    ]);
    assert_eq!(code, 1);
    assert_eq!(
        err,
        format!(
            "{}: `-o` and `--counts` name the same file\n",
            png_file.arg()
        )
    );
    assert!(!png_file.0.exists());
}

/// Issue 12, item 5: `--max-pixels` refuses a scene whose estimated work is
/// over the limit, writing nothing; at the limit it renders.
#[test]
fn issue_12_max_pixels() {
    // 4096 x 4096 and many clears: 2^24 pixels per clear.
    let mut text = String::from("size 4096 4096\n");
    for _ in 0..1000 {
        text.push_str("clear #ffffff\n");
    }
    let heavy = Temp::with("heavy.scene", &text);
    let png_file = Temp::new("heavy.png");
    let pgm_file = Temp::new("heavy.pgm");
    let (code, out, err) = run(&[
        &heavy.arg(),
        "-o",
        &png_file.arg(),
        "--counts",
        &pgm_file.arg(),
        "--max-pixels",
        "100000000",
    ]);
    assert_eq!((code, out.as_str()), (1, ""));
    assert_eq!(
        err,
        format!(
            "{}: too much work: {} pixels, over `--max-pixels 100000000`\n",
            heavy.arg(),
            1000u64 << 24
        )
    );
    assert!(!png_file.0.exists() && !pgm_file.0.exists());

    // SCENE costs 24 (clear) + 4 (rect) + 16 (tri's box 3..6 x 0..3
    // grown by half a pixel: columns 2..=5 and rows 0..=3 once clipped).
    let scene = Temp::with("light.scene", SCENE);
    for (limit, code) in [("44", 0), ("43", 1), ("0", 1)] {
        let (got, _, err) = run(&[&scene.arg(), "-o", &png_file.arg(), "--max-pixels", limit]);
        assert_eq!(got, code, "{limit}: {err}");
        assert_eq!(png_file.0.exists(), code == 0, "{limit}");
        let _ = std::fs::remove_file(&png_file.0);
    }
    for bad in ["-1", "x", "1e9"] {
        let (code, _, err) = run(&[&scene.arg(), "-o", &png_file.arg(), "--max-pixels", bad]);
        assert_eq!(code, 2, "{bad}");
        assert!(
            err.starts_with(&format!(
                "render: `--max-pixels` must be a non-negative integer, got `{bad}`"
            )),
            "{err}"
        );
    }
}

/// Found by `tests/fuzz.rs`: the cost estimate of a rectangle reaching past
/// `i32::MAX` overflowed (`Rectangle::intersection`).
#[test]
fn issue_12_cost_of_a_rectangle_past_i32_max() {
    let scene = embedded_raster::sim::parse_scene(
        "size 8 8\nrect 2147483647 0 2147483647 8 #ffffff\nrect -4 -4 2147483647 6 #ffffff\n",
    )
    .unwrap();
    assert_eq!(scene.pixel_work(), 16);
}

/// Issue 13: `--band N` writes the same PNG and counts as the whole-frame
/// render, for every scene in `scenes/` and band heights 1, 7, 16 and
/// 240, and `--stats` reports the bands and the band buffer's bytes.
#[test]
fn band_rendering_writes_identical_files() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let mut scenes: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| Some(e.ok()?.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "scene"))
        .collect();
    scenes.sort();
    assert!(scenes.len() >= 4, "{scenes:?}");
    for scene in scenes {
        let scene = scene.to_str().unwrap();
        let (png, pgm) = (Temp::new("whole.png"), Temp::new("whole.pgm"));
        let (code, _, err) = run(&[scene, "-o", &png.arg(), "--counts", &pgm.arg()]);
        assert_eq!(code, 0, "{err}");
        let (want_png, want_pgm) = (
            std::fs::read(&png.0).unwrap(),
            std::fs::read(&pgm.0).unwrap(),
        );
        let (w, h, _) = decode_png(&want_png);
        for rows in [1, 7, 16, 240] {
            let (png, pgm) = (Temp::new("band.png"), Temp::new("band.pgm"));
            let band = rows.to_string();
            let args = [
                scene,
                "-o",
                &png.arg(),
                "--counts",
                &pgm.arg(),
                "--band",
                &band,
                "--stats",
            ];
            let (code, out, err) = run(&args);
            assert_eq!(code, 0, "{err}");
            assert!(
                std::fs::read(&png.0).unwrap() == want_png,
                "{scene} --band {rows}: PNG differs"
            );
            assert!(
                std::fs::read(&pgm.0).unwrap() == want_pgm,
                "{scene} --band {rows}: counts differ"
            );
            let rows = rows.min(h);
            let tail = format!(
                r#","bands":{},"buffer_bytes":{}}}"#,
                h.div_ceil(rows),
                w * rows * 3
            );
            assert!(out.trim_end().ends_with(&tail), "{out}");
        }
    }
}

#[test]
fn band_option_errors() {
    let scene = Temp::with("band.scene", "size 2 2\n");
    let png_file = Temp::new("band-err.png");
    for bad in ["0", "-1", "x", "4294967296"] {
        let (code, _, err) = run(&[&scene.arg(), "-o", &png_file.arg(), "--band", bad]);
        assert_eq!(code, 2, "{bad}");
        assert!(
            err.starts_with("render: `--band` must be a number of rows from 1 to 4294967295, got "),
            "{err}"
        );
    }
    let (code, _, err) = run(&[&scene.arg(), "-o", &png_file.arg(), "--band"]);
    assert_eq!(code, 2);
    assert!(err.contains("`--band` needs a number of rows"), "{err}");
}

/// `render` wrote each output under a temporary name and renamed it over
/// the path given, so a symbolic link, a FIFO or a device there (as root,
/// `/dev/null`) was replaced by a plain file, and a link to the other
/// output escaped the same-file check. Links are now followed, and
/// anything but a regular file is refused.
#[cfg(unix)]
#[test]
fn outputs_through_links_and_special_files() {
    use std::os::unix::fs::symlink;

    let scene = Temp::with("links.scene", SCENE);
    // A link to a file that does not exist yet: the file is written, the
    // link stays.
    let (target, link) = (Temp::new("target.png"), Temp::new("link.png"));
    symlink(&target.0, &link.0).unwrap();
    let (code, _, err) = run(&[&scene.arg(), "-o", &link.arg()]);
    assert_eq!(code, 0, "{err}");
    assert!(std::fs::symlink_metadata(&link.0)
        .unwrap()
        .file_type()
        .is_symlink());
    let (w, h, _) = decode_png(&std::fs::read(&target.0).unwrap());
    assert_eq!((w, h), (6, 4));

    // `--counts` through a link to the PNG, which does not exist yet.
    let (png, to_png) = (Temp::new("same.png"), Temp::new("to-same.pgm"));
    symlink(&png.0, &to_png.0).unwrap();
    let (code, _, err) = run(&[&scene.arg(), "-o", &png.arg(), "--counts", &to_png.arg()]);
    assert_eq!(code, 1);
    assert_eq!(
        err,
        format!("{}: `-o` and `--counts` name the same file\n", to_png.arg())
    );
    assert!(!png.0.exists());

    // A link to the scene.
    let to_scene = Temp::new("to-scene.png");
    symlink(&scene.0, &to_scene.0).unwrap();
    let (code, _, err) = run(&[&scene.arg(), "-o", &to_scene.arg()]);
    assert_eq!(code, 1);
    assert_eq!(
        err,
        format!(
            "{}: `-o` names the scene file; refusing to overwrite it\n",
            to_scene.arg()
        )
    );
    assert_eq!(std::fs::read_to_string(&scene.0).unwrap(), SCENE);

    // A directory, and a FIFO where `mkfifo` exists: refused, left as
    // they were, and nothing written.
    let dir = Temp::new("dir.png");
    std::fs::create_dir(&dir.0).unwrap();
    let fifo = Temp::new("fifo.png");
    let made_fifo = std::process::Command::new("mkfifo")
        .arg(&fifo.0)
        .status()
        .is_ok_and(|s| s.success());
    let pgm = Temp::new("special.pgm");
    for (special, option) in [(&dir, "-o"), (&fifo, "--counts")] {
        if special.0 == fifo.0 && !made_fifo {
            continue;
        }
        let args = match option {
            "-o" => [
                scene.arg(),
                "-o".into(),
                special.arg(),
                "--counts".into(),
                pgm.arg(),
            ],
            _ => [
                scene.arg(),
                "-o".into(),
                png.arg(),
                "--counts".into(),
                special.arg(),
            ],
        };
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let (code, _, err) = run(&args);
        assert_eq!(code, 1, "{args:?}");
        assert_eq!(
            err,
            format!(
                "{}: `{option}` names something other than a regular file; refusing to replace it\n",
                special.arg()
            )
        );
        let kind = std::fs::symlink_metadata(&special.0).unwrap().file_type();
        assert!(!kind.is_file(), "{args:?}");
        assert!(!png.0.exists() && !pgm.0.exists(), "{args:?}");
    }
    let _ = std::fs::remove_dir(&dir.0);

    // A relative link, through a chain of two: the file it names, beside
    // the links, is written.
    let (file, first, second) = (
        Temp::new("chained.png"),
        Temp::new("first.png"),
        Temp::new("second.png"),
    );
    symlink(file.0.file_name().unwrap(), &first.0).unwrap();
    symlink(first.0.file_name().unwrap(), &second.0).unwrap();
    let (code, _, err) = run(&[&scene.arg(), "-o", &second.arg()]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(decode_png(&std::fs::read(&file.0).unwrap()).0, 6);
    assert!(std::fs::symlink_metadata(&second.0)
        .unwrap()
        .file_type()
        .is_symlink());

    // Paths that can only name a directory, even where a file of that
    // name exists (the review of the change above found `FILE/` written
    // over `FILE`): refused, the file left as it was.
    let existing = Temp::with("existing.png", "keep");
    for bad in [
        format!("{}/", existing.arg()),
        format!("{}/.", existing.arg()),
        format!("{}/..", existing.arg()),
        format!("{}/", link.arg()),
    ] {
        let (code, _, err) = run(&[&scene.arg(), "-o", &bad]);
        assert_eq!(code, 1, "{bad}");
        assert_eq!(
            err,
            format!("{bad}: `-o` must name a file, not end in `/`, `.` or `..`\n")
        );
        assert_eq!(std::fs::read_to_string(&existing.0).unwrap(), "keep");
        assert!(std::fs::symlink_metadata(&link.0)
            .unwrap()
            .file_type()
            .is_symlink());
    }

    // No temporary file is left by any of the runs above.
    let ours = format!(".render-{}-", std::process::id());
    let dir = std::env::temp_dir();
    let left: Vec<_> = entries_with(&dir, &ours)
        .into_iter()
        .filter(|n| {
            // This test's outputs only: other tests render in parallel.
            let names = [
                "target.png",
                "link.png",
                "same.png",
                "to-same.pgm",
                "to-scene.png",
                "dir.png",
                "fifo.png",
                "special.pgm",
                "chained.png",
                "existing.png",
            ];
            names.iter().any(|k| n.contains(&format!("-{k}.render-")))
        })
        .collect();
    assert!(left.is_empty(), "{left:?}");
}
