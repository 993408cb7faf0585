//! The thesis's maneuvers (SPEC §3, thesis §4.3): raise or lower the boom between
//! 40° and 80° in 30 s or 10 s with a linear or cycloidal ramp, and the outputs of
//! its figures at every sample.

use crate::dynamics::Reactions;
use crate::integrator::State;
use crate::multibody::{CraneModel, FreeCoordinates};
use crate::profile::{RampShape, StrokeProfile};
use crate::{ModelError, Real};

/// Which way the boom moves.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Direction {
    /// From the lower angle to the higher one.
    Up,
    /// From the higher angle to the lower one.
    Down,
}

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
        })
    }

    /// Start and end boom angles (deg).
    pub fn angles_deg(&self) -> (f64, f64) {
        match self.direction {
            Direction::Up => (self.low_angle_deg, self.high_angle_deg),
            Direction::Down => (self.high_angle_deg, self.low_angle_deg),
        }
    }

    /// End time of the simulation (s).
    pub fn end_s(&self) -> f64 {
        self.t3_s + self.settle_s
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
        mut on_sample: impl FnMut(&Sample<T>) -> bool,
    ) -> Result<RunSummary<T>, ModelError> {
        if !(options.step_s > 0.0 && options.step_s <= 0.1 && options.output_every >= 1) {
            return Err(ModelError::InvalidParameter(
                "step must be in (0, 0.1] s and output_every ≥ 1",
            ));
        }
        let stroke = self.stroke(maneuver);
        let load = T::lit(maneuver.load_kg);
        let start = T::lit(maneuver.angles_deg().0.to_radians());
        let free: FreeCoordinates<T, M> = match options.initial {
            InitialState::ListingProjection => self.listing_initial_state(start, load)?,
            InitialState::Equilibrium => self.equilibrium_state(start, load)?,
        };
        let (mut state, ev) = State::new(self, T::zero(), stroke.at(T::zero()), load, free)?;
        let mut summary = RunSummary {
            steps: 0,
            evaluations: 1,
            max_constraint_violation: T::zero(),
        };
        let first = self.sample(&ev, T::zero(), 0)?;
        summary.max_constraint_violation = first.constraint_violation;
        if !on_sample(&first) {
            return Ok(summary);
        }
        let steps = libm::ceil(maneuver.end_s() / options.step_s) as usize;
        let h = T::lit(options.step_s);
        let tol = T::lit(options.tolerance);
        for i in 1..=steps {
            let t = T::lit(i as f64 * options.step_s);
            let act = stroke.at(t);
            let stats = state.step(self, h, act, tol)?;
            state.t_s = t;
            summary.steps = i;
            summary.evaluations += stats.iterations;
            if i % options.output_every == 0 || i == steps {
                let ev = self.evaluate(act, load, &state.free)?;
                summary.evaluations += 1;
                let s = self.sample(&ev, t, stats.iterations)?;
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
        ev: &crate::dynamics::Evaluation<T, M>,
        t_s: T,
        iterations: usize,
    ) -> Result<Sample<T>, ModelError> {
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
            deflection_m,
            constraint_violation: sys.max_violation(),
            swing_rad: ev.config.swing_rad + T::frac_pi_2(),
            iterations,
        })
    }
}
