//! A scene, linearised: the operating point its `[linear]` table names (by default
//! its initial state), the states set aside, the trim, A, B and the modes.

use super::modes::{Mode, Stability, growth_tolerance, modes};
use super::plant::LinearPlant;
use super::reduce::{SetAsideReason, set_aside_why};
use super::trim::{Free, trim};
use super::{EQUILIBRIUM_TOLERANCE, LinearError, rate_scale};
use crate::models::Family;
use nalgebra::{Complex, DMatrix};

/// What a `[linear]` table says, its names checked against the model's layout.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct LinearSpec {
    /// State entries and inputs set at the operating point, by the model's names (SI,
    /// radians); an input is added to the loads'.
    pub at: Vec<(String, f64)>,
    /// The free variables the trim solves for.
    pub trim: Vec<String>,
    /// The outputs y = C x of the linear model, state entries by name; empty for every entry
    /// of the reduced state (C the identity).
    pub outputs: Vec<String>,
}

/// A state entry or an input of a model, by its name: exactly as the model names it, or
/// as the trajectory does (any case) where that is unambiguous.
pub fn resolve(name: &str, state: &[&str], inputs: &[&str]) -> Option<Free> {
    let exact = |list: &[&str]| list.iter().position(|s| *s == name);
    let loose = |list: &[&str]| {
        let found: Vec<usize> = (0..list.len())
            .filter(|&i| list[i].eq_ignore_ascii_case(name))
            .collect();
        (found.len() == 1).then(|| found[0])
    };
    exact(state)
        .map(Free::State)
        .or_else(|| exact(inputs).map(Free::Input))
        .or_else(|| loose(state).map(Free::State))
        .or_else(|| loose(inputs).map(Free::Input))
}

/// [`resolve`], or by one of `aliases` (alias, name), any case.
pub fn resolve_aliased(
    name: &str,
    (state, inputs): (&[&str], &[&str]),
    aliases: &[(&str, &str)],
) -> Option<Free> {
    resolve(name, state, inputs).or_else(|| {
        let (_, named) = aliases
            .iter()
            .find(|(alias, _)| alias.eq_ignore_ascii_case(name))?;
        resolve(named, state, inputs)
    })
}

/// A scene, linearised about its operating point.
#[derive(Debug, Clone)]
pub struct Linearisation {
    /// The model linearised (for a quaternion top, its Euler-angle twin: see `note`).
    pub model: &'static str,
    /// Its family.
    pub family: Family,
    /// Every state entry's name, in the model's layout.
    pub state_names: Vec<&'static str>,
    /// Every input's name.
    pub input_names: Vec<&'static str>,
    /// The state at the operating point.
    pub state: Vec<f64>,
    /// The inputs at the operating point: the loads' there plus what the table adds.
    pub inputs: Vec<f64>,
    /// The indices of the reduced state.
    pub reduced: Vec<usize>,
    /// The indices set aside.
    pub set_aside: Vec<usize>,
    /// Why each of them was set aside, in the order of `set_aside`.
    pub set_aside_why: Vec<SetAsideReason>,
    /// The outputs y = C x + D u, as indices of the state (each in the reduced state): the
    /// `[linear]` table's `outputs`, or the whole reduced state.
    pub outputs: Vec<usize>,
    /// How A and B were obtained ([`LinearPlant::jacobians`]).
    pub jacobians: &'static str,
    /// The rates of the reduced state at the point (zero at an equilibrium).
    pub residual: Vec<f64>,
    /// Whether the point is an equilibrium of the reduced state (to
    /// [`EQUILIBRIUM_TOLERANCE`]).
    pub equilibrium: bool,
    /// The free variables solved for and their values, with the Newton steps taken.
    pub trimmed: Option<(Vec<(String, f64)>, usize)>,
    /// A on the reduced state.
    pub a: DMatrix<f64>,
    /// B: the reduced state's rates by every input.
    pub b: DMatrix<f64>,
    /// The eigenvalues of A, largest real part first.
    pub eigenvalues: Vec<Complex<f64>>,
    /// The modes.
    pub modes: Vec<Mode>,
    /// The verdict, where one holds: `None` at a point that is not an equilibrium of the
    /// reduced state, whose A describes no motion that stays near it.
    pub stability: Option<Stability>,
    /// The size below which a real part counted as zero, 1/s
    /// ([`growth_tolerance`](super::modes::growth_tolerance)).
    pub growth_tolerance: f64,
    /// What was done that the scene did not say (a quaternion top linearised in Euler angles).
    pub note: Option<String>,
    /// The units of the state entries and inputs, by name, where the plant gives its own
    /// ([`LinearPlant::units`]); the others have their names' SI units.
    pub units: Vec<(&'static str, &'static str)>,
}

