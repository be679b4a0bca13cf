//! The Voronoi cells clipped to a box as GeoJSON (RFC 7946): a `FeatureCollection` with one
//! `Feature` per distinct input point, properties `{"site": i}`, whose geometry is its cell
//! clipped to the box as a `Polygon` (one ring, closed, counterclockwise), or `null` when the
//! cell meets the box in no area (a site outside a box given by the caller, or a cell thinner
//! than the rounding; see [`Voronoi::clipped_cells`]). Duplicate points get no feature. Coordinates are the input's, printed as the shortest decimal that
//! reads back as the same `f64`.

use std::io::{self, BufWriter, Write};

use crate::voronoi::{BoundingBox, Voronoi};

/// Writes the cells of `vor` clipped to `bbox` as one GeoJSON `FeatureCollection`, one
/// feature per line.
///
/// # Errors
/// Any error of `out`.
///
/// ```
/// use wdm_crust::BoundingBox;
/// let tri = wdm_crust::triangulate(&[[0.0, 0.0], [2.0, 0.0]])?;
/// let bbox = BoundingBox::new([-1.0, -1.0], [3.0, 1.0])?;
/// let mut out = Vec::new();
/// wdm_crust::io::write_voronoi_geojson(&tri.voronoi(), &bbox, &mut out)?;
/// let text = String::from_utf8(out)?;
/// assert!(text.contains(r#""properties":{"site":0},"geometry":{"type":"Polygon","coordinates":[[[-1.0,-1.0],[1.0,-1.0],[1.0,1.0],[-1.0,1.0],[-1.0,-1.0]]]}"#));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn write_voronoi_geojson<W: Write>(
    vor: &Voronoi<'_>,
    bbox: &BoundingBox,
    out: W,
) -> io::Result<()> {
    let mut out = BufWriter::with_capacity(1 << 16, out);
    let tri = vor.triangulation();
    out.write_all(b"{\"type\":\"FeatureCollection\",\"features\":[")?;
    let mut first = true;
    let cells = vor.clipped_cells(bbox);
    for (site, ring) in cells.iter().enumerate() {
        if tri.is_duplicate(site as u32) {
            continue;
        }
        out.write_all(if first { b"\n" } else { b",\n" })?;
        first = false;
        write!(
            out,
            "{{\"type\":\"Feature\",\"properties\":{{\"site\":{site}}},\"geometry\":"
        )?;
        if ring.is_empty() {
            out.write_all(b"null}")?;
            continue;
        }
        out.write_all(b"{\"type\":\"Polygon\",\"coordinates\":[[")?;
        for (k, p) in ring.iter().chain(ring.first()).enumerate() {
            if k > 0 {
                out.write_all(b",")?;
            }
            // The shortest decimal that reads back as the same f64 (serde_json's `ryu`),
            // never NaN or infinity here: the box and the rounded vertices are finite.
            serde_json::to_writer(&mut out, p)?;
        }
        out.write_all(b"]]}}")?;
    }
    out.write_all(b"\n]}\n")?;
    out.flush()
}
