//! A ship in a wind: the wind's loads in the running model (its Jacobians by the state, ψ
//! and the gust against differences of its rates), the air that moves with the water (a wind
//! equal to the current leaves the turn through the water as in still air), the Mariner's
//! turning circle drifting in a 20 m/s wind, gusts drawn by a seed, and bad scenes refused.

#![cfg(feature = "ship")]

use eom::Model;
use eom::kinds::ship::manoeuvre::{Sample, run};
use eom::kinds::ship::{ShipModel, ShipScene, Side};
use eom_test_support::differences::central_jacobians;
use eom_test_support::ships::{MARINER_WINDAGE, mariner_in};

/// `text` with the runs' tolerances 1e-10 for its 1e-6.
fn tight(text: String) -> String {
    text.replace("rtol = 1e-6\natol = 1e-6", "rtol = 1e-10\natol = 1e-10")
}

fn parse(text: &str) -> Result<ShipScene, String> {
    ShipScene::parse(text, "mariner_wind.toml").map_err(|e| e.to_string())
}

/// The rows and figures of the 35° turning circle to `side`.
fn turn(scene: &ShipScene, side: Side) -> (Vec<Sample>, eom::kinds::ship::manoeuvre::Figures) {
    let model = ShipModel::new(&scene.table).unwrap();
    let manoeuvre = (scene.manoeuvres.iter())
        .find(|m| m.name == "turning_circle_35")
        .unwrap();
    let runs = manoeuvre.runs();
    let (_, sided) = runs.iter().find(|(s, _)| *s == Some(side)).unwrap();
    let mut rows = Vec::new();
    let settings = (&scene.stepper, scene.every);
    let ran = run(
        &model,
        &scene.rudder,
        sided,
        scene.start(),
        settings,
        |sample| {
            rows.push(*sample);
            true
        },
    )
    .unwrap();
    (rows, ran.figures)
}

/// ∂f/∂x and ∂f/∂(δ̇, n, g) of `model` against central differences of its rates at
/// `states`, to 1e-6 of each row's size (the differences' own error at these steps is below
/// 1e-9 of it; the states' relative wind angles avoid the table's breakpoints, where the
/// slope changes), each non-zero entry declared, and u̇, v̇, ṙ depending on ψ.
fn assert_jacobians_are_differences(model: &ShipModel, states: &[[f64; 7]], input: [f64; 3]) {
    for y in states {
        let by_state = model.state_jacobian(y, &input);
        let by_input = model.input_jacobian(y, &input);
        let rates = |x: &[f64; 7], u: &[f64; 3]| model.rhs(x, u);
        let step = |v: f64| 1e-6 * v.abs().max(0.01);
        let (numeric_state, numeric_input) = central_jacobians(rates, (y, &input), step);
        for row in 0..7 {
            let size =
                (by_state[row].iter().chain(&by_input[row])).fold(1e-9f64, |m, d| m.max(d.abs()));
            let exact = by_state[row].iter().chain(&by_input[row]);
            let numeric = numeric_state[row].iter().chain(&numeric_input[row]);
            for (column, (exact, central)) in exact.zip(numeric).enumerate() {
                assert!(
                    (exact - central).abs() <= 1e-6 * size,
                    "∂f{row}/∂x{column} at {y:?}: {exact} against {central}"
                );
                let declared = match column {
                    7.. => {
                        <ShipModel as Model<f64, 7, 3>>::INPUT_JACOBIAN.contains(&(row, column - 7))
                    }
                    j => <ShipModel as Model<f64, 7, 3>>::STATE_JACOBIAN.contains(&(row, j)),
                };
                assert!(declared || *exact == 0.0, "({row}, {column}) undeclared");
            }
        }
        // The wind's loads turn with the heading: u̇, v̇, ṙ depend on ψ.
        assert!((0..3).all(|row| by_state[row][5] != 0.0), "{by_state:?}");
    }
}

