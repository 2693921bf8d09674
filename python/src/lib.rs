//! `eom._eom`: the compiled half of the Python package `eom` (python/pysrc/eom/ is the other).
//!
//! Everything here calls the library, not the binary: a scene is an [`AnyScene`] read by the
//! same reader, run through [`Kind::run`] with a recorder that keeps each run's rows in
//! memory exactly as `trajectory.csv` holds them, its summary the bytes `summary.json` gets
//! ([`eom::kinds::Finished::summary_file`]); the model is the scene's [`DynModel`], evaluated
//! over many states in one call; the linearisation is [`Kind::linear`] reported by
//! [`eom::linear::report`], the same text and JSON as `eom linear`.
//!
//! What crosses into Python is plain: numbers in numpy arrays, JSON text that the Python side
//! reads with `json.loads` (so a summary is the dict `json.load` gives of summary.json), and
//! exceptions of the package's classes (`eom/_errors.py`), each with eom's message and, for a
//! scene's value, its key path. Runs and long evaluations release the GIL; a run goes on in a
//! thread of its own while this one checks for Ctrl-C, which stops it at its next row.

use eom::kinds::{Kind, KindError};
use eom::models::{DynModel, SizeError};
use eom::output::drawing::RunDrawings;
use eom::output::trajectory::header_in;
use eom::run::Row;
use eom::run::record::{RecordError, Recorder, RunStart};
use eom::run::uncertainty::{
    CasesTable, PERCENTILES, Statistics, refuse_contradicting_laws, report_json, run_cases,
};
use eom::scene::sweep::{is_swept, shard_tables};
use eom::scene::uncertainty::{UNCERTAINTY_TABLE, Uncertainty, is_uncertain};
use eom::scene::{AnyScene, Problem, SceneError};
use numpy::ndarray::{Array2, Array3, ArrayView2};
use numpy::{IntoPyArray, PyArray2, PyArray3, PyReadonlyArray2};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyBytes, PyDict};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc;
use std::time::Duration;

/// How often a run in progress looks for Ctrl-C (and other Python signals).
const SIGNAL_CHECK: Duration = Duration::from_millis(50);

/// How many states one stretch of a vectorised call evaluates with the GIL released before
/// Python's signals are checked.
const STATES_PER_STRETCH: usize = 1 << 16;

/// An exception of `eom._errors`: `class` (`SceneError`, `RunError`, …) with eom's message,
/// the key path of the value it is about and the file.
fn exception(
    py: Python<'_>,
    class: &str,
    message: String,
    key: Option<String>,
    file: Option<String>,
) -> PyErr {
    let made = (|| -> PyResult<PyErr> {
        let class = py.import("eom._errors")?.getattr(class)?;
        let error = class.call1((message.clone(), key, file))?;
        Ok(PyErr::from_value(error))
    })();
    made.unwrap_or_else(|error| error)
}

/// The first [`SceneError`] in `error`'s chain: the key path and the file it names.
fn scene_error_in<'a>(error: &'a (dyn std::error::Error + 'static)) -> Option<&'a SceneError> {
    let mut cause = Some(error);
    while let Some(error) = cause {
        if let Some(scene) = error.downcast_ref::<SceneError>() {
            return Some(scene);
        }
        cause = error.source();
    }
    None
}

/// A scene's error as `SceneError` (or `FileError` where the file could not be read).
fn scene_exception(py: Python<'_>, error: &SceneError) -> PyErr {
    let class = match error.problem {
        Problem::Read(_) => "FileError",
        _ => "SceneError",
    };
    let key = Some(error.key.clone()).filter(|key| !key.is_empty());
    exception(py, class, error.to_string(), key, Some(error.file.clone()))
}

/// The class a [`KindError`] is raised as: by what the command's exit code says of it.
fn kind_class(error: &KindError) -> &'static str {
    match error {
        KindError::Scene(_) => "SceneError",
        KindError::Run(_) => "RunError",
        KindError::Stopped(_) => "RunError",
        KindError::Output(_) => "OutputError",
        KindError::Internal(_) => "InternalError",
    }
}

/// A kind's error: its class, its message, and the key path a scene's error in its chain
/// names.
fn kind_exception(py: Python<'_>, error: &KindError) -> PyErr {
    let scene = scene_error_in(error);
    let key = scene.map(|s| s.key.clone()).filter(|key| !key.is_empty());
    let file = scene.map(|s| s.file.clone());
    exception(py, kind_class(error), error.to_string(), key, file)
}

