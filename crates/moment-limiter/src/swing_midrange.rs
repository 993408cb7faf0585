//! A load added at rest while it swings, weighed from one crest and one
//! trough of the force: from half a swing period after the take-up, where
//! the mean over a whole one ([`crate::period_mean`]) needs a period and a
//! third and a second of confirmation.
//!
//! ## Why the midrange is the load
//!
//! With the boom still, a load swinging by φ(t) on a rope pulls the tip with
//! the rope's tension along the rope: at the turning points of the swing
//! (φ = ±φ₀, φ̇ = 0) the tension is W·g·cos φ₀, vertically W·g·cos²φ₀,
//! horizontally ±W·g·cos φ₀·sin φ₀. Read as a load hanging straight and
//! still (factor 1, [`crate::static_load`]), the force at the outward and
//! the inward turning point is
//!
//! W₁(±φ₀) = W·cos²φ₀·(1 ± tan θ·tan φ₀),
//!
//! so the midrange of the two, (W₁max + W₁min)/2 = W·cos²φ₀, is the load
//! less cos²φ₀ (2.4 % for a swing of 9°, 6 % for 14°: it reads low, never
//! high), whatever the rope's length, the boom angle and the amplitude. At
//! a steep boom the horizontal pull dominates, and W₁'s extremes are the
//! swing's turning points; at a shallow one the swing moves the force by
//! little and any extremes are within a few per cent of the load.
//!
//! ## Where the bank needs it
//!
//! At rest after a move no rope of the bank may follow the swing (a rope
//! between the grid's lengths at a steep boom): its weighing is then the
//! move's, held ([`crate::static_load`], "At rest after a move: the move's
//! weighing held"), and a load added is read only at the crests of the
//! ropes' readings until the mean over one swing period is found (P·4/3 and
//! a second of confirmation after the take-up: 10.6 s on a 13 m rope). A
//! 110 % load added 3 s after a raise to 80° on that rope was cut only 12 s
//! after its take-up; from this module's midrange, 8.6 s after.
//!
//! So once the bank sees a load added at rest (W_fast passing the held
//! weighing by [`crate::load_jump::JUMP`]) it follows W₁ through two
//! first-order stages at [`crate::static_load::FAST_SMOOTHING_HZ`] (against
//! the load's 1–2 Hz bounce; a stage passes the mean unchanged and delays
//! the swing's crest and trough alike) and reads the midrange of its last
//! two turning points, a crest and a trough:
//!
//! - a turning point is where W₁, having moved one way, turns back by
//!   [`TURN`] of its range since the following began, and by at least
//!   [`MIN_TURN`] of its highest value (the extreme before the turn is the
//!   turning point);
//! - it counts only if it came at least [`HALF_SWING_S`] after the turning
//!   point before it, and the midrange is read only from two that count;
//!   the first turning point may come sooner after the start of the
//!   following if the force came to it from the start by [`APPROACH`] of
//!   the span to the next (the new load's first crest, just after the
//!   take-up). The swing's crest and trough are at
//!   least 1.75 s apart (a 3 m rope), the bounce's a quarter to half a
//!   second: while the range was still small, a bounce's crest and trough
//!   turned as the swing's, and paired with the swing's next crest read up
//!   to 1.22 × the load (`tests::a_ringing_bounce_on_any_swing_*`: a bounce
//!   of ±30 % at 1–2 Hz ringing down over 0.5–2 s on swings of 3.5–9.5 s
//!   and ±10–80 %; now 0.980–1.018 × the load).
//!
//! The first reading comes half a swing period to a period and two thirds
//! after the following begins (a crest within [`HALF_SWING_S`] of the start
//! that the force did not rise to by [`APPROACH`] of the span does not
//! count, and the next is a period later). A crest or a trough
//! taken while the load was still being taken up is lower than the new
//! load's: the midrange then reads low (a floor that raises less), never
//! high. A load set down while it is followed would read high (the old
//! load's crest against the new one's trough): the bank errs toward cutting
//! there, as with the held weighing.
//!
//! A lowering begun while it follows, before the trough after the new
//! load's first crest, goes on following for a while, in the rest's units
//! ([`crate::static_load::MIDRANGE_CARRY_S`]; [`crate::static_load`], "Into
//! the move"): the lowering's start only deepens that trough.
//!
//! The cost: two stages and a few comparisons a cycle while it follows, no
//! loop, no heap.

