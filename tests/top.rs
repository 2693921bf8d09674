//! The heavy top (`TopEuler`, `TopQuaternion`) against what is known of it without the
//! generator: an independent nalgebra form of its equations; the three constants of a symmetric
//! top's motion (the energy T + V, the vertical component H_Z of the angular momentum about the
//! pivot, and the spin H_z = I_O,zz r); the bounds of its nutation, the two roots in [−1, 1] of
//! the classical cubic in u = cos θ that those constants give (Goldstein, *Classical
//! Mechanics*, §5.7); the two ways of carrying the attitude against each other; and the
//! compound pendulum 4.24, which a non-spinning top hung below its pivot is.
//!
//! Every run is `model.driven_by(Constant::zero())` under `Dop853` at rtol = atol = 1e-12, as a
//! user would integrate it. `cargo test --test top -- --nocapture` prints the largest gaps.

use eom::generic::euler_rates;
use eom::integrate::{AdaptiveOptions, Dop853};
use eom::models::{AnyModel, Constant, Kinematics, Model, Pendulum, TopEuler, TopQuaternion};
use eom::reference::{LargeSwing, attitude_angle};
use eom::{InertiaTensor, PendulumParameters};
use nalgebra::{Quaternion, Rotation3, SVector, UnitQuaternion, Vector3};

/// The body of the symmetric-top runs: a spinning top with G 0.5 m above the pivot, principal
/// moments about G of 0.25 (twice) and 0.2 kg m², so that about the pivot A = I_xx + M h² =
/// 0.5 and C = I_zz = 0.2.
#[derive(Debug, Clone, Copy)]
struct Body {
    mass: f64,
    ixx: f64,
    iyy: f64,
    izz: f64,
    h: f64,
    g: f64,
}

const SYMMETRIC: Body = Body {
    mass: 1.0,
    ixx: 0.25,
    iyy: 0.25,
    izz: 0.2,
    h: 0.5,
    g: 9.81,
};

impl Body {
    fn tensor(&self) -> InertiaTensor {
        InertiaTensor::new(self.ixx, self.iyy, self.izz, 0.0, 0.0, 0.0).expect("a physical tensor")
    }

    fn euler(&self) -> TopEuler<f64> {
        TopEuler::new(self.mass, &self.tensor(), self.h, self.g).expect("a valid top")
    }

    fn quaternion(&self) -> TopQuaternion<f64> {
        TopQuaternion::new(self.mass, &self.tensor(), self.h, self.g).expect("a valid top")
    }

    /// I_O by Steiner (4.23), written here by hand: G on the body z-axis.
    fn about_pivot(&self) -> Vector3<f64> {
        let shift = self.mass * self.h * self.h;
        Vector3::new(self.ixx + shift, self.iyy + shift, self.izz)
    }

    /// M g h, the weight's moment per unit of the sine of the tilt.
    fn mgh(&self) -> f64 {
        self.mass * self.g * self.h
    }
}

/// The body-to-space rotation of a top's state: E(φ, θ, ψ) = Rz Ry Rx (nalgebra's own), or the
/// rotation of q normalised.
fn attitude<const N: usize>(state: &[f64; N]) -> Rotation3<f64> {
    if N == 6 {
        Rotation3::from_euler_angles(state[3], state[4], state[5])
    } else {
        let q = Quaternion::new(state[3], state[4], state[5], state[6]);
        UnitQuaternion::from_quaternion(q).to_rotation_matrix()
    }
}

fn omega<const N: usize>(state: &[f64; N]) -> Vector3<f64> {
    Vector3::new(state[0], state[1], state[2])
}

/// The three constants of a symmetric top's motion, and the nutation cosine u = (R k)·K.
#[derive(Debug, Clone, Copy)]
struct Invariants {
    energy: f64,
    vertical_momentum: f64,
    spin: f64,
    u: f64,
}

