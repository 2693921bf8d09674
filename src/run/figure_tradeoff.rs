//! What each integration choice costs on what a scene of manoeuvres gives its user: its
//! figures. The scene is read again at each setting of every method it can name (its
//! `[integrator]` replaced, every other key as written), run whole through its kind, and each
//! figure of each run (a turning circle's tactical diameter on each side, a zig-zag's
//! overshoots) compared with the reference run's: DOP853 at rtol = atol = [`REFERENCE`].
//!
//! A figure's error is the largest |value − reference| over the runs that gave both, in the
//! figure's own unit (its key's suffix: `_m`, `_deg`, `_s`, `_deg_s`, `_m_s`); a run that did
//! not give a figure the reference gave counts as failing it. Each unit has a target a naval
//! architect would accept ([`Targets::default`]: 0.01 m, 0.001°, 0.01 s, 10⁻⁴ °/s and m/s),
//! which the user may set. A setting is recommended only where the errors converge
//! ([`FigureTradeoff::recommend`]): it and every tighter setting of its method meet every
//! target, and the reference repeats itself within them (DOP853 at [`REFERENCE_CHECKS`]
//! lands within every target of it). Cost is the right-hand-side evaluations of the scene's
//! runs at the setting (its refined runs aside), which repeat where wall times do not; the
//! wall time of the scene's whole run (its refined runs included, as `eom run` makes them)
//! stands beside them.
//!
//! Unlike a catalog body's end-state comparison ([`super::tradeoff`]), this needs nothing of
//! the kind but its [`Summary`]'s figures, so it serves every kind whose runs give figures.

use crate::integrate::Method;
use crate::kinds::KindError;
use crate::output::summary::Summary;
use crate::run::record::Discard;
use crate::scene::{AnyScene, SceneError};
use std::path::Path;
use std::time::Instant;
use toml::{Table, Value};

/// The reference's tolerance, DOP853.
pub const REFERENCE: f64 = 1e-12;

/// The tolerances of the DOP853 settings whose spread from the reference tells whether the
/// reference repeats itself.
pub const REFERENCE_CHECKS: [f64; 2] = [1e-10, 1e-11];

/// The tolerances the adaptive methods are swept over.
pub const TOLERANCES: [f64; 8] = [1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11];

/// The fixed steps, as the rows' interval (`output.every`) divided by these, so that every
/// row falls on a step.
pub const STEP_DIVISORS: [u32; 7] = [1, 2, 5, 10, 20, 50, 100];

/// The rows' interval a scene's tables give: `output.every`, or else its fixed step.
pub fn rows_interval(table: &Table) -> Option<f64> {
    let number = |name: &str, key: &str| {
        let value = table.get(name)?.get(key)?;
        value
            .as_float()
            .or_else(|| value.as_integer().map(|i| i as f64))
    };
    number("output", "every").or_else(|| number("integrator", "step"))
}

/// A method and its setting: a fixed step, or an adaptive method's tolerance.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Setting {
    /// The method.
    pub method: Method,
    /// Its fixed step, s.
    pub step: Option<f64>,
    /// An adaptive method's rtol = atol.
    pub tolerance: Option<f64>,
}

impl Setting {
    /// The setting as the table writes it: `step = 0.1 s` or `rtol = atol = 1e-9`.
    pub fn describe(&self) -> String {
        match (self.step, self.tolerance) {
            (Some(step), _) => format!("step = {step} s"),
            (None, Some(tolerance)) => format!("rtol = atol = {tolerance:e}"),
            (None, None) => String::new(),
        }
    }

