//! `wdm-crust reconstruct`: the curves through a point file (WDM_CRUST, or the crust and
//! NN-crust baselines) and the medial axis, as JSON, an edge list, an SVG picture or GeoJSON.

use std::path::{Path, PathBuf};

use clap::{Args, ValueEnum};
use wdm_crust::io::{
    write_reconstruction_geojson, write_reconstruction_json, write_reconstruction_svg,
    write_reconstruction_text, SvgOptions,
};
use wdm_crust::reconstruct::{
    Algorithm, MedialAxisMode, Options, OptionsConflict, Phase, WdmSetting,
};

use super::common::CommonArgs;
use super::input::{ColumnsArg, Input};
use super::output::Output;
use super::report::{self, counted};
use super::timings::Timings;
use super::{write_timed, CliError};

/// Shown after `wdm-crust reconstruct --help`.
pub const EXAMPLES: &str = "\
Examples:
  wdm-crust reconstruct points.txt -o curves.json
  wdm-crust reconstruct points.txt --format svg -o picture.svg
  wdm-crust reconstruct points.txt -o picture.svg --show delaunay,labels
  wdm-crust reconstruct scan-pixels.txt -o picture.svg --y-down
  wdm-crust reconstruct big-scan.txt -o curves.svg --no-points
  wdm-crust reconstruct points.txt --algorithm nn-crust --format text
  wdm-crust reconstruct points.txt -o shapes.geojson
  wdm-crust reconstruct big-scan.txt --medial-axis none -o curves.json
  wdm-crust reconstruct noisy-scan.txt --smooth -o shapes.geojson

JSON output (one line):
  {\"algorithm\": \"wdm\", \"points\": N, \"edges\": [[i, j], ...],
   \"curves\": [{\"closed\": true, \"points\": [i, j, ...], \"coords\": [[x, y], ...]}, ...],
   \"medial_axis\": {\"vertices\": [[x, y], ...], \"edges\": [[a, b], ...]},
   \"unassigned\": [i, ...], \"duplicates\": [[dup, kept], ...],
   \"warnings\": [{\"code\": \"...\", \"message\": \"...\", \"points\": [i, ...]}, ...]}
  edges are the reconstructed point pairs, i < j, sorted; curves chain them into closed
  loops (counterclockwise, each point once, starting at the smallest index) and open chains
  (from an end or a junction to the next one); the medial axis is the Voronoi edges between
  two inner Voronoi vertices, over its own vertex list (WDM only: empty for crust and
  nn-crust, and with --medial-axis none), pruned of noise branches unless --medial-axis
  raw; unassigned lists the points on no curve (outliers, leftovers of noise), sorted,
  duplicates not listed; coords are the curve's points' coordinates (fitted with --smooth);
  duplicates pair each repeated point with its first occurrence; warnings say when the
  result is probably not what was wanted (codes most-unassigned, scatter, long-edge,
  loop-across-gap, chain-ends-close, curves-too-close, peeling-budget), empty when there
  is nothing to say;
  \"thinned\": N appears when a dense noisy band was thinned to N representatives.
  Warnings are also printed on standard error, and a file written with -o gets a summary
  line there (--quiet: neither).

Text output: one reconstructed edge `i j` per line, nothing else.

GeoJSON output (RFC 7946): a FeatureCollection, one feature per line: a Polygon per outer
closed curve (exterior counterclockwise, the closed curves directly inside it as clockwise
holes; a curve inside a hole starts a new polygon), properties {\"kind\": \"curve\",
\"points\": [...], \"holes\": [[...], ...]}; a LineString per open chain {\"kind\": \"chain\",
\"points\": [...]}; one MultiLineString for the medial axis {\"kind\": \"medial_axis\"}; a
MultiPoint of the unassigned points {\"kind\": \"unassigned\", \"points\": [...]} (left out
when there are none). Rings are closed; coordinates are the input's (with --smooth the
curves' are the fitted ones), written so that they read back exactly.

SVG output: the points, the curves (closed red, open purple), the medial axis (green), the
unassigned points (grey rings) and a legend, y axis up (--y-down: down, for image
coordinates); --show adds faint underlays. The picture is in pixels whatever the data's
units, so it renders at any extent. Line widths and dots follow the samples' spacing;
samples under 2.4 px apart get no dots (the legend says so), and --no-points leaves out
every point, dots and rings. A curve vertex at the position (to 1/100 px) of the one
before it and a dot on a dot already drawn are left out, and long curves are split into
paths of at most 64 KiB, so that a million points make a file of a few megabytes that
viewers open. Without --format, an OUTPUT ending in .svg gets SVG, one ending in .geojson
GeoJSON, and anything else JSON.";

/// Output formats of `reconstruct`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ReconstructFormat {
    /// `{"algorithm", "points", "edges", "curves", "medial_axis", "unassigned", "duplicates",
    /// "warnings"}` on one line.
    Json,
    /// A picture: points, curves, medial axis, legend.
    Svg,
    /// One `i j` edge per line.
    Text,
    /// GeoJSON: polygons with holes, open chains, medial axis, unassigned points.
    Geojson,
}

/// The reconstruction algorithms.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum AlgorithmArg {
    /// WDM_CRUST (water-flow labeling of the Voronoi vertices), with its medial axis.
    Wdm,
    /// The crust of Amenta, Bern and Eppstein (baseline, no medial axis).
    Crust,
    /// The nearest-neighbour crust of Dey and Kumar (baseline, no medial axis).
    NnCrust,
}

