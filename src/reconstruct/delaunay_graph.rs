//! The Delaunay graph of a triangulation as adjacency lists by local index, and the
//! nearest-first queue its walks use (the smoothing's windows, the band probes of thinning).

use std::cmp::Ordering;
use std::hash::{BuildHasherDefault, Hasher};

use super::lengths::distance;
use crate::delaunay::{HalfEdge, Triangulation, NO_TWIN};
use crate::ids::LocalPoint;
use crate::parallel;

/// The Delaunay graph of the triangulation, neighbours by local index.
pub(super) struct Graph {
    offsets: Vec<u32>,
    neighbours: Vec<LocalPoint>,
    /// Every point's distance to its nearest neighbour (a Delaunay neighbour).
    pub(super) nearest: Vec<f64>,
}

impl Graph {
    /// The graph with every point's nearest-neighbour distance.
    pub(super) fn new(tri: &Triangulation) -> Graph {
        let mut graph = Self::adjacency(tri);
        graph.nearest = parallel::map_range(tri.points.len(), |p| {
            graph
                .of(LocalPoint::new(p as u32))
                .iter()
                .map(|&q| distance(tri.points[p], tri.points[q.index()]))
                .fold(f64::INFINITY, f64::min)
        });
        graph
    }

    /// The adjacency lists only (`nearest` empty).
    pub(super) fn adjacency(tri: &Triangulation) -> Graph {
        let n = tri.points.len();
        let twins = tri.halfedges();
        let mut count = vec![0u32; n + 1];
        let undirected = |e: HalfEdge| twins[e.index()] == NO_TWIN || e < twins[e.index()];
        for e in tri.halfedge_ids().filter(|&e| undirected(e)) {
            count[tri.org(e).index() + 1] += 1;
            count[tri.dest(e).index() + 1] += 1;
        }
        for i in 0..n {
            count[i + 1] += count[i];
        }
        let mut fill = count.clone();
        let mut neighbours = vec![LocalPoint::new(0); count[n] as usize];
        for e in tri.halfedge_ids().filter(|&e| undirected(e)) {
            let (a, b) = (tri.org(e), tri.dest(e));
            neighbours[fill[a.index()] as usize] = b;
            fill[a.index()] += 1;
            neighbours[fill[b.index()] as usize] = a;
            fill[b.index()] += 1;
        }
        Graph {
            offsets: count,
            neighbours,
            nearest: Vec::new(),
        }
    }

    pub(super) fn of(&self, p: LocalPoint) -> &[LocalPoint] {
        let (a, b) = (self.offsets[p.index()], self.offsets[p.index() + 1]);
        &self.neighbours[a as usize..b as usize]
    }
}

/// A sample waiting in the gathering, nearest first (ties by local index).
#[derive(PartialEq)]
pub(super) struct Waiting(pub(super) f64, pub(super) LocalPoint);

impl Eq for Waiting {}

impl PartialOrd for Waiting {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Waiting {
    fn cmp(&self, other: &Self) -> Ordering {
        // Reversed: the heap pops the nearest.
        other.0.total_cmp(&self.0).then(other.1.cmp(&self.1))
    }
}

/// Multiply-and-rotate hashing of point indices and grid cells, for the sets the walks keep:
/// a window or a probe marks hundreds of points per vertex, thinning's cover looks up nine
/// cells per point, and the keys are no attacker's (the standard hasher cost a tenth of the
/// smoothing's time).
#[derive(Default)]
pub(super) struct FastHasher(u64);

/// Hash sets and maps of the walks use [`FastHasher`].
pub(super) type FastHash = BuildHasherDefault<FastHasher>;

impl Hasher for FastHasher {
    fn finish(&self) -> u64 {
        self.0
    }

    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.write_u64(u64::from(b));
        }
    }

    fn write_u64(&mut self, v: u64) {
        self.0 = (self.0.rotate_left(26) ^ v).wrapping_mul(0x9e37_79b9_7f4a_7c15);
    }

    fn write_i64(&mut self, v: i64) {
        self.write_u64(v as u64);
    }

    fn write_u32(&mut self, v: u32) {
        self.write_u64(u64::from(v));
    }
}

/// SplitMix64's finaliser: subsamples by `mix(local index) % rate` owe nothing to the
/// locality order's pattern, and depend on the points only.
pub(super) fn mix(i: u64) -> u64 {
    let mut z = i.wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}
