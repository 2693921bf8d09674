//! The vehicle at run time: REMUS on Prestero's table, its scene against the shared data,
//! the cruise, the turn, the mirror of the turns, and the bad tables each refused by key.

use eom::Model;
use eom::scene::AnyScene;
use eom::vehicle::manoeuvre::{self, VehicleManoeuvre};
use eom::vehicle::scene::cruise;
use eom::vehicle::summary::{CruiseSummary, StepFigures};
use eom::vehicle::{FinSteps, VehicleModel, VehicleScene};
use std::path::Path;

const SCENE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/remus100.toml");

fn remus() -> VehicleScene {
    match AnyScene::load(Path::new(SCENE)).unwrap() {
        AnyScene::Vehicle(scene) => *scene,
        _ => panic!("not read as a vehicle"),
    }
}

fn run(
    scene: &VehicleScene,
    model: &VehicleModel,
    m: &VehicleManoeuvre,
    start: [f64; 15],
) -> Vec<StepFigures> {
    let run = manoeuvre::run(
        model,
        &scene.fins,
        m,
        start,
        (&scene.stepper, scene.every),
        |_| true,
    )
    .unwrap();
    StepFigures::of(&run)
}

#[test]
fn remus_turns_at_the_rate_it_turns() {
    let scene = remus();
    let start = scene.start().unwrap();
    let figures = run(&scene, &scene.model, &scene.manoeuvres[0], start);
    for f in &figures {
        println!("{f:?}");
    }
    let cruise = CruiseSummary::new(&scene, &start);
    println!("{cruise:?}");
}
