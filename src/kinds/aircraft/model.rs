//! The aircraft model: the proved program of `eom_codegen::model::aircraft` (the rigid body
//! about G with I_xz and the rotor, the wind-axis state, the aerodynamic build-up, the
//! navigation and the power lag), evaluated by the one interpreter of proved programs
//! (`crate::defined`), with its inputs computed beside it at every call: the coefficients
//! from the tables ([`super::aero`]), the air ([`super::atmosphere`]), the thrust and the
//! power lag ([`super::engine`]).
//!
//! The Jacobians are the proved ∂f/∂x and ∂f/∂(input) composed by the chain rule with the
//! inputs' derivatives in the state (V, α, β, altitude, power) and the controls: the tables'
//! segment slopes, the atmosphere's slopes, the thrust tables' and the lag's.

use super::aero::{Aerodynamics, Flow};
use super::atmosphere::Atmosphere;
use super::derivatives::PerAlphaRate;
use super::engine::Propulsion;
use crate::defined::engine::{
    AIRCRAFT_QUATERNION_STATE, AIRCRAFT_STATE, BuildError, Kinematics, Operations, aircraft_with,
    prove_with_jacobians,
};
use crate::defined::{Functions, Interpreter, Source, Variables, coefficient_values};
use crate::inertia::InertiaTensor;
use crate::models::Model;
use std::collections::BTreeMap;
use std::sync::OnceLock;
use thiserror::Error;

/// The state: airspeed (the source's length unit per second), angle of attack, sideslip,
/// roll, pitch, heading (rad), body rates p, q, r (rad/s), north, east, altitude (length),
/// the engine's power (percent).
pub const STATE: [&str; 13] = AIRCRAFT_STATE;

/// The controls: throttle (0 to 1), elevator, aileron, rudder (deg).
pub const CONTROLS: [&str; 4] = ["throttle", "elevator", "aileron", "rudder"];

/// The state of the quaternion form: the attitude q0 … q3 (scalar first) in the Euler angles'
/// place.
pub const QUATERNION_STATE: [&str; 14] = AIRCRAFT_QUATERNION_STATE;

/// What the inputs computed beside the program depend on, in this order.
const DEPENDENCIES: usize = 9;

/// Where a form of the state keeps what the inputs depend on: V, α, β first in both, the
/// altitude and the power after the attitude and the track.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Layout {
    altitude: usize,
    power: usize,
}

impl Layout {
    const EULER: Layout = Layout {
        altitude: 11,
        power: 12,
    };
    const QUATERNION: Layout = Layout {
        altitude: 12,
        power: 13,
    };

    /// The dependencies' places in the state: V, α, β, altitude, power.
    fn dependencies(self) -> [(usize, usize); 5] {
        [(0, 0), (1, 1), (2, 2), (3, self.altitude), (4, self.power)]
    }
}
const INPUTS: usize = 19;
/// Where C_X, C_Z and C_m, the coefficients with α̇ terms, are among the inputs.
const WITH_ALPHA_RATE: [usize; 3] = [0, 2, 4];

/// Why an aircraft model cannot be built.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum AircraftError {
    /// The symbolic engine could not build or prove the model.
    #[error(transparent)]
    Build(#[from] BuildError),
    /// A number of the body that cannot be used.
    #[error("`{field}`: {why}")]
    Invalid {
        /// The key.
        field: String,
        /// Why.
        why: String,
    },
}

/// The aircraft's body and geometry, in one consistent set of units.
#[derive(Debug, Clone, PartialEq)]
pub struct Airframe {
    /// The mass.
    pub mass: f64,
    /// The inertia tensor about G in body axes (the chapter's sign: the products are the
    /// tensor's off-diagonal entries), symmetric about the xz-plane.
    pub inertia: InertiaTensor,
    /// Gravity.
    pub gravity: f64,
    /// Wing reference area S.
    pub area: f64,
    /// Span b.
    pub span: f64,
    /// Mean aerodynamic chord c̄.
    pub chord: f64,
    /// The aerodynamic reference point (where the moment tables are given) from G, in body
    /// axes (x forward).
    pub reference_point: [f64; 3],
    /// The engine rotor's angular momentum along body x.
    pub rotor_momentum: f64,
}

