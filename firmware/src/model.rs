//! **The** seam where the firmware obtains its crane model: [`hook_load_model`].
//!
//! The microcontroller runs no multibody code at all. The limiter's terms
//! depend on the boom angle alone once the hook load and the rate are factored
//! out (the piston force and the rear-jack reaction are quadratics in the load,
//! the rate enters as ω²), so the host tabulates them with the full f64 model
//! every 0.5° and the image carries the table as f32 constants
//! (`crane_model::loads::load_table`, 184 rows × 11 columns, 7.9 KB; checked against
//! the full model and against a fresh generation by tests). One control cycle
//! asks the table once ([`crane_model::loads::load_model::HookLoadModel::cycle_terms`]):
//! two interpolations, one quadratic root and tan θ1 from the f32 polynomial
//! sine and cosine the pendulums use; no libm trigonometry, no f64, no panic
//! (scripts/check-cycle-image.sh proves the last three on the image).
//! `crane-sim replay` runs the very same table in f32, so their timelines agree
//! sample for sample.

use crane_model::loads::load_model::HookLoadModel;

/// The crane model the limiter runs on this controller (`f32`).
pub fn hook_load_model() -> impl HookLoadModel<f32> + Clone {
    crane_model::loads::thesis_modes::thesis_load_model_f32()
}
