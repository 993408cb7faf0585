//! A load added in motion, seen as it rises: the consistent ropes' common
//! rise over what they read a second earlier ([`crate::static_load`]'s
//! bank).
//!
//! ## Why the bank alone is slow at it
//!
//! In motion the bank reads max(W_fast, W_slow): W_fast = S(min_k W_k), the
//! lowest rope's reading, and W_slow = min_k W̄_k, the ropes' slow averages
//! (two 3 s stages), which stand while a possible rope cannot weigh. A load
//! added mid-luff (a second load hooked on, a hook caught) moves every W_k
//! at once, but at a steep boom in a fast move the wrong ropes' swings
//! spread their readings (up to tan θ·Δφ: ±17 % and more at 60°–80°), so
//! W_fast reads the new load low, and W_slow follows it at its own pace
//! only: 110 % added mid-raise to 80° in 10 s was cut only once the move
//! stopped, 2.3–5.8 s after its take-up, and 90 % added mid-lowering from
//! 80° was cut at true u up to 1.27 (`host-sim` test
//! `a_load_added_in_motion_*`).
//!
//! ## What a load added does to the readings
//!
//! As at rest ([`crate::load_jump`]), every hypothesis solves the same
//! force, F_W(W_k)·f_k(t) = F − F_0, so a change of the load multiplies
//! every F_W(W_k) by one ratio at one instant, while a wrong rope's
//! phantom f*/f_k changes at the pendulums' periods (3.5–9.5 s). The true
//! rope's reading is constant while the load is. So, with S_k(t) the
//! hypothesis's fast stage (0.7 Hz, against the bounce), a load added
//! makes
//!
//! σ_k = S_k(t) / S_k(t − τ),  τ = 0.5–1.5 s
//!
//! rise for every rope together, and for the true rope by exactly the
//! load's ratio. The rest's rescale uses ρ_k = S_k/W̄_k instead; in motion
//! the averages may hold a weighing kept over a logger's dropout or the
//! old load of a move that doubts its start, and a ratio to them is no
//! rise: run in motion, that rescale cut a lowering early from true u
//! 0.833. A rise is measured from what the ropes themselves read before
//! it.
//!
//! ## The rule
//!
//! Every [`SNAP_S`] each hypothesis's S_k and D_k (its inconsistency,
//! [`crate::load_jump::Consistency`]) are snapshot; the reading before a
//! rise is the lower of the two oldest, B_k (0.5–1.5 s old). While the
//! boom has luffed at a steady rate for [`STEADY_FOR_S`] (its acceleration
//! under [`STEADY_ACCEL_RAD_S2`]: the starts and stops of a luff, whose
//! J·θ̈ and ride-up reach the force before the lagging angle shows them,
//! are left out), a rope *votes* if, at the oldest snapshot, it was
//! consistent (D_k within the rest's bar, [`crate::load_jump::bar`], and
//! under [`crate::load_jump::CONSISTENT`], where a rope that starts
//! weighing begins), and both B_k and its average W̄_k were within
//! [`crate::load_jump::JUMP`] of the bank's weighing W_slow. A rise is seen
//! when
//!
//! - min over the voters of S_k/B_k ≥ 1 + JUMP, and every voter rose by
//!   [`crate::load_jump::MIN_JUMP_KG`] at least (the sensors' noise on a
//!   light load);
//! - min over **every** rope that weighs of S_k/B_k ≥ 1 + JUMP: a load
//!   multiplies every reading, a phantom moves each its own way;
//!
//! and it is followed once it has been seen for [`CONFIRM_S`] without a
//! break (a held load's bounce at 1–2 Hz, ζ 0.02, rings common to every
//! rope as a load does, but its crest stays over the threshold for under
//! 0.2 s). Then, for [`FOLLOW_S`], the voters' references B_k are frozen
//! and every cycle (while the luff stays steady)
//!
//! σ = min_voters S_k/B_k,  ρ = min_voters S_k/W̄_k,
//! W̄_k ← W̄_k·s for every rope, s = min(σ/A, ρ, MAX_STEP) when > 1,
//! A ← A·s
//!
//! (A the rise applied so far, starting at 1): the averages, and with them
//! W_slow and the weighing that stands while a rope cannot weigh, rise by
//! the voters' lowest rise and never past what the voters read now.
//!
//! **A rise that rings.** A load taken up on a rope that stretches rings
//! about the new load at the rope's 1–2 Hz: taken up in 0.5 s at 1 Hz the
//! pull overshoots by about 60 % of the load added, ±5–13 % of it through
//! the filters. Followed at σ, the crest stayed in the averages and 90 %
//! added in a 10 s raise to 80° was an OVERLOAD at true u 0.900 (`host-sim`
//! test `a_load_added_in_motion_on_a_ringing_rope_*`). A take-up seen
//! through the filters does not fall; once σ falls from its highest in the
//! follow by [`RING_DROP`], the rise rings, and from then on the target is
//! the voters' lower envelope, min_voters (lowest S_k of the last
//! 0.5–0.75 s)/B_k, at least half a period of a 1 Hz ring: A is raised to
//! it, or lowered to it to give back the crest taken, never below 1 (the
//! averages from before the rise). So the follower only ever raises the
//! averages over what they were before the rise, and delays no overload
//! that the bank reads without it. And for [`crate::load_jump`]'s rescale
//! at rest, the stop's bounce window
//! ([`crate::static_load::BOUNCE_WINDOW_S`]) after a move whose rise was
//! followed is no time to look for a load added: the averages hold the
//! load, and the stop's bounce on the rope rises at the true rope as a
//! load added would (1.8 s after the stop, a 1 Hz bounce at ζ 0.05 was
//! rescaled into an OVERLOAD at true u 0.900).
//!
//! When a follow ends its snapshots are dropped: its rescale kept its
//! voters' ratios at 1 whatever their phantoms did, so their D_k of that
//! time is no consistency to vote with.
//!
//! ## Measured
//!
//! In the second formulation's world (`host-sim` test
//! `a_load_added_in_motion_*`: 50 % of rated taken to 90 % or 110 % over
//! 0.5 s or 2 s mid-luff, every rope, both friction laws), 110 % is cut
//! within 1 s of its take-up in 61 of 96 cases (43 without the follower),
//! at most 3.35 s after (5.80 s); 90 % added in a lowering is uncut past
//! true u 1.05 in 11 of 48 cases, up to 1.11 (f32 1.14; 1.27); 90 % added
//! in a raise is never an OVERLOAD, and no lowering is cut before true u
//! 0.962. On held ropes that ring at 1 Hz (ζ 0.02 and 0.05) and 2 Hz
//! (ζ 0.05), 90 % is never an OVERLOAD either, lowerings are cut from true
//! u 0.943 and uncut up to 1.110, 110 % at most 3.35 s after its take-up.
//! What is left is the filters' delay (a take-up of 0.5 s reads
//! 95 % about 1 s after it ends) and, in 10 s raises to 80°, a consistent
//! rope that votes and reads its swing low as the boom steepens: the min
//! over the voters errs toward the lower reading. Each guard above was
//! found by a field test that failed without it (the test's doc lists
//! them). Campaign seed 1 and `--wide` seed 1 give the same figures as
//! without the follower.
//!
//! The cost: per hypothesis three divisions a cycle, three snapshots and
//! three block minima; no heap, fixed loops. On the controller
//! (`scripts/firmware-budgets.sh`): 1 345 more instructions per cycle at
//! most (10 202), 4.4 KB of flash (62 028 B of 64 KiB), 780 B more of the
//! bank's state (2 776 B in f32).

