//! The low-pass filter used on the piston force and on the boom angle.
//!
//! `n` identical first-order stages in series (n = 1…[`MAX_STAGES`]),
//! discretised exactly for the actual time step:
//! `y += (1 − e^(−Δt/τ))·(x − y)` per stage, τ = 1/(2π·f_c). A filter told
//! its nominal period P ([`LowPass::with_period_s`], as the limiter's are)
//! keeps that step at P and, at any other step, the gain Δt/(Λ + Δt) that
//! lags a ramp by the same Λ as at P: uneven steps (a jittering clock, a
//! gap bridged in sub-steps) then do not make the lag, and so the
//! differences of the output, wobble.
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
//! The limiter runs the force and the angle through the same filter, so the
//! two stay aligned in time whatever the cut-off, and takes the angle's rate
//! and acceleration as differences of the filtered angle (see
//! [`crate::cycle::LimiterConfig::standard`] for the chosen 4 stages at
//! 1.2 Hz: delay 0.53 s; gain 0.014 at 3.3 Hz and 0.007 at 4 Hz, where the
//! loaded and the unloaded boom's first bending oscillation are).

use crane_model::Real;

/// e^x for small x ≥ 0 by its cubic Taylor polynomial, 1 + x + x²/2 + x³/6:
/// no libm exp in the cycle for the stages whose time step is not cached
/// (relative error x⁴/24: 2.6e-7 at x = 0.05, i.e. dt = 10 ms, τ = 0.2 s); at
/// least 1 for every x ≥ 0, so e^(−x) ≈ 1/`exp_taylor3(x)` is in (0, 1].
pub fn exp_taylor3<T: Real>(x: T) -> T {
    T::lit(1.0) + x * (T::lit(1.0) + x * (T::lit(0.5) + x / T::lit(6.0)))
}

/// The gain 1 − e^(−x) of a first-order stage for x = dt/τ ≥ 0, with
/// [`exp_taylor3`]: in [0, 1) for every x ≥ 0.
pub fn stage_gain<T: Real>(x: T) -> T {
    T::lit(1.0) - T::lit(1.0) / exp_taylor3(x)
}

/// e^x for x ≥ 0: x halved k times to under 1/16, the Taylor polynomial of
/// degree 5 there (relative error under 1e-10 in f64), and
/// squared back k times (at most 64: beyond x ≈ 89 it is infinite, as the
/// filters' uses of it expect, e.g. a stage's gain 1 − 1/e^x = 1). The
/// controller then needs no libm exp (464 B of its 64 KiB of flash). NaN
/// gives NaN.
#[inline(never)]
pub fn exp_nonnegative<T: Real>(x: T) -> T {
    let mut y = x;
    let mut halvings = 0u32;
    while y > T::lit(0.0625) && halvings < 64 {
        y *= T::lit(0.5);
        halvings += 1;
    }
    let mut e = T::lit(1.0) + y * (T::lit(1.0) + y * (T::lit(0.5) + y * (T::lit(1.0 / 6.0) + y * (T::lit(1.0 / 24.0) + y * T::lit(1.0 / 120.0)))));
    for _ in 0..halvings {
        e = e * e;
    }
    e
}

/// Most stages a [`LowPass`] can have.
pub const MAX_STAGES: usize = 4;

/// A critically damped low-pass of `n` first-order stages.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LowPass<T> {
    tau_s: T,
    stage_count: usize,
    /// `stage_count` as a `T`, converted once (a run-time integer-to-float
    /// conversion through `T::lit` goes through f64: soft float on the M4F).
    stages_t: T,
    /// The exponentials of the last time step: a cycle at the same period
    /// reuses them instead of recomputing e^(−Δt/τ).
    step: Option<Step<T>>,
    /// Outputs of the stages; `None` until the first sample.
    stages: Option<[T; MAX_STAGES]>,
    /// The nominal period P (s) and each stage's lag behind a ramp at it,
    /// Λ = P/(e^(P/τ) − 1), kept at every other step (see [`Self::with_period_s`]).
    nominal: Option<(T, T)>,
    /// Whether the filter starts from the mean of its first samples
    /// ([`Self::starting_from_the_mean`]).
    start_mean: bool,
    /// That start while it still shows in the output.
    start: Option<StartUp<T>>,
}

