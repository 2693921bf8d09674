//! Proves every equation of the chapter, then emits every model variant `eom` ships into
//! `OUT_DIR`. A derivation that does not match the book's form stops the build, naming the
//! equation and printing the residual; so does a model whose emitted form does not compose
//! back to the proved equations.

use eom_codegen::{check, emit, model::Model};
use std::path::PathBuf;

fn main() {
    println!("cargo::rerun-if-changed=build.rs");
    if let Err(error) = check::check_all() {
        fail(&format!(
            "an equation of motion failed its proof:\n  {error}"
        ));
    }
    let out_dir = PathBuf::from(std::env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
    if let Err(error) = emit::emit_into(&out_dir, &Model::all()) {
        fail(&format!("a model could not be emitted:\n  {error}"));
    }
}

fn fail(message: &str) -> ! {
    eprintln!("eom: {message}");
    std::process::exit(1);
}
