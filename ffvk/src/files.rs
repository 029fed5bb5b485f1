//! Writing files so that a failure never damages one: every output is written to a temporary
//! file in the destination's folder, flushed and synced, then renamed over the destination.
//! An error or an interruption leaves the old file (or none) and a stray temporary file at
//! worst, never a partial or empty destination; every error, the final flush's included,
//! reaches the caller.
//!
//! A program can also ask that nothing it writes land on a file it read ([`protect_inputs`]):
//! from then on every file read through [`read_regular`] (or named to [`note_input`]) is an
//! input, known by its identity (device and inode) rather than its name, and
//! [`write_atomically`] refuses a destination that is one, however it is spelled (`./x`,
//! `a/../x`, a symbolic or hard link). The `ffvk` command turns this on; a library caller
//! that does not is not affected.

use std::fs::{self, File, OpenOptions};
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// Temporary files of this process get distinct names.
static NEXT_TEMPORARY: AtomicU64 = AtomicU64::new(0);

/// The files this process has read, once [`protect_inputs`] turned the guard on: each file's
/// identity and the path it was read by.
static INPUTS: std::sync::Mutex<Option<Vec<(FileId, PathBuf)>>> = std::sync::Mutex::new(None);

/// A file's identity: its device and inode (unchanged by links and by spelling).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct FileId {
    device: u64,
    inode: u64,
}

impl FileId {
    /// The identity of what `path` names after symbolic links, when it exists.
    fn of(path: &Path) -> Option<FileId> {
        fs::metadata(path).ok().map(|m| FileId::from_metadata(&m))
    }

    #[cfg(unix)]
    fn from_metadata(meta: &fs::Metadata) -> FileId {
        use std::os::unix::fs::MetadataExt;
        FileId {
            device: meta.dev(),
            inode: meta.ino(),
        }
    }

    #[cfg(not(unix))]
    fn from_metadata(_: &fs::Metadata) -> FileId {
        // Without inodes the canonical path stands in (see `input_named`).
        FileId { device: 0, inode: 0 }
    }
}

/// The temporary files being written now, for the signal handler of
/// [`remove_temporaries_on_signals`]: each slot null or a path (NUL-terminated) that is never
/// freed, so that the handler can read it at any moment.
static TEMPORARIES: [std::sync::atomic::AtomicPtr<std::ffi::c_char>; 64] =
    [const { std::sync::atomic::AtomicPtr::new(std::ptr::null_mut()) }; 64];

/// Whether [`remove_temporaries_on_signals`] installed its handler.
static SIGNALS_HANDLED: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// A temporary file's place in [`TEMPORARIES`] while it is written: cleared on drop.
struct Temporary(Option<usize>);

impl Temporary {
    #[cfg(not(unix))]
    fn record(_: &Path) -> Temporary {
        Temporary(None)
    }

    /// Records `path` for the handler, when one is installed and a slot is free.
    #[cfg(unix)]
    fn record(path: &Path) -> Temporary {
        if !SIGNALS_HANDLED.load(Ordering::Acquire) {
            return Temporary(None);
        }
        use std::os::unix::ffi::OsStrExt;
        let Ok(c) = std::ffi::CString::new(path.as_os_str().as_bytes()) else {
            return Temporary(None);
        };
        let raw = c.into_raw();
        for (i, slot) in TEMPORARIES.iter().enumerate() {
            if slot
                .compare_exchange(std::ptr::null_mut(), raw, Ordering::AcqRel, Ordering::Relaxed)
                .is_ok()
            {
                return Temporary(Some(i));
            }
        }
        // Every slot busy: this one is simply not removed by a signal. The string is freed.
        // SAFETY: `raw` came from `CString::into_raw` just above and was published nowhere.
        drop(unsafe { std::ffi::CString::from_raw(raw) });
        Temporary(None)
    }
}

