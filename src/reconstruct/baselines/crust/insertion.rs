//! Exact incremental Delaunay insertion (Bowyer–Watson with ghost triangles) of constructed
//! points into an existing Delaunay triangulation.
//!
//! Starting from `Del(S)`, each Voronoi vertex `w` is inserted by
//! 1. locating a triangle in its cavity: the Delaunay triangle of the samples whose
//!    circumcenter it is, if that is still a triangle, else one that contains it, found by a
//!    visibility walk (exact [`MixedPoints::orient`]);
//! 2. growing the cavity: the connected set of triangles whose open circumdisk contains `w`
//!    (exact [`MixedPoints::incircle`]), together with the ghost triangles of the hull edges
//!    that `w` sees strictly from outside (or lies on, see [`Dt::conflicts`]);
//! 3. replacing the cavity by the fan of triangles joining `w` to its boundary.
//!
//! Every decision is exact, so after each insertion the triangulation is a Delaunay
//! triangulation of the points inserted so far, whatever the degeneracies: a triangle is
//! removed only when `w` is strictly inside its circumcircle, and the standard argument (the
//! cavity is star-shaped from `w`, every new triangle has an empty open circumdisk) applies.

use crate::delaunay::{Triangulation, NO_TWIN};
use crate::ids::LocalPoint;
use crate::kernel::Sign;
use crate::parallel;

use crate::kernel::mixed::MixedPoints;

/// The vertex at infinity of ghost triangles.
const GHOST: u32 = u32::MAX;
/// No triangle.
const NONE: u32 = u32::MAX;

/// A triangulation that grows by exact point insertion.
///
/// Triangle `t` has corners `tri[t].v`, counterclockwise. A ghost triangle `[a, b, GHOST]`
/// stands for the outside of the hull edge `b → a` (the interior of the hull lies left of
/// `b → a`, so the outside lies left of `a → b`). `tri[t].nb[k]` is the triangle across the
/// edge opposite corner `k`, i.e. across `(v[k+1], v[k+2])`.
pub(crate) struct Dt<'p, 'a> {
    pts: &'p MixedPoints<'a>,
    tri: Vec<Triangle>,
    free: Vec<u32>,
    /// A live triangle at every vertex (`NONE` until it is inserted).
    at_vertex: Vec<u32>,
    stamp: u32,
    rng: u64,
    // Scratch buffers of one insertion.
    cavity: Vec<u32>,
    /// Cavity boundary edges `(x, y, triangle outside)`.
    boundary: Vec<(u32, u32, u32)>,
    /// The new triangle on the boundary edge that starts at each vertex (valid only for the
    /// vertices of the current boundary), and at the ghost vertex.
    fan_at: Vec<u32>,
    fan_at_ghost: u32,
}

/// Corners, neighbours and mark of one triangle, side by side: a search step reads them
/// together.
#[derive(Clone, Copy)]
#[repr(align(32))]
struct Triangle {
    v: [u32; 3],
    nb: [u32; 3],
    /// The current cavity search's mark (`2·stamp` in, `2·stamp + 1` out; stamps count
    /// insertions, fewer than 2^31), or [`DEAD`].
    mark: u32,
}

/// The mark of a triangle removed by an insertion (its slot is on the free list).
const DEAD: u32 = u32::MAX;

impl<'p, 'a> Dt<'p, 'a> {
    /// The triangulation `tri` (non-degenerate) with ghost triangles, over `pts`, which must
    /// hold `tri`'s points as its samples.
    pub(crate) fn new(tri: &Triangulation, pts: &'p MixedPoints<'a>, vertex_count: usize) -> Self {
        let solid = tri.triangle_count();
        let halfedges = tri.halfedges();
        let mut t: Vec<Triangle> = tri
            .triangles
            .iter()
            .map(|c| Triangle {
                v: c.map(LocalPoint::get),
                nb: [NONE; 3],
                mark: 0,
            })
            .collect();
        // Ghost of the hull edge starting at each hull vertex.
        let mut ghost_from = vec![NONE; tri.points.len()];
        for (e, &twin) in tri.halfedge_ids().zip(halfedges) {
            let (s, j) = (e.triangle().index(), e.corner());
            let k = (j + 2) % 3; // corner opposite half-edge e = (v[j], v[j+1])
            if twin != NO_TWIN {
                t[s].nb[k] = twin.triangle().get();
            } else {
                let (x, y) = (tri.org(e).get(), tri.dest(e).get());
                let g = t.len() as u32;
                t.push(Triangle {
                    v: [y, x, GHOST],
                    nb: [NONE, NONE, s as u32],
                    mark: 0,
                });
                t[s].nb[k] = g;
                ghost_from[x as usize] = g;
            }
        }
        // Link consecutive ghosts: the ghost of x → y meets the ghost of y → z along (y, ∞).
        for g in solid..t.len() {
            let [y, _, _] = t[g].v;
            let next = ghost_from[y as usize];
            t[g].nb[1] = next;
            t[next as usize].nb[0] = g as u32;
        }
        let mut at_vertex = vec![NONE; vertex_count];
        for (s, triangle) in t.iter().enumerate() {
            for &c in &triangle.v {
                if c != GHOST {
                    at_vertex[c as usize] = s as u32;
                }
            }
        }
        Dt {
            pts,
            tri: t,
            free: Vec::new(),
            at_vertex,
            stamp: 0,
            rng: 0x9E37_79B9_7F4A_7C15,
            cavity: Vec::new(),
            boundary: Vec::new(),
            fan_at: vec![NONE; vertex_count],
            fan_at_ghost: NONE,
        }
    }

