//! Real point sets from published curve-reconstruction work (GPL-3.0 data, copied into
//! `tests/data`; origins in `tests/data/README.md`): recall and precision against the known
//! point order, guarded from below. A missing data file fails the test; nothing is skipped.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

/// The real point sets, inside the repository.
const DATA: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data");

/// `tests/data/<rel>`, which must exist: a missing file fails the test.
fn data_path(rel: &str) -> PathBuf {
    let path = Path::new(DATA).join(rel);
    assert!(
        path.exists(),
        "test data {} is missing (the real point sets live in tests/data, see its README.md)",
        path.display()
    );
    path
}

fn read(file: &str) -> Vec<[f64; 2]> {
    let path = data_path(file);
    wdm_crust::io::read_points_from_path(&path)
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// Recall and precision of the reconstruction against the closed polygon in file order.
fn recall_precision(points: &[[f64; 2]]) -> (f64, f64) {
    let n = points.len() as u32;
    let truth: BTreeSet<[u32; 2]> = (0..n)
        .map(|i| [i.min((i + 1) % n), i.max((i + 1) % n)])
        .collect();
    let rec = wdm_crust::reconstruct(points).unwrap();
    let ours: BTreeSet<[u32; 2]> = rec.edges().iter().copied().collect();
    let hits = truth.intersection(&ours).count() as f64;
    (hits / truth.len() as f64, hits / ours.len().max(1) as f64)
}

#[test]
fn ordered_sets_reach_their_recall_and_precision() {
    // (file, recall at least, precision at least): measured values rounded down by ~0.02.
    // The fitconnect sets carry 2 % noise, Circle0 is stair-stepped, mushroom is very sparse
    // with thin spikes: none of them is an ε-sample, so the polygon is not expected exactly.
    // Recall counts every point of the file-order polygon: the points peeling reports as
    // unassigned (noise leftovers, and structure within 1.5 sample spacings of the outline
    // found first, such as the crab's legs) count as misses.
    let cases = [
        // Mushroom's gills lie within 1.5 cap spacings of the sparse cap: peeling takes most
        // of them for noise leftovers and reports them unassigned (see reconstruct/repairs/peel.rs);
        // a later pass draws a 7-point loop through the others since its ear is dropped
        // (reconstruct/repairs/ears.rs; before: recall 0.49, precision 0.88).
        ("hnn-crust-sgp16/mushroom.p2d", 0.53, 0.80),
        ("fitconnect/data/apple_2percent_noise.txt", 0.51, 0.70),
        ("fitconnect/data/butterfly_2percent_noise.txt", 0.66, 0.79),
        ("fitconnect/data/crab_2percent_noise.txt", 0.29, 0.64),
        ("fitconnect/data/dolphin_2percent_noise.txt", 0.44, 0.64),
        ("stretchdenoise/data/Circle0.txt", 0.67, 0.80),
        ("stretchdenoise/data/drill.txt", 0.90, 0.95),
        ("stretchdenoise/data/thing.txt", 0.96, 0.97),
    ];
    for (file, min_recall, min_precision) in cases {
        let (recall, precision) = recall_precision(&read(file));
        eprintln!("{file}: recall {recall:.3}, precision {precision:.3}");
        assert!(recall >= min_recall, "{file}: recall {recall:.3}");
        assert!(
            precision >= min_precision,
            "{file}: precision {precision:.3}"
        );
    }
}

/// Ground truth of a "components" file: consecutive points, a component closing where the
/// gap to the next point exceeds three times the median gap (the files have no break marker).
fn component_edges(points: &[[f64; 2]]) -> BTreeSet<[u32; 2]> {
    let n = points.len();
    let gap = |i: usize| {
        ((points[i + 1][0] - points[i][0]).powi(2) + (points[i + 1][1] - points[i][1]).powi(2))
            .sqrt()
    };
    let mut gaps: Vec<f64> = (0..n - 1).map(gap).collect();
    gaps.sort_by(f64::total_cmp);
    let median = gaps[gaps.len() / 2];
    let mut truth = BTreeSet::new();
    let mut start = 0;
    for i in 0..n {
        if i + 1 < n && gap(i) <= 3.0 * median {
            truth.insert([i as u32, i as u32 + 1]);
        } else {
            if i > start + 1 {
                truth.insert([start as u32, i as u32]);
            }
            start = i + 1;
        }
    }
    truth
}

#[test]
fn multi_curve_sets_keep_their_recall() {
    // Sparse multi-curve sets from HNN-Crust (crust is known to fail on the crocodile);
    // measured values rounded down by ~0.02. The ventilator's spiral turns lie about one
    // sample spacing apart: peeling reports most inner turns as unassigned, and draws one
    // zigzag loop across them (since later passes leave out isolated leftovers and may
    // close a loop by a chord: recall 0.31, precision 0.79; before 0.22, 0.93).
    for (file, min_recall, min_precision) in [
        ("hnn-crust-sgp16/crocodile-conf.p2d", 0.34, 0.61),
        ("hnn-crust-sgp16/ventilator.p2d", 0.29, 0.77),
    ] {
        let points = read(file);
        let truth = component_edges(&points);
        let rec = wdm_crust::reconstruct(&points).unwrap();
        let ours: BTreeSet<[u32; 2]> = rec.edges().iter().copied().collect();
        let hits = truth.intersection(&ours).count() as f64;
        let (recall, precision) = (hits / truth.len() as f64, hits / ours.len() as f64);
        eprintln!(
            "{file}: recall {recall:.3}, precision {precision:.3}, {} curves",
            rec.curves().len()
        );
        assert!(
            recall >= min_recall && precision >= min_precision,
            "{file}: {recall:.3} / {precision:.3}"
        );
    }
}

#[test]
fn every_data_file_triangulates_and_reconstructs() {
    let mut files = Vec::new();
    for sub in ["hnn-crust-sgp16", "fitconnect/data", "stretchdenoise/data"] {
        for entry in std::fs::read_dir(data_path(sub)).unwrap() {
            let path = entry.unwrap().path();
            if matches!(
                path.extension().and_then(|e| e.to_str()),
                Some("p2d" | "txt" | "xy" | "xym" | "gtn")
            ) {
                files.push(path);
            }
        }
    }
    // Every real point set in tests/data: a lost file fails here.
    assert_eq!(files.len(), 29, "real point sets in {DATA}");
    for path in files {
        let points = wdm_crust::io::read_points_from_path(&path).unwrap();
        let tri = wdm_crust::triangulate(&points).unwrap();
        tri.validate()
            .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let rec = wdm_crust::reconstruct(&points).unwrap();
        assert!(!rec.edges().is_empty(), "{}", path.display());
    }
}

/// Axis segments that properly cross an edge of a closed curve of the same reconstruction
/// (exact orientations on the f64 coordinates).
fn axis_crossings(points: &[[f64; 2]], rec: &wdm_crust::Reconstruction) -> usize {
    use wdm_crust::predicates::{orient2d, Orientation};
    let opposite = |s: Orientation, t: Orientation| {
        matches!(
            (s, t),
            (Orientation::Clockwise, Orientation::CounterClockwise)
                | (Orientation::CounterClockwise, Orientation::Clockwise)
        )
    };
    let axis = rec.medial_axis();
    let mut crossings = 0;
    for curve in rec.curves().iter().filter(|c| c.closed) {
        let n = curve.points.len();
        for k in 0..n {
            let (p, q) = (
                points[curve.points[k] as usize],
                points[curve.points[(k + 1) % n] as usize],
            );
            for &[a, b] in &axis.edges {
                let (u, v) = (axis.vertices[a as usize], axis.vertices[b as usize]);
                if opposite(orient2d(p, q, u), orient2d(p, q, v))
                    && opposite(orient2d(u, v, p), orient2d(u, v, q))
                {
                    crossings += 1;
                }
            }
        }
    }
    crossings
}

/// On scans whose later peeling passes close small loops by edges that are no Delaunay
/// edges of the loops' own points (`fish.txt`, `drillcase_xyz.txt`), the faces those edges
/// pass through lie on the loop. Before, the loop was left open there, which faces were
/// inside depended on the order of the search, and the axis ran across the curves (2 and 4
/// crossings). (Some other files cross a curve for other reasons: `stair.xy` 17 times,
/// `Keyboard0.txt` and `family.p2d` twice; not examined.) `fish.txt` is a dense band, which
/// the default thins (one loop through the band's middle): the peeling passes are read
/// with thinning off, and the default's axis crosses no curve either.
#[test]
fn the_medial_axis_of_loops_closed_by_later_passes_crosses_no_curve() {
    let unthinned = wdm_crust::reconstruct::Options::new().with_thinning(false);
    for file in [
        "fitconnect/data/fish.txt",
        "stretchdenoise/data/drillcase_xyz.txt",
    ] {
        let points = read(file);
        let rec = wdm_crust::reconstruct_with(&points, &unthinned).unwrap();
        assert!(
            rec.curves().iter().filter(|c| c.closed).count() >= 2,
            "{file}"
        );
        assert!(!rec.medial_axis().edges.is_empty(), "{file}");
        assert_eq!(axis_crossings(&points, &rec), 0, "{file}");
        let default = wdm_crust::reconstruct(&points).unwrap();
        assert!(!default.medial_axis().edges.is_empty(), "{file}");
        assert_eq!(axis_crossings(&points, &default), 0, "{file}: default");
    }
}
