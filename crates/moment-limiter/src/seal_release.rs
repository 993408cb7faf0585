//! The seals' release time after a raise, learned from the calibration
//! runs' stops (`crane-sim calibrate`; [`crate::calibration`]).
//!
//! While the boom luffs, the cylinder's seals take the sliding friction
//! s·(a + b·F) out of the piston force (s = +1 raising, −1 lowering). When
//! it stops they release it: the pressure settles to what holds the boom,
//! at a pace that is the seals' own, from at once to never (seals that
//! stick). The limiter takes the last motion's friction off a still boom's
//! force times a share that is 1 when its filtered rate shows the stop and
//! decays as e^(−t/τ) after (t the time since, τ
//! [`crate::cycle::LimiterConfig::seal_release_s`];
//! [`crate::load_estimate`]).
//!
//! **After a raise** the share subtracts the up-friction: a τ longer than
//! the seals' takes off friction that has left the force, and the load
//! reads low. With the configured 0.5 s and seals that release at the stop,
//! the weighing after a raise to 70°–80° on the paid-out rope stayed up to
//! 16 % low for 1–2 s, no rope of the bank read the swing consistently
//! through that dip, and 110 % added 3 s after the stop was cut only
//! 6.0–10.3 s after its take-up (`host-sim` test
//! `a_load_added_at_rest_on_the_paid_out_rope_soon_after_a_raise_*`). So
//! the calibration learns τ after a raise, [`Calibration::seal_release_up_s`](crate::load_estimate::Calibration::seal_release_up_s).
//!
//! **After a lowering** the share adds the down-friction back, and a τ too
//! long reads high: the safe side. Learned there too, the short release of
//! seals that let go at the stop read the load low while the filtered force
//! still held part of the down-friction (the filter's tail: it shows the
//! stop about a second late), and the band at rest in the second
//! formulation of the crane fell from p5 1.000 to 0.998. After a lowering
//! the limiter keeps its configured release.
//!
//! **The fit.** An unloaded run's residual at rest after its raise stops,
//! r = F_meas − F_model(0) (the boom's own force; [`crate::calibration`]),
//! is the offset o and the up-friction the seals still hold. Read by the
//! limiter with a release time τ_j, what is left is
//!
//! e_j = r − o − (a + b·F)·e^(−t/τ_j),
//!
//! and the learner takes the τ_j of [`RELEASE_CANDIDATES_S`] whose Σe_j²
//! over the samples of the first [`RELEASE_WINDOW_S`] after each stop is
//! least: the release the limiter reads these runs best with, the filters'
//! delay of the stop included (the share starts when the filtered rate
//! shows it, as in the limiter, so seals that release over a second read
//! as 0.5 s from there), and no shorter than 0.2 s
//! ([`RELEASE_CANDIDATES_S`]). The offset and the law (a, b) are
//! known only once the runs are over, so the learner keeps, per candidate,
//! the sums of sh, sh·r, sh·F, sh·F·r, sh², sh²·F and sh²·F² (sh =
//! e^(−t/τ_j)) with n, Σr and Σr², and forms Σe_j² from them at the end.
//! The time since the stop is read from the share of the runs' limiter, t =
//! −τ₀·ln(share), τ₀ the release it ran with (the configured one: the runs
//! are read with no calibration).
//!
//! **Observable** when the best candidate leaves at most
//! [`RELEASE_CONTRAST`] of the rms error of the worst: the stops show the
//! friction leaving well above the noise. Otherwise (no rest after the
//! raises, or friction lost in the noise) the calibration holds no release
//! time and the limiter keeps its configured one.

use crane_model::Real;

/// Number of [`RELEASE_CANDIDATES_S`].
pub const RELEASE_CANDIDATES: usize = 13;

