//! The Rust side of the Python binding's overhead measurement
//! (`python/bench/bench_binding.py` runs it on the same points and compares).
//!
//! ```text
//! cargo run --release --example query_timing -- POINTS QUERIES CURVE_POINTS REPEATS
//! ```
//!
//! Each file holds raw little-endian `f64` pairs (numpy's `tofile`). Prints one JSON line of
//! best-of-REPEATS wall times in seconds: `triangulate` (POINTS), `locate` and `nearest`
//! (every query, one [`Locator`](wdm_crust::delaunay::Locator) on one thread, as the binding
//! with `threads=1`), `reconstruct` (CURVE_POINTS, default options, rayon's global pool as
//! the binding's default), and check sums of the answers for the caller to compare.

use std::process::ExitCode;
use std::time::{Duration, Instant};

fn main() -> ExitCode {
    match run() {
        Ok(line) => {
            println!("{line}");
            ExitCode::SUCCESS
        }
        Err(message) => {
            eprintln!("query_timing: {message}");
            ExitCode::FAILURE
        }
    }
}

/// Reads a file of little-endian `f64` pairs.
fn read_pairs(path: &str) -> Result<Vec<[f64; 2]>, String> {
    let bytes = std::fs::read(path).map_err(|e| format!("{path}: {e}"))?;
    if bytes.len() % 16 != 0 {
        return Err(format!("{path}: not a whole number of f64 pairs"));
    }
    Ok(bytes
        .chunks_exact(16)
        .map(|pair| {
            let (x, y) = pair.split_at(8);
            let value = |b: &[u8]| f64::from_le_bytes(b.try_into().expect("8 bytes"));
            [value(x), value(y)]
        })
        .collect())
}

/// The least wall time of `repeats` runs of `job`, and its last result.
fn best_of<T>(repeats: usize, mut job: impl FnMut() -> T) -> (Duration, T) {
    let mut best = Duration::MAX;
    let mut result = None;
    for _ in 0..repeats.max(1) {
        let start = Instant::now();
        let value = job();
        best = best.min(start.elapsed());
        result = Some(value);
    }
    (best, result.expect("at least one run"))
}

fn run() -> Result<String, String> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [points, queries, curve_points, repeats] = args.as_slice() else {
        return Err("usage: query_timing POINTS QUERIES CURVE_POINTS REPEATS".to_string());
    };
    let repeats: usize = repeats
        .parse()
        .map_err(|_| format!("REPEATS: not a number: {repeats}"))?;
    let (points, queries) = (read_pairs(points)?, read_pairs(queries)?);
    let curve_points = read_pairs(curve_points)?;

    let (triangulate, tri) = best_of(repeats, || wdm_crust::triangulate(&points));
    let tri = tri.map_err(|e| e.to_string())?;
    let (locate, located) = best_of(repeats, || {
        let mut locator = tri.locator();
        queries
            .iter()
            .map(|&q| {
                locator
                    .triangle_containing(q)
                    .map(|t| t.map_or(-1, |t| i64::from(t.get())))
            })
            .collect::<Result<Vec<i64>, _>>()
    });
    let located = located.map_err(|e| e.to_string())?;
    let (nearest, nearest_found) = best_of(repeats, || {
        let mut locator = tri.locator();
        queries
            .iter()
            .map(|&q| locator.nearest(q).map(|p| p.map_or(-1, i64::from)))
            .collect::<Result<Vec<i64>, _>>()
    });
    let nearest_found = nearest_found.map_err(|e| e.to_string())?;
    let (reconstruct, rec) = best_of(repeats, || wdm_crust::reconstruct(&curve_points));
    let rec = rec.map_err(|e| e.to_string())?;
    Ok(format!(
        "{{\"triangulate\": {}, \"locate\": {}, \"nearest\": {}, \"reconstruct\": {}, \
         \"located_sum\": {}, \"nearest_sum\": {}, \"edges\": {}}}",
        triangulate.as_secs_f64(),
        locate.as_secs_f64(),
        nearest.as_secs_f64(),
        reconstruct.as_secs_f64(),
        located.iter().sum::<i64>(),
        nearest_found.iter().sum::<i64>(),
        rec.edges().len()
    ))
}
