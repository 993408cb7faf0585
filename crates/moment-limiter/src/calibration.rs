//! Learning the friction correction from unloaded runs (`crane-sim calibrate`).
//!
//! With no hook load the model gives the piston force F_model(0) at every
//! boom state, so each sample of an unloaded log in **steady motion** gives a
//! residual r = F_meas − F_model(0) = force_offset + friction(direction). The
//! learner averages r over the steady samples moving up (r_up) and down
//! (r_down), using the very same signal chain as the limiter (feed it the
//! [`Measurement`]s of a [`crate::cycle::Limiter`] run with
//! [`Calibration::none`]).
//!
//! Only steady motion ([`SteadyMotion`]): the residual removes the boom's
//! inertia with the limiter's own acceleration estimate, but in the ramps
//! that estimate lags the force by the pendulum's 0.11 s, and near standstill
//! the friction is not yet (or no longer) fully developed. (Counting every
//! "moving" sample made the learned residuals +9.2 kN / −6.1 kN where the logs
//! carried +12 / −8 kN.) A sample is steady when the boom has moved in one
//! direction for at least `min_moving_s` (the filters and the boom's
//! oscillation after the ramp have settled), at least `min_rate_deg_s`, with
//! |acceleration| at most `max_accel_deg_s2`, **and stays so for
//! `lookahead_s` after it**: the acceleration comes from the filtered
//! pendulum angle, so a deceleration shows in it ≈ 0.11 s after it shows in
//! the force, and the learner holds the last `lookahead_s` of residuals back
//! and drops them when the motion turns out not to have been steady. (The
//! learner runs on recorded logs, after the fact, so it can afford to look
//! ahead; the limiter cannot and does not need to.)
//!
//! **The seal law per direction.** Seal friction grows with the pressure
//! behind the seal, friction = a + b·|F| with F the piston force
//! ([`crate::load_estimate`]). On a run with a known hook load W (0 for the
//! unloaded run, a test weight for `--known-load-kg`, as SAE J376
//! calibrates with test weights) the model gives F = F_model(W) + J·θ̈ at
//! every steady sample, and the residual is
//!
//! r = F_meas − J·θ̈ − F_model(W) = offset + s·(a + b·F), s = ±1 up/down,
//!
//! a straight line in F per direction. The learner keeps, per direction,
//! the running means and co-moments of (F, r) (Welford's update, stable in
//! f32 where the plain sums of F² ≈ 10¹³ N² would cancel) and fits the line
//! by least squares: b = s·cov(F, r)/var(F), a = s·(mean r − offset) −
//! b·mean F. The slope is observable only where F varies: an unloaded run
//! from 40° to 80° spans the empty boom's force over a wide range; a run
//! that spans less than [`MIN_FORCE_SPREAD`] (standard deviation of F over
//! its mean) or whose slope's standard error exceeds [`MAX_SLOPE_SE`] keeps
//! b = 0 and says so ([`DirectionFit::slope_observable`]). A fitted b < 0 (a
//! friction that falls with pressure, noise on a constant law) is clamped to
//! 0 with a refit of a; a < 0 to 0.
//!
//! **Offset and friction apart.** At rest the seals release (the simulator's
//! standstill release, and what a settled cylinder does), so the residual
//! of a still boom is the force offset alone: the learner averages it over
//! the samples before the first motion of each log, r_rest. Where these
//! are fewer than the steady minimum, also over those long after a stop
//! (the limiter's [`Measurement::static_friction_share`] below 1 %, 2.3 s
//! after it sees the stop): taken with them, the offset of the campaign's
//! cranes (runs resting 5 s after their stops, seed 1) moved by up to
//! 0.27 kN, and stuck seals' by 0.9 kN (the field tests' runs). With at
//! least as many rest samples as the steady minimum, the offset is r_rest
//! and each direction's law is fitted against it. Without
//! them, up and down cannot be told from the offset, and the learner
//! reports the symmetric split of the lines' intercepts c_up, c_down:
//! offset = (c_up + c_down)/2, a_up = a_down = max(0, (c_up − c_down)/2),
//! which is exact while moving. Transducer zero offsets (bar) and the
//! pendulum offset are not observable from the force alone (a pressure
//! offset on both transducers is a force offset; an angle offset is a
//! model error the offset and the slope absorb in part) and are not learned
//! (0); a technician may set them in the calibration file.
//!
//! **The seals' release after a raise** is read from the rest after the
//! up runs' stops, once the law and the offset are known
//! ([`crate::seal_release`]).
//!
//! **The angle sensor's lag** is learned before the friction, by
//! [`crate::sensor_lag`]: the runs go through the signal chain once per
//! candidate lag and the lag whose residual, over the moving samples of
//! [`SteadyMotion::lag_search`] (ramps included), the seal-law lines leave
//! smallest is taken ([`CalibrationLearner::line_ssr`]); the friction is
//! then fitted over the steady samples of the runs aligned with that lag.
//! (A lag error Δτ leaves ∂F/∂θ·θ̇·Δτ in the residual: with the default
//! 0.111 s on a 0.3 s sensor, 2 kN that the friction fit took as friction.)
//!
//! **The part that grows with the rate.** A friction that grows with the
//! piston's speed (a viscous seal) adds c·|ω| per direction, ω the boom's
//! rate (the piston's speed over the cylinder's lever da/dθ, 2.0–2.5 m/rad
//! over 20°–85°). The moments carry |ω| beside F, and where the runs show
//! the rate apart from the force (its spread over the steady samples at
//! least [`MIN_RATE_SPREAD`] of its mean: runs at two speeds), the plane
//! z = a + b·F + c·|ω| is fitted by least squares and c kept when positive
//! with a standard error under [`MAX_RATE_SE_N_S`]. At one speed the rate
//! hardly varies over the steady samples (1 % in a 10 s run): c = 0 and a
//! holds the friction at that speed, what the calibration learned before c
//! (`fit_with_rate`; `DirectionFit::rate_observable`). `crane-sim
//! calibrate` fits c only in the directions whose unloaded runs show it
//! ([`CalibrationLearner::fit_with_rates`]): test weights are luffed slowly,
//! and their runs' speed would stand for their load.
//!
//! Several runs combine by merging their moments ([`CalibrationLearner::merge`],
//! Chan's formula): `crane-sim calibrate` learns each log on its own learner,
//! checks each known-load run against the unloaded runs' law, then fits the
//! merged moments.

