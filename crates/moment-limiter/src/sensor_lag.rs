//! Learning the angle sensor's lag from the calibration runs
//! (`crane-sim calibrate`).
//!
//! The limiter lines force and angle up in time by putting the angle
//! sensor's lag τ on the force too (a first-order lag; see
//! [`crate::cycle::Limiter`] "Time alignment"). With a sensor that lags by
//! τ_s while the limiter assumes τ, the model is evaluated at an angle that
//! is (τ_s − τ)·θ̇ behind the force's, and the residual of a steady sample
//! carries
//!
//! ΔF ≈ ∂F_model/∂θ · θ̇ · (τ_s − τ).
//!
//! Like friction it changes sign with the direction of motion, but it
//! scales with ∂F/∂θ (the boom's weight moment: ∝ sin θ over the lever's
//! change), not with 1 and F as the seal law a + b·|F| does; over a 40°–80°
//! run the two have different shapes (a 1° angle error at 60° is several kN
//! on the empty boom). So the residual left by the best seal-law lines is
//! smallest at τ = τ_s.
//!
//! Over a steady run alone the two are hard to tell apart: on a 10 s
//! 40°–80° run the steady samples span 20°, over which ∂F/∂θ is nearly a
//! straight line in F, and the best lines' rms residual changed by 1 %
//! between lags of 0 and 0.5 s. The **ramps** show it: there the rate
//! changes while the force, and so the friction, hardly does, and the lag
//! error leaves a residual ∝ θ̇ that no friction law takes up (the same
//! runs' rms residual, ramps included, was 470 N at the true 0.3 s lag and
//! 1.2 kN at the default 0.111 s).
//!
//! **The search.** The learner's samples do not depend on τ (rate,
//! acceleration and direction come from the angle alone), only their
//! forces do. [`fit_lag`] runs the calibration runs through the limiter's
//! own signal chain once per candidate lag on a grid of [`LAG_STEP_S`]
//! from 0 to [`MAX_ANGLE_SENSOR_LAG_S`], takes for each the sum of squared
//! residuals S(τ) of the best straight line r = c + β·F per direction over
//! the moving samples of
//! [`crate::calibration::SteadyMotion::lag_search`], ramps included
//! ([`crate::calibration::CalibrationLearner::line_ssr`]: the seal law
//! with the offset free, so the lag has to be told from friction by shape
//! alone), and refines the grid's minimum by the parabola through it and
//! its neighbours: S(τ) ≈ S₀ + k·(τ − τ*)². The lag the limiter takes is
//! the sensor's *first-order equivalent on a steady rate*: τ of a
//! first-order sensor, 2ζ/ω_n of an oil-damped pendulum
//! (x'' = ω_n²(θ − x) − 2ζω_n·x'), since in a steady move the force and
//! the angle are to be read at the same instant.
//!
//! **The sensor's shape.** The ramps, which show the lag, show the
//! sensor's step response too, and a pendulum's is not a first-order
//! lag's. Searched with a first-order lag alone, a pendulum of 1 Hz, ζ 0.5
//! (2ζ/ω_n = 0.159 s), quicker in the ramps, was learned as 0.097 s; the
//! force then stood for an instant 0.06 s later than the angle it was read
//! at, and lowerings past the rated radius were cut at true u 0.901–0.905,
//! before 1/1.1. One of 1 Hz, ζ 0.9 (0.286 s), slower, was learned as
//! 0.31–0.33 s: a lag learned too long reads a lowering low. So the search
//! is run once per shape of [`SENSOR_SHAPES`]: the first-order lag, and
//! pendulums of each of [`PENDULUM_DAMPINGS`] whose steady lag is the
//! candidate τ ([`SensorCandidate`]). For a pendulum candidate the limiter's
//! own alignment is off and the pendulum's response is put on both
//! pressures instead ([`PressureLag`]), so that force and angle go through
//! the same sensor; the learner's samples are the same for every candidate
//! (they depend on the angle alone), so the residuals compare.
//! [`choose_sensor`] keeps the first-order lag unless a pendulum leaves
//! [`SHAPE_MARGIN`] less rms residual: the 1 Hz, ζ 0.5 pendulum fits its
//! own shape 15–19 % better and is learned as 0.150–0.163 s, the ζ 0.9 one
//! 0.259–0.291 s; first-order sensors keep a first-order lag. Quicker
//! pendulums differ little from a first-order lag in the ramps, and the
//! shape that fits best then follows the noise: 1.25 Hz, ζ 0.5 (0.127 s)
//! is learned as 0.125 s with one noise draw and 0.077–0.093 s with
//! others, as before; 1.5 Hz, ζ 0.5 (0.106 s) as 0.07–0.09 s. A lag
//! learned short reads lowerings high (toward cutting); the bounds hold
//! there (`host-sim` test `slow_or_underdamped_pendulums_*`).
//!
//! `crane-sim calibrate` searches over the unloaded runs only: in a
//! known-load run's ramps the load's swing and bounce, which the model does
//! not know, dominate the residual (a 3 t test weight luffed in 30 s moved
//! the minimum to the 0.5 s bound).
//!
//! Measured on synthesized unloaded 10 s cycloidal runs 40°↔80° (100 Hz,
//! both friction laws; `host-sim/tests/calibration_cli.rs`): first-order
//! lags 0.05 / 0.1 / 0.2 / 0.3 s learned as 0.04 / 0.09 / 0.20 / 0.30 s,
//! the 2 Hz, ζ 0.7 pendulum (0.111 s) as 0.095–0.096 s, 1 Hz at ζ 0.5
//! (0.159 s) as 0.163 s and at ζ 0.9 (0.286 s) as 0.259 s. 30 s runs
//! (1.3 °/s) show too little: the lag is reported not observable and the
//! default kept.
//!
//! **When it is not observable.** With little motion, a short angle span,
//! or a fit that other effects dominate, S(τ) is flat: a lag error leaves a
//! residual below the noise. The lag is taken only if moving [`LAG_PROBE_S`]
//! away from τ* raises the fit's rms residual by at least
//! [`MIN_RMS_RISE`], and τ* is not at the grid's upper end (a lag beyond the
//! schema's bound is a broken sensor, not a calibration); otherwise
//! [`LagFit::lag_s`] is the configured default and [`LagFit::observable`]
//! is `false`, which `crane-sim calibrate` prints.

