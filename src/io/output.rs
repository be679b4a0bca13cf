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
//! # Voronoi diagram, JSON
//!
//! `{"vertices":[[x,y],...],"edges":[[a,b],...],"rays":[[a,dx,dy],...],"cells":[[v0,v1,...],...]}`
//! on one line. `vertices` are the circumcenters of the merged Delaunay faces (rounded to
//! f64); `edges` join two finite vertices; a ray starts at vertex `a` and runs to infinity
//! along `(dx, dy)`, the outward normal of its hull edge (not normalised); `cells[i]` lists the
//! vertices of the cell of point `i` counterclockwise (for a hull point: from the vertex of
//! its outgoing ray to the vertex of its incoming ray). The cell of a duplicate is empty.
//! Collinear input (and fewer than three distinct points) has no vertex: every array is
//! empty except `cells`, which holds one empty list per point.
//!
//! # Voronoi diagram, text
//!
//! One record per line, a letter first, so that `grep '^v '` (etc.) picks one kind:
//!
//! ```text
//! # wdm-crust voronoi: 5 points, 4 vertices, 4 edges, 4 rays
//! v 1.0 -0.25
//! e 0 1
//! r 0 0.0 -1.0
//! c 0 0 3
//! ```
//!
//! `v x y` is a vertex (numbered from 0 in the order of the `v` lines), `e a b` a finite edge,
//! `r a dx dy` a ray, `c p v0 v1 ...` the cell of point `p` (one `c` line per point, in order;
//! just `c p` when the cell is empty). Coordinates are written in Rust's shortest round-trip
//! form (`0.5`, `1e-7`). For collinear input a `# collinear: ...` comment line follows the
//! first, then one `# bisector i j` line per pair of consecutive points along the line: the
//! diagram is their perpendicular bisectors, which have no vertex.
//!
//! # Reconstruction, JSON
//!
//! `{"algorithm":"wdm","points":N,"edges":[[i,j],...],"curves":[{"closed":true,"points":[...],"coords":[[x,y],...]},...],
//! "medial_axis":{"vertices":[[x,y],...],"edges":[[a,b],...]},"unassigned":[i,...],
//! "duplicates":[[dup,kept],...],"warnings":[{"code":"...","message":"...","points":[...]},...]}`
//! on one line: the fields of [`Reconstruction`] (`edges` with `i < j`, sorted; `curves` as
//! in [`Curve`], each with the coordinates of its points, the fitted ones with smoothing,
//! [`Reconstruction::curve_vertex`]; the medial axis as in
//! [`MedialAxis`], empty for the baseline algorithms; `unassigned` as in
//! [`Reconstruction::unassigned`]; `duplicates` as for the triangulation; `warnings` as in
//! [`Reconstruction::warnings`], empty when there is nothing to say); `"thinned": N` only
//! when a dense noisy band was thinned to N representatives ([`Reconstruction::thinned`]).
//!
//! # Reconstruction, text
//!
//! One reconstructed edge `i j` (`i < j`) per line, sorted, nothing else.
//!
//! Every writer buffers internally and flushes before returning, so any [`Write`] will do.

use std::io::{self, BufWriter, Write};

use serde::ser::{SerializeSeq, Serializer};
use serde::Serialize;

use crate::reconstruct::{Curve, MedialAxis, Warning};
use crate::{Reconstruction, Triangulation, VertexId, Voronoi};

/// Size of the buffer every writer puts in front of its output.
const BUFFER_BYTES: usize = 1 << 16;

/// The JSON shape of a triangulation, in the order of the public contract.
#[derive(Serialize)]
struct TriangulationJson<'a> {
    points: usize,
    triangles: Triangles<'a>,
    hull: Hull<'a>,
    duplicates: &'a [[u32; 2]],
}

/// Serializes the triangles (caller indices) one at a time, without a copy of them all.
struct Triangles<'a>(&'a Triangulation);

impl Serialize for Triangles<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_seq(self.0.triangles())
    }
}

/// Serializes the hull (caller indices) one point at a time.
struct Hull<'a>(&'a Triangulation);

