//! Hook-load estimate from the filtered piston force (thesis §4.2, SPEC §4.3).
//!
//! At the present boom state the model gives the piston force as a function
//! of the hook load, F_model(W) = at_zero + per_kg·W + per_kg2·W². The measured
//! force also carries the cylinder's friction, whose sign follows the motion
//! (the up and down traces of the thesis differ by it), and a zero offset:
//!
//! F_meas = F_model(W) + force_offset + friction(direction), with
//! friction(Up) = +(a_up + b_up·|F| + c_up·|ω|),
//! friction(Down) = −(a_down + b_down·|F| + c_down·|ω|),
//!
//! where F is the piston force the cylinder really exerts (the seal is
//! pressed harder the higher the pressure behind it: the constant a is
//! `friction_*_n`, the share b is `friction_*_per_force`), ω the boom's
//! filtered rate (a friction that grows with the piston's speed, the rate
//! times the cylinder's lever: c is `friction_*_per_rate`, learned from runs
//! at two speeds, [`crate::calibration`]), and W solves
//! F_model(W) = F_meas − force_offset − friction(direction).
//!
//! **Which force the seal law takes.** F is the true force F_meas −
//! force_offset − friction, not the model's force at the estimated load:
//! the model's force at W_est would make the friction depend on the
//! estimate it corrects (a loop whose gain is b·per_kg, and whose error
//! feeds back through the estimate's own filters), while the true force
//! follows from the measured one in closed form. With s = ±1 the sign of
//! the motion and F ≥ 0 (the boom hangs on the piston side),
//! F_meas − offset = F + s·(a + c·|ω| + b·F), so
//!
//! F = (F_meas − offset − s·(a + c·|ω|))/(1 + s·b), friction = (F_meas − offset) − F,
//!
//! one division, no iteration, exact for the seal law (the measured force
//! in place of F would be off by b²·F, 0.16 % of F at b = 0.04). The bound
//! b ≤ 0.2 keeps 1 ± b away from 0. The
//! model's F_model is exactly quadratic in W (the boom's sag grows with the
//! load, [`crane_model::loads::load_model::Quadratic`]); its slope per kg is close to
//! constant, and a load for which the slope at W = 0 is not positive, or which
//! no load on the rising branch explains, is not observable (a FAULT).
//!
//! **When the boom is still**, the seals release: the friction the last
//! motion left in the force relaxes to zero within about a second (the
//! pressure settles to what holds the load), and before any motion there is
//! none. The limiter removes the last motion's friction (at no rate: the
//! rate's part goes with the motion) times a share that
//! is 1 when the filtered rate says the boom stopped and decays with
//! [`crate::cycle::LimiterConfig::seal_release_s`] (the filtered force
//! lags the stop by as much as the filtered rate does). Taking half the
//! sliding friction for ever (the old rule) read a 30 % load at 80° after
//! raising at 0.64–0.87 of itself: half the friction is a large share of a
//! short-armed load. A cylinder whose seals stay stuck after lowering
//! reads low by the lowering friction's share of the load (the ×1.05
//! reading covers 5 %); one stuck after raising reads high.
//!
//! **A swinging load** pulls the tip sideways too: the piston force grows by
//! (F_model(W) − at_zero)·tan θ·tan φ ([`crate::swing`]), so the load part of
//! F_model is scaled by (1 + tan θ·tan φ) for a swing φ (the rope bank,
//! [`crate::static_load`], predicts it for each rope it considers).
//!
//! **Motion.** The model is evaluated at rest, and the motion enters as two
//! corrections. The boom's angular acceleration θ̈ costs the cylinder
//! J(θ)·θ̈ ([`HookLoadModel::piston_force_per_boom_accel`]): subtracted from
//! the force (in the 10 s thesis moves the ramps reach 4–9 °/s², which is
//! +14–17 % of a near-rated load when left in). The rate itself adds nothing
//! the model should see: the boom's centripetal forces point through A0 and
//! have no moment about it, and the load is not carried round with the tip,
//! it hangs from the rope, so its pull is the swing correction's. (Evaluated
//! with the rate, the model held the swing angle fixed and carried the load
//! along: −2 % on the load in the 10 s moves, measured on the flexible model.)