use crane_model::Real;

use crate::load_jump;

/// How often each hypothesis's reading is snapshot (s).
pub const SNAP_S: f64 = 0.5;

/// How many snapshots each hypothesis keeps: the oldest is 1.0–1.5 s old.
pub const SNAPS: usize = 3;

/// Largest boom acceleration of a steady luff (rad/s²): 0.5 °/s².
pub const STEADY_ACCEL_RAD_S2: f64 = 0.5 * core::f64::consts::PI / 180.0;

/// How long a luff must have been steady for a rise to be looked for (s):
/// the snapshots it is measured from are of the steady luff too.
pub const STEADY_FOR_S: f64 = 1.5;

/// How long a rise must be seen without a break before it is followed (s):
/// longer than a bounce's crest (1–2 Hz) stays over the threshold.
pub const CONFIRM_S: f64 = 0.4;

/// How long each block of a rope's lower envelope lasts (s); with
/// [`RING_BLOCKS`] of them the envelope spans 0.5–0.75 s, half a period of
/// the slowest bounce (1 Hz) at least.
pub const RING_BLOCK_S: f64 = 0.25;

/// How many blocks the lower envelope keeps.
pub const RING_BLOCKS: usize = 3;

/// How far the voters' rise must fall from its highest in a follow to be
/// taken as ringing (a take-up's rise through the filters does not fall).
pub const RING_DROP: f64 = 0.03;

