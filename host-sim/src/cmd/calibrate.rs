//! `crane-sim calibrate UNLOADED.csv... [--known-load-kg W LOADED.csv]... --out CAL.json`
//!
//! Learns the angle sensor's lag (`moment_limiter::sensor_lag`, from the
//! unloaded runs: searched as a first-order lag and as pendulums of three
//! dampings, the lag on a steady rate of the shape that fits best), then
//! the cylinder's friction law per direction, friction = a + b·|F| + c·|ω|
//! (c, the part that grows with the boom's rate ω, where runs at two speeds
//! show it), and the force offset from unloaded boom-up and boom-down logs and,
//! when given, runs with a known test weight W (SAE J376 calibrates with test
//! weights): each log is run through the limiter's own signal chain
//! (filters, direction of motion) with no calibration, and
//! `moment_limiter::calibration::CalibrationLearner` fits the residual
//! between the measured piston force and the model's force at the run's
//! load, per direction, over the samples in steady motion (ramps and
//! standstill left out), by least squares (see that module for the fit, the
//! offset at rest and when b is not observable). Samples in which the
//! limiter found a fault are left out and counted.
//!
//! Refused (exit 1, nothing written): a log with p1 below p2 on average
//! (swapped columns), an "unloaded" log whose `true_load_kg` column is not 0
//! or whose boom at rest reads a load, too little steady motion in a
//! direction, a known-load run whose `true_load_kg` column or whose force
//! disagrees with its stated weight, a law out of the schema's bounds.
//!
//! The file is written in the calibration schema
//! (`moment_limiter::tools::config_file`, version 4) and only if every value is
//! within its physical bounds, so the replay and the firmware accept it.
//!
//! Exit codes: 0 written; 1 refused (above) or a log could not be read.

use std::io::{BufReader, Write as _};
use std::path::{Path, PathBuf};

use anyhow::Context as _;
use moment_limiter::calibration::{CalibrationLearner, Learned, SteadyMotion};
use moment_limiter::cycle::{Limiter, LimiterConfig};
use moment_limiter::fault::Fault;
use moment_limiter::io::{Frame, Measurement};
use moment_limiter::seal_release::{ReleaseFit, RELEASE_CANDIDATES_S};
use moment_limiter::sensor_lag::{choose_sensor, fit_lag, SensorCandidate, SensorShape, SENSOR_SHAPES};
use moment_limiter::tools::log_format::LogParser;
use rayon::prelude::*;

use moment_limiter::tools::config_file;

use super::replay::read_line;

/// Largest force at rest that an empty hook's runs may show as a load (N):
/// 10 kN is about 250 kg at 60°. Where the rest samples cannot tell a load
/// from a zero offset (rest at one angle), the largest plausible offset too:
/// transducer zero tolerances (2 % of span, ±4 bar ≈ ±17 kN on the piston
/// side) are far above what a calibrated crane shows (±2 kN).
const REST_RESIDUAL_LIMIT_N: f64 = 10_000.0;

/// Arguments of `crane-sim calibrate`.
#[derive(clap::Args, Debug)]
pub struct CalibrateArgs {
    /// Unloaded logs (docs/log-format.md): at least one boom-up and one boom-down run;
    /// runs at two speeds (10 s and 30 s luffs) also learn a friction that grows with the speed.
    #[arg(required = true)]
    pub logs: Vec<PathBuf>,
    /// A run with a known test weight on the hook: `--known-load-kg W LOADED.csv`
    /// (repeatable); its steady samples enter the fit at the model's force for W.
    #[arg(long, num_args = 2, value_names = ["KG", "LOG"], action = clap::ArgAction::Append, allow_negative_numbers = true)]
    pub known_load_kg: Vec<String>,
    /// Where to write the calibration (JSON).
    #[arg(long)]
    pub out: PathBuf,
    /// Fewest samples needed per direction.
    #[arg(long, default_value_t = 50)]
    pub min_samples: u32,
}

/// Largest disagreement of a known-load run with its stated weight: at
/// rest (seals released, no friction) 5 % of W + 100 kg; in motion
/// (against the unloaded runs' law, whose b may not be observable) 15 % of
/// W + 200 kg.
const KNOWN_AT_REST: (f64, f64) = (0.05, 100.0);
const KNOWN_IN_MOTION: (f64, f64) = (0.15, 200.0);

