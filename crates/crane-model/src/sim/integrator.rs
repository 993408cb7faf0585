//! Time integration of the free coordinates (modes and load swing).
//!
//! Method: Newmark's average-acceleration rule (the trapezoidal rule on the
//! second-order equations), implicit, with a Newton iteration whose matrix is the
//! reduced mass matrix plus h/2·(modal damping) and h²/4·(modal and pendulum
//! stiffness). Why this one:
//! * The retained modes span 25–600 rad/s. An explicit method would need steps
//!   under ~4 ms for the stiffest one alone; the trapezoidal rule is unconditionally
//!   stable, adds no numerical damping and conserves the energy of the linear modal
//!   oscillators exactly, so the step is set by the accuracy of what matters (the
//!   first bending mode at 25 rad/s, the swing, the ramps), not by stability.
//! * Second order, one evaluation of the equations per Newton iteration, usually
//!   two or three iterations a step: a 30 s maneuver costs a few thousand cheap
//!   evaluations of (M + 1)-dimensional equations.
//! * Log synthesis and the campaign take the fast variant of the iteration
//!   ([`NewtonStart::Extrapolated`]): about one evaluation a step instead of two
//!   or three, the same physics to far below any sensor's resolution.
//! * The dependent coordinates are never integrated: they follow from the actuator
//!   and the modes in closed form (`mechanism`), so the position-level constraints
//!   hold to rounding at every step; there is no drift to stabilize.

use crate::multibody::dynamics::Evaluation;
use crate::multibody::{Block2Factor, CraneModel, FreeCoordinates, RigidMotion};
use crate::data::profile::ActuatorMotion;
use crate::{ModelError, Real};
use nalgebra::SVector;

/// Most Newton iterations per step.
pub const MAX_ITERATIONS: usize = 12;

/// Most steps an iteration matrix is reused for ([`NewtonStart::Extrapolated`]).
pub const JACOBIAN_MAX_AGE: usize = 8;

/// After this many iterations on a reused matrix a step refactors it and goes on.
const STALE_JACOBIAN_ITERATIONS: usize = 3;

/// A contraction measured this many steps ago is measured again (a full second
/// iteration) before it may end another step early: the matrix ages and the
/// load may be changing (a lift-off).
pub const CONTRACTION_MAX_AGE: usize = 3;

/// Where each step's Newton iteration starts.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum NewtonStart {
    /// From the accelerations of the previous step: the reference start, which the
    /// thesis reproductions and the other golden numbers were made with.
    #[default]
    PreviousStep,
    /// The fast iteration, for log synthesis and the campaign: (1) it starts from
    /// the accelerations extrapolated linearly over the step, which change
    /// smoothly, so the first correction is O(h²) instead of O(h); (2) it keeps
    /// the iteration matrix (mass matrix plus the step's damping and stiffness,
    /// which change slowly with the configuration) over up to
    /// [`JACOBIAN_MAX_AGE`] steps, refactoring it as soon as a step needs more
    /// than two iterations; (3) it stops after the first correction when the
    /// contraction θ measured on the kept matrix (at most [`CONTRACTION_MAX_AGE`]
    /// steps ago) says the error left, θ/(1 − θ)·‖Δ‖, is within the tolerance
    /// (Hairer and Wanner's rule for simplified Newton). A 30 s held-rope move
    /// takes 21 k evaluations instead of 43 k. Each step still stops within the
    /// tolerance, but not at the reference's iterate: over a run the two part by
    /// up to about 1e-6 of the outputs' scales (0.1 N of piston force), far below
    /// any sensor, which is why it is a choice and not the default.
    Extrapolated,
}

/// The integrator's state: free coordinates, their accelerations and the time.
#[derive(Debug, Clone, Copy)]
pub struct State<T: Real, const M: usize> {
    /// Time (s).
    pub t_s: T,
    /// Modes and swing with their rates.
    pub free: FreeCoordinates<T, M>,
    /// η̈ at `t_s`.
    pub eta_accel: SVector<T, M>,
    /// θ̈5 at `t_s`.
    pub swing_accel: T,
    /// Hook load W (kg).
    pub load_kg: T,
    /// η̈ and θ̈5 one step before `t_s`, once a step has been taken.
    pub previous_accel: Option<(SVector<T, M>, T)>,
    /// Where each step's Newton iteration starts.
    pub newton_start: NewtonStart,
    /// The iteration matrix kept over steps, the step it was made for and its age
    /// in steps ([`NewtonStart::Extrapolated`] only).
    pub kept_jacobian: Option<(Block2Factor<T, M>, T, usize)>,
    /// The iteration's contraction θ = ‖Δ₂‖/‖Δ₁‖ last measured on the kept matrix
    /// and the steps since ([`NewtonStart::Extrapolated`] only; `None` until a step
    /// has measured it).
    pub contraction: Option<(T, usize)>,
}

