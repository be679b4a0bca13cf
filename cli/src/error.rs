//! The one error type of the command line: a one-line message and how to exit.

use std::io::Write;
use std::process::ExitCode;

/// How a failed command ends.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Severity {
    /// Bad input or usage: exit 2.
    BadInput,
    /// Anything else (an I/O failure, an internal error): exit 1.
    Failure,
    /// The reader of standard output went away (`| head`): exit 0 without a message.
    Quiet,
}

/// A failed command: a one-line message (without the `wdm-crust: ` prefix) and its severity.
#[derive(Debug)]
pub struct CliError {
    severity: Severity,
    message: String,
}

impl CliError {
    /// Bad input or usage (exit 2).
    pub fn bad_input(message: impl Into<String>) -> Self {
        CliError {
            severity: Severity::BadInput,
            message: message.into(),
        }
    }

    /// Any other failure (exit 1).
    pub fn failure(message: impl Into<String>) -> Self {
        CliError {
            severity: Severity::Failure,
            message: message.into(),
        }
    }

    /// Standard output was closed by its reader: stop quietly with success.
    pub fn quiet() -> Self {
        CliError {
            severity: Severity::Quiet,
            message: String::new(),
        }
    }

    /// Prints the message as one line on standard error and gives the exit code.
    pub fn report(&self) -> ExitCode {
        let code = match self.severity {
            Severity::Quiet => return ExitCode::SUCCESS,
            Severity::BadInput => 2,
            Severity::Failure => 1,
        };
        // One line, whatever the message holds.
        let message: String = self
            .message
            .chars()
            .map(|c| if c == '\n' || c == '\r' { ' ' } else { c })
            .collect();
        let _ = writeln!(std::io::stderr(), "wdm-crust: {message}");
        ExitCode::from(code)
    }
}
