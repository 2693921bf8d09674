//! A jet transport on a textbook's stability derivatives: the Boeing 747 of Etkin & Reid,
//! Dynamics of Flight (3rd ed.), Mach 0.8 at 40 000 ft, as `data/b747_etkin.json` transcribes
//! its table from a public copy (its source and what in it is uncertain are in the file and in
//! data/README.md), run as `scenes/b747.toml`. Its table has what a light aircraft's leaves
//! out: the speed derivatives, C_Lα̇, C_Dδe, and products of inertia printed as Etkin prints
//! them (∫zx dm).
//!
//! The book's printed roots could not be read from a public copy here, so the modes are held
//! against the small-perturbation model built from the same table, Etkin's dimensional
//! derivatives X_u … N_r at eom's trim, written here independently of eom's derivation.

#![cfg(feature = "ship")]

use eom::kinds::aircraft::AircraftScene;
use eom::linear::modes::eigenvalues;
use eom_test_support::differences::{assert_rows_agree, central_jacobians};
use nalgebra::{Complex, DMatrix, Matrix2, Vector2};
use serde_json::Value;
use std::path::Path;

fn read(path: &str) -> String {
    std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(path)).unwrap()
}

fn parse(text: &str) -> AircraftScene {
    AircraftScene::parse(text, "b747.toml").unwrap()
}

fn b747() -> AircraftScene {
    parse(&read("scenes/b747.toml"))
}

fn sorted(mut values: Vec<Complex<f64>>) -> Vec<Complex<f64>> {
    values.sort_by(|x, y| x.re.total_cmp(&y.re).then(x.im.total_cmp(&y.im)));
    values
}

/// The block of `a` over `states`.
fn block(a: &[[f64; 13]; 13], states: &[usize]) -> DMatrix<f64> {
    DMatrix::from_fn(states.len(), states.len(), |i, j| a[states[i]][states[j]])
}

/// The longitudinal (V, α, θ, q) and lateral-directional (β, φ, p, r) blocks of eom's A at
/// the scene's trim, their eigenvalues sorted.
fn modes_of(scene: &AircraftScene) -> (Vec<Complex<f64>>, Vec<Complex<f64>>) {
    let (a, _) = scene
        .model
        .jacobians(&scene.trim.state, &scene.trim.controls);
    (
        sorted(eigenvalues(&block(&a, &[0, 1, 4, 7]))),
        sorted(eigenvalues(&block(&a, &[2, 6, 8, 3]))),
    )
}

/// The published table as the file gives it.
struct Published(Value);

impl Published {
    fn read() -> Self {
        Published(serde_json::from_str(&read("data/b747_etkin.json")).unwrap())
    }

    fn at(&self, table: &str, key: &str) -> f64 {
        self.0[table][key]
            .as_f64()
            .unwrap_or_else(|| panic!("{table}.{key}"))
    }
}