fn invariants<Mo: Model<f64, N, 3>, const N: usize>(
    body: &Body,
    model: &Mo,
    state: &[f64; N],
) -> Invariants {
    let rotation = attitude(state);
    let momentum = body.about_pivot().component_mul(&omega(state));
    Invariants {
        energy: model.kinetic_energy(state) + model.potential_energy(state).expect("a top has V"),
        vertical_momentum: (rotation * momentum).z,
        spin: momentum.z,
        u: rotation[(2, 2)],
    }
}

/// The roots u₁ ≤ u₂ in [−1, 1] of f(u) = (1 − u²)(α − βu) − (b − au)², with a = H_z/A,
/// b = H_Z/A, α = 2E′/A, E′ = E − H_z²/2C, β = 2Mgh/A (A, C the moments about the pivot):
/// u̇² = f(u), so the nutation stays between them. f(±1) ≤ 0 and f → +∞ as u → +∞, so the
/// two roots bracket the cubic's local maximum, the smaller zero of f′; each is found by
/// bisection to the last bit.
fn nutation_bounds(body: &Body, start: &Invariants) -> (f64, f64) {
    let moments = body.about_pivot();
    let (a_moment, c_moment) = (moments.x, moments.z);
    let a = start.spin / a_moment;
    let b = start.vertical_momentum / a_moment;
    let e_prime = start.energy - start.spin * start.spin / (2.0 * c_moment);
    let alpha = 2.0 * e_prime / a_moment;
    let beta = 2.0 * body.mgh() / a_moment;
    let f = |u: f64| (1.0 - u * u) * (alpha - beta * u) - (b - a * u).powi(2);
    // f′(u) = 3βu² − 2(α + a²)u + (2ab − β).
    let s = alpha + a * a;
    let peak = (s - (s * s - 3.0 * beta * (2.0 * a * b - beta)).sqrt()) / (3.0 * beta);
    assert!(
        f(peak) > 0.0,
        "the start is a steady precession: no nutation"
    );
    let bisect = |mut low: f64, mut high: f64| {
        let rising = f(high) > f(low);
        loop {
            let mid = 0.5 * (low + high);
            if mid <= low || mid >= high {
                return mid;
            }
            if (f(mid) > 0.0) == rising {
                high = mid;
            } else {
                low = mid;
            }
        }
    };
    (bisect(-1.0, peak), bisect(peak, 1.0))
}

fn dop853() -> Dop853 {
    Dop853::new(AdaptiveOptions::dop853(1e-12, 1e-12))
}

/// The states at `times` of the free model from `start`.
fn run<Mo: Model<f64, N, M>, const N: usize, const M: usize>(
    model: &Mo,
    start: [f64; N],
    times: &[f64],
) -> Vec<[f64; N]> {
    let mut out = vec![SVector::<f64, N>::zeros(); times.len()];
    dop853()
        .solve_at(
            &model.driven_by(Constant::zero()),
            0.0,
            SVector::from(start),
            times,
            &mut out,
        )
        .expect("the run completes");
    out.into_iter().map(|y| y.data.0[0]).collect()
}

/// The extremes of sampled values, each refined by the parabola through it and its two
/// neighbours: (smallest, largest, how many local minima).
fn extremes(values: &[f64]) -> (f64, f64, usize) {
    let (mut low, mut high, mut minima) = (f64::INFINITY, f64::NEG_INFINITY, 0);
    for w in values.windows(3) {
        let (a, b, c) = (w[0], w[1], w[2]);
        let curvature = a - 2.0 * b + c;
        if (b <= a && b <= c) || (b >= a && b >= c) {
            let vertex = if curvature == 0.0 {
                b
            } else {
                b - (c - a).powi(2) / (8.0 * curvature)
            };
            low = low.min(vertex);
            high = high.max(vertex);
            minima += usize::from(b <= a && b <= c);
        }
    }
    (low, high, minima)
}

/// The spinning start: tilted 0.5 rad in roll, spinning at 20 rad/s with a small transverse
/// rate, so that the start is not a turning point of the nutation. (At 10 rad/s this top
/// nutates down past the horizontal.)
const SPIN_START_EULER: [f64; 6] = [0.3, -0.2, 20.0, 0.5, 0.0, 0.0];

