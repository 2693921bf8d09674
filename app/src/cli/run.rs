//! `eom run SCENE`: run a scene and write what a person wants to look at.
//!
//! Into the output folder (default: a folder named after the scene file, in the current
//! directory): `trajectory.csv`, `summary.json`, the SVG plots and `view.html`, the run in 3-D. A folder that already
//! holds a run is not overwritten without `--force`, and the folder is taken for the run alone
//! ([`eom::output::folder`]). A scene with a `[sweep]` runs every case
//! in parallel, each into `case-NNNN/`, and writes `sweep.csv`, one line per case; `--shard
//! K/N` runs only the cases k ≡ K (mod N). With no scene, `eom` runs its default scene, the
//! tennis-racket flip.
//!
//! A run that stops early loses nothing it computed: on Ctrl-C (SIGINT) or SIGTERM it ends at
//! its next row, and a run that fails (gimbal lock, a step too long, a value that is not
//! finite) ends where it failed; either way trajectory.csv keeps every row up to there,
//! summary.json says `"interrupted": true` or gives the `"error"`, and the plots show what ran.
//! A second signal ends the process at once (the trajectory then holds the rows last handed
//! to the file). Exit codes: 5 for a failed run, 128 + the signal (130, 143) for an
//! interrupted one.

use super::record::FolderRecorder;
use super::sweep::{SWEEP_PLOT, run_cases, write_sweep_plot};
use anyhow::{Context, Result, bail};
use eom::Short;
use eom::kinds::{Finished, Kind};
use eom::output::folder::{Claim, FolderError, Writer, sweep_identity};
use eom::output::summary::{Extra, Summary, write_atomically};
use eom::output::text::printable;
use eom::output::trajectory::{Columns, TrajectoryWriter, number_text};
use eom::run::{Report, Row, RunError, Sink, run_reporting};
use eom::scene::sweep::{TableCase, is_swept, parse_shard, shard_tables};
use eom::scene::{AnyScene, Body, Problem, Scene, SceneError};
use eom_cli::plots::PLOT_FILES;
use eom_cli::shell_path;
use eom_cli::view::VIEW_FILE;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rayon::prelude::*;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::time::{Duration, Instant};

/// The default scene: `scenes/tennis_racket.toml`, built into the binary.
pub const DEFAULT_SCENE: &str = include_str!("../../../scenes/tennis_racket.toml");
/// The default scene's name, for its output folder.
pub const DEFAULT_NAME: &str = "tennis_racket.toml";

/// Options of `eom run`.
#[derive(clap::Args)]
pub struct Args {
    /// The scene file (TOML); see `scenes/`, `eom new` and docs/scenes.md.
    scene: PathBuf,
    /// The output folder (default: the scene file's name without `.toml`, here).
    #[arg(long)]
    out: Option<PathBuf>,
    /// Write into an output folder that already holds a run (its files are replaced, and
    /// only eom's own), or beside the files of a folder eom did not write.
    #[arg(long)]
    force: bool,
    /// Run only the sweep cases k ≡ K (mod N), written `K/N`.
    #[arg(long, value_parser = parse_shard)]
    shard: Option<(usize, usize)>,
    /// Write a trajectory of more than 100 MB (without it such a run is refused before it
    /// starts).
    #[arg(long)]
    large_output: bool,
}

/// How `eom run` may use its output folder.
#[derive(Debug, Clone, Copy, Default)]
struct Options {
    force: bool,
    shard: Option<(usize, usize)>,
    large_output: bool,
}

/// A command used in a way it does not serve, found after its arguments were read: exits
/// with 2, as clap's own usage errors do.
#[derive(Debug, thiserror::Error)]
#[error("{0}")]
pub struct Usage(pub String);

/// The most a run writes without `--large-output`, bytes.
pub const LARGE_OUTPUT: f64 = 100e6;