use crane_model::Real;

use crate::io::Frame;

pub use crate::load_estimate::MAX_ANGLE_SENSOR_LAG_S;

/// Spacing of the candidate lags (s).
pub const LAG_STEP_S: f64 = 0.025;

/// Number of candidate lags: 0, [`LAG_STEP_S`], … [`MAX_ANGLE_SENSOR_LAG_S`].
pub const LAG_CANDIDATES: usize = 21;

/// How far from the best lag the observability test probes (s).
pub const LAG_PROBE_S: f64 = 0.05;

/// Least relative rise of the rms residual [`LAG_PROBE_S`] away from the
/// best lag for the lag to be observable (–).
pub const MIN_RMS_RISE: f64 = 0.05;

/// The lag learned and how well the runs show it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LagFit<T> {
    /// The lag the calibration takes (s): `best_s` if observable, else the
    /// default given to [`fit_lag`].
    pub lag_s: T,
    /// The minimum of the residual curve (s).
    pub best_s: T,
    /// `true`: the residual curve is steep enough around `best_s`.
    pub observable: bool,
    /// Relative rise of the rms residual [`LAG_PROBE_S`] away from
    /// `best_s` (–; 0.1 = 10 %).
    pub rms_rise: T,
    /// Rms residual of the seal-law lines at `best_s` (N).
    pub rms_n: T,
    /// Rms residual at the default lag (N).
    pub rms_at_default_n: T,
}

