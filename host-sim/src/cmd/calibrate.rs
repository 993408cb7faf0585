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
//! Exit codes: 0 written; 1 a log could not be read, was not unloaded, or had
//! too few samples moving up or down.

use std::fs::File;
use std::io::BufReader;
use std::path::PathBuf;

use anyhow::Context as _;
use moment_limiter::calibration::CalibrationLearner;
use moment_limiter::limiter::{Limiter, LimiterConfig};
use moment_limiter::log_format::LogParser;

use super::replay::{read_line, CalibrationFile};

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
            let report = limiter.step_frame(&record.frame);
            match (report.fault, report.measurement) {
                (None, Some(m)) => learner
                    .observe(limiter.model(), &m)
                    .map_err(|e| anyhow::anyhow!("{name}: line {}: model: {e}", record.line))?,
                _ => faulted += 1,
            }
        }
        parser
            .finish()
            .map_err(|e| anyhow::anyhow!("{name}: {e}"))?;
        learner.end_of_log();
        if faulted > 0 {
            eprintln!("warning: {name}: {faulted} samples with a sensor or model fault left out");
        }
    }
    let cal = learner
        .finish(args.min_samples)
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    let (samples_up, samples_down) = learner.counts();
    let (r_up, r_down) = learner.mean_residuals_n().unwrap_or((f64::NAN, f64::NAN));
    let file = CalibrationFile {
        friction_up_n: cal.friction_up_n,
        friction_down_n: cal.friction_down_n,
        force_offset_n: cal.force_offset_n,
        p1_offset_bar: cal.p1_offset_bar,
        p2_offset_bar: cal.p2_offset_bar,
        angle_offset_deg: cal.angle_offset_deg,
        samples_up: Some(samples_up),
        samples_down: Some(samples_down),
        mean_residual_up_n: Some(r_up),
        mean_residual_down_n: Some(r_down),
    };
    let json = serde_json::to_string_pretty(&file)?;
    std::fs::write(&args.out, json + "\n")
        .with_context(|| format!("cannot write {}", args.out.display()))?;
    println!(
        "friction_up_n={:.1} friction_down_n={:.1} force_offset_n={:.1} samples_up={samples_up} samples_down={samples_down} -> {}",
        cal.friction_up_n,
        cal.friction_down_n,
        cal.force_offset_n,
        args.out.display()
    );
    Ok(0)
}
