//! `wdm-crust voronoi --format geojson [--clip ...]` as a user runs it: the FeatureCollection
//! holds exactly the library's clipped cells, `-o *.geojson` and `--clip` imply the format,
//! and a bad `--clip` is a one-line usage error. (Shapely's checks of the same output are in
//! tests/python/test_geojson_voronoi.py.)

use serde_json::Value;
use wdm_crust::{triangulate, BoundingBox};

mod common;
use common::Run;

fn run(args: &[&str], input: &str) -> Run {
    common::run_in(std::path::Path::new("."), args, input.as_bytes())
}

const POINTS: &str = "0 0\n3 0.5\n1 2\n0 0\n2.5 2.5\n-1 1.25\n";

fn points() -> Vec<[f64; 2]> {
    POINTS
        .lines()
        .map(|l| {
            let v: Vec<f64> = l.split(' ').map(|x| x.parse().unwrap()).collect();
            [v[0], v[1]]
        })
        .collect()
}

/// The features as (site, closed ring) pairs, checking the GeoJSON structure on the way.
/// The coordinates are read from the text with Rust's correctly rounded `f64` parser
/// (serde_json's default one may be an ulp off), one feature per line.
fn features(text: &str) -> Vec<(u64, Option<Vec<[f64; 2]>>)> {
    let mut rings = text
        .lines()
        .filter(|l| l.contains("\"Feature\""))
        .map(|line| {
            let start = line.find("\"coordinates\":[[[")? + "\"coordinates\":[[[".len();
            let end = line[start..].find("]]]")? + start;
            Some(
                line[start..end]
                    .split("],[")
                    .map(|pair| {
                        let (x, y) = pair.split_once(',').expect("x,y");
                        [x.parse().expect("x"), y.parse().expect("y")]
                    })
                    .collect::<Vec<[f64; 2]>>(),
            )
        });
    let json: Value = serde_json::from_str(text).expect("valid JSON");
    assert_eq!(json["type"], "FeatureCollection");
    json["features"]
        .as_array()
        .expect("features")
        .iter()
        .map(|f| {
            assert_eq!(f["type"], "Feature");
            let site = f["properties"]["site"].as_u64().expect("site");
            let geometry = &f["geometry"];
            let ring = rings.next().expect("one feature per line");
            if geometry.is_null() {
                assert!(ring.is_none());
                return (site, None);
            }
            assert_eq!(geometry["type"], "Polygon");
            let parsed = geometry["coordinates"].as_array().expect("rings");
            assert_eq!(parsed.len(), 1);
            let ring = ring.expect("coordinates");
            assert_eq!(parsed[0].as_array().expect("ring").len(), ring.len());
            (site, Some(ring))
        })
        .collect()
}

fn expected(bbox: &BoundingBox) -> Vec<(u64, Option<Vec<[f64; 2]>>)> {
    let pts = points();
    let tri = triangulate(&pts).unwrap();
    let cells = tri.voronoi().clipped_cells(bbox);
    cells
        .into_iter()
        .enumerate()
        .filter(|&(i, _)| !tri.is_duplicate(i as u32))
        .map(|(i, ring)| {
            let closed = (!ring.is_empty()).then(|| {
                let mut closed = ring.clone();
                closed.push(ring[0]);
                closed
            });
            (i as u64, closed)
        })
        .collect()
}

#[test]
fn geojson_holds_the_library_cells_bit_for_bit() {
    let out = run(&["voronoi", "--format", "geojson"], POINTS);
    assert_eq!(out.code, 0, "{}", out.stderr);
    let bbox = BoundingBox::around(&points()).unwrap();
    let got = features(&out.stdout);
    assert_eq!(got, expected(&bbox));
    // Point 3 duplicates point 0: no feature.
    assert_eq!(got.iter().map(|f| f.0).collect::<Vec<_>>(), [0, 1, 2, 4, 5]);
}

#[test]
fn clip_implies_geojson_and_sites_outside_get_null() {
    let out = run(&["voronoi", "--clip", "-0.5,-0.5,1.5,1"], POINTS);
    assert_eq!(out.code, 0, "{}", out.stderr);
    let bbox = BoundingBox::new([-0.5, -0.5], [1.5, 1.0]).unwrap();
    let got = features(&out.stdout);
    assert_eq!(got, expected(&bbox));
    assert!(
        got.iter().any(|f| f.1.is_none()),
        "some cell should miss the box"
    );
}

#[test]
fn an_output_ending_in_geojson_implies_the_format() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("cells.GeoJSON");
    let out = run(&["voronoi", "-o", path.to_str().unwrap()], POINTS);
    assert_eq!(out.code, 0, "{}", out.stderr);
    let bbox = BoundingBox::around(&points()).unwrap();
    assert_eq!(
        features(&std::fs::read_to_string(&path).unwrap()),
        expected(&bbox)
    );
    // The other formats are unchanged by the new flag's absence.
    let json = run(&["voronoi"], POINTS);
    let value: Value = serde_json::from_str(&json.stdout).unwrap();
    assert!(value.get("vertices").is_some() && value.get("type").is_none());
}

#[test]
fn a_bad_clip_is_a_one_line_usage_error() {
    for (clip, message) in [
        (
            "1,0,0,1",
            "box has no interior: xmin = 1 is not below xmax = 0",
        ),
        (
            "0,1,1,1",
            "box has no interior: ymin = 1 is not below ymax = 1",
        ),
        ("0,0,inf,1", "box coordinate inf is not a finite number"),
        ("0,0,NaN,1", "box coordinate NaN is not a finite number"),
        ("0,0,1", "expected four comma-separated numbers"),
        ("0,0,1,x", "'x' is not a number"),
    ] {
        let out = run(&["voronoi", "--clip", clip], POINTS);
        assert_eq!(out.code, 2, "{clip}");
        assert!(out.stdout.is_empty());
        let stderr = out.stderr;
        assert_eq!(stderr.lines().count(), 1, "{stderr}");
        assert!(stderr.contains(message), "{clip}: {stderr}");
    }
    let out = run(
        &["voronoi", "--clip", "0,0,1,1", "--format", "text"],
        POINTS,
    );
    assert_eq!(out.code, 2);
    let stderr = out.stderr;
    assert_eq!(stderr.lines().count(), 1);
    assert!(stderr.contains("--clip"), "{stderr}");
}

#[test]
fn no_points_give_an_empty_collection() {
    let out = run(&["voronoi", "--format", "geojson"], "");
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert!(features(&out.stdout).is_empty());
}