use crane_model::loads::load_model::{BoomState, HookLoadModel, LoadTerms, Quadratic};
use crane_model::{ModelError, Real};

/// Direction of boom motion, from the filtered angle rate: the crates' one
/// direction type ([`crane_model::data::profile::Direction`]).
pub use crane_model::data::profile::Direction;

/// Thresholds of [`DirectionDetector`] (degrees per second, positive).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DirectionThresholds<T> {
    /// |rate| above which a still boom is moving.
    pub start_deg_s: T,
    /// |rate| below which a moving boom is still (< `start_deg_s`: hysteresis).
    pub stop_deg_s: T,
    /// Time (s) a still boom's rate must stay beyond `stop_deg_s` one way
    /// for it to be moving: the seals slide at any speed, and a raise at
    /// 0.13 °/s (under `start_deg_s`) kept the up-friction in the force as
    /// load (+6 %, OVERLOAD at true u 0.898). Counted only once the filters
    /// have run [`CREEP_AFTER_START_S`]. Upward only while the filtered force
    /// stays within [`CREEP_FORCE_CHANGE`] of its value when the creep
    /// began: a 110 % load taken up at rest at 80° shows 0.08 °/s upward for
    /// 0.25 s (the sensor and the boom answering the jerk), and taken as a
    /// raise, with its up-friction out of the force, it was cut 0.37 s
    /// later. Downward always (the down-friction added back errs high).
    pub creep_s: T,
}

impl<T: Real> DirectionThresholds<T> {
    /// Defaults: start at 0.15 °/s, stop below 0.05 °/s (the thesis's slowest
    /// manoeuvre runs at about 1.3 °/s), or creeping at over 0.05 °/s for
    /// 0.25 s (the filtered rate's noise at rest stays under 0.03 °/s,
    /// in a lift-off too).
    pub fn standard() -> Self {
        Self {
            start_deg_s: T::lit(0.15),
            stop_deg_s: T::lit(0.05),
            creep_s: T::lit(0.25),
        }
    }
    /// `true` when 0 < stop ≤ start, 0 ≤ creep and all are finite.
    pub fn is_valid(&self) -> bool {
        self.start_deg_s.is_finite()
            && self.stop_deg_s > T::lit(0.0)
            && self.stop_deg_s <= self.start_deg_s
            && self.creep_s >= T::lit(0.0)
            && self.creep_s.is_finite()
    }
}

/// Time after the filters start (s) before a creep counts (see
/// [`DirectionThresholds::creep_s`]): a filter starts settled on its first
/// sample, and one quantisation step of the angle (0.027°) in it reads as
/// 0.09 °/s for half a second while the filter converges.
pub const CREEP_AFTER_START_S: f64 = 1.0;

/// Largest change of the filtered force over an upward creep (fraction)
/// for it to be a raise: a creeping raise adds only its sliding friction
/// (4–6 %), a load taken up at rest, whose jerk shows the same upward rate,
/// far more.
pub const CREEP_FORCE_CHANGE: f64 = 0.1;

/// Direction of motion with hysteresis, remembering the last moving direction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DirectionDetector<T> {
    thresholds: DirectionThresholds<T>,
    current: Direction,
    last_moving: Option<Direction>,
    /// How long a still boom's rate has been below −`stop_deg_s` (s).
    creeping_s: T,
    /// How long a still boom's rate has been above `stop_deg_s` (s), and
    /// the filtered force when it began (N).
    creeping_up_s: T,
    creep_force_n: Option<T>,
    /// Time since the filters started (s), up to [`CREEP_AFTER_START_S`].
    age_s: T,
}