fn spin_start_quaternion() -> [f64; 7] {
    let [p, q, r, roll, pitch, yaw] = SPIN_START_EULER;
    let attitude = UnitQuaternion::from_euler_angles(roll, pitch, yaw);
    [p, q, r, attitude.w, attitude.i, attitude.j, attitude.k]
}

/// 10 s sampled every 2 ms: nine nutations of about 1.1 s (a = C r / A = 8 rad/s sets their
/// scale), each turning point met by hundreds of samples.
fn times() -> Vec<f64> {
    (1..=5000).map(|i| f64::from(i) * 2e-3).collect()
}

/// The symmetric top keeps its three constants, and its nutation stays between the roots of
/// the cubic and reaches both.
fn symmetric_top_conserves_and_nutates_between_the_roots<Mo, const N: usize>(
    model: &Mo,
    start: [f64; N],
) where
    Mo: Model<f64, N, 3>,
{
    let body = SYMMETRIC;
    let first = invariants(&body, model, &start);
    let (u1, u2) = nutation_bounds(&body, &first);
    // The emitted energies are the independent ones: ½ωᵀ[I_O]ω and Mgh·u.
    let moments = body.about_pivot();
    let w = omega(&start);
    let by_hand = 0.5 * w.dot(&moments.component_mul(&w)) + body.mgh() * first.u;
    assert!((first.energy - by_hand).abs() < 1e-14 * by_hand.abs());

    let states = run(model, start, &times());
    let mut all = vec![first];
    all.extend(states.iter().map(|s| invariants(&body, model, s)));
    // The scales the drifts are relative to: the energy's two parts, and |H_O|.
    let energy_scale = 0.5 * w.dot(&moments.component_mul(&w)) + body.mgh().abs();
    let momentum_scale = moments.component_mul(&w).norm();
    let drift = |f: fn(&Invariants) -> f64, scale: f64| {
        all.iter()
            .map(|i| (f(i) - f(&first)).abs() / scale)
            .fold(0.0, f64::max)
    };
    let energy = drift(|i| i.energy, energy_scale);
    let vertical = drift(|i| i.vertical_momentum, momentum_scale);
    let spin = drift(|i| i.spin, momentum_scale);
    let u: Vec<f64> = all.iter().map(|i| i.u).collect();
    let outside = u
        .iter()
        .map(|&u| (u1 - u).max(u - u2).max(0.0))
        .fold(0.0, f64::max);
    let (low, high, nutations) = extremes(&u);
    let (miss_low, miss_high) = ((low - u1).abs(), (high - u2).abs());
    println!(
        "{}: u in [{u1:.12}, {u2:.12}] (tilt {:.4}..{:.4} rad), {nutations} nutations; drift: \
         energy {energy:.1e}, H_Z {vertical:.1e}, H_z {spin:.1e}; largest step outside \
         {outside:.1e}; extremes miss the roots by {miss_low:.1e} and {miss_high:.1e}",
        Mo::NAME,
        u2.acos(),
        u1.acos()
    );
    // DOP853 at 1e-12 over 10 s: the local errors are ~1e-12 of the state and the constants
    // are smooth functions of it, so each drifts by a few 1e-12 of its scale (seen: energy
    // 9e-13, H_Z 6e-12; H_z exactly 0, as ṙ's coefficient I_xx − I_yy is exactly 0). 1e-10
    // leaves a wide margin while a wrong term of the equations changes them at order one.
    assert!(energy < 1e-10, "energy drift {energy:e}");
    assert!(vertical < 1e-10, "H_Z drift {vertical:e}");
    assert!(spin < 1e-10, "H_z drift {spin:e}");
    // The bounds come from the constants at the start; the state errs by ~1e-11 along the
    // run, which moves u by as much, and a constant's drift moves a root by as much again
    // over f′ at the root (of order one here). 1e-9 is the margin (seen: never outside).
    assert!(outside < 1e-9, "u leaves [u1, u2] by {outside:e}");
    // The sampled extremes, refined by a parabola, miss the turning points by the parabola's
    // error, below |u'''|Δt³/16 ≈ 1e-8 for a nutation of depth 0.19 at 5.7 rad/s (seen:
    // ~1e-12, with the run's own error). 1e-6 tells "reaches the bound" from "turns short
    // of it": the bounds are 0.19 apart.
    assert!(
        miss_low < 1e-6,
        "the nutation turns {miss_low:e} short of u1"
    );
    assert!(
        miss_high < 1e-6,
        "the nutation turns {miss_high:e} short of u2"
    );
}

