//! **The** seam where the firmware obtains its crane model: [`hook_load_model`].
//!
//! The microcontroller never runs the finite-element assembly or the eigen-solve
//! (41–60 KB of stack and 1.4 M instructions for the 35×35 problem, see
//! EMBEDDED-NOTES.md): the reduced model's modal data (the time-invariant matrices
//! of thesis eqs. 3.1–3.11) is computed on the host in f64 and compiled in as f32
//! constants (`crane_model::thesis_modes::THESIS_MODES_F32`, checked against a
//! fresh analysis by a test). Per cycle the MCU only assembles and solves the
//! small equations of the flexible multibody model. `crane-sim replay` uses the
//! very same constants and f32 arithmetic, so their timelines agree sample for
//! sample.

use crane_model::load_model::HookLoadModel;

/// The crane model the limiter runs on this controller (`f32`).
pub fn hook_load_model() -> impl HookLoadModel<f32> + Clone {
    crane_model::thesis_modes::thesis_load_model_f32()
}