fn size_exception(py: Python<'_>, error: SizeError) -> PyErr {
    exception(py, "ShapeError", error.to_string(), None, None)
}

/// A scene, read and checked: its kind, its runs, its model, its linearisation.
#[pyclass(module = "eom._eom", frozen)]
struct Scene {
    scene: Box<dyn Kind>,
    /// The scene's text (empty for a sweep's case, whose table was set by its values).
    table: toml::Table,
    /// How errors and the summary name the file.
    name: String,
    /// Where a file it names is found.
    base: PathBuf,
}

impl Scene {
    fn from_table(py: Python<'_>, table: toml::Table, name: &str, base: &Path) -> PyResult<Self> {
        let checked = py.detach(|| AnyScene::from_table(table.clone(), name, base));
        let scene = checked.map_err(|e| scene_exception(py, &e))?.into_kind();
        Ok(Scene {
            scene,
            table,
            name: name.to_owned(),
            base: base.to_owned(),
        })
    }

    fn parse(py: Python<'_>, text: &str, name: &str, base: &Path) -> PyResult<Self> {
        let table: toml::Table = text.parse().map_err(|e: toml::de::Error| {
            scene_exception(
                py,
                &SceneError::new(name, "", Problem::Syntax(e.to_string())),
            )
        })?;
        Self::from_table(py, table, name, base)
    }
}

#[pymethods]
impl Scene {
    /// Reads and checks the scene file at `path`; `name` is how errors and the summary name
    /// it (by default the path as given, as `eom run PATH` names it).
    #[staticmethod]
    #[pyo3(signature = (path, name = None))]
    fn load(py: Python<'_>, path: PathBuf, name: Option<String>) -> PyResult<Self> {
        let name = name.unwrap_or_else(|| path.display().to_string());
        let text = std::fs::read_to_string(&path)
            .map_err(|e| scene_exception(py, &SceneError::new(&name, "", Problem::Read(e))))?;
        let base = path.parent().unwrap_or(Path::new(".")).to_owned();
        Self::parse(py, &text, &name, &base)
    }

    /// Reads and checks scene text; `base` is where a file it names is found.
    #[staticmethod]
    #[pyo3(signature = (text, name = "<scene>".to_owned(), base = PathBuf::from(".")))]
    fn from_text(py: Python<'_>, text: &str, name: String, base: PathBuf) -> PyResult<Self> {
        Self::parse(py, text, &name, &base)
    }

    /// Reads and checks a scene's tables given as JSON text (`Scene.table` changed).
    #[staticmethod]
    #[pyo3(signature = (table, name = "<scene>".to_owned(), base = PathBuf::from(".")))]
    fn from_table_json(py: Python<'_>, table: &str, name: String, base: PathBuf) -> PyResult<Self> {
        let table: toml::Table = serde_json::from_str(table).map_err(|e| {
            let problem = Problem::Schema(format!("not a scene's tables: {e}"));
            scene_exception(py, &SceneError::new(&name, "", problem))
        })?;
        Self::from_table(py, table, &name, &base)
    }

    /// The scene with each dotted key of `values` (a dict, `{"body.mass": 2.0}`,
    /// `manoeuvre[0].rudder_deg`) set, read and checked again. Each value is taken as Python
    /// holds it (a float stays a float, NaN included, for the scene's check to name its key).
    fn with_values(&self, py: Python<'_>, values: &Bound<'_, PyDict>) -> PyResult<Self> {
        let mut table = self.table.clone();
        for (key, value) in values.iter() {
            let key: String = key.extract()?;
            let invalid =
                |problem: Problem| scene_exception(py, &SceneError::new(&self.name, &key, problem));
            let value = toml_value(&value)
                .map_err(|why| invalid(Problem::Schema(format!("not a TOML value: {why}"))))?;
            eom::scene::sweep::set(&mut table, &key, value).map_err(invalid)?;
        }
        Self::from_table(py, table, &self.name, &self.base)
    }

