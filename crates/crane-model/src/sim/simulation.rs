//! The thesis's maneuvers (SPEC §3, thesis §4.3): raise or lower the boom between
//! 40° and 80° in 30 s or 10 s with a linear or cycloidal ramp, and the outputs of
//! its figures at every sample.

use crate::multibody::dynamics::Reactions;
use crate::sim::integrator::{NewtonStart, State};
use crate::multibody::{CraneModel, FreeCoordinates};
use crate::data::profile::{ActuatorMotion, RampShape, StrokeProfile};
use crate::multibody::rope::{RopeChoice, RopeMode};
use crate::{ModelError, Real};

/// Which way the boom moves (the crates' one direction type, see
/// [`crate::data::profile::Direction`]).
pub use crate::data::profile::Direction;

/// How the simulation starts (see [`CraneModel::equilibrium_state`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum InitialState {
    /// Static deflection projected on the modes in the energy norm: the reduced
    /// model's equilibrium, so the run starts without a transient. The default.
    Equilibrium,
    /// The listing's Euclidean least-squares projection (starts an 84 Hz transient).
    ListingProjection,
}

/// One boom maneuver.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Maneuver {
    /// Hook load W (kg).
    pub load_kg: f64,
    /// Ramp shape.
    pub shape: RampShape,
    /// Direction.
    pub direction: Direction,
    /// End of the acceleration ramp t1 (s).
    pub t1_s: f64,
    /// Start of the deceleration t2 (s).
    pub t2_s: f64,
    /// End of the motion t3 (s).
    pub t3_s: f64,
    /// Lower boom angle (deg).
    pub low_angle_deg: f64,
    /// Higher boom angle (deg).
    pub high_angle_deg: f64,
    /// Time simulated after t3 (s); the listing ran to 30.3 s.
    pub settle_s: f64,
    /// Time at rest before the move starts (s).
    pub hold_before_s: f64,
    /// How the rope behaves (thesis: paid out to keep the clearance; held: constant length).
    pub rope: RopeChoice,
}

impl Maneuver {
    /// A thesis maneuver: 30 s (t1 = 1.5, t2 = 28.5) or 10 s (t1 = 1, t2 = 9), 40°↔80°.
    pub fn thesis(
        load_kg: f64,
        duration_s: f64,
        shape: RampShape,
        direction: Direction,
    ) -> Result<Self, ModelError> {
        let ramp = if (duration_s - 30.0).abs() < 1e-9 {
            1.5
        } else if (duration_s - 10.0).abs() < 1e-9 {
            1.0
        } else {
            return Err(ModelError::InvalidParameter("duration must be 30 or 10 s"));
        };
        if direction == Direction::Still {
            return Err(ModelError::InvalidParameter("a thesis maneuver moves up or down"));
        }
        if !(load_kg >= 0.0 && load_kg.is_finite()) {
            return Err(ModelError::InvalidParameter(
                "hook load must be a finite number ≥ 0 kg",
            ));
        }
        Ok(Maneuver {
            load_kg,
            shape,
            direction,
            t1_s: ramp,
            t2_s: duration_s - ramp,
            t3_s: duration_s,
            low_angle_deg: 40.0,
            high_angle_deg: 80.0,
            settle_s: 0.3,
            hold_before_s: 0.0,
            rope: RopeChoice::Thesis,
        })
    }

