//! `crane-sim calibrate UNLOADED.csv... --out CAL.json`
//!
//! Learns the friction correction from unloaded boom-up and boom-down logs:
//! each log is run through the limiter's own signal chain (filters, direction
//! of motion) with no calibration, and
//! `moment_limiter::calibration::CalibrationLearner` averages the difference
//! between the measured piston force and the model's force at W = 0, per
//! direction, over the samples in steady motion (ramps and standstill left
//! out) (see that module for why the offset/friction split is
//! symmetric). Samples in which the limiter found a fault are left out and
//! counted. A log with a `true_load_kg` column that is not 0 is refused.
//!
//! The file is written in the calibration schema
//! (`moment_limiter::tools::config_file`, version 1) and only if every value is
//! within its physical bounds, so the replay and the firmware accept it.
//!
//! Exit codes: 0 written; 1 a log could not be read, was not unloaded, had
//! too few samples moving up or down, or gave values out of bounds.

use std::fs::File;
use std::io::{BufReader, Write as _};
use std::path::PathBuf;

use anyhow::Context as _;
use moment_limiter::calibration::CalibrationLearner;
use moment_limiter::cycle::{Limiter, LimiterConfig};
use moment_limiter::fault::Fault;
use moment_limiter::tools::log_format::LogParser;

use moment_limiter::tools::config_file;

use super::replay::read_line;

/// Largest plausible force offset of an empty hook at rest (N): transducer
/// zero tolerances (2 % of span, ±4 bar ≈ ±17 kN on the piston side) are
/// far above what a calibrated crane shows (±2 kN); 10 kN is about 250 kg
/// at 60°.
const REST_RESIDUAL_LIMIT_N: f64 = 10_000.0;

/// Arguments of `crane-sim calibrate`.
#[derive(clap::Args, Debug)]
pub struct CalibrateArgs {
    /// Unloaded logs (docs/log-format.md): at least one boom-up and one boom-down run.
    #[arg(required = true)]
    pub logs: Vec<PathBuf>,
    /// Where to write the calibration (JSON).
    #[arg(long)]
    pub out: PathBuf,
    /// Fewest samples needed per direction.
    #[arg(long, default_value_t = 50)]
    pub min_samples: u32,
}

/// Runs the subcommand; returns the exit code.
pub fn run(args: CalibrateArgs) -> anyhow::Result<u8> {
    let mut learner = CalibrationLearner::<f64>::new();
    for path in &args.logs {
        let name = path.display();
        let file = File::open(path).with_context(|| format!("cannot open log {name}"))?;
        let mut limiter = Limiter::new(crate::model::thesis_model()?, LimiterConfig::standard())
            .map_err(|e| anyhow::anyhow!("{e}"))?;
        let mut parser = LogParser::<f64>::new();
        let mut reader = BufReader::new(file);
        let mut buf = Vec::new();
        let mut faulted = 0u32;
        // Mean pressures of the log: an unloaded boom hangs on the piston
        // side, so p1 far above p2 (p2 above p1: the columns are swapped).
        let (mut p1_sum, mut p2_sum, mut n_p) = (0.0f64, 0.0f64, 0u32);
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
                anyhow::ensure!(
                    w.abs() < 1.0,
                    "{name}: line {}: true_load_kg is {w}, calibration needs unloaded runs",
                    record.line
                );
            }
            p1_sum += record.frame.p1_bar;
            p2_sum += record.frame.p2_bar;
            n_p += 1;
            let report = limiter.step_frame(&record.frame);
            // An implausibly negative load is the limiter's verdict on an
            // uncalibrated estimate; the learner needs the measurement itself.
            match (report.fault, report.measurement) {
                (None | Some(Fault::ImplausibleLoad), Some(m)) => learner
                    .observe(limiter.model(), &m)
                    .map_err(|e| anyhow::anyhow!("{name}: line {}: model: {e}", record.line))?,
                _ => faulted += 1,
            }
        }
        parser
            .finish()
            .map_err(|e| anyhow::anyhow!("{name}: {e}"))?;
        if n_p > 0 {
            let (p1, p2) = (p1_sum / f64::from(n_p), p2_sum / f64::from(n_p));
            anyhow::ensure!(
                p1 > p2,
                "{name}: p1 (piston side) reads {p1:.1} bar on average and p2 (rod side) {p2:.1} bar: the boom hangs on the piston side, so p1_bar and p2_bar look swapped (check the wiring or the log's columns)"
            );
        }
        learner.end_of_log();
        if faulted > 0 {
            eprintln!("warning: {name}: {faulted} samples with a sensor or model fault left out");
        }
    }
    // A load on the hook reads as a large force at rest: refuse it before
    // it becomes an offset.
    if let (Some(rest), Some(kg)) = (learner.mean_rest_residual_n(), learner.rest_load_kg()) {
        anyhow::ensure!(
            rest.abs() <= REST_RESIDUAL_LIMIT_N,
            "the boom at rest reads {:.1} kN above the empty crane's model (about {kg:.0} kg on the hook; at most {:.0} kN of offset is plausible): calibration needs runs with an empty hook",
            rest / 1e3,
            REST_RESIDUAL_LIMIT_N / 1e3
        );
    }
    let cal = learner
        .finish(args.min_samples)
        .map_err(|e| anyhow::anyhow!("{e}; each direction needs at least {} samples of steady luffing (1.5 s after the start, ≥ 0.5 °/s)", args.min_samples))?;
    let (samples_up, samples_down) = learner.counts();
    // Only a file the reader (host and firmware) accepts is written.
    config_file::check_calibration(&cal).map_err(|e| {
        anyhow::anyhow!("the learned calibration is implausible, not written: {e}; check that the logs are unloaded runs of this crane")
    })?;
    let mut json = String::new();
    config_file::write_calibration_json(&mut json, &cal)?;
    std::fs::write(&args.out, json)
        .with_context(|| format!("cannot write {}", args.out.display()))?;
    let mut out = crate::stdout::stdout();
    writeln!(
        out,
        "friction_up_n={:.1} friction_down_n={:.1} force_offset_n={:.1} samples_up={samples_up} samples_down={samples_down} -> {}",
        cal.friction_up_n,
        cal.friction_down_n,
        cal.force_offset_n,
        args.out.display()
    )?;
    out.flush()?;
    Ok(0)
}
