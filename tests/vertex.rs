//! Vertex conversions: rounding, ties, ranges, errors.

use embedded_graphics_core::geometry::Point;
use embedded_raster::{CoordinateOutOfRange, ParseCoordinateError, Vertex, I20F12};
use proptest::prelude::*;

/// Exact reference for parsing: round `sign * (int + frac / 10^k)` to the
/// nearest multiple of 1/4096, ties to even, in `u128` arithmetic.
fn reference_raw(negative: bool, int: u64, frac: &str) -> Option<i32> {
    let den = 10u128.pow(frac.len() as u32);
    let num = (u128::from(int) * den + frac.parse::<u128>().unwrap_or(0)) * 4096;
    let (q, r) = (num / den, num % den);
    let rounded = if 2 * r > den || (2 * r == den && q % 2 == 1) {
        q + 1
    } else {
        q
    };
    let signed = if negative {
        -(rounded as i128)
    } else {
        rounded as i128
    };
    i32::try_from(signed).ok()
}

proptest! {
    #[test]
    fn parsing_rounds_exactly(negative in any::<bool>(), int in 0u64..600_000, frac in "[0-9]{0,24}") {
        let text = format!("{}{}.{}", if negative { "-" } else { "" }, int, frac);
        let got = Vertex::parse(&text, "0").map(|v| v.raw().0);
        match reference_raw(negative, int, &frac) {
            Some(raw) => prop_assert_eq!(got, Ok(raw), "{}", text),
            None => prop_assert_eq!(got, Err(ParseCoordinateError::OutOfRange), "{}", text),
        }
    }

    /// Decimal ties (odd multiples of 1/8192), and numbers one unit in the
    /// 30th decimal place above or below them (in magnitude).
    #[test]
    fn parsing_ties_and_near_ties(negative in any::<bool>(), m in 0u64..(1 << 32), nudge in -1i128..=1) {
        // The magnitude m / 8192 has at most 13 decimal places: pad to 30.
        let frac = i128::from(m % 8192) * 10i128.pow(30) / 8192 + nudge;
        prop_assume!((0..10i128.pow(30)).contains(&frac));
        let text = format!("{}{}.{:030}", if negative { "-" } else { "" }, m / 8192, frac);
        // Round the magnitude: m is in half-steps.
        let (steps, half) = (i64::try_from(m / 2).unwrap(), m % 2 == 1);
        let magnitude = match (half, nudge) {
            (false, _) => steps,        // exact, or a hair off an exact value
            (true, 1) => steps + 1,     // just above a tie
            (true, -1) => steps,        // just below a tie
            (true, _) => steps + steps % 2, // a tie: to even
        };
        let want = if negative { -magnitude } else { magnitude };
        let got = Vertex::parse(&text, "0").map(|v| i64::from(v.raw().0));
        if i32::try_from(want).is_ok() {
            prop_assert_eq!(got, Ok(want), "{}", text);
        } else {
            prop_assert_eq!(got, Err(ParseCoordinateError::OutOfRange), "{}", text);
        }
    }

    #[test]
    fn floats_round_to_nearest_ties_even(raw in any::<i32>(), half in any::<bool>()) {
        // Every raw value, and every tie halfway between two, as an f64.
        let x = f64::from(raw) / 4096.0 + if half { 0.5 / 4096.0 } else { 0.0 };
        let want = if half && raw % 2 != 0 { i64::from(raw) + 1 } else { i64::from(raw) };
        let got = Vertex::try_from_num(x, 0.0).map(|v| i64::from(v.raw().0));
        if want > i64::from(i32::MAX) {
            prop_assert_eq!(got, Err(CoordinateOutOfRange));
        } else {
            prop_assert_eq!(got, Ok(want));
        }
    }

    #[test]
    fn points_map_to_pixel_centres(x in any::<i32>(), y in any::<i32>()) {
        let fits = |c: i32| (-524_288..=524_287).contains(&c);
        let got = Vertex::try_from(Point::new(x, y));
        if fits(x) && fits(y) {
            let v = got.unwrap();
            prop_assert_eq!(v.raw(), (x * 4096 + 2048, y * 4096 + 2048));
        } else {
            prop_assert_eq!(got, Err(CoordinateOutOfRange));
        }
    }
}

#[test]
fn range_ends() {
    assert_eq!(
        Vertex::parse("-524288", "524287.999755859375")
            .unwrap()
            .raw(),
        (i32::MIN, i32::MAX)
    );
    // Rounds up past the last representable value.
    assert_eq!(
        Vertex::parse("524287.99987793", "0"),
        Err(ParseCoordinateError::OutOfRange)
    );
    // Rounds down onto it.
    assert_eq!(
        Vertex::parse("524287.9998779", "0").unwrap().raw().0,
        i32::MAX
    );
    // 0.41 of a step below the end rounds onto it; 0.504 of a step does not.
    assert_eq!(
        Vertex::parse("-524288.0001", "0").unwrap().raw().0,
        i32::MIN
    );
    assert_eq!(
        Vertex::parse("-524288.000123", "0"),
        Err(ParseCoordinateError::OutOfRange)
    );
    // A long integer part far outside the range.
    assert_eq!(
        Vertex::parse("99999999999999999999999999", "0"),
        Err(ParseCoordinateError::OutOfRange)
    );
    // The case `fixed`'s own parser rounds the wrong way (4095.49988 steps).
    assert_eq!(Vertex::parse("1.9998779", "0").unwrap().raw().0, 8191);
    assert_eq!(
        Vertex::parse("-524288.0001220703125", "0").unwrap().raw().0,
        i32::MIN
    );
    assert_eq!(Vertex::try_from_num(-524288, 0).unwrap().raw().0, i32::MIN);
    assert_eq!(Vertex::try_from_num(524288, 0), Err(CoordinateOutOfRange));
    assert_eq!(Vertex::try_from_num(i64::MIN, 0), Err(CoordinateOutOfRange));
    assert_eq!(
        Vertex::new(I20F12::MIN, I20F12::MAX).raw(),
        (i32::MIN, i32::MAX)
    );
}

#[test]
fn non_numbers_are_rejected() {
    for bad in [
        "", "-", "+", ".", "nan", "NaN", "inf", "-inf", "1e3", "0x10", "1.2.3", "1,5", " 1", "1 ",
        "--1", "١",
    ] {
        assert_eq!(
            Vertex::parse(bad, "0"),
            Err(ParseCoordinateError::Invalid),
            "{bad:?}"
        );
    }
    for float in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
        assert_eq!(Vertex::try_from_num(float, 0), Err(CoordinateOutOfRange));
    }
}

#[test]
fn decimal_forms_that_are_numbers() {
    for (text, raw) in [
        ("12", 12 * 4096),
        ("-3.5", -3 * 4096 - 2048),
        ("+2", 8192),
        ("5.", 5 * 4096),
        (".5", 2048),
        ("-0", 0),
        ("007.25", 7 * 4096 + 1024),
        ("100.000244140625", 100 * 4096 + 1),
    ] {
        assert_eq!(Vertex::parse(text, "0").unwrap().raw().0, raw, "{text}");
    }
}
