//! Construction store of the divide and conquer: triangles with ghost triangles, pure
//! topology (no coordinates).
//!
//! Half-edge `e` belongs to triangle `e / 3` and runs from corner `e % 3` to the next corner;
//! `twin[e]` is the half-edge running the other way in the neighbouring triangle. This is the
//! layout of the finished [`Triangulation`](super::Triangulation), so the store turns into the
//! result in place.
//!
//! Every convex hull edge `a → b` (counterclockwise, interior on its left) has a *ghost*
//! triangle `[b, a, GHOST]` on its outer side, so every half-edge has a twin while building.
//! Invariants:
//! - the ghost vertex is always corner 2 of a ghost: `[v0, v1, GHOST]` is the ghost of the hull
//!   edge `v1 → v0`; its half-edges are `v0 → v1` (twin: the hull edge), `v1 → GHOST`,
//!   `GHOST → v0`;
//! - the ghosts form a ring along the hull: the ghost of the next hull edge is the twin side
//!   of `GHOST → v0` ([`MeshPart::ring_next`]), the previous one that of `v1 → GHOST`;
//! - a triangulation of `k` points (with at least one edge) uses exactly `2k − 2` triangles,
//!   ghosts included (`2k − 2 − h` real ones and `h` ghosts; `2(k − 1)` ghosts when collinear).
//!
//! The last invariant lets every subproblem of the divide and conquer own a fixed range of
//! slots: points `lo..hi` own triangles `2lo..2hi − 2`, and merging `lo..mid` with `mid..hi`
//! adds exactly the two slots `2mid − 2` and `2mid − 1`. Merging never allocates: it deletes
//! edges by flipping them into the ghost ring and turns ghosts into new triangles.
//!
//! The operations work on a [`MeshPart`], the slots of one subproblem: the whole store for the
//! sequential construction, or (feature `parallel`) disjoint pieces of it that two threads
//! build at the same time.

/// The vertex at infinity of the ghost triangles.
pub const GHOST: u32 = u32::MAX;

/// The next half-edge counterclockwise in the same triangle.
#[inline]
pub fn next(e: u32) -> u32 {
    if e % 3 == 2 {
        e - 2
    } else {
        e + 1
    }
}

/// The previous half-edge counterclockwise in the same triangle.
#[inline]
pub fn prev(e: u32) -> u32 {
    if e % 3 == 0 {
        e + 2
    } else {
        e - 1
    }
}

/// The whole store: room for the `2n − 2` slots of `n` points.
pub struct Mesh {
    /// Corners of every triangle (ghosts: corner 2 is [`GHOST`]).
    pub tri: Vec<[u32; 3]>,
    /// Twin of every half-edge.
    pub twin: Vec<u32>,
}

impl Mesh {
    /// Room for the `2n − 2` triangles of `n ≥ 2` points. Every slot gets written by the
    /// construction, so the zeroed (lazily mapped) memory is never read as such.
    pub fn for_points(n: usize) -> Mesh {
        let slots = 2 * n - 2;
        Mesh {
            tri: vec![[0; 3]; slots],
            twin: vec![0; 3 * slots],
        }
    }

    /// All slots, as the part of the subproblem of every point (`SHIFTED` or not: the ids
    /// are global either way).
    pub fn whole<const SHIFTED: bool>(&mut self) -> MeshPart<'_, SHIFTED> {
        MeshPart {
            tri: &mut self.tri,
            twin: &mut self.twin,
            first_slot: 0,
            first_edge: 0,
        }
    }

    /// Finishes the triangulation: the hull counterclockwise from the ghost `g` of the hull
    /// edge out of its first point (`g = [·, first]`), and the triangles and twins without the
    /// ghosts ([`NO_TWIN`](super::NO_TWIN) on the hull). Vertices keep their construction
    /// indices, which are the local indices of the finished triangulation.
    ///
    /// The real triangles in the last slots move into the ghosts' slots below them, so only as
    /// many triangles move as there are hull edges.
    pub fn finish(mut self, g: u32, no_twin: u32) -> Finished {
        let mut hull = Vec::new();
        let mut ghosts = Vec::new();
        let mut h = g;
        loop {
            hull.push(self.tri[h as usize][1]);
            ghosts.push(h);
            let hull_edge = self.twin[(3 * h) as usize];
            self.twin[hull_edge as usize] = no_twin;
            h = self.whole::<false>().ring_next(h);
            if h == g {
                break;
            }
        }
        let real = self.tri.len() - ghosts.len();
        ghosts.sort_unstable();
        let mut source = self.tri.len();
        for &hole in ghosts.iter().take_while(|&&hole| (hole as usize) < real) {
            // The next real triangle from the end (slots at or above `real` hold the rest of
            // the ghosts, all of which sort after the holes).
            source -= 1;
            while self.tri[source][2] == GHOST {
                source -= 1;
            }
            let (s, t) = (source, hole as usize);
            self.tri[t] = self.tri[s];
            for k in 0..3 {
                let u = self.twin[3 * s + k];
                self.twin[3 * t + k] = u;
                // A neighbour that moves later reads the entry fixed here.
                if u != no_twin {
                    self.twin[u as usize] = (3 * t + k) as u32;
                }
            }
        }
        self.tri.truncate(real);
        self.twin.truncate(3 * real);
        self.tri.shrink_to_fit();
        self.twin.shrink_to_fit();
        Finished {
            triangles: self.tri,
            halfedges: self.twin,
            hull,
        }
    }
}