impl Airframe {
    /// The aerodynamic reference point from G when G and the reference lie along the chord
    /// at fractions `xcg` and `xcg_reference` of c̄ aft of its leading edge (Stevens &
    /// Lewis's x_cg): (x_cg − x_cg,ref)·c̄ forward of G.
    pub fn reference_from_chord(chord: f64, xcg: f64, xcg_reference: f64) -> [f64; 3] {
        [(xcg - xcg_reference) * chord, 0.0, 0.0]
    }

    fn parameters(&self) -> Result<BTreeMap<String, f64>, AircraftError> {
        let tensor = self.inertia.matrix();
        if tensor[(0, 1)] != 0.0 || tensor[(1, 2)] != 0.0 {
            return Err(AircraftError::Invalid {
                field: "body.products_of_inertia".into(),
                why: "an aircraft is symmetric about its xz-plane: I_xy and I_yz must be 0".into(),
            });
        }
        let values = [
            ("M", self.mass, "body.mass"),
            ("Ixx", tensor[(0, 0)], "body.inertia"),
            ("Iyy", tensor[(1, 1)], "body.inertia"),
            ("Izz", tensor[(2, 2)], "body.inertia"),
            ("Ixz", tensor[(0, 2)], "body.products_of_inertia"),
            ("g", self.gravity, "body.gravity"),
            ("S", self.area, "geometry.area"),
            ("b", self.span, "geometry.span"),
            ("cbar", self.chord, "geometry.chord"),
            ("x_ref", self.reference_point[0], "geometry.reference_point"),
            ("y_ref", self.reference_point[1], "geometry.reference_point"),
            ("z_ref", self.reference_point[2], "geometry.reference_point"),
            ("h_E", self.rotor_momentum, "engine.rotor_momentum"),
        ];
        for (_, value, field) in values {
            if !value.is_finite() {
                return Err(AircraftError::Invalid {
                    field: field.into(),
                    why: format!("{value} is not finite"),
                });
            }
        }
        for (value, field) in [
            (self.mass, "body.mass"),
            (self.gravity, "body.gravity"),
            (self.area, "geometry.area"),
            (self.span, "geometry.span"),
            (self.chord, "geometry.chord"),
        ] {
            if value <= 0.0 {
                return Err(AircraftError::Invalid {
                    field: field.into(),
                    why: format!("must be positive, not {value}"),
                });
            }
        }
        Ok(values
            .iter()
            .map(|(symbol, value, _)| (symbol.to_string(), *value))
            .collect())
    }
}

/// The aircraft's proved program in one form of its attitude, built and proved once per
/// process (it does not depend on the numbers).
struct Proved {
    system: crate::defined::engine::System,
    program: crate::defined::engine::Program,
}

fn proved(kinematics: Kinematics) -> Result<&'static Proved, AircraftError> {
    static EULER: OnceLock<Result<Proved, AircraftError>> = OnceLock::new();
    static QUATERNION: OnceLock<Result<Proved, AircraftError>> = OnceLock::new();
    let cell = match kinematics {
        Kinematics::Euler => &EULER,
        Kinematics::Quaternion => &QUATERNION,
    };
    cell.get_or_init(|| {
        let system = aircraft_with("aircraft", kinematics)?;
        let program = prove_with_jacobians(&system).map_err(|e| AircraftError::Invalid {
            field: "model".into(),
            why: e.to_string(),
        })?;
        Ok(Proved { system, program })
    })
    .as_ref()
    .map_err(Clone::clone)
}

/// A proved program with an airframe's numbers hoisted, ready to call.
#[derive(Debug, Clone)]
struct Flown {
    program: Interpreter,
    functions: Functions,
    operations: Operations,
}

