//! Writing results: the JSON of the public contract and a line-oriented text format.
//!
//! # Triangulation, JSON
//!
//! One object on one line, keys in this order:
//! `{"points":N,"triangles":[[a,b,c],...],"hull":[...],"duplicates":[[dup,kept],...]}`.
//! `triangles` are counterclockwise index triples, `hull` lists the convex hull
//! counterclockwise (for collinear input: the points in order along the line), and
//! `duplicates` pairs each repeated point with the first occurrence of its coordinates.
//!
//! # Triangulation, text
//!
//! Line oriented, so that `grep -v '^#'` leaves exactly the triangles; the `#` lines are
//! comments to the parser of this crate too:
//!
//! ```text
//! # wdm-crust triangulation: 5 points, 2 triangles, 4 hull points, 1 duplicates
//! # hull 0 1 3 2
//! # duplicate 4 0
//! 0 1 3
//! 0 3 2
//! ```
//!
//! The first line counts everything; `# hull` lists the hull like the JSON `hull` (on one
//! line, omitted when empty); one `# duplicate d k` line per duplicate `d` of the earlier
//! point `k`; then one counterclockwise triangle `a b c` per line.
//!
//! Every writer buffers internally and flushes before returning, so any [`Write`] will do.

use std::io::{self, BufWriter, Write};

use serde::Serialize;

use crate::Triangulation;

/// Size of the buffer every writer puts in front of its output.
const BUFFER_BYTES: usize = 1 << 16;

/// The JSON shape of a triangulation, in the order of the public contract.
#[derive(Serialize)]
struct TriangulationJson<'a> {
    points: usize,
    triangles: &'a [[u32; 3]],
    hull: &'a [u32],
    duplicates: &'a [[u32; 2]],
}

/// Writes `tri` as the contract's JSON object, followed by a newline (see the
/// [module docs](self)).
///
/// # Errors
/// Any error of `out`.
///
/// ```
/// let tri = wdm_crust::triangulate(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [0.0, 0.0]])?;
/// let mut out = Vec::new();
/// wdm_crust::io::write_triangulation_json(&tri, &mut out)?;
/// let json = String::from_utf8(out)?;
/// assert!(json.starts_with("{\"points\":4,\"triangles\":[["));
/// assert!(json.ends_with("\"duplicates\":[[3,0]]}\n"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn write_triangulation_json<W: Write>(tri: &Triangulation, out: W) -> io::Result<()> {
    let mut out = BufWriter::with_capacity(BUFFER_BYTES, out);
    let json = TriangulationJson {
        points: tri.points().len(),
        triangles: tri.triangles(),
        hull: tri.hull(),
        duplicates: tri.duplicates(),
    };
    serde_json::to_writer(&mut out, &json)?;
    out.write_all(b"\n")?;
    out.flush()
}

/// Writes `tri` in the line-oriented text format of the [module docs](self).
///
/// # Errors
/// Any error of `out`.
///
/// ```
/// let tri = wdm_crust::triangulate(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])?;
/// let mut out = Vec::new();
/// wdm_crust::io::write_triangulation_text(&tri, &mut out)?;
/// let text = String::from_utf8(out)?;
/// let lines: Vec<&str> = text.lines().collect();
/// assert_eq!(lines.len(), 3);
/// assert!(lines[0].starts_with("# wdm-crust triangulation: 3 points, 1 triangles"));
/// assert!(lines[1].starts_with("# hull "));
/// let [a, b, c] = tri.triangles()[0];
/// assert_eq!(lines[2], format!("{a} {b} {c}"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn write_triangulation_text<W: Write>(tri: &Triangulation, out: W) -> io::Result<()> {
    let mut out = BufWriter::with_capacity(BUFFER_BYTES, out);
    writeln!(
        out,
        "# wdm-crust triangulation: {} points, {} triangles, {} hull points, {} duplicates",
        tri.points().len(),
        tri.triangles().len(),
        tri.hull().len(),
        tri.duplicates().len()
    )?;
    let mut line = IndexLine::default();
    if !tri.hull().is_empty() {
        out.write_all(b"# hull")?;
        for &i in tri.hull() {
            line.clear();
            line.push(i);
            out.write_all(line.as_bytes())?;
        }
        out.write_all(b"\n")?;
    }
    for &[duplicate, kept] in tri.duplicates() {
        line.clear();
        line.push(duplicate);
        line.push(kept);
        out.write_all(b"# duplicate")?;
        out.write_all(line.as_bytes())?;
        out.write_all(b"\n")?;
    }
    for triangle in tri.triangles() {
        line.clear();
        for &i in triangle {
            line.push(i);
        }
        line.end();
        out.write_all(&line.as_bytes()[1..])?;
    }
    out.flush()
}

