//! What the page asks of the engine, in plain Rust: reading a point file, the options from
//! the page's controls, the reconstruction, what is drawn, the summary in words and the
//! downloads. The `#[wasm_bindgen]` layer in `lib.rs` only converts; everything here also
//! runs (and is tested) natively.

use std::path::Path;
use std::time::Duration;

use wdm_crust::delaunay::NO_TWIN;
use wdm_crust::io::{
    format_from_path, read_points_with, write_reconstruction_geojson, write_reconstruction_json,
    write_reconstruction_svg, ReadOptions, SvgOptions,
};
use wdm_crust::reconstruct::{
    reconstruct_observed, Algorithm, Label, MedialAxisMode, Options, Phase,
};
use wdm_crust::Reconstruction;

/// Reads the points of the file `name` (its extension picks `.node`/`.gtn` and `.csv` as the
/// command line's does; anything else is told from the content) from its bytes.
///
/// # Errors
/// The parser's message, after the file name: `bad.txt: line 2: ...`.
pub fn read_points(name: &str, bytes: &[u8]) -> Result<Vec<[f64; 2]>, String> {
    let mut options = ReadOptions::new();
    if let Some(format) = format_from_path(Path::new(name)) {
        options = options.with_format(format);
    }
    read_points_with(bytes, &options).map_err(|e| format!("{name}: {e}"))
}

/// The choices of the page's controls, named as the command line's options are.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Choices {
    /// `wdm`, `crust` or `nn-crust` (`--algorithm`).
    pub algorithm: String,
    /// Peeling (WDM; off is `--no-peeling`).
    pub peeling: bool,
    /// `pruned`, `raw` or `none` (`--medial-axis`; WDM, where `none` is also the baselines').
    pub medial_axis: String,
    /// `--smooth`.
    pub smoothing: bool,
    /// Thinning of dense noisy bands (WDM; off is `--no-thinning`).
    pub thinning: bool,
}

/// The library's options for `choices`, set as the command line sets them from the same
/// options: the WDM settings only for WDM, so that the baselines run as
/// `--algorithm crust` does.
///
/// # Errors
/// An unknown algorithm or medial-axis mode.
pub fn options(choices: &Choices) -> Result<Options, String> {
    let algorithm = match choices.algorithm.as_str() {
        "wdm" => Algorithm::Wdm,
        "crust" => Algorithm::Crust,
        "nn-crust" => Algorithm::NnCrust,
        other => {
            return Err(format!(
                "unknown algorithm {other:?}: wdm, crust or nn-crust"
            ))
        }
    };
    let mode = match choices.medial_axis.as_str() {
        "pruned" => MedialAxisMode::Pruned,
        "raw" => MedialAxisMode::Raw,
        "none" => MedialAxisMode::Omitted,
        other => {
            return Err(format!(
                "unknown medial-axis mode {other:?}: pruned, raw or none"
            ))
        }
    };
    let mut options = Options::new()
        .with_algorithm(algorithm)
        .with_smoothing(choices.smoothing);
    if algorithm == Algorithm::Wdm {
        options = options.with_peeling(choices.peeling).with_medial_axis(mode);
        if !choices.thinning {
            options = options.with_thinning(false);
        }
    }
    options.check().map_err(|conflict| conflict.reason())?;
    Ok(options)
}

