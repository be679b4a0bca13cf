//! The input every subcommand shares, run as a user runs it: CSV headers with geographic and
//! projected coordinate names, `--columns` by name and by position, the headers refused as
//! ambiguous, and files that are no point list at all (an SVG drawing, JSON, a compressed
//! file, a spreadsheet, UTF-16 text), each refused with one line naming the file.

use std::collections::HashSet;
use std::path::Path;

use serde_json::Value;

mod common;
use common::{listing, run_in, write};

const SUBCOMMANDS: [&str; 3] = ["triangulate", "voronoi", "reconstruct"];

/// The bundled bean: 150 points on a closed curve.
fn bean() -> Vec<[f64; 2]> {
    let path = common::root().join("examples/data/bean.txt");
    wdm_crust::io::read_points_from_path(&path).unwrap()
}

/// `points` as CSV rows under `header`, each row the fields `row(i, point)`.
fn csv(header: &str, points: &[[f64; 2]], row: impl Fn(usize, [f64; 2]) -> String) -> String {
    let mut text = format!("{header}\n");
    for (i, &p) in points.iter().enumerate() {
        text.push_str(&row(i, p));
        text.push('\n');
    }
    text
}

/// Runs a subcommand that must succeed, and returns its standard output.
fn output(dir: &Path, args: &[&str]) -> String {
    let run = run_in(dir, args, b"");
    assert_eq!(run.code, 0, "{args:?}: {}", run.stderr);
    assert_eq!(run.stderr, "", "{args:?}");
    run.stdout
}

/// Every position of the points in a GeoJSON output (the curves, the chains, the unassigned
/// points; not the medial axis), as bits.
fn geojson_positions(text: &str) -> HashSet<[u64; 2]> {
    fn walk(value: &Value, out: &mut HashSet<[u64; 2]>) {
        match value {
            Value::Array(items) => {
                if let [Value::Number(x), Value::Number(y)] = &items[..] {
                    out.insert([x.as_f64().unwrap().to_bits(), y.as_f64().unwrap().to_bits()]);
                } else {
                    items.iter().for_each(|item| walk(item, out));
                }
            }
            Value::Object(map) => map.values().for_each(|item| walk(item, out)),
            _ => {}
        }
    }
    let value: Value = serde_json::from_str(text).unwrap();
    let mut out = HashSet::new();
    for feature in value["features"].as_array().unwrap() {
        if feature["properties"]["kind"] != "medial_axis" {
            walk(&feature["geometry"]["coordinates"], &mut out);
        }
    }
    out
}

/// A run that must fail with exit 2, one line naming `prefix`, and no output file; returns
/// the message.
fn refused(dir: &Path, args: &[&str], prefix: &str) -> String {
    let before = listing(dir);
    let mut with_output = args.to_vec();
    with_output.extend(["-o", "out.json"]);
    let run = run_in(dir, &with_output, b"");
    assert_eq!(run.code, 2, "{args:?}: {}", run.stderr);
    assert_eq!(run.stdout, "", "{args:?}");
    assert_eq!(run.stderr.lines().count(), 1, "{args:?}: {}", run.stderr);
    assert!(
        run.stderr.starts_with(prefix),
        "{args:?}: {:?} does not start with {prefix:?}",
        run.stderr
    );
    assert_eq!(listing(dir), before, "{args:?}: no output file left");
    run.stderr.trim_end().to_string()
}

#[test]
fn geographic_and_projected_headers_read_longitude_as_x() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let points = bean();
    let bean_txt = common::root().join("examples/data/bean.txt");
    let bean_txt = bean_txt.to_str().unwrap();
    let expected = output(d, &["reconstruct", bean_txt, "--format", "geojson"]);
    // The curve through every point: the output holds each input position, exactly.
    let all: HashSet<[u64; 2]> = points.iter().map(|p| p.map(f64::to_bits)).collect();
    assert_eq!(geojson_positions(&expected), all);
    for (name, header, x_first) in [
        ("lon-lat.csv", "id,lon,lat", true),
        ("lat-lon.csv", "id,lat,lon", false),
        ("long.csv", "id,Lat,Long", false),
        ("longitude.csv", "id,LONGITUDE,LATITUDE", true),
        ("lng.csv", "id,lng,lat", true),
        ("utm.csv", "id,Easting,Northing", true),
        (
            "quoted.csv",
            "\u{feff}\"id\",\"Latitude\",\"Longitude\"",
            false,
        ),
    ] {
        let text = csv(header, &points, |i, [x, y]| {
            if x_first {
                format!("{i},{x:?},{y:?}")
            } else {
                format!("{i},{y:?},{x:?}")
            }
        });
        write(d, name, text.as_bytes());
        let got = output(d, &["reconstruct", name, "--format", "geojson"]);
        assert_eq!(got, expected, "{name}");
    }
}

