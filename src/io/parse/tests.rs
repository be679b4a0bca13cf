use std::io::{BufReader, Read};
use std::path::PathBuf;

use proptest::prelude::*;

use super::*;

fn parse(text: &str) -> Result<Vec<[f64; 2]>, ParseError> {
    read_points(text.as_bytes(), None)
}

fn parse_as(text: &str, format: InputFormat) -> Result<Vec<[f64; 2]>, ParseError> {
    read_points(text.as_bytes(), Some(format))
}

fn ok(text: &str) -> Vec<[f64; 2]> {
    parse(text).unwrap_or_else(|e| panic!("{text:?}: {e}"))
}

/// The error of `text`, checking that it has line `line` and a one-line message.
fn err_at(text: &str, format: Option<InputFormat>, line: usize) -> ParseErrorKind {
    let err = read_points(text.as_bytes(), format).expect_err(text);
    let message = err.to_string();
    assert_eq!(err.line, Some(line), "{text:?}: {message}");
    assert!(message.starts_with(&format!("line {line}: ")), "{message}");
    assert!(
        !message.contains('\n') && !message.contains('\r'),
        "{message:?}"
    );
    err.kind
}

// ----- plain text -----

#[test]
fn text_separators_and_extra_columns() {
    let expected = vec![[1.5, -2.0], [3.0, 4e2], [5.0, 6.0]];
    assert_eq!(ok("1.5 -2\n3\t4e2\n  5 \t 6  \n"), expected);
    assert_eq!(ok("1.5,-2\n3 , 4e2\n  5 ,  6  \n"), expected);
    assert_eq!(ok("1.5 -2 a\n3\t4e2\tb\n5 6 c\n"), expected);
    assert_eq!(ok("1.5,-2,extra\n3,4e2,more\n5,6,\n"), expected);
    assert_eq!(ok("1.5 -2 0.85 x\n3 4e2 0.9 y\n5 6 1 z\n"), expected);
    assert_eq!(
        ok("+.5 1.\n-0 0e-500\n1E+3 2e-3\n"),
        vec![[0.5, 1.0], [-0.0, 0.0], [1000.0, 0.002]]
    );
}

#[test]
fn text_comments_and_blank_lines() {
    let text = "# header comment\n\n   \n1 2 # trailing comment\n\t\n#3 4\n5 6\n\n";
    assert_eq!(ok(text), vec![[1.0, 2.0], [5.0, 6.0]]);
    assert!(ok("").is_empty());
    assert!(ok("# only a comment\n\n").is_empty());
}

#[test]
fn text_line_ends() {
    let expected = vec![[1.0, 2.0], [3.0, 4.0], [5.0, 6.0]];
    assert_eq!(ok("1 2\n3 4\n5 6\n"), expected);
    assert_eq!(ok("1 2\r\n3 4\r\n5 6\r\n"), expected);
    assert_eq!(ok("1 2\r3 4\r5 6\r"), expected);
    assert_eq!(ok("1 2\r\n3 4\r5 6"), expected);
    assert_eq!(ok("\u{feff}1 2\n3 4\n5 6"), expected);
}

#[test]
fn crawl_and_peel_files_are_tab_separated_with_cr_line_ends() {
    let text = "51.8\t267.0525397\t1\r151\t283.6979167\t1\r156\t290.1805556\t1\r";
    assert_eq!(
        ok(text),
        vec![
            [51.8, 267.0525397],
            [151.0, 283.6979167],
            [156.0, 290.1805556]
        ]
    );
    assert_eq!(detect_format(text.as_bytes()), InputFormat::Text);
}

#[test]
fn line_numbers_count_every_kind_of_line_end() {
    // Lines: 1 "1 2" (CR), 2 "" (CRLF), 3 "# c" (LF), 4 "bad".
    let kind = err_at("1 2\r\r\n# c\nbad 1\n", None, 4);
    assert!(matches!(
        kind,
        ParseErrorKind::NotANumber { axis: Axis::X, .. }
    ));
}

#[test]
fn explicit_text_has_no_header() {
    let kind = err_at("x y\n1 2\n", Some(InputFormat::Text), 1);
    assert!(matches!(kind, ParseErrorKind::HeaderInText), "{kind}");
    // Detected, the same content is CSV with a header.
    assert_eq!(ok("x y\n1 2\n"), vec![[1.0, 2.0]]);
}

// ----- CSV -----

#[test]
fn csv_with_and_without_header() {
    let expected = vec![[1.0, 2.0], [3.5, -4.0]];
    assert_eq!(ok("x,y\n1,2\n3.5,-4\n"), expected);
    assert_eq!(ok("X, Y, label\r\n1, 2, a\r\n3.5, -4, b\r\n"), expected);
    assert_eq!(ok("\"x\",\"y\"\n\"1\",\"2\"\n3.5,\"-4\"\n"), expected);
    assert_eq!(ok("# exported\nx y\n1 2\n3.5 -4\n"), expected);
    assert_eq!(ok("1,2\n3.5,-4\n"), expected);
    assert_eq!(
        parse_as("x,y\n1,2\n3.5,-4\n", InputFormat::Csv).unwrap(),
        expected
    );
    assert_eq!(
        parse_as("1,2\n3.5,-4\n", InputFormat::Csv).unwrap(),
        expected
    );
    assert!(ok("x,y\n").is_empty());
}

#[test]
fn header_only_on_the_first_line() {
    let kind = err_at("x,y\n1,2\nx,y\n", None, 3);
    assert!(matches!(kind, ParseErrorKind::NotANumber { .. }));
    // A number word is not a header.
    let kind = err_at("nan,1\n", None, 1);
    assert!(matches!(
        kind,
        ParseErrorKind::NotFinite { axis: Axis::X, .. }
    ));
    // A line mixing words and numbers is not a header.
    let kind = err_at("x,1\n", Some(InputFormat::Csv), 1);
    assert!(matches!(
        kind,
        ParseErrorKind::NotANumber { axis: Axis::X, .. }
    ));
}

// ----- .node / .gtn -----

#[test]
fn node_zero_based() {
    let text = "3 2 0 0\n0 1.5 2\n1 3 4\n2 5 6\n";
    let expected = vec![[1.5, 2.0], [3.0, 4.0], [5.0, 6.0]];
    assert_eq!(ok(text), expected);
    assert_eq!(parse_as(text, InputFormat::Node).unwrap(), expected);
    assert_eq!(detect_format(text.as_bytes()), InputFormat::Node);
}

