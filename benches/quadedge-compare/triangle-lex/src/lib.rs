//! The triangle store of the current wdm-crust driven by the pipeline of its first version.
//!
//! `mesh.rs` is `src/delaunay/mesh.rs` of the current crate, unchanged. The merge below is the
//! current `divide_conquer::merge` restricted to vertical cuts, with every filtered test
//! replaced by the robust-crate predicate that commit 79d15e6 calls. Everything else follows
//! 79d15e6 (`src/delaunay/divide_conquer.rs`): the distinct points are sorted
//! lexicographically by index (no copy of the coordinates), the sorted run is halved at
//! `lo + n / 2` down to leaves of two or three points, and every coordinate is read through
//! its input index. So against 79d15e6 only the store and the merge code written for it
//! differ; against the current crate, the order (Z order, Dwyer cuts), the predicate filters
//! and the contiguous copy of the coordinates.
//!
//! No input validation (the benchmark's points are finite and inside the envelope).

#![forbid(unsafe_code)]

#[allow(dead_code)]
// The live construction store of the crate, not a copy: the comparison follows it.
#[path = "../../../../src/delaunay/mesh.rs"]
#[allow(rustdoc::broken_intra_doc_links, dead_code)]
mod mesh;

use std::cmp::Ordering;

use mesh::{prev, Mesh, GHOST};

/// Marks a half-edge without a twin (a convex hull edge).
pub const NO_TWIN: u32 = u32::MAX;

/// The same flat result as `wdm_crust::Triangulation` (fields public here).
pub struct Triangulation {
    pub points: Vec<[f64; 2]>,
    pub triangles: Vec<[u32; 3]>,
    pub halfedges: Vec<u32>,
    pub hull: Vec<u32>,
    pub duplicates: Vec<[u32; 2]>,
}

#[inline]
fn coord(p: [f64; 2]) -> robust::Coord<f64> {
    robust::Coord { x: p[0], y: p[1] }
}

