//! `eom eval`: one evaluation of a model's right-hand side at a state given in JSON.
//!
//! This is how a user (or a script) checks a single point by hand: the generic nalgebra form
//! of the chosen model is evaluated and its derivative printed as a JSON object under the key
//! `"generic"`, one key per state derivative, in the order of the state. Everything the input
//! gets wrong (a missing or unknown key, a number out of range, an impossible body, a product
//! of inertia that the chosen symmetry class says is zero) is an error naming it.

use anyhow::{Context, Result, bail};
use clap::ValueEnum;
use eom::generic::{
    EulerState, Pendulum, PlanarBody, PlanarMidship, RigidBody, check_pitch,
    euler_state_to_quaternion_state,
};
use nalgebra::{Matrix3, Vector2, Vector3, Vector6};
use serde::de::DeserializeOwned;
use serde::ser::{Serialize, SerializeMap, Serializer};
use serde::{Deserialize, Serialize as SerializeDerive};
use std::io::Read;
use std::path::PathBuf;

/// The smallest `|cos θ|` at which `--kinematics euler` still answers: only an input pitch of
/// ±90° to within about 1e-12 rad is refused, so that states within 1e-6 of the singularity
/// can still be compared.
const MIN_COS_PITCH: f64 = 1e-12;

/// Options of `eom eval`.
#[derive(clap::Args)]
pub struct Args {
    /// Which equations to evaluate.
    #[arg(long, value_enum)]
    model: Model,
    /// Symmetry class of a spatial body; the products it says are zero must be zero.
    #[arg(long, value_enum, default_value = "full")]
    symmetry: Symmetry,
    /// Attitude kinematics of a spatial body.
    #[arg(long, value_enum, default_value = "euler")]
    kinematics: Kinematics,
    /// The JSON input file, or `-` for standard input.
    #[arg(long)]
    input: PathBuf,
}

/// The model families.
#[derive(Clone, Copy, ValueEnum)]
enum Model {
    /// Compound pendulum, 4.24.
    Pendulum,
    /// Planar, body-fixed at G, 4.43 + 4.44.
    PlanarG,
    /// Planar, body-fixed at midship, 4.46 + 4.44.
    PlanarMidship,
    /// Planar, space-fixed, 4.39.
    PlanarSpace,
    /// Spatial 6-DOF, 4.49 + 4.51 with Euler angles or a quaternion.
    Spatial,
}

/// Which products of inertia a spatial body may have.
#[derive(Clone, Copy, ValueEnum)]
enum Symmetry {
    /// All products free (4.51).
    Full,
    /// Symmetric about the xz-plane: `Ixy = Iyz = 0`, `Ixz` free.
    Xz,
    /// Principal axes: all products zero (4.52).
    Principal,
}

/// How a spatial body's attitude is carried.
#[derive(Clone, Copy, ValueEnum)]
enum Kinematics {
    /// Euler angles (4.57, 4.60).
    Euler,
    /// Unit quaternion, `q̇ = ½ q ⊗ (0, ω)`.
    Quaternion,
}

