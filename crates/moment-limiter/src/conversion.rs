//! Per-sensor conversion of raw ADC counts to physical units.
//!
//! The analog front end is a 12-bit ADC (0..=4095 counts over `vref_v`).
//! - Pressure transducers (p1, p2): 4–20 mA loop through a shunt resistor;
//!   counts → volts → loop current (mA) → bar (4 mA = 0 bar, 20 mA = span).
//!   The current is checked against NAMUR NE 43 *before* it becomes a pressure.
//! - Pendulum potentiometer: ratiometric, counts → degrees by a two-point
//!   calibration (counts at 0° and at 90°).
//!
//! Defaults (see [`SensorConversion::standard`]): vref 3.3 V, shunt 150 Ω (so
//! full scale is 22 mA and a short above 21 mA is still visible), 0–200 bar
//! transducers, potentiometer 410 counts at 0° and 3686 counts at 90° (10 % and
//! 90 % of the range: a wiper or supply wire break reads beyond −5°…95°).

use crane_model::Real;

use crate::checks::FaultKind;
use crate::units::{BoomAngle, LoopCurrent, PressureBar, PRESSURE_SPAN_BAR};

/// Highest count a 12-bit converter can return.
pub const ADC_MAX_COUNTS: u16 = 4095;

/// The ADC and the shunt that turns a loop current into a voltage.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AdcFrontEnd<T> {
    /// ADC reference voltage (V) = the voltage read as 4095 counts.
    pub vref_v: T,
    /// Loop-current shunt resistance (Ω).
    pub shunt_ohm: T,
}

impl<T: Real> AdcFrontEnd<T> {
    /// Loop current (mA) for a count, without any check.
    pub fn milliamps(&self, counts: u16) -> T {
        T::lit(f64::from(counts)) / T::lit(f64::from(ADC_MAX_COUNTS)) * self.vref_v / self.shunt_ohm
            * T::lit(1000.0)
    }
    /// The count (rounded, saturated to 0..=4095) that a loop current produces.
    pub fn counts_for_milliamps(&self, milliamps: T) -> u16 {
        let c = milliamps / T::lit(1000.0) * self.shunt_ohm / self.vref_v
            * T::lit(f64::from(ADC_MAX_COUNTS));
        saturate_counts(c.to_f64())
    }
}

/// Rounds and saturates a count; NaN becomes 0 (an open circuit, which faults).
fn saturate_counts(c: f64) -> u16 {
    if c.is_nan() || c <= 0.0 {
        0
    } else if c >= f64::from(ADC_MAX_COUNTS) {
        ADC_MAX_COUNTS
    } else {
        // In range 0..4095 after the checks above; `as` cannot truncate here.
        (c + 0.5) as u16
    }
}

/// A 4–20 mA pressure transducer: 4 mA = 0 bar, 20 mA = `span_bar`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PressureTransducer<T> {
    /// Pressure at 20 mA (bar). The range checks of [`PressureBar`] assume 200 bar.
    pub span_bar: T,
}

impl<T: Real> PressureTransducer<T> {
    /// Pressure (bar) for a loop current, without any check.
    pub fn bar(&self, milliamps: T) -> T {
        (milliamps - T::lit(4.0)) / T::lit(16.0) * self.span_bar
    }
    /// Loop current (mA) for a pressure.
    pub fn milliamps(&self, bar: T) -> T {
        bar / self.span_bar * T::lit(16.0) + T::lit(4.0)
    }
}

/// The pendulum potentiometer, calibrated at two points.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AnglePotentiometer<T> {
    /// Count read with the boom horizontal (0°).
    pub counts_at_0_deg: T,
    /// Count read with the boom vertical (90°).
    pub counts_at_90_deg: T,
}

impl<T: Real> AnglePotentiometer<T> {
    /// Angle (degrees) for a count, without any check.
    pub fn degrees(&self, counts: u16) -> T {
        (T::lit(f64::from(counts)) - self.counts_at_0_deg) * T::lit(90.0)
            / (self.counts_at_90_deg - self.counts_at_0_deg)
    }
    /// The count (rounded, saturated) read at an angle.
    pub fn counts(&self, degrees: T) -> u16 {
        let c = self.counts_at_0_deg
            + degrees / T::lit(90.0) * (self.counts_at_90_deg - self.counts_at_0_deg);
        saturate_counts(c.to_f64())
    }
}

