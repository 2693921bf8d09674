//! An aircraft described by a textbook's stability derivatives: the Navion of R. C. Nelson,
//! Flight Stability and Automatic Control (2nd ed.), as `data/navion_nelson.json` transcribes
//! its table from public copies (its sources and the readings that differ are in the file and
//! in data/README.md), run as `scenes/navion.toml`.
//!
//! The book's printed eigenvalues could not be checked against a copy of the book here, so
//! the modes are held against what the book computes them from: its small-perturbation
//! model, the dimensional derivatives X_u … N_r formed from the same table (Nelson's
//! formulas, with the flight condition's θ₀ = α₀ kept), built here independently of eom's
//! derivation.

#![cfg(feature = "ship")]

use eom::kinds::aircraft::AircraftScene;
use eom::kinds::aircraft::derivatives::Derivatives;
use eom::linear::modes::eigenvalues;
use eom_test_support::differences::{assert_rows_agree, central_jacobians};
use nalgebra::{Complex, DMatrix};
use serde_json::Value;
use std::path::Path;

fn read(path: &str) -> String {
    std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(path)).unwrap()
}

fn navion() -> AircraftScene {
    AircraftScene::parse(&read("scenes/navion.toml"), "navion.toml").unwrap()
}

fn sorted(mut values: Vec<Complex<f64>>) -> Vec<Complex<f64>> {
    values.sort_by(|x, y| x.re.total_cmp(&y.re).then(x.im.total_cmp(&y.im)));
    values
}

/// The block of `a` over `states`.
fn block(a: &[[f64; 13]; 13], states: &[usize]) -> DMatrix<f64> {
    DMatrix::from_fn(states.len(), states.len(), |i, j| a[states[i]][states[j]])
}

/// `scenes/navion.toml` holds the data file's numbers bit for bit: every derivative it gives
/// (and no other), the mass W/g, the inertia, the geometry, the flight condition.
#[test]
fn the_navion_scene_holds_the_published_table_bit_for_bit() {
    let data: Value = serde_json::from_str(&read("data/navion_nelson.json")).unwrap();
    let scene: toml::Table = toml::from_str(&read("scenes/navion.toml")).unwrap();
    let given = scene["aerodynamics"]["derivatives"].as_table().unwrap();
    let published = data["derivatives_per_rad"].as_object().unwrap();
    assert_eq!(given.len(), published.len());
    for (name, value) in published {
        let ours = given[name].as_float().unwrap();
        assert_eq!(ours.to_bits(), value.as_f64().unwrap().to_bits(), "{name}");
    }
    let number = |v: &Value| v.as_f64().unwrap();
    let float = |v: &toml::Value| v.as_float().unwrap();
    let condition = &data["condition"];
    let body = &scene["body"];
    let mass = number(&condition["weight_lbf"]) / number(&condition["gravity_ft_s2"]);
    assert_eq!(float(&body["mass"]).to_bits(), mass.to_bits());
    assert_eq!(float(&body["gravity"]), number(&condition["gravity_ft_s2"]));
    let inertia = &data["inertia_slug_ft2"];
    let tensor = body["inertia"].as_array().unwrap();
    for (k, axis) in ["Ixx", "Iyy", "Izz"].iter().enumerate() {
        assert_eq!(float(&tensor[k]), number(&inertia[axis]), "{axis}");
    }
    let products = body["products_of_inertia"].as_array().unwrap();
    assert_eq!(float(&products[2]), -number(&inertia["Ixz"]));
    let geometry = &data["geometry"];
    for (key, theirs) in [
        ("area", "area_ft2"),
        ("span", "span_ft"),
        ("chord", "chord_ft"),
        ("xcg", "xcg_fraction_of_chord"),
    ] {
        assert_eq!(
            float(&scene["geometry"][key]),
            number(&geometry[theirs]),
            "{key}"
        );
    }
    assert_eq!(
        float(&scene["trim"]["speed"]),
        number(&condition["speed_ft_s"])
    );
    assert_eq!(
        float(&scene["trim"]["altitude"]),
        number(&condition["altitude_ft"])
    );
}

