//! eom's MMG forces (`eom::kinds::ship::mmg`) against the checkpoint table an independent
//! script works from the paper's equations (`peer/mmg/checkpoint.py`, standard-library Python,
//! sharing no code with eom): the KVLCC2 of `data/kvlcc2_mmg.json` at six states, every
//! intermediate quantity from U and β to the totals about midship.
//!
//! Each quantity must agree to 1e-12 relative. A quantity near zero is held instead to 1e-12 of
//! the largest magnitude among the state's quantities of the same unit: a value near zero
//! there comes from terms of that size cancelling (X = X_H + X_P + X_R, β_R = β − l′_R r′,
//! K_T = k₀ + k₁J + k₂J²), and both sides' rounding is of the size of those terms, not of
//! what is left. Exact zeros (the straight course's Y_H, v_R, F_N …) must be zero on both sides.

#![cfg(feature = "ship")]

use eom::kinds::ship::mmg::{Controls, MidshipState, MmgParameters, QUANTITIES};
use serde_json::Value;

const TABLE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/data/kvlcc2_mmg.json");
const CHECKPOINTS: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/peer/mmg/checkpoints.json");
const TOLERANCE: f64 = 1e-12;

fn read_json(path: &str) -> Value {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{path}: {e}"));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("{path}: {e}"))
}

fn number(object: &Value, key: &str) -> f64 {
    object[key]
        .as_f64()
        .unwrap_or_else(|| panic!("`{key}` is not a number in {object}"))
}

/// One quantity's disagreement: |eom − peer| over what it is held to (≤ 1 passes), and the
/// plain relative difference, for the report.
struct Difference {
    state: String,
    quantity: &'static str,
    eom: f64,
    peer: f64,
    scale: f64,
}

impl Difference {
    fn ratio(&self) -> f64 {
        let bound = TOLERANCE * self.eom.abs().max(self.peer.abs()).max(self.scale);
        if bound == 0.0 {
            if self.eom == self.peer {
                0.0
            } else {
                f64::INFINITY
            }
        } else {
            (self.eom - self.peer).abs() / bound
        }
    }

    /// Within the tolerance (a NaN on either side is not).
    fn passes(&self) -> bool {
        self.ratio() <= 1.0
    }

    fn relative(&self) -> f64 {
        let size = self.eom.abs().max(self.peer.abs());
        if size == 0.0 {
            0.0
        } else {
            (self.eom - self.peer).abs() / size
        }
    }
}

/// Every quantity of every checkpoint state, eom's beside the peer's.
fn differences() -> Vec<Difference> {
    let table = read_json(TABLE);
    let checkpoints = read_json(CHECKPOINTS);
    let units = &checkpoints["units"];
    let mut found = Vec::new();
    for state in checkpoints["states"].as_array().expect("states") {
        let name = state["name"].as_str().expect("a state's name");
        let scale = state["scale"].as_str().expect("a state's scale");
        let model = MmgParameters::from_json(&table, scale, number(state, "density"))
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        let midship = MidshipState {
            u: number(state, "u"),
            v_m: number(state, "v_m"),
            r: number(state, "r"),
        };
        let controls = Controls {
            rudder_angle: number(state, "delta"),
            propeller_rate: number(state, "n_P"),
        };
        let forces = model
            .forces(midship, controls)
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        let peer = &state["values"];
        let largest_of_unit = |unit: &Value| {
            (QUANTITIES.iter())
                .filter(|q| &units[**q] == unit)
                .map(|q| number(peer, q).abs())
                .fold(0.0, f64::max)
        };
        for (quantity, eom) in forces.quantities() {
            found.push(Difference {
                state: name.to_owned(),
                quantity,
                eom,
                peer: number(peer, quantity),
                scale: largest_of_unit(&units[quantity]),
            });
        }
    }
    found
}

#[test]
fn every_quantity_of_every_checkpoint_agrees_with_the_independent_peer() {
    let found = differences();
    assert_eq!(
        found.len(),
        6 * QUANTITIES.len(),
        "six states, every quantity"
    );
    let failures: Vec<String> = (found.iter())
        .filter(|d| !d.passes())
        .map(|d| {
            format!(
                "{} {}: eom {:e}, peer {:e}, relative difference {:e}",
                d.state,
                d.quantity,
                d.eom,
                d.peer,
                d.relative()
            )
        })
        .collect();
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    let worst = (found.iter())
        .max_by(|a, b| a.relative().total_cmp(&b.relative()))
        .expect("quantities");
    eprintln!(
        "{} quantities agree; the largest relative difference is {:e} ({} {})",
        found.len(),
        worst.relative(),
        worst.state,
        worst.quantity
    );
}

#[test]
fn the_checkpoints_name_exactly_the_quantities_eom_gives() {
    let checkpoints = read_json(CHECKPOINTS);
    let mut named: Vec<&str> = (checkpoints["units"].as_object().expect("units").keys())
        .map(String::as_str)
        .collect();
    let mut given = QUANTITIES.to_vec();
    named.sort_unstable();
    given.sort_unstable();
    assert_eq!(named, given);
    for state in checkpoints["states"].as_array().expect("states") {
        let values = state["values"].as_object().expect("values");
        assert_eq!(values.len(), QUANTITIES.len(), "{}", state["name"]);
    }
}

#[test]
fn the_checkpoints_cover_both_sides_and_both_signs_of_beta_r() {
    let checkpoints = read_json(CHECKPOINTS);
    let states = checkpoints["states"].as_array().expect("states");
    let has = |test: &dyn Fn(&Value) -> bool| states.iter().any(test);
    let value = |s: &Value, q: &str| number(&s["values"], q);
    assert!(has(&|s| number(s, "delta") > 0.5 && number(s, "r") > 0.0));
    assert!(has(&|s| number(s, "delta") < -0.5 && number(s, "r") < 0.0));
    assert!(has(&|s| number(s, "r") > 0.0 && value(s, "beta_R") < 0.0));
    assert!(has(&|s| number(s, "r") == 0.0 && number(s, "v_m") != 0.0));
    assert!(has(&|s| s["scale"] == "full"));
}
