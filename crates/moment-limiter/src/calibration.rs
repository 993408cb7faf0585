//! Learning the friction correction from unloaded runs (`crane-sim calibrate`).
//!
//! With no hook load the model gives the piston force F_model(0) at every
//! boom state, so each sample of an unloaded log in **steady motion** gives a
//! residual r = F_meas − F_model(0) = force_offset + friction(direction). The
//! learner averages r over the steady samples moving up (r_up) and down
//! (r_down), using the very same signal chain as the limiter (feed it the
//! [`Measurement`]s of a [`crate::cycle::Limiter`] run with
//! [`Calibration::none`]).
//!
//! Only steady motion ([`SteadyMotion`]): the residual removes the boom's
//! inertia with the limiter's own acceleration estimate, but in the ramps
//! that estimate lags the force by the pendulum's 0.11 s, and near standstill
//! the friction is not yet (or no longer) fully developed. (Counting every
//! "moving" sample made the learned residuals +9.2 kN / −6.1 kN where the logs
//! carried +12 / −8 kN.) A sample is steady when the boom has moved in one
//! direction for at least `min_moving_s` (the filters and the boom's
//! oscillation after the ramp have settled), at least `min_rate_deg_s`, with
//! |acceleration| at most `max_accel_deg_s2`, **and stays so for
//! `lookahead_s` after it**: the acceleration comes from the filtered
//! pendulum angle, so a deceleration shows in it ≈ 0.11 s after it shows in
//! the force, and the learner holds the last `lookahead_s` of residuals back
//! and drops them when the motion turns out not to have been steady. (The
//! learner runs on recorded logs, after the fact, so it can afford to look
//! ahead; the limiter cannot and does not need to.)
//!
//! **Offset and friction apart.** At rest the seals release (the simulator's
//! standstill release, and what a settled cylinder does), so the residual
//! of a still boom is the force offset alone: the learner averages it over
//! the samples before the first motion of each log and those long after a
//! stop (the limiter's [`Measurement::static_friction_share`] below 1 %),
//! r_rest. With at least as many rest samples as the steady minimum, the
//! calibration is force_offset = r_rest, friction_up = max(0, r_up −
//! r_rest), friction_down = max(0, r_rest − r_down): a friction per
//! direction, and the offset the limiter also removes at rest. Without
//! them, up and down cannot be told from the offset, and the learner
//! reports the symmetric split force_offset = (r_up + r_down)/2,
//! friction_up = friction_down = max(0, (r_up − r_down)/2), which is exact
//! while moving. Transducer zero offsets (bar) and the pendulum offset are
//! not observable from the force alone and are not learned (0); a
//! technician may set them in the calibration file.

use crane_model::loads::load_model::HookLoadModel;
use crane_model::{ModelError, Real};

use crate::io::Measurement;
use crate::load_estimate::{model_force_terms, Calibration, Direction, Friction};

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

/// Which samples count as steady motion (see the module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteadyMotion<T> {
    /// Least time moving in one direction (s).
    pub min_moving_s: T,
    /// Least |rate| (°/s).
    pub min_rate_deg_s: T,
    /// Largest |acceleration| (°/s²).
    pub max_accel_deg_s2: T,
    /// Time the motion must stay steady after a sample for it to count (s).
    pub lookahead_s: T,
}

impl<T: Real> SteadyMotion<T> {
    /// Defaults: moving for 1.5 s (the thesis's longest ramp, plus the
    /// filter's delay), |rate| ≥ 0.5 °/s (the slowest thesis maneuver runs at
    /// 1.4 °/s), |acceleration| ≤ 2 °/s² (the filtered ramps reach 2 °/s²
    /// (30 s) and 7 °/s² (10 s); steady motion reads ±0.5 °/s² of noise), and
    /// 1.0 s of look-ahead.
    pub fn standard() -> Self {
        Self {
            min_moving_s: T::lit(1.5),
            min_rate_deg_s: T::lit(0.5),
            max_accel_deg_s2: T::lit(2.0),
            lookahead_s: T::lit(1.0),
        }
    }

    /// `true` when the measurement is in steady motion.
    pub fn accepts(&self, m: &Measurement<T>) -> bool {
        m.direction != Direction::Still
            && m.moving_for_s >= self.min_moving_s
            && m.rate_deg_s.abs() >= self.min_rate_deg_s
            && m.accel_deg_s2.abs() <= self.max_accel_deg_s2
    }
}

/// Most residuals held back for the look-ahead (1 s at 500 Hz); when full,
/// the oldest is committed early.
pub const LOOKAHEAD_CAPACITY: usize = 512;

/// A residual waiting for its look-ahead: (time moving when seen, residual, up?).
type Pending<T> = (T, T, bool);

