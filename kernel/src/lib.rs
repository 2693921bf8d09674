//! # eom-kernel — what the generated models call and implement
//!
//! Everything generated code needs at run time, and nothing more: the fused `sin_cos` and
//! `mul_add` it calls, the model contract it implements ([`Model`], [`Loads`], [`Constant`],
//! [`Driven`], in `contract`), and the count of what a call costs ([`Operations`]). A model
//! emitted from a user's own `build.rs` depends on this crate, not on `eom`; `eom` re-exports
//! the contract where its users look for it (`eom::Model`, `eom::models`).
//!
//! ## The sine and cosine
//!
//! In the trigonometric models the three `sin_cos` of the Euler angles (or the one of the
//! heading) cost more than all the arithmetic around them, and the platform's `sin` and `cos`
//! each reduce the argument and branch on its size again. So the generated `rhs` calls one
//! kernel that does both from a single argument reduction: `k = round(2x/π)`, the remainder
//! `r = x − k·π/2` in three steps (Cody–Waite: π/2 split into two 33-bit parts whose products
//! with `k` are exact, and a tail), then the minimax polynomials of fdlibm's `__kernel_sin`
//! and `__kernel_cos` on `|r| ≤ π/4` (Sun Microsystems, 1993; the same coefficients as musl
//! and openlibm), evaluated in pairs (Estrin's scheme) for a short chain of dependent
//! operations, and the quadrant `k mod 4` picks signs and order. A model's angles go through
//! one call side by side, so the compiler can pair them in SIMD registers. An angle within
//! ±π/4 skips the reduction, as fdlibm's own `sin` and `cos` do: the roll and pitch of a ship
//! or an aircraft in ordinary motion stay there, and the reduction is a third of the chain of
//! dependent operations that an integrator's stages wait on. The test is a branch per angle,
//! which only varying angles that cross ±π/4 from call to call would mispredict.
//!
//! The kernel runs on `f64` and `f32` scalars. f32 has one of its own, [`sin_cos_f32`]: the
//! same structure with musl's shorter polynomials for f32 (`__sindf`, `__cosdf`) and a two-step
//! reduction, evaluated in f64 like musl's and rounded once, within one ulp of the correctly
//! rounded pair and faster than the f64 kernel (which f32 went through before, widened and
//! rounded, slower than f64 itself). simba's SIMD lanes, `WideF64x4` and `WideF32x8`, run the
//! same kernels lane by lane ([`sin_cos_f64x4`], [`sin_cos_f32x8`]), bit for bit what each
//! lane's scalar would give. Any other scalar (dual numbers) keeps its own `simd_sin_cos`: the
//! rounding trick would drop a dual number's derivative.
//! Arguments beyond `2¹⁹·π/2`, where the two-part products stop being exact, and NaN or
//! infinite ones go to the platform's f64 `sin_cos` unchanged (f32 ones widened, rounded).
//!
//! The kernel lives here, as ordinary Rust, rather than in the emitter: every generated model
//! calls this one copy as `eom_kernel::sin_cos`, and the compiler, clippy, rustfmt and the
//! tests see it where it is written. Everything on its path is `#[inline(always)]`, so it is
//! compiled into each `rhs` as if it were written there.
//!
//! ```
//! let [(s, c), (s2, c2)] = eom_kernel::sin_cos([0.5_f64, 2.0]);
//! assert!((s - 0.5_f64.sin()).abs() <= f64::EPSILON && (c - 0.5_f64.cos()).abs() <= f64::EPSILON);
//! assert!((s2 - 2.0_f64.sin()).abs() <= f64::EPSILON && (c2 - 2.0_f64.cos()).abs() <= f64::EPSILON);
//! ```
//!
//! ## Feature `platform-trig`
//!
//! With it, [`sin_cos`] calls each scalar's own `simd_sin_cos` for every scalar, `f64` and
//! `f32` included: the platform's `sin` and `cos`, bit for bit. Build a model with and without
//! it to price the kernel inside that model (`eom` forwards the feature), or turn it on when
//! results must match the platform's to the last bit. [`sin_cos_f64`] stays the kernel.
#![deny(missing_docs)]

mod contract;
mod kernel;
mod lanes;
mod operations;
mod single;

pub use contract::{Constant, Driven, Loads, Model, scatter};
pub use kernel::sin_cos as sin_cos_f64;
pub use lanes::{sin_cos_f32x8, sin_cos_f64x4};
pub use operations::Operations;
pub use single::sin_cos as sin_cos_f32;

/// The f64 kernel's constants, for a code generator that writes the kernel out where a model
/// would call it (`eom`'s models compiled at run time). With these, and the operations of
/// [`sin_cos_f64`] in their order (`k = round(2x/π)` by [`ROUNDER`](recipe::ROUNDER), the
/// three-step reduction, the two Estrin polynomials, the quadrant's swap and signs), such code
/// gives the kernel's bits; arguments outside `TINY ≤ |x| ≤ LIMIT` (and NaN) must go to
/// [`sin_cos_f64`] itself.
pub mod recipe {
    pub use crate::kernel::{
        C1, C2, C3, C4, C5, C6, LIMIT, PIO2_1, PIO2_2, PIO2_2T, S1, S2, S3, S4, S5, S6, TINY,
    };
    pub use crate::lanes::{ROUNDER, SIGN_BIT};