    /// Any luffing move from `from_deg` to `to_deg` in `duration_s` (≥ 2 s) with
    /// acceleration and deceleration ramps of `ramp_s` each (the thesis's: 1.5 s for
    /// 30 s moves, 1 s for 10 s moves), thesis rope, no holds.
    pub fn luff(
        load_kg: f64,
        from_deg: f64,
        to_deg: f64,
        duration_s: f64,
        ramp_s: f64,
        shape: RampShape,
    ) -> Result<Self, ModelError> {
        if !(load_kg >= 0.0 && load_kg.is_finite()) {
            return Err(ModelError::InvalidParameter("hook load must be a finite number ≥ 0 kg"));
        }
        check_luff(from_deg, to_deg, duration_s, ramp_s)?;
        let direction = if to_deg > from_deg { Direction::Up } else { Direction::Down };
        Ok(Maneuver {
            load_kg,
            shape,
            direction,
            t1_s: ramp_s,
            t2_s: duration_s - ramp_s,
            t3_s: duration_s,
            low_angle_deg: from_deg.min(to_deg),
            high_angle_deg: from_deg.max(to_deg),
            settle_s: 0.0,
            hold_before_s: 0.0,
            rope: RopeChoice::Thesis,
        })
    }

    /// This maneuver as a program of segments: hold, luff, hold.
    pub fn program(&self) -> Result<Program, ModelError> {
        let (from, to) = self.angles_deg();
        let mut p = Program::new(from, self.load_kg, self.rope)?;
        if self.hold_before_s > 0.0 {
            p.push(Segment::Hold { duration_s: self.hold_before_s })?;
        }
        p.push(Segment::Luff { to_deg: to, shape: self.shape, t1_s: self.t1_s, t2_s: self.t2_s, t3_s: self.t3_s })?;
        if self.settle_s > 0.0 {
            p.push(Segment::Hold { duration_s: self.settle_s })?;
        }
        Ok(p)
    }

    /// Start and end boom angles (deg).
    pub fn angles_deg(&self) -> (f64, f64) {
        match self.direction {
            Direction::Up => (self.low_angle_deg, self.high_angle_deg),
            Direction::Down => (self.high_angle_deg, self.low_angle_deg),
            // Not a move: the program's luff to the same angle is refused.
            Direction::Still => (self.low_angle_deg, self.low_angle_deg),
        }
    }

    /// End time of the simulation (s).
    pub fn end_s(&self) -> f64 {
        self.hold_before_s + self.t3_s + self.settle_s
    }
}

