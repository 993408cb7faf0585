//! A load on a held rope of constant length, as a full (large-angle)
//! pendulum hanging from the moving boom tip: its swing and the force its
//! rope puts on the tip ([`crate::static_load`]'s held-rope hypotheses);
//! and the same pendulum on the paid-out rope, whose length follows the
//! tip's height ([`PaidOutRope`]).
//!
//! The tip C = (x_C, y_C) = L·(cos θ, sin θ) from the boom foot (rigid boom;
//! x outward), the load at C + l·(sin φ, −cos φ) (φ from the vertical,
//! positive outward), rope tension T. Newton for the load, projected across
//! and along the rope:
//!
//! l·φ̈ = −g·sin φ − ẍ_C·cos φ − ÿ_C·sin φ,
//! T/m = g·cos φ − ẍ_C·sin φ + ÿ_C·cos φ + l·φ̇²,
//!
//! with ẍ_C = −L·(sin θ·θ̈ + cos θ·θ̇²), ÿ_C = L·(cos θ·θ̈ − sin θ·θ̇²). The
//! rope pulls the tip with T·(sin φ, −cos φ); about the boom foot its
//! moment is that of a hanging weight m·g times
//!
//! factor = (T/(m·g))·(cos φ + tan θ·sin φ),
//!
//! which is 1 for a load hanging still and includes the load riding up and
//! down with the tip (ÿ_C) and the swing's twice-per-period pull (at 25° of
//! swing T·cos φ varies by ±19 %, which the small-angle model misses). It is
//! integrated with the symplectic Euler rule in sub-steps of at most
//! [`MAX_SUB_STEP_S`] (one per cycle at 100 Hz), at most [`MAX_SUB_STEPS`]
//! per call.
//!
//! ## The boom's give
//!
//! The tip is not rigid: the rope's horizontal pull W·g·sin φ bends the boom
//! and moves the tip outward by c·sin²θ·W·g·sin φ (c the tip's compliance
//! across the boom, [`crate::swing::SwingGeometry::give_m`]; the boom's
//! first bending mode, 4 Hz, follows the swing quasi-statically). The load
//! then sits l·sin φ + give·sin φ from the tip's unloaded place, and
//! Newton across the rope reads (l + give)·φ̈ = −g·sin φ: the loaded rope
//! swings as a rigid one longer by the give. On the COLES 930 that is
//! 2.7 mm per kN of load at 70° (0.29 m under 11 t): a 3 m rope swings
//! 4.7 % slower, a quarter of a period off within six swings. The give is
//! applied at rest ([`HeldRopes::set_give`], and the paid-out rope's
//! length), where the free swing's period is all that keeps a pendulum in
//! phase with the load; in motion the tip's give is one of several
//! flexible-boom effects the rigid tip leaves out (its bending under the
//! ride-up, the bounce), and giving it alone there changed which short
//! rope could weigh at the start of a lowering from 80° and read the load
//! up to 4 % higher for seconds (`crate::static_load`).

use crane_model::Real;

/// The largest swing a pendulum follows (rad, 60°); beyond, or on a
/// non-finite state, it restarts with the load hanging still.
const MAX_SWING_RAD: f64 = 1.047;

/// (sin x, cos x) for |x| ≤ [`MAX_SWING_RAD`] by their Taylor polynomials
/// to x¹¹ and x¹² (Horner in x²): no range reduction and no branch, so the
/// ropes of a bank evaluate it side by side. The series' remainder at
/// |x| = 1.047 is below 3e-10 (x¹³/13!), far under f32's rounding (test
/// `small_angle_sin_cos_matches_f64`). Only for the clamped swing angle:
/// outside the range it loses accuracy as x¹³/13!.
fn sin_cos_swing<T: Real>(x: T) -> (T, T) {
    let z = x * x;
    let c = |v: f64| T::lit(v);
    let s = x
        * (c(1.0)
            + z * (c(-1.0 / 6.0)
                + z * (c(1.0 / 120.0)
                    + z * (c(-1.0 / 5_040.0) + z * (c(1.0 / 362_880.0) + z * c(-1.0 / 39_916_800.0))))));
    let k = c(1.0)
        + z * (c(-0.5)
            + z * (c(1.0 / 24.0)
                + z * (c(-1.0 / 720.0)
                    + z * (c(1.0 / 40_320.0)
                        + z * (c(-1.0 / 3_628_800.0) + z * c(1.0 / 479_001_600.0))))));
    (s, k)
}

