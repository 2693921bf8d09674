//! The keys of a catalog scene ([`SceneFile`](super::file::SceneFile)), in the order a
//! template writes them. Each family's keys in `[body]`, `[initial]`, `[loads]` and `[model]`
//! are what the scene checker allows there; a key that two families read differently (a force
//! of three entries or of two) has an entry for each. Beside them, what the reference page
//! says of catalog scenes: its section's first paragraph, how such a scene runs, and the
//! state columns of each family's layouts.

pub mod loads;

use crate::models::{ENERGY_UNIT, Family, ModelInfo, TIME_UNIT, state_with_unit, with_unit};
use crate::scene::reference::{Choices, Frame, Key, Kind, Required, SceneFamily, Shown};

const PENDULUM: SceneFamily = SceneFamily::Catalog(Family::Pendulum);
const PLANAR_G: SceneFamily = SceneFamily::Catalog(Family::PlanarAtG);
const PLANAR_MIDSHIP: SceneFamily = SceneFamily::Catalog(Family::PlanarMidship);
const PLANAR_SPACE: SceneFamily = SceneFamily::Catalog(Family::PlanarSpaceFixed);
const SPATIAL: SceneFamily = SceneFamily::Catalog(Family::Spatial);
const TOP: SceneFamily = SceneFamily::Catalog(Family::Top);

/// The six catalog families, in the catalog's order: the body's templates.
pub(super) const ALL: &[SceneFamily] = &[
    PENDULUM,
    PLANAR_G,
    PLANAR_MIDSHIP,
    PLANAR_SPACE,
    SPATIAL,
    TOP,
];
const PLANAR: &[SceneFamily] = &[PLANAR_G, PLANAR_MIDSHIP, PLANAR_SPACE];
const PLANAR_AND_PENDULUM: &[SceneFamily] = &[PENDULUM, PLANAR_G, PLANAR_MIDSHIP, PLANAR_SPACE];
const ATTITUDE: &[SceneFamily] = &[SPATIAL, TOP];

/// What a catalog scene's keys are, before them.
pub(super) const INTRO: &str = "The keys of the six catalog families, table by table: each key's \
type, its unit, the axes a vector is in, its default, and whether it is required. A key that \
families read differently has a row for each. Beside them, a catalog scene takes the keys \
every scene takes.";

/// How a catalog scene runs: the notes after its keys.
pub(super) const NOTES: &str = "## How a catalog scene runs\n\n\
- **Model selection.** `model.symmetry = \"auto\"` runs the most pruned class the tensor \
allows; the summary says which variant ran, why, and its operations per call against the \
full variant's.\n\
- **Integrators.** `lie-midpoint` applies to a spatial body with quaternion kinematics that is \
free or under uniform gravity alone, which acts at G and leaves the rotation torque-free (the \
rotation by the geometric integrator, the translation exactly). A fixed-step method \
integrates each interval between rows and a load table's times in equal steps of at most \
`step`, so that rows land on their times and no step straddles a change of load; an adaptive \
one places rows by dense output, and is cut at a table's times likewise.\n\
- **Stop conditions.** `integrator.stop_when` ends a run where its condition first holds, \
found on the step (dense output, or the step retaken) to adjacent doubles; the last row is \
at that time.\n\
- **Energy.** Where every load has a potential (gravity, buoyancy, constant space forces, the \
constant planar and pendulum moments), the trajectory has potential and total energy and the \
summary an energy drift.\n\
- **Stopping early.** A state or a load input that turns NaN or infinite stops the run, named \
with its time. Ctrl-C (or SIGTERM) ends a run at its next row; a second one ends the process \
at once. A run that stops early keeps what it ran: every row, a summary with `\"interrupted\": \
true` or the `\"error\"`, and the plots. Gimbal lock and a fixed step too long for the rate of \
turn stop a run as `model.kinematics` and `integrator.step` say.\n";