/// The twelve thesis cases: (name, maneuver).
pub fn thesis_cases() -> [(&'static str, Maneuver); 12] {
    let m = |w: f64, d: f64, s: RampShape, dir: Direction| {
        Maneuver::thesis(w, d, s, dir).unwrap_or_else(|_| unreachable_maneuver())
    };
    use Direction::{Down, Up};
    use RampShape::{Cycloidal, Linear};
    [
        ("unloaded-30s-linear-up", m(0.0, 30.0, Linear, Up)),
        ("unloaded-30s-linear-down", m(0.0, 30.0, Linear, Down)),
        ("unloaded-30s-cycloidal-up", m(0.0, 30.0, Cycloidal, Up)),
        ("unloaded-30s-cycloidal-down", m(0.0, 30.0, Cycloidal, Down)),
        ("3300kg-30s-linear-up", m(3300.0, 30.0, Linear, Up)),
        ("3300kg-30s-linear-down", m(3300.0, 30.0, Linear, Down)),
        ("3300kg-30s-cycloidal-up", m(3300.0, 30.0, Cycloidal, Up)),
        (
            "3300kg-30s-cycloidal-down",
            m(3300.0, 30.0, Cycloidal, Down),
        ),
        ("3300kg-10s-linear-up", m(3300.0, 10.0, Linear, Up)),
        ("3300kg-10s-linear-down", m(3300.0, 10.0, Linear, Down)),
        ("3300kg-10s-cycloidal-up", m(3300.0, 10.0, Cycloidal, Up)),
        (
            "3300kg-10s-cycloidal-down",
            m(3300.0, 10.0, Cycloidal, Down),
        ),
    ]
}

fn unreachable_maneuver() -> Maneuver {
    // Only reached if `Maneuver::thesis` rejected the fixed thesis values above.
    Maneuver {
        load_kg: 0.0,
        shape: RampShape::Cycloidal,
        direction: Direction::Up,
        t1_s: 1.5,
        t2_s: 28.5,
        t3_s: 30.0,
        low_angle_deg: 40.0,
        high_angle_deg: 80.0,
        settle_s: 0.3,
        hold_before_s: 0.0,
        rope: RopeChoice::Thesis,
    }
}

fn check_luff(from_deg: f64, to_deg: f64, duration_s: f64, ramp_s: f64) -> Result<(), ModelError> {
    if !(from_deg >= 0.0 && from_deg <= 88.0 && to_deg >= 0.0 && to_deg <= 88.0 && (from_deg - to_deg).abs() >= 0.01) {
        return Err(ModelError::InvalidParameter("luff angles must be in [0°, 88°] and differ by ≥ 0.01°"));
    }
    if !(duration_s >= 2.0 && duration_s <= 3600.0) {
        return Err(ModelError::InvalidParameter("luff duration must be in [2, 3600] s"));
    }
    if !(ramp_s > 0.0 && 2.0 * ramp_s <= duration_s) {
        return Err(ModelError::InvalidParameter("ramp must be > 0 s and at most half the luff's duration"));
    }
    Ok(())
}

/// Most segments in a [`Program`].
pub const MAX_SEGMENTS: usize = 32;

/// One segment of a [`Program`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Segment {
    /// The boom at rest where the previous segment left it.
    Hold {
        /// Duration (s).
        duration_s: f64,
    },
    /// A luffing move to `to_deg`: constant-velocity stroke with acceleration ramp
    /// 0..t1 and deceleration t2..t3 (eqs. 3.47/3.48), duration t3.
    Luff {
        /// End angle (deg).
        to_deg: f64,
        /// Ramp shape.
        shape: RampShape,
        /// End of the acceleration ramp (s into the segment).
        t1_s: f64,
        /// Start of the deceleration ramp (s into the segment).
        t2_s: f64,
        /// End of the move (s into the segment).
        t3_s: f64,
    },
    /// A lift-off at the present angle: the hoist takes the load off the ground, the
    /// hook load rising linearly from what hung before to `load_kg` over
    /// `duration_s`; the load hangs from then on. (The load is modelled as a growing
    /// point mass at the rope's end, at rest relative to the pendulum.)
    LiftOff {
        /// Duration of the take-up (s).
        duration_s: f64,
        /// Hook load once lifted (kg).
        load_kg: f64,
    },
    /// The winch hoists the hanging load up by `by_m` (negative: lets it down)
    /// with the boom still, a held rope only: the hanging length L runs from its
    /// value to L − `by_m` on the speed profile of a luff (acceleration ramps of
    /// `ramp_s` at both ends, `shape` as the luff's, eqs. 3.47/3.48), and the rope
    /// is held at the new length from then on. The load's vertical acceleration
    /// −L̈ loads the rope, W·(g − L̈) when hanging straight (the winch's own start
    /// and stop, which no luff shows).
    Hoist {
        /// How far the load goes up (m; negative: down).
        by_m: f64,
        /// Duration of the hoist (s).
        duration_s: f64,
        /// Duration of each of its acceleration and deceleration ramps (s).
        ramp_s: f64,
        /// Ramp shape.
        shape: RampShape,
    },
}

impl Segment {
    /// Duration (s).
    pub fn duration_s(&self) -> f64 {
        match *self {
            Segment::Hold { duration_s } | Segment::LiftOff { duration_s, .. } | Segment::Hoist { duration_s, .. } => duration_s,
            Segment::Luff { t3_s, .. } => t3_s,
        }
    }
}

/// A sequence of segments (hold, luff, lift-off) from a start angle and load: any
/// session of luffing and lifting at a fixed slew. No heap: at most
/// [`MAX_SEGMENTS`] segments.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Program {
    /// Boom angle at t = 0 (deg).
    pub start_deg: f64,
    /// Hook load at t = 0 (kg); 0 before a lift-off.
    pub initial_load_kg: f64,
    /// The rope.
    pub rope: RopeChoice,
    segments: [Segment; MAX_SEGMENTS],
    len: usize,
}

