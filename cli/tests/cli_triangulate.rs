//! `wdm-crust triangulate` run as a user runs it: every input format, every kind of bad
//! input (exit code, a one-line message naming the file and line, no partial output file),
//! usage errors, a closed output pipe, and real data files.

use std::collections::HashSet;
use std::fs;
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use serde_json::Value;
use wdm_crust::predicates::{orient2d, Orientation};

mod common;
use common::{listing, run_in, write, BIN};

/// Checks a successful JSON result against the points it came from.
fn check_json(json: &str, points: &[[f64; 2]]) -> Value {
    assert!(json.ends_with('\n'));
    let value: Value = serde_json::from_str(json).expect("valid JSON");
    let keys: Vec<&str> = value
        .as_object()
        .unwrap()
        .keys()
        .map(String::as_str)
        .collect();
    assert_eq!(keys.len(), 4, "{keys:?}");
    assert_eq!(value["points"].as_u64().unwrap() as usize, points.len());
    let triangles: Vec<[usize; 3]> = serde_json::from_value(value["triangles"].clone()).unwrap();
    let hull: Vec<usize> = serde_json::from_value(value["hull"].clone()).unwrap();
    let duplicates: Vec<[usize; 2]> = serde_json::from_value(value["duplicates"].clone()).unwrap();
    for &[a, b, c] in &triangles {
        assert_eq!(
            orient2d(points[a], points[b], points[c]),
            Orientation::CounterClockwise
        );
    }
    for &[dup, kept] in &duplicates {
        assert!(kept < dup);
        assert_eq!(points[dup], points[kept]);
    }
    let distinct = points.len() - duplicates.len();
    if !triangles.is_empty() {
        // Euler: every boundary point is on the hull.
        assert_eq!(triangles.len(), 2 * distinct - 2 - hull.len());
        let used: HashSet<usize> = triangles.iter().flatten().copied().collect();
        assert_eq!(used.len(), distinct);
    }
    value
}

const SQUARE: [[f64; 2]; 5] = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.0], [0.5, 0.25]];

// ----- every input format -----

#[test]
fn every_input_format_gives_the_same_triangulation() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let files: &[(&str, &[u8])] = &[
        ("lf.txt", b"0 0\n1 0\n0 1\n1 1\n0.5 0.25\n"),
        ("crlf.txt", b"0 0\r\n1 0\r\n0 1\r\n1 1\r\n0.5 0.25\r\n"),
        (
            "cr.txt",
            b"0\t0\t1\r1\t0\t1\r0\t1\t1\r1\t1\t1\r0.5\t0.25\t1\r",
        ),
        (
            "xyz.p2d",
            b"# x y z\n0 0 0.8\n\n1 0 0.8\n0 1 0.8\n1 1 0.8\n0.5 0.25 0.8\n",
        ),
        ("comma.xy", b"0,0\n1, 0\n0 ,1\n1 , 1\n0.5,0.25"),
        ("header.csv", b"x,y\n0,0\n1,0\n0,1\n1,1\n0.5,0.25\n"),
        (
            "id-header.csv",
            b"id,X,Y\n10,0,0\n11,1,0\n12,0,1\n13,1,1\n14,0.5,0.25\n",
        ),
        (
            "swapped.txt",
            b"# exported\nlabel y x\na 0 0\nb 0 1\nc 1 0\nd 1 1\ne 0.25 0.5\n",
        ),
        (
            "header.txt",
            b"\"x\",\"y\"\r\n0,0\r\n1,0\r\n0,1\r\n1,1\r\n0.5,0.25\r\n",
        ),
        (
            "one.node",
            b"5 2 0 1\n1 0 0 1\n2 1 0 1\n3 0 1 1\n4 1 1 1\n5 0.5 0.25 0\n",
        ),
        (
            "zero.gtn",
            b"     5 2 0 0\n0\t0 0\n     1\t1 0\n     2\t0 1\n     3\t1 1\n     4\t0.5 0.25\n",
        ),
        (
            "node-content.txt",
            b"5 2 0 0\n0 0 0\n1 1 0\n2 0 1\n3 1 1\n4 0.5 0.25\n",
        ),
    ];
    let mut first: Option<Value> = None;
    for &(name, content) in files {
        write(d, name, content);
        let run = run_in(d, &["triangulate", name], b"");
        assert_eq!(run.code, 0, "{name}: {}", run.stderr);
        assert_eq!(run.stderr, "", "{name}");
        let value = check_json(&run.stdout, &SQUARE);
        assert_eq!(value["triangles"].as_array().unwrap().len(), 4, "{name}");
        match &first {
            None => first = Some(value),
            Some(v) => assert_eq!(&value, v, "{name}"),
        }
    }
}

