//! The `wdm-crust` command line: argument parsing and dispatch here, the work in the
//! `wdm_crust` library (its file formats are `wdm_crust::io`). See `wdm-crust --help`.
//!
//! One module per subcommand plus the shared pieces (input, output, errors, timings). A new
//! subcommand is a new module with an `Args` struct and a `run` function, and one more
//! variant of [`Command`].
#![forbid(unsafe_code)]

mod common;
mod error;
mod input;
mod output;
mod reconstruct;
mod report;
mod threads;
mod timings;
mod triangulate;
mod voronoi;

use std::io::Write;
use std::process::ExitCode;

use clap::error::ErrorKind;
use clap::{Parser, Subcommand};

use error::CliError;

/// Shown after the top-level help.
const FORMATS_HELP: &str = "\
Input formats (detected from the content, or .node/.gtn/.csv by extension):
  plain text   one point per line: `x y`, `x,y` or `x y z...` (extra columns ignored); a
               line with a comma is split at commas only, one without at white space
  CSV          the same, after an optional header line of column names; the header picks
               the coordinates by name (any case, quoted or not, in any order): x,y;
               lon,lat (lng, long or longitude with lat or latitude); easting,northing.
               `id,x,y` reads columns 2 and 3, `lat,lon` reads x from column 2
  .node/.gtn   Triangle/Dey format: header `N 2 A B`, then `index x y [attributes] [marker]`
--columns X,Y picks other columns: header names (`--columns lon_deg,lat_deg`) or 1-based
positions, which also read a file without a header (`--columns 2,3` for `id x y` rows).
Blank lines and `#` comments are skipped; \\n, \\r\\n and \\r line ends are all accepted.
Refused with file and line, never misread: rows with a different number of columns than the
header or first row, decimal commas (`0,5 1,5`), numbers followed by anything (`1.5x`), a
header with no coordinate pair it knows or with two (`x,y` beside `lon,lat`: use --columns).
Refused with what they look like: SVG/XML/HTML, JSON/GeoJSON, compressed files, ZIP archives
and spreadsheets, PDFs, images, UTF-16 text.
An input without points gives an empty result and a note on standard error.
Point indices in every output are positions among the points read, counting from 0.
On a terminal, inputs of more than 200000 points get a progress line per phase.

Exit status: 0 on success, 2 for bad input or usage, 1 for other failures.";

/// Exact 2D Delaunay triangulation, Voronoi diagram and curve reconstruction (WDM_CRUST).
#[derive(Debug, Parser)]
#[command(
    name = "wdm-crust",
    version,
    propagate_version = true,
    arg_required_else_help = true,
    after_help = FORMATS_HELP
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
enum Command {
    /// Exact Delaunay triangulation of a point file.
    #[command(after_help = triangulate::EXAMPLES)]
    Triangulate(triangulate::TriangulateArgs),
    /// Voronoi diagram (vertices, edges, rays, cells) of a point file.
    #[command(after_help = voronoi::EXAMPLES)]
    Voronoi(voronoi::VoronoiArgs),
    /// Curves through a point file (WDM_CRUST) and their medial axis; JSON, text or SVG.
    #[command(after_help = reconstruct::EXAMPLES)]
    Reconstruct(reconstruct::ReconstructArgs),
}

impl Command {
    /// The subcommand's `--quiet`.
    fn quiet(&self) -> bool {
        match self {
            Command::Triangulate(args) => args.common.quiet,
            Command::Voronoi(args) => args.common.quiet,
            Command::Reconstruct(args) => args.common.quiet,
        }
    }

    /// The subcommand's `--threads`.
    fn threads(&self) -> threads::ThreadsArg {
        match self {
            Command::Triangulate(args) => args.common.threads,
            Command::Voronoi(args) => args.common.threads,
            Command::Reconstruct(args) => args.common.threads,
        }
    }
}

/// Parses the command line, runs the subcommand and turns the outcome into an exit code,
/// with at most one line on standard error for a failure.
fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => return clap_exit(&e),
    };
    let command = &cli.command;
    report::set_quiet(command.quiet());
    let result = command
        .threads()
        .run(|| match command {
            Command::Triangulate(args) => triangulate::run(args),
            Command::Voronoi(args) => voronoi::run(args),
            Command::Reconstruct(args) => reconstruct::run(args),
        })
        .and_then(|result| result);
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => e.report(),
    }
}

/// Help and version go to standard output with exit 0; a usage error becomes one line on
/// standard error with exit 2 (clap's tip and list of possible values kept).
/// The triangulation step of every subcommand, as a timed phase; a library error names the
/// input it came from.
fn triangulate_timed(
    input: &input::Input,
    points: &[[f64; 2]],
    timings: &mut timings::Timings,
    note: impl FnOnce(&wdm_crust::Triangulation) -> String,
) -> Result<wdm_crust::Triangulation, CliError> {
    timings.begin(|| format!("triangulating {} points", points.len()));
    let tri = wdm_crust::triangulate(points).map_err(|e| input.library_error(&e))?;
    timings.phase("triangulate", || note(&tri));
    Ok(tri)
}

/// A note on standard error when `count` of the written vertices (`what`) lie beyond the
/// `f64` range: exact circumcenters of nearly collinear points near `±f64::MAX`, which the
/// library returns as infinities and JSON can only write as `null`.
fn note_infinite_vertices(input: &input::Input, count: usize, what: &str) {
    if count > 0 {
        report::note(
            &input.name(),
            &format!(
                "{what} beyond the f64 range (their exact position overflows): {count}; \
                 written as null in JSON, inf in text"
            ),
        );
    }
}

/// The last step of every subcommand: write the result as a timed phase, report the
/// timings, and when the result went to a file, say what it holds (`what`, one summary
/// line; see [`report::summary`]).
fn write_timed(
    output: &output::Output,
    timings: &mut timings::Timings,
    points: usize,
    what: impl FnOnce() -> String,
    write: impl FnOnce(&mut dyn Write) -> std::io::Result<()>,
) -> Result<(), CliError> {
    timings.begin(|| "writing".to_string());
    output.write(write)?;
    timings.phase("write", String::new);
    timings.report();
    if let Some(file) = output.file_name() {
        report::summary(file, &what(), points, timings.elapsed());
    }
    Ok(())
}

fn clap_exit(e: &clap::Error) -> ExitCode {
    match e.kind() {
        ErrorKind::DisplayHelp | ErrorKind::DisplayVersion => {
            // A closed pipe (`--help | head -1`) is not worth a message.
            let _ = e.print();
            ExitCode::SUCCESS
        }
        ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
            let _ = e.print();
            ExitCode::from(2)
        }
        _ => {
            let rendered = e.render().to_string();
            let mut lines = rendered.lines().map(str::trim).filter(|l| !l.is_empty());
            let first = lines.next().unwrap_or("invalid arguments");
            let first = first.strip_prefix("error: ").unwrap_or(first);
            let mut message = first.to_string();
            for line in lines {
                if let Some(tip) = line.strip_prefix("tip: ") {
                    message.push_str(&format!(" ({tip})"));
                } else if line.starts_with('[') {
                    // `[possible values: json, text]`
                    message.push(' ');
                    message.push_str(line);
                }
            }
            let _ = writeln!(
                std::io::stderr(),
                "wdm-crust: {message}; see 'wdm-crust --help'"
            );
            ExitCode::from(2)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    #[test]
    fn the_command_line_definition_is_consistent() {
        Cli::command().debug_assert();
    }
}
