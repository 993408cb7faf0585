//! `crane-sim synth`: a recorded-style sensor log of a simulated maneuver (SPEC §5).
//!
//! What the limiter's sensors would have recorded on the crane: the simulated
//! piston force plus cylinder friction (higher going up than coming down, the
//! hysteresis of the thesis's measured traces, Figs. 4.2–4.3), split into p1 and
//! p2 by eq. 4.1 with a small rod-side back pressure, transducer noise and the
//! 12-bit quantization of the 4–20 mA front end; the boom angle through an
//! oil-damped pendulum potentiometer (second-order lag) with noise and
//! quantization; and the true hook load as the last column.

//! The sensor model itself is in `host-sim/src/synth_core.rs` (shared with the
//! in-process acceptance tests); this module is its command line.

use super::simulate::{maneuver, DirectionArg, InitialArg, ProfileArg, SimulateArgs};
use crate::model::thesis_model;
use anyhow::{bail, Context, Result};
use synth_core::SensorModel;
use std::io::Write;
use std::path::PathBuf;

/// The log synthesis shared with `host-sim/tests/limiter_acceptance.rs`.
#[path = "../synth_core.rs"]
#[allow(dead_code)] // `SynthRow::truth` and `true_rate_deg_s` are for the tests.
pub mod synth_core;

/// Arguments of `crane-sim synth`.
#[derive(clap::Args, Debug)]
pub struct SynthArgs {
    /// A thesis case by name (`crane-sim simulate --list`).
    #[arg(long)]
    case: Option<String>,
    /// Hook load W (kg).
    #[arg(long, default_value_t = 3300.0)]
    load_kg: f64,
    /// Duration of the motion: 30 or 10 (s).
    #[arg(long, default_value_t = 30.0)]
    duration: f64,
    /// Velocity profile of the piston.
    #[arg(long, value_enum, default_value = "cycloidal")]
    profile: ProfileArg,
    /// Boom up or down.
    #[arg(long, value_enum, default_value = "up")]
    direction: DirectionArg,
    /// Lower boom angle of the move (deg).
    #[arg(long, default_value_t = 40.0)]
    low_deg: f64,
    /// Higher boom angle of the move (deg).
    #[arg(long, default_value_t = 80.0)]
    high_deg: f64,
    /// Samples per second in the log (20–500; the limiter faults on gaps over 50 ms).
    #[arg(long, default_value_t = 50.0)]
    rate_hz: f64,
    /// Seed of the noise.
    #[arg(long, default_value_t = 1)]
    seed: u32,
    /// Cylinder friction while raising (N): the piston force reads higher.
    #[arg(long, default_value_t = 12_000.0)]
    friction_up_n: f64,
    /// Cylinder friction while lowering (N): the piston force reads lower.
    #[arg(long, default_value_t = 8_000.0)]
    friction_down_n: f64,
    /// Standard deviation of the pressure noise (bar).
    #[arg(long, default_value_t = 0.3)]
    noise_bar: f64,
    /// Standard deviation of the angle noise (deg).
    #[arg(long, default_value_t = 0.03)]
    noise_deg: f64,
    /// Natural frequency of the pendulum potentiometer (Hz).
    #[arg(long, default_value_t = 2.0)]
    pendulum_hz: f64,
    /// Damping ratio of the pendulum potentiometer (oil).
    #[arg(long, default_value_t = 0.7)]
    pendulum_damping: f64,
    /// Back pressure on the rod side (bar).
    #[arg(long, default_value_t = 4.0)]
    rod_side_bar: f64,
    /// Seconds of standstill recorded before the move.
    #[arg(long, default_value_t = 1.0)]
    hold_s: f64,
    /// Break the p1 loop (0 mA, reads −50 bar) from this time on (s): a wire break.
    #[arg(long)]
    open_p1_at_s: Option<f64>,
    /// Where to write the log.
    #[arg(long)]
    out: PathBuf,
}

/// Runs the subcommand; returns the exit code.
pub fn run(args: SynthArgs) -> Result<u8> {
    // Below 20 Hz the samples are more than 50 ms apart, a gap the limiter
    // faults on (moment_limiter::clock: 5 periods of its 100 Hz cycle).
    if !(args.rate_hz >= 20.0 && args.rate_hz <= 500.0) {
        bail!("--rate-hz must be in [20, 500]: the limiter faults on samples more than 50 ms apart");
    }
    if !(args.low_deg >= 0.0 && args.high_deg <= 85.0 && args.low_deg < args.high_deg) {
        bail!("--low-deg and --high-deg must satisfy 0 ≤ low < high ≤ 85");
    }
    let sim_args = SimulateArgs {
        case: args.case.clone(),
        list: false,
        load_kg: args.load_kg,
        duration: args.duration,
        profile: args.profile,
        direction: args.direction,
        step_ms: 2.0,
        output_every: 1,
        initial: InitialArg::Equilibrium,
        out: None,
        plot: None,
    };
    let (title, mut m) = maneuver(&sim_args)?;
    if args.case.is_none() {
        m.low_angle_deg = args.low_deg;
        m.high_angle_deg = args.high_deg;
    }
    m.settle_s = 1.0;
    let (options, dt) = synth_core::options_for_rate(args.rate_hz);
    let model = thesis_model()?;
    let samples = synth_core::simulate(&model, &m, &options)
        .map_err(|e| anyhow::anyhow!("simulation failed: {e}"))?;
    let sensors = SensorModel {
        seed: args.seed,
        friction_up_n: args.friction_up_n,
        friction_down_n: args.friction_down_n,
        noise_bar: args.noise_bar,
        noise_deg: args.noise_deg,
        pendulum_hz: args.pendulum_hz,
        pendulum_damping: args.pendulum_damping,
        rod_side_bar: args.rod_side_bar,
        open_p1_at_s: args.open_p1_at_s,
    };
    let rows = synth_core::synthesize(&samples, dt, args.hold_s, m.load_kg, &sensors);
    let mut f = std::io::BufWriter::new(std::fs::File::create(&args.out).with_context(|| format!("cannot create {}", args.out.display()))?);
    writeln!(f, "# crane-sim synth: {title}, {}°..{}°", m.low_angle_deg, m.high_angle_deg)?;
    writeln!(
        f,
        "# flexible model (12 elements, 4 modes), {} Hz, friction up {} N / down {} N, noise {} bar / {} deg, pendulum {} Hz zeta {}, seed {}",
        args.rate_hz, args.friction_up_n, args.friction_down_n, args.noise_bar, args.noise_deg, args.pendulum_hz, args.pendulum_damping, args.seed
    )?;
    writeln!(f, "{}", synth_core::LOG_HEADER)?;
    for row in &rows {
        writeln!(f, "{}", row.csv_line())?;
    }
    f.flush()?;
    let mut out = crate::stdout::stdout();
    writeln!(out, "wrote {} ({title})", args.out.display())?;
    out.flush()?;
    Ok(0)
}
