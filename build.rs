//! Proves every equation of the chapter, then emits every model variant `eom` ships, and the
//! catalog that lists them, into `OUT_DIR`. A derivation that does not match the book's form
//! stops the build, naming the equation and printing the residual; so does a model whose
//! emitted program does not fold back to the proved equations.

fn main() {
    println!("cargo::rerun-if-changed=build.rs");
    if let Err(error) = eom_codegen::check::check_all() {
        fail(&format!(
            "an equation of motion failed its proof:\n  {error}"
        ));
    }
    let out_dir =
        std::path::PathBuf::from(std::env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
    let models = eom_codegen::model::Model::all();
    if let Err(error) = eom_codegen::emit::emit_with_catalog(&out_dir, &models) {
        fail(&format!("a model could not be emitted:\n  {error}"));
    }
}

fn fail(message: &str) -> ! {
    eprintln!("eom: {message}");
    std::process::exit(1);
}
