//! **The** seam where the firmware obtains its crane model: [`hook_load_model`].
//!
//! The microcontroller never runs the finite-element assembly or the eigen-solve
//! (41–60 KB of stack and 1.4 M instructions for the 35×35 problem, see
//! EMBEDDED-NOTES.md): the reduced model (modal data, the time-invariant matrices
//! of thesis eqs. 3.1–3.11) is computed on the host and compiled in as a `const`.
//! Everything else in the firmware gets its model from this one function, so
//! switching from the placeholder to the real model is a change here only.
//!
//! PLACEHOLDER (until crane-model exposes its precomputed reduced model): a rigid
//! boom in static equilibrium with the thesis's geometry. It has the right shape
//! (piston force and rear-jack reaction affine in the hook load) and roughly the
//! right magnitudes, but it is NOT the thesis's flexible multibody model and must
//! not be used on a crane. To finish wiring: replace the body of
//! [`hook_load_model`] with the lead's precomputed value, e.g.
//! `crane_model::reduced::COLES_930_F32` (whatever the generated `const` is named),
//! and delete [`placeholder`].

use crane_model::load_model::HookLoadModel;

/// The crane model the limiter runs on this controller (`f32`).
pub fn hook_load_model() -> impl HookLoadModel<f32> {
    placeholder::RigidBoomStandIn
}

/// A rigid-boom statics stand-in (NOT the thesis model; see the module doc).
pub mod placeholder {
    use crane_model::load_model::{Affine, BoomState, HookLoadModel};
    use crane_model::ModelError;
    use micromath::F32Ext;

    const G: f32 = 9.81;
    /// Boom foot pin A0 (m).
    const A0: (f32, f32) = (2.775, 2.57);
    /// Cylinder foot pin B0 (m).
    const B0: (f32, f32) = (5.125, 1.765);
    /// A0 to the lug end D along the lug (m) and the lug's angle to the boom (rad).
    const LUG_M: f32 = 5.85;
    const LUG_ANGLE_RAD: f32 = -0.096_731_98;
    /// Boom length A0–C (m) and an assumed boom mass and centre (stand-in values).
    const BOOM_M: f32 = 19.5;
    const BOOM_KG: f32 = 2_600.0;
    const BOOM_CG_M: f32 = 8.5;
    /// Tipping line (front jack, m), chassis weight (N) and its lever (m).
    const TIP_X_M: f32 = 7.305;
    const CHASSIS_N: f32 = 222_792.77;
    const CHASSIS_LEVER_M: f32 = 4.125;
    /// Rear jack distance behind the tipping line (m, stand-in).
    const REAR_JACK_LEVER_M: f32 = 5.0;

    /// The stand-in model (no data: everything is a constant above).
    #[derive(Debug, Clone, Copy, Default)]
    pub struct RigidBoomStandIn;

    impl RigidBoomStandIn {
        /// Perpendicular lever of the cylinder force about A0 (m).
        fn cylinder_lever_m(angle_rad: f32) -> Result<f32, ModelError> {
            let a = angle_rad + LUG_ANGLE_RAD;
            let d = (A0.0 + LUG_M * a.cos(), A0.1 + LUG_M * a.sin());
            let (ux, uy) = (d.0 - B0.0, d.1 - B0.1);
            let len = (ux * ux + uy * uy).sqrt();
            if len < 0.1 {
                return Err(ModelError::OutOfReach);
            }
            // |r × u| with r = D − A0.
            let (rx, ry) = (d.0 - A0.0, d.1 - A0.1);
            let lever = (rx * uy - ry * ux) / len;
            if lever.abs() < 0.05 {
                return Err(ModelError::Singular("cylinder lever"));
            }
            Ok(lever)
        }
    }

    impl HookLoadModel<f32> for RigidBoomStandIn {
        fn piston_force_n(&self, boom: BoomState<f32>) -> Result<Affine<f32>, ModelError> {
            let lever = Self::cylinder_lever_m(boom.angle_rad)?;
            let c = boom.angle_rad.cos();
            Ok(Affine {
                at_zero: BOOM_KG * G * BOOM_CG_M * c / lever,
                per_kg: G * BOOM_M * c / lever,
            })
        }

        fn jack_reaction_n(&self, boom: BoomState<f32>) -> Result<Affine<f32>, ModelError> {
            // Moments about the tipping line: chassis stabilises, boom and load tip.
            let c = boom.angle_rad.cos();
            let boom_cg_x = A0.0 + BOOM_CG_M * c;
            let hook_x = A0.0 + BOOM_M * c;
            Ok(Affine {
                at_zero: (CHASSIS_N * CHASSIS_LEVER_M - BOOM_KG * G * (boom_cg_x - TIP_X_M))
                    / REAR_JACK_LEVER_M,
                per_kg: -G * (hook_x - TIP_X_M) / REAR_JACK_LEVER_M,
            })
        }

        fn radius_m(&self, boom_angle_rad: f32) -> f32 {
            BOOM_M * boom_angle_rad.cos() - 1.83
        }
    }
}
