//! The JSON inputs of `eom eval`, the one function that reads them, and the evaluation of one
//! model at that state by the generated model and by the generic nalgebra form.
//!
//! `eom eval` reads the file and prints; this module is what it reads and computes, so that
//! both can be tested without a process per input. Everything the input gets wrong (a missing
//! or unknown key, a number out of range, an impossible body, a product of inertia that the
//! chosen symmetry class says is zero, a state at which the derivative is not finite) is an
//! error naming it. Every key is required unless
//! said otherwise, and an unknown key is an error (`deny_unknown_fields`).
//!
//! Every number is read to the nearest binary64: `serde_json` is built with its
//! `float_roundtrip` feature, without which it reads some decimals one ulp off. Next to pitch
//! ±90° one ulp of θ is a relative change of `ε/|cos θ|` in sec θ and tan θ: 7e-9 of ψ̇ at
//! `cos θ ≈ 3e-8`, far more than any rounding of the arithmetic.
//!
//! ```
//! use eom_cli::eval::{SpatialInput, parse};
//! let input: SpatialInput = parse(
//!     r#"{"mass": 2, "inertia": [[2, 0, 0], [0, 3, 0], [0, 0, 4]],
//!         "state": {"u": 1, "v": 0, "w": 0, "p": 0, "q": 0, "r": 0.5,
//!                   "phi": 0, "theta": 1.5707962967948965, "psi": 0},
//!         "force": [0, 0, 0], "moment": [0, 0, 0]}"#,
//! )?;
//! assert_eq!(input.state.theta, 1.5707962967948965);
//! # Ok::<(), serde_json::Error>(())
//! ```

use anyhow::{Context, Result, bail};
use eom::generic::{
    EulerState, Pendulum, PlanarBody, PlanarMidship, RigidBody, check_pitch,
    euler_state_to_quaternion_state,
};
use eom::models::{self, AnyModel, Family, Kinematics, Model as _, Symmetry};
use eom::{InertiaTensor, PendulumParameters};
use nalgebra::{Matrix3, Vector2, Vector3, Vector6};
use serde::Deserialize;
use serde::de::DeserializeOwned;

/// Reads one input from JSON text, every number to the nearest binary64.
pub fn parse<T: DeserializeOwned>(text: &str) -> Result<T, serde_json::Error> {
    serde_json::from_str(text)
}

/// Input of `--model pendulum`: I₀ about the pivot, M, g, h from pivot to G, the state and an
/// applied moment about the pivot (0 when left out).
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PendulumInput {
    /// I₀ about the pivot.
    pub i0: f64,
    /// M.
    pub mass: f64,
    /// g.
    pub g: f64,
    /// Pivot to G.
    pub h: f64,
    /// `{theta, theta_dot}`.
    pub state: PendulumState,
    /// The applied moment about the pivot; 0 when left out.
    #[serde(default)]
    pub moment: f64,
}

/// The pendulum's state.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PendulumState {
    /// θ from the downward vertical.
    pub theta: f64,
    /// θ̇.
    pub theta_dot: f64,
}

/// Input of the body-fixed planar models (`--model planar-g`, `planar-midship`): `force` is
/// `(F_x, F_y)` (or `(X, Y)`) in body axes, `moment` about the origin (G or midship), `x_g`
/// the midship model's G ahead of midship.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlanarInput {
    /// M.
    pub mass: f64,
    /// I_zz about G.
    pub izz: f64,
    /// G ahead of midship (`planar-midship` only).
    #[serde(default)]
    pub x_g: Option<f64>,
    /// `{u, v, r, x, y, psi}`.
    pub state: PlanarBodyState,
    /// `[F_x, F_y]`, body axes.
    pub force: [f64; 2],
    /// The yaw moment about the origin.
    pub moment: f64,
}

/// The state of a body-fixed planar model.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlanarBodyState {
    /// Surge velocity.
    pub u: f64,
    /// Sway velocity.
    pub v: f64,
    /// Yaw rate.
    pub r: f64,
    /// X in space axes.
    pub x: f64,
    /// Y in space axes.
    pub y: f64,
    /// Heading ψ, rad.
    pub psi: f64,
}

impl PlanarInput {
    /// The model's state `[u, v, r, X, Y, ψ]`.
    pub fn state(&self) -> [f64; 6] {
        let s = &self.state;
        [s.u, s.v, s.r, s.x, s.y, s.psi]
    }

    /// The model's input `[F_x, F_y, M_z]`.
    pub fn load(&self) -> [f64; 3] {
        [self.force[0], self.force[1], self.moment]
    }
}

/// Input of `--model planar-space`: `force` is `(F_X, F_Y)` in space axes.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlanarSpaceInput {
    /// M.
    pub mass: f64,
    /// I_zz about G.
    pub izz: f64,
    /// `{x, y, psi, x_dot, y_dot, psi_dot}`.
    pub state: PlanarSpaceState,
    /// `[F_X, F_Y]`, space axes.
    pub force: [f64; 2],
    /// The yaw moment about G.
    pub moment: f64,
}

