//! `reconstruct --format geojson`'s writer checked for exact validity: rings closed, exterior
//! counterclockwise and holes clockwise (exact signed areas), no ring touching itself or
//! another ring of its polygon (exact segment tests), holes inside their exterior and not
//! inside each other, every coordinate the input's to the bit, and the features matching the
//! reconstruction. On generated shapes (holes, three levels of nesting, several curves, open
//! chains, degenerate input), on ε-samples of the SVG ground truth in tests/data, and on every
//! real point file there.

use std::path::Path;

use num_traits::Signed;
use serde_json::Value;
use wdm_crust::predicates::{orient2d, Orientation};
use wdm_crust::Reconstruction;
use wdm_crust_testkit::{svg_dense_curves, CurveSet, DenseCurve, Rng};

mod exact;
use exact::twice_area;

const DATA: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data");

fn geojson(rec: &Reconstruction) -> Value {
    let mut out = Vec::new();
    wdm_crust::io::write_reconstruction_geojson(rec, &mut out).unwrap();
    serde_json::from_slice(&out).expect("valid JSON")
}

fn position(v: &Value) -> [f64; 2] {
    let a = v.as_array().expect("a position");
    assert_eq!(a.len(), 2, "positions are [x, y]");
    [a[0].as_f64().unwrap(), a[1].as_f64().unwrap()]
}

fn positions(v: &Value) -> Vec<[f64; 2]> {
    v.as_array()
        .expect("positions")
        .iter()
        .map(position)
        .collect()
}

fn indices(v: &Value) -> Vec<u32> {
    v.as_array()
        .expect("indices")
        .iter()
        .map(|i| i.as_u64().unwrap() as u32)
        .collect()
}

/// Exact: `t` strictly inside the closed ring (which `t` is not on).
fn strictly_inside(ring: &[[f64; 2]], t: [f64; 2]) -> bool {
    let mut inside = false;
    for w in ring.windows(2) {
        let (p, q) = (w[0], w[1]);
        if (p[1] > t[1]) != (q[1] > t[1]) {
            let o = orient2d(p, q, t);
            assert_ne!(o, Orientation::Collinear, "{t:?} on the ring");
            let upward = q[1] > t[1];
            if (o == Orientation::CounterClockwise) == upward {
                inside = !inside;
            }
        }
    }
    inside
}

fn bbox_overlap(a: [[f64; 2]; 2], b: [[f64; 2]; 2]) -> bool {
    (0..2).all(|k| {
        a[0][k].min(a[1][k]) <= b[0][k].max(b[1][k]) && b[0][k].min(b[1][k]) <= a[0][k].max(a[1][k])
    })
}

/// Exact: do the closed segments share a point?
fn segments_meet(a: [[f64; 2]; 2], b: [[f64; 2]; 2]) -> bool {
    if !bbox_overlap(a, b) {
        return false;
    }
    let side = |o: Orientation| match o {
        Orientation::CounterClockwise => 1,
        Orientation::Clockwise => -1,
        Orientation::Collinear => 0,
    };
    let (o1, o2) = (
        side(orient2d(a[0], a[1], b[0])),
        side(orient2d(a[0], a[1], b[1])),
    );
    let (o3, o4) = (
        side(orient2d(b[0], b[1], a[0])),
        side(orient2d(b[0], b[1], a[1])),
    );
    // With overlapping boxes, collinear segments meet.
    o1 * o2 <= 0 && o3 * o4 <= 0
}

