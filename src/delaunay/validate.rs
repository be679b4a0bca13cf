//! The invariant checker: is a [`Triangulation`] a valid Delaunay triangulation of its
//! points? Used by unit tests, property tests and fuzz targets; exact throughout.

use std::fmt;

use super::triangulation::{Triangulation, NO_TWIN};
use crate::ids::{HalfEdge, LocalPoint, TriangleId};
use crate::predicates::{incircle, orient2d, CirclePosition, Orientation};

/// The first invariant a [`Triangulation`] was found to break.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum ValidationError {
    /// A triangle is not strictly counterclockwise.
    NotCounterClockwise {
        /// Triangle index.
        triangle: TriangleId,
    },
    /// A triangle uses an index out of range or a duplicate point.
    BadVertex {
        /// Triangle index.
        triangle: TriangleId,
    },
    /// The half-edge array is not an involution with reversed endpoints.
    TwinMismatch {
        /// Half-edge index.
        halfedge: HalfEdge,
    },
    /// The boundary half-edges do not form the hull cycle.
    HullMismatch(String),
    /// The hull turns clockwise somewhere.
    HullNotConvex {
        /// Position in the hull listing.
        position: usize,
    },
    /// The triangle count differs from 2n − 2 − h.
    WrongTriangleCount {
        /// Triangles present.
        found: usize,
        /// 2n − 2 − h.
        expected: usize,
    },
    /// An interior edge has the opposite point strictly inside a triangle's circumcircle.
    NotLocallyDelaunay {
        /// Half-edge index.
        halfedge: HalfEdge,
    },
    /// A point is neither in the triangulation nor reported as a duplicate, or a duplicate
    /// pair is wrong.
    PointUnaccounted {
        /// Point index.
        point: usize,
    },
}

impl fmt::Display for ValidationError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "invalid triangulation: {self:?}")
    }
}

impl std::error::Error for ValidationError {}

impl Triangulation {
    /// Checks every invariant exactly: counterclockwise triangles, symmetric half-edges, a
    /// closed convex hull made of exactly the boundary half-edges, 2n − 2 − h triangles,
    /// every interior edge locally Delaunay, every point present or reported as a duplicate.
    ///
    /// Together these make it a Delaunay triangulation of the distinct points: consistently
    /// oriented triangles glued along twins whose boundary is the convex hull cover it once,
    /// and local Delaunayhood everywhere implies the global empty-circle property.
    ///
    /// Also checks the translation to the caller's indices: local and caller indices map to
    /// each other, and every caller point is either kept or an exact duplicate of an earlier
    /// kept point. Point indices in errors are the caller's.
    pub fn validate(&self) -> Result<(), ValidationError> {
        self.check_translation()?;
        let n = self.points.len();
        if self.triangles.is_empty() {
            return self.check_degenerate();
        }
        let mut used = vec![false; n];
        for t in self.triangle_ids() {
            for v in self.corners(t) {
                let v = v.index();
                if v >= n {
                    return Err(ValidationError::BadVertex { triangle: t });
                }
                used[v] = true;
            }
            let [a, b, c] = self.triangle_points(t);
            if orient2d(a, b, c) != Orientation::CounterClockwise {
                return Err(ValidationError::NotCounterClockwise { triangle: t });
            }
        }
        if let Some(p) = (0..n).find(|&p| !used[p]) {
            return Err(ValidationError::PointUnaccounted {
                point: self.input_of[p] as usize,
            });
        }
        self.check_twins()?;
        self.check_hull()?;
        let expected = 2 * n - 2 - self.hull.len();
        if self.triangles.len() != expected {
            return Err(ValidationError::WrongTriangleCount {
                found: self.triangles.len(),
                expected,
            });
        }
        self.check_locally_delaunay()
    }

    /// Local and caller indices map to each other; every duplicate pair names an earlier
    /// kept point (hence equal coordinates), sorted by duplicate; every caller point is kept
    /// or a duplicate.
    fn check_translation(&self) -> Result<(), ValidationError> {
        let (n, distinct) = (self.local_of.len(), self.points.len());
        let unaccounted = |point: usize| Err(ValidationError::PointUnaccounted { point });
        if self.input_of.len() != distinct {
            return unaccounted(n.min(self.input_of.len()));
        }
        for (p, &i) in self.input_of.iter().enumerate() {
            if i as usize >= n || self.local_of[i as usize].index() != p {
                return unaccounted(i as usize);
            }
        }
        let mut previous = None;
        for &[dup, kept] in &self.duplicates {
            let ok = (dup as usize) < n
                && kept < dup
                && previous < Some(dup)
                && self.local_of[dup as usize] == self.local_of[kept as usize]
                && !self.is_duplicate(kept)
                && self.is_duplicate(dup);
            if !ok {
                return unaccounted((dup as usize).min(n));
            }
            previous = Some(dup);
        }
        if distinct + self.duplicates.len() != n {
            return unaccounted(n);
        }
        Ok(())
    }

    /// No triangles: all distinct points must be collinear and listed along the line.
    fn check_degenerate(&self) -> Result<(), ValidationError> {
        if self.hull.len() != self.points.len()
            || self.hull.iter().any(|&v| v.index() >= self.points.len())
        {
            return Err(ValidationError::HullMismatch(
                "degenerate hull must list every distinct point once".into(),
            ));
        }
        let p = |i: usize| self.position(self.hull[i]);
        for i in 2..self.hull.len() {
            if orient2d(p(0), p(1), p(i)) != Orientation::Collinear {
                return Err(ValidationError::HullMismatch(format!(
                    "no triangles, but hull point {i} is off the line"
                )));
            }
        }
        for i in 1..self.hull.len() {
            let (a, b) = (p(i - 1), p(i));
            if (a[0], a[1]) >= (b[0], b[1]) {
                return Err(ValidationError::HullMismatch(format!(
                    "collinear chain not in order at {i}"
                )));
            }
        }
        let mut seen = vec![false; self.points.len()];
        for &v in &self.hull {
            if std::mem::replace(&mut seen[v.index()], true) {
                return Err(ValidationError::PointUnaccounted {
                    point: self.input_index(v) as usize,
                });
            }
        }
        Ok(())
    }