/// The lag of the calibration runs (see the module doc): `ssr_at(τ)` runs
/// them through the signal chain with lag τ and returns the sum of squared
/// residuals of the seal-law lines and the number of samples
/// ([`crate::calibration::CalibrationLearner::line_ssr`]). Calls `ssr_at`
/// at most [`LAG_CANDIDATES`] + 2 times.
pub fn fit_lag<T: Real, E>(
    default_s: T,
    mut ssr_at: impl FnMut(T) -> Result<(T, u32), E>,
) -> Result<LagFit<T>, E> {
    let zero = T::lit(0.0);
    let h = T::lit(LAG_STEP_S);
    let mut s = [zero; LAG_CANDIDATES];
    let mut n = 1u32;
    for (i, slot) in s.iter_mut().enumerate() {
        let (ssr, count) = ssr_at(h * T::lit(i as f64))?;
        *slot = ssr;
        n = count.max(1);
    }
    let nn = T::lit(f64::from(n));
    let rms = |ssr: T| (ssr.max(zero) / nn).sqrt();
    let (mut i, mut s_min) = (0usize, T::lit(f64::INFINITY));
    for (k, v) in s.iter().enumerate() {
        if *v < s_min {
            (i, s_min) = (k, *v);
        }
    }
    let last = LAG_CANDIDATES - 1;
    // The parabola through the minimum and its neighbours (at an end, the
    // three nearest points).
    let c = i.clamp(1, last - 1);
    let (sl, sc, sr) = (
        s.get(c - 1).copied().unwrap_or(zero),
        s.get(c).copied().unwrap_or(zero),
        s.get(c + 1).copied().unwrap_or(zero),
    );
    let curv = sl - T::lit(2.0) * sc + sr;
    let tau_c = h * T::lit(c as f64);
    let mut best = if curv > zero {
        tau_c - h * (sr - sl) / (T::lit(2.0) * curv)
    } else {
        h * T::lit(i as f64)
    };
    best = best.max(zero).min(h * T::lit(last as f64));
    let (s_best, _) = ssr_at(best)?;
    if s_best > s_min || !s_best.is_finite() {
        best = h * T::lit(i as f64);
    }
    let s0 = s_best.min(s_min);
    // The curve LAG_PROBE_S either side, from the parabola: its second
    // difference over the grid is 2·k·h².
    let probe = T::lit(LAG_PROBE_S);
    let k = if curv > zero { curv / (T::lit(2.0) * h * h) } else { zero };
    let rise_ssr = |d: T| s0 + k * d * d;
    let rms0 = rms(s0);
    let rms_rise = if rms0 > zero {
        rms(rise_ssr(probe)) / rms0 - T::lit(1.0)
    } else {
        zero
    };
    let (s_default, _) = ssr_at(default_s)?;
    let observable = i < last && rms_rise >= T::lit(MIN_RMS_RISE) && best.is_finite();
    Ok(LagFit {
        lag_s: if observable { best } else { default_s },
        best_s: best,
        observable,
        rms_rise,
        rms_n: rms0,
        rms_at_default_n: rms(s_default),
    })
}

/// Dampings of the second-order sensors the search tries besides the
/// first-order lag (see "The sensor's shape" in the module doc): the
/// oil-damped pendulums of luffing cranes lie between about 0.5 and 0.9.
pub const PENDULUM_DAMPINGS: [f64; 3] = [0.5, 0.7, 0.9];

/// The shapes [`fit_sensor`] tries: a first-order lag, then a pendulum of
/// each of [`PENDULUM_DAMPINGS`].
pub const SENSOR_SHAPES: [SensorShape; 1 + PENDULUM_DAMPINGS.len()] = [
    SensorShape::FirstOrder,
    SensorShape::Pendulum { damping: PENDULUM_DAMPINGS[0] },
    SensorShape::Pendulum { damping: PENDULUM_DAMPINGS[1] },
    SensorShape::Pendulum { damping: PENDULUM_DAMPINGS[2] },
];

/// The step response the angle sensor is taken to have while a lag is tried.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SensorShape {
    /// A first-order lag τ: what the limiter's time alignment applies.
    FirstOrder,
    /// An oil-damped pendulum, x'' = ω_n²·(θ − x) − 2ζ·ω_n·x', of damping
    /// ζ; its lag on a steady rate is 2ζ/ω_n.
    Pendulum {
        /// The damping ratio ζ (–).
        damping: f64,
    },
}

/// One candidate of the search: a sensor shape and its lag on a steady
/// rate (s), the first-order equivalent the limiter aligns with.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SensorCandidate<T> {
    /// The sensor's shape.
    pub shape: SensorShape,
    /// Its lag on a steady rate (s): τ, or 2ζ/ω_n.
    pub lag_s: T,
}

impl<T: Real> SensorCandidate<T> {
    /// A first-order lag of `lag_s` (s): what the limiter itself aligns with.
    pub fn first_order(lag_s: T) -> Self {
        Self { shape: SensorShape::FirstOrder, lag_s }
    }

    /// The lag the limiter's own time alignment takes while this candidate
    /// is tried (s): the candidate's for a first-order lag; none for a
    /// pendulum, whose response [`Self::pressure_lag`] puts on the
    /// pressures instead.
    pub fn alignment_lag_s(&self) -> T {
        match self.shape {
            SensorShape::FirstOrder => self.lag_s,
            SensorShape::Pendulum { .. } => T::lit(0.0),
        }
    }

