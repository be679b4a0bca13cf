//! Exact incremental Delaunay insertion (Bowyer–Watson with ghost triangles) of constructed
//! points into an existing Delaunay triangulation.
//!
//! Starting from `Del(S)`, each Voronoi vertex `w` is inserted by
//! 1. locating a triangle that contains it by a visibility walk (exact [`MixedPoints::orient`]);
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

use crate::kernel::mixed::MixedPoints;

/// The vertex at infinity of ghost triangles.
const GHOST: u32 = u32::MAX;
/// No triangle.
const NONE: u32 = u32::MAX;

/// A triangulation that grows by exact point insertion.
///
/// Triangle `t` has corners `v[t]`, counterclockwise. A ghost triangle `[a, b, GHOST]` stands
/// for the outside of the hull edge `b → a` (the interior of the hull lies left of `b → a`,
/// so the outside lies left of `a → b`). `nb[t][k]` is the triangle across the edge opposite
/// corner `k`, i.e. across `(v[t][k+1], v[t][k+2])`.
pub(crate) struct Dt<'p, 'a> {
    pts: &'p MixedPoints<'a>,
    v: Vec<[u32; 3]>,
    nb: Vec<[u32; 3]>,
    alive: Vec<bool>,
    free: Vec<u32>,
    /// A live triangle at every vertex (`NONE` until it is inserted).
    at_vertex: Vec<u32>,
    /// Per-triangle marks of the current cavity search: `2·stamp` in, `2·stamp + 1` out.
    mark: Vec<u32>,
    stamp: u32,
    rng: u64,
    // Scratch buffers of one insertion.
    cavity: Vec<u32>,
    /// Cavity boundary edges `(x, y, triangle outside)`.
    boundary: Vec<(u32, u32, u32)>,
    /// The fan of the last insertion: `(x, y, triangle)` for the new triangle on edge `x → y`.
    created: Vec<(u32, u32, u32)>,
}

impl<'p, 'a> Dt<'p, 'a> {
    /// The triangulation `tri` (non-degenerate) with ghost triangles, over `pts`, which must
    /// hold `tri`'s points as its samples.
    pub(crate) fn new(tri: &Triangulation, pts: &'p MixedPoints<'a>, vertex_count: usize) -> Self {
        let solid = tri.triangle_count();
        let halfedges = tri.halfedges();
        let mut v: Vec<[u32; 3]> = tri
            .triangles
            .iter()
            .map(|t| t.map(LocalPoint::get))
            .collect();
        let mut nb = vec![[NONE; 3]; solid];
        // Ghost of the hull edge starting at each hull vertex.
        let mut ghost_from = vec![NONE; tri.points.len()];
        for (e, &twin) in tri.halfedge_ids().zip(halfedges) {
            let (t, j) = (e.triangle().index(), e.corner());
            let k = (j + 2) % 3; // corner opposite half-edge e = (v[j], v[j+1])
            if twin != NO_TWIN {
                nb[t][k] = twin.triangle().get();
            } else {
                let (x, y) = (tri.org(e).get(), tri.dest(e).get());
                let g = v.len() as u32;
                v.push([y, x, GHOST]);
                nb.push([NONE, NONE, t as u32]);
                nb[t][k] = g;
                ghost_from[x as usize] = g;
            }
        }
        // Link consecutive ghosts: the ghost of x → y meets the ghost of y → z along (y, ∞).
        for g in solid..v.len() {
            let [y, _, _] = v[g];
            let next = ghost_from[y as usize];
            nb[g][1] = next;
            nb[next as usize][0] = g as u32;
        }
        let mut at_vertex = vec![NONE; vertex_count];
        for (t, corners) in v.iter().enumerate() {
            for &c in corners {
                if c != GHOST {
                    at_vertex[c as usize] = t as u32;
                }
            }
        }
        let count = v.len();
        Dt {
            pts,
            v,
            nb,
            alive: vec![true; count],
            free: Vec::new(),
            at_vertex,
            mark: vec![0; count],
            stamp: 0,
            rng: 0x9E37_79B9_7F4A_7C15,
            cavity: Vec::new(),
            boundary: Vec::new(),
            created: Vec::new(),
        }
    }

    fn is_ghost(&self, t: u32) -> bool {
        self.v[t as usize][2] == GHOST
    }