/// Conversion of all three channels.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SensorConversion<T> {
    /// ADC and shunt shared by both pressure loops.
    pub adc: AdcFrontEnd<T>,
    /// Piston-side transducer p1.
    pub p1: PressureTransducer<T>,
    /// Rod-side transducer p2.
    pub p2: PressureTransducer<T>,
    /// Pendulum potentiometer.
    pub angle: AnglePotentiometer<T>,
}

impl<T: Real> SensorConversion<T> {
    /// The front end described in the module doc.
    pub fn standard() -> Self {
        let transducer = PressureTransducer {
            span_bar: T::lit(PRESSURE_SPAN_BAR),
        };
        Self {
            adc: AdcFrontEnd {
                vref_v: T::lit(3.3),
                shunt_ohm: T::lit(150.0),
            },
            p1: transducer,
            p2: transducer,
            angle: AnglePotentiometer {
                counts_at_0_deg: T::lit(410.0),
                counts_at_90_deg: T::lit(3686.0),
            },
        }
    }

    /// `true` when every parameter is finite and the conversion is invertible.
    pub fn is_valid(&self) -> bool {
        let pos = |x: T| x.is_finite() && x > T::lit(0.0);
        pos(self.adc.vref_v)
            && pos(self.adc.shunt_ohm)
            && pos(self.p1.span_bar)
            && pos(self.p2.span_bar)
            && self.angle.counts_at_0_deg.is_finite()
            && pos(self.angle.counts_at_90_deg - self.angle.counts_at_0_deg)
    }

    /// Checked pressure from counts: NAMUR check on the loop current, then the
    /// physical range check.
    // Never inlined: its inlined copies, one per pressure channel and cycle
    // entry, took 0.3 KB more of the board's 64 KiB flash than one call.
    #[inline(never)]
    pub fn pressure(
        &self,
        transducer: &PressureTransducer<T>,
        counts: u16,
    ) -> Result<PressureBar<T>, FaultKind> {
        let current = LoopCurrent::new(self.adc.milliamps(counts))?;
        PressureBar::new(transducer.bar(current.milliamps()))
    }

    /// Checked boom angle from counts.
    pub fn boom_angle(&self, counts: u16) -> Result<BoomAngle<T>, FaultKind> {
        BoomAngle::new(self.angle.degrees(counts))
    }

    /// The count a pressure produces on a transducer (for tests and injectors).
    pub fn counts_for_pressure(&self, transducer: &PressureTransducer<T>, bar: T) -> u16 {
        self.adc.counts_for_milliamps(transducer.milliamps(bar))
    }

    /// The pressure (unchecked) that a count converts to.
    pub fn raw_pressure_bar(&self, transducer: &PressureTransducer<T>, counts: u16) -> T {
        transducer.bar(self.adc.milliamps(counts))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pressure_round_trip_and_faults() {
        let c = SensorConversion::<f64>::standard();
        let counts = c.counts_for_pressure(&c.p1, 100.0);
        let p = c.pressure(&c.p1, counts).unwrap().bar();
        // One count is about 0.067 bar.
        assert!((p - 100.0).abs() < 0.07, "{p}");
        assert_eq!(c.pressure(&c.p1, 0), Err(FaultKind::OpenCircuit));
        assert_eq!(
            c.pressure(&c.p1, ADC_MAX_COUNTS),
            Err(FaultKind::ShortCircuit)
        );
        // 3.7 mA passes NAMUR but is −3.75 bar: inside −2 %.
        let c37 = c.adc.counts_for_milliamps(3.7);
        assert!(c.pressure(&c.p1, c37).is_ok());
    }

    #[test]
    fn angle_round_trip_and_faults() {
        let c = SensorConversion::<f32>::standard();
        let a = c.boom_angle(c.angle.counts(45.0)).unwrap().degrees();
        assert!((a - 45.0).abs() < 0.03);
        assert_eq!(c.boom_angle(0), Err(FaultKind::OutOfRange));
        assert_eq!(c.boom_angle(ADC_MAX_COUNTS), Err(FaultKind::OutOfRange));
    }
}