/// Longest sub-step of the pendulum's integration (s). The symplectic Euler
/// rule runs a free pendulum at (2/h)·asin(ω·h/2) instead of ω: with the
/// shortest rope of the bank (3 m, ω = 1.81 rad/s) and h = 10 ms that is
/// 1.4e-5 fast, 1.2 ms of phase over an hour-long swing, far below the 12 %
/// between neighbouring ropes of the bank. At 100 Hz one sub-step per cycle.
pub const MAX_SUB_STEP_S: f64 = 0.010;

/// Most sub-steps per update (a 4 s gap at [`MAX_SUB_STEP_S`]; a longer gap
/// takes longer sub-steps, still stable while ω·h < 2).
pub const MAX_SUB_STEPS: u32 = 400;

/// What every pendulum on one boom needs from the boom's motion over an
/// update, computed once for a bank of them ([`BoomTip::new`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoomTip<T> {
    /// The tip's horizontal acceleration ẍ_C (m/s²).
    pub accel_x: T,
    /// The tip's vertical acceleration ÿ_C (m/s²).
    pub accel_y: T,
    /// The tip's vertical velocity ẏ_C (m/s): the paid-out rope's l̇.
    pub rate_y: T,
    /// tan θ of the boom angle.
    pub tan_angle: T,
    /// Number of sub-steps (≥ 1).
    pub sub_steps: u32,
    /// Length of each sub-step (s).
    pub h_s: T,
}

impl<T: Real> BoomTip<T> {
    /// The tip's motion for a boom of `boom_length_m` whose angle has
    /// (sin θ, cos θ) = `trig`, with rate and acceleration (rad/s, rad/s²)
    /// held over a step of `dt_s` (a non-finite or negative step counts 0).
    pub fn new((s, c): (T, T), boom_length_m: T, rate_rad_s: T, accel_rad_s2: T, dt_s: T) -> Self {
        let w2 = rate_rad_s * rate_rad_s;
        let dt = if dt_s.is_finite() && dt_s > T::lit(0.0) {
            dt_s
        } else {
            T::lit(0.0)
        };
        // The count by a bounded loop (no libm ceil in the cycle); at
        // 100 Hz it stops at once.
        let sub = T::lit(MAX_SUB_STEP_S);
        let mut n = 1u32;
        while n < MAX_SUB_STEPS && T::from_count(n) * sub < dt {
            n += 1;
        }
        Self {
            accel_x: -boom_length_m * (s * accel_rad_s2 + c * w2),
            accel_y: boom_length_m * (c * accel_rad_s2 - s * w2),
            rate_y: boom_length_m * c * rate_rad_s,
            tan_angle: s / c,
            sub_steps: n,
            h_s: dt / T::from_count(n),
        }
    }
}

/// φ̈ of one rope (see the module doc and [`PaidOutRope`]): gravity `g`, the
/// tip's motion, (sin φ, cos φ), 1/l, and l̇ (0 for a held rope) with φ̇.
#[inline(always)]
fn swing_accel<T: Real>(g: T, tip: &BoomTip<T>, (sp, cp): (T, T), inv_l: T, length_rate: T, phi_dot: T) -> T {
    -(g * sp + tip.accel_x * cp + tip.accel_y * sp + T::lit(2.0) * length_rate * phi_dot) * inv_l
}

