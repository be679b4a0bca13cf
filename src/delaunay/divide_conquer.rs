//! Guibas–Stolfi divide-and-conquer Delaunay construction with Dwyer's alternating cuts, on a
//! triangle store with ghost triangles ([`Mesh`]).
//!
//! The distinct points are put in Z order ([`zorder`](super::zorder)) and copied into one
//! contiguous array, so a subproblem is a contiguous range of points and owns a contiguous
//! range of triangle slots. A range splits at the first key bit its points do not share: by a
//! vertical or a horizontal line, alternately on uniform input (Dwyer's cuts keep the halves
//! roughly square, so a merge deletes few edges). Where a split would leave a single point, the
//! range is sorted lexicographically and split at the middle (vertical cuts only).
//!
//! A merge along a horizontal cut is the textbook merge along a vertical cut seen in a frame
//! turned a quarter clockwise, `(x, y) ↦ (y, −x)`: orientation and in-circle tests do not
//! change under a rotation, so only the extreme points differ. Each subproblem reports its
//! extreme points in both orders, `(x, y)` and `(y, −x)` (ties broken by coordinates, never by
//! input position), with a ghost at each.

use std::cmp::Ordering;

use super::filter::StaticFilter;
use super::mesh::{prev, Mesh, GHOST};
use super::triangulation::{Triangulation, NO_TWIN};
use super::zorder::{lexicographic, order, Grid};
use crate::predicates::{orient2d, Orientation};

/// Triangulates validated points (finite, inside the exact envelope).
pub(super) fn build(points: &[[f64; 2]]) -> Triangulation {
    if points.is_empty() {
        return Triangulation {
            points: Vec::new(),
            triangles: Vec::new(),
            halfedges: Vec::new(),
            hull: Vec::new(),
            duplicates: Vec::new(),
        };
    }
    let grid = Grid::new(points);
    let ordered = order(points, &grid);
    let (mut pts, mut ids) = (ordered.points, ordered.ids);
    let n = pts.len();
    let mut triangles = Vec::new();
    let mut halfedges = Vec::new();
    let hull;
    if n >= 2 {
        let mut dc = DivideConquer {
            pts: &mut pts,
            ids: &mut ids,
            grid,
            mesh: Mesh::for_points(n),
            scratch: Vec::new(),
        };
        let extremes = dc.triangulate(0, n, true);
        let mesh = dc.mesh;
        let start = extremes.min_x;
        let collinear = (0..mesh.tri.len() as u32).all(|t| mesh.is_ghost(t));
        if collinear {
            hull = collinear_chain(&pts, &ids);
        } else {
            let g = if mesh.tri[start.ghost as usize][1] == start.v {
                start.ghost
            } else {
                mesh.ring_next(start.ghost)
            };
            drop(pts);
            let done = mesh.finish(g, &ids, NO_TWIN);
            (triangles, halfedges, hull) = (done.triangles, done.halfedges, done.hull);
        }
    } else {
        hull = std::mem::take(&mut ids);
    }
    Triangulation {
        points: points.to_vec(),
        triangles,
        halfedges,
        hull,
        duplicates: ordered.duplicates,
    }
}

/// The input indices of collinear points in lexicographic order (their order along the line).
fn collinear_chain(pts: &[[f64; 2]], ids: &[u32]) -> Vec<u32> {
    let mut order: Vec<u32> = (0..pts.len() as u32).collect();
    order.sort_unstable_by(|&a, &b| lexicographic(pts[a as usize], pts[b as usize]));
    order.iter().map(|&v| ids[v as usize]).collect()
}

/// `(y, −x)` order: the lexicographic order of the frame turned a quarter clockwise.
#[inline]
fn turned(a: [f64; 2], b: [f64; 2]) -> Ordering {
    lexicographic([a[1], b[0]], [b[1], a[0]])
}

/// Cut direction of a merge.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Cut {
    /// By a vertical line: left half first in `(x, y)` order.
    Vertical,
    /// By a horizontal line: lower half first in `(y, −x)` order.
    Horizontal,
}

/// A hull vertex and a ghost touching it.
#[derive(Debug, Clone, Copy)]
struct Extreme {
    v: u32,
    ghost: u32,
}

/// Extreme points of a subproblem in `(x, y)` and in `(y, −x)` order.
#[derive(Debug, Clone, Copy)]
struct Extremes {
    min_x: Extreme,
    max_x: Extreme,
    min_y: Extreme,
    max_y: Extreme,
}

struct DivideConquer<'a> {
    /// Distinct points; a subproblem may reorder its own range before recursing.
    pts: &'a mut [[f64; 2]],
    /// Input index of every point, reordered with it.
    ids: &'a mut [u32],
    grid: Grid,
    mesh: Mesh,
    scratch: Vec<([f64; 2], u32)>,
}