/// Level trim at 176 ft/s: with C_m0 = 0 and no rate, the pitching moment C_mα α + C_mδe δe
/// is zero to rounding, and the lift C_L = C_L0 + C_Lα α + C_Lδe δe carries the weight less
/// the thrust's share (T sin α, the thrust along body x) to rounding.
#[test]
fn the_navion_trims_with_its_moment_zero_and_its_lift_the_weight() {
    let scene = navion();
    let (state, controls) = (scene.trim.state, scene.trim.controls);
    assert!(scene.trim.residual < 1e-9, "{}", scene.trim.residual);
    let (alpha, elevator) = (state[1], controls[1].to_radians());
    let moment = -0.683 * alpha + -0.923 * elevator;
    assert!(moment.abs() < 1e-12, "C_m = {moment}");
    let air = scene.model.atmosphere().at(0.0).unwrap();
    let dynamic_pressure = 0.5 * air.density * 176.0 * 176.0;
    let lift = 0.41 + 4.44 * alpha + 0.355 * elevator;
    let drag = 0.05 + 0.33 * alpha;
    let thrust = 512.5 * state[12] / 100.0;
    // Along the wind axes' normal: L + T sin α = W cos γ (γ = 0), and along the flight path
    // T cos α = D.
    let weight = 2750.0;
    let normal = lift * dynamic_pressure * 184.0 + thrust * alpha.sin() - weight;
    let along = thrust * alpha.cos() - drag * dynamic_pressure * 184.0;
    assert!(normal.abs() < 1e-9 * weight, "{normal}");
    assert!(along.abs() < 1e-9 * weight, "{along}");
    assert!(
        alpha.abs() < 0.01,
        "alpha {alpha}: the table's condition has α₀ near 0"
    );
}

/// The book's small-perturbation model of the condition, from the scene's table at eom's
/// trim (the air's density, the trim's C_L and C_D, θ₀ = α₀): the longitudinal (u, w, q, θ)
/// and lateral-directional (β, p, r, φ) matrices as Nelson writes them, with Z_q and the
/// lateral model's sin α₀, tan θ₀ kept.
struct Textbook {
    longitudinal: DMatrix<f64>,
    lateral: DMatrix<f64>,
}

fn textbook(scene: &AircraftScene) -> Textbook {
    let d = Derivatives {
        CL_alpha: 4.44,
        CD_alpha: 0.33,
        CL_q: 3.8,
        Cm_alpha: -0.683,
        Cm_alpha_dot: -4.36,
        Cm_q: -9.96,
        CY_beta: -0.564,
        Cl_beta: -0.074,
        Cl_p: -0.41,
        Cl_r: 0.107,
        Cn_beta: 0.071,
        Cn_p: -0.0575,
        Cn_r: -0.125,
        ..Derivatives::default()
    };
    let (u0, g, m) = (176.0, 32.2, 2750.0 / 32.2);
    let (s, b, c) = (184.0, 33.4, 5.7);
    let (ixx, iyy, izz) = (1048.0, 3000.0, 3530.0);
    let alpha0 = scene.trim.state[1];
    let elevator = scene.trim.controls[1].to_radians();
    let air = scene.model.atmosphere().at(0.0).unwrap();
    let q = 0.5 * air.density * u0 * u0;
    let cl0 = 0.41 + d.CL_alpha * alpha0 + 0.355 * elevator;
    let cd0 = 0.05 + d.CD_alpha * alpha0;
    let qs = q * s;
    let xu = -2.0 * cd0 * qs / (m * u0);
    let xw = -(d.CD_alpha - cl0) * qs / (m * u0);
    let zu = -2.0 * cl0 * qs / (m * u0);
    let zw = -(d.CL_alpha + cd0) * qs / (m * u0);
    let zq = -d.CL_q * c / (2.0 * u0) * qs / m;
    let mw = d.Cm_alpha * qs * c / (iyy * u0);
    let mwdot = d.Cm_alpha_dot * c / (2.0 * u0) * qs * c / (iyy * u0);
    let mq = d.Cm_q * c / (2.0 * u0) * qs * c / iyy;
    // In the condition's stability axes, level flight: θ₀ = γ₀ = 0.
    #[rustfmt::skip]
    let longitudinal = DMatrix::from_row_slice(4, 4, &[
        xu, xw, 0.0, -g,
        zu, zw, u0 + zq, 0.0,
        mwdot * zu, mw + mwdot * zw, mq + mwdot * (u0 + zq), 0.0,
        0.0, 0.0, 1.0, 0.0,
    ]);
    // eom's moments and rates are in the scene's body axes, α₀ from the stability axes.
    let (sin, cos) = alpha0.sin_cos();
    let per_rate = b / (2.0 * u0);
    let (roll, yaw) = (qs * b / ixx, qs * b / izz);
    #[rustfmt::skip]
    let lateral = DMatrix::from_row_slice(4, 4, &[
        d.CY_beta * qs / (m * u0), sin, -cos, g * cos / u0,
        d.Cl_beta * roll, d.Cl_p * per_rate * roll, d.Cl_r * per_rate * roll, 0.0,
        d.Cn_beta * yaw, d.Cn_p * per_rate * yaw, d.Cn_r * per_rate * yaw, 0.0,
        0.0, 1.0, alpha0.tan(), 0.0,
    ]);
    Textbook {
        longitudinal,
        lateral,
    }
}

