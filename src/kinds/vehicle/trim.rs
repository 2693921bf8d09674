//! The trim every manoeuvre starts from: a steady motion of the vehicle, at the origin,
//! heading north, its fins at zero but those its autopilots work from the start.
//!
//! Why in two stages. A neutral vehicle (W = B, G below its centre of buoyancy on the same
//! vertical) cruises on the straight level course: u from the thrust against the drag, the
//! roll φ from the propeller's torque against the righting moment, every other state zero.
//! [`cruise`] finds those two by Newton on the running model and its proved Jacobian, to the
//! rounding of their rates, and the closed forms check them. A vehicle heavier or lighter than
//! the water it displaces, or with G forward or aft of its centre of buoyancy, is not in
//! equilibrium there: left to itself it pitches and sinks before its first command, and a
//! trial's figures would read that transient. Its trim is a steady motion of the whole reduced
//! state u, v, w, p, q, r, φ, θ (everything but the position and the heading, which no rate
//! reads): in general a helix, sinking or rising at a steady rate. Where a manoeuvre's
//! autopilots hold the heading or the depth from its start, the fin each works is trimmed too,
//! and ψ̇ or ż is held at zero ([`Held`]); the autopilots then act about that trim
//! ([`super::autopilot::Feedforward`]). Each is found by the linearisation's trim
//! ([`crate::linear::trim`]: Newton on the proved Jacobians, here those of the Euler-angle
//! twin, [`super::linear::VehiclePlant`]) from the cruise; the twin is derived only then,
//! once per vehicle ([`Trimmer`]).
//!
//! A trim is accepted only ahead (u > 0): a table is identified going ahead, and a motion
//! astern (a vehicle so heavy that it backs down as it sinks) is outside it. Where no trim
//! ahead is found, the scene is refused, saying why: no manoeuvre runs from a state that is
//! not steady.

use super::linear::VehiclePlant;
use super::manoeuvre::euler_angles;
use super::model::VehicleModel;
use super::table::VehicleTable;
use crate::Short;
use crate::linear::trim::{Free, trim as newton};
use crate::linear::{EQUILIBRIUM_TOLERANCE, LinearError, rate_scale};
use crate::models::Model;

/// The twin's states the trim solves for and whose rates it brings to zero: u, v, w, p, q, r,
/// φ, θ (the twin's layout, [`super::model::EULER_STATE`]).
const REDUCED: [usize; 8] = [0, 1, 2, 3, 4, 5, 9, 10];

/// Their names, for the messages.
const REDUCED_NAMES: &str = "u, v, w, p, q, r, phi, theta";

/// The twin's z, whose rate vanishes where the depth autopilot holds the depth.
const DEPTH: usize = 8;

/// The twin's ψ, whose rate vanishes where the heading autopilot holds the heading.
const HEADING: usize = 11;

/// What a manoeuvre's autopilots hold from its start: its heading, its depth. Each one held
/// frees its fin (the rudder, the stern planes) and asks its rate (ψ̇, ż) to vanish.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Held {
    /// The heading autopilot holds the heading: ψ̇ = 0, the rudder trimmed.
    pub heading: bool,
    /// The depth autopilot holds the depth: ż = 0, the stern planes trimmed.
    pub depth: bool,
}

/// The steady motion a manoeuvre starts from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Trim {
    /// The running model's state there ([`super::model::STATE`]): at the origin, heading
    /// north, the fins at zero but where an autopilot holds them at their trim.
    pub state: [f64; 15],
    /// Newton's steps on the whole reduced state; `None` where the cruise of u and φ already
    /// was a trim (the straight level course of a neutral vehicle).
    pub whole_state_steps: Option<usize>,
    /// What the autopilots hold in it.
    pub held: Held,
}

impl Trim {
    /// The states and fins solved for: u and φ, or the whole reduced state and the fins the
    /// autopilots work.
    pub fn trimmed(&self) -> Vec<&'static str> {
        if self.whole_state_steps.is_none() {
            return vec!["u", "phi"];
        }
        let mut names: Vec<&str> = REDUCED_NAMES.split(", ").collect();
        names.extend(self.held.heading.then_some("dr"));
        names.extend(self.held.depth.then_some("ds"));
        names
    }

    /// ż of O (4.57, down positive), m/s: the rate a trim sinks at.
    pub fn depth_rate(&self) -> f64 {
        let [phi, theta, _] = euler_angles(&self.state);
        let (u, v, w) = (self.state[0], self.state[1], self.state[2]);
        let (sf, cf) = phi.sin_cos();
        let (st, ct) = theta.sin_cos();
        -u * st + v * ct * sf + w * ct * cf
    }
}

