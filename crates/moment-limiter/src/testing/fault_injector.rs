//! Sensor fault injection, for tests and the simulator (after smoltcp's
//! `phy::FaultInjector`).
//!
//! [`FaultInjector`] wraps any [`SensorInputs`] and corrupts its counts;
//! [`FrameFaultInjector`] corrupts recorded frames in physical units (the
//! replay's input) the same way. Per channel, one fault can be active:
//!
//! | fault | counts | physical frame |
//! |---|---|---|
//! | open circuit | 0 (0 mA, wiper open) | the value 0 counts converts to (−50 bar, −11.3°) |
//! | short circuit | 4095 (22 mA, wiper at supply) | the value 4095 counts converts to (225 bar, 102.5°) |
//! | stuck | the value at the moment the fault was set, forever | same |
//! | spike | one sample offset by ‰ of full scale, then the fault clears itself | ‰ of span (200 bar, 90°) |
//! | NaN | `Err(InputError::BadFrame)` (a count cannot be NaN) | NaN |
//! | noise | uniform ±‰ of full scale, every sample | ±‰ of span |
//!
//! Random faults draw from a seeded xorshift32 generator: no heap, no std,
//! the same sequence for the same seed.

use crane_model::Real;

use crate::conversion::{SensorConversion, ADC_MAX_COUNTS};
use crate::io::{Channel, InputError, SensorInputs};
use crate::io::Frame;
use crate::units::PRESSURE_SPAN_BAR;

/// A fault to inject on one channel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum InjectedFault {
    /// Broken wire.
    OpenCircuit,
    /// Short to supply / over-range.
    ShortCircuit,
    /// Frozen at the value when the fault was set.
    Stuck,
    /// One sample offset by this many thousandths of full scale (signed).
    Spike {
        /// Offset in ‰ of full scale.
        per_mille: i32,
    },
    /// Not a number (a bad converter frame on the counts path).
    Nan,
    /// Uniform noise of this amplitude in ‰ of full scale.
    Noise {
        /// Amplitude in ‰ of full scale.
        per_mille: u16,
    },
}

/// Seeded xorshift32 (Marsaglia 2003): small, no_std, reproducible.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Rng(u32);

impl Rng {
    /// A generator; seed 0 is replaced by 1 (xorshift's fixed point).
    pub fn new(seed: u32) -> Self {
        Self(if seed == 0 { 1 } else { seed })
    }
    /// Next 32 random bits.
    pub fn next_u32(&mut self) -> u32 {
        let mut x = self.0;
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        self.0 = x;
        x
    }
    /// Uniform in [−1, 1].
    pub fn symmetric_unit(&mut self) -> f64 {
        f64::from(self.next_u32()) / f64::from(u32::MAX) * 2.0 - 1.0
    }
}

fn channel_index(channel: Channel) -> usize {
    match channel {
        Channel::PistonSidePressure => 0,
        Channel::RodSidePressure => 1,
        Channel::BoomAngle => 2,
    }
}

/// Per-channel fault state shared by both injectors (`V` is the value type).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Slot<V> {
    fault: Option<InjectedFault>,
    held: Option<V>,
}

/// Wraps a [`SensorInputs`] and injects faults into its counts.
#[derive(Debug, Clone)]
pub struct FaultInjector<S> {
    inner: S,
    slots: [Slot<u16>; 3],
    rng: Rng,
}

impl<S: SensorInputs> FaultInjector<S> {
    /// Wraps `inner` with no fault active.
    pub fn new(inner: S, seed: u32) -> Self {
        Self {
            inner,
            slots: [Slot {
                fault: None,
                held: None,
            }; 3],
            rng: Rng::new(seed),
        }
    }
    /// Sets (or with `None` clears) the fault on a channel.
    pub fn set_fault(&mut self, channel: Channel, fault: Option<InjectedFault>) {
        if let Some(slot) = self.slots.get_mut(channel_index(channel)) {
            *slot = Slot { fault, held: None };
        }
    }
    /// The wrapped source.
    pub fn inner_mut(&mut self) -> &mut S {
        &mut self.inner
    }
}

fn offset_counts(counts: u16, per_mille: f64) -> u16 {
    let c = f64::from(counts) + per_mille / 1000.0 * f64::from(ADC_MAX_COUNTS);
    if c <= 0.0 {
        0
    } else if c >= f64::from(ADC_MAX_COUNTS) {
        ADC_MAX_COUNTS
    } else {
        // In 0..4095 after the checks above.
        (c + 0.5) as u16
    }
}

