//! A load added at rest while the load still swings from a move, seen at
//! once: the common jump of every rope hypothesis's weighing
//! ([`crate::static_load`]'s bank).
//!
//! ## Why the bank alone is slow at it
//!
//! After a move stops nothing damps the swings the bank predicts, so the
//! wrong ropes keep reading the load high and low: W_fast = S(min_k W_k)
//! reads low, and the reading rests on the slow averages W̄_k (two 3 s
//! stages) and the move's weighing held at rest. A load added then was
//! followed at the averages' pace: 1.4–6 s, or not within 7 s.
//!
//! ## What a change of the load does to the bank
//!
//! Every hypothesis solves the same force for its own load,
//! F_W(W_k)·f_k(t) = F − F_0 (f_k its factor, which depends on the boom's
//! motion only). With the true rope's factor f* and the true load W,
//! F_W(W_k) = F_W(W)·f*/f_k: a change of the load multiplies every F_W(W_k)
//! by the same ratio at the same instant (every W_k, for the model's linear
//! part), while the phantom ratio f*/f_k of a wrong rope changes only at
//! the pendulums' periods (3.5–9.5 s). The true rope's W_k is constant
//! while the load is. So each hypothesis k keeps
//!
//! - its own fast stage S_k(W_k) (one first-order stage at
//!   [`crate::static_load::FAST_SMOOTHING_HZ`], against the load's bounce),
//! - its ratio to its own slow average, ρ_k = S_k(W_k)/W̄_k: 1 for the true
//!   rope while the load is constant, the load's ratio W_new/W_old for every
//!   rope right after a change,
//! - its inconsistency D_k: |ρ_k − 1| through one first-order stage of
//!   [`CONSISTENCY_TAU_S`]: near 0 for the true rope (noise, bounce, the
//!   grid's mismatch), large for a wrong rope whose phantom swings.
//!
//! A rope *votes* while it weighs now, its average W̄_k is at least
//! [`MIN_AVERAGE_KG`] (below, the ratio of two small readings is the
//! sensor's noise) and D_k ≤ min(CONSISTENT, 2·D_min + CONSISTENT_MARGIN),
//! D_min the lowest D_k of the ropes that weigh ([`bar`]): the ropes as
//! consistent as the most consistent one, and none beyond [`CONSISTENT`].
//! The common ratio is the lowest of the voters',
//!
//! ρ = min_{voters} ρ_k,
//!
//! which is no more than the true rope's ratio whenever the true rope
//! votes, so no more than the load's ratio: ρ reads a change of the load,
//! never more. D_k is a ratio of a hypothesis's readings, the same for any
//! load, so which ropes vote does not depend on the load's size (a choice
//! made from the size of the W_k would flip with the load). A hypothesis
//! whose average starts afresh starts with D_k = [`CONSISTENT`]: its
//! average starts at or above W_k, so its first ratios are ≤ 1 and can
//! only lower ρ.
//!
//! ## The rescale
//!
//! At rest after a move of at least
//! [`crate::static_load::MOVE_FOR_HOLD_S`] (and while the ropes disagree:
//! when all agree the averages are W_fast already), when ρ ≥ 1 + [`JUMP`]
//! and every voter's reading has risen above its average by at least
//! [`MIN_JUMP_KG`] the bank takes it as a heavier load and, for [`FOLLOW_S`] from then on
//! (the force filter's 0.53 s delay and the fast stages' step response),
//! every cycle
//!
//! W̄_k ← ρ·W̄_k (every stage of every average),
//! W_hold ← max(ρ·W_hold, min_{voters} S_k(W_k)),
//!
//! with ρ taken as 1 when below it and at most [`MAX_STEP`] (a guard):
//! the averages become what they would have been had the new load always
//! hung there (they are linear in the load), the true rope's ρ_k returns to
//! 1 and it keeps voting, and the held weighing (the move's, read ×0.96–1.0
//! of the old load) reads the new load as the voters read it. The reading,
//! max(W_fast, W_slow) or the held weighing, rises within the force
//! filter's and the fast stages' response: a 3 t → 4 t step on the bank's
//! own ropes reads ≥ 97.5 % in 0.52–0.71 s; in the simulator (`host-sim` test
//! `a_load_added_at_rest_after_a_move_*`) 1/1.1 of a load taken up over
//! 0.5 s is read within 0.81 s of the take-up's end (0.93 s when the bank
//! read the force through the sensor's lag at rest).
//!
//! It only ever multiplies by ρ > 1 and raises the held weighing: it raises
//! the reading and lowers nothing, so it delays no overload. A load set
//! down (lighter) is followed at the averages' pace as before (that errs
//! toward cutting). [`JUMP`] and [`MIN_JUMP_KG`] are above the load's
//! bounce as the fast stages pass it (1–2 Hz near rated load, ±25 % of the
//! load's pull after a 10 s move stops in a held rope: ±1.5–9 % through the
//! force filter, ±0.5–5 % through S_k) and the sensors' noise on a light
//! load, so neither starts a rescale; once started, the follow window may
//! take in a bounce's crest (≤ 5 % high), which the averages lose at their
//! pace and the hold keeps until it ends. A heavier load by less than
//! [`JUMP`] or [`MIN_JUMP_KG`], one added to a hook that was (nearly)
//! empty, or one added while no rope votes (a short rope stopped at 60–80°,
//! a rope between the grid's lengths at 80°: the nearest hypotheses drift
//! out of phase with the true swing) is followed at the averages' pace as
//! before.
//! A wider bar (D_k ≤ 0.06) let wrong ropes vote and read 90 % of rated as
//! an OVERLOAD in the simulator; hence [`CONSISTENT`].
//!
//! The cost: per hypothesis two first-order stages and one division per
//! cycle, and the rescale's multiplications during [`FOLLOW_S`]; no heap,
//! fixed loops.