/// Statistics of one step.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct StepStats {
    /// Newton iterations used.
    pub iterations: usize,
    /// Evaluations of the equations: the iterations, plus one when the outputs
    /// at the end of the step needed their own.
    pub evaluations: usize,
}

impl<T: Real, const M: usize> State<T, M> {
    /// A state at time `t_s` with accelerations evaluated from the equations.
    pub fn new(
        model: &CraneModel<T, M>,
        t_s: T,
        act: ActuatorMotion<T>,
        load_kg: T,
        free: FreeCoordinates<T, M>,
    ) -> Result<(Self, Evaluation<T, M>), ModelError> {
        let ev = model.evaluate(act, load_kg, &free)?;
        Ok((
            State {
                t_s,
                free,
                eta_accel: ev.eta_accel,
                swing_accel: ev.swing_accel,
                load_kg,
                previous_accel: None,
                newton_start: NewtonStart::PreviousStep,
                kept_jacobian: None,
                contraction: None,
            },
            ev,
        ))
    }

    /// Advances by `h` seconds; `act_end` is the actuator motion at the end of the
    /// step. The accelerations kept are the converged Newton iterate, which satisfies
    /// the equations at the new state to `tolerance`.
    pub fn step(
        &mut self,
        model: &CraneModel<T, M>,
        h: T,
        act_end: ActuatorMotion<T>,
        tolerance: T,
    ) -> Result<StepStats, ModelError> {
        self.step_with_load(model, h, act_end, self.load_kg, tolerance)
    }

    /// [`Self::step`] with the hook load `load_end` at the end of the step (a
    /// lift-off): the equations at the new state carry the new load.
    pub fn step_with_load(
        &mut self,
        model: &CraneModel<T, M>,
        h: T,
        act_end: ActuatorMotion<T>,
        load_end: T,
        tolerance: T,
    ) -> Result<StepStats, ModelError> {
        self.step_to(model, h, &model.rigid_motion(act_end, load_end)?, tolerance)
    }

    /// [`Self::step_with_load`] with the end of the step's prescribed motion (the
    /// actuator's kinematics and the hook load) already computed: a caller that also
    /// samples the outputs at the end of the step computes it once for both.
    pub fn step_to(
        &mut self,
        model: &CraneModel<T, M>,
        h: T,
        rigid: &RigidMotion<T>,
        tolerance: T,
    ) -> Result<StepStats, ModelError> {
        self.advance(model, h, rigid, tolerance, None)
    }

    /// [`Self::step_to`], also writing into `sample` the equations evaluated at
    /// the end of the step, for a caller that samples the outputs there. With the
    /// reference start they are evaluated afresh at the new state (the reference
    /// numbers); with [`NewtonStart::Extrapolated`] they are the last Newton
    /// iterate's, whose state differs from the new one by the last correction
    /// (within the tolerance), paired with the converged accelerations: one
    /// evaluation fewer per sample.
    pub fn step_to_sampled(
        &mut self,
        model: &CraneModel<T, M>,
        h: T,
        rigid: &RigidMotion<T>,
        tolerance: T,
        sample: &mut Evaluation<T, M>,
    ) -> Result<StepStats, ModelError> {
        if self.newton_start == NewtonStart::Extrapolated {
            return self.advance(model, h, rigid, tolerance, Some(sample));
        }
        let stats = self.advance(model, h, rigid, tolerance, None)?;
        *sample = model.evaluate_at(rigid, &self.free)?;
        Ok(StepStats { evaluations: stats.evaluations + 1, ..stats })
    }

