//! **The** seam where the firmware obtains its crane model: [`hook_load_model`].
//!
//! The microcontroller never runs the finite-element assembly or the eigen-solve
//! (41–60 KB of stack and 1.4 M instructions for the 35×35 problem, see
//! EMBEDDED-NOTES.md): the reduced model (modal data, the time-invariant matrices
//! of thesis eqs. 3.1–3.11) is computed on the host and compiled in as a `const`.
//! Everything else in the firmware gets its model from this one function, so
//! switching from the placeholder to the real model is a change here only.
//!
//! PLACEHOLDER (until crane-model exposes its precomputed reduced model): the
//! limiter crate's rigid, quasi-static stand-in
//! `moment_limiter::rigid_reference::RigidCrane::coles_930()`, the same stand-in
//! `crane-sim replay` uses for now, so the QEMU and host timelines stay
//! comparable. It is NOT the thesis's flexible multibody model and must not be
//! used on a crane. To finish wiring: replace the body of [`hook_load_model`]
//! with the lead's precomputed value (a `const` built on the host or at build
//! time; no FE/eigen work on the MCU), and make `crane-sim replay` use the same
//! model in `f32`.

use crane_model::load_model::HookLoadModel;

/// The crane model the limiter runs on this controller (`f32`).
pub fn hook_load_model() -> impl HookLoadModel<f32> + Clone {
    moment_limiter::rigid_reference::RigidCrane::<f32>::coles_930()
}