/// Evaluates the chosen model and prints the derivative.
pub fn run(args: Args) -> Result<()> {
    let text = read_input(&args.input)?;
    let derivative = match args.model {
        Model::Pendulum => pendulum(&parse(&text)?)?,
        Model::PlanarG => planar_g(&parse(&text)?)?,
        Model::PlanarMidship => planar_midship(&parse(&text)?)?,
        Model::PlanarSpace => planar_space(&parse(&text)?)?,
        Model::Spatial => spatial(&parse(&text)?, args.symmetry, args.kinematics)?,
    };
    if let Some((key, value)) = derivative.iter().find(|(_, x)| !x.is_finite()) {
        bail!("the derivative {key} is not finite ({value}); the state is outside the model");
    }
    let output = Output {
        generic: Ordered(&derivative),
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

fn parse<T: DeserializeOwned>(text: &str) -> Result<T> {
    serde_json::from_str(text).context("parsing the input JSON")
}

/// The printed object; a second key can sit beside `generic`.
#[derive(SerializeDerive)]
struct Output<'a> {
    generic: Ordered<'a>,
}

/// Named values serialised as a JSON object in the order given (the state's order).
struct Ordered<'a>(&'a [(&'static str, f64)]);

impl Serialize for Ordered<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut map = serializer.serialize_map(Some(self.0.len()))?;
        for (key, value) in self.0 {
            map.serialize_entry(key, value)?;
        }
        map.end()
    }
}

/// Input of `--model pendulum`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct PendulumInput {
    i0: f64,
    mass: f64,
    g: f64,
    h: f64,
    state: PendulumState,
    #[serde(default)]
    moment: f64,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct PendulumState {
    theta: f64,
    theta_dot: f64,
}

fn pendulum(input: &PendulumInput) -> Result<Vec<(&'static str, f64)>> {
    let model = Pendulum::<f64>::new(input.i0, input.mass, input.g, input.h)?;
    let state = Vector2::new(input.state.theta, input.state.theta_dot);
    let d = model.rhs(&state, input.moment);
    Ok(vec![("theta_dot", d[0]), ("theta_ddot", d[1])])
}

/// Input of the body-fixed planar models: `force` is `(F_x, F_y)` (or `(X, Y)`) in body
/// axes, `moment` about the origin (G or midship).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct PlanarInput {
    mass: f64,
    izz: f64,
    #[serde(default)]
    x_g: Option<f64>,
    state: PlanarBodyState,
    force: [f64; 2],
    moment: f64,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct PlanarBodyState {
    u: f64,
    v: f64,
    r: f64,
    x: f64,
    y: f64,
    psi: f64,
}

const PLANAR_BODY_KEYS: [&str; 6] = ["u_dot", "v_dot", "r_dot", "x_dot", "y_dot", "psi_dot"];

impl PlanarInput {
    fn state(&self) -> Vector6<f64> {
        let s = &self.state;
        Vector6::new(s.u, s.v, s.r, s.x, s.y, s.psi)
    }

    fn load(&self) -> Vector3<f64> {
        Vector3::new(self.force[0], self.force[1], self.moment)
    }
}

fn planar_g(input: &PlanarInput) -> Result<Vec<(&'static str, f64)>> {
    if input.x_g.is_some() {
        bail!("key x_g belongs to --model planar-midship; at G the origin is G itself");
    }
    let model = PlanarBody::<f64>::new(input.mass, input.izz)?;
    let d = model.rhs_body_at_g(&input.state(), &input.load());
    Ok(named(&PLANAR_BODY_KEYS, d.as_slice()))
}

fn planar_midship(input: &PlanarInput) -> Result<Vec<(&'static str, f64)>> {
    let x_g = input
        .x_g
        .context("missing key x_g (position of G ahead of midship)")?;
    let model = PlanarMidship::<f64>::new(input.mass, input.izz, x_g)?;
    let d = model.rhs_body_at_midship(&input.state(), &input.load());
    Ok(named(&PLANAR_BODY_KEYS, d.as_slice()))
}

/// Input of `--model planar-space`: `force` is `(F_X, F_Y)` in space axes.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct PlanarSpaceInput {
    mass: f64,
    izz: f64,
    state: PlanarSpaceState,
    force: [f64; 2],
    moment: f64,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct PlanarSpaceState {
    x: f64,
    y: f64,
    psi: f64,
    x_dot: f64,
    y_dot: f64,
    psi_dot: f64,
}

fn planar_space(input: &PlanarSpaceInput) -> Result<Vec<(&'static str, f64)>> {
    let model = PlanarBody::<f64>::new(input.mass, input.izz)?;
    let s = &input.state;
    let state = Vector6::new(s.x, s.y, s.psi, s.x_dot, s.y_dot, s.psi_dot);
    let load = Vector3::new(input.force[0], input.force[1], input.moment);
    let d = model.rhs_space_fixed(&state, &load);
    let keys = ["x_dot", "y_dot", "psi_dot", "x_ddot", "y_ddot", "psi_ddot"];
    Ok(named(&keys, d.as_slice()))
}

/// Input of `--model spatial`: the inertia tensor about G in the chapter's convention
/// (products with the sign of 4.14), force and moment about G in body axes.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SpatialInput {
    mass: f64,
    inertia: [[f64; 3]; 3],
    state: SpatialState,
    force: [f64; 3],
    moment: [f64; 3],
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SpatialState {
    u: f64,
    v: f64,
    w: f64,
    p: f64,
    q: f64,
    r: f64,
    phi: f64,
    theta: f64,
    psi: f64,
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

const QUATERNION_KEYS: [&str; 13] = [
    "u_dot", "v_dot", "w_dot", "p_dot", "q_dot", "r_dot", "x_dot", "y_dot", "z_dot", "q0_dot",
    "q1_dot", "q2_dot", "q3_dot",
];

fn spatial(
    input: &SpatialInput,
    symmetry: Symmetry,
    kinematics: Kinematics,
) -> Result<Vec<(&'static str, f64)>> {
    let matrix = Matrix3::from_fn(|r, c| input.inertia[r][c]);
    check_symmetry(&matrix, symmetry)?;
    let body = RigidBody::<f64>::from_matrix(input.mass, matrix)?;
    let state = spatial_state(&input.state);
    let (force, moment) = (Vector3::from(input.force), Vector3::from(input.moment));
    match kinematics {
        Kinematics::Euler => {
            check_pitch(input.state.theta, MIN_COS_PITCH).context(
                "Euler kinematics refused (use --kinematics quaternion near pitch ±90°)",
            )?;
            let d = body.rhs_euler(&state, &force, &moment);
            Ok(named(&EULER_KEYS, d.as_slice()))
        }
        Kinematics::Quaternion => {
            let x = euler_state_to_quaternion_state(&state);
            let d = body.rhs_quaternion(&x, &force, &moment);
            Ok(named(&QUATERNION_KEYS, d.as_slice()))
        }
    }
}

fn spatial_state(s: &SpatialState) -> EulerState<f64> {
    let values = [
        s.u, s.v, s.w, s.p, s.q, s.r, 0.0, 0.0, 0.0, s.phi, s.theta, s.psi,
    ];
    EulerState::from_column_slice(&values)
}

/// Refuses a product of inertia that the symmetry class says is zero.
fn check_symmetry(matrix: &Matrix3<f64>, symmetry: Symmetry) -> Result<()> {
    let zero: &[(&str, usize, usize)] = match symmetry {
        Symmetry::Full => &[],
        Symmetry::Xz => &[("Ixy", 0, 1), ("Iyz", 1, 2)],
        Symmetry::Principal => &[("Ixy", 0, 1), ("Iyz", 1, 2), ("Ixz", 0, 2)],
    };
    for &(name, r, c) in zero {
        let (upper, lower) = (matrix[(r, c)], matrix[(c, r)]);
        if upper != 0.0 || lower != 0.0 {
            bail!("this symmetry class needs {name} = 0, but the inertia has {upper} and {lower}");
        }
    }
    Ok(())
}

fn named(keys: &[&'static str], values: &[f64]) -> Vec<(&'static str, f64)> {
    keys.iter().copied().zip(values.iter().copied()).collect()
}
