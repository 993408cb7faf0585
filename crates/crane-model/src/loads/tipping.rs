//! Tipping and lifting capacity (thesis §4.3.2, eqs. 4.2–4.3).
//!
//! At a given state (positions, velocities, accelerations of the free coordinates)
//! the hook load W enters the equations linearly (masses and weight of body 5), so
//! every Lagrange multiplier, the piston force and the rear-jack reaction F_A are
//! affine in W: two evaluations give them exactly ([`CraneModel::affine_at`]).
//!
//! At rest the boom's static deflection itself grows with W, which makes F_A a
//! quadratic in W (the load's arm grows with the tip's sag). The quasi-static
//! tipping load is its root, from three evaluations, in closed form
//! ([`CraneModel::tipping_load_at_rest`]); no search.

use crate::multibody::dynamics::Reactions;
use crate::loads::load_model::{Affine, BoomState, HookLoadModel, Quadratic};
use crate::multibody::{CraneModel, FreeCoordinates};
use crate::data::profile::ActuatorMotion;
use crate::{ModelError, Real};
use nalgebra::SVector;

/// Default safety factor on the tipping load (thesis §4.3.2).
pub const SAFETY_FACTOR: f64 = 1.5;

/// The tipping load at a boom angle, at rest.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TippingPoint<T> {
    /// Boom angle θ1 (rad).
    pub boom_angle_rad: T,
    /// Hook radius R (m, eq. 4.3).
    pub radius_m: T,
    /// Hook load at which F_A = 0 (kg); infinite if the crane cannot tip here.
    pub tipping_load_kg: T,
    /// F_A with no hook load (N).
    pub jack_reaction_unloaded_n: T,
}

impl<T: Real, const M: usize> CraneModel<T, M> {
    /// Reactions at a quasi-static state: boom at angle θ1 turning at `rate`, the
    /// free coordinates `free` held with zero acceleration, hook load `load_kg`.
    pub fn quasi_static_reactions(&self, boom: BoomState<T>, load_kg: T, free: &FreeCoordinates<T, M>) -> Result<Reactions<T>, ModelError> {
        let act = self.actuator_at(boom.angle_rad, boom.rate_rad_s);
        let mut ev = self.evaluate(act, load_kg, free)?;
        ev.eta_accel = SVector::zeros();
        ev.swing_accel = T::zero();
        let (_, lambda) = self.multipliers(&ev)?;
        Ok(self.reactions(&lambda))
    }

    /// Piston force and F_A as affine functions of W at a fixed state (two evaluations).
    pub fn affine_at(&self, boom: BoomState<T>, free: &FreeCoordinates<T, M>) -> Result<(Affine<T>, Affine<T>), ModelError> {
        let r0 = self.quasi_static_reactions(boom, T::zero(), free)?;
        let r1 = self.quasi_static_reactions(boom, T::one(), free)?;
        Ok((
            Affine { at_zero: r0.piston_force_n, per_kg: r1.piston_force_n - r0.piston_force_n },
            Affine { at_zero: r0.jack_reaction_n, per_kg: r1.jack_reaction_n - r0.jack_reaction_n },
        ))
    }

    /// Reactions at rest at angle θ1 under load W, with the boom at its static
    /// deflection for that load (the quasi-static lifting-capacity state).
    pub fn reactions_at_rest(&self, boom_angle_rad: T, load_kg: T) -> Result<Reactions<T>, ModelError> {
        let free = self.equilibrium_state(boom_angle_rad, load_kg)?;
        self.quasi_static_reactions(BoomState { angle_rad: boom_angle_rad, rate_rad_s: T::zero() }, load_kg, &free)
    }