/// One rope after its sub-steps: back to hanging still beyond the largest
/// swing followed or on a non-finite state (a select, not a branch, so the
/// lanes of [`HeldRopes`] stay in step; `&`, not `&&`), then
/// (sin φ, cos φ) and the factor of its pull, with T/m from the module doc
/// less l̈ `length_accel` (0 for a held rope). Returns (φ, φ̇, sin φ, cos φ,
/// factor).
#[inline(always)]
fn settle_and_pull<T: Real>(
    (phi, phi_dot): (T, T),
    length_m: T,
    length_accel: T,
    (g, inv_g): (T, T),
    tip: &BoomTip<T>,
) -> (T, T, T, T, T) {
    let ok = phi.is_finite() & phi_dot.is_finite() & (phi.abs() <= T::lit(MAX_SWING_RAD));
    let zero = T::lit(0.0);
    let (phi, phi_dot) = if ok { (phi, phi_dot) } else { (zero, zero) };
    let (sp, cp) = sin_cos_swing(phi);
    let tension = g * cp - tip.accel_x * sp + tip.accel_y * cp - length_accel + length_m * phi_dot * phi_dot;
    (phi, phi_dot, sp, cp, tension * inv_g * (cp + tip.tan_angle * sp))
}

/// A free swing (φ, φ̇) of a pendulum driven through a first-order lag τ,
/// with that lag undone: (1 + τ·d/dt) on φ and on φ̇, φ̈ = −(g/l)·sin φ
/// for a still tip. A pendulum is linear in its drive, so one driven by the
/// lagged boom angle swings as the true one seen through the lag: at the
/// swing's ω, amplitude 1/√(1 + ω²τ²) and phase −atan(ωτ) (0.93 and 21°
/// for a 6 m rope behind a 0.3 s sensor), and the lead restores both. A
/// rotation by ωτ restored the phase only: the rope read 7 % too little
/// swing, and a load added at rest behind a 0.3 s sensor was seen after
/// 3.7 s instead of 0.8 s.
#[inline(always)]
fn lead_swing<T: Real>((phi, phi_dot): (T, T), sin_phi: T, g_over_l: T, lead_s: T) -> (T, T) {
    (phi + lead_s * phi_dot, phi_dot - lead_s * g_over_l * sin_phi)
}

/// The tip of a still boom at tan θ = `tan_angle`: what a free swing pulls
/// against.
fn still_tip<T: Real>(tan_angle: T) -> BoomTip<T> {
    let zero = T::lit(0.0);
    BoomTip { accel_x: zero, accel_y: zero, rate_y: zero, tan_angle, sub_steps: 1, h_s: zero }
}

/// The pendulums of `N` hanging lengths on one boom, stored as arrays (one
/// per quantity) and advanced together: every step is the same arithmetic on
/// every rope with no branch, so on the host the compiler runs four ropes at
/// once in SIMD lanes; on the controller it is one loop.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HeldRopes<T, const N: usize> {
    length_m: [T; N],
    /// How much longer than its rope each pendulum swings (m; see "The
    /// boom's give" in the module doc).
    give_m: T,
    /// 1/g: the pull's factor multiplies.
    inv_gravity: T,
    gravity_m_s2: T,
    /// φ and φ̇ of each rope (rad, rad/s).
    phi: [T; N],
    phi_dot: [T; N],
    /// sin φ and cos φ of `phi`, kept because the next update's first
    /// sub-step and [`Self::tan_swing`] need them again: at 100 Hz one
    /// evaluation per rope and update.
    sin_phi: [T; N],
    cos_phi: [T; N],
    factor: [T; N],
}

impl<T: Real, const N: usize> HeldRopes<T, N> {
    /// Loads hanging still on ropes of `lengths_m`, gravity `gravity_m_s2`.
    pub fn new(lengths_m: [T; N], gravity_m_s2: T) -> Self {
        Self {
            length_m: lengths_m,
            give_m: T::lit(0.0),
            inv_gravity: T::lit(1.0) / gravity_m_s2,
            gravity_m_s2,
            phi: [T::lit(0.0); N],
            phi_dot: [T::lit(0.0); N],
            sin_phi: [T::lit(0.0); N],
            cos_phi: [T::lit(1.0); N],
            factor: [T::lit(1.0); N],
        }
    }