/// Why no manoeuvre can start: no steady motion ahead was found.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum TrimError {
    /// Newton on u̇ = ṗ = 0 did not converge.
    #[error("no cruise: Newton on u̇ = ṗ = 0 (surge and roll) did not converge from u = 1 m/s")]
    NoCruise,
    /// Newton on the whole reduced state did not converge, or left the model's reach.
    #[error(
        "no trim: the cruise of u and φ is not a steady motion ({why}), and Newton on {solved} \
         from it finds none: {reason}. No manoeuvre is run from a state that is not steady"
    )]
    NotFound {
        /// What keeps the cruise from being one.
        why: String,
        /// What was solved for.
        solved: String,
        /// What Newton said.
        reason: String,
    },
    /// The only steady motion found runs astern.
    #[error(
        "no trim ahead: the only steady motion Newton finds from the cruise{held} runs astern \
         (u = {} m/s, w = {} m/s, θ = {}°), outside a table identified going ahead ({why}). \
         No manoeuvre is run from a state that is not steady",
        Short(*u), Short(*w), Short(theta.to_degrees())
    )]
    Astern {
        /// u there, m/s.
        u: f64,
        /// w there, m/s.
        w: f64,
        /// θ there, rad.
        theta: f64,
        /// What the autopilots hold in it (` with the depth held`), or nothing.
        held: String,
        /// What keeps the cruise from being a steady motion.
        why: String,
    },
}

impl TrimError {
    /// The scene key the error is about: the propeller for a cruise that does not converge,
    /// else the body whose weight, buoyancy and centres set the trim.
    pub fn key(&self) -> &'static str {
        match self {
            TrimError::NoCruise => "propeller",
            _ => "body",
        }
    }
}

/// The trims of one vehicle: its cruise, and the Euler-angle twin derived once where the
/// cruise is not a steady motion.
#[derive(Debug)]
pub struct Trimmer<'a> {
    table: &'a VehicleTable,
    /// The cruise of u and φ.
    cruise: [f64; 15],
    /// Why the cruise is not a steady motion (the largest rate there and what in the body
    /// makes it), or `None` where it is one.
    not_steady: Option<String>,
    twin: Option<VehiclePlant>,
}

impl<'a> Trimmer<'a> {
    /// The trims of `model`, the vehicle of `table`: its cruise found, and judged.
    pub fn new(table: &'a VehicleTable, model: &VehicleModel) -> Result<Self, TrimError> {
        let cruise = cruise(model).map_err(|_| TrimError::NoCruise)?;
        let rates = Model::<f64, 15, 2>::rhs(model, &cruise, &[0.0; 2]);
        // The cruise has p = q = r = 0 and θ = v = w = 0, so φ̇ = θ̇ = ψ̇ = ż = 0: only ν̇ can
        // keep it from being a trim, whatever the autopilots hold.
        let tolerance = EQUILIBRIUM_TOLERANCE * rate_scale(&twin_state(&cruise));
        let worst = (0..6)
            .max_by(|&a, &b| rates[a].abs().total_cmp(&rates[b].abs()))
            .filter(|&i| rates[i].abs() > tolerance);
        let not_steady = worst.map(|i| {
            format!(
                "{}̇ = {} there{}",
                super::model::STATE[i],
                Short(rates[i]),
                cause(table)
            )
        });
        Ok(Trimmer {
            table,
            cruise,
            not_steady,
            twin: None,
        })
    }

    /// The trim with the autopilots holding `held` (see the module docs): the cruise where it
    /// is a steady motion, else Newton on the whole reduced state and the fins held from it.
    pub fn trim(&mut self, held: Held) -> Result<Trim, TrimError> {
        let Some(why) = self.not_steady.clone() else {
            return Ok(Trim {
                state: self.cruise,
                whole_state_steps: None,
                held,
            });
        };
        let mut reduced = REDUCED.to_vec();
        let mut free: Vec<Free> = REDUCED.iter().map(|&i| Free::State(i)).collect();
        let mut solved = REDUCED_NAMES.to_owned();
        if held.heading {
            reduced.push(HEADING);
            free.push(Free::Input(0));
            solved.push_str(", dr with the heading held");
        }
        if held.depth {
            reduced.push(DEPTH);
            free.push(Free::Input(1));
            solved.push_str(", ds with the depth held");
        }
        let not_found = |reason: String| TrimError::NotFound {
            why: why.clone(),
            solved: solved.clone(),
            reason,
        };
        if self.twin.is_none() {
            self.twin = Some(VehiclePlant::new(self.table).map_err(|e| not_found(e.to_string()))?);
        }
        let twin = self.twin.as_ref().expect("derived above");
        let start = twin_state(&self.cruise);
        let found = newton(twin, (&start, &[0.0; 2]), &reduced, &free, &solved)
            .map_err(|error| not_found(newton_failure(&error)))?;
        let x = &found.state;
        if x[0] <= 0.0 {
            let held = match (held.heading, held.depth) {
                (false, false) => "",
                (true, false) => " with the heading held",
                (false, true) => " with the depth held",
                (true, true) => " with the heading and the depth held",
            };
            return Err(TrimError::Astern {
                u: x[0],
                w: x[2],
                theta: x[10],
                held: held.to_owned(),
                why,
            });
        }
        Ok(Trim {
            state: running_state(x, &found.extra),
            whole_state_steps: Some(found.iterations),
            held,
        })
    }
}