/// A reusable buffer of ` i j k` index lists, formatted without `fmt` machinery.
#[derive(Default)]
struct IndexLine {
    bytes: Vec<u8>,
}

impl IndexLine {
    fn clear(&mut self) {
        self.bytes.clear();
    }

    /// Appends a space and `value` in decimal.
    fn push(&mut self, mut value: u32) {
        let mut digits = [0u8; 10];
        let mut n = digits.len();
        loop {
            n -= 1;
            digits[n] = b'0' + (value % 10) as u8;
            value /= 10;
            if value == 0 {
                break;
            }
        }
        self.bytes.push(b' ');
        self.bytes.extend_from_slice(&digits[n..]);
    }

    /// Appends a line end.
    fn end(&mut self) {
        self.bytes.push(b'\n');
    }

    fn as_bytes(&self) -> &[u8] {
        &self.bytes
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square_with_duplicate() -> Triangulation {
        crate::triangulate(&[[0.0, 0.0], [4.0, 0.0], [0.0, 3.0], [4.0, 3.0], [0.0, 0.0]]).unwrap()
    }

    #[test]
    fn json_has_the_contract_shape() {
        let tri = square_with_duplicate();
        let mut out = Vec::new();
        write_triangulation_json(&tri, &mut out).unwrap();
        let text = String::from_utf8(out).unwrap();
        assert!(text.starts_with("{\"points\":5,\"triangles\":[["));
        assert!(text.ends_with("\"duplicates\":[[4,0]]}\n"));
        let value: serde_json::Value = serde_json::from_str(&text).unwrap();
        let object = value.as_object().unwrap();
        let keys: Vec<&str> = object.keys().map(String::as_str).collect();
        assert_eq!(keys.len(), 4);
        assert_eq!(value["points"], 5);
        assert_eq!(value["triangles"].as_array().unwrap().len(), 2);
        assert_eq!(value["hull"].as_array().unwrap().len(), 4);
        let triangles: Vec<[u32; 3]> = serde_json::from_value(value["triangles"].clone()).unwrap();
        assert_eq!(triangles, tri.triangles());
        let hull: Vec<u32> = serde_json::from_value(value["hull"].clone()).unwrap();
        assert_eq!(hull, tri.hull());
    }

    #[test]
    fn text_lists_triangles_after_comment_lines() {
        let tri = square_with_duplicate();
        let mut out = Vec::new();
        write_triangulation_text(&tri, &mut out).unwrap();
        let text = String::from_utf8(out).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(
            lines[0],
            "# wdm-crust triangulation: 5 points, 2 triangles, 4 hull points, 1 duplicates"
        );
        let hull: Vec<String> = tri.hull().iter().map(u32::to_string).collect();
        assert_eq!(lines[1], format!("# hull {}", hull.join(" ")));
        assert_eq!(lines[2], "# duplicate 4 0");
        let triangles: Vec<[u32; 3]> = lines[3..]
            .iter()
            .map(|line| {
                let v: Vec<u32> = line.split(' ').map(|t| t.parse().unwrap()).collect();
                [v[0], v[1], v[2]]
            })
            .collect();
        assert_eq!(triangles, tri.triangles());
    }

    #[test]
    fn text_of_collinear_and_empty_input() {
        let tri = crate::triangulate(&[[0.0, 0.0], [2.0, 2.0], [1.0, 1.0]]).unwrap();
        let mut out = Vec::new();
        write_triangulation_text(&tri, &mut out).unwrap();
        let text = String::from_utf8(out).unwrap();
        assert_eq!(
            text,
            "# wdm-crust triangulation: 3 points, 0 triangles, 3 hull points, 0 duplicates\n# hull 0 2 1\n"
        );

        let tri = crate::triangulate(&[]).unwrap();
        let mut out = Vec::new();
        write_triangulation_json(&tri, &mut out).unwrap();
        assert_eq!(
            String::from_utf8(out).unwrap(),
            "{\"points\":0,\"triangles\":[],\"hull\":[],\"duplicates\":[]}\n"
        );
    }

    #[test]
    fn decimal_formatting() {
        let mut line = IndexLine::default();
        for v in [0, 7, 10, 99, 1_000_000, u32::MAX] {
            line.clear();
            line.push(v);
            assert_eq!(line.as_bytes(), format!(" {v}").as_bytes());
        }
    }
}