impl Drop for Temporary {
    fn drop(&mut self) {
        if let Some(i) = self.0 {
            // The path stays allocated (leaked): a handler running now on another thread may
            // still be reading it.
            TEMPORARIES[i].store(std::ptr::null_mut(), Ordering::Release);
        }
    }
}

/// Removes the temporary files being written when SIGINT, SIGTERM or SIGHUP arrives, then
/// lets the signal end the process as it would have. For programs (the `ffvk` command); a
/// library caller keeps its own signal handling unless it calls this. Each temporary path is
/// kept for the process's life once written (a few hundred bytes per file written).
#[cfg(unix)]
pub fn remove_temporaries_on_signals() {
    extern "C" fn handler(signal: libc::c_int) {
        for slot in &TEMPORARIES {
            let path = slot.load(Ordering::Acquire);
            if !path.is_null() {
                // SAFETY: a non-null slot holds a NUL-terminated path that is never freed;
                // unlink is async-signal-safe.
                unsafe { libc::unlink(path) };
            }
        }
        // SAFETY: restoring the default action and raising the signal again are
        // async-signal-safe; the process then ends as the signal asks.
        unsafe {
            libc::signal(signal, libc::SIG_DFL);
            libc::raise(signal);
        }
    }
    if SIGNALS_HANDLED.swap(true, Ordering::AcqRel) {
        return;
    }
    for signal in [libc::SIGINT, libc::SIGTERM, libc::SIGHUP] {
        // SAFETY: installs a handler that only does async-signal-safe work (above).
        unsafe {
            libc::signal(
                signal,
                handler as extern "C" fn(libc::c_int) as libc::sighandler_t,
            )
        };
    }
}

/// Whether each write sweeps the stale temporary files of its destination
/// ([`sweep_on_write`]).
static SWEEP_ON_WRITE: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// Turns on (or off) the sweep of stale temporary files by each write of the same file. Only a
/// process that knows every input of its run may turn it on (the sweep spares the inputs it
/// knows, [`note_input`]); a worker that knows only its own scenes' leaves it to the process
/// that knows them all ([`sweep_stale_temporaries`]).
pub fn sweep_on_write(on: bool) {
    SWEEP_ON_WRITE.store(on, Ordering::Release);
}

/// Removes the temporary files of `names` in `dir` that earlier processes left when they died
/// mid-write (their process no longer runs), except inputs of this run ([`note_input`]).
/// Errors are ignored: a sweep is a courtesy.
pub fn sweep_stale_temporaries(dir: &Path, names: &[&str]) {
    let Ok(entries) = fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let file = entry.file_name();
        // `.NAME.PID-N.tmp`, NAME one of `names`.
        let Some((name, rest)) = file
            .to_str()
            .and_then(|f| f.strip_prefix('.')?.strip_suffix(".tmp")?.rsplit_once('.'))
        else {
            continue;
        };
        if !names.contains(&name) {
            continue;
        }
        let Some((pid, count)) = rest.split_once('-') else {
            continue;
        };
        let (Ok(pid), Ok(_)) = (pid.parse::<u32>(), count.parse::<u64>()) else {
            continue;
        };
        // Never a file this run reads, whatever its name.
        if pid != std::process::id() && !process_runs(pid) && input_named(&entry.path()).is_none() {
            let _ = fs::remove_file(entry.path());
        }
    }
}

/// Whether a process `pid` runs now (or may: when unsure, yes).
fn process_runs(pid: u32) -> bool {
    #[cfg(target_os = "linux")]
    {
        Path::new("/proc").join(pid.to_string()).exists() || !Path::new("/proc/self").exists()
    }
    #[cfg(not(target_os = "linux"))]
    {
        let _ = pid;
        true
    }
}