/// `scenes/b747.toml` holds the data file's numbers: the derivatives the scene takes as
/// printed bit for bit, and those that Etkin's stability-axis C_x, C_z become as lift and
/// drag bit for bit to the formula (each one f64 operation or two on the printed numbers,
/// written beside it in the scene); the mass W/g, the inertia with the product as printed,
/// the geometry and the condition. Every derivative the scene gives is one of these.
#[test]
fn the_747_scene_holds_the_published_table() {
    let data = Published::read();
    let scene: toml::Table = toml::from_str(&read("scenes/b747.toml")).unwrap();
    let given = scene["aerodynamics"]["derivatives"].as_table().unwrap();
    let long = |key: &str| data.at("longitudinal_stability_axes", key);
    let lat = |key: &str| data.at("lateral_stability_axes", key);
    let condition = |key: &str| data.at("condition", key);
    let (w, g, s) = (
        condition("weight_N"),
        condition("gravity_m_s2"),
        data.at("geometry", "area_m2"),
    );
    let (rho, u0, cd0) = (
        condition("density_kg_m3"),
        condition("speed_m_s"),
        condition("CD_0"),
    );
    let lift_at_condition = w / (0.5 * rho * u0 * u0 * s);
    let expected: Vec<(&str, f64)> = vec![
        ("CL_0", lift_at_condition),
        ("CL_alpha", -long("Cz_alpha") - cd0),
        ("CL_q", -long("Cz_q")),
        ("CL_alpha_dot", -long("Cz_alpha_dot")),
        ("CL_u", -long("Cz_u")),
        ("CL_elevator", -long("Cz_delta_e")),
        ("CD_0", cd0),
        ("CD_alpha", lift_at_condition - long("Cx_alpha")),
        ("CD_u", -long("Cx_u") - 2.0 * cd0),
        ("CD_elevator", -long("Cx_delta_e")),
        ("Cm_alpha", long("Cm_alpha")),
        ("Cm_alpha_dot", long("Cm_alpha_dot")),
        ("Cm_q", long("Cm_q")),
        ("Cm_u", long("Cm_u")),
        ("Cm_elevator", long("Cm_delta_e")),
        ("CY_beta", lat("Cy_beta")),
        ("CY_rudder", lat("Cy_delta_r")),
        ("Cl_beta", lat("Cl_beta")),
        ("Cl_p", lat("Cl_p")),
        ("Cl_r", lat("Cl_r")),
        ("Cl_aileron", lat("Cl_delta_a")),
        ("Cl_rudder", lat("Cl_delta_r")),
        ("Cn_beta", lat("Cn_beta")),
        ("Cn_p", lat("Cn_p")),
        ("Cn_r", lat("Cn_r")),
        ("Cn_aileron", lat("Cn_delta_a")),
        ("Cn_rudder", lat("Cn_delta_r")),
        ("reference_speed", u0),
    ];
    // What the scene leaves out is 0 in the source.
    for zero in ["Cx_q", "Cx_alpha_dot"] {
        assert_eq!(long(zero), 0.0, "{zero}");
    }
    for zero in ["Cy_p", "Cy_r", "Cy_delta_a"] {
        assert_eq!(lat(zero), 0.0, "{zero}");
    }
    assert_eq!(given.len(), expected.len());
    for (name, value) in &expected {
        let ours = given[*name].as_float().unwrap();
        assert_eq!(ours.to_bits(), value.to_bits(), "{name}: {ours} vs {value}");
    }
    let float = |v: &toml::Value| v.as_float().unwrap();
    let body = &scene["body"];
    assert_eq!(float(&body["mass"]).to_bits(), (w / g).to_bits());
    assert_eq!(float(&body["gravity"]), g);
    let tensor = body["inertia"].as_array().unwrap();
    let inertia = |key: &str| data.at("inertia_stability_axes_kg_m2", key);
    for (k, axis) in ["Ix", "Iy", "Iz"].iter().enumerate() {
        assert_eq!(float(&tensor[k]), inertia(axis), "{axis}");
    }
    let products = body["products_of_inertia_integrals"].as_array().unwrap();
    assert_eq!(float(&products[2]), inertia("Izx"));
    for (key, theirs) in [
        ("area", "area_m2"),
        ("span", "span_m"),
        ("chord", "chord_m"),
        ("xcg", "xcg_fraction_of_chord"),
    ] {
        assert_eq!(
            float(&scene["geometry"][key]),
            data.at("geometry", theirs),
            "{key}"
        );
    }
    assert_eq!(float(&scene["trim"]["speed"]), u0);
    let feet = condition("altitude_ft");
    assert_eq!(float(&scene["trim"]["altitude"]), feet * 0.3048);
}

/// Etkin's small-perturbation model of the condition (stability axes, θ₀ = 0, a thrust
/// constant with speed) from the scene's table at eom's trim: the air's density there, the
/// trim's C_L and C_D, α₀ kept in the lateral model (eom's moments and rates are in the
/// scene's body axes, α₀ from the stability axes), the products of inertia as the tensor's
/// entry J_xz = −I_zx.
struct SmallPerturbation {
    longitudinal: DMatrix<f64>,
    lateral: DMatrix<f64>,
}