use crane_model::loads::load_model::HookLoadModel;
use crane_model::{ModelError, Real};

use crate::io::Measurement;
use crate::load_estimate::{model_force_terms, Calibration, Direction, Friction, MAX_PER_FORCE, MAX_PER_RATE_N_S};
use crate::seal_release::{fit_release, ReleaseFit, ReleaseSums, RELEASE_WINDOW_S};

/// Least spread of the piston force over a direction's steady samples
/// (standard deviation over mean) for the slope b to be observable.
pub const MIN_FORCE_SPREAD: f64 = 0.05;

/// Largest standard error of the fitted slope b for it to be taken (–): at
/// 0.003 the slope's error is ±0.3 % of the force, ±1.5 kN on a 500 kN lift.
pub const MAX_SLOPE_SE: f64 = 0.003;

/// Least spread of the boom rate over a direction's steady samples
/// (standard deviation over mean) for the friction per unit rate c to be
/// observable: runs at two speeds (a 10 s and a 30 s luff spread it by
/// about 0.6); one 10 s run's steady samples by about 0.01.
pub const MIN_RATE_SPREAD: f64 = 0.15;

/// Largest standard error of the fitted c for it to be taken (N·s/rad):
/// ±350 N of friction at 0.07 rad/s (a 10 s luff over 40°).
pub const MAX_RATE_SE_N_S: f64 = 5_000.0;

/// Why no calibration could be learned.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CalibrationError {
    /// Too few samples moving up (`true`) or down (`false`).
    TooFewSamples {
        /// Which direction lacks samples: `true` up, `false` down.
        up: bool,
        /// How many there were.
        found: u32,
    },
    /// A sum became NaN or infinite.
    NotFinite,
}

impl core::fmt::Display for CalibrationError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            CalibrationError::TooFewSamples { up, found } => write!(
                f,
                "too few samples moving {} ({found}): give an unloaded boom-{} log",
                if *up { "up" } else { "down" },
                if *up { "up" } else { "down" }
            ),
            CalibrationError::NotFinite => f.write_str("non-finite residual"),
        }
    }
}

/// Which samples count as steady motion (see the module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteadyMotion<T> {
    /// Least time moving in one direction (s).
    pub min_moving_s: T,
    /// Least |rate| (°/s).
    pub min_rate_deg_s: T,
    /// Largest |acceleration| (°/s²).
    pub max_accel_deg_s2: T,
    /// Time the motion must stay steady after a sample for it to count (s).
    pub lookahead_s: T,
}

impl<T: Real> SteadyMotion<T> {
    /// Defaults: moving for 3 s (the thesis's longest ramp, the filter's
    /// delay, and the boom's oscillation after the start: with 1.5 s, the
    /// first seconds of a run, all at one end of the angle range, read up to
    /// 60 kg off on an empty hook and tilted the seal law's slope by ±0.01;
    /// on the campaign's 16 cranes 3 s halved the learned friction's error
    /// at 300 kN against 1.5 s, 2.5 s and 4 s), |rate| ≥ 0.5 °/s (the slowest thesis maneuver runs at
    /// 1.4 °/s), |acceleration| ≤ 2 °/s² (the filtered ramps reach 2 °/s²
    /// (30 s) and 7 °/s² (10 s); steady motion reads ±0.5 °/s² of noise), and
    /// 1.0 s of look-ahead.
    pub fn standard() -> Self {
        Self {
            min_moving_s: T::lit(3.0),
            min_rate_deg_s: T::lit(0.5),
            max_accel_deg_s2: T::lit(2.0),
            lookahead_s: T::lit(1.0),
        }
    }

    /// The samples the angle sensor's lag is learned from
    /// ([`crate::sensor_lag`]): moving for 1 s in one direction at ≥ 0.5 °/s,
    /// **ramps included** (any acceleration), 1.0 s of look-ahead. In the
    /// ramps the rate changes while the force and so the friction hardly
    /// do, and a lag error leaves a residual ∝ θ̇ that no friction law can
    /// take up; the steady samples alone show it too faintly (a 10 s run's
    /// ∂F/∂θ over its steady 20° is nearly a straight line in F, and its
    /// rms residual changed by 1 % between lags 0 and 0.5 s). The first
    /// second is left out because the friction develops there (the rate
    /// still below its smoothing) and the filters start: with 0.5 s the
    /// learned lag of a 0.3 s sensor read 0.27 s, with 1 s 0.30 s.
    pub fn lag_search() -> Self {
        Self {
            min_moving_s: T::lit(1.0),
            min_rate_deg_s: T::lit(0.5),
            max_accel_deg_s2: T::lit(1.0e3),
            lookahead_s: T::lit(1.0),
        }
    }