impl Linearisation {
    /// The unit of the state entry or input `name`: the plant's own, else its name's SI unit
    /// (`input` for an input).
    pub fn unit(&self, name: &str, input: bool) -> Option<&'static str> {
        match self.units.iter().find(|(n, _)| *n == name) {
            Some((_, unit)) => Some(unit),
            None if input => crate::models::input_unit(name),
            None => crate::models::state_unit(name),
        }
    }

    /// The names of the reduced state.
    pub fn reduced_names(&self) -> Vec<&'static str> {
        self.reduced.iter().map(|&i| self.state_names[i]).collect()
    }

    /// The names of the states set aside.
    pub fn set_aside_names(&self) -> Vec<&'static str> {
        self.set_aside
            .iter()
            .map(|&i| self.state_names[i])
            .collect()
    }

    /// The reduced state at the point, x₀ of the linear model.
    pub fn reduced_state(&self) -> Vec<f64> {
        self.reduced.iter().map(|&i| self.state[i]).collect()
    }

    /// The values of the states set aside at the point.
    pub fn set_aside_values(&self) -> Vec<f64> {
        self.set_aside.iter().map(|&i| self.state[i]).collect()
    }

    /// The names of the outputs.
    pub fn output_names(&self) -> Vec<&'static str> {
        self.outputs.iter().map(|&i| self.state_names[i]).collect()
    }

    /// C: each output's row picks its entry of the reduced state.
    pub fn c(&self) -> DMatrix<f64> {
        DMatrix::from_fn(self.outputs.len(), self.reduced.len(), |row, column| {
            f64::from(u8::from(self.reduced[column] == self.outputs[row]))
        })
    }

    /// D: zero, the outputs being state entries.
    pub fn d(&self) -> DMatrix<f64> {
        DMatrix::zeros(self.outputs.len(), self.input_names.len())
    }
}

/// Sets the `at` entries of `spec` in the state and the inputs added to what acts, by the
/// names of the state entries, of the inputs and their aliases.
pub fn set_at(
    spec: &LinearSpec,
    (state_names, input_names, aliases): (&[&str], &[&str], &[(&str, &str)]),
    (state, extra): (&mut [f64], &mut [f64]),
) -> Result<(), LinearError> {
    for (name, value) in &spec.at {
        match resolve_aliased(name, (state_names, input_names), aliases) {
            Some(Free::State(i)) => state[i] = *value,
            Some(Free::Input(i)) => extra[i] = *value,
            None => return Err(unknown(name)),
        }
    }
    Ok(())
}