    /// The cases of the scene's `[sweep]`, as `eom run` makes them: (index, the swept values
    /// as a JSON object, the case's scene).
    fn cases(&self, py: Python<'_>) -> PyResult<Vec<(usize, String, Scene)>> {
        let text = toml::to_string(&self.table)
            .map_err(|e| exception(py, "InternalError", e.to_string(), None, None))?;
        if !is_swept(&text) {
            return Ok(Vec::new());
        }
        let cases = shard_tables(&text, &self.name, None).map_err(|e| scene_exception(py, &e))?;
        (cases.into_iter())
            .map(|case| {
                let values = serde_json::to_string(&case.values_json()).unwrap_or_default();
                let scene = Scene::from_table(py, case.table, &self.name, &self.base)?;
                Ok((case.index, values, scene))
            })
            .collect()
    }

    /// The kind's name (`body`, `ship`, `vehicle`).
    #[getter]
    fn kind(&self) -> &'static str {
        self.scene.kind()
    }

    /// The title.
    #[getter]
    fn title(&self) -> &str {
        self.scene.title()
    }

    /// How errors and the summary name the file.
    #[getter]
    fn name(&self) -> &str {
        &self.name
    }

    /// Where a file the scene names is found.
    #[getter]
    fn base(&self) -> PathBuf {
        self.base.clone()
    }

    /// What its run writes at the top of its output folder besides summary.json: each
    /// manoeuvre's folder, or `trajectory.csv` for a scene that is one run.
    #[getter]
    fn folders(&self) -> Vec<String> {
        self.scene.folders()
    }

    /// The scene's tables as JSON text.
    #[getter]
    fn table_json(&self) -> String {
        serde_json::to_string(&self.table).unwrap_or_default()
    }

    /// Runs every run the scene asks for: (summary.json's bytes, the report, the warnings,
    /// whether it stopped early, each run's (path, header, rows)) and, for a run that failed
    /// where it failed having kept what it ran, its exception beside.
    fn run<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, pyo3::types::PyTuple>> {
        if self.table.contains_key(UNCERTAINTY_TABLE) {
            let message = format!(
                "{} is a Monte Carlo ([uncertainty]): Scene.monte_carlo() runs its cases, as \
                 `eom run` does; Scene.run() would run only the scene as written",
                self.name
            );
            let error = SceneError::new(&self.name, UNCERTAINTY_TABLE, Problem::Invalid(message));
            return Err(scene_exception(py, &error));
        }
        let (scene, name) = (self.scene.as_ref(), self.name.as_str());
        let outcome = in_thread(py, move |stop| run_scene(scene, name, stop))?;
        let ran = outcome.map_err(|e| kind_exception(py, &e))?;
        let runs: Vec<Bound<'py, PyAny>> = (ran.runs.into_iter())
            .map(|run| {
                let width = run.header.len();
                let rows = run.rows.len() / width.max(1);
                let array = Array2::from_shape_vec((rows, width), run.rows)
                    .map_err(|e| exception(py, "InternalError", e.to_string(), None, None))?;
                let tuple = (run.path, run.header, array.into_pyarray(py));
                Ok(tuple.into_pyobject(py)?.into_any())
            })
            .collect::<PyResult<_>>()?;
        let failure = ran.failure.map(|e| kind_exception(py, &e).into_value(py));
        let summary = PyBytes::new(py, &ran.summary);
        let result = (
            summary,
            ran.report,
            ran.warnings,
            ran.stopped,
            runs,
            failure,
        );
        result.into_pyobject(py)
    }

    /// Runs the scene's Monte Carlo, every case, as `eom run` does: (uncertainty.json's bytes,
    /// uncertainty.csv's text). A scene without `[uncertainty]` is refused.
    fn monte_carlo(&self, py: Python<'_>) -> PyResult<(Py<PyBytes>, String)> {
        let text = toml::to_string(&self.table)
            .map_err(|e| exception(py, "InternalError", e.to_string(), None, None))?;
        if !is_uncertain(&text) {
            let missing = Problem::Missing("an [uncertainty] table".into());
            let error = SceneError::new(&self.name, UNCERTAINTY_TABLE, missing);
            return Err(scene_exception(py, &error));
        }
        let uncertainty =
            Uncertainty::parse(&text, &self.name).map_err(|e| scene_exception(py, &e))?;
        let (name, base) = (self.name.as_str(), self.base.as_path());
        let nominal = self.scene.as_ref();
        let checked = py.detach(|| refuse_contradicting_laws(&uncertainty, nominal, (name, base)));
        checked.map_err(|e| scene_exception(py, &e))?;
        let indices: Vec<usize> = (0..uncertainty.cases).collect();
        let outcomes = in_thread(py, |stop| {
            run_cases(&uncertainty, &indices, (name, base), &|| {
                stop.load(Ordering::SeqCst)
            })
        })?;
        let keys: Vec<String> = uncertainty.varied.iter().map(|v| v.key.clone()).collect();
        let statistics = Statistics::of(&outcomes, &PERCENTILES);
        let report = report_json(&keys, &PERCENTILES, &statistics);
        let table = CasesTable::write(&keys, &outcomes);
        Ok((PyBytes::new(py, &report).unbind(), table))
    }

    /// The scene's model (no loads, schedules or steering gear): its names, rates and
    /// Jacobians.
    fn model(&self, py: Python<'_>) -> PyResult<Model> {
        let model = py.detach(|| self.scene.model());
        let Some(model) = model else {
            let why = format!("a scene of the kind {} gives no model", self.scene.kind());
            return Err(exception(
                py,
                "SceneError",
                why,
                None,
                Some(self.name.clone()),
            ));
        };
        let model = model.map_err(|e| kind_exception(py, &e))?;
        Ok(Model { model })
    }

    /// The scene linearised at its operating point: (linear.json's object as JSON text, the
    /// text report), as `eom linear` gives them.
    fn linear(&self, py: Python<'_>) -> PyResult<(String, String)> {
        let linearised = py.detach(|| self.scene.linear());
        let linearised = linearised.map_err(|e| kind_exception(py, &e))?;
        let linear = &linearised.linearisation;
        let space = eom::linear::StateSpace::new(&self.name, self.scene.title(), linear);
        let mut report = eom::linear::report::json_report(&space, linear);
        if let Some(report) = report.as_object_mut() {
            report.extend(linearised.json.clone());
        }
        let mut text = eom::linear::report::text_report(self.scene.title(), linear);
        text.push_str(&linearised.text);
        Ok((report.to_string(), text))
    }

    fn __repr__(&self) -> String {
        format!(
            "<eom.Scene {} ({}): {:?}>",
            self.name,
            self.scene.kind(),
            self.scene.title()
        )
    }
}