/// Adjacent segments `a → b`, `b → c` meet only at `b`: no fold back along the line.
fn folds_back(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> bool {
    orient2d(a, b, c) == Orientation::Collinear
        && (0..2).all(|k| (a[k] - b[k]).signum() * (c[k] - b[k]).signum() >= 0.0)
}

/// The rings of one polygon: each closed, at least 4 positions; exterior CCW, holes CW; no
/// two segments meet except consecutive ones of a ring at their shared end; holes inside
/// the exterior and outside each other.
fn check_polygon_rings(rings: &[Vec<[f64; 2]>]) {
    assert!(!rings.is_empty());
    for (r, ring) in rings.iter().enumerate() {
        assert!(ring.len() >= 4, "ring {r} has {} positions", ring.len());
        assert_eq!(ring.first(), ring.last(), "ring {r} is closed");
        let area = twice_area(ring);
        if r == 0 {
            assert!(area.is_positive(), "the exterior runs counterclockwise");
        } else {
            assert!(area.is_negative(), "hole {r} runs clockwise");
        }
        let k = ring.len() - 1;
        for i in 0..k {
            assert!(
                !folds_back(ring[i], ring[i + 1], ring[(i + 2) % k]),
                "ring {r} folds back at {i}"
            );
        }
    }
    // Every segment, swept by its left end.
    let mut segments: Vec<(usize, usize, [[f64; 2]; 2])> = Vec::new();
    for (r, ring) in rings.iter().enumerate() {
        for i in 0..ring.len() - 1 {
            segments.push((r, i, [ring[i], ring[i + 1]]));
        }
    }
    let left = |s: &[[f64; 2]; 2]| s[0][0].min(s[1][0]);
    let right = |s: &[[f64; 2]; 2]| s[0][0].max(s[1][0]);
    segments.sort_by(|a, b| left(&a.2).total_cmp(&left(&b.2)));
    for (x, &(ra, ia, sa)) in segments.iter().enumerate() {
        for &(rb, ib, sb) in &segments[x + 1..] {
            if left(&sb) > right(&sa) {
                break;
            }
            let k = rings[ra].len() - 1;
            let adjacent = ra == rb && (ia + 1) % k == ib || (ib + 1) % k == ia;
            if ra == rb && adjacent {
                continue; // their shared end, checked by folds_back
            }
            assert!(
                !segments_meet(sa, sb),
                "segments {ia} of ring {ra} and {ib} of ring {rb} meet"
            );
        }
    }
    for (h, hole) in rings.iter().enumerate().skip(1) {
        assert!(
            strictly_inside(&rings[0], hole[0]),
            "hole {h} is inside the exterior"
        );
        for (g, other) in rings.iter().enumerate().skip(1) {
            if g != h {
                assert!(
                    !strictly_inside(other, hole[0]),
                    "hole {h} is inside hole {g}"
                );
            }
        }
    }
}

/// The whole GeoJSON of `rec` against the contract and exact validity.
fn check(rec: &Reconstruction, points: &[[f64; 2]]) -> Value {
    let json = geojson(rec);
    assert_eq!(json["type"], "FeatureCollection");
    let features = json["features"].as_array().unwrap();
    let point = |i: u32| points[i as usize];
    let same_bits = |a: [f64; 2], b: [f64; 2]| {
        a[0].to_bits() == b[0].to_bits() && a[1].to_bits() == b[1].to_bits()
    };
    let mut ring_sets: Vec<Vec<u32>> = Vec::new();
    let mut chains = Vec::new();
    let (mut axes, mut unassigned) = (0, None);
    let mut last_kind = 0;
    for f in features {
        assert_eq!(f["type"], "Feature");
        let (geometry, properties) = (&f["geometry"], &f["properties"]);
        let kind = properties["kind"].as_str().unwrap();
        let rank = ["curve", "chain", "medial_axis", "unassigned"]
            .iter()
            .position(|&k| k == kind)
            .expect("a known kind");
        assert!(rank >= last_kind, "features in contract order");
        last_kind = rank;
        match kind {
            "curve" => {
                assert_eq!(geometry["type"], "Polygon");
                let rings: Vec<Vec<[f64; 2]>> = geometry["coordinates"]
                    .as_array()
                    .unwrap()
                    .iter()
                    .map(positions)
                    .collect();
                let mut named = vec![indices(&properties["points"])];
                named.extend(properties["holes"].as_array().unwrap().iter().map(indices));
                assert_eq!(named.len(), rings.len());
                for (ring, idx) in rings.iter().zip(&named) {
                    assert_eq!(ring.len(), idx.len() + 1);
                    for (p, &i) in ring.iter().zip(idx) {
                        assert!(same_bits(*p, point(i)), "the input's coordinates");
                    }
                    let mut set = idx.clone();
                    set.sort_unstable();
                    ring_sets.push(set);
                }
                check_polygon_rings(&rings);
            }
            "chain" => {
                assert_eq!(geometry["type"], "LineString");
                let line = positions(&geometry["coordinates"]);
                let idx = indices(&properties["points"]);
                assert!(line.len() >= 2);
                assert_eq!(line.len(), idx.len());
                for (p, &i) in line.iter().zip(&idx) {
                    assert!(same_bits(*p, point(i)));
                }
                chains.push(idx);
            }
            "medial_axis" => {
                assert_eq!(geometry["type"], "MultiLineString");
                let lines = geometry["coordinates"].as_array().unwrap();
                assert_eq!(lines.len(), rec.medial_axis().edges.len());
                for l in lines {
                    assert_eq!(positions(l).len(), 2);
                }
                axes += 1;
            }
            _ => {
                assert_eq!(geometry["type"], "MultiPoint");
                let idx = indices(&properties["points"]);
                assert!(!idx.is_empty(), "left out when empty");
                for (p, &i) in positions(&geometry["coordinates"]).iter().zip(&idx) {
                    assert!(same_bits(*p, point(i)));
                }
                unassigned = Some(idx);
            }
        }
    }
    assert_eq!(axes, 1, "one medial-axis feature");
    assert_eq!(unassigned.unwrap_or_default(), rec.unassigned());
    // Every closed curve is exactly one ring; every open chain one line string.
    let mut closed: Vec<Vec<u32>> = rec
        .curves()
        .iter()
        .filter(|c| c.closed)
        .map(|c| {
            let mut s = c.points.clone();
            s.sort_unstable();
            s
        })
        .collect();
    closed.sort();
    ring_sets.sort();
    assert_eq!(ring_sets, closed);
    let open: Vec<Vec<u32>> = rec
        .curves()
        .iter()
        .filter(|c| !c.closed)
        .map(|c| c.points.clone())
        .collect();
    assert_eq!(chains, open);
    json
}

fn circle(c: [f64; 2], r: f64, n: usize, phase: f64) -> Vec<[f64; 2]> {
    (0..n)
        .map(|k| {
            let t = phase + k as f64 * std::f64::consts::TAU / n as f64;
            [c[0] + r * t.cos(), c[1] + r * t.sin()]
        })
        .collect()
}

/// Polygons of the GeoJSON as (exterior size, hole sizes), sorted.
fn shape_summary(json: &Value) -> Vec<(usize, Vec<usize>)> {
    let mut out: Vec<(usize, Vec<usize>)> = json["features"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|f| f["properties"]["kind"] == "curve")
        .map(|f| {
            let p = &f["properties"];
            let mut holes: Vec<usize> = p["holes"]
                .as_array()
                .unwrap()
                .iter()
                .map(|h| indices(h).len())
                .collect();
            holes.sort_unstable();
            (indices(&p["points"]).len(), holes)
        })
        .collect();
    out.sort();
    out
}

#[test]
fn nested_three_levels_and_neighbours() {
    // Four concentric circles (depths 0..3): two polygons with one hole each; beside them a
    // ring with a hole and a plain disc.
    let mut points = Vec::new();
    for (r, n) in [(16.0, 160), (12.0, 120), (8.0, 80), (4.0, 40)] {
        points.extend(circle([0.0, 0.0], r, n, 0.1));
    }
    points.extend(circle([40.0, 0.0], 6.0, 60, 0.3));
    points.extend(circle([40.0, 0.0], 3.0, 30, 0.2));
    points.extend(circle([0.0, 30.0], 5.0, 50, 0.0));
    let mut rng = Rng::new(11);
    rng.shuffle(&mut points);
    let rec = wdm_crust::reconstruct(&points).unwrap();
    let json = check(&rec, &points);
    assert_eq!(
        shape_summary(&json),
        vec![
            (50, vec![]),
            (60, vec![30]),
            (80, vec![40]),
            (160, vec![120])
        ]
    );
}

#[test]
fn open_chains_and_degenerate_input() {
    // An arc (open chain) beside a closed circle.
    let mut points: Vec<[f64; 2]> = (0..30)
        .map(|k| {
            let t = k as f64 * 0.05;
            [20.0 + 10.0 * t.cos(), 10.0 * t.sin()]
        })
        .collect();
    points.extend(circle([0.0, 0.0], 3.0, 30, 0.0));
    let rec = wdm_crust::reconstruct(&points).unwrap();
    check(&rec, &points);

    let degenerate: Vec<Vec<[f64; 2]>> = vec![
        vec![],
        vec![[1.0, 2.0]],
        vec![[1.0, 2.0], [1.0, 2.0]],
        vec![[0.0, 0.0], [3.0, 1.0]],
        (0..12).map(|k| [k as f64, 2.0 * k as f64]).collect(),
        vec![[0.0, 0.0], [2.0, 0.0], [1.0, 1.0], [2.0, 0.0], [0.0, 0.0]],
        (0..36).map(|k| [(k % 6) as f64, (k / 6) as f64]).collect(),
    ];
    for points in degenerate {
        let rec = wdm_crust::reconstruct(&points).unwrap();
        check(&rec, &points);
    }
}

#[test]
fn held_out_samples_of_the_svg_ground_truth() {
    // ε-samples (some noisy, with outliers) of every SVG drawing, moved and shuffled.
    let mut rng = Rng::new(12);
    let dir = Path::new(DATA).join("sampling2d/data");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .expect("tests/data/sampling2d/data exists")
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "svg"))
        .collect();
    files.sort();
    assert!(files.len() >= 10, "the SVG drawings are there");
    for (k, path) in files.iter().enumerate() {
        let text = std::fs::read_to_string(path).unwrap();
        let curves: Vec<DenseCurve> =
            svg_dense_curves(&text, 4000).unwrap_or_else(|e| panic!("{}: {e:?}", path.display()));
        let set = CurveSet::new(curves);
        let mut sample = set.eps_sample(0.3, &mut rng).randomized(&mut rng);
        if k % 3 == 1 {
            sample = sample.with_lfs_noise(0.05, &mut rng);
        }
        if k % 3 == 2 {
            sample = sample.with_outliers(2.0, &mut rng);
        }
        let rec = wdm_crust::reconstruct(&sample.points).unwrap();
        check(&rec, &sample.points);
    }
}

#[test]
fn every_real_point_file() {
    let mut files = Vec::new();
    let mut stack = vec![Path::new(DATA).to_path_buf()];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
            } else if path
                .extension()
                .is_some_and(|e| ["txt", "p2d", "xy", "xym", "gtn"].iter().any(|x| e == *x))
                && !path.ends_with("GPL-3.0.txt")
            {
                files.push(path);
            }
        }
    }
    files.sort();
    assert!(
        files.len() >= 25,
        "the real point sets are there: {}",
        files.len()
    );
    for path in files {
        let points = wdm_crust::io::read_points_from_path(&path)
            .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let rec = wdm_crust::reconstruct(&points).unwrap();
        check(&rec, &points);
    }
}