/// `c` strictly left of `a → b` (robust::orient2d, as 79d15e6's `orient2d`).
#[inline]
fn ccw(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> bool {
    robust::orient2d(coord(a), coord(b), coord(c)) > 0.0
}

/// `d` strictly inside the circle through the counterclockwise `a, b, c` (robust::incircle).
#[inline]
fn inside(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> bool {
    robust::incircle(coord(a), coord(b), coord(c), coord(d)) > 0.0
}

#[inline]
fn lexicographic(a: [f64; 2], b: [f64; 2]) -> Ordering {
    a[0].partial_cmp(&b[0])
        .unwrap_or(Ordering::Equal)
        .then(a[1].partial_cmp(&b[1]).unwrap_or(Ordering::Equal))
}

/// As 79d15e6: sorted indices of the distinct points, `[duplicate, kept]` pairs.
fn sort_and_merge_duplicates(points: &[[f64; 2]]) -> (Vec<u32>, Vec<[u32; 2]>) {
    let mut order: Vec<u32> = (0..points.len() as u32).collect();
    order.sort_unstable_by(|&i, &j| {
        lexicographic(points[i as usize], points[j as usize]).then(i.cmp(&j))
    });
    let mut duplicates = Vec::new();
    let mut distinct = Vec::with_capacity(order.len());
    for &i in &order {
        match distinct.last() {
            Some(&kept) if lexicographic(points[kept as usize], points[i as usize]).is_eq() => {
                duplicates.push([i, kept]);
            }
            _ => distinct.push(i),
        }
    }
    duplicates.sort_unstable();
    (distinct, duplicates)
}

/// Delaunay triangulation of finite points.
pub fn triangulate(points: &[[f64; 2]]) -> Triangulation {
    let (sorted, duplicates) = sort_and_merge_duplicates(points);
    let n = sorted.len();
    let (mut triangles, mut halfedges, mut hull) = (Vec::new(), Vec::new(), sorted.clone());
    if n >= 2 {
        let mut dc = DivideConquer {
            points,
            sorted: &sorted,
            mesh: Mesh::for_points(n),
        };
        let (min_x, _) = dc.triangulate(0, n);
        let mesh = dc.mesh;
        let collinear = (0..mesh.tri.len() as u32).all(|t| mesh.is_ghost(t));
        if !collinear {
            let g = if mesh.tri[min_x.ghost as usize][1] == min_x.v {
                min_x.ghost
            } else {
                mesh.ring_next(min_x.ghost)
            };
            let done = mesh.finish(g, |v| v, NO_TWIN);
            (triangles, halfedges, hull) = (done.triangles, done.halfedges, done.hull);
        }
    }
    Triangulation {
        points: points.to_vec(),
        triangles,
        halfedges,
        hull,
        duplicates,
    }
}

/// A hull vertex (input index) and a ghost touching it.
#[derive(Debug, Clone, Copy)]
struct Extreme {
    v: u32,
    ghost: u32,
}

#[derive(Clone, Copy)]
enum Side {
    Left,
    Right,
}

struct DivideConquer<'a> {
    points: &'a [[f64; 2]],
    /// Distinct point indices in lexicographic order.
    sorted: &'a [u32],
    mesh: Mesh,
}

impl DivideConquer<'_> {
    #[inline]
    fn p(&self, v: u32) -> [f64; 2] {
        self.points[v as usize]
    }

    /// Triangulates `sorted[lo..hi]` (at least two points) into slots `2lo..2hi − 2`.
    /// Returns the leftmost and the rightmost point, each with a ghost touching it.
    fn triangulate(&mut self, lo: usize, hi: usize) -> (Extreme, Extreme) {
        let n = hi - lo;
        if n <= 3 {
            return self.leaf(lo, n);
        }
        let mid = lo + n / 2;
        let left = self.triangulate(lo, mid);
        let right = self.triangulate(mid, hi);
        self.merge(left, right, mid)
    }

    /// Two or three points (lexicographically sorted).
    fn leaf(&mut self, lo: usize, n: usize) -> (Extreme, Extreme) {
        let s = 2 * lo as u32;
        let v = &self.sorted[lo..lo + n];
        let ghosts;
        if n == 2 {
            self.mesh.pair(s, v[0], v[1]);
            ghosts = [s, s, s];
        } else {
            let (a, b, c) = (self.p(v[0]), self.p(v[1]), self.p(v[2]));
            if ccw(a, b, c) {
                self.mesh.triangle(s, v[0], v[1], v[2]);
                ghosts = [s + 1, s + 1, s + 2];
            } else if ccw(a, c, b) {
                self.mesh.triangle(s, v[0], v[2], v[1]);
                ghosts = [s + 1, s + 3, s + 1];
            } else {
                // Collinear, already in order along the line.
                self.mesh.chain3(s, v[0], v[1], v[2]);
                ghosts = [s, s, s + 1];
            }
        }
        let at = |k: usize| Extreme {
            v: v[k],
            ghost: ghosts[k],
        };
        (at(0), at(n - 1))
    }

    /// See `wdm_crust`'s `settle_candidate`: while the next neighbour behind the side's
    /// ghost lies inside the circle through `l`, `r` and the candidate, flip the edge to the
    /// candidate into the ghost ring.
    #[inline(always)]
    fn settle_candidate(
        &mut self,
        side: Side,
        g: u32,
        (pl, pr): ([f64; 2], [f64; 2]),
        (mut v, mut p): (u32, [f64; 2]),
    ) -> (bool, u32, [f64; 2]) {
        let mut valid = ccw(p, pl, pr);
        if valid {
            let mut flipped = false;
            loop {
                let x = self.mesh.org(prev(self.mesh.twin[3 * g as usize]));
                if x == GHOST {
                    break;
                }
                let px = self.p(x);
                if !inside(pl, pr, p, px) {
                    break;
                }
                v = match side {
                    Side::Left => self.mesh.flip_left(g),
                    Side::Right => self.mesh.flip_right(g),
                };
                p = px;
                flipped = true;
            }
            if flipped {
                valid = ccw(p, pl, pr);
            }
        }
        (valid, v, p)
    }

    /// Merges `sorted[lo..mid]` and `sorted[mid..hi]` (a vertical cut).
    fn merge(
        &mut self,
        (l_min, l_max): (Extreme, Extreme),
        (r_min, r_max): (Extreme, Extreme),
        mid: usize,
    ) -> (Extreme, Extreme) {
        // Hull walk to the lower common tangent: gl = [l, ·] is the ghost of the left hull
        // edge into l, gr = [·, r] that of the right hull edge out of r.
        let mesh = &self.mesh;
        let mut gl = if mesh.tri[l_max.ghost as usize][0] == l_max.v {
            l_max.ghost
        } else {
            mesh.ring_prev(l_max.ghost)
        };
        let mut gr = if mesh.tri[r_min.ghost as usize][1] == r_min.v {
            r_min.ghost
        } else {
            mesh.ring_next(r_min.ghost)
        };
        let (mut l, mut r) = (l_max.v, r_min.v);
        loop {
            let (pl, pr) = (self.p(l), self.p(r));
            if ccw(pl, self.p(self.mesh.tri[gl as usize][1]), pr) {
                gl = self.mesh.ring_prev(gl);
                l = self.mesh.tri[gl as usize][0];
                continue;
            }
            if ccw(pl, self.p(self.mesh.tri[gr as usize][0]), pr) {
                gr = self.mesh.ring_next(gr);
                r = self.mesh.tri[gr as usize][1];
                continue;
            }
            break;
        }
        let opened = 2 * mid as u32 - 2;
        let mut a = self.mesh.ring_next(gl);
        let mut b = self.mesh.ring_prev(gr);
        let mut base = self.mesh.open(opened, l, r, Some(gl), Some(gr));
        let (mut pl, mut pr) = (self.p(l), self.p(r));
        let mut lc = self.mesh.tri[a as usize][0];
        let mut rc = self.mesh.tri[b as usize][1];
        let mut plc = self.p(lc);
        let mut prc = self.p(rc);
        loop {
            let (l_valid, v, p) = self.settle_candidate(Side::Left, a, (pl, pr), (lc, plc));
            (lc, plc) = (v, p);
            let (r_valid, v, p) = self.settle_candidate(Side::Right, b, (pl, pr), (rc, prc));
            (rc, prc) = (v, p);
            if !l_valid && !r_valid {
                break;
            }
            let take_right = !l_valid || (r_valid && inside(pl, pr, plc, prc));
            if take_right {
                let next;
                (base, next) = self.mesh.take_right(b, base, l);
                b = next;
                (r, pr) = (rc, prc);
                rc = self.mesh.tri[next as usize][1];
                prc = self.p(rc);
            } else {
                let next;
                (base, next) = self.mesh.take_left(a, base, r);
                a = next;
                (l, pl) = (lc, plc);
                lc = self.mesh.tri[next as usize][0];
                plc = self.p(lc);
            }
        }
        let closed = opened + 1;
        self.mesh
            .close(closed, (l, r), base, (Some(a), Some(b)), opened);
        // An extreme point whose ghost became a triangle ends a common tangent.
        let mut out = [l_min, r_max];
        for x in &mut out {
            if !self.mesh.ghost_touches(x.ghost, x.v) {
                x.ghost = if self.mesh.ghost_touches(opened, x.v) {
                    opened
                } else {
                    closed
                };
            }
        }
        (out[0], out[1])
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn square_and_line() {
        let t = super::triangulate(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.0]]);
        assert_eq!(t.triangles.len(), 2);
        assert_eq!(t.hull.len(), 4);
        let t = super::triangulate(&[[0.0, 0.0], [1.0, 1.0], [2.0, 2.0], [3.0, 3.0]]);
        assert!(t.triangles.is_empty());
    }
}
