//! Why noisy closed curves fail: the failing trials of the noise rows, by category.
//!
//! ```text
//! cargo run --release --example noise_failures [-- TRIALS]
//! ```
//!
//! `SEEDS=1` lists the failing seeds by category on standard error (with the first pass's
//! pieces for pinches); `NOISES=0.3,1` sets the noise levels (default 0.5, 0.7, 1).
//!
//! Evenly spaced samples of one closed curve (peanut 150, star 200) and of an ellipse with a
//! circular hole (200 + 64), Gaussian noise of 0.5 / 0.7 / 1 sample spacing on each
//! coordinate (the sampler of `tests/reconstruct.rs`). A trial is right when the output is one
//! closed curve per true curve and nothing else. A failing trial is put in the first category
//! that fits, looking at the first pass (no peeling, no detour repair) before the final output:
//! * corridor: a first-pass edge touches a sample of the hole (the water leaked into it);
//! * pinch: the first pass has a point of degree 3 or more, or of degree 1 (an open chain),
//!   or more than one closed loop;
//! * later pass: the first pass is one closed loop of the outer curve, and peeling lost the
//!   hole (no closed loop of hole samples), or added an extra loop or an open chain.

use wdm_crust::reconstruct::{reconstruct_with, Options};
use wdm_crust_testkit::{ClosedCurve, DenseCurve, Ellipse, Peanut, Rng, Similarity, Star};

/// Noisy sample of `curves`, shuffled; also which curve each point came from.
fn noisy_sample(curves: &[DenseCurve], noise: f64, rng: &mut Rng) -> (Vec<[f64; 2]>, Vec<usize>) {
    let n: usize = curves.iter().map(|c| c.points.len()).sum();
    let spacing = curves.iter().map(|c| c.length()).sum::<f64>() / n as f64;
    let mut points: Vec<([f64; 2], usize)> = curves
        .iter()
        .enumerate()
        .flat_map(|(k, c)| c.points.iter().map(move |&p| (p, k)))
        .map(|([x, y], k)| {
            (
                [
                    x + noise * spacing * rng.normal(),
                    y + noise * spacing * rng.normal(),
                ],
                k,
            )
        })
        .collect();
    rng.shuffle(&mut points);
    points.into_iter().unzip()
}

#[derive(Default)]
struct Tally {
    trials: usize,
    right: usize,
    corridor: usize,
    corridor_and_pinch: usize,
    pinch: usize,
    hole_lost: usize,
    extra_loop: usize,
    open_chain: usize,
    seeds: Vec<(u64, &'static str)>,
}

fn degrees(n: usize, edges: &[[u32; 2]]) -> Vec<usize> {
    let mut d = vec![0; n];
    for &[a, b] in edges {
        d[a as usize] += 1;
        d[b as usize] += 1;
    }
    d
}

fn classify(curves: &[DenseCurve], noise: f64, seed: u64, tally: &mut Tally) {
    let (points, origin) = noisy_sample(curves, noise, &mut Rng::new(seed * 7919 + 1));
    let n = points.len();
    tally.trials += 1;
    let rec = reconstruct_with(&points, &Options::new()).unwrap();
    let closed = rec.curves().iter().filter(|c| c.closed).count();
    let open = rec.curves().len() - closed;
    if open == 0 && closed == curves.len() {
        tally.right += 1;
        return;
    }
    let first = reconstruct_with(
        &points,
        &Options::new().with_peeling(false).with_detour_repair(false),
    )
    .unwrap();
    let fp = first.edges();
    let touches_hole = fp.iter().flatten().any(|&p| origin[p as usize] == 1);
    let d = degrees(n, fp);
    let irregular = d.iter().any(|&k| k == 1 || k >= 3);
    let fp_loops = first.curves().iter().filter(|c| c.closed).count();
    let pinch = irregular || fp_loops != 1;
    let category = if touches_hole && pinch {
        tally.corridor_and_pinch += 1;
        "corridor+pinch"
    } else if touches_hole {
        tally.corridor += 1;
        "corridor"
    } else if pinch {
        tally.pinch += 1;
        // The first pass's pieces: (points, ends at its start); an ear is a short piece from
        // a junction back to itself beside the long rest of the loop.
        let chains: Vec<(usize, bool)> = first
            .curves()
            .iter()
            .map(|c| (c.points.len(), c.points.first() == c.points.last()))
            .collect();
        if std::env::var_os("SEEDS").is_some() {
            eprintln!("  pinch seed {seed}: chains {chains:?}");
        }
        "pinch"
    } else {
        let hole_closed = rec
            .curves()
            .iter()
            .any(|c| c.closed && c.points.iter().all(|&p| origin[p as usize] == 1));
        if curves.len() > 1 && !hole_closed {
            tally.hole_lost += 1;
            "hole lost"
        } else if open > 0 {
            tally.open_chain += 1;
            "open chain"
        } else {
            tally.extra_loop += 1;
            "extra loop"
        }
    };
    tally.seeds.push((seed, category));
}

fn main() {
    let trials: u64 = std::env::args()
        .nth(1)
        .map_or(100, |s| s.parse().expect("TRIALS"));
    let single = [
        ("peanut", Peanut { a: 0.3, b: 0.15 }.dense(150)),
        ("star", Star { a: 0.25, k: 5 }.dense(200)),
    ];
    let annulus = vec![
        Ellipse { a: 1.5, b: 1.0 }.dense(200),
        Ellipse::circle(0.4)
            .dense(64)
            .transformed(&Similarity::translation([0.3, 0.0])),
    ];
    println!(
        "| input | noise | trials | right | corridor | corridor + pinch | pinch | hole lost | \
         extra loop | open chain |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    let noises: Vec<f64> = std::env::var("NOISES").map_or(vec![0.5, 0.7, 1.0], |s| {
        s.split(',').map(|x| x.parse().expect("NOISES")).collect()
    });
    for noise in noises {
        let mut rows: Vec<(&str, Tally)> = Vec::new();
        for (name, shape) in &single {
            let mut tally = Tally::default();
            for seed in 0..trials {
                classify(std::slice::from_ref(shape), noise, seed, &mut tally);
            }
            rows.push((name, tally));
        }
        let mut tally = Tally::default();
        for seed in 0..trials {
            classify(&annulus, noise, seed, &mut tally);
        }
        rows.push(("with a hole", tally));
        for (name, t) in &rows {
            println!(
                "| {name} | {noise} | {} | {} | {} | {} | {} | {} | {} | {} |",
                t.trials,
                t.right,
                t.corridor,
                t.corridor_and_pinch,
                t.pinch,
                t.hole_lost,
                t.extra_loop,
                t.open_chain
            );
            if std::env::var_os("SEEDS").is_some() {
                eprintln!("{name} {noise}: {:?}", t.seeds);
            }
        }
    }
}
