//! Emits the two models this crate needs: an AUV, symmetric about its xz-plane, carried by a
//! unit quaternion so it may pitch through ±90°; a ship of this crate's own hydrodynamic
//! table (4.46 with ten terms); and the Mariner's 39-term table in the prime system (the terms
//! `eom` reads from `scenes/mariner.toml`, its rigid-body terms taken out); and REMUS 100 in six
//! degrees of freedom on the table `scenes/remus100.toml` names, each proved before it is
//! written.

use eom_codegen::emit::program::identifier;
use eom_codegen::emit::{EmitError, emit_into, system_source, write_if_changed};
use eom_codegen::model::System;
use eom_codegen::model::ship::{Force, ShipForm, ShipSpec, Term, Units, YawInertia, ship};
use eom_codegen::model::vehicle::{
    AddedMassCoriolis, Convention, InertiaAbout, Propeller, VehicleSpec, vehicle,
};
use eom_codegen::model::{Kinematics, Model, Symmetry};
use std::path::{Path, PathBuf};

/// The ship's table: the terms, and only those, that the generated code computes.
fn ship_spec() -> ShipSpec {
    let term = |force, [a, b, c, d]: [u8; 4]| Term {
        force,
        powers: [a, b, c, d, 0],
    };
    ShipSpec {
        units: Units::Dimensional,
        yaw_inertia: YawInertia::AboutG,
        terms: vec![
            term(Force::X, [1, 0, 0, 0]),
            term(Force::X, [0, 2, 0, 0]),
            term(Force::Y, [0, 1, 0, 0]),
            term(Force::Y, [0, 0, 1, 0]),
            term(Force::Y, [0, 3, 0, 0]),
            term(Force::Y, [0, 0, 0, 1]),
            term(Force::N, [0, 1, 0, 0]),
            term(Force::N, [0, 0, 1, 0]),
            term(Force::N, [0, 2, 1, 0]),
            term(Force::N, [0, 0, 0, 1]),
        ],
        propulsion: false,
        form: ShipForm::Polynomial,
        current: false,
        applied: false,
    }
}

/// The Mariner's terms as `eom` reads `scenes/mariner.toml` (`ShipTable::terms`): the bench
/// checks this model against `eom`'s of the scene bit for bit, so a change of either shows.
fn mariner_spec() -> ShipSpec {
    let term = |force, [a, b, c, d]: [u8; 4]| Term {
        force,
        powers: [a, b, c, d, 0],
    };
    let (x, y, n) = (Force::X, Force::Y, Force::N);
    #[rustfmt::skip]
    let x_terms = [[0, 0, 0, 2], [0, 0, 2, 0], [0, 1, 0, 1], [0, 2, 0, 0], [1, 0, 0, 0],
        [1, 0, 0, 2], [1, 1, 0, 1], [2, 0, 0, 0], [3, 0, 0, 0]];
    #[rustfmt::skip]
    let side_terms = [[0, 0, 0, 0], [0, 0, 0, 1], [0, 0, 0, 3], [0, 0, 1, 0], [0, 1, 0, 0],
        [0, 1, 0, 2], [0, 2, 0, 1], [0, 2, 1, 0], [0, 3, 0, 0], [1, 0, 0, 0], [1, 0, 0, 1],
        [1, 0, 1, 0], [1, 1, 0, 0], [2, 0, 0, 0], [2, 0, 0, 1]];
    let terms = (x_terms.iter().map(|&p| term(x, p)))
        .chain(side_terms.iter().map(|&p| term(y, p)))
        .chain(side_terms.iter().map(|&p| term(n, p)))
        .collect();
    ShipSpec {
        units: Units::Prime,
        yaw_inertia: YawInertia::AboutMidship,
        terms,
        propulsion: false,
        form: ShipForm::Polynomial,
        current: false,
        applied: false,
    }
}