/// The slots of one subproblem: points `lo..hi` own triangles `2lo..2hi − 2` (see the module
/// docs).
///
/// With `SHIFTED`, ids are global (a corner is a point's index in the whole triangulation, a
/// half-edge `3t + k` for the whole store) while the slices start at the part's first slot:
/// the parts of two subproblems are disjoint sub-slices that can be built at the same time
/// and merged without relabelling, and every access subtracts the first slot or half-edge.
/// Without it the part is its own zero-based store (the whole store, or a subproblem built
/// on its own and relocated by `relocate` afterwards): no subtraction in the hot loops.
pub struct MeshPart<'a, const SHIFTED: bool> {
    tri: &'a mut [[u32; 3]],
    twin: &'a mut [u32],
    /// Global id of `tri[0]` and of `twin[0]` (`3 first_slot`); zero unless `SHIFTED`.
    first_slot: u32,
    first_edge: u32,
}

impl<'a, const SHIFTED: bool> MeshPart<'a, SHIFTED> {
    /// Index into `tri` of slot `t`.
    #[inline(always)]
    fn slot(&self, t: u32) -> usize {
        if SHIFTED {
            (t - self.first_slot) as usize
        } else {
            t as usize
        }
    }

    /// Index into `twin` of half-edge `e`.
    #[inline(always)]
    fn edge(&self, e: u32) -> usize {
        if SHIFTED {
            (e - self.first_edge) as usize
        } else {
            e as usize
        }
    }

    /// Corners of slot `t`.
    #[inline]
    pub fn corners(&self, t: u32) -> [u32; 3] {
        self.tri[self.slot(t)]
    }

    /// Twin of half-edge `e`.
    #[inline]
    pub fn twin(&self, e: u32) -> u32 {
        self.twin[self.edge(e)]
    }

    /// Splits the part of points `lo..hi` at `mid` into the parts of `lo..mid` (slots
    /// `2lo..2mid − 2`) and `mid..hi` (slots `2mid..2hi − 2`), with global ids; the two
    /// slots between them are the merge's and stay with `self`.
    #[cfg(any(feature = "parallel", test))]
    pub fn split_at_point(&mut self, mid: u32) -> [MeshPart<'_, true>; 2] {
        let merge_slots = 2 * mid - 2;
        let (at_slot, at_edge) = (self.slot(merge_slots), self.edge(3 * merge_slots));
        let (left_tri, rest_tri) = self.tri.split_at_mut(at_slot);
        let (left_twin, rest_twin) = self.twin.split_at_mut(at_edge);
        [
            MeshPart {
                tri: left_tri,
                twin: left_twin,
                first_slot: self.first_slot,
                first_edge: self.first_edge,
            },
            MeshPart {
                tri: &mut rest_tri[2..],
                twin: &mut rest_twin[6..],
                first_slot: merge_slots + 2,
                first_edge: 3 * (merge_slots + 2),
            },
        ]
    }