    fn is_ghost(&self, t: u32) -> bool {
        self.tri[t as usize].v[2] == GHOST
    }

    /// Does the insertion of `w` destroy triangle `t`?
    ///
    /// A solid triangle: `w` strictly inside its circumcircle. A ghost `[a, b, ∞]`: `w`
    /// strictly outside the hull edge (left of `a → b`), or on its line and inside its
    /// segment, which is exactly when the solid triangle across the edge is destroyed (a
    /// circle meets the line of its chord only at the chord's ends).
    #[inline]
    fn conflicts(&self, t: u32, w: u32) -> bool {
        let [a, b, c] = self.tri[t as usize].v;
        if c != GHOST {
            return self.pts.incircle(a, b, c, w) == Sign::Positive;
        }
        match self.pts.orient(a, b, w) {
            Sign::Positive => true,
            Sign::Negative => false,
            Sign::Zero => {
                let solid = self.tri[t as usize].nb[2];
                let [p, q, r] = self.tri[solid as usize].v;
                self.pts.incircle(p, q, r, w) == Sign::Positive
            }
        }
    }

    fn random(&mut self) -> usize {
        self.rng ^= self.rng << 13;
        self.rng ^= self.rng >> 7;
        self.rng ^= self.rng << 17;
        (self.rng % 3) as usize
    }

