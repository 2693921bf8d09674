//! The output folder of a run: taken for the run alone, and never written over unless it is
//! eom's own.
//!
//! Two runs writing into one folder at once interleave their rows and leave a summary of only
//! one of them, while each reports success; a folder that eom did not make may hold a user's
//! own files of the same names. So a run *claims* its folder before it writes a byte:
//!
//! - **A lock the operating system releases when the process dies.** An unsharded run holds
//!   `.eom-lock` exclusively (`flock`), so a second run into the same folder is refused and
//!   told which process holds it. The shards of one sweep (`--shard K/N`) write disjoint
//!   files, so they share that lock, each holds its own `.eom-lock-shard-K-of-N`, and all of
//!   them must be shards of the same sweep (the scene's text and N, kept in `.eom-sweep`).
//! - **A manifest of what eom wrote.** Every entry a run will write at the folder's top level
//!   (a file, or a case's or manoeuvre's folder) is listed in `.eom-run` (or the shard's
//!   `.eom-run-shard-K-of-N`) *before* the run writes it, so a run killed part-way still
//!   leaves its files known as eom's.
//! - **Whose files.** A folder that exists, is not empty and holds no manifest was not
//!   written by eom: it is refused without `--force`. With `--force` the entries the manifests
//!   list (the earlier run, whole) are removed first; nothing else is touched, and a file this
//!   run would write that eom did not write (a user's own `state.svg`) is refused before
//!   anything runs.
//! - **Never a system folder.** The path is resolved (symbolic links followed) and `/`, the
//!   home folder, `/usr`, `/etc` and the other system folders are refused even with
//!   `--force`.

use std::fs::{File, OpenOptions, TryLockError};
use std::io::{Read, Write};
use std::path::{Component, Path, PathBuf};

/// The lock every run of a folder takes: exclusively, or shared by the shards of one sweep.
const LOCK: &str = ".eom-lock";
/// The manifest of an unsharded run.
const MANIFEST: &str = ".eom-run";
/// The sweep whose shards write into the folder: its scene's name, N and a hash of its text.
const SWEEP: &str = ".eom-sweep";
/// Taken while a shard looks at and tidies the folder, so that shards start one at a time.
const SETUP: &str = ".eom-lock-setup";

/// Why an output folder cannot be used.
#[derive(Debug, thiserror::Error)]
pub enum FolderError {
    /// Another eom process is writing into the folder.
    #[error(
        "{} is being written by another eom run ({holder}); wait for it to end, or use --out \
         for another folder",
        folder.display()
    )]
    Busy {
        /// The folder.
        folder: PathBuf,
        /// Who holds it: the process numbers that the lock files name.
        holder: String,
    },
    /// The folder holds an earlier run.
    #[error("{} already holds a run; use --force to write over it, or --out for another folder", .0.display())]
    HoldsARun(PathBuf),
    /// The folder holds files, and eom did not write them.
    #[error(
        "{} is not empty and was not written by eom (it has no {MANIFEST}); use --out for an \
         empty or new folder, or --force to write beside its files",
        .0.display()
    )]
    NotEoms(PathBuf),
    /// With `--force`, a file the run would write exists and eom did not write it.
    #[error(
        "{} was not written by eom, and --force replaces only eom's own files; move it, or \
         use --out for another folder",
        .0.display()
    )]
    NotEomsFile(PathBuf),
    /// The folder holds the shards of another sweep.
    #[error(
        "{} holds the shards of another sweep ({other}); use --out for another folder, or \
         --force once no shard of that sweep is running",
        folder.display()
    )]
    OtherSweep {
        /// The folder.
        folder: PathBuf,
        /// The other sweep, as its `.eom-sweep` names it.
        other: String,
    },
    /// A system folder, refused even with `--force`.
    #[error(
        "{} resolves to {}, a system folder: eom does not write there, even with --force",
        given.display(),
        resolved.display()
    )]
    SystemFolder {
        /// The path as given.
        given: PathBuf,
        /// The path with its links followed.
        resolved: PathBuf,
    },
    /// The folder cannot be made or written into: a path under a file, a read-only folder.
    #[error("the output folder {} cannot be written: {cause}", path.display())]
    Unwritable {
        /// The folder, or the file in it that failed.
        path: PathBuf,
        /// What the system said.
        cause: std::io::Error,
    },
}

