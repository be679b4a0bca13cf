//! Guibas–Stolfi divide-and-conquer Delaunay construction with Dwyer's alternating cuts, on a
//! triangle store with ghost triangles ([`Mesh`]).
//!
//! The distinct points are put in Z order ([`zorder`](super::zorder)) and copied into one
//! contiguous array, so a subproblem is a contiguous range of points and owns a contiguous
//! range of triangle slots. A range splits at the first key bit its points do not share: by a
//! vertical or a horizontal line, alternately on uniform input (Dwyer's cuts keep the halves
//! roughly square, so a merge deletes few edges: on 10^6 uniform points one edge per point,
//! against eight with vertical cuts only). A side of a split may be a single point; it is
//! merged without a triangulation of its own. A range whose points all share one key (a
//! cluster finer than the grid) is re-keyed on its own bounding box; below 17 points it is
//! sorted lexicographically instead and split at the middle, by vertical cuts.
//!
//! A merge along a horizontal cut is the textbook merge along a vertical cut seen in a frame
//! turned a quarter clockwise, `(x, y) ↦ (y, −x)`: orientation and in-circle tests do not
//! change under a rotation, so only the extreme points differ. Each subproblem reports its
//! extreme points in both orders, `(x, y)` and `(y, −x)`, with a ghost at each.
//!
//! Every decision is an exact predicate (filtered, `crate::kernel::basic`), and every tie
//! is broken by coordinates, never by input position: a permutation of the input gives the
//! same triangles. The hull starts at the lexicographically smallest point.
//!
//! With the `parallel` feature the two halves of every split of a large range are built at
//! the same time (the `parallel` submodule), on disjoint slices of the points and slots; the
//! recursion and every decision stay the ones above, so the arrays are the same on any number
//! of threads.

use super::mesh::{prev, Mesh, MeshPart, GHOST};
use super::triangulation::{Triangulation, NO_TWIN};
use super::zorder::{input_indices, lexicographic, order, Grid};
use crate::ids::{HalfEdge, LocalPoint};
use crate::kernel::basic::orient_in;
use crate::kernel::scale::shift_by;
use crate::kernel::static_filter::{Lifted, StaticFilter};
use crate::kernel::Sign;
use crate::predicates::Orientation;

#[cfg(feature = "parallel")]
mod parallel;

/// Triangulates validated (finite) points. The result keeps the points in the order the
/// construction leaves them in (Z order, see the module docs).
///
/// `shift` is the power of two that brings every non-zero coordinate into the adaptive
/// predicates' range (`kernel::scale::Magnitudes::adaptive_shift`): where it is not zero
/// the construction runs on the points times `2^shift`, exactly and so with the same
/// decisions, at the speed of ordinary input, and the result gets the caller's coordinates
/// back. Where it is `None` (exponents spread wider than that range) it runs on the points
/// as given, its predicates taking their wide-exponent exact stage where needed.
pub(super) fn build(points: &[[f64; 2]], shift: Option<i32>) -> Triangulation {
    match shift {
        Some(s) if s != 0 => {
            let scaled: Vec<[f64; 2]> = points.iter().map(|p| p.map(|x| shift_by(x, s))).collect();
            let mut tri = build_as_given::<true>(&scaled);
            drop(scaled);
            for (p, &input) in tri.points.iter_mut().zip(&tri.input_of) {
                *p = points[input as usize];
            }
            tri
        }
        Some(_) => build_as_given::<true>(points),
        None => build_as_given::<false>(points),
    }
}

