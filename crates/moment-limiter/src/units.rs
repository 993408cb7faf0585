//! Physical values that exist only when they are valid.
//!
//! "Make illegal states irrepresentable" (smoltcp's wire layer): a [`PressureBar`]
//! or a [`BoomAngle`] can only be built through a constructor that rejects a
//! non-finite value and a value outside the sensor's physical range (SPEC §5).
//! Code that holds one never has to ask again whether the reading is faulted.

use crane_model::Real;

use crate::checks::FaultKind;

/// Span of the two pressure transducers (0–200 bar = 20 MPa, SPEC §2).
pub const PRESSURE_SPAN_BAR: f64 = 200.0;
/// Lowest credible pressure reading: −2 % of span. Below it the loop is broken.
pub const PRESSURE_MIN_BAR: f64 = -0.02 * PRESSURE_SPAN_BAR;
/// Highest credible pressure reading: 105 % of span. Above it the loop is shorted.
pub const PRESSURE_MAX_BAR: f64 = 1.05 * PRESSURE_SPAN_BAR;
/// Lowest credible boom angle (degrees from horizontal, SPEC §5).
pub const ANGLE_MIN_DEG: f64 = -5.0;
/// Highest credible boom angle (degrees from horizontal, SPEC §5).
pub const ANGLE_MAX_DEG: f64 = 95.0;
/// NAMUR NE 43: a loop current below this (mA) means an open circuit.
pub const LOOP_OPEN_BELOW_MA: f64 = 3.6;
/// NAMUR NE 43: a loop current above this (mA) means a short or over-range.
pub const LOOP_SHORT_ABOVE_MA: f64 = 21.0;
/// One bar in pascals.
pub const PA_PER_BAR: f64 = 1.0e5;

/// Checks that `x` is finite and inside `[lo, hi]`.
fn in_range<T: Real>(x: T, lo: f64, hi: f64) -> Result<T, FaultKind> {
    if !x.is_finite() {
        Err(FaultKind::NotFinite)
    } else if x < T::lit(lo) || x > T::lit(hi) {
        Err(FaultKind::OutOfRange)
    } else {
        Ok(x)
    }
}

/// A 4–20 mA loop current that passed the NAMUR NE 43 check (3.6 mA ≤ I ≤ 21 mA).
#[derive(Debug, Clone, Copy, PartialEq, PartialOrd)]
pub struct LoopCurrent<T>(T);

impl<T: Real> LoopCurrent<T> {
    /// Checks a measured loop current (mA): NaN → [`FaultKind::NotFinite`],
    /// below 3.6 mA → [`FaultKind::OpenCircuit`], above 21 mA → [`FaultKind::ShortCircuit`].
    pub fn new(milliamps: T) -> Result<Self, FaultKind> {
        if !milliamps.is_finite() {
            Err(FaultKind::NotFinite)
        } else if milliamps < T::lit(LOOP_OPEN_BELOW_MA) {
            Err(FaultKind::OpenCircuit)
        } else if milliamps > T::lit(LOOP_SHORT_ABOVE_MA) {
            Err(FaultKind::ShortCircuit)
        } else {
            Ok(Self(milliamps))
        }
    }
    /// The current in milliamperes.
    pub fn milliamps(self) -> T {
        self.0
    }
}

/// A hydraulic pressure reading (bar, gauge) inside the transducer's credible
/// range [−2 %, 105 %] of its 200 bar span.
#[derive(Debug, Clone, Copy, PartialEq, PartialOrd)]
pub struct PressureBar<T>(T);

impl<T: Real> PressureBar<T> {
    /// Checks a pressure in bar: NaN/∞ → [`FaultKind::NotFinite`], outside
    /// [−4, 210] bar → [`FaultKind::OutOfRange`] (a broken wire or a short).
    pub fn new(bar: T) -> Result<Self, FaultKind> {
        in_range(bar, PRESSURE_MIN_BAR, PRESSURE_MAX_BAR).map(Self)
    }
    /// The pressure in bar.
    pub fn bar(self) -> T {
        self.0
    }
    /// The pressure in pascals.
    pub fn pascals(self) -> T {
        self.0 * T::lit(PA_PER_BAR)
    }
}

/// A boom angle reading (degrees from horizontal) inside [−5°, 95°].
#[derive(Debug, Clone, Copy, PartialEq, PartialOrd)]
pub struct BoomAngle<T>(T);

impl<T: Real> BoomAngle<T> {
    /// Checks an angle in degrees: NaN/∞ → [`FaultKind::NotFinite`], outside
    /// [−5°, 95°] → [`FaultKind::OutOfRange`].
    pub fn new(degrees: T) -> Result<Self, FaultKind> {
        in_range(degrees, ANGLE_MIN_DEG, ANGLE_MAX_DEG).map(Self)
    }
    /// The angle in degrees.
    pub fn degrees(self) -> T {
        self.0
    }
    /// The angle in radians.
    pub fn radians(self) -> T {
        self.0 * T::pi() / T::lit(180.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pressure_range_follows_spec() {
        assert!(PressureBar::new(-3.9_f64).is_ok());
        assert_eq!(PressureBar::new(-4.1_f64), Err(FaultKind::OutOfRange));
        assert!(PressureBar::new(209.9_f64).is_ok());
        assert_eq!(PressureBar::new(210.1_f64), Err(FaultKind::OutOfRange));
        assert_eq!(PressureBar::new(f64::NAN), Err(FaultKind::NotFinite));
        assert_eq!(PressureBar::new(f32::INFINITY), Err(FaultKind::NotFinite));
    }

    #[test]
    fn angle_range_follows_spec() {
        assert!(BoomAngle::new(-5.0_f64).is_ok());
        assert_eq!(BoomAngle::new(-5.01_f64), Err(FaultKind::OutOfRange));
        assert_eq!(BoomAngle::new(95.01_f32), Err(FaultKind::OutOfRange));
        assert!(
            (BoomAngle::new(90.0_f64).unwrap().radians() - core::f64::consts::FRAC_PI_2).abs()
                < 1e-12
        );
    }

    #[test]
    fn namur_limits() {
        assert_eq!(LoopCurrent::new(3.59_f64), Err(FaultKind::OpenCircuit));
        assert!(LoopCurrent::new(3.6_f64).is_ok());
        assert!(LoopCurrent::new(21.0_f64).is_ok());
        assert_eq!(LoopCurrent::new(21.01_f64), Err(FaultKind::ShortCircuit));
        assert_eq!(LoopCurrent::new(f64::NAN), Err(FaultKind::NotFinite));
    }
}
