//! Numbers in messages, to six significant digits, and counts with their nouns.
//!
//! A message names the value it objects to or the time a run stopped at; printed with Rust's
//! shortest round-trip form, `every = 1e-300` came back as a 300-digit decimal and a stop time
//! as `32.08092344497079`. Six significant digits say which value it was without drowning the
//! sentence; the files a run writes keep every digit.

use std::fmt;

/// A number displayed to at most six significant digits: plain between 10⁻⁴ and 10⁶,
/// scientific beyond, trailing zeros dropped (`32.0809`, `20`, `1e-300`, `1.5e+308` as
/// `1.5e308`).
///
/// ```
/// use eom::Short;
/// assert_eq!(Short(32.08092344497079).to_string(), "32.0809");
/// assert_eq!(Short(20.0).to_string(), "20");
/// assert_eq!(Short(1e-300).to_string(), "1e-300");
/// assert_eq!(Short(-1.2345678e9).to_string(), "-1.23457e9");
/// assert_eq!(Short(f64::NAN).to_string(), "NaN");
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Short(pub f64);

impl fmt::Display for Short {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let x = self.0;
        if x == 0.0 || !x.is_finite() {
            return write!(f, "{x}");
        }
        let exponent = x.abs().log10().floor() as i32;
        if (-4..6).contains(&exponent) {
            let decimals = (5 - exponent).max(0) as usize;
            let text = format!("{x:.decimals$}");
            return f.write_str(trim_zeros(&text));
        }
        let text = format!("{x:.5e}");
        let (mantissa, power) = text.split_once('e').unwrap_or((&text, "0"));
        write!(f, "{}e{power}", trim_zeros(mantissa))
    }
}

/// A count and its noun in the number the count takes: `1 value`, `2 values`, `0 values`.
///
/// ```
/// assert_eq!(eom::counted(1, "value", "values"), "1 value");
/// assert_eq!(eom::counted(3, "Newton step", "Newton steps"), "3 Newton steps");
/// ```
pub fn counted(n: usize, one: &str, many: &str) -> String {
    format!("{n} {}", if n == 1 { one } else { many })
}

/// `x` with `decimals` decimals, without the sign of a value that rounds to zero: a figure
/// printed in a fixed column reads `0.000`, never `-0.000`.
///
/// ```
/// assert_eq!(eom::fixed(-2.5e-14, 3), "0.000");
/// assert_eq!(eom::fixed(-0.0006, 3), "-0.001");
/// ```
pub fn fixed(x: f64, decimals: usize) -> String {
    let text = format!("{x:.decimals$}");
    match text.strip_prefix('-') {
        Some(unsigned) if unsigned.chars().all(|c| c == '0' || c == '.') => unsigned.to_owned(),
        _ => text,
    }
}

/// `1.500` → `1.5`, `20.000` → `20`; a number without a decimal point as it is.
fn trim_zeros(text: &str) -> &str {
    match text.contains('.') {
        true => text.trim_end_matches('0').trim_end_matches('.'),
        false => text,
    }
}

#[cfg(test)]
mod tests {
    use super::{Short, fixed};

    #[test]
    fn a_value_that_rounds_to_zero_is_printed_without_its_sign() {
        assert_eq!(fixed(-2.5e-14, 3), "0.000");
        assert_eq!(fixed(-0.0, 2), "0.00");
        assert_eq!(fixed(-0.0006, 3), "-0.001");
        assert_eq!(fixed(-5.3164, 4), "-5.3164");
    }

    #[test]
    fn at_most_six_significant_digits_at_every_scale() {
        for (x, shown) in [
            (0.000123456789, "0.000123457"),
            (0.5, "0.5"),
            (999999.4, "999999"),
            (1e6, "1e6"),
            (1e308, "1e308"),
            (-2.5e-5, "-2.5e-5"),
            (100.0, "100"),
        ] {
            assert_eq!(Short(x).to_string(), shown, "{x}");
        }
    }
}