/// eom's modes of the Navion, from the proved Jacobians at its trim (with C_mα̇'s term through
/// α̇), against the book's small-perturbation model of the same table: the longitudinal
/// block (V, α, θ, q) at constant altitude and the lateral-directional block (β, φ, p, r).
/// They are the same linear model in other coordinates (u = V, w = V α in the stability
/// axes), so the eigenvalues agree to what the two computations round: 1e-12 of each one's
/// magnitude (measured: at most 7e-14, the Schur iterations' and the Jacobians' rounding).
/// What the book's model leaves out moves them: the density's fall with height (eom's
/// altitude row) raises the phugoid's frequency from 0.2140 to 0.2155 rad/s, and dropping
/// the condition's α₀ = −0.054° from the lateral model moves the spiral root by 2 %.
#[test]
fn the_navions_modes_are_its_textbook_models() {
    let scene = navion();
    let (a, _) = scene
        .model
        .jacobians(&scene.trim.state, &scene.trim.controls);
    let book = textbook(&scene);
    let close = |got: &[Complex<f64>], want: &[Complex<f64>], what: &str| {
        assert_eq!(got.len(), want.len());
        for (g, w) in got.iter().zip(want) {
            assert!((g - w).norm() <= 1e-12 * w.norm(), "{what}: {g} vs {w}");
        }
    };
    let longitudinal = sorted(eigenvalues(&block(&a, &[0, 1, 4, 7])));
    let lateral = sorted(eigenvalues(&block(&a, &[2, 6, 8, 3])));
    println!("eom: longitudinal {longitudinal:?}\nlateral {lateral:?}");
    close(
        &longitudinal,
        &sorted(eigenvalues(&book.longitudinal)),
        "longitudinal",
    );
    close(&lateral, &sorted(eigenvalues(&book.lateral)), "lateral");
    // The blocks are the whole story at constant altitude: the full reduced A (with the power
    // lag, decoupled at constant thrust) has these and −1/τ.
    let with_power = sorted(eigenvalues(&block(&a, &[0, 1, 2, 3, 4, 6, 7, 8, 12])));
    let mut expected = [longitudinal.clone(), lateral.clone()].concat();
    expected.push(Complex::new(-1.0, 0.0));
    close(&with_power, &sorted(expected), "reduced");
    // The altitude's coupling, which the book's model has not: the phugoid's frequency with
    // it, eom's full reduced state.
    let full = sorted(eigenvalues(&block(&a, &[0, 1, 2, 3, 4, 6, 7, 8, 11, 12])));
    let phugoid = full
        .iter()
        .find(|z| z.im > 0.1 && z.im < 0.3)
        .expect("a phugoid");
    assert!((phugoid.im - 0.21554).abs() < 5e-5, "{phugoid}");
}