/// Reconstructs `points`, calling `on_phase` with each phase's name as it ends.
///
/// # Errors
/// The library's error about the points (a coordinate that is not finite, too many points).
pub fn reconstruct(
    points: &[[f64; 2]],
    options: &Options,
    on_phase: &mut dyn FnMut(&'static str),
) -> Result<Reconstruction, String> {
    reconstruct_observed(points, options, &mut |phase: Phase, _: Duration| {
        on_phase(phase.name())
    })
    .map_err(|e| e.to_string())
}

/// `1 closed curve`, `2 closed curves`.
fn counted(n: usize, one: &str, many: &str) -> String {
    match n {
        1 => format!("1 {one}"),
        _ => format!("{n} {many}"),
    }
}

/// The result in words, as the command line's summary line says it: `1 closed curve, 0 open
/// chains, 0 points on no curve, 0 duplicates`, then the points, edges, medial axis and
/// passes.
pub fn summary(rec: &Reconstruction) -> String {
    let closed = rec.curves().iter().filter(|c| c.closed).count();
    let axis = match rec.medial_axis_mode() {
        Some(MedialAxisMode::Omitted) | None => "no medial axis".to_string(),
        Some(mode) => format!(
            "{} ({})",
            counted(
                rec.medial_axis().edges.len(),
                "medial-axis edge",
                "medial-axis edges"
            ),
            mode.name()
        ),
    };
    format!(
        "{}, {}, {}, {}. {} by {}: {}, {}, {}{}{}.",
        counted(closed, "closed curve", "closed curves"),
        counted(rec.curves().len() - closed, "open chain", "open chains"),
        counted(
            rec.unassigned().len(),
            "point on no curve",
            "points on no curve"
        ),
        counted(rec.duplicates().len(), "duplicate", "duplicates"),
        counted(rec.triangulation().point_count(), "point", "points"),
        rec.algorithm().name(),
        counted(rec.edges().len(), "edge", "edges"),
        axis,
        counted(rec.passes(), "pass", "passes"),
        if rec.smoothed() { ", smoothed" } else { "" },
        rec.thinned().map_or(String::new(), |n| format!(
            ", a dense band thinned to {}",
            counted(n, "representative", "representatives")
        )),
    )
}

/// The warnings as the command line prints them after `warning: <file>: `: the message and
/// its code in brackets.
pub fn warnings(rec: &Reconstruction) -> Vec<String> {
    rec.warnings().iter().map(ToString::to_string).collect()
}

/// What the page draws, flat, for typed arrays: points as `x, y` pairs, edges as index
/// pairs, all in the caller's indices and coordinates.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Drawing {
    /// Whether each curve is closed (1) or an open chain (0).
    pub curve_closed: Vec<u8>,
    /// Where each curve's points start in `curve_points`, and their end: one more than curves.
    pub curve_offsets: Vec<u32>,
    /// The curves' points, one after the other.
    pub curve_points: Vec<u32>,
    /// The curve vertices' positions, pairwise for `curve_points` (the fitted ones with
    /// smoothing, else the points').
    pub curve_coords: Vec<f64>,
    /// The points on no curve.
    pub unassigned: Vec<u32>,
    /// The medial axis' vertices and its edges over them.
    pub axis_vertices: Vec<f64>,
    /// See `axis_vertices`.
    pub axis_edges: Vec<u32>,
    /// Every Delaunay edge once (for collinear input, the chain of the points).
    pub delaunay_edges: Vec<u32>,
    /// The Voronoi vertices' positions (only when asked for).
    pub voronoi_vertices: Vec<f64>,
    /// The finite Voronoi edges over `voronoi_vertices`.
    pub voronoi_edges: Vec<u32>,
    /// The rays: vertex, then the outward direction, `v, dx, dy` in threes.
    pub voronoi_rays: Vec<f64>,
    /// For collinear input, the point pairs whose bisectors are the diagram.
    pub voronoi_bisectors: Vec<u32>,
    /// Each Voronoi vertex's water-flow label, inner 1 and outer 0 (WDM only; empty for the
    /// baselines or when the Voronoi diagram was not asked for).
    pub labels: Vec<u8>,
    /// The points each warning is about, in one list.
    pub warning_points: Vec<u32>,
}

