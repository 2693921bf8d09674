//! Emits the two models this crate needs: an AUV, symmetric about its xz-plane, carried by a
//! unit quaternion so it may pitch through ±90°; and a ship of this crate's own hydrodynamic
//! table (4.46 with ten terms), proved before it is written.

use eom_codegen::emit::{emit_into, system_source, write_if_changed};
use eom_codegen::model::ship::{Force, ShipSpec, Term, Units, YawInertia, ship};
use eom_codegen::model::{Kinematics, Model, Symmetry};
use std::path::PathBuf;

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
    }
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
    let source = ship("ship", &ship_spec())
        .map_err(eom_codegen::emit::EmitError::from)
        .and_then(|system| system_source(&system))
        .and_then(|source| write_if_changed(&out_dir.join("ship.rs"), &source));
    if let Err(error) = source {
        eprintln!("cannot emit the ship model: {error}");
        std::process::exit(1);
    }
}
