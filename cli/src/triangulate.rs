//! `wdm-crust triangulate`: the exact Delaunay triangulation of a point file.

use std::path::PathBuf;

use clap::{Args, ValueEnum};
use wdm_crust::io::{write_triangulation_json, write_triangulation_text};

use super::common::CommonArgs;
use super::input::{ColumnsArg, Input};
use super::output::Output;
use super::report::counted;
use super::timings::Timings;
use super::{triangulate_timed, write_timed, CliError};

/// Shown after `wdm-crust triangulate --help`.
pub const EXAMPLES: &str = "\
Examples:
  wdm-crust triangulate points.txt -o triangles.json
  wdm-crust triangulate mesh.node --format text | grep -v '^#'
  printf '0 0\\n1 0\\n0 1\\n' | wdm-crust triangulate --timings

JSON output (one line):
  {\"points\": N, \"triangles\": [[a, b, c], ...], \"hull\": [...], \"duplicates\": [[dup, kept], ...]}
  triangles and hull are counterclockwise; a duplicate point is paired with the first point
  with the same coordinates and appears in no triangle.

Text output: `# ...` comment lines (counts, `# hull i j ...`, `# duplicate d k`), then one
counterclockwise triangle `a b c` per line.";

/// Output formats of `triangulate`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum TriangulateFormat {
    /// `{"points", "triangles", "hull", "duplicates"}` on one line.
    Json,
    /// `# ...` comment lines, then one `a b c` triangle per line.
    Text,
}

/// Arguments of `wdm-crust triangulate`.
#[derive(Debug, Args)]
pub struct TriangulateArgs {
    /// Point file (plain text, CSV, .node/.gtn); absent or `-` reads standard input.
    #[arg(value_name = "INPUT")]
    input: Option<PathBuf>,

    /// Output format.
    #[arg(long, value_enum, default_value_t = TriangulateFormat::Json)]
    format: TriangulateFormat,

    #[command(flatten)]
    pub common: CommonArgs,

    #[command(flatten)]
    columns: ColumnsArg,
}

/// Reads, triangulates, writes.
pub fn run(args: &TriangulateArgs) -> Result<(), CliError> {
    let mut timings = Timings::new(args.common.timings);
    let input = Input::new(args.input.as_deref(), &args.columns);
    let output = Output::new(args.common.output.as_deref())?;

    let points = input.read_points_timed(&mut timings)?;

    let tri = triangulate_timed(&input, &points, &mut timings, |tri| {
        format!(
            "{} triangles, {} duplicates",
            tri.triangle_count(),
            tri.duplicates().len()
        )
    })?;
    let what = || {
        format!(
            "{}, {}, {}",
            counted(tri.triangle_count(), "triangle", "triangles"),
            counted(tri.hull().len(), "hull point", "hull points"),
            counted(tri.duplicates().len(), "duplicate", "duplicates")
        )
    };
    write_timed(
        &output,
        &mut timings,
        points.len(),
        what,
        |out| match args.format {
            TriangulateFormat::Json => write_triangulation_json(&tri, out),
            TriangulateFormat::Text => write_triangulation_text(&tri, out),
        },
    )
}
