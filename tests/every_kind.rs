//! Every kind the registry lists, through the one runner, alike: each kind's example scene
//! (`Registered::example`) run as the command runs it, as a Monte Carlo's case runs it, and
//! stopped before it begins. A kind added to the registry is held to the same without a line
//! here.

use eom::kinds::{Finished, REGISTRY};
use eom::output::drawing::RunDrawings;
use eom::output::summary::RunFigures;
use eom::run::Row;
use eom::run::record::{Discard, RecordError, Recorder, RunStart};
use eom::scene::AnyScene;
use std::path::Path;

/// Each registered kind's example scene, read.
fn examples() -> Vec<(&'static str, AnyScene)> {
    let scenes = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    (REGISTRY.iter())
        .map(|kind| {
            let file = scenes.join(kind.example);
            let scene = AnyScene::load(&file).unwrap_or_else(|e| panic!("{file:?}: {e}"));
            assert_eq!(scene.as_kind().kind(), kind.name, "{}", kind.example);
            (kind.example, scene)
        })
        .collect()
}

/// A Monte Carlo's case as `run::uncertainty` runs one: it keeps no rows (a run that builds
/// one anyway fails here) and asks for no refined run.
struct Case;

impl Recorder for Case {
    fn begin(&mut self, _: RunStart) -> Result<(), RecordError> {
        Ok(())
    }
    fn row(&mut self, row: &Row) -> bool {
        panic!(
            "a row at t = {} was built for a recorder that keeps none",
            row.t
        )
    }
    fn end(&mut self) -> Result<(), RecordError> {
        Ok(())
    }
    fn drawn(&mut self, drawings: RunDrawings) -> Result<(), RecordError> {
        panic!(
            "{} was drawn for a recorder that keeps no rows",
            drawings.path
        )
    }
    fn stop_asked(&self) -> bool {
        false
    }
    fn refines(&self) -> bool {
        false
    }
    fn keeps_rows(&self) -> bool {
        false
    }
}

/// The command's recorder as far as rows go: it keeps them (and counts them).
#[derive(Default)]
struct Keeping(usize);

impl Recorder for Keeping {
    fn begin(&mut self, _: RunStart) -> Result<(), RecordError> {
        Ok(())
    }
    fn row(&mut self, row: &Row) -> bool {
        assert!(row.t.is_finite());
        self.0 += 1;
        true
    }
    fn end(&mut self) -> Result<(), RecordError> {
        Ok(())
    }
    fn drawn(&mut self, _: RunDrawings) -> Result<(), RecordError> {
        Ok(())
    }
    fn stop_asked(&self) -> bool {
        false
    }
}

/// A caller that asked to stop before anything ran.
struct StoppedAtOnce(usize);

impl Recorder for StoppedAtOnce {
    fn begin(&mut self, _: RunStart) -> Result<(), RecordError> {
        self.0 += 1;
        Ok(())
    }
    fn row(&mut self, _: &Row) -> bool {
        false
    }
    fn end(&mut self) -> Result<(), RecordError> {
        Ok(())
    }
    fn drawn(&mut self, _: RunDrawings) -> Result<(), RecordError> {
        Ok(())
    }
    fn stop_asked(&self) -> bool {
        true
    }
}

/// A caller that stops the first run after its third row (Ctrl-C mid-run): it refuses the
/// row, and asks every run after to stop.
#[derive(Default)]
struct StoppedMidRun {
    begun: usize,
    rows: usize,
}

impl Recorder for StoppedMidRun {
    fn begin(&mut self, _: RunStart) -> Result<(), RecordError> {
        self.begun += 1;
        Ok(())
    }
    fn row(&mut self, _: &Row) -> bool {
        self.rows += 1;
        self.rows <= 3
    }
    fn end(&mut self) -> Result<(), RecordError> {
        Ok(())
    }
    fn drawn(&mut self, _: RunDrawings) -> Result<(), RecordError> {
        Ok(())
    }
    fn stop_asked(&self) -> bool {
        self.rows > 3
    }
}

/// Each figure's value, as bits, by run and key.
fn values(runs: &[RunFigures]) -> Vec<(String, String, Option<u64>)> {
    let mut values = Vec::new();
    for run in runs {
        for figure in &run.figures {
            values.push((
                run.run.clone(),
                figure.key.clone(),
                figure.value.map(f64::to_bits),
            ));
        }
    }
    values
}