#[test]
fn node_one_based_with_attributes_markers_and_comments() {
    let text =
        "# Triangle output\n3  2  1  1\n1 0 0 0.25 1 # corner\n\n2 1 0 0.5 0\n3 0 1 0.75 1\n";
    let expected = vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
    assert_eq!(ok(text), expected);
    assert_eq!(parse_as(text, InputFormat::Node).unwrap(), expected);
}

#[test]
fn gtn_style_with_padding_tabs_and_crlf() {
    let text = "     3 2 0 0\r\n0\t1.08701 17.0872\r\n     1\t3.20185 21.0835\r\n     2\t5 6\r\n";
    assert_eq!(
        ok(text),
        vec![[1.08701, 17.0872], [3.20185, 21.0835], [5.0, 6.0]]
    );
}

#[test]
fn node_with_no_points() {
    assert!(ok("0 2 0 0\n").is_empty());
    assert!(parse_as("0 2 0 0\n", InputFormat::Node).unwrap().is_empty());
    assert_eq!(detect_format(b"0 2 0 0\n"), InputFormat::Node);
}

#[test]
fn four_integer_text_lines_are_not_mistaken_for_a_node_header() {
    // Second line does not have the `index x y` shape the header asks for.
    assert_eq!(ok("4 2 0 0\n5 6 0 0\n"), vec![[4.0, 2.0], [5.0, 6.0]]);
    assert_eq!(ok("4 2 0 0\n"), vec![[4.0, 2.0]]);
    assert_eq!(detect_format(b"4 2 0 0\n5 6 0 0\n"), InputFormat::Text);
    // Read as text, the rows must then have the first row's four columns.
    let kind = err_at("4 2 0 0\n7 6\n", None, 2);
    assert!(matches!(
        kind,
        ParseErrorKind::ColumnCount {
            found: 2,
            expected: 4,
            line: 1,
            header: false
        }
    ));
    // Not dimension 2, or a marker flag above 1: never a header (and not text either).
    let kind = err_at("3 3 0 0\n0 1 2\n", None, 2);
    assert!(matches!(kind, ParseErrorKind::ColumnCount { .. }));
}

#[test]
fn node_header_mismatch() {
    let node = Some(InputFormat::Node);
    for header in [
        "3 3 0 0",
        "abc 2 0 0",
        "3 2 0",
        "3 2 0 2",
        "3 2 0 0 0",
        "-3 2 0 0",
        "3.0 2 0 0",
    ] {
        let text = format!("{header}\n0 1 2\n1 3 4\n2 5 6\n");
        let kind = err_at(&text, node, 1);
        assert!(
            matches!(kind, ParseErrorKind::NodeHeader { .. }),
            "{header}"
        );
    }
    let kind = err_at("# comment\n\n3 3 0 0\n", node, 3);
    assert!(kind.to_string().contains("dimension is 3"), "{kind}");
}

#[test]
fn node_count_mismatch() {
    let kind = err_at("3 2 0 0\n0 1 2\n1 3 4\n", Some(InputFormat::Node), 1);
    assert!(matches!(
        kind,
        ParseErrorKind::NodeTooFewPoints {
            declared: 3,
            found: 2
        }
    ));
    let kind = err_at("2 2 0 0\n0 1 2\n1 3 4\n2 5 6\n", None, 4);
    assert!(matches!(
        kind,
        ParseErrorKind::NodeTooManyPoints { declared: 2 }
    ));
}

#[test]
fn node_index_checks() {
    let kind = err_at("2 2 0 0\n5 1 2\n6 3 4\n", Some(InputFormat::Node), 2);
    assert!(matches!(
        kind,
        ParseErrorKind::NodeIndex { expected: None, .. }
    ));
    let kind = err_at("3 2 0 0\n1 1 2\n2 3 4\n2 5 6\n", None, 4);
    assert!(matches!(
        kind,
        ParseErrorKind::NodeIndex {
            expected: Some(3),
            ..
        }
    ));
    let kind = err_at("2 2 0 0\n0 1 2\none 3 4\n", None, 3);
    assert!(matches!(kind, ParseErrorKind::NodeIndex { .. }));
}

#[test]
fn node_point_line_problems() {
    let kind = err_at("2 2 0 0\n0 1 2\n1 3\n", None, 3);
    assert!(matches!(kind, ParseErrorKind::NodeFields { found: 2 }));
    let kind = err_at("2 2 0 0\n0 1 2\n1 3 y\n", None, 3);
    assert!(matches!(
        kind,
        ParseErrorKind::NotANumber { axis: Axis::Y, .. }
    ));
    let kind = err_at("2 2 0 0\n0 1 2\n1 nan 4\n", None, 3);
    assert!(matches!(
        kind,
        ParseErrorKind::NotFinite { axis: Axis::X, .. }
    ));
}

// ----- detection -----

#[test]
fn format_detection() {
    assert_eq!(detect_format(b""), InputFormat::Text);
    assert_eq!(detect_format(b"1 2\n"), InputFormat::Text);
    assert_eq!(detect_format(b"1,2\n"), InputFormat::Csv);
    assert_eq!(detect_format(b"x y\n1 2\n"), InputFormat::Csv);
    assert_eq!(detect_format(b"\r\n# c\r\nx,y\r\n"), InputFormat::Csv);
    assert_eq!(
        detect_format(b"2 2 1 0\n1 0 0 7\n2 1 1 7\n"),
        InputFormat::Node
    );
    assert_eq!(
        format_from_path(Path::new("a/b.NODE")),
        Some(InputFormat::Node)
    );
    assert_eq!(
        format_from_path(Path::new("x.gtn")),
        Some(InputFormat::Node)
    );
    assert_eq!(format_from_path(Path::new("x.csv")), Some(InputFormat::Csv));
    assert_eq!(format_from_path(Path::new("x.p2d")), None);
    assert_eq!(format_from_path(Path::new("noext")), None);
}

// ----- bad coordinates -----

