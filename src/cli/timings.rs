//! `--timings`: wall-clock time per phase, printed to standard error.

use std::io::Write;
use std::time::{Duration, Instant};

/// Collects the wall time of each phase of a command.
#[derive(Debug)]
pub struct Timings {
    enabled: bool,
    start: Instant,
    last: Instant,
    phases: Vec<(&'static str, Duration, String)>,
}

impl Timings {
    /// Starts the clock; with `enabled` false nothing is ever printed.
    pub fn new(enabled: bool) -> Self {
        let now = Instant::now();
        Timings {
            enabled,
            start: now,
            last: now,
            phases: Vec::new(),
        }
    }

    /// Ends the phase `name` (begun when the previous one ended), with a short note such as
    /// a count of the items it produced.
    pub fn phase(&mut self, name: &'static str, note: impl FnOnce() -> String) {
        if !self.enabled {
            return;
        }
        let now = Instant::now();
        self.phases.push((name, now - self.last, note()));
        self.last = now;
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
