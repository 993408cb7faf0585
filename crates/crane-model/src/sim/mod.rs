//! Simulation (host tools): the time integrator, the maneuvers and the
//! thesis's dynamic tipping search (§4.3.2).
//!
//! The last layer: nothing else in the crate imports it, so the limiter's path
//! never passes through the simulator.

pub mod dynamic_tipping;
pub mod integrator;
pub mod simulation;
