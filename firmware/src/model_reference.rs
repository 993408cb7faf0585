//! Reference values of the crane model for the power-up self-test, and the one
//! function that evaluates the model at them.
//!
//! The table was generated on the host by evaluating the model behind
//! `model::hook_load_model()` in `f32` (`cargo test -p crane-tests --test
//! firmware_failsafe model_reference` recomputes it and prints a fresh table
//! when the model changes). On the MCU the self-test evaluates the model again
//! and compares: a corrupted constant, a miscompiled routine or a broken FPU
//! shows up as a mismatch before the limiter may grant motion.
//!
//! This file is also compiled into the host test (`#[path]`), so it uses only
//! `core` and `crane_model`.

use crane_model::loads::load_model::{BoomState, HookLoadModel};

/// One reference point: boom state and hook load in, model outputs out.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ModelPoint {
    /// Boom angle (deg).
    pub angle_deg: f32,
    /// Boom angular rate (rad/s).
    pub rate_rad_s: f32,
    /// Hook load (kg).
    pub load_kg: f32,
    /// Expected piston force (N).
    pub piston_force_n: f32,
    /// Expected rear jack reaction (N, thesis eq. 4.2).
    pub jack_reaction_n: f32,
}

/// Relative tolerance of the comparison: the host and the Cortex-M4F compute
/// the same `f32` operations, so they agree far closer than this; a changed or
/// corrupted model differs by much more.
pub const RELATIVE_TOLERANCE: f32 = 1e-4;

/// The reference table (generated on the host, see the module notes).
#[rustfmt::skip]
pub const REFERENCE: [ModelPoint; 4] = [
    ModelPoint { angle_deg: 10.0, rate_rad_s: 0.0, load_kg: 1000.0, piston_force_n: 368829.84, jack_reaction_n: 73475.17 },
    ModelPoint { angle_deg: 35.0, rate_rad_s: 0.02, load_kg: 4000.0, piston_force_n: 406063.8, jack_reaction_n: 43153.895 },
    ModelPoint { angle_deg: 60.0, rate_rad_s: -0.02, load_kg: 2500.0, piston_force_n: 182305.69, jack_reaction_n: 97068.695 },
    ModelPoint { angle_deg: 80.0, rate_rad_s: 0.0, load_kg: 500.0, piston_force_n: 41610.523, jack_reaction_n: 129126.02 },
];

/// Evaluates `model` at `point`'s boom state and load: (piston force, jack
/// reaction), or `None` if the model refuses the state.
pub fn evaluate(model: &impl HookLoadModel<f32>, point: &ModelPoint) -> Option<(f32, f32)> {
    let boom = BoomState {
        angle_rad: point.angle_deg * (core::f32::consts::PI / 180.0),
        rate_rad_s: point.rate_rad_s,
    };
    let force = model.piston_force_n(boom).ok()?.at(point.load_kg);
    let jack = model.jack_reaction_n(boom).ok()?.at(point.load_kg);
    Some((force, jack))
}

/// Whether `got` agrees with `expected` within [`RELATIVE_TOLERANCE`] (of the
/// larger magnitude, at least 1 N).
pub fn agrees(got: f32, expected: f32) -> bool {
    let scale = if expected.abs() > 1.0 {
        expected.abs()
    } else {
        1.0
    };
    // NaN compares false: a NaN never agrees.
    (got - expected).abs() <= RELATIVE_TOLERANCE * scale
}

/// Checks `model` against the whole table; the index of the first point that
/// disagrees (or that the model refuses) on failure.
pub fn check(model: &impl HookLoadModel<f32>) -> Result<usize, usize> {
    for (i, point) in REFERENCE.iter().enumerate() {
        match evaluate(model, point) {
            Some((f, j)) if agrees(f, point.piston_force_n) && agrees(j, point.jack_reaction_n) => {
            }
            _ => return Err(i),
        }
    }
    Ok(REFERENCE.len())
}