    /// The same slots as a zero-based store of their own, for a subproblem built with local
    /// ids (point `lo` is 0); [`Self::relocate`] turns them global afterwards.
    #[cfg(any(feature = "parallel", test))]
    pub fn detached(&mut self) -> MeshPart<'_, false> {
        MeshPart {
            tri: self.tri,
            twin: self.twin,
            first_slot: 0,
            first_edge: 0,
        }
    }

    /// Turns the local ids that a [detached](Self::detached) construction wrote into global
    /// ones: corners move by the part's first point, half-edges by its first half-edge.
    #[cfg(any(feature = "parallel", test))]
    pub fn relocate(&mut self) {
        let first_point = self.first_slot / 2;
        for t in self.tri.iter_mut() {
            for v in t {
                if *v != GHOST {
                    *v += first_point;
                }
            }
        }
        for e in self.twin.iter_mut() {
            *e += self.first_edge;
        }
    }

    /// Start vertex of half-edge `e`.
    #[inline]
    pub fn org(&self, e: u32) -> u32 {
        self.tri[self.slot(e / 3)][(e % 3) as usize]
    }

    #[inline]
    fn link(&mut self, a: u32, b: u32) {
        self.twin[self.edge(a)] = b;
        self.twin[self.edge(b)] = a;
    }

    /// The ghost of the next hull edge (counterclockwise).
    #[inline]
    pub fn ring_next(&self, g: u32) -> u32 {
        self.twin[self.edge(3 * g + 2)] / 3
    }

    /// The ghost of the previous hull edge (counterclockwise).
    #[inline]
    pub fn ring_prev(&self, g: u32) -> u32 {
        self.twin[self.edge(3 * g + 1)] / 3
    }

    /// Does ghost `g` touch vertex `v`?
    #[inline]
    pub fn ghost_touches(&self, g: u32, v: u32) -> bool {
        let t = self.tri[self.slot(g)];
        t[2] == GHOST && (t[0] == v || t[1] == v)
    }

    /// Ghost `g = [b, a, GHOST]` of the hull edge `a → b`, glued to the next ghost `g_next`.
    #[inline]
    fn ghost(&mut self, g: u32, a: u32, b: u32, g_next: u32) {
        self.tri[self.slot(g)] = [b, a, GHOST];
        self.link(3 * g + 2, 3 * g_next + 1);
    }

    /// Two points: two ghosts back to back in slot `s` (`[b, a]`) and `s + 1` (`[a, b]`).
    pub fn pair(&mut self, s: u32, a: u32, b: u32) {
        self.ghost(s, a, b, s + 1);
        self.ghost(s + 1, b, a, s);
        self.link(3 * s, 3 * (s + 1));
    }

    /// The counterclockwise triangle `[a, b, c]` in slot `s`, its ghosts in `s + 1..s + 4`
    /// (`[b, a]`, `[c, b]`, `[a, c]`).
    pub fn triangle(&mut self, s: u32, a: u32, b: u32, c: u32) {
        self.tri[self.slot(s)] = [a, b, c];
        self.ghost(s + 1, a, b, s + 2);
        self.ghost(s + 2, b, c, s + 3);
        self.ghost(s + 3, c, a, s + 1);
        for k in 0..3 {
            self.link(3 * s + k, 3 * (s + 1 + k));
        }
    }

    /// Three collinear points with `b` between `a` and `c`: four ghosts in `s..s + 4`
    /// (`[b, a]`, `[c, b]`, `[b, c]`, `[a, b]`).
    pub fn chain3(&mut self, s: u32, a: u32, b: u32, c: u32) {
        self.ghost(s, a, b, s + 1);
        self.ghost(s + 1, b, c, s + 2);
        self.ghost(s + 2, c, b, s + 3);
        self.ghost(s + 3, b, a, s);
        self.link(3 * s, 3 * (s + 3));
        self.link(3 * (s + 1), 3 * (s + 2));
    }

    /// Starts a merge: the ghost of the new hull edge `l → r` goes to slot `s`, between the
    /// ghost `gl = [l, ·]` (edge into `l`) and `gr = [·, r]` (edge out of `r`); `None` for a
    /// side that is a single point (then [`Self::close`] glues that side). Returns the
    /// half-edge `r → l` that the first new triangle will be glued to.
    pub fn open(&mut self, s: u32, l: u32, r: u32, gl: Option<u32>, gr: Option<u32>) -> u32 {
        self.tri[self.slot(s)] = [r, l, GHOST];
        if let Some(gl) = gl {
            self.link(3 * s + 1, 3 * gl + 2);
        }
        if let Some(gr) = gr {
            self.link(3 * s + 2, 3 * gr + 1);
        }
        3 * s
    }

    /// Ends a merge: the ghost of the new hull edge `r → l` goes to slot `s`, glued to `base`
    /// (`r → l`) and to the ring ghosts `a = [·, l]` and `b = [r, ·]`, or, for a side that is
    /// a single point, to the ghost `opened` of [`Self::open`].
    pub fn close(
        &mut self,
        s: u32,
        (l, r): (u32, u32),
        base: u32,
        (a, b): (Option<u32>, Option<u32>),
        opened: u32,
    ) {
        self.tri[self.slot(s)] = [l, r, GHOST];
        self.link(3 * s, base);
        self.link(3 * s + 1, b.map_or(3 * opened + 2, |b| 3 * b + 2));
        self.link(3 * s + 2, a.map_or(3 * opened + 1, |a| 3 * a + 1));
    }

    /// Deletes the edge between `l` and `c` on the left side of a merge by flipping it with
    /// the ghost `a = [c, l, GHOST]`: the real triangle `[l, c, x]` behind it and `a` become the
    /// ghosts `[x, l]` (still slot `a`) and `[c, x]`. Returns `x`.
    #[inline(always)] // into both monomorphisations of the merge
    pub fn flip_left(&mut self, a: u32) -> u32 {
        let h = self.twin[self.edge(3 * a)]; // l → c
        let (hn, hp) = (next(h), prev(h)); // c → x, x → l
        let f = h / 3;
        let c = self.org(hn);
        let x = self.org(hp);
        let t1 = self.twin[self.edge(hp)];
        let t2 = self.twin[self.edge(hn)];
        let ring = self.twin[self.edge(3 * a + 2)];
        self.tri[self.slot(a)][0] = x;
        self.link(3 * a, t1);
        self.tri[self.slot(f)] = [c, x, GHOST];
        self.link(3 * f, t2);
        self.link(3 * f + 1, 3 * a + 2);
        self.link(3 * f + 2, ring);
        x
    }

    /// Mirror of [`Self::flip_left`] on the right side: the ghost `b = [r, c, GHOST]` and the
    /// real triangle `[c, r, z]` behind it become the ghosts `[r, z]` (still slot `b`) and
    /// `[z, c]`. Returns `z`.
    #[inline(always)] // into both monomorphisations of the merge
    pub fn flip_right(&mut self, b: u32) -> u32 {
        let h = self.twin[self.edge(3 * b)]; // c → r
        let (hn, hp) = (next(h), prev(h)); // r → z, z → c
        let f = h / 3;
        let c = self.org(h);
        let z = self.org(hp);
        let t1 = self.twin[self.edge(hn)];
        let t2 = self.twin[self.edge(hp)];
        let ring = self.twin[self.edge(3 * b + 1)];
        self.tri[self.slot(b)][1] = z;
        self.link(3 * b, t1);
        self.tri[self.slot(f)] = [z, c, GHOST];
        self.link(3 * f, t2);
        self.link(3 * f + 1, ring);
        self.link(3 * f + 2, 3 * b + 1);
        z
    }

    /// Turns the left ghost `a = [c, l, GHOST]` into the triangle `[c, l, r]` glued to `base`
    /// (`r → l`). Returns the new base `r → c` and the next left ghost `[·, c]`.
    #[inline]
    pub fn take_left(&mut self, a: u32, base: u32, r: u32) -> (u32, u32) {
        let next_ghost = self.ring_next(a);
        self.tri[self.slot(a)][2] = r;
        self.link(3 * a + 1, base);
        (3 * a + 2, next_ghost)
    }

    /// Turns the right ghost `b = [r, c, GHOST]` into the triangle `[r, c, l]` glued to `base`
    /// (`r → l`). Returns the new base `c → l` and the next right ghost `[c, ·]`.
    #[inline]
    pub fn take_right(&mut self, b: u32, base: u32, l: u32) -> (u32, u32) {
        let next_ghost = self.ring_prev(b);
        self.tri[self.slot(b)][2] = l;
        self.link(3 * b + 2, base);
        (3 * b + 1, next_ghost)
    }
}

