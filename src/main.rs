//! The `wdm-crust` command line: argument parsing and dispatch live in [`cli`], the work in
//! the `wdm_crust` library. See `wdm-crust --help`.
#![forbid(unsafe_code)]

mod cli;

fn main() -> std::process::ExitCode {
    cli::run()
}
