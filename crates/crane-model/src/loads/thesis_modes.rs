//! The thesis's boom modes as constant data, for the controller.
//!
//! The finite-element assembly and the eigen-solve run on the host (in f64) and
//! their result is compiled in as `f32` constants ([`THESIS_MODES_F32`]), so the
//! microcontroller does no structural analysis: it only assembles and solves the
//! small per-step equations. The host's replay uses the same constants, so host
//! and controller run bit-for-bit the same model.

use crate::data::crane::CraneData;
use crate::structure::modal::{BoomModes, MeshRefinement, ModalAnalysis, ModeKind, THESIS_BASIS};
use crate::multibody::CraneModel;
use crate::ModelError;

include!("thesis_modes_data.rs");

/// The thesis's modal data computed afresh in f64 (12 elements, 4-mode basis).
pub fn compute_thesis_modes_f64() -> Result<BoomModes<f64, 4>, ModelError> {
    let crane = CraneData::coles_mobile_930();
    ModalAnalysis::<f64>::new(&crane, MeshRefinement::THESIS)?.reduce(&THESIS_BASIS, crane.boom.damping_ratio)
}

/// The controller's model: the COLES Mobile 930 with [`THESIS_MODES_F32`], f32.
pub fn thesis_model_f32() -> CraneModel<f32, 4> {
    CraneModel::new(&CraneData::coles_mobile_930(), THESIS_MODES_F32)
}

/// The limiter's model on the controller and in `crane-sim replay`: the
/// load table ([`crate::loads::load_table`]), generated from the full f64 model and
/// interpolated in f32; no multibody code runs in the cycle.
pub fn thesis_load_model_f32() -> crate::loads::load_table::LoadTable {
    crate::loads::load_table::thesis_load_table()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The constants must be what the analysis gives today, to the last f32 bit.
    #[test]
    fn constants_match_a_fresh_analysis() {
        let fresh = compute_thesis_modes_f64().map(|m| m.cast::<f32>());
        assert_eq!(fresh, Ok(THESIS_MODES_F32), "stale: rerun the export_thesis_modes example");
    }

    /// The tip's compliance across the boom two ways: from the four retained
    /// modes (what the controller's data holds) and from the full
    /// finite-element stiffness (a unit force across the boom at the tip,
    /// solved on every free degree of freedom). The modes the thesis keeps
    /// hold the static give to within 1 %: the bending from the lug to the
    /// tip is almost all in its first mode.
    #[test]
    fn tip_compliance_of_the_modes_is_the_structures() {
        use crate::structure::fe::DOF_PER_NODE;
        use crate::structure::modal::boom_mesh;
        let crane = CraneData::coles_mobile_930();
        let analysis = ModalAnalysis::<f64>::new(&crane, MeshRefinement::THESIS).unwrap();
        let tip = boom_mesh::<f64>(&crane, MeshRefinement::THESIS).unwrap().n_nodes() - 1;
        let mut f = [0.0; crate::structure::fe::MAX_DOF];
        f[DOF_PER_NODE * tip + 1] = 1.0;
        let full = analysis.static_deflection(&f).unwrap()[DOF_PER_NODE * tip + 1];
        let modal = compute_thesis_modes_f64().unwrap().tip_compliance_across_m_per_n();
        let data = f64::from(THESIS_MODES_F32.tip_compliance_across_m_per_n());
        // Measured: 3.011e-6 m/N from the modes, 3.036e-6 from the full structure.
        println!("tip compliance across the boom: modes {modal:.4e} m/N (f32 data {data:.4e}), full structure {full:.4e} m/N");
        assert!(full > 0.0 && (modal / full - 1.0).abs() < 0.01, "modes {modal:e}, full {full:e}");
        assert!((data / modal - 1.0).abs() < 1e-5, "f32 data {data:e}, f64 {modal:e}");
    }
}
