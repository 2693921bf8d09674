//! The checks every scene's values go through, whatever its kind: each value against the one
//! set of [`Requirement`]s, the method and its settings (`integrator.*`), the `[linear]`
//! table's names against the model's — every error naming its key by its path in the file
//! (`integrator.step`). Each kind adds the checks of its own tables, in its folder, as
//! methods of the same [`Checker`].

use super::envelope::LinearTable;
use super::{DEFAULT_MAX_STEPS, DEFAULT_TOLERANCE, Method, Problem, SceneError, StopCondition};
use crate::ParameterError;
use crate::Short;
use crate::integrate::AdaptiveOptions;
use crate::validate::Requirement;

/// The checks of one scene file, each naming its key.
pub(crate) struct Checker<'a> {
    pub(crate) name: &'a str,
}

/// The keys of `[integrator]` that choose the method and its settings, as every scene gives
/// them.
pub(crate) struct MethodKeys<'a> {
    /// `integrator.method`.
    pub(crate) method: &'a str,
    /// `integrator.step`.
    pub(crate) step: Option<f64>,
    /// `integrator.rtol`.
    pub(crate) rtol: Option<f64>,
    /// `integrator.atol`.
    pub(crate) atol: Option<f64>,
    /// `integrator.max_steps`.
    pub(crate) max_steps: Option<u64>,
}

/// A method with its settings, checked.
pub(crate) struct MethodSettings {
    pub(crate) method: Method,
    pub(crate) step: Option<f64>,
    pub(crate) adaptive: Option<AdaptiveOptions>,
    pub(crate) max_steps: usize,
}

