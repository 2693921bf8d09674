//! The numerical behaviour of the generated models at the extremes, against exact answers:
//!
//! - `spin`: torque-free bodies spun at 10³ and 10⁴ rad/s through the generated quaternion
//!   model with DOPRI5 and DOP853 keep the error, the energy and |H| they keep at 1 rad/s;
//! - `conditioning`: a thin rod (moment ratio 10⁶) and a body with I_yy = I_zz to 10⁻¹²,
//!   their rates evaluated against a double-double solution of Euler's equations and related
//!   to cond([I]) · ε, and both integrated torque-free;
//! - `single_precision`: how fast an f32 run leaves the f64 run.
//!
//! The tables behind the bounds come from `cargo run --release --example extremes` and
//! `--example f32_vs_f64` (docs/extremes.md, docs/f32_vs_f64.md). Every test here runs in well
//! under a second in a debug build.

#[path = "extremes/conditioning.rs"]
mod conditioning;
#[path = "extremes/single_precision.rs"]
mod single_precision;
#[path = "extremes/spin.rs"]
mod spin;
