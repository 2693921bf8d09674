//! Runs the AUV for two seconds under a constant thrust and a small pitching moment.

use eom_example_user_build_rs::{auv, example_parameters, rk4_step};

fn main() {
    let k = auv::Coefficients::<f64>::new(&example_parameters());
    let mut x = [0.0; 13];
    x[9] = 1.0;
    let input = [20.0, 0.0, 0.0, 0.0, 0.5, 0.0];
    for step in 0..=200 {
        if step % 50 == 0 {
            println!(
                "t = {:4.2} s  u = {:.4} m/s  q = {:.4} rad/s  x = {:.4} m  z = {:.4} m",
                step as f64 * 0.01,
                x[0],
                x[4],
                x[6],
                x[8]
            );
        }
        x = rk4_step(&k, &x, &input, 0.01);
    }
    println!("operations per rhs call: {:?}", auv::OPERATIONS);
}
