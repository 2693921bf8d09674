//! Many bodies of one model stepped together, in SIMD lanes.
//!
//! Monte-Carlo sweeps, fleets and particle filters step thousands of bodies of one model. A
//! [`Batch`] holds them as arrays of lanes: with `T = WideF64x4` four bodies share each
//! register (`[WideF64x4; N]` per group of four), with `WideF32x8` eight; with `T = f64` it is
//! the plain loop over bodies, one at a time. The generated `rhs` is generic over simba's
//! `SimdRealField`, so the same proved code runs on every form, and its sines and cosines are
//! `eom-kernel`'s on the lanes too, bit for bit the scalar kernel's in each lane. A fixed-step
//! RK4, the very step [`Rk4`](crate::Rk4) takes ([`rk4_array`]), steps every group.
//!
//! The x86-64 baseline that rustc targets by default has 128-bit SSE2 registers, so four f64
//! lanes are two registers and the gain over scalar code is small; build with
//! `RUSTFLAGS="-C target-cpu=native"` on a machine with AVX2 for 256-bit registers
//! (`cargo bench --bench batch` measures each form; `docs/batch.md`).
//!
//! ```
//! use eom::batch::Batch;
//! use eom::models::SpatialPrincipalQuaternion;
//! use eom::{Constant, InertiaTensor};
//! use simba::simd::WideF64x4;
//!
//! let inertia = InertiaTensor::new(2.0, 3.0, 4.5, 0.0, 0.0, 0.0)?;
//! let model = SpatialPrincipalQuaternion::<WideF64x4>::new(1.0, &inertia)?;
//! // Ten rackets, each spun a little differently about its middle axis.
//! let starts: Vec<[f64; 13]> = (0..10)
//!     .map(|i| {
//!         let mut y = [0.0; 13];
//!         y[3..6].copy_from_slice(&[0.001 * f64::from(i + 1), 6.0, 0.002]);
//!         y[9] = 1.0;
//!         y
//!     })
//!     .collect();
//! let mut batch = Batch::<WideF64x4, 13>::new(&starts);
//! for step in 0..1000 {
//!     batch.step_rk4(&model, &Constant::zero(), f64::from(step) * 0.005, 0.005);
//! }
//! // Each body is where the scalar model would have taken it: the flip has begun.
//! assert_eq!(batch.bodies(), 10);
//! assert!(batch.state(9)[4] < 6.0);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::integrate::rk4_array;
use crate::models::{Loads, Model};
use simba::simd::SimdRealField;

/// Bodies of one model, as groups of `T::LANES` in SIMD lanes.
#[derive(Debug, Clone)]
pub struct Batch<T, const N: usize> {
    groups: Vec<[T; N]>,
    bodies: usize,
}

impl<T, const N: usize> Batch<T, N>
where
    T: SimdRealField + Copy,
    T::Element: Copy,
{
    /// The bodies in lanes, `T::LANES` to a group; the last group's empty lanes repeat the
    /// last body (they are stepped and never read).
    pub fn new(states: &[[T::Element; N]]) -> Self {
        let groups = states
            .chunks(T::LANES)
            .map(|chunk| {
                let last = chunk[chunk.len() - 1];
                std::array::from_fn(|j| {
                    let mut lanes = T::splat(last[j]);
                    for (lane, body) in chunk.iter().enumerate() {
                        lanes.replace(lane, body[j]);
                    }
                    lanes
                })
            })
            .collect();
        Batch {
            groups,
            bodies: states.len(),
        }
    }

    /// How many bodies.
    pub fn bodies(&self) -> usize {
        self.bodies
    }

    /// The state of body `body`.
    ///
    /// # Panics
    /// If `body` is not below [`bodies`](Self::bodies).
    pub fn state(&self, body: usize) -> [T::Element; N] {
        assert!(body < self.bodies, "body {body} of {}", self.bodies);
        let group = &self.groups[body / T::LANES];
        std::array::from_fn(|j| group[j].extract(body % T::LANES))
    }

    /// Every body's state, in order.
    pub fn states(&self) -> Vec<[T::Element; N]> {
        (0..self.bodies).map(|body| self.state(body)).collect()
    }

    /// One classical RK4 step of `h` from time `t` for every body, under `loads` (evaluated
    /// on the lanes: a [`Constant`](crate::Constant) splatted, or a function of the lanes'
    /// state).
    pub fn step_rk4<Mo, L, const M: usize>(&mut self, model: &Mo, loads: &L, t: f64, h: f64)
    where
        Mo: Model<T, N, M>,
        L: Loads<T, N, M>,
    {
        let (t, h) = (T::from_subset(&t), T::from_subset(&h));
        for group in &mut self.groups {
            rk4_array(|t, y| model.rhs(y, &loads.at(t, y)), t, h, group);
        }
    }
}
