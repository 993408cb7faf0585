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
/// exact for the quasi-static model ([`crate::loads::tipping`]).
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
        let w = T::lit(2.0) * d / (b + disc.sqrt_ieee());
        w.is_finite().then_some(w)
    }

    /// The smallest positive W with value(W) = 0 (numerically stable form;
    /// one division when the curvature is negligible), `None` if there is none.
    pub fn smallest_positive_root(&self) -> Option<T> {
        let (a, b, c) = (self.at_zero, self.per_kg, self.per_kg2);
        // Negligible curvature: one division. (This test once also took
        // |c| ≤ ε·(|a| + |b|) as negligible; in f32 that threw away F_A's
        // curvature, −1.6e-5 N/kg² against ε·1.1e5 N = 0.013, and
        // overestimated the tipping load at 57° by 3 %. The quadratic branch
        // below is stable for any c ≠ 0: a vanishing q or c gives a
        // non-finite root, which is skipped.)
        if c.abs() * T::lit(1e8) <= b.abs() {
            let r = -a / b;
            return if r > T::zero() && r.is_finite() { Some(r) } else { None };
        }
        let disc = b * b - T::lit(4.0) * a * c;
        if disc < T::zero() {
            return None;
        }
        let q = -(b + b.signum() * disc.sqrt_ieee()) * T::lit(0.5);
        let (r1, r2) = (q / c, a / q);
        let mut best: Option<T> = None;
        for r in [r1, r2] {
            if r > T::zero() && r.is_finite() && best.is_none_or(|b| r < b) {
                best = Some(r);
            }
        }
        best
    }

    /// F_A(W) as the limiter's rating takes it: the secant through W = 0 and
    /// the smallest positive root (the tipping load; exact where the crane
    /// tips), or, when no load tips the crane, the slope at W = 0 (≥ 0 there).
    pub fn tipping_secant(&self) -> Affine<T> {
        match self.smallest_positive_root() {
            Some(tip) if tip < T::lit(1e9) => Affine { at_zero: self.at_zero, per_kg: -self.at_zero / tip },
            _ => Affine { at_zero: self.at_zero, per_kg: self.per_kg },
        }
    }

    /// The sum of two quadratics, term by term.
    pub fn plus(&self, other: &Self) -> Self {
        Self { at_zero: self.at_zero + other.at_zero, per_kg: self.per_kg + other.per_kg, per_kg2: self.per_kg2 + other.per_kg2 }
    }

    /// Every term times `factor`.
    pub fn scaled(&self, factor: T) -> Self {
        Self { at_zero: self.at_zero * factor, per_kg: self.per_kg * factor, per_kg2: self.per_kg2 * factor }
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

/// The states one control cycle asks the model at.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CycleQuery<T> {
    /// Boom angle θ1 (rad) at the instant of the filtered piston force: the
    /// load estimate's state (the model at rest there, see
    /// `moment_limiter::load_estimate`).
    pub force_angle_rad: T,
    /// The boom state now (angle and rate): the rating's.
    pub now: BoomState<T>,
}

/// The load estimate's terms, at [`CycleQuery::force_angle_rad`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadTerms<T> {
    /// Piston force at rest (N) as a function of W.
    pub piston_force: Quadratic<T>,
    /// [`HookLoadModel::piston_force_per_boom_accel`] (N·s²/rad).
    pub piston_force_per_boom_accel: T,
    /// tan θ1 (the swing correction's factor).
    pub tan_angle: T,
}

/// The rating's terms, at [`CycleQuery::now`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CapacityTerms<T> {
    /// F_A (N) as [`HookLoadModel::jack_reaction_n`] gives it: affine in W,
    /// the root being the tipping load at this state.
    pub jack_reaction: Affine<T>,
    /// Hook radius R (m, eq. 4.3).
    pub radius_m: T,
}

/// Everything one control cycle needs from the model, from one query
/// ([`HookLoadModel::cycle_terms`]). Each part carries its own result so a
/// fault names the stage that could not be served, as before the seam had
/// one entry. A new term the limiter needs is one more field here.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CycleTerms<T> {
    /// The load estimate's terms.
    pub load: Result<LoadTerms<T>, crate::ModelError>,
    /// The rating's terms.
    pub capacity: Result<CapacityTerms<T>, crate::ModelError>,
}

/// What the limiter needs from a crane model (thesis §4.2–4.3).
///
/// The control cycle asks once, through [`cycle_terms`](Self::cycle_terms);
/// the other methods are the same quantities one at a time (calibration,
/// charts, tests). The controller's implementation is the table of
/// [`crate::loads::load_table`]; the full multibody model ([`crate::multibody::CraneModel`])
/// implements it too, on the host.
pub trait HookLoadModel<T> {
    /// The one query of a control cycle: the load estimate's terms at rest at
    /// `query.force_angle_rad`, the rating's at `query.now`. The default asks
    /// the methods below one by one.
    fn cycle_terms(&self, query: CycleQuery<T>) -> CycleTerms<T>
    where
        T: crate::Real,
    {
        let angle = query.force_angle_rad;
        let at_rest = BoomState { angle_rad: angle, rate_rad_s: T::zero() };
        let load = self.piston_force_n(at_rest).and_then(|piston_force| {
            Ok(LoadTerms {
                piston_force,
                piston_force_per_boom_accel: self.piston_force_per_boom_accel(angle)?,
                tan_angle: angle.tan(),
            })
        });
        let capacity = self
            .jack_reaction_n(query.now)
            .map(|jack_reaction| CapacityTerms { jack_reaction, radius_m: self.radius_m(query.now.angle_rad) });
        CycleTerms { load, capacity }
    }

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
