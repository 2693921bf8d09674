//! The three forms of a scene-defined ship against each other, as the bench times them: the
//! table compiled by rustc from this crate's `build.rs`, the same table as `eom` runs a
//! scene's (compiled to machine code when it is read), and `eom`'s interpreter of the proved
//! program; for the ten-term ship, the Mariner and REMUS in six degrees of freedom. Every
//! output of 10⁵ random states, bit for bit: the interpreter computes each
//! coefficient and each operation as the emitted code writes it, and the compiled code is the
//! interpreter's operations one for one. In a build with FMA (`-C target-feature=+fma`) rustc
//! fuses the emitted `mul_add`s and the machine code does not, so there the rustc form is
//! left out and the other two still agree bit for bit.

mod common;

use common::{
    differing_bits, differing_vehicle_bits, mariner_coefficients, mariner_rates, mariner_table,
    remus_coefficients, remus_rates, remus_scene, table,
};
use eom::Model;
use eom::kinds::ship::ShipModel;
use eom_example_user_build_rs::{example_ship, ship};

/// Whether rustc's `mul_add` is one fused operation in this build.
const FUSED: bool = cfg!(target_feature = "fma");

#[test]
fn the_ten_term_ship_is_the_same_in_all_three_forms() {
    let k = ship::Coefficients::<f64>::new(&example_ship());
    let compiled = ShipModel::new(&table()).expect("the table builds");
    let interpreted = compiled.interpreted();
    let jit = |s: &[f64; 7], d: f64| compiled.rhs(s, &[d, 0.0, 0.0]);
    assert_eq!(
        differing_bits(jit, |s, d| interpreted.rhs(s, &[d, 0.0, 0.0])),
        0
    );
    if !FUSED {
        assert_eq!(differing_bits(|s, d| k.rhs(s, &[d]), jit), 0);
    }
}

#[test]
fn the_mariner_is_the_same_in_all_three_forms() {
    let table = mariner_table();
    let m = mariner_coefficients(&table);
    let rustc = |s: &[f64; 7], d: f64| mariner_rates(&m, s, d);
    let compiled = ShipModel::new(&table).expect("the Mariner builds");
    assert_eq!(compiled.terms(), 39);
    let interpreted = compiled.interpreted();
    let jit = |s: &[f64; 7], d: f64| compiled.rhs(s, &[d, 0.0, 0.0]);
    assert_eq!(
        differing_bits(jit, |s, d| interpreted.rhs(s, &[d, 0.0, 0.0])),
        0
    );
    if !FUSED {
        assert_eq!(differing_bits(rustc, jit), 0);
    }
}

#[test]
fn remus_is_the_same_in_all_three_forms() {
    let scene = remus_scene();
    let k = remus_coefficients(&scene);
    let compiled = &scene.model;
    let interpreted = compiled.interpreted();
    let body = |rates: [f64; 15]| -> [f64; 13] { std::array::from_fn(|i| rates[i]) };
    let jit = |s: &[f64; 15]| body(compiled.rhs(s, &[0.0, 0.0]));
    assert_eq!(
        differing_vehicle_bits(jit, |s| body(interpreted.rhs(s, &[0.0, 0.0]))),
        0
    );
    if !FUSED {
        assert_eq!(differing_vehicle_bits(|s| remus_rates(&k, s), jit), 0);
    }
}
