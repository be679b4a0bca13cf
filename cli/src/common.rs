//! The options every subcommand takes, written once and flattened into each one's arguments.

use std::path::PathBuf;

use clap::Args;

use super::threads::ThreadsArg;

/// Where the result goes, what is said on standard error, and the worker pool.
#[derive(Debug, Clone, Args)]
pub struct CommonArgs {
    /// Write to OUTPUT instead of standard output; OUTPUT is replaced only on success.
    #[arg(short, long, value_name = "OUTPUT")]
    pub output: Option<PathBuf>,

    /// Print the wall time of each phase (parse, the subcommand's phases, write) to standard
    /// error.
    #[arg(long)]
    pub timings: bool,

    #[command(flatten)]
    pub threads: ThreadsArg,

    /// Nothing on standard error but errors: no summary line, no warnings, no notes, no
    /// progress.
    #[arg(short, long, conflicts_with = "timings")]
    pub quiet: bool,
}
