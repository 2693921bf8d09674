//! An AUV and a ship emitted by `eom-codegen` from this crate's own `build.rs`, integrated by
//! `eom`'s integrators like any model of eom's catalog.
//!
//! Each generated module holds `Parameters`, `Coefficients<T>`, `STATE`, `INPUTS`,
//! `OPERATIONS`, `rhs`, its Jacobians and energies, and the model contract for its
//! coefficients (`eom::Model`, written by the emitter): so `Coefficients::driven_by(loads)`
//! is a system `eom::Rk4`, `eom::Dop853` and the rest advance, with nothing written here but
//! the numbers.
//!
//! ```
//! use eom::integrate::{Integrator, Rk4};
//! use eom::{Constant, Model};
//! use eom_example_user_build_rs::{auv, example_parameters};
//!
//! let auv = auv::Coefficients::<f64>::new(&example_parameters());
//! let mut start = [0.0; 13];
//! start[9] = 1.0; // the identity attitude
//! let thrust = auv.driven_by(Constant([20.0, 0.0, 0.0, 0.0, 0.0, 0.0]));
//! let end = Rk4::new(0.01).integrate(&thrust, 0.0, start.into(), 1.0).unwrap();
//! assert!((end[0] - 20.0 / 50.0).abs() < 1e-12); // u = F t / M from rest
//! ```

/// The generated model: spatial 6-DOF, xz-symmetric, unit quaternion.
#[allow(clippy::let_and_return, clippy::redundant_locals)]
pub mod auv {
    include!(concat!(env!("OUT_DIR"), "/spatial_xz_quaternion.rs"));
}

/// A ship of this crate's own table (`build.rs`): 4.46 at midship with the added mass and ten
/// hydrodynamic terms, state `[u, v, r, X, Y, psi, delta]`, input `[delta_rate]`.
#[allow(clippy::let_and_return, clippy::redundant_locals)]
pub mod ship {
    include!(concat!(env!("OUT_DIR"), "/ship.rs"));
}

/// The Mariner's table (`build.rs`): 4.46 at midship in the prime system with its 39 terms,
/// the state and input of [`ship`]; its parameters by symbol (`Parameters::from_symbols`).
#[allow(clippy::let_and_return, clippy::redundant_locals)]
pub mod mariner {
    include!(concat!(env!("OUT_DIR"), "/mariner.rs"));
}

/// REMUS 100 in six degrees of freedom (`build.rs`): the vehicle's equations about its
/// table's origin with the terms `scenes/remus100.toml` names, state `[u, v, w, p, q, r, x,
/// y, z, q0, q1, q2, q3]`, inputs the fins and |u| … of the drag terms; its parameters by
/// symbol (`Parameters::from_symbols`).
#[allow(clippy::let_and_return, clippy::redundant_locals)]
pub mod remus {
    include!(concat!(env!("OUT_DIR"), "/remus.rs"));
}

/// A torpedo-shaped AUV: 50 kg, slender, with a small I_xz from an offset payload.
pub fn example_parameters() -> auv::Parameters {
    auv::Parameters {
        mass: 50.0,
        ixx: 0.5,
        iyy: 8.0,
        izz: 8.2,
        ixz: 0.05,
    }
}