/// A run ended early by a signal (Ctrl-C's SIGINT, or SIGTERM) after it kept what it had.
#[derive(Debug, thiserror::Error)]
#[error("interrupted by {}: {kept}", signal_name(*signal))]
pub struct Interrupted {
    /// The signal's number: the exit code is 128 plus it.
    pub signal: i32,
    /// What was kept, and where.
    pub kept: String,
}

fn signal_name(signal: i32) -> String {
    match signal {
        2 => "Ctrl-C (SIGINT)".into(),
        15 => "SIGTERM".into(),
        other => format!("signal {other}"),
    }
}

/// The signal that asked the run to end, 0 while none has.
static SIGNAL: AtomicUsize = AtomicUsize::new(0);
/// Set by the first signal: a second one ends the process at once.
static ARMED: AtomicBool = AtomicBool::new(false);

/// The signal received, if any.
pub(super) fn signal_received() -> Option<i32> {
    match SIGNAL.load(Ordering::SeqCst) {
        0 => None,
        signal => Some(signal as i32),
    }
}

/// Installs the handlers of SIGINT and SIGTERM, once: the first signal sets [`SIGNAL`], which
/// the run reads at each row; the second exits at once with 128 + the signal. Where a handler
/// cannot be installed the signal keeps its default action (the process ends).
fn watch_signals() {
    use signal_hook::consts::{SIGINT, SIGTERM};
    use signal_hook::flag;
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        for signal in [SIGINT, SIGTERM] {
            // The order matters: the exit runs first, and only once armed by the first signal.
            let _ = flag::register_conditional_shutdown(signal, 128 + signal, &ARMED);
            let _ = flag::register_usize(signal, &SIGNAL, signal as usize);
            let _ = flag::register(signal, &ARMED);
        }
    });
}

/// The trajectory writer, refusing the rows after a signal: the run ends at its next row, and
/// the last row written is the last the run reports.
struct Interruptible<'a>(&'a mut TrajectoryWriter);

impl Sink for Interruptible<'_> {
    fn row(&mut self, row: &Row) -> bool {
        signal_received().is_none() && self.0.row(row)
    }
}

/// Runs `eom run`.
pub fn run_command(args: Args) -> Result<()> {
    let name = args.scene.display().to_string();
    let text = std::fs::read_to_string(&args.scene)
        .map_err(|e| SceneError::new(&name, "", Problem::Read(e)))?;
    let base = args.scene.parent().unwrap_or(Path::new(".")).to_owned();
    let out = args.out.unwrap_or_else(|| default_folder(&args.scene));
    let options = Options {
        force: args.force,
        shard: args.shard,
        large_output: args.large_output,
    };
    execute(&text, &name, &base, &out, options)
}

/// Runs the default scene into `./tennis_racket/` (what `cargo run --release` does).
pub fn run_default() -> Result<()> {
    watch_signals();
    let out = default_folder(Path::new(DEFAULT_NAME));
    println!(
        "eom: no subcommand given, so running the default scene ({DEFAULT_NAME}); `eom --help` lists the others."
    );
    // The default run writes over its own earlier run, so that the first command can be run
    // again, and says so; any other folder is taken as `eom run` takes one (a user's files,
    // another scene's run: refused, for there is no --force to give).
    let replacing = holds_the_default_run(&out);
    if replacing {
        println!(
            "eom: replacing the default run in {}/ (eom run SCENE keeps a run unless --force)",
            out.display()
        );
    }
    let options = Options {
        force: replacing,
        ..Options::default()
    };
    execute(
        DEFAULT_SCENE,
        DEFAULT_NAME,
        Path::new("scenes"),
        &out,
        options,
    )
    .map_err(|error| match error.downcast_ref::<FolderError>() {
        Some(FolderError::NotEoms(_)) => taken(&out, "files eom did not write"),
        Some(FolderError::HoldsARun(_)) => taken(&out, "another scene's run"),
        _ => error,
    })
}

fn taken(folder: &Path, holds: &'static str) -> anyhow::Error {
    DefaultFolderTaken {
        folder: folder.to_owned(),
        holds,
    }
    .into()
}

