//! Dense polyline approximations of curves, and similarity transforms.

use super::rng::Rng;
use super::vec2::{add, angle_between, dist, left, mul, norm, sub, unit, P2};
use std::f64::consts::TAU;

/// A rotation about the origin, then a uniform scale, then a translation:
/// `p ↦ scale · R(angle) · p + offset`.
///
/// Similarities map ε-samples to ε-samples: distances and the local feature size both scale by
/// `scale`, so they are the only transforms offered.
///
/// ```
/// use wdm_crust_testkit::Similarity;
/// let s = Similarity::rotation(std::f64::consts::FRAC_PI_2).then(&Similarity::translation([1.0, 0.0]));
/// let p = s.apply([1.0, 0.0]);
/// assert!((p[0] - 1.0).abs() < 1e-12 && (p[1] - 1.0).abs() < 1e-12);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Similarity {
    /// Rotation angle in radians, counter-clockwise.
    pub angle: f64,
    /// Uniform scale factor; must be positive.
    pub scale: f64,
    /// Translation applied last.
    pub offset: [f64; 2],
}

impl Similarity {
    /// The identity transform.
    pub fn identity() -> Self {
        Similarity {
            angle: 0.0,
            scale: 1.0,
            offset: [0.0, 0.0],
        }
    }

    /// Rotation by `angle` radians about the origin.
    pub fn rotation(angle: f64) -> Self {
        Similarity {
            angle,
            ..Self::identity()
        }
    }

    /// Uniform scaling by `scale` about the origin.
    pub fn scaling(scale: f64) -> Self {
        Similarity {
            scale,
            ..Self::identity()
        }
    }

    /// Translation by `offset`.
    pub fn translation(offset: [f64; 2]) -> Self {
        Similarity {
            offset,
            ..Self::identity()
        }
    }

    /// A random similarity: angle uniform in `[0, 2π)`, scale log-uniform in `[1/4, 4]`,
    /// offset uniform in `[-10, 10]²`.
    pub fn random(rng: &mut Rng) -> Self {
        Similarity {
            angle: rng.range(0.0, TAU),
            scale: rng.range(-4f64.ln(), 4f64.ln()).exp(),
            offset: [rng.range(-10.0, 10.0), rng.range(-10.0, 10.0)],
        }
    }

    /// The transform that applies `self` first and `next` second.
    pub fn then(&self, next: &Similarity) -> Similarity {
        Similarity {
            angle: self.angle + next.angle,
            scale: self.scale * next.scale,
            offset: next.apply(self.offset),
        }
    }

    /// Image of a point.
    pub fn apply(&self, p: [f64; 2]) -> [f64; 2] {
        add(self.apply_vector(p), self.offset)
    }

    /// Image of a direction or displacement (rotation and scale, no translation).
    pub fn apply_vector(&self, v: [f64; 2]) -> [f64; 2] {
        let (s, c) = self.angle.sin_cos();
        [
            self.scale * (c * v[0] - s * v[1]),
            self.scale * (s * v[0] + c * v[1]),
        ]
    }
}

/// A smooth closed curve, parametrised over `t ∈ [0, 1)` with period 1.
///
/// Implementors should run counter-clockwise and be simple (no self-intersections) and
/// regular (non-zero derivative), so that the dense polyline and its normals are meaningful.
pub trait ClosedCurve {
    /// The point at parameter `t` (period 1).
    fn point(&self, t: f64) -> [f64; 2];

    /// The derivative `d point / dt` at `t`.
    fn derivative(&self, t: f64) -> [f64; 2];

    /// A dense polyline with `n` points; see [`DenseCurve::from_closed_curve`].
    fn dense(&self, n: usize) -> DenseCurve
    where
        Self: Sized,
    {
        DenseCurve::from_closed_curve(self, n)
    }
}