use crane_model::Real;

/// Smallest common ratio ρ that starts a rescale (a load heavier by 10 %).
pub const JUMP: f64 = 0.10;

/// Largest inconsistency D_k of a rope that votes for the common ratio.
pub const CONSISTENT: f64 = 0.03;

/// How much more inconsistent than the most consistent rope a rope may be
/// and still vote: D_k ≤ 2·D_min + this.
pub const CONSISTENT_MARGIN: f64 = 0.005;

/// The bar a rope's D_k must meet to vote, given the lowest D_min of the
/// ropes that weigh: min(CONSISTENT, 2·D_min + CONSISTENT_MARGIN).
pub fn bar<T: Real>(d_min: T) -> T {
    (T::lit(2.0) * d_min + T::lit(CONSISTENT_MARGIN)).min(T::lit(CONSISTENT))
}

/// Smallest slow average W̄_k that votes (kg): below it (an empty hook, a
/// light one) the ratio of two small readings is the sensor's noise.
pub const MIN_AVERAGE_KG: f64 = 500.0;

/// Smallest rise S_k(W_k) − W̄_k of every voter that starts a rescale (kg):
/// the sensors' noise on a light load (0.55–0.85 t in the 10 000-scenario
/// campaign) made ρ ≥ 1.1 from rises of 75–110 kg.
pub const MIN_JUMP_KG: f64 = 300.0;

/// Largest rescale in one cycle (a guard; S_k's stage at 0.7 Hz rises by
/// less than 5 % of the step a cycle at 100 Hz).
pub const MAX_STEP: f64 = 1.5;

/// Time constant of the inconsistency's stage (s): a wrong rope's phantom
/// swing (periods 3.5–9.5 s) shows within it.
pub const CONSISTENCY_TAU_S: f64 = 1.0;

/// How long after a rescale starts the bank keeps rescaling (s): the
/// force filter's delay (0.53 s) and the fast stages' step response (99 %
/// in 1 s) after a take-up of up to 0.5 s.
pub const FOLLOW_S: f64 = 2.0;

