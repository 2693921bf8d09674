//! The generic nalgebra forms and the generated models through one contract (`eom::Model`):
//! the same names and layouts, the same energies, Jacobians that agree (the generic ones are
//! dual numbers through the generic rates, the emitted ones proved symbolic derivatives), and
//! the same trajectory from the same integrator through the same `driven_by`.

use eom::generic;
use eom::integrate::{Integrator, Rk4};
use eom::models::{
    Model, Pendulum, PlanarAtG, PlanarMidship, PlanarSpaceFixed, SpatialFullEuler,
    SpatialFullQuaternion,
};
use eom::{InertiaTensor, PendulumParameters};

/// What one model of each kind gives at one state, and after one run.
struct Case<const N: usize, const M: usize> {
    state: [f64; N],
    input: [f64; M],
    /// The size of each state entry over the run, for the trajectory's tolerance.
    scale: [f64; N],
}

/// Two f64 forms of one formula differ by a few roundings of the size of its terms; the
/// states here keep every term within a factor of ten of the largest of its row, so 1e-12 of
/// the largest entry of a row bounds the gap of two evaluations (as in
/// `tests/generated_vs_generic.rs`), for the rates and for each row of the Jacobians.
const ROW_TOLERANCE: f64 = 1e-12;

/// After 1000 RK4 steps of the same size from the same state, the two runs differ by the
/// rates' rounding gaps (a few ε of each rate) carried through the steps: in a motion that is
/// not chaotic over one second they add up at most linearly, 1000 × a few ε × h × rate, far
/// below 1e-12 of each entry's size for h = 1e-3 (1e-16 is seen).
const TRAJECTORY_TOLERANCE: f64 = 1e-12;

fn row_gap(a: &[f64], b: &[f64]) -> f64 {
    let size = a.iter().chain(b).fold(0.0_f64, |m, x| m.max(x.abs()));
    let gap = a
        .iter()
        .zip(b)
        .fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()));
    if size == 0.0 { gap } else { gap / size }
}

/// Holds `generic` and `generated` to one another through the contract alone.
fn through_the_contract<G, E, const N: usize, const M: usize>(
    generic: &G,
    generated: &E,
    case: &Case<N, M>,
) where
    G: Model<f64, N, M>,
    E: Model<f64, N, M>,
{
    assert_eq!(G::NAME, E::NAME);
    assert_eq!(G::STATE, E::STATE, "{}", E::NAME);
    assert_eq!(G::INPUTS, E::INPUTS, "{}", E::NAME);
    let (x, u) = (&case.state, &case.input);
    let gap = row_gap(&generic.rhs(x, u), &generated.rhs(x, u));
    assert!(gap <= ROW_TOLERANCE, "{}: rates {gap:e}", E::NAME);
    let (t_generic, t_generated) = (generic.kinetic_energy(x), generated.kinetic_energy(x));
    assert!(
        (t_generic - t_generated).abs() <= ROW_TOLERANCE * t_generated,
        "{}: kinetic energy {t_generic} vs {t_generated}",
        E::NAME
    );
    match (generic.potential_energy(x), generated.potential_energy(x)) {
        (None, None) => {}
        (Some(a), Some(b)) => assert!((a - b).abs() <= ROW_TOLERANCE * b.abs(), "{a} vs {b}"),
        other => panic!("{}: potential energy {other:?}", E::NAME),
    }
    let (a, b) = (generic.state_jacobian(x, u), generated.state_jacobian(x, u));
    jacobians_agree(E::NAME, "∂f/∂x", &a, &b, E::STATE_JACOBIAN);
    let (a, b) = (generic.input_jacobian(x, u), generated.input_jacobian(x, u));
    jacobians_agree(E::NAME, "∂f/∂u", &a, &b, E::INPUT_JACOBIAN);

    let (loads, start) = (eom::Constant(case.input), (*x).into());
    let mut method = Rk4::new(1e-3);
    let a = method
        .integrate(&generic.driven_by(loads), 0.0, start, 1.0)
        .unwrap();
    let b = method
        .integrate(&generated.driven_by(loads), 0.0, start, 1.0)
        .unwrap();
    for i in 0..N {
        let gap = (a[i] - b[i]).abs() / case.scale[i];
        assert!(
            gap <= TRAJECTORY_TOLERANCE,
            "{}: {} after 1 s, {gap:e}",
            E::NAME,
            E::STATE[i]
        );
    }
}