impl FolderError {
    fn unwritable(path: &Path, cause: std::io::Error) -> Self {
        Self::Unwritable {
            path: path.to_owned(),
            cause,
        }
    }
}

/// Who writes into a folder: a whole run, or one shard of a sweep.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Writer {
    /// An unsharded run or sweep: the folder is its alone.
    Whole,
    /// Shard `index` of `count` of the sweep whose scene text hashes to `sweep`.
    Shard {
        /// K.
        index: usize,
        /// N.
        count: usize,
        /// Names the sweep: the scene and a hash of its text ([`sweep_identity`]).
        sweep: String,
    },
}

impl Writer {
    fn manifest(&self) -> String {
        match self {
            Writer::Whole => MANIFEST.into(),
            Writer::Shard { index, count, .. } => format!("{MANIFEST}-shard-{index}-of-{count}"),
        }
    }

    fn own_lock(&self) -> Option<String> {
        match self {
            Writer::Whole => None,
            Writer::Shard { index, count, .. } => Some(format!("{LOCK}-shard-{index}-of-{count}")),
        }
    }
}

/// What names a sweep across the machines that run its shards: the scene's file name (not
/// its path, which may be written differently on each machine), the number of shards and a
/// hash (FNV-1a, 64 bits: the same on every machine and build) of its text.
pub fn sweep_identity(name: &str, text: &str, count: usize) -> String {
    let name = Path::new(name)
        .file_name()
        .map_or_else(|| name.to_owned(), |n| n.to_string_lossy().into_owned());
    let hash = text.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    });
    format!("{name}, {count} shards, text {hash:016x}")
}

/// An output folder taken for one run: the lock is held until this is dropped.
#[derive(Debug)]
pub struct Claim {
    folder: PathBuf,
    /// The lock files held; the operating system releases them when the process ends.
    _locks: Vec<File>,
}

impl Claim {
    /// Takes `folder` for a run (see the module's documentation), refusing it when another run
    /// holds it, when it holds an earlier run (without `force`), when it is not eom's and not
    /// empty (without `force`), when `planned` names a file eom did not write, and always when
    /// it is a system folder. `planned` is every top-level entry the run may write (the
    /// entries of an earlier run are removed only after every refusal has been decided).
    pub fn take(
        folder: &Path,
        force: bool,
        writer: &Writer,
        planned: &[String],
    ) -> Result<Claim, FolderError> {
        refuse_system_folder(folder)?;
        if folder.is_file() {
            let cause = std::io::Error::other("it is a file, not a folder");
            return Err(FolderError::unwritable(folder, cause));
        }
        if !force && !is_empty_or_eoms(folder)? {
            return Err(FolderError::NotEoms(folder.to_owned()));
        }
        // Read before anything is written, so that a refusal leaves the folder as it was. A
        // run claiming the folder at this moment may have begun its files while its manifest
        // was still being renamed into place: where the folder bears eom's marks, the lock
        // below (busy while the other holds it) and the reading under it decide instead.
        let before = refuse_others_files(folder, planned, &earlier_entries(folder, writer));
        if let Err(error) = before
            && !bears_eoms_marks(folder)
        {
            return Err(error);
        }
        std::fs::create_dir_all(folder).map_err(|e| FolderError::unwritable(folder, e))?;
        let (locks, setup) = match writer {
            Writer::Whole => (vec![lock_whole(folder)?], None),
            Writer::Shard { .. } => lock_shard(folder, writer, force)?,
        };
        // Read again under the lock: what is removed is what eom wrote, as of now.
        let earlier = earlier_entries(folder, writer);
        refuse_others_files(folder, planned, &earlier)?;
        let present: Vec<&String> = earlier
            .iter()
            .filter(|e| folder.join(e).symlink_metadata().is_ok())
            .collect();
        if !present.is_empty() && !force {
            return Err(FolderError::HoldsARun(folder.to_owned()));
        }
        for entry in present {
            remove_entry(&folder.join(entry))?;
        }
        start_manifest(folder, writer, planned)?;
        drop(setup);
        Ok(Claim {
            folder: folder.to_owned(),
            _locks: locks,
        })
    }