/// The default run's folder holds what the default run does not replace: it has no `--force`
/// to give, so it is refused as `eom run` would refuse it without one (exit 4).
#[derive(Debug, thiserror::Error)]
#[error(
    "the default run writes into {}/, which holds {holds}; it replaces only an earlier default \
     run there, so run eom in another folder (or move that one)",
    folder.display()
)]
pub struct DefaultFolderTaken {
    /// The default run's folder.
    folder: PathBuf,
    /// What it holds.
    holds: &'static str,
}

/// Whether `out` holds a run of the default scene: its summary names the default scene's file
/// and title.
fn holds_the_default_run(out: &Path) -> bool {
    let read = |text: &str| serde_json::from_str::<serde_json::Value>(text).ok();
    let Some(summary) = std::fs::read_to_string(out.join("summary.json"))
        .ok()
        .and_then(|text| read(&text))
    else {
        return false;
    };
    let title = toml::from_str::<toml::Table>(DEFAULT_SCENE)
        .ok()
        .and_then(|scene| scene.get("title")?.as_str().map(str::to_owned));
    summary["scene"] == DEFAULT_NAME && summary["title"].as_str() == title.as_deref()
}

/// The folder named after the scene file, in the current directory.
fn default_folder(scene: &Path) -> PathBuf {
    let stem = scene
        .file_stem()
        .map_or_else(|| "run".into(), |s| s.to_string_lossy().into_owned());
    PathBuf::from(stem)
}

fn execute(text: &str, name: &str, base: &Path, out: &Path, options: Options) -> Result<()> {
    watch_signals();
    let swept = is_swept(text);
    if options.shard.is_some() && !swept {
        let message =
            format!("--shard splits a [sweep]; {name} has none, so every shard would run it whole");
        return Err(Usage(message).into());
    }
    // Every case is checked before any runs: a bad value fails the sweep at once.
    let cases: Vec<(TableCase, AnyScene)> = shard_tables(text, name, options.shard)?
        .into_iter()
        .map(|case| {
            let scene = AnyScene::from_table(case.table.clone(), name, base)?;
            Ok((case, scene))
        })
        .collect::<Result<_, SceneError>>()?;
    let mut scenes: Vec<(TableCase, Scene)> = Vec::new();
    let mut kinds: Vec<(TableCase, Box<dyn Kind>)> = Vec::new();
    for (case, scene) in cases {
        match scene {
            AnyScene::Catalog(scene) => scenes.push((case, *scene)),
            AnyScene::Kind(scene) => kinds.push((case, scene)),
        }
    }
    if !kinds.is_empty() {
        return execute_kind(kinds, (text, name, out, options, swept));
    }
    refuse_large_output(
        scenes.iter().map(|(_, s)| trajectory_bytes(s)).sum(),
        options,
    )?;
    let writer = writer_of(name, text, options.shard);
    let planned = planned_entries(&scenes, swept, options.shard);
    let _claim = Claim::take(out, options.force, &writer, &planned)?;
    if !swept {
        let (_, scene) = &scenes[0];
        let outcome = run_case(scene, name, out, true, None)?;
        print_outcome(scene, &outcome, out);
        return Ok(());
    }
    run_sweep(&scenes, name, out, options.shard)
}