/// The state of the space-fixed planar model.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlanarSpaceState {
    /// X.
    pub x: f64,
    /// Y.
    pub y: f64,
    /// Heading ψ, rad.
    pub psi: f64,
    /// Ẋ.
    pub x_dot: f64,
    /// Ẏ.
    pub y_dot: f64,
    /// ψ̇.
    pub psi_dot: f64,
}

/// Input of `--model spatial`: the inertia tensor about G in the chapter's convention
/// (products with the sign of 4.14), force and moment about G in body axes.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SpatialInput {
    /// M.
    pub mass: f64,
    /// `[[Ixx, Ixy, Ixz], [Ixy, Iyy, Iyz], [Ixz, Iyz, Izz]]` about G.
    pub inertia: [[f64; 3]; 3],
    /// `{u, v, w, p, q, r, phi, theta, psi}`.
    pub state: SpatialState,
    /// Force, body axes.
    pub force: [f64; 3],
    /// Moment about G, body axes.
    pub moment: [f64; 3],
}

/// The state of a spatial model, with the attitude as Euler angles (4.56), rad.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SpatialState {
    /// Surge velocity.
    pub u: f64,
    /// Sway velocity.
    pub v: f64,
    /// Heave velocity.
    pub w: f64,
    /// Roll rate.
    pub p: f64,
    /// Pitch rate.
    pub q: f64,
    /// Yaw rate.
    pub r: f64,
    /// Roll φ.
    pub phi: f64,
    /// Pitch θ.
    pub theta: f64,
    /// Yaw ψ.
    pub psi: f64,
}

/// The smallest `|cos θ|` at which `--kinematics euler` still answers: only an input pitch of
/// ±90° to within about 1e-12 rad is refused, so that states within 1e-6 of the singularity
/// can still be compared.
const MIN_COS_PITCH: f64 = 1e-12;

