//! # crane-model
//!
//! A reduced-order flexible multibody model of a hydraulic mobile crane (the COLES
//! Mobile 930 of S. Kılıçaslan's 1997 METU thesis), written for a load moment
//! limiter: `no_std`, no heap, generic over `f32` (microcontroller) and `f64` (host).
//!
//! ## Layers
//!
//! Each folder uses only the folders above it in this table (a module never
//! imports a later layer):
//!
//! | layer | folder | what it holds |
//! |---|---|---|
//! | crane data | [`data`] | the crane's dimensions and masses ([`CraneData`]), boom sections, actuator stroke profiles, the [`Real`] float trait |
//! | structure | [`structure`] | the boom's finite elements, the eigen-solver and the modal reduction (host work: its result is compiled in as constants) |
//! | multibody | [`multibody`] | the bodies, the luffing mechanism, the constrained equations of motion, the rope and the static equilibrium ([`multibody::CraneModel`]) |
//! | load responses | [`loads`] | the limiter's seam ([`loads::load_model::HookLoadModel`]), the load table and its data, the thesis's mode constants, the static tipping load |
//! | simulation | [`sim`] | the integrator, the maneuvers and the dynamic tipping search (host tools) |
//!
//! ## What the firmware calls
//!
//! The work seam for the limiter is [`loads::load_model::HookLoadModel`]: one
//! query per control cycle ([`loads::load_model::HookLoadModel::cycle_terms`]).
//! On the controller and in `crane-sim replay` it is answered by
//! [`loads::load_table::LoadTable`] ([`loads::thesis_modes::thesis_load_model_f32`]),
//! the limiter's terms tabulated over the boom angle from the full f64 model (no
//! multibody code in the cycle); on the host the full model
//! ([`multibody::CraneModel`]) answers it too. The firmware imports from
//! [`data`], [`multibody`] and [`loads`] only; nothing in its path reaches
//! [`sim`] or [`structure`]'s solvers.
#![cfg_attr(not(any(test, feature = "std")), no_std)]
#![forbid(unsafe_code)]
// `!(x > 0)` is deliberate throughout: unlike `x <= 0` it also rejects NaN.
#![allow(clippy::neg_cmp_op_on_partial_ord)]
// Matrix loops index several arrays with one index, as the equations they implement do.
#![allow(clippy::needless_range_loop)]
// Range checks are written out so NaN fails them too, as `!(x > 0)` does.
#![allow(clippy::manual_range_contains)]

pub mod data;
pub mod error;
pub mod loads;
pub mod multibody;
pub mod sim;
pub mod structure;

pub use data::crane::CraneData;
pub use data::real::Real;
pub use error::ModelError;