/// One hypothesis's consistency with a constant load (see the module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Consistency<T> {
    /// S_k(W_k) (kg); `None` until the hypothesis weighs.
    pub(crate) fast_kg: Option<T>,
    /// D_k.
    pub(crate) inconsistency: T,
}

impl<T: Real> Default for Consistency<T> {
    fn default() -> Self {
        Self::new()
    }
}

impl<T: Real> Consistency<T> {
    /// A hypothesis that has not weighed yet: D_k = [`CONSISTENT`], the
    /// most a voter may have (a wrong rope's swing drives its D_k up within
    /// [`CONSISTENCY_TAU_S`]).
    pub fn new() -> Self {
        Self { fast_kg: None, inconsistency: T::lit(CONSISTENT) }
    }

    /// A hypothesis that starts weighing with W_k = `w_kg` while its W̄_k
    /// starts at `start_kg` (the bank's weighing: a rope that becomes usable
    /// in motion has not followed the swing, and its W_k of that instant is
    /// no weighing). Its D_k starts at |W_k/W̄_k − 1|, and no lower than
    /// [`CONSISTENT`]: a rope that reads what the bank weighed may vote at
    /// once, one that reads otherwise only once its ratio has settled
    /// (voting at once, a rope restarted at rest at 80° and reading 1.3 ×
    /// the bank's weighing raised the reading to 2.2 × the load).
    pub fn starting(w_kg: T, start_kg: T) -> Self {
        let d = (w_kg / start_kg - T::lit(1.0)).abs();
        let inconsistency = if d.is_finite() { d.max(T::lit(CONSISTENT)) } else { T::lit(1.0) };
        Self { fast_kg: None, inconsistency }
    }

    /// Passes W_k (kg) through S_k with the stage's `gain`; returns S_k(W_k).
    pub fn smooth(&mut self, w_kg: T, gain: T) -> T {
        let s = match self.fast_kg {
            Some(y) => y + gain * (w_kg - y),
            None => w_kg,
        };
        self.fast_kg = Some(s);
        s
    }

    /// ρ_k = S_k(W_k)/W̄_k against the slow average `average_kg`; `None`
    /// before the hypothesis weighs or for an average that is not positive.
    pub fn ratio(&self, average_kg: T) -> Option<T> {
        let r = self.fast_kg? / average_kg;
        (average_kg > T::lit(0.0) && r.is_finite()).then_some(r)
    }

    /// Passes |ρ_k − 1| through the inconsistency's stage (`gain`).
    pub fn settle(&mut self, ratio: T, gain: T) {
        let d = (ratio - T::lit(1.0)).abs();
        self.inconsistency += gain * (d - self.inconsistency);
        if !self.inconsistency.is_finite() {
            self.inconsistency = T::lit(1.0);
        }
    }

    /// S_k(W_k) (kg); `None` before the hypothesis weighs.
    pub fn fast_kg(&self) -> Option<T> {
        self.fast_kg
    }

    /// D_k.
    pub fn inconsistency(&self) -> T {
        self.inconsistency
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::filter::stage_gain;

    #[test]
    fn a_constant_weighing_becomes_consistent_and_a_swinging_one_does_not() {
        let (mut steady, mut swinging) = (Consistency::<f64>::new(), Consistency::<f64>::new());
        let (g_fast, g_dev) = (stage_gain(0.01 * 2.0 * core::f64::consts::PI * 0.7), stage_gain(0.01 / CONSISTENCY_TAU_S));
        for k in 0..1000 {
            let t = f64::from(k) * 0.01;
            steady.smooth(3000.0, g_fast);
            steady.settle(steady.ratio(3000.0).unwrap(), g_dev);
            // A phantom swing of ±10 % at a 3 m rope's period (3.5 s).
            swinging.smooth(3000.0 * (1.0 + 0.1 * (t * 1.8).sin()), g_fast);
            swinging.settle(swinging.ratio(3000.0).unwrap(), g_dev);
        }
        assert!(steady.inconsistency() <= bar(0.0));
        assert!(swinging.inconsistency() > CONSISTENT);
        assert!(swinging.ratio(0.0).is_none());
    }
}