/// What a scene's run gave, in plain data (the run's own [`eom::kinds::Finished`] stays in
/// its thread).
struct Ran {
    summary: Vec<u8>,
    report: String,
    warnings: Vec<String>,
    stopped: bool,
    runs: Vec<Recorded>,
    failure: Option<KindError>,
}

fn run_scene(scene: &dyn Kind, name: &str, stop: &AtomicBool) -> Result<Ran, KindError> {
    let mut recorder = Memory {
        runs: Vec::new(),
        stop,
        potential: false,
    };
    let finished = scene.run(name, &mut recorder)?;
    Ok(Ran {
        summary: finished.summary_file(None),
        report: finished.report(),
        warnings: finished.warnings(),
        stopped: finished.stopped(),
        runs: recorder.runs,
        failure: finished.failure(),
    })
}

/// Runs `work` in a thread of its own, the GIL released, while this one checks for Ctrl-C
/// (and Python's other signals) every [`SIGNAL_CHECK`]: on one, `work`'s stop flag is set, its
/// thread joined, and the signal's exception raised.
fn in_thread<T: Send>(py: Python<'_>, work: impl FnOnce(&AtomicBool) -> T + Send) -> PyResult<T> {
    let stop = AtomicBool::new(false);
    let (sender, receiver) = mpsc::channel();
    std::thread::scope(|threads| {
        let stop = &stop;
        threads.spawn(move || {
            let _ = sender.send(work(stop));
        });
        let mut receiver = receiver;
        loop {
            // The receiver is moved into the wait and back: it is Send, not Sync.
            let (back, received) = py.detach(move || {
                let received = receiver.recv_timeout(SIGNAL_CHECK);
                (receiver, received)
            });
            receiver = back;
            match received {
                Ok(outcome) => return Ok(outcome),
                Err(mpsc::RecvTimeoutError::Disconnected) => {
                    let why = "the run's thread ended without a result".to_owned();
                    return Err(exception(py, "InternalError", why, None, None));
                }
                Err(mpsc::RecvTimeoutError::Timeout) => {}
            }
            if let Err(signal) = py.check_signals() {
                // Ctrl-C: the work ends at its next row; its thread is joined as the scope
                // ends, and what it kept is dropped with the exception.
                stop.store(true, Ordering::SeqCst);
                return Err(signal);
            }
        }
    })
}