/// How long a rise is followed once seen (s): a take-up of up to 2 s and
/// the filters' response after it.
pub const FOLLOW_S: f64 = 3.0;

/// What one hypothesis that weighs gives the follower in a cycle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reading<T> {
    /// S_k(W_k) (kg).
    pub fast_kg: T,
    /// W̄_k (kg); `None` while the hypothesis has no average.
    pub average_kg: Option<T>,
    /// D_k.
    pub inconsistency: T,
}

/// One hypothesis's readings at the last [`SNAPS`] snapshots, newest first.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Snapshots<T> {
    /// S_k(W_k) at each snapshot (kg); `None` where it did not weigh.
    reading_kg: [Option<T>; SNAPS],
    /// D_k at each snapshot.
    inconsistency: [T; SNAPS],
    /// The reading a followed rise is measured from (kg); `None` for a
    /// rope that does not vote in it.
    reference_kg: Option<T>,
    /// The lowest S_k of each of the last [`RING_BLOCKS`] blocks of
    /// [`RING_BLOCK_S`], the present one first (kg): the lower envelope a
    /// ringing rise is followed at.
    block_min_kg: [Option<T>; RING_BLOCKS],
}

impl<T: Real> Snapshots<T> {
    fn new() -> Self {
        Self { reading_kg: [None; SNAPS], inconsistency: [T::lit(load_jump::CONSISTENT); SNAPS], reference_kg: None, block_min_kg: [None; RING_BLOCKS] }
    }

    fn take(&mut self, reading_kg: Option<T>, inconsistency: T) {
        self.reading_kg.rotate_right(1);
        self.inconsistency.rotate_right(1);
        if let (Some(r), Some(d)) = (self.reading_kg.first_mut(), self.inconsistency.first_mut()) {
            *r = reading_kg;
            *d = inconsistency;
        }
    }

    /// B_k: the lower of the two oldest snapshots; `None` unless both
    /// weighed.
    fn before_kg(&self) -> Option<T> {
        let a = (*self.reading_kg.get(SNAPS - 2)?)?;
        let b = (*self.reading_kg.get(SNAPS - 1)?)?;
        Some(a.min(b))
    }

    /// The lowest reading of the last 0.5–0.75 s (kg); `None` unless the
    /// rope weighed in every block.
    fn envelope_kg(&self) -> Option<T> {
        let mut lowest: Option<T> = None;
        for b in self.block_min_kg.iter() {
            let b = (*b)?;
            lowest = Some(lowest.map_or(b, |m: T| m.min(b)));
        }
        lowest
    }

    /// D_k at the oldest snapshot.
    fn inconsistency_before(&self) -> T {
        self.inconsistency.last().copied().unwrap_or(T::lit(load_jump::CONSISTENT))
    }

    /// B_k if this rope votes, with its average now `average_kg`, the
    /// bank's weighing `weighing_kg` and the consistency bar `bar` (see the
    /// module doc); `None` if it does not.
    fn votes(&self, average_kg: Option<T>, weighing_kg: Option<T>, bar: T) -> Option<T> {
        let d = self.inconsistency_before();
        let near = |x: T, w: T| x <= w * T::lit(1.0 + load_jump::JUMP) && x * T::lit(1.0 + load_jump::JUMP) >= w;
        match (self.before_kg(), average_kg, weighing_kg) {
            (Some(b), Some(a), Some(w)) if w >= T::lit(load_jump::MIN_AVERAGE_KG) && near(a, w) && near(b, w) && d <= bar && d < T::lit(load_jump::CONSISTENT) => Some(b),
            _ => None,
        }
    }
}

