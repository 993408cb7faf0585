//! Fault detection on each reading.
//!
//! Two kinds of check:
//! - **Instant** checks on one reading, done by the constructors of
//!   [`crate::units`]: NaN, open circuit (< 3.6 mA) and short / over-range
//!   (> 21 mA) per NAMUR NE 43, and the physical range (pressure −2 %…105 % of
//!   span, angle −5°…95°).
//! - **History** checks across cycles, done by [`PlausibilityMonitor`]:
//!   - *implausible rate of change*: |Δx| / Δt above the channel's limit
//!     (defaults: 5000 bar/s, i.e. 50 bar in one 10 ms cycle; 60 °/s, where the
//!     thesis's fastest manoeuvre moves the boom at about 4 °/s), with Δt
//!     taken as at least the nominal period
//!     ([`PlausibilityMonitor::with_period_s`]): a reading's noise and
//!     quantization do not shrink with the interval, and a logger's
//!     timestamps jitter (±5 ms at 100 Hz puts readings 0.2 ms apart; the
//!     angle's noise of 0.04° over 1.3 ms is 30 °/s, and a log of a moving
//!     boom FAULTed every few seconds). A jump is still caught: 0.6° or
//!     50 bar within one period;
//!   - *stuck*: a channel has stayed within `stuck_band` of one value for at
//!     least `stuck_time_s` counted only over cycles in which another channel
//!     had changed within the last `stuck_time_s` ("frozen while others move").
//!     A live transducer always shows at least one count of noise; a value
//!     frozen by a failed converter, multiplexer or driver does not. The "while
//!     another changed" clause stops a perfectly quiet (e.g. hand-made) log of a
//!     crane at rest from faulting. Defaults: band 0 (bit-identical), 2.0 s.
//!
//! A monitor never forgets how long a channel has been frozen because of a
//! fault elsewhere: a stuck channel stays faulted, so the limiter cannot cycle
//! between FAULT and recovery on it.

use crane_model::Real;

use crate::io::{Channel, InputError};

/// What is wrong with one reading.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FaultKind {
    /// Loop current below 3.6 mA (NAMUR NE 43): broken wire.
    OpenCircuit,
    /// Loop current above 21 mA (NAMUR NE 43): short or over-range.
    ShortCircuit,
    /// Physical value outside the sensor's credible range.
    OutOfRange,
    /// NaN or infinite value.
    NotFinite,
    /// Frozen value while the other channels change.
    Stuck,
    /// Change faster than the channel can physically move.
    RateOfChange,
    /// The reading could not be obtained (bus or converter).
    Input(InputError),
}

impl FaultKind {
    /// Short lower-case description, for logs and the replay timeline.
    pub fn as_str(self) -> &'static str {
        match self {
            FaultKind::OpenCircuit => "open circuit",
            FaultKind::ShortCircuit => "short circuit",
            FaultKind::OutOfRange => "out of range",
            FaultKind::NotFinite => "not a number",
            FaultKind::Stuck => "stuck",
            FaultKind::RateOfChange => "implausible rate of change",
            FaultKind::Input(InputError::Bus) => "bus error",
            FaultKind::Input(InputError::BadFrame) => "bad converter frame",
        }
    }
}

/// A fault on one channel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SensorFault {
    /// Which sensor.
    pub channel: Channel,
    /// What is wrong with it.
    pub kind: FaultKind,
}

/// Short name of a channel as used in the log format (`p1`, `p2`, `angle`).
pub fn channel_name(channel: Channel) -> &'static str {
    match channel {
        Channel::PistonSidePressure => "p1",
        Channel::RodSidePressure => "p2",
        Channel::BoomAngle => "angle",
    }
}

/// Limits of the history checks for one channel.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ChannelLimits<T> {
    /// Largest credible rate of change (unit per second).
    pub max_rate_per_s: T,
    /// A change of at most this much counts as "no change" for the stuck check.
    pub stuck_band: T,
}

impl<T: Real> ChannelLimits<T> {
    /// Whether a change of `change` over `dt_s` is faster than the channel
    /// can change, the rate taken over at least `period_s` (the cycle's
    /// nominal period: see the module doc).
    pub fn exceeds_rate(&self, change: T, dt_s: T, period_s: T) -> bool {
        change.abs() > self.max_rate_per_s * dt_s.max(period_s)
    }
}

