//! # eom-peer — eom's generated models against SymPy's C
//!
//! `sympy/` holds what a user who does not use eom would write: the six spatial variants
//! derived with SymPy from vectors and matrices, `sympy.cse` over all outputs, printed as C99
//! (`sympy/README.md`). The build script compiles that C twice, op by op
//! (`-ffp-contract=off`) and with FMA contraction (`-ffp-contract=fast`), both
//! `-O3 -march=native`; this crate declares both builds ([`op_by_op`], [`fma`]), wraps eom's
//! generated `rhs` of each variant as a plain function that is not inlined into its caller
//! ([`eom_rhs`], [`EomModel`]), and draws the states that `benches/peer.rs` times them on ([`draw`]).
//!
//! Both sides compute the same function: the same state and input layout, the inertia
//! products with the sign of 4.14 (`I_xy = −∫xy dm`, eom's `Parameters`), and for quaternions
//! the normalised contract, R(q)v/|q|². SymPy's `_unit` form drops the division by |q|² and
//! is right only when |q| = 1; eom has no such form.

use eom::InertiaTensor;
use nalgebra::UnitQuaternion;

/// The bodies of eom's models bench, one per symmetry class: diag(2, 3, 4) turned so that
/// every product is non-zero (`full`), only I_xz (`xz`), none (`principal`).
pub use eom_test_support::bodies;

/// A right-hand side of SymPy's C: `void f(const double *k, const double *state, const double
/// *input, double *out)`.
pub type CRhs =
    unsafe extern "C" fn(k: *const f64, state: *const f64, input: *const f64, out: *mut f64);

/// The coefficients of SymPy's C: `void f(const double *parameters, double *k)`, with
/// `parameters = [mass, ixx, iyy, izz, ixy, iyz, ixz]`.
pub type CCoefficients = unsafe extern "C" fn(parameters: *const f64, k: *mut f64);

/// One variant's functions from one of the two C builds.
#[derive(Clone, Copy, Debug)]
pub struct CModel {
    /// The variant, e.g. `spatial_full_euler`.
    pub name: &'static str,
    /// The state's length: 12 (Euler angles) or 13 (quaternion).
    pub state_len: usize,
    /// How many coefficients `coefficients_fn` writes.
    pub k_len: usize,
    /// The right-hand side, normalised contract for quaternions.
    pub rhs_fn: CRhs,
    /// The same without the division by |q|², for quaternion variants only.
    pub unit_fn: Option<CRhs>,
    /// Computes `k` once per body.
    pub coefficients_fn: CCoefficients,
}

impl CModel {
    /// The coefficients of a body given as SymPy's `parameters` (see [`parameters`]).
    pub fn coefficients(&self, parameters: &[f64; 7]) -> Vec<f64> {
        let mut k = vec![0.0; self.k_len];
        // SAFETY: `parameters` holds the 7 entries the function reads and `k` the `k_len` it
        // writes (checked by this crate's tests).
        unsafe { (self.coefficients_fn)(parameters.as_ptr(), k.as_mut_ptr()) };
        k
    }

    /// The right-hand side at one state and input.
    ///
    /// # Panics
    /// When `N` is not the variant's state length or `k` not its coefficients' length.
    pub fn rhs<const N: usize>(&self, k: &[f64], state: &[f64; N], input: &[f64; 6]) -> [f64; N] {
        self.call(self.rhs_fn, k, state, input)
    }

    /// SymPy's unit-quaternion form at one state and input, `None` for Euler variants.
    ///
    /// # Panics
    /// As [`CModel::rhs`].
    pub fn rhs_unit<const N: usize>(
        &self,
        k: &[f64],
        state: &[f64; N],
        input: &[f64; 6],
    ) -> Option<[f64; N]> {
        self.unit_fn.map(|f| self.call(f, k, state, input))
    }

    fn call<const N: usize>(
        &self,
        f: CRhs,
        k: &[f64],
        state: &[f64; N],
        input: &[f64; 6],
    ) -> [f64; N] {
        assert_eq!(N, self.state_len, "state length of {}", self.name);
        assert_eq!(k.len(), self.k_len, "coefficients of {}", self.name);
        let mut out = [0.0; N];
        // SAFETY: the lengths are those the C reads and writes, checked above.
        unsafe { f(k.as_ptr(), state.as_ptr(), input.as_ptr(), out.as_mut_ptr()) };
        out
    }
}

/// SymPy's `parameters` of a body: `[mass, ixx, iyy, izz, ixy, iyz, ixz]`, as eom's
/// `FromBody` fills its own `Parameters` (I_xz is the tensor's `izx`, sign of 4.14).
pub fn parameters(mass: f64, inertia: &InertiaTensor) -> [f64; 7] {
    [
        mass,
        inertia.ixx(),
        inertia.iyy(),
        inertia.izz(),
        inertia.ixy(),
        inertia.iyz(),
        inertia.izx(),
    ]
}

