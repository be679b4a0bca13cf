//! GeoJSON (RFC 7946) output of a reconstruction, and the pieces every GeoJSON writer of the
//! crate shares.
//!
//! # Reconstruction
//!
//! A `FeatureCollection`, one feature per line, in this order:
//!
//! * one `Polygon` per outer closed curve (see [`Reconstruction::polygons`]): its first ring
//!   is that curve, counterclockwise; the further rings are the closed curves directly inside
//!   it (holes), clockwise; a curve inside a hole starts a polygon of its own. Properties
//!   `{"kind":"curve","points":[...],"holes":[[...],...]}`: the point indices of the outer
//!   ring and of each hole, in ring order, not repeated at the end;
//! * one `LineString` per open chain, properties `{"kind":"chain","points":[...]}`;
//! * one `MultiLineString` for the medial axis, one two-point line per segment (empty for the
//!   baseline algorithms and with `MedialAxisMode::Omitted`), properties
//!   `{"kind":"medial_axis"}`;
//! * one `MultiPoint` of the unassigned points, properties `{"kind":"unassigned","points":[...]}`,
//!   left out when there are none.
//!
//! The collection's own `properties` (after the features) carry `"duplicates"` (pairs
//! `[duplicate, kept]`) and `"warnings"` (`[{"code","message","points"}, ...]`, as in the
//! JSON).
//!
//! Rings are closed (the first position repeated last). Coordinates are the input's, not
//! reprojected, written in the shortest form that reads back to the same `f64`; medial-axis
//! vertices are circumcenters rounded to `f64` (a segment whose rounded end overflowed to an
//! infinity, possible only for coordinates near the top of the `f64` range, is left out: GeoJSON has
//! no infinite positions).
//!
//! ```text
//! {"type":"FeatureCollection","features":[
//! {"type":"Feature","geometry":{"type":"Polygon","coordinates":[[[0.0,0.0],[2.0,0.0],...,[0.0,0.0]],...]},"properties":{"kind":"curve","points":[0,1,...],"holes":[[...]]}},
//! ...
//! ],"properties":{"duplicates":[],"warnings":[]}}
//! ```

use std::io::{self, BufWriter, Write};

use serde::Serialize;

use super::output::WarningsJson;
use crate::Reconstruction;

/// Size of the buffer a writer puts in front of its output.
const BUFFER_BYTES: usize = 1 << 16;

/// A GeoJSON geometry over `[x, y]` positions, serialized as
/// `{"type": "<variant>", "coordinates": ...}`. Rings of a polygon must be closed already
/// (see [`closed_ring`]).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "type", content = "coordinates")]
pub(crate) enum Geometry {
    Polygon(Vec<Vec<[f64; 2]>>),
    LineString(Vec<[f64; 2]>),
    MultiLineString(Vec<Vec<[f64; 2]>>),
    MultiPoint(Vec<[f64; 2]>),
}

/// One `Feature` with its geometry and properties.
#[derive(Serialize)]
struct Feature<'a, P: Serialize> {
    #[serde(rename = "type")]
    kind: &'static str,
    geometry: &'a Geometry,
    properties: &'a P,
}

/// `ring` closed: its first position repeated at the end (unless empty or already closed).
pub(crate) fn closed_ring(mut ring: Vec<[f64; 2]>) -> Vec<[f64; 2]> {
    if let (Some(&first), Some(&last)) = (ring.first(), ring.last()) {
        if ring.len() == 1 || first != last {
            ring.push(first);
        }
    }
    ring
}

/// Writes a `FeatureCollection` one feature per line: [`begin`](Self::begin), then
/// [`feature`](Self::feature) for each, then [`finish_with`](Self::finish_with).
pub(crate) struct FeatureCollectionWriter<W: Write> {
    out: BufWriter<W>,
    features: usize,
}

impl<W: Write> FeatureCollectionWriter<W> {
    /// Starts the collection.
    pub(crate) fn begin(out: W) -> io::Result<Self> {
        let mut out = BufWriter::with_capacity(BUFFER_BYTES, out);
        out.write_all(b"{\"type\":\"FeatureCollection\",\"features\":[")?;
        Ok(FeatureCollectionWriter { out, features: 0 })
    }

    /// Writes one feature.
    pub(crate) fn feature(
        &mut self,
        geometry: &Geometry,
        properties: &impl Serialize,
    ) -> io::Result<()> {
        self.out
            .write_all(if self.features == 0 { b"\n" } else { b",\n" })?;
        let feature = Feature {
            kind: "Feature",
            geometry,
            properties,
        };
        serde_json::to_writer(&mut self.out, &feature)?;
        self.features += 1;
        Ok(())
    }

    /// Ends the collection with `properties` of its own (a foreign member, RFC 7946 § 6.1)
    /// and flushes.
    pub(crate) fn finish_with(mut self, properties: &impl Serialize) -> io::Result<()> {
        self.out.write_all(b"\n],\"properties\":")?;
        serde_json::to_writer(&mut self.out, properties)?;
        self.out.write_all(b"}\n")?;
        self.out.flush()
    }
}

/// Properties of a polygon feature.
#[derive(Serialize)]
struct CurveProperties<'a> {
    kind: &'static str,
    points: &'a [u32],
    holes: &'a [Vec<u32>],
}