    /// The factor of each rope's pull with a sensor lag of `lead_s` (s)
    /// undone (`lead_swing`), the boom still at tan θ = `tan_angle`.
    pub fn led_factors(&self, lead_s: T, tan_angle: T) -> [T; N] {
        let tip = still_tip(tan_angle);
        let (g, zero) = (self.gravity_m_s2, T::lit(0.0));
        let mut out = [T::lit(1.0); N];
        let lanes = self.phi.iter().zip(self.phi_dot.iter()).zip(self.sin_phi.iter());
        for ((f, &l), ((&phi, &phi_dot), &sp)) in out.iter_mut().zip(self.length_m.iter()).zip(lanes) {
            let led = lead_swing((phi, phi_dot), sp, g / (l + self.give_m), lead_s);
            *f = settle_and_pull(led, l, zero, (g, self.inv_gravity), &tip).4;
        }
        out
    }

    /// Lengthens every rope's swing by `give_m` (m, see "The boom's give"
    /// in the module doc; 0 for a rigid tip, a negative or non-finite
    /// value counts 0). The swing itself is kept: a pendulum's length may
    /// change under it.
    pub fn set_give(&mut self, give_m: T) {
        self.give_m = if give_m.is_finite() && give_m > T::lit(0.0) { give_m } else { T::lit(0.0) };
    }

    /// How much longer than its rope each pendulum swings now (m).
    pub fn give_m(&self) -> T {
        self.give_m
    }

    /// The tip moved out by `dx_m` (m) faster than the loads follow: each
    /// load keeps its place and its velocity, so each rope turns in by
    /// dx/(l + give) (small angles: a give of centimetres on ropes of
    /// metres). Call before [`Self::update`], which sets the factors anew.
    pub fn shift_tip(&mut self, dx_m: T) {
        let give = self.give_m;
        let lanes = self.phi.iter_mut().zip(self.sin_phi.iter_mut()).zip(self.cos_phi.iter_mut());
        for (((phi, s), c), &l) in lanes.zip(self.length_m.iter()) {
            *phi -= dx_m / (l + give);
            (*s, *c) = phi.sin_cos_own();
        }
    }

    /// The hanging length of rope `i` (m); `None` past the last rope.
    pub fn length_m(&self, i: usize) -> Option<T> {
        self.length_m.get(i).copied()
    }

    /// tan φ of rope `i` now; `None` past the last rope.
    pub fn tan_swing(&self, i: usize) -> Option<T> {
        Some(*self.sin_phi.get(i)? / *self.cos_phi.get(i)?)
    }

    /// The factor of rope `i`'s pull on the cylinder now (see the module
    /// doc); `None` past the last rope.
    pub fn factor(&self, i: usize) -> Option<T> {
        self.factor.get(i).copied()
    }

    /// Every load hanging still; the next [`Self::update`] starts from
    /// there (its first sub-step reads sin φ = 0; cos φ and the factor it
    /// sets anew).
    pub fn still(&mut self) {
        let zero = T::lit(0.0);
        self.phi = [zero; N];
        self.phi_dot = [zero; N];
        self.sin_phi = [zero; N];
    }

    /// Advances every rope by the boom tip's motion over one update
    /// ([`BoomTip`]).
    pub fn update(&mut self, tip: &BoomTip<T>) {
        let (g, h) = (self.gravity_m_s2, tip.h_s);
        let zero = T::lit(0.0);
        let mut k = 0u32;
        while k < tip.sub_steps {
            // The first sub-step starts from the kept sin φ, cos φ.
            if k > 0 {
                for ((s, c), &phi) in self.sin_phi.iter_mut().zip(self.cos_phi.iter_mut()).zip(self.phi.iter()) {
                    (*s, *c) = phi.sin_cos_own();
                }
            }
            let lanes = self.phi.iter_mut().zip(self.phi_dot.iter_mut());
            let trig = self.sin_phi.iter().zip(self.cos_phi.iter()).zip(self.length_m.iter());
            for ((phi, phi_dot), ((&sp, &cp), &l)) in lanes.zip(trig) {
                // One division per rope and sub-step (one per cycle at 100 Hz):
                // 1/(l + give) kept per rope cost 232 bytes of the board's
                // flash to recompute when the give changes.
                let inv_l = T::lit(1.0) / (l + self.give_m);
                *phi_dot += swing_accel(g, tip, (sp, cp), inv_l, zero, *phi_dot) * h;
                *phi += *phi_dot * h;
            }
            k += 1;
        }
        let lanes = self.phi.iter_mut().zip(self.phi_dot.iter_mut()).zip(self.length_m.iter());
        let out = self.sin_phi.iter_mut().zip(self.cos_phi.iter_mut()).zip(self.factor.iter_mut());
        for (((phi, phi_dot), &l), ((s, c), factor)) in lanes.zip(out) {
            (*phi, *phi_dot, *s, *c, *factor) = settle_and_pull((*phi, *phi_dot), l, zero, (g, self.inv_gravity), tip);
        }
    }
}

