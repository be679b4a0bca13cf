//! `wdm-crust voronoi`: the Voronoi diagram of a point file (the dual of the exact Delaunay
//! triangulation, cocircular faces merged).

use std::path::{Path, PathBuf};

use clap::{Args, ValueEnum};
use wdm_crust::io::{write_voronoi_geojson, write_voronoi_json, write_voronoi_text};
use wdm_crust::BoundingBox;

use super::common::CommonArgs;
use super::input::{ColumnsArg, Input};
use super::output::Output;
use super::report::counted;
use super::timings::Timings;
use super::{triangulate_timed, write_timed, CliError};

/// Shown after `wdm-crust voronoi --help`.
pub const EXAMPLES: &str = "\
Examples:
  wdm-crust voronoi points.txt -o voronoi.json
  wdm-crust voronoi points.txt --format text | grep '^v '
  wdm-crust voronoi points.txt -o cells.geojson --clip 0,0,100,50
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
For collinear input, `# collinear: ...` and `# bisector i j` comment lines come first.

GeoJSON output (RFC 7946): a FeatureCollection with one Feature per distinct point,
properties {\"site\": i}, geometry its cell clipped to the box as a Polygon (one closed
counterclockwise ring), or null if the cell meets the box in no area (a site outside a box
given with --clip). Hull cells are clipped too, so the cells tile the box. The box is --clip
XMIN,YMIN,XMAX,YMAX or, by default, the points' bounding box enlarged by 10 % of its larger
side on every side. Which side of the box and of each bisector a vertex lies on is decided
exactly; coordinates are the exact ones correctly rounded (vertices that rounding
leaves within 16 ulps of each other are merged, in every cell alike).";

/// Output formats of `voronoi`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum VoronoiFormat {
    /// `{"vertices", "edges", "rays", "cells"}` on one line.
    Json,
    /// One `v`, `e`, `r` or `c` record per line.
    Text,
    /// The cells clipped to a box, as polygons (RFC 7946).
    Geojson,
}

/// Arguments of `wdm-crust voronoi`.
#[derive(Debug, Args)]
pub struct VoronoiArgs {
    /// Point file (plain text, CSV, .node/.gtn); absent or `-` reads standard input.
    #[arg(value_name = "INPUT")]
    input: Option<PathBuf>,

    /// Output format [default: geojson with --clip or an OUTPUT ending in .geojson, else
    /// json].
    #[arg(long, value_enum)]
    format: Option<VoronoiFormat>,

    /// The box the GeoJSON cells are clipped to [default: the points' bounding box enlarged
    /// by 10 % of its larger side on every side].
    #[arg(long, value_name = "XMIN,YMIN,XMAX,YMAX", allow_hyphen_values = true, value_parser = parse_clip)]
    clip: Option<BoundingBox>,

    #[command(flatten)]
    pub common: CommonArgs,

    #[command(flatten)]
    columns: ColumnsArg,
}

impl VoronoiArgs {
    /// The explicit format, or the one implied by --clip or the output file name.
    fn format(&self) -> VoronoiFormat {
        self.format.unwrap_or_else(|| {
            let is_geojson = self
                .common
                .output
                .as_deref()
                .and_then(Path::extension)
                .is_some_and(|ext| ext.eq_ignore_ascii_case("geojson"));
            if is_geojson || self.clip.is_some() {
                VoronoiFormat::Geojson
            } else {
                VoronoiFormat::Json
            }
        })
    }
}

/// `XMIN,YMIN,XMAX,YMAX`: four finite numbers with `XMIN < XMAX` and `YMIN < YMAX`.
fn parse_clip(text: &str) -> Result<BoundingBox, String> {
    let fields: Vec<&str> = text.split(',').map(str::trim).collect();
    if fields.len() != 4 {
        return Err(format!(
            "expected four comma-separated numbers XMIN,YMIN,XMAX,YMAX, got {}",
            fields.len()
        ));
    }
    let mut values = [0.0f64; 4];
    for (value, field) in values.iter_mut().zip(&fields) {
        *value = field
            .parse()
            .map_err(|_| format!("'{field}' is not a number"))?;
    }
    let [xmin, ymin, xmax, ymax] = values;
    BoundingBox::new([xmin, ymin], [xmax, ymax]).map_err(|e| e.to_string())
}

/// Reads, triangulates, builds the dual, writes.
pub fn run(args: &VoronoiArgs) -> Result<(), CliError> {
    let format = args.format();
    if args.clip.is_some() && format != VoronoiFormat::Geojson {
        return Err(CliError::bad_input(
            "--clip clips the cells of the GeoJSON output: it needs --format geojson; see 'wdm-crust voronoi --help'",
        ));
    }
    let mut timings = Timings::new(args.common.timings);
    let input = Input::new(args.input.as_deref(), &args.columns);
    let output = Output::new(args.common.output.as_deref())?;

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

    if format != VoronoiFormat::Geojson {
        let infinite = (vor.vertex_ids())
            .filter(|&v| vor.vertex_position(v).iter().any(|x| !x.is_finite()))
            .count();
        super::note_infinite_vertices(&input, infinite, "Voronoi vertices");
    }
    let bbox = args.clip.or_else(|| BoundingBox::around(&points));
    let what = || {
        format!(
            "{}, {}, {}{}",
            counted(vor.vertex_count(), "vertex", "vertices"),
            counted(vor.finite_edges().count(), "edge", "edges"),
            counted(vor.rays().count(), "ray", "rays"),
            if format == VoronoiFormat::Geojson {
                format!(
                    ", {}",
                    counted(tri.distinct_point_count(), "clipped cell", "clipped cells")
                )
            } else {
                String::new()
            }
        )
    };
    write_timed(&output, &mut timings, points.len(), what, |out| {
        match (format, bbox) {
            (VoronoiFormat::Json, _) => write_voronoi_json(&vor, out),
            (VoronoiFormat::Text, _) => write_voronoi_text(&vor, out),
            (VoronoiFormat::Geojson, Some(bbox)) => write_voronoi_geojson(&vor, &bbox, out),
            // No points: no cells.
            (VoronoiFormat::Geojson, None) => {
                out.write_all(b"{\"type\":\"FeatureCollection\",\"features\":[]}\n")
            }
        }
    })
}
