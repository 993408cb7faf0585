//! The negative-load bound: a load estimate that no hook can produce is a
//! FAULT, not a reading (issue 12).
//!
//! No hook load is negative, but the estimate of an unloaded hook reads below
//! zero by what the limiter cannot know exactly: the static friction of a
//! still cylinder (half the friction, see [`crate::load_estimate`]), and the
//! inertia of the boom in a fast ramp, whose estimate lags the force. Both
//! are **forces at the cylinder**, so the load they fake scales with the
//! inverse of the load's arm: the same 5 kN reads −0.4 t at 40° and −2.2 t
//! at 85°. A bound in kilograms would either cut an unloaded crane standing
//! at 85° or let a grossly wrong reading pass at 45°. So the bound is on the
//! **load moment about the boom foot**, W·L·cos θ (kg·m; L the boom length,
//! θ the boom angle at the force's instant), and it must hold for
//! [`NegativeLoadBound::hold_s`] to fault:
//!
//! - **bound −6000 kg·m for 1 s** (defaults). Measured with `crane-sim synth`
//!   and `replay` on unloaded moves (20°→80°, 40°→80°, 40°→85°, both
//!   directions, 10 s and 30 s, linear and cycloidal, two seeds, with and
//!   without the example calibration): the lowest moment was −3.8 t·m
//!   (standing at 85° after raising: static friction), −2.7 t·m in the
//!   lowering ramps. In the fast lowerings from 80° and 85° the synthetic p1
//!   itself drops out of range (a sensor FAULT) and, when it comes back, the
//!   restarted estimate dips to −14 t·m, but stays below −6 t·m for at most
//!   0.42 s. A p1 transducer whose zero is 50 bar off puts an 8 t load at 75°
//!   at −8.3 t·m, held: a FAULT after 1 s.
//! - The bound is a plausibility check, not an alarm: a real overload never
//!   waits for it (a heavier load only raises the estimate). Its delay is
//!   the price of not cutting an unloaded crane in every fast lowering ramp.
//! - A transducer that reads too low but still positive is not caught here
//!   (no bound on a positive load can tell); the calibration schema's bounds
//!   ([`crate::tools::config_file`]) and the range checks ([`crate::checks`]) are
//!   the defences there.

use crane_model::Real;

/// Rounding allowance when comparing accumulated times (s), as the state
/// machine's.
const TIME_EPS_S: f64 = 1e-6;

/// The bound (see the module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NegativeLoadBound<T> {
    /// Boom length from the foot pin A0 to the tip (m): the arm of the load
    /// is L·cos θ.
    pub boom_length_m: T,
    /// Lowest load moment about the boom foot still read as a load (kg·m, ≤ 0).
    pub min_moment_kg_m: T,
    /// Time the moment must stay below the bound to fault (s, ≥ 0).
    pub hold_s: T,
}

impl<T: Real> NegativeLoadBound<T> {
    /// The thesis crane (L = 19.5 m), −6000 kg·m held 1 s.
    pub fn standard() -> Self {
        Self {
            boom_length_m: T::lit(crane_model::CraneData::coles_mobile_930().boom.length_m()),
            min_moment_kg_m: T::lit(-6000.0),
            hold_s: T::lit(1.0),
        }
    }

    /// `true` when the length is positive, the bound not positive and the
    /// time not negative, all finite.
    pub fn is_valid(&self) -> bool {
        self.boom_length_m.is_finite()
            && self.boom_length_m > T::lit(0.0)
            && self.min_moment_kg_m.is_finite()
            && self.min_moment_kg_m <= T::lit(0.0)
            && self.hold_s.is_finite()
            && self.hold_s >= T::lit(0.0)
    }
}

/// How long the estimate has been beyond the bound.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NegativeLoadMonitor<T> {
    bound: NegativeLoadBound<T>,
    below_for_s: Option<T>,
}

impl<T: Real> NegativeLoadMonitor<T> {
    /// A monitor that has seen nothing yet.
    pub fn new(bound: NegativeLoadBound<T>) -> Self {
        Self {
            bound,
            below_for_s: None,
        }
    }

    /// Forgets the time spent below the bound (after a cycle without an
    /// estimate).
    pub fn reset(&mut self) {
        self.below_for_s = None;
    }

    /// One cycle's estimate `load_kg` at boom angle `angle_rad`, `dt_s` after
    /// the previous one; `true` when it is implausible (below the bound for
    /// the hold time).
    pub fn implausible(&mut self, load_kg: T, angle_rad: T, dt_s: T) -> bool {
        let zero = T::lit(0.0);
        // The trigonometry only for negative readings (rare under load).
        let below = load_kg < zero && {
            // In f32 the type's own trigonometry, never libm's `cosf` (soft
            // f64 on the controller).
            let arm = (self.bound.boom_length_m * angle_rad.sin_cos_own().1).max(zero);
            load_kg * arm < self.bound.min_moment_kg_m
        };
        if !below {
            self.below_for_s = None;
            return false;
        }
        let held = self.below_for_s.map_or(zero, |h| h + dt_s);
        self.below_for_s = Some(held);
        held + T::lit(TIME_EPS_S) >= self.bound.hold_s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_bound_is_on_the_moment_and_must_hold() {
        let mut m = NegativeLoadMonitor::new(NegativeLoadBound::<f64>::standard());
        let at = |deg: f64| deg.to_radians();
        // −2.2 t standing at 85° (arm 1.70 m: −3.7 t·m): a reading, forever.
        for _ in 0..1000 {
            assert!(!m.implausible(-2200.0, at(85.0), 0.01));
        }
        // −1.65 t at 75° (arm 5.05 m: −8.3 t·m): implausible after 1 s.
        let mut cycles = 0;
        while !m.implausible(-1650.0, at(75.0), 0.01) {
            cycles += 1;
            assert!(cycles <= 100, "not caught within 1 s");
        }
        assert_eq!(cycles, 100);
        // A dip shorter than the hold time never faults, and resets.
        let mut m = NegativeLoadMonitor::new(NegativeLoadBound::<f64>::standard());
        for _ in 0..3 {
            for _ in 0..50 {
                assert!(!m.implausible(-4000.0, at(79.5), 0.01));
            }
            assert!(!m.implausible(-100.0, at(79.5), 0.01));
        }
        // Beyond 90° the load has no arm: never implausible.
        assert!(!m.implausible(-5000.0, at(92.0), 10.0));
    }
}
