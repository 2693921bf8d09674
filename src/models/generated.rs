//! The generated right-hand sides, one module per variant, emitted by `build.rs` into
//! `OUT_DIR` from the proved equations.
//!
//! Each module has `Parameters` (f64, as given), `Coefficients<T>` (every parameter-only
//! coefficient, computed once), `STATE` and `INPUTS` (the array layouts), `OPERATIONS` (the
//! cost of one call) and `rhs`, generic over simba's `SimdRealField`. The typed wrappers in
//! [`crate::models`] validate the parameters; call these directly only with validated ones.
//!
//! The models with angles call [`eom_kernel::sin_cos`] for all of their angles at once; the
//! feature `platform-trig` makes that the platform's sine and cosine.

macro_rules! generated_modules {
    ($($name:ident: $doc:literal,)*) => {
        $(
            #[doc = $doc]
            #[allow(clippy::let_and_return, clippy::redundant_locals)]
            pub mod $name {
                include!(concat!(env!("OUT_DIR"), "/", stringify!($name), ".rs"));
            }
        )*

        /// Every generated module's name, title and operation count per call.
        pub const CATALOG: &[(&str, &str, [(&str, u32); 5])] = &[
            $((stringify!($name), $doc, $name::OPERATIONS),)*
        ];
    };
}

generated_modules! {
    pendulum: "Compound pendulum, 4.24; state `[θ, θ̇]`, input `[M_O]`.",
    planar_at_g: "Planar motion in body axes at G, 4.43 + 4.44; state `[u, v, r, X, Y, ψ]`, inputs `[F_x, F_y, M_z]`.",
    planar_midship: "Planar motion in body axes at midship, 4.46 + 4.44; state `[u, v, r, X, Y, ψ]`, inputs `[X, Y, N]` at midship.",
    planar_space_fixed: "Planar motion in space-fixed axes, 4.39; state `[X, Y, ψ, Ẋ, Ẏ, ψ̇]`, inputs `[F_X, F_Y, M_z]`.",
    spatial_full_euler: "Spatial 6-DOF, all products of inertia (4.51), Euler angles (4.57, 4.60).",
    spatial_full_quaternion: "Spatial 6-DOF, all products of inertia (4.51), unit quaternion.",
    spatial_xz_euler: "Spatial 6-DOF, symmetric about the xz-plane (I_xy = I_yz = 0), Euler angles.",
    spatial_xz_quaternion: "Spatial 6-DOF, symmetric about the xz-plane (I_xy = I_yz = 0), unit quaternion.",
    spatial_principal_euler: "Spatial 6-DOF, principal axes (4.52), Euler angles.",
    spatial_principal_quaternion: "Spatial 6-DOF, principal axes (4.52), unit quaternion.",
}
