//! SymPy's C, both builds, computes what eom's generated models compute: the bench compares
//! their speed only if these hold.

use eom_peer::{Draw, EomModel, MASS, SEED, body, draw, eom_model, fma, op_by_op};

/// Agreement asked of every entry, relative to the output's largest entry.
const TOLERANCE: f64 = 1e-12;

fn draws() -> Vec<Draw> {
    draw(64, SEED)
}

/// eom and both C builds of one variant at every draw, on the variant's body.
fn check<K, const N: usize>(eom: EomModel<K, N>, state: impl Fn(&Draw) -> [f64; N]) {
    let parameters = eom_peer::parameters(MASS, &body(eom.name));
    for c in [op_by_op::MODELS, fma::MODELS].iter().map(|models| {
        models
            .iter()
            .find(|m| m.name == eom.name)
            .expect("a C model")
    }) {
        let k = c.coefficients(&parameters);
        for (i, d) in draws().iter().enumerate() {
            let x = state(d);
            let expected = (eom.rhs)(&eom.k, &x, &d.input);
            let got = c.rhs(&k, &x, &d.input);
            assert!(
                eom_peer::agree(&expected, &got, TOLERANCE).is_ok(),
                "{} draw {i}: eom {expected:?}, C {got:?}",
                eom.name
            );
            // The unit form differs from the normalised one only by |q|² − 1, a rounding here.
            if let Some(unit) = c.rhs_unit(&k, &x, &d.input) {
                assert!(
                    eom_peer::agree(&expected, &unit, TOLERANCE).is_ok(),
                    "{} draw {i}: eom {expected:?}, C unit {unit:?}",
                    eom.name
                );
            }
        }
    }
}

#[test]
fn full_euler() {
    check(
        eom_model::spatial_full_euler(MASS, &body("spatial_full_euler")),
        |d| d.euler,
    );
}

#[test]
fn full_quaternion() {
    let name = "spatial_full_quaternion";
    check(eom_model::spatial_full_quaternion(MASS, &body(name)), |d| {
        d.quaternion
    });
}

#[test]
fn xz_euler() {
    check(
        eom_model::spatial_xz_euler(MASS, &body("spatial_xz_euler")),
        |d| d.euler,
    );
}

#[test]
fn xz_quaternion() {
    check(
        eom_model::spatial_xz_quaternion(MASS, &body("spatial_xz_quaternion")),
        |d| d.quaternion,
    );
}

#[test]
fn principal_euler() {
    let name = "spatial_principal_euler";
    check(eom_model::spatial_principal_euler(MASS, &body(name)), |d| {
        d.euler
    });
}

#[test]
fn principal_quaternion() {
    let name = "spatial_principal_quaternion";
    check(
        eom_model::spatial_principal_quaternion(MASS, &body(name)),
        |d| d.quaternion,
    );
}

/// The normalised C form divides by |q|²: a quaternion of norm 2 gives what its unit
/// quaternion gives, as eom's contract says; the unit form does not.
#[test]
fn quaternion_contract() {
    let name = "spatial_full_quaternion";
    let eom = eom_model::spatial_full_quaternion(MASS, &body(name));
    let c = op_by_op::MODELS[1];
    assert_eq!(c.name, name);
    let k = c.coefficients(&eom_peer::parameters(MASS, &body(name)));
    let d = draws()[0];
    let mut doubled = d.quaternion;
    doubled[9..].iter_mut().for_each(|q| *q *= 2.0);
    let at_unit = c.rhs(&k, &d.quaternion, &d.input);
    let at_double = c.rhs(&k, &doubled, &d.input);
    assert!(eom_peer::agree(&at_unit[6..9], &at_double[6..9], TOLERANCE).is_ok());
    let eom_double = (eom.rhs)(&eom.k, &doubled, &d.input);
    assert!(eom_peer::agree(&eom_double[6..9], &at_double[6..9], TOLERANCE).is_ok());
    let unit_double = c
        .rhs_unit(&k, &doubled, &d.input)
        .expect("a quaternion variant");
    assert!(eom_peer::agree(&unit_double[6..9], &at_double[6..9], 1e-3).is_err());
}

/// Each `_coefficients` writes exactly the `k_len` entries declared for it: all of them
/// finite, none past the end.
#[test]
fn coefficient_lengths() {
    for c in op_by_op::MODELS.iter().chain(&fma::MODELS) {
        let parameters = eom_peer::parameters(MASS, &body(c.name));
        let mut k = vec![f64::NAN; c.k_len + 8];
        // SAFETY: a buffer longer than any variant writes; the test is what it writes.
        unsafe { (c.coefficients_fn)(parameters.as_ptr(), k.as_mut_ptr()) };
        assert!(
            k[..c.k_len].iter().all(|x| x.is_finite()),
            "{}: {k:?}",
            c.name
        );
        assert!(k[c.k_len..].iter().all(|x| x.is_nan()), "{}: {k:?}", c.name);
    }
}

/// The two builds hold the same variants in the same order, with the unit form exactly where
/// the state is a quaternion.
#[test]
fn builds_match() {
    for (a, b) in op_by_op::MODELS.iter().zip(&fma::MODELS) {
        assert_eq!(
            (a.name, a.state_len, a.k_len),
            (b.name, b.state_len, b.k_len)
        );
        assert_eq!(a.unit_fn.is_some(), a.state_len == 13, "{}", a.name);
        assert_eq!(b.unit_fn.is_some(), b.state_len == 13, "{}", b.name);
    }
}

/// The draws are unit quaternions of the same attitude as the Euler angles (the same position
/// rates), pitch within ±80°.
#[test]
fn draws_are_realistic() {
    let euler = eom_model::spatial_principal_euler(MASS, &body("spatial_principal_euler"));
    let quaternion =
        eom_model::spatial_principal_quaternion(MASS, &body("spatial_principal_quaternion"));
    for d in draws() {
        let by_angles = (euler.rhs)(&euler.k, &d.euler, &d.input);
        let by_quaternion = (quaternion.rhs)(&quaternion.k, &d.quaternion, &d.input);
        assert!(eom_peer::agree(&by_angles[..9], &by_quaternion[..9], TOLERANCE).is_ok());
        let q = &d.quaternion[9..];
        let norm2: f64 = q.iter().map(|x| x * x).sum();
        assert!((norm2 - 1.0).abs() < 4.0 * f64::EPSILON, "{norm2}");
        assert!(d.euler[10].abs() <= 80f64.to_radians());
        assert_eq!(d.euler[..9], d.quaternion[..9]);
    }
    assert_eq!(draw(3, SEED), draw(3, SEED));
}
