//! Testing aids (cargo feature `testing`; the crate's own tests, the
//! integration tests and `crane-sim` enable it): the sensor fault injector
//! and a rigid stand-in model. Never built into the firmware.

pub mod fault_injector;
pub mod rigid_reference;
