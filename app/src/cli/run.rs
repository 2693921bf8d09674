//! `eom run SCENE`: run a scene and write what a person wants to look at.
//!
//! Into the output folder (default: a folder named after the scene file, in the current
//! directory): `trajectory.csv`, `summary.json`, the SVG plots and `view.html`, the run in 3-D. A folder that already
//! holds a run is not overwritten without `--force`, and the folder is taken for the run alone
//! ([`eom::output::folder`]). A scene with a `[sweep]` runs every case
//! in parallel, each into `case-NNNN/`, and writes `sweep.csv`, one line per case; `--shard
//! K/N` runs only the cases k ≡ K (mod N). A scene with an `[uncertainty]` is a Monte Carlo
//! (`uncertainty`): its cases' figures and verdicts, counted. With no scene, `eom` runs its default scene, the
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
use super::uncertainty;
use anyhow::{Context, Result};
use eom::Short;
use eom::kinds::{Finished, Kind};
use eom::output::folder::{Claim, FolderError, Writer, sweep_identity};
use eom::output::summary::write_atomically;
use eom::scene::sweep::{TableCase, is_swept, parse_shard, shard_tables};
use eom::scene::uncertainty::is_uncertain;
use eom::scene::{AnyScene, Problem, SceneError};
use eom_cli::plots::PLOT_FILES;
use eom_cli::shell_path;
use eom_cli::view::VIEW_FILE;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
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
    /// Run only the cases k ≡ K (mod N) of a sweep or a Monte Carlo, written `K/N`.
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

/// Cases of a sweep or a Monte Carlo that failed (a scene their values make refused, a run that
/// failed), after every other case ran and the table, which says why each failed, was written:
/// the command exits 5, as for a run that fails.
#[derive(Debug, thiserror::Error)]
#[error("{failed} of {cases} cases failed; {table} says why each did")]
pub struct CasesFailed {
    /// How many failed.
    pub failed: usize,
    /// How many there were.
    pub cases: usize,
    /// The table that lists them.
    pub table: String,
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
    if is_uncertain(text) {
        return uncertainty::execute(text, name, base, out, (options.force, options.shard));
    }
    let swept = is_swept(text);
    if options.shard.is_some() && !swept {
        let message =
            format!("--shard splits a [sweep]; {name} has none, so every shard would run it whole");
        return Err(Usage(message).into());
    }
    // Every case is checked before any runs: a bad value fails the sweep at once.
    let cases: Vec<(TableCase, Box<dyn Kind>)> = shard_tables(text, name, options.shard)?
        .into_iter()
        .map(|case| {
            let scene = AnyScene::from_table(case.table.clone(), name, base)?.into_kind();
            Ok((case, scene))
        })
        .collect::<Result<_, SceneError>>()?;
    let numbers: f64 = (cases.iter())
        .map(|(_, scene)| scene.trajectory_numbers())
        .sum();
    refuse_large_output(numbers * NUMBER_BYTES, options)?;
    let single = cases.first().filter(|_| !swept).map(|(_, scene)| scene);
    let planned: Vec<String> = match single {
        Some(scene) => planned_entries(scene.as_ref()),
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

/// Every top-level entry a scene run alone may write into its folder: its runs' folders (or
/// a run's trajectory at the top, with the plots and the view drawn beside it) and its
/// summary.
fn planned_entries(scene: &dyn Kind) -> Vec<String> {
    let mut entries = scene.folders();
    let at_top = entries.iter().any(|entry| entry == TRAJECTORY);
    entries.push("summary.json".to_owned());
    if at_top {
        entries.extend(PLOT_FILES.map(String::from));
        entries.push(VIEW_FILE.to_owned());
    }
    entries
}

/// A run's trajectory, in its folder.
const TRAJECTORY: &str = "trajectory.csv";

/// What a scene's run wrote at the top of its folder (a run recorded there: its trajectory,
/// the summary, its plots and view), and the plots left out, with why.
pub(super) struct Written {
    files: Vec<PathBuf>,
    not_drawn: Vec<String>,
}

/// Runs a scene into `out`, a folder claimed and found writable: each run's trajectory and
/// drawings through the command's recorder, then `summary.json`, which for a sweep's `case`
/// says its number and values under `"case"`.
pub(super) fn run_into<'a>(
    scene: &'a dyn Kind,
    name: &str,
    (out, progress, case): (&Path, bool, Option<&TableCase>),
) -> Result<(Box<dyn Finished + 'a>, Written)> {
    let mut recorder = FolderRecorder::new(out, progress, case.map(TableCase::label));
    let finished = scene.run(name, &mut recorder)?;
    let bytes = finished.summary_file(case);
    let path = out.join("summary.json");
    write_atomically(&path, &bytes).with_context(|| format!("writing {}", path.display()))?;
    let mut files = recorder.written;
    if let Some(at) = files.iter().position(|file| file.ends_with(TRAJECTORY)) {
        files.insert(at + 1, path);
    }
    let written = Written {
        files,
        not_drawn: recorder.not_drawn,
    };
    Ok((finished, written))
}

/// Why a run that failed where it failed, having kept what it ran, failed, with where it
/// kept it.
pub(super) fn failed(finished: &dyn Finished, name: &str, out: &Path) -> Option<anyhow::Error> {
    let error = finished.failure()?;
    let kept = format!(
        "{name} stopped early; {} holds {}",
        out.display(),
        finished.kept()
    );
    Some(anyhow::Error::new(error).context(kept))
}

/// Runs a scene alone into `out` and prints its report and what it wrote; a signal that
/// stopped it, or a failure where it kept what it ran, says what was kept.
fn execute_alone(scene: &dyn Kind, name: &str, out: &Path) -> Result<()> {
    let (finished, written) = run_into(scene, name, (out, true, None))?;
    for warning in finished.warnings() {
        eprintln!("warning: {warning}");
    }
    print!("{}", finished.report());
    print_written(out, &written);
    if let (true, Some(signal)) = (finished.stopped(), signal_received()) {
        let kept = format!("{}, in {}", finished.kept(), out.display());
        return Err(Interrupted { signal, kept }.into());
    }
    match failed(finished.as_ref(), name, out) {
        Some(error) => Err(error),
        None => Ok(()),
    }
}

/// Where the run wrote: each file at the top of its folder, with the plots left out and the
/// view to open, or the folder that holds its runs.
fn print_written(out: &Path, written: &Written) {
    if written.files.is_empty() {
        println!("  written to {}", shell_path(out));
        return;
    }
    println!("  wrote into {}:", shell_path(out));
    for file in &written.files {
        let name = file.file_name().unwrap_or_default().to_string_lossy();
        println!("    {name}");
    }
    for reason in &written.not_drawn {
        println!("    ({reason})");
    }
    let view = (written.files.iter()).find(|file| file.extension().is_some_and(|e| e == "html"));
    if let Some(view) = view {
        println!("  open {} in a browser to see the run", shell_path(view));
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
        let table = shell_path(&file);
        return Err(CasesFailed {
            failed,
            cases,
            table,
        }
        .into());
    }
    Ok(())
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