#[test]
fn standard_input_absent_or_dash() {
    let dir = tempfile::tempdir().unwrap();
    let input = b"0 0\n1 0\n0 1\n1 1\n0.5 0.25\n";
    let a = run_in(dir.path(), &["triangulate"], input);
    let b = run_in(dir.path(), &["triangulate", "-"], input);
    assert_eq!((a.code, b.code), (0, 0), "{} {}", a.stderr, b.stderr);
    assert_eq!(a.stdout, b.stdout);
    check_json(&a.stdout, &SQUARE);
}

#[test]
fn text_output_format() {
    let dir = tempfile::tempdir().unwrap();
    let run = run_in(
        dir.path(),
        &["triangulate", "--format", "text"],
        b"0 0\n1 0\n0 1\n1 1\n0 0\n",
    );
    assert_eq!(run.code, 0, "{}", run.stderr);
    let lines: Vec<&str> = run.stdout.lines().collect();
    assert_eq!(
        lines[0],
        "# wdm-crust triangulation: 5 points, 2 triangles, 4 hull points, 1 duplicates"
    );
    assert!(lines[1].starts_with("# hull "));
    assert_eq!(lines[2], "# duplicate 4 0");
    let triangles: Vec<Vec<usize>> = lines[3..]
        .iter()
        .map(|l| l.split(' ').map(|t| t.parse().unwrap()).collect())
        .collect();
    assert_eq!(triangles.len(), 2);
    assert!(triangles.iter().all(|t| t.len() == 3));
}

#[test]
fn degenerate_inputs_succeed() {
    let dir = tempfile::tempdir().unwrap();
    let run = run_in(dir.path(), &["triangulate"], b"");
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert_eq!(
        run.stdout,
        "{\"points\":0,\"triangles\":[],\"hull\":[],\"duplicates\":[]}\n"
    );
    let run = run_in(dir.path(), &["triangulate"], b"0 0\n2 2\n1 1\n");
    assert_eq!(run.code, 0, "{}", run.stderr);
    let value: Value = serde_json::from_str(&run.stdout).unwrap();
    assert_eq!(value["triangles"].as_array().unwrap().len(), 0);
    assert_eq!(value["hull"], serde_json::json!([0, 2, 1]));
}

#[test]
fn output_file_and_timings() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write(d, "in.txt", b"0 0\n1 0\n0 1\n1 1\n0.5 0.25\n");
    let run = run_in(
        d,
        &["triangulate", "in.txt", "-o", "out.json", "--timings"],
        b"",
    );
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert_eq!(run.stdout, "");
    for phase in ["parse", "triangulate", "write", "total"] {
        assert!(
            run.stderr
                .lines()
                .any(|l| l.trim_start().starts_with(phase)),
            "{phase} missing from {}",
            run.stderr
        );
    }
    check_json(&fs::read_to_string(d.join("out.json")).unwrap(), &SQUARE);
    // Replacing an existing file, through `-o -` meaning standard output, and text.
    let run = run_in(
        d,
        &[
            "triangulate",
            "in.txt",
            "--output",
            "out.json",
            "--format",
            "text",
        ],
        b"",
    );
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert!(fs::read_to_string(d.join("out.json"))
        .unwrap()
        .starts_with("# wdm-crust"));
    let run = run_in(d, &["triangulate", "in.txt", "-o", "-"], b"");
    check_json(&run.stdout, &SQUARE);
    assert_eq!(listing(d), ["in.txt", "out.json"]);
}

// ----- every kind of bad input -----

