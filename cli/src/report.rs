//! What the command line says on standard error besides errors: a summary of what was
//! written, notes, and warnings that the result is probably not what was wanted. `--quiet`
//! silences all of it (errors still print): the flag is set once, before any work, and read
//! by every writer of such a line, the progress lines included.

use std::io::Write;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

static QUIET: AtomicBool = AtomicBool::new(false);

/// Silences everything but errors from now on (`--quiet`).
pub fn set_quiet(quiet: bool) {
    QUIET.store(quiet, Ordering::Relaxed);
}

/// Whether `--quiet` was given.
pub fn quiet() -> bool {
    QUIET.load(Ordering::Relaxed)
}

/// `wdm-crust: note: <input>: <text>`.
pub fn note(input: &str, text: &str) {
    line(&format!("wdm-crust: note: {input}: {text}"));
}

/// `warning: <input>: <message> [<code>]`: the line starts with `warning:` so that scripts
/// can pick it out.
pub fn warning(input: &str, warning: &wdm_crust::Warning) {
    line(&format!("warning: {input}: {warning}"));
}

/// `wdm-crust: wrote <output>: <what>; <n> points in <time>`: the one summary line of a
/// command that wrote a file.
pub fn summary(output: &str, what: &str, points: usize, time: Duration) {
    line(&format!(
        "wdm-crust: wrote {output}: {what}; {} in {}",
        counted(points, "point", "points"),
        short_time(time)
    ));
}

/// `1 closed curve`, `2 closed curves`.
pub fn counted(n: usize, one: &str, many: &str) -> String {
    if n == 1 {
        format!("1 {one}")
    } else {
        format!("{n} {many}")
    }
}

fn line(text: &str) {
    if !quiet() {
        let _ = writeln!(std::io::stderr(), "{text}");
    }
}

/// `850 µs`, `12 ms`, `1.25 s`.
fn short_time(time: Duration) -> String {
    let s = time.as_secs_f64();
    if s < 1e-3 {
        format!("{:.0} µs", s * 1e6)
    } else if s < 1.0 {
        format!("{:.0} ms", s * 1e3)
    } else {
        format!("{s:.2} s")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_and_times_read_as_words() {
        assert_eq!(
            counted(1, "closed curve", "closed curves"),
            "1 closed curve"
        );
        assert_eq!(counted(0, "open chain", "open chains"), "0 open chains");
        assert_eq!(short_time(Duration::from_micros(850)), "850 µs");
        assert_eq!(short_time(Duration::from_millis(12)), "12 ms");
        assert_eq!(short_time(Duration::from_millis(1250)), "1.25 s");
    }
}
