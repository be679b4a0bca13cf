//! What a reconstruction returns.

use std::fmt;

use super::curves::{self, Curve};
use super::options::{Algorithm, MedialAxisMode};
use super::wdm::Label;
use crate::delaunay::Triangulation;
use crate::ids::LocalPoint;

/// The medial axis approximation: segments between Voronoi vertices inside the shape.
#[derive(Debug, Clone, Default, PartialEq)]
#[non_exhaustive]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct MedialAxis {
    /// Circumcenters (rounded to f64) of the vertices that have a medial-axis edge, in the
    /// caller's coordinates, rounded as
    /// [`Voronoi::vertex_position`](crate::Voronoi::vertex_position) rounds them.
    pub vertices: Vec<[f64; 2]>,
    /// Segments as index pairs into `vertices`, `[a, b]` with `a < b`, sorted.
    pub edges: Vec<[u32; 2]>,
}

/// The result of a reconstruction.
#[derive(Debug, Clone)]
pub struct Reconstruction {
    pub(super) algorithm: Algorithm,
    pub(super) triangulation: Triangulation,
    pub(super) labels: Vec<Label>,
    pub(super) edges: Vec<[u32; 2]>,
    pub(super) curves: Vec<Curve>,
    pub(super) medial_axis: MedialAxis,
    pub(super) medial_axis_mode: Option<MedialAxisMode>,
    pub(super) unassigned: Vec<u32>,
    pub(super) passes: usize,
    pub(super) budget_exhausted: bool,
    /// With smoothing: the fitted position of every distinct point, by the triangulation's
    /// local index (a point on no curve, or one the fit left, at its input coordinates).
    pub(super) fitted: Option<Vec<[f64; 2]>>,
    /// [`Self::warnings`], computed on the first call.
    pub(super) warnings: std::sync::OnceLock<Vec<Warning>>,
    /// With thinning: how many representatives the curves were reconstructed through.
    pub(super) thinned: Option<usize>,
}

impl Reconstruction {
    /// When the input was a dense noisy band and thinned
    /// ([`Options::with_thinning`](super::Options::with_thinning)): the number of
    /// representatives the curves were reconstructed through (every other point is
    /// unassigned, and [`labels`](Self::labels) is empty).
    pub fn thinned(&self) -> Option<usize> {
        self.thinned
    }

    /// The algorithm that produced this result.
    pub fn algorithm(&self) -> Algorithm {
        self.algorithm
    }

    /// Reconstructed edges `[i, j]` with `i < j`, sorted, over the caller's indices.
    pub fn edges(&self) -> &[[u32; 2]] {
        &self.edges
    }

    /// Closed loops and open chains assembled from [`Self::edges`].
    pub fn curves(&self) -> &[Curve] {
        &self.curves
    }

    /// True when peeling stopped because the next pass would have exceeded
    /// [`Options::with_peeling_budget`](super::Options::with_peeling_budget): the [`untouched_points`](Self::untouched_points) may
    /// then still hold curves.
    pub fn peeling_budget_exhausted(&self) -> bool {
        self.budget_exhausted
    }

    /// The medial axis: by default that of the closed curves, pruned of noise branches; with
    /// [`MedialAxisMode::Raw`](super::MedialAxisMode::Raw) the paper's WDM_MAT (segments
    /// between inner Voronoi vertices).
    pub fn medial_axis(&self) -> &MedialAxis {
        &self.medial_axis
    }

    /// Which medial axis [`medial_axis`](Self::medial_axis) is: the one the options asked
    /// for with WDM, `None` with the baseline algorithms (they compute none). An empty axis
    /// means none was asked for only with [`MedialAxisMode::Omitted`]; otherwise it means
    /// the curves enclose nothing.
    pub fn medial_axis_mode(&self) -> Option<MedialAxisMode> {
        self.medial_axis_mode
    }

    /// Whether the curves were smoothed ([`Options::with_smoothing`](super::Options::with_smoothing)):
    /// then [`curve_coords`](Self::curve_coords) and [`curve_vertex`](Self::curve_vertex) give
    /// the fitted positions.
    pub fn smoothed(&self) -> bool {
        self.fitted.is_some()
    }

    /// Where point `i` (a caller index) lies as a curve vertex: its fitted position with
    /// smoothing, its input coordinates otherwise (those of the point it repeats, for a
    /// duplicate). `None` beyond the input.
    pub fn curve_vertex(&self, i: u32) -> Option<[f64; 2]> {
        if (i as usize) >= self.triangulation.point_count() {
            return None;
        }
        Some(match &self.fitted {
            Some(fitted) => fitted[self.triangulation.local_index(i).index()],
            None => self.triangulation.point(i),
        })
    }

