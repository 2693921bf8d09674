//! `eom eval --model spatial --kinematics euler` next to pitch ±90°, against the Euler rates
//! (4.60) computed in double-double arithmetic from the same doubles.
//!
//! Next to the vertical, φ̇ = p + (q sin φ + r cos φ) tan θ and ψ̇ = (q sin φ + r cos φ) sec θ
//! grow as 1/|cos θ|, and one ulp of θ changes them by ε/|cos θ| of themselves: 7e-9 at the
//! pitch 1.5707962967948965 (cos θ ≈ 3e-8), 2e-4 at 1e-12 rad from ±90°. So the real binary is
//! run at pitches 2e-12 to 1e-6 rad from ±90°, on both sides of both, and each of φ̇, θ̇, ψ̇ it
//! prints, generated and generic, must be within [`TOLERANCE`] ε of the size of its terms of
//! the rate computed with ~32 significant digits from the same input doubles. The same
//! models evaluated in this process, at the same doubles, show what the arithmetic alone
//! costs.
//!
//! The reference takes sin and cos of θ near ±π/2 as cos and sin of the tiny difference
//! δ = θ ∓ π/2, with π/2 to 160 bits: a double θ is exact, so δ comes out to ~32 significant
//! digits even at 1e-12, and its sine and cosine by their series.
//!
//! Before serde_json read `eom eval`'s input to the nearest double (its `float_roundtrip`
//! feature), 7 of these 17 pitches were read an ulp off: 3.3e7 ε of the terms at
//! 1.5707962967948965 and 8.3e10 ε at 1.15e-11 rad from +90°, while the same models in
//! process were within 1.9 ε at every pitch. Now the binary is too.

use eom::InertiaTensor;
use eom::generic::{EulerState, RigidBody};
use eom::models::{Model, SpatialFullEuler};
use nalgebra::Vector3;

use eom_test_support::double_double::Dd;
use eom_test_support::eval as eom_eval;
use eom_test_support::random::Random;

/// Each form computes φ̇ with at most seven roundings of ε/2 of the terms (q sin φ, r cos φ,
/// their sum, 1/cos θ, two products, the sum with p): 3.5ε. Its four sines and cosines add an
/// ulp each (ε relative at most) where the platform's are within an ulp of exact; the kernel's
/// `sin_cos` is within one more ulp of the platform's for everyday angles (φ) and two more next
/// to a multiple of π/2 (θ): 3.5 + 2 + 2 + 3 + 3 = 13.5ε at worst. The reference is ~10¹⁶
/// times more accurate, and the printed value is the double itself (shortest round trip, read
/// back exactly).
const TOLERANCE: f64 = 16.0;

/// π/2 as three doubles, 160 bits (the sum is π/2 to ~1e-49).
const HALF_PI: [f64; 3] = [
    std::f64::consts::FRAC_PI_2,
    6.123233995736766e-17,
    -1.4973849048591698e-33,
];

/// sin x and cos x of a double x (|x| < 4) in double-double: x = kπ/2 + t with t in
/// [−π/4, π/4] computed from the three-part π/2 (t is x ∓ π/2, tiny, next to ±90°), then the
/// series of sin t and cos t, and the quadrant.
fn sin_cos(x: f64) -> (Dd, Dd) {
    let k = (x / HALF_PI[0]).round();
    assert!(k.abs() <= 2.0, "small angles only");
    // k·HALF_PI[i] is exact for |k| ≤ 2.
    let t =
        Dd::new(x) - Dd::new(k * HALF_PI[0]) - Dd::new(k * HALF_PI[1]) - Dd::new(k * HALF_PI[2]);
    let t2 = t * t;
    // sin t = t − t³/3! + …, cos t = 1 − t²/2! + …, to below 1e-33 of the leading term.
    let (mut sin, mut cos) = (t, Dd::new(1.0));
    let (mut s_term, mut c_term) = (t, Dd::new(1.0));
    for n in 1..30 {
        let n = n as f64;
        s_term = -(s_term * t2) / Dd::new((2.0 * n) * (2.0 * n + 1.0));
        c_term = -(c_term * t2) / Dd::new((2.0 * n - 1.0) * (2.0 * n));
        sin = sin + s_term;
        cos = cos + c_term;
    }
    match k as i64 {
        0 => (sin, cos),
        1 => (cos, -sin),
        2 | -2 => (-sin, -cos),
        _ => (-cos, sin), // k = −1
    }
}

