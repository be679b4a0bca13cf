//! Where results go: standard output, or a file that is replaced only when everything
//! succeeded (written to a temporary file in the same directory, then renamed into place).

use std::fs::{self, File, OpenOptions};
use std::io::{self, Write};
use std::path::{Path, PathBuf};

use super::CliError;

/// The output of a subcommand.
#[derive(Debug)]
pub enum Output {
    /// Standard output (no `-o`, or `-o -`).
    Stdout,
    /// A file.
    File {
        /// The path as given, for messages.
        shown: String,
        /// Where the result goes: the given path with symbolic links resolved, so that a link
        /// keeps pointing at the updated file.
        dest: PathBuf,
        /// Write straight into `dest` (a FIFO, `/dev/null`, ...) rather than rename over it.
        direct: bool,
    },
}

impl Output {
    /// The output named by `-o`, checked before any work is done: its directory must exist
    /// and it must not be a directory itself.
    pub fn new(arg: Option<&Path>) -> Result<Self, CliError> {
        let Some(path) = arg.filter(|p| p.as_os_str() != "-") else {
            return Ok(Output::Stdout);
        };
        let shown = path.display().to_string();
        match fs::metadata(path) {
            Ok(meta) if meta.is_dir() => Err(CliError::bad_input(format!(
                "{shown}: is a directory; -o needs a file name"
            ))),
            Ok(meta) if meta.is_file() => Ok(Output::File {
                dest: fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf()),
                shown,
                direct: false,
            }),
            Ok(_) => Ok(Output::File {
                dest: path.to_path_buf(),
                shown,
                direct: true,
            }),
            Err(e) if e.kind() == io::ErrorKind::NotFound => {
                let dir = parent_dir(path);
                if !dir.is_dir() {
                    return Err(CliError::bad_input(format!(
                        "{shown}: the directory {} does not exist",
                        dir.display()
                    )));
                }
                Ok(Output::File {
                    dest: path.to_path_buf(),
                    shown,
                    direct: false,
                })
            }
            Err(e) => Err(CliError::failure(format!("{shown}: {e}"))),
        }
    }

    /// The file's name as given, `None` for standard output.
    pub fn file_name(&self) -> Option<&str> {
        match self {
            Output::Stdout => None,
            Output::File { shown, .. } => Some(shown),
        }
    }

    /// Runs `write` on the output. For a file, nothing appears under the file's name unless
    /// `write` and the final rename succeed; a failure leaves an existing file untouched.
    pub fn write(
        &self,
        write: impl FnOnce(&mut dyn Write) -> io::Result<()>,
    ) -> Result<(), CliError> {
        match self {
            Output::Stdout => {
                let stdout = io::stdout();
                let mut lock = stdout.lock();
                write(&mut lock)
                    .and_then(|()| lock.flush())
                    .map_err(|e| write_error("<stdout>", &e))
            }
            Output::File {
                shown,
                dest,
                direct: true,
            } => File::create(dest)
                .and_then(|mut file| write(&mut file))
                .map_err(|e| write_error(shown, &e)),
            Output::File {
                shown,
                dest,
                direct: false,
            } => {
                let mut temp = TempFile::create_next_to(dest).map_err(|e| {
                    CliError::failure(format!("{shown}: cannot create a temporary file: {e}"))
                })?;
                write(&mut temp.file)
                    .and_then(|()| temp.persist(dest))
                    .map_err(|e| write_error(shown, &e))
            }
        }
    }
}

/// A closed pipe ends the command quietly; any other error is a one-line failure.
fn write_error(shown: &str, e: &io::Error) -> CliError {
    if e.kind() == io::ErrorKind::BrokenPipe {
        CliError::quiet()
    } else {
        CliError::failure(format!("{shown}: cannot write: {e}"))
    }
}

/// The directory holding `path` (`.` for a bare file name).
fn parent_dir(path: &Path) -> &Path {
    match path.parent() {
        Some(dir) if !dir.as_os_str().is_empty() => dir,
        _ => Path::new("."),
    }
}

/// A hidden temporary file next to the destination, removed on drop unless persisted.
struct TempFile {
    path: PathBuf,
    file: File,
    persisted: bool,
}

impl TempFile {
    /// Creates `.<name>.<pid>-<k>.tmp` in the directory of `dest`, with the permissions of
    /// `dest` if it exists.
    fn create_next_to(dest: &Path) -> io::Result<Self> {
        let dir = parent_dir(dest);
        let name = dest
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_else(|| "output".to_string());
        let pid = std::process::id();
        let mut k = 0u32;
        loop {
            let path = dir.join(format!(".{name}.{pid}-{k}.tmp"));
            match OpenOptions::new().write(true).create_new(true).open(&path) {
                Ok(file) => {
                    let temp = TempFile {
                        path,
                        file,
                        persisted: false,
                    };
                    if let Ok(meta) = fs::metadata(dest) {
                        temp.file.set_permissions(meta.permissions())?;
                    }
                    return Ok(temp);
                }
                Err(e) if e.kind() == io::ErrorKind::AlreadyExists && k < 1000 => k += 1,
                Err(e) => return Err(e),
            }
        }
    }

    /// Makes the content durable and renames the file to `dest`.
    fn persist(&mut self, dest: &Path) -> io::Result<()> {
        self.file.flush()?;
        self.file.sync_all()?;
        fs::rename(&self.path, dest)?;
        self.persisted = true;
        Ok(())
    }
}

impl Drop for TempFile {
    fn drop(&mut self) {
        if !self.persisted {
            let _ = fs::remove_file(&self.path);
        }
    }
}