impl<T: Real> DirectionDetector<T> {
    /// A detector that starts with a still boom and no motion history.
    pub fn new(thresholds: DirectionThresholds<T>) -> Self {
        Self {
            thresholds,
            current: Direction::Still,
            last_moving: None,
            creeping_s: T::lit(0.0),
            creeping_up_s: T::lit(0.0),
            creep_force_n: None,
            age_s: T::lit(0.0),
        }
    }

    /// The filters restarted: their start-up is no creep (see
    /// [`CREEP_AFTER_START_S`]).
    pub fn filters_restarted(&mut self) {
        self.age_s = T::lit(0.0);
        self.creeping_s = T::lit(0.0);
        self.creeping_up_s = T::lit(0.0);
        self.creep_force_n = None;
    }

    /// Updates with the filtered angle rate (°/s), `dt_s` after the last
    /// update, and returns the direction.
    pub fn update(&mut self, rate_deg_s: T, dt_s: T, force_n: T) -> Direction {
        let th = self.thresholds;
        let zero = T::lit(0.0);
        let dt = if dt_s > zero { dt_s } else { zero };
        self.age_s = (self.age_s + dt).min(T::lit(CREEP_AFTER_START_S));
        // A still boom creeping down: how long its rate has stayed below
        // the stop threshold (restarted when it rises inside).
        let counts = self.age_s >= T::lit(CREEP_AFTER_START_S);
        self.creeping_s = if counts && rate_deg_s < -th.stop_deg_s {
            self.creeping_s + dt
        } else {
            zero
        };
        if counts && rate_deg_s > th.stop_deg_s {
            self.creeping_up_s += dt;
            if self.creep_force_n.is_none() {
                self.creep_force_n = Some(force_n);
            }
        } else {
            self.creeping_up_s = zero;
            self.creep_force_n = None;
        }
        let steady = self.creep_force_n.is_some_and(|f| (force_n - f).abs() <= T::lit(CREEP_FORCE_CHANGE) * f.abs());
        self.current = match self.current {
            Direction::Up if rate_deg_s > th.stop_deg_s => Direction::Up,
            Direction::Down if rate_deg_s < -th.stop_deg_s => Direction::Down,
            _ if rate_deg_s > th.start_deg_s => Direction::Up,
            _ if rate_deg_s < -th.start_deg_s => Direction::Down,
            _ if self.creeping_s > th.creep_s => Direction::Down,
            _ if self.creeping_up_s > th.creep_s && steady => Direction::Up,
            _ => Direction::Still,
        };
        if self.current != Direction::Still {
            self.last_moving = Some(self.current);
        }
        self.current
    }

    /// The present direction (before the next update).
    pub fn current(&self) -> Direction {
        self.current
    }

    /// The friction in the measured force now (see the module doc).
    pub fn friction(&self) -> Friction {
        match (self.current, self.last_moving) {
            (Direction::Up, _) => Friction::Sliding(Direction::Up),
            (Direction::Down, _) => Friction::Sliding(Direction::Down),
            (Direction::Still, last) => Friction::Static { last_moving: last },
        }
    }
}

/// The cylinder friction the measured force carries.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Friction {
    /// Moving: the full friction of that direction (never `Still`).
    Sliding(Direction),
    /// Still: static friction, between zero and the friction of the last
    /// motion (`None`: none seen since power-up, between the two).
    Static {
        /// Direction of the last motion.
        last_moving: Option<Direction>,
    },
}

/// Largest seal-friction share b of the piston force (–): a seal that takes
/// a fifth of the force is worn out, and 1 ± b stays far from 0.
pub const MAX_PER_FORCE: f64 = 0.2;

/// Largest friction per unit boom rate c (N·s/rad): 40 kN, the largest
/// constant part a calibration file may hold, at 0.1 rad/s (a 10 s luff
/// over 57°).
pub const MAX_PER_RATE_N_S: f64 = 400_000.0;