/// Runs a scene of a registered kind, or each case of its sweep, into `out`.
fn execute_kind(
    cases: Vec<(TableCase, Box<dyn Kind>)>,
    (text, name, out, options, swept): (&str, &str, &Path, Options, bool),
) -> Result<()> {
    let numbers: f64 = (cases.iter())
        .map(|(_, scene)| scene.trajectory_numbers())
        .sum();
    let bytes = numbers * NUMBER_BYTES;
    refuse_large_output(bytes, options)?;
    let single = cases.first().filter(|_| !swept).map(|(_, scene)| scene);
    let planned: Vec<String> = match single {
        Some(scene) => (scene.folders().into_iter())
            .chain(["summary.json".to_owned()])
            .collect(),
        None => (cases.iter())
            .map(|(case, _)| case_folder(case.index))
            .chain([sweep_file(options.shard)])
            .chain((options.shard.is_none()).then(|| SWEEP_PLOT.to_owned()))
            .collect(),
    };
    let writer = writer_of(name, text, options.shard);
    let _claim = Claim::take(out, options.force, &writer, &planned)?;
    if let Some(scene) = single {
        return execute_alone(scene.as_ref(), name, out);
    }
    let (table, failures) = run_cases(&cases, name, |index| {
        let folder = out.join(case_folder(index));
        writable_folder(&folder)?;
        Ok(folder)
    });
    // A shard's table is a part; its plot is drawn when the shards are merged.
    if options.shard.is_none() {
        write_sweep_plot(out, &table)?;
    }
    finish_sweep(name, out, options.shard, &table, &failures)
}

/// Runs a scene of a registered kind into `out`, a folder claimed and found writable: each
/// run's trajectory and drawings through the command's recorder, then `summary.json`.
pub(super) fn run_into<'a>(
    scene: &'a dyn Kind,
    name: &str,
    (out, progress): (&Path, bool),
) -> Result<Box<dyn Finished + 'a>> {
    let mut recorder = FolderRecorder::new(out, progress);
    let finished = scene.run(name, &mut recorder)?;
    let bytes = serde_json::to_vec_pretty(&finished.summary())?;
    let path = out.join("summary.json");
    write_atomically(&path, &bytes).with_context(|| format!("writing {}", path.display()))?;
    Ok(finished)
}

/// Runs a scene of a registered kind alone into `out` and prints its report; a signal that
/// stopped it says what was kept.
fn execute_alone(scene: &dyn Kind, name: &str, out: &Path) -> Result<()> {
    let finished = run_into(scene, name, (out, true))?;
    print!("{}", finished.report());
    println!("  written to {}", eom_cli::shell_path(out));
    match (finished.stopped(), signal_received()) {
        (true, Some(signal)) => Err(Interrupted {
            signal,
            kept: format!(
                "the {} finished before it, and summary.json, in {}",
                eom::counted(finished.runs_kept(), "manoeuvre", "manoeuvres"),
                out.display()
            ),
        }
        .into()),
        _ => Ok(()),
    }
}

/// Who writes into the folder: the whole run, or one shard of its sweep.
fn writer_of(name: &str, text: &str, shard: Option<(usize, usize)>) -> Writer {
    match shard {
        Some((index, count)) => Writer::Shard {
            index,
            count,
            sweep: sweep_identity(name, text, count),
        },
        None => Writer::Whole,
    }
}

/// Bytes per trajectory number as written (shortest round-trip, up to 24 characters, most
/// 18–20) with its comma.
const NUMBER_BYTES: f64 = 21.0;

/// About how many bytes a scene's trajectory.csv takes.
fn trajectory_bytes(scene: &Scene) -> f64 {
    let rows = scene.integrator.end_time / scene.every + 1.0;
    let energies = if scene.selection.info.potential_energy || scene.loads.has_potential() {
        3.0
    } else {
        1.0
    };
    let columns = 1.0 + scene.state_names().len() as f64 + energies;
    rows * columns * NUMBER_BYTES
}

/// Refuses, before anything runs, a run that would write more than [`LARGE_OUTPUT`] without
/// `--large-output`.
fn refuse_large_output(bytes: f64, options: Options) -> Result<()> {
    if bytes <= LARGE_OUTPUT || options.large_output {
        return Ok(());
    }
    let message = format!(
        "this run would write about {} MB of trajectory; pass --large-output to write it, or \
         make output.every longer",
        Short((bytes / 1e6).round())
    );
    Err(Usage(message).into())
}

