//! Sine and cosine of `f64` angles from one argument reduction each.
//!
//! `k = round(2x/π)`; `r = x − k·π/2` in three steps, π/2 split Cody–Waite style so that the
//! first two products are exact; the minimax polynomials of fdlibm's `__kernel_sin` and
//! `__kernel_cos` on |r| ≤ π/4; the quadrant `k mod 4`, read from the low bits of the rounding
//! sum (those of k, two's complement), orders the pair and flips sign bits. Tiny arguments,
//! NaN, infinities and |x| > [`LIMIT`] take a cold path.
//!
//! The constants are written as IEEE-754 bit patterns, the form fdlibm documents them in.

use crate::lanes::{Lane, SIGN_BIT, place, quadrant};
use core::f64::consts::FRAC_PI_4;

/// The first 33 bits of π/2: `k·PIO2_1` is exact for |k| ≤ 2¹⁹.
pub const PIO2_1: f64 = f64::from_bits(0x3FF9_21FB_5440_0000);
/// The next 33 bits of π/2: `k·PIO2_2` is exact too.
pub const PIO2_2: f64 = f64::from_bits(0x3DD0_B461_1A60_0000);
/// π/2 − PIO2_1 − PIO2_2.
pub const PIO2_2T: f64 = f64::from_bits(0x3BA3_198A_2E03_7073);
/// Below 2¹⁹·π/2, so that |k| ≤ 2¹⁹ and the products above stay exact.
pub const LIMIT: f64 = f64::from_bits(0x4129_21FA_0000_0000);
/// 2⁻²⁷: below it sin x rounds to x and cos x to 1.
pub const TINY: f64 = f64::from_bits(0x3E40_0000_0000_0000);

/// fdlibm `__kernel_sin`, r³.
pub const S1: f64 = f64::from_bits(0xBFC5_5555_5555_5549);
/// fdlibm `__kernel_sin`, r⁵.
pub const S2: f64 = f64::from_bits(0x3F81_1111_1110_F8A6);
/// fdlibm `__kernel_sin`, r⁷.
pub const S3: f64 = f64::from_bits(0xBF2A_01A0_19C1_61D5);
/// fdlibm `__kernel_sin`, r⁹.
pub const S4: f64 = f64::from_bits(0x3EC7_1DE3_57B1_FE7D);
/// fdlibm `__kernel_sin`, r¹¹.
pub const S5: f64 = f64::from_bits(0xBE5A_E5E6_8A2B_9CEB);
/// fdlibm `__kernel_sin`, r¹³.
pub const S6: f64 = f64::from_bits(0x3DE5_D93A_5ACF_D57C);

/// fdlibm `__kernel_cos`, r⁴.
pub const C1: f64 = f64::from_bits(0x3FA5_5555_5555_554C);
/// fdlibm `__kernel_cos`, r⁶.
pub const C2: f64 = f64::from_bits(0xBF56_C16C_16C1_5177);
/// fdlibm `__kernel_cos`, r⁸.
pub const C3: f64 = f64::from_bits(0x3EFA_01A0_19CB_1590);
/// fdlibm `__kernel_cos`, r¹⁰.
pub const C4: f64 = f64::from_bits(0xBE92_7E4F_809C_52AD);
/// fdlibm `__kernel_cos`, r¹².
pub const C5: f64 = f64::from_bits(0x3E21_EE9E_BDB4_B1C4);
/// fdlibm `__kernel_cos`, r¹⁴.
pub const C6: f64 = f64::from_bits(0xBDA8_FAE9_BE88_38D4);

/// `(sin x, cos x)` of every `x`, from one argument reduction each: the kernel itself, which
/// [`sin_cos`](crate::sin_cos) calls for `f64` and `f32` (and which the feature
/// `platform-trig` leaves as it is).
///
/// One unsigned comparison of the bits of each |x|, which order as the magnitudes do, tells
/// whether all are in the kernel's range.
#[inline(always)]
pub fn sin_cos<const N: usize>(x: [f64; N]) -> [(f64, f64); N] {
    let outside = !all_in_range(&x);
    let mut pairs = [(0.0, 0.0); N];
    for (pair, &x) in pairs.iter_mut().zip(&x) {
        *pair = if outside {
            one_at_a_time(x)
        } else if N == 1 {
            in_range(x, Placement::Branch)
        } else {
            in_range(x, Placement::Masks)
        };
    }
    pairs
}

/// Whether every angle is in the kernel's range, TINY ≤ |x| ≤ LIMIT (NaN and the infinities
/// are not): one unsigned comparison of the bits of each |x|, which order as the magnitudes do.
#[inline(always)]
pub(crate) fn all_in_range<const N: usize>(x: &[f64; N]) -> bool {
    !x.iter().fold(false, |outside, &x| {
        let magnitude = x.to_bits() & !SIGN_BIT;
        outside | (magnitude.wrapping_sub(TINY.to_bits()) > LIMIT.to_bits() - TINY.to_bits())
    })
}

/// How [`in_range`] puts a reduced pair in its quadrant. With several angles, by bit masks,
/// which the compiler can pair in SIMD registers; with one, by branches, so that a model that
/// reads only the sine (the pendulum) evaluates the cosine's polynomial only in the quadrants
/// that need it.
#[derive(Clone, Copy, PartialEq)]
enum Placement {
    Masks,
    Branch,
}

