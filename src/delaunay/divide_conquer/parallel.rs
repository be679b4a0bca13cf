//! The parallel top of the divide and conquer (feature `parallel`).
//!
//! Every range of points owns a fixed range of triangle slots (see the `mesh` module docs),
//! so the two halves of a split write disjoint slices of the points, Z-order items,
//! triangles and twins: [`rayon::join`] builds them at the same time on `split_at_mut`
//! pieces, and the merge then runs on the whole range. The recursion is the sequential one:
//! every split, re-keying and merge is decided by the points alone, and a subproblem writes
//! the same values into the same slots whichever thread runs it, so the arrays are
//! bit-identical for every number of threads (only the order in which slots get written
//! changes).
//!
//! Ranges of at least [`CUTOFF`] points form the parallel top: they address the store with
//! global ids through slices that start at their first point (`SHIFTED`, one subtraction per
//! access). A smaller half is built on its own with local ids from 0 — the sequential code,
//! with no subtraction in its hot loops — and relocated to global ids after, one pass over
//! its slots while they are still in cache. One thread, or fewer than [`CUTOFF`] points,
//! runs the sequential construction on the whole input: the same arrays, without the
//! relocations.

use super::{DivideConquer, Extremes, NO_GHOST};

/// Ranges of at least this many points triangulate their two halves in parallel; smaller
/// ones are built sequentially by the thread that gets them.
///
/// Chosen by measurement (2-core machine, 10^6 uniform and curve points, see
/// ARCHITECTURE.md): from 2^12 to 2^16 the 2-thread time varies by a few percent; below,
/// the parallel top's offset arithmetic and the relocations grow, above, the last levels
/// leave one core idle for longer.
pub(super) const CUTOFF: usize = 1 << 14;

/// Does the construction of `n` points go parallel? Only with more than one thread in the
/// current pool (rayon's global one unless called inside [`rayon::ThreadPool::install`]),
/// and only if the recursion splits at least once at the parallel top.
pub(super) fn pays(n: usize) -> bool {
    n >= CUTOFF && rayon::current_num_threads() > 1
}

impl Extremes {
    /// The extremes of a subproblem built with local ids, in the ids of the whole store:
    /// points move by `first`, slots by `2 first`.
    fn shifted(mut self, first: usize) -> Extremes {
        for x in [
            &mut self.min_x,
            &mut self.max_x,
            &mut self.min_y,
            &mut self.max_y,
        ] {
            x.v += first as u32;
            if x.ghost != NO_GHOST {
                x.ghost += 2 * first as u32;
            }
        }
        self
    }
}

impl<const IN_RANGE: bool, const SHIFTED: bool> DivideConquer<'_, IN_RANGE, SHIFTED> {
    /// Triangulates `lo..mid` and `mid..hi` (this whole range) at the same time.
    pub(super) fn triangulate_halves_in_parallel(
        &mut self,
        (lo, mid, hi): (usize, usize, usize),
        zorder: bool,
    ) -> (Extremes, Extremes) {
        let [mut left, mut right] = self.halves(mid);
        rayon::join(
            || left.triangulate_part(lo, mid, zorder),
            || right.triangulate_part(mid, hi, zorder),
        )
    }

    /// The constructions of the halves `first..mid` and `mid..` of this range, on disjoint
    /// parts of the points and slots (the two merge slots stay with `self`).
    fn halves(&mut self, mid: usize) -> [DivideConquer<'_, IN_RANGE, true>; 2] {
        let at = self.at(mid);
        let (left_pts, right_pts) = self.pts.split_at_mut(at);
        let (left_items, right_items) = self.items.split_at_mut(at);
        let [left_mesh, right_mesh] = self.mesh.split_at_point(mid as u32);
        [
            DivideConquer {
                pts: left_pts,
                items: left_items,
                first: self.first,
                grid: self.grid,
                mesh: left_mesh,
                scratch: Vec::new(),
            },
            DivideConquer {
                pts: right_pts,
                items: right_items,
                first: mid,
                grid: self.grid,
                mesh: right_mesh,
                scratch: Vec::new(),
            },
        ]
    }
}

impl<const IN_RANGE: bool> DivideConquer<'_, IN_RANGE, true> {
    /// Triangulates this whole part, points `lo..hi`: at the parallel top if it is large,
    /// else with local ids on this thread, relocated after.
    fn triangulate_part(&mut self, lo: usize, hi: usize, zorder: bool) -> Extremes {
        debug_assert_eq!((lo, hi - lo), (self.first, self.pts.len()));
        if hi - lo >= CUTOFF {
            return self.triangulate(lo, hi, zorder);
        }
        if hi - lo == 1 {
            return Extremes::point(lo as u32);
        }
        let local = DivideConquer::<IN_RANGE, false> {
            pts: self.pts,
            items: self.items,
            first: 0,
            grid: self.grid,
            mesh: self.mesh.detached(),
            scratch: std::mem::take(&mut self.scratch),
        }
        .triangulate(0, hi - lo, zorder);
        self.mesh.relocate();
        local.shifted(lo)
    }
}