/// The Mariner (a prime polynomial table) in a gusting wind across a current, at states all
/// round the compass.
#[test]
fn the_jacobians_in_a_wind_are_those_of_the_rates() {
    let scene = parse(&mariner_in(
        "wind_m_s = 20.0\nwind_from_deg = 250.0\ncurrent_m_s = 0.7\ncurrent_toward_deg = 30.0",
    ))
    .unwrap();
    let model = ShipModel::new(&scene.table).unwrap();
    let states = [
        [7.0, 0.3, 0.004, 10.0, -4.0, 0.41, 0.2],
        [6.0, -0.5, -0.01, 0.0, 0.0, 2.33, -0.3],
        [7.5, 0.1, 0.002, 0.0, 0.0, -1.97, 0.05],
        [5.5, 0.8, 0.012, 0.0, 0.0, 4.1, 0.6],
    ];
    assert_jacobians_are_differences(&model, &states, [0.01, 0.0, 1.3]);
}

/// An MMG ship (the KVLCC2 at 7 m) in a wind with a table of its own: the wind's loads add to
/// the propeller's and the rudder's, and so do their derivatives, n's column among them.
#[test]
fn an_mmg_ship_takes_the_wind_as_its_propeller_and_rudder() {
    let text = std::fs::read_to_string("scenes/kvlcc2_l7.toml").unwrap();
    // Its spiral (the file's last manoeuvre) is refused in a wind.
    let text = &text[..text.find("# Dieudonné's direct spiral").unwrap()];
    let start = text.find("[[manoeuvre]]").unwrap();
    let windy = format!(
        "{}[environment]\nwind_m_s = 3.0\nwind_from_deg = 120.0\n\n[windage]\n\
         length_overall_m = 7.3\nfrontal_area_m2 = 0.35\nlateral_area_m2 = 1.2\n\
         angles_deg = [0.0, 45.0, 90.0, 135.0, 180.0]\nC_X = [-0.8, -0.5, 0.0, 0.4, 0.6]\n\
         C_Y = [0.0, 0.6, 0.85, 0.55, 0.0]\nC_N = [0.0, 0.09, 0.02, -0.06, 0.0]\n\n{}",
        &text[..start],
        &text[start..]
    );
    let scene = ShipScene::parse(&windy, "kvlcc2_wind.toml").unwrap();
    let model = ShipModel::new(&scene.table).unwrap();
    assert!(model.mmg().is_some() && model.wind().is_some());
    let n = model.approach_rate();
    let states = [
        [1.0, -0.1, 0.02, 1.0, 2.0, 0.4, 0.3],
        [0.8, 0.12, -0.04, 0.0, 0.0, -1.0, -0.5],
    ];
    assert_jacobians_are_differences(&model, &states, [0.01, n, 0.4]);
}

/// Air that moves with the water: in a 0.5 m/s current toward the east and a 0.5 m/s wind
/// from the west, the air is still relative to the water, so through the water the turn is
/// the turn in still air and still water, and over ground that turn carried east at 0.5 m/s.
/// The two runs' steps differ (the track enters the step control), so they agree to their
/// tolerance's order, which shrinks with it (at 1e-6, 1e-8, 1e-10: u to 7e-6, 7e-8, 7e-10
/// m/s): run at rtol = atol = 1e-10 the largest differences are 7e-10 m/s in u and v, 2.5e-11
/// rad/s in r, 2.4e-10 rad in ψ and 8e-7 m over ground, and the bounds are ten times those.
#[test]
fn air_moving_with_the_water_is_still_air_to_the_ship() {
    let (still, moving) = (
        parse(&tight(mariner_in(""))).unwrap(),
        parse(&tight(mariner_in(
            "current_m_s = 0.5\ncurrent_toward_deg = 90.0\nwind_m_s = 0.5\nwind_from_deg = 270.0",
        )))
        .unwrap(),
    );
    for side in Side::BOTH {
        let ((a, _), (b, _)) = (turn(&still, side), turn(&moving, side));
        // The drifting run adds its turns' events; the rows every second are both runs'.
        let by_time: std::collections::HashMap<u64, &Sample> =
            b.iter().map(|q| (q.t.to_bits(), q)).collect();
        let pairs: Vec<(&Sample, &Sample)> = (a.iter())
            .filter_map(|p| by_time.get(&p.t.to_bits()).map(|q| (p, *q)))
            .collect();
        assert!(
            pairs.len() > 1500,
            "{side:?}: {} rows in common",
            pairs.len()
        );
        let bounds = [1e-8, 1e-8, 1e-9, 0.0, 0.0, 1e-8];
        for (p, q) in pairs {
            for k in [0, 1, 2, 5] {
                let error = (p.state[k] - q.state[k]).abs();
                assert!(
                    error <= bounds[k],
                    "{side:?} t = {} entry {k}: {error}",
                    p.t
                );
            }
            let carried = [p.state[3], p.state[4] + 0.5 * p.t];
            let offset = (carried[0] - q.state[3]).hypot(carried[1] - q.state[4]);
            assert!(offset < 1e-5, "{side:?} t = {}: {offset} m", p.t);
        }
    }
}