    /// Takes a folder eom wrote, exclusively, to add `names` to it beside what is there (the
    /// merged table of a sweep's shards, and its plot): refused while any run holds the
    /// folder, and when one of `names` exists and eom did not write it.
    pub fn add_to(folder: &Path, names: &[String]) -> Result<Claim, FolderError> {
        refuse_system_folder(folder)?;
        if !folder.is_dir() || !is_empty_or_eoms(folder)? {
            return Err(FolderError::NotEoms(folder.to_owned()));
        }
        let lock = lock_whole(folder)?;
        let earlier = earlier_entries(folder, &Writer::Whole);
        refuse_others_files(folder, names, &earlier)?;
        let path = folder.join(MANIFEST);
        let mut manifest = OpenOptions::new()
            .create(true)
            .append(true)
            .open(&path)
            .map_err(|e| FolderError::unwritable(folder, e))?;
        for name in names {
            writeln!(manifest, "{name}").map_err(|e| FolderError::unwritable(folder, e))?;
        }
        Ok(Claim {
            folder: folder.to_owned(),
            _locks: vec![lock],
        })
    }

    /// The folder.
    pub fn folder(&self) -> &Path {
        &self.folder
    }
}

/// Refuses a planned entry that exists and that no manifest lists.
fn refuse_others_files(
    folder: &Path,
    planned: &[String],
    earlier: &[String],
) -> Result<(), FolderError> {
    match planned
        .iter()
        .filter(|p| !earlier.contains(p))
        .map(|p| folder.join(p))
        .find(|p| p.symlink_metadata().is_ok())
    {
        Some(clash) => Err(FolderError::NotEomsFile(clash)),
        None => Ok(()),
    }
}

/// Whether `folder` is missing, empty, or holds a manifest or lock of eom's (a run that has
/// just taken its lock has not yet written its manifest).
fn is_empty_or_eoms(folder: &Path) -> Result<bool, FolderError> {
    let mut entries = match std::fs::read_dir(folder) {
        Ok(entries) => entries,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(true),
        Err(e) => return Err(FolderError::unwritable(folder, e)),
    };
    let mut empty = true;
    for entry in entries.by_ref().flatten() {
        empty = false;
        let name = entry.file_name().to_string_lossy().into_owned();
        if name.starts_with(MANIFEST) || name.starts_with(LOCK) {
            return Ok(true);
        }
    }
    Ok(empty)
}

/// Whether the folder holds a lock or a manifest of eom's (of a run, or of a shard).
fn bears_eoms_marks(folder: &Path) -> bool {
    std::fs::read_dir(folder).is_ok_and(|entries| {
        entries.flatten().any(|entry| {
            let name = entry.file_name().to_string_lossy().into_owned();
            name.starts_with(MANIFEST) || name.starts_with(LOCK)
        })
    })
}

/// Opens (creating it) a lock file of the folder.
fn open_lock(folder: &Path, name: &str) -> Result<File, FolderError> {
    let path = folder.join(name);
    OpenOptions::new()
        .read(true)
        .write(true)
        .create(true)
        .truncate(false)
        .open(&path)
        .map_err(|e| FolderError::unwritable(folder, e))
}

/// Writes this process's number into a lock file it holds, for a refused run to name.
fn sign(lock: &mut File, folder: &Path) -> Result<(), FolderError> {
    lock.set_len(0)
        .and_then(|()| write!(lock, "process {}", std::process::id()))
        .map_err(|e| FolderError::unwritable(folder, e))
}

