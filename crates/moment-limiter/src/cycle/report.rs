//! What one cycle returns.

use crate::clock::Ticks;
use crate::fault::Fault;
use crate::io::{Measurement, OutputCommand};
use crate::state_machine::LimiterState;
use crate::static_load::StaticLoad;

/// Load, capacity and utilization of one cycle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Estimate<T> {
    /// Estimated hook load (kg).
    pub load_kg: T,
    /// Rated load (kg).
    pub rated_load_kg: T,
    /// Tipping load (kg); `None` when no load can tip the crane here.
    pub tipping_load_kg: Option<T>,
    /// load / rated, capped at [`super::UTILIZATION_CEILING`].
    pub utilization: T,
    /// Hook radius (m).
    pub radius_m: T,
    /// The rope-hypothesis bank's parts of the load, before the reading
    /// factor ([`crate::static_load`]); `None` without the swing geometry.
    pub static_load: Option<StaticLoad<T>>,
}

/// The result of one cycle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepReport<T> {
    /// Time of the cycle.
    pub t: Ticks,
    /// State after the cycle.
    pub state: LimiterState,
    /// Outputs to drive.
    pub command: OutputCommand,
    /// Filtered signals, when all readings were good.
    pub measurement: Option<Measurement<T>>,
    /// Load and capacity, when they could be computed.
    pub estimate: Option<Estimate<T>>,
    /// The fault found in this cycle, if any.
    pub fault: Option<Fault>,
}
