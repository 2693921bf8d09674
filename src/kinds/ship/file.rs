//! A ship scene's tables as written, read by serde: every key by its path, none unknown.
//! [`super::scene`] checks them into a [`super::ShipScene`].

use crate::scene::envelope::{FamilyTable, IntegratorTable, OutputTable, SteeringGearTable};
use serde::Deserialize;
use std::collections::BTreeMap;

/// The file as written.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ShipSceneFile {
    /// What the scene is.
    pub title: String,
    /// `family = "planar-midship"`.
    pub model: FamilyTable,
    /// The body.
    pub body: BodyTable,
    /// The hydrodynamic table.
    pub hydrodynamics: HydrodynamicsTable,
    /// The steering gear.
    #[serde(default)]
    pub rudder: SteeringGearTable,
    /// The propeller, its thrust law and the rudder in its slipstream (prime tables).
    pub propulsion: Option<PropulsionTable>,
    /// The water and the air around the ship: a uniform current, a wind.
    pub environment: Option<EnvironmentTable>,
    /// The ship above water: its wind coefficients and areas.
    pub windage: Option<WindageTable>,
    /// The step.
    pub integrator: IntegratorTable,
    /// The manoeuvres, each run from the same approach.
    #[serde(default)]
    pub manoeuvre: Vec<ManoeuvreTable>,
    /// Trajectory rows.
    #[serde(default)]
    pub output: OutputTable,
    /// Values to sweep over (read by [`crate::scene::sweep`], which runs each case).
    pub sweep: Option<toml::Table>,
    /// A Monte Carlo's laws (read by [`crate::scene::uncertainty`], which runs each case).
    #[serde(default)]
    pub uncertainty: Option<crate::scene::uncertainty::UncertaintyTable>,
    /// The operating point of `eom linear`.
    pub linear: Option<crate::scene::envelope::LinearTable>,
}

/// `[body]`: the keys of the table's units (`_prime` in the prime system), one of each.
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BodyTable {
    /// L, m.
    pub length: Option<f64>,
    /// M, kg (dimensional).
    pub mass: Option<f64>,
    /// m′ = M/(½ρL³) (prime).
    pub mass_prime: Option<f64>,
    /// I_zz about G, kg m² (dimensional).
    pub izz: Option<f64>,
    /// I_O about midship, kg m² (dimensional).
    pub izz_midship: Option<f64>,
    /// I_zz′ about G, over ½ρL⁵ (prime).
    pub izz_prime: Option<f64>,
    /// I_O′ about midship, over ½ρL⁵ (prime).
    pub izz_midship_prime: Option<f64>,
    /// G ahead of midship, m (dimensional).
    pub x_g: Option<f64>,
    /// x_G′ = x_G/L (prime).
    pub x_g_prime: Option<f64>,
}

/// `[hydrodynamics]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HydrodynamicsTable {
    /// `polynomial` (the default) or `mmg`.
    pub model: Option<String>,
    /// `prime` or `dimensional` (a polynomial table's).
    pub units: Option<String>,
    /// `folded` or `separate` (a polynomial table's).
    pub rigid_body_terms: Option<String>,
    /// ρ, kg/m³ (prime and MMG tables).
    pub density: Option<f64>,
    /// U₀, m/s.
    pub design_speed: f64,
    /// The coefficients by name, as the table writes them.
    pub coefficients: BTreeMap<String, f64>,
    /// An MMG table's particulars by name (B, d, D_P, H_R, A_R), m and m².
    pub particulars: Option<BTreeMap<String, f64>>,
    /// An MMG ship's propeller rate, rev/s, held in every run (by default the rate that
    /// balances the approach, solved).
    pub propeller_rate_rps: Option<f64>,
}

/// `[propulsion]`: the propeller, its thrust law, and the rudder in its slipstream
/// ([`super::propulsion`]); every key required where the table is given (the checker names the
/// one missing).
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PropulsionTable {
    /// d, m.
    pub diameter: Option<f64>,
    /// A_R, m².
    pub rudder_area: Option<f64>,
    /// w.
    pub wake_fraction: Option<f64>,
    /// K_T of the induced velocity.
    pub thrust_coefficient: Option<f64>,
    /// k.
    pub slipstream_factor: Option<f64>,
    /// x_R/L, the rudder ahead of midship (negative aft).
    pub rudder_position_prime: Option<f64>,
    /// [T′_uu, T′_un, T′_nn].
    pub thrust: Option<[f64; 3]>,
    /// C_R on the wetted surface.
    pub resistance: Option<f64>,
    /// S, m².
    pub wetted_surface: Option<f64>,
    /// The engine's rate limit, rev/s².
    pub max_rate_rps_s: Option<f64>,
}

