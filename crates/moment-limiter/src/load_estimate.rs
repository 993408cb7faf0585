//! Hook-load estimate from the filtered piston force (thesis §4.2, SPEC §4.3).
//!
//! At the present boom state the model gives the piston force as an affine
//! function of the hook load, F_model(W) = at_zero + per_kg·W. The measured
//! force also carries the cylinder's friction, whose sign follows the motion
//! (the up and down traces of the thesis differ by it), and a zero offset:
//!
//! F_meas = F_model(W) + force_offset + friction(direction), with
//! friction(Up) = +friction_up_n, friction(Down) = −friction_down_n,
//!
//! so W = (F_meas − force_offset − friction(direction) − at_zero) / per_kg.
//!
//! **When the boom is still**, the friction is static: anywhere between zero
//! (the seals relaxed) and the friction of the last motion (the pressure
//! trapped when the boom stopped). The limiter takes the end of that interval
//! that gives the higher, i.e. the safe, load: after lowering the Down
//! correction (the force may read low by up to friction_down), after raising
//! none (the force may read high, which only overestimates). Before any
//! motion has been seen (power-up), the Down correction.
//!
//! **A swinging load** pulls the tip sideways too: the piston force grows by
//! per_kg·W·tan θ·tan φ ([`crate::swing`]), so the slope per kg is
//! per_kg·(1 + tan θ·tan φ) with tan φ from the swing observer (0 without it).

use crane_model::load_model::{BoomState, HookLoadModel};
use crane_model::{ModelError, Real};

/// Direction of boom motion, from the filtered angle rate.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Direction {
    /// Luffing up (angle increasing).
    Up,
    /// Luffing down (angle decreasing).
    Down,
    /// Not moving (|rate| below the threshold).
    Still,
}

impl Direction {
    /// Lower-case name (`up`, `down`, `still`).
    pub fn as_str(self) -> &'static str {
        match self {
            Direction::Up => "up",
            Direction::Down => "down",
            Direction::Still => "still",
        }
    }
}

/// Thresholds of [`DirectionDetector`] (degrees per second, positive).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DirectionThresholds<T> {
    /// |rate| above which a still boom is moving.
    pub start_deg_s: T,
    /// |rate| below which a moving boom is still (< `start_deg_s`: hysteresis).
    pub stop_deg_s: T,
}

impl<T: Real> DirectionThresholds<T> {
    /// Defaults: start at 0.15 °/s, stop below 0.05 °/s (the thesis's slowest
    /// manoeuvre runs at about 1.3 °/s).
    pub fn standard() -> Self {
        Self {
            start_deg_s: T::lit(0.15),
            stop_deg_s: T::lit(0.05),
        }
    }
    /// `true` when 0 < stop ≤ start and both are finite.
    pub fn is_valid(&self) -> bool {
        self.start_deg_s.is_finite()
            && self.stop_deg_s > T::lit(0.0)
            && self.stop_deg_s <= self.start_deg_s
    }
}

/// Direction of motion with hysteresis, remembering the last moving direction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DirectionDetector<T> {
    thresholds: DirectionThresholds<T>,
    current: Direction,
    last_moving: Option<Direction>,
}

impl<T: Real> DirectionDetector<T> {
    /// A detector that starts with a still boom and no motion history.
    pub fn new(thresholds: DirectionThresholds<T>) -> Self {
        Self {
            thresholds,
            current: Direction::Still,
            last_moving: None,
        }
    }

    /// Updates with the filtered angle rate (°/s) and returns the direction.
    pub fn update(&mut self, rate_deg_s: T) -> Direction {
        let th = self.thresholds;
        self.current = match self.current {
            Direction::Up if rate_deg_s > th.stop_deg_s => Direction::Up,
            Direction::Down if rate_deg_s < -th.stop_deg_s => Direction::Down,
            _ if rate_deg_s > th.start_deg_s => Direction::Up,
            _ if rate_deg_s < -th.start_deg_s => Direction::Down,
            _ => Direction::Still,
        };
        if self.current != Direction::Still {
            self.last_moving = Some(self.current);
        }
        self.current
    }

    /// The present direction (before the next update).
    pub fn current(&self) -> Direction {
        self.current
    }

