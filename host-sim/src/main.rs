//! `crane-sim`: the desktop tool of the load moment limiter.
//!
//! It runs the same `no_std` crane model and limiter as the firmware, in `f64`:
//! modes of the boom, the thesis maneuvers, the lifting-capacity chart, synthetic
//! sensor logs, calibration and replay of recorded logs. See `crane-sim --help`.

use clap::{Parser, Subcommand};
use std::process::ExitCode;

mod cmd;
mod maneuver_file;
mod model;
mod plot;

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
    /// Simulate one boom maneuver: a thesis case, any luffing move, a lift-off or a maneuver file.
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
    /// Validation campaign: seeded scenarios synthesized, replayed through the limiter and graded.
    Campaign(cmd::campaign::CampaignArgs),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Modes(args) => cmd::modes::run(args),
        Command::Simulate(args) => cmd::simulate::run(args),
        Command::Chart(args) => cmd::chart::run(args),
        Command::Synth(args) => cmd::synth::run(args),
        Command::Calibrate(args) => cmd::calibrate::run(args),
        Command::Replay(args) => cmd::replay::run(args),
        Command::Report(args) => cmd::report::run(args),
        Command::Campaign(args) => cmd::campaign::run(args),
    };
    match result {
        Ok(code) => ExitCode::from(code),
        Err(err) => {
            eprintln!("error: {err:#}");
            ExitCode::from(1)
        }
    }
}
