//! `crane-sim`: the desktop tool of the load moment limiter.
//!
//! It runs the same `no_std` crane model and limiter as the firmware, in `f64`:
//! modes of the boom, the thesis maneuvers, the lifting-capacity chart, synthetic
//! sensor logs, calibration and replay of recorded logs. See `crane-sim --help`
//! and `docs/cli.md`.

use clap::Parser;
use host_sim::cli::Cli;
use std::process::ExitCode;

fn main() -> ExitCode {
    // SPEC §5: a usage error exits 1, never 2 (which scripts read as an
    // alarm); `--help` and `--version` exit 0.
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            let _ = e.print();
            return ExitCode::from(if e.use_stderr() { 1 } else { 0 });
        }
    };
    let result = cli.command.run();
    match result {
        Ok(code) => ExitCode::from(code),
        Err(err) => {
            eprintln!("error: {err:#}");
            ExitCode::from(1)
        }
    }
}
