//! `interleaved [ROUNDS]`: a check of the criterion numbers that is robust to a shared
//! machine. For each set and size, the three stores run in turn, ROUNDS times (default 7),
//! and the minimum and the median wall time of each are printed in ns per point, with the
//! ratios of the minima. Each call is the same library call the bench times.

use std::time::Instant;

use quadedge_compare::{noisy_ellipse, uniform, Store};

fn main() {
    let rounds: usize = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(7);
    type Gen = fn(usize, u64) -> Vec<[f64; 2]>;
    let sets: [(&str, Gen); 2] = [("uniform", uniform), ("noisy_ellipse", noisy_ellipse)];
    println!("set n store min_ns_per_point median_ns_per_point");
    for (set, generate) in sets {
        for n in [10_000usize, 100_000, 1_000_000] {
            let pts = generate(n, 0x5EED ^ n as u64);
            let reps = (1_000_000 / n).max(1); // calls per timing, so one timing is ~10^6 points
            let mut times = vec![Vec::new(); Store::ALL.len()];
            for _ in 0..rounds {
                for (k, store) in Store::ALL.into_iter().enumerate() {
                    let start = Instant::now();
                    for _ in 0..reps {
                        std::hint::black_box(store.run(std::hint::black_box(&pts)));
                    }
                    times[k].push(start.elapsed().as_secs_f64() * 1e9 / (reps * n) as f64);
                }
            }
            let mut mins = Vec::new();
            for (k, store) in Store::ALL.into_iter().enumerate() {
                times[k].sort_by(f64::total_cmp);
                let (min, med) = (times[k][0], times[k][rounds / 2]);
                mins.push(min);
                println!("{set} {n} {} {min:.1} {med:.1}", store.name());
            }
            println!(
                "{set} {n} ratio_of_minima quadedge/triangle_oldpipeline={:.2} quadedge/triangle_current={:.2} triangle_oldpipeline/triangle_current={:.2}",
                mins[0] / mins[1],
                mins[0] / mins[2],
                mins[1] / mins[2]
            );
        }
    }
}
