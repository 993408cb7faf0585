//! The command line: what `crane-sim` accepts and which command runs it.

use clap::{Parser, Subcommand};

use crate::cmd;

/// The command line of `crane-sim` (SPEC §5; every subcommand in `docs/cli.md`).
#[derive(Parser)]
#[command(
    name = "crane-sim",
    version,
    about = "Load moment limiter simulator for the COLES Mobile 930 (Kılıçaslan 1997)",
    long_about = "Load moment limiter simulator for the COLES Mobile 930 (Kılıçaslan 1997).\n\n\
It runs the same crane model and limiter code as the controller: the boom's modes, the thesis's \
maneuvers, the lifting-capacity chart, synthetic sensor logs, friction calibration and the replay \
of recorded logs through the limiter, with figures (SVG or PNG) and HTML reports.",
    after_help = "Documentation: docs/README.md in the repository (docs/cli.md: every subcommand and exit code; \
docs/log-format.md: the sensor log; docs/calibration.md: the calibration file).\n\
Exit codes: 0 done (replay: never OVERLOAD or FAULT); 2 replay entered OVERLOAD or FAULT; 1 anything else."
)]
pub struct Cli {
    /// The subcommand to run.
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands.
#[derive(Subcommand)]
pub enum Command {
    /// Boom mass, natural frequencies and kinds of the boom's modes.
    Modes(cmd::modes::ModesArgs),
    /// Simulate one boom maneuver: a thesis case, any luffing move, a lift-off or a maneuver file.
    #[command(allow_negative_numbers = true)]
    Simulate(cmd::simulate::SimulateArgs),
    /// Lifting capacity chart: tipping and rated load against radius.
    #[command(allow_negative_numbers = true)]
    Chart(cmd::chart::ChartArgs),
    /// Make a recorded-style sensor log of a simulated maneuver.
    #[command(allow_negative_numbers = true, after_help = "The log format is in docs/log-format.md.")]
    Synth(cmd::synth::SynthArgs),
    /// Learn cylinder friction and sensor offsets from unloaded up/down logs.
    #[command(after_help = "The log format is in docs/log-format.md; the file written, key by key, in docs/calibration.md.")]
    Calibrate(cmd::calibrate::CalibrateArgs),
    /// Replay a sensor log through the limiter and print its alarm timeline.
    #[command(after_help = "The log format is in docs/log-format.md, the calibration file in docs/calibration.md, \
the page of --report in docs/reports.md.\n\
Exit codes: 0 the log was read to its end and never entered OVERLOAD or FAULT; 2 it entered OVERLOAD or FAULT \
at least once; 1 the log or the calibration could not be read, or the command line was wrong.")]
    Replay(cmd::replay::ReplayArgs),
    /// Every figure as SVG and PNG plus an HTML page (thesis maneuvers, chart, limiter on the example logs).
    #[command(after_help = "What each file shows: docs/reports.md.")]
    Report(cmd::report::ReportArgs),
    /// Validation campaign: seeded scenarios synthesized, replayed through the limiter and graded.
    Campaign(cmd::campaign::CampaignArgs),
}

impl Command {
    /// Runs the subcommand; the exit code on success (SPEC §5: 0, or 2 when a
    /// replay entered OVERLOAD or FAULT).
    pub fn run(self) -> anyhow::Result<u8> {
        match self {
            Command::Modes(args) => cmd::modes::run(args),
            Command::Simulate(args) => cmd::simulate::run(args),
            Command::Chart(args) => cmd::chart::run(args),
            Command::Synth(args) => cmd::synth::run(args),
            Command::Calibrate(args) => cmd::calibrate::run(args),
            Command::Replay(args) => cmd::replay::run(args),
            Command::Report(args) => cmd::report::run(args),
            Command::Campaign(args) => cmd::campaign::run(args),
        }
    }
}
