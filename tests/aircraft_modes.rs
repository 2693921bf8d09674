//! The names of an aircraft's modes across the centre-of-gravity range, through and behind the
//! neutral point: the F-16 of `scenes/f16.toml` at x_cg = 0.25, 0.30, 0.35, 0.38 c̄ and the
//! Navion of `scenes/navion.toml` at 0.295 (its table's), 0.40, 0.44, 0.46 c̄.
//!
//! What holds whatever the c.g. (each from the motion, not from eom's output):
//!
//! - Every mode has a name.
//! - No name is given to more roots than its motion has: the short period and the phugoid are
//!   each one second-order motion (a pair, or split into two real roots: two roots at most),
//!   the height mode, the roll subsidence, the spiral and the power lag are one root each, the
//!   Dutch roll one pair. The longitudinal motion (V, α, θ, q, altitude) has five roots in all;
//!   what is not one of these is coupled, and named so.
//! - Where a short-period and a phugoid oscillation are both named, the short period is the
//!   faster (what the names mean).
//! - Each root is named once, by a name of its group: the longitudinal motion's five roots
//!   (short period, phugoid, height, or coupled between the first two), the lateral motion's
//!   four (Dutch roll, roll subsidence, spiral), the power's one.
//! - The lateral modes move with the c.g. (the yawing moment carried to G, the trim's α) but
//!   keep their kind: the Dutch roll, the roll subsidence and the spiral are there at every
//!   x_cg, once each.
//!
//! And at the forward c.g., where the books name the modes, the modes they name: the F-16 at
//! 0.30 c̄ (Stevens, Lewis & Johnson's short period −1.2039 ± 1.4922i, phugoid near −0.0087 ±
//! 0.0739i, which eom's altitude row moves to −0.0077 ± 0.078i: docs/aircraft.md), the Navion at
//! its table's 0.295 c̄ (Nelson's model of the same table: short period −2.4969 ± 2.5562i,
//! phugoid −0.0167 ± 0.2155i with the altitude row, tests/aircraft_derivatives.rs). There
//! the short period moves α at nearly constant speed and the phugoid speed and height at
//! nearly constant α, which is what the books' approximations of each assume: the dominant
//! states say so.

use eom::kinds::aircraft::AircraftScene;
use eom::kinds::aircraft::linear::linearise_aircraft;
use eom::linear::{Linearisation, Mode};
use nalgebra::Complex;
use std::path::Path;

fn read(path: &str) -> String {
    std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(path)).unwrap()
}

/// The scene `file` with its c.g. at `xcg` (its `xcg = … #` line replaced), linearised at its
/// trim.
fn at_xcg(file: &str, xcg: f64) -> Linearisation {
    let text = read(file);
    let line = (text.lines())
        .find(|l| l.starts_with("xcg = "))
        .expect("the scene's xcg");
    let moved = text.replacen(line, &format!("xcg = {xcg}"), 1);
    let scene = AircraftScene::parse(&moved, file).unwrap();
    linearise_aircraft(&scene).unwrap()
}

const F16: (&str, [f64; 4]) = ("scenes/f16.toml", [0.25, 0.30, 0.35, 0.38]);
const NAVION: (&str, [f64; 4]) = ("scenes/navion.toml", [0.295, 0.40, 0.44, 0.46]);

fn show(what: &str, linear: &Linearisation) {
    println!("{what}");
    for m in &linear.modes {
        println!(
            "  {:>12.6} {:>12.6}  {:<40} {:?}",
            m.eigenvalue.re,
            m.eigenvalue.im,
            m.dominant.join(", "),
            m.name
        );
    }
}

/// The roots a mode stands for: two for a pair, one for a real root.
fn roots(mode: &Mode) -> usize {
    if mode.eigenvalue.im > 0.0 { 2 } else { 1 }
}

/// The roots named by any of `names`.
fn roots_named(linear: &Linearisation, names: &[&str]) -> usize {
    (linear.modes.iter())
        .filter(|m| m.name.is_some_and(|n| names.contains(&n)))
        .map(roots)
        .sum()
}

