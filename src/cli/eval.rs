//! `eom eval`: one evaluation of a model's right-hand side at a state given in JSON.
//!
//! This is how a user (or a script) checks a single point by hand: the generated model and the
//! generic nalgebra form are both evaluated and their derivatives printed as JSON objects under
//! the keys `"generated"` and `"generic"`, one key per state derivative, in the order of the
//! state. The generated models refuse a product of inertia that their symmetry class prunes. Everything the input
//! gets wrong (a missing or unknown key, a number out of range, an impossible body, a product
//! of inertia that the chosen symmetry class says is zero) is an error naming it.

use anyhow::{Context, Result, bail};
use eom::eval::{PendulumInput, PlanarInput, PlanarSpaceInput, SpatialInput, SpatialState};
use eom::generic::{
    EulerState, Pendulum, PlanarBody, PlanarMidship, RigidBody, check_pitch,
    euler_state_to_quaternion_state,
};
use eom::models::{self, AnyModel, Family, Kinematics, Model as _, Symmetry};
use eom::{InertiaTensor, PendulumParameters};
use nalgebra::{Matrix3, Vector2, Vector3, Vector6};
use serde::Serialize as SerializeDerive;
use serde::de::DeserializeOwned;
use serde::ser::{Serialize, SerializeMap, Serializer};
use std::io::Read;
use std::path::PathBuf;

/// The smallest `|cos θ|` at which `--kinematics euler` still answers: only an input pitch of
/// ±90° to within about 1e-12 rad is refused, so that states within 1e-6 of the singularity
/// can still be compared.
const MIN_COS_PITCH: f64 = 1e-12;

/// Options of `eom eval`.
#[derive(clap::Args)]
pub struct Args {
    /// Which equations to evaluate: the model family.
    #[arg(long, value_parser = super::values::family())]
    model: Family,
    /// Symmetry class of a spatial body; the products it says are zero must be zero.
    #[arg(long, value_parser = super::values::symmetry(), default_value = "full")]
    symmetry: Symmetry,
    /// Attitude kinematics of a spatial body.
    #[arg(long, value_parser = super::values::kinematics(), default_value = "euler")]
    kinematics: Kinematics,
    /// The JSON input file, or `-` for standard input.
    #[arg(long)]
    input: PathBuf,
}

/// Evaluates the chosen model and prints the derivative.
pub fn run(args: Args) -> Result<()> {
    let text = read_input(&args.input)?;
    let derivative = match args.model {
        Family::Pendulum => pendulum(&parse(&text)?)?,
        Family::PlanarAtG => planar_g(&parse(&text)?)?,
        Family::PlanarMidship => planar_midship(&parse(&text)?)?,
        Family::PlanarSpaceFixed => planar_space(&parse(&text)?)?,
        Family::Spatial => spatial(&parse(&text)?, args.symmetry, args.kinematics)?,
        Family::Top => bail!(
            "eval does not cover the top family yet: it has no generic form to print beside \
             the generated one"
        ),
    };
    let all = derivative.generated.iter().chain(&derivative.generic);
    if let Some((key, value)) = all.into_iter().find(|(_, x)| !x.is_finite()) {
        bail!("the derivative {key} is not finite ({value}); the state is outside the model");
    }
    let output = Output {
        generated: Ordered(&derivative.generated),
        generic: Ordered(&derivative.generic),
    };
    println!("{}", serde_json::to_string_pretty(&output)?);
    Ok(())
}

fn read_input(path: &PathBuf) -> Result<String> {
    let mut text = String::new();
    if path.as_os_str() == "-" {
        std::io::stdin()
            .read_to_string(&mut text)
            .context("reading the input from standard input")?;
    } else {
        text = std::fs::read_to_string(path)
            .with_context(|| format!("reading the input file {}", path.display()))?;
    }
    Ok(text)
}

/// The input JSON as the type of the model's input, every number read to the nearest binary64
/// (`eom::eval::parse`).
fn parse<T: DeserializeOwned>(text: &str) -> Result<T> {
    eom::eval::parse(text).context("parsing the input JSON")
}

/// The printed object; a second key can sit beside `generic`.
#[derive(SerializeDerive)]
struct Output<'a> {
    generated: Ordered<'a>,
    generic: Ordered<'a>,
}

/// One model evaluated both ways, keys in the state's order.
struct Evaluation {
    generated: Vec<(&'static str, f64)>,
    generic: Vec<(&'static str, f64)>,
}

/// Named values serialised as a JSON object in the order given (the state's order).
struct Ordered<'a>(&'a [(&'static str, f64)]);

impl Serialize for Ordered<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut map = serializer.serialize_map(Some(self.0.len()))?;
        // Keys are in the state's order, which is why this is not a BTreeMap.
        for (key, value) in self.0 {
            map.serialize_entry(key, value)?;
        }
        map.end()
    }
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