/// The flat arrays of a finished triangulation.
pub struct Finished {
    pub triangles: Vec<[u32; 3]>,
    pub halfedges: Vec<u32>,
    pub hull: Vec<u32>,
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every half-edge's twin points back and runs the other way.
    fn assert_glued<const S: bool>(m: &MeshPart<S>) {
        let edges = m.first_edge..m.first_edge + m.twin.len() as u32;
        for e in edges.clone() {
            let t = m.twin(e);
            assert!(edges.contains(&t), "twin of {e} inside the part");
            assert_eq!(m.twin(t), e, "twin of twin of {e}");
            assert_eq!(m.org(t), m.org(next(e)), "twin of {e} reversed");
        }
    }

    /// The hull walk along the ghost ring from ghost `g`.
    fn ring<const S: bool>(m: &MeshPart<S>, g: u32) -> Vec<u32> {
        let mut hull = vec![m.corners(g)[1]];
        let mut h = m.ring_next(g);
        while h != g {
            hull.push(m.corners(h)[1]);
            h = m.ring_next(h);
        }
        hull
    }

    #[test]
    fn leaves_are_closed_rings() {
        let mut store = Mesh::for_points(2);
        let mut m = store.whole::<false>();
        m.pair(0, 5, 6);
        assert_glued(&m);
        assert_eq!(ring(&m, 0), vec![5, 6]);

        let mut store = Mesh::for_points(3);
        let mut m = store.whole::<false>();
        m.triangle(0, 1, 2, 3);
        assert_glued(&m);
        assert_eq!(ring(&m, 1), vec![1, 2, 3]);
        assert_eq!(m.ring_prev(1), 3);

        let mut store = Mesh::for_points(3);
        let mut m = store.whole::<false>();
        m.chain3(0, 1, 2, 3);
        assert_glued(&m);
        assert_eq!(ring(&m, 0), vec![1, 2, 3, 2]);
    }