/// φ̇, θ̇, ψ̇ of 4.60 in double-double at the doubles (p, q, r, φ, θ), and the size of each
/// one's terms.
fn euler_rates(p: f64, q: f64, r: f64, phi: f64, theta: f64) -> ([f64; 3], [f64; 3]) {
    let ((s_phi, c_phi), (s_theta, c_theta)) = (sin_cos(phi), sin_cos(theta));
    let (p, q, r) = (Dd::new(p), Dd::new(q), Dd::new(r));
    let sec = Dd::new(1.0) / c_theta;
    let lateral = q * s_phi + r * c_phi;
    let rates = [
        p + lateral * s_theta * sec,
        q * c_phi - r * s_phi,
        lateral * sec,
    ]
    .map(Dd::to_f64);
    let lateral_terms = (q * s_phi).abs() + (r * c_phi).abs();
    let terms = [
        p.abs() + lateral_terms * (s_theta * sec).abs(),
        (q * c_phi).abs() + (r * s_phi).abs(),
        lateral_terms * sec.abs(),
    ]
    .map(Dd::to_f64);
    (rates, terms)
}

/// The state's pitches: the one that showed the fault, and doubles 2e-12 to 1e-6 rad from
/// +90° and −90°, evenly on a log scale, above and below each in turn.
fn pitches() -> Vec<f64> {
    let mut pitches = vec![1.5707962967948965];
    for i in 0..16 {
        let offset = 10f64.powf(-11.7 + 5.7 * f64::from(i) / 15.0);
        let vertical = if i % 2 == 0 { 1.0 } else { -1.0 };
        let side = if i % 4 < 2 { 1.0 } else { -1.0 };
        pitches.push(vertical * std::f64::consts::FRAC_PI_2 + side * offset);
    }
    pitches
}

const INERTIA: [[f64; 3]; 3] = [[2.0, -0.1, 0.2], [-0.1, 3.0, 0.05], [0.2, 0.05, 4.0]];

/// The rates `eom eval` prints, generated and generic, for the state.
fn eval(rates: [f64; 3], angles: [f64; 3], long: bool) -> [[f64; 3]; 2] {
    // Half the inputs in the shortest form, half with 17 digits.
    let n = |x: f64| {
        if long {
            format!("{x:.16e}")
        } else {
            format!("{x:?}")
        }
    };
    let [p, q, r] = rates.map(n);
    let [phi, theta, psi] = angles.map(n);
    let input = format!(
        r#"{{"mass": 2.0, "inertia": {INERTIA:?},
  "state": {{"u": 1.0, "v": -0.5, "w": 0.25, "p": {p}, "q": {q}, "r": {r},
            "phi": {phi}, "theta": {theta}, "psi": {psi}}},
  "force": [1.0, 0.0, 0.0], "moment": [0.0, 0.5, 0.0]}}"#
    );
    let run = eom_eval::eval(&["--model", "spatial", "--kinematics", "euler"], &input);
    assert!(run.ok, "{input}: {}", run.stderr);
    let printed: serde_json::Value = serde_json::from_str(&run.stdout).unwrap();
    ["generated", "generic"].map(|form| {
        ["phi_dot", "theta_dot", "psi_dot"].map(|key| printed[form][key].as_f64().unwrap())
    })
}

