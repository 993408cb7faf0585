//! The one rated load of `crane-sim`: the chart, the report and the replayed
//! limiter all take it from [`rated_at`].
//!
//! It is `moment_limiter::capacity::Capacity::rating` with the limiter's own
//! model (`cmd::replay::crane_load_model`, `f32`, the firmware's) and the
//! limiter's own capacity settings (`LimiterConfig::standard().capacity`:
//! tipping load / safety factor, capped by the structural limit and the
//! optional manufacturer chart), at the boom angle at rest. So the chart a
//! user reads is the rating the limiter trips on, to the last `f32` bit for a
//! still boom.

use crate::cmd::replay::crane_load_model;
use anyhow::{anyhow, bail, Result};
use crane_model::loads::load_model::{BoomState, HookLoadModel};
use moment_limiter::capacity::{Capacity, Rating};
use moment_limiter::cycle::LimiterConfig;

/// The limiter's capacity settings with another safety factor (≥ 1).
pub fn limiter_capacity(safety_factor: f64) -> Result<Capacity<f32>> {
    let mut capacity = LimiterConfig::<f32>::standard().capacity;
    capacity.safety_factor = safety_factor as f32;
    if !capacity.is_valid() {
        bail!("--safety-factor must be a number ≥ 1, got {safety_factor}");
    }
    Ok(capacity)
}

/// The model the rating is computed on: the limiter's.
pub fn rating_model() -> impl HookLoadModel<f32> {
    crane_load_model()
}

/// The rating at a boom angle (rad), boom at rest.
pub fn rated_at<M: HookLoadModel<f32>>(
    model: &M,
    capacity: &Capacity<f32>,
    angle_rad: f32,
) -> Result<Rating<f32>> {
    capacity
        .rating(model, BoomState { angle_rad, rate_rad_s: 0.0 })
        .map_err(|e| anyhow!("no rated load at {:.2}°: {e:?}", angle_rad.to_degrees()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use moment_limiter::cycle::Limiter;
    use moment_limiter::tools::log_format::LogParser;
    use moment_limiter::tools::replay::Replay;

    /// A moving replay: every rated sample of the limiter is the chart's
    /// rating at rest ([`rated_at`]) at the angle it rated
    /// (`Measurement::boom_now`: its filtered angle extrapolated to "now"),
    /// bit for bit, in motion as at rest: the chart carries the dynamic
    /// margin (SPEC §4 item 8), so the boom's rate takes nothing off it
    /// (with the model's velocity terms it took up to 1.8 % at 4 °/s). The
    /// log luffs at up to 4 °/s, so a rating that still took the rate would
    /// differ. With the boom still the two are one number
    /// (`tests/chart_cli.rs`).
    #[test]
    fn limiter_rates_with_the_chart_function_in_motion_too() {
        let log = include_str!("../../examples/logs/overload_lowering.csv");
        let model = rating_model();
        let capacity = limiter_capacity(1.5).unwrap();
        let limiter = Limiter::new(crane_load_model(), LimiterConfig::standard()).unwrap();
        let mut replay = Replay::new(limiter, true);
        let mut parser = LogParser::<f32>::new();
        let (mut compared, mut fastest) = (0, 0.0f32);
        for line in log.lines() {
            let Some(record) = parser.feed_line(line).unwrap() else { continue };
            let (report, _) = replay.feed(&record);
            let (Some(m), Some(est)) = (report.measurement, report.estimate) else { continue };
            let chart = rated_at(&model, &capacity, m.boom_now.angle_rad).unwrap().rated_load_kg;
            assert_eq!(est.rated_load_kg, chart, "t = {} µs, {} °/s", record.t_us, m.boom_now.rate_rad_s.to_degrees());
            fastest = fastest.max(m.boom_now.rate_rad_s.abs().to_degrees());
            compared += 1;
        }
        assert!(compared > 500, "only {compared} rated samples");
        assert!(fastest > 3.0, "the log must luff (fastest {fastest:.2} °/s)");
    }
}