fn the_names_hold(what: &str, linear: &Linearisation) {
    show(what, linear);
    assert!(linear.equilibrium, "{what}: the trim");
    for mode in &linear.modes {
        assert!(
            mode.name.is_some(),
            "{what}: {:?} has no name",
            mode.eigenvalue
        );
    }
    let short = ["short period", "short period, aperiodic"];
    let phugoid = ["phugoid", "phugoid, aperiodic"];
    for (names, most) in [
        (&short[..], 2),
        (&phugoid[..], 2),
        (&["height"][..], 1),
        (&["roll subsidence"][..], 1),
        (&["spiral"][..], 1),
        (&["power lag"][..], 1),
    ] {
        let named = roots_named(linear, names);
        assert!(named <= most, "{what}: {named} roots named {names:?}");
    }
    // Each root is counted once, by a name of its group: the longitudinal motion (V, α, θ, q,
    // altitude) has five roots, the lateral (β, φ, p, r) four, the power one.
    let longitudinal = [
        &short[..],
        &phugoid[..],
        &["height", "coupled: short period + phugoid"][..],
    ]
    .concat();
    let lateral = ["Dutch roll", "roll subsidence", "spiral"];
    assert_eq!(
        roots_named(linear, &longitudinal),
        5,
        "{what}: longitudinal"
    );
    assert_eq!(roots_named(linear, &lateral), 4, "{what}: lateral");
    for name in ["Dutch roll", "roll subsidence", "spiral", "power lag"] {
        let found = (linear.modes.iter())
            .filter(|m| m.name == Some(name))
            .count();
        assert_eq!(found, 1, "{what}: {name}");
    }
    let frequency = |name: &str| {
        (linear.modes.iter())
            .find(|m| m.name == Some(name))
            .map(|m| m.eigenvalue.im)
    };
    if let (Some(fast), Some(slow)) = (frequency("short period"), frequency("phugoid")) {
        assert!(
            fast > slow,
            "{what}: short period {fast} rad/s, phugoid {slow}"
        );
    }
}

/// The names hold across the c.g. range of both aircraft (see the module docs).
#[test]
fn the_names_hold_across_the_centre_of_gravity_range() {
    for (file, range) in [F16, NAVION] {
        for xcg in range {
            the_names_hold(&format!("{file} at x_cg = {xcg}"), &at_xcg(file, xcg));
        }
    }
}

/// The mode at `eigenvalue` as printed: within 1e-3 of its magnitude, a unit in the last of
/// the four or five digits the books and docs/aircraft.md print (the modes nearest any of
/// these are at least twice their magnitude away).
fn near(linear: &Linearisation, eigenvalue: Complex<f64>) -> &Mode {
    (linear.modes.iter())
        .find(|m| (m.eigenvalue - eigenvalue).norm() <= 1e-3 * eigenvalue.norm())
        .unwrap_or_else(|| panic!("no mode near {eigenvalue}"))
}

fn has(mode: &Mode, state: &str) -> bool {
    mode.dominant.iter().any(|d| d == state)
}

/// At the forward c.g. the books' modes carry the books' names, and what moves in each is
/// what the books' approximations keep (see the module docs).
#[test]
fn at_the_forward_centre_of_gravity_the_books_modes_have_their_names() {
    let f16 = at_xcg(F16.0, 0.30);
    let navion = at_xcg(NAVION.0, 0.295);
    for (linear, short, phugoid) in [
        (
            &f16,
            Complex::new(-1.2038, 1.4920),
            Complex::new(-0.00767, 0.0780),
        ),
        (
            &navion,
            Complex::new(-2.4969, 2.5562),
            Complex::new(-0.016723, 0.215544),
        ),
    ] {
        show("forward", linear);
        let short = near(linear, short);
        assert_eq!(short.name, Some("short period"));
        assert!(has(short, "alpha"), "{:?}", short.dominant);
        assert!(
            !has(short, "vt") && !has(short, "altitude"),
            "{:?}",
            short.dominant
        );
        let phugoid = near(linear, phugoid);
        assert_eq!(phugoid.name, Some("phugoid"));
        assert!(has(phugoid, "vt"), "{:?}", phugoid.dominant);
        assert!(!has(phugoid, "alpha"), "{:?}", phugoid.dominant);
    }
    // The height mode: the F-16's at −0.00205/s (docs/aircraft.md), the Navion's at constant
    // thrust neither growing nor decaying (its verdict marginal).
    let height = near(&f16, Complex::new(-0.00205, 0.0));
    assert_eq!(height.name, Some("height"));
    let neutral = (navion.modes.iter())
        .find(|m| m.damping_ratio.is_none())
        .expect("the Navion's neutral root");
    assert_eq!(neutral.name, Some("height"));
    assert!(has(neutral, "altitude"), "{:?}", neutral.dominant);
}