/// The start of a filter that starts from the mean of its samples so far
/// ([`LowPass::starting_from_the_mean`]).
#[derive(Debug, Clone, Copy, PartialEq)]
struct StartUp<T> {
    /// Samples so far, and their mean.
    samples: T,
    mean: T,
    /// Each stage's response to a start at 1 with no input since.
    response: [T; MAX_STAGES],
}

/// The start's share of the output under which a filter that starts from
/// the mean stops following it: e.g. 2.2 s after the start of 4 stages at
/// 1.2 Hz, 1 s after one of 0.11 s.
pub const START_SHARE_END: f64 = 1e-4;

/// What a time step Δt costs to know: the gain 1 − e^(−Δt/τ) of a stage and
/// the filter's delay for samples Δt apart.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Step<T> {
    dt_s: T,
    gain: T,
    delay_s: T,
}

impl<T: Real> LowPass<T> {
    /// A filter of `stages` stages (clamped to 1…[`MAX_STAGES`]), each with
    /// cut-off `cutoff_hz` (must be > 0).
    pub fn new(cutoff_hz: T, stages: usize) -> Self {
        let stage_count = stages.clamp(1, MAX_STAGES);
        Self {
            tau_s: T::lit(1.0) / (T::two_pi() * cutoff_hz),
            stage_count,
            stages_t: T::lit(stage_count as f64),
            step: None,
            stages: None,
            nominal: None,
            start_mean: false,
            start: None,
        }
    }

    /// The same filter starting, after construction or
    /// [`reset`](Self::reset), from the mean of the samples so far rather
    /// than from the first one alone. Started settled at its first sample,
    /// the filter keeps that sample's noise in its output for as long as
    /// its start shows (0.3 s at 4 stages of 1.2 Hz; see
    /// [`crate::static_load`], "Power-up"). The filter is linear, so its
    /// output is the response to its inputs since the start plus its
    /// stages' response r_n to the start itself (1 at the first sample,
    /// decaying) times the value it started at; each sample, that value
    /// becomes the mean of the samples so far, x̄_n, by adding
    /// r_n·(x̄_n − x̄_(n−1)) to the stages. The output stays a weighted sum of
    /// the inputs with weights ≥ 0 that sum to 1, so it still never
    /// overshoots, is monotone and has unit gain at DC; the first sample's
    /// weight r_n is shared among all samples so far, so a heavier load
    /// taken up after the start is seen no later. Stops once r_n is under
    /// [`START_SHARE_END`]. For a still signal (a boom switched on at rest:
    /// in motion the limiter FAULTs) the mean of the samples is their best
    /// estimate.
    pub fn starting_from_the_mean(self) -> Self {
        Self { start_mean: true, ..self }
    }

    /// The same filter for samples that should come every `period_s` but
    /// may not (a logger's jittering clock, a gap bridged in sub-steps).
    /// At the period each stage is the exact one, y += (1 − e^(−P/τ))·(x − y),
    /// which lags a ramp by Λ = P/(e^(P/τ) − 1) ≈ τ − P/2. At any other
    /// step Δt the exact stage would lag by Δt/(e^(Δt/τ) − 1), so the lag
    /// would wobble with uneven steps, and so would the differences of the
    /// output (a lowering's rate and acceleration, and with them the rated
    /// load's angle: a log stamped ±3 ms off its grid was cut 0.26 s late).
    /// There the stage's gain is Δt/(Λ + Δt) instead (the implicit Euler
    /// step of a stage of time constant Λ): it lags a ramp by exactly Λ for
    /// every Δt, and equals the exact gain at Δt = P. In (0, 1) for every
    /// Δt > 0: stable, no overshoot, monotone.
    pub fn with_period_s(self, period_s: T) -> Self {
        let x = period_s / self.tau_s;
        let nominal = (period_s > T::lit(0.0) && x.is_finite()).then(|| (period_s, period_s / (exp_nonnegative(x) - T::lit(1.0))));
        Self { nominal, ..self }
    }

