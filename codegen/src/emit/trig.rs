//! Which sine and cosine the generated code calls.
//!
//! The kernel itself is ordinary Rust in the crate `eom-kernel` (`kernel/`): one argument
//! reduction shared by sine and cosine, fdlibm's polynomials, all of a model's angles in one
//! call. The emitter only writes the call, so a crate that includes a trigonometric model
//! emitted with [`Trig::Kernel`] depends on `eom-kernel`.

/// Which sine and cosine the generated `rhs` calls.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
pub enum Trig {
    /// `eom_kernel::sin_cos([…])`, one call for all of a model's angles: the kernel for `f64`
    /// and `f32`, the scalar's own `simd_sin_cos` for every other scalar (and for every
    /// scalar with `eom-kernel`'s feature `platform-trig`).
    #[default]
    Kernel,
    /// The scalar's own `simd_sin_cos` for each angle, written into `rhs`: the platform's `sin`
    /// and `cos` for `f64`, and no dependency on `eom-kernel`.
    Std,
}
