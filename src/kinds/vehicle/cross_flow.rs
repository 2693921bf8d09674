//! The cross-flow drag of a hull in strips, as Fossen's MSS `npsauv.m` integrates it for the
//! NPS AUV II ("a block-shaped body and strip theory"): at each strip i, at x_i along the
//! hull, of length Δx_i, height H_i and breadth B_i, the local cross flow of the body's
//! velocity at (x_i, 0, 0),
//!
//! ```text
//! a_i = v + x_i r,   b_i = w − x_i q,   U_i = √(a_i² + b_i²),
//! D_i = C_dy H_i a_i² + C_dz B_i b_i²,
//! F_y,i = −½ρ Δx_i D_i a_i/U_i,   F_z,i = −½ρ Δx_i D_i b_i/U_i,
//! ```
//!
//! and the loads about O are the sums of these forces and of their moments about O:
//! Y = Σ F_y,i, Z = Σ F_z,i, M = −Σ x_i F_z,i, N = Σ x_i F_y,i (X = K = 0).
//!
//! This is not a polynomial in the state (U_i is a root), and its polynomial part, D_i a_i,
//! is cubic in the velocities with dimensional coefficients per strip: no term of a prime
//! table (at most two velocity factors) and no name of the table's vocabulary. So the drag is
//! a force of its own, hand-written here with its derivatives by v, w, q, r and tested
//! against a transcription of the source and against dual numbers; the proved program reads
//! its loads as the generator's applied loads (inputs `F_x` … `M_z`, added to the six
//! equations' right side, which are proved with them), and the model's Jacobian adds
//! ∂f/∂F · ∂F/∂ν. At U_i = 0 (no cross flow at the strip) its force and derivatives are zero,
//! their limits; the source's 1e-6 added to U_i against dividing by zero is not carried.
//!
//! The pitch moment: npsauv.m's reads (w + x_i q) where its heave force reads the local
//! b_i = w − x_i q, so its M is not the moment of its own Z forces; the two agree in the part
//! in q (a damping, −½ρΣ Δx_i D_i x_i² q/U_i) and differ in sign in the part in w (which the
//! source makes −½ρ Σ Δx_i D_i x_i w/U_i). eom takes the moment of the forces it applies,
//! M = −Σ x_i F_z,i, so that the drag is one system of forces, dissipative as a drag must be:
//! its power −Σ (F_y,i a_i + F_z,i b_i) ≤ 0 is the loads' power on (v, w, q, r) exactly.

use simba::simd::SimdRealField;

/// A hull in strips and its drag coefficients, as the scene gives them.
#[derive(Debug, Clone, PartialEq)]
pub struct CrossFlow {
    /// x_i, the strips' stations along body x from O, m.
    pub stations: Vec<f64>,
    /// Δx_i, the strips' lengths, m.
    pub lengths: Vec<f64>,
    /// H_i, the strips' heights (the area the sway flow meets per length), m.
    pub heights: Vec<f64>,
    /// B_i, the strips' breadths (the area the heave flow meets per length), m.
    pub breadths: Vec<f64>,
    /// C_dy, the drag coefficient of the sway flow.
    pub sway_coefficient: f64,
    /// C_dz, the drag coefficient of the heave flow.
    pub heave_coefficient: f64,
    /// ρ, kg/m³.
    pub density: f64,
}

/// The drag's loads about O (X, Y, Z, K, M, N) and their derivatives by ν = (u, v, w, p, q,
/// r): `by[load][velocity]`.
#[derive(Debug, Clone, Copy)]
pub struct CrossFlowLoads<T> {
    /// τ, N and N m.
    pub loads: [T; 6],
    /// ∂τ/∂ν.
    pub by: [[T; 6]; 6],
}

impl CrossFlow {
    /// The loads at the body velocities `nu` = (u, v, w, p, q, r), without their derivatives:
    /// what the rates read, the same numbers as [`Self::loads`]'s.
    pub fn forces<T: SimdRealField + Copy>(&self, nu: &[T]) -> [T; 6] {
        let value = |x: f64| T::from_subset(&x);
        let (v, w, q, r) = (nu[1], nu[2], nu[4], nu[5]);
        let mut loads = [T::zero(); 6];
        for i in 0..self.stations.len() {
            let x = value(self.stations[i]);
            let half_rho_dx = value(0.5 * self.density * self.lengths[i]);
            let cy = value(self.sway_coefficient * self.heights[i]);
            let cz = value(self.heave_coefficient * self.breadths[i]);
            let [fa, fb] = Strip::force(v + x * r, w - x * q, cy, cz);
            loads[1] -= half_rho_dx * fa;
            loads[2] -= half_rho_dx * fb;
            loads[4] += half_rho_dx * x * fb;
            loads[5] -= half_rho_dx * x * fa;
        }
        loads
    }