/// Running sums of the residual per direction.
#[derive(Debug, Clone)]
pub struct CalibrationLearner<T> {
    steady: SteadyMotion<T>,
    pending: heapless::Deque<Pending<T>, LOOKAHEAD_CAPACITY>,
    up: (T, u32),
    down: (T, u32),
    rest: (T, u32),
    /// Sum of the model's piston force per kg over the rest samples.
    rest_per_kg: T,
}

impl<T: Real> Default for CalibrationLearner<T> {
    fn default() -> Self {
        Self::new()
    }
}

impl<T: Real> CalibrationLearner<T> {
    /// No samples yet; the [`SteadyMotion::standard`] criteria.
    pub fn new() -> Self {
        Self::with_steady_motion(SteadyMotion::standard())
    }

    /// No samples yet; the given criteria.
    pub fn with_steady_motion(steady: SteadyMotion<T>) -> Self {
        Self {
            steady,
            pending: heapless::Deque::new(),
            up: (T::lit(0.0), 0),
            down: (T::lit(0.0), 0),
            rest: (T::lit(0.0), 0),
            rest_per_kg: T::lit(0.0),
        }
    }

    /// Adds one sample of an unloaded run (samples not in steady motion are
    /// ignored).
    pub fn observe<M: HookLoadModel<T>>(
        &mut self,
        model: &M,
        m: &Measurement<T>,
    ) -> Result<(), ModelError> {
        let up = match m.direction {
            Direction::Up => true,
            Direction::Down => false,
            Direction::Still => {
                self.pending.clear();
                // Before any motion, or with the seals released: the offset.
                let released = matches!(m.friction, Friction::Static { last_moving: None })
                    || m.static_friction_share < T::lit(0.01);
                if released {
                    let (f, inertia) =
                        model_force_terms(model, m.boom.angle_rad, m.accel_rad_s2())?;
                    let r = m.piston_force_n - inertia - f.at_zero;
                    self.rest.0 += r;
                    self.rest.1 = self.rest.1.saturating_add(1);
                    self.rest_per_kg += f.per_kg;
                }
                return Ok(());
            }
        };
        if !self.steady.accepts(m) || self.pending.front().is_some_and(|p| p.2 != up) {
            // The motion was not steady: nor were the last `lookahead_s`.
            self.pending.clear();
            if !self.steady.accepts(m) {
                return Ok(());
            }
        }
        let (f, inertia) = model_force_terms(model, m.boom.angle_rad, m.accel_rad_s2())?;
        let r = m.piston_force_n - inertia - f.at_zero;
        let now = m.moving_for_s;
        while let Some(&(t, _, _)) = self.pending.front() {
            if now - t < self.steady.lookahead_s && !self.pending.is_full() {
                break;
            }
            if let Some((_, r, up)) = self.pending.pop_front() {
                self.commit(r, up);
            }
        }
        // Not full here: the loop above made room.
        let _ = self.pending.push_back((now, r, up));
        Ok(())
    }

    fn commit(&mut self, r: T, up: bool) {
        let slot = if up { &mut self.up } else { &mut self.down };
        slot.0 += r;
        slot.1 = slot.1.saturating_add(1);
    }

    /// Ends a log: the residuals still waiting for their look-ahead are
    /// dropped (the log may have ended mid-motion). Call between logs.
    pub fn end_of_log(&mut self) {
        self.pending.clear();
    }

    /// Number of (up, down) samples counted.
    pub fn counts(&self) -> (u32, u32) {
        (self.up.1, self.down.1)
    }

    /// Number of samples at rest with the seals released.
    pub fn rest_count(&self) -> u32 {
        self.rest.1
    }

    /// The hook load (kg) the mean rest residual would be (the residual over
    /// the model's mean force per kg at the rest samples): what a load left
    /// on the "unloaded" run weighs.
    pub fn rest_load_kg(&self) -> Option<T> {
        let per_kg = self.rest_per_kg / T::lit(f64::from(self.rest.1.max(1)));
        let r = self.mean_rest_residual_n()?;
        (per_kg > T::lit(0.0)).then(|| r / per_kg)
    }

    /// Mean residual at rest (N): the force offset, if any rest sample.
    pub fn mean_rest_residual_n(&self) -> Option<T> {
        (self.rest.1 > 0).then(|| self.rest.0 / T::lit(f64::from(self.rest.1)))
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
        let zero = T::lit(0.0);
        let (offset, up, down) = match self.mean_rest_residual_n() {
            Some(rest) if self.rest.1 >= min_samples.max(1) => {
                (rest, (r_up - rest).max(zero), (rest - r_down).max(zero))
            }
            _ => {
                let f = ((r_up - r_down) * half).max(zero);
                ((r_up + r_down) * half, f, f)
            }
        };
        if !(offset.is_finite() && up.is_finite() && down.is_finite()) {
            return Err(CalibrationError::NotFinite);
        }
        Ok(Calibration {
            friction_up_n: up,
            friction_down_n: down,
            force_offset_n: offset,
            ..Calibration::none()
        })
    }
}