/// Declares both C builds from one list of variants: their state length, how many
/// coefficients their `_coefficients` writes (the route `derive.py --emit` chose: built for
/// `full` and `xz`, hoisted for `principal`), and whether they have a `_unit` form.
macro_rules! sympy_c {
    ($($variant:ident { state: $n:literal, k: $k:literal $(, $unit:ident)? }),* $(,)?) => {
        sympy_c!(@build op_by_op, "peer_op_",
            "SymPy's C compiled `-O3 -march=native -ffp-contract=off`: every operation rounded \
             on its own, as written.",
            [$($variant { state: $n, k: $k $(, $unit)? }),*]);
        sympy_c!(@build fma, "peer_fma_",
            "SymPy's C compiled `-O3 -march=native -ffp-contract=fast`: the compiler may fuse a \
             multiplication and an addition into one FMA.",
            [$($variant { state: $n, k: $k $(, $unit)? }),*]);
    };
    (@build $build:ident, $prefix:literal, $doc:expr,
        [$($variant:ident { state: $n:literal, k: $k:literal $(, $unit:ident)? }),*]) => {
        #[doc = $doc]
        pub mod $build {
            use super::CModel;
            $(
                #[doc = concat!("The C functions of `", stringify!($variant), "`.")]
                pub mod $variant {
                    unsafe extern "C" {
                        /// The right-hand side (normalised contract for quaternions).
                        #[link_name = concat!($prefix, stringify!($variant))]
                        pub fn rhs(k: *const f64, state: *const f64, input: *const f64, out: *mut f64);
                        /// The coefficients, once per body.
                        #[link_name = concat!($prefix, stringify!($variant), "_coefficients")]
                        pub fn coefficients(parameters: *const f64, k: *mut f64);
                        $(
                            /// The right-hand side without the division by |q|².
                            #[link_name = concat!($prefix, stringify!($variant), "_unit")]
                            pub fn $unit(k: *const f64, state: *const f64, input: *const f64, out: *mut f64);
                        )?
                    }
                }
            )*
            /// Every variant of this build, in the order of `sympy/README.md`'s tables.
            pub const MODELS: [CModel; 6] = [$(CModel {
                name: stringify!($variant),
                state_len: $n,
                k_len: $k,
                rhs_fn: $variant::rhs,
                unit_fn: sympy_c!(@option $($variant::$unit)?),
                coefficients_fn: $variant::coefficients,
            }),*];
        }
    };
    (@option) => { None };
    (@option $($path:tt)+) => { Some($($path)+) };
}

sympy_c! {
    spatial_full_euler { state: 12, k: 13 },
    spatial_full_quaternion { state: 13, k: 13, unit },
    spatial_xz_euler { state: 12, k: 9 },
    spatial_xz_quaternion { state: 13, k: 9, unit },
    spatial_principal_euler { state: 12, k: 7 },
    spatial_principal_quaternion { state: 13, k: 7, unit },
}

/// eom's side of one variant: its coefficients for one body and its generated `rhs` behind a
/// `fn` pointer, as SymPy's C is called.
#[derive(Clone, Copy, Debug)]
pub struct EomModel<K, const N: usize> {
    /// The variant, e.g. `spatial_full_euler`.
    pub name: &'static str,
    /// `generated::<variant>::Coefficients::new` of the body.
    pub k: K,
    /// The generated `rhs`, wrapped in a function that is never inlined ([`eom_rhs`]).
    pub rhs: fn(&K, &[f64; N], &[f64; 6]) -> [f64; N],
}

/// eom's generated `rhs` of each variant, each a plain function that is never inlined into its
/// caller, and each variant's [`EomModel`] for a body ([`eom_model`]).
pub mod eom_rhs {
    use super::EomModel;
    use eom::InertiaTensor;
    use eom::models::{FromBody, generated};

    macro_rules! wrappers {
        ($($variant:ident: $n:literal),* $(,)?) => {
            $(
                #[doc = concat!("`generated::", stringify!($variant), "::rhs` for `f64`.")]
                #[inline(never)]
                pub fn $variant(
                    k: &generated::$variant::Coefficients<f64>,
                    state: &[f64; $n],
                    input: &[f64; 6],
                ) -> [f64; $n] {
                    generated::$variant::rhs(k, state, input)
                }
            )*
            /// Each variant's [`EomModel`] for one body: `Coefficients::new` of the
            /// `Parameters` that eom's `FromBody` fills from the mass and tensor.
            pub mod eom_model {
                use super::*;
                $(
                    #[doc = concat!("`", stringify!($variant), "` of a body.")]
                    pub fn $variant(
                        mass: f64,
                        inertia: &InertiaTensor,
                    ) -> EomModel<generated::$variant::Coefficients<f64>, $n> {
                        let parameters = generated::$variant::Parameters::from_body(mass, inertia);
                        EomModel {
                            name: stringify!($variant),
                            k: generated::$variant::Coefficients::new(&parameters),
                            rhs: super::$variant,
                        }
                    }
                )*
            }
        };
    }