impl Program {
    /// An empty program at `start_deg` with `initial_load_kg` hanging.
    pub fn new(start_deg: f64, initial_load_kg: f64, rope: RopeChoice) -> Result<Self, ModelError> {
        if !(start_deg >= 0.0 && start_deg <= 88.0) {
            return Err(ModelError::InvalidParameter("start angle must be in [0°, 88°]"));
        }
        if !(initial_load_kg >= 0.0 && initial_load_kg.is_finite()) {
            return Err(ModelError::InvalidParameter("hook load must be a finite number ≥ 0 kg"));
        }
        Ok(Program { start_deg, initial_load_kg, rope, segments: [Segment::Hold { duration_s: 0.0 }; MAX_SEGMENTS], len: 0 })
    }

    /// Appends a segment after checking it.
    pub fn push(&mut self, segment: Segment) -> Result<(), ModelError> {
        match segment {
            Segment::Hold { duration_s } => {
                if !(duration_s > 0.0 && duration_s <= 3600.0) {
                    return Err(ModelError::InvalidParameter("hold duration must be in (0, 3600] s"));
                }
            }
            Segment::Luff { to_deg, t1_s, t2_s, t3_s, .. } => {
                check_luff(self.end_deg(), to_deg, t3_s, t1_s)?;
                if !(t1_s <= t2_s && t2_s < t3_s) {
                    return Err(ModelError::InvalidParameter("luff needs 0 < t1 ≤ t2 < t3"));
                }
            }
            Segment::LiftOff { duration_s, load_kg } => {
                if !(duration_s > 0.0 && duration_s <= 600.0) {
                    return Err(ModelError::InvalidParameter("lift-off duration must be in (0, 600] s"));
                }
                if !(load_kg >= 0.0 && load_kg.is_finite()) {
                    return Err(ModelError::InvalidParameter("hook load must be a finite number ≥ 0 kg"));
                }
            }
            Segment::Hoist { by_m, duration_s, ramp_s, .. } => {
                if !matches!(self.rope, RopeChoice::Held { .. }) {
                    return Err(ModelError::InvalidParameter("a hoist needs a held rope (the thesis's rope is paid out to keep the load's clearance)"));
                }
                if !(by_m.is_finite() && by_m.abs() >= 0.01 && by_m.abs() <= 100.0) {
                    return Err(ModelError::InvalidParameter("a hoist moves the load by 0.01 to 100 m up or down"));
                }
                if !(duration_s <= 3600.0 && ramp_s > 0.0 && 2.0 * ramp_s <= duration_s) {
                    return Err(ModelError::InvalidParameter("a hoist's ramps must be > 0 s and at most half its duration, which is at most 3600 s"));
                }
            }
        }
        let slot = self.segments.get_mut(self.len).ok_or(ModelError::InvalidParameter("too many segments"))?;
        *slot = segment;
        self.len += 1;
        Ok(())
    }

    /// The segments in order.
    pub fn segments(&self) -> &[Segment] {
        self.segments.get(..self.len).unwrap_or(&[])
    }

    /// Boom angle at the end of the program (deg).
    pub fn end_deg(&self) -> f64 {
        self.segments().iter().fold(self.start_deg, |a, s| match *s {
            Segment::Luff { to_deg, .. } => to_deg,
            _ => a,
        })
    }

    /// Hook load at the end of the program (kg).
    pub fn end_load_kg(&self) -> f64 {
        self.segments().iter().fold(self.initial_load_kg, |w, s| match *s {
            Segment::LiftOff { load_kg, .. } => load_kg,
            _ => w,
        })
    }

    /// Total duration (s).
    pub fn duration_s(&self) -> f64 {
        self.segments().iter().map(Segment::duration_s).sum()
    }
}