/// The processes named by the folder's lock files, for the message of a refused run. A run
/// signs its lock just after taking it, so an unsigned lock is read again for a moment.
fn holders(folder: &Path) -> String {
    for _ in 0..50 {
        if let Some(names) = signed_holders(folder) {
            return names;
        }
        std::thread::sleep(std::time::Duration::from_millis(10));
    }
    "a process that has not signed its lock".into()
}

/// The signatures of the folder's lock files, if any is signed.
fn signed_holders(folder: &Path) -> Option<String> {
    let mut names: Vec<String> = names_starting_with(folder, LOCK)
        .filter_map(|name| {
            let mut text = String::new();
            File::open(folder.join(name))
                .ok()?
                .read_to_string(&mut text)
                .ok()?;
            (!text.is_empty()).then_some(text)
        })
        .collect();
    names.sort();
    names.dedup();
    (!names.is_empty()).then(|| names.join(", "))
}

/// Whether a lock could not be taken because someone holds it.
fn would_block(result: Result<(), TryLockError>, folder: &Path) -> Result<bool, FolderError> {
    match result {
        Ok(()) => Ok(false),
        Err(TryLockError::WouldBlock) => Ok(true),
        Err(TryLockError::Error(e)) => Err(FolderError::unwritable(folder, e)),
    }
}

fn busy(folder: &Path) -> FolderError {
    FolderError::Busy {
        folder: folder.to_owned(),
        holder: holders(folder),
    }
}

/// The exclusive lock of an unsharded run.
fn lock_whole(folder: &Path) -> Result<File, FolderError> {
    let mut lock = open_lock(folder, LOCK)?;
    if would_block(lock.try_lock(), folder)? {
        return Err(busy(folder));
    }
    sign(&mut lock, folder)?;
    Ok(lock)
}

/// A shard's locks: the folder's lock shared, its own exclusively; the folder must hold no
/// other sweep's shards (with `force`, those of a sweep no longer running are replaced).
/// The second value returned is the setup lock, held until the shard's manifest is started.
fn lock_shard(
    folder: &Path,
    writer: &Writer,
    force: bool,
) -> Result<(Vec<File>, Option<File>), FolderError> {
    let Writer::Shard { sweep, .. } = writer else {
        unreachable!("lock_shard is called for shards")
    };
    let shared = open_lock(folder, LOCK)?;
    if would_block(shared.try_lock_shared(), folder)? {
        return Err(busy(folder));
    }
    let setup = open_lock(folder, SETUP)?;
    setup
        .lock()
        .map_err(|e| FolderError::unwritable(folder, e))?;
    let own_name = writer.own_lock().unwrap_or_default();
    let mut own = open_lock(folder, &own_name)?;
    if would_block(own.try_lock(), folder)? {
        return Err(busy(folder));
    }
    let recorded = std::fs::read_to_string(folder.join(SWEEP)).ok();
    if let Some(other) = recorded.filter(|r| r != sweep) {
        if !force || other_shards_running(folder, &own_name)? {
            return Err(FolderError::OtherSweep {
                folder: folder.to_owned(),
                other,
            });
        }
        remove_other_shards(folder)?;
    }
    std::fs::write(folder.join(SWEEP), sweep).map_err(|e| FolderError::unwritable(folder, e))?;
    sign(&mut own, folder)?;
    Ok((vec![shared, own], Some(setup)))
}

/// The folder's shard lock files other than `own`.
fn shard_locks(folder: &Path, own: &str) -> Vec<PathBuf> {
    names_starting_with(folder, &format!("{LOCK}-shard-"))
        .filter(|name| name != own)
        .map(|name| folder.join(name))
        .collect()
}

