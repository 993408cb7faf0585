//! What the limiter is built with: constant while it runs.

use core::fmt;

use crane_model::Real;

use crate::capacity::Capacity;
use crate::clock::ClockConfig;
use crate::checks::PlausibilityConfig;
use crate::conversion::SensorConversion;
use crate::negative_load::NegativeLoadBound;
use crate::load_estimate::{Calibration, DirectionThresholds};
use crate::state_machine::Thresholds;
use crate::swing::SwingGeometry;


/// Number of events the limiter's log holds.
pub const EVENT_LOG_LEN: usize = 64;

/// Utilization reported when the rated load is zero, and the ceiling of any
/// reported utilization (keeps logs finite; far above every threshold).
pub const UTILIZATION_CEILING: f64 = 10.0;

/// Why a [`LimiterConfig`] was refused; the name says which part.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ConfigError(pub &'static str);

impl fmt::Display for ConfigError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "invalid limiter configuration: {}", self.0)
    }
}

/// The angle sensor's lag of the thesis crane's recorder (s): a pendulum of
/// 2 Hz, ζ = 0.7, lags a steady rate by 2ζ/ω_n = 2·0.7/(2π·2) = 0.1114 s.
pub const DEFAULT_ANGLE_SENSOR_LAG_S: f64 = 2.0 * 0.7 / (2.0 * core::f64::consts::PI * 2.0);

/// The seals' release time the limiter assumes when its calibration has
/// none (s; see [`LimiterConfig::seal_release_s`]).
pub const DEFAULT_SEAL_RELEASE_S: f64 = 0.5;

/// Everything the limiter is configured with (constant while it runs).
#[derive(Debug, Clone, PartialEq)]
pub struct LimiterConfig<T> {
    /// Counts → physical units.
    pub conversion: SensorConversion<T>,
    /// Rate-of-change and stuck limits.
    pub plausibility: PlausibilityConfig<T>,
    /// Cut-off of each stage of the filter on the piston force and the boom
    /// angle (Hz): one filter for both keeps them aligned in time.
    pub filter_hz: T,
    /// Number of first-order stages of that filter (1…[`crate::filter::MAX_STAGES`]).
    pub filter_stages: usize,
    /// Direction-of-motion thresholds.
    pub direction: DirectionThresholds<T>,
    /// Lag of the angle sensor behind the boom for a steady rate (s): for a
    /// pendulum potentiometer of natural frequency ω_n and damping ζ, 2ζ/ω_n
    /// (the sensor's data; see [`super::Limiter`] "Time alignment"). 0 for a sensor
    /// without lag. A calibration that holds a lag
    /// ([`Calibration::angle_sensor_lag_s`]) overrides it
    /// ([`Self::effective_angle_sensor_lag_s`]).
    pub angle_sensor_lag_s: T,
    /// Time constant (s) with which the friction of the last motion is taken
    /// to leave the force once the boom is still (the seals release; see
    /// [`crate::load_estimate`]). After a raise, a calibration that holds
    /// one ([`Calibration::seal_release_up_s`]) overrides it
    /// ([`Self::effective_seal_release_s`]; [`crate::seal_release`]).
    pub seal_release_s: T,
    /// Crane geometry for the bank of rope hypotheses and their
    /// pendulums ([`crate::static_load`]); `None` turns the rope and swing
    /// corrections off (the load taken hanging straight and still).
    pub swing: Option<SwingGeometry<T>>,
    /// Safety factor and chart.
    pub capacity: Capacity<T>,
    /// State machine thresholds and times.
    pub thresholds: Thresholds<T>,
    /// Friction and offsets.
    pub calibration: Calibration<T>,
    /// The factor the model's load estimate is read with (1.0…1.1). SAE
    /// J376 asks a load indicator to read between 100 % and 110 % of the true
    /// load, never below it: the limiter aims at the middle of that band, so
    /// an estimate within ±5 % of the truth still reads inside it. The
    /// utilization, and so every alarm, uses the load as read.
    pub load_reading_factor: T,
    /// The clock's nominal period and longest allowed step ([`crate::clock`]).
    pub clock: ClockConfig,
    /// How negative a load estimate may be, and for how long, before it is
    /// a FAULT ([`crate::negative_load`]).
    pub negative_load: NegativeLoadBound<T>,
}