use crane_model::Real;

use crate::static_load::stage;

/// Share of W₁'s range since the following began by which it must turn
/// back from an extreme for the extreme to be a turning point.
pub const TURN: f64 = 0.15;

/// Smallest turn, as a share of the highest pull since the following
/// began: while the range is still small, a wiggle of the force (what is
/// left of a bounce after the two stages) turns by more than [`TURN`] of
/// it. Without it (and before [`HALF_SWING_S`] held between every two
/// turning points), a dip 0.2 s after the following began counted as a
/// trough, and 90 % of rated added on the paid-out rope at 80° read 1.10 ×
/// itself (`host-sim` test
/// `a_load_added_at_rest_on_the_paid_out_rope_soon_after_a_raise_is_cut_within_6_5_s_f32`,
/// then `…_within_10_5_s_f32`).
pub const MIN_TURN: f64 = 0.05;

/// A first turning point within [`HALF_SWING_S`] of the start of the
/// following counts if the force came to it from the start by this share
/// of the span to the next turning point: a crest the take-up's rise led
/// into, not a bounce's wiggle on the swing's slow rise.
pub const APPROACH: f64 = 0.5;

/// Shortest time from one turning point to the next for it to count (s):
/// under half the shortest rope's period (3.5 s at 3 m), twice half the
/// period of the load's slowest bounce (1 Hz). At 1.2 s the new load's
/// first crest on the 8.9 m rope of `host-sim` test
/// `a_lowering_5_s_after_a_load_added_at_rest_soon_after_a_stop_*` (1.15 s
/// after the following began, from less than [`APPROACH`] of the span) did
/// not count, the lowering 5 s after the take-up started before the next
/// crest, and that rope was cut only at true u 1.13; at 1.0 s the midrange
/// is read about 0.2 s before the lowering starts, and the bounces of
/// `tests::a_ringing_bounce_on_any_swing_*` read as they did at 1.2 s
/// (0.980–1.018 × the load).
pub const HALF_SWING_S: f64 = 1.0;

/// The midrange of the swing's force since a load was added at rest (see
/// the module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SwingMidrange<T> {
    /// W₁ through two stages; `None` while not following.
    stages: Option<(T, T)>,
    /// Time since the following began (s).
    t_s: T,
    /// Where the following began, and the highest and lowest since.
    first: T,
    highest: T,
    lowest: T,
    /// Which way W₁ heads since its last turning point: +1 rising, −1
    /// falling, 0 before it has moved a turn from where the following began.
    heading: T,
    /// The extreme of the present half swing and when (s).
    candidate: (T, T),
    /// The last turning point and when (s; the start until the first), and
    /// whether it came [`HALF_SWING_S`] after the one before it.
    last: (T, T, bool),
    /// Whether a turning point has been found since the following began.
    turned: bool,
    /// The last turning point is the first, and came within
    /// [`HALF_SWING_S`] of the start (see [`APPROACH`]).
    early_first: bool,
    /// The midrange of the last two turning points that were both so.
    reading: Option<T>,
}

impl<T: Real> Default for SwingMidrange<T> {
    fn default() -> Self {
        Self::new()
    }
}

impl<T: Real> SwingMidrange<T> {
    /// Not following.
    pub fn new() -> Self {
        let zero = T::lit(0.0);
        Self { stages: None, t_s: zero, first: zero, highest: zero, lowest: zero, heading: zero, candidate: (zero, zero), last: (zero, zero, false), turned: false, early_first: false, reading: None }
    }

    /// Whether a load added is being followed.
    pub fn following(&self) -> bool {
        self.stages.is_some()
    }

    /// Stops following (the boom moved, the force was interrupted, the
    /// rest's hold ended).
    pub fn clear(&mut self) {
        *self = Self::new();
    }

