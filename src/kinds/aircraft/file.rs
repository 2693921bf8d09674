//! An aircraft scene's tables as written, read by serde: every key by its path, none unknown.
//! [`super::scene`] checks them into a [`super::scene::AircraftScene`].

use super::derivatives::Derivatives;
use crate::scene::envelope::{IntegratorTable, LinearTable, OutputTable};
use serde::Deserialize;

/// The file as written.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AircraftSceneFile {
    /// What the scene is.
    pub title: String,
    /// The units, the atmosphere and the form of the aerodynamic tables.
    pub aircraft: AircraftTable,
    /// Mass, inertia, gravity.
    pub body: BodyTable,
    /// Wing area, span, chord, and where G and the tables' reference lie.
    pub geometry: GeometryTable,
    /// Thrust tables and the rotor.
    pub engine: EngineTable,
    /// The aerodynamic tables.
    pub aerodynamics: AerodynamicsTable,
    /// Where the tables and the surfaces end.
    pub limits: LimitsTable,
    /// The steady flight every manoeuvre starts from.
    pub trim: TrimTable,
    /// The method.
    pub integrator: IntegratorTable,
    /// The manoeuvres, each from the trim.
    #[serde(default)]
    pub manoeuvre: Vec<ManoeuvreTable>,
    /// Trajectory rows.
    #[serde(default)]
    pub output: OutputTable,
    /// The operating point of `eom linear` (by default the trim).
    pub linear: Option<LinearTable>,
    /// Values to sweep over (read by [`crate::scene::sweep`]).
    pub sweep: Option<toml::Table>,
    /// A Monte Carlo's laws (read by [`crate::scene::uncertainty`], which runs each case).
    #[serde(default)]
    pub uncertainty: Option<crate::scene::uncertainty::UncertaintyTable>,
}

/// `[aircraft]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AircraftTable {
    /// `us` (ft, slug, lbf) or `si` (m, kg, N); seconds, and degrees for the tables' angles
    /// and the surfaces, in both.
    pub units: String,
    /// `stevens-lewis` (its `adc`, in `us` units) or `standard-1976`.
    pub atmosphere: String,
    /// The form of the aerodynamics: `stevens-lewis` (tables) or `derivatives`.
    pub aerodynamics: String,
    /// How a run carries the attitude: `euler` (the default) or `quaternion`.
    pub kinematics: Option<String>,
}

/// `[body]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BodyTable {
    /// Mass.
    pub mass: f64,
    /// I_xx, I_yy, I_zz about G.
    pub inertia: [f64; 3],
    /// I_xy, I_yz, I_xz about G, the tensor's off-diagonal entries (the chapter's sign:
    /// −∫xz dm; Stevens & Lewis's J_xz = +982 slug ft² is −982 here).
    pub products_of_inertia: Option<[f64; 3]>,
    /// The same products as the integrals ∫xy dm, ∫yz dm, ∫xz dm, the sign Etkin, Nelson and
    /// Stevens print them in (Etkin's 747: I_zx = −0.212e7 kg m²); the tensor's entries are
    /// their negatives. A scene gives one of the two keys, not both.
    pub products_of_inertia_integrals: Option<[f64; 3]>,
    /// Gravity.
    pub gravity: f64,
}

/// `[geometry]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GeometryTable {
    /// Wing reference area S.
    pub area: f64,
    /// Span b.
    pub span: f64,
    /// Mean aerodynamic chord c̄.
    pub chord: f64,
    /// G, as a fraction of c̄ aft of its leading edge.
    pub xcg: f64,
    /// The fuselage's length, drawn in the view (nothing else reads it).
    #[serde(default)]
    pub length: Option<f64>,
    /// Where the moment tables are given, likewise.
    pub xcg_reference: f64,
}

/// `[engine]`: thrust tables (`altitude`, `mach`, `idle`, `military`, `maximum`), or a
/// constant thrust (`thrust`, `time_constant_s`).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EngineTable {
    /// The rotor's angular momentum along body x.
    pub rotor_momentum: f64,
    /// The thrust tables' altitudes.
    pub altitude: Option<Vec<f64>>,
    /// Their Mach numbers.
    pub mach: Option<Vec<f64>>,
    /// Thrust at idle, `[altitude][mach]`.
    pub idle: Option<Vec<Vec<f64>>>,
    /// At military power.
    pub military: Option<Vec<Vec<f64>>>,
    /// At maximum power.
    pub maximum: Option<Vec<Vec<f64>>>,
    /// A constant thrust's value at full throttle.
    pub thrust: Option<f64>,
    /// A constant thrust's power lag, s.
    pub time_constant_s: Option<f64>,
}

