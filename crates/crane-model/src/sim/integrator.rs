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
//! * The dependent coordinates are never integrated: they follow from the actuator
//!   and the modes in closed form (`mechanism`), so the position-level constraints
//!   hold to rounding at every step; there is no drift to stabilize.

use crate::multibody::dynamics::Evaluation;
use crate::multibody::{CraneModel, FreeCoordinates};
use crate::data::profile::ActuatorMotion;
use crate::{ModelError, Real};
use nalgebra::SVector;

/// Most Newton iterations per step.
pub const MAX_ITERATIONS: usize = 12;

/// The integrator's state: free coordinates, their accelerations and the time.
#[derive(Debug, Clone, Copy, PartialEq)]
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
}

/// Statistics of one step.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct StepStats {
    /// Newton iterations used (= evaluations of the equations).
    pub iterations: usize,
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
        let half = T::lit(0.5);
        let quarter_h2 = h * h * T::lit(0.25);
        let t1 = self.t_s + h;
        let z0 = self.free;
        let (a0_eta, a0_sw) = (self.eta_accel, self.swing_accel);
        let (mut a_eta, mut a_sw) = (a0_eta, a0_sw);
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
        let rigid = model.rigid_motion(act_end, load_end)?;
        let mut jacobian = None;
        for iteration in 1..=MAX_ITERATIONS {
            let free = predict(&a_eta, a_sw);
            // The equations at the trial state; their own solve is not needed here.
            let cfg = model.configure(&rigid, &free);
            let eq = model.reduced_equations(&cfg);
            // Residual of the equations at the trial accelerations.
            let r_eta = eq.mass.a * a_eta + eq.mass.b * a_sw - eq.force_eta;
            let r_sw = eq.mass.b.dot(&a_eta) + eq.mass.c * a_sw - eq.force_swing;
            let jac = match jacobian {
                Some(j) => j,
                None => {
                    let mut j = eq.mass;
                    for k in 0..M {
                        let w = model.modes.omega_rad_s[k];
                        j.a[(k, k)] += model.modes.damping[k] * h * half + w * w * quarter_h2;
                    }
                    // The pendulum's gravity stiffness −∂f/∂θ5 = −Σ·g·sin θ5 (≥ 0 near hanging).
                    let p = &cfg.pendulum;
                    let k_swing = -p.first_moment_kg_m * model.gravity_m_s2 * free.swing_rad.sin();
                    j.c += k_swing.max(T::zero()) * quarter_h2;
                    // Factored once per step, reused by every iteration.
                    let f = j.factor()?;
                    jacobian = Some(f);
                    f
                }
            };
            let (d_eta, d_sw) = jac.solve(&r_eta, r_sw)?;
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
            if d_eta.amax().max(d_sw.abs()) <= tolerance * size {
                let free = predict(&a_eta, a_sw);
                *self = State {
                    t_s: t1,
                    free,
                    eta_accel: a_eta,
                    swing_accel: a_sw,
                    load_kg: load_end,
                };
                return Ok(StepStats {
                    iterations: iteration,
                });
            }
        }
        Err(ModelError::NoConvergence("Newmark step"))
    }
}
