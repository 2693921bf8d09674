//! An MMG ship on 4.46: the proved program with the propeller's and the rudder's loads
//! against the paper's equations of motion solved here by hand, its Jacobians against
//! differences, the approach held at the solved propeller rate, the KVLCC2's two scales by
//! Froude's similarity, the linear model both ways, the sides, and bad scenes refused.

#![cfg(feature = "ship")]

use eom::Model;
use eom::kinds::ship::linear::{LinearModel, linearise};
use eom::kinds::ship::manoeuvre::{Figures, run};
use eom::kinds::ship::mmg::{Controls, Edge, MidshipState};
use eom::kinds::ship::{ShipModel, ShipScene, Side};
use nalgebra::{Matrix3, Vector3};

fn scene(file: &str) -> ShipScene {
    ShipScene::load(std::path::Path::new(&format!("scenes/{file}"))).unwrap()
}

/// (u̇, v̇, ṙ) of the paper's equations of motion at midship, written here with nalgebra from
/// the MMG forces at the state: (M + m_x)u̇ − (M + m_y)vr − M x_G r² = X, (M + m_y)v̇ +
/// (M + m_x)ur + M x_G ṙ = Y, (I_zz + M x_G² + J_z)ṙ + M x_G(v̇ + ur) = N.
fn paper_accelerations(scene: &ShipScene, y: [f64; 7], n: f64) -> [f64; 3] {
    let mmg = scene.table.mmg.as_ref().unwrap();
    let p = &mmg.parameters;
    let ship = &p.particulars;
    let [u, v, r, _, _, _, delta] = y;
    let forces = p
        .forces(
            MidshipState { u, v_m: v, r },
            Controls {
                rudder_angle: delta,
                propeller_rate: n,
            },
        )
        .unwrap();
    let half = 0.5 * ship.density;
    let m_x = half * ship.length.powi(2) * ship.draft * p.added_mass.surge;
    let m_y = half * ship.length.powi(2) * ship.draft * p.added_mass.sway;
    let j_z = half * ship.length.powi(4) * ship.draft * p.added_mass.yaw;
    let body = &scene.table.body;
    let (m, x_g, i_zz) = (body.mass, body.x_g, body.yaw_inertia);
    let mass = Matrix3::new(
        m + m_x,
        0.0,
        0.0,
        0.0,
        m + m_y,
        m * x_g,
        0.0,
        m * x_g,
        i_zz + m * x_g * x_g + j_z,
    );
    let total = forces.total;
    let right = Vector3::new(
        total.x + (m + m_y) * v * r + m * x_g * r * r,
        total.y - (m + m_x) * u * r,
        total.n - m * x_g * u * r,
    );
    let solved = mass.lu().solve(&right).unwrap();
    [solved[0], solved[1], solved[2]]
}

/// The proved program with the applied loads gives the paper's accelerations, at states on
/// both sides of each branch, at both scales, to 1e-12 of each acceleration's size (the two
/// sum the same forces in other orders and solve the mass matrix by other routes).
#[test]
fn the_proved_program_is_the_papers_equations_of_motion() {
    for (file, speed) in [("kvlcc2_l7.toml", 1.179_f64), ("kvlcc2_full.toml", 7.97389)] {
        let scene = scene(file);
        let model = ShipModel::new(&scene.table).unwrap();
        let n = model.approach_rate();
        for [v, r, delta] in [
            [0.0, 0.0, 0.0],
            [-0.1, 0.01, 0.3],
            [0.12, -0.02, -0.5],
            [0.05, 0.015, 0.1],
            [-0.03, -0.01, -0.6],
        ] {
            let scale = speed / 1.179;
            let y = [
                0.9 * speed,
                v * scale,
                r / scale.sqrt(),
                0.0,
                0.0,
                0.3,
                delta,
            ];
            let rates = model.rhs(&y, &[0.0, n, 0.0]);
            let expected = paper_accelerations(&scene, y, n);
            for (k, name) in ["u̇", "v̇", "ṙ"].iter().enumerate() {
                let size = expected.iter().map(|a| a.abs()).fold(1e-9, f64::max);
                assert!(
                    (rates[k] - expected[k]).abs() <= 1e-12 * size,
                    "{file} at {y:?}: {name} {} against {}",
                    rates[k],
                    expected[k]
                );
            }
        }
    }
}