/// [`build`] on the points as they are; `IN_RANGE` tells whether every coordinate is zero
/// or in the adaptive predicates' range, so that the exact stages of the construction's
/// predicates skip their range check and underflow terms (a monomorphised construction: no
/// test of the mode in the inner loop).
fn build_as_given<const IN_RANGE: bool>(points: &[[f64; 2]]) -> Triangulation {
    if points.is_empty() {
        return Triangulation {
            points: Vec::new(),
            triangles: Vec::new(),
            halfedges: Vec::new(),
            hull: Vec::new(),
            input_of: Vec::new(),
            local_of: Vec::new(),
            duplicates: Vec::new(),
        };
    }
    let grid = Grid::new(points);
    let ordered = order(points, &grid);
    let (mut pts, mut items) = (ordered.points, ordered.items);
    let n = pts.len();
    let mut triangles = Vec::new();
    let mut halfedges = Vec::new();
    let hull;
    if n >= 2 {
        let mut mesh = Mesh::for_points(n);
        let start = construct::<IN_RANGE>(&mut pts, &mut items, grid, &mut mesh).min_x;
        let collinear = mesh.tri.iter().all(|t| t[2] == GHOST);
        if collinear {
            hull = collinear_chain(&pts);
        } else {
            let ring = mesh.whole::<false>();
            let g = if ring.corners(start.ghost)[1] == start.v {
                start.ghost
            } else {
                ring.ring_next(start.ghost)
            };
            let done = mesh.finish(g, NO_TWIN.get());
            // In place (each id is a `u32`): the store becomes the result.
            triangles = (done.triangles.into_iter())
                .map(|t| t.map(LocalPoint::new))
                .collect();
            halfedges = done.halfedges.into_iter().map(HalfEdge::new).collect();
            hull = done.hull.into_iter().map(LocalPoint::new).collect();
        }
    } else {
        hull = vec![LocalPoint::new(0)];
    }
    // The construction reorders points inside ranges (re-keyed clusters): the final order
    // is the one the items are in now.
    let input_of = input_indices(&items, &grid);
    drop(items);
    let mut local_of = vec![LocalPoint::new(0); points.len()];
    for (local, &input) in input_of.iter().enumerate() {
        local_of[input as usize] = LocalPoint::new(local as u32);
    }
    for &[duplicate, kept] in &ordered.duplicates {
        local_of[duplicate as usize] = local_of[kept as usize];
    }
    pts.shrink_to_fit();
    Triangulation {
        points: pts,
        triangles,
        halfedges,
        hull,
        input_of,
        local_of,
        duplicates: ordered.duplicates,
    }
}

/// The divide and conquer over all `pts` (at least two) into the empty `mesh`: on several
/// threads where that pays (see `divide_conquer/parallel.rs`), else on this one. Both give
/// the same arrays.
fn construct<const IN_RANGE: bool>(
    pts: &mut [[f64; 2]],
    items: &mut [u64],
    grid: Grid,
    mesh: &mut Mesh,
) -> Extremes {
    let n = pts.len();
    #[cfg(feature = "parallel")]
    if parallel::pays(n) {
        return DivideConquer::<IN_RANGE, true>::new(pts, items, grid, mesh.whole())
            .triangulate(0, n, true);
    }
    DivideConquer::<IN_RANGE, false>::new(pts, items, grid, mesh.whole()).triangulate(0, n, true)
}

/// Collinear points in lexicographic order (their order along the line).
fn collinear_chain(pts: &[[f64; 2]]) -> Vec<LocalPoint> {
    let mut order: Vec<LocalPoint> = crate::ids::ids(pts.len()).collect();
    order.sort_unstable_by(|&a, &b| lexicographic(pts[a.index()], pts[b.index()]));
    order
}

/// Cut direction of a merge.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Cut {
    /// By a vertical line: left half first in `(x, y)` order.
    Vertical,
    /// By a horizontal line: lower half first in `(y, −x)` order.
    Horizontal,
}

/// A hull vertex and a ghost touching it ([`NO_GHOST`] for a single point).
#[derive(Debug, Clone, Copy)]
struct Extreme {
    v: u32,
    ghost: u32,
}

/// The ghost of a subproblem that is a single point: there is none.
const NO_GHOST: u32 = u32::MAX;

/// Extreme points of a subproblem in `(x, y)` and in `(y, −x)` order.
#[derive(Debug, Clone, Copy)]
struct Extremes {
    min_x: Extreme,
    max_x: Extreme,
    min_y: Extreme,
    max_y: Extreme,
}