impl Serialize for Hull<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_seq(self.0.hull())
    }
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
        points: tri.point_count(),
        triangles: Triangles(tri),
        hull: Hull(tri),
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
/// let [a, b, c] = tri.triangle(wdm_crust::TriangleId::new(0));
/// assert_eq!(lines[2], format!("{a} {b} {c}"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn write_triangulation_text<W: Write>(tri: &Triangulation, out: W) -> io::Result<()> {
    let mut out = BufWriter::with_capacity(BUFFER_BYTES, out);
    writeln!(
        out,
        "# wdm-crust triangulation: {} points, {} triangles, {} hull points, {} duplicates",
        tri.point_count(),
        tri.triangle_count(),
        tri.hull().len(),
        tri.duplicates().len()
    )?;
    let mut line = IndexLine::default();
    if tri.hull().len() > 0 {
        out.write_all(b"# hull")?;
        for i in tri.hull() {
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
        for i in triangle {
            line.push(i);
        }
        line.end();
        out.write_all(&line.as_bytes()[1..])?;
    }
    out.flush()
}

/// The JSON shape of a Voronoi diagram, in the order of the public contract.
#[derive(Serialize)]
struct VoronoiJson<'v, 'a> {
    vertices: &'v [[f64; 2]],
    edges: Vec<[VertexId; 2]>,
    rays: Vec<(VertexId, f64, f64)>,
    cells: Cells<'v, 'a>,
}

/// Serializes the cells one at a time, without holding them all.
struct Cells<'v, 'a>(&'v Voronoi<'a>);

impl Serialize for Cells<'_, '_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let n = self.0.triangulation().point_count();
        let mut seq = serializer.serialize_seq(Some(n))?;
        let mut cell = Vec::new();
        for p in 0..n as u32 {
            cell.clear();
            cell.extend(self.0.cell(p));
            seq.serialize_element(&cell)?;
        }
        seq.end()
    }
}

/// Writes `vor` as the contract's JSON object, followed by a newline (see the
/// [module docs](self)).
///
/// # Errors
/// Any error of `out`.
///
/// ```
/// // A square and its centre: four vertices, four edges, four rays.
/// let pts = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0], [1.0, 0.5]];
/// let tri = wdm_crust::triangulate(&pts)?;
/// let mut out = Vec::new();
/// wdm_crust::io::write_voronoi_json(&tri.voronoi(), &mut out)?;
/// let json: serde_json::Value = serde_json::from_slice(&out)?;
/// assert_eq!(json["vertices"].as_array().unwrap().len(), 4);
/// assert_eq!(json["edges"].as_array().unwrap().len(), 4);
/// assert_eq!(json["rays"].as_array().unwrap().len(), 4);
/// assert_eq!(json["cells"][4].as_array().unwrap().len(), 4);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn write_voronoi_json<W: Write>(vor: &Voronoi<'_>, out: W) -> io::Result<()> {
    let mut out = BufWriter::with_capacity(BUFFER_BYTES, out);
    let json = VoronoiJson {
        vertices: vor.vertex_positions(),
        edges: vor.finite_edges().map(|(_, a, b)| [a, b]).collect(),
        rays: vor.rays().map(|(_, v, [dx, dy])| (v, dx, dy)).collect(),
        cells: Cells(vor),
    };
    serde_json::to_writer(&mut out, &json)?;
    out.write_all(b"\n")?;
    out.flush()
}