impl From<AlgorithmArg> for Algorithm {
    fn from(arg: AlgorithmArg) -> Self {
        match arg {
            AlgorithmArg::Wdm => Algorithm::Wdm,
            AlgorithmArg::Crust => Algorithm::Crust,
            AlgorithmArg::NnCrust => Algorithm::NnCrust,
        }
    }
}

/// Which medial axis to return.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum MedialAxisArg {
    /// The medial axis of the closed curves, without the branches noise grows (the rule is
    /// documented in ARCHITECTURE.md).
    Pruned,
    /// The paper's WDM_MAT: every finite Voronoi edge between two inner vertices.
    Raw,
    /// No medial axis: the curves only, in about half the time.
    None,
}

impl From<MedialAxisArg> for MedialAxisMode {
    fn from(arg: MedialAxisArg) -> Self {
        match arg {
            MedialAxisArg::Pruned => MedialAxisMode::Pruned,
            MedialAxisArg::Raw => MedialAxisMode::Raw,
            MedialAxisArg::None => MedialAxisMode::Omitted,
        }
    }
}

/// Underlays of the SVG picture.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Layer {
    /// The Delaunay edges, faint grey.
    Delaunay,
    /// The Voronoi edges and rays (clipped to the picture), faint blue.
    Voronoi,
    /// The Voronoi vertices coloured by their water-flow label (WDM only).
    Labels,
}

/// Arguments of `wdm-crust reconstruct`.
#[derive(Debug, Args)]
pub struct ReconstructArgs {
    /// Point file (plain text, CSV, .node/.gtn); absent or `-` reads standard input.
    #[arg(value_name = "INPUT")]
    input: Option<PathBuf>,

    /// Reconstruction algorithm. The options for WDM that ask for what the baselines do not
    /// do (--medial-axis pruned|raw, --peeling-budget, --show labels) are refused with crust
    /// and nn-crust; --medial-axis none and --no-peeling are accepted with every algorithm.
    #[arg(long, value_enum, default_value_t = AlgorithmArg::Wdm)]
    algorithm: AlgorithmArg,

    /// Output format [default: svg if OUTPUT ends in .svg, geojson if in .geojson, else json].
    #[arg(long, value_enum)]
    format: Option<ReconstructFormat>,

    #[command(flatten)]
    pub common: CommonArgs,

    #[command(flatten)]
    columns: ColumnsArg,

    /// WDM: one pass only, as in the paper (curves nested inside others are then lost).
    /// By default WDM reruns on the points no curve reached, to find holes.
    #[arg(long)]
    no_peeling: bool,

    /// WDM: peeling stops before the extra passes together would run on more than N times
    /// the input's points (a note on standard error says so) [default: 4]. Curve samples
    /// with holes never reach it; noise and grids would otherwise peel for hundreds of
    /// passes.
    #[arg(long, value_name = "N")]
    peeling_budget: Option<usize>,

    /// WDM: the medial axis returned: `pruned` (default: the axis of the closed curves, one
    /// tree per simply connected shape, noise branches removed), `raw` (the paper's
    /// WDM_MAT: every Voronoi edge between two inner vertices) or `none` (the curves only,
    /// in about half the time; the output's medial axis is empty).
    #[arg(long, value_enum)]
    medial_axis: Option<MedialAxisArg>,

    /// Fit the curves to the samples: every curve vertex is placed on a local fit of the
    /// noisy samples around it (the JSON's `coords`, the GeoJSON's and the SVG's curves);
    /// without it the curve vertices are the input points themselves. For dense noisy
    /// scans; corners stay sharp, clean samples stay put, curves stay simple.
    #[arg(long)]
    smooth: bool,

