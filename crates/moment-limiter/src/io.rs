//! The hardware seam: what the limiter reads and drives.
//!
//! Small on purpose: the firmware implements these over embedded-hal (an SPI ADC
//! and four `OutputPin`s, see the `limiter-drivers` crate) in a few lines, tests
//! implement them with plain structs, and the replay tool feeds recorded values
//! straight into the limiter without them.

use crane_model::loads::load_model::BoomState;
use crane_model::Real;

use crate::clock::Ticks;
use crate::load_estimate::{Direction, Friction};

/// The three analog inputs of the limiter.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Channel {
    /// p1: pressure transducer on the piston side of the luffing cylinder (4–20 mA loop).
    PistonSidePressure,
    /// p2: pressure transducer on the rod side of the luffing cylinder (4–20 mA loop).
    RodSidePressure,
    /// Pendulum potentiometer giving the boom angle (ratiometric voltage).
    BoomAngle,
}

impl Channel {
    /// All channels in the order the limiter samples them each cycle.
    pub const ALL: [Channel; 3] = [
        Channel::PistonSidePressure,
        Channel::RodSidePressure,
        Channel::BoomAngle,
    ];
}

/// Why a raw reading could not be obtained at all (bus or converter failure).
/// The limiter treats it exactly like a broken sensor: FAULT and cut-off.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum InputError {
    /// The bus transaction (SPI/I2C) failed.
    Bus,
    /// The converter answered with a frame that cannot be decoded.
    BadFrame,
}

/// Source of raw readings: 12-bit ADC counts (0..=4095) per channel.
pub trait SensorInputs {
    /// Reads one channel once. Counts are converted to physical units by the
    /// limiter's per-sensor calibration, not here.
    fn read_counts(&mut self, channel: Channel) -> Result<u16, InputError>;
}

/// What the limiter commands every cycle. `true` means "on" / "cut".
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct OutputCommand {
    /// Amber warning lamp (utilization ≥ 90 %).
    pub warning_lamp: bool,
    /// Red overload lamp and buzzer (OVERLOAD or FAULT).
    pub overload_alarm: bool,
    /// Cut the boom-down (luffing down) motion: it increases the load moment.
    pub cut_boom_down: bool,
    /// Cut the hoist-up motion: it increases the load moment.
    pub cut_hoist_up: bool,
}

impl OutputCommand {
    /// The fail-safe command: alarm on and both moment-increasing motions cut.
    pub const FAIL_SAFE: OutputCommand = OutputCommand {
        warning_lamp: true,
        overload_alarm: true,
        cut_boom_down: true,
        cut_hoist_up: true,
    };
}

/// Why the outputs could not be driven.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct OutputError;

/// The alarm and cut-off outputs.
pub trait Outputs {
    /// Drives all outputs to `command`. Implementations must leave the
    /// moment-increasing motions cut if they fail part-way (fail-safe wiring:
    /// a de-energised cut-off relay blocks the motion).
    fn apply(&mut self, command: OutputCommand) -> Result<(), OutputError>;
}

/// One sample of a recorded log, in physical units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame<T> {
    /// Time on the limiter's clock ([`crate::clock`]).
    pub t: Ticks,
    /// Piston-side pressure p1 (bar).
    pub p1_bar: T,
    /// Rod-side pressure p2 (bar).
    pub p2_bar: T,
    /// Boom angle (degrees from horizontal).
    pub boom_angle_deg: T,
}

/// The signals after conversion and filtering.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Measurement<T> {
    /// Filtered piston force (N), transducer offsets removed, through the
    /// angle sensor's lag too: the force of the filtered angle's instant.
    pub piston_force_n: T,
    /// The same force through the filter only, without the sensor's lag
    /// (N): the force of a still boom, read that much sooner
    /// ([`crate::static_load`], "A still boom: the force without the
    /// sensor's lag"). While a load rises from an empty hook, through one
    /// filter stage fewer ([`crate::static_load`], "A lift-off: one stage
    /// fewer").
    pub force_still_n: T,
    /// Boom angle now (degrees): the filtered reading, pendulum offset
    /// removed, advanced by rate × (sensor lag + filter delay).
    pub boom_angle_deg: T,
    /// Filtered angle rate (degrees per second).
    pub rate_deg_s: T,
    /// Angular acceleration (degrees per second²): the second difference of
    /// the filtered angle, at the time of the filtered force.
    pub accel_deg_s2: T,
    /// Time the boom has been moving in `direction` without interruption (s);
    /// 0 when still.
    pub moving_for_s: T,
    /// Direction of motion.
    pub direction: Direction,
    /// The friction in the force (see [`crate::load_estimate`]).
    pub friction: Friction,
    /// The share of the last motion's friction still in the force of a
    /// still boom (1 at the stop, decaying as the seals release).
    pub static_friction_share: T,
    /// The boom state at the time of the filtered force (force and angle
    /// both through the sensor's lag and the filter): what the load estimate
    /// hands to the model.
    pub boom: BoomState<T>,
    /// The boom state now: what the rated load is computed at.
    pub boom_now: BoomState<T>,
    /// tan of the load swing the paid-out-rope hypothesis predicts at the
    /// time of the filtered force (a diagnostic; 0 without the swing geometry).
    pub tan_swing: T,
}

impl<T: Real> Measurement<T> {
    /// The angular acceleration in rad/s², as the model takes it.
    pub fn accel_rad_s2(&self) -> T {
        self.accel_deg_s2 * T::pi() / T::lit(180.0)
    }
}
