//! Lemma 3.1 of the paper as a property test: for an ε-sample (ε < 0.4) of a smooth closed
//! BNC curve, WDM_CRUST contains the edge between every pair of adjacent samples.
//!
//! The samples and their local feature size come from `wdm_crust_testkit`, which computes
//! lfs from tangent medial balls of a dense polyline, independently of the crate's
//! Delaunay/Voronoi code. Extra edges are reported: the goal is the exact polygon.

use proptest::prelude::*;
use wdm_crust_testkit::{
    ClosedCurve, CurveSet, DenseCurve, Ellipse, Peanut, Rng, Star, Superellipse,
};

const DENSE: usize = 20_000;

fn curve(kind: u8, p1: f64, p2: f64) -> DenseCurve {
    match kind % 4 {
        0 => Ellipse {
            a: 1.0,
            b: 0.3 + 0.7 * p1,
        }
        .dense(DENSE),
        1 => Star {
            a: 0.05 + 0.2 * p1,
            k: 3 + (p2 * 5.0) as u32,
        }
        .dense(DENSE),
        2 => Peanut {
            a: 0.1 + 0.25 * p1,
            b: 0.05 + 0.1 * p2,
        }
        .dense(DENSE),
        _ => Superellipse {
            a: 1.0,
            b: 0.4 + 0.6 * p1,
            p: 2.5 + 3.0 * p2,
        }
        .dense(DENSE),
    }
}

/// Ground-truth edges missing from the reconstruction, and reconstructed edges not in it.
fn compare(
    truth: &std::collections::BTreeSet<(usize, usize)>,
    edges: &[[u32; 2]],
) -> (usize, usize) {
    let ours: std::collections::BTreeSet<(usize, usize)> = edges
        .iter()
        .map(|&[a, b]| (a as usize, b as usize))
        .collect();
    (
        truth.difference(&ours).count(),
        ours.difference(truth).count(),
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn every_adjacent_pair_is_a_crust_edge(
        kind in 0u8..4,
        p1 in 0.0..1.0f64,
        p2 in 0.0..1.0f64,
        eps in 0.05..0.39f64,
        seed in any::<u64>(),
    ) {
        let mut rng = Rng::new(seed);
        let set = CurveSet::new(vec![curve(kind, p1, p2)]);
        let sample = set.eps_sample(eps, &mut rng).randomized(&mut rng);
        let rec = wdm_crust::reconstruct(&sample.points).expect("valid points");
        let (missing, extra) = compare(&sample.edge_set(), rec.edges());
        prop_assert_eq!(missing, 0, "{} of {} adjacent pairs missing ({} extra), kind {} eps {}", missing, sample.len(), extra, kind, eps);
    }
}

/// The exact-polygon rate over a fixed set of seeds: below 0.4 every adjacent pair must be
/// found (the lemma) and, in practice, nothing else; beyond the theory the rate is reported.
#[test]
fn exact_polygon_rate_by_epsilon() {
    let mut rng = Rng::new(2024);
    for (eps, min_rate) in [
        (0.2, 0.95),
        (0.39, 0.95),
        (0.5, 0.0),
        (0.8, 0.0),
        (1.2, 0.0),
    ] {
        let trials = 24;
        let (mut all_adjacent, mut exact) = (0, 0);
        for t in 0..trials {
            let set = CurveSet::new(vec![curve(t as u8, rng.f64(), rng.f64())]);
            let sample = set.eps_sample(eps, &mut rng).randomized(&mut rng);
            let rec = wdm_crust::reconstruct(&sample.points).expect("valid points");
            let (missing, extra) = compare(&sample.edge_set(), rec.edges());
            if eps < 0.4 {
                assert_eq!(missing, 0, "lemma 3.1 at eps {eps}, trial {t}");
            }
            all_adjacent += usize::from(missing == 0);
            exact += usize::from(missing == 0 && extra == 0);
        }
        let rate = exact as f64 / trials as f64;
        eprintln!(
            "eps {eps}: all adjacent pairs {all_adjacent}/{trials}, exact polygon {exact}/{trials}"
        );
        assert!(rate >= min_rate, "eps {eps}: exact-polygon rate {rate}");
    }
}
