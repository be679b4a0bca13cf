//! Points in and curves out in the types of other geometry crates, behind optional features.
//!
//! * [`ToPoints`]: the points the library takes (`&[[f64; 2]]`), copied out of
//!   `geo_types` coordinates, points, multi-points and line strings (feature `geo-types`) and
//!   of `mint::Point2<f64>` (feature `mint`), in their order: point `i` of the result is item
//!   `i` of the source, so every index in a result refers to the source.
//! * With `geo-types`, a [`Reconstruction`](crate::Reconstruction)'s curves as
//!   `geo_types` geometry: `Reconstruction::polygons_geo` (a `MultiPolygon` with holes),
//!   `Reconstruction::chains_geo` (a `LineString` per open chain),
//!   `Reconstruction::medial_axis_geo` (a `MultiLineString`), and `Polygon::to_geo`.
//!
//! Without these features the module holds only [`ToPoints`] for `[[f64; 2]]`, and the
//! engine compiles without the extra crates.
//!
//! ```
//! use wdm_crust::interop::ToPoints;
//!
//! let raw = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
//! let tri = wdm_crust::triangulate(&raw.to_points())?;
//! assert_eq!(tri.triangle_count(), 1);
//! # Ok::<(), wdm_crust::Error>(())
//! ```

/// A source of points, copied into the `[x, y]` pairs the library takes, in order.
pub trait ToPoints {
    /// The points, in the source's order.
    fn to_points(&self) -> Vec<[f64; 2]>;
}

impl ToPoints for [[f64; 2]] {
    fn to_points(&self) -> Vec<[f64; 2]> {
        self.to_vec()
    }
}

#[cfg(feature = "mint")]
mod with_mint {
    use super::ToPoints;

    /// ```
    /// use wdm_crust::interop::ToPoints;
    ///
    /// let points = [
    ///     mint::Point2 { x: 0.0, y: 0.0 },
    ///     mint::Point2 { x: 2.0, y: 0.0 },
    ///     mint::Point2 { x: 0.0, y: 2.0 },
    /// ];
    /// let tri = wdm_crust::triangulate(&points.to_points())?;
    /// assert_eq!(tri.point(1), [2.0, 0.0]);
    /// # Ok::<(), wdm_crust::Error>(())
    /// ```
    impl ToPoints for [mint::Point2<f64>] {
        fn to_points(&self) -> Vec<[f64; 2]> {
            self.iter().map(|p| [p.x, p.y]).collect()
        }
    }
}

#[cfg(feature = "geo-types")]
mod with_geo_types {
    use geo_types::{Coord, LineString, MultiLineString, MultiPoint, Point};

    use super::ToPoints;
    use crate::reconstruct::Polygon;
    use crate::Reconstruction;

    impl ToPoints for [Coord<f64>] {
        fn to_points(&self) -> Vec<[f64; 2]> {
            self.iter().map(|c| [c.x, c.y]).collect()
        }
    }

    impl ToPoints for [Point<f64>] {
        fn to_points(&self) -> Vec<[f64; 2]> {
            self.iter().map(|p| [p.x(), p.y()]).collect()
        }
    }

    impl ToPoints for MultiPoint<f64> {
        fn to_points(&self) -> Vec<[f64; 2]> {
            self.0.to_points()
        }
    }

    /// Every position of the line string, a closed one's repeated end included.
    impl ToPoints for LineString<f64> {
        fn to_points(&self) -> Vec<[f64; 2]> {
            self.0.to_points()
        }
    }

    fn line(coords: Vec<[f64; 2]>) -> LineString<f64> {
        coords.into_iter().map(|[x, y]| Coord { x, y }).collect()
    }

    impl Polygon {
        /// This polygon as a `geo_types::Polygon` (rings closed, exterior counterclockwise,
        /// holes clockwise), with the coordinates of the reconstruction `rec` it came from.
        pub fn to_geo(&self, rec: &Reconstruction) -> geo_types::Polygon<f64> {
            geo_types::Polygon::new(
                line(self.exterior_coords(rec)),
                self.hole_coords(rec).into_iter().map(line).collect(),
            )
        }
    }