/// The Mariner's 35° turning circle in a 20 m/s wind from the west: the turn drifts (a
/// distance per turn, toward a direction, in a period, all given), it is not steady (the
/// steady radius is not given, and a note says why), each side's drift mirrors the other's
/// across the wind's axis (to 1°: the Mariner's table is not exactly symmetric). (No IMO
/// criterion is judged: `app/tests/cli_ship_wind.rs`.)
#[test]
fn the_mariner_drifts_in_a_wind_and_is_not_judged() {
    let scene = parse(&mariner_in("wind_m_s = 20.0\nwind_from_deg = 270.0")).unwrap();
    let mut toward = Vec::new();
    for side in Side::BOTH {
        let (_, figures) = turn(&scene, side);
        let drift = figures.get("drift_m_per_turn").unwrap();
        let period = figures.get("turn_period_s").unwrap();
        assert!(
            drift > 100.0 && period > 600.0,
            "{side:?}: {drift} m in {period} s"
        );
        assert_eq!(figures.get("steady_turning_radius_m"), None, "{side:?}");
        assert!(
            figures.notes.iter().any(|n| n.contains("not settled")),
            "{side:?}: {:?}",
            figures.notes
        );
        toward.push(figures.get("drift_toward_deg").unwrap());
    }
    // Mirrored across the east-west axis, θ ↦ 180° − θ.
    let mirrored = (180.0 - toward[1]).rem_euclid(360.0);
    assert!((toward[0] - mirrored).abs() < 1.0, "{toward:?}");
}

/// A seed draws one gust series: two runs with it give the same bits, another seed other
/// figures; the gusts change the turn from the steady wind's.
#[test]
fn a_seed_gives_one_gusting_run() {
    let gusting = |seed: u64| {
        let text = mariner_in(&format!(
            "wind_m_s = 20.0\nwind_from_deg = 270.0\nwind_spectrum = \"norsok\"\nwind_seed = {seed}"
        ));
        let (_, figures) = turn(&parse(&text).unwrap(), Side::Port);
        figures.get("tactical_diameter_m").unwrap()
    };
    let steady = {
        let text = mariner_in("wind_m_s = 20.0\nwind_from_deg = 270.0");
        let (_, figures) = turn(&parse(&text).unwrap(), Side::Port);
        figures.get("tactical_diameter_m").unwrap()
    };
    let (a, b, c) = (gusting(7), gusting(7), gusting(8));
    assert_eq!(a.to_bits(), b.to_bits());
    assert_ne!(a, c);
    assert_ne!(a, steady);
}