/// A Python value as the TOML value a scene's key takes: a bool, an integer (Python's or
/// numpy's), a float (NaN and infinities kept), a string, a list or a dict of them.
fn toml_value(value: &Bound<'_, PyAny>) -> Result<toml::Value, String> {
    use toml::Value;
    if let Ok(flag) = value.cast::<PyBool>() {
        return Ok(Value::Boolean(flag.is_true()));
    }
    if let Ok(integer) = value.extract::<i64>() {
        return Ok(Value::Integer(integer));
    }
    if let Ok(number) = value.extract::<f64>() {
        return Ok(Value::Float(number));
    }
    if let Ok(text) = value.extract::<String>() {
        return Ok(Value::String(text));
    }
    if let Ok(table) = value.cast::<PyDict>() {
        let mut entries = toml::Table::new();
        for (key, value) in table.iter() {
            let key: String = key.extract().map_err(|_| "a table's key is not a string")?;
            entries.insert(key, toml_value(&value)?);
        }
        return Ok(Value::Table(entries));
    }
    if let Ok(items) = value.try_iter() {
        let items: Result<Vec<Value>, String> = items
            .map(|item| {
                item.map_err(|e| e.to_string())
                    .and_then(|item| toml_value(&item))
            })
            .collect();
        return items.map(Value::Array);
    }
    let kind = value
        .get_type()
        .name()
        .map_or_else(|_| "?".to_owned(), |n| n.to_string());
    Err(format!("a {kind}"))
}

/// One run's rows as trajectory.csv holds them: its header (with units) and its numbers,
/// row after row.
struct Recorded {
    path: String,
    header: Vec<String>,
    rows: Vec<f64>,
}

/// Keeps every run's rows in memory, as the command's recorder writes them; stops at the next
/// row once `stop` is set.
struct Memory<'a> {
    runs: Vec<Recorded>,
    stop: &'a AtomicBool,
    potential: bool,
}

impl Recorder for Memory<'_> {
    fn begin(&mut self, run: RunStart) -> Result<(), RecordError> {
        let header = header_in(run.columns, run.potential, run.energy_unit);
        let rows = Vec::with_capacity(run.expected_rows.min(1 << 22) * header.len());
        self.potential = run.potential;
        self.runs.push(Recorded {
            path: run.path.to_owned(),
            header,
            rows,
        });
        Ok(())
    }

    /// The numbers of one line of trajectory.csv ([`eom::output::trajectory`]): t, the state,
    /// the kinetic energy and, with a potential, the potential (NaN where a row has none) and
    /// their sum.
    fn row(&mut self, row: &Row) -> bool {
        if self.stop.load(Ordering::Relaxed) {
            return false;
        }
        let Some(run) = self.runs.last_mut() else {
            return false;
        };
        run.rows.push(row.t);
        run.rows.extend_from_slice(row.state);
        run.rows.push(row.kinetic_energy);
        if self.potential {
            let potential = row.potential_energy.unwrap_or(f64::NAN);
            run.rows.push(potential);
            run.rows.push(row.kinetic_energy + potential);
        }
        true
    }

    fn end(&mut self) -> Result<(), RecordError> {
        Ok(())
    }

    fn drawn(&mut self, _: RunDrawings) -> Result<(), RecordError> {
        Ok(())
    }

    fn stop_asked(&self) -> bool {
        self.stop.load(Ordering::Relaxed)
    }
}

/// A shape as Python writes it: `(7, 3)`.
fn tuple(shape: &[usize]) -> String {
    let sizes: Vec<String> = shape.iter().map(usize::to_string).collect();
    format!("({})", sizes.join(", "))
}

/// A scene's model: its names, and its rates and proved Jacobians over many states at once.
#[pyclass(module = "eom._eom", frozen)]
struct Model {
    model: Box<dyn DynModel>,
}

/// Which of the model's functions a vectorised call evaluates.
#[derive(Clone, Copy)]
enum Function {
    Rates,
    StateJacobian,
    InputJacobian,
}

