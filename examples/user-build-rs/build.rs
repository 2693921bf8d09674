//! Emits the one model this crate needs: an AUV, symmetric about its xz-plane, carried by a
//! unit quaternion so it may pitch through ±90°.

use eom_codegen::emit::emit_into;
use eom_codegen::model::{Kinematics, Model, Symmetry};
use std::path::PathBuf;

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
}