/// Writes `vor` in the line-oriented text format of the [module docs](self).
///
/// # Errors
/// Any error of `out`.
///
/// ```
/// let tri = wdm_crust::triangulate(&[[0.0, 0.0], [2.0, 0.0], [0.0, 2.0]])?;
/// let mut out = Vec::new();
/// wdm_crust::io::write_voronoi_text(&tri.voronoi(), &mut out)?;
/// let text = String::from_utf8(out)?;
/// let lines: Vec<&str> = text.lines().collect();
/// assert_eq!(lines[0], "# wdm-crust voronoi: 3 points, 1 vertices, 0 edges, 3 rays");
/// assert_eq!(lines[1], "v 1.0 1.0");
/// assert_eq!(lines.iter().filter(|l| l.starts_with("r 0 ")).count(), 3);
/// assert_eq!(lines.iter().filter(|l| l.starts_with("c ")).count(), 3);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn write_voronoi_text<W: Write>(vor: &Voronoi<'_>, out: W) -> io::Result<()> {
    let mut out = BufWriter::with_capacity(BUFFER_BYTES, out);
    let tri = vor.triangulation();
    let edges: Vec<(VertexId, VertexId)> = vor.finite_edges().map(|(_, a, b)| (a, b)).collect();
    writeln!(
        out,
        "# wdm-crust voronoi: {} points, {} vertices, {} edges, {} rays",
        tri.point_count(),
        vor.vertex_count(),
        edges.len(),
        vor.rays().count()
    )?;
    let bisectors = vor.collinear_bisectors();
    if !bisectors.is_empty() {
        out.write_all(
            b"# collinear: no vertices; the diagram is the perpendicular bisectors of these pairs\n",
        )?;
        for [a, b] in bisectors {
            writeln!(out, "# bisector {a} {b}")?;
        }
    }
    for &[x, y] in vor.vertex_positions() {
        writeln!(out, "v {x:?} {y:?}")?;
    }
    let mut line = IndexLine::default();
    for (a, b) in edges {
        line.clear();
        line.push(a.get());
        line.push(b.get());
        line.end();
        out.write_all(b"e")?;
        out.write_all(line.as_bytes())?;
    }
    for (_, v, [dx, dy]) in vor.rays() {
        writeln!(out, "r {v} {dx:?} {dy:?}")?;
    }
    for p in 0..tri.point_count() as u32 {
        line.clear();
        line.push(p);
        for v in vor.cell(p) {
            line.push(v.get());
        }
        line.end();
        out.write_all(b"c")?;
        out.write_all(line.as_bytes())?;
    }
    out.flush()
}

/// The JSON shape of a reconstruction, in the order of the public contract.
#[derive(Serialize)]
struct ReconstructionJson<'a> {
    algorithm: &'static str,
    points: usize,
    edges: &'a [[u32; 2]],
    curves: CurvesJson<'a>,
    medial_axis: &'a MedialAxis,
    unassigned: &'a [u32],
    duplicates: &'a [[u32; 2]],
    warnings: WarningsJson<'a>,
    #[serde(skip_serializing_if = "Option::is_none")]
    thinned: Option<usize>,
}

/// The curves, each with the coordinates of its points.
struct CurvesJson<'a>(&'a Reconstruction);

impl Serialize for CurvesJson<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let rec = self.0;
        serializer.collect_seq(rec.curves().iter().map(|curve| CurveJson { rec, curve }))
    }
}

/// One curve: `{"closed", "points", "coords"}`.
struct CurveJson<'a> {
    rec: &'a Reconstruction,
    curve: &'a Curve,
}

impl Serialize for CurveJson<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeStruct;
        /// The curve vertices: the input points, or the fitted ones with smoothing.
        struct Coords<'a>(&'a Reconstruction, &'a [u32]);
        impl Serialize for Coords<'_> {
            fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
                serializer.collect_seq(self.1.iter().filter_map(|&i| self.0.curve_vertex(i)))
            }
        }
        let mut curve = serializer.serialize_struct("Curve", 3)?;
        curve.serialize_field("closed", &self.curve.closed)?;
        curve.serialize_field("points", &self.curve.points)?;
        curve.serialize_field("coords", &Coords(self.rec, &self.curve.points))?;
        curve.end()
    }
}

/// The warnings as `[{"code", "message", "points"}, ...]`.
pub(crate) struct WarningsJson<'a>(pub(crate) &'a [Warning]);

impl Serialize for WarningsJson<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        #[derive(Serialize)]
        struct One<'a> {
            code: &'static str,
            message: &'a str,
            points: &'a [u32],
        }
        serializer.collect_seq(self.0.iter().map(|w| One {
            code: w.code.name(),
            message: &w.message,
            points: &w.points,
        }))
    }
}