/// Every top-level entry a run may write into its folder: a sweep's case folders and its
/// table, or a single run's trajectory, summary and plots.
fn planned_entries(
    scenes: &[(TableCase, Scene)],
    swept: bool,
    shard: Option<(usize, usize)>,
) -> Vec<String> {
    if swept {
        let mut entries: Vec<String> = scenes
            .iter()
            .map(|(case, _)| case_folder(case.index))
            .collect();
        entries.push(sweep_file(shard));
        return entries;
    }
    let mut entries = vec!["trajectory.csv".to_owned(), "summary.json".to_owned()];
    entries.extend(PLOT_FILES.map(String::from));
    entries.push(VIEW_FILE.to_owned());
    entries
}

/// The folder of sweep case `index`, `case-NNNN`, for a case of any kind.
fn case_folder(index: usize) -> String {
    format!("case-{index:04}")
}

/// The sweep's table: `sweep.csv`, or a shard's `sweep-shard-K-of-N.csv`.
fn sweep_file(shard: Option<(usize, usize)>) -> String {
    match shard {
        Some((k, n)) => format!("sweep-shard-{k}-of-{n}.csv"),
        None => "sweep.csv".into(),
    }
}

/// Creates a case's folder and makes sure files can be written into it, so that a folder the
/// run could not write into is named before the run, not after.
fn writable_folder(out: &Path) -> Result<(), FolderError> {
    let unwritable = |cause| FolderError::Unwritable {
        path: out.to_owned(),
        cause,
    };
    std::fs::create_dir_all(out).map_err(unwritable)?;
    let probe = out.join(format!(".eom-write-check-{}", std::process::id()));
    std::fs::write(&probe, b"")
        .and_then(|()| std::fs::remove_file(&probe))
        .map_err(unwritable)
}