#[test]
fn euler_top_keeps_its_constants_and_nutates_between_the_roots_of_the_cubic() {
    symmetric_top_conserves_and_nutates_between_the_roots(&SYMMETRIC.euler(), SPIN_START_EULER);
}

#[test]
fn quaternion_top_keeps_its_constants_and_nutates_between_the_roots_of_the_cubic() {
    symmetric_top_conserves_and_nutates_between_the_roots(
        &SYMMETRIC.quaternion(),
        spin_start_quaternion(),
    );
}

/// The same top from the same start, once in Euler angles and once in a quaternion: the body
/// rates and the attitude agree all along (the tilt stays below 0.82 rad, so the pitch never
/// comes near ±90°).
#[test]
fn euler_and_quaternion_tops_move_alike() {
    let times = times();
    let euler = run(&SYMMETRIC.euler(), SPIN_START_EULER, &times);
    let quaternion = run(&SYMMETRIC.quaternion(), spin_start_quaternion(), &times);
    let (mut rates, mut turn) = (0.0f64, 0.0f64);
    for (a, b) in euler.iter().zip(&quaternion) {
        rates = rates.max((omega(a) - omega(b)).norm() / omega(a).norm());
        // 2 atan2(|δ⃗|, |δ₀|), accurate near zero; the acos of a rotation's trace
        // (`Rotation3::angle_to`) cannot resolve angles below √(2ε) ≈ 2e-8 rad.
        let a = UnitQuaternion::from_rotation_matrix(&attitude(a));
        turn = turn.max(attitude_angle(&a, &Quaternion::new(b[3], b[4], b[5], b[6])));
    }
    println!("Euler against quaternion: rates {rates:.1e} (relative), attitude {turn:.1e} rad");
    // Each run stays within ~3e-11 rad of a run at rtol = atol = 1e-14 (tried while writing
    // this test); the two integrate different coordinates, so their errors differ and add
    // (seen: rates 2e-12, attitude 2e-11 rad). 1e-9 is the margin.
    assert!(rates < 1e-9, "rates differ by {rates:e}");
    assert!(turn < 1e-9, "attitudes differ by {turn:e} rad");
}

/// A small xorshift generator: the cases repeat from run to run.
struct Cases(u64);

impl Cases {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }

    fn between(&mut self, low: f64, high: f64) -> f64 {
        low + (high - low) * self.next()
    }
}