    /// The hook load that makes F_A = 0 at rest at angle θ1: the root of the exact
    /// quadratic F_A(W) = a + b·W + c·W², from F_A at W = 0, W1, 2·W1.
    pub fn tipping_load_at_rest(&self, boom_angle_rad: T) -> Result<TippingPoint<T>, ModelError> {
        let w1 = T::lit(5000.0);
        let f0 = self.reactions_at_rest(boom_angle_rad, T::zero())?.jack_reaction_n;
        let f1 = self.reactions_at_rest(boom_angle_rad, w1)?.jack_reaction_n;
        let f2 = self.reactions_at_rest(boom_angle_rad, w1 + w1)?.jack_reaction_n;
        let two = T::lit(2.0);
        let c = (f2 - two * f1 + f0) / (two * w1 * w1);
        let b = (f1 - f0) / w1 - c * w1;
        let a = f0;
        let radius_m = T::lit(self.crane.boom.length_m()) * boom_angle_rad.cos() - T::lit(self.crane.chassis.radius_offset_m);
        let tipping_load_kg = smallest_positive_root(a, b, c).unwrap_or_else(|| T::max_value().unwrap_or_else(T::one));
        Ok(TippingPoint { boom_angle_rad, radius_m, tipping_load_kg, jack_reaction_unloaded_n: f0 })
    }
}

/// Smallest positive root of a + b·W + c·W² ([`Quadratic::smallest_positive_root`]).
fn smallest_positive_root<T: Real>(a: T, b: T, c: T) -> Option<T> {
    Quadratic { at_zero: a, per_kg: b, per_kg2: c }.smallest_positive_root()
}

/// Piston force and F_A at rest as exact quadratics in W, from three evaluations.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadResponses<T> {
    /// Piston force (N): the exact quadratic in W.
    pub piston_force: Quadratic<T>,
    /// F_A (N) as an affine map: secant through W = 0 and the tipping load, so its
    /// root is the exact quasi-static tipping load.
    pub jack_reaction: Affine<T>,
    /// The quasi-static tipping load (kg); `T::max_value()` if the crane cannot tip.
    pub tipping_load_kg: T,
}

impl<T: Real, const M: usize> CraneModel<T, M> {
    /// What the limiter needs at a boom state, from three evaluations of the
    /// multipliers at W = 0, W1 and 2·W1 with the boom at its static deflection for
    /// each load: F_A(W) and F(W) are exact quadratics there (the sag grows with W),
    /// so the tipping load is the root of F_A's, F_A is returned as its secant
    /// through W = 0 and the tipping load (exact where the crane tips), and F as the
    /// quadratic itself (the limiter solves it for W).
    pub fn load_responses(&self, boom: BoomState<T>) -> Result<LoadResponses<T>, ModelError> {
        let w1 = T::lit(5000.0);
        let two = T::lit(2.0);
        // The mechanism is the same for every load: compute it (and its
        // trigonometry) once, then only the pendulum's masses change.
        let rigid0 = self.rigid_motion(self.actuator_at(boom.angle_rad, boom.rate_rad_s), T::zero())?;
        let at = |w: T| -> Result<Reactions<T>, ModelError> {
            let rigid = self.with_load(&rigid0, w)?;
            let free = self.equilibrium_state_at(&rigid);
            let mut ev = self.evaluate_at(&rigid, &free)?;
            ev.eta_accel = SVector::zeros();
            ev.swing_accel = T::zero();
            let (_, lambda) = self.multipliers(&ev)?;
            Ok(self.reactions(&lambda))
        };
        let (r0, r1, r2) = (at(T::zero())?, at(w1)?, at(w1 + w1)?);
        let quad = |f0: T, f1: T, f2: T| {
            let c = (f2 - two * f1 + f0) / (two * w1 * w1);
            (f0, (f1 - f0) / w1 - c * w1, c)
        };
        let (fa, fb, fc) = quad(r0.jack_reaction_n, r1.jack_reaction_n, r2.jack_reaction_n);
        let (pa, pb, pc) = quad(r0.piston_force_n, r1.piston_force_n, r2.piston_force_n);
        let huge = T::max_value().unwrap_or_else(T::one);
        let jack = Quadratic { at_zero: fa, per_kg: fb, per_kg2: fc };
        let tipping = jack.smallest_positive_root().unwrap_or(huge);
        let jack_reaction = jack.tipping_secant();
        let piston_force = Quadratic { at_zero: pa, per_kg: pb, per_kg2: pc };
        Ok(LoadResponses { piston_force, jack_reaction, tipping_load_kg: tipping })
    }
}