/// Turns on (or off) the guard that keeps this process's outputs off its inputs: while on,
/// every file read through [`read_regular`] or named to [`note_input`] is remembered, and
/// [`write_atomically`] refuses to write onto one. Off by default.
pub fn protect_inputs(on: bool) {
    let mut inputs = INPUTS.lock().unwrap_or_else(|e| e.into_inner());
    match (on, inputs.is_some()) {
        (true, false) => *inputs = Some(Vec::new()),
        (false, _) => *inputs = None,
        _ => {}
    }
}

/// Remembers `path` as an input of this process when the guard is on ([`protect_inputs`]):
/// for files read other than through [`read_regular`], or named before they are read.
pub fn note_input(path: &Path) {
    let mut inputs = INPUTS.lock().unwrap_or_else(|e| e.into_inner());
    let Some(list) = inputs.as_mut() else {
        return;
    };
    if let Some(id) = FileId::of(path) {
        let named = fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf());
        if !list.iter().any(|(known, p)| *known == id && *p == named) {
            list.push((id, named));
        }
    }
}

/// The input (as it was read) that `path` names, after links, when the guard is on.
pub fn input_named(path: &Path) -> Option<PathBuf> {
    let inputs = INPUTS.lock().unwrap_or_else(|e| e.into_inner());
    let list = inputs.as_ref()?;
    if cfg!(unix) {
        // A path through a folder not made yet (`new/../x`) names what it will name.
        drop(inputs);
        input_with_id(FileId::of(path).or_else(|| FileId::of(&resolved(path)))?)
    } else {
        let real = fs::canonicalize(path).ok()?;
        list.iter().find(|(_, p)| *p == real).map(|(_, p)| p.clone())
    }
}

/// Why a destination path is refused before anything is written.
fn refuse(path: &Path, problem: &str) -> io::Error {
    io::Error::new(
        io::ErrorKind::InvalidInput,
        format!("{}: {problem}", path.display()),
    )
}

/// An input of this process (as it was read) that lies inside the folder `dir`, after links,
/// when the guard is on: what a command that replaces the folder's contents would delete.
pub fn input_within(dir: &Path) -> Option<PathBuf> {
    let dir = resolved(dir);
    let inputs = INPUTS.lock().unwrap_or_else(|e| e.into_inner());
    inputs
        .as_ref()?
        .iter()
        .find(|(_, p)| p.starts_with(&dir))
        .map(|(_, p)| p.clone())
}

/// Refuses `path` as an output when it names (after links) a file this process read, with
/// the guard on ([`protect_inputs`]): the error names the output and the input.
pub fn refuse_input(path: &Path) -> io::Result<()> {
    match input_named(path) {
        Some(input) => Err(refused_input(path, &input)),
        None => Ok(()),
    }
}

/// The error of an output `path` that names `input`, a file this process read.
fn refused_input(path: &Path, input: &Path) -> io::Error {
    let how = if fs::symlink_metadata(path).is_ok_and(|m| m.file_type().is_symlink()) {
        "is a symbolic link to"
    } else {
        "is"
    };
    refuse(
        path,
        &format!(
            "{how} {}, which this run reads: refused, nothing written; expected an output path that is not one of the run's inputs",
            input.display()
        ),
    )
}

/// Where the bytes for `path` really go: the path itself, or the regular file a symlink
/// points at (so that the link survives). Anything else that exists there (a folder, a
/// device such as /dev/full, a pipe) is refused: it cannot be replaced atomically.
fn destination(path: &Path) -> io::Result<PathBuf> {
    refuse_input(path)?;
    match fs::metadata(path) {
        Ok(meta) if meta.is_file() => fs::canonicalize(path),
        Ok(_) => Err(refuse(
            path,
            "exists and is not a regular file: expected a file or a new path",
        )),
        Err(e) if e.kind() == io::ErrorKind::NotFound => {
            // Only a link counts: a file another writer renamed into place since the
            // metadata call is replaced like any other.
            if fs::symlink_metadata(path).is_ok_and(|m| m.file_type().is_symlink()) {
                return Err(refuse(
                    path,
                    "is a dangling symbolic link: expected a file or a new path",
                ));
            }
            Ok(path.to_path_buf())
        }
        Err(e) => Err(e),
    }
}

