//! Sine and cosine of `f32` angles: the structure of the f64 kernel, with what f32 needs.
//!
//! `k = round(2x/π)`; `r = x − k·π/2` in two steps, π/2 split into a 33-bit head, whose
//! product with `k` is exact for |k| ≤ 2²⁰, and a tail; the minimax polynomials of musl's
//! `__sindf` and `__cosdf` on |r| ≤ π/4, of degree 9 and 8 instead of fdlibm's 13 and 14; the
//! quadrant from the low bits of the rounding sum, as in the f64 kernel. Like musl, the
//! arithmetic is in f64 (an f32 converts to f64 exactly) and the result is rounded to f32 once:
//! the polynomials are good to 2⁻³⁴ and the reduction to far better, so what is left is the one
//! rounding. No path for tiny arguments is needed: the sine is written `r·(1 + r²P(r²))`, which
//! keeps the sign of ±0 and gives back `r` when r² is negligible. NaN, infinities and
//! |x| > [`LIMIT`] take the f64 kernel's cold path (the platform's f64 `sin_cos`), rounded.
//!
//! The constants are written as IEEE-754 bit patterns, as in the f64 kernel.

use crate::lanes::{Lane, place, quadrant};
use core::f64::consts::FRAC_PI_4;

/// The first 33 bits of π/2 (fdlibm's `pio2_1`): `k·PIO2_1` is exact for |k| ≤ 2²⁰.
const PIO2_1: f64 = f64::from_bits(0x3FF9_21FB_5440_0000);
/// π/2 − PIO2_1 (fdlibm's `pio2_1t`).
const PIO2_1T: f64 = f64::from_bits(0x3DD0_B461_1A62_6331);
/// The f64 kernel's limit, below 2¹⁹·π/2: |k| ≤ 2¹⁹, and beyond it the same platform path.
const LIMIT: f32 = 823_549.0;

/// musl `__sindf`, r³.
const S1: f64 = f64::from_bits(0xBFC5_5555_54CB_AC77);
/// musl `__sindf`, r⁵.
const S2: f64 = f64::from_bits(0x3F81_1110_896E_FBB2);
/// musl `__sindf`, r⁷.
const S3: f64 = f64::from_bits(0xBF2A_00F9_E2CA_E774);
/// musl `__sindf`, r⁹.
const S4: f64 = f64::from_bits(0x3EC6_CD87_8C3B_46A7);

/// musl `__cosdf`, r².
const C0: f64 = f64::from_bits(0xBFDF_FFFF_FD0C_5E81);
/// musl `__cosdf`, r⁴.
const C1: f64 = f64::from_bits(0x3FA5_5553_E105_3A42);
/// musl `__cosdf`, r⁶.
const C2: f64 = f64::from_bits(0xBF56_C087_E80F_1E27);
/// musl `__cosdf`, r⁸.
const C3: f64 = f64::from_bits(0x3EF9_9342_E0EE_5069);

/// The sign bit of an f32.
const SIGN_BIT: u32 = 1 << 31;

