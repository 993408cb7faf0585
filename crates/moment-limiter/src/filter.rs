//! The low-pass filter used on the piston force and on the boom angle.
//!
//! Two identical first-order stages in series (a critically damped
//! second-order low-pass), discretised exactly for the actual time step:
//! `y += (1 − e^(−Δt/τ))·(x − y)` per stage, τ = 1/(2π·f_c).
//!
//! Why this filter and not a sharper one:
//! - its impulse response is never negative, so it **never overshoots** (no
//!   false alarm from a step) and it is **monotone**: a higher input history
//!   never gives a lower output. That is what makes "more load never lowers
//!   the utilization" hold sample by sample;
//! - it has unit gain at DC: a sustained overload is never hidden, only
//!   delayed by the group delay 2τ = 1/(π·f_c) (a ramp is followed with that
//!   constant lag; a step reaches 90 % after 3.9τ);
//! - it is stable for any time step, so replayed logs at other rates than
//!   100 Hz are filtered correctly.
//!
//! With the default f_c = 3 Hz per stage: delay 0.106 s; gain 0.26 (−11.6 dB) at
//! 5 Hz and 0.08 (−22 dB) at 10 Hz, where the boom's bending oscillations are.

use crane_model::Real;

/// A critically damped second-order low-pass (two first-order stages).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LowPass<T> {
    tau_s: T,
    /// Outputs of the two stages; `None` until the first sample.
    stages: Option<(T, T)>,
}

impl<T: Real> LowPass<T> {
    /// A filter whose two stages each have cut-off `cutoff_hz` (must be > 0).
    pub fn new(cutoff_hz: T) -> Self {
        Self {
            tau_s: T::lit(1.0) / (T::two_pi() * cutoff_hz),
            stages: None,
        }
    }

    /// Low-frequency group delay 2τ (s): the lag behind a ramp.
    pub fn delay_s(&self) -> T {
        self.tau_s + self.tau_s
    }

    /// Forgets the state: the next sample starts the filter at that value.
    pub fn reset(&mut self) {
        self.stages = None;
    }

    /// Feeds `x`, taken `dt_s` after the previous sample; returns the output.
    /// The first sample after construction or [`reset`](Self::reset) is
    /// returned unchanged (the filter starts settled at it).
    pub fn update(&mut self, x: T, dt_s: T) -> T {
        let (s1, s2) = match self.stages {
            None => (x, x),
            Some((s1, s2)) => {
                let dt = if dt_s > T::lit(0.0) {
                    dt_s
                } else {
                    T::lit(0.0)
                };
                let a = T::lit(1.0) - (-dt / self.tau_s).exp();
                let s1 = s1 + a * (x - s1);
                (s1, s2 + a * (s1 - s2))
            }
        };
        self.stages = Some((s1, s2));
        s2
    }

    /// The present output, if any sample has been fed.
    pub fn output(&self) -> Option<T> {
        self.stages.map(|(_, s2)| s2)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn step_never_overshoots_and_settles() {
        let mut f = LowPass::new(3.0_f64);
        f.update(0.0, 0.01);
        let mut y = 0.0;
        for _ in 0..200 {
            y = f.update(1.0, 0.01);
            assert!(y <= 1.0);
        }
        assert!((y - 1.0).abs() < 1e-6);
    }

    #[test]
    fn ramp_lag_is_the_documented_delay() {
        let mut f = LowPass::new(3.0_f64);
        let mut y = 0.0;
        for k in 0..1000 {
            y = f.update(f64::from(k) * 0.01, 0.01);
        }
        let lag = 9.99 - y; // input slope is 1 per second
        assert!(
            (lag - f.delay_s()).abs() < 0.01,
            "lag {lag} vs {}",
            f.delay_s()
        );
    }

    #[test]
    fn oscillation_at_5_hz_is_attenuated() {
        let mut f = LowPass::new(3.0_f64);
        let mut peak: f64 = 0.0;
        for k in 0..1000 {
            let t = f64::from(k) * 0.01;
            let y = f.update((2.0 * core::f64::consts::PI * 5.0 * t).sin(), 0.01);
            if t > 5.0 {
                peak = peak.max(y.abs());
            }
        }
        assert!(peak < 0.3, "{peak}");
    }
}
