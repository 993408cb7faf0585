//! The built-in crane model, built once per process (f64, thesis mesh and basis).

use crane_model::structure::modal::{MeshRefinement, THESIS_BASIS};
use crane_model::multibody::ThesisModel;
use crane_model::CraneData;

/// The COLES Mobile 930 with the thesis's 12 elements and 4 modes.
pub fn thesis_model() -> anyhow::Result<ThesisModel<f64>> {
    ThesisModel::<f64>::build(
        &CraneData::coles_mobile_930(),
        MeshRefinement::THESIS,
        &THESIS_BASIS,
    )
    .map_err(|e| anyhow::anyhow!("building the crane model failed: {e}"))
}