/// One log, read and checked.
struct Log {
    name: String,
    load_kg: f64,
    frames: Vec<(u32, Frame<f64>)>,
}

/// One log, learned on its own.
struct Run {
    name: String,
    load_kg: f64,
    learner: CalibrationLearner<f64>,
    /// The limiter's measurements of the log (for the residual pass).
    measurements: Vec<Measurement<f64>>,
}

/// Reads a log and checks it is a run of the stated load with the
/// pressures the right way round.
fn read_log(path: &Path, load_kg: f64) -> anyhow::Result<Log> {
    let name = path.display().to_string();
    let file = super::replay::open_log(path)?;
    let mut frames = Vec::new();
    let mut parser = LogParser::<f64>::new();
    let mut reader = BufReader::new(file);
    let mut buf = Vec::new();
    let mut pressures = super::replay::PressureMeans::default();
    let mut angles = super::replay::AngleSpan::default();
    loop {
        let line = match read_line(&mut reader, &mut buf) {
            Ok(Some(line)) => line,
            Ok(None) => break,
            Err(kind) => anyhow::bail!("{name}: {}", parser.reject_next_line(kind)),
        };
        let Some(record) = parser
            .feed_line(&line)
            .map_err(|e| anyhow::anyhow!("{name}: {e}"))?
        else {
            continue;
        };
        if let Some(w) = record.true_load_kg {
            if load_kg == 0.0 {
                anyhow::ensure!(
                    w.abs() < 1.0,
                    "{name}: line {}: true_load_kg is {w}, calibration needs unloaded runs (give a run with a test weight as --known-load-kg W {name})",
                    record.line
                );
            } else {
                anyhow::ensure!(
                    (w - load_kg).abs() <= 0.01 * load_kg + 1.0,
                    "{name}: line {}: true_load_kg is {w}, but --known-load-kg says {load_kg} kg: the run is not of the stated test weight",
                    record.line
                );
            }
        }
        pressures.add(record.frame.p1_bar, record.frame.p2_bar);
        angles.add(record.frame.boom_angle_deg);
        frames.push((record.line, record.frame));
    }
    parser
        .finish()
        .map_err(|e| anyhow::anyhow!("{name}: {e}"))?;
    // A calibration run luffs through tens of degrees; one that never
    // leaves horizontal is a column in radians far more likely than a run.
    if let Some(hint) = angles.radians_hint() {
        anyhow::bail!("{name}: {hint}; a calibration run luffs the boom through tens of degrees");
    }
    if let Some(hint) = pressures.swapped_hint() {
        anyhow::bail!("{name}: {hint}");
    }
    Ok(Log { name, load_kg, frames })
}

/// Runs a log through the limiter, its angle sensor's lag taken as
/// `lag_s`, and its own learner; `keep` keeps the measurements (for the
/// residual pass) and warns of faulted samples.
fn learn_log(log: &Log, lag_s: f64, keep: bool) -> anyhow::Result<Run> {
    learn_log_with(log, SensorCandidate::first_order(lag_s), keep, SteadyMotion::standard())
}

/// [`learn_log`] with the angle sensor taken as `sensor` (the lag search's
/// candidates) and the samples of `steady`.
fn learn_log_with(log: &Log, sensor: SensorCandidate<f64>, keep: bool, steady: SteadyMotion<f64>) -> anyhow::Result<Run> {
    let name = &log.name;
    let config = LimiterConfig { angle_sensor_lag_s: sensor.alignment_lag_s(), ..LimiterConfig::standard() };
    let mut pressure_lag = sensor.pressure_lag();
    let mut limiter =
        Limiter::new(crate::model::thesis_model()?, config).map_err(|e| anyhow::anyhow!("{e}"))?;
    let mut learner = CalibrationLearner::<f64>::with_steady_motion(steady).loaded(log.load_kg);
    let mut measurements = Vec::new();
    let mut faulted = 0u32;
    // The first faulted sample's line and fault: what the user looks up.
    let mut first_fault: Option<(u32, String)> = None;
    for (line, frame) in &log.frames {
        let report = limiter.step_frame(&pressure_lag.apply(*frame));
        // An implausibly negative load is the limiter's verdict on an
        // uncalibrated estimate, and a run recorded from the middle of a move
        // has no weighing at rest to start from; the learner needs neither,
        // only the measurement itself.
        match (report.fault, report.measurement) {
            (None | Some(Fault::ImplausibleLoad | Fault::StartedMoving), Some(m)) => {
                learner
                    .observe(limiter.model(), &m)
                    .map_err(|e| anyhow::anyhow!("{name}: line {line}: model: {e}"))?;
                if keep {
                    measurements.push(m);
                }
            }
            (fault, _) => {
                faulted += 1;
                if first_fault.is_none() {
                    let why = fault.map_or_else(|| "no measurement".to_string(), |f| f.to_string());
                    first_fault = Some((*line, why));
                }
            }
        }
    }
    learner.end_of_log();
    if keep && faulted > 0 {
        let first = first_fault.map_or_else(String::new, |(line, why)| format!(" (the first at line {line}: {why})"));
        eprintln!("warning: {name}: {faulted} samples with a sensor or model fault left out{first}");
    }
    Ok(Run {
        name: name.clone(),
        load_kg: log.load_kg,
        learner,
        measurements,
    })
}