/// The follower of a load added in motion (see the module doc), for `N`
/// hypotheses.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RiseFollower<T, const N: usize> {
    snapshots: [Snapshots<T>; N],
    /// Time since the last snapshot (s).
    snap_s: T,
    /// The boom luffs (its rate over the bank's still threshold), and for
    /// how long steadily (s).
    moving: bool,
    steady_s: T,
    /// How long a rise has been seen without a break (s).
    seen_s: T,
    /// Time left to follow a rise (s), and A, the rise applied so far.
    follow_s: T,
    applied: T,
    /// Time since the last ring block began (s).
    block_s: T,
    /// The highest rise σ read in this follow, and whether σ has since
    /// fallen from it by [`RING_DROP`]: the rise rings.
    peak: T,
    ringing: bool,
    /// A rise was followed in the present move, or in the last one if the
    /// boom is still.
    followed: bool,
}

impl<T: Real, const N: usize> Default for RiseFollower<T, N> {
    fn default() -> Self {
        Self::new()
    }
}

impl<T: Real, const N: usize> RiseFollower<T, N> {
    /// A follower with no snapshot yet.
    pub fn new() -> Self {
        Self {
            snapshots: [Snapshots::new(); N],
            snap_s: T::lit(0.0),
            moving: false,
            steady_s: T::lit(0.0),
            seen_s: T::lit(0.0),
            follow_s: T::lit(0.0),
            applied: T::lit(1.0),
            block_s: T::lit(0.0),
            peak: T::lit(1.0),
            ringing: false,
            followed: false,
        }
    }

    /// Forgets every snapshot and any rise followed (the force was
    /// interrupted: the filters restart).
    pub fn clear(&mut self) {
        self.snapshots = [Snapshots::new(); N];
        self.seen_s = T::lit(0.0);
        self.follow_s = T::lit(0.0);
    }

    /// Forgets hypothesis `k`'s snapshots (it stopped weighing: its
    /// reading starts afresh).
    pub fn forget(&mut self, k: usize) {
        if let Some(s) = self.snapshots.get_mut(k) {
            *s = Snapshots::new();
        }
    }

    /// The boom's motion at an advance of `dt_s`: whether it luffs, and its
    /// acceleration (rad/s²).
    pub fn luff(&mut self, moving: bool, accel_rad_s2: T, dt_s: T) {
        let steady = moving && accel_rad_s2.abs() <= T::lit(STEADY_ACCEL_RAD_S2);
        self.steady_s = if steady { self.steady_s + dt_s } else { T::lit(0.0) };
        if moving && !self.moving {
            self.followed = false;
        }
        self.moving = moving;
    }

    /// Whether a rise was followed in the present move, or in the last one
    /// while the boom is still.
    pub fn followed_in_move(&self) -> bool {
        self.followed
    }

    /// Whether a rise is being followed.
    pub fn following(&self) -> bool {
        self.follow_s > T::lit(0.0)
    }

    /// One cycle of `dt_s`: the `readings` of the hypotheses that weigh and
    /// the bank's weighing W_slow of the last cycle (kg). Returns the factor
    /// every slow average is to be multiplied by: over 1 while a rise is
    /// followed, under 1 only where a ringing rise's crest is given back
    /// (never below the averages from before the rise).
    pub fn update(&mut self, readings: &[Option<Reading<T>>; N], weighing_kg: Option<T>, dt_s: T) -> T {
        let one = T::lit(1.0);
        let mut scale = one;
        self.block_s += dt_s;
        let new_block = self.block_s >= T::lit(RING_BLOCK_S);
        if new_block {
            self.block_s = T::lit(0.0);
        }
        for (s, r) in self.snapshots.iter_mut().zip(readings.iter()) {
            if new_block {
                s.block_min_kg.rotate_right(1);
                if let Some(b) = s.block_min_kg.first_mut() {
                    *b = None;
                }
            }
            if let Some(b) = s.block_min_kg.first_mut() {
                *b = match (r, *b) {
                    (Some(r), Some(m)) => Some(m.min(r.fast_kg)),
                    (Some(r), None) => Some(r.fast_kg),
                    (None, _) => None,
                };
            }
        }
        if !self.moving {
            self.end_follow();
            self.seen_s = T::lit(0.0);
        } else {
            let steady = self.steady_s >= T::lit(STEADY_FOR_S);
            if !self.following() && steady {
                self.look_for_rise(readings, weighing_kg, dt_s);
            } else if !self.following() {
                self.seen_s = T::lit(0.0);
            }
            if self.following() {
                if steady {
                    scale = self.follow(readings);
                }
                self.follow_s -= dt_s;
                if !self.following() {
                    self.end_follow();
                }
            }
        }
        self.snap_s += dt_s;
        if self.snap_s >= T::lit(SNAP_S) {
            self.snap_s = T::lit(0.0);
            for (s, r) in self.snapshots.iter_mut().zip(readings.iter()) {
                s.take(r.map(|r| r.fast_kg), r.map_or(T::lit(load_jump::CONSISTENT), |r| r.inconsistency));
            }
        }
        scale
    }