/// `(sin x, cos x)` of every `x`, each within one f32 ulp of the correctly rounded value: the
/// f32 kernel, which [`sin_cos`](crate::sin_cos) calls for `f32`.
///
/// One unsigned comparison of the bits of each |x| tells whether all are in the kernel's
/// range (NaN and the infinities order above every finite magnitude).
#[inline(always)]
pub fn sin_cos<const N: usize>(x: [f32; N]) -> [(f32, f32); N] {
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

/// Whether every |x| ≤ LIMIT (NaN and the infinities order above every finite magnitude).
#[inline(always)]
pub(crate) fn all_in_range<const N: usize>(x: &[f32; N]) -> bool {
    !x.iter().fold(false, |outside, &x| {
        outside | ((x.to_bits() & !SIGN_BIT) > LIMIT.to_bits())
    })
}

/// How [`in_range`] puts a reduced pair in its quadrant, as in the f64 kernel: by bit masks for
/// several angles, by branches for one.
#[derive(Clone, Copy, PartialEq)]
enum Placement {
    Masks,
    Branch,
}

/// One angle in the kernel's range: within ±π/4 evaluate it as it is; beyond, reduce,
/// evaluate, place in its quadrant.
#[inline(always)]
fn in_range(x: f32, placement: Placement) -> (f32, f32) {
    let x = f64::from(x);
    if x.abs() <= FRAC_PI_4 {
        return (sin_reduced(x) as f32, cos_reduced(x) as f32);
    }
    if placement == Placement::Masks {
        let (s, c) = reduce_and_place(x);
        return (s as f32, c as f32);
    }
    let (quadrant, r) = reduce(x);
    // The low bits of k, two's complement.
    let quadrant = quadrant as u32;
    let s = (sin_reduced(r) as f32).to_bits();
    let c = (cos_reduced(r) as f32).to_bits();
    let (s, c) = if quadrant & 1 == 0 { (s, c) } else { (c, s) };
    let sin_sign = (quadrant << 30) & SIGN_BIT;
    let cos_sign = (quadrant.wrapping_add(1) << 30) & SIGN_BIT;
    (f32::from_bits(s ^ sin_sign), f32::from_bits(c ^ cos_sign))
}

/// The quadrant bits and `r = x − k·π/2`, in two steps (the first product exact), in f64.
#[inline(always)]
fn reduce<V: Lane>(x: V) -> (V::Bits, V) {
    let (bits, k) = quadrant(x);
    (bits, (x - k * V::splat(PIO2_1)) - k * V::splat(PIO2_1T))
}

/// Reduce, evaluate, place by bit masks, all in f64 (the caller rounds to f32 once: rounding
/// commutes with the placement's swap and sign flips).
#[inline(always)]
pub(crate) fn reduce_and_place<V: Lane>(x: V) -> (V, V) {
    let (bits, r) = reduce(x);
    place(bits, sin_reduced(r), cos_reduced(r))
}

/// Any angle: NaN, infinite and beyond [`LIMIT`] ones through the f64 kernel (which hands them
/// to the platform), rounded; the others through this kernel.
#[cold]
#[inline(never)]
fn one_at_a_time(x: f32) -> (f32, f32) {
    if x.abs() <= LIMIT {
        in_range(x, Placement::Branch)
    } else {
        let [(s, c)] = crate::kernel::sin_cos([f64::from(x)]);
        (s as f32, c as f32)
    }
}

/// sin r for |r| ≤ π/4: `r·(1 + r²P(r²))`, P of degree 3 in pairs (Estrin's scheme).
#[inline(always)]
fn sin_reduced<V: Lane>(r: V) -> V {
    let c = V::splat;
    let z = r * r;
    let w = z * z;
    let p = (c(S1) + z * c(S2)) + w * (c(S3) + z * c(S4));
    r * (c(1.0) + z * p)
}

/// cos r for |r| ≤ π/4: `1 + r²Q(r²)`, Q of degree 3 in pairs.
#[inline(always)]
fn cos_reduced<V: Lane>(r: V) -> V {
    let c = V::splat;
    let z = r * r;
    let w = z * z;
    c(1.0) + z * ((c(C0) + z * c(C1)) + w * (c(C2) + z * c(C3)))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The bit patterns against the hexadecimal significands musl writes them in.
    #[test]
    fn constants_match_musl() {
        let p = |significand: u64, exponent: i32| significand as f64 * 2f64.powi(exponent);
        let constants = [
            ("S1", S1, -p(0x15_5555_54CB_AC77, -55)),
            ("S2", S2, p(0x11_1110_896E_FBB2, -59)),
            ("S3", S3, -p(0x1A_00F9_E2CA_E774, -65)),
            ("S4", S4, p(0x16_CD87_8C3B_46A7, -71)),
            ("C0", C0, -p(0x1F_FFFF_FD0C_5E81, -54)),
            ("C1", C1, p(0x15_5553_E105_3A42, -57)),
            ("C2", C2, -p(0x16_C087_E80F_1E27, -62)),
            ("C3", C3, p(0x19_9342_E0EE_5069, -68)),
        ];
        for (name, constant, musl) in constants {
            assert_eq!(constant, musl, "{name}");
        }
        assert_eq!(
            PIO2_1T,
            "6.07710050650619224932e-11".parse::<f64>().unwrap()
        );
    }

    /// PIO2_1 has at most 33 significant bits, the split is π/2 to the tail's precision, and
    /// |k| stays within 2¹⁹ below LIMIT, which is the f64 kernel's.
    #[test]
    fn reduction_constants_keep_the_products_exact() {
        let mantissa = PIO2_1.to_bits() & ((1 << 52) - 1);
        assert!(mantissa.trailing_zeros() >= 52 - 32);
        assert_eq!(PIO2_1 + PIO2_1T, core::f64::consts::FRAC_PI_2);
        assert!((f64::from(LIMIT) * core::f64::consts::FRAC_2_PI).round() <= f64::from(1 << 19));
        assert_eq!(f64::from(LIMIT), 823_549.0);
    }
}