/// A dense polyline standing in for a curve: points in curve order with unit normals.
///
/// Closed curves do not repeat their first point at the end. Normals point to the left of the
/// direction of travel (inwards on a counter-clockwise curve); at sharp corners they bisect the
/// two edge normals. `corners` lists, in increasing order, the indices of points where the
/// curve has a tangent discontinuity; the ε-sampler always keeps them as samples.
#[derive(Debug, Clone, PartialEq)]
pub struct DenseCurve {
    /// Points in curve order.
    pub points: Vec<[f64; 2]>,
    /// Unit normal at each point, to the left of the direction of travel.
    pub normals: Vec<[f64; 2]>,
    /// Whether the last point connects back to the first.
    pub closed: bool,
    /// Indices of sharp corners, increasing.
    pub corners: Vec<usize>,
}

/// Corners sharper than this turning angle (radians) are marked as corners.
const CORNER_ANGLE: f64 = 1e-9;

impl DenseCurve {
    /// `n` points (at least 3) on a smooth closed curve, spaced evenly in arc length plus a
    /// turning-angle term, so high-curvature parts get more points.
    ///
    /// The spacing measure is `ds + β·|dθ|` with `β = L / (4π)` (`L` the length), which on a
    /// circle gives a third of the points to the turning term. Every point and normal is
    /// evaluated exactly on the curve; only the parameter values are interpolated.
    pub fn from_closed_curve<C: ClosedCurve + ?Sized>(curve: &C, n: usize) -> Self {
        let n = n.max(3);
        let params = measure_params(curve, n);
        let points = params.iter().map(|&t| curve.point(t)).collect();
        let normals = params
            .iter()
            .map(|&t| unit(left(curve.derivative(t))))
            .collect();
        DenseCurve {
            points,
            normals,
            closed: true,
            corners: Vec::new(),
        }
    }

    /// About `n` points along the closed polygon through `vertices`, every vertex included.
    ///
    /// Every vertex with a non-zero turning angle is a corner. Duplicate consecutive vertices
    /// are dropped.
    pub fn polygon(vertices: &[[f64; 2]], n: usize) -> Self {
        Self::polyline(vertices, true, n)
    }

    /// About `n` points along the polyline through `vertices` (closed or open), every vertex
    /// included; edges are subdivided evenly, in proportion to their length.
    ///
    /// Interior vertices (and, when closed, all vertices) with a non-zero turning angle are
    /// corners. Duplicate consecutive vertices are dropped.
    pub fn polyline(vertices: &[[f64; 2]], closed: bool, n: usize) -> Self {
        let verts = dedup(vertices, closed);
        let m = verts.len();
        let edges = if closed { m } else { m.saturating_sub(1) };
        let total: f64 = (0..edges).map(|e| dist(verts[e], verts[(e + 1) % m])).sum();
        let spacing = total / n.max(1) as f64;
        let mut points = Vec::with_capacity(n + m);
        let mut normals = Vec::with_capacity(n + m);
        let mut corners = Vec::new();
        for v in 0..m {
            let into = (closed || v > 0).then(|| sub(verts[v], verts[(v + m - 1) % m]));
            let out = (closed || v + 1 < m).then(|| sub(verts[(v + 1) % m], verts[v]));
            if let (Some(a), Some(b)) = (into, out) {
                if angle_between(a, b) > CORNER_ANGLE {
                    corners.push(points.len());
                }
            }
            let bisector = add(
                into.map_or([0.0; 2], |d| left(unit(d))),
                out.map_or([0.0; 2], |d| left(unit(d))),
            );
            points.push(verts[v]);
            normals.push(unit(bisector));
            if let Some(d) = out {
                let pieces = (norm(d) / spacing).round().max(1.0) as usize;
                for k in 1..pieces {
                    points.push(add(verts[v], mul(d, k as f64 / pieces as f64)));
                    normals.push(left(unit(d)));
                }
            }
        }
        DenseCurve {
            points,
            normals,
            closed,
            corners,
        }
    }