/// Run as the command runs it, every kind gives each figure with how far it moved when its
/// run was refined, and says how it was refined; the summary's runs are its figures' runs.
#[test]
fn every_kind_gives_its_figures_refined() {
    for (example, scene) in examples() {
        let finished = scene.as_kind().run(example, &mut Discard).unwrap();
        assert!(finished.failure().is_none(), "{example}");
        assert!(!finished.stopped(), "{example}");
        let (runs, _) = finished.figures();
        let with_figures: Vec<&RunFigures> = (runs.iter())
            .filter(|run| run.figures.iter().any(|f| f.value.is_some()))
            .collect();
        assert!(!with_figures.is_empty(), "{example} gives no figure");
        for run in with_figures {
            assert!(run.refinement.is_some(), "{example} {}", run.run);
            let moved = (run.figures.iter()).any(|f| f.difference.is_some());
            assert!(
                moved || run.largest_difference.is_some(),
                "{example} {}: no difference from the refined run",
                run.run
            );
        }
        let summary = finished.summary();
        assert_eq!(summary.kind, scene.as_kind().kind());
        assert!(summary.error.is_none() && !summary.interrupted, "{example}");
    }
}

/// A Monte Carlo's case builds no rows, draws nothing and is not refined, and gives the same
/// figures, bit for bit, as the run the command makes, whose rows are kept.
#[test]
fn every_kinds_monte_carlo_case_builds_no_rows_and_gives_the_same_figures() {
    for (example, scene) in examples() {
        let mut keeping = Keeping::default();
        let whole = scene.as_kind().run(example, &mut keeping).unwrap();
        assert!(keeping.0 >= 2, "{example}: {} rows", keeping.0);
        let case = scene.as_kind().run(example, &mut Case).unwrap();
        let (whole_runs, whole_verdicts) = whole.figures();
        let (case_runs, case_verdicts) = case.figures();
        assert_eq!(values(whole_runs), values(case_runs), "{example}");
        assert_eq!(whole_verdicts, case_verdicts, "{example}");
        for run in case_runs {
            assert!(run.refinement.is_none(), "{example} {}", run.run);
            assert!(run.largest_difference.is_none(), "{example} {}", run.run);
            assert!(
                run.figures.iter().all(|f| f.difference.is_none()),
                "{example}"
            );
        }
    }
}

/// A stop asked before anything ran: no run begins, and the scene's run says it was
/// interrupted, with a summary and what it kept.
#[test]
fn every_kind_stopped_before_it_began_runs_nothing_and_says_so() {
    for (example, scene) in examples() {
        let mut stopped = StoppedAtOnce(0);
        let finished: Box<dyn Finished + '_> = scene.as_kind().run(example, &mut stopped).unwrap();
        assert_eq!(stopped.0, 0, "{example}: a run began");
        assert!(finished.stopped(), "{example}");
        assert!(finished.figures().0.is_empty(), "{example}");
        let summary = finished.summary();
        assert!(summary.interrupted, "{example}");
        assert!(finished.kept().contains("summary.json"), "{example}");
    }
}

/// A stop asked in the middle of the first run is the caller's stop for every kind, whatever
/// error the kind's integration gave for it (the runner says it, from the rows it refused):
/// the scene's run is interrupted, no run fails, and no run after it begins.
#[test]
fn every_kind_stopped_mid_run_is_interrupted_not_failed() {
    for (example, scene) in examples() {
        let mut stopped = StoppedMidRun::default();
        let finished = scene.as_kind().run(example, &mut stopped).unwrap();
        assert_eq!(stopped.begun, 1, "{example}: a run after the stop began");
        assert_eq!(
            stopped.rows, 4,
            "{example}: rows offered after the refused one"
        );
        assert!(finished.stopped(), "{example}");
        assert!(
            finished.failure().is_none(),
            "{example}: {:?}",
            finished.failure()
        );
        let summary = finished.summary();
        assert!(summary.interrupted, "{example}");
        assert!(summary.error.is_none(), "{example}: {:?}", summary.error);
    }
}

/// A manoeuvre named as an earlier one is refused at its name, for every kind whose example
/// has manoeuvres: each manoeuvre's name is its folder in the output and its key in the
/// summary.
#[test]
fn every_kind_refuses_a_manoeuvre_named_as_an_earlier_one() {
    let scenes = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let mut checked = 0;
    for kind in REGISTRY {
        let file = scenes.join(kind.example);
        let text = std::fs::read_to_string(&file).unwrap();
        let mut table: toml::Table = toml::from_str(&text).unwrap();
        let Some(toml::Value::Array(manoeuvres)) = table.get_mut("manoeuvre") else {
            continue;
        };
        let again = manoeuvres[0].clone();
        let index = manoeuvres.len();
        manoeuvres.push(again);
        let error = AnyScene::from_table(table, kind.example, &scenes).unwrap_err();
        let message = error.to_string();
        assert!(
            message.contains(&format!("manoeuvre[{index}].name")),
            "{}: {message}",
            kind.example
        );
        assert!(
            message.contains("is taken by an earlier manoeuvre"),
            "{message}"
        );
        checked += 1;
    }
    assert!(
        checked >= 3,
        "the ship's, the vehicle's and the aircraft's examples"
    );
}