fn small_perturbation(scene: &AircraftScene) -> SmallPerturbation {
    let data = Published::read();
    let scene_table: toml::Table = toml::from_str(&read("scenes/b747.toml")).unwrap();
    let d = |key: &str| {
        scene_table["aerodynamics"]["derivatives"]
            .get(key)
            .map_or(0.0, |v| v.as_float().unwrap())
    };
    let geometry = |key: &str| data.at("geometry", key);
    let inertia = |key: &str| data.at("inertia_stability_axes_kg_m2", key);
    let (g, m) = (9.81, 2.83176e6 / 9.81);
    let (s, b, c) = (geometry("area_m2"), geometry("span_m"), geometry("chord_m"));
    let (ixx, iyy, izz, jxz) = (inertia("Ix"), inertia("Iy"), inertia("Iz"), -inertia("Izx"));
    let u0 = scene.trim.state[0];
    assert_eq!(
        u0,
        d("reference_speed"),
        "the trim is the table's condition"
    );
    let alpha0 = scene.trim.state[1];
    let elevator = scene.trim.controls[1].to_radians();
    let air = scene.model.atmosphere().at(scene.trim.state[11]).unwrap();
    let qs = 0.5 * air.density * u0 * u0 * s;
    let cl0 = d("CL_0") + d("CL_alpha") * alpha0 + d("CL_elevator") * elevator;
    let cd0 = d("CD_0") + d("CD_alpha") * alpha0 + d("CD_elevator") * elevator;
    // Etkin's dimensional derivatives, per unit u, w, q, ẇ (the speed's per û = u/u₀).
    let xu = -(2.0 * cd0 + d("CD_u")) * qs / u0;
    let xw = (cl0 - d("CD_alpha")) * qs / u0;
    let xq = -d("CD_q") * qs * c / (2.0 * u0);
    let zu = -(2.0 * cl0 + d("CL_u")) * qs / u0;
    let zw = -(d("CL_alpha") + cd0) * qs / u0;
    let zq = -d("CL_q") * qs * c / (2.0 * u0);
    let zwdot = -d("CL_alpha_dot") * qs * c / (2.0 * u0 * u0);
    let mu = d("Cm_u") * qs * c / u0;
    let mw = d("Cm_alpha") * qs * c / u0;
    let mq = d("Cm_q") * qs * c * c / (2.0 * u0);
    let mwdot = d("Cm_alpha_dot") * qs * c * c / (2.0 * u0 * u0);
    // (m − Z_ẇ) ẇ = Z_u u + Z_w w + (Z_q + m u₀) q, and I_y q̇ = M_u u + M_w w + M_ẇ ẇ + M_q q.
    let heave = m - zwdot;
    let (wu, ww, wq) = (zu / heave, zw / heave, (zq + m * u0) / heave);
    #[rustfmt::skip]
    let longitudinal = DMatrix::from_row_slice(4, 4, &[
        xu / m, xw / m, xq / m, -g,
        wu, ww, wq, 0.0,
        (mu + mwdot * wu) / iyy, (mw + mwdot * ww) / iyy, (mq + mwdot * wq) / iyy, 0.0,
        0.0, 0.0, 1.0, 0.0,
    ]);
    let (sin, cos) = alpha0.sin_cos();
    let per_rate = b / (2.0 * u0);
    let side = qs / (m * u0);
    let moments = |by: [f64; 3]| {
        [
            by[0] * qs * b,
            by[1] * per_rate * qs * b,
            by[2] * per_rate * qs * b,
        ]
    };
    let roll = moments([d("Cl_beta"), d("Cl_p"), d("Cl_r")]);
    let yaw = moments([d("Cn_beta"), d("Cn_p"), d("Cn_r")]);
    // [I_x J_xz; J_xz I_z] (ṗ, ṙ) = (L, N), the tensor's entries.
    let inverse = Matrix2::new(ixx, jxz, jxz, izz).try_inverse().unwrap();
    let rates: Vec<Vector2<f64>> = (0..3)
        .map(|k| inverse * Vector2::new(roll[k], yaw[k]))
        .collect();
    #[rustfmt::skip]
    let lateral = DMatrix::from_row_slice(4, 4, &[
        d("CY_beta") * side, sin + d("CY_p") * per_rate * side,
            -cos + d("CY_r") * per_rate * side, g * cos / u0,
        rates[0][0], rates[1][0], rates[2][0], 0.0,
        rates[0][1], rates[1][1], rates[2][1], 0.0,
        0.0, 1.0, alpha0.tan(), 0.0,
    ]);
    SmallPerturbation {
        longitudinal,
        lateral,
    }
}