    /// A dense curve from points already dense and in order, with normals estimated by
    /// central differences (one-sided at the ends of an open curve).
    ///
    /// Consecutive duplicates are dropped and `corners` is remapped accordingly (corner
    /// indices that are out of range are ignored).
    pub fn from_points(points: &[[f64; 2]], closed: bool, corners: &[usize]) -> Self {
        let mut kept = Vec::with_capacity(points.len());
        let mut new_index = Vec::with_capacity(points.len());
        for &p in points {
            if kept.last().map_or(true, |&q| q != p) {
                kept.push(p);
            }
            new_index.push(kept.len() - 1);
        }
        if closed && kept.len() > 1 && kept[0] == kept[kept.len() - 1] {
            kept.pop();
            for i in new_index.iter_mut() {
                if *i == kept.len() {
                    *i = 0;
                }
            }
        }
        let m = kept.len();
        let normals = (0..m)
            .map(|i| {
                let prev = if closed || i > 0 { (i + m - 1) % m } else { i };
                let next = if closed || i + 1 < m { (i + 1) % m } else { i };
                unit(left(sub(kept[next], kept[prev])))
            })
            .collect();
        let mut corner_list: Vec<usize> = corners
            .iter()
            .filter_map(|&c| new_index.get(c).copied())
            .collect();
        corner_list.sort_unstable();
        corner_list.dedup();
        DenseCurve {
            points: kept,
            normals,
            closed,
            corners: corner_list,
        }
    }

    /// Number of dense points.
    pub fn len(&self) -> usize {
        self.points.len()
    }

    /// Whether the curve has no points.
    pub fn is_empty(&self) -> bool {
        self.points.is_empty()
    }

    /// Length of the polyline (including the closing edge of a closed curve).
    pub fn length(&self) -> f64 {
        let n = self.points.len();
        let edges = if self.closed { n } else { n.saturating_sub(1) };
        (0..edges)
            .map(|i| dist(self.points[i], self.points[(i + 1) % n]))
            .sum()
    }

    /// The image of the curve under a similarity (normals are rotated with it).
    pub fn transformed(&self, s: &Similarity) -> DenseCurve {
        DenseCurve {
            points: self.points.iter().map(|&p| s.apply(p)).collect(),
            normals: self
                .normals
                .iter()
                .map(|&v| unit(s.apply_vector(v)))
                .collect(),
            closed: self.closed,
            corners: self.corners.clone(),
        }
    }
}

/// Drops consecutive duplicate vertices (and a closing duplicate of the first vertex).
fn dedup(vertices: &[P2], closed: bool) -> Vec<P2> {
    let mut out: Vec<P2> = Vec::with_capacity(vertices.len());
    for &v in vertices {
        if out.last() != Some(&v) {
            out.push(v);
        }
    }
    if closed && out.len() > 1 && out.first() == out.last() {
        out.pop();
    }
    out
}

/// Parameter values of `n` points spaced evenly in the measure `ds + β·|dθ|`.
fn measure_params<C: ClosedCurve + ?Sized>(curve: &C, n: usize) -> Vec<f64> {
    // A fine parameter grid on which the measure is accumulated, then inverted linearly.
    let fine = 8 * n;
    let pts: Vec<P2> = (0..=fine)
        .map(|i| curve.point(i as f64 / fine as f64))
        .collect();
    let ders: Vec<P2> = (0..=fine)
        .map(|i| curve.derivative(i as f64 / fine as f64))
        .collect();
    let ds: Vec<f64> = (0..fine).map(|i| dist(pts[i], pts[i + 1])).collect();
    let length: f64 = ds.iter().sum();
    let beta = length / (2.0 * TAU);
    let mut cumulative = Vec::with_capacity(fine + 1);
    cumulative.push(0.0);
    for i in 0..fine {
        let step = ds[i] + beta * angle_between(ders[i], ders[i + 1]);
        cumulative.push(cumulative[i] + step);
    }
    let total = cumulative[fine];
    let mut params = Vec::with_capacity(n);
    let mut seg = 0;
    for k in 0..n {
        let target = total * k as f64 / n as f64;
        while seg + 1 < fine && cumulative[seg + 1] <= target {
            seg += 1;
        }
        let span = cumulative[seg + 1] - cumulative[seg];
        let frac = if span > 0.0 {
            (target - cumulative[seg]) / span
        } else {
            0.0
        };
        params.push((seg as f64 + frac) / fine as f64);
    }
    params
}
