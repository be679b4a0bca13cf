//! `wdm_crust::io::read_points` on arbitrary bytes, in every input format (given or detected):
//! an error with a plausible line number or points, never a panic. Accepted points are finite
//! (so `triangulate` accepts them); the result does not depend on how the
//! reader splits its buffer; detection on the fly agrees with `detect_format`; and the points
//! survive a round trip through plain text.
#![no_main]

use std::io::BufReader;

use libfuzzer_sys::fuzz_target;
use wdm_crust::io::{detect_format, read_points, InputFormat, ParseError, ParseErrorKind};
use wdm_crust_fuzz::checks::expected_error;

/// Number of lines, with `\n`, `\r\n` and lone `\r` as line ends and a final unterminated one.
fn line_count(data: &[u8]) -> usize {
    let mut lines = 0;
    let mut i = 0;
    let mut open = false;
    while i < data.len() {
        match data[i] {
            b'\n' => {
                lines += 1;
                open = false;
            }
            b'\r' => {
                lines += 1;
                open = false;
                if data.get(i + 1) == Some(&b'\n') {
                    i += 1;
                }
            }
            _ => open = true,
        }
        i += 1;
    }
    lines + usize::from(open)
}

/// Results compared by value: points bitwise, errors by line and message.
fn summary(r: &Result<Vec<[f64; 2]>, ParseError>) -> Result<Vec<[u64; 2]>, String> {
    match r {
        Ok(points) => Ok(points.iter().map(|p| p.map(f64::to_bits)).collect()),
        Err(e) => Err(e.to_string()),
    }
}

fuzz_target!(|input: &[u8]| {
    let Some((&capacity, data)) = input.split_first() else {
        return;
    };
    let lines = line_count(data);
    for format in [
        None,
        Some(InputFormat::Text),
        Some(InputFormat::Csv),
        Some(InputFormat::Node),
    ] {
        let whole = read_points(data, format);
        // A tiny buffer splits lines, `\r\n` pairs and UTF-8 sequences across reads.
        let reader = BufReader::with_capacity(usize::from(capacity % 8) + 1, data);
        let split = read_points(reader, format);
        assert_eq!(
            summary(&whole),
            summary(&split),
            "format {format:?}: buffer size matters"
        );
        match &whole {
            // A file that is no point list at all is refused before its first line.
            Err(e) if matches!(e.kind, ParseErrorKind::NotAPointFile { .. }) => {
                assert!(e.line.is_none(), "format {format:?}: {e} on a line");
            }
            Err(e) => {
                let line = e.line.expect("reading a slice cannot fail without a line");
                assert!(
                    line >= 1 && line <= lines.max(1),
                    "format {format:?}: error on line {line} of {lines}: {e}"
                );
            }
            Ok(points) => {
                assert!(
                    expected_error(points).is_none(),
                    "format {format:?}: accepted {:?}",
                    expected_error(points)
                );
                assert!(points.len() <= lines, "more points than lines");
                let text: String = points
                    .iter()
                    .map(|p| format!("{} {}\n", p[0], p[1]))
                    .collect();
                let again = read_points(text.as_bytes(), Some(InputFormat::Text));
                assert_eq!(summary(&whole), summary(&again), "text round trip");
                assert!(wdm_crust::triangulate(points).is_ok());
            }
        }
        if format.is_none() {
            let detected = read_points(data, Some(detect_format(data)));
            assert_eq!(
                summary(&whole),
                summary(&detected),
                "detection on the fly differs from detect_format = {:?}",
                detect_format(data)
            );
        }
    }
});
