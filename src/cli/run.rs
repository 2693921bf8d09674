//! `eom run SCENE`: run a scene and write what a person wants to look at.
//!
//! Into the output folder (default: a folder named after the scene file, in the current
//! directory): `trajectory.csv`, `summary.json` and the SVG plots. A folder that already
//! holds a run is not overwritten without `--force`. A scene with a `[sweep]` runs every case
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

use anyhow::{Context, Result, bail};
use eom::output::summary::{Summary, write_atomically};
use eom::output::text::printable;
use eom::output::trajectory::{Columns, TrajectoryWriter};
use eom::run::{Report, Row, RunError, Sink, run_reporting};
use eom::scene::sweep::{Case, cases, parse_shard};
use eom::scene::{Body, Problem, Scene, SceneError};
use eom::ship::ShipScene;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rayon::prelude::*;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::time::{Duration, Instant};

/// The default scene: `scenes/tennis_racket.toml`, built into the binary.
pub const DEFAULT_SCENE: &str = include_str!("../../scenes/tennis_racket.toml");
/// The default scene's name, for its output folder.
pub const DEFAULT_NAME: &str = "tennis_racket.toml";

/// Options of `eom run`.
#[derive(clap::Args)]
pub struct Args {
    /// The scene file (TOML); see `scenes/` and README.
    scene: PathBuf,
    /// The output folder (default: the scene file's name without `.toml`, here).
    #[arg(long)]
    out: Option<PathBuf>,
    /// Write into an output folder that already holds a run.
    #[arg(long)]
    force: bool,
    /// Run only the sweep cases k ≡ K (mod N), written `K/N`.
    #[arg(long)]
    shard: Option<String>,
}

/// An output folder that already holds a run, refused without `--force`.
#[derive(Debug, thiserror::Error)]
#[error("{0} already holds a run; use --force to write over it, or --out for another folder")]
pub struct OutputExists(pub PathBuf);

/// An output folder that cannot be made or written into: a path under a file, a read-only
/// directory. Named before anything runs.
#[derive(Debug, thiserror::Error)]
#[error("the output folder {} cannot be written: {cause}", path.display())]
pub struct OutputFolder {
    /// The folder.
    pub path: PathBuf,
    /// What the system said.
    pub cause: std::io::Error,
}

impl OutputFolder {
    fn new(path: &Path, cause: std::io::Error) -> Self {
        Self {
            path: path.to_owned(),
            cause,
        }
    }
}

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
    let shard = args
        .shard
        .as_deref()
        .map(parse_shard)
        .transpose()
        .map_err(anyhow::Error::msg)?;
    execute(&text, &name, &base, &out, args.force, shard)
}

/// Runs the default scene into `./tennis_racket/` (what `cargo run --release` does).
pub fn run_default() -> Result<()> {
    watch_signals();
    let out = default_folder(Path::new(DEFAULT_NAME));
    println!(
        "eom: no subcommand given, so running the default scene ({DEFAULT_NAME}); `eom --help` lists the others."
    );
    // The default run writes over its own folder, so that the first command can be run again;
    // it says so when there is a run to replace.
    if out.join("summary.json").exists() {
        println!(
            "eom: replacing the default run in {}/ (eom run SCENE keeps a run unless --force)",
            out.display()
        );
    }
    execute(
        DEFAULT_SCENE,
        DEFAULT_NAME,
        Path::new("scenes"),
        &out,
        true,
        None,
    )
}

/// The folder named after the scene file, in the current directory.
fn default_folder(scene: &Path) -> PathBuf {
    let stem = scene
        .file_stem()
        .map_or_else(|| "run".into(), |s| s.to_string_lossy().into_owned());
    PathBuf::from(stem)
}

fn execute(
    text: &str,
    name: &str,
    base: &Path,
    out: &Path,
    force: bool,
    shard: Option<(usize, usize)>,
) -> Result<()> {
    watch_signals();
    if eom::ship::scene::is_ship_scene(text) {
        let scene = ShipScene::parse(text, name)?;
        if shard.is_some() {
            bail!("--shard splits a [sweep]; a ship scene has none");
        }
        prepare_folder(out, force)?;
        return super::ship::execute(&scene, name, out);
    }
    let all = cases(text, name)?;
    let swept = !all[0].values.is_empty();
    // Every case is checked before any runs: a bad value fails the sweep at once.
    let scenes: Vec<(Case, Scene)> = all
        .into_iter()
        .filter(|case| shard.is_none_or(|(k, n)| case.index % n == k))
        .map(|case| {
            let scene = Scene::from_file(&case.file, name, base)?;
            Ok((case, scene))
        })
        .collect::<Result<_, SceneError>>()?;
    prepare_folder(out, force)?;
    if !swept {
        let (_, scene) = &scenes[0];
        let outcome = run_case(scene, name, out, true)?;
        print_outcome(scene, &outcome, out);
        return Ok(());
    }
    run_sweep(&scenes, name, out, shard)
}