impl Flown {
    /// The program of `kinematics` with the airframe's `values`.
    fn new(kinematics: Kinematics, values: &BTreeMap<String, f64>) -> Result<Self, AircraftError> {
        let proved = proved(kinematics)?;
        let coefficients = coefficient_values(&proved.system, &proved.program, values);
        if let Some((c, _)) = (proved.program.coefficients.iter())
            .zip(&coefficients)
            .find(|(_, v)| !v.is_finite())
        {
            return Err(AircraftError::Invalid {
                field: "body".into(),
                why: format!("the coefficient `{}` is not finite", c.value),
            });
        }
        let (state, inputs) = (&proved.system.state, &proved.system.inputs);
        let place = |name: &str| {
            if let Some(i) = state.iter().position(|s| *s == name) {
                return Some(Source::State(i));
            }
            inputs.iter().position(|s| *s == name).map(Source::Computed)
        };
        let program = Interpreter::new(&proved.program, &coefficients, place).map_err(|name| {
            AircraftError::Invalid {
                field: "model".into(),
                why: format!("the program reads `{name}`, which nothing sets"),
            }
        })?;
        let functions = Functions::of(&proved.program)
            .map_err(|what| AircraftError::Invalid {
                field: "model".into(),
                why: format!("the program has no {what}"),
            })?
            .compile(&program);
        Ok(Flown {
            operations: proved.program.operations(&proved.program.rhs),
            program,
            functions,
        })
    }

    /// The rates of `state` with the inputs at `computed`.
    fn rates<const N: usize>(&self, state: &[f64; N], computed: &[f64; INPUTS]) -> [f64; N] {
        let mut rates = [0.0; N];
        let variables = Variables { state, computed };
        (self.program).evaluate_into(&self.functions.rhs, variables, &mut rates);
        rates
    }
}

/// An aircraft on its tables or derivatives, ready to evaluate: its attitude in Euler angles
/// (the state of trims, linear models and rows), and on demand in a quaternion
/// ([`AircraftModel::in_quaternion`]) for runs through the vertical.
#[derive(Debug, Clone)]
pub struct AircraftModel {
    euler: Flown,
    quaternion: OnceLock<Result<Flown, AircraftError>>,
    parameters: BTreeMap<String, f64>,
    aerodynamics: Aerodynamics,
    engine: Propulsion,
    atmosphere: Atmosphere,
    gravity: f64,
    chord: f64,
}

/// The inputs the program reads, computed beside it, with their derivatives in
/// (V, α, β, altitude, power, throttle, elevator, aileron, rudder).
struct Beside {
    values: [f64; INPUTS],
    by: [[f64; DEPENDENCIES]; INPUTS],
}

/// The inputs with their α̇ terms added: α̇ itself, and the terms per unit α̇.
struct WithAlphaRate {
    beside: Beside,
    alpha_rate: f64,
    per: PerAlphaRate,
}

impl AircraftModel {
    /// The model of `airframe` on `aerodynamics` (the Stevens & Lewis tables or a table of
    /// derivatives), with its `engine` in `atmosphere`: the proved program with the
    /// airframe's numbers hoisted.
    pub fn new(
        airframe: &Airframe,
        aerodynamics: impl Into<Aerodynamics>,
        engine: impl Into<Propulsion>,
        atmosphere: Atmosphere,
    ) -> Result<Self, AircraftError> {
        let parameters = airframe.parameters()?;
        Ok(AircraftModel {
            euler: Flown::new(Kinematics::Euler, &parameters)?,
            quaternion: OnceLock::new(),
            parameters,
            aerodynamics: aerodynamics.into(),
            engine: engine.into(),
            atmosphere,
            gravity: airframe.gravity,
            chord: airframe.chord,
        })
    }

    /// Where flight at `speed` and `altitude` lies beyond the engine's tables (Mach from the
    /// atmosphere's speed of sound there), each such argument with the range the tables hold;
    /// none outside the atmosphere, which the model refuses on its own.
    pub fn beyond_engine_tables(&self, speed: f64, altitude: f64) -> Vec<String> {
        match self.atmosphere.at(altitude) {
            Ok(air) => (self.engine).beyond_tables(altitude, speed / air.speed_of_sound),
            Err(_) => Vec::new(),
        }
    }

    /// What one call of the proved right-hand side costs, as the emitter counts it.
    pub fn operations(&self) -> Operations {
        self.euler.operations
    }