/// A 100 m ship's numbers, SI, for the ten-term table of `build.rs`.
pub fn example_ship() -> ship::Parameters {
    ship::Parameters {
        mass: 4.0e6,
        izz: 2.5e9,
        x_g: -1.5,
        x_udot: -2.0e5,
        y_vdot: -3.0e6,
        y_rdot: -1.0e7,
        n_vdot: -2.0e7,
        n_rdot: -1.5e9,
        x_u: -4.0e5,
        x_vv: -3.0e5,
        y_v: -2.0e6,
        y_r: 5.0e7,
        y_vvv: -8.0e5,
        y_d: 1.0e6,
        n_v: -8.0e7,
        n_r: -3.0e9,
        n_vvr: -6.0e8,
        n_d: -5.0e7,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use eom::integrate::{AdaptiveOptions, Dop853, Integrator, Rk4, Statistics};
    use eom::models::SpatialXzQuaternion;
    use eom::nalgebra::SVector;
    use eom::{Constant, InertiaTensor, Model};

    fn state() -> [f64; 13] {
        let mut x = [0.0; 13];
        x[0] = 1.5; // surge u
        x[3..6].copy_from_slice(&[0.2, -0.1, 0.3]); // p, q, r
        x[9] = 1.0; // identity attitude
        x
    }

    #[test]
    fn torque_free_motion_conserves_kinetic_energy_and_unit_quaternion() {
        let params = example_parameters();
        let auv = auv::Coefficients::<f64>::new(&params);
        // 4.32 written out by hand, against the emitted energy the contract gives: the same
        // ten or so roundings in another order (fused where the build has FMA), a few ε apart.
        let energy = |x: &[f64; 13]| {
            let (p, q, r) = (x[3], x[4], x[5]);
            let rotation = params.ixx * p * p
                + params.iyy * q * q
                + params.izz * r * r
                + 2.0 * params.ixz * p * r;
            0.5 * params.mass * (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) + 0.5 * rotation
        };
        let x = state();
        let e0 = energy(&x);
        assert!((auv.kinetic_energy(&x) - e0).abs() <= 1e-14 * e0);
        let free = auv.driven_by(Constant::zero());
        let end = Rk4::new(1e-3).integrate(&free, 0.0, x.into(), 1.0).unwrap();
        let end = end.data.0[0];
        // RK4 with h = 1e-3 over 1 s of rates ~0.3 rad/s: local error ~h⁵ per step, so the
        // relative drift is far below 1e-10.
        assert!((energy(&end) - e0).abs() < 1e-10 * e0);
        assert!((auv.kinetic_energy(&end) - e0).abs() < 1e-10 * e0);
        let norm: f64 = end[9..13].iter().map(|q| q * q).sum();
        assert!((norm - 1.0).abs() < 1e-10);
    }

    /// The crate's own emission and eom's catalog model of the same variant are the same
    /// generated code: through the same trait and integrator they give the same bits.
    #[test]
    fn the_emitted_auv_runs_as_the_catalog_model_of_its_variant() {
        let p = example_parameters();
        let inertia = InertiaTensor::new(p.ixx, p.iyy, p.izz, 0.0, 0.0, p.ixz).unwrap();
        let catalog = SpatialXzQuaternion::<f64>::new(p.mass, &inertia).unwrap();
        let emitted = auv::Coefficients::<f64>::new(&p);
        assert_eq!(
            <auv::Coefficients<f64> as Model<f64, 13, 6>>::NAME,
            <SpatialXzQuaternion<f64> as Model<f64, 13, 6>>::NAME
        );
        assert_eq!(
            <auv::Coefficients<f64> as Model<f64, 13, 6>>::STATE,
            <SpatialXzQuaternion<f64> as Model<f64, 13, 6>>::STATE
        );
        let loads = |t: f64, _: &[f64; 13]| [20.0, 0.0, -1.0, 0.1 * t, 0.5, 0.0];
        let mut method = Dop853::new(AdaptiveOptions::dop853(1e-10, 1e-10));
        let a = method
            .integrate(&emitted.driven_by(loads), 0.0, state().into(), 2.0)
            .unwrap();
        let steps = method.stats().steps;
        let b = method
            .integrate(&catalog.driven_by(loads), 0.0, state().into(), 2.0)
            .unwrap();
        assert_eq!(a, b);
        assert_eq!(method.stats().steps, steps);
        let (x, u) = (state(), loads(0.5, &state()));
        assert_eq!(
            emitted.state_jacobian(&x, &u),
            catalog.state_jacobian(&x, &u)
        );
    }

    #[test]
    fn pure_surge_translates_along_x() {
        let auv = auv::Coefficients::<f64>::new(&example_parameters());
        let mut x = [0.0; 13];
        x[0] = 2.0;
        x[9] = 1.0;
        let rate = auv.rhs(&x, &[0.0; 6]);
        assert_eq!(rate[6], 2.0); // ẋ = u for the identity attitude
        assert_eq!(&rate[7..9], &[0.0, 0.0]);
    }

    /// 4.46 with this crate's table, written out by hand: the rates at `state` with the
    /// rudder moving at `delta_rate`.
    fn ship_by_hand(p: &ship::Parameters, state: &[f64; 7], delta_rate: f64) -> [f64; 7] {
        let [u, v, r, _, _, psi, delta] = *state;
        let (m, xg) = (p.mass, p.x_g);
        let x = p.x_u * u + p.x_vv * v * v + m * v * r + m * xg * r * r;
        let y = p.y_v * v + p.y_r * r + p.y_vvv * v.powi(3) + p.y_d * delta - m * u * r;
        let n = p.n_v * v + p.n_r * r + p.n_vvr * v * v * r + p.n_d * delta - m * xg * u * r;
        let (a, b) = (m - p.y_vdot, m * xg - p.y_rdot);
        let (c, d) = (m * xg - p.n_vdot, p.izz + m * xg * xg - p.n_rdot);
        let det = a * d - b * c;
        [
            x / (m - p.x_udot),
            (d * y - b * n) / det,
            (a * n - c * y) / det,
            u * psi.cos() - v * psi.sin(),
            u * psi.sin() + v * psi.cos(),
            r,
            delta_rate,
        ]
    }

    /// The compiled ship against 4.46 written out by hand: the same formula in another order,
    /// so 1e-12 of the largest term (some tens of roundings) bounds the difference.
    #[test]
    fn the_compiled_ship_is_4_46_with_its_table() {
        let p = example_ship();
        let k = ship::Coefficients::<f64>::new(&p);
        let state = [6.0, 0.4, -0.02, 10.0, -5.0, 0.3, 0.1];
        let rates = k.rhs(&state, &[0.01]);
        let expected = ship_by_hand(&p, &state, 0.01);
        let [u, v, r, ..] = state;
        let (m, xg) = (p.mass, p.x_g);
        let x = p.x_u * u + p.x_vv * v * v + m * v * r + m * xg * r * r;
        let y = p.y_v * v + p.y_r * r + p.y_vvv * v.powi(3) + p.y_d * 0.1 - m * u * r;
        let n = p.n_v * v + p.n_r * r + p.n_vvr * v * v * r + p.n_d * 0.1 - m * xg * u * r;
        let sizes = [
            x.abs() / m,
            y.abs() / m,
            n.abs() / p.izz,
            u,
            u,
            r.abs(),
            0.01,
        ];
        for i in 0..7 {
            assert!(
                (rates[i] - expected[i]).abs() <= 1e-12 * sizes[i].max(expected[i].abs()),
                "rate {i}: {} vs {}",
                rates[i],
                expected[i]
            );
        }
    }

    /// With the rudder amidships and no sway or yaw, only X_u acts: u decays as
    /// u₀ e^(−t/τ) with τ = (M − X_u̇)/(−X_u), and midship travels u₀ τ (1 − e^(−t/τ)).
    #[test]
    fn straight_ahead_the_ship_slows_as_its_surge_damping_says() {
        let p = example_ship();
        let ship = ship::Coefficients::<f64>::new(&p);
        let tau = (p.mass - p.x_udot) / -p.x_u;
        let (u0, t) = (6.0, 20.0);
        let start = SVector::from([u0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
        let mut method = Dop853::new(AdaptiveOptions::dop853(1e-12, 1e-12));
        let end = method
            .integrate(&ship.driven_by(Constant([0.0])), 0.0, start, t)
            .unwrap();
        let decay = (-t / tau).exp();
        assert!((end[0] - u0 * decay).abs() < 1e-10 * u0, "u = {}", end[0]);
        let travelled = u0 * tau * (1.0 - decay);
        assert!(
            (end[3] - travelled).abs() < 1e-10 * travelled,
            "X = {}",
            end[3]
        );
        assert_eq!(
            (end[1], end[2], end[4], end[5], end[6]),
            (0.0, 0.0, 0.0, 0.0, 0.0)
        );
    }

    /// A turn, the helm putting the rudder over towards 0.1 rad at a rate proportional to what
    /// is left: the emitted ship and 4.46 written by hand, through the same RK4 steps, stay
    /// within a few roundings per step.
    #[test]
    fn a_turn_of_the_compiled_ship_follows_4_46_by_hand() {
        let p = example_ship();
        let ship = ship::Coefficients::<f64>::new(&p);
        let helm = |_: f64, y: &[f64; 7]| [0.5 * (0.1 - y[6])];
        let by_hand = |t: f64, y: &SVector<f64, 7>, dy: &mut SVector<f64, 7>| {
            let state = y.data.0[0];
            dy.data.0[0] = ship_by_hand(&p, &state, helm(t, &state)[0]);
        };
        let start = SVector::from([6.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
        let mut method = Rk4::new(0.05);
        let a = method
            .integrate(&ship.driven_by(helm), 0.0, start, 120.0)
            .unwrap();
        let b = method.integrate(&by_hand, 0.0, start, 120.0).unwrap();
        assert!((a[6] - 0.1).abs() < 1e-12, "δ = {}", a[6]); // 0.1 (1 − e^(−t/2))
        // N_δ δ < 0: the ship turns to port, its heading ψ decreasing.
        assert!(a[2] < 0.0 && a[5] < -0.2, "r = {}, ψ = {}", a[2], a[5]);
        for i in 0..7 {
            let scale = [6.0, 6.0, 0.1, 600.0, 600.0, 1.0, 0.1][i];
            assert!(
                (a[i] - b[i]).abs() < 1e-9 * scale,
                "{i}: {} vs {}",
                a[i],
                b[i]
            );
        }
    }

    /// The contract's Jacobians of the ship are the proved derivatives: the rudder rate moves
    /// δ alone, and ∂f/∂x agrees with central differences of `rhs`.
    #[test]
    fn the_ship_jacobians_are_derivatives_of_its_rates() {
        let ship = ship::Coefficients::<f64>::new(&example_ship());
        let (x, u) = ([6.0, 0.4, -0.02, 10.0, -5.0, 0.3, 0.1], [0.01]);
        let b = ship.input_jacobian(&x, &u);
        assert_eq!(b, [[0.0], [0.0], [0.0], [0.0], [0.0], [0.0], [1.0]]);
        let a = ship.state_jacobian(&x, &u);
        for j in 0..7 {
            let h = 1e-6 * x[j].abs().max(1.0);
            let (mut up, mut down) = (x, x);
            up[j] += h;
            down[j] -= h;
            let (fu, fd) = (ship.rhs(&up, &u), ship.rhs(&down, &u));
            for i in 0..7 {
                let difference = (fu[i] - fd[i]) / (2.0 * h);
                let scale = a[i][j].abs().max(1e-6);
                assert!(
                    (a[i][j] - difference).abs() < 1e-6 * scale,
                    "∂f{i}/∂x{j}: {} vs {difference}",
                    a[i][j]
                );
            }
        }
    }
}
