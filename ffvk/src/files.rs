//! Writing files so that a failure never damages one: every output is written to a temporary
//! file in the destination's folder, flushed and synced, then renamed over the destination.
//! An error or an interruption leaves the old file (or none) and a stray temporary file at
//! worst, never a partial or empty destination; every error, the final flush's included,
//! reaches the caller.

use std::fs::{self, File, OpenOptions};
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// Temporary files of this process get distinct names.
static NEXT_TEMPORARY: AtomicU64 = AtomicU64::new(0);

/// Why a destination path is refused before anything is written.
fn refuse(path: &Path, problem: &str) -> io::Error {
    io::Error::new(
        io::ErrorKind::InvalidInput,
        format!("{}: {problem}", path.display()),
    )
}

/// Where the bytes for `path` really go: the path itself, or the regular file a symlink
/// points at (so that the link survives). Anything else that exists there (a folder, a
/// device such as /dev/full, a pipe) is refused: it cannot be replaced atomically.
fn destination(path: &Path) -> io::Result<PathBuf> {
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
    fs::create_dir_all(&dir)?;
    let name = target
        .file_name()
        .ok_or_else(|| refuse(path, "has no file name: expected a file path"))?
        .to_string_lossy();
    let temporary = dir.join(format!(
        ".{name}.{}-{}.tmp",
        std::process::id(),
        NEXT_TEMPORARY.fetch_add(1, Ordering::Relaxed)
    ));
    let result = (|| {
        let file = OpenOptions::new().write(true).create_new(true).open(&temporary)?;
        let mut writer = BufWriter::new(file);
        write(&mut writer)?;
        // into_inner flushes; its error is the write error a drop would have lost.
        let file = writer.into_inner().map_err(|e| e.into_error())?;
        file.sync_all()?;
        fs::rename(&temporary, &target)
    })();
    if result.is_err() {
        let _ = fs::remove_file(&temporary);
    }
    result?;
    // The rename is durable once the folder is synced; a failure here loses nothing written.
    if let Ok(d) = File::open(&dir) {
        let _ = d.sync_all();
    }
    Ok(())
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
    let absolute = if path.is_absolute() {
        path.to_path_buf()
    } else {
        std::env::current_dir().unwrap_or_default().join(path)
    };
    let mut existing = absolute.clone();
    let mut rest = Vec::new();
    while !existing.exists() {
        match (existing.parent(), existing.file_name()) {
            (Some(parent), Some(name)) => {
                rest.push(name.to_os_string());
                existing = parent.to_path_buf();
            }
            _ => return absolute,
        }
    }
    let mut out = fs::canonicalize(&existing).unwrap_or(existing);
    for name in rest.into_iter().rev() {
        out.push(name);
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
}