/// A table in α and the elevator.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AlphaElevator {
    /// α's breakpoints, deg.
    pub alpha_deg: Vec<f64>,
    /// The elevator's, deg.
    pub elevator_deg: Vec<f64>,
    /// `[α][elevator]`.
    pub values: Vec<Vec<f64>>,
}

/// A table in α and |β|.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AlphaBetaAbs {
    /// α's breakpoints, deg.
    pub alpha_deg: Vec<f64>,
    /// |β|'s, deg.
    pub beta_abs_deg: Vec<f64>,
    /// `[α][|β|]`.
    pub values: Vec<Vec<f64>>,
}

/// A table in α and β.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AlphaBeta {
    /// α's breakpoints, deg.
    pub alpha_deg: Vec<f64>,
    /// β's, deg.
    pub beta_deg: Vec<f64>,
    /// `[α][β]`.
    pub values: Vec<Vec<f64>>,
}

/// A table in α.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Alpha {
    /// α's breakpoints, deg.
    pub alpha_deg: Vec<f64>,
    /// The values.
    pub values: Vec<f64>,
}

/// The damping derivatives, each in α.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
#[allow(non_snake_case)]
pub struct DampingTable {
    /// α's breakpoints, deg.
    pub alpha_deg: Vec<f64>,
    /// C_Xq.
    pub CXq: Vec<f64>,
    /// C_Yr.
    pub CYr: Vec<f64>,
    /// C_Yp.
    pub CYp: Vec<f64>,
    /// C_Zq.
    pub CZq: Vec<f64>,
    /// C_lr.
    pub Clr: Vec<f64>,
    /// C_lp.
    pub Clp: Vec<f64>,
    /// C_mq.
    pub Cmq: Vec<f64>,
    /// C_nr.
    pub Cnr: Vec<f64>,
    /// C_np.
    pub Cnp: Vec<f64>,
}

/// `[aerodynamics]`: the tables of the Stevens & Lewis form, or the stability derivatives.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AerodynamicsTable {
    /// C_x(α, δ_e).
    pub cx: Option<AlphaElevator>,
    /// C_z(α).
    pub cz: Option<Alpha>,
    /// C_m(α, δ_e).
    pub cm: Option<AlphaElevator>,
    /// C_l(α, |β|).
    pub cl: Option<AlphaBetaAbs>,
    /// C_n(α, |β|).
    pub cn: Option<AlphaBetaAbs>,
    /// ΔC_l per δ_a/20.
    pub dlda: Option<AlphaBeta>,
    /// ΔC_l per δ_r/30.
    pub dldr: Option<AlphaBeta>,
    /// ΔC_n per δ_a/20.
    pub dnda: Option<AlphaBeta>,
    /// ΔC_n per δ_r/30.
    pub dndr: Option<AlphaBeta>,
    /// The damping derivatives.
    pub damping: Option<DampingTable>,
    /// The stability derivatives (`aerodynamics = "derivatives"`), each per radian.
    pub derivatives: Option<Derivatives>,
}

/// `[limits]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LimitsTable {
    /// α's range with data, deg.
    pub alpha_deg: [f64; 2],
    /// The elevator's deflection limit, ± deg.
    pub elevator_deg: f64,
    /// The aileron's.
    pub aileron_deg: f64,
    /// The rudder's.
    pub rudder_deg: f64,
}

/// `[trim]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TrimTable {
    /// True airspeed.
    pub speed: f64,
    /// Altitude.
    pub altitude: f64,
    /// Flight-path angle γ, rad.
    pub climb_angle_rad: Option<f64>,
    /// Turn rate ψ̇ of a coordinated turn, rad/s.
    pub turn_rate_rad_s: Option<f64>,
    /// Pitch rate of a pull-up, rad/s.
    pub pull_up_rate_rad_s: Option<f64>,
}

/// `[[manoeuvre]]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ManoeuvreTable {
    /// `elevator_doublet`, `aileron_step`, `rudder_kick`, `throttle_step`, `pull_up`.
    pub kind: String,
    /// Its folder's name; `kind` where absent.
    pub name: Option<String>,
    /// The deflection from the trim, deg (a throttle step's change of throttle, 0 to 1).
    pub amount: f64,
    /// When it starts, s.
    pub start_s: Option<f64>,
    /// A doublet's half and a kick's pulse, s.
    pub width_s: Option<f64>,
    /// How long the run lasts, s.
    pub duration_s: f64,
}