impl Extremes {
    /// A single point, merged into its sibling without a triangulation of its own.
    fn point(v: u32) -> Extremes {
        let e = Extreme { v, ghost: NO_GHOST };
        Extremes {
            min_x: e,
            max_x: e,
            min_y: e,
            max_y: e,
        }
    }
}

/// A side of a merge.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Side {
    Left,
    Right,
}

/// One side's candidate for the next triangle above the merge base `l–r`.
struct Candidate {
    /// The candidate lies strictly above the base (`r × candidate > 0` seen from `l`).
    valid: bool,
    v: u32,
    p: [f64; 2],
    /// The candidate relative to `l`, and `r × candidate`.
    rel: Lifted,
    cross: f64,
}

/// The construction of one range of points (all of them at the top) and the slots it
/// owns. With `SHIFTED` (the parallel top of the recursion, `divide_conquer/parallel.rs`)
/// point and slot ids are global and the slices start at point `first` and its slots;
/// without it the range starts at 0 (the whole input, or a subproblem built with local ids
/// and relocated after).
struct DivideConquer<'a, const IN_RANGE: bool, const SHIFTED: bool> {
    /// Distinct points from `first` on; a subproblem may reorder its own range before
    /// recursing.
    pts: &'a mut [[f64; 2]],
    /// Z-order item (key and input index) of every point, reordered with it.
    items: &'a mut [u64],
    /// Global index of `pts[0]` (zero unless `SHIFTED`).
    first: usize,
    grid: Grid,
    mesh: MeshPart<'a, SHIFTED>,
    scratch: Vec<([f64; 2], u64)>,
}

impl<'a, const IN_RANGE: bool, const SHIFTED: bool> DivideConquer<'a, IN_RANGE, SHIFTED> {
    /// The construction of all of `pts` (ids from 0) into `mesh`.
    fn new(
        pts: &'a mut [[f64; 2]],
        items: &'a mut [u64],
        grid: Grid,
        mesh: MeshPart<'a, SHIFTED>,
    ) -> Self {
        DivideConquer {
            pts,
            items,
            first: 0,
            grid,
            mesh,
            scratch: Vec::new(),
        }
    }

    /// Index into `pts` and `items` of point `v`.
    #[inline(always)]
    fn at(&self, v: usize) -> usize {
        if SHIFTED {
            v - self.first
        } else {
            v
        }
    }

    #[inline]
    fn p(&self, v: u32) -> [f64; 2] {
        self.pts[self.at(v as usize)]
    }

    /// Positions in `pts` and `items` of the points `lo..hi`.
    #[inline]
    fn local(&self, lo: usize, hi: usize) -> std::ops::Range<usize> {
        self.at(lo)..self.at(hi)
    }

    /// Settles the candidate of one side of the merge step at base `l–r` (`base` holds
    /// `l`, `r` and `r` relative to `l`): while the next neighbour `x` behind the side's
    /// ghost lies inside the circle through `l`, `r` and the candidate, the edge to the
    /// candidate is flipped into the ghost ring and `x` becomes the candidate. Every test is
    /// evaluated relative to `l`; the orientation `r × candidate` doubles as a minor of the
    /// in-circle test. A side without a ghost (a single point) has no valid candidate.
    #[inline(always)]
    fn settle_candidate(
        &mut self,
        f: &StaticFilter<IN_RANGE>,
        side: Side,
        ghost: Option<u32>,
        (pl, pr, rel_r): ([f64; 2], [f64; 2], &Lifted),
        (mut v, mut p): (u32, [f64; 2]),
    ) -> Candidate {
        let mut rel = Lifted::new(p, pl);
        let mut cross = rel_r.cross(&rel);
        let mut valid = false;
        if let Some(g) = ghost {
            valid = f
                .orientation(cross)
                .unwrap_or_else(|| f.orient_fallback(p, pl, pr))
                == Sign::Positive;
            if valid {
                let mut flipped = false;
                loop {
                    let x = self.mesh.org(prev(self.mesh.twin(3 * g)));
                    if x == GHOST {
                        break;
                    }
                    let px = self.p(x);
                    let rel_x = Lifted::new(px, pl);
                    let delete = f
                        .in_circle(rel_r, &rel, &rel_x, cross)
                        .unwrap_or_else(|| f.incircle_fallback(pl, pr, p, px))
                        == Sign::Positive;
                    if !delete {
                        break;
                    }
                    v = match side {
                        Side::Left => self.mesh.flip_left(g),
                        Side::Right => self.mesh.flip_right(g),
                    };
                    (p, rel) = (px, rel_x);
                    cross = rel_r.cross(&rel);
                    flipped = true;
                }
                if flipped {
                    valid = f
                        .orientation(cross)
                        .unwrap_or_else(|| f.orient_fallback(p, pl, pr))
                        == Sign::Positive;
                }
            }
        }
        Candidate {
            valid,
            v,
            p,
            rel,
            cross,
        }
    }