/// Whether any other shard holds its lock.
fn other_shards_running(folder: &Path, own: &str) -> Result<bool, FolderError> {
    for path in shard_locks(folder, own) {
        let file = File::open(&path).map_err(|e| FolderError::unwritable(folder, e))?;
        if would_block(file.try_lock(), folder)? {
            return Ok(true);
        }
    }
    Ok(false)
}

/// Removes the entries of every shard manifest (another sweep's, no longer running).
fn remove_other_shards(folder: &Path) -> Result<(), FolderError> {
    for manifest in manifests(folder).filter(|m| m != MANIFEST) {
        for entry in read_manifest(&folder.join(&manifest)) {
            remove_entry(&folder.join(entry))?;
        }
        remove_entry(&folder.join(manifest))?;
    }
    Ok(())
}

/// The names of the folder's manifests.
fn manifests(folder: &Path) -> impl Iterator<Item = String> {
    names_starting_with(folder, MANIFEST)
}

/// The names of the folder's entries that start with `prefix` (none if it cannot be read).
fn names_starting_with(folder: &Path, prefix: &str) -> impl Iterator<Item = String> {
    let prefix = prefix.to_owned();
    std::fs::read_dir(folder)
        .into_iter()
        .flatten()
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(move |name| name.starts_with(&prefix))
}

/// The entries a manifest lists; only plain names at the folder's top level are believed.
fn read_manifest(path: &Path) -> Vec<String> {
    std::fs::read_to_string(path)
        .unwrap_or_default()
        .lines()
        .filter(|line| is_plain_name(line))
        .map(str::to_owned)
        .collect()
}

/// A single normal path component: no `..`, no `/`, nothing absolute.
fn is_plain_name(name: &str) -> bool {
    let mut components = Path::new(name).components();
    matches!(components.next(), Some(Component::Normal(_))) && components.next().is_none()
}

/// The entries eom wrote before, that this writer may replace: an unsharded run, every
/// manifest's; a shard, its own and an unsharded run's (shards of the same sweep write
/// disjoint entries and leave each other's alone).
fn earlier_entries(folder: &Path, writer: &Writer) -> Vec<String> {
    let own = writer.manifest();
    let mut entries: Vec<String> = manifests(folder)
        .filter(|m| *writer == Writer::Whole || *m == own || m == MANIFEST)
        .flat_map(|m| read_manifest(&folder.join(m)))
        .collect();
    entries.sort();
    entries.dedup();
    entries
}

/// Writes this writer's manifest afresh, listing what the run will write before it writes
/// it; an unsharded run also removes the shards' manifests, whose entries it has removed.
fn start_manifest(folder: &Path, writer: &Writer, planned: &[String]) -> Result<(), FolderError> {
    if *writer == Writer::Whole {
        for manifest in manifests(folder).filter(|m| m != MANIFEST) {
            remove_entry(&folder.join(manifest))?;
        }
        let _ = std::fs::remove_file(folder.join(SWEEP));
    }
    let lines: String = planned.iter().map(|name| format!("{name}\n")).collect();
    // Whole or not at all: a run starting beside this one reads it before it takes the lock.
    // The temporary name does not start with the manifest's, so it is never read as one.
    let name = writer.manifest();
    let partial = folder.join(format!(".partial{name}"));
    std::fs::write(&partial, lines)
        .and_then(|()| std::fs::rename(&partial, folder.join(&name)))
        .map_err(|e| FolderError::unwritable(folder, e))
}

/// Removes a file, a link (not what it points to) or a folder eom wrote.
fn remove_entry(path: &Path) -> Result<(), FolderError> {
    let removed = match path.symlink_metadata() {
        Err(_) => return Ok(()),
        Ok(meta) if meta.is_dir() => std::fs::remove_dir_all(path),
        Ok(_) => std::fs::remove_file(path),
    };
    match removed {
        Err(e) if e.kind() != std::io::ErrorKind::NotFound => Err(FolderError::unwritable(path, e)),
        _ => Ok(()),
    }
}

