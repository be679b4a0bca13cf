//! How often the derived exact predicates leave their floating-point filter, per workload.
//!
//! ```text
//! cargo run --release --features predicate-stats --example fallback_rates    # 100 000 points per set
//! cargo run --release --features predicate-stats --example fallback_rates -- 1000000
//! ```
//!
//! Runs the whole reconstruction (with peeling) on each point set of the benches, then a
//! Voronoi dual with all its vertex positions, and prints, for every derived predicate,
//! the calls, the share decided after the filter (`slow`: running-error or exact stage) and
//! the share that needed exact integer arithmetic (`exact`).

#[path = "../benches/common/mod.rs"]
mod common;

use common::PointSet;
use wdm_crust::predicates::{fallback_counts, PredicateCounts};

fn main() {
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(100_000);
    println!("| set | predicate | calls | slow | exact |");
    println!("|---|---|---:|---:|---:|");
    for set in PointSet::ALL {
        let points = set.points(n, 42);
        let before = fallback_counts();
        let rec = wdm_crust::reconstruct(&points).expect("valid points");
        std::hint::black_box(rec.triangulation().voronoi().vertex_positions().len());
        let d = fallback_counts().since(&before);
        let rows: [(&str, PredicateCounts); 5] = [
            ("dot_sign_circumcenters", d.dot_sign_circumcenters),
            ("compare_circumradius", d.compare_circumradius),
            ("circumcenter_in_convex_hull", d.circumcenter_in_convex_hull),
            ("orient2d_circumcenter", d.orient2d_circumcenter),
            ("circumcenter", d.circumcenter),
        ];
        for (name, c) in rows {
            let share = |k: u64| {
                if c.calls == 0 {
                    "–".to_string()
                } else {
                    format!("{:.4} %", 100.0 * k as f64 / c.calls as f64)
                }
            };
            println!(
                "| {} | {name} | {} | {} | {} |",
                set.name(),
                c.calls,
                share(c.slow),
                share(c.exact)
            );
        }
    }
}