/// A catalog scene's trajectory.csv: the columns every one writes, then the state columns of
/// each family's layouts, as the reference page says it.
pub(super) fn columns() -> String {
    let mut out = format!(
        "One row per output time. Every column is labelled `name[unit]`: `{}`, the model's \
         state in its layout, `{}`, and `{}`, `{}` where the loads have a potential. Angles \
         are in radians, `-` marks a dimensionless column. The state columns by model:\n\n\
         | family | kinematics | state columns |\n|---|---|---|\n",
        with_unit("t", TIME_UNIT),
        with_unit("kinetic_energy", ENERGY_UNIT),
        with_unit("potential_energy", ENERGY_UNIT),
        with_unit("total_energy", ENERGY_UNIT),
    );
    for family in Family::ALL {
        let mut layouts: Vec<(&str, &[&str])> = Vec::new();
        for info in ModelInfo::of_family(family) {
            if !layouts.iter().any(|(_, state)| *state == info.state) {
                let kinematics = info.kinematics.map_or("—", |k| k.name());
                layouts.push((kinematics, info.state));
            }
        }
        for (variant, state) in layouts {
            let columns: Vec<String> = state
                .iter()
                .map(|name| format!("`{}`", state_with_unit(&name.to_lowercase())))
                .collect();
            out.push_str(&format!(
                "| `{}` | {variant} | {} |\n",
                family.name(),
                columns.join(", ")
            ));
        }
    }
    out
}

/// Every key of a catalog body's scene, a list a part, in the order a template writes them.
pub static EVERY_KEY: &[&[Key]] = &[KEYS, loads::LOADS, LATER];

