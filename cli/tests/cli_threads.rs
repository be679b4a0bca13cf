//! `--threads N` and `RAYON_NUM_THREADS`: every subcommand writes the same bytes whatever
//! the number of threads, and a thread count of 0 is a one-line usage error.

use std::path::Path;
use std::process::Command;

mod common;
#[path = "../../benches/common/mod.rs"]
mod sets;

use common::{listing, run_in, write, BIN};
use sets::PointSet;

/// A point file that the triangulation splits at its parallel top several times: a noisy
/// curve (the reconstruction workload) with uniform points around it.
fn write_points(dir: &Path) {
    let mut points = PointSet::Curve.points(50_000, 1);
    points.extend(PointSet::Uniform.points(20_000, 2));
    let text: String = points
        .iter()
        .map(|p| format!("{} {}\n", p[0], p[1]))
        .collect();
    write(dir, "points.txt", text.as_bytes());
}

/// The subcommands and the output each is compared on.
const COMMANDS: [&[&str]; 4] = [
    &["triangulate", "points.txt"],
    &["voronoi", "points.txt"],
    &["reconstruct", "points.txt"],
    &["reconstruct", "points.txt", "--format", "geojson"],
];

#[test]
fn output_is_byte_identical_for_one_and_four_threads() {
    let dir = tempfile::tempdir().unwrap();
    write_points(dir.path());
    for command in COMMANDS {
        let outputs: Vec<String> = ["1", "4"]
            .iter()
            .map(|threads| {
                let args = [command, &["--threads", threads]].concat();
                let run = run_in(dir.path(), &args, b"");
                assert_eq!(run.code, 0, "{args:?}: {}", run.stderr);
                assert!(run.stdout.len() > 100_000, "{args:?}: a real output");
                run.stdout
            })
            .collect();
        assert!(
            outputs[0] == outputs[1],
            "{command:?}: --threads 1 and --threads 4 differ"
        );
    }
}

#[test]
fn output_is_byte_identical_for_any_rayon_num_threads() {
    let dir = tempfile::tempdir().unwrap();
    write_points(dir.path());
    let run_with = |threads: &str| {
        let output = Command::new(BIN)
            .args(["triangulate", "points.txt"])
            .current_dir(dir.path())
            .env("RAYON_NUM_THREADS", threads)
            .output()
            .expect("the wdm-crust binary runs");
        assert!(output.status.success(), "RAYON_NUM_THREADS={threads}");
        output.stdout
    };
    assert!(run_with("1") == run_with("3"));
}

#[test]
fn zero_threads_is_a_one_line_usage_error() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "points.txt", b"0 0\n1 0\n0 1\n");
    for command in ["triangulate", "voronoi", "reconstruct"] {
        let args = [command, "points.txt", "--threads", "0", "-o", "out.json"];
        let run = run_in(dir.path(), &args, b"");
        assert_eq!(run.code, 2, "{args:?}");
        assert_eq!(run.stdout, "");
        assert_eq!(run.stderr.lines().count(), 1, "{args:?}: {}", run.stderr);
        assert!(
            run.stderr.starts_with("wdm-crust: ")
                && run.stderr.contains("--threads")
                && run.stderr.contains("at least 1"),
            "{args:?}: {}",
            run.stderr
        );
        assert_eq!(listing(dir.path()), ["points.txt"], "no output file");
    }
    let run = run_in(dir.path(), &["triangulate", "--threads", "many"], b"");
    assert_eq!(run.code, 2);
    assert_eq!(run.stderr.lines().count(), 1, "{}", run.stderr);
}