/// One segment of a program compiled in the model's float type.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Phase<T> {
    start_s: T,
    end_s: T,
    stroke: Option<StrokeProfile<T>>,
    extension_m: T,
    load_from_kg: T,
    load_to_kg: T,
    /// A held rope's hanging length in this phase (m; `None` for the
    /// thesis's rope), and its profile while a hoist changes it.
    length_m: Option<T>,
    hoist: Option<StrokeProfile<T>>,
}

/// A [`Program`] compiled for one model: the actuator motion, hook load and
/// hanging length at any time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Schedule<T> {
    phases: [Phase<T>; MAX_SEGMENTS],
    len: usize,
    start_extension_m: T,
    initial_load_kg: T,
    /// The program hoists: the hanging length is the schedule's, not the
    /// rope mode's constant.
    hoists: bool,
}

impl<T: Real> Schedule<T> {
    fn phase_at(&self, t_s: T) -> Option<&Phase<T>> {
        let phases = self.phases.get(..self.len).unwrap_or(&[]);
        // The last phase that has started; times before the first one read it too.
        phases.iter().rev().find(|p| p.start_s <= t_s).or(phases.first())
    }

    /// The actuator motion at `t_s`.
    pub fn actuator_at(&self, t_s: T) -> ActuatorMotion<T> {
        match self.phase_at(t_s) {
            Some(Phase { stroke: Some(stroke), start_s, .. }) => stroke.at(t_s - *start_s),
            Some(p) => ActuatorMotion { extension_m: p.extension_m, rate_m_s: T::zero(), accel_m_s2: T::zero() },
            None => ActuatorMotion { extension_m: self.start_extension_m, rate_m_s: T::zero(), accel_m_s2: T::zero() },
        }
    }

    /// The hook load at `t_s` (kg).
    pub fn load_at(&self, t_s: T) -> T {
        match self.phase_at(t_s) {
            Some(p) if p.load_from_kg != p.load_to_kg => {
                let f = ((t_s - p.start_s) / (p.end_s - p.start_s)).max(T::zero()).min(T::one());
                p.load_from_kg + (p.load_to_kg - p.load_from_kg) * f
            }
            Some(p) => p.load_to_kg,
            None => self.initial_load_kg,
        }
    }

    /// The held rope's hanging length at `t_s` with its rate and acceleration
    /// (m, m/s, m/s²) once the program has hoisted; `None` when the rope
    /// mode's own length holds (no hoist in the program, or the thesis's rope).
    pub fn hanging_length_at(&self, t_s: T) -> Option<ActuatorMotion<T>> {
        if !self.hoists {
            return None;
        }
        let p = self.phase_at(t_s)?;
        match p.hoist {
            Some(profile) => Some(profile.at(t_s - p.start_s)),
            None => p.length_m.map(|l| ActuatorMotion { extension_m: l, rate_m_s: T::zero(), accel_m_s2: T::zero() }),
        }
    }
}

/// Integration settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SimulationOptions {
    /// Time step h (s).
    pub step_s: f64,
    /// Emit a sample every this many steps.
    pub output_every: usize,
    /// Newton tolerance (relative).
    pub tolerance: f64,
    /// How the simulation starts.
    pub initial: InitialState,
    /// What each sample computes.
    pub outputs: Outputs,
    /// Where each step's Newton iteration starts (the reference start by default).
    pub newton_start: NewtonStart,
}

/// What a [`Sample`] carries.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Outputs {
    /// Every multiplier (14×14 solve over the full system): piston force, pin
    /// forces, F_A, rope tension, constraint violation. The default.
    All,
    /// The piston force alone, by inverse dynamics along the actuator
    /// ([`CraneModel::piston_force_along_actuator_n`], equal to the multiplier to rounding), for
    /// log synthesis; pin forces, F_A, the stabilizing moment and the rope tension
    /// are NaN, and the constraint violation is not evaluated (reported as 0).
    PistonForce,
}