#[test]
fn not_a_number() {
    let kind = err_at("1 2\nfoo 3\n", None, 2);
    assert!(
        matches!(kind, ParseErrorKind::NotANumber { axis: Axis::X, ref token } if token == "foo")
    );
    let kind = err_at("1 2\n3 4\n5 6y\n", None, 3);
    assert!(
        matches!(kind, ParseErrorKind::NotANumber { axis: Axis::Y, ref token } if token == "6y")
    );
    let kind = err_at("1;2\n", None, 1);
    assert!(matches!(kind, ParseErrorKind::NotANumber { .. }));
    let kind = err_at("0x10 1\n", None, 1);
    assert!(matches!(kind, ParseErrorKind::NotANumber { .. }));
    let long = format!("1 2\n{} 1\n", "z".repeat(500));
    let kind = err_at(&long, None, 2);
    assert!(kind.to_string().len() < 200, "{kind}");
}

#[test]
fn one_number_on_a_line() {
    assert!(matches!(
        err_at("1 2\n\n3\n", None, 3),
        ParseErrorKind::MissingY
    ));
    assert!(matches!(err_at("3,\n", None, 1), ParseErrorKind::MissingY));
    assert!(matches!(
        err_at("3 # 4\n", None, 1),
        ParseErrorKind::MissingY
    ));
}

#[test]
fn empty_fields() {
    let kind = err_at("1,,2\n", None, 1);
    assert!(matches!(kind, ParseErrorKind::EmptyField { axis: Axis::Y }));
    let kind = err_at("1 2\n,2\n", None, 2);
    assert!(matches!(kind, ParseErrorKind::EmptyField { axis: Axis::X }));
    let kind = err_at("1, ,2\n", None, 1);
    assert!(matches!(kind, ParseErrorKind::EmptyField { axis: Axis::Y }));
}

#[test]
fn nan_and_infinity() {
    for token in ["nan", "NaN", "inf", "-inf", "+Infinity"] {
        let kind = err_at(&format!("1 2\n{token} 1\n"), None, 2);
        assert!(
            matches!(kind, ParseErrorKind::NotFinite { axis: Axis::X, .. }),
            "{token}"
        );
        let kind = err_at(&format!("1 {token}\n"), None, 1);
        assert!(
            matches!(kind, ParseErrorKind::NotFinite { axis: Axis::Y, .. }),
            "{token}"
        );
    }
}

#[test]
fn every_finite_coordinate() {
    // Any finite f64 is accepted, subnormals and the ends of the range included.
    assert_eq!(
        ok("1e-300 -1e300\n5e-324 1.7976931348623157e308\n0.0000e-999999 -2.2250738585072014e-308\n"),
        vec![
            [1e-300, -1e300],
            [5e-324, f64::MAX],
            [0.0, -f64::MIN_POSITIVE]
        ]
    );
    // Decimals that would move the point (round to zero) or overflow are refused.
    for (token, small) in [
        ("1e-400", true),
        ("-2e-324", true),
        ("1e400", false),
        ("-1e309", false),
    ] {
        let err = parse(&format!("0 0\n1 {token}\n")).expect_err(token);
        assert_eq!(err.line, Some(2));
        if small {
            assert!(
                matches!(err.kind, ParseErrorKind::TooSmall { axis: Axis::Y, .. }),
                "{token}"
            );
        } else {
            assert!(
                matches!(err.kind, ParseErrorKind::TooLarge { axis: Axis::Y, .. }),
                "{token}"
            );
        }
    }
}

// ----- binary and I/O -----

#[test]
fn binary_garbage() {
    let err = read_points(&b"1 2\n3 4\n\x00\x01\x02"[..], None).unwrap_err();
    assert_eq!(err.line, Some(3));
    assert!(matches!(err.kind, ParseErrorKind::NulByte));

    let err = read_points(&b"1 2\n\x89PNG\r\n\x1a\n"[..], None).unwrap_err();
    assert_eq!(err.line, Some(2));
    assert!(matches!(err.kind, ParseErrorKind::InvalidUtf8));

    // UTF-16 text: said so, before its NUL bytes on line 1.
    let err = read_points(&b"\xff\xfe1\x00 \x002\x00"[..], None).unwrap_err();
    assert_eq!(err.line, None);
    assert!(matches!(
        err.kind,
        ParseErrorKind::NotAPointFile {
            looks_like: FileKind::Utf16
        }
    ));
    // NUL bytes that are not UTF-16.
    let err = read_points(&b"\x00\x00\x01\x02"[..], None).unwrap_err();
    assert_eq!(err.line, Some(1));
    assert!(matches!(err.kind, ParseErrorKind::NulByte));

    let long = vec![b'1'; 3 << 20];
    let err = read_points(&long[..], None).unwrap_err();
    assert_eq!(err.line, Some(1));
    assert!(matches!(err.kind, ParseErrorKind::LineTooLong { .. }));
}

/// Gives `data`, then fails.
struct FailingReader<'a> {
    data: &'a [u8],
}

impl Read for FailingReader<'_> {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        if self.data.is_empty() {
            return Err(io::Error::other("disk on fire"));
        }
        let n = buf.len().min(self.data.len());
        buf[..n].copy_from_slice(&self.data[..n]);
        self.data = &self.data[n..];
        Ok(n)
    }
}

#[test]
fn io_error_names_the_line_being_read() {
    let reader = BufReader::with_capacity(
        4,
        FailingReader {
            data: b"1 2\n3 4\n5",
        },
    );
    let err = read_points(reader, None).unwrap_err();
    assert_eq!(err.line, Some(3));
    assert!(matches!(err.kind, ParseErrorKind::Io(_)));
    assert!(std::error::Error::source(&err).is_some());
    assert_eq!(err.to_string(), "line 3: read error: disk on fire");
}

#[test]
fn missing_file_has_no_line() {
    let err = read_points_from_path(Path::new("/nonexistent/dir/points.txt")).unwrap_err();
    assert_eq!(err.line, None);
    assert!(matches!(err.kind, ParseErrorKind::Io(_)));
    assert!(!err.to_string().starts_with("line"));
}

#[test]
fn messages_are_one_line_and_name_the_problem() {
    let cases: &[(&str, &str)] = &[
        (
            "1 2\nabc 3\n",
            "line 2: x coordinate \"abc\" is not a number",
        ),
        ("7\n", "line 1: only one number on the line"),
        (
            "1 inf\n",
            "line 1: y coordinate \"inf\" is not a finite number",
        ),
        (
            "1e-400 0\n",
            "line 1: x coordinate \"1e-400\" is non-zero but rounds to zero",
        ),
        (
            "1e400 0\n",
            "line 1: x coordinate \"1e400\" overflows a 64-bit float",
        ),
        (
            "2 2 0 0\n0 1 2\n",
            "line 1: the .node header declares 2 points but the file has 1",
        ),
        (
            "1 2 0 0\n0 1 2\n1 3 4\n",
            "line 3: more points than the 1 declared",
        ),
    ];
    for (text, start) in cases {
        let message = parse(text).unwrap_err().to_string();
        assert!(message.starts_with(start), "{message:?} vs {start:?}");
        assert!(!message.contains('\n'));
    }
    let message = parse("1 \u{1b}[31m\n").unwrap_err().to_string();
    assert!(!message.contains('\u{1b}'), "{message:?}");
}