    /// The loads at the body velocities `nu` = (u, v, w, p, q, r), with their derivatives.
    pub fn loads<T: SimdRealField + Copy>(&self, nu: &[T]) -> CrossFlowLoads<T> {
        let value = |x: f64| T::from_subset(&x);
        let (v, w, q, r) = (nu[1], nu[2], nu[4], nu[5]);
        let mut loads = [T::zero(); 6];
        let mut by = [[T::zero(); 6]; 6];
        for i in 0..self.stations.len() {
            let x = value(self.stations[i]);
            let half_rho_dx = value(0.5 * self.density * self.lengths[i]);
            let cy = value(self.sway_coefficient * self.heights[i]);
            let cz = value(self.heave_coefficient * self.breadths[i]);
            let strip = Strip::at(v + x * r, w - x * q, cy, cz);
            // F_y = −½ρΔx f_a, F_z = −½ρΔx f_b; M = −x F_z, N = x F_y.
            let [fa, fb] = strip.force;
            let [[fa_a, fa_b], [fb_a, fb_b]] = strip.by;
            loads[1] -= half_rho_dx * fa;
            loads[2] -= half_rho_dx * fb;
            loads[4] += half_rho_dx * x * fb;
            loads[5] -= half_rho_dx * x * fa;
            // ∂a/∂v = 1, ∂a/∂r = x; ∂b/∂w = 1, ∂b/∂q = −x.
            let by_velocity = |f_a: T, f_b: T| [f_a, f_b, -x * f_b, x * f_a];
            for (load, (f_a, f_b), scale) in [
                (1, (fa_a, fa_b), -half_rho_dx),
                (2, (fb_a, fb_b), -half_rho_dx),
                (4, (fb_a, fb_b), half_rho_dx * x),
                (5, (fa_a, fa_b), -half_rho_dx * x),
            ] {
                for (velocity, d) in [1, 2, 4, 5].into_iter().zip(by_velocity(f_a, f_b)) {
                    by[load][velocity] += scale * d;
                }
            }
        }
        CrossFlowLoads { loads, by }
    }
}

/// One strip's f = D·(a, b)/U and its derivatives by (a, b), zero where U = 0.
struct Strip<T> {
    force: [T; 2],
    by: [[T; 2]; 2],
}

impl<T: SimdRealField + Copy> Strip<T> {
    /// f alone, as [`Self::at`] computes it.
    fn force(a: T, b: T, cy: T, cz: T) -> [T; 2] {
        let squared = a * a + b * b;
        let flowing = squared.simd_gt(T::zero());
        let speed = squared.simd_sqrt().select(flowing, T::one());
        let drag = cy * a * a + cz * b * b;
        let zeroed = |x: T| x.select(flowing, T::zero());
        [zeroed(drag * a / speed), zeroed(drag * b / speed)]
    }