    /// Direction whose friction is in the measured force now (see module doc).
    pub fn friction_direction(&self) -> Direction {
        match (self.current, self.last_moving) {
            (Direction::Still, Some(Direction::Up)) => Direction::Still,
            (Direction::Still, _) => Direction::Down,
            (moving, _) => moving,
        }
    }
}

/// What `crane-sim calibrate` learns (and a technician may adjust).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Calibration<T> {
    /// Cylinder friction while luffing up (N, ≥ 0): the force reads this much high.
    pub friction_up_n: T,
    /// Cylinder friction while luffing down (N, ≥ 0): the force reads this much low.
    pub friction_down_n: T,
    /// Zero-load force offset (N): transducer offsets and model error at W = 0.
    pub force_offset_n: T,
    /// Zero offset of p1 (bar), subtracted before eq. 4.1.
    pub p1_offset_bar: T,
    /// Zero offset of p2 (bar), subtracted before eq. 4.1.
    pub p2_offset_bar: T,
    /// Zero offset of the pendulum (degrees), subtracted from the reading
    /// after its range check.
    pub angle_offset_deg: T,
}

impl<T: Real> Calibration<T> {
    /// No friction and no offsets.
    pub fn none() -> Self {
        let z = T::lit(0.0);
        Self {
            friction_up_n: z,
            friction_down_n: z,
            force_offset_n: z,
            p1_offset_bar: z,
            p2_offset_bar: z,
            angle_offset_deg: z,
        }
    }

    /// `true` when all values are finite and the frictions are not negative.
    pub fn is_valid(&self) -> bool {
        [
            self.friction_up_n,
            self.friction_down_n,
            self.force_offset_n,
            self.p1_offset_bar,
            self.p2_offset_bar,
            self.angle_offset_deg,
        ]
        .iter()
        .all(|x| x.is_finite())
            && self.friction_up_n >= T::lit(0.0)
            && self.friction_down_n >= T::lit(0.0)
    }

    /// Signed friction (N) in the measured force for a direction.
    pub fn friction_n(&self, direction: Direction) -> T {
        match direction {
            Direction::Up => self.friction_up_n,
            Direction::Down => -self.friction_down_n,
            Direction::Still => T::lit(0.0),
        }
    }
}

/// Why no load estimate could be made.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EstimateError {
    /// The model could not be evaluated at this state.
    Model(ModelError),
    /// The model's piston force does not grow with the load (per_kg ≤ 0 or not
    /// finite): the load cannot be inferred from the force here.
    NotObservable,
}

/// Hook load (kg) from the filtered measured force (see the module doc).
/// The force must already have the transducer offsets removed; `tan_swing`
/// is tan φ of the load swing (0: hanging straight).
pub fn estimate_load_kg<T: Real, M: HookLoadModel<T>>(
    model: &M,
    boom: BoomState<T>,
    force_n: T,
    calibration: &Calibration<T>,
    friction_direction: Direction,
    tan_swing: T,
) -> Result<T, EstimateError> {
    let f = model.piston_force_n(boom).map_err(EstimateError::Model)?;
    let per_kg = f.per_kg * (T::lit(1.0) + boom.angle_rad.tan() * tan_swing);
    if !(per_kg.is_finite() && f.at_zero.is_finite() && per_kg > T::lit(0.0)) {
        return Err(EstimateError::NotObservable);
    }
    let w = (force_n
        - calibration.force_offset_n
        - calibration.friction_n(friction_direction)
        - f.at_zero)
        / per_kg;
    if w.is_finite() {
        Ok(w)
    } else {
        Err(EstimateError::NotObservable)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn direction_has_hysteresis_and_memory() {
        let mut d = DirectionDetector::new(DirectionThresholds::<f64>::standard());
        assert_eq!(d.friction_direction(), Direction::Down);
        assert_eq!(d.update(0.1), Direction::Still);
        assert_eq!(d.update(0.2), Direction::Up);
        assert_eq!(d.update(0.1), Direction::Up); // above stop threshold
        assert_eq!(d.update(0.01), Direction::Still);
        // Still after raising: no correction (the safe end of [0, friction_up]).
        assert_eq!(d.friction_direction(), Direction::Still);
        assert_eq!(d.update(-1.0), Direction::Down);
    }
}
