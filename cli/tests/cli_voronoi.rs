//! `wdm-crust voronoi` run as a user runs it: both output formats checked against the
//! library, collinear and duplicate points, every kind of bad input (exit code 2, a one-line
//! message naming the file and line, no partial output) and usage errors.

use std::fs;
use std::path::Path;

use serde_json::Value;

mod common;
use common::{listing, run_in, write};

fn close(a: f64, b: f64) -> bool {
    a == b || (a - b).abs() <= 1e-15 * a.abs().max(b.abs())
}

/// The diagram as plain data, from the library.
#[derive(Debug, PartialEq)]
struct Diagram {
    vertices: Vec<[f64; 2]>,
    edges: Vec<[u32; 2]>,
    rays: Vec<(u32, [f64; 2])>,
    cells: Vec<Vec<u32>>,
}

fn library_diagram(points: &[[f64; 2]]) -> Diagram {
    let tri = wdm_crust::triangulate(points).unwrap();
    let vor = tri.voronoi();
    Diagram {
        vertices: vor.vertex_positions().to_vec(),
        edges: vor
            .finite_edges()
            .map(|(_, a, b)| [a.get(), b.get()])
            .collect(),
        rays: vor.rays().map(|(_, v, d)| (v.get(), d)).collect(),
        cells: (0..points.len() as u32)
            .map(|p| vor.cell(p).map(|v| v.get()).collect())
            .collect(),
    }
}

fn assert_same(got: &Diagram, want: &Diagram) {
    assert_eq!(got.vertices.len(), want.vertices.len());
    for (a, b) in got.vertices.iter().zip(&want.vertices) {
        assert!(close(a[0], b[0]) && close(a[1], b[1]), "{a:?} {b:?}");
    }
    assert_eq!(got.edges, want.edges);
    assert_eq!(got.rays.len(), want.rays.len());
    for ((va, da), (vb, db)) in got.rays.iter().zip(&want.rays) {
        assert_eq!(va, vb);
        assert!(close(da[0], db[0]) && close(da[1], db[1]), "{da:?} {db:?}");
    }
    assert_eq!(got.cells, want.cells);
}

/// Parses and checks the JSON of a run against the library.
fn check_json(json: &str, points: &[[f64; 2]]) -> Diagram {
    assert!(json.ends_with('\n'));
    let value: Value = serde_json::from_str(json).expect("valid JSON");
    let keys: Vec<&str> = value
        .as_object()
        .unwrap()
        .keys()
        .map(String::as_str)
        .collect();
    assert_eq!(keys, ["cells", "edges", "rays", "vertices"]); // sorted by serde_json
    let at = |key: &str| json.find(&format!("\"{key}\":")).unwrap();
    assert!(json.starts_with("{\"vertices\":"));
    assert!(at("vertices") < at("edges") && at("edges") < at("rays") && at("rays") < at("cells"));
    let rays: Vec<(u32, f64, f64)> = serde_json::from_value(value["rays"].clone()).unwrap();
    let got = Diagram {
        vertices: serde_json::from_value(value["vertices"].clone()).unwrap(),
        edges: serde_json::from_value(value["edges"].clone()).unwrap(),
        rays: rays.into_iter().map(|(v, dx, dy)| (v, [dx, dy])).collect(),
        cells: serde_json::from_value(value["cells"].clone()).unwrap(),
    };
    assert_eq!(got.cells.len(), points.len());
    assert_same(&got, &library_diagram(points));
    got
}

/// Parses the text format back into a diagram, checking the count line.
fn parse_text(text: &str, points: usize) -> Diagram {
    let mut lines = text.lines();
    let header = lines.next().unwrap();
    assert!(header.starts_with(&format!("# wdm-crust voronoi: {points} points, ")));
    let mut diagram = Diagram {
        vertices: Vec::new(),
        edges: Vec::new(),
        rays: Vec::new(),
        cells: Vec::new(),
    };
    for line in lines {
        let mut fields = line.split(' ');
        let kind = fields.next().unwrap();
        let rest: Vec<&str> = fields.collect();
        match kind {
            "#" => {}
            "v" => diagram
                .vertices
                .push([rest[0].parse().unwrap(), rest[1].parse().unwrap()]),
            "e" => diagram
                .edges
                .push([rest[0].parse().unwrap(), rest[1].parse().unwrap()]),
            "r" => diagram.rays.push((
                rest[0].parse().unwrap(),
                [rest[1].parse().unwrap(), rest[2].parse().unwrap()],
            )),
            "c" => {
                assert_eq!(rest[0].parse::<usize>().unwrap(), diagram.cells.len());
                diagram
                    .cells
                    .push(rest[1..].iter().map(|t| t.parse().unwrap()).collect());
            }
            other => panic!("unknown record {other:?} in {line:?}"),
        }
    }
    assert!(header.ends_with(&format!(
        "{} vertices, {} edges, {} rays",
        diagram.vertices.len(),
        diagram.edges.len(),
        diagram.rays.len()
    )));
    diagram
}