    /// `table` with its `[integrator]` set to this setting, every other key kept.
    fn applied(&self, table: &Table) -> Table {
        let mut table = table.clone();
        let integrator = table
            .entry("integrator")
            .or_insert_with(|| Value::Table(Table::new()));
        if let Value::Table(integrator) = integrator {
            for key in ["method", "step", "rtol", "atol"] {
                integrator.remove(key);
            }
            integrator.insert("method".into(), self.method.name().into());
            if let Some(step) = self.step {
                integrator.insert("step".into(), step.into());
            }
            if let Some(tolerance) = self.tolerance {
                integrator.insert("rtol".into(), tolerance.into());
                integrator.insert("atol".into(), tolerance.into());
            }
        }
        table
    }
}

/// The settings a scene whose rows are `every` apart is compared over: RK4 at `every` over
/// each of [`STEP_DIVISORS`], then DOPRI5 and DOP853 at each of [`TOLERANCES`].
pub fn settings(every: f64) -> Vec<Setting> {
    let fixed = STEP_DIVISORS.iter().map(|divisor| Setting {
        method: Method::Rk4,
        step: Some(every / f64::from(*divisor)),
        tolerance: None,
    });
    let adaptive = [Method::Dopri5, Method::Dop853]
        .into_iter()
        .flat_map(|method| {
            TOLERANCES.iter().map(move |&tolerance| Setting {
                method,
                step: None,
                tolerance: Some(tolerance),
            })
        });
    fixed.chain(adaptive).collect()
}

/// The target error of each figure, by its unit.
#[derive(Debug, Clone, PartialEq)]
pub struct Targets(pub Vec<(String, f64)>);

impl Default for Targets {
    /// 0.01 m, 0.001°, 0.01 s, 10⁻⁴ °/s, 10⁻⁴ m/s.
    fn default() -> Self {
        let units = [
            ("m", 0.01),
            ("deg", 0.001),
            ("s", 0.01),
            ("deg_s", 1e-4),
            ("m_s", 1e-4),
        ];
        Targets(units.iter().map(|(u, t)| ((*u).to_owned(), *t)).collect())
    }
}

impl Targets {
    /// The target of the figure `key`: its own where one is set under its whole key
    /// (`dutch_roll_damping`), else by the longest unit its key ends in (`_deg_s` before `_s`);
    /// `None` for a figure of another unit, which is compared but not judged.
    pub fn of(&self, key: &str) -> Option<f64> {
        (self.0.iter())
            .filter(|(unit, _)| key == unit || key.ends_with(&format!("_{unit}")))
            .max_by_key(|(unit, _)| unit.len())
            .map(|(_, target)| *target)
    }

    /// Sets the target of `unit` (`m`, `deg`, …, or a figure's whole key), a unit of its own
    /// if no default has it.
    pub fn set(&mut self, unit: &str, target: f64) {
        match self.0.iter_mut().find(|(u, _)| u == unit) {
            Some(entry) => entry.1 = target,
            None => self.0.push((unit.to_owned(), target)),
        }
    }
}

/// One figure's error at one setting.
#[derive(Debug, Clone, PartialEq)]
pub struct FigureError {
    /// The figure's key (`tactical_diameter_m`).
    pub key: String,
    /// The largest |value − reference| over the runs; `None` where a run did not give a
    /// figure the reference gave.
    pub error: Option<f64>,
}

/// One setting's outcome.
#[derive(Debug, Clone, PartialEq)]
pub struct FigureRow {
    /// The setting.
    pub setting: Setting,
    /// Accepted steps over every run.
    pub steps: u64,
    /// Right-hand-side evaluations over every run, where the kind counts them.
    pub rhs_evals: Option<u64>,
    /// Wall time of the scene's run, s.
    pub seconds: f64,
    /// Each figure's error, in the order the reference gives them.
    pub errors: Vec<FigureError>,
    /// Why the scene's run failed at this setting, if it did.
    pub failure: Option<String>,
}

impl FigureRow {
    /// Whether every figure with a target is within it.
    pub fn meets(&self, targets: &Targets) -> bool {
        self.failure.is_none()
            && (self.errors.iter()).all(|figure| match targets.of(&figure.key) {
                Some(target) => figure.error.is_some_and(|error| error <= target),
                None => true,
            })
    }