#[test]
fn columns_choose_x_and_y_for_every_subcommand() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let points = bean();
    write(
        d,
        "plain.txt",
        csv("", &points, |_, [x, y]| format!("{x:?} {y:?}"))
            .trim_start()
            .as_bytes(),
    );
    // y before x, among other columns whose names are no coordinates.
    let named = csv("station,North (m),height,East (m)", &points, |i, [x, y]| {
        format!("s{i},{y:?},{},{x:?}", i * 3)
    });
    write(d, "named.csv", named.as_bytes());
    // No header; x in the third column, y in the first.
    let positions = csv("# y id x", &points, |i, [x, y]| format!("{y:?} {i} {x:?}"));
    write(d, "positions.txt", positions.as_bytes());
    for subcommand in SUBCOMMANDS {
        let expected = output(d, &[subcommand, "plain.txt"]);
        for args in [
            &[subcommand, "named.csv", "--columns", "east (m),NORTH (M)"][..],
            &[subcommand, "named.csv", "--columns", "4,2"],
            &[subcommand, "positions.txt", "--columns", "3,1"],
            &[subcommand, "--columns=3, 1", "positions.txt"],
        ] {
            assert_eq!(output(d, args), expected, "{args:?}");
        }
    }
    // Standard input too.
    let run = run_in(
        d,
        &["triangulate", "--columns", "3,1"],
        positions.as_bytes(),
    );
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert_eq!(run.stdout, output(d, &["triangulate", "plain.txt"]));
}

#[test]
fn a_header_that_could_be_misread_is_refused_with_a_way_out() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let square = "0,0,10,20\n1,0,11,20\n1,1,11,21\n0,1,10,21\n";
    write(d, "both.csv", format!("x,y,lon,lat\n{square}").as_bytes());
    write(
        d,
        "twice.csv",
        b"lon,longitude,lat,z\n5,10,20,0\n5,11,20,0\n5,11,21,0\n5,10,21,0\n",
    );
    write(d, "none.csv", format!("a,b,c,d\n{square}").as_bytes());
    write(
        d,
        "lat-only.csv",
        format!("id,lat,c,d\n{square}").as_bytes(),
    );
    for subcommand in SUBCOMMANDS {
        let message = refused(d, &[subcommand, "both.csv"], "wdm-crust: both.csv:1: ");
        assert!(
            message.ends_with(
                "the header line names more than one pair of coordinate columns (`x,y` and \
                 `lon,lat`): choose one with --columns X,Y (e.g. --columns x,y)"
            ),
            "{message}"
        );
        let message = refused(d, &[subcommand, "twice.csv"], "wdm-crust: twice.csv:1: ");
        assert!(
            message.contains("(`lon,lat` and `longitude,lat`)"),
            "{message}"
        );
        for name in ["none.csv", "lat-only.csv"] {
            let message = refused(d, &[subcommand, name], &format!("wdm-crust: {name}:1: "));
            assert!(
                message.contains("choose the columns with --columns X,Y"),
                "{message}"
            );
        }
    }
    // The way out, and what it reads.
    let x_y = output(d, &["triangulate", "both.csv", "--columns", "x,y"]);
    let lon_lat = output(d, &["triangulate", "both.csv", "--columns", "LON,LAT"]);
    write(d, "square.txt", b"0 0\n1 0\n1 1\n0 1\n");
    write(d, "shifted.txt", b"10 20\n11 20\n11 21\n10 21\n");
    assert_eq!(x_y, output(d, &["triangulate", "square.txt"]));
    assert_eq!(lon_lat, output(d, &["triangulate", "shifted.txt"]));
    let first = output(d, &["voronoi", "twice.csv", "--columns", "longitude,lat"]);
    assert_eq!(first, output(d, &["voronoi", "shifted.txt"]));
}