    /// Takes one reading `w1` of the load's pull at factor 1 (any unit
    /// linear in the pull, zero for no load), `dt_s` after the last, through
    /// two stages of gain `gain`; starts following at the first. Returns the
    /// midrange of the last crest and trough that turned, each
    /// [`HALF_SWING_S`] after the turning point before it (see the module
    /// doc).
    pub fn push(&mut self, w1: T, dt_s: T, gain: T) -> Option<T> {
        if !w1.is_finite() {
            return self.reading;
        }
        let zero = T::lit(0.0);
        if self.stages.is_none() {
            *self = Self { first: w1, highest: w1, lowest: w1, candidate: (w1, zero), last: (w1, zero, false), ..Self::new() };
        }
        // The bank's first-order stage, twice (it starts at its input).
        let a = stage(w1, self.stages.map(|s| s.0), gain, false);
        let y = stage(a, self.stages.map(|s| s.1), gain, false);
        self.stages = Some((a, y));
        if dt_s.is_finite() && dt_s > zero {
            self.t_s += dt_s;
        }
        self.highest = self.highest.max(y);
        self.lowest = self.lowest.min(y);
        let turn = ((self.highest - self.lowest) * T::lit(TURN)).max(self.highest.abs() * T::lit(MIN_TURN));
        // Rising and falling alike, the falling half mirrored (h = −1).
        let h = self.heading;
        if h == zero {
            let moved = y - self.first;
            if turn > zero && moved.abs() >= turn {
                self.heading = if moved > zero { T::lit(1.0) } else { T::lit(-1.0) };
                self.candidate = (y, self.t_s);
            }
        } else if h * y > h * self.candidate.0 {
            self.candidate = (y, self.t_s);
        } else if h * (self.candidate.0 - y) >= turn {
            // A turning point: the bounce's come a quarter to half a second
            // after the one before, the swing's at least HALF_SWING_S.
            let (value, at_s) = self.candidate;
            let apart = at_s - self.last.1 >= T::lit(HALF_SWING_S);
            // A first turning point soon after the start counts if the
            // force came to it from the start by APPROACH of the pair's span.
            let approached = !self.early_first || (self.last.0 - self.first).abs() >= (value - self.last.0).abs() * T::lit(APPROACH);
            if apart && self.last.2 && approached {
                self.reading = Some((value + self.last.0) * T::lit(0.5));
            }
            self.early_first = !self.turned && !apart;
            self.last = (value, at_s, apart || !self.turned);
            self.turned = true;
            self.heading = -h;
            self.candidate = (y, self.t_s);
        }
        self.reading
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The midrange of a swing read W·cos²φ₀·(1 + tan θ·tan φ), stage gain
    /// for 0.7 Hz at 100 Hz, from `start_s` into the swing for `for_s`.
    fn run(w: f64, phi0: f64, tan_theta: f64, period_s: f64, start_s: f64, for_s: f64) -> Vec<Option<f64>> {
        let dt = 0.01;
        let gain = 1.0 - (-dt * 2.0 * core::f64::consts::PI * 0.7f64).exp();
        let mut m = SwingMidrange::new();
        (0..(for_s / dt) as usize)
            .map(|k| {
                let t = start_s + k as f64 * dt;
                let phi = phi0 * (2.0 * core::f64::consts::PI * t / period_s).sin();
                let w1 = w * (phi.cos() * phi0.cos()) * (1.0 + tan_theta * phi.tan());
                m.push(w1, dt, gain)
            })
            .collect()
    }

    #[test]
    fn a_steady_swing_reads_the_load_less_its_cos_squared_within_a_period_and_two_thirds() {
        // 14° on a 6 m rope (4.9 s) at 80°: W₁ from 0.06 to 2.3 of the load.
        for start in [0.0, 0.7, 1.5, 2.9, 4.0] {
            let out = run(1000.0, 14f64.to_radians(), 80f64.to_radians().tan(), 4.9, start, 12.0);
            let first = out.iter().position(Option::is_some).expect("read");
            let read = out.iter().flatten().copied();
            let (lo, hi) = read.fold((f64::MAX, f64::MIN), |(a, b), x| (a.min(x), b.max(x)));
            println!("start {start}: read after {:.2} s, {lo:.1}..{hi:.1} kg", first as f64 * 0.01);
            // At most a period and two thirds: a start just before a crest
            // waits for the trough and the next crest (a crest within
            // HALF_SWING_S of the start is not counted), and the stages'
            // lag and a turn.
            assert!(first as f64 * 0.01 <= 4.9 * 1.7, "read only after {} s", first as f64 * 0.01);
            let cos2 = 14f64.to_radians().cos().powi(2) * 1000.0;
            assert!(lo >= cos2 - 15.0 && hi <= 1000.0, "{lo}..{hi} against {cos2}");
        }
    }

    #[test]
    fn a_bounce_alone_has_no_crest_and_trough_far_enough_apart() {
        // ±30 % at 1.5 Hz, decaying, on no swing: its extremes are 0.33 s apart.
        let dt = 0.01;
        let gain = 1.0 - (-dt * 2.0 * core::f64::consts::PI * 0.7f64).exp();
        let mut m = SwingMidrange::new();
        let read = (0..800).filter_map(|k| {
            let t = k as f64 * dt;
            let w1 = 1000.0 * (1.0 + 0.3 * (-t / 2.0).exp() * (2.0 * core::f64::consts::PI * 1.5 * t).sin());
            m.push(w1, dt, gain)
        });
        assert_eq!(read.count(), 0);
    }

    #[test]
    fn a_take_up_then_half_a_swing_reads_no_midrange_from_the_take_ups_foot() {
        // From 400 kg rising to the load over 1 s into a swing's crest, then
        // falling: the foot is no trough, so nothing is read before the
        // swing's own trough has turned.
        let dt = 0.01;
        let gain = 1.0 - (-dt * 2.0 * core::f64::consts::PI * 0.7f64).exp();
        let mut m = SwingMidrange::new();
        let period = 6.0;
        let mut first = None;
        for k in 0..1000 {
            let t = k as f64 * dt;
            let load = 400.0 + 600.0 * (t.min(1.0));
            let w1 = load * (1.0 + 0.8 * (2.0 * core::f64::consts::PI * t / period).sin());
            if let (None, Some(x)) = (first, m.push(w1, dt, gain)) {
                first = Some((t, x));
            }
        }
        let (t, x) = first.expect("read");
        println!("read at {t:.2} s: {x:.1} kg");
        // The trough is at 4.5 s.
        assert!(t > 4.5 && (950.0..=1000.0).contains(&x), "{t} {x}");
    }

    #[test]
    fn a_ringing_bounce_on_any_swing_moves_the_midrange_by_under_2_5_percent() {
        // Swings of 3.5–9.5 s (ropes of 3–22 m), ±10–80 %, followed from
        // any phase, with a bounce of up to ±30 % at 1–2 Hz ringing down
        // over 0.5–2 s from where the following began (a take-up's). Bounce
        // turning points passed for the swing's while the range was small:
        // before turning points had to come HALF_SWING_S after the one
        // before, the worst of these read 1.22 × the load.
        let dt = 0.01;
        let gain = 1.0 - (-dt * 2.0 * core::f64::consts::PI * 0.7f64).exp();
        let tau = 2.0 * core::f64::consts::PI;
        let (mut lowest, mut highest) = (f64::MAX, f64::MIN);
        for period in [3.5, 6.0, 9.5] {
            for amplitude in [0.1, 0.3, 0.8] {
                for before_crest in [0.5, 2.0, 3.0, 4.5] {
                    for (bounce, hz, ring_s) in [(0.0, 1.0, 1.0), (0.1, 1.0, 2.0), (0.3, 1.0, 2.0), (0.3, 1.5, 0.5), (0.3, 1.5, 2.0), (0.3, 2.0, 2.0)] {
                        let mut m = SwingMidrange::new();
                        let t0 = period / 4.0 - before_crest;
                        for k in 0..2500 {
                            let (t, since) = (t0 + k as f64 * dt, k as f64 * dt);
                            let ring = bounce * (-since / ring_s).exp() * (tau * hz * since).sin();
                            let w1 = 1000.0 * (1.0 + amplitude * (tau * t / period).sin() + ring);
                            if let Some(x) = m.push(w1, dt, gain) {
                                lowest = lowest.min(x);
                                highest = highest.max(x);
                            }
                        }
                    }
                }
            }
        }
        println!("midrange {lowest:.1}..{highest:.1} kg of 1000");
        assert!(lowest >= 975.0 && highest <= 1025.0, "{lowest}..{highest}");
    }

    #[test]
    fn not_a_number_is_no_reading_and_clear_stops_following() {
        let mut m = SwingMidrange::<f64>::new();
        assert_eq!(m.push(f64::NAN, 0.01, 0.1), None);
        assert!(!m.following());
        m.push(1000.0, 0.01, 0.1);
        assert!(m.following());
        m.clear();
        assert!(!m.following());
    }
}