    /// What the setting costs, to compare settings by: its right-hand-side evaluations where
    /// the kind counts them, else its wall time.
    pub fn cost(&self) -> f64 {
        self.rhs_evals.map_or(self.seconds, |evals| evals as f64)
    }

    /// The figure furthest from its target, as (key, error, error / target).
    pub fn worst(&self, targets: &Targets) -> Option<(&str, Option<f64>, f64)> {
        (self.errors.iter())
            .filter_map(|figure| {
                let target = targets.of(&figure.key)?;
                let ratio = figure.error.map_or(f64::INFINITY, |error| error / target);
                Some((figure.key.as_str(), figure.error, ratio))
            })
            .max_by(|a, b| a.2.total_cmp(&b.2))
    }
}

/// The whole comparison.
#[derive(Debug, Clone)]
pub struct FigureTradeoff {
    /// What the errors are measured against.
    pub reference: String,
    /// The reference run's accepted steps, right-hand-side evaluations and wall time, s.
    pub reference_cost: (u64, Option<u64>, f64),
    /// The figures compared, by key, in the order the reference gives them.
    pub keys: Vec<String>,
    /// Every setting, method by method, coarsest first.
    pub rows: Vec<FigureRow>,
}

/// What the comparison recommends for its targets.
#[derive(Debug, Clone, PartialEq)]
pub enum FigureRecommendation<'a> {
    /// The cheapest setting that meets every target where its method's tighter settings do
    /// too.
    Setting(&'a FigureRow),
    /// No setting is recommended, and why.
    None(String),
}

impl FigureTradeoff {
    /// The figures compared whose unit has no target in `targets`: shown, not judged.
    pub fn not_judged<'a>(&'a self, targets: &Targets) -> Vec<&'a str> {
        (self.keys.iter())
            .filter(|key| targets.of(key).is_none())
            .map(String::as_str)
            .collect()
    }

    /// The cheapest setting ([`FigureRow::cost`]) meeting `targets` where the errors converge,
    /// or why there is none.
    pub fn recommend(&self, targets: &Targets) -> FigureRecommendation<'_> {
        let checks = (self.rows.iter()).filter(|row| {
            row.setting.method == Method::Dop853
                && (row.setting.tolerance).is_some_and(|t| REFERENCE_CHECKS.contains(&t))
        });
        if let Some(check) = checks.into_iter().find(|row| !row.meets(targets)) {
            let worst = check
                .worst(targets)
                .map_or_else(String::new, |(key, error, _)| {
                    format!(
                        ": {key} moves by {}",
                        error.map_or("all".into(), |e| format!("{e:.2e}"))
                    )
                });
            return FigureRecommendation::None(format!(
                "the reference does not repeat itself within the targets (DOP853 at {} lands \
                 off it{worst})",
                check.setting.describe()
            ));
        }
        let converged = |index: usize| {
            let method = self.rows[index].setting.method;
            (self.rows[index..].iter())
                .filter(|row| row.setting.method == method)
                .all(|row| row.meets(targets))
        };
        let best = (0..self.rows.len())
            .filter(|&index| converged(index))
            .map(|index| &self.rows[index])
            .min_by(|a, b| a.cost().total_cmp(&b.cost()));
        match best {
            Some(row) => FigureRecommendation::Setting(row),
            None => FigureRecommendation::None(
                "no setting meets every target with every tighter setting of its method".into(),
            ),
        }
    }
}

