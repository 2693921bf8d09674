//! The Mariner in a wind as a user runs it: `eom run` reports what the ship moves in and what
//! the figures are over, drifts, judges no IMO criterion; `eom linear` keeps the heading.

use eom_test_support::cli::{eom, folder, run_into, succeeded};
use eom_test_support::ships::mariner_in;

/// A gusting wind from the west: summary.json says the wind, its gusts (the series' σ below
/// the spectrum's) and the windage, each turn drifts, no criterion is judged, and the text
/// says the figures are over ground.
#[test]
fn a_ship_in_a_gusting_wind_drifts_and_is_not_judged() {
    let dir = folder("wind");
    let environment =
        "wind_m_s = 20.0\nwind_from_deg = 270.0\nwind_spectrum = \"norsok\"\nwind_seed = 7";
    let path = dir.join("mariner_wind.toml");
    std::fs::write(&path, mariner_in(environment)).unwrap();
    let out = dir.join("out");
    let stdout = run_into(&path, &out, None);
    let text = std::fs::read_to_string(out.join("summary.json")).unwrap();
    let summary: serde_json::Value = serde_json::from_str(&text).unwrap();
    let environment = &summary["model"]["environment"];
    assert_eq!(environment["wind"]["speed_m_s"], 20.0, "{environment}");
    assert_eq!(environment["wind"]["from_deg"], 270.0, "{environment}");
    let gust = &environment["wind"]["gust"];
    let (sigma, whole) = (
        gust["sigma_m_s"].as_f64().unwrap(),
        gust["spectrum_sigma_m_s"].as_f64().unwrap(),
    );
    assert!(sigma > 0.9 * whole && sigma < whole, "{gust}");
    assert_eq!(environment["windage"]["coefficients"], "isherwood");
    assert!(
        environment["figures"]
            .as_str()
            .unwrap()
            .contains("over ground")
    );
    let turn = &summary["manoeuvre"]["turning_circle_35"];
    for side in ["port", "starboard"] {
        let figures = &turn["sides"][side];
        assert!(
            figures["drift_m_per_turn"].as_f64().unwrap() > 100.0,
            "{figures}"
        );
        assert!(figures["steady_turning_radius_m"].is_null(), "{figures}");
    }
    for criterion in summary["manoeuvre"]["imo"].as_array().unwrap() {
        assert_eq!(criterion["judged"], false, "{criterion}");
    }
    assert!(stdout.contains("judges trials in calm weather"), "{stdout}");
    assert!(
        stdout.contains("in a wind of 20 m/s from 270°, gusting"),
        "{stdout}"
    );
}

/// `eom linear` in a wind trims the rudder, the drift and the speed that hold the straight
/// course across it, and keeps ψ in the reduced state (the wind's loads turn with it); its
/// Nomoto report is the ship's in calm air, and says so.
#[test]
fn the_linear_model_in_a_wind_keeps_the_heading() {
    let dir = folder("wind_linear");
    let path = dir.join("mariner_wind.toml");
    std::fs::write(&path, mariner_in("wind_m_s = 20.0\nwind_from_deg = 270.0")).unwrap();
    let stdout = succeeded(&eom(&["linear", path.to_str().unwrap()]));
    assert!(stdout.contains("reduced state: u, v, r, psi"), "{stdout}");
    assert!(stdout.contains("the point is an equilibrium"), "{stdout}");
    assert!(stdout.contains("in calm air"), "{stdout}");
}