/// The paid-out rope (thesis assumption vi): the winch keeps the load at
/// its clearance under the rigid tip, so the hanging length is the tip's
/// height less the clearance, l(θ) = y_A0 + L·sin θ − c, and l̇ = ẏ_C,
/// l̈ = ÿ_C. The held rope's pendulum with the terms of the changing length:
///
/// l·φ̈ = −g·sin φ − ẍ_C·cos φ − ÿ_C·sin φ − 2·l̇·φ̇,
/// T/m = g·cos φ − ẍ_C·sin φ + ÿ_C·(cos φ − 1) + l·φ̇²,
///
/// (hanging straight, the rope paid out cancels the tip's vertical
/// acceleration: the load does not ride), and the same factor
/// (T/(m·g))·(cos φ + tan θ·sin φ). Once the boom stops, the length stops
/// too and the load swings as a pendulum of that length, whose tension
/// varies twice per period (a small-angle observer of the load's
/// horizontal position missed that: after a fast lowering to 7.5° a 24°
/// swing varied the pull by ±14 %, read as load at 1.08 of it).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PaidOutRope<T> {
    gravity_m_s2: T,
    inv_gravity: T,
    phi: T,
    phi_dot: T,
    sin_phi: T,
    cos_phi: T,
    factor: T,
}

impl<T: Real> PaidOutRope<T> {
    /// The load hanging still, gravity `gravity_m_s2`.
    pub fn new(gravity_m_s2: T) -> Self {
        Self {
            gravity_m_s2,
            inv_gravity: T::lit(1.0) / gravity_m_s2,
            phi: T::lit(0.0),
            phi_dot: T::lit(0.0),
            sin_phi: T::lit(0.0),
            cos_phi: T::lit(1.0),
            factor: T::lit(1.0),
        }
    }

    /// tan φ now.
    pub fn tan_swing(&self) -> T {
        self.sin_phi / self.cos_phi
    }

    /// The load hanging still, as [`HeldRopes::still`].
    pub fn still(&mut self) {
        (self.phi, self.phi_dot, self.sin_phi) = (T::lit(0.0), T::lit(0.0), T::lit(0.0));
    }

    /// The factor of the rope's pull on the cylinder now.
    pub fn factor(&self) -> T {
        self.factor
    }

    /// [`HeldRopes::shift_tip`] for this rope, `length_m` long (m, > 0).
    pub fn shift_tip(&mut self, dx_m: T, length_m: T) {
        self.phi -= dx_m / length_m;
        (self.sin_phi, self.cos_phi) = self.phi.sin_cos_own();
    }

    /// The factor of the rope's pull with a sensor lag of `lead_s` (s)
    /// undone (`lead_swing`), the boom still at tan θ = `tan_angle` with
    /// the hanging length `length_m` (m, > 0).
    pub fn led_factor(&self, length_m: T, lead_s: T, tan_angle: T) -> T {
        let g = self.gravity_m_s2;
        let led = lead_swing((self.phi, self.phi_dot), self.sin_phi, g / length_m, lead_s);
        settle_and_pull(led, length_m, T::lit(0.0), (g, self.inv_gravity), &still_tip(tan_angle)).4
    }

