//! Runs the AUV for two seconds under a constant thrust and a small pitching moment, with
//! `eom`'s RK4 through the contract the emitter wrote for it.

use eom::integrate::{Integrator, Rk4};
use eom::{Constant, Model};
use eom_example_user_build_rs::{auv, example_parameters};

fn main() {
    let auv = auv::Coefficients::<f64>::new(&example_parameters());
    let mut start = [0.0; 13];
    start[9] = 1.0;
    let thrust = auv.driven_by(Constant([20.0, 0.0, 0.0, 0.0, 0.5, 0.0]));
    let print = |t: f64, x: &[f64; 13]| {
        println!(
            "t = {t:4.2} s  u = {:.4} m/s  q = {:.4} rad/s  x = {:.4} m  z = {:.4} m",
            x[0], x[4], x[6], x[8]
        );
    };
    print(0.0, &start);
    let mut method = Rk4::new(0.01);
    let mut step = 0;
    let run = method.integrate_with(&thrust, 0.0, start.into(), 2.0, |t, x| {
        step += 1;
        if step % 50 == 0 {
            print(t, &x.data.0[0]);
        }
    });
    if let Err(error) = run {
        eprintln!("the run failed: {error}");
        std::process::exit(1);
    }
    println!("operations per rhs call: {:?}", auv::OPERATIONS);
}