impl SimulationOptions {
    /// The defaults: h = 2 ms, a sample every 5 steps (100 Hz), starting at equilibrium.
    pub fn for_type<T: Real>() -> Self {
        let f32_like = T::default_epsilon().to_f64() > 1e-10;
        SimulationOptions {
            step_s: 2e-3,
            output_every: 5,
            tolerance: if f32_like { 1e-5 } else { 1e-10 },
            initial: InitialState::Equilibrium,
            outputs: Outputs::All,
            newton_start: NewtonStart::PreviousStep,
        }
    }
}

/// One output sample: the quantities of the thesis's figures.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample<T: Real> {
    /// Time (s).
    pub t_s: T,
    /// Boom angle θ1 (rad).
    pub boom_angle_rad: T,
    /// Multiplier-derived reactions: piston force, pin forces, F_A.
    pub reactions: Reactions<T>,
    /// Transverse deflection of the reported nodes (thesis nodes 3, 8, 13) (m).
    pub deflection_m: [T; 3],
    /// Largest position-level constraint violation |Φ| (m or rad).
    pub constraint_violation: T,
    /// Load swing θ5 + π/2 (rad): 0 when hanging straight down.
    pub swing_rad: T,
    /// Newton iterations of the step that produced this sample.
    pub iterations: usize,
    /// Force of the rope on the tip C along the rope (N): the revolute-at-C
    /// multipliers projected on the rope; (rope + load)·g at rest.
    pub rope_tension_n: T,
    /// Hook load hanging at this instant (kg; grows during a lift-off).
    pub hook_load_kg: T,
    /// Piston speed da/dt (m/s), positive extending.
    pub actuator_rate_m_s: T,
}

/// Totals of a run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RunSummary<T> {
    /// Steps taken.
    pub steps: usize,
    /// Newton iterations (evaluations) in all.
    pub evaluations: usize,
    /// Largest |Φ| over the output samples.
    pub max_constraint_violation: T,
}

impl<T: Real, const M: usize> CraneModel<T, M> {
    /// The actuator stroke of a maneuver.
    pub fn stroke(&self, maneuver: &Maneuver) -> StrokeProfile<T> {
        let (a, b) = maneuver.angles_deg();
        StrokeProfile {
            shape: maneuver.shape,
            t1_s: T::lit(maneuver.t1_s),
            t2_s: T::lit(maneuver.t2_s),
            t3_s: T::lit(maneuver.t3_s),
            start_m: self.geometry.extension_at_angle(T::lit(a.to_radians())),
            end_m: self.geometry.extension_at_angle(T::lit(b.to_radians())),
        }
    }

    /// Simulates `maneuver`, calling `on_sample` at t = 0 and every `output_every`
    /// steps. `on_sample` may stop the run early by returning `false` (the dynamic
    /// tipping search stops at F_A ≤ 0). No allocation.
    pub fn simulate(
        &self,
        maneuver: &Maneuver,
        options: &SimulationOptions,
        on_sample: impl FnMut(&Sample<T>) -> bool,
    ) -> Result<RunSummary<T>, ModelError> {
        self.simulate_program(&maneuver.program()?, options, on_sample)
    }