// ----- reading from paths -----

#[test]
fn path_extension_forces_the_format() {
    let dir = tempfile::tempdir().unwrap();
    let node = dir.path().join("pts.node");
    // Valid as text (two points with extra columns), but the extension says .node.
    std::fs::write(&node, "4 2 0 0\n5 6 0 0\n").unwrap();
    let err = read_points_from_path(&node).unwrap_err();
    assert_eq!(err.line, Some(2));
    let csv = dir.path().join("pts.csv");
    std::fs::write(&csv, "A,B,X,Y\r\n0,0,1,2\r\n").unwrap();
    assert_eq!(read_points_from_path(&csv).unwrap(), vec![[1.0, 2.0]]);
    let txt = dir.path().join("pts.txt");
    std::fs::write(&txt, "2 2 0 0\n0 1 2\n1 3 4\n").unwrap();
    assert_eq!(
        read_points_from_path(&txt).unwrap(),
        vec![[1.0, 2.0], [3.0, 4.0]]
    );
}

proptest! {
    #[test]
    fn shortest_decimal_round_trips_exactly(
        points in prop::collection::vec((-1e6f64..1e6, -1e6f64..1e6), 0..40),
        ends in prop::sample::select(vec!["\n", "\r\n", "\r"]),
        separator in prop::sample::select(vec![" ", "\t", ",", " , ", "  "]),
    ) {
        let mut text = String::new();
        for &(x, y) in &points {
            text.push_str(&format!("{x}{separator}{y}{ends}"));
        }
        let parsed = parse(&text).unwrap();
        let expected: Vec<[f64; 2]> = points.iter().map(|&(x, y)| [x, y]).collect();
        prop_assert_eq!(parsed, expected);
    }

    #[test]
    fn arbitrary_bytes_never_panic(bytes in prop::collection::vec(any::<u8>(), 0..200)) {
        if let Err(err) = read_points(&bytes[..], None) {
            let message = err.to_string();
            prop_assert!(!message.contains('\n') && !message.contains('\r'));
        }
    }

    #[test]
    fn arbitrary_text_lines_never_panic(
        lines in prop::collection::vec("[0-9eE.,+\\- \t#a-z\"]{0,12}", 0..12),
        format in prop::sample::select(vec![None, Some(InputFormat::Text), Some(InputFormat::Csv), Some(InputFormat::Node)]),
    ) {
        let text = lines.join("\n");
        if let Err(err) = read_points(text.as_bytes(), format) {
            prop_assert!(err.line.is_some());
            prop_assert!(err.line.unwrap() <= lines.len().max(1));
        }
    }
}

// ----- the real data files -----

/// The real point sets inside the repository (GPL-3.0 data, see `tests/data/README.md`). A
/// missing directory fails the test; nothing is skipped.
fn data_dir() -> PathBuf {
    let dir = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data"));
    assert!(
        dir.is_dir(),
        "test data {} is missing (the real point sets live in tests/data, see its README.md)",
        dir.display()
    );
    dir
}

#[test]
fn real_data_files_have_their_documented_point_counts() {
    let dir = data_dir();
    let files: &[(&str, usize)] = &[
        ("hnn-crust-sgp16/crocodile-conf.p2d", 129),
        ("hnn-crust-sgp16/crocodile-conf.gtn", 129),
        ("hnn-crust-sgp16/mushroom.p2d", 59),
        ("hnn-crust-sgp16/ventilator.p2d", 194),
        ("hnn-crust-sgp16/ventilator.gtn", 194),
        ("fitconnect/data/apple_2percent_noise.txt", 170),
        ("fitconnect/data/butterfly_2percent_noise.txt", 164),
        ("fitconnect/data/crab_2percent_noise.txt", 284),
        ("fitconnect/data/dolphin_2percent_noise.txt", 179),
        ("fitconnect/data/fish.txt", 1000),
        ("fitconnect/data/bot.txt", 1000),
        ("fitconnect/data/Cup0.txt", 263),
        ("fitconnect/data/Keyboard0.txt", 585),
        ("fitconnect/data/Monitor0.txt", 915),
        ("fitconnect/data/Mouse0.txt", 157),
        ("stretchdenoise/data/Circle0.txt", 248),
        ("stretchdenoise/data/drill.txt", 372),
        ("stretchdenoise/data/drill2_xyz.txt", 372),
        ("stretchdenoise/data/drill_xyz.txt", 408),
        ("stretchdenoise/data/drillcase_xyz.txt", 611),
        ("stretchdenoise/data/thing.txt", 343),
        ("stretchdenoise/data/what_xyz.txt", 343),
        ("stretchdenoise/data/vase.txt", 317),
        ("stretchdenoise/data/vase2_xyz.txt", 317),
        ("stretchdenoise/data/vase_xyz.txt", 329),
        ("stretchdenoise/data/stair.xy", 160),
        ("stretchdenoise/data/stair-noise00.xy", 160),
        ("stretchdenoise/data/stair.xym", 160),
        ("stretchdenoise/data/family.p2d", 9990),
    ];
    for &(name, count) in files {
        let path = dir.join(name);
        let points = read_points_from_path(&path).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(points.len(), count, "{name}");
        // Content detection agrees with the extension.
        let head = std::fs::read(&path).unwrap();
        let detected = read_points(&head[..], None).unwrap();
        assert_eq!(detected, points, "{name}");
    }
    for stem in ["crocodile-conf", "ventilator"] {
        let p2d = read_points_from_path(&dir.join(format!("hnn-crust-sgp16/{stem}.p2d"))).unwrap();
        let gtn = read_points_from_path(&dir.join(format!("hnn-crust-sgp16/{stem}.gtn"))).unwrap();
        assert_eq!(p2d, gtn, "{stem}: .gtn and .p2d hold the same points");
        let head = std::fs::read(dir.join(format!("hnn-crust-sgp16/{stem}.gtn"))).unwrap();
        assert_eq!(detect_format(&head), InputFormat::Node);
    }
    // The xyz variants hold the 2D points of their silhouettes in the first two columns.
    let drill = read_points_from_path(&dir.join("stretchdenoise/data/drill.txt")).unwrap();
    let drill2 = read_points_from_path(&dir.join("stretchdenoise/data/drill2_xyz.txt")).unwrap();
    assert_eq!(drill, drill2);
}