    wrappers! {
        spatial_full_euler: 12,
        spatial_full_quaternion: 13,
        spatial_xz_euler: 12,
        spatial_xz_quaternion: 13,
        spatial_principal_euler: 12,
        spatial_principal_quaternion: 13,
    }
}

pub use eom_rhs::eom_model;

/// The body a variant is measured on: [`bodies::tensor_of`] its symmetry class.
///
/// # Panics
/// When `variant` is not a spatial model of eom's catalog.
pub fn body(variant: &str) -> InertiaTensor {
    let symmetry = eom::models::ModelInfo::find(variant)
        .and_then(|info| info.symmetry)
        .unwrap_or_else(|| panic!("{variant} is not a spatial model of eom's catalog"));
    bodies::tensor_of(symmetry)
}

/// The seed of the states the bench times and the tests check.
pub const SEED: u64 = 0x5EED_4E0F_2026;

/// The mass of every body, as in eom's models bench.
pub const MASS: f64 = 5.0;

/// One draw: a state in both attitude forms (the quaternion of the same Euler angles, of unit
/// norm to rounding) and an input.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Draw {
    /// `[u, v, w, p, q, r, x, y, z, φ, θ, ψ]`.
    pub euler: [f64; 12],
    /// `[u, v, w, p, q, r, x, y, z, q0, q1, q2, q3]`, the same motion.
    pub quaternion: [f64; 13],
    /// `[F_x, F_y, F_z, M_x, M_y, M_z]`, body axes, about G.
    pub input: [f64; 6],
}

/// `count` draws from `seed`, of a body in free motion, in SI units: forward speed 5 to
/// 40 m/s, side and vertical ±5 m/s, body rates ±1.5 rad/s, position within 1 km (no rate
/// reads it), roll and heading anywhere in [−π, π), pitch within ±80° (4.60 divides by
/// cos θ), force ±100 N and moment ±10 N·m on each axis.
pub fn draw(count: usize, seed: u64) -> Vec<Draw> {
    let mut rng = SplitMix64(seed);
    let pi = std::f64::consts::PI;
    (0..count)
        .map(|_| {
            let velocity = [
                rng.uniform(5.0, 40.0),
                rng.uniform(-5.0, 5.0),
                rng.uniform(-5.0, 5.0),
            ];
            let rates = [0; 3].map(|_| rng.uniform(-1.5, 1.5));
            let position = [0; 3].map(|_| rng.uniform(-1000.0, 1000.0));
            let (phi, theta, psi) = (
                rng.uniform(-pi, pi),
                rng.uniform(-80f64.to_radians(), 80f64.to_radians()),
                rng.uniform(-pi, pi),
            );
            let q = UnitQuaternion::from_euler_angles(phi, theta, psi);
            let force = [0; 3].map(|_| rng.uniform(-100.0, 100.0));
            let moment = [0; 3].map(|_| rng.uniform(-10.0, 10.0));
            let mut euler = [0.0; 12];
            let mut quaternion = [0.0; 13];
            for x in [&mut euler[..9], &mut quaternion[..9]] {
                x[..3].copy_from_slice(&velocity);
                x[3..6].copy_from_slice(&rates);
                x[6..9].copy_from_slice(&position);
            }
            euler[9..].copy_from_slice(&[phi, theta, psi]);
            quaternion[9..].copy_from_slice(&[q.w, q.i, q.j, q.k]);
            let mut input = [0.0; 6];
            input[..3].copy_from_slice(&force);
            input[3..].copy_from_slice(&moment);
            Draw {
                euler,
                quaternion,
                input,
            }
        })
        .collect()
}

/// Whether two evaluations of one right-hand side agree: every entry within `tolerance` times
/// the larger of the two outputs' largest entries (an entry's own size can be a cancellation
/// of larger terms). Returns the first entry that does not, with both values.
pub fn agree(a: &[f64], b: &[f64], tolerance: f64) -> Result<(), (usize, f64, f64)> {
    let scale = a.iter().chain(b).fold(0.0_f64, |m, x| m.max(x.abs()));
    match a
        .iter()
        .zip(b)
        .position(|(x, y)| (x - y).abs() > tolerance * scale || !(x - y).is_finite())
    {
        Some(i) => Err((i, a[i], b[i])),
        None => Ok(()),
    }
}

/// Sebastiano Vigna's SplitMix64: a fixed, portable stream, so the draws are the same on every
/// machine and need no dependency.
struct SplitMix64(u64);

impl SplitMix64 {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [lo, hi), from the top 53 bits.
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        let unit = (self.next() >> 11) as f64 / (1u64 << 53) as f64;
        lo + (hi - lo) * unit
    }
}