    /// Whether [`sin_cos`](crate::sin_cos) of `f64` is this kernel: false with the feature
    /// `platform-trig`, whose platform `sin` and `cos` no written-out kernel reproduces.
    pub const IS_THE_KERNEL: bool = !cfg!(feature = "platform-trig");
}

use core::any::Any;
use simba::simd::{SimdRealField, WideF32x8, WideF64x4};

/// `(sin a, cos a)` of every angle in `angles`, as the generated `rhs` computes them.
///
/// For `f64` this is the kernel, [`sin_cos_f64`]: one argument reduction shared by sine and
/// cosine, within 2 ulp of the platform's `sin` and `cos`, the angles side by side so that the
/// compiler can pair them in SIMD registers. For `f32` it is [`sin_cos_f32`], the same for
/// f32, within one ulp of the correctly rounded pair. For `WideF64x4` and `WideF32x8` the same,
/// lane by lane. Every other scalar (dual numbers) uses its own `simd_sin_cos`, and so does
/// every scalar with the feature `platform-trig`.
#[inline(always)]
pub fn sin_cos<T: SimdRealField + Copy, const N: usize>(angles: [T; N]) -> [(T, T); N] {
    let scalars: &dyn Any = &angles;
    let mut pairs = [(T::zero(), T::zero()); N];
    if cfg!(feature = "platform-trig") {
        return each_own(angles);
    } else if let Some(angles) = scalars.downcast_ref::<[f64; N]>() {
        for (pair, (s, c)) in pairs.iter_mut().zip(sin_cos_f64(*angles)) {
            *pair = (T::from_subset(&s), T::from_subset(&c));
        }
    } else if let Some(angles) = scalars.downcast_ref::<[f32; N]>() {
        // f32 → f64 → f32 is exact, and the compiler drops it.
        for (pair, (s, c)) in pairs.iter_mut().zip(sin_cos_f32(*angles)) {
            *pair = (T::from_subset(&f64::from(s)), T::from_subset(&f64::from(c)));
        }
    } else if let Some(angles) = scalars.downcast_ref::<[WideF64x4; N]>() {
        let lanes: &mut dyn Any = &mut pairs;
        let lanes = lanes
            .downcast_mut::<[(WideF64x4, WideF64x4); N]>()
            .expect("T is WideF64x4");
        for (pair, angle) in lanes.iter_mut().zip(angles) {
            let (s, c) = sin_cos_f64x4(angle.0);
            *pair = (WideF64x4(s), WideF64x4(c));
        }
    } else if let Some(angles) = scalars.downcast_ref::<[WideF32x8; N]>() {
        let lanes: &mut dyn Any = &mut pairs;
        let lanes = lanes
            .downcast_mut::<[(WideF32x8, WideF32x8); N]>()
            .expect("T is WideF32x8");
        for (pair, angle) in lanes.iter_mut().zip(angles) {
            let (s, c) = sin_cos_f32x8(angle.0);
            *pair = (WideF32x8(s), WideF32x8(c));
        }
    } else {
        return each_own(angles);
    }
    pairs
}

/// `a·b + c` as the generated models write every product that feeds a sum: one fused
/// multiply–add, rounded once, when the build targets a CPU with FMA
/// (`cfg(target_feature = "fma")`, e.g. `RUSTFLAGS="-C target-cpu=native"`), and the product
/// and the sum each rounded otherwise (the default x86-64 target), which is the op-by-op
/// result bit for bit. The choice is made at compile time, so one build gives one set of bits.
///
/// ```
/// // 0.1·3 − 0.3: the product rounded first leaves 2⁻⁵⁴ (5.6e-17); fused, the exact
/// // product of the double nearest 0.1 with 3, less 0.3, is 2⁻⁵⁵ (2.8e-17). Which one a build
/// // gives is fixed when it is compiled.
/// let r = eom_kernel::mul_add(0.1_f64, 3.0, -0.3);
/// assert!(r == 0.1_f64 * 3.0 - 0.3 || r == 0.1_f64.mul_add(3.0, -0.3));
/// ```
#[inline(always)]
pub fn mul_add<T: SimdRealField + Copy>(a: T, b: T, c: T) -> T {
    if cfg!(target_feature = "fma") {
        a.simd_mul_add(b, c)
    } else {
        a * b + c
    }
}

/// Each angle's own `simd_sin_cos`.
#[inline(always)]
fn each_own<T: SimdRealField + Copy, const N: usize>(angles: [T; N]) -> [(T, T); N] {
    let mut pairs = [(T::zero(), T::zero()); N];
    for (pair, angle) in pairs.iter_mut().zip(angles) {
        *pair = angle.simd_sin_cos();
    }
    pairs
}