/// The known-load pairs of the command line.
fn known_loads(args: &CalibrateArgs) -> anyhow::Result<Vec<(f64, PathBuf)>> {
    args.known_load_kg
        .chunks(2)
        .map(|pair| {
            let [kg, log] = pair else {
                anyhow::bail!("--known-load-kg needs a weight and a log: --known-load-kg W LOADED.csv");
            };
            let w: f64 = kg.trim().parse().map_err(|_| {
                anyhow::anyhow!("--known-load-kg {kg} {log}: `{kg}` is not a weight in kg")
            })?;
            anyhow::ensure!(
                w.is_finite() && (1.0..=50_000.0).contains(&w),
                "--known-load-kg {kg} {log}: the test weight must be between 1 and 50000 kg"
            );
            Ok((w, PathBuf::from(log)))
        })
        .collect()
}

/// The unloaded runs' own readings at rest must agree: a zero offset is the
/// same in every run of the crane, a load left on the hook is in one run
/// only. Their mean rest residuals may differ by at most
/// [`REST_RESIDUAL_LIMIT_N`]. Together the runs cannot show it: an empty up
/// run and a down run with 800 kg read a load and an offset neither has
/// (the load-or-offset check below passed them), and the fit learned
/// 5.8 kN of offset, up friction 6.2 kN for 12 kN and down friction 0 for
/// 8 kN (residual rms 23 kN), which reads every lowering low.
fn unloaded_runs_agree_at_rest(runs: &[Run]) -> anyhow::Result<()> {
    // Each unloaded run's mean rest residual (N) and the load it reads (kg).
    let rests: Vec<(&Run, f64, Option<f64>)> = runs
        .iter()
        .filter(|r| r.load_kg == 0.0)
        .filter_map(|r| r.learner.mean_rest_residual_n().map(|n| (r, n, r.learner.rest_load_kg())))
        .collect();
    let span = |v: &mut dyn Iterator<Item = f64>| v.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| (lo.min(x), hi.max(x)));
    let (lo, hi) = span(&mut rests.iter().map(|x| x.1));
    // The same load on every run differs in N between runs that rest at
    // other angles, but not in kg: that is the check below's, which says so.
    let (kg_lo, kg_hi) = span(&mut rests.iter().filter_map(|x| x.2));
    let weighed = rests.iter().all(|x| x.2.is_some());
    let same_load = weighed && kg_hi - kg_lo <= 0.2 * kg_lo.abs().max(kg_hi.abs());
    if rests.len() < 2 || hi - lo <= REST_RESIDUAL_LIMIT_N || same_load {
        return Ok(());
    }
    let each: Vec<String> = rests
        .iter()
        .map(|(r, n, kg)| match kg {
            Some(kg) => format!("{} {:+.1} kN (about {kg:.0} kg)", r.name, n / 1e3),
            None => format!("{} {:+.1} kN", r.name, n / 1e3),
        })
        .collect();
    anyhow::bail!(
        "the unloaded runs disagree at rest by {:.1} kN (at most {:.0} kN; a zero offset is the same in every run, a load is not): {}. Calibration needs every run with an empty hook",
        (hi - lo) / 1e3,
        REST_RESIDUAL_LIMIT_N / 1e3,
        each.join(", ")
    )
}

