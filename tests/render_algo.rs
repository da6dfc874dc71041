//! `render --algo NAME --bits N`.

#![cfg(feature = "sim")]

use embedded_raster::sim::cli;
use embedded_raster::TriangleAlgorithm;

fn run(args: &[&str]) -> (i32, String, String) {
    let (mut out, mut err) = (Vec::new(), Vec::new());
    let code = cli::run(args.iter().copied(), &mut out, &mut err);
    (
        code,
        String::from_utf8_lossy(&out).into(),
        String::from_utf8_lossy(&err).into(),
    )
}

#[test]
fn help_lists_every_algorithm_and_precision() {
    let (code, out, _) = run(&["--help"]);
    assert_eq!(code, cli::EXIT_OK);
    for a in TriangleAlgorithm::ALL {
        assert!(out.contains(a.name()), "{a} missing from --help");
    }
    assert!(out.contains("--bits N") && out.contains("0, 4, 8 or 12"));
}

#[test]
fn algorithms_and_precisions_change_the_pixels_written() {
    let dir = std::env::temp_dir();
    let id = std::process::id();
    let scene = dir.join(format!("algo-{id}.scene"));
    let png = dir.join(format!("algo-{id}.png"));
    // Two triangles sharing a diagonal: the closed Bresenham triangles
    // draw it twice.
    std::fs::write(
        &scene,
        "size 16 16\ntri 0 0 16 0 0 16 #ff0000\ntri 16 0 16 16 0 16 #0000ff\n",
    )
    .unwrap();
    let pixels = |extra: &[&str]| {
        let mut args = vec![
            scene.to_str().unwrap(),
            "-o",
            png.to_str().unwrap(),
            "--stats",
        ];
        args.extend_from_slice(extra);
        let (code, out, err) = run(&args);
        assert_eq!(code, cli::EXIT_OK, "{err}");
        let n = out.split("\"pixels_written\":").nth(1).unwrap();
        n.split(',').next().unwrap().parse::<u64>().unwrap()
    };
    assert_eq!(pixels(&[]), 256);
    assert_eq!(pixels(&["--algo", "exact", "--bits", "12"]), 256);
    assert_eq!(pixels(&["--algo", "barycentric", "--bits", "0"]), 256);
    assert_eq!(pixels(&["--algo", "walk", "--bits", "4"]), 256);
    assert!(pixels(&["--algo", "bresenham"]) > 256);
    for bad in [
        &["--algo", "scanline"][..],
        &["--bits", "6"],
        &["--bits"],
        &["--algo"],
    ] {
        let mut args = vec![scene.to_str().unwrap(), "-o", png.to_str().unwrap()];
        args.extend_from_slice(bad);
        let (code, _, err) = run(&args);
        assert_eq!(code, cli::EXIT_USAGE, "{bad:?}: {err}");
    }
    let _ = std::fs::remove_file(&scene);
    let _ = std::fs::remove_file(&png);
}

/// Found by a robustness audit: `--max-pixels` accepted these scenes
/// with `--algo walk` and `--algo bresenham`, which then wrote more
/// pixels than the estimate it checks. The walk drifted whole pixels
/// left of the triangle's vertices over half a million rows; the
/// Bresenham walk lights the pixels holding the vertices, outside the
/// box of pixel centres the estimate counted. Each scene, at every
/// precision, now stays within its estimate (read from the refusal at
/// `--max-pixels 0`) and is accepted at exactly that limit.
#[test]
fn inexact_variants_stay_within_the_estimate() {
    let dir = std::env::temp_dir();
    let id = std::process::id();
    let cases = [
        (
            "walk",
            "size 15 9\ntri 32.440673828125 24.465087890625 25.524658203125 -524288 \
             13.33251953125 161751.94783922 #bba974\n",
        ),
        ("bresenham", "size 64 64\ntri 10 10 20 10 10 11 #ffffff\n"),
    ];
    for (k, (algo, text)) in cases.into_iter().enumerate() {
        let scene = dir.join(format!("estimate-{id}-{k}.scene"));
        let png = dir.join(format!("estimate-{id}-{k}.png"));
        std::fs::write(&scene, text).unwrap();
        let (scene, png) = (scene.to_str().unwrap(), png.to_str().unwrap());
        for bits in ["0", "4", "8", "12"] {
            let base = [scene, "-o", png, "--algo", algo, "--bits", bits];
            let (code, _, err) = run(&[&base[..], &["--max-pixels", "0"]].concat());
            assert_eq!(code, 1, "{err}");
            let estimate = err.split("too much work: ").nth(1).unwrap();
            let estimate = estimate.split(' ').next().unwrap();
            let (code, out, err) =
                run(&[&base[..], &["--max-pixels", estimate, "--stats"]].concat());
            assert_eq!(code, cli::EXIT_OK, "{algo} at {bits} bits: {err}");
            let written = out.split("\"pixels_written\":").nth(1).unwrap();
            let written: u64 = written.split(',').next().unwrap().parse().unwrap();
            let estimate: u64 = estimate.parse().unwrap();
            assert!(
                written <= estimate,
                "{algo} at {bits} bits: {written} > {estimate}"
            );
            assert!(written > 0, "{algo} at {bits} bits lit nothing");
        }
    }
}
