//! Where the points come from: a file or standard input, and the messages naming it.

use std::fs::File;
use std::io::{self, BufReader};
use std::path::{Path, PathBuf};

use clap::Args;
use wdm_crust::io::{
    format_from_path, read_points_with, ColumnSelection, ParseError, ParseErrorKind, ReadOptions,
};

use super::timings::{Timings, PROGRESS_BYTES, PROGRESS_POINTS};
use super::CliError;

/// The `--columns` option, flattened into each subcommand's arguments.
#[derive(Debug, Clone, Args)]
pub struct ColumnsArg {
    /// The columns to read as x and y, by header name (any case) or 1-based position (which
    /// also reads a file without a header): `--columns lon_deg,lat_deg`, `--columns 2,3`.
    /// Without it a header picks x,y, lon,lat (lng, long or longitude with lat or latitude)
    /// or easting,northing; a header with none of them, or with more than one pair, is
    /// refused.
    #[arg(long, value_name = "X,Y", value_parser = parse_columns)]
    columns: Option<ColumnSelection>,
}

/// `X,Y` as a [`ColumnSelection`].
fn parse_columns(text: &str) -> Result<ColumnSelection, String> {
    text.parse().map_err(|e| format!("{e}"))
}

/// The input of a subcommand: a file, or standard input for an absent INPUT or `-`.
#[derive(Debug)]
pub struct Input {
    path: Option<PathBuf>,
    columns: Option<ColumnSelection>,
}

/// The note for an input without points.
const EMPTY_NOTE: &str = "no points (the input is empty, or only comments, blank lines or a \
                          header); the result is empty";

impl Input {
    /// The input named on the command line, read with its `--columns`.
    pub fn new(arg: Option<&Path>, columns: &ColumnsArg) -> Self {
        let path = arg.filter(|p| p.as_os_str() != "-").map(Path::to_path_buf);
        Input {
            path,
            columns: columns.columns.clone(),
        }
    }

    /// The name used in messages: the path as given, or `<stdin>`.
    pub fn name(&self) -> String {
        match &self.path {
            Some(path) => path.display().to_string(),
            None => "<stdin>".to_string(),
        }
    }

    /// The size of the input file in bytes (`None` for standard input or an unreadable file).
    pub fn file_size(&self) -> Option<u64> {
        let path = self.path.as_ref()?;
        std::fs::metadata(path).ok().map(|m| m.len())
    }

    /// Reads all points, in the format implied by the extension or detected from the content.
    pub fn read_points(&self) -> Result<Vec<[f64; 2]>, CliError> {
        let mut options = ReadOptions::new();
        if let Some(columns) = &self.columns {
            options = options.with_columns(columns.clone());
        }
        let result = match &self.path {
            None => read_points_with(
                BufReader::with_capacity(1 << 16, io::stdin().lock()),
                &options,
            ),
            Some(path) => {
                if path.is_dir() {
                    return Err(CliError::bad_input(format!(
                        "{}: is a directory, not a point file",
                        self.name()
                    )));
                }
                let file = File::open(path).map_err(|e| {
                    CliError::bad_input(format!("{}: cannot open: {e}", self.name()))
                })?;
                if let Some(format) = format_from_path(path) {
                    options = options.with_format(format);
                }
                read_points_with(BufReader::with_capacity(1 << 16, file), &options)
            }
        };
        result.map_err(|e| self.parse_error(&e))
    }

    /// Reads all points as the `parse` phase of `timings`, with a progress line for a large
    /// file; afterwards progress lines are on for the next phases if there are many points.
    pub fn read_points_timed(&self, timings: &mut Timings) -> Result<Vec<[f64; 2]>, CliError> {
        timings.progress_if(self.file_size().is_some_and(|bytes| bytes > PROGRESS_BYTES));
        timings.begin(|| format!("reading {}", self.name()));
        let points = self.read_points()?;
        if points.is_empty() {
            // Not an error (an empty set is a valid point set), but rarely what was meant.
            super::report::note(&self.name(), EMPTY_NOTE);
        }
        timings.phase("parse", || format!("{} points", points.len()));
        timings.progress_if(points.len() > PROGRESS_POINTS);
        Ok(points)
    }

    /// `<file>:<line>: <problem>`; exit 2, except for a failing read (exit 1).
    fn parse_error(&self, e: &ParseError) -> CliError {
        let message = match e.line {
            Some(line) => format!("{}:{line}: {}", self.name(), e.kind),
            None => format!("{}: {}", self.name(), e.kind),
        };
        match e.kind {
            ParseErrorKind::Io(_) => CliError::failure(message),
            _ => CliError::bad_input(message),
        }
    }

    /// A library error about the points read (normally caught by the parser already): it
    /// names the point index.
    pub fn library_error(&self, e: &wdm_crust::Error) -> CliError {
        CliError::bad_input(format!("{}: {e}", self.name()))
    }
}