/// One model evaluated both ways, keys in the state's order.
#[derive(Debug, Clone, PartialEq)]
pub struct Evaluation {
    /// The generated model's derivative, by name.
    pub generated: Vec<(&'static str, f64)>,
    /// The generic form's derivative, by name.
    pub generic: Vec<(&'static str, f64)>,
}

/// Reads `text` as the JSON input of `family` (a spatial body with the given symmetry class
/// and kinematics) and evaluates the model there, both ways. Every derivative returned is
/// finite.
pub fn evaluate(
    text: &str,
    family: Family,
    symmetry: Symmetry,
    kinematics: Kinematics,
) -> Result<Evaluation> {
    let derivative = match family {
        Family::Pendulum => pendulum(&read(text)?)?,
        Family::PlanarAtG => planar_g(&read(text)?)?,
        Family::PlanarMidship => planar_midship(&read(text)?)?,
        Family::PlanarSpaceFixed => planar_space(&read(text)?)?,
        Family::Spatial => spatial(&read(text)?, symmetry, kinematics)?,
        Family::Top => bail!(
            "eval does not cover the top family yet: it has no generic form to print beside \
             the generated one"
        ),
    };
    let all = derivative.generated.iter().chain(&derivative.generic);
    if let Some((key, value)) = all.into_iter().find(|(_, x)| !x.is_finite()) {
        bail!("the derivative {key} is not finite ({value}); the state is outside the model");
    }
    Ok(derivative)
}

/// [`parse`], with the error saying what was being read.
fn read<T: DeserializeOwned>(text: &str) -> Result<T> {
    parse(text).context("parsing the input JSON")
}

fn pendulum(input: &PendulumInput) -> Result<Evaluation> {
    let parameters = PendulumParameters::new(input.i0, input.mass, input.g, input.h)?;
    let model = Pendulum::<f64>::new(&parameters);
    let generated = models::Pendulum::<f64>::new(&parameters);
    let state = [input.state.theta, input.state.theta_dot];
    let keys = ["theta_dot", "theta_ddot"];
    Ok(Evaluation {
        generated: named(&keys, &generated.rhs(&state, &[input.moment])),
        generic: named(
            &keys,
            model.rhs(&Vector2::from(state), input.moment).as_slice(),
        ),
    })
}

const PLANAR_BODY_KEYS: [&str; 6] = ["u_dot", "v_dot", "r_dot", "x_dot", "y_dot", "psi_dot"];

fn planar_g(input: &PlanarInput) -> Result<Evaluation> {
    if input.x_g.is_some() {
        bail!("key x_g belongs to --model planar-midship; at G the origin is G itself");
    }
    let model = PlanarBody::<f64>::new(input.mass, input.izz)?;
    let generated = models::PlanarAtG::<f64>::new(input.mass, input.izz)?;
    let (state, load) = (input.state(), input.load());
    let d = model.rhs_body_at_g(&Vector6::from(state), &Vector3::from(load));
    Ok(Evaluation {
        generated: named(&PLANAR_BODY_KEYS, &generated.rhs(&state, &load)),
        generic: named(&PLANAR_BODY_KEYS, d.as_slice()),
    })
}

fn planar_midship(input: &PlanarInput) -> Result<Evaluation> {
    let x_g = input
        .x_g
        .context("missing key x_g (position of G ahead of midship)")?;
    let model = PlanarMidship::<f64>::new(input.mass, input.izz, x_g)?;
    let generated = models::PlanarMidship::<f64>::new(input.mass, input.izz, x_g)?;
    let (state, load) = (input.state(), input.load());
    let d = model.rhs_body_at_midship(&Vector6::from(state), &Vector3::from(load));
    Ok(Evaluation {
        generated: named(&PLANAR_BODY_KEYS, &generated.rhs(&state, &load)),
        generic: named(&PLANAR_BODY_KEYS, d.as_slice()),
    })
}

fn planar_space(input: &PlanarSpaceInput) -> Result<Evaluation> {
    let model = PlanarBody::<f64>::new(input.mass, input.izz)?;
    let generated = models::PlanarSpaceFixed::<f64>::new(input.mass, input.izz)?;
    let s = &input.state;
    let state = [s.x, s.y, s.psi, s.x_dot, s.y_dot, s.psi_dot];
    let load = [input.force[0], input.force[1], input.moment];
    let d = model.rhs_space_fixed(&Vector6::from(state), &Vector3::from(load));
    let keys = ["x_dot", "y_dot", "psi_dot", "x_ddot", "y_ddot", "psi_ddot"];
    Ok(Evaluation {
        generated: named(&keys, &generated.rhs(&state, &load)),
        generic: named(&keys, d.as_slice()),
    })
}

const EULER_KEYS: [&str; 12] = [
    "u_dot",
    "v_dot",
    "w_dot",
    "p_dot",
    "q_dot",
    "r_dot",
    "x_dot",
    "y_dot",
    "z_dot",
    "phi_dot",
    "theta_dot",
    "psi_dot",
];

/// Quaternion variants print the Euler-angle keys (rates by 4.60) and then these.
const QUATERNION_RATE_KEYS: [&str; 4] = ["q0_dot", "q1_dot", "q2_dot", "q3_dot"];

fn spatial(input: &SpatialInput, symmetry: Symmetry, kinematics: Kinematics) -> Result<Evaluation> {
    let matrix = Matrix3::from_fn(|r, c| input.inertia[r][c]);
    let body = RigidBody::<f64>::from_matrix(input.mass, matrix)?;
    let tensor = InertiaTensor::from_matrix(matrix)?;
    let state = spatial_state(&input.state);
    let (force, moment) = (Vector3::from(input.force), Vector3::from(input.moment));
    let pitch = check_pitch(input.state.theta, MIN_COS_PITCH);
    if kinematics == Kinematics::Euler {
        pitch
            .clone()
            .context("Euler kinematics refused (use --kinematics quaternion near pitch ±90°)")?;
    }
    let (mut generated, mut generic) = (Vec::new(), Vec::new());
    if pitch.is_ok() {
        let euler: [f64; 12] = state.into();
        let g = generated_spatial(
            symmetry,
            Kinematics::Euler,
            input.mass,
            &tensor,
            &euler,
            &input.force,
            &input.moment,
        )?;
        generated = named(&EULER_KEYS, &g);
        generic = named(
            &EULER_KEYS,
            body.rhs_euler(&state, &force, &moment).as_slice(),
        );
    }
    if kinematics == Kinematics::Quaternion {
        let x = euler_state_to_quaternion_state(&state);
        let quaternion: [f64; 13] = x.into();
        let g = generated_spatial(
            symmetry,
            Kinematics::Quaternion,
            input.mass,
            &tensor,
            &quaternion,
            &input.force,
            &input.moment,
        )?;
        let d = body.rhs_quaternion(&x, &force, &moment);
        if pitch.is_err() {
            // At pitch ±90° the Euler rates (4.60) do not exist; the rest is well defined.
            generated = named(&EULER_KEYS[..9], &g[..9]);
            generic = named(&EULER_KEYS[..9], &d.as_slice()[..9]);
        }
        for (i, key) in QUATERNION_RATE_KEYS.iter().enumerate() {
            generated.push((key, g[9 + i]));
            generic.push((key, d[9 + i]));
        }
    }
    Ok(Evaluation { generated, generic })
}

/// The generated variant of the symmetry class and kinematics, at `state`.
fn generated_spatial(
    symmetry: Symmetry,
    kinematics: Kinematics,
    mass: f64,
    tensor: &InertiaTensor,
    state: &[f64],
    force: &[f64; 3],
    moment: &[f64; 3],
) -> Result<Vec<f64>> {
    let model = AnyModel::spatial(symmetry, kinematics, mass, tensor)?;
    let input = [
        force[0], force[1], force[2], moment[0], moment[1], moment[2],
    ];
    Ok(model.rhs(state, &input)?)
}

fn spatial_state(s: &SpatialState) -> EulerState<f64> {
    let values = [
        s.u, s.v, s.w, s.p, s.q, s.r, 0.0, 0.0, 0.0, s.phi, s.theta, s.psi,
    ];
    EulerState::from_column_slice(&values)
}

fn named(keys: &[&'static str], values: &[f64]) -> Vec<(&'static str, f64)> {
    keys.iter().copied().zip(values.iter().copied()).collect()
}