    /// The model with its attitude in a quaternion (q̇ = ½ q ⊗ (0, ω)), for runs that pass
    /// through the vertical; its program is built and proved the first time it is asked for.
    pub fn in_quaternion(&self) -> Result<InQuaternion<'_>, AircraftError> {
        let flown = self
            .quaternion
            .get_or_init(|| Flown::new(Kinematics::Quaternion, &self.parameters))
            .as_ref()
            .map_err(Clone::clone)?;
        Ok(InQuaternion {
            aircraft: self,
            flown,
        })
    }

    /// Gravity, as the airframe gives it.
    pub fn gravity(&self) -> f64 {
        self.gravity
    }

    /// The atmosphere the model flies in.
    pub fn atmosphere(&self) -> Atmosphere {
        self.atmosphere
    }

    /// What drives it.
    pub fn engine(&self) -> &Propulsion {
        &self.engine
    }

    /// How its aerodynamics is described.
    pub fn aerodynamics(&self) -> &Aerodynamics {
        &self.aerodynamics
    }

    /// The inputs at `state` with the α̇ terms of C_X, C_Z and C_m added, and α̇. The
    /// program's α̇ reads C_X and C_Z (the lift), not C_m, and is affine in them: α̇ =
    /// α̇₀ + g α̇, where α̇₀ is α̇ without the terms and g what one unit of α̇'s terms adds to
    /// it, so α̇ = α̇₀/(1 − g), from two evaluations.
    fn beside_with_alpha_rate<const N: usize>(
        &self,
        (flown, layout): (&Flown, Layout),
        state: &[f64; N],
        controls: &[f64; 4],
    ) -> WithAlphaRate {
        let mut beside = self.beside(layout, state, controls);
        let per = (self.aerodynamics).per_alpha_rate(&flow_at(state, controls), self.chord);
        if per.is_zero() {
            return WithAlphaRate {
                beside,
                alpha_rate: 0.0,
                per,
            };
        }
        let without = flown.rates(state, &beside.values)[1];
        let mut one = beside.values;
        for (input, k) in WITH_ALPHA_RATE.into_iter().zip(per.per) {
            one[input] += k;
        }
        let gain = flown.rates(state, &one)[1] - without;
        let alpha_rate = without / (1.0 - gain);
        for (input, k) in WITH_ALPHA_RATE.into_iter().zip(per.per) {
            beside.values[input] += k * alpha_rate;
        }
        WithAlphaRate {
            beside,
            alpha_rate,
            per,
        }
    }

    /// The program's inputs at `state` under `controls`, with their derivatives. Outside the
    /// atmosphere the air is NaN, and so are the rates: a run's guard says where.
    fn beside(&self, layout: Layout, state: &[f64], controls: &[f64; 4]) -> Beside {
        let mut values = [0.0; INPUTS];
        let mut by = [[0.0; DEPENDENCIES]; INPUTS];
        let flow = flow_at(state, controls);
        // The coefficients depend on α, β (dependencies 1, 2), the surfaces (6, 7, 8) and V
        // (0).
        for (k, c) in self.aerodynamics.coefficients(&flow).iter().enumerate() {
            values[k] = c.value;
            for (slot, derivative) in [1, 2, 6, 7, 8, 0].into_iter().zip(c.by) {
                by[k][slot] = derivative;
            }
        }
        let (speed, altitude, power) = (state[0], state[layout.altitude], state[layout.power]);
        let nan = super::atmosphere::Air {
            density: f64::NAN,
            density_by_altitude: f64::NAN,
            speed_of_sound: f64::NAN,
            sound_by_altitude: f64::NAN,
        };
        let air = self.atmosphere.at(altitude).unwrap_or(nan);
        values[15] = air.density;
        by[15][3] = air.density_by_altitude;
        let mach = speed / air.speed_of_sound;
        let mach_by_speed = 1.0 / air.speed_of_sound;
        let mach_by_altitude = -mach / air.speed_of_sound * air.sound_by_altitude;
        let thrust = self.engine.thrust(power, altitude, mach);
        values[16] = thrust.value;
        by[16][0] = thrust.by_mach * mach_by_speed;
        by[16][3] = thrust.by_altitude + thrust.by_mach * mach_by_altitude;
        by[16][4] = thrust.by_power;
        let lag = self.engine.lag(power, controls[0]);
        values[17] = lag.command;
        by[17][4] = lag.command_by_power;
        by[17][5] = lag.command_by_throttle;
        values[18] = lag.gain;
        by[18][4] = lag.gain_by_power;
        by[18][5] = lag.gain_by_throttle;
        Beside { values, by }
    }

    /// The rates of `state` under `controls`.
    pub fn rates(&self, state: &[f64; 13], controls: &[f64; 4]) -> [f64; 13] {
        self.rates_in((&self.euler, Layout::EULER), state, controls)
    }

    /// The rates of `state`, in the form of `flown`, under `controls`.
    fn rates_in<const N: usize>(
        &self,
        (flown, layout): (&Flown, Layout),
        state: &[f64; N],
        controls: &[f64; 4],
    ) -> [f64; N] {
        let with = self.beside_with_alpha_rate((flown, layout), state, controls);
        flown.rates(state, &with.beside.values)
    }

    /// ∂f/∂x and ∂f/∂(controls): the proved Jacobians composed with the inputs' slopes, and
    /// with the α̇ terms (C_m + C_mα̇ α̇ c̄/(2V), the lift's C_Lα̇ α̇ c̄/(2V)) through α̇'s own
    /// row.
    pub fn jacobians(
        &self,
        state: &[f64; 13],
        controls: &[f64; 4],
    ) -> ([[f64; 13]; 13], [[f64; 4]; 13]) {
        self.jacobians_in((&self.euler, Layout::EULER), state, controls)
    }

    /// The Jacobians of the form of `flown`.
    fn jacobians_in<const N: usize>(
        &self,
        (flown, layout): (&Flown, Layout),
        state: &[f64; N],
        controls: &[f64; 4],
    ) -> ([[f64; N]; N], [[f64; 4]; N]) {
        let with = self.beside_with_alpha_rate((flown, layout), state, controls);
        let beside = &with.beside;
        let variables = Variables {
            state,
            computed: &beside.values,
        };
        let (program, functions) = (&flown.program, &flown.functions);
        let mut by_state = [[0.0; N]; N];
        let entries = program.evaluate(&functions.state_jacobian, variables);
        for (&(row, column), value) in functions.state_pattern.iter().zip(entries) {
            by_state[row][column] += value;
        }
        let mut by_controls = [[0.0; 4]; N];
        // Σ ∂f/∂C_i · (∂C_i/∂α̇): what a unit of α̇ adds to each rate through its terms.
        let mut by_alpha_rate = [0.0; N];
        let entries = program.evaluate(&functions.input_jacobian, variables);
        for (&(row, input), value) in functions.input_pattern.iter().zip(entries) {
            let mut slopes = beside.by[input];
            if let Some(k) = WITH_ALPHA_RATE.iter().position(|&i| i == input) {
                by_alpha_rate[row] += value * with.per.per[k];
                // The term k(V, α) α̇ moves with V and α at α̇ held.
                slopes[0] += with.per.by_speed[k] * with.alpha_rate;
                slopes[1] += with.per.by_alpha[k] * with.alpha_rate;
            }
            for (dependency, column) in layout.dependencies() {
                by_state[row][column] += value * slopes[dependency];
            }
            for (control, slot) in by_controls[row].iter_mut().enumerate() {
                *slot += value * slopes[5 + control];
            }
        }
        if !with.per.is_zero() {
            // α̇ = F₁(x, C(x) + k(x) α̇): dα̇ = (∂F₁ + ∂F₁/∂C · dC)/(1 − g), g = by_alpha_rate[1];
            // every rate then takes its share of dα̇.
            let whole = 1.0 - by_alpha_rate[1];
            let alpha_by_state = by_state[1].map(|x| x / whole);
            let alpha_by_controls = by_controls[1].map(|x| x / whole);
            for (row, &share) in by_alpha_rate.iter().enumerate() {
                if share == 0.0 {
                    continue;
                }
                for (slot, by) in by_state[row].iter_mut().zip(alpha_by_state) {
                    *slot += share * by;
                }
                for (slot, by) in by_controls[row].iter_mut().zip(alpha_by_controls) {
                    *slot += share * by;
                }
            }
        }
        (by_state, by_controls)
    }

    /// The kinetic energy ½MV² + ½ωᵀ\[I\]ω of `state`, from the proved form.
    pub fn kinetic_energy(&self, state: &[f64; 13]) -> f64 {
        kinetic_energy_in(&self.euler, state)
    }
}