    impl Reconstruction {
        /// The closed curves as polygons with holes ([`polygons`](Self::polygons)), as one
        /// `geo_types::MultiPolygon`.
        ///
        /// ```
        /// use geo_types::MultiPoint;
        /// use wdm_crust::interop::ToPoints;
        ///
        /// // Two concentric circles: one polygon with a hole.
        /// let mut points = Vec::new();
        /// for (r, n) in [(2.0, 40), (1.0, 20)] {
        ///     for k in 0..n {
        ///         let t = k as f64 * std::f64::consts::TAU / n as f64;
        ///         points.push(geo_types::Point::new(r * t.cos(), r * t.sin()));
        ///     }
        /// }
        /// let points = MultiPoint::new(points);
        /// let rec = wdm_crust::reconstruct(&points.to_points())?;
        /// let shapes = rec.polygons_geo();
        /// assert_eq!(shapes.0.len(), 1);
        /// assert_eq!(shapes.0[0].exterior().0.len(), 41); // closed
        /// assert_eq!(shapes.0[0].interiors().len(), 1);
        /// # Ok::<(), wdm_crust::Error>(())
        /// ```
        pub fn polygons_geo(&self) -> geo_types::MultiPolygon<f64> {
            self.polygons().iter().map(|p| p.to_geo(self)).collect()
        }

        /// Every open chain as a `geo_types::LineString`, in the order of
        /// [`curves`](Self::curves).
        pub fn chains_geo(&self) -> Vec<LineString<f64>> {
            self.curves()
                .iter()
                .filter(|c| !c.closed)
                .map(|c| line(self.curve_coords(c)))
                .collect()
        }

        /// The medial axis as a `geo_types::MultiLineString` of two-point segments.
        pub fn medial_axis_geo(&self) -> MultiLineString<f64> {
            let axis = self.medial_axis();
            MultiLineString::new(
                axis.edges
                    .iter()
                    .map(|&[a, b]| line(vec![axis.vertices[a as usize], axis.vertices[b as usize]]))
                    .collect(),
            )
        }
    }
}

#[cfg(all(test, feature = "geo-types"))]
mod tests {
    use super::ToPoints;
    use geo_types::{Coord, LineString, MultiPoint, Point};

    #[test]
    fn geo_types_sources_keep_order_and_values() {
        let raw = vec![[0.5, -1.0], [3.0, 2.25], [-0.0, 7.0]];
        let coords: Vec<Coord<f64>> = raw.iter().map(|&[x, y]| Coord { x, y }).collect();
        let points: Vec<Point<f64>> = coords.iter().map(|&c| Point(c)).collect();
        assert_eq!(coords.to_points(), raw);
        assert_eq!(points.to_points(), raw);
        assert_eq!(MultiPoint::new(points).to_points(), raw);
        assert_eq!(LineString::new(coords).to_points(), raw);
    }

    #[test]
    fn polygons_with_holes_as_geo_types() {
        // A square ring of 24 points around a square hole of 8, two spacings away.
        let mut points = Vec::new();
        for (r, k) in [(3.0, 6), (1.0, 2)] {
            let corners = [[-r, -r], [r, -r], [r, r], [-r, r]];
            for s in 0..4 {
                let (a, b): ([f64; 2], [f64; 2]) = (corners[s], corners[(s + 1) % 4]);
                for i in 0..k {
                    let t = i as f64 / k as f64;
                    points.push([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]);
                }
            }
        }
        let rec = crate::reconstruct(&points).unwrap();
        let polygons = rec.polygons_geo();
        assert_eq!(polygons.0.len(), 1);
        let polygon = &polygons.0[0];
        assert_eq!(polygon.exterior().0.len(), 25);
        assert!(polygon.exterior().is_closed());
        assert_eq!(polygon.interiors().len(), 1);
        assert_eq!(polygon.interiors()[0].0.len(), 9);
        // Exterior counterclockwise, hole clockwise: the shoelace sums (exact here: small
        // integers) have opposite signs.
        let twice_area = |ring: &LineString<f64>| {
            ring.lines()
                .map(|l| l.start.x * l.end.y - l.end.x * l.start.y)
                .sum::<f64>()
        };
        assert_eq!(twice_area(polygon.exterior()), 72.0);
        assert_eq!(twice_area(&polygon.interiors()[0]), -8.0);
        assert!(rec.chains_geo().is_empty());
        assert_eq!(rec.medial_axis_geo().0.len(), rec.medial_axis().edges.len());
    }
}
