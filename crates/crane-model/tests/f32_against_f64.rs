//! The model in f32 (the controller's float) against f64.

use crane_model::data::crane::CraneData;
use crane_model::structure::modal::{MeshRefinement, THESIS_BASIS};
use crane_model::multibody::{CraneModel, ThesisModel};
use crane_model::data::profile::RampShape;
use crane_model::sim::simulation::{Direction, SimulationOptions};

mod common;
use common::dynamics::*;

fn f32_gap(m32: &ThesisModel<f32>, opts32: &SimulationOptions, label: &str) -> f64 {
    let m64 = model();
    let mut worst = 0.0f64;
    for load in [0.0, 3300.0] {
        let man = maneuver(load, 30.0, RampShape::Cycloidal, Direction::Up);
        let r64 = run(&m64, &man, &SimulationOptions::for_type::<f64>());
        let r32 = run(m32, &man, opts32);
        let (gap, at) = max_relative_gap(&r32, &r64);
        let tip_gap = r32
            .iter()
            .zip(r64.iter())
            .fold(0.0f64, |m, (a, b)| m.max((a.tip - b.tip).abs()));
        println!(
            "W {load} kg, 30 s cycloidal up, f32 ({label}, Newton tol {:e}) vs f64: max piston-force gap {gap:.2e} at t = {at:.2} s, max tip-deflection gap {tip_gap:.2e} m, {} samples",
            opts32.tolerance,
            r64.len()
        );
        worst = worst.max(gap);
    }
    worst
}

/// The f32 Newton tolerance that the f32 residual can reach: at rest the f32 modal
/// forces (differences of ~1e3 N-scale terms ω²η − χᵀ·g·A) carry ~1e-4 m/s² of rounding,
/// so the shipped default 1e-5 cannot be met (see the ignored test below); 3e-4 can.
const F32_REACHABLE_TOLERANCE: f64 = 3e-4;

#[test]
fn f32_model_from_f64_modes_matches_f64_over_the_30_s_maneuver() {
    let m32 =
        CraneModel::<f32, 4>::new(&CraneData::coles_mobile_930(), model().modes.cast::<f32>());
    let opts = SimulationOptions {
        tolerance: F32_REACHABLE_TOLERANCE,
        ..SimulationOptions::for_type::<f32>()
    };
    let gap = f32_gap(&m32, &opts, "modes from f64, cast");
    // f32 (MCU) piston force within 0.5 % of f64 at every sample (issue 3).
    assert!(gap < 5e-3, "f32 piston force off by {gap:e}");
}

#[test]
fn f32_model_built_in_f32_matches_f64_over_the_30_s_maneuver() {
    let m32 = ThesisModel::<f32>::build(
        &CraneData::coles_mobile_930(),
        MeshRefinement::THESIS,
        &THESIS_BASIS,
    )
    .expect("f32 model");
    let opts = SimulationOptions {
        tolerance: F32_REACHABLE_TOLERANCE,
        ..SimulationOptions::for_type::<f32>()
    };
    let gap = f32_gap(&m32, &opts, "FE + eigen in f32");
    // f32 throughout (FE, eigen, dynamics): piston force within 0.5 % of f64 at every sample (issue 3),
    // although its first bending frequency is 3.5 % off (boom_modes.rs): the piston force is quasi-static.
    assert!(gap < 5e-3, "f32 piston force off by {gap:e}");
}

/// Measured: with `SimulationOptions::for_type::<f32>()` (Newton tolerance 1e-5) the
/// very first step fails with NoConvergence("Newmark step") for W = 0 and 3300 kg.
/// At the equilibrium state the f32 accelerations that should be 0 come out as
/// 1.1e-4 (W = 0) and 3.5e-4 m/s² (3300 kg): f32 rounding of f_η, a difference of
/// terms of 240–1400 (ω²η against the gravity projection). The stopping test
/// |Δa| ≤ tol·(max|a| + 1) of State::step needs tol ≳ 3e-4 to be reachable
/// (1e-4 still fails at t = 1.13 s with 3300 kg, at 24.5 s unloaded).
#[test]
fn f32_simulation_with_default_options_runs_the_30_s_maneuver() {
    let m32 =
        CraneModel::<f32, 4>::new(&CraneData::coles_mobile_930(), model().modes.cast::<f32>());
    let gap = f32_gap(
        &m32,
        &SimulationOptions::for_type::<f32>(),
        "default options",
    );
    // f32 with its default options piston force within 0.5 % of f64 at every sample (issue 3).
    assert!(gap < 5e-3, "f32 piston force off by {gap:e}");
}