/// Linearises `plant` about `(state, extra)`, trimmed for the free variables `spec.trim`
/// names (its `at` entries are the caller's, already in the point): the states set aside, A
/// and B on the reduced state, the outputs `spec.outputs` names, the modes and the verdict.
pub fn linearise(
    plant: &dyn LinearPlant,
    (state, extra): (Vec<f64>, Vec<f64>),
    spec: &LinearSpec,
) -> Result<Linearisation, LinearError> {
    let trim_names = &spec.trim;
    let state_names = plant.state_names();
    let input_names = plant.input_names();
    let first = plant.evaluate(&state, &extra)?;
    let depends = dependencies(&plant.pattern(), &first.a);
    let coordinate: Vec<bool> = state_names.iter().map(|s| is_coordinate(s)).collect();
    let (set_aside, set_aside_why): (Vec<usize>, Vec<SetAsideReason>) =
        set_aside_why(&depends, &first.rates, &state, &coordinate)
            .into_iter()
            .unzip();
    let reduced: Vec<usize> = (0..state.len())
        .filter(|i| !set_aside.contains(i))
        .collect();
    let outputs = outputs(
        &spec.outputs,
        (&state_names, &reduced),
        (&set_aside, &set_aside_why),
        plant.name(),
    )?;
    let (state, extra, trimmed) = if trim_names.is_empty() {
        (state, extra, None)
    } else {
        let free = trim_names
            .iter()
            .map(|name| {
                resolve_aliased(name, (&state_names, &input_names), plant.aliases())
                    .ok_or_else(|| unknown(name))
            })
            .collect::<Result<Vec<_>, _>>()?;
        let names = trim_names.join(", ");
        let solved = trim(plant, (&state, &extra), &reduced, &free, &names)?;
        let values = trim_names
            .iter()
            .zip(&free)
            .map(|(name, f)| match *f {
                Free::State(i) => (name.clone(), solved.state[i]),
                Free::Input(i) => (name.clone(), solved.extra[i]),
            })
            .collect();
        (
            solved.state,
            solved.extra,
            Some((values, solved.iterations)),
        )
    };
    let at = plant.evaluate(&state, &extra)?;
    let residual: Vec<f64> = reduced.iter().map(|&i| at.rates[i]).collect();
    let tolerance = EQUILIBRIUM_TOLERANCE * rate_scale(&state);
    let a = at.a.select_rows(&reduced).select_columns(&reduced);
    let b = at.b.select_rows(&reduced);
    let names: Vec<String> = reduced.iter().map(|&i| state_names[i].to_owned()).collect();
    let family = plant.family();
    // A top's roll and pitch are measured in axes turned by its heading, which turns with
    // the spin: its modes are also given as seen in space.
    let heading_rate = match state_names.iter().position(|s| *s == "psi") {
        Some(i) if family == Family::Top && set_aside.contains(&i) => at.rates[i],
        _ => 0.0,
    };
    let all_readings = plant.readings(&state);
    let readings: Vec<_> = (reduced.iter())
        .map(|&i| all_readings.get(i).copied().unwrap_or(super::Reading::AsIs))
        .collect();
    let (eigenvalues, mut modes, stability) =
        modes(&a, (&names, &readings), plant.naming(), heading_rate);
    let equilibrium = residual.iter().all(|r| r.abs() <= tolerance);
    if !equilibrium {
        // Away from an equilibrium the eigenvalues of A describe no motion that stays near
        // the point: no mode is named as if it were one.
        modes.iter_mut().for_each(|mode| mode.name = None);
    }
    Ok(Linearisation {
        model: plant.name(),
        family,
        state_names,
        input_names,
        inputs: plant.inputs(&state, &extra),
        equilibrium,
        stability: equilibrium.then_some(stability),
        growth_tolerance: growth_tolerance(&a),
        state,
        reduced,
        set_aside,
        set_aside_why,
        outputs,
        jacobians: plant.jacobians(),
        units: plant.units(),
        residual,
        trimmed,
        a,
        b,
        eigenvalues,
        modes,
        note: None,
    })
}

/// A position, an angle or a quaternion's part, by its unit, rather than a velocity.
fn is_coordinate(name: &str) -> bool {
    matches!(crate::models::state_unit(name), Some("m" | "rad" | "-"))
}

fn unknown(name: &str) -> LinearError {
    LinearError::Unknown(name.to_owned())
}

/// The outputs `names` names, as indices of the state: each must be in the reduced state (a
/// state set aside has no row in A). No names: the whole reduced state.
fn outputs(
    names: &[String],
    (state_names, reduced): (&[&str], &[usize]),
    (set_aside, why): (&[usize], &[SetAsideReason]),
    model: &str,
) -> Result<Vec<usize>, LinearError> {
    if names.is_empty() {
        return Ok(reduced.to_vec());
    }
    let reduced_names: Vec<&str> = reduced.iter().map(|&i| state_names[i]).collect();
    let refused = |index: usize, name: &str, why: String| LinearError::Output {
        index,
        name: name.to_owned(),
        why,
        reduced: reduced_names.join(", "),
    };
    (names.iter().enumerate())
        .map(|(index, name)| match resolve(name, state_names, &[]) {
            Some(Free::State(i)) if reduced.contains(&i) => Ok(i),
            Some(Free::State(i)) => {
                let reason = set_aside
                    .iter()
                    .position(|&j| j == i)
                    .map_or("", |k| why[k].describe());
                Err(refused(
                    index,
                    name,
                    format!("is set aside at this point (it {reason}), so A has no row for it"),
                ))
            }
            _ => Err(refused(
                index,
                name,
                format!("is not a state entry of the model linearised ({model})"),
            )),
        })
        .collect()
}

/// Row i depends on state j: the declared pattern, and what the loads add at the point.
fn dependencies(pattern: &[(usize, usize)], a: &DMatrix<f64>) -> Vec<Vec<bool>> {
    let n = a.nrows();
    let mut depends: Vec<Vec<bool>> = (0..n)
        .map(|i| (0..n).map(|j| a[(i, j)] != 0.0).collect())
        .collect();
    for &(i, j) in pattern {
        depends[i][j] = true;
    }
    depends
}