/// What one run wrote.
struct Outcome {
    report: Report,
    files: Vec<PathBuf>,
    /// The plots left out although the run has their data, each with why.
    not_drawn: Vec<String>,
    /// The family's own figures ([`family_measures`]), or why each is not given.
    measures: Vec<(&'static str, Result<f64, String>)>,
}

/// Runs one scene into `out`, a folder already known to be writable: trajectory, summary,
/// plots. A run that stops early (a failure, a signal) still writes its summary and plots of
/// the rows it wrote, then returns the error.
fn run_case(
    scene: &Scene,
    name: &str,
    out: &Path,
    progress: bool,
    case: Option<&TableCase>,
) -> Result<Outcome> {
    let names = scene.state_names();
    // Potential and total energy columns where the model or the loads have a potential.
    let model_potential = scene.selection.info.potential_energy;
    let with_potential = model_potential || scene.loads.has_potential();
    let rows = (scene.integrator.end_time / scene.every) as usize + 1;
    let csv_path = out.join("trajectory.csv");
    let mut writer = TrajectoryWriter::create(&csv_path, &names, with_potential, rows)
        .with_context(|| format!("creating {}", csv_path.display()))?;
    if progress {
        writer.on_row(progress_bar(scene.integrator.end_time));
    }
    let ran = run_reporting(scene, &mut Interruptible(&mut writer));
    // The first write error, as an I/O error (exit 4), before anything the run says.
    let columns = writer
        .finish()
        .with_context(|| format!("writing {}", csv_path.display()))?;
    let report = ran.report;
    if progress {
        for warning in &report.warnings {
            eprintln!("warning: {warning}");
        }
    }
    // A row refused after a signal is the only way the run stops that the run calls `Stopped`.
    let interrupted = match (&ran.error, signal_received()) {
        (Some(RunError::Stopped { .. }), Some(signal)) => Some(signal),
        _ => None,
    };
    let mut summary = Summary::new(
        name.to_owned(),
        scene.title.clone(),
        (scene.selection.info, scene.selection.reason.clone()),
        scene.integrator.method.name(),
        &report,
        &names,
    );
    summary.interrupted = interrupted.is_some();
    if interrupted.is_none() {
        summary.error = ran.error.as_ref().map(RunError::to_string);
    }
    let measures = family_measures(scene, &columns);
    for (key, value) in &measures {
        match value {
            Ok(value) => {
                summary.extra.insert((*key).into(), Extra::Number(*value));
            }
            Err(why) => summary.warnings.push(format!("{key} is not given: {why}")),
        }
    }
    if let Some(case) = case {
        let values = (case.values.iter())
            .map(|(key, value)| (key.clone(), toml_to_json(value)))
            .collect();
        let index = case.index;
        summary
            .extra
            .insert("case".into(), Extra::Case { index, values });
    }
    add_stop(scene, &report, &mut summary);
    let summary_path = out.join("summary.json");
    summary
        .write(&summary_path)
        .with_context(|| format!("writing {}", summary_path.display()))?;
    let mut files = vec![csv_path, summary_path];
    let mut not_drawn = Vec::new();
    // A plot needs two rows; a run stopped at its start has at most one.
    if columns.time.len() >= 2 {
        // A sweep case's plots say its values; its summary keeps the scene's title exactly
        // and says them under "case".
        let title = match case {
            Some(case) => format!("{} — {}", scene.title, case.label()),
            None => scene.title.clone(),
        };
        let (plots, left_out) = super::plots::write(scene, &title, &columns, out)?;
        files.extend(plots);
        not_drawn = left_out;
        files.push(super::view::write(scene, &columns, out)?);
    }
    if let Some(signal) = interrupted {
        let kept = format!(
            "the run stopped at t = {} s of {} s; {} holds it up to there: every row in \
             trajectory.csv, summary.json (\"interrupted\": true) and the plots",
            Short(report.final_time),
            Short(scene.integrator.end_time),
            out.display()
        );
        return Err(Interrupted { signal, kept }.into());
    }
    if let Some(error) = ran.error {
        let kept = match columns.time.len() {
            0 => format!(
                "{name} stopped at its start; {} holds its summary.json",
                out.display()
            ),
            _ => format!(
                "{name} stopped early; {} holds its rows up to t = {} s, summary.json and the \
                 plots",
                out.display(),
                Short(report.final_time)
            ),
        };
        return Err(anyhow::Error::new(error).context(kept));
    }
    Ok(Outcome {
        report,
        files,
        not_drawn,
        measures,
    })
}

/// What a scene with a stop condition adds to its summary: the condition, and the time it
/// ended the run (`null` if it never held before the end time).
fn add_stop(scene: &Scene, report: &Report, summary: &mut Summary) {
    if let Some(condition) = &scene.stop {
        let extra = &mut summary.extra;
        extra.insert("stop_when".into(), Extra::Text(condition.text.clone()));
        extra.insert("stopped_at".into(), Extra::Time(report.stopped_at));
    }
}

/// The figures a family adds to its summary and its sweep's table, by key.
fn family_measure_keys(scene: &Scene) -> &'static [&'static str] {
    match scene.body {
        Body::Pendulum(_) => &["period_s"],
        _ => &[],
    }
}

/// The family's figures: the pendulum's period, measured from the trajectory by the swing
/// test's own measurement ([`eom::swing::measure_period`]); where the run gives none (fewer
/// than two swings), why.
fn family_measures(scene: &Scene, columns: &Columns) -> Vec<(&'static str, Result<f64, String>)> {
    family_measure_keys(scene)
        .iter()
        .map(|&key| {
            let value = match key {
                "period_s" => eom::swing::measure_period(&columns.time, &columns.state[0])
                    .map_err(|e| e.to_string()),
                _ => Err(format!("{key} is not a figure of this family")),
            };
            (key, value)
        })
        .collect()
}

/// A swept value as JSON: TOML's numbers, strings, booleans and arrays as they are.
fn toml_to_json(value: &toml::Value) -> serde_json::Value {
    serde_json::to_value(value).unwrap_or(serde_json::Value::Null)
}

/// A progress bar on a terminal for runs longer than about a second; none otherwise.
struct Progress {
    bar: ProgressBar,
    start: Instant,
    shown: bool,
    end_time: f64,
}