    #[inline]
    fn less(&self, cut: Cut, a: u32, b: u32) -> bool {
        let (pa, pb) = (self.p(a), self.p(b));
        match cut {
            // (x, y) order.
            Cut::Vertical => pa[0] < pb[0] || (pa[0] == pb[0] && pa[1] < pb[1]),
            // (y, −x) order: the (x, y) order of the frame turned a quarter clockwise.
            Cut::Horizontal => pa[1] < pb[1] || (pa[1] == pb[1] && pa[0] > pb[0]),
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
                let (left, right) = self.triangulate_halves((lo, mid, hi), true);
                return self.merge(left, right, cut, mid);
            }
            // All keys equal: a cluster finer than the grid. Quantize it on its own box and
            // go on in Z order, unless it is small.
            if n > 16 && self.rekey(lo, hi) {
                return self.triangulate(lo, hi, true);
            }
            self.sort_lexicographically(lo, hi);
        }
        let mid = lo + n / 2;
        let (left, right) = self.triangulate_halves((lo, mid, hi), false);
        self.merge(left, right, Cut::Vertical, mid)
    }

    /// Triangulates `lo..mid` and `mid..hi`; at the parallel top of the recursion
    /// (`SHIFTED`), at the same time.
    fn triangulate_halves(
        &mut self,
        (lo, mid, hi): (usize, usize, usize),
        zorder: bool,
    ) -> (Extremes, Extremes) {
        #[cfg(feature = "parallel")]
        if SHIFTED {
            return self.triangulate_halves_in_parallel((lo, mid, hi), zorder);
        }
        (
            self.triangulate_side(lo, mid, zorder),
            self.triangulate_side(mid, hi, zorder),
        )
    }

    /// Triangulates one side of a split, which may be a single point: that gets no
    /// triangulation of its own (never both sides: a split range has at least four points).
    fn triangulate_side(&mut self, lo: usize, hi: usize, zorder: bool) -> Extremes {
        match hi - lo {
            1 => Extremes::point(lo as u32),
            _ => self.triangulate(lo, hi, zorder),
        }
    }

    /// Splits a Z-ordered range at the first key bit its points do not share, if any.
    fn z_split(&self, lo: usize, hi: usize) -> Option<(usize, Cut)> {
        let items = &self.items[self.local(lo, hi)];
        let low = self.grid.index_bits();
        let diff = (items[0] ^ items[items.len() - 1]) >> low;
        if diff == 0 {
            return None;
        }
        let bit = 63 - diff.leading_zeros() + low;
        let mid = lo + items.partition_point(|&item| (item >> bit) & 1 == 0);
        // Odd key bits come from x cells, even ones from y cells.
        let cut = if bit % 2 == 1 {
            Cut::Vertical
        } else {
            Cut::Horizontal
        };
        Some((mid, cut))
    }

    /// Re-sorts a range (not yet triangulated) of equal keys along the Z curve of its own
    /// bounding box, points of one new key lexicographically (not by input index: a leaf of
    /// two or three points keeps its order, which then is the local order); the items get
    /// the new keys. True when the range now splits, which the distinct points guarantee
    /// (extremes in cells 0 and 2^32 − 1 on an axis with extent).
    fn rekey(&mut self, lo: usize, hi: usize) -> bool {
        let range = self.local(lo, hi);
        let (pts, items) = (&mut self.pts[range.clone()], &mut self.items[range]);
        let bits = self.grid.index_bits();
        let local = Grid::of_box(pts.iter().copied(), bits);
        let index_mask = (1u64 << bits) - 1;
        self.scratch.clear();
        self.scratch.extend(
            pts.iter()
                .zip(items.iter())
                .map(|(&p, &item)| (p, local.key(p) | (item & index_mask))),
        );
        self.scratch.sort_unstable_by(|a, b| {
            (a.1 >> bits)
                .cmp(&(b.1 >> bits))
                .then_with(|| lexicographic(a.0, b.0))
        });
        for (k, &(p, item)) in self.scratch.iter().enumerate() {
            pts[k] = p;
            items[k] = item;
        }
        (items[0] ^ items[items.len() - 1]) >> bits != 0
    }

    /// Sorts a range (not yet triangulated) lexicographically, input indices along.
    fn sort_lexicographically(&mut self, lo: usize, hi: usize) {
        let range = self.local(lo, hi);
        let (pts, items) = (&mut self.pts[range.clone()], &mut self.items[range]);
        if pts.len() <= 16 {
            // Small ranges (every fallback of Z order is one) in place.
            for k in 1..pts.len() {
                let mut j = k;
                while j > 0 && lexicographic(pts[j], pts[j - 1]).is_lt() {
                    pts.swap(j, j - 1);
                    items.swap(j, j - 1);
                    j -= 1;
                }
            }
            return;
        }
        self.scratch.clear();
        self.scratch
            .extend(pts.iter().copied().zip(items.iter().copied()));
        self.scratch
            .sort_unstable_by(|a, b| lexicographic(a.0, b.0));
        for (k, &(p, item)) in self.scratch.iter().enumerate() {
            pts[k] = p;
            items[k] = item;
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
            match Orientation::from(orient_in::<IN_RANGE>(
                self.p(v[0]),
                self.p(v[1]),
                self.p(v[2]),
            )) {
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
        let f = StaticFilter::<IN_RANGE>::for_box(
            self.p(e.max_x.v)[0] - self.p(e.min_x.v)[0],
            self.p(e.max_y.v)[1] - self.p(e.min_y.v)[1],
        );

        // Hull walk to the lower common tangent (in the frame of the cut). `gl = [l, l_cw]` is
        // the ghost of the left hull edge into l, `gr = [r_ccw, r]` that of the right hull edge
        // out of r; `None` for a side that is a single point.
        let mesh = &self.mesh;
        let mut gl = (l_in.ghost != NO_GHOST).then(|| {
            if mesh.corners(l_in.ghost)[0] == l_in.v {
                l_in.ghost
            } else {
                mesh.ring_prev(l_in.ghost)
            }
        });
        let mut gr = (r_in.ghost != NO_GHOST).then(|| {
            if mesh.corners(r_in.ghost)[1] == r_in.v {
                r_in.ghost
            } else {
                mesh.ring_next(r_in.ghost)
            }
        });
        let (mut l, mut r) = (l_in.v, r_in.v);
        loop {
            let (pl, pr) = (self.p(l), self.p(r));
            if let Some(g) = gl {
                if f.orient(pl, self.p(self.mesh.corners(g)[1]), pr) == Sign::Positive {
                    let g = self.mesh.ring_prev(g);
                    (gl, l) = (Some(g), self.mesh.corners(g)[0]);
                    continue;
                }
            }
            if let Some(g) = gr {
                if f.orient(pl, self.p(self.mesh.corners(g)[0]), pr) == Sign::Positive {
                    let g = self.mesh.ring_next(g);
                    (gr, r) = (Some(g), self.mesh.corners(g)[1]);
                    continue;
                }
            }
            break;
        }
        let opened = 2 * mid as u32 - 2;
        // Left ghost a = [lc, l] and right ghost b = [r, rc] bound the region still to fill:
        // lc and rc are the candidates, the first neighbours of l and r above the base l–r.
        // A side that is a single point has no candidates.
        let mut a = gl.map(|g| self.mesh.ring_next(g));
        let mut b = gr.map(|g| self.mesh.ring_prev(g));
        let mut base = self.mesh.open(opened, l, r, gl, gr);
        let (mut pl, mut pr) = (self.p(l), self.p(r));
        let mut lc = a.map_or(GHOST, |a| self.mesh.corners(a)[0]);
        let mut rc = b.map_or(GHOST, |b| self.mesh.corners(b)[1]);
        let mut plc = a.map_or(pl, |_| self.p(lc));
        let mut prc = b.map_or(pr, |_| self.p(rc));
        // Every test of a step is evaluated relative to l: r, lc, rc and the next neighbours
        // as lifted differences, the validity orientations r × lc, r × rc reused as minors.
        loop {
            let rel_r = Lifted::new(pr, pl);
            let left = self.settle_candidate(&f, Side::Left, a, (pl, pr, &rel_r), (lc, plc));
            let right = self.settle_candidate(&f, Side::Right, b, (pl, pr, &rel_r), (rc, prc));
            let (l_valid, rel_lc, cross_l) = (left.valid, left.rel, left.cross);
            let (r_valid, rel_rc) = (right.valid, right.rel);
            (lc, plc, rc, prc) = (left.v, left.p, right.v, right.p);
            if !l_valid && !r_valid {
                break;
            }
            // Both valid: the right candidate wins if it lies inside the circle through l, r
            // and the left one.
            let take_right = !l_valid
                || (r_valid
                    && f.in_circle(&rel_r, &rel_lc, &rel_rc, cross_l)
                        .unwrap_or_else(|| f.incircle_fallback(pl, pr, plc, prc))
                        == Sign::Positive);
            if let (true, Some(b_ghost)) = (take_right, b) {
                let next;
                (base, next) = self.mesh.take_right(b_ghost, base, l);
                b = Some(next);
                (r, pr) = (rc, prc);
                rc = self.mesh.corners(next)[1];
                prc = self.p(rc);
            } else if let Some(a_ghost) = a {
                let next;
                (base, next) = self.mesh.take_left(a_ghost, base, r);
                a = Some(next);
                (l, pl) = (lc, plc);
                lc = self.mesh.corners(next)[0];
                plc = self.p(lc);
            }
        }
        let closed = opened + 1;
        self.mesh.close(closed, (l, r), base, (a, b), opened);

        // A ghost of an extreme point may have been turned into a triangle; the point is
        // then an end of a common tangent, whose new ghost touches it.
        for x in [&mut e.min_x, &mut e.max_x, &mut e.min_y, &mut e.max_y] {
            if x.ghost == NO_GHOST || !self.mesh.ghost_touches(x.ghost, x.v) {
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

#[cfg(test)]
mod tests {
    use super::*;

    /// SplitMix64 in [0, 1).
    fn rng(seed: u64) -> impl FnMut() -> f64 {
        let mut s = seed;
        move || {
            s = s.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = s;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
        }
    }

    /// Triangles by coordinates, each rotated to start at its smallest corner, sorted.
    fn by_coordinates(tri: &Triangulation) -> Vec<[[u64; 2]; 3]> {
        let key = |v: LocalPoint| tri.position(v).map(f64::to_bits);
        let mut all: Vec<[[u64; 2]; 3]> = tri
            .triangles
            .iter()
            .map(|t| {
                let k = t.map(key);
                let m = (0..3).min_by_key(|&i| k[i]).unwrap_or(0);
                [k[m], k[(m + 1) % 3], k[(m + 2) % 3]]
            })
            .collect();
        all.sort_unstable();
        all
    }

    /// Valid, and the same arrays for a reversed and a shuffled input: the same points in
    /// the same local order (what every later stage's order follows), the same triangles.
    fn check(points: &[[f64; 2]]) -> Triangulation {
        let tri = build(points, Some(0));
        if let Err(e) = tri.validate() {
            panic!("{e}");
        }
        let mut next = rng(points.len() as u64);
        let mut shuffled = points.to_vec();
        for i in (1..shuffled.len()).rev() {
            shuffled.swap(i, (next() * (i + 1) as f64) as usize);
        }
        let reversed: Vec<[f64; 2]> = points.iter().rev().copied().collect();
        for other in [shuffled, reversed] {
            let t = build(&other, Some(0));
            assert_eq!(by_coordinates(&t), by_coordinates(&tri));
            assert_eq!(t.points, tri.points, "the same local order");
            assert_eq!(t.triangles, tri.triangles);
            assert_eq!(t.halfedges, tri.halfedges);
            let hull = |t: &Triangulation| -> Vec<[f64; 2]> {
                t.hull.iter().map(|&v| t.position(v)).collect()
            };
            assert_eq!(hull(&t), hull(&tri), "same hull from the same first point");
        }
        tri
    }

    #[test]
    fn outliers_merge_as_single_points() {
        let mut next = rng(1);
        for outliers in [1, 2, 3, 7] {
            let mut pts: Vec<[f64; 2]> = (0..500).map(|_| [next() * 1e-3, next() * 1e-3]).collect();
            for k in 0..outliers {
                let angle = k as f64 * 2.1;
                pts.push([1e3 * angle.cos(), 1e3 * angle.sin()]);
            }
            let tri = check(&pts);
            assert_eq!(tri.distinct_point_count(), pts.len());
        }
    }

    #[test]
    fn a_cluster_finer_than_the_grid_is_requantized() {
        // 2000 points in a box of 2^-30 next to 1 at distance 1: every cluster point has the
        // same key on the global grid.
        let mut next = rng(2);
        let mut pts: Vec<[f64; 2]> = (0..2000)
            .map(|_| {
                [
                    0.5 + next() * 2f64.powi(-30),
                    0.25 + next() * 2f64.powi(-30),
                ]
            })
            .collect();
        pts.push([1.5, -0.75]);
        pts.push([-3.0, 2.0]);
        check(&pts);
    }

    /// Pairs of points 1 ulp apart in a cluster far finer than the grid (one far point
    /// beside it): the re-keyed cluster's keys cannot tell a pair apart, and the pair's
    /// order, hence the local order, is the coordinates', not the input's.
    #[test]
    fn points_sharing_a_requantized_key_keep_their_order() {
        let mut next = rng(5);
        let mut pts: Vec<[f64; 2]> = Vec::new();
        for k in 0..60 {
            let t = k as f64 / 60.0 * std::f64::consts::TAU;
            let p = [4e-41 * t.cos() * (1.0 + 0.1 * next()), 4e-41 * t.sin()];
            pts.push(p);
            if k % 3 == 0 {
                pts.push(p.map(|x| f64::from_bits(x.to_bits() + 1)));
            }
        }
        pts.push([2.5e260, 1.0]);
        check(&pts);
    }

    #[test]
    fn long_runs_of_duplicates_map_to_the_first_occurrence() {
        let mut next = rng(3);
        let distinct: Vec<[f64; 2]> = (0..10).map(|_| [next(), next()]).collect();
        let pts: Vec<[f64; 2]> = (0..1000).map(|i| distinct[(i * 7) % 10]).collect();
        let tri = check(&pts);
        assert_eq!(tri.duplicates.len(), 990);
        for &[dup, kept] in &tri.duplicates {
            assert_eq!(pts[dup as usize], pts[kept as usize]);
            assert!(kept < 10, "the first occurrence is kept");
        }
    }

    #[test]
    fn alternating_cuts_on_curves_and_lattices() {
        let mut next = rng(4);
        let circle: Vec<[f64; 2]> = (0..3000)
            .map(|_| {
                let t = next() * std::f64::consts::TAU;
                [t.cos(), t.sin()]
            })
            .collect();
        check(&circle);
        let lattice: Vec<[f64; 2]> = (0..2500)
            .map(|i| [(i % 50) as f64, (i / 50) as f64])
            .collect();
        check(&lattice);
    }
}