/// A square with its centre, a duplicate, and a few more points.
const POINTS: &str = "0 0\n2 0\n2 2\n0 2\n1 0.5\n2 0\n3.5 1\n-1 1.25\n";

fn points() -> Vec<[f64; 2]> {
    wdm_crust::io::read_points(POINTS.as_bytes(), None).unwrap()
}

#[test]
fn json_and_text_match_the_library() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write(d, "in.txt", POINTS.as_bytes());
    let points = points();
    let run = run_in(d, &["voronoi", "in.txt"], b"");
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert_eq!(run.stderr, "");
    let json = check_json(&run.stdout, &points);
    assert!(!json.vertices.is_empty());
    // The duplicate (point 5 repeats point 1) has an empty cell; the centre a bounded one.
    assert!(json.cells[5].is_empty());
    assert_eq!(json.cells[4].len(), 4);

    let run = run_in(d, &["voronoi", "in.txt", "--format", "text"], b"");
    assert_eq!(run.code, 0, "{}", run.stderr);
    let text = parse_text(&run.stdout, points.len());
    assert_same(&text, &library_diagram(&points));
}

#[test]
fn real_data_round_trip() {
    let path = common::root().join("examples/data/crocodile-conf.p2d");
    let points = wdm_crust::io::read_points_from_path(&path).unwrap();
    let arg = path.to_str().unwrap();
    let run = run_in(Path::new("."), &["voronoi", arg], b"");
    assert_eq!(run.code, 0, "{}", run.stderr);
    check_json(&run.stdout, &points);
    let run = run_in(Path::new("."), &["voronoi", arg, "--format", "text"], b"");
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert_same(
        &parse_text(&run.stdout, points.len()),
        &library_diagram(&points),
    );
}

#[test]
fn collinear_and_tiny_inputs_have_no_vertices() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let run = run_in(d, &["voronoi"], b"0 0\n2 2\n1 1\n");
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert_eq!(
        run.stdout,
        "{\"vertices\":[],\"edges\":[],\"rays\":[],\"cells\":[[],[],[]]}\n"
    );
    let run = run_in(d, &["voronoi", "--format", "text"], b"0 0\n2 2\n1 1\n");
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert_eq!(
        run.stdout,
        "# wdm-crust voronoi: 3 points, 0 vertices, 0 edges, 0 rays\n\
         # collinear: no vertices; the diagram is the perpendicular bisectors of these pairs\n\
         # bisector 0 2\n# bisector 2 1\nc 0\nc 1\nc 2\n"
    );
    let run = run_in(d, &["voronoi"], b"");
    assert_eq!(
        run.stdout,
        "{\"vertices\":[],\"edges\":[],\"rays\":[],\"cells\":[]}\n"
    );
    let run = run_in(d, &["voronoi"], b"5 5\n5 5\n");
    assert_eq!(
        run.stdout,
        "{\"vertices\":[],\"edges\":[],\"rays\":[],\"cells\":[[],[]]}\n"
    );
    // Four cocircular points: one vertex of degree four.
    let run = run_in(d, &["voronoi"], b"0 0\n2 0\n2 2\n0 2\n");
    let value: Value = serde_json::from_str(&run.stdout).unwrap();
    assert_eq!(value["vertices"], serde_json::json!([[1.0, 1.0]]));
    assert_eq!(value["rays"].as_array().unwrap().len(), 4);
}

/// Near ±f64::MAX a nearly collinear triangle's exact circumcenter lies beyond the f64
/// range: the library's infinity is JSON `null` and text `inf`, and a note says so; the rays
/// stay finite (their directions halved where the differences overflow).
#[test]
fn vertices_beyond_the_f64_range_are_written_as_null_with_a_note() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let input = b"1.7976931348623157e308 1.7976931348623157e308\n\
                  -1.7976931348623157e308 1.7976931348623157e308\n\
                  0 -1.7976931348623157e308\n\
                  1e300 1.7976931348623155e308\n";
    let run = run_in(d, &["voronoi"], input);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let value: Value = serde_json::from_str(&run.stdout).unwrap();
    let vertices = value["vertices"].as_array().unwrap();
    let nulls = vertices
        .iter()
        .flat_map(|v| v.as_array().unwrap())
        .filter(|x| x.is_null())
        .count();
    assert_eq!(nulls, 1, "{}", run.stdout);
    for ray in value["rays"].as_array().unwrap() {
        assert!(
            ray.as_array().unwrap().iter().all(Value::is_number),
            "{ray}"
        );
    }
    assert_eq!(
        run.stderr,
        "wdm-crust: note: <stdin>: Voronoi vertices beyond the f64 range (their exact position \
         overflows): 1; written as null in JSON, inf in text\n"
    );
    let run = run_in(d, &["voronoi", "--format", "text"], input);
    assert!(run
        .stdout
        .lines()
        .any(|l| l.starts_with("v ") && l.contains("inf")));
    // Ordinary input has no such note.
    let run = run_in(d, &["voronoi"], b"0 0\n2 0\n0 2\n");
    assert_eq!(run.stderr, "");
}