    #[test]
    fn split_parts_speak_global_ids() {
        // Points 0..7 split at 3: slots 0..4 for 0..3, 4 and 5 for the merge, 6..12 for 3..7.
        let mut store = Mesh::for_points(7);
        let mut whole = store.whole::<false>();
        let [mut left, mut right] = whole.split_at_point(3);
        left.triangle(0, 0, 1, 2);
        right.chain3(6, 3, 4, 5);
        right.pair(10, 5, 6);
        assert_glued(&left);
        assert_eq!(ring(&left, 1), vec![0, 1, 2]);
        assert_eq!(right.twin(3 * 10), 3 * 11);
        assert_eq!(ring(&right, 6), vec![3, 4, 5, 4]);
        assert_eq!(store.tri[6], [4, 3, GHOST], "written through the part");
        assert_eq!(store.tri[4], [0; 3], "the merge's slots untouched");
    }

    #[test]
    fn a_detached_part_relocates_to_the_global_ids() {
        // The right half (points 3..7, slots 6..12) built with local ids, then relocated,
        // equals the same construction with global ids.
        let build = |global: bool| {
            let mut store = Mesh::for_points(7);
            let mut whole = store.whole::<false>();
            let [_, mut right] = whole.split_at_point(3);
            if global {
                right.chain3(6, 3, 4, 5);
                right.pair(10, 5, 6);
            } else {
                let mut local = right.detached();
                local.chain3(0, 0, 1, 2);
                local.pair(4, 2, 3);
                right.relocate();
            }
            store
        };
        let (global, relocated) = (build(true), build(false));
        assert_eq!(relocated.tri, global.tri);
        assert_eq!(relocated.twin, global.twin);
    }

    #[test]
    fn flips_and_takes_keep_the_twins_glued() {
        // Triangle [0, 1, 2]; the left side of a merge is at l = 0 with ghost a = [1, 0].
        let mut store = Mesh::for_points(3);
        let mut m = store.whole::<false>();
        m.triangle(0, 0, 1, 2);
        assert_eq!(m.corners(1), [1, 0, GHOST]);
        assert_eq!(m.flip_left(1), 2);
        assert_glued(&m);
        assert_eq!(ring(&m, 1), vec![0, 2, 1, 2]);
        // Edge 0–1 is gone: two ghosts [2, 0] and [1, 2] plus the old ones of 1→2, 2→0.
        assert_eq!(store.tri.iter().filter(|t| t[2] == GHOST).count(), 4);
    }

    #[test]
    fn compaction_moves_triangles_over_ghosts() {
        // A real triangle in the last slot, behind its three ghosts: it has to move.
        let mut store = Mesh::for_points(3);
        let mut m = store.whole::<false>();
        m.ghost(0, 0, 1, 1);
        m.ghost(1, 1, 2, 2);
        m.ghost(2, 2, 0, 0);
        m.tri[3] = [0, 1, 2];
        for k in 0..3 {
            m.link(3 * k, 9 + k);
        }
        assert_glued(&m);
        let done = store.finish(0, u32::MAX);
        assert_eq!(done.triangles, vec![[0, 1, 2]]);
        assert_eq!(done.halfedges, vec![u32::MAX; 3]);
        assert_eq!(done.hull, vec![0, 1, 2]);
    }
}