/// Writes `rec` as the contract's JSON object, followed by a newline (see the
/// [module docs](self)).
///
/// # Errors
/// Any error of `out`.
///
/// ```
/// // Eight points on a circle: one closed curve.
/// let octagon: Vec<[f64; 2]> = (0..8)
///     .map(|k| [(k as f64 * 0.785).cos(), (k as f64 * 0.785).sin()])
///     .collect();
/// let rec = wdm_crust::reconstruct(&octagon)?;
/// let mut out = Vec::new();
/// wdm_crust::io::write_reconstruction_json(&rec, &mut out)?;
/// let json = String::from_utf8(out)?;
/// assert!(json.starts_with("{\"algorithm\":\"wdm\",\"points\":8,\"edges\":[["));
/// let value: serde_json::Value = serde_json::from_str(&json)?;
/// assert_eq!(value["edges"].as_array().unwrap().len(), rec.edges().len());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn write_reconstruction_json<W: Write>(rec: &Reconstruction, out: W) -> io::Result<()> {
    let mut out = BufWriter::with_capacity(BUFFER_BYTES, out);
    let json = ReconstructionJson {
        algorithm: rec.algorithm().name(),
        points: rec.triangulation().point_count(),
        edges: rec.edges(),
        curves: CurvesJson(rec),
        medial_axis: rec.medial_axis(),
        unassigned: rec.unassigned(),
        duplicates: rec.duplicates(),
        warnings: WarningsJson(rec.warnings()),
        thinned: rec.thinned(),
    };
    serde_json::to_writer(&mut out, &json)?;
    out.write_all(b"\n")?;
    out.flush()
}