    /// Compiles `program` for this model: the stroke of every luff, the extension of
    /// every hold and the hook load of every lift-off.
    pub fn schedule(&self, program: &Program) -> Result<Schedule<T>, ModelError> {
        let ext = |deg: f64| self.geometry.extension_at_angle(T::lit(deg.to_radians()));
        let start_extension_m = ext(program.start_deg);
        let initial = T::lit(program.initial_load_kg);
        let mut length = match self.rope {
            RopeMode::Held { length_m } => Some(length_m),
            RopeMode::Thesis => None,
        };
        let mut sched = Schedule {
            phases: [Phase { start_s: T::zero(), end_s: T::zero(), stroke: None, extension_m: start_extension_m, load_from_kg: initial, load_to_kg: initial, length_m: length, hoist: None }; MAX_SEGMENTS],
            len: 0,
            start_extension_m,
            initial_load_kg: initial,
            hoists: false,
        };
        let (mut t, mut extension, mut load, mut deg) = (0.0f64, start_extension_m, initial, program.start_deg);
        for (seg, phase) in program.segments().iter().zip(sched.phases.iter_mut()) {
            let d = seg.duration_s();
            let mut p = Phase { start_s: T::lit(t), end_s: T::lit(t + d), stroke: None, extension_m: extension, load_from_kg: load, load_to_kg: load, length_m: length, hoist: None };
            match *seg {
                Segment::Hoist { by_m, duration_s, ramp_s, shape } => {
                    let from = length.ok_or(ModelError::InvalidParameter("a hoist needs a held rope"))?;
                    let to = from - T::lit(by_m);
                    // The load stays on the rope and above the ground: at
                    // least a metre of rope, and no more than the rigid tip's
                    // height at this angle.
                    let tip_height = self.clearance_length_m(T::lit(deg.to_radians()))? + self.load_clearance_m;
                    if !(to >= T::one() && to <= tip_height) {
                        return Err(ModelError::InvalidParameter("a hoist must leave between 1 m of rope and the tip's height hanging"));
                    }
                    p.hoist = Some(StrokeProfile { shape, t1_s: T::lit(ramp_s), t2_s: T::lit(duration_s - ramp_s), t3_s: T::lit(duration_s), start_m: from, end_m: to });
                    length = Some(to);
                    p.length_m = length;
                    sched.hoists = true;
                }
                Segment::Hold { .. } => {}
                Segment::Luff { to_deg, shape, t1_s, t2_s, t3_s } => {
                    let stroke = StrokeProfile { shape, t1_s: T::lit(t1_s), t2_s: T::lit(t2_s), t3_s: T::lit(t3_s), start_m: extension, end_m: ext(to_deg) };
                    extension = stroke.at(stroke.t3_s).extension_m;
                    deg = to_deg;
                    p.stroke = Some(stroke);
                }
                Segment::LiftOff { load_kg, .. } => {
                    load = T::lit(load_kg);
                    p.load_to_kg = load;
                }
            }
            *phase = p;
            sched.len += 1;
            t += d;
        }
        Ok(sched)
    }

    /// Simulates a program of segments (see [`Self::simulate`]). The rope mode is the
    /// program's: a held rope without a length gets the clearance length at the start.
    pub fn simulate_program(
        &self,
        program: &Program,
        options: &SimulationOptions,
        mut on_sample: impl FnMut(&Sample<T>) -> bool,
    ) -> Result<RunSummary<T>, ModelError> {
        if !(options.step_s > 0.0 && options.step_s <= 0.1 && options.output_every >= 1) {
            return Err(ModelError::InvalidParameter(
                "step must be in (0, 0.1] s and output_every ≥ 1",
            ));
        }
        let start = T::lit(program.start_deg.to_radians());
        let model = self.with_rope(self.rope_for(program.rope, start)?);
        let sched = model.schedule(program)?;
        let load0 = sched.load_at(T::zero());
        let free: FreeCoordinates<T, M> = match options.initial {
            InitialState::ListingProjection => model.listing_initial_state(start, load0)?,
            InitialState::Equilibrium => model.equilibrium_state(start, load0)?,
        };
        let (mut state, mut ev) = State::new(&model, T::zero(), sched.actuator_at(T::zero()), load0, free)?;
        state.newton_start = options.newton_start;
        let mut summary = RunSummary {
            steps: 0,
            evaluations: 1,
            max_constraint_violation: T::zero(),
        };
        let first = model.sample_with(&ev, T::zero(), 0, options.outputs)?;
        summary.max_constraint_violation = first.constraint_violation;
        if !on_sample(&first) {
            return Ok(summary);
        }
        let steps = libm::ceil(program.duration_s() / options.step_s) as usize;
        let h = T::lit(options.step_s);
        let tol = T::lit(options.tolerance);
        for i in 1..=steps {
            let t = T::lit(i as f64 * options.step_s);
            let act = sched.actuator_at(t);
            let load = sched.load_at(t);
            let rigid = model.rigid_motion(act, load)?;
            let rigid = match sched.hanging_length_at(t) {
                Some(l) => model.with_length(&rigid, l)?,
                None => rigid,
            };
            let sampled = i % options.output_every == 0 || i == steps;
            if !sampled {
                let stats = state.step_to(&model, h, &rigid, tol)?;
                state.t_s = t;
                summary.steps = i;
                summary.evaluations += stats.evaluations;
            } else {
                let stats = state.step_to_sampled(&model, h, &rigid, tol, &mut ev)?;
                state.t_s = t;
                summary.steps = i;
                summary.evaluations += stats.evaluations;
                let s = model.sample_with(&ev, t, stats.iterations, options.outputs)?;
                summary.max_constraint_violation =
                    summary.max_constraint_violation.max(s.constraint_violation);
                if !on_sample(&s) {
                    break;
                }
            }
        }
        Ok(summary)
    }