    /// `true` when the measurement is in steady motion.
    pub fn accepts(&self, m: &Measurement<T>) -> bool {
        m.direction != Direction::Still
            && m.moving_for_s >= self.min_moving_s
            && m.rate_deg_s.abs() >= self.min_rate_deg_s
            && m.accel_deg_s2.abs() <= self.max_accel_deg_s2
    }
}

/// Least spread of the rest samples' force per kg (standard deviation over
/// mean) at which [`CalibrationLearner::rest_split`] tells an offset from a
/// load: rest at 40° and at 80° spreads it by about 0.6.
pub const REST_SPLIT_SPREAD: f64 = 0.2;

/// Most residuals held back for the look-ahead (1 s at 500 Hz); when full,
/// the oldest is committed early.
pub const LOOKAHEAD_CAPACITY: usize = 512;

/// A residual waiting for its look-ahead: (time moving when seen, force F,
/// boom rate |ω|, residual, up?).
type Pending<T> = (T, T, T, T, bool);

/// Running means and co-moments of (x, v, y) = (piston force F, boom rate
/// |ω|, residual r) (Welford's update; see the module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Moments<T> {
    /// Number of samples.
    pub n: u32,
    /// Mean of x (N).
    pub mean_x: T,
    /// Mean of y (N).
    pub mean_y: T,
    /// Σ(x − x̄)² (N²).
    pub cxx: T,
    /// Σ(x − x̄)(y − ȳ) (N²).
    pub cxy: T,
    /// Σ(y − ȳ)² (N²).
    pub cyy: T,
    /// Mean of v (rad/s).
    pub mean_v: T,
    /// Σ(v − v̄)² (rad²/s²).
    pub cvv: T,
    /// Σ(x − x̄)(v − v̄) (N·rad/s).
    pub cxv: T,
    /// Σ(v − v̄)(y − ȳ) (N·rad/s).
    pub cvy: T,
}

impl<T: Real> Moments<T> {
    /// No samples.
    pub fn new() -> Self {
        let z = T::lit(0.0);
        Self {
            n: 0,
            mean_x: z,
            mean_y: z,
            cxx: z,
            cxy: z,
            cyy: z,
            mean_v: z,
            cvv: z,
            cxv: z,
            cvy: z,
        }
    }

    /// Adds one sample (x, y), at no rate.
    pub fn add(&mut self, x: T, y: T) {
        self.add_at_rate(x, T::lit(0.0), y);
    }

    /// Adds one sample (x, v, y).
    pub fn add_at_rate(&mut self, x: T, v: T, y: T) {
        self.n = self.n.saturating_add(1);
        let n = T::lit(f64::from(self.n));
        let dx = x - self.mean_x;
        self.mean_x += dx / n;
        let dv = v - self.mean_v;
        self.mean_v += dv / n;
        let dy = y - self.mean_y;
        self.mean_y += dy / n;
        self.cxx += dx * (x - self.mean_x);
        self.cxy += dx * (y - self.mean_y);
        self.cyy += dy * (y - self.mean_y);
        self.cvv += dv * (v - self.mean_v);
        self.cxv += dx * (v - self.mean_v);
        self.cvy += dv * (y - self.mean_y);
    }

    /// Adds the samples of `other` (Chan's formula).
    pub fn merge(&mut self, other: &Self) {
        if other.n == 0 {
            return;
        }
        if self.n == 0 {
            *self = *other;
            return;
        }
        let (na, nb) = (T::lit(f64::from(self.n)), T::lit(f64::from(other.n)));
        let n = na + nb;
        let dx = other.mean_x - self.mean_x;
        let dv = other.mean_v - self.mean_v;
        let dy = other.mean_y - self.mean_y;
        let w = na * nb / n;
        self.mean_x += dx * nb / n;
        self.mean_v += dv * nb / n;
        self.mean_y += dy * nb / n;
        self.cxx += other.cxx + dx * dx * w;
        self.cxy += other.cxy + dx * dy * w;
        self.cyy += other.cyy + dy * dy * w;
        self.cvv += other.cvv + dv * dv * w;
        self.cxv += other.cxv + dx * dv * w;
        self.cvy += other.cvy + dv * dy * w;
        self.n = self.n.saturating_add(other.n);
    }
}

impl<T: Real> Default for Moments<T> {
    fn default() -> Self {
        Self::new()
    }
}