/// How far below zero the unloaded runs' mean friction may read in either
/// direction (N): the force offset is learned within about 0.5 kN, and an
/// empty crane with no friction at all reads +0.1 kN.
const NEGATIVE_FRICTION_LIMIT_N: f64 = 2_000.0;

/// Friction opposes the motion: raising, the cylinder reads more force than
/// the boom at rest needs, lowering less. A mean friction below
/// −[`NEGATIVE_FRICTION_LIMIT_N`] is no friction. 300 kg on the hook of the
/// down run alone (the up run empty) reads −3.1 kN lowering; the fit would
/// clamp it to a friction of 0 where the crane has 7.7 kN, which reads
/// every lowering low. Lighter loads show as a low friction (100 kg: 4.3 kN
/// for 7.7 down; on the up run alone 7.2 kN for 12.2 up) that no check here
/// can tell from a crane's own.
fn friction_opposes_the_motion(learned: &Learned<f64>) -> anyhow::Result<()> {
    for (dir, f, reads) in [("raising", &learned.up, "less"), ("lowering", &learned.down, "more")] {
        anyhow::ensure!(
            f.mean_friction_n >= -NEGATIVE_FRICTION_LIMIT_N,
            "{dir}, the unloaded runs read {:.1} kN {reads} force than the boom at rest gives (a friction helping the motion, which no seal does; at most {:.0} kN is noise): a load on the hook in the {dir} run(s), or runs of another crane",
            -f.mean_friction_n / 1e3,
            NEGATIVE_FRICTION_LIMIT_N / 1e3
        );
    }
    Ok(())
}

/// Share of the fastest unloaded run's steady rate (of its direction) a run
/// needs to enter the lag search: a lag shows in proportion to the rate, so
/// a 30 s run beside a 10 s one adds three times the samples and a third of
/// the lag's signature, and with it the search's residual went flat (the
/// lag not learned) where the 10 s runs alone learned it.
const LAG_RUN_SPEED_SHARE: f64 = 0.6;

/// The unloaded runs the angle sensor's lag is searched over: those at
/// least [`LAG_RUN_SPEED_SHARE`] as fast as the fastest of their direction
/// (each run's direction is the one it has more steady samples of; its
/// rate their mean, through the limiter at the lag `lag_s`).
fn fastest_unloaded_runs(logs: &[Log], lag_s: f64) -> anyhow::Result<Vec<&Log>> {
    let mut rated = Vec::new();
    for log in logs.iter().filter(|l| l.load_kg == 0.0) {
        let (up, down) = learn_log(log, lag_s, false)?.learner.moments();
        let (is_up, rate) = if up.n >= down.n { (true, up.mean_v) } else { (false, down.mean_v) };
        rated.push((log, is_up, rate));
    }
    let fastest = |dir: bool| rated.iter().filter(|r| r.1 == dir).map(|r| r.2).fold(0.0f64, f64::max);
    let (up_max, down_max) = (fastest(true), fastest(false));
    Ok(rated
        .iter()
        .filter(|(_, is_up, rate)| *rate >= LAG_RUN_SPEED_SHARE * if *is_up { up_max } else { down_max })
        .map(|r| r.0)
        .collect())
}

/// How `crane-sim calibrate` names the sensor shape that fitted best, with
/// its steady-rate lag `lag_s`.
fn shape_text(shape: SensorShape, lag_s: f64) -> String {
    match shape {
        SensorShape::FirstOrder => "a first-order lag fits best".to_string(),
        SensorShape::Pendulum { damping } => format!(
            "a pendulum of {:.2} Hz and damping {damping} fits best",
            2.0 * damping / lag_s / (2.0 * std::f64::consts::PI)
        ),
    }
}