/// C_mα̇'s term is q̄ S c̄ C_mα̇ (c̄/2V) α̇ / I_yy in q̇, and nothing else: the rates with and
/// without it differ there alone, by that, at a state where α̇ is far from zero.
#[test]
fn the_alpha_rate_term_is_the_pitching_moment_of_alpha_rate() {
    let scene = navion();
    let text = read("scenes/navion.toml").replace("Cm_alpha_dot = -4.36\n", "");
    let without = AircraftScene::parse(&text, "navion.toml").unwrap();
    let mut state = scene.trim.state;
    state[1] += 0.05;
    state[7] = 0.2;
    let controls = scene.trim.controls;
    let (with_term, without_term) = (
        scene.model.rates(&state, &controls),
        without.model.rates(&state, &controls),
    );
    let alpha_rate = without_term[1];
    assert!(alpha_rate.abs() > 0.05, "{alpha_rate}");
    let air = scene.model.atmosphere().at(state[11]).unwrap();
    let v = state[0];
    let moment = 0.5 * air.density * v * v * 184.0 * 5.7 * -4.36 * 5.7 / (2.0 * v) * alpha_rate;
    for k in 0..13 {
        let expected = if k == 7 { moment / 3000.0 } else { 0.0 };
        let difference = with_term[k] - without_term[k];
        assert!(
            (difference - expected).abs() < 1e-12 * (1.0 + without_term[k].abs()),
            "rate {k}: {difference} vs {expected}"
        );
    }
}

/// The Jacobians (the proved ones composed with the derivatives' slopes and C_mα̇'s term
/// through α̇'s row) against central differences of the rates, off the trim where every
/// term acts. Step 1e-6 of each entry's scale; the rates are smooth there, so truncation
/// (h²) and rounding (1e-16 |f| / h) stay below 1e-6 of each row's largest entry.
#[test]
fn the_navions_jacobians_are_its_rates_slopes() {
    let scene = navion();
    let mut state = scene.trim.state;
    state[0] = 180.0;
    state[1] = 0.06;
    state[2] = 0.03;
    state[3] = 0.2;
    state[4] = 0.1;
    state[6] = 0.1;
    state[7] = -0.05;
    state[8] = 0.08;
    state[11] = 1500.0;
    let controls = [0.7, -2.0, 1.5, 3.0];
    let (a, b) = scene.model.jacobians(&state, &controls);
    let (numeric_a, numeric_b) = central_jacobians(
        |x, u| scene.model.rates(x, u),
        (&state, &controls),
        |v| 1e-6 * v.abs().max(1.0),
    );
    assert_rows_agree(&a, &numeric_a, "x", 1e-6);
    assert_rows_agree(&b, &numeric_b, "u", 1e-6);
}

/// Bad derivative scenes are refused naming the key: a term not in the list, a term that is
/// not finite, a table of the other form, an engine given both ways or half.
#[test]
fn bad_derivative_scenes_name_the_key() {
    let text = read("scenes/navion.toml");
    let refused = |from: &str, to: &str, key: &str| {
        assert!(text.contains(from), "{from}");
        let error = AircraftScene::parse(&text.replacen(from, to, 1), "navion.toml")
            .err()
            .unwrap_or_else(|| panic!("{to} was accepted"))
            .to_string();
        assert!(error.contains(key), "{error}");
    };
    refused("CL_alpha = 4.44", "CL_alfa = 4.44", "CL_alfa");
    refused(
        "CL_alpha = 4.44",
        "CL_alpha = nan",
        "aerodynamics.derivatives.CL_alpha",
    );
    refused(
        "[limits]",
        "[aerodynamics.cz]\nalpha_deg = [0.0, 1.0]\nvalues = [0.0, 1.0]\n\n[limits]",
        "aerodynamics.cz",
    );
    refused("time_constant_s = 1.0\n", "", "engine.time_constant_s");
    refused("thrust = 512.5", "thrust = -512.5", "engine.thrust");
    refused(
        "time_constant_s = 1.0",
        "time_constant_s = 1.0\nmach = [0.0, 1.0]",
        "engine.mach",
    );
    refused("thrust = 512.5", "# no thrust", "engine.time_constant_s");
    let no_engine =
        text.replacen("thrust = 512.5", "#", 1)
            .replacen("time_constant_s = 1.0", "#", 1);
    let error = AircraftScene::parse(&no_engine, "navion.toml")
        .err()
        .unwrap();
    assert!(error.to_string().contains("engine.altitude"), "{error}");
    refused(
        "aerodynamics = \"derivatives\"",
        "aerodynamics = \"stevens-lewis\"",
        "aerodynamics.derivatives",
    );
}