// ----- headers select the columns by name -----

#[test]
fn a_header_selects_x_and_y_by_name() {
    let expected = vec![[1.5, 2.0], [-3.0, 4.0]];
    for text in [
        "id,x,y\n7,1.5,2\n8,-3,4\n",
        "ID, X ,Y\n7, 1.5, 2\n8, -3, 4\n",
        "\"id\",\"x\",\"y\"\n\"7\",1.5,2\n\"8\",-3,\"4\"\n",
        "y,x\n2,1.5\n4,-3\n",
        "name,y,weight,x\nNew York,2,0.5,1.5\n\"Bath, UK\",4,1,-3\n",
        // pandas writes an unnamed index column, R a quoted empty name.
        ",x,y\n0,1.5,2\n1,-3,4\n",
        "\"\",\"x\",\"y\"\n\"1\",1.5,2\n\"2\",-3,4\n",
        "id x y\n7 1.5 2\n8 -3 4\n",
        "# exported\n\n  id\tX\tY  # columns\n7\t1.5\t2\n8\t-3\t4\n",
    ] {
        assert_eq!(ok(text), expected, "{text:?}");
        assert_eq!(detect_format(text.as_bytes()), InputFormat::Csv, "{text:?}");
        assert_eq!(
            parse_as(text, InputFormat::Csv).unwrap(),
            expected,
            "{text:?}"
        );
    }
    // A header alone is an empty file.
    assert!(ok("id,x,y\n").is_empty());
}

#[test]
fn a_header_without_x_and_y_names_its_columns() {
    for (text, names) in [
        ("lat,height\n1,2\n", "\"lat\", \"height\""),
        ("long lat_deg\n1 2\n", "\"long\", \"lat_deg\""),
        ("id,x,z\n1,2,3\n", "\"id\", \"x\", \"z\""),
        ("\"X coord\",\"Y coord\"\n1,2\n", "\"X coord\", \"Y coord\""),
        ("east,north\n1,2\n", "\"east\", \"north\""),
    ] {
        let kind = err_at(text, None, 1);
        assert!(
            matches!(kind, ParseErrorKind::HeaderWithoutXY { .. }),
            "{text:?}: {kind}"
        );
        let message = kind.to_string();
        assert!(message.contains(names), "{message}");
        assert!(
            message.contains("but no pair of coordinate names it knows"),
            "{message}"
        );
        assert!(message.contains("--columns X,Y"), "{message}");
    }
    let many: Vec<String> = (0..40).map(|i| format!("c{i}")).collect();
    let kind = err_at(&format!("{}\n", many.join(",")), None, 1);
    assert!(kind.to_string().contains("and 28 more"), "{kind}");
    let kind = err_at("x,y,X\n1,2,3\n", None, 1);
    assert!(
        matches!(kind, ParseErrorKind::DuplicateColumn { ref name } if name == "x"),
        "{kind}"
    );
}

#[test]
fn rows_must_have_the_columns_of_the_header_or_first_row() {
    for (text, line, found, expected, header) in [
        // One column short of the header: id read as x without it.
        ("id,x,y\n7,1.5,2\n1.5,2\n", 3, 2, 3, true),
        ("x,y\n1,2\n3,4,5\n", 3, 3, 2, true),
        // A thousands separator.
        ("1,2\n1,000.5,2\n", 2, 3, 2, false),
        ("1.5 2\n3 4 5\n", 2, 3, 2, false),
        ("1 2 3\n4 5\n", 2, 2, 3, false),
        ("1,2,\n3,4\n", 2, 2, 3, false),
    ] {
        let kind = err_at(text, None, line);
        match kind {
            ParseErrorKind::ColumnCount {
                found: f,
                expected: e,
                header: h,
                ..
            } => assert_eq!((f, e, h), (found, expected, header), "{text:?}"),
            other => panic!("{text:?}: {other}"),
        }
    }
    let message = err_at("id,x,y\n7,1.5,2\n1.5,2\n", None, 3).to_string();
    assert!(
        message.starts_with("2 columns, but the header on line 1 has 3"),
        "{message}"
    );
}

#[test]
fn decimal_commas_are_refused() {
    for (text, axis, token) in [
        ("0,5 1,5\n", Axis::Y, "5 1"),
        ("0,5\t1,5\n", Axis::Y, "5\t1"),
        ("1 0,5\n", Axis::X, "1 0"),
        ("0,5 1\n", Axis::Y, "5 1"),
        ("\"0,5\",\"1,5\"\n", Axis::X, "0,5"),
        ("0,5;1,5\n", Axis::Y, "5;1"),
        ("0;5\n", Axis::X, "0;5"),
        ("x,y,z\n3,25 4,75\n", Axis::Y, "25 4"),
    ] {
        let line = text.lines().count();
        let kind = err_at(text, None, line);
        match &kind {
            ParseErrorKind::NotANumber { axis: a, token: t } => {
                assert_eq!((*a, t.as_str()), (axis, token), "{text:?}");
            }
            other => panic!("{text:?}: {other}"),
        }
        let message = kind.to_string();
        assert!(
            message.contains("decimal commas are not supported"),
            "{message}"
        );
    }
    let message = err_at("0,5;1,5\n", None, 1).to_string();
    assert!(message.contains("semicolons"), "{message}");
    // After rows of two columns, the three fields of `3,25 4,75` are refused first as a
    // change in the number of columns, whose message names the likely cause.
    let kind = err_at("1 2\n3,25 4,75\n", None, 2);
    assert!(
        matches!(kind, ParseErrorKind::ColumnCount { found: 3, .. }),
        "{kind}"
    );
    assert!(kind.to_string().contains("decimal comma"), "{kind}");
}

