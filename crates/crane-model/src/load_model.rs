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
    /// up) as an affine function of the hook load, at the given boom state.
    fn piston_force_n(&self, boom: BoomState<T>) -> Result<Affine<T>, crate::ModelError>;
    /// Ground reaction on the rear jack F_A (N, thesis eq. 4.2) as an affine
    /// function of the hook load; the crane tips when it reaches zero.
    fn jack_reaction_n(&self, boom: BoomState<T>) -> Result<Affine<T>, crate::ModelError>;
    /// Hook radius R (m) at boom angle θ1: R = 19.5·cos θ1 − 1.83 (thesis eq. 4.3).
    fn radius_m(&self, boom_angle_rad: T) -> T;
}