/// The keys before `[loads]`: the title, `[body]`, `[model]`, `[initial]`.
pub static KEYS: &[Key] = &[
    Key::shared(
        "title",
        ALL,
        "\"A {family} scene from eom new\"",
        Shown::Set,
    ),
    // [body]
    Key {
        path: "body.i0",
        families: &[PENDULUM],
        unit: "kg m²",
        required: Required::Yes,
        description: "I₀, the moment of inertia about the pivot (4.24).",
        example: "2.0",
        ..Key::BLANK
    },
    Key {
        path: "body.mass",
        families: &[PENDULUM, PLANAR_G, PLANAR_MIDSHIP, PLANAR_SPACE, TOP],
        unit: "kg",
        required: Required::Yes,
        description: "M, the body's mass.",
        example: "1.0",
        ..Key::BLANK
    },
    Key {
        path: "body.mass",
        families: &[SPATIAL],
        unit: "kg",
        required: Required::When("unless body.file is given"),
        description: "M, the body's mass.",
        example: "1.0",
        ..Key::BLANK
    },
    Key {
        path: "body.inertia",
        families: &[SPATIAL],
        kind: Kind::Tensor,
        unit: "kg m²",
        frame: Frame::Body,
        required: Required::When("unless body.file is given"),
        description: "The inertia tensor about G, [[Ixx, Ixy, Ixz], [Ixy, Iyy, Iyz], [Ixz, \
                      Iyz, Izz]]: symmetric, each moment at most the sum of the other two. The \
                      products are the tensor's off-diagonal entries with the chapter's sign, \
                      Ixy = −∫xy dm, Iyz = −∫yz dm, Ixz = −∫xz dm (4.12–4.14), so H = [I]ω: a \
                      CAD program that reports the product integral +∫xy dm is entered with \
                      its sign changed.",
        example: "[[2.0, 0.0, 0.0], [0.0, 3.0, 0.0], [0.0, 0.0, 4.5]]",
        ..Key::BLANK
    },
    Key {
        path: "body.inertia",
        families: &[TOP],
        kind: Kind::Tensor,
        unit: "kg m²",
        frame: Frame::Body,
        required: Required::Yes,
        description: "The inertia tensor about G in principal axes, [[Ixx, 0, 0], [0, Iyy, 0], \
                      [0, 0, Izz]], the body z-axis through the pivot and G.",
        example: "[[0.25, 0.0, 0.0], [0.0, 0.25, 0.0], [0.0, 0.0, 0.2]]",
        ..Key::BLANK
    },
    Key {
        path: "body.file",
        families: &[SPATIAL],
        kind: Kind::Text(Choices::Free),
        description: "A body description as `eom mass` reads it (parts, each with its offset \
                      and rotation), relative to the scene file: its mass and its tensor about \
                      G stand for body.mass and body.inertia, which the scene then leaves out.",
        example: "\"bodies/ship_blocks.toml\"",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "body.izz",
        families: PLANAR,
        unit: "kg m²",
        required: Required::Yes,
        description: "I_zz, the moment of inertia about the vertical axis through G.",
        example: "3.0",
        ..Key::BLANK
    },
    Key {
        path: "body.x_g",
        families: &[PLANAR_MIDSHIP],
        unit: "m",
        frame: Frame::Body,
        required: Required::Yes,
        description: "x_G, how far G lies ahead of midship, this family's body origin (4.45).",
        example: "0.1",
        ..Key::BLANK
    },
    Key {
        path: "body.h",
        families: &[PENDULUM],
        unit: "m",
        required: Required::Yes,
        description: "h, the distance from the pivot to G (4.24).",
        example: "0.5",
        ..Key::BLANK
    },
    Key {
        path: "body.h",
        families: &[TOP],
        unit: "m",
        frame: Frame::Body,
        required: Required::Yes,
        description: "h, the distance from the pivot to G along the body z-axis.",
        example: "0.5",
        ..Key::BLANK
    },
    Key {
        path: "body.g",
        families: &[PENDULUM, TOP],
        unit: "m/s²",
        required: Required::Yes,
        description: "g, gravity: the body's weight acts at G (the top's along −Z of its own \
                      space axes, which have Z up).",
        example: "9.81",
        ..Key::BLANK
    },
    // [model]
    Key {
        path: "model.family",
        families: ALL,
        kind: Kind::Text(Choices::Families),
        required: Required::Yes,
        description: "Which equations run; a key of another family is refused, not ignored.",
        example: "\"{family}\"",
        ..Key::BLANK
    },
    Key {
        path: "model.symmetry",
        families: &[SPATIAL],
        kind: Kind::Text(Choices::Symmetries),
        default: "auto",
        description: "Which spatial model runs. `auto` runs the most pruned class the tensor \
                      allows: every product of inertia the class sets to zero must be zero to \
                      1e-12 of the largest moment (eom::models::PRODUCT_TOLERANCE). A class \
                      named runs as named, if the tensor has zeros where it prunes. The summary \
                      says which variant ran, why, and its operations per call against the full \
                      variant's.",
        example: "\"auto\"",
        ..Key::BLANK
    },
    Key {
        path: "model.kinematics",
        families: ATTITUDE,
        kind: Kind::Text(Choices::Kinematics),
        default: "quaternion",
        description: "How the attitude is carried: a unit quaternion (q0…q3 in the state) or \
                      Euler angles (φ, θ, ψ by 4.60), singular at pitch ±90°. With `euler` the \
                      run stops, naming the time and the pitch, when a step ends with the pitch \
                      within ε|θ|/η of ±90° or crosses ±90°: there the rounding of θ alone, \
                      amplified by 4.60's sec θ, would make the attitude rates err by more than \
                      η = min(rtol, 1e-8) (1e-8 for a fixed step; 3.5e-8 rad at 90°). \
                      scenes/looping.toml in Euler angles stops at 1.254 s, agreeing with the \
                      quaternion run to 1e-10 until then.",
        example: "\"quaternion\"",
        ..Key::BLANK
    },
    // [initial]: what is left out is zero, the identity attitude.
    Key {
        path: "initial.theta_deg",
        families: &[PENDULUM],
        unit: "deg",
        default: "0",
        description: "θ, the angle of OG from the downward vertical.",
        example: "90.0",
        ..Key::BLANK
    },
    Key {
        path: "initial.theta_dot",
        families: &[PENDULUM],
        unit: "rad/s",
        default: "0",
        description: "θ̇, the angular rate.",
        example: "0.0",
        ..Key::BLANK
    },
    Key {
        path: "initial.u",
        families: PLANAR,
        unit: "m/s",
        frame: Frame::Body,
        default: "0",
        description: "Surge, the body origin's velocity along the body x-axis (the origin is G; \
                      midship for planar-midship). In body axes for every planar family: a \
                      planar-space scene's state holds the space components Ẋ, Ẏ, made from \
                      u, v and psi_deg.",
        example: "1.0",
        ..Key::BLANK
    },
    Key {
        path: "initial.v",
        families: PLANAR,
        unit: "m/s",
        frame: Frame::Body,
        default: "0",
        description: "Sway, the body origin's velocity along the body y-axis.",
        example: "0.0",
        ..Key::BLANK
    },
    Key {
        path: "initial.x_dot",
        families: PLANAR,
        unit: "m/s",
        frame: Frame::Space,
        default: "0",
        description: "Ẋ, the body origin's velocity north, instead of u and v (never both): \
                      turned into body axes through psi_deg.",
        example: "1.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "initial.y_dot",
        families: PLANAR,
        unit: "m/s",
        frame: Frame::Space,
        default: "0",
        description: "Ẏ, the body origin's velocity east, with initial.x_dot.",
        example: "0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "initial.r",
        families: PLANAR,
        unit: "rad/s",
        default: "0",
        description: "r, the yaw rate about the vertical (body z and space Z are parallel).",
        example: "0.1",
        ..Key::BLANK
    },
    Key {
        path: "initial.x",
        families: PLANAR,
        unit: "m",
        frame: Frame::Space,
        default: "0",
        description: "X, the body origin's position north.",
        example: "0.0",
        ..Key::BLANK
    },
    Key {
        path: "initial.y",
        families: PLANAR,
        unit: "m",
        frame: Frame::Space,
        default: "0",
        description: "Y, the body origin's position east.",
        example: "0.0",
        ..Key::BLANK
    },
    Key {
        path: "initial.psi_deg",
        families: PLANAR,
        unit: "deg",
        frame: Frame::Attitude,
        default: "0",
        description: "ψ, the heading: from X (north) to the body x-axis, positive towards Y \
                      (east).",
        example: "30.0",
        ..Key::BLANK
    },
    Key {
        path: "initial.velocity",
        families: &[SPATIAL],
        kind: Kind::Numbers("3: u, v, w"),
        unit: "m/s",
        frame: Frame::Body,
        default: "zero",
        description: "The velocity of G along the body axes.",
        example: "[1.0, 0.0, 0.0]",
        ..Key::BLANK
    },
    Key {
        path: "initial.velocity_space",
        families: &[SPATIAL],
        kind: Kind::Numbers("3: Ẋ, Ẏ, Ż"),
        unit: "m/s",
        frame: Frame::Space,
        default: "zero",
        description: "The velocity of G in space axes, instead of initial.velocity (never \
                      both): turned into body axes through attitude_deg, v = Eᵀ V (4.57).",
        example: "[1.0, 0.0, 0.0]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "initial.rates",
        families: &[SPATIAL],
        kind: Kind::Numbers("3: p, q, r"),
        unit: "rad/s",
        frame: Frame::Body,
        default: "zero",
        description: "The angular velocity about the body axes.",
        example: "[0.1, 0.0, 2.0]",
        ..Key::BLANK
    },
    Key {
        path: "initial.rates",
        families: &[TOP],
        kind: Kind::Numbers("3: p, q, r"),
        unit: "rad/s",
        frame: Frame::Body,
        default: "zero",
        description: "The angular velocity about the body axes through the pivot.",
        example: "[0.0, 0.0, 20.0]",
        ..Key::BLANK
    },
    Key {
        path: "initial.position",
        families: &[SPATIAL],
        kind: Kind::Numbers("3: x, y, z"),
        unit: "m",
        frame: Frame::Space,
        default: "zero",
        description: "The position of G: x north, y east, z down.",
        example: "[0.0, 0.0, 0.0]",
        ..Key::BLANK
    },
    Key {
        path: "initial.attitude_deg",
        families: &[SPATIAL],
        kind: Kind::Numbers("3: roll, pitch, yaw"),
        unit: "deg",
        frame: Frame::Attitude,
        default: "zero",
        description: "The Euler angles φ, θ, ψ that turn space axes into body axes: yaw ψ \
                      about z, then pitch θ about the new y, then roll φ about the new x \
                      (4.53–4.57). A quaternion run starts from their quaternion.",
        example: "[0.0, 10.0, 30.0]",
        ..Key::BLANK
    },
    Key {
        path: "initial.attitude_deg",
        families: &[TOP],
        kind: Kind::Numbers("3: roll, pitch, yaw"),
        unit: "deg",
        frame: Frame::Attitude,
        default: "zero",
        description: "The Euler angles from the top's own space axes, which have Z up: zero \
                      stands the top upright, its body z-axis along Z.",
        example: "[28.6, 0.0, 0.0]",
        ..Key::BLANK
    },
];