    /// WDM: reconstruct a dense noisy band as it is. By default an input whose points form a
    /// band many sample spacings wide (a dense scan) is thinned to representatives near the
    /// band's middle and the curves are drawn through them (the JSON's `thinned` counts
    /// them); every other point is unassigned.
    #[arg(long)]
    no_thinning: bool,

    /// SVG underlays, comma-separated: delaunay, voronoi, labels (WDM only).
    #[arg(long, value_enum, value_delimiter = ',', value_name = "LAYERS")]
    show: Vec<Layer>,

    /// The data is in image coordinates (y grows downwards, as pixel positions of a scan):
    /// the SVG is drawn the right way up. JSON and text output are unchanged (coordinates
    /// stay the input's).
    #[arg(long)]
    y_down: bool,

    /// SVG: leave out the input points, the dots and the unassigned points' rings alike, so
    /// that only the curves and the medial axis are drawn; the legend still counts them.
    /// Without it, samples under 2.4 px apart get no dots either, but the unassigned points
    /// keep their rings.
    #[arg(long)]
    no_points: bool,
}

impl ReconstructArgs {
    /// The library's options from the arguments given; options that do not apply to the
    /// algorithm (or to each other) are a usage error saying why.
    fn options(&self) -> Result<Options, CliError> {
        let algorithm = Algorithm::from(self.algorithm);
        let mut options = Options::new().with_algorithm(algorithm);
        if self.no_peeling {
            options = options.with_peeling(false);
        }
        if let Some(budget) = self.peeling_budget {
            options = options.with_peeling_budget(budget);
        }
        if let Some(mode) = self.medial_axis {
            options = options.with_medial_axis(mode.into());
        }
        options = options.with_smoothing(self.smooth);
        if self.no_thinning {
            options = options.with_thinning(false);
        }
        let inapplicable = |option: String, conflict: OptionsConflict| {
            CliError::bad_input(format!(
                "{option} does not apply to --algorithm {}: {}; leave it out, or use \
                 --algorithm wdm; see 'wdm-crust reconstruct --help'",
                algorithm.name(),
                conflict.reason()
            ))
        };
        if let Err(conflict) = options.check() {
            return Err(match conflict {
                OptionsConflict::WdmOnly { setting, .. } => {
                    let option = match (setting, self.medial_axis) {
                        (WdmSetting::MedialAxis, Some(mode)) => {
                            format!("--medial-axis {}", MedialAxisMode::from(mode).name())
                        }
                        (WdmSetting::PeelingBudget, _) => "--peeling-budget".to_string(),
                        (WdmSetting::Peeling, _) => "--no-peeling".to_string(),
                        (other, _) => format!("the {} setting", other.name()),
                    };
                    inapplicable(option, conflict)
                }
                OptionsConflict::BudgetWithoutPeeling => CliError::bad_input(format!(
                    "--peeling-budget does not apply with --no-peeling: {}; leave one of them \
                     out; see 'wdm-crust reconstruct --help'",
                    conflict.reason()
                )),
                _ => CliError::bad_input(format!("{conflict}")),
            });
        }
        if algorithm != Algorithm::Wdm && self.show.contains(&Layer::Labels) {
            // The labels drawn are the water flow's, as a label rule would ask for.
            let conflict = OptionsConflict::WdmOnly {
                setting: WdmSetting::LabelRule,
                algorithm,
            };
            return Err(inapplicable("--show labels".to_string(), conflict));
        }
        Ok(options)
    }

    /// The explicit format, or the one implied by the output file name.
    fn format(&self) -> ReconstructFormat {
        self.format.unwrap_or_else(|| {
            let extension = self.common.output.as_deref().and_then(Path::extension);
            let is = |name: &str| extension.is_some_and(|ext| ext.eq_ignore_ascii_case(name));
            if is("svg") {
                ReconstructFormat::Svg
            } else if is("geojson") {
                ReconstructFormat::Geojson
            } else {
                ReconstructFormat::Json
            }
        })
    }
}