#[test]
fn standard_input_output_file_and_timings() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let a = run_in(d, &["voronoi"], POINTS.as_bytes());
    let b = run_in(d, &["voronoi", "-"], POINTS.as_bytes());
    assert_eq!((a.code, b.code), (0, 0));
    assert_eq!(a.stdout, b.stdout);
    let run = run_in(
        d,
        &["voronoi", "-o", "out.json", "--timings"],
        POINTS.as_bytes(),
    );
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert_eq!(run.stdout, "");
    for phase in ["parse", "triangulate", "voronoi", "write", "total"] {
        assert!(
            run.stderr
                .lines()
                .any(|l| l.trim_start().starts_with(phase)),
            "{phase} missing from {}",
            run.stderr
        );
    }
    assert_eq!(fs::read_to_string(d.join("out.json")).unwrap(), a.stdout);
    assert_eq!(listing(d), ["out.json"]);
}

/// Bad inputs: file name, content, the line the message must name, a word it must contain.
const BAD_INPUTS: &[(&str, &[u8], usize, &str)] = &[
    ("word.txt", b"0 0\n1 0\nfoo 1\n", 3, "not a number"),
    (
        "cr-only.txt",
        b"0\t0\t1\r1\t0\t1\rbad\t1\t1\r",
        3,
        "not a number",
    ),
    ("one.txt", b"0 0\n\n# c\n7\n", 4, "only one number"),
    ("nan.txt", b"0 0\nnan 1\n", 2, "not a finite number"),
    ("huge.txt", b"0 0\n1 1e400\n", 2, "overflows"),
    ("tiny.txt", b"0 0\n1e-400 1\n", 2, "rounds to zero"),
    ("binary.txt", b"0 0\n\x89PNG\r\n\x1a\n", 2, "invalid UTF-8"),
    (
        "many.gtn",
        b"2 2 0 0\n0 0 0\n1 1 0\n2 0 1\n",
        4,
        "more points than the 2",
    ),
];

#[test]
fn bad_input_names_file_and_line_and_leaves_no_output() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write(d, "out.txt", b"previous\n");
    for &(name, content, line, problem) in BAD_INPUTS {
        write(d, name, content);
        for format in ["json", "text"] {
            let before = listing(d);
            for out in ["out.json", "out.txt"] {
                let run = run_in(d, &["voronoi", name, "--format", format, "-o", out], b"");
                assert_eq!(run.code, 2, "{name}: {}", run.stderr);
                assert_eq!(run.stdout, "", "{name}");
                let prefix = format!("wdm-crust: {name}:{line}: ");
                assert!(run.stderr.starts_with(&prefix), "{name}: {:?}", run.stderr);
                assert!(run.stderr.contains(problem), "{name}: {:?}", run.stderr);
                assert_eq!(run.stderr.lines().count(), 1, "{name}: {:?}", run.stderr);
                assert!(!run.stderr.contains("panicked"), "{name}");
            }
            assert_eq!(
                listing(d),
                before,
                "{name}: no output or temporary file left"
            );
        }
    }
    assert_eq!(fs::read(d.join("out.txt")).unwrap(), b"previous\n");
    let run = run_in(d, &["voronoi"], b"1 2\n3\n");
    assert_eq!(run.code, 2);
    assert!(run
        .stderr
        .starts_with("wdm-crust: <stdin>:2: only one number"));
}

#[test]
fn usage_errors_and_help() {
    let dir = tempfile::tempdir().unwrap();
    for args in [
        &["voronoi", "--format", "svg"][..],
        &["voronoi", "a", "b"],
        &["voronoi", "-o"],
        &["voronoi", "--algorithm", "wdm"],
    ] {
        let run = run_in(dir.path(), args, b"");
        assert_eq!(run.code, 2, "{args:?}: {}", run.stderr);
        assert!(run.stderr.starts_with("wdm-crust: "), "{args:?}");
        assert_eq!(run.stderr.lines().count(), 1, "{args:?}: {}", run.stderr);
    }
    let run = run_in(dir.path(), &["voronoi", "--help"], b"");
    assert_eq!(run.code, 0);
    for needle in [
        "Examples:",
        "\"cells\"",
        "Collinear input",
        "c p v0 v1",
        "--timings",
    ] {
        assert!(
            run.stdout.contains(needle),
            "{needle} missing from the help"
        );
    }
}