impl Progress {
    fn tick_to(&mut self, t: f64) {
        if !self.shown && self.start.elapsed() > Duration::from_secs(1) {
            self.bar.set_draw_target(ProgressDrawTarget::stderr());
            self.shown = true;
        }
        self.bar.set_position((t * 1000.0) as u64);
        if self.shown {
            self.bar.set_message(progress_message(t, self.end_time));
        }
    }
}

/// What the bar says beside itself: `t = 12.5 s of 20 s`.
fn progress_message(t: f64, end_time: f64) -> String {
    format!("t = {} s of {} s", Short(t), Short(end_time))
}

impl Drop for Progress {
    fn drop(&mut self) {
        self.bar.finish_and_clear();
    }
}

/// A bar over the run's simulated time, hidden until the run has taken a second; indicatif
/// draws nothing when standard error is not a terminal.
pub(super) fn progress_bar(end_time: f64) -> impl FnMut(f64) + 'static {
    let bar = ProgressBar::with_draw_target(
        Some((end_time * 1000.0) as u64),
        ProgressDrawTarget::hidden(),
    );
    bar.set_style(
        ProgressStyle::with_template("{bar:40} {msg}, {eta} left")
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    let mut progress = Progress {
        bar,
        start: Instant::now(),
        shown: false,
        end_time,
    };
    move |t| progress.tick_to(t)
}

fn print_outcome(scene: &Scene, outcome: &Outcome, out: &Path) {
    let info = scene.selection.info;
    let (ops, full) = (info.operations, info.full_variant().operations);
    let report = &outcome.report;
    println!(
        "{}: ran {} ({})",
        printable(&scene.title),
        info.name,
        scene.selection.reason
    );
    if full.arithmetic() != ops.arithmetic() {
        println!(
            "  {} arithmetic operations per call, against {} for {}",
            ops.arithmetic(),
            full.arithmetic(),
            info.full_variant().name
        );
    }
    println!(
        "  {}: {} steps ({} rejected), {} rhs calls, {:.3} s",
        scene.integrator.method.name(),
        report.steps,
        report.rejected,
        report.rhs_evals,
        report.wall_seconds
    );
    if let Some(drift) = report.energy_drift {
        println!(
            "  energy drift {drift:.2e} (largest |E − E₀| over the rows, relative to max(|E₀|, largest T))"
        );
    }
    if let (Some(t), Some(condition)) = (report.stopped_at, &scene.stop) {
        println!(
            "  stopped at t = {} s, where `{condition}` first held (summary.json: stopped_at, every digit)",
            Short(t)
        );
    }

    println!("  wrote into {}:", shell_path(out));
    for file in &outcome.files {
        println!(
            "    {}",
            file.file_name()
                .map_or_else(String::new, |f| f.to_string_lossy().into_owned())
        );
    }
    for reason in &outcome.not_drawn {
        println!("    ({reason})");
    }
    if let Some(view) = outcome
        .files
        .iter()
        .find(|f| f.extension().is_some_and(|e| e == "html"))
    {
        println!("  open {} in a browser to see the run", shell_path(view));
    }
}

/// Runs every case of a sweep in parallel and writes `sweep.csv`.
fn run_sweep(
    scenes: &[(TableCase, Scene)],
    name: &str,
    out: &Path,
    shard: Option<(usize, usize)>,
) -> Result<()> {
    let outcomes: Vec<Result<Outcome>> = scenes
        .par_iter()
        .map(|(case, scene)| {
            if signal_received().is_some() {
                bail!("not run: the sweep was interrupted");
            }
            let folder = out.join(case_folder(case.index));
            writable_folder(&folder)?;
            run_case(scene, name, &folder, false, Some(case))
        })
        .collect();
    let table = sweep_table(scenes, &outcomes);
    let failures: Vec<(usize, Option<String>)> = scenes
        .iter()
        .zip(&outcomes)
        .map(|((case, _), outcome)| (case.index, outcome.as_ref().err().map(|e| format!("{e:#}"))))
        .collect();
    finish_sweep(name, out, shard, &table, &failures)
}

