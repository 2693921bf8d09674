//! The kernel on SIMD lanes: four f64 angles in a `wide::f64x4`, eight f32 angles in a
//! `wide::f32x8` (widened to eight f64 lanes, as the scalar f32 kernel widens), bit for bit
//! what the scalar kernels give each lane.
//!
//! The scalar kernels are written once, over [`Lane`]: the arithmetic, the constants
//! splatted, and the bit operations that place a pair in its quadrant. A lane needs no branch
//! for angles within ±π/4: there `k = round(2x/π)` is 0 and the reduction gives back `x`
//! exactly, so the reduced path is the scalar's small-angle path, bit for bit. Lanes outside
//! the kernel's range (tiny, beyond its limit, NaN, infinite) take the scalar kernel's cold
//! path one lane at a time, as one such scalar would.
//!
//! This replaces the lanes' own `simd_sin_cos` (wide's, which rounds with `round` and converts
//! with `round_int`, emulated lane by lane on the x86-64 baseline).

use core::ops::{Add, BitAnd, BitXor, Mul, Shl, Sub};
use wide::{f32x8, f64x4, f64x8, u64x4, u64x8};

/// What the kernel needs of a number: `f64`, or four of them in lanes.
pub(crate) trait Lane:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self>
{
    /// The bits of the number, lane by lane.
    type Bits: Copy
        + BitAnd<Output = Self::Bits>
        + BitXor<Output = Self::Bits>
        + Shl<u32, Output = Self::Bits>
        + Add<Output = Self::Bits>;
    /// The constant in every lane.
    fn splat(x: f64) -> Self;
    /// The integer in every lane.
    fn splat_bits(x: u64) -> Self::Bits;
    /// The IEEE-754 bits.
    fn to_bits(self) -> Self::Bits;
    /// From IEEE-754 bits.
    fn from_bits(bits: Self::Bits) -> Self;
    /// All ones in the lanes where `bits` is odd, zeros elsewhere.
    fn odd_mask(bits: Self::Bits) -> Self::Bits;
}

impl Lane for f64 {
    type Bits = u64;
    #[inline(always)]
    fn splat(x: f64) -> Self {
        x
    }
    #[inline(always)]
    fn splat_bits(x: u64) -> u64 {
        x
    }
    #[inline(always)]
    fn to_bits(self) -> u64 {
        f64::to_bits(self)
    }
    #[inline(always)]
    fn from_bits(bits: u64) -> Self {
        f64::from_bits(bits)
    }
    #[inline(always)]
    fn odd_mask(bits: u64) -> u64 {
        0u64.wrapping_sub(bits & 1)
    }
}

impl Lane for f64x4 {
    type Bits = u64x4;
    #[inline(always)]
    fn splat(x: f64) -> Self {
        f64x4::splat(x)
    }
    #[inline(always)]
    fn splat_bits(x: u64) -> u64x4 {
        u64x4::splat(x)
    }
    #[inline(always)]
    fn to_bits(self) -> u64x4 {
        bytemuck::cast(self)
    }
    #[inline(always)]
    fn from_bits(bits: u64x4) -> Self {
        bytemuck::cast(bits)
    }
    #[inline(always)]
    fn odd_mask(bits: u64x4) -> u64x4 {
        let one = u64x4::splat(1);
        (bits & one).simd_eq(one)
    }
}

impl Lane for f64x8 {
    type Bits = u64x8;
    #[inline(always)]
    fn splat(x: f64) -> Self {
        f64x8::splat(x)
    }
    #[inline(always)]
    fn splat_bits(x: u64) -> u64x8 {
        u64x8::splat(x)
    }
    #[inline(always)]
    fn to_bits(self) -> u64x8 {
        bytemuck::cast(self)
    }
    #[inline(always)]
    fn from_bits(bits: u64x8) -> Self {
        bytemuck::cast(bits)
    }
    #[inline(always)]
    fn odd_mask(bits: u64x8) -> u64x8 {
        let one = u64x8::splat(1);
        (bits & one).simd_eq(one)
    }
}

/// 1.5·2⁵²: adding and subtracting it rounds an f64 below 2⁵¹ to an integer.
pub const ROUNDER: f64 = f64::from_bits(0x4338_0000_0000_0000);
/// The sign bit of an f64.
pub const SIGN_BIT: u64 = 1 << 63;

/// `(x·2/π + ROUNDER, k)`: the rounding sum, whose low bits are those of k (two's
/// complement), and k = round(2x/π) itself.
#[inline(always)]
pub(crate) fn quadrant<V: Lane>(x: V) -> (V::Bits, V) {
    let shifted = x * V::splat(core::f64::consts::FRAC_2_PI) + V::splat(ROUNDER);
    (shifted.to_bits(), shifted - V::splat(ROUNDER))
}

/// The reduced pair `(sin r, cos r)` put in quadrant `k mod 4` (the low bits of `quadrant`):
/// swapped for odd k, the sine negated for k ≡ 2, 3 and the cosine for k ≡ 1, 2.
#[inline(always)]
pub(crate) fn place<V: Lane>(quadrant: V::Bits, sin: V, cos: V) -> (V, V) {
    let (s, c) = (sin.to_bits(), cos.to_bits());
    let swap = (s ^ c) & V::odd_mask(quadrant);
    let sign = V::splat_bits(SIGN_BIT);
    let sin_sign = (quadrant << 62) & sign;
    let cos_sign = ((quadrant + V::splat_bits(1)) << 62) & sign;
    (
        V::from_bits(s ^ swap ^ sin_sign),
        V::from_bits(c ^ swap ^ cos_sign),
    )
}

/// `(sin, cos)` of four f64 angles, as [`crate::sin_cos_f64`] gives each.
#[inline(always)]
pub fn sin_cos_f64x4(x: f64x4) -> (f64x4, f64x4) {
    let angles = x.to_array();
    if !crate::kernel::all_in_range(&angles) {
        return cold_f64x4(angles);
    }
    crate::kernel::reduce_and_place(x)
}

#[cold]
#[inline(never)]
fn cold_f64x4(angles: [f64; 4]) -> (f64x4, f64x4) {
    let pairs = crate::kernel::sin_cos(angles);
    (
        f64x4::new(pairs.map(|p| p.0)),
        f64x4::new(pairs.map(|p| p.1)),
    )
}

/// `(sin, cos)` of eight f32 angles, as [`crate::sin_cos_f32`] gives each: widened to eight
/// f64 lanes (one AVX-512 register, or two AVX2 ones), the f32 kernel's arithmetic there,
/// rounded once.
#[inline(always)]
pub fn sin_cos_f32x8(x: f32x8) -> (f32x8, f32x8) {
    let angles = x.to_array();
    if !crate::single::all_in_range(&angles) {
        let pairs = crate::single::sin_cos(angles);
        return (
            f32x8::new(pairs.map(|p| p.0)),
            f32x8::new(pairs.map(|p| p.1)),
        );
    }
    let wide = f64x8::new(angles.map(f64::from));
    let (s, c) = crate::single::reduce_and_place(wide);
    let narrow = |x: f64x8| f32x8::new(x.to_array().map(|x| x as f32));
    (narrow(s), narrow(c))
}