    /// What the candidate puts on the runs' pressures: the pendulum's
    /// response, or nothing (a first-order candidate, or no lag at all).
    pub fn pressure_lag(&self) -> PressureLag<T> {
        match self.shape {
            SensorShape::Pendulum { damping } if self.lag_s > T::lit(0.0) => PressureLag::pendulum(self.lag_s, T::lit(damping)),
            _ => PressureLag::none(),
        }
    }
}

/// A pendulum's response put on both pressures of a calibration run, so
/// that force and angle go through the same sensor while a pendulum
/// candidate is tried (the limiter's own alignment is first-order), or
/// nothing. Trapezoidal rule on (x, x'), unconditionally stable at any
/// step and exact in the steady-rate lag; it starts settled on the first
/// frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PressureLag<T> {
    /// ω_n and ζ; `None`: the pressures pass unchanged.
    pendulum: Option<(T, T)>,
    /// The last frame's time and each pressure's state; `None` before the
    /// first frame.
    state: Option<(crate::clock::Ticks, [PendulumState<T>; 2])>,
}

/// One pressure through the pendulum: its output, the output's rate and
/// the last input.
type PendulumState<T> = (T, T, T);

impl<T: Real> PressureLag<T> {
    /// A pendulum of damping `damping` whose lag on a steady rate is
    /// `lag_s` (> 0): ω_n = 2ζ/lag.
    pub fn pendulum(lag_s: T, damping: T) -> Self {
        Self {
            pendulum: Some((T::lit(2.0) * damping / lag_s, damping)),
            state: None,
        }
    }

    /// No response: every frame passes unchanged.
    pub fn none() -> Self {
        Self { pendulum: None, state: None }
    }

    /// The frame with its pressures through the pendulum's response.
    pub fn apply(&mut self, frame: Frame<T>) -> Frame<T> {
        let Some((w, z)) = self.pendulum else {
            return frame;
        };
        let (dt, mut state) = match self.state {
            Some((prev, state)) => (T::from_count(frame.t.since(prev)) * T::lit(1e-6), state),
            None => (T::lit(0.0), [(frame.p1_bar, T::lit(0.0), frame.p1_bar), (frame.p2_bar, T::lit(0.0), frame.p2_bar)]),
        };
        let half = dt * T::lit(0.5);
        let det = T::lit(1.0) + dt * z * w + half * half * w * w;
        for ((x, v, u0), u1) in state.iter_mut().zip([frame.p1_bar, frame.p2_bar]) {
            // (I − h·A/2)·s₁ = (I + h·A/2)·s₀ + h/2·B·(u₀ + u₁).
            let r0 = *x + half * *v;
            let r1 = *v + half * (w * w * (*u0 + u1 - *x) - T::lit(2.0) * z * w * *v);
            let v1 = (r1 - half * w * w * r0) / det;
            *x = r0 + half * v1;
            *v = v1;
            *u0 = u1;
        }
        self.state = Some((frame.t, state));
        let [(p1, ..), (p2, ..)] = state;
        Frame { p1_bar: p1, p2_bar: p2, ..frame }
    }
}

/// The sensor learned: the lag of the shape that fits the runs best.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SensorFit<T> {
    /// The lag and how well the runs show it, for `shape`.
    pub lag: LagFit<T>,
    /// The shape whose best lag leaves the least residual among those
    /// whose lag is observable (first-order when none is).
    pub shape: SensorShape,
}

/// Least relative drop of the rms residual, against the first-order lag's,
/// for a pendulum shape to be taken instead (–). The shapes differ only in
/// the ramps' first instants, and where they fit alike the choice followed
/// the noise: a first-order 0.3 s sensor fitted a pendulum of ζ 0.9 as well
/// (410.3 N against 410.5 N) at 0.256 s. Where the pendulum's shape shows,
/// it fits clearly better: 15–19 % at 1 Hz, ζ 0.5.
pub const SHAPE_MARGIN: f64 = 0.03;

/// Chooses among the searches of each of [`SENSOR_SHAPES`], the
/// first-order one first (see the module doc): the first-order lag, unless
/// an observable pendulum leaves at least [`SHAPE_MARGIN`] less rms
/// residual (then the one that leaves least). When the first-order lag is
/// not observable, none is: the runs do not show the lag, whatever its
/// shape, and the default stays. `None` when `fits` is empty.
pub fn choose_sensor<T: Real>(fits: &[(SensorShape, LagFit<T>)]) -> Option<SensorFit<T>> {
    let (first, others) = fits.split_first()?;
    let bar = first.1.rms_n * T::lit(1.0 - SHAPE_MARGIN);
    let best = others
        .iter()
        .filter(|(_, f)| first.1.observable && f.observable && f.rms_n < bar)
        .fold(first, |best, c| if c.1.rms_n < best.1.rms_n { c } else { best });
    Some(SensorFit { lag: best.1, shape: best.0 })
}

