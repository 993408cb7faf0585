//! # crane-model
//!
//! A reduced-order flexible multibody model of a hydraulic mobile crane (the COLES
//! Mobile 930 of S. Kılıçaslan's 1997 METU thesis), written for a load moment
//! limiter: `no_std`, no heap, generic over `f32` (microcontroller) and `f64` (host).
//!
//! The work seam for the limiter is [`load_model::HookLoadModel`]: one query per
//! control cycle ([`load_model::HookLoadModel::cycle_terms`]). On the controller
//! and in `crane-sim replay` it is answered by [`load_table::LoadTable`], the
//! limiter's terms tabulated over the boom angle from the full f64 model (no
//! multibody code in the cycle); on the host the full model
//! ([`multibody::CraneModel`]) answers it too.
#![cfg_attr(not(any(test, feature = "std")), no_std)]
#![forbid(unsafe_code)]
// `!(x > 0)` is deliberate throughout: unlike `x <= 0` it also rejects NaN.
#![allow(clippy::neg_cmp_op_on_partial_ord)]
// Matrix loops index several arrays with one index, as the equations they implement do.
#![allow(clippy::needless_range_loop)]
// Range checks are written out so NaN fails them too, as `!(x > 0)` does.
#![allow(clippy::manual_range_contains)]

pub mod bodies;
pub mod crane;
pub mod dense;
pub mod dynamics;
pub mod eigen;
pub mod error;
pub mod fe;
pub mod integrator;
pub mod load_model;
pub mod load_table;
pub mod mechanism;
pub mod modal;
pub mod multibody;
pub mod profile;
pub mod real;
pub mod rope;
pub mod section;
pub mod simulation;
pub mod statics;
pub mod thesis_modes;
pub mod tipping;

pub use crane::CraneData;
pub use error::ModelError;
pub use real::Real;