/// Creates the output folder and makes sure files can be written into it, refusing one that
/// holds a run unless `force`.
fn prepare_folder(out: &Path, force: bool) -> Result<()> {
    let holds_a_run = out.join("summary.json").exists()
        || out.join("trajectory.csv").exists()
        || out.join("sweep.csv").exists();
    if holds_a_run && !force {
        return Err(OutputExists(out.to_owned()).into());
    }
    writable_folder(out)?;
    Ok(())
}

/// Creates `out` if need be and writes and removes a file in it, so that a folder the run
/// could not write into is named before the run, not after.
fn writable_folder(out: &Path) -> Result<(), OutputFolder> {
    if out.is_file() {
        let cause = std::io::Error::other("it is a file, not a folder");
        return Err(OutputFolder::new(out, cause));
    }
    std::fs::create_dir_all(out).map_err(|e| OutputFolder::new(out, e))?;
    let probe = out.join(format!(".eom-write-check-{}", std::process::id()));
    std::fs::write(&probe, b"")
        .and_then(|()| std::fs::remove_file(&probe))
        .map_err(|e| OutputFolder::new(out, e))
}

/// What one run wrote.
struct Outcome {
    report: Report,
    files: Vec<PathBuf>,
}

/// Runs one scene into `out`, a folder already known to be writable: trajectory, summary,
/// plots. A run that stops early (a failure, a signal) still writes its summary and plots of
/// the rows it wrote, then returns the error.
fn run_case(scene: &Scene, name: &str, out: &Path, progress: bool) -> Result<Outcome> {
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
    let write_error = writer.error().map(|e| e.to_string());
    let columns = writer.finish();
    if let Some(error) = write_error {
        bail!("writing {}: {error}", csv_path.display());
    }
    let columns = columns.with_context(|| format!("writing {}", csv_path.display()))?;
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
    add_family_measures(scene, &columns, &mut summary);
    add_stop(scene, &report, &mut summary);
    let summary_path = out.join("summary.json");
    summary
        .write(&summary_path)
        .with_context(|| format!("writing {}", summary_path.display()))?;
    let mut files = vec![csv_path, summary_path];
    // A plot needs two rows; a run stopped at its start has at most one.
    if columns.time.len() >= 2 {
        files.extend(super::plots::write(scene, &columns, out)?);
    }
    if let Some(signal) = interrupted {
        let kept = format!(
            "the run stopped at t = {} s of {} s; {} holds it up to there: every row in \
             trajectory.csv, summary.json (\"interrupted\": true) and the plots",
            report.final_time,
            scene.integrator.end_time,
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
                report.final_time
            ),
        };
        return Err(anyhow::Error::new(error).context(kept));
    }
    Ok(Outcome { report, files })
}

/// What a scene with a stop condition adds to its summary: the condition, and the time it
/// ended the run (`null` if it never held before the end time).
fn add_stop(scene: &Scene, report: &Report, summary: &mut Summary) {
    if let Some(condition) = &scene.stop {
        let extra = &mut summary.extra;
        extra.insert("stop_when".into(), serde_json::json!(condition.text));
        extra.insert("stopped_at".into(), serde_json::json!(report.stopped_at));
    }
}

/// What a family adds to its summary: the pendulum's period, measured from the trajectory by
/// the swing test's own measurement ([`eom::swing::measure_period`]).
fn add_family_measures(scene: &Scene, columns: &Columns, summary: &mut Summary) {
    if let Body::Pendulum(_) = scene.body
        && let Ok(period) = eom::swing::measure_period(&columns.time, &columns.state[0])
    {
        summary
            .extra
            .insert("period_s".into(), serde_json::json!(period));
    }
}

/// A progress bar on a terminal for runs longer than about a second; none otherwise.
struct Progress {
    bar: ProgressBar,
    start: Instant,
    shown: bool,
}

impl Progress {
    fn tick_to(&mut self, t: f64) {
        if !self.shown && self.start.elapsed() > Duration::from_secs(1) {
            self.bar.set_draw_target(ProgressDrawTarget::stderr());
            self.shown = true;
        }
        self.bar.set_position((t * 1000.0) as u64);
    }
}