/// The drawing of `rec`; the Voronoi diagram and the labels only `with_voronoi`.
pub fn drawing(rec: &Reconstruction, with_voronoi: bool) -> Drawing {
    let tri = rec.triangulation();
    let mut d = Drawing::default();
    d.curve_offsets.push(0);
    for curve in rec.curves() {
        d.curve_closed.push(u8::from(curve.closed));
        d.curve_points.extend_from_slice(&curve.points);
        for &i in &curve.points {
            d.curve_coords
                .extend(rec.curve_vertex(i).unwrap_or_else(|| tri.point(i)));
        }
        d.curve_offsets.push(d.curve_points.len() as u32);
    }
    d.unassigned = rec.unassigned().to_vec();
    let axis = rec.medial_axis();
    d.axis_vertices = axis.vertices.iter().flatten().copied().collect();
    d.axis_edges = axis.edges.iter().flatten().copied().collect();
    if tri.is_degenerate() {
        let hull = tri.hull();
        d.delaunay_edges = hull
            .clone()
            .zip(hull.skip(1))
            .flat_map(|(a, b)| [a, b])
            .collect();
    } else {
        for (e, &twin) in tri.halfedge_ids().zip(tri.halfedges()) {
            if twin == NO_TWIN || e < twin {
                d.delaunay_edges
                    .extend([tri.halfedge_origin(e), tri.halfedge_destination(e)]);
            }
        }
    }
    if with_voronoi {
        let vor = tri.voronoi();
        d.voronoi_vertices = vor.vertex_positions().iter().flatten().copied().collect();
        for (_, a, b) in vor.finite_edges() {
            d.voronoi_edges.extend([a.get(), b.get()]);
        }
        for (_, v, [dx, dy]) in vor.rays() {
            d.voronoi_rays.extend([f64::from(v.get()), dx, dy]);
        }
        d.voronoi_bisectors = vor.collinear_bisectors().into_iter().flatten().collect();
        d.labels = rec
            .labels()
            .iter()
            .map(|&label| u8::from(label == Label::Inner))
            .collect();
    }
    d.warning_points = rec
        .warnings()
        .iter()
        .flat_map(|w| w.points.iter().copied())
        .collect();
    d
}

/// The layers of a downloaded SVG picture.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct SvgLayers {
    /// `--show delaunay`.
    pub delaunay: bool,
    /// `--show voronoi`.
    pub voronoi: bool,
    /// `--show labels` (WDM only: the baselines have no labels to draw).
    pub labels: bool,
    /// `--y-down`.
    pub y_down: bool,
}

/// The SVG picture the command line writes with the same layers.
pub fn svg(rec: &Reconstruction, layers: SvgLayers) -> String {
    let mut options = SvgOptions::default();
    options.delaunay = layers.delaunay;
    options.voronoi = layers.voronoi;
    options.labels = layers.labels && rec.algorithm() == Algorithm::Wdm;
    options.y_down = layers.y_down;
    written(|out| write_reconstruction_svg(rec, &options, out))
}

/// The GeoJSON the command line writes (`--format geojson`).
pub fn geojson(rec: &Reconstruction) -> String {
    written(|out| write_reconstruction_geojson(rec, out))
}

/// The JSON the command line writes (`--format json`).
pub fn json(rec: &Reconstruction) -> String {
    written(|out| write_reconstruction_json(rec, out))
}