    /// Ends a follow: its snapshots are dropped (see the module doc).
    fn end_follow(&mut self) {
        if self.follow_s > T::lit(0.0) || self.snapshots.iter().any(|s| s.reference_kg.is_some()) {
            self.snapshots = [Snapshots::new(); N];
        }
        self.follow_s = T::lit(0.0);
    }

    /// Counts how long a rise has been seen, and starts following it after
    /// [`CONFIRM_S`].
    fn look_for_rise(&mut self, readings: &[Option<Reading<T>>; N], weighing_kg: Option<T>, dt_s: T) {
        // The most consistent rope at the oldest snapshot sets the bar.
        let mut best: Option<T> = None;
        for (s, r) in self.snapshots.iter().zip(readings.iter()) {
            if r.is_some() && s.before_kg().is_some() {
                let d = s.inconsistency_before();
                best = Some(best.map_or(d, |m: T| m.min(d)));
            }
        }
        let bar = best.map_or(T::lit(0.0), load_jump::bar);
        let (mut common, mut voted, mut up): (Option<T>, Option<T>, Option<T>) = (None, None, None);
        for (s, r) in self.snapshots.iter().zip(readings.iter()) {
            let (Some(r), Some(b)) = (r, s.before_kg()) else {
                continue;
            };
            let q = r.fast_kg / b;
            common = Some(common.map_or(q, |m: T| m.min(q)));
            if s.votes(r.average_kg, weighing_kg, bar).is_some() {
                voted = Some(voted.map_or(q, |m: T| m.min(q)));
                let d = r.fast_kg - b;
                up = Some(up.map_or(d, |m: T| m.min(d)));
            }
        }
        let jump = T::lit(1.0 + load_jump::JUMP);
        // Every rope at the rise's start; the voters alone while it is
        // confirmed (a wrong rope's phantom may fall meanwhile).
        let started = self.seen_s > T::lit(0.0);
        let seen = matches!((common, voted, up), (Some(c), Some(q), Some(d)) if (started || c >= jump) && q >= jump && d >= T::lit(load_jump::MIN_JUMP_KG));
        self.seen_s = if seen { self.seen_s + dt_s } else { T::lit(0.0) };
        if self.seen_s < T::lit(CONFIRM_S) {
            return;
        }
        self.seen_s = T::lit(0.0);
        for (s, r) in self.snapshots.iter_mut().zip(readings.iter()) {
            s.reference_kg = r.and_then(|r| s.votes(r.average_kg, weighing_kg, bar));
        }
        self.follow_s = T::lit(FOLLOW_S);
        self.applied = T::lit(1.0);
        self.peak = T::lit(1.0);
        self.ringing = false;
        self.followed = true;
    }