/// ∂f/∂x and ∂f/∂n of the running model (the proved Jacobian programs with the chain rule
/// through U and the applied loads' dual-number derivatives) against central differences of
/// its rates, away from the branches' edges, to 1e-6 of each row's size.
#[test]
fn the_jacobians_are_those_of_the_rates() {
    let scene = scene("kvlcc2_l7.toml");
    let model = ShipModel::new(&scene.table).unwrap();
    let n = model.approach_rate();
    for y in [
        [1.0, -0.1, 0.02, 1.0, 2.0, 0.4, 0.3],
        [0.8, 0.12, -0.04, 0.0, 0.0, -1.0, -0.5],
    ] {
        let input = [0.01, n, 0.0];
        let by_state = model.state_jacobian(&y, &input);
        let by_input = model.input_jacobian(&y, &input);
        for row in 0..7 {
            let size = (0..7).map(|j| by_state[row][j].abs()).fold(1e-6, f64::max);
            for column in 0..8 {
                let (exact, h) = match column {
                    7 => (by_input[row][1], 1e-5 * n),
                    j => (by_state[row][j], 1e-6 * y[j].abs().max(0.01)),
                };
                let shifted = |sign: f64| {
                    let (mut state, mut input) = (y, input);
                    match column {
                        7 => input[1] += sign * h,
                        j => state[j] += sign * h,
                    }
                    model.rhs(&state, &input)[row]
                };
                let central = (shifted(1.0) - shifted(-1.0)) / (2.0 * h);
                assert!(
                    (exact - central).abs() <= 1e-6 * size,
                    "∂f{row}/∂x{column} at {y:?}: {exact} against {central}"
                );
            }
        }
    }
}

/// At the solved propeller rate the approach is an equilibrium: every rate but the track's
/// is zero on the straight course at U₀ (u̇ to the rounding of the forces it balances).
#[test]
fn the_solved_rate_holds_the_approach() {
    for file in ["kvlcc2_l7.toml", "kvlcc2_full.toml"] {
        let scene = scene(file);
        let model = ShipModel::new(&scene.table).unwrap();
        let rates = model.rhs(&scene.start(), &[0.0, model.approach_rate(), 0.0]);
        let speed = scene.table.design_speed;
        assert!(rates[0].abs() <= 1e-14 * speed, "{file}: u̇ = {}", rates[0]);
        assert_eq!(rates[1..3], [0.0, 0.0], "{file}: v̇, ṙ");
        let lower = model.rhs(&scene.start(), &[0.0, 0.99 * model.approach_rate(), 0.0]);
        assert!(lower[0] < 0.0, "{file}: below n₀ the ship slows");
    }
}

/// The figures of the manoeuvre `name` run to `side` (`None` for one without sides).
fn figures(scene: &ShipScene, name: &str, side: impl Into<Option<Side>>) -> Figures {
    let model = ShipModel::new(&scene.table).unwrap();
    let manoeuvre = scene.manoeuvres.iter().find(|m| m.name == name).unwrap();
    let runs = manoeuvre.runs();
    let side = side.into();
    let (_, sided) = runs.iter().find(|(s, _)| *s == side).unwrap();
    run(
        &model,
        &scene.rudder,
        sided,
        scene.start(),
        (&scene.stepper, scene.every),
        |_| true,
    )
    .unwrap()
    .figures
}

/// The full-scale ship runs the model's coefficients at 320/7 times the size, its approach
/// at Fn = 0.142 and its rudder rate the model's scaled by Froude's law (15.68/√(320/7) =
/// 2.319°/s, SIMMAN's 2.32): each turning figure over L, and each time over √(L/g), agrees
/// with the model's to 0.5 %, what the rounded rate, the speeds' 0.02 % and the steering
/// gear's lags (not scaled alike) leave.
#[test]
fn the_two_scales_agree_by_froudes_law() {
    let (model, full) = (scene("kvlcc2_l7.toml"), scene("kvlcc2_full.toml"));
    let name = "turning_circle_35";
    let (small, large) = (
        figures(&model, name, Side::Starboard),
        figures(&full, name, Side::Starboard),
    );
    let scale = full.length / model.length;
    for (key, power) in [
        ("advance_90_m", 1.0),
        ("transfer_90_m", 1.0),
        ("tactical_diameter_m", 1.0),
        ("t_90_s", 0.5),
        ("t_180_s", 0.5),
    ] {
        let (a, b) = (small.get(key).unwrap(), large.get(key).unwrap());
        let ratio = b / (a * scale.powf(power));
        assert!(
            (ratio - 1.0).abs() < 5e-3,
            "{key}: {a} and {b}, ratio {ratio}"
        );
    }
}

