//! `crane-sim synth`: a recorded-style sensor log of a simulated maneuver (SPEC §5).
//!
//! What the limiter's sensors would have recorded on the crane: the simulated
//! piston force plus cylinder friction (higher going up than coming down, the
//! hysteresis of the thesis's measured traces, Figs. 4.2–4.3), split into p1 and
//! p2 by eq. 4.1 with a small rod-side back pressure, transducer noise and the
//! 12-bit quantization of the 4–20 mA front end; the boom angle through an
//! oil-damped pendulum potentiometer (second-order lag) or a first-order lag
//! with noise and quantization; and the true hook load as the last column.
//! Any maneuver of `simulate` (rope modes, luffs, lift-off, maneuver files).

//! The sensor model itself is in [`crate::synth_core`] (shared with the
//! in-process acceptance tests); this module is its command line.

use super::simulate::{program, DirectionArg, ManeuverArgs};
use crate::model::thesis_model;
use anyhow::{bail, Context, Result};
use crate::synth_core::{self, FrictionLaw, PendulumSensor, SensorModel};
use std::io::Write;
use std::path::PathBuf;

/// Friction law on the command line.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum FrictionArg {
    /// Constant per direction (--friction-up-n / --friction-down-n).
    Constant,
    /// Seal friction a + b·|F|: a = --friction-*-n, b = --friction-*-b (fraction of the piston force).
    Seal,
    /// Viscous a + c·|v|: a = --friction-*-n, c = --friction-*-b (N per m/s of piston speed).
    Viscous,
    /// Stribeck F_s + (F_b − F_s)·exp(−(v/v_s)²): sliding F_s = --friction-*-n, breakaway
    /// F_b = --friction-*-b (N), v_s = --stribeck-speed-m-s.
    Stribeck,
}

/// Angle sensor dynamics on the command line.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum PendulumArg {
    /// Oil-damped pendulum (--pendulum-hz, --pendulum-damping).
    SecondOrder,
    /// First-order lag (--pendulum-tau-s).
    FirstOrder,
}

/// Arguments of `crane-sim synth`.
#[derive(clap::Args, Debug)]
pub struct SynthArgs {
    /// The maneuver (as for `simulate`).
    #[command(flatten)]
    maneuver: ManeuverArgs,
    /// Lower boom angle of the thesis move (deg; without --from-deg, --case or --maneuver).
    #[arg(long, default_value_t = 40.0)]
    low_deg: f64,
    /// Higher boom angle of the thesis move (deg).
    #[arg(long, default_value_t = 80.0)]
    high_deg: f64,
    /// Samples per second in the log (20–500; the limiter faults on gaps over 50 ms).
    #[arg(long, default_value_t = 50.0)]
    rate_hz: f64,
    /// Seed of the noise.
    #[arg(long, default_value_t = 1)]
    seed: u32,
    /// Friction law of the cylinder (both directions).
    #[arg(long, value_enum, default_value = "constant")]
    friction_law: FrictionArg,
    /// Cylinder friction while raising (N; the constant part): the piston force reads higher.
    #[arg(long, default_value_t = 12_000.0)]
    friction_up_n: f64,
    /// Cylinder friction while lowering (N; the constant part): the piston force reads lower.
    #[arg(long, default_value_t = 8_000.0)]
    friction_down_n: f64,
    /// Seal: fraction of |F|; viscous: N per m/s of piston speed; Stribeck: breakaway force, N (raising).
    #[arg(long, default_value_t = 0.0)]
    friction_up_b: f64,
    /// Seal: fraction of |F|; viscous: N per m/s of piston speed; Stribeck: breakaway force, N (lowering).
    #[arg(long, default_value_t = 0.0)]
    friction_down_b: f64,
    /// Time constant with which friction stuck at standstill relaxes (s; 0: at once).
    #[arg(long, default_value_t = 0.0)]
    standstill_release_s: f64,
    /// Stribeck speed of the piston (m/s; --friction-law stribeck).
    #[arg(long, default_value_t = 0.005)]
    stribeck_speed_m_s: f64,
    /// Boom rate over which the friction turns from one direction's to the other's (°/s): the
    /// friction while moving is its law times tanh(rate / this).
    #[arg(long, default_value_t = 0.2)]
    friction_onset_deg_s: f64,
    /// Standard deviation of the pressure noise (bar).
    #[arg(long, default_value_t = 0.3)]
    noise_bar: f64,
    /// Standard deviation of the angle noise (deg).
    #[arg(long, default_value_t = 0.03)]
    noise_deg: f64,
    /// Angle sensor dynamics.
    #[arg(long, value_enum, default_value = "second-order")]
    pendulum: PendulumArg,
    /// Natural frequency of the pendulum potentiometer (Hz).
    #[arg(long, default_value_t = 2.0)]
    pendulum_hz: f64,
    /// Damping ratio of the pendulum potentiometer (oil).
    #[arg(long, default_value_t = 0.7)]
    pendulum_damping: f64,
    /// Time constant of the first-order pendulum lag (s).
    #[arg(long, default_value_t = 0.2)]
    pendulum_tau_s: f64,
    /// Offset added to the angle reading (deg).
    #[arg(long, default_value_t = 0.0)]
    angle_offset_deg: f64,
    /// Offset added to both pressure readings (bar).
    #[arg(long, default_value_t = 0.0)]
    pressure_offset_bar: f64,
    /// Back pressure on the rod side (bar).
    #[arg(long, default_value_t = 4.0)]
    rod_side_bar: f64,
    /// Seconds of standstill recorded before the move (copies of the first sample).
    #[arg(long, default_value_t = 1.0)]
    hold_s: f64,
    /// Break the p1 loop (0 mA, reads −50 bar) from this time on (s): a wire break.
    #[arg(long)]
    open_p1_at_s: Option<f64>,
    /// Where to write the log.
    #[arg(long)]
    out: PathBuf,
}