/// eom's modes of the 747, from the proved Jacobians at its trim (with the α̇ terms of lift
/// and moment solved for α̇, and the speed derivatives), against Etkin's small-perturbation
/// model of the same table: the longitudinal block (V, α, θ, q) at constant altitude and the
/// lateral-directional block (β, φ, p, r). They are one linear model in other coordinates
/// (u = V, w = V α in the stability axes), so the eigenvalues agree to what the two
/// computations round: 1e-11 of each one's magnitude (the phugoid's is 0.07 against entries
/// near 1e3 in the dimensional derivatives).
#[test]
fn the_747s_modes_are_its_small_perturbation_model() {
    let scene = b747();
    let (longitudinal, lateral) = modes_of(&scene);
    let book = small_perturbation(&scene);
    let close = |got: &[Complex<f64>], want: &[Complex<f64>], what: &str| {
        assert_eq!(got.len(), want.len());
        for (g, w) in got.iter().zip(want) {
            let apart = (g - w).norm() / w.norm();
            println!("{what}: {g} vs {w}, {apart:.1e} of its magnitude apart");
            assert!(apart <= 1e-11, "{what}: {g} vs {w}");
        }
    };
    let want_longitudinal = sorted(eigenvalues(&book.longitudinal));
    let want_lateral = sorted(eigenvalues(&book.lateral));
    println!(
        "trim: alpha {} rad, elevator {} deg, throttle {}",
        scene.trim.state[1], scene.trim.controls[1], scene.trim.controls[0]
    );
    println!("eom longitudinal {longitudinal:?}\nmodel longitudinal {want_longitudinal:?}");
    println!("eom lateral {lateral:?}\nmodel lateral {want_lateral:?}");
    close(&longitudinal, &want_longitudinal, "longitudinal");
    close(&lateral, &want_lateral, "lateral");
}

/// What the jet's terms do: without C_Lα̇, C_Lu, C_Du, C_mu (the scene as a light aircraft's
/// table could say it) the phugoid's damping ratio falls by a third, as the issue says of
/// Etkin's condition (0.049 to 0.034 there). The measured ratio is printed; the assertion is
/// that the damping falls by more than a fifth.
#[test]
fn without_the_jet_terms_the_phugoid_is_another() {
    let text = read("scenes/b747.toml");
    let mut without = text.clone();
    for line in text.lines() {
        let jet = ["CL_alpha_dot", "CL_u", "CD_u", "Cm_u", "reference_speed"];
        if jet.iter().any(|key| line.starts_with(&format!("{key} ="))) {
            without = without.replace(&format!("{line}\n"), "");
        }
    }
    let phugoid = |scene: &AircraftScene| {
        let (longitudinal, _) = modes_of(scene);
        *longitudinal
            .iter()
            .filter(|z| z.im > 0.0)
            .min_by(|x, y| x.norm().total_cmp(&y.norm()))
            .unwrap()
    };
    let (with_terms, without_terms) = (phugoid(&b747()), phugoid(&parse(&without)));
    let ratio = |z: Complex<f64>| -z.re / z.norm();
    println!(
        "phugoid with {with_terms} (ζ {}), without {without_terms} (ζ {})",
        ratio(with_terms),
        ratio(without_terms)
    );
    assert!(ratio(without_terms) < 0.8 * ratio(with_terms));
}

/// α̇ solves its own equation: the lift's α̇ term is −q̄ S C_Lα̇ (c̄/2V) α̇ / (m V) in α̇ at
/// β = 0, so the α̇ of the scene with C_Lα̇ less the α̇ of the scene without it is that, with
/// the α̇ found. At a state where α̇ is far from zero; to 1e-12 of α̇ (the rates' rounding).
#[test]
fn the_alpha_rate_solves_the_lift_it_makes() {
    let scene = b747();
    let text = read("scenes/b747.toml");
    let line = text
        .lines()
        .find(|l| l.starts_with("CL_alpha_dot ="))
        .unwrap();
    let without = parse(&text.replace(&format!("{line}\n"), ""));
    let mut state = scene.trim.state;
    state[1] += 0.03;
    state[7] = 0.02;
    let controls = scene.trim.controls;
    let with_term = scene.model.rates(&state, &controls)[1];
    let without_term = without.model.rates(&state, &controls)[1];
    assert!(with_term.abs() > 0.01, "{with_term}");
    let air = scene.model.atmosphere().at(state[11]).unwrap();
    let v = state[0];
    let lift = 0.5 * air.density * v * v * 511.0 * -5.896 * 8.324 / (2.0 * v) * with_term;
    let expected = -lift / (2.83176e6 / 9.81 * v);
    let difference = with_term - without_term;
    assert!(
        (difference - expected).abs() < 1e-12 * with_term.abs(),
        "{difference} vs {expected}"
    );
}