impl DivideConquer<'_> {
    #[inline]
    fn p(&self, v: u32) -> [f64; 2] {
        self.pts[v as usize]
    }

    #[inline]
    fn less(&self, cut: Cut, a: u32, b: u32) -> bool {
        let (pa, pb) = (self.p(a), self.p(b));
        match cut {
            Cut::Vertical => lexicographic(pa, pb).is_lt(),
            Cut::Horizontal => turned(pa, pb).is_lt(),
        }
    }

    /// Triangulates points `lo..hi` (at least two) into slots `2lo..2hi − 2`. While `zorder`,
    /// the range is in Z order; otherwise it is sorted lexicographically.
    fn triangulate(&mut self, lo: usize, hi: usize, zorder: bool) -> Extremes {
        let n = hi - lo;
        if n <= 3 {
            return self.leaf(lo, n);
        }
        if zorder {
            if let Some((mid, cut)) = self.z_split(lo, hi) {
                let left = self.triangulate(lo, mid, true);
                let right = self.triangulate(mid, hi, true);
                return self.merge(left, right, cut, mid);
            }
            self.sort_lexicographically(lo, hi);
        }
        let mid = lo + n / 2;
        let left = self.triangulate(lo, mid, false);
        let right = self.triangulate(mid, hi, false);
        self.merge(left, right, Cut::Vertical, mid)
    }

    /// Splits a Z-ordered range at the first key bit its points do not share, unless a side
    /// would keep fewer than two points.
    fn z_split(&self, lo: usize, hi: usize) -> Option<(usize, Cut)> {
        let diff = self.grid.key(self.pts[lo]) ^ self.grid.key(self.pts[hi - 1]);
        if diff == 0 {
            return None;
        }
        let bit = 63 - diff.leading_zeros();
        let grid = self.grid;
        let mid = lo + self.pts[lo..hi].partition_point(|&p| !grid.key_bit(p, bit));
        if mid - lo < 2 || hi - mid < 2 {
            return None;
        }
        let cut = if bit % 2 == 1 {
            Cut::Vertical
        } else {
            Cut::Horizontal
        };
        Some((mid, cut))
    }

    /// Sorts a range (not yet triangulated) lexicographically, input indices along.
    fn sort_lexicographically(&mut self, lo: usize, hi: usize) {
        self.scratch.clear();
        self.scratch
            .extend((lo..hi).map(|v| (self.pts[v], self.ids[v])));
        self.scratch.sort_unstable_by(|a, b| lexicographic(a.0, b.0));
        for (k, &(p, id)) in self.scratch.iter().enumerate() {
            self.pts[lo + k] = p;
            self.ids[lo + k] = id;
        }
    }

    /// Two or three points.
    fn leaf(&mut self, lo: usize, n: usize) -> Extremes {
        let s = 2 * lo as u32;
        let mut v = [lo as u32, lo as u32 + 1, lo as u32 + 2];
        // Ghost touching each vertex, by position in `v`.
        let ghosts;
        if n == 2 {
            self.mesh.pair(s, v[0], v[1]);
            ghosts = [s, s, s];
        } else {
            match orient2d(self.p(v[0]), self.p(v[1]), self.p(v[2])) {
                Orientation::CounterClockwise => {
                    self.mesh.triangle(s, v[0], v[1], v[2]);
                    ghosts = [s + 1, s + 1, s + 2];
                }
                Orientation::Clockwise => {
                    self.mesh.triangle(s, v[0], v[2], v[1]);
                    ghosts = [s + 1, s + 3, s + 1];
                }
                Orientation::Collinear => {
                    v[..3].sort_unstable_by(|&a, &b| lexicographic(self.p(a), self.p(b)));
                    self.mesh.chain3(s, v[0], v[1], v[2]);
                    ghosts = [s, s, s + 1];
                }
            }
        }
        let at = |k: usize| Extreme {
            v: v[k],
            ghost: ghosts[k],
        };
        let mut e = Extremes {
            min_x: at(0),
            max_x: at(0),
            min_y: at(0),
            max_y: at(0),
        };
        for k in 1..n {
            let x = at(k);
            if self.less(Cut::Vertical, x.v, e.min_x.v) {
                e.min_x = x;
            }
            if self.less(Cut::Vertical, e.max_x.v, x.v) {
                e.max_x = x;
            }
            if self.less(Cut::Horizontal, x.v, e.min_y.v) {
                e.min_y = x;
            }
            if self.less(Cut::Horizontal, e.max_y.v, x.v) {
                e.max_y = x;
            }
        }
        e
    }

    /// Merges the triangulations of `lo..mid` and `mid..hi`, separated by `cut`.
    fn merge(&mut self, left: Extremes, right: Extremes, cut: Cut, mid: usize) -> Extremes {
        let pick_min = |dc: &Self, c: Cut, x: Extreme, y: Extreme| {
            if dc.less(c, y.v, x.v) {
                y
            } else {
                x
            }
        };
        let pick_max = |dc: &Self, c: Cut, x: Extreme, y: Extreme| {
            if dc.less(c, x.v, y.v) {
                y
            } else {
                x
            }
        };
        let (l_in, r_in, mut e) = match cut {
            Cut::Vertical => (
                left.max_x,
                right.min_x,
                Extremes {
                    min_x: left.min_x,
                    max_x: right.max_x,
                    min_y: pick_min(self, Cut::Horizontal, left.min_y, right.min_y),
                    max_y: pick_max(self, Cut::Horizontal, left.max_y, right.max_y),
                },
            ),
            Cut::Horizontal => (
                left.max_y,
                right.min_y,
                Extremes {
                    min_x: pick_min(self, Cut::Vertical, left.min_x, right.min_x),
                    max_x: pick_max(self, Cut::Vertical, left.max_x, right.max_x),
                    min_y: left.min_y,
                    max_y: right.max_y,
                },
            ),
        };
        // Every point of the merge lies in the bounding box of the extreme points.
        let f = StaticFilter::for_box(
            self.p(e.max_x.v)[0] - self.p(e.min_x.v)[0],
            self.p(e.max_y.v)[1] - self.p(e.min_y.v)[1],
        );

        // Hull walk to the lower common tangent (in the frame of the cut). `gl = [l, l_cw]` is
        // the ghost of the left hull edge into l, `gr = [r_ccw, r]` that of the right hull edge
        // out of r.
        let mesh = &self.mesh;
        let mut gl = if mesh.tri[l_in.ghost as usize][0] == l_in.v {
            l_in.ghost
        } else {
            mesh.ring_prev(l_in.ghost)
        };
        let mut gr = if mesh.tri[r_in.ghost as usize][1] == r_in.v {
            r_in.ghost
        } else {
            mesh.ring_next(r_in.ghost)
        };
        loop {
            let [l, l_cw, _] = self.mesh.tri[gl as usize];
            let [r_ccw, r, _] = self.mesh.tri[gr as usize];
            let (pl, pr) = (self.p(l), self.p(r));
            if f.ccw(pl, self.p(l_cw), pr) {
                gl = self.mesh.ring_prev(gl);
            } else if f.ccw(pl, self.p(r_ccw), pr) {
                gr = self.mesh.ring_next(gr);
            } else {
                break;
            }
        }
        let opened = 2 * mid as u32 - 2;
        // Left ghost a = [lc, l] and right ghost b = [r, rc] bound the region still to fill:
        // lc and rc are the candidates, the first neighbours of l and r above the base l–r.
        let mut a = self.mesh.ring_next(gl);
        let mut b = self.mesh.ring_prev(gr);
        let mut base = self.mesh.open(opened, gl, gr);
        let mut l = self.mesh.tri[gl as usize][0];
        let mut r = self.mesh.tri[gr as usize][1];
        let (mut pl, mut pr) = (self.p(l), self.p(r));
        let mut lc = self.mesh.tri[a as usize][0];
        let mut rc = self.mesh.tri[b as usize][1];
        let (mut plc, mut prc) = (self.p(lc), self.p(rc));
        loop {
            // The edge l–lc is deleted (flipped into the ghost ring) while the next neighbour
            // x of l lies inside the circle through l, r, lc.
            let mut l_valid = f.ccw(plc, pl, pr);
            if l_valid {
                let mut flipped = false;
                loop {
                    let x = self.mesh.org(prev(self.mesh.twin[3 * a as usize]));
                    if x == GHOST {
                        break;
                    }
                    let px = self.p(x);
                    if !f.inside(pl, pr, plc, px) {
                        break;
                    }
                    lc = self.mesh.flip_left(a);
                    plc = px;
                    flipped = true;
                }
                if flipped {
                    l_valid = f.ccw(plc, pl, pr);
                }
            }
            let mut r_valid = f.ccw(prc, pl, pr);
            if r_valid {
                let mut flipped = false;
                loop {
                    let z = self.mesh.org(prev(self.mesh.twin[3 * b as usize]));
                    if z == GHOST {
                        break;
                    }
                    let pz = self.p(z);
                    if !f.inside(pl, pr, prc, pz) {
                        break;
                    }
                    rc = self.mesh.flip_right(b);
                    prc = pz;
                    flipped = true;
                }
                if flipped {
                    r_valid = f.ccw(prc, pl, pr);
                }
            }
            if !l_valid && !r_valid {
                break;
            }
            if !l_valid || (r_valid && f.inside(plc, pl, pr, prc)) {
                (base, b) = self.mesh.take_right(b, base, l);
                (r, pr) = (rc, prc);
                rc = self.mesh.tri[b as usize][1];
                prc = self.p(rc);
            } else {
                (base, a) = self.mesh.take_left(a, base, r);
                (l, pl) = (lc, plc);
                lc = self.mesh.tri[a as usize][0];
                plc = self.p(lc);
            }
        }
        let closed = opened + 1;
        self.mesh.close(closed, base, a, b);

        // A ghost of an extreme point may have been turned into a triangle; the point is
        // then an end of a common tangent, whose new ghost touches it.
        for x in [&mut e.min_x, &mut e.max_x, &mut e.min_y, &mut e.max_y] {
            if !self.mesh.ghost_touches(x.ghost, x.v) {
                x.ghost = if self.mesh.ghost_touches(opened, x.v) {
                    opened
                } else {
                    closed
                };
            }
        }
        e
    }
}
