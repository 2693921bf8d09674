//! The scene file as written: TOML tables read by serde, every table closed to unknown keys.
//!
//! Nothing here is checked beyond types; [`super::BodyScene::from_file`] checks values, per
//! family, and names each offending key by its path in the file (`integrator.step`).

use crate::scene::envelope::LinearTable;
use serde::Deserialize;

/// A whole scene file.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneFile {
    /// What the scene is, for the summary and the plots.
    pub title: String,
    /// The body: mass properties, or the file that describes them.
    pub body: BodyTable,
    /// Which family of models, and for a spatial body which symmetry and kinematics.
    pub model: ModelTable,
    /// Where the body starts.
    #[serde(default)]
    pub initial: InitialTable,
    /// What acts on it.
    #[serde(default)]
    pub loads: LoadsTable,
    /// How to integrate.
    pub integrator: IntegratorTable,
    /// What to write.
    #[serde(default)]
    pub output: OutputTable,
    /// Values to vary, one run per combination (see [`crate::scene::sweep`]).
    #[serde(default)]
    pub sweep: Option<toml::Table>,
    /// A Monte Carlo's laws (read by [`crate::scene::uncertainty`], which runs each case).
    #[serde(default)]
    pub uncertainty: Option<crate::scene::uncertainty::UncertaintyTable>,
    /// Where `eom linear` linearises (see [`crate::linear`]).
    #[serde(default)]
    pub linear: Option<LinearTable>,
}

/// `[body]`: each family reads its own keys and refuses the others.
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BodyTable {
    /// M, kg.
    pub mass: Option<f64>,
    /// The tensor about G in body axes, kg m², with the chapter's signs (4.12–4.14).
    pub inertia: Option<[[f64; 3]; 3]>,
    /// A mass-properties description (`eom mass`), relative to the scene file.
    pub file: Option<String>,
    /// The pendulum's I₀ about the pivot, kg m².
    pub i0: Option<f64>,
    /// Gravity for the pendulum, m/s².
    pub g: Option<f64>,
    /// The pendulum's pivot-to-G distance, m.
    pub h: Option<f64>,
    /// A planar body's I_zz about G, kg m².
    pub izz: Option<f64>,
    /// A planar body's G ahead of midship, m (4.45).
    pub x_g: Option<f64>,
}

/// `[model]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ModelTable {
    /// The family's name (`eom::models::Family::name`).
    pub family: String,
    /// `auto` or a symmetry class (spatial only).
    pub symmetry: Option<String>,
    /// `euler` or `quaternion` (spatial and top).
    pub kinematics: Option<String>,
}

/// `[initial]`: each family reads its own keys and refuses the others; what is left out is
/// zero (the identity attitude).
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct InitialTable {
    /// Spatial: body velocity of G, (u, v, w), m/s.
    pub velocity: Option<[f64; 3]>,
    /// Spatial: the velocity of G in space axes, (Ẋ, Ẏ, Ż), m/s: instead of `velocity`, and
    /// turned into body axes through `attitude_deg` (v = Rᵀ V).
    pub velocity_space: Option<[f64; 3]>,
    /// Spatial: body rates (p, q, r), rad/s.
    pub rates: Option<[f64; 3]>,
    /// Spatial: position of G in space axes, (x, y, z), m.
    pub position: Option<[f64; 3]>,
    /// Spatial: roll, pitch, yaw (4.56), degrees.
    pub attitude_deg: Option<[f64; 3]>,
    /// Pendulum: the angle from the downward vertical, degrees.
    pub theta_deg: Option<f64>,
    /// Pendulum: the angular rate, rad/s.
    pub theta_dot: Option<f64>,
    /// Planar: surge velocity u in body axes, m/s (every planar family; the space-fixed
    /// state is given its space components).
    pub u: Option<f64>,
    /// Planar: sway velocity v in body axes, m/s (as `u`).
    pub v: Option<f64>,
    /// Planar: Ẋ, the velocity of G along X in space axes, m/s: with `y_dot`, instead of `u`
    /// and `v`, turned into body axes through `psi_deg`.
    pub x_dot: Option<f64>,
    /// Planar: Ẏ, the velocity of G along Y in space axes, m/s (see `x_dot`).
    pub y_dot: Option<f64>,
    /// Planar: yaw rate, rad/s.
    pub r: Option<f64>,
    /// Planar: position X in space axes, m.
    pub x: Option<f64>,
    /// Planar: position Y in space axes, m.
    pub y: Option<f64>,
    /// Planar: heading ψ, degrees.
    pub psi_deg: Option<f64>,
}

/// `[loads]`. Space axes: X north, Y east, Z down, as the chapter's ship dynamics.
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LoadsTable {
    /// Gravity g along +Z (down), m/s²; acts at G (spatial).
    pub gravity: Option<f64>,
    /// Buoyancy B along −Z (up), N; acts at the centre of buoyancy (spatial).
    pub buoyancy: Option<f64>,
    /// The centre of buoyancy relative to G, body axes, m (spatial).
    pub buoyancy_centre: Option<[f64; 3]>,
    /// A force in body axes, N: 3 entries (spatial) or 2 (planar), constant or a time table.
    pub force_body: Option<Timed<Vec<f64>>>,
    /// A force in space axes, N: 3 entries (spatial) or 2 (planar), constant or a time table.
    pub force_space: Option<Timed<Vec<f64>>>,
    /// The point where `force_body` acts, body axes from G, m: 3 entries (spatial) or 2
    /// (planar); it adds the moment r_P × F about G (4.2). Without it the force acts at G.
    pub force_body_at: Option<Vec<f64>>,
    /// The point where `force_space` acts, body axes from G, m (see `force_body_at`).
    pub force_space_at: Option<Vec<f64>>,
    /// A moment about G (the pivot for a top) in body axes, N m, 3 entries, constant or a
    /// time table.
    pub moment_body: Option<Timed<Vec<f64>>>,
    /// A moment about G in space axes, N m (spatial), constant or a time table.
    pub moment_space: Option<Timed<Vec<f64>>>,
    /// A moment about the vertical (planar) or the pivot (pendulum), N m, constant or a time
    /// table.
    pub moment: Option<Timed<f64>>,
    /// Linear damping, each load −dᵢ xᵢ on a velocity: (u, v, w, p, q, r) spatial,
    /// (u, v, r) planar, (θ̇) pendulum.
    pub linear_damping: Option<Vec<f64>>,
    /// Quadratic damping, each load −dᵢ xᵢ|xᵢ|, on the same velocities.
    pub quadratic_damping: Option<Vec<f64>>,
}

