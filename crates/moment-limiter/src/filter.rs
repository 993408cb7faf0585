//! The low-pass filter used on the piston force and on the boom angle.
//!
//! `n` identical first-order stages in series (n = 1…[`MAX_STAGES`]),
//! discretised exactly for the actual time step:
//! `y += (1 − e^(−Δt/τ))·(x − y)` per stage, τ = 1/(2π·f_c).
//!
//! Why this filter and not a sharper one:
//! - its impulse response is never negative, so it **never overshoots** (no
//!   false alarm from a step) and it is **monotone**: a higher input history
//!   never gives a lower output. That is what makes "more load never lowers
//!   the utilization" hold sample by sample;
//! - it has unit gain at DC: a sustained overload is never hidden, only
//!   delayed by the group delay n·τ (a ramp is followed with that constant
//!   lag);
//! - it is stable for any time step, so replayed logs at other rates than
//!   100 Hz are filtered correctly.
//!
//! The step comes from the limiter's integer clock ([`crate::clock`]), so it
//! takes few distinct values (one on the board): the coefficient
//! 1 − e^(−Δt/τ) and the group delay are computed when the step changes and
//! reused, keeping `exp` out of the steady cycle.
//!
//! The limiter runs the force and the angle through the same filter, so the
//! two stay aligned in time whatever the cut-off, and takes the angle's rate
//! and acceleration as differences of the filtered angle (see
//! [`crate::limiter::LimiterConfig::standard`] for the chosen 4 stages at
//! 1.2 Hz: delay 0.53 s; gain 0.014 at 3.3 Hz and 0.007 at 4 Hz, where the
//! loaded and the unloaded boom's first bending oscillation are).

use crane_model::Real;

/// Most stages a [`LowPass`] can have.
pub const MAX_STAGES: usize = 4;

/// A critically damped low-pass of `n` first-order stages.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LowPass<T> {
    tau_s: T,
    stage_count: usize,
    /// Outputs of the stages; `None` until the first sample.
    stages: Option<[T; MAX_STAGES]>,
    /// (Δt, 1 − e^(−Δt/τ), delay) of the last step (see the module doc).
    cached: (T, T, T),
}

impl<T: Real> LowPass<T> {
    /// A filter of `stages` stages (clamped to 1…[`MAX_STAGES`]), each with
    /// cut-off `cutoff_hz` (must be > 0).
    pub fn new(cutoff_hz: T, stages: usize) -> Self {
        let tau_s = T::lit(1.0) / (T::two_pi() * cutoff_hz);
        let stage_count = stages.clamp(1, MAX_STAGES);
        let zero = T::lit(0.0);
        Self {
            tau_s,
            stage_count,
            stages: None,
            cached: (zero, zero, T::lit(stage_count as f64) * tau_s),
        }
    }

    /// Low-frequency group delay (s) for samples `dt_s` apart: the lag behind
    /// a ramp, n·Δt/(e^(Δt/τ) − 1) for the discretised stages (n·τ − n·Δt/2
    /// to second order; n·τ as Δt → 0).
    pub fn delay_s(&self, dt_s: T) -> T {
        if dt_s == self.cached.0 {
            return self.cached.2;
        }
        self.compute_delay_s(dt_s)
    }

    fn compute_delay_s(&self, dt_s: T) -> T {
        let n = T::lit(self.stage_count as f64);
        let x = dt_s / self.tau_s;
        if x > T::lit(1e-6) && x.is_finite() {
            n * dt_s / (x.exp() - T::lit(1.0))
        } else {
            n * self.tau_s
        }
    }

    /// Forgets the state: the next sample starts the filter at that value.
    pub fn reset(&mut self) {
        self.stages = None;
    }

    /// Feeds `x`, taken `dt_s` after the previous sample; returns the output.
    /// The first sample after construction or [`reset`](Self::reset) is
    /// returned unchanged (the filter starts settled at it).
    pub fn update(&mut self, x: T, dt_s: T) -> T {
        let stages = match self.stages {
            None => [x; MAX_STAGES],
            Some(mut st) => {
                let dt = if dt_s > T::lit(0.0) {
                    dt_s
                } else {
                    T::lit(0.0)
                };
                if dt != self.cached.0 {
                    self.cached = (
                        dt,
                        T::lit(1.0) - (-dt / self.tau_s).exp(),
                        self.compute_delay_s(dt),
                    );
                }
                let a = self.cached.1;
                let mut input = x;
                for s in st.iter_mut().take(self.stage_count) {
                    *s += a * (input - *s);
                    input = *s;
                }
                st
            }
        };
        self.stages = Some(stages);
        self.output().unwrap_or(x)
    }

    /// The present output, if any sample has been fed.
    pub fn output(&self) -> Option<T> {
        let last = self.stage_count.checked_sub(1)?;
        self.stages.and_then(|st| st.get(last).copied())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn step_never_overshoots_and_settles() {
        let mut f = LowPass::new(3.0_f64, 2);
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
        let mut f = LowPass::new(3.0_f64, 2);
        let mut y = 0.0;
        for k in 0..1000 {
            y = f.update(f64::from(k) * 0.01, 0.01);
        }
        let lag = 9.99 - y; // input slope is 1 per second
        assert!(
            (lag - f.delay_s(0.01)).abs() < 1e-9,
            "lag {lag} vs {}",
            f.delay_s(0.01)
        );
    }

    #[test]
    fn four_stages_lag_a_ramp_by_four_tau() {
        let mut f = LowPass::new(2.0_f64, 4);
        let mut y = 0.0;
        for k in 0..1000 {
            y = f.update(f64::from(k) * 0.01, 0.01);
        }
        let tau = 1.0 / (2.0 * core::f64::consts::PI * 2.0);
        assert!((f.delay_s(0.0) - 4.0 * tau).abs() < 1e-12);
        assert!(
            (9.99 - y - f.delay_s(0.01)).abs() < 1e-9,
            "lag {}",
            9.99 - y
        );
        assert!((f.delay_s(0.01) - (4.0 * tau - 0.02)).abs() < 1e-3);
    }

    #[test]
    fn oscillation_at_5_hz_is_attenuated() {
        let mut f = LowPass::new(3.0_f64, 2);
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