/// Longest angle-sensor lag a calibration may hold (s): a pendulum or
/// potentiometer lagging the boom by half a second misreads a 10 s move by
/// 4°; it is broken or mounted wrong, not something to correct for.
pub const MAX_ANGLE_SENSOR_LAG_S: f64 = 0.5;

/// Shortest seals' release time a calibration may hold (s): a technician
/// may set one down to it (the calibration learns none under 0.2 s,
/// [`crate::seal_release::RELEASE_CANDIDATES_S`]); the limiter divides a
/// cycle's step by it.
pub const MIN_SEAL_RELEASE_S: f64 = 0.01;

/// Longest seals' release time a calibration may hold (s): the longest the
/// calibration learns, seals that stay stuck.
pub const MAX_SEAL_RELEASE_S: f64 = 60.0;

/// What `crane-sim calibrate` learns (and a technician may adjust).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Calibration<T> {
    /// Cylinder friction while luffing up (N, ≥ 0): the force reads this much high.
    pub friction_up_n: T,
    /// Cylinder friction while luffing down (N, ≥ 0): the force reads this much low.
    pub friction_down_n: T,
    /// Seal friction while luffing up per newton of piston force (b_up, ≥ 0):
    /// the friction is `friction_up_n` + b_up·|F|.
    pub friction_up_per_force: T,
    /// Seal friction while luffing down per newton of piston force (b_down, ≥ 0).
    pub friction_down_per_force: T,
    /// Friction while luffing up per unit boom rate (c_up, N·s/rad, ≥ 0):
    /// a friction that grows with the piston's speed (the piston's speed is
    /// the boom's rate times the cylinder's lever da/dθ).
    pub friction_up_per_rate: T,
    /// Friction while luffing down per unit boom rate (c_down, N·s/rad, ≥ 0).
    pub friction_down_per_rate: T,
    /// Zero-load force offset (N): transducer offsets and model error at W = 0.
    pub force_offset_n: T,
    /// Zero offset of p1 (bar), subtracted before eq. 4.1.
    pub p1_offset_bar: T,
    /// Zero offset of p2 (bar), subtracted before eq. 4.1.
    pub p2_offset_bar: T,
    /// Zero offset of the pendulum (degrees), subtracted from the reading
    /// after its range check.
    pub angle_offset_deg: T,
    /// The angle sensor's lag as calibrated (s, first-order equivalent; see
    /// [`crate::calibration`]): the limiter aligns force and angle with it.
    /// `None` (no calibration, or a file of schema version 1 or 2): the
    /// configured [`crate::cycle::LimiterConfig::angle_sensor_lag_s`].
    pub angle_sensor_lag_s: Option<T>,
    /// The seals' release time after a raise as calibrated (s;
    /// [`crate::seal_release`]): the limiter takes a raise's friction off a
    /// still boom's force with it. `None` (not observable in the runs, or a
    /// file of schema version 1–4): the configured
    /// [`crate::cycle::LimiterConfig::seal_release_s`], as after a lowering.
    pub seal_release_up_s: Option<T>,
}

impl<T: Real> Calibration<T> {
    /// No friction and no offsets.
    pub fn none() -> Self {
        let z = T::lit(0.0);
        Self {
            friction_up_n: z,
            friction_down_n: z,
            friction_up_per_force: z,
            friction_down_per_force: z,
            friction_up_per_rate: z,
            friction_down_per_rate: z,
            force_offset_n: z,
            p1_offset_bar: z,
            p2_offset_bar: z,
            angle_offset_deg: z,
            angle_sensor_lag_s: None,
            seal_release_up_s: None,
        }
    }