/// What the coefficients read at `state` under `controls`: V, α, β and the surfaces.
fn flow_at(state: &[f64], controls: &[f64; 4]) -> Flow {
    Flow {
        speed: state[0],
        alpha: state[1],
        beta: state[2],
        elevator: controls[1],
        aileron: controls[2],
        rudder: controls[3],
    }
}

/// The kinetic energy of `state` in the form of `flown` (it reads V and the body rates only).
fn kinetic_energy_in<const N: usize>(flown: &Flown, state: &[f64; N]) -> f64 {
    let beside = [0.0; INPUTS];
    let variables = Variables {
        state,
        computed: &beside,
    };
    let plan = &flown.functions.kinetic_energy;
    flown
        .program
        .evaluate(plan, variables)
        .next()
        .unwrap_or(0.0)
}

/// The aircraft with its attitude in a quaternion, scalar first ([`QUATERNION_STATE`]): the
/// same loads, air and engine as its Euler-angle form, through the proved program of
/// `aircraft_with(…, Kinematics::Quaternion)`. A run through the vertical integrates this;
/// its rows give the Euler angles of the quaternion ([`euler_of`]).
#[derive(Debug, Clone, Copy)]
pub struct InQuaternion<'a> {
    aircraft: &'a AircraftModel,
    flown: &'a Flown,
}