/// The Jacobians (the proved ones composed with the derivatives' slopes, the speed's among
/// them, and the α̇ terms through α̇'s own row) against central differences of the rates, off
/// the trim where every term acts. Step 1e-6 of each entry's scale; the rates are smooth
/// there, so truncation (h²) and rounding (1e-16 |f| / h) stay below 1e-6 of each row's
/// largest entry.
#[test]
fn the_747s_jacobians_are_its_rates_slopes() {
    let scene = b747();
    let mut state = scene.trim.state;
    state[0] = 250.0;
    state[1] = 0.06;
    state[2] = 0.03;
    state[3] = 0.2;
    state[4] = 0.1;
    state[6] = 0.05;
    state[7] = -0.03;
    state[8] = 0.04;
    state[11] = 11000.0;
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

/// The products as the book prints them (`products_of_inertia_integrals`, ∫zx dm =
/// −0.212e7) and as the tensor's entries (`products_of_inertia`, +0.212e7) give the same
/// tensor, bit for bit, and the same linear model; typed as printed into the tensor's key,
/// the Dutch roll grows, as the issue warns.
#[test]
fn the_products_as_integrals_are_the_tensors_entries_negated() {
    let text = read("scenes/b747.toml");
    let integrals = "products_of_inertia_integrals = [0.0, 0.0, -0.212e7]";
    assert!(text.contains(integrals));
    let as_integrals = b747();
    let as_entries = parse(&text.replace(integrals, "products_of_inertia = [0.0, 0.0, 0.212e7]"));
    let bits = |scene: &AircraftScene| scene.mass_properties.1.map(|row| row.map(f64::to_bits));
    assert_eq!(bits(&as_integrals), bits(&as_entries));
    assert_eq!(as_integrals.mass_properties.1[0][2], 0.212e7);
    assert_eq!(modes_of(&as_integrals), modes_of(&as_entries));
    let dutch_roll = |scene: &AircraftScene| {
        let (_, lateral) = modes_of(scene);
        *lateral.iter().max_by(|x, y| x.im.total_cmp(&y.im)).unwrap()
    };
    let wrong = parse(&text.replace(integrals, "products_of_inertia = [0.0, 0.0, -0.212e7]"));
    let (right, wrong) = (dutch_roll(&as_integrals), dutch_roll(&wrong));
    println!("Dutch roll: {right} with the tensor's +2.12e6, {wrong} with -2.12e6");
    assert!(right.re < 0.0, "{right}");
    assert!(wrong.re > 0.0, "{wrong}");
}

/// Bad input is refused naming the key: the products given both ways, an integral that
/// breaks the aircraft's symmetry or is not finite, a speed derivative without its u₀, a u₀
/// without speed derivatives, a new term misspelt or not finite.
#[test]
fn bad_jet_scenes_name_the_key() {
    let text = read("scenes/b747.toml");
    let refused = |from: &str, to: &str, key: &str| {
        assert!(text.contains(from), "{from}");
        let error = AircraftScene::parse(&text.replacen(from, to, 1), "b747.toml")
            .err()
            .unwrap_or_else(|| panic!("{to} was accepted"))
            .to_string();
        assert!(error.contains(key), "{key} not in: {error}");
    };
    let integrals = "products_of_inertia_integrals = [0.0, 0.0, -0.212e7]";
    refused(
        integrals,
        &format!("{integrals}\nproducts_of_inertia = [0.0, 0.0, 0.212e7]"),
        "body.products_of_inertia_integrals",
    );
    refused(
        integrals,
        "products_of_inertia_integrals = [1.0, 0.0, -0.212e7]",
        "body.products_of_inertia_integrals",
    );
    refused(
        integrals,
        "products_of_inertia_integrals = [0.0, 0.0, nan]",
        "body.products_of_inertia_integrals[2]",
    );
    refused(
        "reference_speed = 235.9",
        "# no u0",
        "aerodynamics.derivatives.reference_speed",
    );
    refused(
        "reference_speed = 235.9",
        "reference_speed = -235.9",
        "aerodynamics.derivatives.reference_speed",
    );
    let no_speed_terms = ["CL_u = ", "CD_u = ", "Cm_u = "]
        .iter()
        .fold(text.clone(), |t, key| {
            t.replacen(key, &format!("# {key}"), 1)
        });
    let error = AircraftScene::parse(&no_speed_terms, "b747.toml")
        .err()
        .unwrap_or_else(|| panic!("a u0 without speed derivatives was accepted"))
        .to_string();
    assert!(
        error.contains("aerodynamics.derivatives.reference_speed"),
        "{error}"
    );
    refused(
        "CL_alpha_dot = -5.896",
        "CL_alphadot = -5.896",
        "CL_alphadot",
    );
    refused(
        "CD_elevator = 3.818e-6",
        "CD_elevator = inf",
        "aerodynamics.derivatives.CD_elevator",
    );
}

/// The lift-and-drag lines of `scenes/b747.toml`'s table replaced by Etkin's stability-axis
/// C_x, C_z as the data file prints them, in the body-axis form: every term the printed
/// number but three, each one f64 operation on printed numbers: C_X0 = −C_D0 and C_Z0 =
/// −C_w0 (the scene's CL_0), and C_Xu = C_xu + 2 C_D0 (Etkin's C_xu counts the thrust's
/// −2 C_T0, C_T0 = C_D0, which the engine's constant thrust gives).
fn b747_in_body_axes() -> String {
    let data = Published::read();
    let long = |key: &str| data.at("longitudinal_stability_axes", key);
    let cd0 = data.at("condition", "CD_0");
    let text = read("scenes/b747.toml");
    let lift_at_condition =
        toml::from_str::<toml::Table>(&text).unwrap()["aerodynamics"]["derivatives"]["CL_0"]
            .as_float()
            .unwrap();
    let body_axis = [
        ("CX_0", -cd0),
        ("CX_alpha", long("Cx_alpha")),
        ("CX_alpha_dot", long("Cx_alpha_dot")),
        ("CX_q", long("Cx_q")),
        ("CX_u", long("Cx_u") + 2.0 * cd0),
        ("CX_elevator", long("Cx_delta_e")),
        ("CZ_0", -lift_at_condition),
        ("CZ_alpha", long("Cz_alpha")),
        ("CZ_alpha_dot", long("Cz_alpha_dot")),
        ("CZ_q", long("Cz_q")),
        ("CZ_u", long("Cz_u")),
        ("CZ_elevator", long("Cz_delta_e")),
    ];
    let mut lines: Vec<String> = (text.lines())
        .filter(|line| !(line.starts_with("CL_") || line.starts_with("CD_")))
        .map(str::to_owned)
        .collect();
    let at = lines
        .iter()
        .position(|line| line == "[aerodynamics.derivatives]")
        .unwrap();
    for (k, (name, value)) in body_axis.iter().enumerate() {
        lines.insert(at + 1 + k, format!("{name} = {value:?}"));
    }
    lines.join("\n")
}

/// The longitudinal small-perturbation model of a body-axis table in the scene's body axes
/// at eom's trim, written from the equations of motion (Etkin's chapter 4 with W₀ ≠ 0, since
/// eom's trim α₀ is not the stability axes' zero): m(u̇ + W₀ q) = ΔX − m g cos θ₀ θ,
/// m(ẇ − U₀ q) = ΔZ − m g sin θ₀ θ, I_y q̇ = ΔM, θ̇ = q, the forces q̄ S C and the moment
/// q̄ S c̄ C_m, with V, α and α̇ of u and w. The α̇ terms make it E ẋ = A x; its eigenvalues
/// are E⁻¹A's.
fn body_axis_small_perturbation(scene: &AircraftScene, text: &str) -> DMatrix<f64> {
    let table: toml::Table = toml::from_str(text).unwrap();
    let d = |key: &str| {
        table["aerodynamics"]["derivatives"]
            .get(key)
            .map_or(0.0, |v| v.as_float().unwrap())
    };
    let data = Published::read();
    let (s, c) = (
        data.at("geometry", "area_m2"),
        data.at("geometry", "chord_m"),
    );
    let iyy = data.at("inertia_stability_axes_kg_m2", "Iy");
    let (g, m) = (9.81, 2.83176e6 / 9.81);
    let (v0, alpha0, theta0) = (
        scene.trim.state[0],
        scene.trim.state[1],
        scene.trim.state[4],
    );
    assert_eq!(
        v0,
        d("reference_speed"),
        "the trim is the table's condition"
    );
    let elevator = scene.trim.controls[1].to_radians();
    let rho = scene
        .model
        .atmosphere()
        .at(scene.trim.state[11])
        .unwrap()
        .density;
    let q = 0.5 * rho * v0 * v0 * s;
    let (sin, cos) = alpha0.sin_cos();
    // Each of X, Z, M: its slopes in V, α, q and α̇ at the trim (û = 0 there).
    let slopes = |c_name: &str, length: f64| {
        let at_trim = d(&format!("{c_name}_0"))
            + d(&format!("{c_name}_alpha")) * alpha0
            + d(&format!("{c_name}_elevator")) * elevator;
        let per_rate = q * length * c / (2.0 * v0);
        [
            rho * v0 * s * length * at_trim + q * length * d(&format!("{c_name}_u")) / v0,
            q * length * d(&format!("{c_name}_alpha")),
            per_rate * d(&format!("{c_name}_q")),
            per_rate * d(&format!("{c_name}_alpha_dot")),
        ]
    };
    let [x, z, pitch] = [slopes("CX", 1.0), slopes("CZ", 1.0), slopes("Cm", c)];
    // ∂/∂u and ∂/∂w through V (cos α₀, sin α₀) and α (−sin α₀/V₀, cos α₀/V₀).
    let by_u = |f: [f64; 4]| f[0] * cos - f[1] * sin / v0;
    let by_w = |f: [f64; 4]| f[0] * sin + f[1] * cos / v0;
    // α̇ = (cos α₀ ẇ − sin α₀ u̇)/V₀: its terms move to the left.
    let rate_row = |f: [f64; 4]| [f[3] * sin / v0, -f[3] * cos / v0];
    let (u0, w0) = (v0 * cos, v0 * sin);
    let [ex, ez, em] = [rate_row(x), rate_row(z), rate_row(pitch)];
    #[rustfmt::skip]
    let e = DMatrix::from_row_slice(4, 4, &[
        m + ex[0], ex[1], 0.0, 0.0,
        ez[0], m + ez[1], 0.0, 0.0,
        em[0], em[1], iyy, 0.0,
        0.0, 0.0, 0.0, 1.0,
    ]);
    #[rustfmt::skip]
    let a = DMatrix::from_row_slice(4, 4, &[
        by_u(x), by_w(x), x[2] - m * w0, -m * g * theta0.cos(),
        by_u(z), by_w(z), z[2] + m * u0, -m * g * theta0.sin(),
        by_u(pitch), by_w(pitch), pitch[2], 0.0,
        0.0, 0.0, 1.0, 0.0,
    ]);
    e.try_inverse().unwrap() * a
}

/// The 747 as Etkin prints it, in the body-axis form (`CX_…`, `CZ_…`): its longitudinal modes
/// from eom's proved Jacobians against the body-axis small-perturbation model of the same
/// table (one linear model in other coordinates, so to 1e-10 of each mode's magnitude, what
/// the two computations round with entries near 1e3 around a phugoid of 0.07; measured
/// 2.8e-14), and its
/// lateral modes against Etkin's lateral model as for the lift-and-drag scene. Against that
/// scene (the same table turned into lift and drag) the modes differ by what the forms do
/// apart at eom's trim α₀ (8.5e-4 rad: the air of the standard atmosphere at 40 000 ft is not
/// Etkin's ρ): the forms agree to first order in α about 0, so each mode within α₀ of its
/// magnitude (measured: 2.7e-4 for the phugoid, 4e-5 for the short period, 1e-7 lateral).
#[test]
fn the_747_in_body_axes_is_its_small_perturbation_model() {
    let text = b747_in_body_axes();
    let scene = parse(&text);
    let (longitudinal, lateral) = modes_of(&scene);
    let want = sorted(eigenvalues(&body_axis_small_perturbation(&scene, &text)));
    let lift_and_drag = b747();
    let (other_longitudinal, other_lateral) = modes_of(&lift_and_drag);
    println!(
        "trim in body axes: alpha {} rad; lift and drag: alpha {} rad",
        scene.trim.state[1], lift_and_drag.trim.state[1]
    );
    let close = |got: &[Complex<f64>], want: &[Complex<f64>], tolerance: f64, what: &str| {
        assert_eq!(got.len(), want.len());
        for (g, w) in got.iter().zip(want) {
            let apart = (g - w).norm() / w.norm();
            println!("{what}: {g} vs {w}, {apart:.1e} of its magnitude apart");
            assert!(apart <= tolerance, "{what}: {g} vs {w}");
        }
    };
    close(&longitudinal, &want, 1e-10, "longitudinal, model");
    let lateral_model = sorted(eigenvalues(&small_perturbation(&scene).lateral));
    close(&lateral, &lateral_model, 1e-11, "lateral, model");
    let alpha0 = scene.trim.state[1];
    assert!(alpha0 > 0.0 && alpha0 < 1e-3, "{alpha0}");
    close(
        &longitudinal,
        &other_longitudinal,
        alpha0,
        "longitudinal, lift and drag",
    );
    close(&lateral, &other_lateral, alpha0, "lateral, lift and drag");
}

/// Heffley & Jewell's C_DM (0.0275 at M₀ = 0.8, as Caughey reads it, data/README.md) in the
/// drag's speed derivative's place gives the modes of C_Du = M₀ C_DM: the scene's CD_u is
/// 0.022 written as 0.1080 − 0.086, M₀ C_DM rounds to another f64 a few ulps away, so to
/// 1e-12 of each mode's magnitude.
#[test]
fn a_mach_derivative_is_its_speed_derivative_times_the_mach_number() {
    let text = read("scenes/b747.toml");
    let line = text.lines().find(|l| l.starts_with("CD_u = ")).unwrap();
    let per_mach = text.replacen(line, "CD_M = 0.0275\nreference_mach = 0.8", 1);
    let (a, b) = (modes_of(&b747()), modes_of(&parse(&per_mach)));
    for (g, w) in a.0.iter().chain(&a.1).zip(b.0.iter().chain(&b.1)) {
        assert!((g - w).norm() <= 1e-12 * w.norm(), "{g} vs {w}");
    }
}

/// A table gives its forces one way and each speed slope once: a body-axis term beside lift
/// and drag, a Mach derivative beside its coefficient's speed derivative, a Mach derivative
/// without its M₀, an M₀ without Mach derivatives, are refused naming the key.
#[test]
fn mixed_forms_and_missing_references_name_the_key() {
    let text = read("scenes/b747.toml");
    let refused = |text: &str, key: &str| {
        let error = AircraftScene::parse(text, "b747.toml")
            .err()
            .unwrap_or_else(|| panic!("accepted, where {key} is wrong"))
            .to_string();
        assert!(error.contains(key), "{key} not in: {error}");
    };
    let with = |extra: &str| text.replacen("Cm_q = ", &format!("{extra}\nCm_q = "), 1);
    refused(
        &with("CZ_alpha = -4.92"),
        "aerodynamics.derivatives.CZ_alpha",
    );
    refused(
        &with("CL_M = 0.1\nreference_mach = 0.8"),
        "aerodynamics.derivatives.CL_M",
    );
    let moment_per_mach = with("Cm_M = -0.1").replacen("Cm_u = 0.1043", "", 1);
    refused(&moment_per_mach, "aerodynamics.derivatives.reference_mach");
    refused(
        &with("reference_mach = 0.8"),
        "aerodynamics.derivatives.reference_mach",
    );
    refused(
        &with("reference_mach = nan"),
        "aerodynamics.derivatives.reference_mach",
    );
    let body = b747_in_body_axes();
    let no_u0 = body.replace("reference_speed = 235.9", "");
    refused(&no_u0, "aerodynamics.derivatives.reference_speed");
}
