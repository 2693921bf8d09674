//! Proves every equation of the chapter before `eom` is compiled: a derivation that does not
//! match the book's form stops the build, naming the equation and printing the residual.

fn main() {
    println!("cargo::rerun-if-changed=build.rs");
    if let Err(error) = eom_codegen::check::check_all() {
        eprintln!("eom: an equation of motion failed its proof:\n  {error}");
        std::process::exit(1);
    }
}