/// Writes `path` atomically with `write`, creating its folder when needed. On any error the
/// destination is untouched and the temporary file removed.
pub fn write_atomically(
    path: &Path,
    write: impl FnOnce(&mut BufWriter<File>) -> io::Result<()>,
) -> io::Result<()> {
    let target = destination(path)?;
    let dir = match target.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    // The folders this write makes, deepest first: removed again if it is refused.
    let made: Vec<PathBuf> = dir
        .ancestors()
        .take_while(|d| !d.as_os_str().is_empty() && fs::symlink_metadata(d).is_err())
        .map(Path::to_path_buf)
        .collect();
    let file_name = target
        .file_name()
        .ok_or_else(|| refuse(path, "has no file name: expected a file path"))?;
    fs::create_dir_all(&dir)?;
    // From here on the folder is held open and named by its descriptor, and the destination's
    // identity is checked in the folder the file really lands in: with its folders made, or
    // the folder swapped for a link since the check above, the path may name an input now.
    let folder = Folder::open(&dir)?;
    if let Some(input) = folder.identity(file_name).and_then(input_with_id) {
        for made in &made {
            // Only while empty: nothing of anyone else's is removed.
            let _ = fs::remove_dir(made);
        }
        return Err(refused_input(path, &input));
    }
    let name = file_name.to_string_lossy();
    if SWEEP_ON_WRITE.load(Ordering::Acquire) {
        sweep_stale_temporaries(&dir, &[&name]);
    }
    let temporary_name = format!(
        ".{name}.{}-{}.tmp",
        std::process::id(),
        NEXT_TEMPORARY.fetch_add(1, Ordering::Relaxed)
    );
    let temporary = dir.join(&temporary_name);
    let _recorded = Temporary::record(&temporary);
    let result = (|| {
        let file = folder.create_new(temporary_name.as_ref())?;
        let mut writer = BufWriter::new(file);
        write(&mut writer)?;
        // into_inner flushes; its error is the write error a drop would have lost.
        let file = writer.into_inner().map_err(|e| e.into_error())?;
        file.sync_all()?;
        folder.rename(temporary_name.as_ref(), file_name)
    })();
    if result.is_err() {
        folder.remove(temporary_name.as_ref());
    }
    result?;
    // The rename is durable once the folder is synced; a failure here loses nothing written.
    folder.sync();
    Ok(())
}

/// The input of this process whose identity is `id`, when the guard is on.
fn input_with_id(id: FileId) -> Option<PathBuf> {
    let inputs = INPUTS.lock().unwrap_or_else(|e| e.into_inner());
    inputs
        .as_ref()?
        .iter()
        .find(|(known, _)| *known == id)
        .map(|(_, p)| p.clone())
}

/// A folder held open: files in it are named relative to its descriptor (`openat`,
/// `renameat`, `fstatat`), so that what its path names can change without moving the write.
#[cfg(unix)]
struct Folder(File);

#[cfg(unix)]
impl Folder {
    fn open(dir: &Path) -> io::Result<Folder> {
        use std::os::unix::fs::OpenOptionsExt;
        let file = OpenOptions::new()
            .read(true)
            .custom_flags(libc::O_DIRECTORY)
            .open(dir)?;
        Ok(Folder(file))
    }

    fn fd(&self) -> std::os::fd::RawFd {
        use std::os::fd::AsRawFd;
        self.0.as_raw_fd()
    }

    fn c_name(name: &std::ffi::OsStr) -> io::Result<std::ffi::CString> {
        use std::os::unix::ffi::OsStrExt;
        std::ffi::CString::new(name.as_bytes())
            .map_err(|_| io::Error::new(io::ErrorKind::InvalidInput, "a file name with a NUL byte"))
    }