    /// A triangle containing `w` (closed), or a ghost whose hull edge `w` sees from outside,
    /// by a visibility walk from `start`. Walks in Delaunay triangulations never cycle.
    fn locate(&mut self, start: u32, w: u32) -> u32 {
        let mut t = start;
        if self.is_ghost(t) {
            t = self.tri[t as usize].nb[2];
        }
        let mut came_from = NONE;
        'walk: loop {
            if self.is_ghost(t) {
                return t;
            }
            let r = self.random();
            let Triangle { v: corners, nb, .. } = self.tri[t as usize];
            for i in 0..3 {
                let k = (i + r) % 3;
                let next = nb[k];
                if next == came_from {
                    continue; // w is known to be strictly on this side of that edge
                }
                let (a, b) = (corners[(k + 1) % 3], corners[(k + 2) % 3]);
                if self.pts.orient(a, b, w) == Sign::Negative {
                    came_from = t;
                    t = next;
                    continue 'walk;
                }
            }
            return t;
        }
    }

    fn new_triangle(&mut self, v: [u32; 3]) -> u32 {
        let triangle = Triangle {
            v,
            nb: [NONE; 3],
            mark: 0,
        };
        if let Some(t) = self.free.pop() {
            self.tri[t as usize] = triangle;
            t
        } else {
            self.tri.push(triangle);
            (self.tri.len() - 1) as u32
        }
    }

    fn corner_index(&self, t: u32, c: u32) -> usize {
        let v = self.tri[t as usize].v;
        if v[0] == c {
            0
        } else if v[1] == c {
            1
        } else {
            2
        }
    }

    /// The new triangle on the boundary edge that starts at `x`.
    fn fan_slot(&mut self, x: u32) -> &mut u32 {
        if x == GHOST {
            &mut self.fan_at_ghost
        } else {
            &mut self.fan_at[x as usize]
        }
    }

    /// Inserts point `w`, walking from a triangle at vertex `near` (already inserted).
    /// Returns false if `w` coincides with a vertex (nothing changes).
    ///
    /// `seed` is a triangle `t` and its corners, counterclockwise, whose circumcircle holds
    /// `w` strictly inside (a Delaunay triangle of the samples and its circumcenter): if `t`
    /// still has those corners, it is in the cavity of `w` and no walk is needed.
    pub(crate) fn insert(&mut self, w: u32, near: u32, seed: (u32, [u32; 3])) -> bool {
        let (t, corners) = seed;
        let live = self.tri[t as usize];
        let t0 = if live.mark != DEAD && live.v == corners {
            t
        } else {
            let start = self.at_vertex[near as usize];
            self.locate(start, w)
        };
        if !self.conflicts(t0, w) {
            return false; // w is a vertex of t0
        }
        self.stamp += 1;
        let (inside, outside) = (2 * self.stamp, 2 * self.stamp + 1);
        self.cavity.clear();
        self.boundary.clear();
        self.cavity.push(t0);
        self.tri[t0 as usize].mark = inside;
        let mut i = 0;
        while i < self.cavity.len() {
            let t = self.cavity[i];
            i += 1;
            for k in 0..3 {
                let n = self.tri[t as usize].nb[k];
                let m = self.tri[n as usize].mark;
                if m == inside {
                    continue;
                }
                if m != outside && self.conflicts(n, w) {
                    self.tri[n as usize].mark = inside;
                    self.cavity.push(n);
                    continue;
                }
                self.tri[n as usize].mark = outside;
                let c = self.tri[t as usize].v;
                self.boundary.push((c[(k + 1) % 3], c[(k + 2) % 3], n));
            }
        }
        for &t in &self.cavity {
            self.tri[t as usize].mark = DEAD;
            self.free.push(t);
        }
        // The fan: [x, y, w] for every boundary edge x → y, with the ghost vertex moved last.
        for b in 0..self.boundary.len() {
            let (x, y, out) = self.boundary[b];
            let corners = if x == GHOST {
                [y, w, GHOST]
            } else if y == GHOST {
                [w, x, GHOST]
            } else {
                [x, y, w]
            };
            let t = self.new_triangle(corners);
            let kw = self.corner_index(t, w);
            self.tri[t as usize].nb[kw] = out;
            // The outside triangle's edge (y, x) is opposite its corner that is neither.
            let ko = (0..3)
                .find(|&k| {
                    let c = self.tri[out as usize].v[k];
                    c != x && c != y
                })
                .unwrap_or(0);
            self.tri[out as usize].nb[ko] = t;
            *self.fan_slot(x) = t;
        }
        // Link the fan: [x, y, w] and [y, z, w] share the edge (y, w), which is opposite x in
        // the first and opposite z in the second. Edge starts are unique on the boundary cycle.
        for b in 0..self.boundary.len() {
            let (x, y, _) = self.boundary[b];
            let t = *self.fan_slot(x);
            let partner = *self.fan_slot(y);
            let kx = self.corner_index(t, x);
            self.tri[t as usize].nb[kx] = partner;
            // In the partner [y, z, w] the shared edge is opposite z: neither y nor w.
            let v = self.tri[partner as usize].v;
            let kz = (0..3).find(|&k| v[k] != y && v[k] != w).unwrap_or(0);
            self.tri[partner as usize].nb[kz] = t;
        }
        // Every corner of the cavity is on its boundary: each gets a new triangle, and so
        // does w.
        for b in 0..self.boundary.len() {
            let x = self.boundary[b].0;
            let t = *self.fan_slot(x);
            if x != GHOST {
                self.at_vertex[x as usize] = t;
            }
            self.at_vertex[w as usize] = t;
        }
        true
    }

    /// The edges `[a, b]`, `a < b`, between two samples for which `keep(a, b, c, across)`
    /// holds, where `(a, b, c)` is a counterclockwise solid triangle on the edge and `across`
    /// the corner of the triangle on the other side (`None` on the hull); an edge may come
    /// twice (from both of its triangles when it is on the hull of none).
    pub(crate) fn sample_edges(
        &self,
        keep: impl Fn(u32, u32, u32, Option<u32>) -> bool + Sync + Send,
    ) -> Vec<[u32; 2]> {
        parallel::flat_map_chunks(self.tri.len(), |range, out| {
            for triangle in &self.tri[range] {
                let corners = triangle.v;
                if triangle.mark == DEAD || corners[2] == GHOST {
                    continue;
                }
                for k in 0..3 {
                    let (a, b) = (corners[(k + 1) % 3], corners[(k + 2) % 3]);
                    if !self.pts.is_sample(a) || !self.pts.is_sample(b) {
                        continue;
                    }
                    let n = triangle.nb[k];
                    let across = if self.is_ghost(n) {
                        None
                    } else if a < b {
                        self.tri[n as usize]
                            .v
                            .into_iter()
                            .find(|&c| c != a && c != b)
                    } else {
                        continue; // the triangle across reports it
                    };
                    if keep(a, b, corners[k], across) {
                        out.push([a.min(b), a.max(b)]);
                    }
                }
            }
        })
    }
}