impl<T: Real, const M: usize> HookLoadModel<T> for CraneModel<T, M> {
    /// See [`CraneModel::load_responses`].
    fn piston_force_n(&self, boom: BoomState<T>) -> Result<Quadratic<T>, ModelError> {
        Ok(self.load_responses(boom)?.piston_force)
    }

    /// See [`CraneModel::load_responses`].
    fn jack_reaction_n(&self, boom: BoomState<T>) -> Result<Affine<T>, ModelError> {
        Ok(self.load_responses(boom)?.jack_reaction)
    }

    /// J/(da/dθ1), J the mechanism's inertia reduced to θ1: twice its kinetic
    /// energy with the boom turning at 1 rad/s (undeformed boom about A0, and the
    /// lug, rod and cylinder-with-oil at the velocities the mechanism gives them).
    fn piston_force_per_boom_accel(&self, boom_angle_rad: T) -> Result<T, ModelError> {
        let lever = self.geometry.extension_per_radian(boom_angle_rad);
        let act = ActuatorMotion {
            extension_m: self.geometry.extension_at_angle(boom_angle_rad),
            rate_m_s: lever,
            accel_m_s2: T::zero(),
        };
        let mech = self.geometry.motion(act)?;
        let cylinder = self.cylinder.at_extension(act.extension_m)?;
        let two = T::lit(2.0);
        let mut j = self.modes.inertia_rest;
        for (b, m) in [(&mech.lug, self.lug), (&mech.rod, self.rod), (&mech.cylinder, cylinder)] {
            let w = b.angular_velocity;
            j += m.mass_kg * b.velocity.norm_squared()
                + two * m.first_moment_kg_m * w * b.normal().dot(&b.velocity)
                + m.inertia_kg_m2 * w * w;
        }
        let per_accel = j / lever;
        if lever > T::zero() && per_accel.is_finite() {
            Ok(per_accel)
        } else {
            Err(ModelError::OutOfReach)
        }
    }

    fn radius_m(&self, boom_angle_rad: T) -> T {
        T::lit(self.crane.boom.length_m()) * boom_angle_rad.cos() - T::lit(self.crane.chassis.radius_offset_m)
    }
}

/// The crane model with a one-entry cache, for the limiter: it asks for the piston
/// force and the jack reaction at the same boom state every cycle, and both come
/// from the same three evaluations.
#[derive(Debug, Clone)]
pub struct CachedLoadModel<T: Real, const M: usize> {
    model: CraneModel<T, M>,
    last: core::cell::Cell<Option<(BoomState<T>, LoadResponses<T>)>>,
}

impl<T: Real, const M: usize> CachedLoadModel<T, M> {
    /// Wraps a model.
    pub fn new(model: CraneModel<T, M>) -> Self {
        CachedLoadModel { model, last: core::cell::Cell::new(None) }
    }

    /// The wrapped model.
    pub fn model(&self) -> &CraneModel<T, M> {
        &self.model
    }

    fn responses(&self, boom: BoomState<T>) -> Result<LoadResponses<T>, ModelError> {
        if let Some((b, r)) = self.last.get() {
            if b == boom {
                return Ok(r);
            }
        }
        let r = self.model.load_responses(boom)?;
        self.last.set(Some((boom, r)));
        Ok(r)
    }
}

impl<T: Real, const M: usize> HookLoadModel<T> for CachedLoadModel<T, M> {
    fn piston_force_n(&self, boom: BoomState<T>) -> Result<Quadratic<T>, ModelError> {
        Ok(self.responses(boom)?.piston_force)
    }

    fn jack_reaction_n(&self, boom: BoomState<T>) -> Result<Affine<T>, ModelError> {
        Ok(self.responses(boom)?.jack_reaction)
    }

    fn piston_force_per_boom_accel(&self, boom_angle_rad: T) -> Result<T, ModelError> {
        self.model.piston_force_per_boom_accel(boom_angle_rad)
    }

    fn radius_m(&self, boom_angle_rad: T) -> T {
        self.model.radius_m(boom_angle_rad)
    }
}