/// The paper's sides differ (γ_R⁻ = 0.395 for inflow from port, γ_R⁺ = 0.64; C₂⁻, C₂⁺): the
/// turns to port and starboard are not mirror images, and δ > 0 turns to starboard.
#[test]
fn the_turns_to_the_two_sides_differ_as_the_coefficients_do() {
    let scene = scene("kvlcc2_l7.toml");
    let port = figures(&scene, "turning_circle_35", Side::Port);
    let starboard = figures(&scene, "turning_circle_35", Side::Starboard);
    assert_eq!(
        (port.side, starboard.side),
        (Some("port"), Some("starboard"))
    );
    let (p, s) = (
        port.get("tactical_diameter_m").unwrap(),
        starboard.get("tactical_diameter_m").unwrap(),
    );
    assert!((p - s).abs() > 1e-3 * s, "port {p}, starboard {s}");
    let linear = LinearModel::closed_form(&scene.table);
    let (_, b) = linear.state_space();
    assert!(b[1] > 0.0, "δ > 0 gives ṙ > 0: a turn to starboard");
}

/// The linear model by its closed form (the hull's linear derivatives and the rudder's
/// dual-number derivatives) and from the running model's Jacobian agree to rounding.
#[test]
fn the_linear_model_is_the_same_both_ways() {
    let scene = scene("kvlcc2_l7.toml");
    let model = ShipModel::new(&scene.table).unwrap();
    let closed = LinearModel::closed_form(&scene.table).state_space();
    let running = linearise(&model, scene.table.design_speed);
    for (a, b) in (closed.0.iter().flatten().chain(&closed.1))
        .zip(running.0.iter().flatten().chain(&running.1))
    {
        assert!(
            (a - b).abs() <= 1e-12 * a.abs().max(1e-9),
            "{a} against {b}"
        );
    }
}

/// What an MMG scene must not say, each refused with the key named.
#[test]
fn bad_mmg_scenes_are_refused_naming_the_key() {
    let text = std::fs::read_to_string("scenes/kvlcc2_l7.toml").unwrap();
    for (change, key) in [
        (
            ("k_2 = -0.1385", "k2 = -0.1385"),
            "hydrodynamics.coefficients.k2",
        ),
        (("k_2 = -0.1385\n", ""), "hydrodynamics.coefficients.k_2"),
        (
            ("D_P = 0.216", "D_P = -0.216"),
            "hydrodynamics.particulars.D_P",
        ),
        (("D_P = 0.216", "L = 7.0"), "hydrodynamics.particulars.L"),
        (
            ("model = \"mmg\"", "model = \"mmg\"\nunits = \"prime\""),
            "hydrodynamics.units",
        ),
        (
            ("model = \"mmg\"", "model = \"MMG\""),
            "hydrodynamics.model",
        ),
        (
            ("design_speed = 1.179", "design_speed = 0.0"),
            "hydrodynamics.design_speed",
        ),
        (
            ("density = 1025.0", "density = nan"),
            "hydrodynamics.density",
        ),
        (
            ("m_y_p = 0.223", "m_y_p = -2.0"),
            "hydrodynamics.coefficients",
        ),
        (
            (
                "duration_s = 300.0",
                "duration_s = 300.0\n[[manoeuvre]]\nkind = \"crash_stop\"\nastern_rps = -5.0\n\
                 duration_s = 300.0",
            ),
            "an MMG ship's propeller turns ahead only",
        ),
    ] {
        let (from, to) = change;
        assert!(text.contains(from), "{from}");
        let changed = text.replacen(from, to, 1);
        let error = ShipScene::parse(&changed, "kvlcc2.toml")
            .unwrap_err()
            .to_string();
        assert!(error.contains(key), "{from} → {to}: {error}");
    }
}

