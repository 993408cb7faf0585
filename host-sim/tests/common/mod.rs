//! Helpers shared by the test binaries of `host-sim/tests`: the built
//! `crane-sim`, the example logs, a replay run and its output, and the thesis
//! model with its rated load for the limiter's acceptance tests.
// Each test binary compiles this module and uses only some of it.
#![allow(dead_code)]

use crane_model::loads::load_model::BoomState;
use crane_model::multibody::ThesisModel;
use crane_model::structure::modal::{MeshRefinement, THESIS_BASIS};
use crane_model::CraneData;
use moment_limiter::capacity::Capacity;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::OnceLock;

/// The thesis model in f64, built once per test binary.
pub fn model() -> &'static ThesisModel<f64> {
    static M: OnceLock<ThesisModel<f64>> = OnceLock::new();
    M.get_or_init(|| {
        ThesisModel::build(&CraneData::coles_mobile_930(), MeshRefinement::THESIS, &THESIS_BASIS)
            .expect("thesis model")
    })
}

/// The true rated load at a still boom angle (kg): the grading's truth.
pub fn rated_kg(angle_rad: f64) -> f64 {
    Capacity::<f64>::standard()
        .rating(model(), BoomState { angle_rad, rate_rad_s: 0.0 })
        .expect("rating")
        .rated_load_kg
}

/// The `crane-sim` binary cargo built for these tests.
pub fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_crane-sim"))
}

/// A file of `examples/logs`.
pub fn example(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../examples/logs")
        .join(name)
}

/// `crane-sim replay LOG EXTRA...`, run to its end.
pub fn replay(log: &Path, extra: &[&str]) -> Output {
    bin()
        .arg("replay")
        .arg(log)
        .args(extra)
        .output()
        .expect("run crane-sim")
}

/// Bytes of an output as text (lossy).
pub fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

/// stdout parsed as one JSON value.
pub fn json(out: &Output) -> serde_json::Value {
    serde_json::from_slice(&out.stdout)
        .unwrap_or_else(|e| panic!("bad JSON ({e}): {}", text(&out.stdout)))
}

/// The first of `replay --json`'s `events` that enters `state`; a panic
/// that lists them all when none does.
pub fn first_event<'a>(events: &'a [serde_json::Value], state: &str) -> &'a serde_json::Value {
    events
        .iter()
        .find(|e| e["state"] == state)
        .unwrap_or_else(|| panic!("no {state} in {events:#?}"))
}