/// The folders no run writes into directly: the root, the home folder, and the system's own.
#[cfg(unix)]
const SYSTEM_FOLDERS: &[&str] = &[
    "/bin", "/boot", "/dev", "/etc", "/lib", "/lib32", "/lib64", "/libx32", "/proc", "/sbin",
    "/sys", "/usr",
];
/// System folders refused themselves, though a run may write into folders under them.
#[cfg(unix)]
const SYSTEM_ROOTS: &[&str] = &[
    "/", "/home", "/media", "/mnt", "/opt", "/root", "/run", "/srv", "/tmp", "/var", "/var/tmp",
];

/// Refuses a folder that resolves to a system folder or lies under one.
fn refuse_system_folder(folder: &Path) -> Result<(), FolderError> {
    let resolved = resolve(folder);
    let home = std::env::var_os("HOME").map(PathBuf::from);
    let is_system = resolved.parent().is_none() || home.as_deref() == Some(resolved.as_path());
    #[cfg(unix)]
    let is_system = is_system
        || SYSTEM_ROOTS.iter().any(|root| resolved == Path::new(root))
        || SYSTEM_FOLDERS
            .iter()
            .any(|system| resolved.starts_with(system));
    match is_system {
        true => Err(FolderError::SystemFolder {
            given: folder.to_owned(),
            resolved,
        }),
        false => Ok(()),
    }
}