impl Model {
    /// `x` (n, N) and `u` (m, N) checked: their shapes, and every value finite.
    fn check(&self, py: Python<'_>, x: &ArrayView2<f64>, u: &ArrayView2<f64>) -> PyResult<usize> {
        let (n, m) = (
            self.model.state_names().len(),
            self.model.input_names().len(),
        );
        let name = self.model.name();
        let shape = |what: &str, got: &[usize], rows: usize| {
            let why = format!(
                "{what} has shape {}; the model {name} takes ({rows}, N): one column per state",
                tuple(got)
            );
            exception(py, "ShapeError", why, None, None)
        };
        if x.nrows() != n {
            return Err(shape("x", x.shape(), n));
        }
        if u.nrows() != m || u.ncols() != x.ncols() {
            let why = format!(
                "u has shape {}; the model {name} takes ({m}, {}): one column of inputs per state",
                tuple(u.shape()),
                x.ncols()
            );
            return Err(exception(py, "ShapeError", why, None, None));
        }
        let names = [self.model.state_names(), self.model.input_names()];
        for ((what, array), names) in [("x", x), ("u", u)].into_iter().zip(names) {
            // One pass over the values; their places are looked for only where one is not finite.
            if array.iter().all(|value| value.is_finite()) {
                continue;
            }
            if let Some(((row, column), value)) =
                array.indexed_iter().find(|(_, value)| !value.is_finite())
            {
                let why = format!(
                    "{what}[{row}, {column}] ({}) is {value}: the model takes finite numbers",
                    names[row]
                );
                return Err(exception(py, "InvalidValue", why, None, None));
            }
        }
        Ok(x.ncols())
    }

    /// `function` at every column of `x`, `u`: an (n, width, N) array, width 1 for the
    /// rates, in stretches with the GIL released, Python's signals checked between them.
    fn evaluate(
        &self,
        py: Python<'_>,
        (x, u): (PyReadonlyArray2<f64>, PyReadonlyArray2<f64>),
        function: Function,
    ) -> PyResult<Array3<f64>> {
        let (x, u) = (x.as_array(), u.as_array());
        let count = self.check(py, &x, &u)?;
        let (n, m) = (x.nrows(), u.nrows());
        let width = match function {
            Function::Rates => 1,
            Function::StateJacobian => n,
            Function::InputJacobian => m,
        };
        // Row-major slices: entry (i, k) of x at i·N + k, entry (i, w, k) of the result at
        // (i·width + w)·N + k.
        let (x, u) = (x.as_standard_layout(), u.as_standard_layout());
        let internal = |what: &str| {
            exception(
                py,
                "InternalError",
                format!("{what} is not contiguous"),
                None,
                None,
            )
        };
        let xs = x.as_slice().ok_or_else(|| internal("x"))?;
        let us = u.as_slice().ok_or_else(|| internal("u"))?;
        let mut out = Array3::<f64>::zeros((n, width, count));
        let results = out.as_slice_mut().ok_or_else(|| internal("the result"))?;
        let model = self.model.as_ref();
        let mut start = 0;
        while start < count {
            let end = (start + STATES_PER_STRETCH).min(count);
            let results = &mut *results;
            let done = py.detach(|| -> Result<(), SizeError> {
                let (mut state, mut input) = (vec![0.0; n], vec![0.0; m]);
                let mut values = vec![0.0; n * width];
                for k in start..end {
                    for (i, entry) in state.iter_mut().enumerate() {
                        *entry = xs[i * count + k];
                    }
                    for (j, entry) in input.iter_mut().enumerate() {
                        *entry = us[j * count + k];
                    }
                    match function {
                        Function::Rates => model.rhs(&state, &input, &mut values)?,
                        Function::StateJacobian => {
                            model.state_jacobian(&state, &input, &mut values)?
                        }
                        Function::InputJacobian => {
                            model.input_jacobian(&state, &input, &mut values)?
                        }
                    }
                    for (index, value) in values.iter().enumerate() {
                        results[index * count + k] = *value;
                    }
                }
                Ok(())
            });
            done.map_err(|e| size_exception(py, e))?;
            py.check_signals()?;
            start = end;
        }
        Ok(out)
    }
}

