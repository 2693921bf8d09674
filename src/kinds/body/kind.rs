//! The catalog body as a [`Kind`]: one run at the top of the output, linearised at its
//! initial state (or its `[linear]` point).

use super::run::{BodyRun, run_body, trajectory_numbers};
use crate::kinds::{Finished, Kind, KindError, Linearised};
use crate::output::summary::Summary;
use crate::run::record::Recorder;
use crate::scene::Scene;
use crate::scene::sweep::TableCase;
use std::any::Any;

/// The kind's name.
pub const NAME: &str = "body";

impl Kind for Scene {
    fn kind(&self) -> &'static str {
        NAME
    }

    fn title(&self) -> &str {
        &self.title
    }

    /// Its one run's trajectory, at the top of the output (its drawings beside it).
    fn folders(&self) -> Vec<String> {
        vec!["trajectory.csv".to_owned()]
    }

    fn trajectory_numbers(&self) -> f64 {
        trajectory_numbers(self)
    }

    fn run(
        &self,
        name: &str,
        recorder: &mut dyn Recorder,
    ) -> Result<Box<dyn Finished + '_>, KindError> {
        Ok(Box::new(run_body(self, name, recorder)?))
    }

    fn linear(&self) -> Result<Linearised, KindError> {
        Ok(Linearised::alone(crate::linear::linearise_scene(self)?))
    }

    fn as_any(&self) -> &dyn Any {
        self
    }

    fn into_any(self: Box<Self>) -> Box<dyn Any> {
        self
    }
}

impl Finished for BodyRun<'_> {
    fn summary(&self) -> Summary {
        self.summary.clone().into_json()
    }

    /// In the order of its section's fields (the section as a JSON value would sort them).
    fn summary_file(&self, case: Option<&TableCase>) -> Vec<u8> {
        self.summary.file(case)
    }

    fn report(&self) -> String {
        BodyRun::report(self)
    }

    fn cells(&self, _: &TableCase) -> Vec<(String, String)> {
        BodyRun::cells(self)
    }

    fn stopped(&self) -> bool {
        self.stopped
    }

    fn kept(&self) -> String {
        BodyRun::kept(self)
    }

    fn failure(&self) -> Option<KindError> {
        (self.error.clone()).map(|error| KindError::Run(Box::new(error)))
    }

    fn warnings(&self) -> Vec<String> {
        self.summary.warnings.clone()
    }
}
