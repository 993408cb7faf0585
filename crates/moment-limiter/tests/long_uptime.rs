//! A day of operation in one run: the controller's f32 limiter with the
//! shipped model and configuration (swing bank included), fed a crane that
//! luffs a constant load between 40° and 60° every ten minutes for 24 h at
//! 100 Hz. The tick counter wraps 20 times (every 71.6 min); the filters,
//! the rope bank's pendulums and averages run 8.64 M cycles. Nothing the
//! limiter computes may depend on how long it has been running: the weighing
//! at the end of every hold must be the first hold's (to the spread that the
//! swing observers' memory of past moves gives it), and the state must
//! never leave NORMAL. (The sensors' dither repeats every period, so the
//! input itself repeats exactly: what changes between holds is the
//! limiter's own state.)

use crane_model::loads::load_model::{BoomState, HookLoadModel};
use crane_model::loads::thesis_modes::thesis_load_model_f32;
use moment_limiter::clock::Ticks;
use moment_limiter::cycle::{Limiter, LimiterConfig};
use moment_limiter::io::Frame;
use moment_limiter::piston_force::p1_bar_for_force;
use moment_limiter::state_machine::LimiterState;

/// One period of the duty cycle (s): hold at 40°, raise to 60°, hold, lower.
const PERIOD_S: u32 = 600;
const HOLD_S: f64 = 270.0;
const MOVE_S: f64 = 30.0;
const RATE_HZ: u32 = 100;

/// The boom angle (deg) at `t` s into a period: cycloidal moves.
fn angle_deg(t: f64) -> f64 {
    let cyclo = |x: f64| x - (2.0 * core::f64::consts::PI * x).sin() / (2.0 * core::f64::consts::PI);
    if t < HOLD_S {
        40.0
    } else if t < HOLD_S + MOVE_S {
        40.0 + 20.0 * cyclo((t - HOLD_S) / MOVE_S)
    } else if t < 2.0 * HOLD_S + MOVE_S {
        60.0
    } else {
        60.0 - 20.0 * cyclo((t - 2.0 * HOLD_S - MOVE_S) / MOVE_S)
    }
}

#[test]
fn a_day_of_luffing_weighs_the_same_load_at_every_hold() {
    let model = thesis_load_model_f32();
    let mut limiter = Limiter::new(thesis_load_model_f32(), LimiterConfig::<f32>::standard()).expect("standard limiter");
    let load_kg = 4000.0f32;
    let hours: u32 = std::env::var("UPTIME_HOURS").ok().and_then(|h| h.parse().ok()).unwrap_or(24);
    let day_s = hours * 3600;
    let per_period = PERIOD_S * RATE_HZ;
    // The weighing at the end of each 40° hold, and the first one.
    let mut first: Option<f32> = None;
    let (mut worst, mut holds) = (0.0f32, 0u32);
    let mut departures: Vec<f32> = Vec::new();
    let mut states_seen = [false; 4];
    for k in 0..day_s * RATE_HZ {
        let t_in = f64::from(k % per_period) / f64::from(RATE_HZ);
        let deg = angle_deg(t_in);
        // Quasi-static luffing (20° in 30 s): the model's force at rest, as
        // a log records it (0.01 bar, 0.01°).
        let force = model
            .piston_force_n(BoomState { angle_rad: (deg as f32).to_radians(), rate_rad_s: 0.0 })
            .expect("in reach")
            .at(load_kg);
        // Live sensors (a constant reading is a stuck transducer): ±2
        // counts of 0.01 of dither, the same in every period, so the input
        // repeats exactly and any difference between holds is the limiter's.
        let phase = k % per_period;
        let dither = |salt: u32| {
            let h = phase.wrapping_mul(2_654_435_761).wrapping_add(salt).rotate_left(13).wrapping_mul(2_246_822_519);
            ((h >> 16) % 5) as f32 * 0.01 - 0.02
        };
        let p2 = 5.0f32 + dither(1);
        let round = |x: f32| (x * 100.0).round() / 100.0;
        let frame = Frame {
            t: Ticks::from_cycle(k, 1_000_000 / RATE_HZ),
            p1_bar: round(p1_bar_for_force(force, p2) + dither(2)),
            p2_bar: round(p2),
            boom_angle_deg: round(deg as f32 + dither(3)),
        };
        let report = limiter.step_frame(&frame);
        let slot = match report.state {
            LimiterState::Normal => 0,
            LimiterState::Warning => 1,
            LimiterState::Overload => 2,
            LimiterState::Fault => 3,
        };
        states_seen[slot] = true;
        if k > RATE_HZ {
            assert_eq!(report.state, LimiterState::Normal, "cycle {k} ({} h): {:?}", k / (3600 * RATE_HZ), report.fault);
        }
        if k % per_period == (HOLD_S as u32) * RATE_HZ - 1 {
            let w = report.estimate.expect("an estimate at rest").load_kg;
            let w0 = *first.get_or_insert(w);
            worst = worst.max((w / w0 - 1.0).abs());
            departures.push(w / w0 - 1.0);
            holds += 1;
        }
    }
    // The first and the last six hours' mean weighing.
    let mean = |v: &[f32]| v.iter().sum::<f32>() / v.len().max(1) as f32;
    let quarter = departures.len() / 4;
    let (early, late) = (mean(&departures[..quarter]), mean(&departures[departures.len() - quarter..]));
    println!(
        "{holds} holds in {hours} h: largest departure from the first weighing {worst:.2e}, mean of the first quarter {early:.2e}, of the last {late:.2e}; states seen {states_seen:?}"
    );
    assert_eq!(holds, 6 * hours);
    // Measured: departures within ±1.2e-3 (the undamped swing observers keep
    // what each move excites, and the bank weighs through it), stationary
    // over 120 h (`UPTIME_HOURS=120`); the quarters' means within 1e-4.
    // Bounds: a tenth of the J376 reading margin, and no drift between the
    // first and the last quarter of the run beyond 2e-4 of the load.
    assert!(worst < 2.5e-3, "a hold's weighing departed by {worst:.2e} of the load from the first");
    assert!((late - early).abs() < 2e-4, "the weighing drifted from {early:.2e} to {late:.2e} of the load");
}
