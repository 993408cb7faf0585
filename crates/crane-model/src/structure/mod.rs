//! The boom as a structure: finite elements, the generalized eigen-solver and
//! the modal reduction (thesis ch. 2.4–2.6).
//!
//! Host work in practice: the controller's modes are compiled in as constants
//! ([`crate::loads::thesis_modes`]), so no eigen-solve runs on the target. Uses
//! [`crate::data`] only.

pub mod dense;
pub mod eigen;
pub mod fe;
pub mod modal;