/// The generated right-hand side against an independent nalgebra form at random states of
/// random asymmetric tops: ω̇ = [I_O]⁻¹(r_G × M Rᵀg + M − ω × [I_O]ω), with R from nalgebra,
/// and the attitude rates from `eom::generic::euler_rates` or ½ q ⊗ (0, ω).
#[test]
fn generated_rates_match_an_independent_form() {
    let mut cases = Cases(0x9e37_79b9_7f4a_7c15);
    let mut worst = 0.0f64;
    for _ in 0..500 {
        // Moments in [1, 2] satisfy the triangle inequality of 4.13 whatever their order.
        let body = Body {
            mass: cases.between(0.5, 5.0),
            ixx: cases.between(1.0, 2.0),
            iyy: cases.between(1.0, 2.0),
            izz: cases.between(1.0, 2.0),
            h: cases.between(-1.0, 1.0),
            g: 9.81,
        };
        let w = Vector3::new(
            cases.between(-20.0, 20.0),
            cases.between(-20.0, 20.0),
            cases.between(-20.0, 20.0),
        );
        let moment = Vector3::new(
            cases.between(-5.0, 5.0),
            cases.between(-5.0, 5.0),
            cases.between(-5.0, 5.0),
        );
        let (roll, pitch, yaw) = (
            cases.between(-3.0, 3.0),
            cases.between(-1.4, 1.4),
            cases.between(-3.0, 3.0),
        );
        let rotation = Rotation3::from_euler_angles(roll, pitch, yaw);
        let moments = body.about_pivot();
        let momentum = moments.component_mul(&w);
        let weight = rotation.inverse() * Vector3::new(0.0, 0.0, -body.g * body.mass);
        let gravity = Vector3::new(0.0, 0.0, body.h).cross(&weight);
        let gyroscopic = w.cross(&momentum);
        let expected = (gravity + moment - gyroscopic).component_div(&moments);
        // Each rate's scale: the sizes of the terms it sums, over its moment.
        let (a, m) = (w.abs(), momentum.abs());
        let gyroscopic_size = Vector3::new(
            a.y * m.z + a.z * m.y,
            a.z * m.x + a.x * m.z,
            a.x * m.y + a.y * m.x,
        );
        let scale = (gravity.abs() + moment.abs() + gyroscopic_size).component_div(&moments);
        let input = [moment.x, moment.y, moment.z];

        let euler = body.euler().rhs(&[w.x, w.y, w.z, roll, pitch, yaw], &input);
        let rates = euler_rates(roll, pitch, &w);
        let q = UnitQuaternion::from_rotation_matrix(&rotation);
        let state = [w.x, w.y, w.z, q.w, q.i, q.j, q.k];
        let quaternion = body.quaternion().rhs(&state, &input);
        let q_rate = q.quaternion() * Quaternion::from_imag(w) * 0.5;
        for i in 0..3 {
            for generated in [euler[i], quaternion[i]] {
                worst = worst.max((generated - expected[i]).abs() / scale[i]);
            }
            let euler_scale = w.abs().sum() / pitch.cos();
            worst = worst.max((euler[3 + i] - rates[i]).abs() / euler_scale);
        }
        for (i, expected) in [q_rate.w, q_rate.i, q_rate.j, q_rate.k].iter().enumerate() {
            worst = worst.max((quaternion[3 + i] - expected).abs() / w.abs().sum());
        }
    }
    println!("generated against nalgebra: largest gap {worst:.1e} of the terms' size");
    // Two evaluations of a few terms in different orders, and two ways of forming R (E's
    // product against nalgebra's, q against its matrix): a few ε of the size of the terms.
    // 1e-13 is ~450 ε (seen: 4e-16); a wrong term is off at order one.
    assert!(worst < 1e-13, "largest gap {worst:e}");
}

