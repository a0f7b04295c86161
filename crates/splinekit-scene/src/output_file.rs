//! Writing an output file without harm to what is there: the one home of "write a file"
//! for every crate above the kernel (command line, mesh exports, pictures, gallery, STEP,
//! studio, Python; the kernel writes no files).
//!
//! A failed write must never remove or truncate what the program did not create:
//!
//! * a **regular file** (or a path that does not exist yet) is written to a new temporary
//!   file beside it (same directory, so the same file system) and renamed over the target
//!   only when every byte is written and flushed; a failure removes only the temporary
//!   file, so the user's old file survives a full disk. The replaced file's permissions
//!   are kept;
//! * a **device, FIFO, socket or symbolic link** is written in place (opened for writing,
//!   not truncated, not created) and never unlinked: `-o /dev/full` fails with the device
//!   node intact, `-o /dev/stdout` and `-o fifo` stream, and a symbolic link keeps pointing
//!   where it pointed.

use std::fs::{File, OpenOptions};
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};

/// An output being written; see the module documentation. Dropped without
/// [`OutputFile::commit`], it removes its temporary file (if any) and nothing else.
#[derive(Debug)]
pub struct OutputFile {
    file: Option<File>,
    target: PathBuf,
    /// The temporary file renamed over the target on commit (regular files only).
    temporary: Option<PathBuf>,
}

impl OutputFile {
    /// Starts writing `path`: a temporary file beside it for regular files and new paths,
    /// the path itself in place for devices, FIFOs, sockets and symbolic links.
    pub fn create(path: impl AsRef<Path>) -> io::Result<Self> {
        let target = path.as_ref().to_path_buf();
        let existing = match std::fs::symlink_metadata(&target) {
            Ok(m) => Some(m),
            Err(e) if e.kind() == io::ErrorKind::NotFound => None,
            Err(e) => return Err(e),
        };
        match existing {
            Some(m) if m.is_dir() => Err(io::Error::new(io::ErrorKind::IsADirectory, "is a directory")),
            Some(m) if !m.file_type().is_file() => {
                // Device, FIFO, socket or symbolic link: in place, never created or truncated
                // here (a link to a regular file is truncated after it opened, so a write that
                // fails later cannot leave a longer old tail behind).
                let file = OpenOptions::new().write(true).open(&target)?;
                if file.metadata().is_ok_and(|m| m.is_file()) {
                    file.set_len(0)?;
                }
                Ok(OutputFile { file: Some(file), target, temporary: None })
            }
            regular => {
                let (file, temporary) = temporary_beside(&target)?;
                if let Some(m) = regular {
                    // Keep the permissions of the file being replaced.
                    let _ = file.set_permissions(m.permissions());
                }
                Ok(OutputFile { file: Some(file), target, temporary: Some(temporary) })
            }
        }
    }

    /// The path being written (the target, not the temporary file).
    pub fn path(&self) -> &Path {
        &self.target
    }

    /// Flushes everything and puts the output in place (renames the temporary file over the
    /// target). On an error the temporary file is removed and the target left as it was.
    pub fn commit(mut self) -> io::Result<()> {
        let mut file = self.file.take().expect("an open output");
        file.flush()?;
        if let Some(temporary) = &self.temporary {
            file.sync_all()?;
            drop(file);
            std::fs::rename(temporary, &self.target)?;
            self.temporary = None;
        }
        Ok(())
    }
}

impl Write for OutputFile {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        self.file.as_mut().expect("an open output").write(buf)
    }
    fn flush(&mut self) -> io::Result<()> {
        self.file.as_mut().expect("an open output").flush()
    }
}

impl Drop for OutputFile {
    /// An output dropped before [`OutputFile::commit`] (an error on the way) removes its
    /// temporary file; the target is left as it was.
    fn drop(&mut self) {
        self.file = None;
        if let Some(temporary) = self.temporary.take() {
            let _ = std::fs::remove_file(temporary);
        }
    }
}

/// Writes `bytes` to `path` as [`OutputFile`] does: all or nothing for regular files, in
/// place for devices, FIFOs and symbolic links.
pub fn write_file(path: impl AsRef<Path>, bytes: &[u8]) -> io::Result<()> {
    let mut out = OutputFile::create(path)?;
    out.write_all(bytes)?;
    out.commit()
}