    /// Advances by the boom tip's motion over one update, the hanging
    /// length being `length_m` (m, > 0).
    pub fn update(&mut self, tip: &BoomTip<T>, length_m: T) {
        let (g, h) = (self.gravity_m_s2, tip.h_s);
        let inv_l = T::lit(1.0) / length_m;
        let mut k = 0u32;
        while k < tip.sub_steps {
            if k > 0 {
                (self.sin_phi, self.cos_phi) = self.phi.sin_cos_own();
            }
            let trig = (self.sin_phi, self.cos_phi);
            self.phi_dot += swing_accel(g, tip, trig, inv_l, tip.rate_y, self.phi_dot) * h;
            self.phi += self.phi_dot * h;
            k += 1;
        }
        // l̈ = ÿ_C: the paid-out rope cancels the tip's vertical acceleration.
        (self.phi, self.phi_dot, self.sin_phi, self.cos_phi, self.factor) =
            settle_and_pull((self.phi, self.phi_dot), length_m, tip.accel_y, (g, self.inv_gravity), tip);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn small_angle_sin_cos_matches_f64() {
        let (mut worst32, mut worst64) = (0.0f64, 0.0f64);
        for i in -10_000..=10_000 {
            let x = MAX_SWING_RAD * f64::from(i) / 10_000.0;
            let (s, c) = sin_cos_swing(x);
            worst64 = worst64.max((s - x.sin()).abs()).max((c - x.cos()).abs());
            let (s, c) = sin_cos_swing(x as f32);
            let (xs, xc) = ((x as f32) as f64).sin_cos();
            worst32 = worst32.max((f64::from(s) - xs).abs()).max((f64::from(c) - xc).abs());
        }
        assert!(worst64 < 5e-10, "{worst64}");
        assert!(worst32 < 3e-7, "{worst32}"); // sin_cos_f32's bound is 2.4e-7
    }

    #[test]
    fn hanging_still_the_factor_is_one_and_riding_up_adds_the_tip_acceleration() {
        let mut p = HeldRopes::new([8.0_f64], 9.81);
        let th = 40f64.to_radians();
        let update = |p: &mut HeldRopes<f64, 1>, acc: f64, dt: f64| {
            p.update(&BoomTip::new(th.sin_cos(), 19.5, 0.0, acc, dt));
            p.factor(0).unwrap()
        };
        for _ in 0..100 {
            assert!((update(&mut p, 0.0, 0.01) - 1.0).abs() < 1e-12);
        }
        // First instant of an upward angular acceleration: the load is still
        // vertical, its weight grows by ÿ_C/g.
        let f = update(&mut p, 0.1, 1e-6);
        let expect = 1.0 + 19.5 * th.cos() * 0.1 / 9.81;
        assert!((f - expect).abs() < 1e-4, "{f} vs {expect}");
    }

    #[test]
    fn the_paid_out_rope_does_not_ride_with_the_tip_but_a_held_one_does() {
        // The first instant of an upward angular acceleration from rest at
        // 40°: the held load is lifted with the tip (1 + ÿ_C/g), the paid-out
        // one is not (the winch pays the rope out as the tip rises).
        let th = 40f64.to_radians();
        let tip = BoomTip::new(th.sin_cos(), 19.5, 0.0, 0.1, 1e-6);
        let mut held = HeldRopes::new([8.0_f64], 9.81);
        let mut paid = PaidOutRope::new(9.81);
        held.update(&tip);
        paid.update(&tip, 8.0);
        let ride = 19.5 * th.cos() * 0.1 / 9.81;
        assert!((held.factor(0).unwrap() - (1.0 + ride)).abs() < 1e-4);
        assert!((paid.factor() - 1.0).abs() < 1e-9, "{}", paid.factor());
    }

    #[test]
    fn at_a_still_boom_the_paid_out_rope_swings_as_a_held_one() {
        // Released at 25° at a still boom: the length no longer changes, so
        // swing and pull are the held pendulum's of that length, step for step.
        let (l, phi0) = (5.0_f64, 25f64.to_radians());
        let mut held = HeldRopes::new([l], 9.81);
        held.phi = [phi0];
        (held.sin_phi, held.cos_phi) = ([phi0.sin()], [phi0.cos()]);
        let mut paid = PaidOutRope::new(9.81);
        paid.phi = phi0;
        (paid.sin_phi, paid.cos_phi) = phi0.sin_cos();
        let still = BoomTip::new(50f64.to_radians().sin_cos(), 19.5, 0.0, 0.0, 0.01);
        for _ in 0..1000 {
            held.update(&still);
            paid.update(&still, l);
            assert!((held.factor(0).unwrap() - paid.factor()).abs() < 1e-12);
            assert!((held.tan_swing(0).unwrap() - paid.tan_swing()).abs() < 1e-12);
        }
    }

    #[test]
    fn a_swing_driven_through_a_lag_and_led_by_it_is_the_true_one() {
        // A 6 m rope at a boom of 60° accelerated at 0.1 rad/s² for 1 s and
        // stopped over the next; a second rope gets the same motion through
        // a first-order lag of 0.3 s (the angle sensor's). At rest, the
        // lagged rope led by the lag pulls as the true one; unled, it is
        // behind in phase and short in swing.
        let (l, tau, dt, tan) = (6.0_f64, 0.3, 0.01, 60f64.to_radians().tan());
        let trig = (60f64.to_radians().sin(), 60f64.to_radians().cos());
        let (mut truth, mut lagged) = (HeldRopes::new([l], 9.81), HeldRopes::new([l], 9.81));
        let (mut rate, mut lag_rate, mut lag_accel) = (0.0_f64, 0.0_f64, 0.0_f64);
        let (mut led_err, mut unled_err) = (0.0_f64, 0.0_f64);
        for k in 0..1300 {
            let accel = match k {
                0..100 => 0.1,
                100..200 => -0.1,
                _ => 0.0,
            };
            rate += accel * dt;
            lag_rate += (rate - lag_rate) * dt / tau;
            lag_accel += (accel - lag_accel) * dt / tau;
            truth.update(&BoomTip::new(trig, 19.5, rate, accel, dt));
            lagged.update(&BoomTip::new(trig, 19.5, lag_rate, lag_accel, dt));
            if k >= 800 {
                let f = truth.factor(0).unwrap();
                led_err = led_err.max((lagged.led_factors(tau, tan)[0] - f).abs());
                unled_err = unled_err.max((lagged.factor(0).unwrap() - f).abs());
            }
        }
        assert!(unled_err > 0.05, "{unled_err}");
        assert!(led_err < 0.2 * unled_err, "led {led_err} unled {unled_err}");
        // At a still boom the paid-out rope is a held rope of its length.
        let mut paid = PaidOutRope::new(9.81);
        (paid.phi, paid.phi_dot, paid.sin_phi, paid.cos_phi) = (lagged.phi[0], lagged.phi_dot[0], lagged.sin_phi[0], lagged.cos_phi[0]);
        assert!((paid.led_factor(l, tau, tan) - lagged.led_factors(tau, tan)[0]).abs() < 1e-12);
    }

    #[test]
    fn a_rope_with_the_booms_give_swings_as_a_longer_one() {
        // Released at 5° at a still boom: the zero crossings of a 3 m rope
        // given 0.29 m come at the period of a rigid 3.29 m rope, 2π√(l/g)
        // with the small-angle correction (1 + φ0²/16), and the swing is
        // kept when the give is set mid-swing.
        let (l, give, phi0, dt) = (3.0_f64, 0.29, 5f64.to_radians(), 0.001);
        let period = |p: &mut HeldRopes<f64, 1>| {
            let still = BoomTip::new((0.0, 1.0), 19.5, 0.0, 0.0, dt);
            let (mut crossings, mut last) = (Vec::new(), p.phi[0]);
            let mut t = 0.0;
            while crossings.len() < 11 && t < 60.0 {
                p.update(&still);
                t += dt;
                if last < 0.0 && p.phi[0] >= 0.0 {
                    crossings.push(t);
                }
                last = p.phi[0];
            }
            (crossings[10] - crossings[0]) / 10.0
        };
        let released = || {
            let mut p = HeldRopes::new([l], 9.81);
            p.phi = [phi0];
            (p.sin_phi, p.cos_phi) = ([phi0.sin()], [phi0.cos()]);
            p
        };
        let expect = |len: f64| 2.0 * core::f64::consts::PI * (len / 9.81).sqrt() * (1.0 + phi0 * phi0 / 16.0);
        let mut given = released();
        given.set_give(give);
        assert_eq!(given.phi, [phi0], "the swing is kept");
        let (rigid, longer) = (period(&mut released()), period(&mut given));
        assert!((rigid / expect(l) - 1.0).abs() < 1e-3, "{rigid} vs {}", expect(l));
        assert!((longer / expect(l + give) - 1.0).abs() < 1e-3, "{longer} vs {}", expect(l + give));
        // A give that is no length is none.
        for bad in [-0.1, f64::NAN, f64::INFINITY] {
            given.set_give(bad);
            assert_eq!(given.give_m, 0.0, "{bad}");
        }
    }

    #[test]
    fn a_tip_moved_out_swings_the_load_by_as_much_as_it_cannot_follow() {
        // The tip moved out by 4.55 cm on a 3 m rope, as a ramp of `ramp_s`
        // in 10 ms steps at a still boom: the load keeps its place, so the
        // swing left is that of a pendulum whose support moved by a ramp,
        // (dx/l)·|sin(ωT/2)/(ωT/2)|, all of it for a step (ω = √(g/l)).
        let (l, dx, dt) = (3.0_f64, 0.0455, 0.01);
        let w = (9.81 / l).sqrt();
        for ramp_s in [0.0, 0.3, 1.0, 2.0] {
            let mut p = HeldRopes::new([l], 9.81);
            let still = BoomTip::new((0.0, 1.0), 19.5, 0.0, 0.0, dt);
            let steps = ((ramp_s / dt) as usize).max(1);
            let mut amplitude = 0.0f64;
            for k in 0..steps + 800 {
                if k < steps {
                    p.shift_tip(dx / steps as f64);
                    assert_eq!(p.sin_phi[0], p.phi[0].sin_cos_own().0, "kept with φ");
                }
                p.update(&still);
                if k >= steps {
                    amplitude = amplitude.max(p.phi[0].abs());
                }
            }
            let x = w * ramp_s / 2.0;
            let expect = dx / l * if x > 0.0 { (x.sin() / x).abs() } else { 1.0 };
            assert!((amplitude / expect - 1.0).abs() < 0.02, "ramp {ramp_s} s: {amplitude} vs {expect}");
        }
        // Turned in, as the tip moved out: φ < 0 just after a step.
        let mut p = HeldRopes::new([l], 9.81);
        p.shift_tip(dx);
        assert!((p.phi[0] + dx / l).abs() < 1e-15 && p.phi_dot[0] == 0.0);
    }

    #[test]
    fn a_free_swing_keeps_its_period_and_pulls_twice_per_period() {
        // Released at 25° at a still boom at 0° (tan θ = 0): the factor is
        // T·cos φ/(m·g), cos²25° = 0.82 at the ends, 1 + 2(1 − cos 25°)
        // = 1.19 at the bottom.
        let l = 3.0_f64;
        let mut p = HeldRopes::new([l], 9.81);
        p.phi = [25f64.to_radians()];
        (p.sin_phi, p.cos_phi) = ([25f64.to_radians().sin()], [25f64.to_radians().cos()]);
        let (mut lo, mut hi) = (f64::INFINITY, 0.0f64);
        for _ in 0..1000 {
            p.update(&BoomTip::new((0.0, 1.0), 19.5, 0.0, 0.0, 0.01));
            let f = p.factor(0).unwrap();
            lo = lo.min(f);
            hi = hi.max(f);
        }
        assert!((lo - 25f64.to_radians().cos().powi(2)).abs() < 0.01, "{lo}");
        assert!(
            (hi - (3.0 - 2.0 * 25f64.to_radians().cos())).abs() < 0.01,
            "{hi}"
        );
    }
}
