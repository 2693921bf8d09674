//! A `[loads]` table's values read and checked, each refused with its key: finite numbers,
//! vectors and lists of the right length, points of application, time tables, damping; and
//! the damping and levers they make.

use super::*;

/// A load's key path (`loads.force_body`) and what is wrong with its value.
pub(super) type LoadError = (String, Problem);

pub(super) fn invalid(key: &str, message: String) -> LoadError {
    (format!("loads.{key}"), Problem::Invalid(message))
}

/// Every entry finite; the key path names the first that is not.
pub(super) fn finite<const K: usize>(key: &str, values: [f64; K]) -> Result<[f64; K], LoadError> {
    checked(key, Requirement::Finite, values)
}

/// Every entry meets `requirement` ([`Requirement`], the one set of value checks); the key
/// path names the first that does not.
pub(super) fn checked<const K: usize>(
    key: &str,
    requirement: Requirement,
    values: [f64; K],
) -> Result<[f64; K], LoadError> {
    requirement
        .check_all(values)
        .map_err(|(i, violation)| invalid(&format!("{key}[{i}]"), violation.to_string()))
}

pub(super) fn scalar(key: &str, value: Option<f64>) -> Result<f64, LoadError> {
    Ok(finite(key, [value.unwrap_or(0.0)])?[0])
}

pub(super) fn vector(key: &str, value: Option<[f64; 3]>) -> Result<[f64; 3], LoadError> {
    finite(key, value.unwrap_or([0.0; 3]))
}

/// A list of exactly `K` entries (zeros when absent).
pub(super) fn list<const K: usize>(
    key: &str,
    values: &Option<Vec<f64>>,
) -> Result<[f64; K], LoadError> {
    let Some(values) = values else {
        return Ok([0.0; K]);
    };
    let array: [f64; K] = values
        .as_slice()
        .try_into()
        .map_err(|_| invalid(key, format!("must have {K} entries, got {}", values.len())))?;
    finite(key, array)
}

/// The point a force acts at, body axes from G (zeros when absent), refused without its
/// force: it would be ignored.
pub(super) fn point<const K: usize>(
    key: &str,
    values: &Option<Vec<f64>>,
    force: (&str, bool),
) -> Result<[f64; K], LoadError> {
    if values.is_some() && !force.1 {
        return Err(invalid(key, format!("is given without loads.{}", force.0)));
    }
    list(key, values)
}

/// The forces a planar (`K` = 2) or spatial (`K` = 3) scene states, read alike: in body and
/// in space axes, each constant or a time table, each at the body origin or at a point.
pub(super) struct Forces<const K: usize> {
    pub(super) body: [f64; K],
    pub(super) space: [f64; K],
    pub(super) body_at: [f64; K],
    pub(super) space_at: [f64; K],
}

impl<const K: usize> Forces<K> {
    pub(super) fn read(table: &LoadsTable, tables: &mut Vec<TimedLoad>) -> Result<Self, LoadError> {
        let given = |force: &Option<Timed<Vec<f64>>>| force.is_some();
        Ok(Forces {
            body: timed("force_body", &table.force_body, (Target::ForceBody, tables))?,
            space: timed(
                "force_space",
                &table.force_space,
                (Target::ForceSpace, tables),
            )?,
            body_at: point(
                "force_body_at",
                &table.force_body_at,
                ("force_body", given(&table.force_body)),
            )?,
            space_at: point(
                "force_space_at",
                &table.force_space_at,
                ("force_space", given(&table.force_space)),
            )?,
        })
    }
}

/// A load that may be a time table: its constant (zeros when absent or tabulated), its table
/// pushed onto `tables` for `target`.
pub(super) fn timed<const K: usize>(
    key: &str,
    value: &Option<Timed<Vec<f64>>>,
    (target, tables): (Target, &mut Vec<TimedLoad>),
) -> Result<[f64; K], LoadError> {
    match value {
        None => Ok([0.0; K]),
        Some(Timed::Constant(v)) => list(key, &Some(v.clone())),
        Some(Timed::Table(spec)) => {
            let table = TimeTable::new(&format!("loads.{key}"), spec, K)
                .map_err(|(key, message)| (key, Problem::Invalid(message)))?;
            tables.push(TimedLoad { target, table });
            Ok([0.0; K])
        }
    }
}

/// [`timed`] for a scalar load (`moment`).
pub(super) fn timed_scalar(
    key: &str,
    value: &Option<Timed<f64>>,
    (target, tables): (Target, &mut Vec<TimedLoad>),
) -> Result<f64, LoadError> {
    match value {
        None => Ok(0.0),
        Some(Timed::Constant(v)) => scalar(key, Some(*v)),
        Some(Timed::Table(spec)) => {
            let table = TimeTable::scalar(&format!("loads.{key}"), spec)
                .map_err(|(key, message)| (key, Problem::Invalid(message)))?;
            tables.push(TimedLoad { target, table });
            Ok(0.0)
        }
    }
}

/// The moment r × F of a force F at r, in the plane: its component along the vertical.
pub(super) fn lever_2d(r: [f64; 2], f: [f64; 2]) -> f64 {
    r[0] * f[1] - r[1] * f[0]
}

/// Damping coefficients: finite and not negative (a negative one would feed energy in).
pub(super) fn damping<const K: usize>(
    key: &str,
    values: &Option<Vec<f64>>,
) -> Result<[f64; K], LoadError> {
    checked(key, Requirement::NonNegative, list::<K>(key, values)?)
}

/// −d₁x − d₂x|x|.
pub(super) fn damped(linear: f64, quadratic: f64, x: f64) -> f64 {
    -linear * x - quadratic * x * x.abs()
}

/// Adds each velocity's damping, [`damped`], to its load, where `acting` says the scene has
/// any: an undamped body's inputs then do not depend on its state, and a model's stage need
/// not wait on them.
pub(super) fn add_damping(
    acting: Acting,
    (linear, quadratic): (&[f64], &[f64]),
    velocities: &[f64],
    loads: &mut [f64],
) {
    if !acting.damping {
        return;
    }
    let coefficients = linear.iter().zip(quadratic);
    for ((load, (&linear, &quadratic)), &x) in loads.iter_mut().zip(coefficients).zip(velocities) {
        *load += damped(linear, quadratic, x);
    }
}

pub(super) fn all_zero<'a>(values: impl IntoIterator<Item = &'a f64>) -> bool {
    values.into_iter().all(|x| *x == 0.0)
}