/// Bad inputs: file name, content, the line the message must name, a word it must contain.
const BAD_INPUTS: &[(&str, &[u8], usize, &str)] = &[
    ("word.txt", b"0 0\n1 0\nfoo 1\n", 3, "not a number"),
    (
        "word-y.txt",
        b"0 0\r\n1 0\r\n2 3\r\n1 1x\r\n",
        4,
        "not a number",
    ),
    (
        "cr-only.txt",
        b"0\t0\t1\r1\t0\t1\rbad\t1\t1\r",
        3,
        "not a number",
    ),
    ("one.txt", b"0 0\n\n# c\n7\n", 4, "only one number"),
    ("empty-field.csv", b"x,y,z\n1,,2\n", 2, "empty field"),
    ("nan.txt", b"0 0\nnan 1\n", 2, "not a finite number"),
    ("inf.txt", b"0 0\n1 0\n1 -inf\n", 3, "not a finite number"),
    ("underflow.txt", b"0 0\n1e-400 1\n", 2, "rounds to zero"),
    ("overflow.txt", b"1e999 0\n", 1, "overflows a 64-bit float"),
    ("nul.txt", b"0 0\n1 1\n\x00\x00\x00\x00", 3, "NUL byte"),
    // (UTF-16 text is refused as such, without a line: tests/cli_input.rs.)
    ("nul-first.txt", b"\x00\x01 1\n", 1, "NUL byte"),
    ("binary.txt", b"0 0\n\x89PNG\r\n\x1a\n", 2, "invalid UTF-8"),
    (
        "dim3.node",
        b"3 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n",
        1,
        "dimension is 3",
    ),
    (
        "fields.node",
        b"3 2 0\n0 0 0\n1 1 0\n2 0 1\n",
        1,
        "bad .node header",
    ),
    (
        "few.node",
        b"4 2 0 0\n0 0 0\n1 1 0\n2 0 1\n",
        1,
        "declares 4 points but the file has 3",
    ),
    (
        "many.gtn",
        b"2 2 0 0\n0 0 0\n1 1 0\n2 0 1\n",
        4,
        "more points than the 2",
    ),
    (
        "index.node",
        b"3 2 0 0\n0 0 0\n1 1 0\n3 0 1\n",
        4,
        "out of sequence",
    ),
    (
        "base.node",
        b"3 2 0 0\n7 0 0\n8 1 0\n9 0 1\n",
        2,
        "must be 0 or 1",
    ),
    (
        "attributes.node",
        b"2 2 1 0\n0 0 0\n1 1 0\n",
        2,
        "the .node header asks for 3 + 1 + 0",
    ),
    (
        "decimal-comma.txt",
        b"0,5 1,5\n2,5 0,5\n",
        1,
        "decimal commas are not supported",
    ),
    ("semicolons.csv", b"x;y\n0,5;1,5\n", 1, "semicolons"),
    (
        "no-xy.csv",
        b"lat,height\n1,2\n3,4\n",
        1,
        "names the columns \"lat\", \"height\" but no pair of coordinate names",
    ),
    ("twice.csv", b"x,y,X\n1,2,3\n", 1, "two columns \"x\""),
    (
        "short-row.csv",
        b"id,x,y\n1,0,0\n2,1\n",
        3,
        "2 columns, but the header on line 1 has 3",
    ),
    (
        "thousands.txt",
        b"1,2\n1,000.5,2\n",
        2,
        "3 columns, but the first row on line 1 has 2",
    ),
    (
        "ragged.txt",
        b"0 0 1\n1 0\n",
        2,
        "2 columns, but the first row on line 1 has 3",
    ),
];

#[test]
fn bad_input_names_file_and_line_and_leaves_no_output() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for &(name, content, line, problem) in BAD_INPUTS {
        write(d, name, content);
        let before = listing(d);
        let run = run_in(d, &["triangulate", name, "-o", "out.json"], b"");
        assert_eq!(run.code, 2, "{name}: {}", run.stderr);
        assert_eq!(run.stdout, "", "{name}");
        let prefix = format!("wdm-crust: {name}:{line}: ");
        assert!(run.stderr.starts_with(&prefix), "{name}: {:?}", run.stderr);
        assert!(run.stderr.contains(problem), "{name}: {:?}", run.stderr);
        assert_eq!(run.stderr.lines().count(), 1, "{name}: {:?}", run.stderr);
        assert!(!run.stderr.contains("panicked"), "{name}");
        assert_eq!(
            listing(d),
            before,
            "{name}: no output or temporary file left"
        );
    }
}

