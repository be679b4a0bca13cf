//! `--timings`: wall-clock time per phase, printed to standard error; and progress lines
//! for large inputs.
//!
//! Progress: when standard error is a terminal and the input is large (more than
//! [`PROGRESS_POINTS`] points, or a file of more than [`PROGRESS_BYTES`] bytes while it is
//! read), every phase prints `wdm-crust: <what>...` when it begins and its wall time when it
//! ends, on one line. Nothing is printed when standard error is redirected.

use std::io::{IsTerminal, Write};
use std::time::{Duration, Instant};

/// Inputs with more points than this get progress lines (on a terminal).
pub const PROGRESS_POINTS: usize = 200_000;
/// Input files larger than this get a progress line while they are read (on a terminal).
pub const PROGRESS_BYTES: u64 = 4 << 20;

/// Collects the wall time of each phase of a command.
#[derive(Debug)]
pub struct Timings {
    enabled: bool,
    /// Progress lines wanted (standard error is a terminal and the input is large).
    progress: bool,
    /// A progress line has been begun and awaits its time.
    line_open: bool,
    start: Instant,
    last: Instant,
    phases: Vec<(&'static str, Duration, String)>,
}

impl Timings {
    /// Starts the clock; with `enabled` false no timings are printed.
    pub fn new(enabled: bool) -> Self {
        let now = Instant::now();
        Timings {
            enabled,
            progress: false,
            line_open: false,
            start: now,
            last: now,
            phases: Vec::new(),
        }
    }

    /// Turns progress lines on when `large` is true and standard error is a terminal, off
    /// otherwise.
    pub fn progress_if(&mut self, large: bool) {
        self.progress = large && !super::report::quiet() && std::io::stderr().is_terminal();
    }

    /// The wall time since the clock started.
    pub fn elapsed(&self) -> Duration {
        self.start.elapsed()
    }

    /// Announces the phase that starts now (a progress line, if they are on): `what` is a
    /// short description such as `triangulating 1000000 points`.
    pub fn begin(&mut self, what: impl FnOnce() -> String) {
        if self.progress {
            let mut stderr = std::io::stderr().lock();
            let _ = write!(stderr, "wdm-crust: {}...", what());
            let _ = stderr.flush();
            self.line_open = true;
        }
    }

    /// Ends the phase `name` (begun when the previous one ended), with a short note such as
    /// a count of the items it produced.
    pub fn phase(&mut self, name: &'static str, note: impl FnOnce() -> String) {
        if !self.enabled && !self.line_open {
            return;
        }
        let now = Instant::now();
        let time = now - self.last;
        self.last = now;
        if self.line_open {
            self.line_open = false;
            let _ = writeln!(std::io::stderr(), " {}", progress_time(time));
        }
        if self.enabled {
            self.phases.push((name, time, note()));
        }
    }

    /// Prints one line per phase and the total to standard error, if enabled.
    pub fn report(&self) {
        if !self.enabled {
            return;
        }
        let mut out = String::from("wdm-crust: timings (wall clock)\n");
        let rows = self
            .phases
            .iter()
            .map(|(name, time, note)| (*name, *time, note.as_str()))
            .chain(std::iter::once(("total", self.last - self.start, "")));
        for (name, time, note) in rows {
            let ms = time.as_secs_f64() * 1e3;
            let line = format!("  {name:<12} {ms:>10.3} ms  {note}");
            out.push_str(line.trim_end());
            out.push('\n');
        }
        let _ = std::io::stderr().write_all(out.as_bytes());
    }
}

impl Drop for Timings {
    /// A phase that failed leaves its progress line open: end it, so that the error message
    /// gets a line of its own.
    fn drop(&mut self) {
        if self.line_open {
            let _ = writeln!(std::io::stderr(), " failed");
        }
    }
}

/// `0.42 s`, `12.3 s`, `2 min 05 s`.
fn progress_time(time: Duration) -> String {
    let s = time.as_secs_f64();
    if s < 10.0 {
        format!("{s:.2} s")
    } else if s < 100.0 {
        format!("{s:.1} s")
    } else {
        let whole = time.as_secs();
        format!("{} min {:02} s", whole / 60, whole % 60)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn progress_times_are_short() {
        assert_eq!(progress_time(Duration::from_millis(420)), "0.42 s");
        assert_eq!(progress_time(Duration::from_millis(12_340)), "12.3 s");
        assert_eq!(progress_time(Duration::from_secs(125)), "2 min 05 s");
    }

    #[test]
    fn nothing_is_recorded_when_disabled() {
        let mut timings = Timings::new(false);
        timings.progress_if(false);
        timings.begin(|| unreachable!());
        timings.phase("parse", || unreachable!());
        assert!(timings.phases.is_empty());
        let mut timings = Timings::new(true);
        timings.phase("parse", || "3 points".to_string());
        assert_eq!(timings.phases.len(), 1);
    }
}