    /// The identity of what `name` in this folder is (after a link there), if it exists.
    fn identity(&self, name: &std::ffi::OsStr) -> Option<FileId> {
        let c = Folder::c_name(name).ok()?;
        let mut stat = std::mem::MaybeUninit::<libc::stat>::uninit();
        // SAFETY: a live folder descriptor, a NUL-terminated name and a writable stat buffer.
        let r = unsafe { libc::fstatat(self.fd(), c.as_ptr(), stat.as_mut_ptr(), 0) };
        if r != 0 {
            return None;
        }
        // SAFETY: fstatat returned 0, so it filled the buffer.
        let stat = unsafe { stat.assume_init() };
        Some(FileId {
            device: stat.st_dev,
            inode: stat.st_ino,
        })
    }

    /// A new file `name` in this folder, opened for writing; an existing one is an error.
    fn create_new(&self, name: &std::ffi::OsStr) -> io::Result<File> {
        use std::os::fd::FromRawFd;
        let c = Folder::c_name(name)?;
        let flags = libc::O_WRONLY | libc::O_CREAT | libc::O_EXCL | libc::O_CLOEXEC;
        // SAFETY: a live folder descriptor and a NUL-terminated name; the mode is an integer.
        let fd = unsafe { libc::openat(self.fd(), c.as_ptr(), flags, 0o666 as libc::c_uint) };
        if fd < 0 {
            return Err(io::Error::last_os_error());
        }
        // SAFETY: `fd` was just opened and is owned by nothing else.
        Ok(unsafe { File::from_raw_fd(fd) })
    }

    /// Renames `from` over `to`, both in this folder.
    fn rename(&self, from: &std::ffi::OsStr, to: &std::ffi::OsStr) -> io::Result<()> {
        let (from, to) = (Folder::c_name(from)?, Folder::c_name(to)?);
        // SAFETY: a live folder descriptor (both sides) and NUL-terminated names.
        let r = unsafe { libc::renameat(self.fd(), from.as_ptr(), self.fd(), to.as_ptr()) };
        if r != 0 {
            return Err(io::Error::last_os_error());
        }
        Ok(())
    }

    /// Removes `name` from this folder, if it can.
    fn remove(&self, name: &std::ffi::OsStr) {
        if let Ok(c) = Folder::c_name(name) {
            // SAFETY: a live folder descriptor and a NUL-terminated name.
            unsafe { libc::unlinkat(self.fd(), c.as_ptr(), 0) };
        }
    }

    fn sync(&self) {
        let _ = self.0.sync_all();
    }
}

/// Without descriptors for folders: the same steps by path.
#[cfg(not(unix))]
struct Folder(PathBuf);

#[cfg(not(unix))]
impl Folder {
    fn open(dir: &Path) -> io::Result<Folder> {
        Ok(Folder(dir.to_path_buf()))
    }

    fn identity(&self, name: &std::ffi::OsStr) -> Option<FileId> {
        FileId::of(&self.0.join(name))
    }

    fn create_new(&self, name: &std::ffi::OsStr) -> io::Result<File> {
        OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(self.0.join(name))
    }

    fn rename(&self, from: &std::ffi::OsStr, to: &std::ffi::OsStr) -> io::Result<()> {
        fs::rename(self.0.join(from), self.0.join(to))
    }

    fn remove(&self, name: &std::ffi::OsStr) {
        let _ = fs::remove_file(self.0.join(name));
    }

    fn sync(&self) {
        if let Ok(d) = File::open(&self.0) {
            let _ = d.sync_all();
        }
    }
}

/// [`write_atomically`] of a byte slice.
pub fn write_bytes(path: &Path, bytes: &[u8]) -> io::Result<()> {
    write_atomically(path, |w| w.write_all(bytes))
}