#[test]
fn bad_standard_input_is_named_stdin() {
    let dir = tempfile::tempdir().unwrap();
    let run = run_in(dir.path(), &["triangulate"], b"1 2\n3\n");
    assert_eq!(run.code, 2);
    assert!(
        run.stderr
            .starts_with("wdm-crust: <stdin>:2: only one number"),
        "{}",
        run.stderr
    );
    assert_eq!(run.stderr.lines().count(), 1);
}

#[test]
fn failure_leaves_an_existing_output_untouched() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write(d, "bad.txt", b"1 2\nx y\n");
    write(d, "out.json", b"previous result\n");
    let run = run_in(d, &["triangulate", "bad.txt", "-o", "out.json"], b"");
    assert_eq!(run.code, 2);
    assert_eq!(fs::read(d.join("out.json")).unwrap(), b"previous result\n");
    assert_eq!(listing(d), ["bad.txt", "out.json"]);
}

#[test]
fn missing_or_unreadable_input() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let run = run_in(d, &["triangulate", "missing.txt", "-o", "out.json"], b"");
    assert_eq!(run.code, 2);
    assert!(
        run.stderr
            .starts_with("wdm-crust: missing.txt: cannot open"),
        "{}",
        run.stderr
    );
    assert_eq!(run.stderr.lines().count(), 1);
    fs::create_dir(d.join("sub")).unwrap();
    let run = run_in(d, &["triangulate", "sub"], b"");
    assert_eq!(run.code, 2);
    assert!(
        run.stderr.starts_with("wdm-crust: sub: is a directory"),
        "{}",
        run.stderr
    );
    assert_eq!(listing(d), ["sub"]);
}

#[test]
fn bad_output_path() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write(d, "in.txt", b"0 0\n1 0\n0 1\n");
    let run = run_in(
        d,
        &["triangulate", "in.txt", "-o", "no/such/dir/out.json"],
        b"",
    );
    assert_eq!(run.code, 2);
    assert!(
        run.stderr.starts_with("wdm-crust: no/such/dir/out.json: "),
        "{}",
        run.stderr
    );
    let run = run_in(d, &["triangulate", "in.txt", "-o", "."], b"");
    assert_eq!(run.code, 2);
    assert!(run.stderr.contains("is a directory"), "{}", run.stderr);
    assert_eq!(run.stderr.lines().count(), 1);
    assert_eq!(listing(d), ["in.txt"]);
}

// ----- usage -----

#[test]
fn usage_errors_are_one_line_with_exit_2() {
    let dir = tempfile::tempdir().unwrap();
    for args in [
        &["triangulate", "--formt", "json"][..],
        &["triangulate", "--format", "xml"],
        &["triangulate", "a", "b"],
        &["triangulate", "-o"],
        &["frobnicate"],
    ] {
        let run = run_in(dir.path(), args, b"");
        assert_eq!(run.code, 2, "{args:?}: {}", run.stderr);
        assert!(
            run.stderr.starts_with("wdm-crust: "),
            "{args:?}: {}",
            run.stderr
        );
        assert_eq!(run.stderr.lines().count(), 1, "{args:?}: {}", run.stderr);
    }
    let run = run_in(dir.path(), &["triangulate", "--format", "xml"], b"");
    assert!(run.stderr.contains("json, text"), "{}", run.stderr);
}

#[test]
fn help_and_version() {
    let dir = tempfile::tempdir().unwrap();
    let run = run_in(dir.path(), &["triangulate", "--help"], b"");
    assert_eq!(run.code, 0);
    assert!(run.stdout.contains("Examples:"));
    assert!(run
        .stdout
        .contains("wdm-crust triangulate points.txt -o triangles.json"));
    assert!(run.stdout.contains("--timings"));
    let run = run_in(dir.path(), &["--help"], b"");
    assert_eq!(run.code, 0);
    assert!(run.stdout.contains("triangulate"));
    let run = run_in(dir.path(), &["--version"], b"");
    assert_eq!(run.code, 0);
    assert_eq!(
        run.stdout.trim(),
        format!("wdm-crust {}", env!("CARGO_PKG_VERSION"))
    );
    let run = run_in(dir.path(), &[], b"");
    assert_eq!(run.code, 2);
    assert!(run.stderr.contains("Usage"));
}

// ----- a closed output pipe -----

