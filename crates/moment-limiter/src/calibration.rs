//! Learning the friction correction from unloaded runs (`crane-sim calibrate`).
//!
//! With no hook load the model gives the piston force F_model(0) at every
//! boom state, so each moving sample of an unloaded log gives a residual
//! r = F_meas − F_model(0) = force_offset + friction(direction). The learner
//! averages r over the samples moving up (r_up) and moving down (r_down),
//! using the very same signal chain as the limiter (feed it the
//! [`Measurement`]s of a [`crate::limiter::Limiter`] run with
//! [`Calibration::none`]).
//!
//! A constant zero offset and a per-direction friction cannot be told apart
//! from these two numbers, and the limiter does not need them apart: it
//! subtracts offset + friction(up) = r_up while raising and
//! offset − friction(down) = r_down while lowering, whatever the split. The
//! learner reports the symmetric split: force_offset = (r_up + r_down)/2,
//! friction_up = friction_down = max(0, (r_up − r_down)/2). Transducer zero
//! offsets (bar) and the pendulum offset are not learned (0); a technician
//! may set them in the calibration file.

use crane_model::load_model::HookLoadModel;
use crane_model::{ModelError, Real};

use crate::limiter::Measurement;
use crate::load_estimate::{Calibration, Direction};

/// Why no calibration could be learned.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CalibrationError {
    /// Too few samples moving up (`true`) or down (`false`).
    TooFewSamples {
        /// Which direction lacks samples: `true` up, `false` down.
        up: bool,
        /// How many there were.
        found: u32,
    },
    /// A sum became NaN or infinite.
    NotFinite,
}

impl core::fmt::Display for CalibrationError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            CalibrationError::TooFewSamples { up, found } => write!(
                f,
                "too few samples moving {} ({found}): give an unloaded boom-{} log",
                if *up { "up" } else { "down" },
                if *up { "up" } else { "down" }
            ),
            CalibrationError::NotFinite => f.write_str("non-finite residual"),
        }
    }
}

/// Running sums of the residual per direction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CalibrationLearner<T> {
    up: (T, u32),
    down: (T, u32),
}

impl<T: Real> Default for CalibrationLearner<T> {
    fn default() -> Self {
        Self::new()
    }
}

impl<T: Real> CalibrationLearner<T> {
    /// No samples yet.
    pub fn new() -> Self {
        Self {
            up: (T::lit(0.0), 0),
            down: (T::lit(0.0), 0),
        }
    }

    /// Adds one sample of an unloaded run (samples with a still boom are ignored).
    pub fn observe<M: HookLoadModel<T>>(
        &mut self,
        model: &M,
        m: &Measurement<T>,
    ) -> Result<(), ModelError> {
        let slot = match m.direction {
            Direction::Up => &mut self.up,
            Direction::Down => &mut self.down,
            Direction::Still => return Ok(()),
        };
        let r = m.piston_force_n - model.piston_force_n(m.boom)?.at_zero;
        slot.0 += r;
        slot.1 = slot.1.saturating_add(1);
        Ok(())
    }

    /// Number of (up, down) samples seen.
    pub fn counts(&self) -> (u32, u32) {
        (self.up.1, self.down.1)
    }

    /// Mean residuals (r_up, r_down) in N, if both directions have samples.
    pub fn mean_residuals_n(&self) -> Option<(T, T)> {
        let mean = |(s, n): (T, u32)| (n > 0).then(|| s / T::lit(f64::from(n)));
        Some((mean(self.up)?, mean(self.down)?))
    }

    /// The calibration, if each direction has at least `min_samples` samples.
    pub fn finish(&self, min_samples: u32) -> Result<Calibration<T>, CalibrationError> {
        for (up, n) in [(true, self.up.1), (false, self.down.1)] {
            if n < min_samples.max(1) {
                return Err(CalibrationError::TooFewSamples { up, found: n });
            }
        }
        let (r_up, r_down) = self.mean_residuals_n().ok_or(CalibrationError::NotFinite)?;
        let half = T::lit(0.5);
        let offset = (r_up + r_down) * half;
        let friction = ((r_up - r_down) * half).max(T::lit(0.0));
        if !(offset.is_finite() && friction.is_finite()) {
            return Err(CalibrationError::NotFinite);
        }
        Ok(Calibration {
            friction_up_n: friction,
            friction_down_n: friction,
            force_offset_n: offset,
            ..Calibration::none()
        })
    }
}