/// Reads `path`, which must be a regular file of at most `max` bytes: a device (such as
/// /dev/zero), a pipe (which could block forever) or a folder is refused before it is opened,
/// and so is a larger file, with an error naming the path and the limit.
pub fn read_regular(path: &Path, max: u64) -> io::Result<Vec<u8>> {
    let meta = fs::metadata(path)?;
    if !meta.is_file() {
        return Err(refuse(
            path,
            "is not a regular file: expected a file (not a device, pipe or folder)",
        ));
    }
    if meta.len() > max {
        return Err(refuse(
            path,
            &format!("is {} bytes: expected at most {max} bytes", meta.len()),
        ));
    }
    note_input(path);
    let mut bytes = Vec::new();
    bytes
        .try_reserve_exact(meta.len() as usize)
        .map_err(|_| refuse(path, &format!("cannot allocate {} bytes to read it", meta.len())))?;
    // The file may grow while it is read: never read past the limit.
    use std::io::Read;
    File::open(path)?.take(max + 1).read_to_end(&mut bytes)?;
    if bytes.len() as u64 > max {
        return Err(refuse(path, &format!("grew past {max} bytes while being read")));
    }
    Ok(bytes)
}

/// Whether two paths name the same existing file (after symbolic links).
pub fn same_file(a: &Path, b: &Path) -> bool {
    match (fs::canonicalize(a), fs::canonicalize(b)) {
        (Ok(a), Ok(b)) => a == b,
        _ => false,
    }
}

/// `path` made absolute with symbolic links resolved as far as it exists, so that a folder
/// that does not exist yet can still be compared with one that does.
pub fn resolved(path: &Path) -> PathBuf {
    use std::path::Component;
    let absolute = if path.is_absolute() {
        path.to_path_buf()
    } else {
        std::env::current_dir().unwrap_or_default().join(path)
    };
    // Component by component: `out` is an existing folder with every link resolved, then
    // `missing` names that do not exist (so cannot be links). `..` drops a missing name, or
    // goes to the real parent; once every missing name is dropped (`new/../link/x`), links
    // are resolved again.
    let mut out = PathBuf::new();
    let mut missing = 0usize;
    for component in absolute.components() {
        match component {
            Component::Prefix(_) | Component::RootDir => out.push(component),
            Component::CurDir => {}
            Component::ParentDir => {
                out.pop();
                missing = missing.saturating_sub(1);
            }
            Component::Normal(name) => {
                out.push(name);
                if missing == 0 {
                    match fs::canonicalize(&out) {
                        Ok(real) => out = real,
                        Err(_) => missing = 1,
                    }
                } else {
                    missing += 1;
                }
            }
        }
    }
    out
}

