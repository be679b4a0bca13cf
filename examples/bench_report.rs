//! Turns the criterion results of `benches/triangulate.rs` and `benches/pipeline.rs` into the
//! README's tables and the pipeline scaling plot.
//!
//! ```text
//! cargo bench --bench triangulate --bench pipeline
//! cargo run --release --example bench_report            # tables on stdout
//! cargo run --release --example bench_report -- docs/pipeline-scaling.svg
//! ```
//!
//! Reads every `target/criterion/**/new/{benchmark,estimates}.json` and uses the median.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::Path;

use serde_json::Value;

/// Median nanoseconds per iteration, by (group, function, n).
type Results = BTreeMap<(String, String, u64), f64>;

fn main() {
    let mut results = Results::new();
    collect(Path::new("target/criterion"), &mut results);
    if results.is_empty() {
        eprintln!("no criterion results under target/criterion: run the benches first");
        std::process::exit(1);
    }
    triangulation_tables(&results);
    pipeline_table(&results);
    predicate_table(&results);
    if let Some(svg_path) = std::env::args().nth(1) {
        let svg = scaling_plot(&results);
        std::fs::write(&svg_path, svg).expect("write the plot");
        println!("\nplot written to {svg_path}");
    }
}

fn collect(dir: &Path, results: &mut Results) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let path = entry.path();
        if !path.is_dir() {
            continue;
        }
        if path.file_name().is_some_and(|name| name == "new") {
            if let Some(r) = read_result(&path) {
                results.insert(r.0, r.1);
            }
        } else {
            collect(&path, results);
        }
    }
}

fn read_result(dir: &Path) -> Option<((String, String, u64), f64)> {
    let read = |name: &str| -> Option<Value> {
        serde_json::from_str(&std::fs::read_to_string(dir.join(name)).ok()?).ok()
    };
    let bench = read("benchmark.json")?;
    let estimates = read("estimates.json")?;
    let group = bench["group_id"].as_str()?.to_string();
    let function = bench["function_id"].as_str().unwrap_or("").to_string();
    let n = bench["value_str"]
        .as_str()
        .and_then(|s| s.parse().ok())
        .unwrap_or(0);
    let median = estimates["median"]["point_estimate"].as_f64()?;
    Some(((group, function, n), median))
}

fn sizes(results: &Results, group: &str) -> Vec<u64> {
    let mut n: Vec<u64> = results
        .keys()
        .filter(|(g, _, _)| g == group)
        .map(|&(_, _, n)| n)
        .collect();
    n.sort_unstable();
    n.dedup();
    n
}

fn per_point(results: &Results, group: &str, function: &str, n: u64) -> Option<f64> {
    results
        .get(&(group.to_string(), function.to_string(), n))
        .map(|ns| ns / n as f64)
}

fn triangulation_tables(results: &Results) {
    println!("### Triangulation: median ns per point (ratio = peer time / wdm-crust time)\n");
    println!(
        "| points | n | wdm-crust | spade bulk | delaunator | spade / ours | delaunator / ours |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|");
    for set in ["uniform", "clusters", "grid", "curve"] {
        let group = format!("triangulate/{set}");
        for n in sizes(results, &group) {
            let ours = per_point(results, &group, "wdm_crust", n);
            let spade = per_point(results, &group, "spade_bulk", n);
            let del = per_point(results, &group, "delaunator", n);
            let cell = |x: Option<f64>| x.map_or("–".into(), |x| format!("{x:.0}"));
            let ratio = |peer: Option<f64>| match (peer, ours) {
                (Some(p), Some(o)) => format!("{:.2}×", p / o),
                _ => "–".into(),
            };
            println!(
                "| {set} | {} | {} | {} | {} | {} | {} |",
                power_of_ten(n),
                cell(ours),
                cell(spade),
                cell(del),
                ratio(spade),
                ratio(del)
            );
        }
    }
    println!();
}

/// The phases of `reconstruct` on curve samples; `extract` is what `reconstruct` spends
/// beyond the three measured phases (crust edges, peeling check, medial axis, the translation
/// of the edges to caller indices and the curves).
fn pipeline_rows(results: &Results) -> Vec<(u64, [f64; 5])> {
    sizes(results, "pipeline")
        .into_iter()
        .filter_map(|n| {
            let t = per_point(results, "pipeline", "triangulate", n)?;
            let v = per_point(results, "pipeline", "voronoi", n)?;
            let l = per_point(results, "pipeline", "label_vertices", n)?;
            let r = per_point(results, "pipeline", "reconstruct", n)?;
            Some((n, [t, v, l, (r - t - v - l).max(0.0), r]))
        })
        .collect()
}

fn pipeline_table(results: &Results) {
    let rows = pipeline_rows(results);
    if rows.is_empty() {
        return;
    }
    println!("### Pipeline on curve samples: median ns per point (ns per point per log2 n)\n");
    println!(
        "| n | triangulate | voronoi | label | extract | reconstruct | reconstruct / triangulate |"
    );
    println!("|---:|---:|---:|---:|---:|---:|---:|");
    for (n, phases) in rows {
        let log = (n as f64).log2();
        let mut line = format!("| {} |", power_of_ten(n));
        for x in phases {
            let _ = write!(line, " {x:.0} ({:.1}) |", x / log);
        }
        let _ = write!(line, " {:.2}× |", phases[4] / phases[0]);
        println!("{line}");
    }
    println!();
}