/// The friction law fitted for one direction and how well it fits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DirectionFit<T> {
    /// Constant part a (N, ≥ 0).
    pub a_n: T,
    /// Share b of the piston force (–, 0 … [`MAX_PER_FORCE`]).
    pub b: T,
    /// `false`: the force did not vary enough for b (it is 0).
    pub slope_observable: bool,
    /// The slope as the least squares gave it, before clamping (–).
    pub raw_b: T,
    /// Standard error of the raw slope (–).
    pub b_se: T,
    /// Root mean square of the fit's residuals (N).
    pub rms_n: T,
    /// Mean friction over the samples as measured, a + b·F before `a` is
    /// clamped at 0 (N): below zero the force read as if the seals helped
    /// the motion, which no friction does.
    pub mean_friction_n: T,
    /// Samples.
    pub n: u32,
    /// Mean and standard deviation of the piston force over the samples (N).
    pub force_mean_n: T,
    /// Standard deviation of the piston force over the samples (N).
    pub force_sd_n: T,
    /// Friction per unit boom rate c (N·s/rad, 0 … [`MAX_PER_RATE_N_S`]).
    pub c: T,
    /// `false`: c is 0, because the rate did not vary enough apart from
    /// the force, c's error was too large, or it came out ≤ 0.
    pub rate_observable: bool,
    /// Standard error of c as fitted (N·s/rad).
    pub c_se: T,
    /// Mean and standard deviation of the boom rate over the samples (rad/s).
    pub rate_mean: T,
    /// Standard deviation of the boom rate over the samples (rad/s).
    pub rate_sd: T,
}

/// Fits z = s·(r − offset) = a + b·F over moments of (F, r).
fn fit_direction<T: Real>(m: &Moments<T>, s: T, offset: T) -> DirectionFit<T> {
    let zero = T::lit(0.0);
    let n = T::lit(f64::from(m.n.max(1)));
    let mean_z = s * (m.mean_y - offset);
    let cxz = s * m.cxy;
    let czz = m.cyy;
    let sd = (m.cxx / n).max(zero).sqrt();
    let raw_b = if m.cxx > zero { cxz / m.cxx } else { zero };
    let dof = T::lit(f64::from(m.n.saturating_sub(2).max(1)));
    let ssr_line = (czz - raw_b * cxz).max(zero);
    let b_se = if m.cxx > zero {
        (ssr_line / dof / m.cxx).sqrt()
    } else {
        T::lit(f64::INFINITY)
    };
    let observable = m.mean_x.abs() > zero
        && sd >= T::lit(MIN_FORCE_SPREAD) * m.mean_x.abs()
        && b_se <= T::lit(MAX_SLOPE_SE);
    let mut b = if observable {
        raw_b.max(zero).min(T::lit(MAX_PER_FORCE))
    } else {
        zero
    };
    let mut a = mean_z - b * m.mean_x;
    if a < zero {
        // A law through the origin: b from Σx·z/Σx² (uncentred).
        a = zero;
        if observable {
            let sxx = m.cxx + n * m.mean_x * m.mean_x;
            let sxz = cxz + n * m.mean_x * mean_z;
            b = if sxx > zero { (sxz / sxx).max(zero).min(T::lit(MAX_PER_FORCE)) } else { zero };
        }
    }
    // Σ(z − a − b·x)² from the moments.
    let bias = mean_z - a - b * m.mean_x;
    let ssr = (czz - T::lit(2.0) * b * cxz + b * b * m.cxx + n * bias * bias).max(zero);
    DirectionFit {
        a_n: a,
        b,
        slope_observable: observable,
        raw_b,
        b_se,
        rms_n: (ssr / n).sqrt(),
        mean_friction_n: mean_z,
        n: m.n,
        force_mean_n: m.mean_x,
        force_sd_n: sd,
        c: zero,
        rate_observable: false,
        c_se: T::lit(f64::INFINITY),
        rate_mean: m.mean_v,
        rate_sd: (m.cvv / n).max(zero).sqrt(),
    }
}

/// The fit `base` (a + b·F, [`fit_direction`]) with a friction per unit
/// boom rate c where the rate is observable apart from the force: z =
/// s·(r − offset) = a + b·F + c·|ω| by least squares over the moments
/// (see the module doc). Returns `base` where c is not observable, not
/// positive, or its fit is not finite.
fn fit_with_rate<T: Real>(m: &Moments<T>, s: T, offset: T, base: DirectionFit<T>) -> DirectionFit<T> {
    let zero = T::lit(0.0);
    let n = T::lit(f64::from(m.n.max(1)));
    let dof = T::lit(f64::from(m.n.saturating_sub(3).max(1)));
    let (sxx, sxv, svv) = (m.cxx, m.cxv, m.cvv);
    let (sxz, svz, szz) = (s * m.cxy, s * m.cvy, m.cyy);
    let sd_v = (svv / n).max(zero).sqrt();
    let spread = m.mean_v > zero && sd_v >= T::lit(MIN_RATE_SPREAD) * m.mean_v;
    // Over 0, and not NaN.
    let positive = |x: T| x > zero;
    if !spread || !positive(svv) {
        return base;
    }
    // Jointly with the slope where the slope is observable, else alone.
    let (b, b_se, c, c_se) = if base.slope_observable {
        let det = sxx * svv - sxv * sxv;
        if !positive(det) {
            return base;
        }
        let b = (sxz * svv - svz * sxv) / det;
        let c = (svz * sxx - sxz * sxv) / det;
        let var = (szz - b * sxz - c * svz).max(zero) / dof;
        (b, (var * svv / det).sqrt(), c, (var * sxx / det).sqrt())
    } else {
        let c = svz / svv;
        let ssr = (szz - c * svz).max(zero);
        (base.raw_b, base.b_se, c, (ssr / dof / svv).sqrt())
    };
    if !(c > zero && c_se <= T::lit(MAX_RATE_SE_N_S) && b.is_finite()) {
        return base;
    }
    let raw_b = b;
    let b = if base.slope_observable { b } else { zero };
    let b_clamped = b.max(zero).min(T::lit(MAX_PER_FORCE));
    // The rate's part refitted for the slope as clamped.
    let c = if b_clamped == b { c } else { (svz - b_clamped * sxv) / svv };
    let c = c.max(zero).min(T::lit(MAX_PER_RATE_N_S));
    let b = b_clamped;
    let mean_z = s * (m.mean_y - offset);
    let a = (mean_z - b * m.mean_x - c * m.mean_v).max(zero);
    let bias = mean_z - a - b * m.mean_x - c * m.mean_v;
    let ssr = (szz - T::lit(2.0) * (b * sxz + c * svz) + b * b * sxx + T::lit(2.0) * b * c * sxv + c * c * svv + n * bias * bias).max(zero);
    if !(a.is_finite() && c.is_finite()) {
        return base;
    }
    DirectionFit {
        a_n: a,
        b,
        raw_b,
        b_se,
        c,
        rate_observable: true,
        c_se,
        rms_n: (ssr / n).sqrt(),
        ..base
    }
}