/// Whether `inner` is `outer` or lies inside it (after symbolic links).
pub fn is_within(inner: &Path, outer: &Path) -> bool {
    resolved(inner).starts_with(resolved(outer))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(test: &str) -> PathBuf {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../target/ffvk-test-files")
            .join(test);
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        dir
    }

    fn leftovers(dir: &Path) -> Vec<String> {
        fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .filter(|n| n.ends_with(".tmp"))
            .collect()
    }

    #[test]
    fn a_failed_write_leaves_the_old_file_and_no_temporary() {
        let dir = scratch("failed");
        let path = dir.join("a.png");
        fs::write(&path, b"old contents").unwrap();
        let e = write_atomically(&path, |w| {
            w.write_all(&[7; 100_000])?;
            Err(io::Error::new(
                io::ErrorKind::StorageFull,
                "no space left (injected)",
            ))
        })
        .unwrap_err();
        assert_eq!(e.kind(), io::ErrorKind::StorageFull);
        assert_eq!(fs::read(&path).unwrap(), b"old contents");
        assert!(leftovers(&dir).is_empty(), "{:?}", leftovers(&dir));
    }

    #[test]
    fn a_successful_write_replaces_the_file_whole() {
        let dir = scratch("replaced");
        let path = dir.join("nested/b.bin");
        write_bytes(&path, &[1; 10]).unwrap();
        write_bytes(&path, &[2; 5]).unwrap();
        assert_eq!(fs::read(&path).unwrap(), [2; 5]);
        assert!(leftovers(&dir.join("nested")).is_empty());
    }

    #[test]
    fn devices_folders_and_dangling_links_are_refused_untouched() {
        let dir = scratch("refused");
        let e = write_bytes(&dir, b"x").unwrap_err();
        assert!(e.to_string().contains("not a regular file"), "{e}");
        #[cfg(unix)]
        {
            let full = dir.join("full.png");
            std::os::unix::fs::symlink("/dev/full", &full).unwrap();
            let e = write_bytes(&full, b"x").unwrap_err();
            assert!(e.to_string().contains("not a regular file"), "{e}");
            assert!(fs::symlink_metadata(&full).unwrap().file_type().is_symlink());
            let dangling = dir.join("dangling.png");
            std::os::unix::fs::symlink(dir.join("nowhere/x.png"), &dangling).unwrap();
            assert!(write_bytes(&dangling, b"x").is_err());
        }
    }

    #[test]
    fn a_link_to_a_file_is_kept_and_its_target_replaced() {
        let dir = scratch("link");
        let target = dir.join("target.png");
        fs::write(&target, b"old").unwrap();
        #[cfg(unix)]
        {
            let link = dir.join("link.png");
            std::os::unix::fs::symlink(&target, &link).unwrap();
            write_bytes(&link, b"new").unwrap();
            assert!(fs::symlink_metadata(&link).unwrap().file_type().is_symlink());
            assert_eq!(fs::read(&target).unwrap(), b"new");
        }
    }

    #[test]
    fn concurrent_writers_leave_one_whole_file() {
        let dir = scratch("concurrent");
        let path = dir.join("c.bin");
        let writers: Vec<_> = (0..8u8)
            .map(|k| {
                let path = path.clone();
                std::thread::spawn(move || write_bytes(&path, &vec![k; 1 << 20 >> (k % 3)]).unwrap())
            })
            .collect();
        for w in writers {
            w.join().unwrap();
        }
        let bytes = fs::read(&path).unwrap();
        let k = bytes[0];
        assert_eq!(bytes.len(), 1 << 20 >> (k % 3), "one writer's length");
        assert!(bytes.iter().all(|&b| b == k), "one writer's bytes only");
        assert!(leftovers(&dir).is_empty());
    }

    #[test]
    fn folders_inside_folders() {
        let dir = scratch("within");
        assert!(is_within(&dir.join("refs/new/sub"), &dir.join("refs")));
        assert!(is_within(&dir.join("refs"), &dir.join("refs/.")));
        assert!(!is_within(&dir.join("refs2"), &dir.join("refs")));
    }

    #[test]
    fn a_path_through_folders_not_made_yet_resolves_to_what_it_will_name() {
        let dir = scratch("not-yet");
        fs::write(dir.join("x"), b"x").unwrap();
        let x = fs::canonicalize(dir.join("x")).unwrap();
        assert_eq!(resolved(&dir.join("new/../x")), x);
        assert_eq!(resolved(&dir.join("new/a/./../../x")), x);
        assert_eq!(
            resolved(&dir.join("new/y")),
            fs::canonicalize(&dir).unwrap().join("new/y")
        );
        // Back out of the missing folder, links count again: `new/../link/..` is the
        // link's target's parent, not `dir`.
        #[cfg(unix)]
        {
            fs::create_dir_all(dir.join("far/sub")).unwrap();
            std::os::unix::fs::symlink(dir.join("far/sub"), dir.join("link")).unwrap();
            let far = fs::canonicalize(dir.join("far")).unwrap();
            assert_eq!(resolved(&dir.join("new/../link/..")), far);
            assert_eq!(resolved(&dir.join("new/a/../../link/x")), far.join("sub/x"));
        }
    }
}
