//! Peak-memory driver: runs one operation on one point set, for `/usr/bin/time -v`
//! ("Maximum resident set size"). Not a timing bench; without arguments it does nothing.
//!
//! ```text
//! cargo bench --bench peak_memory --no-run   # prints the binary path
//! /usr/bin/time -v target/release/deps/peak_memory-<hash> triangulate curve 1000000
//! ```
//! Operations: `points` (only generate the input, the baseline), `triangulate`, `voronoi`
//! (triangulate, then the dual with all vertex positions), `reconstruct`. Point sets:
//! `uniform`, `clusters`, `grid`, `curve`.

mod common;

use common::PointSet;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (Some(op), Some(set), Some(n)) = (
        args.first(),
        args.get(1).and_then(|s| PointSet::parse(s)),
        args.get(2).and_then(|s| s.parse::<usize>().ok()),
    ) else {
        eprintln!("usage: peak_memory <points|triangulate|voronoi|reconstruct> <point set> <n>");
        return;
    };
    let points = set.points(n, 42);
    match op.as_str() {
        "points" => println!("{} points", std::hint::black_box(&points).len()),
        "triangulate" => {
            let tri = wdm_crust::triangulate(&points).expect("valid points");
            println!("{} triangles", tri.triangle_count());
        }
        "voronoi" => {
            let tri = wdm_crust::triangulate(&points).expect("valid points");
            let vor = tri.voronoi();
            println!(
                "{} vertices, {} positions",
                vor.vertex_count(),
                vor.vertex_positions().len()
            );
        }
        "reconstruct" => {
            let rec = wdm_crust::reconstruct(&points).expect("valid points");
            println!(
                "{} crust edges, {} curves",
                rec.edges().len(),
                rec.curves().len()
            );
        }
        other => eprintln!("unknown operation {other}"),
    }
}