/// The learned calibration and its fit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Learned<T> {
    /// What the limiter takes.
    pub calibration: Calibration<T>,
    /// The fit moving up.
    pub up: DirectionFit<T>,
    /// The fit moving down.
    pub down: DirectionFit<T>,
    /// `true`: the offset came from samples at rest; `false`: the
    /// symmetric split (see the module doc).
    pub offset_from_rest: bool,
    /// The seals' release time read from the rest after the runs' raises
    /// ([`crate::seal_release`]); `None` without such rest.
    pub release: Option<ReleaseFit<T>>,
}

/// Running moments of the residual per direction for one or more runs.
#[derive(Debug, Clone)]
pub struct CalibrationLearner<T> {
    steady: SteadyMotion<T>,
    pending: heapless::Deque<Pending<T>, LOOKAHEAD_CAPACITY>,
    up: Moments<T>,
    down: Moments<T>,
    /// The rest samples' moments of (model's piston force per kg, residual):
    /// their mean residual is the offset, their line the offset and a load
    /// told apart ([`Self::rest_split`]).
    rest: Moments<T>,
    /// The same over the samples before each log's first motion: seals that
    /// hold no friction whatever their release (the offset where there are
    /// enough of them; see the module doc).
    rest_before: Moments<T>,
    /// Sum of the model's piston force per kg over the steady samples.
    steady_per_kg: T,
    /// The known hook load of the runs observed now (kg).
    load_kg: T,
    /// A law to check against: the largest |residual| per direction.
    check: Option<Calibration<T>>,
    max_residual: (T, T),
    /// The samples at rest after raises' stops ([`crate::seal_release`]).
    release: ReleaseSums<T>,
    /// The release time the runs' limiter took the friction off with (s):
    /// its share gives the time since the stop.
    runs_release_s: T,
}

impl<T: Real> Default for CalibrationLearner<T> {
    fn default() -> Self {
        Self::new()
    }
}

impl<T: Real> CalibrationLearner<T> {
    /// No samples yet; the [`SteadyMotion::standard`] criteria; unloaded.
    pub fn new() -> Self {
        Self::with_steady_motion(SteadyMotion::standard())
    }

    /// No samples yet; the given criteria; unloaded.
    pub fn with_steady_motion(steady: SteadyMotion<T>) -> Self {
        Self {
            steady,
            pending: heapless::Deque::new(),
            up: Moments::new(),
            down: Moments::new(),
            rest: Moments::new(),
            rest_before: Moments::new(),
            steady_per_kg: T::lit(0.0),
            load_kg: T::lit(0.0),
            check: None,
            release: ReleaseSums::new(),
            runs_release_s: T::lit(crate::cycle::DEFAULT_SEAL_RELEASE_S),
            max_residual: (T::lit(0.0), T::lit(0.0)),
        }
    }

    /// A learner for runs with a known hook load (kg): the test weight of
    /// `--known-load-kg`.
    pub fn with_known_load(load_kg: T) -> Self {
        Self {
            load_kg,
            ..Self::new()
        }
    }

    /// This learner for runs with a known hook load (kg).
    pub fn loaded(self, load_kg: T) -> Self {
        Self { load_kg, ..self }
    }

    /// A learner that, fed the same runs again, measures the largest
    /// residual of `law` per direction ([`Self::max_residual_n`]).
    pub fn checking(law: Calibration<T>, load_kg: T) -> Self {
        Self {
            check: Some(law),
            ..Self::with_known_load(load_kg)
        }
    }

    /// The known hook load of the runs (kg; 0 unloaded).
    pub fn known_load_kg(&self) -> T {
        self.load_kg
    }