#[test]
fn closed_standard_output_is_a_quiet_success() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // Enough output to overflow any pipe buffer.
    let mut text = String::new();
    for i in 0..30_000u32 {
        let (x, y) = (
            f64::from(i % 173),
            f64::from(i / 173) + f64::from(i % 7) * 0.01,
        );
        text.push_str(&format!("{x} {y}\n"));
    }
    write(d, "many.txt", text.as_bytes());
    for format in ["json", "text"] {
        let mut child = Command::new(BIN)
            .args(["triangulate", "many.txt", "--format", format])
            .current_dir(d)
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        // Read a little, as `| head -c 100` would, then hang up.
        let mut stdout = child.stdout.take().unwrap();
        let mut start = [0u8; 100];
        stdout.read_exact(&mut start).unwrap();
        drop(stdout);
        let mut stderr = String::new();
        child
            .stderr
            .take()
            .unwrap()
            .read_to_string(&mut stderr)
            .unwrap();
        let status = child.wait().unwrap();
        assert_eq!(status.code(), Some(0), "{format}: {stderr}");
        assert_eq!(stderr, "", "{format}");
    }
}

// ----- real data -----

/// `tests/data/<rel>`: the real point sets, inside the repository (GPL-3.0 data, see
/// `tests/data/README.md`). A missing file fails the test.
fn data_path(rel: &str) -> PathBuf {
    let path = common::root().join("tests/data").join(rel);
    assert!(
        path.is_file(),
        "test data {} is missing (the real point sets live in tests/data, see its README.md)",
        path.display()
    );
    path
}

#[test]
fn real_data_round_trip() {
    for (name, count) in [
        ("hnn-crust-sgp16/crocodile-conf.gtn", 129),
        ("fitconnect/data/bot.txt", 1000),
        ("fitconnect/data/Monitor0.txt", 915),
        ("stretchdenoise/data/Circle0.txt", 248),
        ("stretchdenoise/data/vase_xyz.txt", 329),
        ("stretchdenoise/data/family.p2d", 9990),
    ] {
        let path = data_path(name);
        let points = wdm_crust::io::read_points_from_path(&path).unwrap();
        assert_eq!(points.len(), count, "{name}");
        let path_arg = path.to_str().unwrap();
        let run = run_in(Path::new("."), &["triangulate", path_arg], b"");
        assert_eq!(run.code, 0, "{name}: {}", run.stderr);
        let value = check_json(&run.stdout, &points);
        assert!(!value["triangles"].as_array().unwrap().is_empty(), "{name}");
        // The same through standard input (content detection only, no extension).
        let run = run_in(Path::new("."), &["triangulate"], &fs::read(&path).unwrap());
        assert_eq!(run.code, 0, "{name}: {}", run.stderr);
        check_json(&run.stdout, &points);
    }
}

#[test]
fn an_empty_input_succeeds_with_a_note_for_every_subcommand() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write(d, "comments.txt", b"# nothing yet\n\n   \n");
    write(d, "header.csv", b"id,x,y\r\n");
    write(d, "none.node", b"0 2 0 0\n");
    for subcommand in ["triangulate", "voronoi", "reconstruct"] {
        for (input, stdin, name) in [
            (None, &b""[..], "<stdin>"),
            (Some("-"), &b"\n# only a comment\n"[..], "<stdin>"),
            (Some("comments.txt"), &b""[..], "comments.txt"),
            (Some("header.csv"), &b""[..], "header.csv"),
            (Some("none.node"), &b""[..], "none.node"),
        ] {
            let mut args = vec![subcommand];
            args.extend(input);
            let run = run_in(d, &args, stdin);
            assert_eq!(run.code, 0, "{subcommand} {name}: {}", run.stderr);
            assert!(
                !run.stdout.is_empty(),
                "{subcommand} {name}: an empty result is written"
            );
            let lines: Vec<&str> = run.stderr.lines().collect();
            assert_eq!(lines.len(), 1, "{subcommand} {name}: {:?}", run.stderr);
            assert!(
                lines[0].starts_with(&format!("wdm-crust: note: {name}: no points")),
                "{subcommand} {name}: {}",
                lines[0]
            );
        }
        // One point is not empty: no note.
        let run = run_in(d, &[subcommand], b"1 2\n");
        assert_eq!((run.code, run.stderr.as_str()), (0, ""), "{subcommand}");
    }
}