impl<S: SensorInputs> SensorInputs for FaultInjector<S> {
    fn read_counts(&mut self, channel: Channel) -> Result<u16, InputError> {
        let value = self.inner.read_counts(channel)?;
        let Some(slot) = self.slots.get_mut(channel_index(channel)) else {
            return Ok(value);
        };
        match slot.fault {
            None => Ok(value),
            Some(InjectedFault::OpenCircuit) => Ok(0),
            Some(InjectedFault::ShortCircuit) => Ok(ADC_MAX_COUNTS),
            Some(InjectedFault::Stuck) => Ok(*slot.held.get_or_insert(value)),
            Some(InjectedFault::Spike { per_mille }) => {
                slot.fault = None;
                Ok(offset_counts(value, f64::from(per_mille)))
            }
            Some(InjectedFault::Nan) => Err(InputError::BadFrame),
            Some(InjectedFault::Noise { per_mille }) => Ok(offset_counts(
                value,
                f64::from(per_mille) * self.rng.symmetric_unit(),
            )),
        }
    }
}

/// Injects faults into recorded frames in physical units.
#[derive(Debug, Clone)]
pub struct FrameFaultInjector<T> {
    conversion: SensorConversion<T>,
    slots: [Slot<T>; 3],
    rng: Rng,
}

impl<T: Real> FrameFaultInjector<T> {
    /// An injector with no fault active; `conversion` gives the values an open
    /// or shorted sensor reads.
    pub fn new(conversion: SensorConversion<T>, seed: u32) -> Self {
        Self {
            conversion,
            slots: [Slot {
                fault: None,
                held: None,
            }; 3],
            rng: Rng::new(seed),
        }
    }

    /// Sets (or with `None` clears) the fault on a channel.
    pub fn set_fault(&mut self, channel: Channel, fault: Option<InjectedFault>) {
        if let Some(slot) = self.slots.get_mut(channel_index(channel)) {
            *slot = Slot { fault, held: None };
        }
    }

    /// Returns `frame` with the active faults applied.
    pub fn apply(&mut self, frame: Frame<T>) -> Frame<T> {
        let c = self.conversion;
        let mut out = frame;
        for channel in Channel::ALL {
            let (value, span, at_counts): (&mut T, T, &dyn Fn(u16) -> T) = match channel {
                Channel::PistonSidePressure => (&mut out.p1_bar, T::lit(PRESSURE_SPAN_BAR), &|n| {
                    c.raw_pressure_bar(&c.p1, n)
                }),
                Channel::RodSidePressure => (&mut out.p2_bar, T::lit(PRESSURE_SPAN_BAR), &|n| {
                    c.raw_pressure_bar(&c.p2, n)
                }),
                Channel::BoomAngle => (&mut out.boom_angle_deg, T::lit(90.0), &|n| {
                    c.angle.degrees(n)
                }),
            };
            let Some(slot) = self.slots.get_mut(channel_index(channel)) else {
                continue;
            };
            let offset = |pm: f64| span * T::lit(pm / 1000.0);
            match slot.fault {
                None => {}
                Some(InjectedFault::OpenCircuit) => *value = at_counts(0),
                Some(InjectedFault::ShortCircuit) => *value = at_counts(ADC_MAX_COUNTS),
                Some(InjectedFault::Stuck) => *value = *slot.held.get_or_insert(*value),
                Some(InjectedFault::Spike { per_mille }) => {
                    slot.fault = None;
                    *value += offset(f64::from(per_mille));
                }
                Some(InjectedFault::Nan) => *value = T::lit(f64::NAN),
                Some(InjectedFault::Noise { per_mille }) => {
                    *value += offset(f64::from(per_mille) * self.rng.symmetric_unit());
                }
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    struct Fixed(u16);
    impl SensorInputs for Fixed {
        fn read_counts(&mut self, _: Channel) -> Result<u16, InputError> {
            Ok(self.0)
        }
    }

    #[test]
    fn counts_faults() {
        let mut f = FaultInjector::new(Fixed(2000), 7);
        let p1 = Channel::PistonSidePressure;
        assert_eq!(f.read_counts(p1), Ok(2000));
        f.set_fault(p1, Some(InjectedFault::OpenCircuit));
        assert_eq!(f.read_counts(p1), Ok(0));
        f.set_fault(p1, Some(InjectedFault::Spike { per_mille: 100 }));
        assert_eq!(f.read_counts(p1), Ok(2410));
        assert_eq!(f.read_counts(p1), Ok(2000)); // one-shot
        f.set_fault(p1, Some(InjectedFault::Stuck));
        assert_eq!(f.read_counts(p1), Ok(2000));
        f.inner_mut().0 = 2100;
        assert_eq!(f.read_counts(p1), Ok(2000));
        assert_eq!(f.read_counts(Channel::BoomAngle), Ok(2100)); // other channels untouched
        f.set_fault(p1, Some(InjectedFault::Noise { per_mille: 10 }));
        let r: Vec<u16> = (0..50).map(|_| f.read_counts(p1).unwrap()).collect();
        assert!(r.iter().all(|&c| (2059..=2141).contains(&c)));
        assert!(r.iter().any(|&c| c != 2100));
    }

    #[test]
    fn same_seed_same_sequence() {
        let mut a = Rng::new(42);
        let mut b = Rng::new(42);
        assert!((0..100).all(|_| a.next_u32() == b.next_u32()));
    }
}
