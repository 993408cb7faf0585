//! Crane data: what the crane is, before any analysis (thesis ch. 2, table 2.1).
//!
//! The first layer: nothing here imports another layer of the crate.

pub mod crane;
pub mod profile;
pub mod real;
pub mod section;
