//! The hardware seam: what the limiter reads and drives.
//!
//! Small on purpose: the firmware implements these over embedded-hal (an SPI ADC
//! and four `OutputPin`s, see the `limiter-drivers` crate) in a few lines, tests
//! implement them with plain structs, and the replay tool feeds recorded values
//! straight into the limiter without them.

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
