//! The finite Voronoi edges between two inside vertices, with the vertices numbered in the
//! order the edges first use them (which follows the triangulation's locality): on one
//! thread in one pass, or on all threads in a few.

use crate::delaunay::{HalfEdge, NO_TWIN};
use crate::voronoi::Voronoi;

/// Vertices numbered in order of first use, and edges between the numbers.
pub(super) struct Numbered {
    /// The number of every vertex (of `slots`), or `u32::MAX` where none uses it.
    pub(super) index: Vec<u32>,
    /// The vertex of every number.
    pub(super) used: Vec<u32>,
    /// `[min, max]` numbers, in the order of the diagram's finite edges.
    pub(super) edges: Vec<[u32; 2]>,
}

impl Numbered {
    /// The number of `v`, numbering it next if it has none.
    pub(super) fn number(&mut self, v: u32) -> u32 {
        if self.index[v as usize] == u32::MAX {
            self.index[v as usize] = self.used.len() as u32;
            self.used.push(v);
        }
        self.index[v as usize]
    }

    /// Adds the edge `a–b`, numbering its ends (`a` first) where they have no number.
    pub(super) fn add(&mut self, a: u32, b: u32) {
        let (ia, ib) = (self.number(a), self.number(b));
        self.edges.push([ia.min(ib), ia.max(ib)]);
    }
}

/// The finite edges of `vor` between two vertices with `inside`, numbered; `slots` (at
/// least the vertex count) is the length of the index, for vertices added later.
pub(super) fn inside_edges(vor: &Voronoi<'_>, inside: &[bool], slots: usize) -> Numbered {
    #[cfg(feature = "parallel")]
    if crate::parallel::pays(vor.vertex_count()) {
        return on_all_threads::inside_edges(vor, inside, slots);
    }
    let mut numbered = Numbered {
        index: vec![u32::MAX; slots],
        used: Vec::new(),
        edges: Vec::new(),
    };
    for (a, b) in finite_edges_between(vor, inside, 0..vor.triangulation().halfedges().len()) {
        numbered.add(a, b);
    }
    numbered
}

/// The finite edges, as `vor.finite_edges()` lists them, whose dual half-edge is in
/// `halfedges` (from the smaller of the two) and whose ends are both `inside`.
fn finite_edges_between<'a>(
    vor: &'a Voronoi<'_>,
    inside: &'a [bool],
    halfedges: std::ops::Range<usize>,
) -> impl Iterator<Item = (u32, u32)> + 'a {
    let twins = vor.triangulation().halfedges();
    halfedges.filter_map(move |e| {
        let twin = twins[e];
        let e = HalfEdge::new(e as u32);
        if twin == NO_TWIN || e > twin || !vor.has_dual(e) {
            return None;
        }
        let (a, b) = (vor.vertex_of_halfedge(e), vor.vertex_of_halfedge(twin));
        (inside[a.index()] && inside[b.index()]).then_some((a.get(), b.get()))
    })
}

/// The same numbering on all threads: the edges in order, then every vertex's first use
/// (the least position of an end naming it, an atomic minimum), then the vertices whose
/// first use each end is, in order of the ends.
#[cfg(feature = "parallel")]
mod on_all_threads {
    use std::sync::atomic::{AtomicU32, Ordering::Relaxed};

    use rayon::prelude::*;

    use super::{finite_edges_between, Numbered};
    use crate::parallel;
    use crate::voronoi::Voronoi;

    pub(super) fn inside_edges(vor: &Voronoi<'_>, inside: &[bool], slots: usize) -> Numbered {
        let halfedge_count = vor.triangulation().halfedges().len();
        // Both lists reserved on this thread (see `flat_map_chunks_reserved`): at most one
        // edge a half-edge, two first ends an edge.
        let mut edges: Vec<[u32; 2]> =
            parallel::flat_map_chunks_reserved(halfedge_count, 1, |range, out| {
                out.extend(finite_edges_between(vor, inside, range).map(|(a, b)| [a, b]));
            });
        // End `k` of edge `i` is at position `2i + k` (the first end first, as numbered
        // one edge at a time). Below `6n − 6`, the half-edge count, so below `u32::MAX` for
        // every input allowed (`MAX_POINTS`); computed in `usize`, as there may be more than
        // 2^31 edges.
        let first: Vec<AtomicU32> = (0..slots)
            .into_par_iter()
            .map(|_| AtomicU32::new(u32::MAX))
            .collect();
        edges.par_iter().enumerate().for_each(|(i, &[a, b])| {
            first[a as usize].fetch_min((2 * i) as u32, Relaxed);
            first[b as usize].fetch_min((2 * i + 1) as u32, Relaxed);
        });
        let used: Vec<u32> = parallel::flat_map_chunks_reserved(edges.len(), 2, |range, out| {
            for i in range {
                for (k, v) in edges[i].into_iter().enumerate() {
                    if first[v as usize].load(Relaxed) == (2 * i + k) as u32 {
                        out.push(v);
                    }
                }
            }
        });
        used.par_iter()
            .enumerate()
            .for_each(|(number, &v)| first[v as usize].store(number as u32, Relaxed));
        let index: Vec<u32> = first.into_iter().map(AtomicU32::into_inner).collect();
        edges.par_iter_mut().for_each(|edge| {
            let [a, b] = edge.map(|v| index[v as usize]);
            *edge = [a.min(b), a.max(b)];
        });
        Numbered { index, used, edges }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::delaunay::triangulate;
    use wdm_crust_testkit::Rng;

    /// A region of faces with holes in it, and some vertex slots past the diagram's: the
    /// numbering of every form is the one of taking `vor.finite_edges()` one at a time.
    #[test]
    fn every_form_numbers_in_order_of_first_use() {
        let mut rng = Rng::new(8);
        let points: Vec<[f64; 2]> = (0..30_000).map(|_| [rng.f64(), rng.f64()]).collect();
        let tri = triangulate(&points).unwrap();
        let vor = tri.voronoi();
        let n = vor.vertex_count();
        let inside: Vec<bool> = (vor.vertex_ids())
            .map(|v| {
                let [x, y] = vor.vertex_position(v);
                (x - 0.5).hypot(y - 0.4) < 0.45 && rng.below(30) != 0
            })
            .collect();
        let slots = n + 7;
        let mut reference = Numbered {
            index: vec![u32::MAX; slots],
            used: Vec::new(),
            edges: Vec::new(),
        };
        for (_, a, b) in vor.finite_edges() {
            if inside[a.index()] && inside[b.index()] {
                reference.add(a.get(), b.get());
            }
        }
        assert!(reference.used.len() > n / 2);
        let same = |numbered: &Numbered| {
            numbered.index == reference.index
                && numbered.used == reference.used
                && numbered.edges == reference.edges
        };
        assert!(same(&inside_edges(&vor, &inside, slots)));
        #[cfg(feature = "parallel")]
        for threads in [1, 2, 3] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            let numbered = pool.install(|| on_all_threads::inside_edges(&vor, &inside, slots));
            assert!(same(&numbered), "{threads} threads");
        }
    }
}