impl InQuaternion<'_> {
    /// The aircraft in its Euler-angle form.
    pub fn aircraft(&self) -> &AircraftModel {
        self.aircraft
    }
}

/// Every entry: the quaternion form's pattern is not refined.
const QUATERNION_JACOBIAN: [(usize, usize); 14 * 14] = {
    let mut entries = [(0, 0); 196];
    let mut k = 0;
    while k < 196 {
        entries[k] = (k / 14, k % 14);
        k += 1;
    }
    entries
};

/// Every control on every rate.
const QUATERNION_INPUT_JACOBIAN: [(usize, usize); 14 * 4] = {
    let mut entries = [(0, 0); 56];
    let mut k = 0;
    while k < 56 {
        entries[k] = (k / 4, k % 4);
        k += 1;
    }
    entries
};

impl Model<f64, 14, 4> for InQuaternion<'_> {
    const NAME: &'static str = "aircraft_quaternion";
    const STATE: [&'static str; 14] = QUATERNION_STATE;
    const INPUTS: [&'static str; 4] = CONTROLS;
    const STATE_JACOBIAN: &'static [(usize, usize)] = &QUATERNION_JACOBIAN;
    const INPUT_JACOBIAN: &'static [(usize, usize)] = &QUATERNION_INPUT_JACOBIAN;

    fn rhs(&self, state: &[f64; 14], input: &[f64; 4]) -> [f64; 14] {
        (self.aircraft).rates_in((self.flown, Layout::QUATERNION), state, input)
    }

    fn kinetic_energy(&self, state: &[f64; 14]) -> f64 {
        kinetic_energy_in(self.flown, state)
    }

    fn state_jacobian(&self, state: &[f64; 14], input: &[f64; 4]) -> [[f64; 14]; 14] {
        (self.aircraft)
            .jacobians_in((self.flown, Layout::QUATERNION), state, input)
            .0
    }

    fn input_jacobian(&self, state: &[f64; 14], input: &[f64; 4]) -> [[f64; 4]; 14] {
        (self.aircraft)
            .jacobians_in((self.flown, Layout::QUATERNION), state, input)
            .1
    }
}

/// The quaternion form's state of an Euler-angle state: q = q_z(ψ) ⊗ q_y(θ) ⊗ q_x(φ), the
/// rest as it is.
pub fn quaternion_of(state: &[f64; 13]) -> [f64; 14] {
    let q = nalgebra::UnitQuaternion::from_euler_angles(state[3], state[4], state[5]);
    let mut out = [0.0; 14];
    out[..3].copy_from_slice(&state[..3]);
    out[3..7].copy_from_slice(&[q.w, q.i, q.j, q.k]);
    out[7..].copy_from_slice(&state[6..]);
    out
}

/// The Euler-angle state of a quaternion form's state, the quaternion normalised first (φ and
/// ψ are then one of the pairs that give it at θ = ±90°).
pub fn euler_of(state: &[f64; 14]) -> [f64; 13] {
    let q = nalgebra::UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(
        state[3], state[4], state[5], state[6],
    ));
    let (phi, theta, psi) = q.euler_angles();
    let mut out = [0.0; 13];
    out[..3].copy_from_slice(&state[..3]);
    out[3..6].copy_from_slice(&[phi, theta, psi]);
    out[6..].copy_from_slice(&state[7..]);
    out
}

