//! The `camber` binary: parses the command line, runs it through [`camber_cli::run`], and
//! reports a failure as one line `error: …` on stderr with exit code 2 (0 on success).

use std::process::ExitCode;

use camber_cli::Cli;
use clap::Parser;

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            // Help and version go to stdout with 0; usage errors keep clap's text, code 2.
            let _ = e.print();
            return if e.use_stderr() {
                ExitCode::from(2)
            } else {
                ExitCode::SUCCESS
            };
        }
    };
    match camber_cli::run(&cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            // `{:#}` joins the context chain on one line: "file: what: why".
            eprintln!(
                "error: {}",
                camber_cli::tidy_numbers(&one_line(&format!("{e:#}")))
            );
            ExitCode::from(2)
        }
    }
}

/// Folds any line breaks of a message into spaces, so an error is always one line.
fn one_line(s: &str) -> String {
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}