/// The absolute path with every link followed: the longest part that exists is canonicalised
/// and the rest (which does not exist yet) appended with `.` and `..` taken lexically.
fn resolve(folder: &Path) -> PathBuf {
    let absolute = std::env::current_dir()
        .map(|here| here.join(folder))
        .unwrap_or_else(|_| folder.to_owned());
    let mut existing = absolute.as_path();
    let mut rest = Vec::new();
    loop {
        if let Ok(resolved) = existing.canonicalize() {
            return rest
                .iter()
                .rev()
                .fold(resolved, |mut path, part: &Component| {
                    match part {
                        Component::ParentDir => {
                            path.pop();
                        }
                        Component::Normal(name) => path.push(name),
                        _ => {}
                    }
                    path
                });
        }
        match (existing.parent(), existing.components().next_back()) {
            (Some(parent), Some(last)) => {
                rest.push(last);
                existing = parent;
            }
            _ => return absolute,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("eom-folder-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    fn planned() -> Vec<String> {
        vec!["trajectory.csv".into(), "summary.json".into()]
    }

    #[test]
    fn a_second_whole_run_is_refused_naming_the_first_process() {
        let dir = scratch("busy");
        let _first = Claim::take(&dir, false, &Writer::Whole, &planned()).unwrap();
        let second = Claim::take(&dir, true, &Writer::Whole, &planned()).unwrap_err();
        let message = second.to_string();
        assert!(matches!(second, FolderError::Busy { .. }), "{message}");
        assert!(
            message.contains(&format!("process {}", std::process::id())),
            "{message}"
        );
    }

    #[test]
    fn the_lock_is_released_when_the_claim_is_dropped() {
        let dir = scratch("released");
        drop(Claim::take(&dir, false, &Writer::Whole, &planned()).unwrap());
        Claim::take(&dir, false, &Writer::Whole, &planned()).unwrap();
    }

    #[test]
    fn an_earlier_run_is_kept_without_force_and_replaced_whole_with_it() {
        let dir = scratch("earlier");
        let earlier = vec!["trajectory.csv".to_owned(), "case-0003".to_owned()];
        let claim = Claim::take(&dir, false, &Writer::Whole, &earlier).unwrap();
        std::fs::write(dir.join("trajectory.csv"), "t\n").unwrap();
        std::fs::create_dir(dir.join("case-0003")).unwrap();
        drop(claim);
        let refused = Claim::take(&dir, false, &Writer::Whole, &planned()).unwrap_err();
        assert!(matches!(refused, FolderError::HoldsARun(_)), "{refused}");
        std::fs::write(dir.join("notes.txt"), "mine").unwrap();
        let _claim = Claim::take(&dir, true, &Writer::Whole, &planned()).unwrap();
        assert!(!dir.join("trajectory.csv").exists() && !dir.join("case-0003").exists());
        assert_eq!(
            std::fs::read_to_string(dir.join("notes.txt")).unwrap(),
            "mine"
        );
    }

    #[test]
    fn a_users_folder_is_refused_and_force_does_not_replace_their_files() {
        let dir = scratch("users");
        std::fs::write(dir.join("state.svg"), "<svg/>").unwrap();
        let refused = Claim::take(&dir, false, &Writer::Whole, &planned()).unwrap_err();
        assert!(matches!(refused, FolderError::NotEoms(_)), "{refused}");
        let with_plot = vec!["state.svg".to_owned()];
        let refused = Claim::take(&dir, true, &Writer::Whole, &with_plot).unwrap_err();
        assert!(matches!(refused, FolderError::NotEomsFile(_)), "{refused}");
        // Nothing was written by either refusal.
        let names: Vec<_> = std::fs::read_dir(&dir).unwrap().flatten().collect();
        assert_eq!(names.len(), 1);
        assert_eq!(
            std::fs::read_to_string(dir.join("state.svg")).unwrap(),
            "<svg/>"
        );
    }

    #[test]
    fn shards_of_one_sweep_share_the_folder_and_another_sweep_is_refused() {
        let dir = scratch("shards");
        let shard = |index, sweep: &str| Writer::Shard {
            index,
            count: 2,
            sweep: sweep.into(),
        };
        let first = Claim::take(&dir, false, &shard(0, "a"), &[]).unwrap();
        let second = Claim::take(&dir, false, &shard(1, "a"), &[]).unwrap();
        let again = Claim::take(&dir, false, &shard(1, "a"), &[]).unwrap_err();
        assert!(matches!(again, FolderError::Busy { .. }), "{again}");
        let whole = Claim::take(&dir, true, &Writer::Whole, &[]).unwrap_err();
        assert!(matches!(whole, FolderError::Busy { .. }), "{whole}");
        drop(second);
        let other = Claim::take(&dir, true, &shard(1, "b"), &[]).unwrap_err();
        assert!(matches!(other, FolderError::OtherSweep { .. }), "{other}");
        drop(first);
        Claim::take(&dir, true, &shard(1, "b"), &[]).unwrap();
    }

    #[test]
    fn a_sweep_is_named_by_its_file_and_text_not_the_path_it_was_given_by() {
        let text = "title = \"t\"";
        let here = sweep_identity("scenes/s.toml", text, 4);
        assert_eq!(here, sweep_identity("/home/u/eom/./scenes/s.toml", text, 4));
        assert_ne!(here, sweep_identity("scenes/s.toml", "title = \"u\"", 4));
        assert_ne!(here, sweep_identity("scenes/s.toml", text, 5));
    }

    #[test]
    fn system_folders_are_refused_through_links() {
        for path in ["/", "/usr", "/usr/share/eom", "/etc/x", "/tmp"] {
            let refused = refuse_system_folder(Path::new(path)).unwrap_err();
            assert!(
                matches!(refused, FolderError::SystemFolder { .. }),
                "{path}"
            );
        }
        refuse_system_folder(Path::new("/tmp/eom-run")).unwrap();
        #[cfg(unix)]
        {
            let dir = scratch("link");
            let link = dir.join("root");
            std::os::unix::fs::symlink("/", &link).unwrap();
            for path in [link.clone(), link.join("usr/..")] {
                let refused = refuse_system_folder(&path).unwrap_err();
                assert!(refused.to_string().contains("resolves to /,"), "{refused}");
            }
        }
    }

    #[test]
    fn a_manifest_names_only_entries_of_the_folder_itself() {
        assert!(is_plain_name("case-0001"));
        for bad in ["", "..", "/etc", "a/b", "."] {
            assert!(!is_plain_name(bad), "{bad}");
        }
    }
}