#[test]
fn a_number_followed_by_anything_is_refused() {
    for (text, axis) in [
        ("1.5x 2\n", Axis::X),
        ("1 2y\n", Axis::Y),
        ("1.5.2 3\n", Axis::X),
        ("1e 2\n", Axis::X),
        ("1e5e 2\n", Axis::X),
        ("0x1A 2\n", Axis::X),
        ("1_000 2\n", Axis::X),
        ("1'000 2\n", Axis::X),
        ("\u{2212}1 2\n", Axis::X),
        ("1 2%\n", Axis::Y),
        ("1-2 3\n", Axis::X),
        ("\"1\"x 2\n", Axis::X),
        ("1,2\"\n", Axis::Y),
    ] {
        let kind = err_at(text, None, 1);
        assert!(
            matches!(kind, ParseErrorKind::NotANumber { axis: a, .. } if a == axis),
            "{text:?}: {kind}"
        );
    }
    // A non-breaking space is no separator: one token, not a number.
    let kind = err_at("1\u{a0}2\n", None, 1);
    assert!(
        matches!(kind, ParseErrorKind::NotANumber { axis: Axis::X, .. }),
        "{kind}"
    );
}

#[test]
fn node_lines_need_exactly_the_fields_of_the_header() {
    let node = Some(InputFormat::Node);
    // One attribute declared, none given; or one too many.
    let kind = err_at("2 2 1 0\n0 1 2\n1 3 4\n", node, 2);
    assert!(
        matches!(
            kind,
            ParseErrorKind::NodeFieldCount {
                found: 3,
                attributes: 1,
                markers: 0
            }
        ),
        "{kind}"
    );
    let kind = err_at("2 2 0 1\n0 1 2 1\n1 3 4 0 9\n", node, 3);
    assert!(
        matches!(kind, ParseErrorKind::NodeFieldCount { found: 5, .. }),
        "{kind}"
    );
    assert!(kind.to_string().contains("3 + 0 + 1"), "{kind}");
    // A decimal comma in a .node point line.
    let kind = err_at("1 2 0 0\n0 1,5 2,5\n", node, 2);
    assert!(matches!(kind, ParseErrorKind::NodeIndex { .. }), "{kind}");
    // Detected, the same content is not a .node file, and not a consistent table either.
    let kind = err_at("1 2 0 0\n0 1,5 2,5\n", None, 2);
    assert!(
        matches!(
            kind,
            ParseErrorKind::NotANumber { .. } | ParseErrorKind::ColumnCount { .. }
        ),
        "{kind}"
    );
}

#[test]
fn every_message_names_the_problem_on_one_line() {
    for text in [
        "id,x,z\n1,2,3\n",
        "x,x,y\n",
        "x,y\n1,2,3\n",
        "0,5 1,5\n",
        "2 2 1 0\n0 1 2\n1 3 4\n",
    ] {
        let err = parse(text).unwrap_err();
        let message = err.to_string();
        assert!(message.starts_with("line "), "{message}");
        assert!(!message.contains('\n'), "{message:?}");
    }
}

proptest! {
    #[test]
    fn a_header_reads_the_named_columns_wherever_they_are(
        rows in prop::collection::vec(prop::collection::vec(-1e6f64..1e6, 4), 1..20),
        x_at in 0usize..4,
        y_offset in 1usize..4,
        separator in prop::sample::select(vec![",", " ", "\t", ", "]),
    ) {
        let y_at = (x_at + y_offset) % 4;
        let names: Vec<&str> = (0..4)
            .map(|i| if i == x_at { "X" } else if i == y_at { "y" } else if i % 2 == 0 { "id" } else { "weight" })
            .collect();
        let mut text = names.join(separator);
        text.push('\n');
        for row in &rows {
            let fields: Vec<String> = row.iter().map(f64::to_string).collect();
            text.push_str(&fields.join(separator));
            text.push('\n');
        }
        let expected: Vec<[f64; 2]> = rows.iter().map(|r| [r[x_at], r[y_at]]).collect();
        prop_assert_eq!(parse(&text).unwrap(), expected);
    }
}

// ----- coordinate names other than x and y; choosing the columns -----

fn read_with(text: &str, columns: &str) -> Result<Vec<[f64; 2]>, ParseError> {
    let options = ReadOptions::new().with_columns(columns.parse().unwrap());
    read_points_with(text.as_bytes(), &options)
}

/// The error of `text` read with `--columns columns`, checking its line and that its message
/// is one line.
fn err_with(text: &str, columns: &str, line: usize) -> ParseErrorKind {
    let err = read_with(text, columns).expect_err(text);
    let message = err.to_string();
    assert_eq!(err.line, Some(line), "{text:?}: {message}");
    assert!(!message.contains('\n'), "{message:?}");
    err.kind
}

#[test]
fn geographic_and_projected_names_are_recognised_in_any_case() {
    // Longitude is x, latitude y, whatever their order in the file.
    let expected = vec![[7.4474, 46.948], [-0.1276, 51.5072]];
    for header in [
        "lon,lat",
        "LON,LAT",
        "Lon,Lat",
        "longitude,latitude",
        "Longitude,Latitude",
        "lng,lat",
        "long,lat",
        "longitude,lat",
        "lon,latitude",
        "easting,northing",
        "Easting,Northing",
        "x,y",
    ] {
        let text = format!("{header}\n7.4474,46.948\n-0.1276,51.5072\n");
        assert_eq!(ok(&text), expected, "{header}");
        assert_eq!(detect_format(text.as_bytes()), InputFormat::Csv, "{header}");
        // Reversed: the y name first.
        let (a, b) = header.split_once(',').unwrap();
        let text = format!("{b},{a}\n46.948,7.4474\n51.5072,-0.1276\n");
        assert_eq!(ok(&text), expected, "{b},{a}");
    }
    // Lat/Long spreadsheets: lat is y although it comes first.
    assert_eq!(
        ok("City,Lat,Long\nBern,46.948,7.4474\nLondon,51.5072,-0.1276\n"),
        expected
    );
    // Quoted names, a byte-order mark, white space around the names, tab separation.
    assert_eq!(
        ok("\u{feff}\"lat\",\"lon\"\r\n46.948,7.4474\r\n51.5072,-0.1276\r\n"),
        expected
    );
    assert_eq!(
        ok("\u{feff}id\t Latitude \tLongitude\n1\t46.948\t7.4474\n2\t51.5072\t-0.1276\n"),
        expected
    );
    // The exact decimals read back bit for bit.
    let [[x, y]] = ok("lat,lon\n0.1,-179.99999999999997\n")[..] else {
        panic!()
    };
    assert_eq!(
        (x.to_bits(), y.to_bits()),
        ((-179.99999999999997f64).to_bits(), 0.1f64.to_bits())
    );
}