    /// The step's exponentials, from the cache when Δt is the last one's.
    fn step_for(&self, dt_s: T) -> Step<T> {
        match self.step {
            Some(step) if step.dt_s == dt_s => step,
            _ => {
                let x = dt_s / self.tau_s;
                if let Some((period_s, lag_s)) = self.nominal {
                    // Within a millionth of the period: the period (a
                    // period converted to seconds otherwise than the step;
                    // the limiter's are alike, `ClockConfig::period_s`).
                    if (dt_s - period_s).abs() > period_s * T::lit(1e-6) {
                        let gain = if dt_s > T::lit(0.0) { dt_s / (lag_s + dt_s) } else { T::lit(0.0) };
                        return Step { dt_s, gain, delay_s: self.stages_t * lag_s };
                    }
                }
                let delay_s = if x > T::lit(1e-6) && x.is_finite() {
                    self.stages_t * dt_s / (exp_nonnegative(x) - T::lit(1.0))
                } else {
                    self.stages_t * self.tau_s
                };
                Step { dt_s, gain: T::lit(1.0) - T::lit(1.0) / exp_nonnegative(x), delay_s }
            }
        }
    }

    /// Low-frequency group delay (s) for samples `dt_s` apart: the lag behind
    /// a ramp, n·Δt/(e^(Δt/τ) − 1) for the discretised stages (n·τ − n·Δt/2
    /// to second order; n·τ as Δt → 0); with a nominal period P
    /// ([`Self::with_period_s`]), n·Λ = n·P/(e^(P/τ) − 1) at every step.
    pub fn delay_s(&self, dt_s: T) -> T {
        self.step_for(dt_s).delay_s
    }

    /// Forgets the state: the next sample starts the filter at that value.
    pub fn reset(&mut self) {
        self.stages = None;
        self.start = None;
    }

