//! The generated models behind a typed, validated API.
//!
//! Each type validates its parameters once (finite numbers, mass > 0, a physical inertia
//! tensor, products of inertia zero where the symmetry class prunes them; the pendulum takes
//! them already validated as a [`crate::PendulumParameters`]), computes the
//! generated coefficients once, and then offers `rhs` — the generated right-hand side — and the
//! kinetic energy (4.32). All are generic over the scalar `T: SimdRealField + Copy`: `f32`,
//! `f64`, `simba::simd::WideF64x4` lanes, or dual numbers.
//!
//! | type | state | inputs |
//! |---|---|---|
//! | [`Pendulum`] | `[θ, θ̇]` | moment about the pivot |
//! | [`PlanarAtG`] | `[u, v, r, X, Y, ψ]` | `[F_x, F_y, M_z]` body axes, about G |
//! | [`PlanarMidship`] | `[u, v, r, X, Y, ψ]` of the midship origin | `[X, Y, N]` body axes, about midship |
//! | [`PlanarSpaceFixed`] | `[X, Y, ψ, Ẋ, Ẏ, ψ̇]` | `[F_X, F_Y, M_z]` space axes |
//! | [`SpatialFullEuler`], [`SpatialXzEuler`], [`SpatialPrincipalEuler`] | `[u, v, w, p, q, r, x, y, z, φ, θ, ψ]` | force and moment about G, body axes |
//! | [`SpatialFullQuaternion`], [`SpatialXzQuaternion`], [`SpatialPrincipalQuaternion`] | `[u, v, w, p, q, r, x, y, z, q0, q1, q2, q3]` | force and moment about G, body axes |
//!
//! The Euler-angle variants are singular at θ = ±90° (4.60 divides by cos θ); use a
//! quaternion variant for attitudes that may get there.

pub mod generated;
mod pendulum;
mod planar;
mod spatial;

pub use pendulum::Pendulum;
pub use planar::{PlanarAtG, PlanarMidship, PlanarSpaceFixed};
pub use spatial::{
    FromBody, SpatialFullEuler, SpatialFullQuaternion, SpatialPrincipalEuler,
    SpatialPrincipalQuaternion, SpatialXzEuler, SpatialXzQuaternion, Symmetry,
};

/// Converts a validated f64 parameter to the scalar type.
fn scalar<T: simba::simd::SimdRealField>(value: f64) -> T {
    T::from_subset(&value)
}