#[test]
fn a_chosen_column_the_file_lacks_is_named() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write(
        d,
        "stations.csv",
        b"# export\nStation,Lon_deg,Lat_deg\nA,7.5,46\nB,8,47\nC,8,46\n",
    );
    write(d, "rows.txt", b"0 0 5\n1 0 5\n0 1 5\n");
    write(d, "mesh.node", b"3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n");
    for subcommand in SUBCOMMANDS {
        let message = refused(
            d,
            &[subcommand, "stations.csv", "--columns", "lon,lat"],
            "wdm-crust: stations.csv:2: ",
        );
        assert_eq!(
            message,
            "wdm-crust: stations.csv:2: --columns asks for a column \"lon\", but the header line \
             has none (names are compared in any case); its columns are \"Station\", \
             \"Lon_deg\", \"Lat_deg\""
        );
        let message = refused(
            d,
            &[subcommand, "stations.csv", "--columns", "2,4"],
            "wdm-crust: stations.csv:2: ",
        );
        assert!(
            message.ends_with("--columns asks for column 4, but the header line has 3 columns"),
            "{message}"
        );
        let message = refused(
            d,
            &[subcommand, "rows.txt", "--columns", "lon,lat"],
            "wdm-crust: rows.txt:1: ",
        );
        assert!(
            message.contains("by name, but the file has no header line"),
            "{message}"
        );
        let message = refused(
            d,
            &[subcommand, "mesh.node", "--columns", "2,3"],
            "wdm-crust: mesh.node:1: ",
        );
        assert!(message.contains("leave --columns out"), "{message}");
    }
    // The column names as the file spells them, in any case.
    let run = run_in(
        d,
        &[
            "triangulate",
            "stations.csv",
            "--columns",
            "LON_DEG,lat_deg",
        ],
        b"",
    );
    assert_eq!(run.code, 0, "{}", run.stderr);
}

#[test]
fn a_malformed_columns_option_is_a_usage_error() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write(d, "in.txt", b"0 0\n1 0\n0 1\n");
    for (value, problem) in [
        (
            "lon",
            "expected two columns X,Y (names or 1-based positions) separated by a comma, got one",
        ),
        ("a,b,c", "got 3"),
        ("0,1", "column positions count from 1"),
        (
            "lat,Lat",
            "x and y must be two different columns, got lat and Lat",
        ),
        (",y", "a column name is empty"),
    ] {
        let message = refused(
            d,
            &["triangulate", "in.txt", "--columns", value],
            "wdm-crust: invalid value ",
        );
        assert!(message.contains(problem), "{value:?}: {message}");
    }
}

#[test]
fn files_that_are_no_point_list_say_what_to_do() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let svg = b"<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n\
        <svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 100 100\">\n\
        <circle cx=\"10\" cy=\"20\" r=\"1\"/>\n</svg>\n";
    for (name, content, says) in [
        (
            "drawing.svg",
            &svg[..],
            "this looks like an SVG drawing (XML), not a list of points; export the points as \
             text (one `x y` per line) or CSV",
        ),
        (
            "bare.svg",
            b"\xEF\xBB\xBF\n<svg width=\"10\" height=\"10\"></svg>\n",
            "an SVG drawing",
        ),
        (
            "curves.geojson",
            b"{\"type\": \"FeatureCollection\", \"features\": []}\n",
            "this looks like JSON (or GeoJSON), not a list of points",
        ),
        (
            "points.txt.gz",
            b"\x1f\x8b\x08\x00\x00\x00\x00\x00",
            "decompress it first",
        ),
        (
            "sheet.xlsx",
            b"PK\x03\x04\x14\x00\x06\x00\x08\x00",
            "save the spreadsheet as CSV",
        ),
        (
            "scan.png",
            b"\x89PNG\r\n\x1a\n\x00\x00\x00\x0dIHDR",
            "an image",
        ),
        (
            "utf16.txt",
            b"\xff\xfe0\x00 \x000\x00\r\x00\n\x00",
            "UTF-16 text",
        ),
    ] {
        write(d, name, content);
        for subcommand in SUBCOMMANDS {
            let prefix = format!("wdm-crust: {name}: this looks like ");
            let message = refused(d, &[subcommand, name], &prefix);
            assert!(message.contains(says), "{message}");
        }
        // The same content on standard input.
        let run = run_in(d, &["triangulate"], content);
        assert_eq!(run.code, 2);
        assert!(
            run.stderr
                .starts_with("wdm-crust: <stdin>: this looks like "),
            "{}",
            run.stderr
        );
    }
}