/// [`fit_lag`] for each of [`SENSOR_SHAPES`] in turn, and
/// [`choose_sensor`]: `ssr_at(candidate)` runs the calibration runs
/// through the signal chain with the candidate's alignment lag and its
/// pressure lag. (`crane-sim calibrate` runs the shapes in parallel and
/// chooses the same way.)
pub fn fit_sensor<T: Real, E>(
    default_s: T,
    mut ssr_at: impl FnMut(SensorCandidate<T>) -> Result<(T, u32), E>,
) -> Result<SensorFit<T>, E> {
    let mut fits = [(SensorShape::FirstOrder, LagFit::unfitted(default_s)); SENSOR_SHAPES.len()];
    for (slot, shape) in fits.iter_mut().zip(SENSOR_SHAPES) {
        *slot = (shape, fit_lag(default_s, |lag_s| ssr_at(SensorCandidate { shape, lag_s }))?);
    }
    Ok(choose_sensor(&fits).unwrap_or(SensorFit { lag: LagFit::unfitted(default_s), shape: SensorShape::FirstOrder }))
}

impl<T: Real> LagFit<T> {
    /// A fit that found nothing: the default kept, not observable.
    pub fn unfitted(default_s: T) -> Self {
        Self {
            lag_s: default_s,
            best_s: default_s,
            observable: false,
            rms_rise: T::lit(0.0),
            rms_n: T::lit(f64::INFINITY),
            rms_at_default_n: T::lit(f64::INFINITY),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_parabola_is_found_between_the_grid_points_and_a_flat_curve_keeps_the_default() {
        // S(τ) = 1e6·(1 + 400·(τ − 0.137)²) over 100 samples.
        let curve = |t: f64| Ok::<_, ()>((1e6 * (1.0 + 400.0 * (t - 0.137) * (t - 0.137)), 100));
        let f = fit_lag(0.111, curve).unwrap();
        assert!((f.best_s - 0.137).abs() < 1e-9 && f.observable, "{f:?}");
        assert_eq!(f.lag_s, f.best_s);
        // rms rises by sqrt(1 + 400·0.05²) − 1 = 41 %.
        assert!((f.rms_rise - (2.0f64.sqrt() - 1.0)).abs() < 1e-9, "{f:?}");
        // Flat within 1 %: not observable, the default kept.
        let flat = |t: f64| Ok::<_, ()>((1e6 * (1.0 + 1.0 * (t - 0.3) * (t - 0.3)), 100));
        let f = fit_lag(0.111, flat).unwrap();
        assert!(!f.observable && f.lag_s == 0.111, "{f:?}");
        // The minimum at the upper end: a broken sensor, not a calibration.
        let edge = |t: f64| Ok::<_, ()>((1e6 * (1.0 + 400.0 * (t - 0.7) * (t - 0.7)), 100));
        let f = fit_lag(0.111, edge).unwrap();
        assert!(!f.observable && f.lag_s == 0.111, "{f:?}");
        // Zero lag is a lag like any other (a potentiometer without damping).
        let none = |t: f64| Ok::<_, ()>((1e6 * (1.0 + 400.0 * t * t), 100));
        let f = fit_lag(0.111, none).unwrap();
        assert!(f.observable && f.lag_s.abs() < 1e-9, "{f:?}");
        // In f32 too.
        let c32 = |t: f32| Ok::<_, ()>((1e6 * (1.0 + 400.0 * (t - 0.2) * (t - 0.2)), 100));
        let f = fit_lag(0.111f32, c32).unwrap();
        assert!((f.lag_s - 0.2).abs() < 1e-3, "{f:?}");
    }

    fn frame(t_us: u32, p: f64) -> Frame<f64> {
        Frame { t: crate::clock::Ticks::from_micros(t_us), p1_bar: p, p2_bar: -p, boom_angle_deg: 0.0 }
    }

    #[test]
    fn the_pressure_lag_lags_a_ramp_by_its_lag_and_rings_as_a_pendulum() {
        // A ramp of 10 bar/s at 100 Hz: once settled the output is the input
        // 2ζ/ω_n earlier, to the trapezoidal rule's exactness.
        for (lag, zeta) in [(0.159f64, 0.5f64), (0.111, 0.7), (0.3, 0.9)] {
            let mut pl = PressureLag::pendulum(lag, zeta);
            let mut last = frame(0, 0.0);
            for k in 0..1000u32 {
                let t = f64::from(k) * 0.01;
                last = pl.apply(frame(k * 10_000, 10.0 * t));
                assert!((last.p1_bar + last.p2_bar).abs() < 1e-9, "both pressures alike");
            }
            let lag_seen = 9.99 - last.p1_bar / 10.0;
            assert!((lag_seen - lag).abs() < 1e-6, "{lag} {zeta}: {lag_seen}");
        }
        // A step: the overshoot of a pendulum of ζ = 0.5 is
        // exp(−π·ζ/√(1 − ζ²)) = 16.3 %, at t = π/(ω_n·√(1 − ζ²)).
        let (lag, zeta) = (0.159f64, 0.5f64);
        let wn = 2.0 * zeta / lag;
        let mut pl = PressureLag::pendulum(lag, zeta);
        pl.apply(frame(0, 0.0));
        let peak = (1..2000u32).map(|k| pl.apply(frame(k * 1000, 1.0)).p1_bar).fold(f64::MIN, f64::max);
        let expected = 1.0 + (-core::f64::consts::PI * zeta / (1.0 - zeta * zeta).sqrt()).exp();
        assert!((peak - expected).abs() < 2e-4, "{peak} {expected} (ω_n {wn})");
    }

    #[test]
    fn the_shape_chosen_is_the_observable_one_with_the_least_residual() {
        let fit = |lag_s: f64, observable: bool, rms_n: f64| LagFit { lag_s, best_s: lag_s, observable, rms_rise: 0.1, rms_n, rms_at_default_n: 500.0 };
        let p = |damping| SensorShape::Pendulum { damping };
        let fits = [(SensorShape::FirstOrder, fit(0.097, true, 451.0)), (p(0.5), fit(0.152, true, 380.0)), (p(0.7), fit(0.11, true, 420.0))];
        let chosen = choose_sensor(&fits).unwrap();
        assert_eq!((chosen.shape, chosen.lag.lag_s), (p(0.5), 0.152));
        // A lower residual whose lag is not observable does not count.
        let fits = [(SensorShape::FirstOrder, fit(0.2, true, 400.0)), (p(0.5), fit(0.111, false, 300.0))];
        assert_eq!(choose_sensor(&fits).unwrap().shape, SensorShape::FirstOrder);
        // Nor one less than SHAPE_MARGIN lower.
        let fits = [(SensorShape::FirstOrder, fit(0.3, true, 410.5)), (p(0.9), fit(0.256, true, 410.3)), (p(0.7), fit(0.2, true, 399.0))];
        assert_eq!(choose_sensor(&fits).unwrap().lag.lag_s, 0.3);
        let fits = [(SensorShape::FirstOrder, fit(0.3, true, 410.5)), (p(0.9), fit(0.256, true, 397.0))];
        assert_eq!(choose_sensor(&fits).unwrap().lag.lag_s, 0.256);
        // The first-order lag not observable: no shape is, the default stays.
        let fits = [(SensorShape::FirstOrder, fit(0.111, false, 400.0)), (p(0.5), fit(0.15, true, 300.0))];
        let chosen = choose_sensor(&fits).unwrap();
        assert!(chosen.shape == SensorShape::FirstOrder && !chosen.lag.observable && chosen.lag.lag_s == 0.111);
        assert!(choose_sensor::<f64>(&[]).is_none());
        // A candidate runs the chain without alignment when it lags the
        // pressures, and leaves them unchanged when it does not.
        let (f0, f1) = (frame(0, 0.0), frame(10_000, 1.0));
        let c = SensorCandidate { shape: p(0.7), lag_s: 0.1 };
        let mut pl = c.pressure_lag();
        assert!(c.alignment_lag_s() == 0.0 && pl.apply(f0) == f0 && pl.apply(f1).p1_bar < 0.5);
        let c = SensorCandidate::first_order(0.1);
        let mut pl = c.pressure_lag();
        assert!(c.alignment_lag_s() == 0.1 && pl.apply(f0) == f0 && pl.apply(f1) == f1);
        let mut pl = SensorCandidate { shape: p(0.7), lag_s: 0.0 }.pressure_lag();
        assert!(pl.apply(f0) == f0 && pl.apply(f1) == f1);
    }

}