/// A top hung below its pivot (h < 0), not spinning and swinging about its body x-axis, is the
/// compound pendulum 4.24 with I₀ = I_xx + M h² (4.23) and the distance |h|: the roll φ is the
/// pendulum's angle at any amplitude. Released from rest at 2 rad, it follows the generated
/// pendulum and Jacobi's exact solution, and its potential energy is the pendulum's.
#[test]
fn a_hanging_top_swinging_in_a_plane_is_the_compound_pendulum() {
    let body = Body {
        h: -0.5,
        ..SYMMETRIC
    };
    let i0 = body.about_pivot().x;
    let parameters = PendulumParameters::new(i0, body.mass, body.g, -body.h).unwrap();
    let pendulum = Pendulum::<f64>::new(&parameters);
    let exact = LargeSwing::new(&parameters, 2.0).unwrap();
    let times: Vec<f64> = (1..=400).map(|i| f64::from(i) * 0.01).collect();
    let top = run(&body.euler(), [0.0, 0.0, 0.0, 2.0, 0.0, 0.0], &times);
    let swing = run(&pendulum, [2.0, 0.0], &times);
    let (mut against_model, mut against_exact, mut energies) = (0.0f64, 0.0f64, 0.0f64);
    for ((t, top), swing) in times.iter().zip(&top).zip(&swing) {
        against_model = against_model.max((top[3] - swing[0]).abs().max((top[0] - swing[1]).abs()));
        let e = exact.exact(*t);
        against_exact = against_exact.max((top[3] - e[0]).abs().max((top[0] - e[1]).abs()));
        let (v_top, v_pendulum) = (
            body.euler().potential_energy(top).unwrap(),
            pendulum.potential_energy(&[top[3], top[0]]).unwrap(),
        );
        energies = energies.max((v_top - v_pendulum).abs() / body.mgh().abs());
        // Nothing turns it out of its plane.
        assert_eq!([top[1], top[2], top[4], top[5]], [0.0; 4]);
    }
    println!(
        "planar swing at 2 rad over {:.1} periods: against the pendulum model {against_model:.1e}, \
         against Jacobi {against_exact:.1e}, potential energies {energies:.1e}",
        4.0 / exact.period()
    );
    // The top's p and φ obey the pendulum's equation exactly (q = r = θ = ψ = 0 stay zero);
    // the coefficients differ in rounding (Mgh/(I_xx + Mh²) against Mgh/I₀), so the step
    // sizes differ and each run carries its own ~1e-11 of DOP853's error at 1e-12 (seen:
    // 2e-11 between them, 2e-11 from Jacobi's exact solution). 1e-9 is the margin.
    assert!(against_model < 1e-9, "{against_model:e}");
    assert!(against_exact < 1e-9, "{against_exact:e}");
    // Both are −Mgh cos of the angle (4.35) from the same angle: a few ε.
    assert!(energies < 1e-14, "{energies:e}");
}

/// The small-oscillation limit: released from rest tilted 0.01 rad about a skew horizontal
/// axis, a hanging symmetric top swings in the vertical plane of its tilt as the compound
/// pendulum does, s(t) = sin of the pendulum's angle, where s is the body z-axis's horizontal
/// component along the first tilt; and to O(θ₀²) that is 4.27's harmonic motion of period
/// 2π√(I₀/Mgh).
#[test]
fn a_hanging_top_released_with_a_small_tilt_swings_as_the_pendulum_of_4_27() {
    let body = Body {
        h: -0.5,
        ..SYMMETRIC
    };
    let rotation = Rotation3::from_euler_angles(0.006, -0.008, 0.7);
    let q = UnitQuaternion::from_rotation_matrix(&rotation);
    let start = [0.0, 0.0, 0.0, q.w, q.i, q.j, q.k];
    let axis: Vector3<f64> = rotation * Vector3::z();
    let tilt = axis.z.acos();
    let along = Vector3::new(axis.x, axis.y, 0.0).normalize();
    let across = Vector3::z().cross(&along);
    let i0 = body.about_pivot().x;
    let parameters = PendulumParameters::new(i0, body.mass, body.g, -body.h).unwrap();
    let exact = LargeSwing::new(&parameters, tilt).unwrap();
    let omega0 = (body.mgh().abs() / i0).sqrt();
    let times: Vec<f64> = (1..=600).map(|i| f64::from(i) * 0.01).collect();
    let states = run(&body.quaternion(), start, &times);
    let (mut against_exact, mut against_harmonic, mut out_of_plane) = (0.0f64, 0.0f64, 0.0f64);
    for (t, state) in times.iter().zip(&states) {
        let axis = attitude(state) * Vector3::z();
        let s = axis.dot(&along);
        against_exact = against_exact.max((s - exact.exact(*t)[0].sin()).abs());
        against_harmonic = against_harmonic.max((s - tilt.sin() * (omega0 * t).cos()).abs());
        out_of_plane = out_of_plane.max(axis.dot(&across).abs());
    }
    println!(
        "small tilt {tilt:.4} rad over {:.1} periods: against Jacobi {against_exact:.1e}, \
         against 4.27 {against_harmonic:.1e} ({:.1e} of the tilt), out of the plane \
         {out_of_plane:.1e}",
        6.0 * omega0 / std::f64::consts::TAU,
        against_harmonic / tilt
    );
    // The swing is planar and exactly the pendulum's: DOP853 at 1e-12 keeps it to ~1e-11
    // (seen: 7e-12 against Jacobi, 2e-17 out of the plane); 1e-10 is the margin.
    assert!(against_exact < 1e-10, "{against_exact:e}");
    assert!(out_of_plane < 1e-10, "{out_of_plane:e}");
    // 4.27 leaves out the amplitude's lengthening of the period, θ₀²/16 = 6e-6 of it, which
    // after ωt ≈ 20 rad is a phase error of ~1.3e-4 rad, and the difference of sin θ and θ
    // (θ₀³/6 ≈ 2e-7): s differs from the harmonic by ~1.3e-4 of the tilt (seen: 1.1e-4).
    // 5e-4 of the tilt is the bound; a wrong restoring moment (a wrong I₀ or h) changes the
    // period at order one and fails it.
    assert!(against_harmonic < 5e-4 * tilt, "{against_harmonic:e}");
}

