//! `--threads N`, shared by every subcommand: the size of the worker pool the command runs
//! in. The library's results do not depend on it, only the wall time does.

use clap::Args;

use super::CliError;

/// The `--threads` option, flattened into each subcommand's arguments.
#[derive(Debug, Clone, Copy, Args)]
pub struct ThreadsArg {
    /// Worker threads (default: all cores, or RAYON_NUM_THREADS); results do not depend on N.
    #[arg(long, value_name = "N", value_parser = parse_threads)]
    threads: Option<usize>,
}

impl ThreadsArg {
    /// Runs `command` in a pool of the requested number of threads, or without `--threads`
    /// in rayon's global pool (all cores, or `RAYON_NUM_THREADS`).
    pub fn run<T: Send>(self, command: impl FnOnce() -> T + Send) -> Result<T, CliError> {
        let Some(threads) = self.threads else {
            return Ok(command());
        };
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .map_err(|e| CliError::failure(format!("cannot start {threads} threads: {e}")))?;
        Ok(pool.install(command))
    }
}

/// A thread count: a whole number of at least 1 (rayon would read 0 as "the default").
fn parse_threads(text: &str) -> Result<usize, String> {
    match text.trim().parse::<usize>() {
        Ok(0) => Err("the number of threads must be at least 1".to_string()),
        Ok(n) => Ok(n),
        Err(_) => Err(format!(
            "'{text}' is not a number of threads (a whole number, at least 1)"
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn thread_counts_are_whole_and_positive() {
        assert_eq!(parse_threads("4"), Ok(4));
        assert!(parse_threads("0").unwrap_err().contains("at least 1"));
        assert!(parse_threads("-1").is_err());
        assert!(parse_threads("two").is_err());
    }

    #[test]
    fn the_command_runs_in_a_pool_of_that_size() {
        let threads = ThreadsArg { threads: Some(3) };
        assert_eq!(threads.run(rayon::current_num_threads).ok(), Some(3));
        let default = ThreadsArg { threads: None };
        assert_eq!(
            default.run(rayon::current_num_threads).ok(),
            Some(rayon::current_num_threads())
        );
    }
}