    /// The factor of this cycle of a followed rise (see the module doc).
    fn follow(&mut self, readings: &[Option<Reading<T>>; N]) -> T {
        let one = T::lit(1.0);
        let (mut sigma, mut envelope, mut rho): (Option<T>, Option<T>, Option<T>) = (None, None, None);
        let lowest = |m: Option<T>, x: T| Some(m.map_or(x, |m: T| m.min(x)));
        for (s, r) in self.snapshots.iter().zip(readings.iter()) {
            if let (Some(b), Some(r)) = (s.reference_kg, r) {
                let Some(a) = r.average_kg else {
                    continue;
                };
                sigma = lowest(sigma, r.fast_kg / b);
                rho = lowest(rho, r.fast_kg / a);
                // A voter without a full envelope yet bounds it at nothing.
                envelope = lowest(envelope, s.envelope_kg().map_or(T::lit(0.0), |e| e / b));
            }
        }
        let (Some(sg), Some(rh), Some(env)) = (sigma, rho, envelope) else {
            // Every voter stopped weighing: nothing to follow.
            self.follow_s = T::lit(0.0);
            return one;
        };
        self.peak = self.peak.max(sg);
        self.ringing |= sg < self.peak * T::lit(1.0 - RING_DROP);
        // A rise that rings is followed at its lower envelope, and the crest
        // it took is given back down to it, never below the averages before
        // the rise.
        let want = if self.ringing { env.max(one) } else { sg };
        let s = if want > self.applied {
            (want / self.applied).min(rh).min(T::lit(load_jump::MAX_STEP))
        } else if self.ringing {
            want / self.applied
        } else {
            one
        };
        if s.is_finite() && s > T::lit(0.0) {
            self.applied *= s;
            s
        } else {
            one
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const N: usize = 4;
    const DT: f64 = 0.01;


    /// Runs a follower over `seconds` of a steady luff on readings
    /// `reading(k, t)` (kg) of N ropes, each with an average that follows it
    /// as the bank's does (one 3 s stage) and is multiplied by the factors
    /// the follower returns, D_k 0.01 for the ropes in `consistent`, 0.2
    /// for the others. Returns, every cycle, the time, the lowest average
    /// (the bank's W_slow) and whether a rise is followed.
    fn run(seconds: f64, consistent: &[usize], reading: impl Fn(usize, f64) -> f64) -> Vec<(f64, f64, bool)> {
        let mut follower = RiseFollower::<f64, N>::new();
        let mut averages: [f64; N] = core::array::from_fn(|k| reading(k, 0.0));
        let gain = DT / 3.0;
        let mut weighing = averages.iter().copied().fold(f64::INFINITY, f64::min);
        let mut out = Vec::new();
        for i in 0..(seconds / DT) as usize {
            let t = i as f64 * DT;
            follower.luff(true, 0.0, DT);
            // The averages first, as the bank moves them before the follower.
            for (a, k) in averages.iter_mut().zip(0..N) {
                *a += gain * (reading(k, t) - *a);
            }
            let readings: [Option<Reading<f64>>; N] = core::array::from_fn(|k| {
                Some(Reading { fast_kg: reading(k, t), average_kg: Some(averages[k]), inconsistency: if consistent.contains(&k) { 0.01 } else { 0.2 } })
            });
            let s = follower.update(&readings, Some(weighing), DT);
            for a in averages.iter_mut() {
                *a *= s;
            }
            weighing = averages.iter().copied().fold(f64::INFINITY, f64::min);
            out.push((t, weighing, follower.following()));
        }
        out
    }

    /// A phantom: rope k's reading swings ±`amp` about the load at its own
    /// period (3.5–9.5 s), rope 0 (the true one) not at all.
    fn phantom(k: usize, t: f64, amp: f64) -> f64 {
        if k == 0 {
            1.0
        } else {
            1.0 + amp * (t * core::f64::consts::TAU / (3.5 + 2.0 * k as f64) + k as f64).sin()
        }
    }

    /// A load that goes from 3 t to `ratio` × 3 t over `take_up_s` from 5 s
    /// on (kg).
    fn load(t: f64, ratio: f64, take_up_s: f64) -> f64 {
        3000.0 * (1.0 + (ratio - 1.0) * ((t - 5.0) / take_up_s).clamp(0.0, 1.0))
    }

    #[test]
    fn a_load_added_in_a_steady_luff_raises_the_weighing_to_the_true_ropes_reading_and_no_higher() {
        for (ratio, take_up) in [(1.8, 2.0), (2.2, 0.5), (1.3, 1.0)] {
            let out = run(12.0, &[0], |k, t| load(t, ratio, take_up) * phantom(k, t, 0.1));
            // The weighing rises by the load's ratio within a second of the
            // take-up's end, and never reads above the load.
            let done = 5.0 + take_up;
            let before = out.iter().find(|o| o.0 >= 5.0).map_or(0.0, |o| o.1);
            let at = out.iter().find(|o| o.1 >= 0.95 * ratio * before).map(|o| o.0 - done);
            assert!(at.is_some_and(|s| s <= 1.0), "{ratio} in {take_up} s: seen {at:?} s after the take-up");
            let over = out.iter().map(|o| o.1 / load(o.0, ratio, take_up)).fold(0.0, f64::max);
            assert!(over <= 1.0 + 1e-12, "{ratio} in {take_up} s: read up to {over:.3} of the load");
        }
    }

    #[test]
    fn a_ringing_rise_is_followed_at_its_lower_envelope() {
        // 3 t → 5.4 t over 0.5 s, the pull ringing about the new load at
        // 1 Hz (±25 % of it, decaying over 6 s) on every rope. The first
        // crest comes while the rise is still taken for a take-up; from the
        // first fall on the weighing is the lower envelope, and the crest is
        // given back (kept, it would stay 1.25 × the load; the averages' own
        // 3 s stage takes in a little of every ring).
        let ring = |t: f64| if t < 5.5 { 1.0 } else { 1.0 + 0.25 * (-(t - 5.5) / 6.0).exp() * ((t - 5.5) * core::f64::consts::TAU).sin() };
        let out = run(14.0, &[0], |k, t| load(t, 1.8, 0.5) * ring(t) * phantom(k, t, 0.05));
        let before = out.iter().find(|o| o.0 >= 5.0).map_or(0.0, |o| o.1);
        let after_first_cycle = out.iter().filter(|o| o.0 >= 6.5).map(|o| o.1 / before).fold(0.0, f64::max);
        let seen = out.iter().find(|o| o.1 >= 0.9 * 1.8 * before).map(|o| o.0 - 5.5);
        assert!(after_first_cycle <= 1.8 * 1.04, "kept the ring's crest: {after_first_cycle:.3} of the load before");
        assert!(seen.is_some_and(|s| s <= 1.0), "0.9 of the load seen {seen:?} s after its take-up");
        // The follow ends at the envelope, which the averages then carry
        // toward the load at their own pace.
        let end = out.last().map_or(0.0, |o| o.1 / before);
        assert!((0.9 * 1.8..=1.8 * 1.04).contains(&end), "ends at {end:.3} of the load before");
    }

    #[test]
    fn a_constant_load_and_the_wrong_ropes_phantoms_raise_nothing() {
        let out = run(30.0, &[0], |k, t| 3000.0 * phantom(k, t, 0.3));
        assert!(out.iter().all(|o| !o.2), "followed a phantom");
    }

    #[test]
    fn a_bounce_common_to_every_rope_is_no_load_added() {
        // ±20 % at 1 and 2 Hz on every reading, as a held load's bounce
        // reaches S_k through the force filter.
        for hz in [1.0, 2.0] {
            let out = run(20.0, &[0], |k, t| 3000.0 * phantom(k, t, 0.05) * (1.0 + 0.2 * (t * core::f64::consts::TAU * hz).sin()));
            assert!(out.iter().all(|o| !o.2), "{hz} Hz: followed the bounce");
        }
    }

    #[test]
    fn a_rise_of_the_consistent_rope_alone_is_no_load_added() {
        // The one consistent rope's reading drifts up by a quarter while
        // another rope's falls: a phantom, not a load.
        let out = run(15.0, &[0], |k, t| match k {
            0 => 3000.0 * (1.0 + 0.25 * ((t - 5.0) / 2.0).clamp(0.0, 1.0)),
            1 => 3000.0 * (1.0 - 0.2 * ((t - 5.0) / 2.0).clamp(0.0, 1.0)),
            _ => 3000.0,
        });
        assert!(out.iter().all(|o| !o.2), "followed one rope's drift");
    }

    #[test]
    fn no_rope_that_was_inconsistent_or_away_from_the_weighing_votes() {
        // Every rope inconsistent: a load added is left to the bank.
        let out = run(12.0, &[], |k, t| load(t, 2.0, 1.0) * phantom(k, t, 0.1));
        assert!(out.iter().all(|o| !o.2));
        // The consistent rope reads 1.3 × the others before the rise: it
        // is no weighing to scale.
        let out = run(12.0, &[3], |k, t| load(t, 2.0, 1.0) * if k == 3 { 1.3 } else { 1.0 });
        assert!(out.iter().all(|o| !o.2));
    }

    #[test]
    fn at_rest_or_in_a_luffs_start_nothing_is_followed() {
        let mut follower = RiseFollower::<f64, N>::new();
        let mut weighing = 3000.0;
        for i in 0..1200 {
            let t = f64::from(i) * DT;
            // Accelerating (1 °/s²) for the first 6 s, then still.
            follower.luff(t < 6.0, if t < 6.0 { 1.0f64.to_radians() } else { 0.0 }, DT);
            let r = Some(Reading { fast_kg: load(t, 2.0, 1.0), average_kg: Some(weighing), inconsistency: 0.01 });
            let s = follower.update(&[r; N], Some(weighing), DT);
            assert!(s == 1.0 && !follower.following(), "followed at {t:.2} s");
            weighing = load(t, 1.0, 1.0);
        }
    }
}