/// Row by row within [`ROW_TOLERANCE`]; and the generic form's derivative is exactly zero
/// where the emitted pattern says the entry vanishes identically, an independent check of
/// the pattern.
fn jacobians_agree<const N: usize, const C: usize>(
    name: &str,
    what: &str,
    generic: &[[f64; C]; N],
    generated: &[[f64; C]; N],
    pattern: &[(usize, usize)],
) {
    for (row, (a, b)) in generic.iter().zip(generated).enumerate() {
        let gap = row_gap(a, b);
        assert!(gap <= ROW_TOLERANCE, "{name}: {what} row {row}, {gap:e}");
        for (column, value) in a.iter().enumerate() {
            if !pattern.contains(&(row, column)) {
                assert_eq!(
                    *value, 0.0,
                    "{name}: {what} ({row}, {column}) is outside the pattern"
                );
            }
        }
    }
}

#[test]
fn the_generic_pendulum_is_the_generated_one_through_the_contract() {
    let parameters = PendulumParameters::new(2.0, 3.0, 9.81, 0.5).unwrap();
    let case = Case {
        state: [0.7, -0.4],
        input: [0.3],
        scale: [1.0, 3.0],
    };
    let generic = generic::Pendulum::new(&parameters);
    through_the_contract(&generic, &Pendulum::new(&parameters), &case);
}

#[test]
fn the_generic_planar_forms_are_the_generated_ones_through_the_contract() {
    let body = generic::PlanarBody::new(2.0, 8.0).unwrap();
    let at_g = Case {
        state: [1.0, 0.3, 0.2, 0.0, 0.0, 0.4],
        input: [0.5, -0.2, 0.3],
        scale: [1.0, 1.0, 1.0, 1.0, 1.0, 1.0],
    };
    through_the_contract(&body, &PlanarAtG::new(2.0, 8.0).unwrap(), &at_g);
    let space_fixed = Case {
        state: [0.0, 0.0, 0.4, 1.0, 0.3, 0.2],
        input: [0.5, -0.2, 0.3],
        scale: [1.0; 6],
    };
    let generated = PlanarSpaceFixed::new(2.0, 8.0).unwrap();
    through_the_contract(&generic::PlanarSpaceFixed(body), &generated, &space_fixed);
    let midship = generic::PlanarMidship::new(2.0, 8.0, -0.3).unwrap();
    let generated = PlanarMidship::new(2.0, 8.0, -0.3).unwrap();
    through_the_contract(&midship, &generated, &at_g);
}

#[test]
fn the_generic_rigid_body_is_the_full_variant_of_either_kinematics_through_the_contract() {
    let tensor = InertiaTensor::new(2.0, 3.0, 4.5, 0.1, -0.2, 0.15).unwrap();
    let body = generic::RigidBody::new(5.0, &tensor).unwrap();
    let euler = Case {
        state: [1.0, 0.2, -0.1, 0.3, -0.2, 0.5, 0.0, 0.0, 0.0, 0.1, 0.2, 0.3],
        input: [1.0, -0.5, 0.2, 0.1, 0.3, -0.2],
        scale: [1.0; 12],
    };
    through_the_contract(&body, &SpatialFullEuler::new(5.0, &tensor).unwrap(), &euler);
    let q = generic::quaternion_from_euler(0.1, 0.2, 0.3);
    let mut state = [0.0; 13];
    state[..9].copy_from_slice(&euler.state[..9]);
    state[9..].copy_from_slice(&[q.w, q.i, q.j, q.k]);
    let quaternion = Case {
        state,
        input: euler.input,
        scale: [1.0; 13],
    };
    let generated = SpatialFullQuaternion::new(5.0, &tensor).unwrap();
    through_the_contract(&body, &generated, &quaternion);
}