/// `[environment]`: a uniform current, constant in space and time; a wind fixed in direction,
/// steady or gusting.
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EnvironmentTable {
    /// The current's speed, m/s.
    pub current_m_s: Option<f64>,
    /// The direction it flows toward, degrees clockwise from north.
    pub current_toward_deg: Option<f64>,
    /// The wind's mean speed, m/s.
    pub wind_m_s: Option<f64>,
    /// The direction it blows from, degrees clockwise from north.
    pub wind_from_deg: Option<f64>,
    /// The spectrum its gusts are drawn from (`"norsok"`); steady without one.
    pub wind_spectrum: Option<String>,
    /// The seed the gusts are drawn with.
    pub wind_seed: Option<u64>,
    /// The height of the wind above the sea, m (10 by default).
    pub wind_height_m: Option<f64>,
}

/// `[windage]`: the ship above water, as its wind loads are given: its areas and length
/// overall, and its coefficients over the relative wind's angle, as a table or by Isherwood's
/// regression on its geometry.
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WindageTable {
    /// `"isherwood"` for Isherwood's regression; a table (`angles_deg`, `C_X` …) without it.
    pub coefficients: Option<String>,
    /// The table's angles off the bow, 0 to 180 degrees.
    pub angles_deg: Option<Vec<f64>>,
    /// C_X at each angle.
    #[serde(rename = "C_X")]
    pub c_x: Option<Vec<f64>>,
    /// C_Y at each angle.
    #[serde(rename = "C_Y")]
    pub c_y: Option<Vec<f64>>,
    /// C_N at each angle.
    #[serde(rename = "C_N")]
    pub c_n: Option<Vec<f64>>,
    /// L_oa, m.
    pub length_overall_m: Option<f64>,
    /// A_F, m².
    pub frontal_area_m2: Option<f64>,
    /// A_L, m².
    pub lateral_area_m2: Option<f64>,
    /// ρ_a, kg/m³.
    pub air_density_kg_m3: Option<f64>,
    /// B, m (Isherwood's).
    pub beam_m: Option<f64>,
    /// A_SS, m² (Isherwood's).
    pub superstructure_area_m2: Option<f64>,
    /// S, m (Isherwood's).
    pub perimeter_m: Option<f64>,
    /// C, m (Isherwood's).
    pub centroid_from_bow_m: Option<f64>,
    /// M (Isherwood's).
    pub masts: Option<f64>,
}

/// `[[manoeuvre]]`: each kind reads its own keys and refuses the others.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ManoeuvreTable {
    /// The output folder's name.
    pub name: Option<String>,
    /// `turning_circle`, `zigzag`, `pull_out` or `rudder_series`.
    pub kind: String,
    /// The rudder angle, degrees (not for a series).
    pub rudder_deg: Option<f64>,
    /// A zig-zag's ψ_a, degrees.
    pub heading_deg: Option<f64>,
    /// When the rudder is put over, s (default 0).
    pub execute_s: Option<f64>,
    /// A pull-out's release, s.
    pub release_s: Option<f64>,
    /// The end of the run, s (a spiral's: the longest it may take, by default).
    pub duration_s: Option<f64>,
    /// A series' times, s.
    pub times_s: Option<Vec<f64>>,
    /// A series' angles, degrees.
    pub series_deg: Option<Vec<f64>>,
    /// `both` (default), `port` or `starboard`: the sides a turning circle or zig-zag runs to.
    pub side: Option<String>,
    /// A direct spiral's rudder angles, degrees, strictly monotonic.
    pub rudders_deg: Option<Vec<f64>>,
    /// A direct spiral's first angle, degrees (with `to_deg` and `step_deg`, in place of
    /// `rudders_deg`).
    pub from_deg: Option<f64>,
    /// A direct spiral's last angle of the first pass, degrees.
    pub to_deg: Option<f64>,
    /// A direct spiral's spacing of the angles from `from_deg` to `to_deg`, degrees.
    pub step_deg: Option<f64>,
    /// A reverse spiral's commanded yaw rates, degrees per second.
    pub yaw_rates_deg_s: Option<Vec<f64>>,
    /// A spiral's settling window, s.
    pub settle_window_s: Option<f64>,
    /// A spiral's settling tolerance on r over the window, degrees per second.
    pub settle_tolerance_deg_s: Option<f64>,
    /// The longest a spiral holds an angle, s.
    pub max_hold_s: Option<f64>,
    /// The reverse spiral's closed-loop yaw time constant, s.
    pub controller_time_s: Option<f64>,
    /// The reverse spiral's settling tolerance on the mean rudder from window to window,
    /// degrees.
    pub settle_rudder_deg: Option<f64>,
    /// A spiral's settling tolerance on the speed over the window, m/s.
    pub settle_speed_m_s: Option<f64>,
    /// A crash stop's full-astern propeller rate, rev/s (negative).
    pub astern_rps: Option<f64>,
}