/// Writes a sweep's table (any family's) and says how it went: how many cases ran and
/// failed, each failure, and, after a signal, what was kept.
fn finish_sweep(
    name: &str,
    out: &Path,
    shard: Option<(usize, usize)>,
    table: &str,
    failures: &[(usize, Option<String>)],
) -> Result<()> {
    let file = out.join(sweep_file(shard));
    write_atomically(&file, table.as_bytes())
        .with_context(|| format!("writing {}", file.display()))?;
    let failed = failures.iter().filter(|(_, e)| e.is_some()).count();
    let cases = failures.len();
    println!(
        "{name}: {cases} cases in {}, {failed} failed; one line per case in {}",
        shell_path(out),
        shell_path(&file)
    );
    for (index, error) in failures {
        if let Some(error) = error {
            eprintln!("  case {index}: {error}");
        }
    }
    if let Some(signal) = signal_received() {
        let kept = format!(
            "{} of {cases} cases finished; each interrupted case keeps what it ran, and {} \
             lists every case",
            cases - failed,
            file.display()
        );
        return Err(Interrupted { signal, kept }.into());
    }
    if failed > 0 {
        bail!("{failed} of {cases} cases failed");
    }
    Ok(())
}

/// `case, <swept keys…>, variant, steps, rhs_evals, wall_seconds, energy_drift, <final
/// state…>, error`, one line per case.
fn sweep_table(scenes: &[(TableCase, Scene)], outcomes: &[Result<Outcome>]) -> String {
    let Some((first, scene)) = scenes.first() else {
        return String::new();
    };
    let mut header = vec!["case".to_owned()];
    header.extend(first.values.iter().map(|(k, _)| k.clone()));
    header.extend(
        [
            "variant",
            "steps",
            "rhs_evals",
            "wall_seconds",
            "energy_drift",
        ]
        .map(String::from),
    );
    let measures = family_measure_keys(scene);
    header.extend(measures.iter().map(|key| (*key).to_owned()));
    header.extend(scene.state_names().iter().map(|n| format!("final_{n}")));
    header.push("error".into());
    let mut writer = csv::Writer::from_writer(Vec::new());
    let _ = writer.write_record(&header);
    for ((case, scene), outcome) in scenes.iter().zip(outcomes) {
        let mut row = vec![case.index.to_string()];
        row.extend(case.values.iter().map(|(_, v)| v.to_string()));
        row.push(scene.selection.info.name.to_owned());
        match outcome {
            Ok(Outcome {
                report: r,
                measures,
                ..
            }) => {
                row.extend([
                    r.steps.to_string(),
                    r.rhs_evals.to_string(),
                    number_text(r.wall_seconds),
                ]);
                row.push(r.energy_drift.map_or_else(String::new, number_text));
                row.extend((measures.iter()).map(|(_, v)| {
                    v.as_ref()
                        .map_or_else(|_| String::new(), |v| number_text(*v))
                }));
                row.extend(r.final_state.iter().map(|x| number_text(*x)));
                row.push(String::new());
            }
            Err(error) => {
                row.extend(std::iter::repeat_n(
                    String::new(),
                    4 + measures.len() + scene.state_names().len(),
                ));
                row.push(format!("{error:#}"));
            }
        }
        let _ = writer.write_record(&row);
    }
    String::from_utf8(writer.into_inner().unwrap_or_default()).unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_progress_bar_says_the_simulated_time_and_its_end() {
        assert_eq!(progress_message(12.5, 20.0), "t = 12.5 s of 20 s");
        assert_eq!(
            progress_message(1.0 / 3.0, 1e4),
            "t = 0.333333 s of 10000 s"
        );
        assert!(ProgressStyle::with_template("{bar:40} {msg}, {eta} left").is_ok());
    }
}