/// Parameters of [`PlausibilityMonitor`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlausibilityConfig<T> {
    /// Limits for p1 (bar).
    pub p1: ChannelLimits<T>,
    /// Limits for p2 (bar).
    pub p2: ChannelLimits<T>,
    /// Limits for the boom angle (degrees).
    pub angle: ChannelLimits<T>,
    /// How long a channel may stay frozen while another changes (s).
    pub stuck_time_s: T,
}

impl<T: Real> PlausibilityConfig<T> {
    /// The defaults given in the module doc.
    pub fn standard() -> Self {
        let pressure = ChannelLimits {
            max_rate_per_s: T::lit(5000.0),
            stuck_band: T::lit(0.0),
        };
        Self {
            p1: pressure,
            p2: pressure,
            angle: ChannelLimits {
                max_rate_per_s: T::lit(60.0),
                stuck_band: T::lit(0.0),
            },
            stuck_time_s: T::lit(2.0),
        }
    }

    /// `true` when every limit is finite and non-negative and the rates positive.
    pub fn is_valid(&self) -> bool {
        let ok = |l: &ChannelLimits<T>| {
            l.max_rate_per_s.is_finite()
                && l.max_rate_per_s > T::lit(0.0)
                && l.stuck_band.is_finite()
                && l.stuck_band >= T::lit(0.0)
        };
        ok(&self.p1)
            && ok(&self.p2)
            && ok(&self.angle)
            && self.stuck_time_s.is_finite()
            && self.stuck_time_s > T::lit(0.0)
    }

    fn limits(&self, i: usize) -> ChannelLimits<T> {
        match i {
            0 => self.p1,
            1 => self.p2,
            _ => self.angle,
        }
    }
}

/// History of one channel.
#[derive(Debug, Clone, Copy, PartialEq)]
struct ChannelHistory<T> {
    /// Last accepted value, for the rate check (`None` after a gap).
    last: Option<T>,
    /// Value the channel has stayed near, and for how long (s).
    hold_value: Option<T>,
    hold_s: T,
    /// Part of the hold during which another channel was live (s).
    frozen_while_others_live_s: T,
}

/// Rate-of-change and stuck checks across cycles, for the three channels in
/// the order of [`Channel::ALL`].
#[derive(Debug, Clone, PartialEq)]
pub struct PlausibilityMonitor<T> {
    config: PlausibilityConfig<T>,
    history: [ChannelHistory<T>; 3],
    /// The shortest interval a rate is taken over (s; see the module doc).
    period_s: T,
}

impl<T: Real> PlausibilityMonitor<T> {
    /// A monitor with no history.
    pub fn new(config: PlausibilityConfig<T>) -> Self {
        let empty = ChannelHistory {
            last: None,
            hold_value: None,
            hold_s: T::lit(0.0),
            frozen_while_others_live_s: T::lit(0.0),
        };
        Self {
            config,
            history: [empty; 3],
            period_s: T::lit(0.0),
        }
    }

    /// The same, taking every rate over at least `period_s`, the nominal
    /// period of the cycle (see the module doc).
    pub fn with_period_s(self, period_s: T) -> Self {
        Self { period_s, ..self }
    }

    /// Forgets the last values (not the stuck timers): called when a cycle had
    /// an instant fault, so the first good reading after it is not compared
    /// with a reading from before the gap.
    pub fn break_rate_history(&mut self) {
        for h in self.history.iter_mut() {
            h.last = None;
        }
    }