/// REMUS 100 as `eom` builds a vehicle scene's model (`eom::kinds::vehicle::model::spec`): the
/// added-mass entries and the terms `scenes/remus100.toml` names, read as Prestero writes
/// them, in SI; quaternions; the principal moments of inertia about the point the scene's
/// `body.inertia_about` names (G by default; Prestero's are about O); the fins `dr` and `ds`;
/// the table's cross terms holding Kirchhoff's terms; the propeller's thrust and torque
/// constant. The test `three_forms` holds this model to `eom`'s of the scene, bit for bit.
fn remus_spec(scene: &Path) -> Result<VehicleSpec, String> {
    let text = std::fs::read_to_string(scene).map_err(|e| format!("{}: {e}", scene.display()))?;
    let scene: toml::Table = text
        .parse()
        .map_err(|e| format!("{}: {e}", scene.display()))?;
    let names = |table: &str| -> Result<Vec<String>, String> {
        let table = (scene.get("hydrodynamics").and_then(|h| h.get(table)))
            .and_then(toml::Value::as_table)
            .ok_or(format!("no [hydrodynamics.{table}]"))?;
        // Sorted, as eom's table keeps them.
        Ok(table.keys().cloned().collect())
    };
    let about = scene.get("body").and_then(|body| body.get("inertia_about"));
    let inertia = match about.map(|a| a.as_str()) {
        None | Some(Some("G")) => InertiaAbout::Gravity,
        Some(Some("origin")) => InertiaAbout::Origin,
        Some(other) => return Err(format!("body.inertia_about: {other:?} is not G or origin")),
    };
    Ok(VehicleSpec {
        units: Units::Dimensional,
        kinematics: Kinematics::Quaternion,
        inertia,
        symmetry: Symmetry::Principal,
        convention: Convention::Prestero,
        controls: vec!["dr".into(), "ds".into()],
        added_mass: names("added_mass")?,
        added_mass_coriolis: AddedMassCoriolis::Folded,
        terms: names("coefficients")?,
        propeller: Propeller::Constant,
        hydrostatics: true,
        applied_loads: false,
    })
}

/// The source of `system`, with `Parameters::from_symbols`: the parameters by the symbols of
/// the system (`M`, `Y_vvr`, `rho`, …), as a table keyed by symbol gives them.
fn source_with_symbols(system: &System) -> Result<String, EmitError> {
    let fields: String = (system.parameters.iter())
        .map(|p| {
            format!(
                "            {}: value({:?}),\n",
                identifier(&p.symbol),
                p.symbol
            )
        })
        .collect();
    Ok(format!(
        "{}\nimpl Parameters {{\n    /// Every parameter from `value` of its symbol.\n    \
         pub fn from_symbols(value: impl Fn(&str) -> f64) -> Self {{\n        Parameters {{\n\
         {fields}        }}\n    }}\n}}\n",
        system_source(system)?
    ))
}

fn main() {
    println!("cargo::rerun-if-changed=build.rs");
    let out_dir = PathBuf::from(std::env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
    let auv = Model::Spatial {
        symmetry: Symmetry::Xz,
        kinematics: Kinematics::Quaternion,
    };
    if let Err(error) = emit_into(&out_dir, &[auv]) {
        eprintln!("cannot emit the AUV model: {error}");
        std::process::exit(1);
    }
    let scene = Path::new("../../scenes/remus100.toml");
    println!("cargo::rerun-if-changed={}", scene.display());
    let remus = remus_spec(scene)
        .and_then(|spec| vehicle("remus", &spec).map_err(|e| e.to_string()))
        .unwrap_or_else(|error| {
            eprintln!("cannot read REMUS's table: {error}");
            std::process::exit(1);
        });
    let ships = [("ship", ship_spec()), ("mariner", mariner_spec())]
        .map(|(name, spec)| (name, ship(name, &spec).map_err(EmitError::from)));
    for (name, system) in ships.into_iter().chain([("remus", Ok(remus))]) {
        let source = system
            .and_then(|system| source_with_symbols(&system))
            .and_then(|source| write_if_changed(&out_dir.join(format!("{name}.rs")), &source));
        if let Err(error) = source {
            eprintln!("cannot emit the {name} model: {error}");
            std::process::exit(1);
        }
    }
}