    /// Adds one sample of a run (samples not in steady motion are
    /// ignored; at rest, the offset).
    pub fn observe<M: HookLoadModel<T>>(
        &mut self,
        model: &M,
        m: &Measurement<T>,
    ) -> Result<(), ModelError> {
        let up = match m.direction {
            Direction::Up => true,
            Direction::Down => false,
            Direction::Still => {
                self.pending.clear();
                // Before any motion, or with the seals released: the offset.
                let before = matches!(m.friction, Friction::Static { last_moving: None });
                let released = before || m.static_friction_share < T::lit(0.01);
                let (f, inertia) = model_force_terms(model, m.boom.angle_rad, m.accel_rad_s2())?;
                let at_load = f.at(self.load_kg);
                let r = m.piston_force_n - inertia - at_load;
                if released {
                    self.rest.add(f.per_kg, r);
                }
                if before {
                    self.rest_before.add(f.per_kg, r);
                }
                // After a raise's stop: the seals' release (the share's
                // time since the stop, t = −τ₀·ln(share)).
                let share = m.static_friction_share;
                if m.friction == (Friction::Static { last_moving: Some(Direction::Up) }) && share > T::lit(0.0) {
                    let since_s = -self.runs_release_s * share.ln();
                    if since_s <= T::lit(RELEASE_WINDOW_S) {
                        self.release.add(since_s, (at_load + inertia).abs(), r);
                    }
                }
                return Ok(());
            }
        };
        if !self.steady.accepts(m) || self.pending.front().is_some_and(|p| p.4 != up) {
            // The motion was not steady: nor were the last `lookahead_s`.
            self.pending.clear();
            if !self.steady.accepts(m) {
                return Ok(());
            }
        }
        let (f, inertia) = model_force_terms(model, m.boom.angle_rad, m.accel_rad_s2())?;
        let at_load = f.at(self.load_kg);
        let r = m.piston_force_n - inertia - at_load;
        let x = (at_load + inertia).abs();
        self.steady_per_kg += f.per_kg;
        let now = m.moving_for_s;
        let v = m.boom.rate_rad_s.abs();
        while let Some(&(t, _, _, _, _)) = self.pending.front() {
            if now - t < self.steady.lookahead_s && !self.pending.is_full() {
                break;
            }
            if let Some((_, x, v, r, up)) = self.pending.pop_front() {
                self.commit(x, v, r, up);
            }
        }
        // Not full here: the loop above made room.
        let _ = self.pending.push_back((now, x, v, r, up));
        Ok(())
    }

    fn commit(&mut self, x: T, v: T, r: T, up: bool) {
        if up {
            self.up.add_at_rate(x, v, r);
        } else {
            self.down.add_at_rate(x, v, r);
        }
        if let Some(c) = &self.check {
            let d = if up { Direction::Up } else { Direction::Down };
            // The law's prediction of r at the true force x and rate v.
            let s = if up { T::lit(1.0) } else { T::lit(-1.0) };
            let e = (r - c.force_offset_n - s * c.sliding_n(d, x, v)).abs();
            let slot = if up { &mut self.max_residual.0 } else { &mut self.max_residual.1 };
            *slot = slot.max(e);
        }
    }

    /// Ends a log: the residuals still waiting for their look-ahead are
    /// dropped (the log may have ended mid-motion). Call between logs.
    pub fn end_of_log(&mut self) {
        self.pending.clear();
    }

    /// Adds the samples of another learner's runs (its pending look-ahead
    /// is not taken: end its log first).
    pub fn merge(&mut self, other: &Self) {
        self.up.merge(&other.up);
        self.down.merge(&other.down);
        self.rest.merge(&other.rest);
        self.rest_before.merge(&other.rest_before);
        self.release.merge(&other.release);
        self.steady_per_kg += other.steady_per_kg;
        self.max_residual.0 = self.max_residual.0.max(other.max_residual.0);
        self.max_residual.1 = self.max_residual.1.max(other.max_residual.1);
    }

    /// Sum of squared residuals of the best straight line r = c + β·F per
    /// direction, and the number of samples: what a lag error leaves that
    /// friction and offset cannot explain ([`crate::sensor_lag`]).
    pub fn line_ssr(&self) -> (T, u32) {
        let zero = T::lit(0.0);
        let ssr = |m: &Moments<T>| {
            let explained = if m.cxx > zero { m.cxy * m.cxy / m.cxx } else { zero };
            (m.cyy - explained).max(zero)
        };
        (ssr(&self.up) + ssr(&self.down), self.up.n.saturating_add(self.down.n))
    }

    /// Number of (up, down) samples counted.
    pub fn counts(&self) -> (u32, u32) {
        (self.up.n, self.down.n)
    }

    /// The moments (up, down).
    pub fn moments(&self) -> (Moments<T>, Moments<T>) {
        (self.up, self.down)
    }

    /// Largest |residual| (up, down) of the law given to [`Self::checking`] (N).
    pub fn max_residual_n(&self) -> (T, T) {
        self.max_residual
    }

    /// Number of samples at rest with the seals released.
    pub fn rest_count(&self) -> u32 {
        self.rest.n
    }

    /// The hook load (kg) the mean rest residual would be (the residual over
    /// the model's mean force per kg at the rest samples): what a load left
    /// on the "unloaded" run weighs, or how far a known-load run is from its
    /// stated weight.
    pub fn rest_load_kg(&self) -> Option<T> {
        let per_kg = self.rest.mean_x;
        let r = self.mean_rest_residual_n()?;
        (per_kg > T::lit(0.0)).then(|| r / per_kg)
    }