impl Checker<'_> {
    /// The error naming `key`.
    pub(crate) fn error(&self, key: &str, problem: Problem) -> SceneError {
        SceneError::new(self.name, key, problem)
    }

    /// `key`'s value cannot be used, and why.
    pub(crate) fn invalid(&self, key: &str, message: impl Into<String>) -> SceneError {
        self.error(key, Problem::Invalid(message.into()))
    }

    /// Refuses the name of manoeuvre `index` where an earlier manoeuvre has it: a manoeuvre's
    /// name is its folder in the output, and its key in the summary. The kinds with manoeuvres
    /// read scenes with feature `ship`.
    #[cfg(feature = "ship")]
    pub(crate) fn unique_manoeuvre<'n>(
        &self,
        index: usize,
        name: &str,
        mut earlier: impl Iterator<Item = &'n str>,
    ) -> Result<(), SceneError> {
        match earlier.any(|taken| taken == name) {
            true => Err(self.invalid(
                &format!("manoeuvre[{index}].name"),
                format!("`{name}` is taken by an earlier manoeuvre"),
            )),
            false => Ok(()),
        }
    }

    /// `key` is missing, and why it is needed.
    pub(crate) fn missing(&self, key: &str, why: &str) -> SceneError {
        self.error(key, Problem::Missing(why.to_owned()))
    }

    /// A value checked by the crate's parameter checks, the error naming its key.
    pub(crate) fn parameter(
        &self,
        key: &str,
        check: impl FnOnce() -> Result<f64, ParameterError>,
    ) -> Result<f64, SceneError> {
        check().map_err(|e| {
            self.invalid(
                key,
                format!("must be {}, got {}", e.requirement, Short(e.value)),
            )
        })
    }

    /// An error naming the first of `keys` that is given, where none may be.
    pub(crate) fn refuse_given(
        &self,
        keys: [(&str, bool); 2],
        why: &str,
    ) -> Result<(), SceneError> {
        match keys.iter().find(|(_, given)| *given) {
            Some((key, _)) => Err(self.invalid(key, why)),
            None => Ok(()),
        }
    }

    pub(crate) fn required(
        &self,
        key: &str,
        value: Option<f64>,
        what: &str,
    ) -> Result<f64, SceneError> {
        value.ok_or_else(|| self.missing(key, what))
    }

    /// One of `choices` by the word a scene-defined table gives, or the error naming `key`
    /// that the tables' words have always given: "`x`: expected `a` or `b`".
    #[cfg_attr(not(feature = "ship"), allow(dead_code))]
    pub(crate) fn word<V: Copy, const K: usize>(
        &self,
        key: &str,
        given: &str,
        choices: [(V, &str); K],
    ) -> Result<V, SceneError> {
        if let Some((value, _)) = choices.iter().find(|(_, name)| *name == given) {
            return Ok(*value);
        }
        let names: Vec<String> = choices.iter().map(|(_, n)| format!("`{n}`")).collect();
        let listed = match names.split_last() {
            Some((last, [])) => last.clone(),
            Some((last, rest)) => format!("{} or {last}", rest.join(", ")),
            None => String::new(),
        };
        Err(self.invalid(key, format!("`{given}`: expected {listed}")))
    }

    /// One of `values` by its name, or an error listing the names.
    pub(crate) fn named<V: Copy, const K: usize>(
        &self,
        key: &str,
        name: &str,
        values: [(V, &'static str); K],
        extra: &str,
    ) -> Result<V, SceneError> {
        values
            .iter()
            .find(|(_, n)| *n == name)
            .map(|(v, _)| *v)
            .ok_or_else(|| {
                let mut names: Vec<&str> = values.iter().map(|(_, n)| *n).collect();
                if !extra.is_empty() {
                    names.insert(0, extra);
                }
                self.invalid(
                    key,
                    format!("unknown value `{name}`; one of {}", names.join(", ")),
                )
            })
    }

    /// `value` if it meets `requirement`, else the error naming `key` ([`Requirement`], the
    /// one set of value checks).
    pub(crate) fn checked(
        &self,
        key: &str,
        requirement: Requirement,
        value: f64,
    ) -> Result<f64, SceneError> {
        requirement
            .check(value)
            .map_err(|violation| self.invalid(key, violation.to_string()))
    }

    /// A finite value, the error naming `key`.
    pub(crate) fn finite(&self, key: &str, value: f64) -> Result<f64, SceneError> {
        self.checked(key, Requirement::Finite, value)
    }

    /// A finite value above zero, the error naming `key`.
    #[cfg_attr(not(feature = "ship"), allow(dead_code))]
    pub(crate) fn positive(&self, key: &str, value: f64) -> Result<f64, SceneError> {
        self.checked(key, Requirement::Positive, value)
    }

    /// Three finite values (zeros where absent), the error naming the entry.
    pub(crate) fn finite3(
        &self,
        key: &str,
        value: Option<[f64; 3]>,
    ) -> Result<[f64; 3], SceneError> {
        let v = value.unwrap_or([0.0; 3]);
        for (i, x) in v.iter().enumerate() {
            self.finite(&format!("{key}[{i}]"), *x)?;
        }
        Ok(v)
    }

    /// The method and its settings for a run of `end_time` seconds: a fixed step for a
    /// fixed-step method (and no more than `max_steps` of it), tolerances for an adaptive one,
    /// and never the keys of the other kind.
    pub(crate) fn method_settings(
        &self,
        t: &MethodKeys<'_>,
        end_time: f64,
    ) -> Result<MethodSettings, SceneError> {
        let method = self.named("integrator.method", t.method, Method::ALL, "")?;
        let max_steps = match t.max_steps {
            None => DEFAULT_MAX_STEPS,
            Some(0) => {
                return Err(self.invalid("integrator.max_steps", "must be at least 1, got 0"));
            }
            Some(n) => usize::try_from(n).unwrap_or(usize::MAX),
        };
        let (step, adaptive) = if method.is_adaptive() {
            if t.step.is_some() {
                return Err(self.invalid(
                    "integrator.step",
                    format!(
                        "{} chooses its own steps; give rtol and atol",
                        method.name()
                    ),
                ));
            }
            let rtol = self.tolerance("integrator.rtol", t.rtol)?;
            let min_rtol = crate::integrate::min_rtol::<f64>();
            if rtol < min_rtol {
                return Err(self.invalid(
                    "integrator.rtol",
                    format!(
                        "must be at least {min_rtol:e}, ten rounding units of f64 (below it \
                         the method takes more steps for no accuracy), got {}",
                        Short(rtol)
                    ),
                ));
            }
            let atol = self.tolerance("integrator.atol", t.atol)?;
            let mut options = match method {
                Method::Dopri5 => AdaptiveOptions::dopri5(rtol, atol),
                _ => AdaptiveOptions::dop853(rtol, atol),
            };
            options.max_steps = max_steps;
            (None, Some(options))
        } else {
            self.refuse_given(
                [
                    ("integrator.rtol", t.rtol.is_some()),
                    ("integrator.atol", t.atol.is_some()),
                ],
                &format!("{} takes a fixed step; give integrator.step", method.name()),
            )?;
            let step = self.required("integrator.step", t.step, "the fixed step, s")?;
            let step = self.checked("integrator.step", Requirement::Positive, step)?;
            let steps = (end_time / step).ceil();
            if steps > max_steps as f64 {
                return Err(self.invalid(
                    "integrator.max_steps",
                    format!(
                        "the run needs {} steps of {} s to reach {} s, more than max_steps = \
                         {max_steps}",
                        Short(steps),
                        Short(step),
                        Short(end_time)
                    ),
                ));
            }
            (Some(step), None)
        };
        Ok(MethodSettings {
            method,
            step,
            adaptive,
            max_steps,
        })
    }

    fn tolerance(&self, key: &str, value: Option<f64>) -> Result<f64, SceneError> {
        self.checked(
            key,
            Requirement::Positive,
            value.unwrap_or(DEFAULT_TOLERANCE),
        )
    }

    /// The `[linear]` table, its names those of `model`'s state entries, inputs and their
    /// aliases, and its values finite.
    pub(crate) fn linear(
        &self,
        table: Option<&LinearTable>,
        model: &str,
        (state, inputs, aliases): (&[&str], &[&str], &[(&str, &str)]),
    ) -> Result<crate::linear::LinearSpec, SceneError> {
        let Some(table) = table else {
            return Ok(crate::linear::LinearSpec::default());
        };
        let known = |key: &str, name: &str| match crate::linear::resolve_aliased(
            name,
            (state, inputs),
            aliases,
        ) {
            Some(_) => Ok(()),
            None => {
                let also = aliases
                    .iter()
                    .map(|(alias, _)| *alias)
                    .collect::<Vec<_>>()
                    .join(", ");
                let also = if also.is_empty() {
                    String::new()
                } else {
                    format!(" (also named {also})")
                };
                Err(self.invalid(
                    key,
                    format!(
                        "`{name}` is not a state entry or an input of {model}: it has {} \
                             and {}{also}",
                        state.join(", "),
                        inputs.join(", ")
                    ),
                ))
            }
        };
        let mut spec = crate::linear::LinearSpec::default();
        for (name, value) in table.at.iter().flatten() {
            let key = format!("linear.at.{name}");
            known(&key, name)?;
            if !value.is_finite() {
                return Err(self.invalid(&key, "must be finite"));
            }
            spec.at.push((name.clone(), *value));
        }
        for (i, name) in table.trim.iter().flatten().enumerate() {
            known(&format!("linear.trim[{i}]"), name)?;
            spec.trim.push(name.clone());
        }
        if let Some(outputs) = &table.outputs {
            spec.outputs = self.linear_outputs(outputs, model, state)?;
        }
        Ok(spec)
    }

    /// `linear.outputs`: state entries of `model`, each once, at least one.
    fn linear_outputs(
        &self,
        names: &[String],
        model: &str,
        state: &[&str],
    ) -> Result<Vec<String>, SceneError> {
        if names.is_empty() {
            return Err(self.invalid(
                "linear.outputs",
                "names no output; leave it out for every entry of the reduced state",
            ));
        }
        let mut resolved = Vec::with_capacity(names.len());
        for (i, name) in names.iter().enumerate() {
            let key = format!("linear.outputs[{i}]");
            let Some(crate::linear::trim::Free::State(index)) =
                crate::linear::resolve(name, state, &[])
            else {
                return Err(self.invalid(
                    &key,
                    format!(
                        "`{name}` is not a state entry of {model}: it has {}",
                        state.join(", ")
                    ),
                ));
            };
            if resolved.contains(&index) {
                return Err(self.invalid(
                    &key,
                    format!(
                        "`{}` is already an output (each state entry is named once)",
                        state[index]
                    ),
                ));
            }
            resolved.push(index);
        }
        Ok(names.to_vec())
    }

    /// `integrator.stop_when`, as any kind gives it (`text`), read against `names`, what its
    /// trajectory.csv calls the columns of a row after `t` (before their units); refused where
    /// it holds at one of `starts`, the rows its runs start from at t = 0 (each with where it
    /// is, for the message: `""` for the one start of every run), since that run would end
    /// before it begins.
    pub(crate) fn stop_when<Name: AsRef<str>, Row: AsRef<[f64]>>(
        &self,
        text: Option<&str>,
        names: &[Name],
        starts: impl IntoIterator<Item = (String, Row)>,
    ) -> Result<Option<StopCondition>, SceneError> {
        let Some(text) = text else {
            return Ok(None);
        };
        let key = "integrator.stop_when";
        let names: Vec<String> = names.iter().map(|name| name.as_ref().to_owned()).collect();
        let condition =
            StopCondition::parse(text, &names).map_err(|message| self.invalid(key, message))?;
        for (place, row) in starts {
            let row = row.as_ref();
            if condition.holds(0.0, row) {
                let x = condition.index.map_or(0.0, |i| row[i]);
                return Err(self.invalid(
                    key,
                    format!(
                        "`{condition}` holds at the start{place} ({}), so the run would end \
                         before it begins",
                        Short(x)
                    ),
                ));
            }
        }
        Ok(Some(condition))
    }
}
