//! Which faces of the diagram closed loops of Delaunay edges enclose: the parity of the loop
//! edges crossed on the way from infinity, by a depth-first search on one thread, or on
//! all threads by the connected components of the faces that no loop separates.

use crate::ids::HalfEdge;
use crate::voronoi::{EdgeEnd, Voronoi};

/// Every Voronoi vertex not marked in `blocked`: is it separated from infinity by an odd
/// number of the Delaunay edges `crosses` accepts (searched from the rays)? Blocked
/// vertices, and those reached only through them, are `false`. Well defined when the
/// accepted edges form disjoint closed loops whose every crossing is a Voronoi edge: then
/// every closed walk crosses them an even number of times, and the answer does not depend
/// on the path, hence not on the order of the search, nor on the number of threads.
/// `crosses` must accept both half-edges of an edge or neither.
pub(in crate::reconstruct) fn parity_from_infinity(
    vor: &Voronoi<'_>,
    blocked: Vec<bool>,
    crosses: impl Fn(HalfEdge) -> bool + Sync,
) -> Vec<bool> {
    // The components do about two and a half times the depth-first search's work (at 10^7
    // points: 0.56 s one thread, 0.72–0.75 s for the components on two), so they pay from
    // four threads.
    #[cfg(feature = "parallel")]
    if crate::parallel::pays(vor.vertex_count()) && rayon::current_num_threads() >= 4 {
        return components::parity(vor, &blocked, crosses);
    }
    depth_first(vor, blocked, crosses)
}

/// [`parity_from_infinity`] on this thread. Depth first, which stays among neighbours in
/// memory (the vertices follow the triangulation's locality order): the axis phase 2 %
/// faster than breadth first at 10^6 and 10^7 noisy points, the same axes.
fn depth_first(
    vor: &Voronoi<'_>,
    mut blocked: Vec<bool>,
    crosses: impl Fn(HalfEdge) -> bool,
) -> Vec<bool> {
    let seen = &mut blocked;
    let mut inside = vec![false; vor.vertex_count()];
    let mut stack = Vec::new();
    for (e, v, _) in vor.rays() {
        if !seen[v.index()] {
            seen[v.index()] = true;
            inside[v.index()] = crosses(e);
            stack.push(v);
        }
        while let Some(v) = stack.pop() {
            for edge in vor.face_edges(v) {
                if let EdgeEnd::Vertex(u) = edge.to {
                    if !seen[u.index()] {
                        seen[u.index()] = true;
                        inside[u.index()] = inside[v.index()] ^ crosses(edge.halfedge);
                        stack.push(u);
                    }
                }
            }
        }
    }
    inside
}

/// The parity on all threads. The vertices joined by Voronoi edges that cross no loop
/// fall into components (a concurrent union–find), which all have one parity; the
/// components, few (about one per loop and one outside), are then joined across the loops'
/// edges and searched from the rays' on one thread. The depth-first search is one
/// dependent chain of cache misses: 0.55 s of a 13.5 s reconstruction at 10^7 points on
/// one thread (noisy curve set); on two threads the components took 0.72–0.75 s against the
/// search's 0.56 s (0.57 against 0.39 s on the curve set), so they run from four threads.
#[cfg(feature = "parallel")]
mod components {
    use std::sync::atomic::{AtomicU32, Ordering::Relaxed};

    use rayon::prelude::*;

    use crate::delaunay::NO_TWIN;
    use crate::ids::HalfEdge;
    use crate::parallel;
    use crate::voronoi::Voronoi;

    /// A component's parity before the search reaches it.
    const UNREACHED: u8 = 2;

    /// Half-edges per task of the unions.
    const CHUNK: usize = 1 << 12;

    pub(super) fn parity(
        vor: &Voronoi<'_>,
        blocked: &[bool],
        crosses: impl Fn(HalfEdge) -> bool + Sync,
    ) -> Vec<bool> {
        let halfedges = vor.triangulation().halfedges();
        let forest = Forest::new(vor.vertex_count());
        let open = |v: u32| !blocked[v as usize];
        // Every finite Voronoi edge once (from its smaller half-edge) between open vertices,
        // with whether it crosses a loop.
        let edges = |range: std::ops::Range<usize>| {
            range.map(|e| HalfEdge::new(e as u32)).filter_map(|e| {
                let twin = halfedges[e.index()];
                if twin == NO_TWIN || e > twin || !vor.has_dual(e) {
                    return None;
                }
                let (a, b) = (vor.vertex_of_halfedge(e), vor.vertex_of_halfedge(twin));
                let (a, b) = (a.get(), b.get());
                (open(a) && open(b)).then(|| (a, b, crosses(e)))
            })
        };
        // The ones that cross no loop join components.
        (0..halfedges.len().div_ceil(CHUNK))
            .into_par_iter()
            .for_each(|c| {
                let range = c * CHUNK..((c + 1) * CHUNK).min(halfedges.len());
                for (a, b, _) in edges(range).filter(|&(_, _, crossing)| !crossing) {
                    forest.union(a, b);
                }
            });
        let root = forest.into_roots();
        // The crossing ones link components: found in a second pass, once the components
        // are known, so that only the links are kept (consecutive edges mostly link the same
        // two; a list of every crossing edge, 8 bytes a loop edge, stayed in the worker
        // threads' allocators after it was freed).
        let mut links: Vec<[u32; 2]> = parallel::flat_map_chunks(halfedges.len(), |range, out| {
            for (a, b, _) in edges(range).filter(|&(_, _, crossing)| crossing) {
                let (x, y) = (root[a as usize], root[b as usize]);
                let link = [x.min(y), x.max(y)];
                if out.last() != Some(&link) {
                    out.push(link);
                }
            }
        });
        links.sort_unstable();
        links.dedup();
        // Both directions of every link, sorted: the neighbours of a component are a run.
        let mut across: Vec<[u32; 2]> = links.iter().flat_map(|&[x, y]| [[x, y], [y, x]]).collect();
        across.sort_unstable();
        let neighbours = |c: u32| {
            let from = across.partition_point(|l| l[0] < c);
            let to = across.partition_point(|l| l[0] <= c);
            across[from..to].iter().map(|l| l[1])
        };
        // Searched from the rays in order, as the depth-first search is.
        let mut parity = vec![UNREACHED; vor.vertex_count()];
        let mut stack = Vec::new();
        for (e, v, _) in vor.rays() {
            let v = v.get();
            let c = root[v as usize];
            if !open(v) || parity[c as usize] != UNREACHED {
                continue;
            }
            parity[c as usize] = u8::from(crosses(e));
            stack.push(c);
            while let Some(c) = stack.pop() {
                for d in neighbours(c) {
                    if parity[d as usize] == UNREACHED {
                        parity[d as usize] = parity[c as usize] ^ 1;
                        stack.push(d);
                    }
                }
            }
        }
        // A blocked vertex is its own component, never reached.
        parallel::map_range(root.len(), |v| parity[root[v] as usize] == 1)
    }

