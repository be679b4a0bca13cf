//! `wdm-crust voronoi`: the Voronoi diagram of a point file (the dual of the exact Delaunay
//! triangulation, cocircular faces merged).

use std::path::PathBuf;

use clap::{Args, ValueEnum};
use wdm_crust::io::{write_voronoi_json, write_voronoi_text};

use super::input::Input;
use super::output::Output;
use super::timings::Timings;
use super::{triangulate_timed, write_timed, CliError};

/// Shown after `wdm-crust voronoi --help`.
pub const EXAMPLES: &str = "\
Examples:
  wdm-crust voronoi points.txt -o voronoi.json
  wdm-crust voronoi points.txt --format text | grep '^v '
  printf '0 0\\n2 0\\n0 2\\n2 2\\n1 0.5\\n' | wdm-crust voronoi --timings

JSON output (one line):
  {\"vertices\": [[x, y], ...], \"edges\": [[a, b], ...], \"rays\": [[a, dx, dy], ...],
   \"cells\": [[v0, v1, ...], ...]}
  vertices are circumcenters, one per Delaunay face after merging the faces that share a
  circumcircle (so four cocircular points give one vertex, not a zero-length edge); edges join
  two vertices; a ray starts at vertex a and goes to infinity along (dx, dy), the outward
  normal of its convex hull edge; cells[i] lists the vertices of the cell of point i
  counterclockwise (for a point on the hull: from its outgoing ray's vertex to its incoming
  ray's vertex), and is empty for a duplicate point.
  Collinear input (or fewer than three distinct points) has no vertex: the diagram is then
  the parallel bisectors of consecutive points, which this format cannot hold, so vertices,
  edges and rays are empty and every cell is empty. The text format lists the bisectors.

Text output: a `# wdm-crust voronoi: ...` count line, then one record per line:
  v x y            a vertex (numbered from 0 in the order of the v lines)
  e a b            a finite edge between vertices a and b
  r a dx dy        a ray from vertex a along (dx, dy)
  c p v0 v1 ...    the cell of point p, counterclockwise (one line per point; `c p` if empty)
For collinear input, `# collinear: ...` and `# bisector i j` comment lines come first.";

/// Output formats of `voronoi`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum VoronoiFormat {
    /// `{"vertices", "edges", "rays", "cells"}` on one line.
    Json,
    /// One `v`, `e`, `r` or `c` record per line.
    Text,
}

/// Arguments of `wdm-crust voronoi`.
#[derive(Debug, Args)]
pub struct VoronoiArgs {
    /// Point file (plain text, CSV, .node/.gtn); absent or `-` reads standard input.
    #[arg(value_name = "INPUT")]
    input: Option<PathBuf>,

    /// Output format.
    #[arg(long, value_enum, default_value_t = VoronoiFormat::Json)]
    format: VoronoiFormat,

    /// Write to OUTPUT instead of standard output; OUTPUT is replaced only on success.
    #[arg(short, long, value_name = "OUTPUT")]
    output: Option<PathBuf>,

    /// Print the wall time of each phase (parse, triangulate, voronoi, write) to standard
    /// error.
    #[arg(long)]
    timings: bool,
}

/// Reads, triangulates, builds the dual, writes.
pub fn run(args: &VoronoiArgs) -> Result<(), CliError> {
    let mut timings = Timings::new(args.timings);
    let input = Input::new(args.input.as_deref());
    let output = Output::new(args.output.as_deref())?;

    let points = input.read_points_timed(&mut timings)?;

    let tri = triangulate_timed(&input, &points, &mut timings, |tri| {
        format!("{} triangles", tri.triangle_count())
    })?;

    timings.begin(|| "building the Voronoi diagram".to_string());
    let vor = tri.voronoi();
    timings.phase("voronoi", || {
        format!(
            "{} vertices, {} edges, {} rays",
            vor.vertex_count(),
            vor.finite_edges().count(),
            vor.rays().count()
        )
    });

    write_timed(&output, &mut timings, |out| match args.format {
        VoronoiFormat::Json => write_voronoi_json(&vor, out),
        VoronoiFormat::Text => write_voronoi_text(&vor, out),
    })
}