    /// Feeds `x`, taken `dt_s` after the previous sample; returns the output.
    /// The first sample after construction or [`reset`](Self::reset) is
    /// returned unchanged (the filter starts settled at it).
    pub fn update(&mut self, x: T, dt_s: T) -> T {
        let stages = match self.stages {
            None => {
                self.start = self.start_mean.then_some(StartUp { samples: T::lit(1.0), mean: x, response: [T::lit(1.0); MAX_STAGES] });
                [x; MAX_STAGES]
            }
            Some(mut st) => {
                let dt = if dt_s > T::lit(0.0) {
                    dt_s
                } else {
                    T::lit(0.0)
                };
                let step = self.step_for(dt);
                self.step = Some(step);
                let a = step.gain;
                let mut input = x;
                for s in st.iter_mut().take(self.stage_count) {
                    *s += a * (input - *s);
                    input = *s;
                }
                if let Some(mut start) = self.start {
                    // The start moved to the mean of the samples so far,
                    // through each stage's response to it (see
                    // `starting_from_the_mean`).
                    start.samples += T::lit(1.0);
                    let shift = (x - start.mean) / start.samples;
                    start.mean += shift;
                    let mut input = T::lit(0.0);
                    for (s, r) in st.iter_mut().zip(start.response.iter_mut()).take(self.stage_count) {
                        *r += a * (input - *r);
                        input = *r;
                        *s += *r * shift;
                    }
                    self.start = (input > T::lit(START_SHARE_END)).then_some(start);
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

    /// The first stage's output, if any sample has been fed: the filter
    /// with one stage, which shows a turn of its input soonest.
    pub fn first_stage(&self) -> Option<T> {
        self.stages.and_then(|st| st.first().copied())
    }

    /// How far the output of the stage before the last leads the output:
    /// added to the output, the same filter with one stage fewer, at no cost
    /// (the stages are in series). 0 before the first sample or with a
    /// single stage.
    pub fn last_stage_lead(&self) -> T {
        match (self.stage_count.checked_sub(2), self.stages) {
            (Some(k), Some(st)) => match (st.get(k), st.get(k + 1)) {
                (Some(&before), Some(&last)) => before - last,
                _ => T::lit(0.0),
            },
            _ => T::lit(0.0),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exp_nonnegative_is_the_exponential() {
        let (mut worst, mut worst32) = ([0.0f64; 3], [0.0f64; 3]);
        for k in 0..=4000 {
            let x = f64::from(k) * 0.01;
            let band = if x <= 0.0625 { 0 } else if x <= 1.0 { 1 } else { 2 };
            worst[band] = worst[band].max((exp_nonnegative(x) / x.exp() - 1.0).abs());
            let x32 = x as f32;
            worst32[band] = worst32[band].max((f64::from(exp_nonnegative(x32)) / f64::from(x32).exp() - 1.0).abs());
        }
        println!("relative error up to 1/16, 1, 40: f64 {worst:?}, f32 {worst32:?}");
        // Measured: f64 6e-11, 1.3e-9, 4e-8; f32 5e-8, 1.2e-6, 9.4e-5 (each
        // squaring doubles the error it squares). A stage's gain at 100 Hz
        // and 1.2 Hz is at x = 0.075.
        assert!(worst[0] < 1e-10 && worst[1] < 2e-9 && worst[2] < 1e-7, "{worst:?}");
        assert!(worst32[0] < 1e-7 && worst32[1] < 2e-6 && worst32[2] < 2e-4, "{worst32:?}");
        assert_eq!(exp_nonnegative(0.0_f64), 1.0);
        assert!(exp_nonnegative(1e30_f32).is_infinite() && exp_nonnegative(f32::INFINITY).is_infinite());
        assert!(exp_nonnegative(f64::NAN).is_nan());
    }

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

    /// With a nominal period, a ramp sampled 0.2–19.8 ms apart is followed
    /// with the lag it has at the period, so the output's differences are
    /// the ramp's slope (the exact stage at each step read it 0.949–1.030 of
    /// itself); at the period itself the stage is the exact one, bit for bit.
    #[test]
    fn with_a_period_uneven_steps_keep_the_lag_and_even_ones_are_unchanged() {
        let mut f = LowPass::new(1.2_f64, 4).with_period_s(0.01);
        let (mut t, mut seed, mut prev, mut worst) = (0.0, 12345u32, None::<(f64, f64)>, 0.0f64);
        for k in 0..3000 {
            seed = seed.wrapping_mul(1_103_515_245).wrapping_add(12345);
            let dt = 0.0002 + 0.0196 * f64::from(seed >> 16) / 65_536.0;
            t += dt;
            let y = f.update(2.0 * t, dt);
            if let (Some((t0, y0)), true) = (prev, k > 300) {
                worst = worst.max(((y - y0) / (t - t0) - 2.0).abs());
                assert!((2.0 * t - y - 2.0 * f.delay_s(dt)).abs() < 1e-6, "lag at {t}");
            }
            prev = Some((t, y));
        }
        assert!(worst < 1e-6, "slope off by {worst}");
        let (mut a, mut b) = (LowPass::new(1.2_f64, 4), LowPass::new(1.2_f64, 4).with_period_s(0.01));
        for k in 0..500 {
            let x = (f64::from(k) * 0.37).sin() * 100.0 + f64::from(k);
            assert_eq!(a.update(x, 0.01).to_bits(), b.update(x, 0.01).to_bits(), "sample {k}");
        }
        assert_eq!(a.delay_s(0.01), b.delay_s(0.01));
    }

    /// Started from the mean, the output at every sample is exactly the
    /// plain filter's had it started at the mean of the samples so far (the
    /// filter is linear); a constant signal's noise at the start is that of
    /// the mean, not of the first sample; and the start's share ends.
    #[test]
    fn starting_from_the_mean_is_the_filter_started_at_the_mean_so_far() {
        let (mut seed, mut xs) = (7u32, Vec::new());
        for _ in 0..300 {
            seed = seed.wrapping_mul(1_103_515_245).wrapping_add(12345);
            xs.push(100.0 + f64::from(seed >> 16) / 65_536.0 - 0.5);
        }
        let mut f = LowPass::new(1.2_f64, 4).with_period_s(0.01).starting_from_the_mean();
        let mut mean = 0.0;
        for (n, &x) in xs.iter().enumerate() {
            let following = f.start.is_some() || n == 0;
            let y = f.update(x, 0.01);
            mean += (x - mean) / (n + 1) as f64;
            let mut plain = LowPass::new(1.2_f64, 4).with_period_s(0.01);
            plain.update(mean, 0.01);
            let mut z = mean;
            for &later in xs.iter().take(n + 1).skip(1) {
                z = plain.update(later, 0.01);
            }
            // Once the start's share is under START_SHARE_END, the mean's
            // later moves (under 1 here) are no longer followed.
            let tolerance = if following { 1e-9 } else { START_SHARE_END };
            assert!((y - z).abs() < tolerance, "sample {n}: {y} against {z}");
        }
        // The start's share is gone after 2.2 s at 4 stages of 1.2 Hz.
        assert!(f.start.is_none());
        // The noise: from the 10th sample on (0.1 s), the error against the
        // constant 100 is within 5 % of the mean's of the samples so far
        // (0.097 and 0.096 here) and under half the plain filter's, which
        // stays near the first sample's (0.293 and 0.299).
        let mut a = LowPass::new(1.2_f64, 4).starting_from_the_mean();
        let mut b = LowPass::new(1.2_f64, 4);
        let (mut worst_a, mut worst_b, mut worst_mean, mut mean) = (0.0f64, 0.0f64, 0.0f64, 0.0);
        for (n, &x) in xs.iter().enumerate().take(50) {
            let (ya, yb) = (a.update(x, 0.01), b.update(x, 0.01));
            mean += (x - mean) / (n + 1) as f64;
            if n >= 10 {
                worst_a = worst_a.max((ya - 100.0).abs());
                worst_b = worst_b.max((yb - 100.0).abs());
                worst_mean = worst_mean.max((mean - 100.0).abs());
            }
        }
        println!("worst error from the 10th sample: {worst_a:.4} from the mean, {worst_b:.4} plain, {worst_mean:.4} the mean itself, first sample {:.4}", xs[0] - 100.0);
        assert!(worst_a <= worst_mean * 1.05 && worst_a < 0.5 * worst_b, "{worst_a} {worst_b} {worst_mean}");
    }

    /// Started from the mean, a step up is followed no later than by the
    /// plain filter, never beyond the step (weights ≥ 0 summing to 1).
    #[test]
    fn starting_from_the_mean_delays_no_step_and_never_overshoots() {
        for step_at in [1usize, 5, 30, 80, 150] {
            let mut a = LowPass::new(1.2_f64, 4).with_period_s(0.01).starting_from_the_mean();
            let mut b = LowPass::new(1.2_f64, 4).with_period_s(0.01);
            for k in 0..400 {
                let x = if k >= step_at { 1.0 } else { 0.0 };
                let (ya, yb) = (a.update(x, 0.01), b.update(x, 0.01));
                assert!(ya >= yb - 1e-12 && (-1e-12..=1.0 + 1e-12).contains(&ya), "step at {step_at}, sample {k}: {ya} {yb}");
            }
        }
    }

    /// The output plus the last stage's lead is the filter with one stage
    /// fewer, sample by sample, at uneven steps too (the stages are in
    /// series); started from the mean, up to what the shorter filter stops
    /// following of the start (its last stage's share falls under
    /// [`START_SHARE_END`] sooner). A single stage has no lead.
    #[test]
    fn the_last_stage_lead_gives_the_filter_with_one_stage_fewer() {
        for from_mean in [false, true] {
            let make = |n: usize| {
                let f = LowPass::new(1.2_f64, n).with_period_s(0.01);
                if from_mean {
                    f.starting_from_the_mean()
                } else {
                    f
                }
            };
            let (mut four, mut three) = (make(4), make(3));
            assert_eq!(four.last_stage_lead(), 0.0);
            let mut seed = 11u32;
            let mut worst: f64 = 0.0;
            for k in 0..600 {
                seed = seed.wrapping_mul(1_103_515_245).wrapping_add(12345);
                let x = if k >= 200 { 150.0 } else { 100.0 } + f64::from(seed >> 16) / 65_536.0 - 0.5;
                let dt = if k % 7 == 3 { 0.013 } else { 0.01 };
                let (y4, y3) = (four.update(x, dt), three.update(x, dt));
                worst = worst.max((y4 + four.last_stage_lead() - y3).abs());
            }
            println!("from the mean {from_mean}: largest difference {worst:.2e}");
            let tolerance = if from_mean { START_SHARE_END } else { 1e-9 };
            assert!(worst < tolerance, "{worst}");
        }
        let mut one = LowPass::new(1.2_f64, 1);
        one.update(5.0, 0.01);
        one.update(7.0, 0.01);
        assert_eq!(one.last_stage_lead(), 0.0);
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
