//! Opt-in statistics: how often a predicate left its fast filter.
//!
//! Without the `predicate-stats` feature every hook here is an empty inline function, so the
//! predicates carry no counting cost at all. With it, the counts are thread-local (no shared
//! cache line on the hot path, and a thread's counts are not disturbed by other threads).

/// Which stage decided a call.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub(super) enum Stage {
    /// The semi-static filter, possibly after rescaling.
    Filter,
    /// The running-error filter.
    Bounded,
    /// Double-word arithmetic with a running error bound.
    DoubleWord,
    /// Exact arithmetic.
    Exact,
}

/// The counted predicates.
#[derive(Debug, Clone, Copy)]
pub(super) enum Which {
    Orient,
    Dot,
    Radius,
    Hull,
    Circumcenter,
}

/// How often one predicate was called and how often its fast filter could not decide.
#[cfg(feature = "predicate-stats")]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct PredicateCounts {
    /// Number of calls.
    pub calls: u64,
    /// Number of calls the fast (semi-static) filter could not decide on the input as given:
    /// they were rescaled, or went on to the running-error filter.
    pub slow: u64,
    /// Number of calls that needed exact arithmetic (a subset of `slow`).
    pub exact: u64,
}

/// Call and fallback counts of the derived predicates on the calling thread, since the
/// thread started or the last [`reset_fallback_counts`].
#[cfg(feature = "predicate-stats")]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct FallbackCounts {
    /// `orient2d_circumcenter` (direct calls only, not those made by the hull test).
    pub orient2d_circumcenter: PredicateCounts,
    /// `dot_sign_circumcenters`.
    pub dot_sign_circumcenters: PredicateCounts,
    /// `compare_circumradius`.
    pub compare_circumradius: PredicateCounts,
    /// `circumcenter_in_convex_hull`; a call counts as slow (exact) if any of its
    /// orientation tests was.
    pub circumcenter_in_convex_hull: PredicateCounts,
    /// `circumcenter` (also the Voronoi vertex positions); a call counts as exact if the
    /// coordinates were rounded from the exact circumcenter.
    pub circumcenter: PredicateCounts,
}

#[cfg(feature = "predicate-stats")]
impl FallbackCounts {
    /// The counts accumulated between `earlier` and `self` (saturating at zero).
    pub fn since(&self, earlier: &FallbackCounts) -> FallbackCounts {
        let d = |a: PredicateCounts, b: PredicateCounts| PredicateCounts {
            calls: a.calls.saturating_sub(b.calls),
            slow: a.slow.saturating_sub(b.slow),
            exact: a.exact.saturating_sub(b.exact),
        };
        FallbackCounts {
            orient2d_circumcenter: d(self.orient2d_circumcenter, earlier.orient2d_circumcenter),
            dot_sign_circumcenters: d(self.dot_sign_circumcenters, earlier.dot_sign_circumcenters),
            compare_circumradius: d(self.compare_circumradius, earlier.compare_circumradius),
            circumcenter_in_convex_hull: d(
                self.circumcenter_in_convex_hull,
                earlier.circumcenter_in_convex_hull,
            ),
            circumcenter: d(self.circumcenter, earlier.circumcenter),
        }
    }

    fn slot(&mut self, which: Which) -> &mut PredicateCounts {
        match which {
            Which::Orient => &mut self.orient2d_circumcenter,
            Which::Dot => &mut self.dot_sign_circumcenters,
            Which::Radius => &mut self.compare_circumradius,
            Which::Hull => &mut self.circumcenter_in_convex_hull,
            Which::Circumcenter => &mut self.circumcenter,
        }
    }
}

#[cfg(feature = "predicate-stats")]
thread_local! {
    static COUNTS: std::cell::Cell<FallbackCounts> = const {
        std::cell::Cell::new(FallbackCounts {
            orient2d_circumcenter: ZERO,
            dot_sign_circumcenters: ZERO,
            compare_circumradius: ZERO,
            circumcenter_in_convex_hull: ZERO,
            circumcenter: ZERO,
        })
    };
}

#[cfg(feature = "predicate-stats")]
const ZERO: PredicateCounts = PredicateCounts {
    calls: 0,
    slow: 0,
    exact: 0,
};

#[cfg(feature = "predicate-stats")]
fn update(which: Which, f: impl FnOnce(&mut PredicateCounts)) {
    COUNTS.with(|c| {
        let mut all = c.get();
        f(all.slot(which));
        c.set(all);
    });
}

/// Counts `n` calls of `which`.
#[inline(always)]
pub(super) fn calls(which: Which, n: u64) {
    #[cfg(feature = "predicate-stats")]
    update(which, |c| c.calls += n);
    #[cfg(not(feature = "predicate-stats"))]
    let _ = (which, n);
}

/// Counts a call of `which` that left the fast filter and was decided by `stage`.
#[inline(always)]
pub(super) fn slow(which: Which, stage: Stage) {
    #[cfg(feature = "predicate-stats")]
    update(which, |c| {
        c.slow += 1;
        c.exact += u64::from(stage == Stage::Exact);
    });
    #[cfg(not(feature = "predicate-stats"))]
    let _ = (which, stage);
}

/// A snapshot of the calling thread's counters.
#[cfg(feature = "predicate-stats")]
pub fn fallback_counts() -> FallbackCounts {
    COUNTS.with(|c| c.get())
}

/// Sets the calling thread's counters to zero.
#[cfg(feature = "predicate-stats")]
pub fn reset_fallback_counts() {
    COUNTS.with(|c| c.set(FallbackCounts::default()));
}