/// The keys after `[loads]`: the integrator, the output, the linearisation, the sweep and the
/// Monte Carlo.
pub static LATER: &[Key] = &[
    // [integrator]
    Key::shared("integrator.method", ALL, "\"dop853\"", Shown::Set),
    Key::shared("integrator.rtol", ALL, "1e-9", Shown::Set),
    Key::shared("integrator.atol", ALL, "1e-9", Shown::Set),
    Key::shared("integrator.step", ALL, "0.001", Shown::Commented),
    Key {
        path: "integrator.end_time",
        families: ALL,
        unit: "s",
        required: Required::Yes,
        description: "The end of the run, which starts at t = 0.",
        example: "1.0",
        ..Key::BLANK
    },
    Key::shared("integrator.stop_when", ALL, "\"t > 1e9\"", Shown::Commented),
    Key::shared("integrator.max_steps", ALL, "1_000_000", Shown::Set),
    // [output]
    Key {
        path: "output.every",
        families: ALL,
        unit: "s",
        default: "end_time/500",
        description: "Trajectory rows at exactly t = k·every (at most 10⁸ rows).",
        example: "0.01",
        ..Key::BLANK
    },
    // [linear]
    Key {
        path: "linear.trim",
        families: &[PENDULUM],
        kind: Kind::Names("state entries or inputs"),
        description: "Free variables of `eom linear`: state entries or inputs solved for, by Newton's method on the reduced state, so that the operating point is an equilibrium of it (a clear error when it does not converge).",
        example: "[\"M_O\"]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "linear.trim",
        families: &[PLANAR_G, PLANAR_MIDSHIP],
        kind: Kind::Names("state entries or inputs"),
        description: "Free variables of `eom linear`: state entries or inputs solved for, by Newton's method on the reduced state, so that the operating point is an equilibrium of it (a clear error when it does not converge).",
        example: "[\"F_x\"]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "linear.trim",
        families: &[PLANAR_SPACE],
        kind: Kind::Names("state entries or inputs"),
        description: "Free variables of `eom linear`: state entries or inputs solved for, by Newton's method on the reduced state, so that the operating point is an equilibrium of it (a clear error when it does not converge).",
        example: "[\"F_X\"]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "linear.trim",
        families: ATTITUDE,
        kind: Kind::Names("state entries or inputs"),
        description: "Free variables of `eom linear`: state entries or inputs solved for, by Newton's method on the reduced state, so that the operating point is an equilibrium of it (a clear error when it does not converge).",
        example: "[\"M_x\"]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "linear.at.*",
        families: &[PENDULUM],
        kind: Kind::Table("state entries and inputs by name, and values"),
        description: "The operating point of `eom linear`, where it differs from [initial]: state entries and inputs by the model's names (as trajectory.csv names its columns, or as the model does: `theta`, `M_O`), in SI units and radians; an input is added to what the loads give. `eom linear` linearises there, by default at the initial state.",
        example: "theta = 0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "linear.at.*",
        families: PLANAR,
        kind: Kind::Table("state entries and inputs by name, and values"),
        description: "The operating point of `eom linear`, where it differs from [initial]: state entries and inputs by the model's names (as trajectory.csv names its columns, or as the model does: `theta`, `M_O`), in SI units and radians; an input is added to what the loads give. `eom linear` linearises there, by default at the initial state.",
        example: "r = 0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "linear.at.*",
        families: &[SPATIAL],
        kind: Kind::Table("state entries and inputs by name, and values"),
        description: "The operating point of `eom linear`, where it differs from [initial]: state entries and inputs by the model's names (as trajectory.csv names its columns, or as the model does: `theta`, `M_O`), in SI units and radians; an input is added to what the loads give. `eom linear` linearises there, by default at the initial state.",
        example: "p = 6.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "linear.at.*",
        families: &[TOP],
        kind: Kind::Table("state entries and inputs by name, and values"),
        description: "The operating point of `eom linear`, where it differs from [initial]: state entries and inputs by the model's names (as trajectory.csv names its columns, or as the model does: `theta`, `M_O`), in SI units and radians; an input is added to what the loads give. `eom linear` linearises there, by default at the initial state.",
        example: "r = 60.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "linear.outputs",
        families: &[PENDULUM],
        kind: Kind::Names("state entries"),
        description: "Outputs of the linear model `eom linear` writes (y = C x + D u in linear.json and linear.mat): state entries by the model's names, each in the reduced state at the point; C picks them, D is zero. By default every entry of the reduced state (C the identity).",
        example: "[\"theta\"]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "linear.outputs",
        families: &[PLANAR_G, PLANAR_MIDSHIP],
        kind: Kind::Names("state entries"),
        description: "Outputs of the linear model `eom linear` writes (y = C x + D u in linear.json and linear.mat): state entries by the model's names, each in the reduced state at the point; C picks them, D is zero. By default every entry of the reduced state (C the identity).",
        example: "[\"v\", \"r\"]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "linear.outputs",
        families: &[PLANAR_SPACE],
        kind: Kind::Names("state entries"),
        description: "Outputs of the linear model `eom linear` writes (y = C x + D u in linear.json and linear.mat): state entries by the model's names, each in the reduced state at the point; C picks them, D is zero. By default every entry of the reduced state (C the identity).",
        example: "[\"X_dot\", \"psi_dot\"]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "linear.outputs",
        families: ATTITUDE,
        kind: Kind::Names("state entries"),
        description: "Outputs of the linear model `eom linear` writes (y = C x + D u in linear.json and linear.mat): state entries by the model's names, each in the reduced state at the point; C picks them, D is zero. By default every entry of the reduced state (C the identity).",
        example: "[\"p\", \"q\"]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    // [sweep]
    Key::shared(
        "sweep.*",
        ALL,
        "\"body.mass\" = { from = 1.0, to = 3.0, count = 5 }",
        Shown::Commented,
    ),
    // [uncertainty]
    Key::shared("uncertainty.cases", ALL, "1000", Shown::Commented),
    Key::shared("uncertainty.seed", ALL, "1", Shown::Commented),
    Key::shared(
        "uncertainty.vary.*",
        ALL,
        "\"body.mass\" = { distribution = \"normal\", sigma_relative = 0.05, truncate = 3.0 }",
        Shown::Commented,
    ),
];
