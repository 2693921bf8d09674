//! An AUV model emitted by `eom-codegen` from this crate's own `build.rs`.
//!
//! The generated module `auv` holds `Parameters`, `Coefficients<T>`, `STATE`, `INPUTS`,
//! `OPERATIONS` and `rhs`; this crate adds a fixed-step RK4 to show a complete use.

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

/// One classical Runge–Kutta step of `h` with constant inputs.
pub fn rk4_step(
    k: &auv::Coefficients<f64>,
    state: &[f64; 13],
    input: &[f64; 6],
    h: f64,
) -> [f64; 13] {
    let f = |x: &[f64; 13]| auv::rhs(k, x, input);
    let add = |x: &[f64; 13], d: &[f64; 13], s: f64| std::array::from_fn(|i| x[i] + s * d[i]);
    let k1 = f(state);
    let k2 = f(&add(state, &k1, h / 2.0));
    let k3 = f(&add(state, &k2, h / 2.0));
    let k4 = f(&add(state, &k3, h));
    std::array::from_fn(|i| state[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]))
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
        let k = auv::Coefficients::<f64>::new(&params);
        let energy = |x: &[f64; 13]| {
            let (p, q, r) = (x[3], x[4], x[5]);
            let rotation = params.ixx * p * p
                + params.iyy * q * q
                + params.izz * r * r
                + 2.0 * params.ixz * p * r;
            0.5 * params.mass * (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) + 0.5 * rotation
        };
        let mut x = state();
        let e0 = energy(&x);
        for _ in 0..1000 {
            x = rk4_step(&k, &x, &[0.0; 6], 1e-3);
        }
        // RK4 with h = 1e-3 over 1 s of rates ~0.3 rad/s: local error ~h⁵ per step, so the
        // relative drift is far below 1e-10.
        assert!((energy(&x) - e0).abs() < 1e-10 * e0);
        let norm: f64 = x[9..13].iter().map(|q| q * q).sum();
        assert!((norm - 1.0).abs() < 1e-10);
    }

    #[test]
    fn pure_surge_translates_along_x() {
        let k = auv::Coefficients::<f64>::new(&example_parameters());
        let mut x = [0.0; 13];
        x[0] = 2.0;
        x[9] = 1.0;
        let rate = auv::rhs(&k, &x, &[0.0; 6]);
        assert_eq!(rate[6], 2.0); // ẋ = u for the identity attitude
        assert_eq!(&rate[7..9], &[0.0, 0.0]);
    }

    /// The compiled ship against 4.46 written out by hand: the same formula in another order,
    /// so 1e-12 of the largest term (some tens of roundings) bounds the difference.
    #[test]
    fn the_compiled_ship_is_4_46_with_its_table() {
        let p = example_ship();
        let k = ship::Coefficients::<f64>::new(&p);
        let state = [6.0, 0.4, -0.02, 10.0, -5.0, 0.3, 0.1];
        let [u, v, r, _, _, psi, delta] = state;
        let rates = ship::rhs(&k, &state, &[0.01]);
        let (m, xg) = (p.mass, p.x_g);
        let x = p.x_u * u + p.x_vv * v * v + m * v * r + m * xg * r * r;
        let y = p.y_v * v + p.y_r * r + p.y_vvv * v.powi(3) + p.y_d * delta - m * u * r;
        let n = p.n_v * v + p.n_r * r + p.n_vvr * v * v * r + p.n_d * delta - m * xg * u * r;
        let (a, b) = (m - p.y_vdot, m * xg - p.y_rdot);
        let (c, d) = (m * xg - p.n_vdot, p.izz + m * xg * xg - p.n_rdot);
        let det = a * d - b * c;
        let expected = [
            x / (m - p.x_udot),
            (d * y - b * n) / det,
            (a * n - c * y) / det,
            u * psi.cos() - v * psi.sin(),
            u * psi.sin() + v * psi.cos(),
            r,
            0.01,
        ];
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
}
