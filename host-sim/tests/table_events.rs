//! The controller's load table against the full model, as the limiter sees
//! them: replaying the example logs through the limiter with the table (f32,
//! what the firmware and `crane-sim replay` run) and with the full multibody
//! model (f64) gives the same state changes at the same samples.

use std::path::PathBuf;

use crane_model::loads::load_model::HookLoadModel;
use crane_model::Real;
use moment_limiter::cycle::{Limiter, LimiterConfig};
use moment_limiter::tools::log_format::LogParser;
use moment_limiter::tools::replay::Replay;
use moment_limiter::state_machine::LimiterState;

fn example(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../examples/logs").join(name)
}

/// (sample, state) of every state change, and the largest utilization.
fn events<T: Real, M: HookLoadModel<T>>(model: M, log: &str) -> (Vec<(u32, LimiterState)>, f64) {
    let mut replay = Replay::new(Limiter::new(model, LimiterConfig::<T>::standard()).expect("config"), false);
    let mut parser = LogParser::<T>::new();
    let mut out = Vec::new();
    let text = std::fs::read_to_string(example(log)).expect("log");
    for line in text.lines() {
        match parser.feed_line(line) {
            Ok(Some(record)) => {
                if let (_, Some(e)) = replay.feed(&record) {
                    out.push((e.sample, e.state));
                }
            }
            Ok(None) => {}
            Err(_) => break,
        }
    }
    (out, replay.summary().max_utilization.map_or(0.0, |u| u.to_f64()))
}

#[test]
fn table_and_full_model_change_state_at_the_same_samples_on_the_example_logs() {
    let full = crane_model::loads::tipping::CachedLoadModel::new(crane_model::loads::load_table::thesis_full_model().expect("model"));
    for log in ["safe_lift.csv", "overload_lowering.csv", "unloaded_up.csv", "unloaded_down.csv", "wire_break.csv", "malformed.csv"] {
        let (table_events, table_max) = events::<f32, _>(crane_model::loads::thesis_modes::thesis_load_model_f32(), log);
        let (full_events, full_max) = events::<f64, _>(full.clone(), log);
        println!("{log}: table {table_events:?} max {table_max:.4}; full {full_events:?} max {full_max:.4}");
        assert_eq!(table_events, full_events, "{log}");
        // 0.2 % of the rated load: the table's bound, in utilization points.
        assert!((table_max - full_max).abs() <= 0.002, "{log}: {table_max} vs {full_max}");
    }
}