fn predicate_table(results: &Results) {
    let rows: Vec<(&String, f64)> = results
        .iter()
        .filter(|((g, _, _), _)| g == "predicates")
        .map(|((_, f, _), ns)| (f, ns / 1024.0))
        .collect();
    if rows.is_empty() {
        return;
    }
    println!("### Predicates: median ns per call (batches of 1024)\n");
    println!("| predicate / input | ns per call |");
    println!("|---|---:|");
    for (f, ns) in rows {
        println!("| {f} | {ns:.1} |");
    }
    println!();
}

fn power_of_ten(n: u64) -> String {
    let exponent = (n as f64).log10().round() as u32;
    if 10u64.pow(exponent) == n {
        format!("10^{exponent}")
    } else {
        n.to_string()
    }
}

/// Line plot of ns / (n log2 n) per phase against n (log scale): flat lines are O(n log n).
fn scaling_plot(results: &Results) -> String {
    let rows = pipeline_rows(results);
    let names = ["triangulate", "voronoi", "label", "extract", "reconstruct"];
    let colours = ["#1f77b4", "#2ca02c", "#d62728", "#9467bd", "#000000"];
    let (w, h, left, right, top, bottom) = (640.0, 360.0, 60.0, 150.0, 30.0, 45.0);
    let ys: Vec<f64> = rows
        .iter()
        .flat_map(|(n, p)| p.iter().map(move |x| x / (*n as f64).log2()))
        .collect();
    let y_max = ys.iter().cloned().fold(0.0, f64::max) * 1.15;
    let y_max = if y_max > 0.0 { y_max } else { 1.0 };
    let (x_lo, x_hi) = (3.0, 6.0);
    let px = |n: u64| left + ((n as f64).log10() - x_lo) / (x_hi - x_lo) * (w - left - right);
    let py = |y: f64| h - bottom - y / y_max * (h - top - bottom);
    let mut svg = String::new();
    let _ = writeln!(
        svg,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" font-family="sans-serif" font-size="12">"#
    );
    let _ = writeln!(svg, r#"<rect width="{w}" height="{h}" fill="white"/>"#);
    let _ = writeln!(
        svg,
        r#"<text x="{left}" y="18">wdm-crust on curve samples: median time / (n log2 n), ns</text>"#
    );
    // Axes, ticks and grid.
    let (x0, x1, y0, y1) = (left, w - right, h - bottom, top);
    let _ = writeln!(
        svg,
        r##"<path d="M{x0} {y1} V{y0} H{x1}" stroke="#333" fill="none"/>"##
    );
    for e in 3..=6 {
        let x = px(10u64.pow(e));
        let _ = writeln!(
            svg,
            r##"<line x1="{x}" y1="{y0}" x2="{x}" y2="{}" stroke="#333"/><text x="{x}" y="{}" text-anchor="middle">10{}</text>"##,
            y0 + 5.0,
            y0 + 18.0,
            ["⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷"][e as usize]
        );
    }
    let _ = writeln!(
        svg,
        r#"<text x="{}" y="{}" text-anchor="middle">points n</text>"#,
        (x0 + x1) / 2.0,
        h - 8.0
    );
    let step = nice_step(y_max / 5.0);
    let mut y = 0.0;
    while y <= y_max {
        let yy = py(y);
        let _ = writeln!(
            svg,
            r##"<line x1="{x0}" y1="{yy}" x2="{x1}" y2="{yy}" stroke="#ddd"/><text x="{}" y="{}" text-anchor="end">{y}</text>"##,
            x0 - 6.0,
            yy + 4.0
        );
        y += step;
    }
    for (k, (name, colour)) in names.iter().zip(colours).enumerate() {
        let points: Vec<String> = rows
            .iter()
            .map(|(n, p)| format!("{:.1},{:.1}", px(*n), py(p[k] / (*n as f64).log2())))
            .collect();
        let _ = writeln!(
            svg,
            r#"<polyline points="{}" fill="none" stroke="{colour}" stroke-width="2"/>"#,
            points.join(" ")
        );
        for p in &points {
            let (cx, cy) = p.split_once(',').unwrap_or(("0", "0"));
            let _ = writeln!(
                svg,
                r#"<circle cx="{cx}" cy="{cy}" r="3" fill="{colour}"/>"#
            );
        }
        let ly = top + 20.0 + 20.0 * k as f64;
        let _ = writeln!(
            svg,
            r#"<line x1="{}" y1="{ly}" x2="{}" y2="{ly}" stroke="{colour}" stroke-width="2"/><text x="{}" y="{}">{name}</text>"#,
            x1 + 15.0,
            x1 + 40.0,
            x1 + 46.0,
            ly + 4.0
        );
    }
    svg.push_str("</svg>\n");
    svg
}

/// 1, 2 or 5 times a power of ten, at least `raw`.
fn nice_step(raw: f64) -> f64 {
    let base = 10f64.powf(raw.log10().floor());
    [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * base)
        .find(|&s| s >= raw)
        .unwrap_or(10.0 * base)
}
