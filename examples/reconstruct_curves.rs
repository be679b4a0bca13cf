//! Reconstructs the curves through a point file and prints what was found.
//!
//! ```text
//! cargo run --release --example reconstruct_curves                       # the bundled bean
//! cargo run --release --example reconstruct_curves -- examples/data/mushroom.p2d
//! ```
//!
//! The file may be plain text (`x y` per line), CSV or Triangle `.node` / Dey `.gtn`.

use std::path::PathBuf;
use std::process::ExitCode;

/// The bundled example used when no file is given.
const DEFAULT_INPUT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/data/bean.txt");

fn main() -> ExitCode {
    let path = PathBuf::from(
        std::env::args_os()
            .nth(1)
            .unwrap_or_else(|| DEFAULT_INPUT.into()),
    );
    match run(&path) {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("reconstruct_curves: {}: {message}", path.display());
            ExitCode::FAILURE
        }
    }
}

fn run(path: &std::path::Path) -> Result<(), Box<dyn std::error::Error>> {
    // Read the points: every format is detected from the extension or the content.
    let points = wdm_crust::io::read_points_from_path(path)?;

    // WDM_CRUST with the default options (peeling on, to find nested curves).
    let rec = wdm_crust::reconstruct(&points)?;

    println!(
        "{}: {} points, {} edges ({} pass{})",
        path.display(),
        points.len(),
        rec.edges().len(),
        rec.passes(),
        if rec.passes() == 1 { "" } else { "es" }
    );
    for (k, curve) in rec.curves().iter().enumerate() {
        let kind = if curve.closed {
            "closed loop"
        } else {
            "open chain "
        };
        let first = curve.points.iter().take(6).map(u32::to_string);
        let more = if curve.points.len() > 6 { " ..." } else { "" };
        println!(
            "  curve {k}: {kind} through {:>4} points: {}{more}",
            curve.points.len(),
            first.collect::<Vec<_>>().join(" ")
        );
    }
    let untouched = rec.untouched_points();
    if !untouched.is_empty() {
        println!("  {} points lie on no curve", untouched.len());
    }
    let axis = rec.medial_axis();
    println!(
        "  medial axis: {} vertices, {} segments",
        axis.vertices.len(),
        axis.edges.len()
    );
    Ok(())
}