impl<T: Real> LimiterConfig<T> {
    /// The documented defaults of every module; force and angle filtered by
    /// 4 stages at 1.2 Hz (delay 0.53 s; the boom's first bending oscillation,
    /// 3.3–4 Hz, is cut to 0.7–1.4 %, and the angle's second difference is
    /// smooth enough for the inertia correction: 0.09 °/s² of noise, 0.3 %
    /// of a 3.3 t load at 60°, for 0.03° on the angle; a step of load shows
    /// 90 % of its size after 0.88 s); the load read ×1.05 (J376); the angle sensor of the thesis crane's
    /// recorder (pendulum of 2 Hz, ζ = 0.7: lag 2·0.7/(2π·2) = 0.1114 s); the
    /// rope bank with the COLES Mobile 930 geometry; no calibration.
    pub fn standard() -> Self {
        Self {
            conversion: SensorConversion::standard(),
            plausibility: PlausibilityConfig::standard(),
            filter_hz: T::lit(1.2),
            filter_stages: 4,
            direction: DirectionThresholds::standard(),
            angle_sensor_lag_s: T::lit(DEFAULT_ANGLE_SENSOR_LAG_S),
            seal_release_s: T::lit(DEFAULT_SEAL_RELEASE_S),
            swing: Some(SwingGeometry::coles_930()),
            capacity: Capacity::standard(),
            thresholds: Thresholds::standard(),
            calibration: Calibration::none(),
            load_reading_factor: T::lit(1.05),
            clock: ClockConfig::standard(),
            negative_load: NegativeLoadBound::standard(),
        }
    }

    /// The angle sensor's lag the limiter aligns with (s): the
    /// calibration's, if it holds one, else the configured default.
    pub fn effective_angle_sensor_lag_s(&self) -> T {
        self.calibration.angle_sensor_lag_s.unwrap_or(self.angle_sensor_lag_s)
    }

    /// The seals' release time the limiter takes the friction of the last
    /// motion off with (s), given the friction in the force: after a raise
    /// the calibration's, if it holds one, else (and after a lowering) the
    /// configured one ([`crate::seal_release`]).
    pub fn effective_seal_release_s(&self, friction: crate::load_estimate::Friction) -> T {
        use crate::load_estimate::{Direction, Friction};
        match (friction, self.calibration.seal_release_up_s) {
            (Friction::Static { last_moving: Some(Direction::Up) }, Some(s)) => s,
            _ => self.seal_release_s,
        }
    }

    /// Checks every part.
    pub fn validate(&self) -> Result<(), ConfigError> {
        let hz = |x: T| x.is_finite() && x > T::lit(0.0);
        let checks = [
            (self.conversion.is_valid(), "conversion"),
            (self.plausibility.is_valid(), "plausibility"),
            (hz(self.filter_hz), "filter_hz"),
            (
                (1..=crate::filter::MAX_STAGES).contains(&self.filter_stages),
                "filter_stages",
            ),
            (self.direction.is_valid(), "direction"),
            (
                self.angle_sensor_lag_s.is_finite() && self.angle_sensor_lag_s >= T::lit(0.0),
                "angle_sensor_lag_s",
            ),
            (hz(self.seal_release_s), "seal_release_s"),
            (self.swing.is_none_or(|g| g.is_valid()), "swing"),
            (self.capacity.is_valid(), "capacity"),
            (self.thresholds.is_valid(), "thresholds"),
            (self.calibration.is_valid(), "calibration"),
            (
                self.load_reading_factor >= T::lit(1.0) && self.load_reading_factor <= T::lit(1.1),
                "load_reading_factor",
            ),
            (self.clock.is_valid(), "clock"),
            (self.negative_load.is_valid(), "negative_load"),
        ];
        match checks.iter().find(|(ok, _)| !ok) {
            Some((_, name)) => Err(ConfigError(name)),
            None => Ok(()),
        }
    }
}