/// A load's value: a constant, or a table of its values over time.
///
/// Read from either TOML form of the same key: `moment_body = [0.0, 0.0, 2.0]`, or a table
/// `moment_body = { times = [0.0, 1.0], values = [[0.0, 0.0, 0.0], [0.0, 0.0, 2.0]],
/// interpolation = "step" }` (see [`super::table`]).
#[derive(Debug, Clone, PartialEq)]
pub enum Timed<V> {
    /// The same value at every time.
    Constant(V),
    /// Values at given times.
    Table(TableSpec<V>),
}

/// A time table as written: the times, the value at each, and how to read between them.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TableSpec<V> {
    /// The times, s, strictly increasing.
    pub times: Vec<f64>,
    /// The value at each time.
    pub values: Vec<V>,
    /// `"linear"` (straight between the times) or `"step"` (each value until the next time).
    pub interpolation: Option<String>,
}

impl<'de, V: Deserialize<'de>> Deserialize<'de> for Timed<V> {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        deserializer.deserialize_any(TimedVisitor(std::marker::PhantomData))
    }
}

/// Reads a constant (a number or an array) or a table (an inline or a sub-table), each by
/// its own type's reader, so that an error inside either names its own key.
struct TimedVisitor<V>(std::marker::PhantomData<V>);

impl<'de, V: Deserialize<'de>> serde::de::Visitor<'de> for TimedVisitor<V> {
    type Value = Timed<V>;

    fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str("a constant, or a time table { times, values, interpolation }")
    }

    fn visit_f64<E: serde::de::Error>(self, v: f64) -> Result<Self::Value, E> {
        V::deserialize(serde::de::value::F64Deserializer::new(v)).map(Timed::Constant)
    }

    fn visit_i64<E: serde::de::Error>(self, v: i64) -> Result<Self::Value, E> {
        V::deserialize(serde::de::value::I64Deserializer::new(v)).map(Timed::Constant)
    }

    fn visit_seq<A: serde::de::SeqAccess<'de>>(self, seq: A) -> Result<Self::Value, A::Error> {
        V::deserialize(serde::de::value::SeqAccessDeserializer::new(seq)).map(Timed::Constant)
    }

    fn visit_map<A: serde::de::MapAccess<'de>>(self, map: A) -> Result<Self::Value, A::Error> {
        TableSpec::deserialize(serde::de::value::MapAccessDeserializer::new(map)).map(Timed::Table)
    }
}

/// `[integrator]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct IntegratorTable {
    /// `euler`, `symplectic-euler`, `rk4`, `dopri5`, `dop853` or `lie-midpoint`.
    pub method: String,
    /// Relative tolerance (adaptive methods).
    pub rtol: Option<f64>,
    /// Absolute tolerance (adaptive methods).
    pub atol: Option<f64>,
    /// The step (fixed-step methods), s.
    pub step: Option<f64>,
    /// The end of the run, s (the run starts at 0).
    pub end_time: f64,
    /// The most steps (accepted and rejected) a run may take.
    pub max_steps: Option<u64>,
    /// A condition that ends the run where it first holds, `"z > 10"` (see
    /// [`crate::scene::stop`]).
    pub stop_when: Option<String>,
}

/// `[output]`.
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OutputTable {
    /// Trajectory rows at exactly t = k·every, s.
    pub every: Option<f64>,
}

/// The keys a table has, for refusing the ones another family reads.
pub(crate) trait GivenKeys {
    /// The names of the keys present.
    fn given(&self) -> Vec<&'static str>;
}

macro_rules! given_keys {
    ($table:ident { $($key:ident),* }) => {
        impl GivenKeys for $table {
            fn given(&self) -> Vec<&'static str> {
                let mut keys = Vec::new();
                $(if self.$key.is_some() { keys.push(stringify!($key)); })*
                keys
            }
        }
    };
}

impl GivenKeys for ModelTable {
    fn given(&self) -> Vec<&'static str> {
        let mut keys = vec!["family"];
        if self.symmetry.is_some() {
            keys.push("symmetry");
        }
        if self.kinematics.is_some() {
            keys.push("kinematics");
        }
        keys
    }
}

given_keys!(BodyTable {
    mass,
    inertia,
    file,
    i0,
    g,
    h,
    izz,
    x_g
});
given_keys!(InitialTable {
    velocity,
    velocity_space,
    rates,
    position,
    attitude_deg,
    theta_deg,
    theta_dot,
    u,
    v,
    x_dot,
    y_dot,
    r,
    x,
    y,
    psi_deg
});
given_keys!(LoadsTable {
    gravity,
    buoyancy,
    buoyancy_centre,
    force_body,
    force_space,
    force_body_at,
    force_space_at,
    moment_body,
    moment_space,
    moment,
    linear_damping,
    quadratic_damping
});