/// Why a scene's figures could not be compared.
#[derive(Debug, thiserror::Error)]
pub enum FigureTradeoffError {
    /// The scene, or the scene at a setting, could not be read.
    #[error(transparent)]
    Scene(#[from] SceneError),
    /// The reference run failed.
    #[error("the reference run (DOP853 at rtol = atol = {REFERENCE:e}) failed: {0}")]
    Reference(KindError),
    /// The scene's runs give no figures to compare.
    #[error("the scene's runs give no figures to compare")]
    NoFigures,
    /// A figure asked for by key that the scene's runs do not give.
    #[error("the scene's runs give no figure {key}; they give {}", known.join(", "))]
    UnknownFigure {
        /// The key asked for.
        key: String,
        /// The keys the runs give, in their order.
        known: Vec<String>,
    },
}

/// Compares every setting of [`settings`] on the figures of the scene whose tables are
/// `table` (`name` how errors name it, `base` where a file it names is found), its rows
/// `every` apart. Each of `asked`, figures a caller will show, must be one the reference run
/// gives: one that is not is refused before any setting runs.
pub fn compare(
    table: &Table,
    (name, base): (&str, &Path),
    every: f64,
    asked: &[String],
) -> Result<FigureTradeoff, FigureTradeoffError> {
    let reference = Setting {
        method: Method::Dop853,
        step: None,
        tolerance: Some(REFERENCE),
    };
    // The scene as written must read: an error there is the user's, with its key.
    AnyScene::from_table(table.clone(), name, base)?;
    let (summary, seconds) =
        run_at(table, (name, base), &reference).map_err(FigureTradeoffError::Reference)?;
    let wanted = figures(&summary);
    if wanted.is_empty() {
        return Err(FigureTradeoffError::NoFigures);
    }
    let mut keys: Vec<String> = Vec::new();
    for (_, key, _) in &wanted {
        if !keys.contains(key) {
            keys.push(key.clone());
        }
    }
    if let Some(key) = asked.iter().find(|key| !keys.contains(key)) {
        let key = key.clone();
        return Err(FigureTradeoffError::UnknownFigure { key, known: keys });
    }
    let mut rows = Vec::new();
    for setting in settings(every) {
        rows.push(match run_at(table, (name, base), &setting) {
            Ok((ran, seconds)) => FigureRow {
                setting,
                steps: ran.integrator.steps,
                rhs_evals: ran.integrator.rhs_evals,
                seconds,
                errors: errors(&wanted, &ran),
                failure: None,
            },
            // A setting the scene refuses (more steps than its max_steps) fails as a run does.
            Err(error) => FigureRow {
                setting,
                steps: 0,
                rhs_evals: None,
                seconds: f64::NAN,
                errors: Vec::new(),
                failure: Some(error.to_string()),
            },
        });
    }
    Ok(FigureTradeoff {
        keys,
        reference: format!("DOP853 at rtol = atol = {REFERENCE:e}"),
        reference_cost: (
            summary.integrator.steps,
            summary.integrator.rhs_evals,
            seconds,
        ),
        rows,
    })
}

/// The scene read at `setting` and run whole, its rows dropped: its summary and wall time, or
/// why it could not be read at the setting (more steps than its `max_steps`) or run.
fn run_at(
    table: &Table,
    (name, base): (&str, &Path),
    setting: &Setting,
) -> Result<(Summary, f64), KindError> {
    let scene = AnyScene::from_table(setting.applied(table), name, base)
        .map_err(|error| KindError::Scene(Box::new(error)))?
        .into_kind();
    let clock = Instant::now();
    let finished = scene.run(name, &mut Discard)?;
    let seconds = clock.elapsed().as_secs_f64();
    match finished.failure() {
        Some(error) => Err(error),
        None => Ok((finished.summary(), seconds)),
    }
}

/// Every figure the reference gave: (run, key, value).
fn figures(summary: &Summary) -> Vec<(String, String, f64)> {
    (summary.runs.iter())
        .flat_map(|run| {
            (run.figures.iter())
                .filter_map(|figure| Some((run.run.clone(), figure.key.clone(), figure.value?)))
        })
        .collect()
}

/// Each figure's largest error over the runs, in the order `wanted` first names them.
fn errors(wanted: &[(String, String, f64)], ran: &Summary) -> Vec<FigureError> {
    let mut errors: Vec<FigureError> = Vec::new();
    for (run, key, reference) in wanted {
        let error = ran.figure(run, key).map(|value| (value - reference).abs());
        match errors.iter_mut().find(|figure| figure.key == *key) {
            Some(figure) => {
                figure.error = match (figure.error, error) {
                    (Some(a), Some(b)) => Some(a.max(b)),
                    _ => None,
                };
            }
            None => errors.push(FigureError {
                key: key.clone(),
                error,
            }),
        }
    }
    errors
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_figure_s_target_is_its_unit_s_the_longest_suffix_first() {
        let mut targets = Targets::default();
        assert_eq!(targets.of("tactical_diameter_m"), Some(0.01));
        assert_eq!(targets.of("first_overshoot_deg"), Some(0.001));
        assert_eq!(targets.of("loop_height_deg_s"), Some(1e-4));
        assert_eq!(targets.of("steady_speed_m_s"), Some(1e-4));
        assert_eq!(targets.of("t_90_s"), Some(0.01));
        assert_eq!(targets.of("newton_steps"), None);
        targets.set("m", 0.05);
        targets.set("rps", 0.1);
        assert_eq!(targets.of("tactical_diameter_m"), Some(0.05));
        assert_eq!(targets.of("astern_rps"), Some(0.1));
    }

    #[test]
    fn a_setting_replaces_only_the_method_s_keys() {
        let table: Table = "title = \"x\"\n[integrator]\nmethod = \"rk4\"\nstep = 0.1\n\
                            max_steps = 10\n"
            .parse()
            .unwrap();
        let setting = Setting {
            method: Method::Dop853,
            step: None,
            tolerance: Some(1e-9),
        };
        let applied = setting.applied(&table);
        let integrator = applied["integrator"].as_table().unwrap();
        assert_eq!(integrator["method"].as_str(), Some("dop853"));
        assert!(integrator.get("step").is_none());
        assert_eq!(integrator["rtol"].as_float(), Some(1e-9));
        assert_eq!(integrator["atol"].as_float(), Some(1e-9));
        assert_eq!(integrator["max_steps"].as_integer(), Some(10));
        assert_eq!(applied["title"].as_str(), Some("x"));
    }

    fn row(method: Method, tolerance: Option<f64>, error: f64, seconds: f64) -> FigureRow {
        FigureRow {
            setting: Setting {
                method,
                step: tolerance.is_none().then_some(0.1),
                tolerance,
            },
            steps: 1,
            rhs_evals: None,
            seconds,
            errors: vec![FigureError {
                key: "tactical_diameter_m".into(),
                error: Some(error),
            }],
            failure: None,
        }
    }

    #[test]
    fn the_fastest_setting_whose_tighter_ones_meet_the_targets_too_is_recommended() {
        let targets = Targets::default();
        let rows = vec![
            // Meets it, then a tighter one does not: not converged.
            row(Method::Rk4, None, 0.001, 0.1),
            row(Method::Rk4, None, 0.5, 0.2),
            row(Method::Dop853, Some(1e-9), 0.005, 0.3),
            row(Method::Dop853, Some(1e-10), 1e-6, 0.4),
            row(Method::Dop853, Some(1e-11), 1e-7, 0.5),
        ];
        let compared = FigureTradeoff {
            reference: String::new(),
            reference_cost: (0, None, 0.0),
            keys: vec!["tactical_diameter_m".into()],
            rows,
        };
        let FigureRecommendation::Setting(best) = compared.recommend(&targets) else {
            panic!("a setting meets the target");
        };
        assert_eq!(best.setting.tolerance, Some(1e-9));
        // A reference that does not repeat itself recommends nothing.
        let mut spread = compared.clone();
        spread.rows[3].errors[0].error = Some(0.02);
        assert!(matches!(
            spread.recommend(&targets),
            FigureRecommendation::None(why) if why.contains("does not repeat itself")
        ));
    }
}
