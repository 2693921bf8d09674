//! The JSON inputs of `eom eval`, and the one function that reads them.
//!
//! `eom eval` evaluates one model at one state given as JSON; this module is what it reads, so
//! that the reading can be tested without a process per number. Every key is required unless
//! said otherwise, and an unknown key is an error (`deny_unknown_fields`).
//!
//! Every number is read to the nearest binary64: `serde_json` is built with its
//! `float_roundtrip` feature, without which it reads some decimals one ulp off. Next to pitch
//! ±90° one ulp of θ is a relative change of `ε/|cos θ|` in sec θ and tan θ: 7e-9 of ψ̇ at
//! `cos θ ≈ 3e-8`, far more than any rounding of the arithmetic.
//!
//! ```
//! use eom::eval::{SpatialInput, parse};
//! let input: SpatialInput = parse(
//!     r#"{"mass": 2, "inertia": [[2, 0, 0], [0, 3, 0], [0, 0, 4]],
//!         "state": {"u": 1, "v": 0, "w": 0, "p": 0, "q": 0, "r": 0.5,
//!                   "phi": 0, "theta": 1.5707962967948965, "psi": 0},
//!         "force": [0, 0, 0], "moment": [0, 0, 0]}"#,
//! )?;
//! assert_eq!(input.state.theta, 1.5707962967948965);
//! # Ok::<(), serde_json::Error>(())
//! ```

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