    /// The Delaunay triangulation of all the points.
    pub fn triangulation(&self) -> &Triangulation {
        &self.triangulation
    }

    /// The label of every vertex of `self.triangulation().voronoi()` from the first pass,
    /// ears repaired (a small loop of the crust hanging off a curve at one point; see
    /// ARCHITECTURE.md, "Ears"), so that the first pass's crust edges are exactly those between
    /// an inner and an outer vertex (empty for the baseline algorithms, which do not label).
    pub fn labels(&self) -> &[Label] {
        &self.labels
    }

    /// Distinct points with a degree other than 0 or 2 in the reconstruction: curve ends and
    /// junctions.
    pub fn irregular_points(&self) -> Vec<u32> {
        curves::irregular_points(self.triangulation.point_count(), &self.edges)
    }

    /// Distinct points that no reconstructed edge touches.
    pub fn untouched_points(&self) -> Vec<u32> {
        let tri = &self.triangulation;
        untouched_points(
            tri,
            self.edges.iter().map(|e| e.map(|i| tri.local_index(i))),
        )
    }

    /// Distinct points on no reconstructed curve (outliers, leftovers of noise), sorted, in
    /// the caller's indices; duplicates are not listed (they follow the point they repeat).
    pub fn unassigned(&self) -> &[u32] {
        &self.unassigned
    }

    /// How many passes ran (more than one when peeling found nested curves).
    pub fn passes(&self) -> usize {
        self.passes
    }

    /// Pairs `[duplicate, kept]`: a point with the same coordinates as an earlier one, and
    /// that first occurrence (as [`Triangulation::duplicates`]).
    pub fn duplicates(&self) -> &[[u32; 2]] {
        self.triangulation.duplicates()
    }
}

/// The distinct points of `tri` (caller indices, sorted) that no edge of `edges` touches.
pub(super) fn untouched_points(
    tri: &Triangulation,
    edges: impl Iterator<Item = [LocalPoint; 2]>,
) -> Vec<u32> {
    let mut touched = vec![false; tri.distinct_point_count()];
    for [a, b] in edges {
        touched[a.index()] = true;
        touched[b.index()] = true;
    }
    // Read in local order (a point's caller index is where its first occurrence was): the
    // caller's order jumps all over the marks, a cache miss per point at 10^7.
    let mut untouched: Vec<u32> = (tri.local_points())
        .filter(|&p| !touched[p.index()])
        .map(|p| tri.input_index(p))
        .collect();
    untouched.sort_unstable();
    untouched
}

/// What a warning is about; [`name`](Self::name) is its stable code.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[non_exhaustive]
pub enum WarningCode {
    /// Most points are on no curve, or no curve was found.
    MostUnassigned,
    /// The points look like a scatter, a filled area or a wide band of noise.
    Scatter,
    /// A curve edge far longer than the curve edges beside it.
    LongEdge,
    /// A closed loop may close across the gap of an open curve.
    LoopAcrossGap,
    /// Two open chains end within a step or two of each other: they may be one curve.
    ChainEndsClose,
    /// Curves come within the sample spacing of each other.
    CurvesTooClose,
    /// Peeling stopped at its budget.
    PeelingBudget,
}

impl WarningCode {
    /// Every code, in the order the warnings are listed.
    pub const ALL: [WarningCode; 7] = [
        WarningCode::MostUnassigned,
        WarningCode::Scatter,
        WarningCode::LongEdge,
        WarningCode::LoopAcrossGap,
        WarningCode::ChainEndsClose,
        WarningCode::CurvesTooClose,
        WarningCode::PeelingBudget,
    ];

    /// The stable code: what the JSON, the GeoJSON and Python carry.
    pub fn name(self) -> &'static str {
        match self {
            WarningCode::MostUnassigned => "most-unassigned",
            WarningCode::Scatter => "scatter",
            WarningCode::LongEdge => "long-edge",
            WarningCode::LoopAcrossGap => "loop-across-gap",
            WarningCode::ChainEndsClose => "chain-ends-close",
            WarningCode::CurvesTooClose => "curves-too-close",
            WarningCode::PeelingBudget => "peeling-budget",
        }
    }
}

impl fmt::Display for WarningCode {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A sign that the result is probably not what was wanted, with what to try.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct Warning {
    /// What it is about.
    pub code: WarningCode,
    /// One sentence for a person: what was seen, where, and what to try.
    pub message: String,
    /// The points it is about (caller indices; for an edge its two ends), at most a few.
    pub points: Vec<u32>,
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} [{}]", self.message, self.code)
    }
}