/// The same models in this process, at the doubles themselves.
fn in_process(rates: [f64; 3], angles: [f64; 3]) -> [[f64; 3]; 2] {
    let tensor = InertiaTensor::from_matrix(INERTIA.into()).unwrap();
    let mut state = [1.0, -0.5, 0.25, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
    state[3..6].copy_from_slice(&rates);
    state[9..12].copy_from_slice(&angles);
    let load = [1.0, 0.0, 0.0, 0.0, 0.5, 0.0];
    let generated = SpatialFullEuler::<f64>::new(2.0, &tensor)
        .unwrap()
        .rhs(&state, &load);
    let body = RigidBody::<f64>::new(2.0, &tensor).unwrap();
    let generic = body.rhs_euler(
        &EulerState::from_column_slice(&state),
        &Vector3::new(1.0, 0.0, 0.0),
        &Vector3::new(0.0, 0.5, 0.0),
    );
    [
        [generated[9], generated[10], generated[11]],
        [generic[9], generic[10], generic[11]],
    ]
}

#[test]
fn the_reference_rates_are_right() {
    // sin and cos against the platform away from the vertical, and at θ = 0.5 the rates by
    // hand: each within an ulp or two of the double-double value.
    for x in [0.1, -0.7, 1.2, -2.5, 3.0, std::f64::consts::FRAC_PI_2] {
        let (s, c) = sin_cos(x);
        assert!(
            (s.to_f64() - x.sin()).abs() <= 2.0 * f64::EPSILON,
            "sin {x}"
        );
        assert!(
            (c.to_f64() - x.cos()).abs() <= 2.0 * f64::EPSILON,
            "cos {x}"
        );
        // sin² + cos² = 1 to dd precision.
        assert!(((s * s + c * c).to_f64() - 1.0).abs() < 1e-30, "{x}");
    }
    // cos(π/2) in dd is the π/2 double's distance from π/2: 6.123233995736766e-17.
    let (_, c) = sin_cos(std::f64::consts::FRAC_PI_2);
    assert!((c.to_f64() - 6.123233995736766e-17).abs() < 1e-32);
    let (rates, _) = euler_rates(0.1, 0.2, 0.3, 0.4, 0.5);
    let expected = [
        0.1 + (0.2 * 0.4f64.sin() + 0.3 * 0.4f64.cos()) * 0.5f64.tan(),
        0.2 * 0.4f64.cos() - 0.3 * 0.4f64.sin(),
        (0.2 * 0.4f64.sin() + 0.3 * 0.4f64.cos()) / 0.5f64.cos(),
    ];
    for (a, b) in rates.iter().zip(expected) {
        assert!((a - b).abs() <= 4.0 * f64::EPSILON * b.abs(), "{a} vs {b}");
    }
}

#[test]
fn eval_near_the_vertical_matches_double_double_rates() {
    let mut rng = Random(0x90DE6);
    let mut worst = [0.0f64; 4];
    println!("errors in ε of the terms, the worst of φ̇, θ̇, ψ̇:");
    println!(
        "{:>24} {:>9}  {:>9} {:>9}   {:>9} {:>9}",
        "θ", "|cos θ|", "eom eval", "(generic)", "in proc.", "(generic)"
    );
    for (i, theta) in pitches().into_iter().enumerate() {
        let mut draw = |scale: f64| (2.0 * rng.unit() - 1.0) * scale;
        let rates = [draw(10.0), draw(10.0), draw(10.0)];
        let angles = [
            draw(std::f64::consts::PI),
            theta,
            draw(std::f64::consts::PI),
        ];
        let (exact, terms) = euler_rates(rates[0], rates[1], rates[2], angles[0], theta);
        let [binary_generated, binary_generic] = eval(rates, angles, i % 2 == 1);
        let [process_generated, process_generic] = in_process(rates, angles);
        let errors = [
            binary_generated,
            binary_generic,
            process_generated,
            process_generic,
        ]
        .map(|got| {
            (0..3)
                .map(|k| (got[k] - exact[k]).abs() / terms[k] / f64::EPSILON)
                .fold(0.0, f64::max)
        });
        println!(
            "{theta:>24?} {:9.2e}  {:9.2e} {:9.2e}   {:9.2e} {:9.2e}",
            theta.cos().abs(),
            errors[0],
            errors[1],
            errors[2],
            errors[3]
        );
        for (w, e) in worst.iter_mut().zip(errors) {
            *w = w.max(e);
        }
    }
    println!(
        "worst: binary {:.2} and {:.2} ε, in process {:.2} and {:.2} ε (tolerance {TOLERANCE} ε)",
        worst[0], worst[1], worst[2], worst[3]
    );
    for (what, w) in ["binary generated", "binary generic", "generated", "generic"]
        .iter()
        .zip(worst)
    {
        assert!(w <= TOLERANCE, "{what}: {w:.3e} ε of the terms");
    }
}