impl Drop for Progress {
    fn drop(&mut self) {
        self.bar.finish_and_clear();
    }
}

/// A bar over the run's simulated time, hidden until the run has taken a second; indicatif
/// draws nothing when standard error is not a terminal.
fn progress_bar(end_time: f64) -> impl FnMut(f64) + 'static {
    let bar = ProgressBar::with_draw_target(
        Some((end_time * 1000.0) as u64),
        ProgressDrawTarget::hidden(),
    );
    bar.set_style(
        ProgressStyle::with_template("{bar:40} t = {msg} s of {len_s} s, {eta} left")
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    let mut progress = Progress {
        bar,
        start: Instant::now(),
        shown: false,
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
        println!("  stopped at t = {t} s, where `{condition}` first held");
    }

    println!("  wrote into {}:", out.display());
    for file in &outcome.files {
        println!(
            "    {}",
            file.file_name()
                .map_or_else(String::new, |f| f.to_string_lossy().into_owned())
        );
    }
    if let Some(plot) = outcome
        .files
        .iter()
        .find(|f| f.extension().is_some_and(|e| e == "svg"))
    {
        println!("  open {} in a browser to see the run", plot.display());
    }
}

/// Runs every case of a sweep in parallel and writes `sweep.csv`.
fn run_sweep(
    scenes: &[(Case, Scene)],
    name: &str,
    out: &Path,
    shard: Option<(usize, usize)>,
) -> Result<()> {
    let outcomes: Vec<Result<Report>> = scenes
        .par_iter()
        .map(|(case, scene)| {
            if signal_received().is_some() {
                bail!("not run: the sweep was interrupted");
            }
            let folder = out.join(format!("case-{:04}", case.index));
            writable_folder(&folder)?;
            run_case(scene, name, &folder, false).map(|o| o.report)
        })
        .collect();
    let table = sweep_table(scenes, &outcomes);
    let file = match shard {
        Some((k, n)) => format!("sweep-shard-{k}-of-{n}.csv"),
        None => "sweep.csv".into(),
    };
    write_atomically(&out.join(&file), table.as_bytes())
        .with_context(|| format!("writing {}", out.join(&file).display()))?;
    let failed = outcomes.iter().filter(|o| o.is_err()).count();
    println!(
        "{}: {} cases in {}, {} failed; one line per case in {}",
        name,
        scenes.len(),
        out.display(),
        failed,
        out.join(&file).display()
    );
    for ((case, _), outcome) in scenes.iter().zip(&outcomes) {
        if let Err(error) = outcome {
            eprintln!("  case {}: {error:#}", case.index);
        }
    }
    if let Some(signal) = signal_received() {
        let kept = format!(
            "{} of {} cases finished; each interrupted case keeps its rows, summary and plots, \
             and {} lists every case",
            scenes.len() - failed,
            scenes.len(),
            out.join(&file).display()
        );
        return Err(Interrupted { signal, kept }.into());
    }
    if failed > 0 {
        bail!("{failed} of {} cases failed", scenes.len());
    }
    Ok(())
}

/// `case, <swept keys…>, variant, steps, rhs_evals, wall_seconds, energy_drift, <final
/// state…>, error`, one line per case.
fn sweep_table(scenes: &[(Case, Scene)], outcomes: &[Result<Report>]) -> String {
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
    header.extend(scene.state_names().iter().map(|n| format!("final_{n}")));
    header.push("error".into());
    let mut writer = csv::Writer::from_writer(Vec::new());
    let _ = writer.write_record(&header);
    for ((case, scene), outcome) in scenes.iter().zip(outcomes) {
        let mut row = vec![case.index.to_string()];
        row.extend(case.values.iter().map(|(_, v)| v.to_string()));
        row.push(scene.selection.info.name.to_owned());
        match outcome {
            Ok(r) => {
                row.extend([
                    r.steps.to_string(),
                    r.rhs_evals.to_string(),
                    r.wall_seconds.to_string(),
                ]);
                row.push(r.energy_drift.map_or_else(String::new, |d| d.to_string()));
                row.extend(r.final_state.iter().map(f64::to_string));
                row.push(String::new());
            }
            Err(error) => {
                row.extend(std::iter::repeat_n(
                    String::new(),
                    4 + scene.state_names().len(),
                ));
                row.push(format!("{error:#}"));
            }
        }
        let _ = writer.write_record(&row);
    }
    String::from_utf8(writer.into_inner().unwrap_or_default()).unwrap_or_default()
}