/// Writes the edges of `rec`, one `i j` per line (see the [module docs](self)).
///
/// # Errors
/// Any error of `out`.
///
/// ```
/// // Eight points on a circle: one closed curve.
/// let octagon: Vec<[f64; 2]> = (0..8)
///     .map(|k| [(k as f64 * 0.785).cos(), (k as f64 * 0.785).sin()])
///     .collect();
/// let rec = wdm_crust::reconstruct(&octagon)?;
/// let mut out = Vec::new();
/// wdm_crust::io::write_reconstruction_text(&rec, &mut out)?;
/// let text = String::from_utf8(out)?;
/// assert_eq!(text.lines().count(), rec.edges().len());
/// let [i, j] = rec.edges()[0];
/// assert!(text.starts_with(&format!("{i} {j}\n")));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn write_reconstruction_text<W: Write>(rec: &Reconstruction, out: W) -> io::Result<()> {
    let mut out = BufWriter::with_capacity(BUFFER_BYTES, out);
    let mut line = IndexLine::default();
    for &[i, j] in rec.edges() {
        line.clear();
        line.push(i);
        line.push(j);
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
        assert_eq!(triangles, tri.triangles().collect::<Vec<_>>());
        let hull: Vec<u32> = serde_json::from_value(value["hull"].clone()).unwrap();
        assert_eq!(hull, tri.hull().collect::<Vec<_>>());
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
        let hull: Vec<String> = tri.hull().map(|i| i.to_string()).collect();
        assert_eq!(lines[1], format!("# hull {}", hull.join(" ")));
        assert_eq!(lines[2], "# duplicate 4 0");
        let triangles: Vec<[u32; 3]> = lines[3..]
            .iter()
            .map(|line| {
                let v: Vec<u32> = line.split(' ').map(|t| t.parse().unwrap()).collect();
                [v[0], v[1], v[2]]
            })
            .collect();
        assert_eq!(triangles, tri.triangles().collect::<Vec<_>>());
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
    fn voronoi_json_and_text_of_a_square_with_its_centre() {
        let tri = crate::triangulate(&[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0], [1.0, 0.5]])
            .unwrap();
        let vor = tri.voronoi();
        let mut out = Vec::new();
        write_voronoi_json(&vor, &mut out).unwrap();
        let text = String::from_utf8(out).unwrap();
        assert!(text.starts_with("{\"vertices\":[["));
        let value: serde_json::Value = serde_json::from_str(&text).unwrap();
        let vertices: Vec<[f64; 2]> = serde_json::from_value(value["vertices"].clone()).unwrap();
        assert_eq!(vertices.len(), vor.vertex_positions().len());
        for (a, b) in vertices.iter().zip(vor.vertex_positions()) {
            assert!(
                (a[0] - b[0]).abs() + (a[1] - b[1]).abs() <= 1e-15,
                "{a:?} {b:?}"
            );
        }
        let rays: Vec<(VertexId, f64, f64)> =
            serde_json::from_value(value["rays"].clone()).unwrap();
        let expected: Vec<(VertexId, f64, f64)> =
            vor.rays().map(|(_, v, [dx, dy])| (v, dx, dy)).collect();
        assert_eq!(rays, expected);
        let cells: Vec<Vec<VertexId>> = serde_json::from_value(value["cells"].clone()).unwrap();
        assert_eq!(cells.len(), 5);
        assert_eq!(cells[4], vor.cell(4).collect::<Vec<_>>());

        let mut out = Vec::new();
        write_voronoi_text(&vor, &mut out).unwrap();
        let text = String::from_utf8(out).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(
            lines[0],
            "# wdm-crust voronoi: 5 points, 4 vertices, 4 edges, 4 rays"
        );
        assert_eq!(lines.iter().filter(|l| l.starts_with("v ")).count(), 4);
        assert_eq!(lines.iter().filter(|l| l.starts_with("e ")).count(), 4);
        assert_eq!(lines.iter().filter(|l| l.starts_with("r ")).count(), 4);
        let c4: Vec<String> = vor.cell(4).map(|v| v.to_string()).collect();
        assert_eq!(*lines.last().unwrap(), format!("c 4 {}", c4.join(" ")));
    }

    #[test]
    fn voronoi_text_of_collinear_points_lists_the_bisectors() {
        let tri = crate::triangulate(&[[0.0, 0.0], [1.0, 1.0], [1.0, 1.0]]).unwrap();
        let mut out = Vec::new();
        write_voronoi_text(&tri.voronoi(), &mut out).unwrap();
        assert_eq!(
            String::from_utf8(out).unwrap(),
            "# wdm-crust voronoi: 3 points, 0 vertices, 0 edges, 0 rays\n\
             # collinear: no vertices; the diagram is the perpendicular bisectors of these pairs\n\
             # bisector 0 1\nc 0\nc 1\nc 2\n"
        );
    }

    #[test]
    fn reconstruction_json_and_text() {
        let points: Vec<[f64; 2]> = (0..10)
            .map(|k| {
                let t = f64::from(k * 3 % 10) * std::f64::consts::TAU / 10.0;
                [t.cos(), t.sin()]
            })
            .collect();
        let rec = crate::reconstruct(&points).unwrap();
        let mut out = Vec::new();
        write_reconstruction_json(&rec, &mut out).unwrap();
        let text = String::from_utf8(out).unwrap();
        let value: serde_json::Value = serde_json::from_str(&text).unwrap();
        assert_eq!(value["algorithm"], "wdm");
        assert_eq!(value["points"], 10);
        let edges: Vec<[u32; 2]> = serde_json::from_value(value["edges"].clone()).unwrap();
        assert_eq!(edges, rec.edges());
        let curves = value["curves"].as_array().unwrap();
        assert_eq!(curves.len(), rec.curves().len());
        for (json, curve) in curves.iter().zip(rec.curves()) {
            assert_eq!(json["closed"], curve.closed);
            assert_eq!(json["points"], serde_json::to_value(&curve.points).unwrap());
            let coords: Vec<[f64; 2]> = serde_json::from_value(json["coords"].clone()).unwrap();
            assert_eq!(coords, rec.curve_coords(curve));
        }
        assert_eq!(value["duplicates"], serde_json::json!([]));
        assert!(value["warnings"].is_array());
        let axis = &value["medial_axis"];
        let axis_edges: Vec<[u32; 2]> = serde_json::from_value(axis["edges"].clone()).unwrap();
        assert_eq!(axis_edges, rec.medial_axis().edges);
        // serde_json's parser may be one unit in the last place off: compare loosely.
        let vertices: Vec<[f64; 2]> = serde_json::from_value(axis["vertices"].clone()).unwrap();
        assert_eq!(vertices.len(), rec.medial_axis().vertices.len());
        for (a, b) in vertices.iter().zip(&rec.medial_axis().vertices) {
            for k in 0..2 {
                assert!((a[k] - b[k]).abs() <= 1e-15 * b[k].abs(), "{a:?} {b:?}");
            }
        }

        let mut out = Vec::new();
        write_reconstruction_text(&rec, &mut out).unwrap();
        let expected: String = rec
            .edges()
            .iter()
            .map(|[i, j]| format!("{i} {j}\n"))
            .collect();
        assert_eq!(String::from_utf8(out).unwrap(), expected);
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