/// Bad winds and windages are refused, naming the key.
#[test]
fn bad_winds_are_refused_naming_the_key() {
    let windage_removed = |text: String| text.replace(MARINER_WINDAGE, "");
    let cases: Vec<(String, &str)> = vec![
        (
            windage_removed(mariner_in("wind_m_s = 20.0\nwind_from_deg = 270.0")),
            "environment.wind_m_s",
        ),
        (mariner_in("wind_m_s = 20.0"), "environment.wind_from_deg"),
        (
            mariner_in("wind_m_s = -2.0\nwind_from_deg = 0.0"),
            "environment.wind_m_s",
        ),
        (
            mariner_in("wind_m_s = 20.0\nwind_from_deg = 0.0\nwind_spectrum = \"norsok\""),
            "environment.wind_seed",
        ),
        (
            mariner_in("wind_m_s = 20.0\nwind_from_deg = 0.0\nwind_seed = 3"),
            "environment.wind_seed",
        ),
        (
            mariner_in(
                "wind_m_s = 20.0\nwind_from_deg = 0.0\nwind_spectrum = \"harris\"\nwind_seed = 3",
            ),
            "environment.wind_spectrum",
        ),
        (
            mariner_in("wind_m_s = 20.0\nwind_from_deg = nan"),
            "environment.wind_from_deg",
        ),
        (mariner_in("").replace("masts = 4\n", ""), "windage.masts"),
        (
            mariner_in("").replace("masts = 4", "masts = 2.5"),
            "windage.masts",
        ),
        (
            mariner_in("").replace("beam_m = 23.17", "beam_m = 0.0"),
            "windage.beam_m",
        ),
        (
            mariner_in("").replace("masts = 4", "masts = 4\nC_X = [0.0]"),
            "windage.C_X",
        ),
        (
            mariner_in("").replace(
                "coefficients = \"isherwood\"",
                "coefficients = \"fujiwara\"",
            ),
            "windage.coefficients",
        ),
        (
            mariner_in("").replace("coefficients = \"isherwood\"\n", ""),
            "windage.beam_m",
        ),
        (
            mariner_in("").replace("lateral_area_m2 = 1450.0", "lateral_area_m2 = -1.0"),
            "windage.lateral_area_m2",
        ),
    ];
    for (text, key) in cases {
        let error = parse(&text).unwrap_err();
        assert!(error.contains(key), "{key}: {error}");
    }
    // A table of one's own: the side force at the bow must be zero.
    let own = mariner_in("").replace(
        MARINER_WINDAGE,
        "[windage]\nlength_overall_m = 171.8\nfrontal_area_m2 = 320.0\nlateral_area_m2 = 1450.0\n\
         angles_deg = [0.0, 90.0, 180.0]\nC_X = [-0.6, 0.0, 0.5]\nC_Y = [0.1, 0.8, 0.0]\n\
         C_N = [0.0, 0.05, 0.0]\n",
    );
    let error = parse(&own).unwrap_err();
    assert!(error.contains("windage.C_Y"), "{error}");
    assert!(parse(&own.replace("C_Y = [0.1,", "C_Y = [0.0,")).is_ok());
    // A spiral's steady turns do not exist in a wind.
    let text = std::fs::read_to_string("scenes/mariner.toml").unwrap();
    let spiral = text.replacen(
        "[integrator]",
        &format!(
            "[environment]\nwind_m_s = 5.0\nwind_from_deg = 0.0\n\n{MARINER_WINDAGE}\n[integrator]"
        ),
        1,
    );
    let error = parse(&spiral).unwrap_err();
    assert!(error.contains("manoeuvre[3].kind"), "{error}");
    // Nor where still air moves over the water, a current under a windage; a current alone,
    // or a windage in still air over still water, keeps its steady turns.
    let with = |environment: &str, windage: &str| {
        let tables = format!("[environment]\n{environment}\n\n{windage}\n[integrator]");
        parse(&text.replacen("[integrator]", &tables, 1))
    };
    let current = "current_m_s = 0.5\ncurrent_toward_deg = 90.0";
    let error = with(current, MARINER_WINDAGE).unwrap_err();
    assert!(error.contains("manoeuvre[3].kind"), "{error}");
    assert!(with(current, "").is_ok());
    assert!(with("", MARINER_WINDAGE).is_ok());
}