#[test]
fn a_header_that_could_be_misread_is_refused() {
    for (text, pairs) in [
        ("x,y,lon,lat\n1,2,3,4\n", "(`x,y` and `lon,lat`)"),
        (
            "lat,lon,Easting,Northing\n1,2,3,4\n",
            "(`lon,lat` and `Easting,Northing`)",
        ),
        (
            "lon,longitude,lat\n1,2,3\n",
            "(`lon,lat` and `longitude,lat`)",
        ),
        (
            "lon,lat,latitude\n1,2,3\n",
            "(`lon,lat` and `lon,latitude`)",
        ),
    ] {
        let kind = err_at(text, None, 1);
        assert!(
            matches!(kind, ParseErrorKind::AmbiguousColumns { .. }),
            "{text:?}: {kind}"
        );
        let message = kind.to_string();
        assert!(message.contains(pairs), "{message}");
        assert!(
            message.contains("choose one with --columns X,Y"),
            "{message}"
        );
    }
    for (text, name) in [("lat,lon,LAT\n1,2,3\n", "lat"), ("x,y,X\n1,2,3\n", "x")] {
        let kind = err_at(text, None, 1);
        assert!(
            matches!(kind, ParseErrorKind::DuplicateColumn { name: ref n } if n == name),
            "{text:?}: {kind}"
        );
        assert!(kind.to_string().contains("--columns 2,3"), "{kind}");
    }
    // A lone coordinate name of another family does not make x,y ambiguous.
    assert_eq!(ok("x,y,lat\n1,2,3\n"), vec![[1.0, 2.0]]);
    // --columns settles each of them.
    assert_eq!(
        read_with("x,y,lon,lat\n1,2,3,4\n", "lon,lat").unwrap(),
        vec![[3.0, 4.0]]
    );
    assert_eq!(
        read_with("x,y,lon,lat\n1,2,3,4\n", "X,Y").unwrap(),
        vec![[1.0, 2.0]]
    );
    assert_eq!(
        read_with("x,y,X\n1,2,3\n", "3,2").unwrap(),
        vec![[3.0, 2.0]]
    );
}

#[test]
fn columns_by_name_in_any_case() {
    let text = "station,height,\"Lon (deg)\",\"Lat (deg)\"\nA,500,7.5,46.25\n\"B, C\",0,-8,47\n";
    let expected = vec![[7.5, 46.25], [-8.0, 47.0]];
    assert_eq!(read_with(text, "lon (deg),LAT (DEG)").unwrap(), expected);
    assert_eq!(
        read_with(text, " Lon (deg) , Lat (deg) ").unwrap(),
        expected
    );
    // y before x.
    assert_eq!(
        read_with(text, "Lat (deg),Lon (deg)").unwrap(),
        vec![[46.25, 7.5], [47.0, -8.0]]
    );
    // The recognised names can be chosen too, and other columns swapped in.
    assert_eq!(
        read_with("id,x,y,z\n1,2,3,4\n", "x,z").unwrap(),
        vec![[2.0, 4.0]]
    );
    // The same with explicit CSV.
    let options = ReadOptions::new()
        .with_format(InputFormat::Csv)
        .with_columns("y,x".parse().unwrap());
    assert_eq!(
        read_points_with("x,y\n1,2\n".as_bytes(), &options).unwrap(),
        vec![[2.0, 1.0]]
    );
}

#[test]
fn columns_by_position() {
    // A file without a header.
    assert_eq!(
        read_with("7 1.5 2\n8 -3 4\n", "2,3").unwrap(),
        vec![[1.5, 2.0], [-3.0, 4.0]]
    );
    assert_eq!(
        read_with("7,1.5,2\n8,-3,4\n", "3,1").unwrap(),
        vec![[2.0, 7.0], [4.0, 8.0]]
    );
    // A header's columns, by position.
    assert_eq!(
        read_with("a,b,c\n1,2,3\n", "3,1").unwrap(),
        vec![[3.0, 1.0]]
    );
    // A first line that looks like a .node header but is a row of four numbers.
    assert_eq!(
        read_with("5 2 0 1\n6 7 8 9\n", "4,3").unwrap(),
        vec![[1.0, 0.0], [9.0, 8.0]]
    );
    assert_eq!(read_with("5 2 0 1\n", "4,1").unwrap(), vec![[1.0, 5.0]]);
    // Every row still needs the columns of the first.
    let kind = err_with("7 1 2\n8 3\n", "2,3", 2);
    assert!(
        matches!(
            kind,
            ParseErrorKind::ColumnCount {
                found: 2,
                expected: 3,
                line: 1,
                header: false
            }
        ),
        "{kind}"
    );
}

#[test]
fn a_chosen_column_the_file_lacks_is_named_with_the_columns_it_has() {
    let kind = err_with("# export\nid,lon,lat\n1,2,3\n", "longitude,lat", 2);
    match &kind {
        ParseErrorKind::ColumnNotFound {
            name,
            columns,
            more,
        } => {
            assert_eq!(name, "longitude");
            assert_eq!(columns, &["id", "lon", "lat"]);
            assert_eq!(*more, 0);
        }
        other => panic!("{other}"),
    }
    assert_eq!(
        kind.to_string(),
        "--columns asks for a column \"longitude\", but the header line has none (names are \
         compared in any case); its columns are \"id\", \"lon\", \"lat\""
    );
    let many: Vec<String> = (0..20).map(|i| format!("c{i}")).collect();
    let kind = err_with(&format!("{}\n", many.join(",")), "x,c1", 1);
    assert!(kind.to_string().ends_with("\"c11\" and 8 more"), "{kind}");
    // By position.
    let kind = err_with("a,b,c\n1,2,3\n", "2,4", 1);
    assert_eq!(
        kind.to_string(),
        "--columns asks for column 4, but the header line has 3 columns"
    );
    let kind = err_with("\n1 2 3\n", "5,1", 2);
    assert_eq!(
        kind.to_string(),
        "--columns asks for column 5, but the first row has 3 columns"
    );
    // A name twice in the header, a name and a position of one column.
    let kind = err_with("lon,Lon,lat\n1,2,3\n", "lon,lat", 1);
    assert!(
        matches!(kind, ParseErrorKind::DuplicateColumn { .. }),
        "{kind}"
    );
    let kind = err_with("lon,lat\n1,2\n", "lon,1", 1);
    assert_eq!(
        kind.to_string(),
        "--columns chooses the column \"lon\" for both x and y"
    );
}

