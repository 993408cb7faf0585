//! Load responses: what the limiter asks of the model (thesis §4.3).
//!
//! The seam ([`load_model::HookLoadModel`], one query per cycle), its table
//! ([`load_table`], generated from the full model and compiled in), the
//! thesis's mode constants ([`thesis_modes`]) and the static tipping load and
//! reactions of the full model ([`tipping`]). Uses [`crate::data`],
//! [`crate::structure`] and [`crate::multibody`]; never [`crate::sim`].

pub mod load_model;
pub mod load_table;
pub mod thesis_modes;
pub mod tipping;