    /// Does the insertion of `w` destroy triangle `t`?
    ///
    /// A solid triangle: `w` strictly inside its circumcircle. A ghost `[a, b, ∞]`: `w`
    /// strictly outside the hull edge (left of `a → b`), or on its line and inside its
    /// segment, which is exactly when the solid triangle across the edge is destroyed (a
    /// circle meets the line of its chord only at the chord's ends).
    fn conflicts(&self, t: u32, w: u32) -> bool {
        let [a, b, c] = self.v[t as usize];
        if c != GHOST {
            return self.pts.incircle(a, b, c, w) == Sign::Positive;
        }
        match self.pts.orient(a, b, w) {
            Sign::Positive => true,
            Sign::Negative => false,
            Sign::Zero => {
                let solid = self.nb[t as usize][2];
                let [p, q, r] = self.v[solid as usize];
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
            t = self.nb[t as usize][2];
        }
        let mut came_from = NONE;
        'walk: loop {
            if self.is_ghost(t) {
                return t;
            }
            let r = self.random();
            for i in 0..3 {
                let k = (i + r) % 3;
                let next = self.nb[t as usize][k];
                if next == came_from {
                    continue; // w is known to be strictly on this side of that edge
                }
                let corners = self.v[t as usize];
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

    fn new_triangle(&mut self, corners: [u32; 3]) -> u32 {
        if let Some(t) = self.free.pop() {
            self.v[t as usize] = corners;
            self.nb[t as usize] = [NONE; 3];
            self.alive[t as usize] = true;
            t
        } else {
            self.v.push(corners);
            self.nb.push([NONE; 3]);
            self.alive.push(true);
            self.mark.push(0);
            (self.v.len() - 1) as u32
        }
    }

    fn corner_index(&self, t: u32, c: u32) -> usize {
        let v = self.v[t as usize];
        if v[0] == c {
            0
        } else if v[1] == c {
            1
        } else {
            2
        }
    }

    /// Inserts point `w`, walking from a triangle at vertex `near` (already inserted).
    /// Returns false if `w` coincides with a vertex (nothing changes).
    pub(crate) fn insert(&mut self, w: u32, near: u32) -> bool {
        let start = self.at_vertex[near as usize];
        let t0 = self.locate(start, w);
        if !self.conflicts(t0, w) {
            return false; // w is a vertex of t0
        }
        self.stamp += 1;
        let (inside, outside) = (2 * self.stamp, 2 * self.stamp + 1);
        self.cavity.clear();
        self.boundary.clear();
        self.cavity.push(t0);
        self.mark[t0 as usize] = inside;
        let mut i = 0;
        while i < self.cavity.len() {
            let t = self.cavity[i];
            i += 1;
            for k in 0..3 {
                let n = self.nb[t as usize][k];
                let m = self.mark[n as usize];
                if m == inside {
                    continue;
                }
                if m != outside && self.conflicts(n, w) {
                    self.mark[n as usize] = inside;
                    self.cavity.push(n);
                    continue;
                }
                self.mark[n as usize] = outside;
                let c = self.v[t as usize];
                self.boundary.push((c[(k + 1) % 3], c[(k + 2) % 3], n));
            }
        }
        for &t in &self.cavity {
            self.alive[t as usize] = false;
            self.free.push(t);
        }
        // The fan: [x, y, w] for every boundary edge x → y, with the ghost vertex moved last.
        self.created.clear();
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
            self.nb[t as usize][kw] = out;
            // The outside triangle's edge (y, x) is opposite its corner that is neither.
            let ko = (0..3)
                .find(|&k| {
                    let c = self.v[out as usize][k];
                    c != x && c != y
                })
                .unwrap_or(0);
            self.nb[out as usize][ko] = t;
            self.created.push((x, y, t));
        }
        // Link the fan: [x, y, w] and [y, z, w] share the edge (y, w), which is opposite x in
        // the first and opposite z in the second. Edge starts are unique on the boundary cycle.
        self.created.sort_unstable();
        for j in 0..self.created.len() {
            let (x, y, t) = self.created[j];
            let Ok(p) = self.created.binary_search_by_key(&y, |&(s, _, _)| s) else {
                continue; // unreachable: the cavity boundary is a closed cycle
            };
            let (_, z, partner) = self.created[p];
            let kx = self.corner_index(t, x);
            self.nb[t as usize][kx] = partner;
            let kz = self.corner_index(partner, z);
            self.nb[partner as usize][kz] = t;
        }
        for j in 0..self.created.len() {
            let t = self.created[j].2;
            for c in self.v[t as usize] {
                if c != GHOST {
                    self.at_vertex[c as usize] = t;
                }
            }
        }
        true
    }

    /// Calls `f(a, b, c, across)` once for every edge `a → b` of a solid triangle `(a, b, c)`
    /// (counterclockwise) whose ends are both samples: `across` is the corner of the triangle
    /// on the other side of the edge, `None` for a hull edge.
    pub(crate) fn for_each_sample_edge(&self, mut f: impl FnMut(u32, u32, u32, Option<u32>)) {
        for (t, corners) in self.v.iter().enumerate() {
            if !self.alive[t] || corners[2] == GHOST {
                continue;
            }
            for k in 0..3 {
                let (a, b) = (corners[(k + 1) % 3], corners[(k + 2) % 3]);
                if !self.pts.is_sample(a) || !self.pts.is_sample(b) {
                    continue;
                }
                let n = self.nb[t][k];
                if self.is_ghost(n) {
                    f(a, b, corners[k], None);
                } else if a < b {
                    let across = self.v[n as usize].into_iter().find(|&c| c != a && c != b);
                    f(a, b, corners[k], across);
                }
            }
        }
    }
}