    /// Checks one cycle's values `[p1_bar, p2_bar, angle_deg]`, `dt_s` after
    /// the previous cycle. Returns the first fault found in channel order.
    pub fn check(&mut self, values: [T; 3], dt_s: T) -> Result<(), SensorFault> {
        let mut fault = None;
        // Rate check and update of the hold timers.
        for (i, (h, &v)) in self.history.iter_mut().zip(values.iter()).enumerate() {
            let limits = self.config.limits(i);
            if let Some(last) = h.last {
                if dt_s > T::lit(0.0)
                    && limits.exceeds_rate(v - last, dt_s, self.period_s)
                    && fault.is_none()
                {
                    fault = Some((i, FaultKind::RateOfChange));
                }
            }
            h.last = Some(v);
            match h.hold_value {
                Some(held) if (v - held).abs() <= limits.stuck_band => h.hold_s += dt_s,
                _ => {
                    h.hold_value = Some(v);
                    h.hold_s = T::lit(0.0);
                    h.frozen_while_others_live_s = T::lit(0.0);
                }
            }
        }
        // Stuck: frozen for `stuck_time_s` of cycles in which another channel
        // had changed within the last `stuck_time_s`.
        let window = self.config.stuck_time_s;
        let [h1, h2, h3] = &self.history;
        let holds = [h1.hold_s, h2.hold_s, h3.hold_s];
        for (i, h) in self.history.iter_mut().enumerate() {
            let other_live = holds
                .iter()
                .enumerate()
                .any(|(j, &other_hold)| j != i && other_hold < window);
            if h.hold_s > T::lit(0.0) && other_live {
                h.frozen_while_others_live_s += dt_s;
            }
            if h.frozen_while_others_live_s >= window && fault.is_none() {
                fault = Some((i, FaultKind::Stuck));
            }
        }
        match fault {
            None => Ok(()),
            Some((i, kind)) => Err(SensorFault {
                channel: Channel::ALL.get(i).copied().unwrap_or(Channel::BoomAngle),
                kind,
            }),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spike_is_a_rate_fault() {
        let mut m = PlausibilityMonitor::new(PlausibilityConfig::<f64>::standard());
        assert!(m.check([50.0, 5.0, 45.0], 0.01).is_ok());
        assert!(m.check([50.2, 5.1, 45.01], 0.01).is_ok());
        let f = m.check([150.0, 5.0, 45.02], 0.01).unwrap_err();
        assert_eq!(
            f,
            SensorFault {
                channel: Channel::PistonSidePressure,
                kind: FaultKind::RateOfChange
            }
        );
    }

    #[test]
    fn a_reading_early_is_allowed_one_period_of_change_and_no_more() {
        let mut m = PlausibilityMonitor::new(PlausibilityConfig::<f64>::standard()).with_period_s(0.01);
        assert!(m.check([50.0, 5.0, 45.0], 0.01).is_ok());
        // 1.3 ms later, 0.1° and 2 bar of noise: 77 °/s over 1.3 ms, but
        // within one period's 0.6°.
        assert!(m.check([52.0, 5.0, 45.1], 0.0013).is_ok());
        // Without the period, that was a fault.
        let mut bare = PlausibilityMonitor::new(PlausibilityConfig::<f64>::standard());
        assert!(bare.check([50.0, 5.0, 45.0], 0.01).is_ok());
        assert!(bare.check([52.0, 5.0, 45.1], 0.0013).is_err());
        // A jump beyond one period's change is caught however early it comes.
        let f = m.check([52.0, 5.0, 45.8], 0.0013).unwrap_err();
        assert_eq!(f, SensorFault { channel: Channel::BoomAngle, kind: FaultKind::RateOfChange });
        // A late reading is still allowed its interval's change, not more.
        let mut late = PlausibilityMonitor::new(PlausibilityConfig::<f64>::standard()).with_period_s(0.01);
        assert!(late.check([50.0, 5.0, 45.0], 0.01).is_ok());
        assert!(late.check([50.0, 5.0, 46.1], 0.02).is_ok());
        assert!(late.check([50.0, 5.0, 47.5], 0.02).is_err());
    }

    #[test]
    fn frozen_channel_is_stuck_only_while_others_move() {
        let mut m = PlausibilityMonitor::new(PlausibilityConfig::<f64>::standard());
        // Everything frozen for 5 s: a quiet log at rest, no fault.
        for _ in 0..500 {
            assert!(m.check([50.0, 5.0, 45.0], 0.01).is_ok());
        }
        // Now p1 and the angle move, p2 stays frozen: stuck after 2 s of that.
        let mut t_fault = None;
        for k in 0..400 {
            let x = f64::from(k) * 0.01;
            if let Err(f) = m.check([50.0 + x, 5.0, 45.0 + x], 0.01) {
                assert_eq!(
                    f,
                    SensorFault {
                        channel: Channel::RodSidePressure,
                        kind: FaultKind::Stuck
                    }
                );
                t_fault = Some(x);
                break;
            }
        }
        let t = t_fault.expect("stuck p2 not detected");
        assert!(t <= 2.0 + 1e-9, "detected after {t} s");
    }
}
