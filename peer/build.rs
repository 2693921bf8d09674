//! Compiles SymPy's C (`sympy/c/*.c`, committed as `derive.py --emit` wrote it) twice, into two
//! static libraries whose functions carry distinct prefixes, so that one process can call both:
//!
//! - `peer_sympy_op`, prefix `peer_op_`: `-O3 -march=native -ffp-contract=off`, every
//!   multiplication and addition rounded on its own, as the C is written and as Rust computes;
//! - `peer_sympy_fma`, prefix `peer_fma_`: `-O3 -march=native -ffp-contract=fast`, the
//!   compiler free to fuse a multiplication and an addition into one FMA.
//!
//! The sources are not edited: `-D<name>=peer_op_<name>` renames each function as the
//! preprocessor reads it. The compiler's version and the flags are passed on to the bench.

use std::env;
use std::path::PathBuf;
use std::process::Command;

/// The variants `derive.py --emit` writes, one file each.
const VARIANTS: [&str; 6] = [
    "spatial_full_euler",
    "spatial_full_quaternion",
    "spatial_xz_euler",
    "spatial_xz_quaternion",
    "spatial_principal_euler",
    "spatial_principal_quaternion",
];

/// The functions a file may define, after its variant's name (Euler files have no `_unit`;
/// defining a macro that nothing uses is harmless).
const SUFFIXES: [&str; 3] = ["", "_coefficients", "_unit"];

/// The two builds: library name, symbol prefix, `-ffp-contract`.
const BUILDS: [(&str, &str, &str); 2] = [
    ("peer_sympy_op", "peer_op_", "off"),
    ("peer_sympy_fma", "peer_fma_", "fast"),
];

fn main() {
    let manifest = PathBuf::from(env::var_os("CARGO_MANIFEST_DIR").expect("set by cargo"));
    let out = PathBuf::from(env::var_os("OUT_DIR").expect("set by cargo"));
    let sources: Vec<PathBuf> = VARIANTS
        .iter()
        .map(|v| manifest.join("sympy").join("c").join(format!("{v}.c")))
        .collect();
    for source in &sources {
        println!("cargo:rerun-if-changed={}", source.display());
    }
    println!("cargo:rerun-if-changed=build.rs");

    let mut flags = Vec::new();
    for (library, prefix, contract) in BUILDS {
        let contract = format!("-ffp-contract={contract}");
        let mut build = cc::Build::new();
        build
            .files(&sources)
            .out_dir(out.join(library))
            .opt_level(3)
            .flag("-std=c99")
            .flag("-march=native")
            .flag(&contract);
        for variant in VARIANTS {
            for suffix in SUFFIXES {
                let name = format!("{variant}{suffix}");
                build.define(&name, format!("{prefix}{name}").as_str());
            }
        }
        if flags.is_empty() {
            let compiler = build.get_compiler();
            println!(
                "cargo:rustc-env=EOM_PEER_CC={}",
                first_line(Command::new(compiler.path()).arg("--version"))
            );
        }
        flags.push(format!("-O3 -march=native {contract}"));
        build.compile(library);
    }
    // cc adds the environment's CFLAGS to both builds (callgrind, for one, needs
    // CFLAGS=-mno-avx512f on a machine with AVX-512): say so wherever the flags are printed.
    println!("cargo:rerun-if-env-changed=CFLAGS");
    let mut flags = flags.join(" | ");
    if let Some(extra) = env::var("CFLAGS").ok().filter(|f| !f.trim().is_empty()) {
        flags.push_str(&format!(" (and CFLAGS {extra})"));
    }
    println!("cargo:rustc-env=EOM_PEER_CFLAGS={flags}");
    let rustc = env::var_os("RUSTC").unwrap_or_else(|| "rustc".into());
    println!(
        "cargo:rustc-env=EOM_PEER_RUSTC={}",
        first_line(Command::new(rustc).arg("--version"))
    );
}

/// The first line a command prints, or `unknown` when it cannot be run.
fn first_line(command: &mut Command) -> String {
    command
        .output()
        .ok()
        .and_then(|o| String::from_utf8(o.stdout).ok())
        .and_then(|s| s.lines().next().map(str::to_owned))
        .unwrap_or_else(|| "unknown".to_owned())
}
