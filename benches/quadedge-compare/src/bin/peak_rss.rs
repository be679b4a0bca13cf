//! `peak_rss STORE N`: triangulates N uniform points (the bench's set) with one store and
//! exits; run under `/usr/bin/time -v` for the peak RSS. STORE is one of
//! `quadedge_79d15e6`, `triangle_oldpipeline`, `triangle_current`, or `none` (points only,
//! the baseline to subtract).

use quadedge_compare::{uniform, Store};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let store = args.get(1).map(String::as_str).unwrap_or("none");
    let n: usize = args
        .get(2)
        .and_then(|s| s.parse().ok())
        .unwrap_or(1_000_000);
    let pts = uniform(n, 0x5EED ^ n as u64);
    let triangles = match store {
        "none" => 0,
        name => Store::from_name(name).expect("unknown store").run(&pts),
    };
    println!("{store} n={n} triangles={triangles}");
}