fn law(kind: FrictionArg, a: f64, b: f64, stribeck_speed_m_s: f64) -> Result<FrictionLaw> {
    if !(a >= 0.0 && a.is_finite() && b >= 0.0 && b.is_finite()) {
        bail!("friction values must be finite and ≥ 0");
    }
    Ok(match kind {
        FrictionArg::Constant => FrictionLaw::Constant { force_n: a },
        FrictionArg::Seal => FrictionLaw::Seal { base_n: a, per_force: b },
        FrictionArg::Viscous => FrictionLaw::Viscous { base_n: a, per_m_s: b },
        FrictionArg::Stribeck => {
            if !(stribeck_speed_m_s > 0.0 && stribeck_speed_m_s <= 1.0) {
                bail!("--stribeck-speed-m-s must be in (0, 1] m/s");
            }
            if b < a {
                bail!("Stribeck friction: the breakaway force --friction-*-b ({b} N) must be at least the sliding force --friction-*-n ({a} N)");
            }
            FrictionLaw::Stribeck { sliding_n: a, breakaway_n: b, speed_m_s: stribeck_speed_m_s }
        }
    })
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
    let mut mv = args.maneuver.clone();
    // The log's standstill after the move: 1 s unless asked otherwise.
    mv.hold_after_s = Some(mv.hold_after_s.unwrap_or(1.0));
    let thesis_move = mv.case.is_none() && mv.maneuver.is_none() && mv.from_deg.is_none();
    if thesis_move && (args.low_deg != 40.0 || args.high_deg != 80.0) {
        let (a, b) = match mv.direction {
            DirectionArg::Up => (args.low_deg, args.high_deg),
            DirectionArg::Down => (args.high_deg, args.low_deg),
        };
        mv.from_deg = Some(a);
        mv.to_deg = Some(b);
        if mv.ramp_s.is_none() && (mv.duration == 30.0 || mv.duration == 10.0) {
            mv.ramp_s = Some(if mv.duration == 30.0 { 1.5 } else { 1.0 });
        }
    }
    let (title, program) = program(&mv)?;
    let pendulum = match args.pendulum {
        PendulumArg::SecondOrder => {
            if !(args.pendulum_hz > 0.0 && args.pendulum_damping > 0.0) {
                bail!("--pendulum-hz and --pendulum-damping must be > 0");
            }
            PendulumSensor::SecondOrder { hz: args.pendulum_hz, damping: args.pendulum_damping }
        }
        PendulumArg::FirstOrder => {
            if !(args.pendulum_tau_s > 0.0 && args.pendulum_tau_s <= 5.0) {
                bail!("--pendulum-tau-s must be in (0, 5] s");
            }
            PendulumSensor::FirstOrder { tau_s: args.pendulum_tau_s }
        }
    };
    if !(args.standstill_release_s >= 0.0 && args.standstill_release_s <= 60.0) {
        bail!("--standstill-release-s must be in [0, 60] s");
    }
    if !(args.friction_onset_deg_s > 0.0 && args.friction_onset_deg_s <= 5.0) {
        bail!("--friction-onset-deg-s must be in (0, 5] °/s");
    }
    let (options, dt) = synth_core::options_for_rate(args.rate_hz);
    let model = thesis_model()?;
    let samples = synth_core::simulate_program(&model, &program, &options)
        .map_err(|e| anyhow::anyhow!("simulation failed: {e}"))?;
    let sensors = SensorModel {
        seed: args.seed,
        friction_up: law(args.friction_law, args.friction_up_n, args.friction_up_b, args.stribeck_speed_m_s)?,
        friction_down: law(args.friction_law, args.friction_down_n, args.friction_down_b, args.stribeck_speed_m_s)?,
        standstill_release_s: args.standstill_release_s,
        friction_onset_deg_s: args.friction_onset_deg_s,
        noise_bar: args.noise_bar,
        noise_deg: args.noise_deg,
        pendulum,
        angle_offset_deg: args.angle_offset_deg,
        pressure_offset_bar: args.pressure_offset_bar,
        rod_side_bar: args.rod_side_bar,
        open_p1_at_s: args.open_p1_at_s,
    };
    let rows = synth_core::synthesize(&samples, dt, args.hold_s, program.end_load_kg(), &sensors);
    let mut f = std::io::BufWriter::new(std::fs::File::create(&args.out).with_context(|| format!("cannot create {}", args.out.display()))?);
    writeln!(f, "# crane-sim synth: {title}, {}°..{}°", program.start_deg, program.end_deg())?;
    writeln!(
        f,
        "# flexible model (12 elements, 4 modes), {} Hz, friction up {:?} / down {:?}, standstill release {} s, friction onset {} deg/s, noise {} bar / {} deg, angle sensor {:?}, offsets {} deg / {} bar, seed {}",
        args.rate_hz, sensors.friction_up, sensors.friction_down, args.standstill_release_s, args.friction_onset_deg_s, args.noise_bar, args.noise_deg, pendulum, args.angle_offset_deg, args.pressure_offset_bar, args.seed
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