    /// `true` when all values are finite and the frictions are not negative.
    pub fn is_valid(&self) -> bool {
        [
            self.friction_up_n,
            self.friction_down_n,
            self.force_offset_n,
            self.p1_offset_bar,
            self.p2_offset_bar,
            self.angle_offset_deg,
        ]
        .iter()
        .all(|x| x.is_finite())
            && self.friction_up_n >= T::lit(0.0)
            && self.friction_down_n >= T::lit(0.0)
            && [self.friction_up_per_force, self.friction_down_per_force]
                .iter()
                .all(|b| b.is_finite() && *b >= T::lit(0.0) && *b <= T::lit(MAX_PER_FORCE))
            && [self.friction_up_per_rate, self.friction_down_per_rate]
                .iter()
                .all(|c| c.is_finite() && *c >= T::lit(0.0) && *c <= T::lit(MAX_PER_RATE_N_S))
            && self
                .angle_sensor_lag_s
                .is_none_or(|l| l.is_finite() && l >= T::lit(0.0) && l <= T::lit(MAX_ANGLE_SENSOR_LAG_S))
            && self
                .seal_release_up_s
                .is_none_or(|r| r.is_finite() && r >= T::lit(MIN_SEAL_RELEASE_S) && r <= T::lit(MAX_SEAL_RELEASE_S))
    }

    /// The friction law (a, b, c) of a direction of motion (N, –, N·s/rad),
    /// or `None` for `Still`.
    pub fn law(&self, direction: Direction) -> Option<(T, T, T)> {
        match direction {
            Direction::Up => Some((self.friction_up_n, self.friction_up_per_force, self.friction_up_per_rate)),
            Direction::Down => Some((self.friction_down_n, self.friction_down_per_force, self.friction_down_per_rate)),
            Direction::Still => None,
        }
    }

    /// The size of the sliding friction (N) at the true piston force
    /// `force_n` and boom rate `rate_rad_s` moving in `direction`,
    /// a + b·|F| + c·|ω| (0 for `Still`; a rate that is not a number adds
    /// nothing): the law forward, as the calibration's residuals see it.
    pub fn sliding_n(&self, direction: Direction, force_n: T, rate_rad_s: T) -> T {
        let Some((a, b, c)) = self.law(direction) else {
            return T::lit(0.0);
        };
        a + b * force_n.abs() + c * speed(rate_rad_s)
    }

    /// Signed friction (N) in a measured force `force_n` (offset removed)
    /// for a direction of motion at boom rate `rate_rad_s`: the seal law
    /// solved for the true force (see the module doc),
    /// F = (F_meas − s·(a + c·|ω|))/(1 + s·b).
    // Never inlined: its two inlined copies (sliding and breaking away) took
    // 0.35 KB more of the board's 64 KiB flash than one function.
    #[inline(never)]
    pub fn friction_n(&self, direction: Direction, force_n: T, rate_rad_s: T) -> T {
        let Some((a, b, c)) = self.law(direction) else {
            return T::lit(0.0);
        };
        let a = a + c * speed(rate_rad_s);
        let one = T::lit(1.0);
        let (s, sa) = if direction == Direction::Up {
            (one, a)
        } else {
            (-one, -a)
        };
        // The boom hangs on the piston side (F ≥ 0); a force that reads
        // below the friction itself takes the other branch of |F|.
        let mut true_force = (force_n - sa) / (one + s * b);
        if true_force < T::lit(0.0) {
            true_force = (force_n - sa) / (one - s * b);
        }
        let f = force_n - true_force;
        if f.is_finite() {
            f
        } else {
            sa
        }
    }

    /// The friction (N) the estimate removes from the measured force
    /// `force_n` (offset removed): the sliding friction when moving; when
    /// still, the last motion's friction times `static_share` (1 at the
    /// stop, decaying to 0 as the seals release; see the module doc), none
    /// before any motion.
    pub fn correction_n(&self, friction: Friction, static_share: T, force_n: T, rate_rad_s: T) -> T {
        match friction {
            Friction::Sliding(d) => self.friction_n(d, force_n, rate_rad_s),
            // The speed's part is gone as the boom stops.
            Friction::Static {
                last_moving: Some(d),
            } => self.friction_n(d, force_n, T::lit(0.0)) * static_share,
            Friction::Static { last_moving: None } => T::lit(0.0),
        }
    }
}