/// The seals' release times the learner weighs (s), about 1.5 apart where
/// the reading after a stop depends on it most, up to seals that stay stuck
/// for a minute. None shorter than 0.2 s: when the limiter sees the stop,
/// its force filter (four stages at 1.2 Hz) still holds part of a friction
/// the seals let go at the stop, and lets it go at about that pace. With
/// candidates down to 0.01 s, seals that let go over 0.55 s read as 0.1 s,
/// and the up-friction still in the filtered force read as load at a
/// raise's stop: 9 t raised 55° → 80° in 58 s was cut again there at true u
/// 0.905, before SAE J159's 1/1.1 (`crane-sim campaign --seed 12 --only
/// 8826`).
pub const RELEASE_CANDIDATES_S: [f64; RELEASE_CANDIDATES] =
    [0.2, 0.3, 0.4, 0.5, 0.7, 1.0, 1.5, 2.0, 3.0, 5.0, 10.0, 20.0, 60.0];

/// How long after the limiter sees a stop its samples are read for the
/// release (s).
pub const RELEASE_WINDOW_S: f64 = 10.0;

/// Largest rms error of the best release over that of the worst for the
/// release to be observable (–).
pub const RELEASE_CONTRAST: f64 = 0.5;

/// Number of sums kept per candidate: sh, sh·r, sh·F, sh·F·r, sh², sh²·F,
/// sh²·F².
const SUMS: usize = 7;

/// The sums of the samples at rest after raises' stops (see the module
/// doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReleaseSums<T> {
    n: u32,
    r: T,
    rr: T,
    by_candidate: [[T; SUMS]; RELEASE_CANDIDATES],
}

impl<T: Real> Default for ReleaseSums<T> {
    fn default() -> Self {
        Self::new()
    }
}

impl<T: Real> ReleaseSums<T> {
    /// No samples.
    pub fn new() -> Self {
        let z = T::lit(0.0);
        Self { n: 0, r: z, rr: z, by_candidate: [[z; SUMS]; RELEASE_CANDIDATES] }
    }

    /// Adds a sample at rest `since_stop_s` after the stop was seen: the
    /// residual `r_n` at the true piston force `force_n` (N).
    pub fn add(&mut self, since_stop_s: T, force_n: T, r_n: T) {
        for (sums, tau) in self.by_candidate.iter_mut().zip(RELEASE_CANDIDATES_S) {
            let sh = (-since_stop_s / T::lit(tau)).exp();
            let terms = [sh, sh * r_n, sh * force_n, sh * force_n * r_n, sh * sh, sh * sh * force_n, sh * sh * force_n * force_n];
            for (sum, term) in sums.iter_mut().zip(terms) {
                *sum += term;
            }
        }
        self.n = self.n.saturating_add(1);
        self.r += r_n;
        self.rr += r_n * r_n;
    }

    /// Adds the samples of `other`.
    pub fn merge(&mut self, other: &Self) {
        for (mine, theirs) in self.by_candidate.iter_mut().zip(other.by_candidate.iter()) {
            for (a, b) in mine.iter_mut().zip(theirs) {
                *a += *b;
            }
        }
        self.n = self.n.saturating_add(other.n);
        self.r += other.r;
        self.rr += other.rr;
    }

    /// Σe² of candidate `sums` for the up-friction's law a + b·F and the
    /// offset (see the module doc).
    fn ssr(&self, sums: &[T; SUMS], (a, b): (T, T), offset: T) -> T {
        let [sh, sh_r, sh_f, sh_fr, sh2, sh2_f, sh2_ff] = *sums;
        let n = T::lit(f64::from(self.n));
        let two = T::lit(2.0);
        let plain = self.rr - two * offset * self.r + n * offset * offset;
        let cross = a * (sh_r - offset * sh) + b * (sh_fr - offset * sh_f);
        (plain - two * cross + a * a * sh2 + two * a * b * sh2_f + b * b * sh2_ff).max(T::lit(0.0))
    }
}

/// The release time learned from the rest after the raises' stops.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReleaseFit<T> {
    /// The candidate whose error is least (s).
    pub release_s: T,
    /// The runs' stops show the release (see the module doc).
    pub observable: bool,
    /// Samples at rest after raises' stops.
    pub samples: u32,
    /// The rms error e_j of each candidate of [`RELEASE_CANDIDATES_S`] (N).
    pub rms_n: [T; RELEASE_CANDIDATES],
}