    /// The rest residual split into a force offset and a hook load,
    /// r = c + W·f_W(θ) (N, kg), when the rest samples were taken at angles
    /// whose force per kg f_W differs by at least [`REST_SPLIT_SPREAD`] of
    /// its mean (standard deviation over mean): an offset is the same at
    /// every angle, a load's force is not (at 80° a fifth of what it is at
    /// 40°). Returns (c, W, the rest samples' mean f_W in N/kg); `None`
    /// when the rest samples cannot tell the two apart.
    pub fn rest_split(&self) -> Option<(T, T, T)> {
        let m = &self.rest;
        let n = T::lit(f64::from(m.n));
        if m.n < 2 || m.mean_x <= T::lit(0.0) {
            return None;
        }
        let sd = (m.cxx / n).max(T::lit(0.0)).sqrt();
        if sd < T::lit(REST_SPLIT_SPREAD) * m.mean_x {
            return None;
        }
        let load_kg = m.cxy / m.cxx;
        Some((m.mean_y - load_kg * m.mean_x, load_kg, m.mean_x))
    }

    /// The model's mean piston force per kg over the steady samples (N/kg).
    pub fn steady_per_kg(&self) -> Option<T> {
        let n = self.up.n.saturating_add(self.down.n);
        (n > 0).then(|| self.steady_per_kg / T::lit(f64::from(n)))
    }

    /// Mean residual at rest (N): the force offset, if any rest sample.
    pub fn mean_rest_residual_n(&self) -> Option<T> {
        (self.rest.n > 0).then_some(self.rest.mean_y)
    }

    /// Mean residuals (r_up, r_down) in N, if both directions have samples.
    pub fn mean_residuals_n(&self) -> Option<(T, T)> {
        (self.up.n > 0 && self.down.n > 0).then_some((self.up.mean_y, self.down.mean_y))
    }

    /// Mean of the residual left by `cal`'s law over this learner's steady
    /// samples (N), if any: how far these runs are from the law.
    pub fn mean_law_residual_n(&self, cal: &Calibration<T>) -> Option<T> {
        let one = T::lit(1.0);
        let mut sum = T::lit(0.0);
        for (m, s, d) in [(self.up, one, Direction::Up), (self.down, -one, Direction::Down)] {
            sum += T::lit(f64::from(m.n))
                * (m.mean_y - cal.force_offset_n - s * cal.sliding_n(d, m.mean_x, m.mean_v));
        }
        let n = self.up.n.saturating_add(self.down.n);
        (n > 0).then(|| sum / T::lit(f64::from(n)))
    }

    /// The calibration, if each direction has at least `min_samples` samples.
    pub fn finish(&self, min_samples: u32) -> Result<Calibration<T>, CalibrationError> {
        self.fit(min_samples).map(|l| l.calibration)
    }

    /// The calibration and its fit, if each direction has at least
    /// `min_samples` samples (see the module doc).
    pub fn fit(&self, min_samples: u32) -> Result<Learned<T>, CalibrationError> {
        self.fit_with_rates(min_samples, (true, true))
    }

    /// [`Self::fit`] with the friction per unit rate c fitted (where
    /// observable) only in the directions `rates` (up, down) allows: the
    /// directions whose unloaded runs showed it, so that test-weight runs
    /// luffed at another speed than the unloaded ones cannot make the
    /// difference between a loaded and an unloaded run a speed's.
    pub fn fit_with_rates(&self, min_samples: u32, rates: (bool, bool)) -> Result<Learned<T>, CalibrationError> {
        for (up, n) in [(true, self.up.n), (false, self.down.n)] {
            if n < min_samples.max(1) {
                return Err(CalibrationError::TooFewSamples { up, found: n });
            }
        }
        let one = T::lit(1.0);
        // The rest before the first motion where it is long enough: after a
        // stop the seals may still hold friction (see the module doc).
        let before = self.rest_before.n >= min_samples.max(1);
        let (offset, from_rest) = match self.mean_rest_residual_n() {
            _ if before => (self.rest_before.mean_y, true),
            Some(rest) if self.rest.n >= min_samples.max(1) => (rest, true),
            _ => {
                // Intercepts of the lines r = c + s·b·F with the offset
                // unknown: the symmetric split.
                let c_up = intercept(&self.up, one);
                let c_down = intercept(&self.down, -one);
                ((c_up + c_down) * T::lit(0.5), false)
            }
        };
        let fit = |m: &Moments<T>, s: T, rate: bool| {
            let base = fit_direction(m, s, offset);
            if rate {
                fit_with_rate(m, s, offset, base)
            } else {
                base
            }
        };
        let up = fit(&self.up, one, rates.0);
        let down = fit(&self.down, -one, rates.1);
        let cal = Calibration {
            friction_up_n: up.a_n,
            friction_down_n: down.a_n,
            friction_up_per_force: up.b,
            friction_down_per_force: down.b,
            friction_up_per_rate: up.c,
            friction_down_per_rate: down.c,
            force_offset_n: offset,
            ..Calibration::none()
        };
        let finite = [offset, up.a_n, up.b, up.c, up.rms_n, down.a_n, down.b, down.c, down.rms_n]
            .iter()
            .all(|v| v.is_finite());
        if !finite {
            return Err(CalibrationError::NotFinite);
        }
        let release = fit_release(&self.release, (up.a_n, up.b), offset);
        let cal = Calibration {
            seal_release_up_s: release.filter(|r| r.observable && r.samples >= min_samples).map(|r| r.release_s),
            ..cal
        };
        Ok(Learned {
            calibration: cal,
            up,
            down,
            offset_from_rest: from_rest,
            release,
        })
    }
}