/// Properties of a chain or of the unassigned points.
#[derive(Serialize)]
struct PointsProperties<'a> {
    kind: &'static str,
    points: &'a [u32],
}

/// Properties with the kind alone.
#[derive(Serialize)]
struct KindProperties {
    kind: &'static str,
}

/// Writes `rec` as a GeoJSON `FeatureCollection` (see the [module docs](self)).
///
/// # Errors
/// Any error of `out`.
///
/// ```
/// // A square ring of 24 points around a square hole of 8, two spacings away.
/// let mut points = Vec::new();
/// for (r, k) in [(3.0, 6), (1.0, 2)] {
///     let corners = [[-r, -r], [r, -r], [r, r], [-r, r]];
///     for s in 0..4 {
///         let (a, b): ([f64; 2], [f64; 2]) = (corners[s], corners[(s + 1) % 4]);
///         for i in 0..k {
///             let t = i as f64 / k as f64;
///             points.push([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]);
///         }
///     }
/// }
/// let rec = wdm_crust::reconstruct(&points)?;
/// let mut out = Vec::new();
/// wdm_crust::io::write_reconstruction_geojson(&rec, &mut out)?;
/// let json: serde_json::Value = serde_json::from_slice(&out)?;
/// assert_eq!(json["type"], "FeatureCollection");
/// let polygon = &json["features"][0];
/// assert_eq!(polygon["geometry"]["type"], "Polygon");
/// assert_eq!(polygon["properties"]["kind"], "curve");
/// let rings = polygon["geometry"]["coordinates"].as_array().unwrap();
/// assert_eq!(rings.len(), 2); // the outer ring and one hole
/// assert_eq!(rings[0].as_array().unwrap().len(), 25); // closed: 24 points and the first again
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn write_reconstruction_geojson<W: Write>(rec: &Reconstruction, out: W) -> io::Result<()> {
    let mut collection = FeatureCollectionWriter::begin(out)?;
    for polygon in rec.polygons() {
        let mut rings = vec![closed_ring(polygon.exterior_coords(rec))];
        rings.extend(polygon.hole_coords(rec).into_iter().map(closed_ring));
        let properties = CurveProperties {
            kind: "curve",
            points: &polygon.exterior,
            holes: &polygon.holes,
        };
        collection.feature(&Geometry::Polygon(rings), &properties)?;
    }
    for chain in rec.curves().iter().filter(|c| !c.closed) {
        let properties = PointsProperties {
            kind: "chain",
            points: &chain.points,
        };
        collection.feature(&Geometry::LineString(rec.curve_coords(chain)), &properties)?;
    }
    let axis = rec.medial_axis();
    let finite = |p: &[f64; 2]| p[0].is_finite() && p[1].is_finite();
    let segments = axis
        .edges
        .iter()
        .map(|&[a, b]| vec![axis.vertices[a as usize], axis.vertices[b as usize]])
        .filter(|segment| segment.iter().all(finite))
        .collect();
    collection.feature(
        &Geometry::MultiLineString(segments),
        &KindProperties {
            kind: "medial_axis",
        },
    )?;
    let unassigned = rec.unassigned();
    if !unassigned.is_empty() {
        let properties = PointsProperties {
            kind: "unassigned",
            points: unassigned,
        };
        let coords = unassigned
            .iter()
            .map(|&i| rec.triangulation().point(i))
            .collect();
        collection.feature(&Geometry::MultiPoint(coords), &properties)?;
    }
    #[derive(Serialize)]
    struct CollectionProperties<'a> {
        duplicates: &'a [[u32; 2]],
        warnings: WarningsJson<'a>,
    }
    collection.finish_with(&CollectionProperties {
        duplicates: rec.duplicates(),
        warnings: WarningsJson(rec.warnings()),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rings_close_once() {
        assert_eq!(closed_ring(vec![]), Vec::<[f64; 2]>::new());
        assert_eq!(closed_ring(vec![[1.0, 2.0]]), vec![[1.0, 2.0], [1.0, 2.0]]);
        let ring = vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
        let closed = closed_ring(ring.clone());
        assert_eq!(closed.len(), 4);
        assert_eq!(closed_ring(closed.clone()), closed);
    }

    #[test]
    fn coordinates_round_trip_exactly() {
        let collection = {
            let mut out = Vec::new();
            let mut w = FeatureCollectionWriter::begin(&mut out).unwrap();
            let coords = vec![
                [0.1, -0.0],
                [1e-300, 123_456_789.123_456_79],
                [f64::MAX / 1e100, 2f64.powi(-142)],
            ];
            w.feature(
                &Geometry::MultiPoint(coords.clone()),
                &KindProperties { kind: "test" },
            )
            .unwrap();
            w.finish_with(&KindProperties { kind: "collection" })
                .unwrap();
            (out, coords)
        };
        let (out, coords) = collection;
        let value: serde_json::Value = serde_json::from_slice(&out).unwrap();
        let read: Vec<[f64; 2]> =
            serde_json::from_value(value["features"][0]["geometry"]["coordinates"].clone())
                .unwrap();
        for (a, b) in read.iter().zip(&coords) {
            assert_eq!(a[0].to_bits(), b[0].to_bits());
            assert_eq!(a[1].to_bits(), b[1].to_bits());
        }
    }
}