/// One angle in the kernel's range: within ±π/4 evaluate it as it is; beyond, reduce,
/// evaluate, place in its quadrant.
#[inline(always)]
fn in_range(x: f64, placement: Placement) -> (f64, f64) {
    if x.abs() <= FRAC_PI_4 {
        return (sin_reduced(x), cos_reduced(x));
    }
    if placement == Placement::Masks {
        return reduce_and_place(x);
    }
    let (quadrant, r) = reduce(x);
    let (s, c) = if quadrant & 1 == 0 {
        (sin_reduced(r), cos_reduced(r))
    } else {
        (cos_reduced(r), sin_reduced(r))
    };
    let sin_sign = (quadrant << 62) & SIGN_BIT;
    let cos_sign = (quadrant.wrapping_add(1) << 62) & SIGN_BIT;
    (
        f64::from_bits(s.to_bits() ^ sin_sign),
        f64::from_bits(c.to_bits() ^ cos_sign),
    )
}

/// The quadrant bits and `r = x − k·π/2`, in three steps (the first two products exact).
#[inline(always)]
fn reduce<V: Lane>(x: V) -> (V::Bits, V) {
    let (bits, k) = quadrant(x);
    let r = ((x - k * V::splat(PIO2_1)) - k * V::splat(PIO2_2)) - k * V::splat(PIO2_2T);
    (bits, r)
}

/// Reduce, evaluate both polynomials, place by bit masks: for several angles side by side, and
/// for lanes (where an angle within ±π/4 has k = 0 and comes back as it is).
#[inline(always)]
pub(crate) fn reduce_and_place<V: Lane>(x: V) -> (V, V) {
    let (bits, r) = reduce(x);
    place(bits, sin_reduced(r), cos_reduced(r))
}

/// Any angle: tiny ones, where sin x rounds to x and cos x to 1; NaN, infinite and beyond
/// [`LIMIT`] ones, for the platform; the others through the kernel.
#[cold]
#[inline(never)]
fn one_at_a_time(x: f64) -> (f64, f64) {
    let magnitude = x.abs();
    if magnitude < TINY {
        (x, 1.0)
    } else if magnitude <= LIMIT {
        in_range(x, Placement::Branch)
    } else {
        x.sin_cos()
    }
}

/// sin r for |r| ≤ π/4: `r + r³ P(r²)`, P of degree 5 in pairs (Estrin's scheme), so that the
/// chain of dependent operations is four deep instead of seven.
#[inline(always)]
fn sin_reduced<V: Lane>(r: V) -> V {
    let c = V::splat;
    let z = r * r;
    let w = z * z;
    let p = (c(S1) + z * c(S2)) + w * ((c(S3) + z * c(S4)) + w * (c(S5) + z * c(S6)));
    r + z * r * p
}

/// cos r for |r| ≤ π/4: `1 − r²/2 + r⁴ Q(r²)`, with the rounding error of `1 − r²/2` added
/// back; Q in pairs as in [`sin_reduced`].
#[inline(always)]
fn cos_reduced<V: Lane>(r: V) -> V {
    let c = V::splat;
    let z = r * r;
    let w = z * z;
    let q = (c(C1) + z * c(C2)) + w * ((c(C3) + z * c(C4)) + w * (c(C5) + z * c(C6)));
    let half_z = c(0.5) * z;
    let head = c(1.0) - half_z;
    head + (((c(1.0) - head) - half_z) + w * q)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The bit patterns against the decimal values fdlibm prints beside them (its `invpio2`
    /// is the standard library's 2/π, which the kernel uses).
    #[test]
    fn constants_match_fdlibm_decimals() {
        assert_eq!(
            core::f64::consts::FRAC_2_PI,
            "6.36619772367581382433e-01".parse::<f64>().unwrap()
        );
        let decimals = [
            ("PIO2_1", PIO2_1, "1.57079632673412561417e+00"),
            ("PIO2_2", PIO2_2, "6.07710050630396597660e-11"),
            ("PIO2_2T", PIO2_2T, "2.02226624879595063154e-21"),
            ("S1", S1, "-1.66666666666666324348e-01"),
            ("S2", S2, "8.33333333332248946124e-03"),
            ("S3", S3, "-1.98412698298579493134e-04"),
            ("S4", S4, "2.75573137070700676789e-06"),
            ("S5", S5, "-2.50507602534068634195e-08"),
            ("S6", S6, "1.58969099521155010221e-10"),
            ("C1", C1, "4.16666666666666019037e-02"),
            ("C2", C2, "-1.38888888888741095749e-03"),
            ("C3", C3, "2.48015872894767294178e-05"),
            ("C4", C4, "-2.75573143513906633035e-07"),
            ("C5", C5, "2.08757232129817482790e-09"),
            ("C6", C6, "-1.13596475577881948265e-11"),
        ];
        for (name, constant, decimal) in decimals {
            assert_eq!(constant, decimal.parse::<f64>().unwrap(), "{name}");
        }
    }

    /// The reduction's exactness rests on these: PIO2_1 and PIO2_2 have at most 33
    /// significant bits, the split sums to π/2, and |k| stays within 2¹⁹ below LIMIT.
    #[test]
    fn reduction_constants_keep_the_products_exact() {
        for (name, constant) in [("PIO2_1", PIO2_1), ("PIO2_2", PIO2_2)] {
            let mantissa = constant.to_bits() & ((1 << 52) - 1);
            assert!(mantissa.trailing_zeros() >= 52 - 32, "{name}");
        }
        assert_eq!(PIO2_1 + PIO2_2 + PIO2_2T, core::f64::consts::FRAC_PI_2);
        let k_max = (LIMIT * core::f64::consts::FRAC_2_PI).round();
        assert!(k_max <= f64::from(1 << 19));
        assert_eq!(crate::lanes::ROUNDER, 1.5 * 2f64.powi(52));
        assert_eq!(TINY, 2f64.powi(-27));
    }
}
