//! The simplifier, one line per rule: input text ⇒ canonical output text.

use eom_codegen::symbolic::{Expr, Mat3, Vec3, parse};

fn canonical(text: &str) -> String {
    parse(text).unwrap().to_string()
}

macro_rules! simplifies {
    ($($name:ident: $input:expr => $output:expr;)*) => {$(
        #[test]
        fn $name() {
            assert_eq!(canonical($input), $output, "input: {}", $input);
        }
    )*};
}

simplifies! {
    like_terms_merge: "x + 2*x - y" => "3*x - y";
    difference_of_equals_vanishes: "(a + b)*(a - b) - (a*a - b*b)" => "0";
    product_expands_and_orders: "(q*z - r*y)*x" => "q*x*z - r*x*y";
    pythagoras_reduces_to_one: "theta.sin()*theta.sin() + theta.cos()*theta.cos()" => "1";
    sine_squared_becomes_one_minus_cosine_squared: "phi.sin().powi(2)" => "1 - cos(phi)^2";
    sine_cubed_keeps_one_sine: "phi.sin().powi(3)" => "sin(phi) - sin(phi)*cos(phi)^2";
    tangent_is_sine_over_cosine: "theta.tan() - theta.sin()/theta.cos()" => "0";
    secant_is_reciprocal_cosine: "theta.sec()*theta.cos()" => "1";
    secant_squared_minus_tangent_squared: "theta.sec().powi(2) - theta.tan().powi(2)" => "1";
    call_form_equals_method_form: "sin(psi) - psi.sin()" => "0";
    exact_decimals: "0.5*x + x/2" => "x";
    rational_coefficients_stay_exact: "x/3 + x/6" => "1/2*x";
    division_by_a_symbol: "(M*g*h)/I0*I0" => "M*g*h";
    negative_power_of_symbol: "I0.powi(-2)*I0.powi(3)" => "I0";
    unary_minus_distributes: "-(x - y)" => "-x + y";
    angles_are_independent: "phi.sin()*phi.sin() + theta.cos()*theta.cos()" => "1 - cos(phi)^2 + cos(theta)^2";
    inertia_cross_term: "Ixx*p_dot + (Izz - Iyy)*q*r - Izz*q*r" => "Ixx*p_dot - Iyy*q*r";
}

#[test]
fn division_by_a_sum_is_refused() {
    let err = parse("x/(a + b)").unwrap_err();
    assert!(err.to_string().contains("cannot divide"), "{err}");
}

#[test]
fn sine_of_a_sum_is_refused() {
    assert!(parse("(a + b).sin()").is_err());
}

#[test]
fn unsupported_operator_is_named() {
    let err = parse("x % y").unwrap_err();
    assert!(err.to_string().contains("x % y"), "{err}");
}

#[test]
fn derivative_of_product_with_trig() {
    let e = parse("x*x*theta.sin()").unwrap();
    assert_eq!(e.diff("x").to_string(), "2*x*sin(theta)");
    assert_eq!(e.diff("theta").to_string(), "x^2*cos(theta)");
    assert_eq!(
        parse("theta.sec()").unwrap().diff("theta"),
        parse("theta.sec()*theta.tan()").unwrap()
    );
}

#[test]
fn time_derivative_uses_the_chain_rule() {
    let e = parse("theta.cos()*theta_dot").unwrap();
    let rates = [
        ("theta", Expr::symbol("theta_dot")),
        ("theta_dot", Expr::symbol("theta_ddot")),
    ];
    let expected = parse("-theta.sin()*theta_dot*theta_dot + theta.cos()*theta_ddot").unwrap();
    assert_eq!(e.time_derivative(&rates), expected);
}

#[test]
fn substitution_replaces_symbol_and_renames_angles() {
    let e = parse("v*r + psi.sin()").unwrap();
    let shifted = e.subs("v", &parse("v + x_G*r").unwrap()).unwrap();
    assert_eq!(shifted, parse("v*r + x_G*r*r + psi.sin()").unwrap());
    let renamed = e.subs("psi", &Expr::symbol("chi")).unwrap();
    assert_eq!(renamed, parse("v*r + chi.sin()").unwrap());
    assert!(e.subs("psi", &parse("a + b").unwrap()).is_err());
}

#[test]
fn cross_product_is_anticommutative() {
    let a = Vec3::symbols(["a1", "a2", "a3"]);
    let b = Vec3::symbols(["b1", "b2", "b3"]);
    let sum = a.cross(&b).add(&b.cross(&a));
    assert_eq!(sum, Vec3::zero());
    assert!(a.dot(&a.cross(&b)).is_zero());
}

#[test]
fn symbolic_inverse_times_matrix_is_identity() {
    let m = Mat3::from_fn(|r, c| match (r, c) {
        (0, 0) | (1, 1) | (2, 2) => Expr::cos("t"),
        (0, 1) => Expr::sin("t"),
        (1, 0) => -Expr::sin("t"),
        _ => Expr::zero(),
    });
    assert_eq!(m.inverse().unwrap().mul_mat(&m), Mat3::identity());
}

#[test]
fn coefficient_of_takes_exactly_the_first_power() {
    let e = parse("a*x + b*x*x + c + d/x + x.sin()").unwrap();
    assert_eq!(e.coefficient_of("x"), parse("a").unwrap());
    assert_eq!(
        e.coefficient_of_power("x", 0),
        parse("c + x.sin()").unwrap()
    );
    assert_eq!(e.coefficient_of_power("x", -1), parse("d").unwrap());
}