/// On the straight course the rudder's and the wake's derivatives by v and r have two
/// one-sided values (γ_R⁺ or γ_R⁻, C₂⁺ or C₂⁻, the slope of |β_P|): the dual numbers taken
/// toward each side are the one-sided differences toward it (v < 0 and r > 0 make β_P, β_R
/// positive; v > 0 and r < 0 negative), to 1e-6 of the derivative's size (the differences'
/// own truncation at h = 1e-7 of U₀).
#[test]
fn the_one_sided_derivatives_are_those_toward_each_side() {
    let scene = scene("kvlcc2_l7.toml");
    let mmg = scene.table.mmg.as_ref().unwrap();
    let u0 = scene.table.design_speed;
    let at = [u0, 0.0, 0.0, 0.0, mmg.approach_rate];
    let base = mmg.loads(at).unwrap();
    for (edge, sign) in [(Edge::TowardPositive, 1.0), (Edge::TowardNegative, -1.0)] {
        let exact = mmg.loads_with_derivatives_toward(at, edge).unwrap().by;
        // β grows as v falls and as r grows (x′_P, l′_R < 0).
        for (variable, toward) in [(1, -sign), (2, sign)] {
            let h = 1e-7 * u0 * toward;
            let mut shifted = at;
            shifted[variable] += h;
            let moved = mmg.loads(shifted).unwrap();
            for load in 0..3 {
                let difference = (moved[load] - base[load]) / h;
                let size = exact[load][variable].abs().max(1e-9);
                assert!(
                    (exact[load][variable] - difference).abs() <= 1e-6 * size,
                    "{edge:?}, load {load}, variable {variable}: {} against {difference}",
                    exact[load][variable]
                );
            }
        }
    }
    let (positive, negative) = (
        mmg.loads_with_derivatives_toward(at, Edge::TowardPositive)
            .unwrap()
            .by,
        mmg.loads_with_derivatives_toward(at, Edge::TowardNegative)
            .unwrap()
            .by,
    );
    assert!((positive[1][1] - negative[1][1]).abs() > 0.1 * positive[1][1].abs());
}

/// The KVLCC2's straight course is stable toward starboard (γ_R⁺ = 0.64) and unstable toward
/// port (γ_R⁻ = 0.395): the summary's verdict is that it is not stable, and the direct spiral
/// finds the loop, on the side of small rudder angles, that the steady turns' folds bound.
#[test]
fn the_kvlcc2_is_course_stable_toward_starboard_only_and_its_spiral_loops() {
    let scene = scene("kvlcc2_l7.toml");
    let mmg = scene.table.mmg.as_ref().unwrap();
    let starboard = LinearModel::mmg(&scene.table, mmg, Edge::TowardPositive);
    let port = LinearModel::mmg(&scene.table, mmg, Edge::TowardNegative);
    assert!(starboard.course_stable(), "toward starboard");
    assert!(!port.course_stable(), "toward port");
    assert_eq!((starboard.mass, starboard.rudder), (port.mass, port.rudder));
    let spiral = figures(&scene, "spiral", None);
    let loop_width = spiral.get("steady_loop_width_deg").unwrap();
    assert!(loop_width > 0.1 && loop_width < 1.0, "{loop_width}");
    assert!(spiral.get("loop_width_deg").unwrap() > 0.0);
}

/// A polynomial table refuses the MMG table's keys, naming each.
#[test]
fn a_polynomial_table_refuses_the_mmg_keys() {
    let text = std::fs::read_to_string("scenes/mariner.toml").unwrap();
    for (added, key) in [
        (
            "propeller_rate_rps = 1.0",
            "hydrodynamics.propeller_rate_rps",
        ),
        ("particulars = { B = 1.0 }", "hydrodynamics.particulars"),
    ] {
        let changed = text.replacen(
            "[hydrodynamics]\n",
            &format!("[hydrodynamics]\n{added}\n"),
            1,
        );
        assert_ne!(changed, text);
        let error = ShipScene::parse(&changed, "mariner.toml")
            .unwrap_err()
            .to_string();
        assert!(error.contains(key) && error.contains("MMG"), "{error}");
    }
}