/// The residual's line at F = 0, s·b taken as the fit gives it (the
/// offset plus s·a): for the symmetric split.
fn intercept<T: Real>(m: &Moments<T>, s: T) -> T {
    let b = fit_direction(m, s, m.mean_y).b_unclamped_a();
    m.mean_y - s * b * m.mean_x
}

impl<T: Real> DirectionFit<T> {
    /// The slope as gated for observability and clamped to its bounds, but
    /// not refitted for a negative a.
    fn b_unclamped_a(&self) -> T {
        if self.slope_observable {
            self.raw_b.max(T::lit(0.0)).min(T::lit(MAX_PER_FORCE))
        } else {
            T::lit(0.0)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Steady samples of one direction (sign `s`) of a crane whose friction
    /// is a + b·F + c·|ω|, at the boom rates `rates` (rad/s) over forces
    /// sweeping 200–400 kN, with ±300 N of deterministic noise.
    fn moments(s: f64, (a, b, c): (f64, f64, f64), offset: f64, rates: &[f64]) -> Moments<f64> {
        let mut m = Moments::new();
        for &rate in rates {
            // The run's own phase of wander and noise.
            let k = rate * 30.0;
            for i in 0..400 {
                let f = 200_000.0 + 500.0 * f64::from(i);
                // The rate wanders ±3 % as a luff's does.
                let v = rate * (1.0 + 0.03 * (0.05 * f64::from(i) + k).sin());
                let noise = 300.0 * (1.7 * f64::from(i) + 0.3 * k).sin();
                m.add_at_rate(f, v, offset + s * (a + b * f + c * v) + noise);
            }
        }
        m
    }

    fn fit(m: &Moments<f64>, s: f64, offset: f64) -> DirectionFit<f64> {
        fit_with_rate(m, s, offset, fit_direction(m, s, offset))
    }

    /// Runs at two speeds (a 10 s and a 30 s luff over 40°: 0.07 and 0.023
    /// rad/s) give the friction per unit rate, up and down, with the seal
    /// law's slope beside it.
    #[test]
    fn runs_at_two_speeds_learn_the_friction_per_unit_rate() {
        for (s, law) in [(1.0, (6_000.0, 0.0, 140_000.0)), (-1.0, (4_000.0, 0.01, 95_000.0))] {
            let m = moments(s, law, 150.0, &[0.07, 0.023]);
            let f = fit(&m, s, 150.0);
            assert!(f.rate_observable, "{f:?}");
            assert!((f.c - law.2).abs() < 3_000.0, "c {} for {}", f.c, law.2);
            assert!((f.a_n - law.0).abs() < 300.0, "a {} for {}", f.a_n, law.0);
            assert!((f.b - law.1).abs() < 0.002, "b {} for {}", f.b, law.1);
            assert!(f.rms_n < 400.0, "{f:?}");
        }
    }

    /// One speed cannot tell the rate's part from the constant one: c is
    /// not observable, stays 0, and the constant part takes the run's
    /// friction at its speed (what the calibration learned before c).
    #[test]
    fn one_speed_leaves_the_friction_per_unit_rate_at_zero() {
        let law = (6_000.0, 0.0, 140_000.0);
        let m = moments(1.0, law, 0.0, &[0.07]);
        let f = fit(&m, 1.0, 0.0);
        assert!(!f.rate_observable && f.c == 0.0, "{f:?}");
        assert!((f.a_n - (6_000.0 + 140_000.0 * 0.07)).abs() < 500.0, "{f:?}");
    }

    /// A friction that does not grow with the rate, seen at two speeds,
    /// learns no rate part to speak of (under 50 N at 0.07 rad/s).
    #[test]
    fn a_constant_friction_at_two_speeds_learns_no_rate_part() {
        for s in [1.0, -1.0] {
            let m = moments(s, (12_000.0, 0.02, 0.0), -500.0, &[0.07, 0.023]);
            let f = fit(&m, s, -500.0);
            assert!(f.c * 0.07 < 50.0, "{f:?}");
            assert!((f.a_n - 12_000.0).abs() < 300.0 && (f.b - 0.02).abs() < 0.002, "{f:?}");
        }
    }

    /// The moments of two runs merged are those of both runs' samples added
    /// one by one (Chan's formula, the rate's moments included).
    #[test]
    fn merged_moments_are_the_moments_of_all_samples() {
        let one = moments(1.0, (6_000.0, 0.01, 140_000.0), 0.0, &[0.07]);
        let two = moments(1.0, (6_000.0, 0.01, 140_000.0), 0.0, &[0.023]);
        let all = moments(1.0, (6_000.0, 0.01, 140_000.0), 0.0, &[0.07, 0.023]);
        let mut merged = one;
        merged.merge(&two);
        let close = |x: f64, y: f64| (x - y).abs() <= 1e-9 * x.abs().max(y.abs()).max(1.0);
        for (x, y) in [
            (merged.mean_v, all.mean_v),
            (merged.cvv, all.cvv),
            (merged.cxv, all.cxv),
            (merged.cvy, all.cvy),
            (merged.cxy, all.cxy),
        ] {
            assert!(close(x, y), "{x} vs {y}");
        }
    }
}