    fn at(a: T, b: T, cy: T, cz: T) -> Self {
        let two = T::from_subset(&2.0);
        let squared = a * a + b * b;
        let flowing = squared.simd_gt(T::zero());
        // U where there is cross flow, 1 where there is none (every result is then zeroed).
        let speed = squared.simd_sqrt().select(flowing, T::one());
        let drag = cy * a * a + cz * b * b;
        let cubed = speed * speed * speed;
        let zeroed = |x: T| x.select(flowing, T::zero());
        let cross = -drag * a * b / cubed;
        Strip {
            force: [zeroed(drag * a / speed), zeroed(drag * b / speed)],
            by: [
                [
                    zeroed((two * cy * a * a + drag) / speed - drag * a * a / cubed),
                    zeroed(two * cz * b * a / speed + cross),
                ],
                [
                    zeroed(two * cy * a * b / speed + cross),
                    zeroed((two * cz * b * b + drag) / speed - drag * b * b / cubed),
                ],
            ],
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_dual::Dual64;

    /// npsauv.m's hull: 11 strips at −L/2, −L/2 + L/10, …, L/2, each L/10 long, 0.53 m by
    /// 0.53 m, C_dy = 0.5, C_dz = 0.6.
    fn nps() -> CrossFlow {
        let length = 5.3;
        CrossFlow {
            stations: (0..11)
                .map(|k| -length / 2.0 + k as f64 * length / 10.0)
                .collect(),
            lengths: vec![length / 10.0; 11],
            heights: vec![0.53; 11],
            breadths: vec![0.53; 11],
            sway_coefficient: 0.5,
            heave_coefficient: 0.6,
            density: 1025.0,
        }
    }

    /// The source's loop as it writes it (without its 1e-6), with its pitch arm (w + x q) or
    /// the moment of its forces (−(w − x q)).
    fn source(hull: &CrossFlow, nu: [f64; 6], own_pitch_arm: bool) -> [f64; 6] {
        let (v, w, q, r) = (nu[1], nu[2], nu[4], nu[5]);
        let (mut cy, mut cz, mut cm, mut cn) = (0.0, 0.0, 0.0, 0.0);
        for (i, &x) in hull.stations.iter().enumerate() {
            let dx = hull.lengths[i];
            let ucf = ((v + x * r).powi(2) + (w - x * q).powi(2)).sqrt();
            let drag = hull.sway_coefficient * hull.heights[i] * (v + x * r).powi(2)
                + hull.heave_coefficient * hull.breadths[i] * (w - x * q).powi(2);
            cy += dx * drag * (v + x * r) / ucf;
            cz += dx * drag * (w - x * q) / ucf;
            let arm = if own_pitch_arm {
                w + x * q
            } else {
                -(w - x * q)
            };
            cm += dx * drag * arm / ucf * x;
            cn += dx * drag * (v + x * r) / ucf * x;
        }
        let half_rho = hull.density / 2.0;
        [
            0.0,
            -half_rho * cy,
            -half_rho * cz,
            0.0,
            -half_rho * cm,
            -half_rho * cn,
        ]
    }

    const STATES: [[f64; 6]; 4] = [
        [1.4, 0.178, -0.02, 0.01, -0.003, -0.052],
        [1.6, 0.05, 0.1, 0.0, 0.02, 0.0],
        [1.0, -0.3, 0.0, 0.0, 0.0, 0.1],
        [1.2, 0.0, 0.15, 0.0, 0.0, 0.0],
    ];

    #[test]
    fn the_loads_are_the_source_s_with_the_moment_of_its_forces() {
        let hull = nps();
        for nu in STATES {
            let ours = hull.loads(&nu).loads;
            let theirs = source(&hull, nu, false);
            for (load, (a, b)) in ours.iter().zip(theirs).enumerate() {
                // The same sums in another order: rounding of loads of order 10–100 N.
                assert!(
                    (a - b).abs() <= 1e-12 * (1.0 + b.abs()),
                    "{nu:?} load {load}"
                );
            }
            // The source's own pitch arm (w + x q) gives another M where w and q are both
            // non-zero (see the module docs); printed for the record.
            let own = source(&hull, nu, true);
            println!(
                "{nu:?}: M = {:.6} N m, the source's arm {:.6} N m",
                ours[4], own[4]
            );
        }
        // What the rates read is the same numbers.
        for nu in STATES {
            assert_eq!(hull.forces(&nu), hull.loads(&nu).loads);
        }
        // Pure sway: Y and N only; pure heave on a symmetric hull: Z only.
        let sway = hull.loads(&[1.0, 0.2, 0.0, 0.0, 0.0, 0.0]).loads;
        assert!(sway[1] < 0.0 && sway[2] == 0.0 && sway[4] == 0.0);
        let still = hull.loads(&[1.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
        assert!(
            still
                .loads
                .iter()
                .chain(still.by.iter().flatten())
                .all(|x| *x == 0.0)
        );
    }

    /// The hand-written derivatives against the dual numbers', to rounding (1e-12 of the
    /// largest entry).
    #[test]
    fn the_derivatives_are_those_of_the_loads() {
        let hull = nps();
        for nu in STATES {
            let by = hull.loads(&nu).by;
            let scale = by.iter().flatten().fold(0.0_f64, |m, x| m.max(x.abs()));
            for velocity in 0..6 {
                let mut seeded = nu.map(Dual64::from);
                seeded[velocity].eps = 1.0;
                let dual = hull.loads(&seeded).loads;
                for load in 0..6 {
                    let difference = (by[load][velocity] - dual[load].eps).abs();
                    assert!(difference <= 1e-12 * scale, "{nu:?}: ∂τ{load}/∂ν{velocity}");
                }
            }
        }
    }

    /// The drag takes energy out: its power on (v, w, q, r) is never positive.
    #[test]
    fn the_drag_is_dissipative() {
        let hull = nps();
        for nu in STATES {
            let loads = hull.loads(&nu).loads;
            let power = loads[1] * nu[1] + loads[2] * nu[2] + loads[4] * nu[4] + loads[5] * nu[5];
            assert!(power <= 0.0, "{nu:?}: {power}");
        }
    }
}