/// A new file `.NAME.PID-N.tmp` in the directory of `target`.
fn temporary_beside(target: &Path) -> io::Result<(File, PathBuf)> {
    static COUNTER: AtomicUsize = AtomicUsize::new(0);
    let name = target
        .file_name()
        .ok_or_else(|| io::Error::new(io::ErrorKind::InvalidInput, "not a file name"))?
        .to_string_lossy()
        .into_owned();
    let dir = match target.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    loop {
        let n = COUNTER.fetch_add(1, Ordering::Relaxed);
        let temporary = dir.join(format!(".{name}.{}-{n}.tmp", std::process::id()));
        match OpenOptions::new().write(true).create_new(true).open(&temporary) {
            Ok(file) => return Ok((file, temporary)),
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists => continue,
            Err(e) => return Err(e),
        }
    }
}

#[cfg(all(test, unix))]
mod tests {
    use super::*;

    /// A new empty folder for one test, removed with its contents when dropped.
    struct Scratch(PathBuf);

    impl std::ops::Deref for Scratch {
        type Target = Path;
        fn deref(&self) -> &Path {
            &self.0
        }
    }

    impl Drop for Scratch {
        fn drop(&mut self) {
            let _ = std::fs::remove_dir_all(&self.0);
        }
    }

    fn scratch(name: &str) -> Scratch {
        let d = std::env::temp_dir().join(format!("splinekit-output-file-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        Scratch(d)
    }

    fn leftovers(dir: &Path) -> Vec<String> {
        let mut names: Vec<String> =
            std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
        names.sort();
        names
    }

    #[test]
    fn a_new_file_appears_only_on_commit() {
        let d = scratch("new");
        let target = d.join("out.txt");
        let mut out = OutputFile::create(&target).unwrap();
        out.write_all(b"hello").unwrap();
        assert!(!target.exists(), "the target appears before the commit");
        out.commit().unwrap();
        assert_eq!(std::fs::read(&target).unwrap(), b"hello");
        assert_eq!(leftovers(&d), ["out.txt"]);
    }

    #[test]
    fn an_abandoned_write_leaves_the_old_file_and_no_temporary() {
        use std::os::unix::fs::PermissionsExt;
        let d = scratch("old");
        let target = d.join("out.txt");
        std::fs::write(&target, b"the user's old file").unwrap();
        std::fs::set_permissions(&target, std::fs::Permissions::from_mode(0o640)).unwrap();
        let mut out = OutputFile::create(&target).unwrap();
        out.write_all(b"half a resu").unwrap();
        drop(out);
        assert_eq!(std::fs::read(&target).unwrap(), b"the user's old file");
        assert_eq!(leftovers(&d), ["out.txt"]);
        // A committed one replaces it, keeping its permissions.
        write_file(&target, b"new").unwrap();
        assert_eq!(std::fs::read(&target).unwrap(), b"new");
        assert_eq!(std::fs::metadata(&target).unwrap().permissions().mode() & 0o777, 0o640);
        assert_eq!(leftovers(&d), ["out.txt"]);
    }

    #[test]
    fn a_device_is_written_in_place_and_never_removed() {
        // /dev/full takes the open and fails the write with "no space left". It is reached
        // through a link only: should this regress, a test run as root writing to
        // /dev/full itself would remove the machine's device node. The link survives the
        // failure, still pointing there, and so does the device.
        let full = Path::new("/dev/full");
        if !full.exists() {
            return;
        }
        let d = scratch("link");
        let link = d.join("link");
        std::os::unix::fs::symlink(full, &link).unwrap();
        let e = write_file(&link, &[0u8; 1 << 16]).unwrap_err();
        assert!(e.kind() == io::ErrorKind::StorageFull || e.raw_os_error().is_some(), "{e}");
        assert_eq!(std::fs::read_link(&link).unwrap(), full);
        assert!(full.exists(), "/dev/full is gone");
        assert_eq!(leftovers(&d), ["link"]);
        // /dev/null takes everything.
        write_file("/dev/null", b"gone").unwrap();
        assert!(Path::new("/dev/null").exists());
    }

    #[test]
    fn a_symbolic_link_to_a_file_is_written_through() {
        let d = scratch("through");
        let (file, link) = (d.join("real.txt"), d.join("link.txt"));
        std::fs::write(&file, b"a long old content").unwrap();
        std::os::unix::fs::symlink(&file, &link).unwrap();
        write_file(&link, b"short").unwrap();
        assert_eq!(std::fs::read(&file).unwrap(), b"short");
        assert!(std::fs::symlink_metadata(&link).unwrap().file_type().is_symlink());
    }

    #[test]
    fn a_directory_is_refused() {
        let d = scratch("dir");
        assert!(OutputFile::create(&*d).is_err());
        assert!(d.is_dir());
    }
}