/// Reads, reconstructs, writes.
pub fn run(args: &ReconstructArgs) -> Result<(), CliError> {
    let format = args.format();
    if !args.show.is_empty() && format != ReconstructFormat::Svg {
        return Err(CliError::bad_input(
            "--show draws underlays in a picture: it needs --format svg (or an OUTPUT ending in .svg); see 'wdm-crust reconstruct --help'",
        ));
    }
    if args.no_points && format != ReconstructFormat::Svg {
        return Err(CliError::bad_input(
            "--no-points leaves the points out of a picture: it needs --format svg (or an OUTPUT ending in .svg); see 'wdm-crust reconstruct --help'",
        ));
    }
    let options = args.options()?;
    let mut timings = Timings::new(args.common.timings);
    let input = Input::new(args.input.as_deref(), &args.columns);
    let output = Output::new(args.common.output.as_deref())?;

    let points = input.read_points_timed(&mut timings)?;

    let n = points.len();
    timings.begin(|| format!("triangulating {n} points"));
    // The library reports each phase as it ends; the next one begins right then. The
    // phases after the labels are printed as one, `extract`, with their split in its note.
    let mut extract_parts: Vec<(Phase, std::time::Duration)> = Vec::new();
    let rec = wdm_crust::reconstruct_observed(&points, &options, &mut |phase, time| {
        if matches!(
            phase,
            Phase::Triangulate | Phase::Thin | Phase::Voronoi | Phase::Label
        ) {
            timings.phase(phase.name(), String::new);
        } else {
            extract_parts.push((phase, time));
        }
        if let Some(next) = next_phase(&options, phase) {
            timings.begin(|| match next {
                Phase::Voronoi => "building the Voronoi diagram".to_string(),
                Phase::Label => "labeling by water flow".to_string(),
                Phase::Thin => "looking for a dense noisy band".to_string(),
                _ => format!("extracting ({})", options.algorithm().name()),
            });
        }
    })
    .map_err(|e| input.library_error(&e))?;
    timings.phase("extract", || {
        let split: Vec<String> = extract_parts
            .iter()
            .map(|(phase, time)| format!("{} {:.1}", phase.name(), time.as_secs_f64() * 1e3))
            .collect();
        format!(
            "{}, {}, {}, {} (ms: {})",
            counted(rec.edges().len(), "edge", "edges"),
            curve_counts(&rec),
            counted(
                rec.medial_axis().edges.len(),
                "medial-axis edge",
                "medial-axis edges"
            ),
            counted(rec.passes(), "pass", "passes"),
            split.join(", ")
        )
    });

    let name = input.name();
    for warning in rec.warnings() {
        report::warning(&name, warning);
    }
    let infinite = rec
        .medial_axis()
        .vertices
        .iter()
        .filter(|p| p.iter().any(|x| !x.is_finite()))
        .count();
    super::note_infinite_vertices(&input, infinite, "medial-axis vertices");
    let mut svg = SvgOptions::default();
    svg.delaunay = args.show.contains(&Layer::Delaunay);
    svg.voronoi = args.show.contains(&Layer::Voronoi);
    svg.labels = args.show.contains(&Layer::Labels);
    svg.y_down = args.y_down;
    svg.points = !args.no_points;
    let what = || {
        format!(
            "{}, {}, {}",
            curve_counts(&rec),
            counted(
                rec.unassigned().len(),
                "point on no curve",
                "points on no curve"
            ),
            counted(rec.duplicates().len(), "duplicate", "duplicates")
        )
    };
    write_timed(&output, &mut timings, n, what, |out| match format {
        ReconstructFormat::Json => write_reconstruction_json(&rec, out),
        ReconstructFormat::Text => write_reconstruction_text(&rec, out),
        ReconstructFormat::Svg => write_reconstruction_svg(&rec, &svg, out),
        ReconstructFormat::Geojson => write_reconstruction_geojson(&rec, out),
    })
}

/// `1 closed curve, 2 open chains`.
fn curve_counts(rec: &wdm_crust::Reconstruction) -> String {
    let closed = rec.curves().iter().filter(|c| c.closed).count();
    format!(
        "{}, {}",
        counted(closed, "closed curve", "closed curves"),
        counted(rec.curves().len() - closed, "open chain", "open chains")
    )
}

/// The phase after `phase` in the pipeline `options` ask for (after thinning that chose
/// representatives: their triangulation, reported as the Voronoi diagram's beginning).
fn next_phase(options: &wdm_crust::reconstruct::Options, phase: Phase) -> Option<Phase> {
    match (options.algorithm(), phase) {
        (Algorithm::Wdm, Phase::Triangulate) if options.thinning() => Some(Phase::Thin),
        (Algorithm::Wdm, Phase::Thin | Phase::Triangulate) => Some(Phase::Voronoi),
        (Algorithm::Wdm, Phase::Voronoi) => Some(Phase::Label),
        (Algorithm::Wdm, Phase::Label) => Some(Phase::Extract),
        (_, Phase::Triangulate) => Some(Phase::Extract),
        _ => None,
    }
}