/// |ω| of a boom rate (rad/s), 0 for one that is not a number.
fn speed<T: Real>(rate_rad_s: T) -> T {
    if rate_rad_s.is_finite() {
        rate_rad_s.abs()
    } else {
        T::lit(0.0)
    }
}

/// Why no load estimate could be made.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EstimateError {
    /// The model could not be evaluated at this state.
    Model(ModelError),
    /// The model's piston force does not grow with the load (slope ≤ 0 or not
    /// finite): the load cannot be inferred from the force here.
    NotObservable,
}

/// The model's terms of the load equation at boom angle `angle_rad` turning
/// with angular acceleration `accel_rad_s2` (see "Motion" in the module doc):
/// the piston force at rest as a function of W, and the force the boom's
/// acceleration costs. Shared by the estimate and the calibration learner so
/// that both see the same model.
pub fn model_force_terms<T: Real, M: HookLoadModel<T>>(
    model: &M,
    angle_rad: T,
    accel_rad_s2: T,
) -> Result<(Quadratic<T>, T), ModelError> {
    let at_rest = BoomState {
        angle_rad,
        rate_rad_s: T::lit(0.0),
    };
    let inertia = model.piston_force_per_boom_accel(angle_rad)? * accel_rad_s2;
    Ok((model.piston_force_n(at_rest)?, inertia))
}

/// Hook load (kg) from the filtered measured force (see the module doc).
/// The force must already have the transducer offsets removed; `terms` are
/// the model's at the force's instant ([`crane_model::loads::load_model::CycleTerms::load`]),
/// `accel_rad_s2` the boom's angular acceleration then, `rate_rad_s` its
/// rate (for the friction's part per unit rate), and `tan_swing` tan φ of
/// the load swing (0: hanging straight).
pub fn estimate_load_kg<T: Real>(
    terms: &LoadTerms<T>,
    accel_rad_s2: T,
    rate_rad_s: T,
    force_n: T,
    calibration: &Calibration<T>,
    friction: Friction,
    tan_swing: T,
) -> Result<T, EstimateError> {
    let (f, force) = load_equation(
        terms,
        accel_rad_s2,
        force_n,
        calibration,
        friction,
        T::lit(0.0),
        rate_rad_s,
    )?;
    let f = f.scale_load_part(T::lit(1.0) + terms.tan_angle * tan_swing);
    f.solve(force).ok_or(EstimateError::NotObservable)
}