/// Where the rates can depend on the state: V̇, α̇, β̇ on the wind axes, the attitude but the
/// heading, the rates, the altitude (the air) and the power (the thrust); the Euler angles'
/// rates on φ, θ and the rates; ṗ, q̇, ṙ on the wind axes, the rates and the altitude, and,
/// through C_mα̇'s α̇, on what α̇ depends on; the track on the wind axes and the attitude (the
/// altitude not on the heading); the power on itself.
const STATE_JACOBIAN: [(usize, usize); 3 * 10 + 3 * 5 + 3 * 10 + 2 * 6 + 5 + 1] = state_pattern();

const fn state_pattern() -> [(usize, usize); 93] {
    let mut entries = [(0, 0); 93];
    let mut k = 0;
    let mut row = 0;
    while row < 13 {
        let mut column = 0;
        while column < 13 {
            let wind = column < 3;
            let rates = column >= 6 && column < 9;
            let depends = match row {
                0..=2 | 6..=8 => wind || column == 3 || column == 4 || rates || column >= 11,
                3..=5 => column == 3 || column == 4 || rates,
                9 | 10 => column < 6,
                11 => column < 5,
                _ => column == 12,
            };
            if depends {
                entries[k] = (row, column);
                k += 1;
            }
            column += 1;
        }
        row += 1;
    }
    entries
}

/// The surfaces act on the forces and moments; the throttle on the power's rate.
const INPUT_JACOBIAN: [(usize, usize); 19] = [
    (0, 1),
    (0, 2),
    (0, 3),
    (1, 1),
    (1, 2),
    (1, 3),
    (2, 1),
    (2, 2),
    (2, 3),
    (6, 1),
    (6, 2),
    (6, 3),
    (7, 1),
    (7, 2),
    (7, 3),
    (8, 1),
    (8, 2),
    (8, 3),
    (12, 0),
];

/// The aircraft as a model like the catalog's, in f64 (the tables are looked up per call).
impl Model<f64, 13, 4> for AircraftModel {
    const NAME: &'static str = "aircraft";
    const STATE: [&'static str; 13] = STATE;
    const INPUTS: [&'static str; 4] = CONTROLS;
    const STATE_JACOBIAN: &'static [(usize, usize)] = &STATE_JACOBIAN;
    const INPUT_JACOBIAN: &'static [(usize, usize)] = &INPUT_JACOBIAN;

    fn rhs(&self, state: &[f64; 13], input: &[f64; 4]) -> [f64; 13] {
        self.rates(state, input)
    }

    fn kinetic_energy(&self, state: &[f64; 13]) -> f64 {
        AircraftModel::kinetic_energy(self, state)
    }

    fn state_jacobian(&self, state: &[f64; 13], input: &[f64; 4]) -> [[f64; 13]; 13] {
        self.jacobians(state, input).0
    }

    fn input_jacobian(&self, state: &[f64; 13], input: &[f64; 4]) -> [[f64; 4]; 13] {
        self.jacobians(state, input).1
    }
}