/// The release time that reads the rest after the raises' stops best,
/// given their sums, the up-friction's law (a, b) and the offset (N, –;
/// see the module doc). `None` without samples.
pub fn fit_release<T: Real>(up: &ReleaseSums<T>, law: (T, T), offset: T) -> Option<ReleaseFit<T>> {
    if up.n == 0 {
        return None;
    }
    let n = T::lit(f64::from(up.n));
    let mut rms_n = [T::lit(0.0); RELEASE_CANDIDATES];
    for (rms, sums) in rms_n.iter_mut().zip(up.by_candidate.iter()) {
        *rms = (up.ssr(sums, law, offset) / n).sqrt();
    }
    let (mut best, mut worst) = (0, T::lit(0.0));
    for (j, &e) in rms_n.iter().enumerate() {
        if rms_n.get(best).is_some_and(|&b| e < b) {
            best = j;
        }
        worst = worst.max(e);
    }
    let least = rms_n.get(best).copied().unwrap_or(worst);
    let release_s = T::lit(RELEASE_CANDIDATES_S.get(best).copied().unwrap_or(crate::cycle::DEFAULT_SEAL_RELEASE_S));
    let observable = least.is_finite() && least <= worst * T::lit(RELEASE_CONTRAST);
    Some(ReleaseFit { release_s, observable, samples: up.n, rms_n })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The samples after a raise's stop of seals that release with `tau_s`,
    /// up-friction 5 kN + 0.02·F at the stop, offset 200 N, ±300 N of
    /// deterministic noise, every 10 ms for `rest_s`, the stop seen
    /// `seen_after_s` late.
    fn learned(tau_s: f64, rest_s: f64, seen_after_s: f64) -> ReleaseFit<f64> {
        let (law, force) = ((5_000.0, 0.02), 120_000.0);
        let mut up = ReleaseSums::new();
        for i in 0..(rest_s * 100.0) as u32 {
            let t = f64::from(i) * 0.01;
            let left = if tau_s > 0.0 { (-(t + seen_after_s) / tau_s).exp() } else { 0.0 };
            let noise = 300.0 * (1.7 * f64::from(i)).sin();
            up.add(t, force, 200.0 + (law.0 + law.1 * force) * left + noise);
        }
        fit_release(&up, law, 200.0).unwrap()
    }

    /// Seals that release over half a second, two seconds, or stay stuck,
    /// seen as they stop: the candidate they release with; at once or over
    /// 0.15 s, the shortest candidate, 0.2 s.
    #[test]
    fn the_release_of_the_seals_is_learned() {
        for tau in [0.0, 0.15, 0.5, 2.0, 60.0] {
            let fit = learned(tau, 3.0, 0.0);
            assert!(fit.observable, "{tau}: {fit:?}");
            assert_eq!(fit.release_s, tau.max(0.2), "{tau}: {fit:?}");
        }
    }

    /// Seen 0.3 s after the stop, when a part of the friction has left: a
    /// shorter release reads the friction left best (the limiter's share
    /// starts at 1 when it sees the stop); at once and stuck as before.
    #[test]
    fn a_stop_seen_late_reads_a_shorter_release() {
        for (tau, expect) in [(0.0, 0.2), (0.5, 0.2), (1.0, 0.7), (60.0, 60.0)] {
            let fit = learned(tau, 3.0, 0.3);
            assert!(fit.observable, "{tau}: {fit:?}");
            assert_eq!(fit.release_s, expect, "{tau}: {fit:?}");
        }
    }

    /// Friction lost in the noise (no friction at all): every candidate
    /// reads alike, and the release is not observable.
    #[test]
    fn no_friction_no_release() {
        let mut up = ReleaseSums::new();
        for i in 0..300 {
            up.add(f64::from(i) * 0.01, 120_000.0, 200.0 + 300.0 * (1.7 * f64::from(i)).sin());
        }
        let fit = fit_release(&up, (0.0, 0.0), 200.0).unwrap();
        assert!(!fit.observable, "{fit:?}");
        assert_eq!(fit_release::<f64>(&ReleaseSums::new(), (1.0, 0.0), 0.0), None);
    }
}