    fn advance(
        &mut self,
        model: &CraneModel<T, M>,
        h: T,
        rigid: &RigidMotion<T>,
        tolerance: T,
        sample: Option<&mut Evaluation<T, M>>,
    ) -> Result<StepStats, ModelError> {
        let half = T::lit(0.5);
        let quarter_h2 = h * h * T::lit(0.25);
        let (a0_eta, a0_sw) = (self.eta_accel, self.swing_accel);
        let (mut a_eta, mut a_sw) = match (self.newton_start, self.previous_accel) {
            (NewtonStart::Extrapolated, Some((p_eta, p_sw))) => {
                (a0_eta * T::lit(2.0) - p_eta, a0_sw * T::lit(2.0) - p_sw)
            }
            _ => (a0_eta, a0_sw),
        };
        let z0 = self.free;
        let eta0 = SVector::<T, M>::from_column_slice(&z0.eta);
        let v0 = SVector::<T, M>::from_column_slice(&z0.eta_rate);
        let predict = |a_eta: &SVector<T, M>, a_sw: T| {
            let eta = eta0 + v0 * h + (a0_eta + a_eta) * quarter_h2;
            let rate = v0 + (a0_eta + a_eta) * (h * half);
            let mut f = z0;
            f.eta.copy_from_slice(eta.as_slice());
            f.eta_rate.copy_from_slice(rate.as_slice());
            f.swing_rad = z0.swing_rad + z0.swing_rate * h + (a0_sw + a_sw) * quarter_h2;
            f.swing_rate = z0.swing_rate + (a0_sw + a_sw) * (h * half);
            f
        };
        let keep = self.newton_start == NewtonStart::Extrapolated;
        // The matrix lives in `kept_jacobian` (age 0: made in this step), used in
        // place: it is too large to move around every iteration.
        if !matches!(self.kept_jacobian, Some((_, kept_h, age)) if keep && kept_h == h && age < JACOBIAN_MAX_AGE) {
            self.kept_jacobian = None;
        }
        let mut cfg = model.configure(rigid, &predict(&a_eta, a_sw));
        let mut previous_correction: Option<T> = None;
        for iteration in 1..=MAX_ITERATIONS {
            if matches!(self.kept_jacobian, Some((_, _, age)) if age > 0) && iteration > STALE_JACOBIAN_ITERATIONS {
                // The kept matrix has drifted (a lift-off, a jolt): make a new one.
                self.kept_jacobian = None;
            }
            let free = predict(&a_eta, a_sw);
            // The equations at the trial state; their own solve is not needed here.
            if iteration > 1 {
                model.reconfigure(&mut cfg, &free);
            }
            let eq = model.reduced_equations(&cfg);
            // Residual of the equations at the trial accelerations.
            let r_eta = eq.mass.a * a_eta + eq.mass.b * a_sw - eq.force_eta;
            let r_sw = eq.mass.b.dot(&a_eta) + eq.mass.c * a_sw - eq.force_swing;
            if self.kept_jacobian.is_none() {
                let mut j = eq.mass;
                for k in 0..M {
                    let w = model.modes.omega_rad_s[k];
                    j.a[(k, k)] += model.modes.damping[k] * h * half + w * w * quarter_h2;
                }
                // The pendulum's gravity stiffness −∂f/∂θ5 = −Σ·g·sin θ5 (≥ 0 near hanging).
                let p = &cfg.pendulum;
                let k_swing = -p.first_moment_kg_m * model.gravity_m_s2 * free.swing_rad.sin();
                j.c += k_swing.max(T::zero()) * quarter_h2;
                // Factored once per step (or kept over steps), reused by every iteration.
                let factor = j.factor()?;
                self.kept_jacobian = Some((if keep { factor.with_inverse() } else { factor }, h, 0));
            }
            let (d_eta, d_sw) = match &self.kept_jacobian {
                Some((jac, _, _)) => jac.solve(&r_eta, r_sw)?,
                None => return Err(ModelError::Singular("Newmark iteration matrix")),
            };
            a_eta -= d_eta;
            a_sw -= d_sw;
            // Converged when the correction is small against the size of the terms
            // that make up the accelerations (gravity, ω²·η): in f32 the equilibrium
            // accelerations themselves are rounding left over from those terms.
            let mut size = a_eta.amax().max(a_sw.abs()) + model.gravity_m_s2;
            for k in 0..M {
                let w = model.modes.omega_rad_s[k];
                size += w * w * free.eta[k].abs();
            }
            let correction = d_eta.amax().max(d_sw.abs());
            // With the kept matrix the iteration contracts by θ per iteration, so
            // after a correction Δ the error left is at most θ/(1 − θ)·‖Δ‖ (Hairer
            // and Wanner's stopping rule for simplified Newton, Solving ODEs II
            // §IV.8). Once θ has been measured on this matrix, a first correction
            // that small ends the step: the second evaluation would only confirm it.
            let error_left = match (iteration, self.contraction, &self.kept_jacobian) {
                (1, Some((theta, since)), Some((_, _, age)))
                    if keep && *age > 0 && since < CONTRACTION_MAX_AGE && theta < T::lit(0.5) =>
                {
                    theta / (T::one() - theta) * correction
                }
                _ => correction,
            };
            if iteration >= 2 && keep {
                if let Some(prev) = previous_correction {
                    if prev > T::zero() {
                        self.contraction = Some((correction / prev, 0));
                    }
                }
            }
            previous_correction = Some(correction);
            if error_left <= tolerance * size {
                self.free = predict(&a_eta, a_sw);
                self.t_s += h;
                self.previous_accel = Some((a0_eta, a0_sw));
                self.eta_accel = a_eta;
                self.swing_accel = a_sw;
                self.load_kg = rigid.load_kg;
                if let Some((_, since)) = &mut self.contraction {
                    *since += 1;
                }
                // A matrix that needed more than two iterations is not kept.
                match &mut self.kept_jacobian {
                    Some((_, _, age)) if keep && (*age == 0 || iteration <= 2) => *age += 1,
                    _ => self.kept_jacobian = None,
                }
                if let Some(ev) = sample {
                    ev.config = cfg;
                    ev.equations = eq;
                    ev.eta_accel = a_eta;
                    ev.swing_accel = a_sw;
                }
                return Ok(StepStats { iterations: iteration, evaluations: iteration });
            }
        }
        Err(ModelError::NoConvergence("Newmark step"))
    }
}