/// Runs the subcommand; returns the exit code.
pub fn run(args: CalibrateArgs) -> anyhow::Result<u8> {
    let known = known_loads(&args)?;
    let mut logs = Vec::new();
    for path in &args.logs {
        logs.push(read_log(path, 0.0)?);
    }
    for (w, path) in &known {
        logs.push(read_log(path, *w)?);
    }
    // The angle sensor's lag: the one that leaves the least residual
    // (moment_limiter::sensor_lag), over the unloaded runs. Not the
    // known-load runs: the load's swing and bounce in their ramps, which the
    // model does not know, dominate their residual (with a 3 t test weight
    // luffed in 30 s the search's minimum went to the 0.5 s bound). Each
    // sensor shape is its own search, so they run side by side.
    let default_lag_s = LimiterConfig::<f64>::standard().angle_sensor_lag_s;
    let lag_logs = fastest_unloaded_runs(&logs, default_lag_s)?;
    let fits = SENSOR_SHAPES
        .par_iter()
        .map(|&shape| {
            // Each run's own lines: runs at two speeds carry two frictions
            // where the friction grows with the rate, which one line per
            // direction over both cannot fit whatever the lag (the residual
            // went flat, and the lag was not learned).
            let fit = fit_lag(default_lag_s, |lag_s| {
                let (mut ssr, mut n) = (0.0, 0u32);
                for log in &lag_logs {
                    let (s, k) = learn_log_with(log, SensorCandidate { shape, lag_s }, false, SteadyMotion::lag_search())?.learner.line_ssr();
                    ssr += s;
                    n = n.saturating_add(k);
                }
                anyhow::Ok((ssr, n))
            })?;
            anyhow::Ok((shape, fit))
        })
        .collect::<anyhow::Result<Vec<_>>>()?;
    let sensor = choose_sensor(&fits).context("no sensor shape searched")?;
    let lag = sensor.lag;
    let mut runs = Vec::new();
    for log in &logs {
        runs.push(learn_log(log, lag.lag_s, true)?);
    }
    let mut unloaded = CalibrationLearner::<f64>::new();
    for r in runs.iter().filter(|r| r.load_kg == 0.0) {
        unloaded.merge(&r.learner);
    }
    // A load on the hook reads as a large force at rest: refuse it before
    // it becomes an offset. Rest at angles far enough apart (the up run
    // starts at its low end, the down run at its high end) tells the two
    // apart: an offset is the same at every angle, a load's force is not.
    // Then only the load is held to the limit (as the force it puts on the
    // cylinder at the rest samples' mean angle), and the offset to the
    // schema's bound below: two transducers within their ±2 % zero
    // tolerance can together be 12 kN off, and such a crane was refused as
    // carrying 330 kg. Rest at one angle alone cannot tell them apart, and
    // the whole rest residual is held to the limit.
    unloaded_runs_agree_at_rest(&runs)?;
    if let (Some(rest), Some(kg)) = (unloaded.mean_rest_residual_n(), unloaded.rest_load_kg()) {
        match unloaded.rest_split() {
            Some((offset_n, load_kg, per_kg)) => anyhow::ensure!(
                (load_kg * per_kg).abs() <= REST_RESIDUAL_LIMIT_N,
                "the boom at rest reads about {load_kg:.0} kg on the hook ({:.1} kN at the cylinder, besides a zero offset of {:.1} kN; at most {:.0} kN of load is plausible): calibration needs runs with an empty hook",
                load_kg * per_kg / 1e3,
                offset_n / 1e3,
                REST_RESIDUAL_LIMIT_N / 1e3
            ),
            None => anyhow::ensure!(
                rest.abs() <= REST_RESIDUAL_LIMIT_N,
                "the boom at rest reads {:+.1} kN off the empty crane's model (about {kg:.0} kg on the hook; at most {:.0} kN of offset is plausible when the runs rest at one angle only): calibration needs runs with an empty hook",
                rest / 1e3,
                REST_RESIDUAL_LIMIT_N / 1e3
            ),
        }
    }
    let min = args.min_samples;
    let too_few = |e| {
        anyhow::anyhow!("{e}; each direction needs at least {min} samples of steady luffing (3 s after the start, ≥ 0.5 °/s)")
    };
    let base = unloaded.fit(min).map_err(too_few)?;
    friction_opposes_the_motion(&base)?;
    // Each known-load run against the unloaded runs: at rest the seals
    // release and the force is the load's alone; in motion, the unloaded law.
    let mut all = unloaded.clone();
    for r in runs.iter().filter(|r| r.load_kg > 0.0) {
        let l = &r.learner;
        let w = r.load_kg;
        let offset = base.calibration.force_offset_n;
        let (what, err_kg, (share, floor)) = match (l.rest_count() >= min, l.rest_load_kg(), l.mean_rest_residual_n()) {
            (true, Some(kg), Some(res)) if res != 0.0 => {
                // rest_load_kg = res/per_kg: the offset's share taken out.
                ("at rest", kg * (res - offset) / res, KNOWN_AT_REST)
            }
            _ => {
                let per_kg = l.steady_per_kg().filter(|p| *p > 0.0);
                let res = l.mean_law_residual_n(&base.calibration);
                let (Some(per_kg), Some(res)) = (per_kg, res) else {
                    anyhow::bail!("{}: the run with --known-load-kg {w} has neither {min} samples at rest nor steady motion: it cannot be checked against its weight", r.name);
                };
                ("in steady motion", res / per_kg, KNOWN_IN_MOTION)
            }
        };
        let limit = share * w + floor;
        anyhow::ensure!(
            err_kg.abs() <= limit,
            "{}: the run said to carry {w:.0} kg reads {:.0} kg {what} against the unloaded runs (off by {err_kg:+.0} kg, more than the {limit:.0} kg a calibration tolerates): check the test weight, its rigging (hook block, slings) and that the log is of this crane",
            r.name,
            w + err_kg
        );
        all.merge(l);
    }
    // c only where the unloaded runs show it: test weights are luffed
    // slowly, and their runs' speed would stand for their load.
    let learned = all.fit_with_rates(min, (base.up.rate_observable, base.down.rate_observable)).map_err(too_few)?;
    let cal = moment_limiter::load_estimate::Calibration {
        angle_sensor_lag_s: Some(lag.lag_s),
        ..learned.calibration
    };
    let (samples_up, samples_down) = all.counts();
    // Only a file the reader (host and firmware) accepts is written.
    config_file::check_calibration(&cal).map_err(|e| {
        anyhow::anyhow!("the learned calibration is implausible, not written: {e}; check that the logs are runs of this crane (unloaded, or of the stated test weight)")
    })?;
    // The residual pass: the largest |residual| of the law, per direction.
    let model = crate::model::thesis_model()?;
    let mut max = (0.0f64, 0.0f64);
    for r in &runs {
        let mut check = CalibrationLearner::checking(cal, r.load_kg);
        for m in &r.measurements {
            check
                .observe(&model, m)
                .map_err(|e| anyhow::anyhow!("{}: model: {e}", r.name))?;
        }
        check.end_of_log();
        let (u, d) = check.max_residual_n();
        max = (max.0.max(u), max.1.max(d));
    }
    let mut json = String::new();
    config_file::write_calibration_json(&mut json, &cal)?;
    std::fs::write(&args.out, json)
        .with_context(|| format!("cannot write {}", args.out.display()))?;
    let mut out = crate::stdout::stdout();
    writeln!(
        out,
        "friction_up_n={:.1} friction_up_per_force={:.5} friction_down_n={:.1} friction_down_per_force={:.5} friction_up_per_rate={:.0} friction_down_per_rate={:.0} force_offset_n={:.1} angle_sensor_lag_s={:.3} seal_release_up_s={:.2} samples_up={samples_up} samples_down={samples_down} -> {}",
        cal.friction_up_n,
        cal.friction_up_per_force,
        cal.friction_down_n,
        cal.friction_down_per_force,
        cal.friction_up_per_rate,
        cal.friction_down_per_rate,
        cal.force_offset_n,
        lag.lag_s,
        cal.seal_release_up_s.unwrap_or(moment_limiter::cycle::DEFAULT_SEAL_RELEASE_S),
        args.out.display()
    )?;
    let runs_text = if known.is_empty() {
        format!("{} unloaded run(s)", args.logs.len())
    } else {
        let w: Vec<String> = known.iter().map(|(w, _)| format!("{w:.0}")).collect();
        format!("{} unloaded run(s) and test weights {} kg", args.logs.len(), w.join(", "))
    };
    writeln!(out, "fit over {runs_text}: friction = a + b*|F| + c*|w| per direction (w the boom rate, rad/s)")?;
    for (dir, f, unloaded_fit, mx) in [("up", learned.up, base.up, max.0), ("down", learned.down, base.down, max.1)] {
        let b_note = if f.slope_observable && f.raw_b < 0.0 {
            format!(
                "b = 0: the fitted slope {:.5} +- {:.5} is negative (a friction falling with pressure is noise on a constant law), a refitted",
                f.raw_b, f.b_se
            )
        } else if f.slope_observable {
            format!(
                "b learned (slope {:.5} +- {:.5}, force {:.1} +- {:.1} kN)",
                f.raw_b,
                f.b_se,
                f.force_mean_n / 1e3,
                f.force_sd_n / 1e3
            )
        } else {
            format!(
                "b NOT observable (force spread {:.1} kN of {:.1} kN, slope {:.5} +- {:.5}): b = 0; add a --known-load-kg run",
                f.force_sd_n / 1e3,
                f.force_mean_n / 1e3,
                f.raw_b,
                f.b_se
            )
        };
        let c_note = if f.rate_observable {
            format!(
                "c learned ({:.0} +- {:.0} N*s/rad, rate {:.3} +- {:.3} rad/s)",
                f.c, f.c_se, f.rate_mean, f.rate_sd
            )
        } else {
            format!(
                "c NOT observable or not above 0 (the unloaded runs' rate spread {:.3} of {:.3} rad/s): c = 0, the constant part holds the friction at these runs' speed; add unloaded runs at another speed (a 30 s luff besides the 10 s one)",
                unloaded_fit.rate_sd, unloaded_fit.rate_mean
            )
        };
        writeln!(
            out,
            "  {dir:<4} a={:.1} N b={:.5} c={:.0} N*s/rad samples={} residual rms={:.1} N max={:.1} N; {b_note}; {c_note}",
            f.a_n, f.b, f.c, f.n, f.rms_n, mx
        )?;
    }
    if lag.observable {
        writeln!(
            out,
            "  angle sensor lag {:.3} s learned ({}; first-order equivalent on a steady rate; residual rms {:.1} N, +{:.0} % at {:.2} s off, {:.1} N at the default {:.3} s)",
            lag.lag_s,
            shape_text(sensor.shape, lag.lag_s),
            lag.rms_n,
            lag.rms_rise * 100.0,
            moment_limiter::sensor_lag::LAG_PROBE_S,
            lag.rms_at_default_n,
            LimiterConfig::<f64>::standard().angle_sensor_lag_s
        )?;
    } else {
        writeln!(
            out,
            "  angle sensor lag NOT observable (residual flat: +{:.1} % rms at {:.2} s from its minimum at {:.3} s, {} % needed): the default {:.3} s kept; give longer runs over a wider angle span",
            lag.rms_rise * 100.0,
            moment_limiter::sensor_lag::LAG_PROBE_S,
            lag.best_s,
            moment_limiter::sensor_lag::MIN_RMS_RISE * 100.0,
            lag.lag_s
        )?;
    }
    let default_release_s = moment_limiter::cycle::DEFAULT_SEAL_RELEASE_S;
    let release_rms = |r: &ReleaseFit<f64>, s: f64| RELEASE_CANDIDATES_S.iter().zip(r.rms_n).find(|(c, _)| **c == s).map_or(f64::NAN, |(_, e)| e);
    match (learned.release, cal.seal_release_up_s) {
        (Some(r), Some(s)) => writeln!(
            out,
            "  seals' release after a raise {s:.2} s learned (counted from when the limiter sees the stop; {} samples at rest after the up runs' stops, residual rms {:.1} N, {:.1} N at the default {default_release_s:.2} s; after a lowering the default is kept, see docs/calibration.md)",
            r.samples,
            release_rms(&r, s),
            release_rms(&r, default_release_s)
        )?,
        (Some(r), None) => writeln!(
            out,
            "  seals' release NOT observable (samples at rest after the up runs' stops: {}, {min} needed; residual rms {:.1} N at best against {:.1} N at worst, at most half of it needed): the default {default_release_s:.2} s kept; let each up run rest 5 s after its stop",
            r.samples,
            r.rms_n.iter().copied().fold(f64::INFINITY, f64::min),
            r.rms_n.iter().copied().fold(0.0, f64::max)
        )?,
        (None, _) => writeln!(
            out,
            "  seals' release NOT observable (no rest after the up runs' stops): the default {default_release_s:.2} s kept; let each up run rest 5 s after its stop"
        )?,
    }
    writeln!(
        out,
        "learned: friction law per direction, force offset ({}), angle sensor lag ({}), seals' release ({}); not observable, left 0: p1/p2 zero offsets (a common offset is the force offset), pendulum offset",
        if learned.offset_from_rest {
            "from the boom at rest"
        } else {
            "no rest samples: symmetric split of up and down"
        },
        if lag.observable { "from the residual's shape in motion" } else { "default kept" },
        if cal.seal_release_up_s.is_some() { "from the rest after the raises" } else { "default kept" }
    )?;
    out.flush()?;
    Ok(0)
}