    /// The outputs at an evaluated state.
    pub fn sample(
        &self,
        ev: &crate::multibody::dynamics::Evaluation<T, M>,
        t_s: T,
        iterations: usize,
    ) -> Result<Sample<T>, ModelError> {
        self.sample_with(ev, t_s, iterations, Outputs::All)
    }

    /// The outputs at an evaluated state, all or the piston force alone.
    pub fn sample_with(
        &self,
        ev: &crate::multibody::dynamics::Evaluation<T, M>,
        t_s: T,
        iterations: usize,
        outputs: Outputs,
    ) -> Result<Sample<T>, ModelError> {
        let mut deflection_m = [T::zero(); 3];
        for (s, d) in deflection_m.iter_mut().enumerate() {
            for k in 0..M {
                *d += self.modes.deflection_modes[s][k] * ev.config.eta[k];
            }
        }
        if outputs == Outputs::PistonForce {
            let nan = T::lit(f64::NAN);
            return Ok(Sample {
                t_s,
                boom_angle_rad: ev.config.mech.boom.angle,
                reactions: Reactions {
                    piston_force_n: self.piston_force_along_actuator_n(ev)?,
                    boom_foot_n: nalgebra::Vector2::new(nan, nan),
                    cylinder_foot_n: nalgebra::Vector2::new(nan, nan),
                    jack_reaction_n: nan,
                    stabilizing_moment_nm: nan,
                },
                deflection_m,
                constraint_violation: T::zero(),
                swing_rad: ev.config.swing_rad + T::frac_pi_2(),
                iterations,
                rope_tension_n: nan,
                hook_load_kg: ev.config.load_kg,
                actuator_rate_m_s: ev.config.mech.actuator.rate_m_s,
            });
        }
        let (sys, lambda) = self.multipliers(ev)?;
        let mut deflection_m = [T::zero(); 3];
        for (s, d) in deflection_m.iter_mut().enumerate() {
            for k in 0..M {
                *d += self.modes.deflection_modes[s][k] * ev.config.eta[k];
            }
        }
        Ok(Sample {
            t_s,
            boom_angle_rad: ev.config.mech.boom.angle,
            reactions: self.reactions(&lambda),
            rope_tension_n: self.rope_tension_n(&lambda, ev.config.swing_axis),
            hook_load_kg: ev.config.load_kg,
            actuator_rate_m_s: ev.config.mech.actuator.rate_m_s,
            deflection_m,
            constraint_violation: sys.max_violation(),
            swing_rad: ev.config.swing_rad + T::frac_pi_2(),
            iterations,
        })
    }
}
