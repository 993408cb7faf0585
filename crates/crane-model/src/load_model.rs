//! The seam between the crane model and the limiter.
//!
//! At a given boom state the model's Lagrange multipliers are affine in the hook
//! load W: the piston force (multiplier of the prescribed-motion constraint) and the
//! rear-jack reaction F_A (thesis eq. 4.2, from the ground-joint multipliers). The
//! limiter inverts the first to estimate W and divides with the second to get the
//! tipping load. Both are exposed through [`HookLoadModel`] so the limiter can be
//! tested against simple stand-ins and run the real model on the controller.

/// A quantity that is affine in the hook load: `value(W) = at_zero + per_kg · W`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Affine<T> {
    /// Value with no hook load (W = 0 kg).
    pub at_zero: T,
    /// Change per kilogram of hook load.
    pub per_kg: T,
}

impl<T: Copy + core::ops::Add<Output = T> + core::ops::Mul<Output = T>> Affine<T> {
    /// Evaluates the affine map at hook load `load_kg`.
    pub fn at(&self, load_kg: T) -> T {
        self.at_zero + self.per_kg * load_kg
    }
}

/// A quantity quadratic in the hook load:
/// `value(W) = at_zero + per_kg · W + per_kg2 · W²`.
///
/// The piston force at rest is one: the boom's static sag grows with W and
/// moves the load's arm, so the force is not quite affine in W (the secant
/// through 0 and 20 t misreads 3.3 t by −2.4 % at 80°). The quadratic is
/// exact for the quasi-static model ([`crate::tipping`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Quadratic<T> {
    /// Value with no hook load (W = 0 kg).
    pub at_zero: T,
    /// Slope at W = 0 (per kg).
    pub per_kg: T,
    /// Curvature term (per kg²).
    pub per_kg2: T,
}

impl<T: crate::Real> Quadratic<T> {
    /// An affine map as a quadratic (no curvature).
    pub fn linear(a: Affine<T>) -> Self {
        Self { at_zero: a.at_zero, per_kg: a.per_kg, per_kg2: T::zero() }
    }

    /// Evaluates at hook load `load_kg`.
    pub fn at(&self, load_kg: T) -> T {
        self.at_zero + (self.per_kg + self.per_kg2 * load_kg) * load_kg
    }

    /// Multiplies the load-dependent part by `factor` (the value at W = 0
    /// stays): how a swinging load's horizontal pull scales it.
    pub fn scale_load_part(&self, factor: T) -> Self {
        Self { at_zero: self.at_zero, per_kg: self.per_kg * factor, per_kg2: self.per_kg2 * factor }
    }

    /// The load W at which the value is `value`, on the branch through W = 0
    /// that rises with W: W = 2d / (b + √(b² + 4·c·d)), d = value − at_zero
    /// (the form without cancellation when c is small). `None` when the slope
    /// at W = 0 is not positive or no load on that branch gives `value`.
    pub fn solve(&self, value: T) -> Option<T> {
        let (b, c) = (self.per_kg, self.per_kg2);
        let d = value - self.at_zero;
        let disc = b * b + T::lit(4.0) * c * d;
        if !(b > T::zero() && disc >= T::zero()) {
            return None;
        }
        let w = T::lit(2.0) * d / (b + disc.sqrt());
        w.is_finite().then_some(w)
    }
}

/// The boom state the limiter measures: angle from horizontal and its rate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoomState<T> {
    /// Boom angle θ1 from horizontal (rad).
    pub angle_rad: T,
    /// Boom angular velocity dθ1/dt (rad/s), positive when raising.
    pub rate_rad_s: T,
}

/// What the limiter needs from a crane model (thesis §4.2–4.3).
pub trait HookLoadModel<T> {
    /// Piston force of the luffing cylinder (N, positive when it pushes the boom
    /// up) as a function of the hook load at the given boom state: affine for a
    /// fixed state (a Lagrange multiplier), quadratic when the boom's sag is
    /// allowed to grow with the load ([`Quadratic`]).
    fn piston_force_n(&self, boom: BoomState<T>) -> Result<Quadratic<T>, crate::ModelError>;
    /// Piston force (N) per unit angular acceleration of the boom (rad/s²) at
    /// boom angle θ1, hook load excluded: the mechanism's inertia reduced to θ1,
    /// seen through the cylinder's lever da/dθ1 (virtual work: F·δa = M·δθ1).
    /// The load hangs from a rope and is not carried along by the boom's
    /// acceleration: its horizontal pull is the swing's, and the hoist holds it
    /// at its height. The limiter subtracts this times the measured
    /// acceleration from the force before it solves for W (in the acceleration
    /// ramps the measured force carries the boom's inertia).
    fn piston_force_per_boom_accel(&self, boom_angle_rad: T) -> Result<T, crate::ModelError>;
    /// Ground reaction on the rear jack F_A (N, thesis eq. 4.2) as an affine
    /// function of the hook load; the crane tips when it reaches zero.
    fn jack_reaction_n(&self, boom: BoomState<T>) -> Result<Affine<T>, crate::ModelError>;
    /// Hook radius R (m) at boom angle θ1: R = 19.5·cos θ1 − 1.83 (thesis eq. 4.3).
    fn radius_m(&self, boom_angle_rad: T) -> T;
}