/// What a writer writes into memory, which cannot fail, as text (the writers write UTF-8).
fn written(write: impl FnOnce(&mut Vec<u8>) -> std::io::Result<()>) -> String {
    let mut out = Vec::new();
    write(&mut out).expect("writing into memory does not fail");
    String::from_utf8(out).expect("the writers write UTF-8")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn choices(algorithm: &str) -> Choices {
        Choices {
            algorithm: algorithm.to_string(),
            peeling: true,
            medial_axis: "pruned".to_string(),
            smoothing: false,
            thinning: true,
        }
    }

    fn circle(n: usize) -> Vec<[f64; 2]> {
        (0..n)
            .map(|k| {
                let t = (k * 7 % n) as f64 * std::f64::consts::TAU / n as f64;
                [t.cos(), t.sin()]
            })
            .collect()
    }

    #[test]
    fn a_bad_line_is_named_after_the_file() {
        let err = read_points("bad.txt", b"1 2\n3 four\n").unwrap_err();
        let parser = wdm_crust::io::read_points(&b"1 2\n3 four\n"[..], None).unwrap_err();
        assert_eq!(err, format!("bad.txt: {parser}"));
        assert!(err.starts_with("bad.txt: line 2: "), "{err}");
    }

    #[test]
    fn the_extension_picks_the_format_as_on_the_command_line() {
        let node = b"3 2 0 0\n0 1.5 2\n1 3 4\n2 5 6\n";
        assert_eq!(
            read_points("a.node", node).unwrap(),
            vec![[1.5, 2.0], [3.0, 4.0], [5.0, 6.0]]
        );
        assert_eq!(
            read_points("a.csv", b"x,y\n1,2\n").unwrap(),
            vec![[1.0, 2.0]]
        );
    }

    #[test]
    fn options_are_the_command_lines() {
        let wdm = options(&Choices {
            peeling: false,
            medial_axis: "raw".to_string(),
            smoothing: true,
            thinning: false,
            ..choices("wdm")
        })
        .unwrap();
        let cli = Options::new()
            .with_peeling(false)
            .with_medial_axis(MedialAxisMode::Raw)
            .with_smoothing(true)
            .with_thinning(false);
        assert_eq!(wdm, cli.with_peeling(false));
        // The baselines take no WDM setting, whatever the controls say.
        let crust = options(&choices("crust")).unwrap();
        assert_eq!(
            crust,
            Options::new()
                .with_algorithm(Algorithm::Crust)
                .with_smoothing(false)
        );
        assert!(options(&choices("alpha")).unwrap_err().contains("alpha"));
    }

    #[test]
    fn the_summary_starts_with_the_counts_and_the_json_is_the_libraries() {
        let points = circle(24);
        let mut phases = Vec::new();
        let rec = reconstruct(&points, &options(&choices("wdm")).unwrap(), &mut |p| {
            phases.push(p)
        })
        .unwrap();
        assert_eq!(phases.first(), Some(&"triangulate"));
        let text = summary(&rec);
        assert!(
            text.starts_with("1 closed curve, 0 open chains, 0 points on no curve, 0 duplicates. 24 points by wdm: 24 edges"),
            "{text}"
        );
        let mut expected = Vec::new();
        write_reconstruction_json(&rec, &mut expected).unwrap();
        assert_eq!(json(&rec).as_bytes(), expected);
        assert!(svg(&rec, SvgLayers::default()).starts_with("<svg "));
        assert!(geojson(&rec).contains("\"Polygon\""));
    }

    #[test]
    fn the_drawing_holds_every_curve_point_and_edge() {
        let points = circle(30);
        let rec = reconstruct(&points, &Options::new(), &mut |_| {}).unwrap();
        let d = drawing(&rec, true);
        assert_eq!(d.curve_closed, vec![1]);
        assert_eq!(d.curve_offsets, vec![0, 30]);
        assert_eq!(d.curve_coords.len(), 60);
        for (k, &i) in d.curve_points.iter().enumerate() {
            assert_eq!(
                [d.curve_coords[2 * k], d.curve_coords[2 * k + 1]],
                points[i as usize]
            );
        }
        // Euler: a triangulation of n points with h on the hull has 3n - 3 - h edges.
        assert_eq!(d.delaunay_edges.len() / 2, 3 * 30 - 3 - 30);
        assert_eq!(d.labels.len(), d.voronoi_vertices.len() / 2);
        assert_eq!(d.voronoi_rays.len() / 3, 30);
        assert!(drawing(&rec, false).voronoi_vertices.is_empty());
    }

    #[test]
    fn an_error_of_the_engine_is_its_message() {
        let err = reconstruct(&[[0.0, f64::NAN]], &Options::new(), &mut |_| {}).unwrap_err();
        assert!(err.contains("finite"), "{err}");
    }
}
