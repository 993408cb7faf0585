//! `crane-sim`: the desktop tool of the load moment limiter.
//!
//! It runs the same `no_std` crane model and limiter as the firmware, in `f64`:
//! modes of the boom, the thesis maneuvers, the lifting-capacity chart, synthetic
//! sensor logs, calibration and replay of recorded logs. See `crane-sim --help`.

use clap::{Parser, Subcommand};
use std::process::ExitCode;

mod cmd;
mod model;
mod plot;
mod stdout;

#[derive(Parser)]
#[command(
    name = "crane-sim",
    version,
    about = "Load moment limiter simulator for the COLES Mobile 930 (Kılıçaslan 1997)"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Boom mass, natural frequencies and kinds of the boom's modes.
    Modes(cmd::modes::ModesArgs),
    /// Simulate one boom maneuver of the thesis (piston force, deflections, jack reaction).
    Simulate(cmd::simulate::SimulateArgs),
    /// Lifting capacity chart: tipping and rated load against radius.
    Chart(cmd::chart::ChartArgs),
    /// Make a recorded-style sensor log of a simulated maneuver.
    Synth(cmd::synth::SynthArgs),
    /// Learn cylinder friction and sensor offsets from unloaded up/down logs.
    Calibrate(cmd::calibrate::CalibrateArgs),
    /// Replay a sensor log through the limiter and print its alarm timeline.
    Replay(cmd::replay::ReplayArgs),
    /// Every figure as SVG plus an HTML page.
    Report(cmd::report::ReportArgs),
}

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
    let result = match cli.command {
        Command::Modes(args) => cmd::modes::run(args),
        Command::Simulate(args) => cmd::simulate::run(args),
        Command::Chart(args) => cmd::chart::run(args),
        Command::Synth(args) => cmd::synth::run(args),
        Command::Calibrate(args) => cmd::calibrate::run(args),
        Command::Replay(args) => cmd::replay::run(args),
        Command::Report(args) => cmd::report::run(args),
    };
    match result {
        Ok(code) => ExitCode::from(code),
        Err(err) => {
            eprintln!("error: {err:#}");
            ExitCode::from(1)
        }
    }
}