    fn check_twins(&self) -> Result<(), ValidationError> {
        if self.halfedges.len() != 3 * self.triangles.len() {
            return Err(ValidationError::TwinMismatch {
                halfedge: HalfEdge::new(self.halfedges.len() as u32),
            });
        }
        for (e, &twin) in self.halfedge_ids().zip(&self.halfedges) {
            if twin == NO_TWIN {
                continue;
            }
            let t = twin;
            let ok = t.index() < self.halfedges.len()
                && t != e
                && self.halfedges[t.index()] == e
                && self.org(t) == self.dest(e)
                && self.dest(t) == self.org(e);
            if !ok {
                return Err(ValidationError::TwinMismatch { halfedge: e });
            }
        }
        Ok(())
    }

    /// The boundary half-edges have the interior on their left, so they run counterclockwise
    /// around the hull: `hull[i] → hull[i+1]` must be one of them for every i, and there must
    /// be no others. The hull must be convex.
    fn check_hull(&self) -> Result<(), ValidationError> {
        let h = self.hull.len();
        let mut boundary: Vec<(LocalPoint, LocalPoint)> = (self.halfedge_ids())
            .filter(|&e| self.twin(e).is_none())
            .map(|e| (self.org(e), self.dest(e)))
            .collect();
        boundary.sort_unstable();
        let mut expected: Vec<(LocalPoint, LocalPoint)> = (0..h)
            .map(|i| (self.hull[i], self.hull[(i + 1) % h]))
            .collect();
        expected.sort_unstable();
        if boundary != expected {
            return Err(ValidationError::HullMismatch(format!(
                "{} boundary half-edges, hull has {h} edges (or they differ)",
                boundary.len()
            )));
        }
        let p = |i: usize| self.position(self.hull[i % h]);
        let mut strict_turns = 0;
        for i in 0..h {
            match orient2d(p(i), p(i + 1), p(i + 2)) {
                Orientation::Clockwise => {
                    return Err(ValidationError::HullNotConvex { position: i + 1 })
                }
                Orientation::CounterClockwise => strict_turns += 1,
                Orientation::Collinear => {}
            }
        }
        if strict_turns < 3 {
            return Err(ValidationError::HullNotConvex { position: 0 });
        }
        Ok(())
    }

    fn check_locally_delaunay(&self) -> Result<(), ValidationError> {
        for (e, &twin) in self.halfedge_ids().zip(&self.halfedges) {
            if twin == NO_TWIN || twin < e {
                continue;
            }
            let opposite = self.position(self.org(twin.prev()));
            let [a, b, c] = self.triangle_points(e.triangle());
            if incircle(a, b, c, opposite) == CirclePosition::Inside {
                return Err(ValidationError::NotLocallyDelaunay { halfedge: e });
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::triangulate;

    fn square_with_centre() -> Triangulation {
        triangulate(&[[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0], [2.0, 1.0]]).unwrap()
    }

    #[test]
    fn the_checker_accepts_a_real_triangulation() {
        square_with_centre().validate().unwrap();
    }

    #[test]
    fn the_checker_catches_a_flipped_triangle() {
        let mut tri = square_with_centre();
        tri.triangles[0].swap(1, 2);
        assert!(tri.validate().is_err());
    }

    #[test]
    fn the_checker_catches_a_broken_twin() {
        let mut tri = square_with_centre();
        let e = tri.halfedges.iter().position(|&t| t != NO_TWIN).unwrap();
        tri.halfedges[e] = NO_TWIN;
        assert!(tri.validate().is_err());
    }

    #[test]
    fn the_checker_catches_a_non_delaunay_edge() {
        // Two triangles over a convex quad, split along the wrong diagonal.
        let mut tri = triangulate(&[[0.0, 0.0], [3.0, -1.0], [6.0, 0.0], [3.0, 1.0]]).unwrap();
        tri.validate().unwrap();
        // Rebuild with the other diagonal: (0, 2) is the long one and fails incircle.
        let l = |i| tri.local_index(i);
        tri.triangles = vec![[l(0), l(1), l(2)], [l(0), l(2), l(3)]];
        let [e2, e3] = [2, 3].map(HalfEdge::new);
        tri.halfedges = vec![NO_TWIN, NO_TWIN, e3, e2, NO_TWIN, NO_TWIN];
        assert_eq!(
            tri.validate(),
            Err(ValidationError::NotLocallyDelaunay { halfedge: e2 })
        );
    }

    #[test]
    fn the_checker_catches_a_missing_point_and_a_wrong_hull() {
        let mut tri = square_with_centre();
        tri.points.push([9.0, 9.0]);
        tri.input_of.push(5);
        tri.local_of.push(LocalPoint::new(5));
        assert_eq!(
            tri.validate(),
            Err(ValidationError::PointUnaccounted { point: 5 })
        );
        let mut tri = square_with_centre();
        tri.hull.reverse();
        assert!(matches!(
            tri.validate(),
            Err(ValidationError::HullMismatch(_))
        ));
    }
}
