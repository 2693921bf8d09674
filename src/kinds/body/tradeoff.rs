//! A catalog body's integrators compared ([`crate::run::tradeoff`]): every method that applies
//! to the scene over the steps or tolerances swept, each run to the end time with rows only
//! there, its end state judged against the exact solution where the scene has one (a
//! pendulum released from rest with no other load: [`LargeSwing`]) or DOP853 at 1e-13.

use super::{Body, SceneLoads};
use super::{BodyScene, IntegratorSpec, Report, RunError, run};
use crate::integrate::AdaptiveOptions;
use crate::reference::LargeSwing;
use crate::run::tradeoff::{REPEATS, STEP_COUNTS, TOLERANCES, Tradeoff, TradeoffRow};
use crate::run::{Row, Sink};
use crate::scene::Method;

/// A sink that keeps nothing.
struct Discard;

impl Sink for Discard {
    fn row(&mut self, _row: &Row) -> bool {
        true
    }
}

/// Runs `scene` with `spec`, rows only at the start and the end.
fn end_state(scene: &BodyScene, spec: IntegratorSpec) -> Result<Report, RunError> {
    let mut once = scene.clone();
    once.integrator = spec;
    once.every = spec.end_time;
    // The settings are compared at the end time, which a stop condition would move.
    once.stop = None;
    run(&once, &mut Discard)
}

/// The methods that apply to a scene.
fn methods(scene: &BodyScene) -> Vec<Method> {
    let mut methods = vec![
        Method::Euler,
        Method::SymplecticEuler,
        Method::Rk4,
        Method::Dopri5,
        Method::Dop853,
    ];
    let free_quaternion = scene.loads.rotation_is_torque_free();
    if free_quaternion {
        methods.push(Method::LieMidpoint);
    }
    methods
}

/// The settings a method is swept over, within the scene's step limit.
fn settings(method: Method, scene: &BodyScene) -> Vec<(IntegratorSpec, String)> {
    let end = scene.integrator.end_time;
    let max_steps = scene.integrator.max_steps;
    if method.is_adaptive() {
        TOLERANCES
            .iter()
            .map(|&tol| {
                let mut options = match method {
                    Method::Dopri5 => AdaptiveOptions::dopri5(tol, tol),
                    _ => AdaptiveOptions::dop853(tol, tol),
                };
                options.max_steps = max_steps;
                let spec = IntegratorSpec {
                    method,
                    step: None,
                    adaptive: Some(options),
                    end_time: end,
                    max_steps,
                };
                (spec, format!("rtol = atol = {tol:e}"))
            })
            .collect()
    } else {
        STEP_COUNTS
            .iter()
            .filter(|&&n| n <= max_steps)
            .map(|&n| {
                let step = end / n as f64;
                let spec = IntegratorSpec {
                    method,
                    step: Some(step),
                    adaptive: None,
                    end_time: end,
                    max_steps,
                };
                (spec, format!("step = {step:.4e} s ({n} steps)"))
            })
            .collect()
    }
}

/// The reference end state, and what it is.
fn reference(scene: &BodyScene) -> Result<(Vec<f64>, String), RunError> {
    if let (Body::Pendulum(parameters), SceneLoads::Pendulum(_)) = (&scene.body, &scene.loads) {
        let at_rest = scene.initial[1] == 0.0 && scene.loads.is_free();
        if at_rest && let Ok(swing) = LargeSwing::new(parameters, scene.initial[0].abs()) {
            let mut exact = swing.exact(scene.integrator.end_time);
            if scene.initial[0] < 0.0 {
                exact = -exact;
            }
            return Ok((
                exact.as_slice().to_vec(),
                "the exact solution (Jacobi's elliptic functions)".into(),
            ));
        }
    }
    let mut options = AdaptiveOptions::dop853(1e-13, 1e-13);
    options.max_steps = usize::MAX / 2;
    let spec = IntegratorSpec {
        method: Method::Dop853,
        step: None,
        adaptive: Some(options),
        end_time: scene.integrator.end_time,
        max_steps: usize::MAX / 2,
    };
    let report = end_state(scene, spec)?;
    Ok((report.final_state, "DOP853 at rtol = atol = 1e-13".into()))
}

/// `max |yᵢ − yᵢ,ref| / max(1, max |yᵢ,ref|)`.
fn error(state: &[f64], reference: &[f64]) -> f64 {
    let scale = reference.iter().fold(1.0f64, |m, x| m.max(x.abs()));
    let worst = state
        .iter()
        .zip(reference)
        .map(|(a, b)| (a - b).abs())
        .fold(
            0.0f64,
            |m, d| if d.is_nan() { f64::INFINITY } else { m.max(d) },
        );
    worst / scale
}

/// Sweeps every applicable method over its settings.
pub fn tradeoff(scene: &BodyScene) -> Result<Tradeoff, RunError> {
    let (reference_state, reference) = reference(scene)?;
    let mut rows = Vec::new();
    for method in methods(scene) {
        for (spec, setting) in settings(method, scene) {
            let mut best: Option<Report> = None;
            let mut failure = None;
            for _ in 0..REPEATS {
                match end_state(scene, spec) {
                    Ok(report) => {
                        if best
                            .as_ref()
                            .is_none_or(|b| report.wall_seconds < b.wall_seconds)
                        {
                            best = Some(report);
                        }
                    }
                    Err(e) => {
                        failure = Some(e.to_string());
                        break;
                    }
                }
            }
            rows.push(match (best, failure) {
                (Some(report), None) => TradeoffRow {
                    method: method.name(),
                    setting,
                    error: Some(error(&report.final_state, &reference_state)),
                    rhs_evals: report.rhs_evals,
                    seconds: report.wall_seconds,
                    failure: None,
                },
                (_, failure) => TradeoffRow {
                    method: method.name(),
                    setting,
                    error: None,
                    rhs_evals: 0,
                    seconds: f64::NAN,
                    failure,
                },
            });
        }
    }
    let run = format!(
        "{} to t = {} s",
        scene.selection.info.name, scene.integrator.end_time
    );
    Ok(Tradeoff {
        run,
        reference,
        rows,
    })
}
