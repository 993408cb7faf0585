//! Why the limiter is in FAULT: the vocabulary the cycle, the event log and
//! the replay share (here, not in the cycle, so they need not import it).

use core::fmt;

use crate::capacity::CapacityError;
use crate::checks::{channel_name, SensorFault};
use crate::clock::ClockFault;
use crate::load_estimate::EstimateError;

/// Why the limiter is in FAULT.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Fault {
    /// A sensor reading failed a check.
    Sensor(SensorFault),
    /// No load estimate could be made.
    Estimate(EstimateError),
    /// No rated load could be computed.
    Capacity(CapacityError),
    /// The time of the cycle cannot be trusted (stalled, gap, backwards).
    Clock(ClockFault),
    /// The load estimate stayed below [`crate::cycle::LimiterConfig::negative_load`]: no
    /// hook load is negative, so the estimate (or a sensor or the
    /// calibration) is wrong.
    ImplausibleLoad,
    /// The signal chain restarted after a fault less than
    /// [`crate::cycle::SETTLE_S`] ago with the boom moving: the filters'
    /// start-up is no reading yet.
    Settling,
    /// Switched on while the boom moved: no weighing until it has stopped
    /// ([`crate::cycle::power_up`]).
    StartedMoving,
    /// The outputs could not be driven.
    Output,
}

impl fmt::Display for Fault {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Fault::Sensor(s) => write!(f, "{} {}", channel_name(s.channel), s.kind.as_str()),
            Fault::Estimate(EstimateError::Model(e)) => write!(f, "load model: {e}"),
            Fault::Estimate(EstimateError::NotObservable) => f.write_str("load not observable"),
            Fault::Capacity(CapacityError::Model(e)) => write!(f, "capacity model: {e}"),
            Fault::Capacity(CapacityError::NotObservable) => f.write_str("capacity not observable"),
            Fault::Clock(c) => write!(f, "{c}"),
            Fault::ImplausibleLoad => f.write_str("load estimate implausibly negative"),
            Fault::Settling => f.write_str("signal chain settling after a fault"),
            Fault::StartedMoving => f.write_str("switched on while the boom moved: no weighing until it stops"),
            Fault::Output => f.write_str("output driver failed"),
        }
    }
}