#[test]
fn new_checks_the_body_and_says_what_is_wrong() {
    let tensor = SYMMETRIC.tensor();
    let field = |e: eom::generic::ModelError| e.to_string();
    assert!(field(TopEuler::<f64>::new(0.0, &tensor, 0.5, 9.81).unwrap_err()).contains("mass"));
    assert!(field(TopEuler::<f64>::new(1.0, &tensor, f64::NAN, 9.81).unwrap_err()).contains("h"));
    assert!(
        field(TopQuaternion::<f64>::new(1.0, &tensor, 0.5, f64::INFINITY).unwrap_err())
            .contains("g must be finite")
    );
    // A product of inertia: the top takes principal axes at G.
    let skew = InertiaTensor::new(0.25, 0.25, 0.2, 0.01, 0.0, 0.0).unwrap();
    let error = field(TopEuler::<f64>::new(1.0, &skew, 0.5, 9.81).unwrap_err());
    assert!(
        error.contains("Ixy") && error.contains("principal"),
        "{error}"
    );
    // M h² overflows: the moments about the pivot are not finite.
    let error = field(TopEuler::<f64>::new(1.0, &tensor, 1e160, 9.81).unwrap_err());
    assert!(error.contains("I + M h²"), "{error}");
    // G below the pivot, and gravity turned over, are tops too.
    assert!(TopEuler::<f64>::new(1.0, &tensor, -0.5, 9.81).is_ok());
    assert!(TopQuaternion::<f64>::new(1.0, &tensor, 0.5, -9.81).is_ok());
}

#[test]
fn any_model_builds_a_top_and_reports_both_energies() {
    for kinematics in Kinematics::ALL {
        let b = SYMMETRIC;
        let model = AnyModel::top(kinematics, b.mass, &b.tensor(), b.h, b.g).unwrap();
        assert_eq!(model.info().kinematics, Some(kinematics));
        assert_eq!(model.info().family, eom::models::Family::Top);
        let state: Vec<f64> = match kinematics {
            Kinematics::Euler => SPIN_START_EULER.to_vec(),
            Kinematics::Quaternion => spin_start_quaternion().to_vec(),
        };
        let v = model.potential_energy(&state).unwrap().unwrap();
        // Mgh cos of the 0.5 rad tilt.
        assert!((v - b.mgh() * 0.5f64.cos()).abs() < 1e-14 * b.mgh());
        let t = model.kinetic_energy(&state).unwrap();
        let w = Vector3::new(state[0], state[1], state[2]);
        let by_hand = 0.5 * w.dot(&b.about_pivot().component_mul(&w));
        assert!((t - by_hand).abs() < 1e-14 * by_hand);
    }
    // A free body has no potential energy.
    let free = AnyModel::spatial(
        eom::models::Symmetry::Principal,
        Kinematics::Quaternion,
        1.0,
        &SYMMETRIC.tensor(),
    )
    .unwrap();
    assert_eq!(free.potential_energy(&[0.0; 13]).unwrap(), None);
}