#[test]
fn columns_by_name_need_a_header() {
    let kind = err_with("# no header\n1 2 3\n4 5 6\n", "lon,lat", 2);
    assert!(
        matches!(kind, ParseErrorKind::ColumnsWithoutHeader { ref name } if name == "lon"),
        "{kind}"
    );
    assert!(kind.to_string().contains("--columns 2,3"), "{kind}");
    // Explicit text has no header: a header line stays an error there.
    let options = ReadOptions::new()
        .with_format(InputFormat::Text)
        .with_columns("lon,lat".parse().unwrap());
    let err = read_points_with("lon,lat\n1,2\n".as_bytes(), &options).unwrap_err();
    assert!(matches!(err.kind, ParseErrorKind::HeaderInText), "{err}");
}

#[test]
fn columns_are_refused_for_node_files() {
    let node = "3 2 0 0\n0 1.5 2\n1 3 4\n2 5 6\n";
    // Detected from the content, and asked for.
    let kind = err_with(node, "2,3", 1);
    assert!(matches!(kind, ParseErrorKind::ColumnsInNode), "{kind}");
    let options = ReadOptions::new()
        .with_format(InputFormat::Node)
        .with_columns("2,3".parse().unwrap());
    let err = read_points_with(node.as_bytes(), &options).unwrap_err();
    assert!(matches!(err.kind, ParseErrorKind::ColumnsInNode), "{err}");
    assert_eq!(err.line, Some(1));
}

#[test]
fn column_selections_are_parsed_strictly() {
    let selection: ColumnSelection = " Lon , 3 ".parse().unwrap();
    assert_eq!(selection.x(), &Column::Name("Lon".to_string()));
    assert_eq!(selection.y(), &Column::Position(3));
    assert_eq!(selection.to_string(), "Lon,3");
    for (text, message) in [
        ("lon", "expected two columns X,Y (names or 1-based positions) separated by a comma, got one"),
        ("a,b,c", "expected two columns X,Y (names or 1-based positions) separated by a comma, got 3"),
        ("lon,", "a column name is empty"),
        ("0,1", "column positions count from 1"),
        ("lat,LAT", "x and y must be two different columns, got lat and LAT (names are compared in any case)"),
        ("lat,lat", "x and y must be two different columns, got lat twice"),
        ("2,2", "x and y must be two different columns, got 2 twice"),
        ("1,99999999999999999999999", "column position 99999999999999999999999 is too large"),
    ] {
        let err = text.parse::<ColumnSelection>().unwrap_err();
        assert_eq!(err.to_string(), message, "{text:?}");
    }
}

#[test]
fn files_that_are_no_point_list_say_what_they_look_like() {
    for (content, looks_like, advice) in [
        (
            &b"<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 10 10\">\n"[..],
            FileKind::Svg,
            "this looks like an SVG drawing (XML), not a list of points; export the points as text (one `x y` per line) or CSV",
        ),
        (b"\xEF\xBB\xBF\n  <svg>", FileKind::Svg, "export the points as text"),
        (b"<!DOCTYPE html>\n<html>", FileKind::Html, "an HTML page"),
        (b"<?xml version=\"1.0\"?>\n<gpx>", FileKind::Xml, "an XML document"),
        (
            b"{\"type\":\"FeatureCollection\",\"features\":[]}\n",
            FileKind::Json,
            "this looks like JSON (or GeoJSON), not a list of points",
        ),
        (b"[[0, 1], [2, 3]]\n", FileKind::Json, "JSON"),
        (b"\x1f\x8b\x08\x00\x00\x00", FileKind::Gzip, "gzip -dc FILE"),
        (b"PK\x03\x04\x14\x00\x06\x00", FileKind::Zip, "save the spreadsheet as CSV"),
        (b"\x89PNG\r\n\x1a\n\x00\x00", FileKind::Image, "an image"),
        (b"%PDF-1.7\n%\xe2\xe3", FileKind::Pdf, "a PDF document"),
        (b"\xff\xfe1\x00 \x002\x00\r\x00\n\x00", FileKind::Utf16, "save it as UTF-8"),
    ] {
        for format in [None, Some(InputFormat::Text), Some(InputFormat::Csv), Some(InputFormat::Node)] {
            let err = read_points(content, format).unwrap_err();
            assert_eq!(err.line, None, "{content:?}");
            assert!(
                matches!(err.kind, ParseErrorKind::NotAPointFile { looks_like: k } if k == looks_like),
                "{content:?}: {err}"
            );
            let message = err.to_string();
            assert!(message.contains(advice), "{message}");
            assert!(!message.contains('\n'), "{message:?}");
        }
    }
    // Markup after a comment line, or inside one, keeps the ordinary messages.
    let kind = err_at("# drawing\n<svg>\n", None, 2);
    assert!(matches!(kind, ParseErrorKind::NotANumber { .. }), "{kind}");
    assert_eq!(ok("# <svg> and {json}\n1 2\n"), vec![[1.0, 2.0]]);
}

/// Found by the `parse` fuzz target: with a one-byte buffer the kind of file was told from
/// the one byte buffered, and a head that is UTF-16 without a byte-order mark (ASCII
/// bytes each followed by a NUL) was read as text with a NUL byte. The verdict is taken on
/// a head of fixed length now.
#[test]
fn the_kind_of_file_does_not_depend_on_the_buffer() {
    let inputs: [&[u8]; 4] = [
        b"\t\x00\x0c\x00]\n\n\x95",
        b"  \n\n   <?xml version=\"1.0\"?>\n<svg width=\"10\"/>\n",
        b"\xef\xbb\xbf{\"type\": \"FeatureCollection\"}",
        b"1\x002\x00 \x003\x00\n\x00",
    ];
    for data in inputs {
        let whole = read_points(data, None).map_err(|e| e.to_string());
        for capacity in 1..=8 {
            let split = read_points(BufReader::with_capacity(capacity, data), None)
                .map_err(|e| e.to_string());
            assert_eq!(split, whole, "{data:?}, buffer of {capacity}");
        }
        assert!(
            whole.as_ref().is_err_and(|e| e.contains("this looks like")),
            "{data:?}: {whole:?}"
        );
    }
}