/// The two sides of the load equation at rest (see the module doc): the
/// model's piston force at rest as a function of W, and the measured force
/// less the boom's inertia J·θ̈, the offset and the friction. The load W
/// solves `at_rest(W) = force` once the load part of `at_rest` is scaled for
/// the swing (and, for [`crate::static_load`], the load's vertical
/// acceleration).
pub fn load_equation<T: Real>(
    terms: &LoadTerms<T>,
    accel_rad_s2: T,
    force_n: T,
    calibration: &Calibration<T>,
    friction: Friction,
    static_share: T,
    rate_rad_s: T,
) -> Result<(Quadratic<T>, T), EstimateError> {
    let inertia = terms.piston_force_per_boom_accel * accel_rad_s2;
    let f = terms.piston_force;
    if !(f.at_zero.is_finite() && inertia.is_finite()) {
        return Err(EstimateError::NotObservable);
    }
    let force_n = force_n - calibration.force_offset_n;
    Ok((
        f,
        force_n - inertia - calibration.correction_n(friction, static_share, force_n, rate_rad_s),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn direction_has_hysteresis_and_memory() {
        let mut d = DirectionDetector::new(DirectionThresholds::<f64>::standard());
        assert_eq!(d.friction(), Friction::Static { last_moving: None });
        assert_eq!(d.update(0.1, 0.01, 1e5), Direction::Still);
        assert_eq!(d.update(0.2, 0.01, 1e5), Direction::Up);
        assert_eq!(d.update(0.1, 0.01, 1e5), Direction::Up); // above stop threshold
        assert_eq!(d.update(0.01, 0.01, 1e5), Direction::Still);
        // Still after raising: static friction in [0, friction_up].
        assert_eq!(
            d.friction(),
            Friction::Static {
                last_moving: Some(Direction::Up)
            }
        );
        assert_eq!(d.update(-1.0, 0.01, 1e5), Direction::Down);
        assert_eq!(d.friction(), Friction::Sliding(Direction::Down));
    }

    #[test]
    fn a_creeping_boom_moves_and_noise_and_a_load_taken_up_do_not() {
        let dt = 0.01;
        // Lowering at 0.13 °/s, under the start rate: moving once its rate
        // has stayed under the stop rate for 0.25 s, then held by the
        // hysteresis.
        let mut d = DirectionDetector::new(DirectionThresholds::<f64>::standard());
        for _ in 0..100 {
            assert_eq!(d.update(0.0, dt, 1e5), Direction::Still);
        }
        let started = (0..100).find(|_| d.update(-0.13, dt, 1e5) != Direction::Still);
        // The 25th or 26th update: 0.25 s of rate (sums of steps round).
        assert!(started.is_some_and(|k| (24..=25).contains(&k)), "{started:?}");
        assert_eq!(d.friction(), Friction::Sliding(Direction::Down));
        assert_eq!((0..100).map(|_| d.update(-0.06, dt, 1e5)).last(), Some(Direction::Down));
        // The same rate upward with the force rising (a load taken up at
        // rest shows it) is no raise: its friction is not taken out.
        let mut d = DirectionDetector::new(DirectionThresholds::<f64>::standard());
        for k in 0..500 {
            assert_eq!(d.update(0.13, dt, 1e5 * (1.0 + 0.01 * f64::from(k))), Direction::Still);
        }
        // With its force steady it is a creeping raise.
        let mut d = DirectionDetector::new(DirectionThresholds::<f64>::standard());
        for _ in 0..100 {
            d.update(0.0, dt, 1e5);
        }
        assert_eq!((0..30).map(|_| d.update(0.13, dt, 1.04e5)).last(), Some(Direction::Up));
        // A still boom whose rate stays within ±0.05 °/s never moves, nor
        // one whose rate leaves that band for less than 0.25 s at a time (at
        // 2 Hz, 0.1 s each way each period), nor the filters' start-up
        // (−0.09 °/s for half a second), after power-up or a restart.
        let mut d = DirectionDetector::new(DirectionThresholds::<f64>::standard());
        for k in 0..3000 {
            let t = f64::from(k) * dt;
            let rate = if k < 1500 { 0.045 * (0.2 * t).cos() } else { 0.09 * (4.0 * core::f64::consts::PI * t).cos() };
            assert_eq!(d.update(rate, dt, 1e5), Direction::Still, "{t}");
        }
        for restart in [false, true] {
            if restart {
                d.filters_restarted();
            } else {
                d = DirectionDetector::new(DirectionThresholds::<f64>::standard());
            }
            for _ in 0..60 {
                assert_eq!(d.update(-0.09, dt, 1e5), Direction::Still);
            }
        }
    }

    #[test]
    fn static_friction_is_the_last_motions_times_its_share() {
        let cal = Calibration {
            friction_up_n: 12.0,
            friction_down_n: 8.0,
            ..Calibration::<f64>::none()
        };
        let at = |last_moving, share| {
            cal.correction_n(Friction::Static { last_moving }, share, 1000.0, 0.0)
        };
        assert_eq!(
            cal.correction_n(Friction::Sliding(Direction::Up), 0.3, 1000.0, 0.0),
            12.0
        );
        assert_eq!(
            cal.correction_n(Friction::Sliding(Direction::Down), 0.3, 1000.0, 0.0),
            -8.0
        );
        assert_eq!(at(Some(Direction::Up), 1.0), 12.0);
        assert_eq!(at(Some(Direction::Up), 0.5), 6.0);
        assert_eq!(at(Some(Direction::Down), 0.25), -2.0);
        assert_eq!(at(None, 1.0), 0.0);
    }

    /// The part of the friction that grows with the rate, c·|ω|, is the
    /// rate's in either direction and gone at a stop: a still boom's
    /// friction is the last motion's at no rate, times its share.
    #[test]
    fn the_friction_per_unit_rate_is_taken_at_the_boom_rate() {
        let cal = Calibration {
            friction_up_n: 6_000.0,
            friction_down_n: 4_000.0,
            friction_up_per_force: 0.01,
            friction_up_per_rate: 140_000.0,
            friction_down_per_rate: 90_000.0,
            ..Calibration::<f64>::none()
        };
        for (rate, f) in [(0.07, 300_000.0), (-0.07, 300_000.0), (0.02, 50_000.0)] {
            let up = f + 6_000.0 + 0.01 * f + 140_000.0 * f64::abs(rate);
            let down = f - 4_000.0 - 90_000.0 * f64::abs(rate);
            let fu = cal.correction_n(Friction::Sliding(Direction::Up), 1.0, up, rate);
            let fd = cal.correction_n(Friction::Sliding(Direction::Down), 1.0, down, rate);
            assert!((up - fu - f).abs() < 1e-6, "up at {f}, {rate} rad/s: {fu}");
            assert!((down - fd - f).abs() < 1e-6, "down at {f}, {rate} rad/s: {fd}");
        }
        let still = cal.correction_n(Friction::Static { last_moving: Some(Direction::Down) }, 0.5, 1e5, 0.07);
        assert_eq!(still, -2_000.0);
        // A rate that is not a number adds nothing.
        assert_eq!(cal.friction_n(Direction::Down, 1e5, f64::NAN), -4_000.0);
        // Bounds: c within 0 … MAX_PER_RATE_N_S.
        assert!(cal.is_valid());
        assert!(!Calibration { friction_up_per_rate: -1.0, ..cal }.is_valid());
        assert!(!Calibration { friction_down_per_rate: 2.0 * MAX_PER_RATE_N_S, ..cal }.is_valid());
        assert!(!Calibration { friction_down_per_rate: f64::NAN, ..cal }.is_valid());
    }

    #[test]
    fn the_seal_law_is_solved_for_the_true_force() {
        let cal = Calibration {
            friction_up_n: 5_000.0,
            friction_down_n: 3_000.0,
            friction_up_per_force: 0.03,
            friction_down_per_force: 0.02,
            ..Calibration::<f64>::none()
        };
        // The simulator's law: measured = F ± (a + b·F).
        for f in [0.0, 50_000.0, 400_000.0] {
            let up = f + 5_000.0 + 0.03 * f;
            let down = f - 3_000.0 - 0.02 * f;
            let fu = cal.friction_n(Direction::Up, up, 0.0);
            let fd = cal.friction_n(Direction::Down, down, 0.0);
            assert!((up - fu - f).abs() < 1e-6, "up at {f}: {fu}");
            assert!((down - fd - f).abs() < 1e-6, "down at {f}: {fd}");
        }
        // The same in f32 at a heavy load.
        let c32 = Calibration {
            friction_up_n: 5_000.0f32,
            friction_up_per_force: 0.03,
            ..Calibration::<f32>::none()
        };
        let f = 400_000.0f32;
        let got = c32.friction_n(Direction::Up, f + 5_000.0 + 0.03 * f, 0.0);
        assert!((got - 17_000.0).abs() < 1.0, "{got}");
        assert_eq!(cal.friction_n(Direction::Still, 1e5, 0.0), 0.0);
    }
}