#[pymethods]
impl Model {
    /// The model's name (`ship`, `spatial_principal_quaternion`).
    #[getter]
    fn name(&self) -> &'static str {
        self.model.name()
    }

    /// Every state entry's name, in the model's layout.
    #[getter]
    fn state_names(&self) -> Vec<&'static str> {
        self.model.state_names()
    }

    /// Every input's name.
    #[getter]
    fn input_names(&self) -> Vec<&'static str> {
        self.model.input_names()
    }

    /// f(x, u) at each column: x (n, N), u (m, N) of float64; an (n, N) array.
    fn rhs<'py>(
        &self,
        py: Python<'py>,
        x: PyReadonlyArray2<'py, f64>,
        u: PyReadonlyArray2<'py, f64>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let out = self.evaluate(py, (x, u), Function::Rates)?;
        let (n, _, count) = out.dim();
        let out = out
            .into_shape_with_order((n, count))
            .map_err(|e| exception(py, "InternalError", e.to_string(), None, None))?;
        Ok(out.into_pyarray(py))
    }

    /// ∂f/∂x at each column, an (n, n, N) array; with `by_inputs`, ∂f/∂u, (n, m, N).
    #[pyo3(signature = (x, u, by_inputs = false))]
    fn jacobian<'py>(
        &self,
        py: Python<'py>,
        x: PyReadonlyArray2<'py, f64>,
        u: PyReadonlyArray2<'py, f64>,
        by_inputs: bool,
    ) -> PyResult<Bound<'py, PyArray3<f64>>> {
        let function = match by_inputs {
            false => Function::StateJacobian,
            true => Function::InputJacobian,
        };
        Ok(self.evaluate(py, (x, u), function)?.into_pyarray(py))
    }

    fn __repr__(&self) -> String {
        format!(
            "<eom.Model {}: x = [{}], u = [{}]>",
            self.model.name(),
            self.model.state_names().join(", "),
            self.model.input_names().join(", ")
        )
    }
}

/// Derives every equation afresh and proves it, as `eom derive` does: (the report as
/// Markdown, each equation's (number, description, components, why it is not proved or None)).
#[pyfunction]
#[allow(clippy::type_complexity)]
fn derive(py: Python<'_>) -> PyResult<(String, Vec<(String, String, usize, Option<String>)>)> {
    let derived = py.detach(|| -> Result<_, eom_codegen::check::CheckError> {
        let equations = eom_codegen::derivation::all()?;
        let checked: Vec<(String, String, usize, Option<String>)> = (equations.iter())
            .map(|equation| {
                let proved = equation.check().err().map(|e| e.to_string());
                let (number, description) = (equation.number, equation.description);
                let components = equation.components.len();
                (
                    number.to_owned(),
                    description.to_owned(),
                    components,
                    proved,
                )
            })
            .collect();
        Ok((eom_codegen::report::markdown(&equations), checked))
    });
    derived.map_err(|e| exception(py, "InternalError", e.to_string(), None, None))
}

/// The mass properties of a body file, as `eom mass --json` prints them (JSON text), with the
/// tensor about `about` where given.
#[pyfunction]
#[pyo3(signature = (path, about = None))]
fn mass(py: Python<'_>, path: PathBuf, about: Option<[f64; 3]>) -> PyResult<String> {
    use eom::mass::{BodyFile, BodyFileError, MassReport};
    let file = Some(path.display().to_string());
    let body = BodyFile::load(&path).map_err(|e| {
        let class = match e {
            BodyFileError::Read { .. } => "FileError",
            _ => "SceneError",
        };
        exception(py, class, e.to_string(), None, file.clone())
    })?;
    let properties = (body.mass_properties())
        .map_err(|e| exception(py, "SceneError", e.to_string(), None, file.clone()))?;
    let report = MassReport::new(&body, &properties, about).map_err(|e| {
        let message = format!("about: the tensor about that point: {e}");
        exception(py, "InvalidValue", message, Some("about".into()), None)
    })?;
    serde_json::to_string(&report)
        .map_err(|e| exception(py, "InternalError", e.to_string(), None, None))
}

/// The compiled module: `Scene`, `Model`, `derive`, `mass`.
#[pymodule]
fn _eom(module: &Bound<'_, PyModule>) -> PyResult<()> {
    module.add_class::<Scene>()?;
    module.add_class::<Model>()?;
    module.add_function(wrap_pyfunction!(derive, module)?)?;
    module.add_function(wrap_pyfunction!(mass, module)?)?;
    Ok(())
}