    /// A union–find over vertices that several threads join at once. A root is always the
    /// smallest vertex of its component (the larger root is linked to the smaller), so the
    /// roots do not depend on the order of the unions, and every parent is smaller than its
    /// child: a find ends. Relaxed atomics suffice: a link is a compare-and-swap on a root,
    /// which fails if another thread linked it first (then the finds are redone), and a
    /// shortcut only ever points to an ancestor.
    struct Forest {
        parent: Vec<AtomicU32>,
    }

    impl Forest {
        fn new(n: usize) -> Forest {
            Forest {
                parent: (0..n as u32).into_par_iter().map(AtomicU32::new).collect(),
            }
        }

        fn find(&self, mut v: u32) -> u32 {
            loop {
                let p = self.parent[v as usize].load(Relaxed);
                if p == v {
                    return v;
                }
                // Path halving: `v` skips to its grandparent.
                let g = self.parent[p as usize].load(Relaxed);
                if g != p {
                    let _ = self.parent[v as usize].compare_exchange_weak(p, g, Relaxed, Relaxed);
                }
                v = g;
            }
        }

        fn union(&self, a: u32, b: u32) {
            let (mut a, mut b) = (a, b);
            loop {
                (a, b) = (self.find(a), self.find(b));
                if a == b {
                    return;
                }
                let (low, high) = (a.min(b), a.max(b));
                if self.parent[high as usize]
                    .compare_exchange(high, low, Relaxed, Relaxed)
                    .is_ok()
                {
                    return;
                }
            }
        }

        /// The root of every vertex, once every union is done.
        fn into_roots(self) -> Vec<u32> {
            let roots: Vec<u32> = (0..self.parent.len() as u32)
                .into_par_iter()
                .map(|v| self.find(v))
                .collect();
            roots
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::delaunay::{triangulate, NO_TWIN};
    use wdm_crust_testkit::Rng;

    /// Faces whose circumcentres lie in a ring, or in a band along the hull or beyond it
    /// (so that every ray crosses), and the edges between such a face and any other: the
    /// parity must be exactly membership, on one thread and on several. With some faces
    /// blocked, the components and the depth-first search must agree.
    #[test]
    fn the_parity_is_the_enclosed_region_on_any_thread_count() {
        let mut rng = Rng::new(17);
        let points: Vec<[f64; 2]> = (0..40_000).map(|_| [rng.f64(), rng.f64()]).collect();
        let tri = triangulate(&points).unwrap();
        let vor = tri.voronoi();
        let n = vor.vertex_count();
        let region: Vec<bool> = (vor.vertex_ids())
            .map(|v| {
                let [x, y] = vor.vertex_position(v);
                let ring = (x - 0.5).hypot(y - 0.5);
                let band = x.min(y).min(1.0 - x).min(1.0 - y) < 0.03;
                (0.2..0.35).contains(&ring) || band
            })
            .collect();
        let halfedges = tri.halfedges();
        let crosses = |e: HalfEdge| {
            let twin = halfedges[e.index()];
            let far = twin != NO_TWIN && region[vor.vertex_of_halfedge(twin).index()];
            region[vor.vertex_of_halfedge(e).index()] != far
        };
        let blocked: Vec<bool> = (0..n).map(|_| rng.below(50) == 0).collect();
        let one = depth_first(&vor, vec![false; n], crosses);
        assert_eq!(one, region);
        assert!(vor.rays().all(|(e, _, _)| crosses(e)));
        let one_blocked = depth_first(&vor, blocked.clone(), crosses);
        assert!(one_blocked.iter().filter(|&&i| i).count() > n / 10);
        #[cfg(feature = "parallel")]
        for threads in [1, 2, 4] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            let (all, some) = pool.install(|| {
                (
                    components::parity(&vor, &vec![false; n], crosses),
                    components::parity(&vor, &blocked, crosses),
                )
            });
            assert!(all == region, "{threads} threads");
            assert!(some == one_blocked, "{threads} threads, blocked faces");
        }
    }
}
