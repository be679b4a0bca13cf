//! What the command line says on standard error: one summary line for a written file,
//! warnings when the result is probably not what was wanted, and nothing but errors with
//! `--quiet`.

use std::f64::consts::TAU;

use serde_json::Value;

mod common;
use common::{run_in, write};

fn points_text(points: &[[f64; 2]]) -> String {
    points
        .iter()
        .map(|p| format!("{} {}\n", p[0], p[1]))
        .collect()
}

fn circle(centre: [f64; 2], n: usize) -> Vec<[f64; 2]> {
    (0..n)
        .map(|k| {
            let t = k as f64 * TAU / n as f64;
            [centre[0] + t.cos(), centre[1] + t.sin()]
        })
        .collect()
}

/// Two unit circles of 200 points one spacing apart (they merge), and a duplicate point.
fn pinched() -> Vec<[f64; 2]> {
    let mut points = circle([0.0, 0.0], 200);
    points.extend(circle([2.0 + TAU / 200.0, 0.0], 200));
    points.push(points[7]);
    points
}

#[test]
fn a_written_file_gets_one_summary_line() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let mut points = circle([0.0, 0.0], 64);
    points.push(points[3]);
    write(d, "ring.txt", points_text(&points).as_bytes());
    let run = run_in(d, &["reconstruct", "ring.txt", "-o", "ring.svg"], b"");
    assert_eq!(run.code, 0, "{}", run.stderr);
    let lines: Vec<&str> = run.stderr.lines().collect();
    assert_eq!(lines.len(), 1, "{}", run.stderr);
    let line = lines[0];
    assert!(
        line.starts_with(
            "wdm-crust: wrote ring.svg: 1 closed curve, 0 open chains, 0 points on no curve, \
             1 duplicate; 65 points in "
        ),
        "{line}"
    );
    // To standard output: no summary (the output is the message).
    let run = run_in(d, &["reconstruct", "ring.txt"], b"");
    assert_eq!((run.code, run.stderr.as_str()), (0, ""));
    // triangulate and voronoi say what they wrote too.
    let run = run_in(d, &["triangulate", "ring.txt", "-o", "t.json"], b"");
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert!(
        run.stderr.starts_with(
            "wdm-crust: wrote t.json: 62 triangles, 64 hull points, 1 duplicate; 65 points in "
        ),
        "{}",
        run.stderr
    );
    let run = run_in(d, &["voronoi", "ring.txt", "-o", "cells.geojson"], b"");
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert!(
        run.stderr.starts_with("wdm-crust: wrote cells.geojson: ")
            && run
                .stderr
                .contains(" rays, 64 clipped cells; 65 points in "),
        "{}",
        run.stderr
    );
    assert_eq!(run.stderr.lines().count(), 1);
}

#[test]
fn warnings_go_to_standard_error_and_into_the_json() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write(d, "pinched.txt", points_text(&pinched()).as_bytes());
    let run = run_in(d, &["reconstruct", "pinched.txt", "-o", "out.json"], b"");
    assert_eq!(run.code, 0, "{}", run.stderr);
    let lines: Vec<&str> = run.stderr.lines().collect();
    assert_eq!(lines.len(), 2, "{}", run.stderr);
    assert!(
        lines[0].starts_with("warning: pinched.txt: curves pass within the sample spacing")
            && lines[0].ends_with("[curves-too-close]"),
        "{}",
        lines[0]
    );
    assert!(lines[1].starts_with("wdm-crust: wrote out.json: 1 closed curve, 0 open chains, 0 points on no curve, 1 duplicate;"));
    let json: Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("out.json")).unwrap()).unwrap();
    assert_eq!(json["duplicates"], serde_json::json!([[400, 7]]));
    let warnings = json["warnings"].as_array().unwrap();
    assert_eq!(warnings.len(), 1);
    assert_eq!(warnings[0]["code"], "curves-too-close");
    assert!(lines[0].contains(warnings[0]["message"].as_str().unwrap()));
    // GeoJSON: in the collection's properties.
    let run = run_in(
        d,
        &["reconstruct", "pinched.txt", "--format", "geojson"],
        b"",
    );
    assert_eq!(run.code, 0, "{}", run.stderr);
    let geojson: Value = serde_json::from_str(&run.stdout).unwrap();
    assert_eq!(geojson["type"], "FeatureCollection");
    assert_eq!(geojson["properties"]["duplicates"], json["duplicates"]);
    assert_eq!(geojson["properties"]["warnings"], json["warnings"]);
    // The warning is printed when the output goes to standard output too.
    assert_eq!(run.stderr.lines().count(), 1, "{}", run.stderr);
}

#[test]
fn quiet_leaves_only_errors() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write(d, "pinched.txt", points_text(&pinched()).as_bytes());
    write(d, "empty.txt", b"# nothing\n");
    for command in ["reconstruct", "triangulate", "voronoi"] {
        for input in ["pinched.txt", "empty.txt"] {
            let run = run_in(d, &[command, input, "-o", "out.json", "--quiet"], b"");
            assert_eq!(
                (run.code, run.stderr.as_str()),
                (0, ""),
                "{command} {input}"
            );
            let run = run_in(d, &[command, input, "-o", "out.json", "-q"], b"");
            assert_eq!(
                (run.code, run.stderr.as_str()),
                (0, ""),
                "{command} {input}"
            );
        }
        // Errors still print.
        let run = run_in(d, &[command, "missing.txt", "--quiet"], b"");
        assert_eq!(run.code, 2);
        assert!(
            run.stderr
                .starts_with("wdm-crust: missing.txt: cannot open"),
            "{}",
            run.stderr
        );
        // --quiet and --timings ask for opposite things.
        let run = run_in(d, &[command, "pinched.txt", "--quiet", "--timings"], b"");
        assert_eq!(run.code, 2);
        assert!(
            run.stderr
                .contains("'--quiet' cannot be used with '--timings'"),
            "{}",
            run.stderr
        );
    }
    // Without --quiet the empty input gets its note.
    let run = run_in(d, &["reconstruct", "empty.txt"], b"");
    assert!(
        run.stderr
            .starts_with("wdm-crust: note: empty.txt: no points"),
        "{}",
        run.stderr
    );
}

#[test]
fn timings_count_in_words() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write(
        d,
        "ring.txt",
        points_text(&circle([0.0, 0.0], 64)).as_bytes(),
    );
    let run = run_in(d, &["reconstruct", "ring.txt", "--timings"], b"");
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert!(
        run.stderr.contains("1 closed curve, 0 open chains"),
        "{}",
        run.stderr
    );
    assert!(run.stderr.contains(", 1 pass (ms:"), "{}", run.stderr);
}