/// What in the body's keys the straight level cruise cannot hold: W ≠ B, G and the centre of
/// buoyancy not on one vertical.
fn cause(table: &VehicleTable) -> String {
    let mut causes = Vec::new();
    if table.weight != table.buoyancy {
        causes.push(format!(
            "body.weight − body.buoyancy = {} N",
            Short(table.weight - table.buoyancy)
        ));
    }
    let (g, b) = (table.centre_of_gravity, table.centre_of_buoyancy);
    if g[0] != b[0] || g[1] != b[1] {
        causes.push(format!(
            "body.centre_of_gravity [{}, {}] m against body.centre_of_buoyancy [{}, {}] m in x \
             and y",
            Short(g[0]),
            Short(g[1]),
            Short(b[0]),
            Short(b[1])
        ));
    }
    match causes.is_empty() {
        true => String::new(),
        false => format!(": {}", causes.join(", ")),
    }
}

/// Newton's failure, in the trim's words (the linearisation's own message speaks of its
/// `[linear]` table).
fn newton_failure(error: &LinearError) -> String {
    match error {
        LinearError::NoConvergence {
            iterations,
            state,
            residual,
            tolerance,
            ..
        } => format!(
            "after {} the largest rate left is d{state}/dt = {} (tolerance {})",
            crate::counted(*iterations, "Newton step", "Newton steps"),
            Short(*residual),
            Short(*tolerance)
        ),
        other => other.to_string(),
    }
}

/// The twin's state ([`super::model::EULER_STATE`] without the fins) of the running model's
/// `state`.
fn twin_state(state: &[f64; 15]) -> Vec<f64> {
    let mut twin = state[..9].to_vec();
    twin.extend(euler_angles(state));
    twin
}

/// The running model's state of the twin's `twin` (its heading zero) with the fins at `fins`.
fn running_state(twin: &[f64], fins: &[f64]) -> [f64; 15] {
    let mut state = [0.0; 15];
    state[..6].copy_from_slice(&twin[..6]);
    state[13..].copy_from_slice(fins);
    let (phi, theta) = (twin[9], twin[10]);
    let q = crate::generic::quaternion_from_euler(phi, theta, 0.0);
    state[9..13].copy_from_slice(&[q.w, q.i, q.j, q.k]);
    state
}

/// The cruise: at the origin, heading north, fins at zero, u and φ found by Newton so that
/// u̇ = ṗ = 0 on the model (its proved Jacobian, the chain rule through |u| added), from
/// u = 1 m/s, φ = 0; converged when both rates are below 1e-13 (in m/s² and rad/s²: rounding
/// of rates of order one). The straight level course of a neutral vehicle;
/// [`Trimmer::trim`] goes on from it where it is not a steady motion.
pub fn cruise(model: &VehicleModel) -> Result<[f64; 15], super::VehicleError> {
    let state = |u: f64, phi: f64| {
        let mut x = [0.0; 15];
        x[0] = u;
        x[9] = (phi / 2.0).cos();
        x[10] = (phi / 2.0).sin();
        x
    };
    let (mut u, mut phi) = (1.0, 0.0);
    for _ in 0..50 {
        let x = state(u, phi);
        let f = Model::<f64, 15, 2>::rhs(model, &x, &[0.0; 2]);
        let (r_u, r_p) = (f[0], f[3]);
        if r_u.abs() < 1e-13 && r_p.abs() < 1e-13 {
            return Ok(x);
        }
        let j = Model::<f64, 15, 2>::state_jacobian(model, &x, &[0.0; 2]);
        let dq = [-(phi / 2.0).sin() / 2.0, (phi / 2.0).cos() / 2.0];
        let d_phi = |row: usize| j[row][9] * dq[0] + j[row][10] * dq[1];
        let (a, b, c, d) = (j[0][0], d_phi(0), j[3][0], d_phi(3));
        let det = a * d - b * c;
        if det == 0.0 || !det.is_finite() {
            break;
        }
        u -= (d * r_u - b * r_p) / det;
        phi -= (a * r_p - c * r_u) / det;
    }
    Err(super::VehicleError::invalid(
        "propeller",
        "no cruise: Newton on u̇ = ṗ = 0 (surge and roll) did not converge from u = 1 m/s",
    ))
}
