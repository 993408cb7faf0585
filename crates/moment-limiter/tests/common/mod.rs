//! Shared test helpers: a synthetic recorded log of a luffing manoeuvre made
//! with the rigid stand-in model, and a simulated sensor front end.
#![allow(dead_code)]

use crane_model::loads::load_model::{BoomState, HookLoadModel};
use moment_limiter::conversion::SensorConversion;
use moment_limiter::testing::fault_injector::Rng;
use moment_limiter::io::{Channel, InputError, SensorInputs};
use moment_limiter::clock::Ticks;
use moment_limiter::io::Frame;
use moment_limiter::piston_force::p1_bar_for_force;
use moment_limiter::testing::rigid_reference::RigidCrane;

/// One luffing manoeuvre: hold, cycloidal move, hold.
#[derive(Debug, Clone, Copy)]
pub struct Manoeuvre {
    pub load_kg: f64,
    pub from_deg: f64,
    pub to_deg: f64,
    pub move_s: f64,
    pub hold_s: f64,
    pub rate_hz: f64,
    pub friction_up_n: f64,
    pub friction_down_n: f64,
    /// Uniform noise amplitude on pressures (bar) and angle (deg).
    pub noise_bar: f64,
    pub noise_deg: f64,
    pub seed: u32,
}

impl Manoeuvre {
    pub fn new(load_kg: f64, from_deg: f64, to_deg: f64, move_s: f64) -> Self {
        Self {
            load_kg,
            from_deg,
            to_deg,
            move_s,
            hold_s: 1.0,
            rate_hz: 100.0,
            friction_up_n: 0.0,
            friction_down_n: 0.0,
            noise_bar: 0.2,
            noise_deg: 0.02,
            seed: 1,
        }
    }

    /// Boom angle (deg) and rate (deg/s) at time t.
    pub fn angle_at(&self, t: f64) -> (f64, f64) {
        let x = ((t - self.hold_s) / self.move_s).clamp(0.0, 1.0);
        let two_pi = 2.0 * core::f64::consts::PI;
        let s = x - (two_pi * x).sin() / two_pi;
        let ds = if (0.0..1.0).contains(&x) {
            (1.0 - (two_pi * x).cos()) / self.move_s
        } else {
            0.0
        };
        let span = self.to_deg - self.from_deg;
        (self.from_deg + span * s, span * ds)
    }

    pub fn duration_s(&self) -> f64 {
        self.move_s + 2.0 * self.hold_s
    }

    /// Boom angular acceleration (deg/s²) at time t.
    pub fn accel_at(&self, t: f64) -> f64 {
        let x = (t - self.hold_s) / self.move_s;
        let two_pi = 2.0 * core::f64::consts::PI;
        if (0.0..1.0).contains(&x) {
            (self.to_deg - self.from_deg) * two_pi * (two_pi * x).sin()
                / (self.move_s * self.move_s)
        } else {
            0.0
        }
    }

    /// Noise-free pressures (p1, p2) in bar at time t: the stand-in's static
    /// force plus the boom's inertia.
    pub fn pressures_at(&self, model: &RigidCrane<f64>, t: f64) -> (f64, f64) {
        let (deg, rate) = self.angle_at(t);
        let boom = BoomState {
            angle_rad: deg.to_radians(),
            rate_rad_s: rate.to_radians(),
        };
        let inertia = model
            .piston_force_per_boom_accel(boom.angle_rad)
            .expect("stand-in model")
            * self.accel_at(t).to_radians();
        let f = model
            .piston_force_n(boom)
            .expect("stand-in model")
            .at(self.load_kg)
            + inertia;
        let (f, p2) = if rate > 1e-6 {
            (f + self.friction_up_n, 5.0)
        } else if rate < -1e-6 {
            (f - self.friction_down_n, 20.0)
        } else {
            (f, 5.0)
        };
        (p1_bar_for_force(f, p2), p2)
    }

    /// The recorded-style frames (noisy, rounded to 0.01; time to 10 ms).
    pub fn frames(&self) -> Vec<Frame<f64>> {
        let model = RigidCrane::coles_930();
        let mut rng = Rng::new(self.seed);
        let n = (self.duration_s() * self.rate_hz).round() as usize;
        let round = |x: f64| (x * 100.0).round() / 100.0;
        (0..=n)
            .map(|k| {
                let t = k as f64 / self.rate_hz;
                let (deg, _) = self.angle_at(t);
                let (p1, p2) = self.pressures_at(&model, t);
                Frame {
                    t: Ticks::from_millis((t * 100.0).round() as u32 * 10),
                    p1_bar: round(p1 + self.noise_bar * rng.symmetric_unit()),
                    p2_bar: round(p2 + self.noise_bar * rng.symmetric_unit()),
                    boom_angle_deg: round(deg + self.noise_deg * rng.symmetric_unit()),
                }
            })
            .collect()
    }

    /// True utilization (load / rated with safety factor 1.5, 10 t cap) at t.
    pub fn true_utilization(&self, t: f64) -> f64 {
        let model = RigidCrane::coles_930();
        let (deg, _) = self.angle_at(t);
        let j = model
            .jack_reaction_n(BoomState {
                angle_rad: deg.to_radians(),
                rate_rad_s: 0.0,
            })
            .expect("stand-in model");
        let rated = if j.per_kg < 0.0 {
            (-j.at_zero / j.per_kg / 1.5).min(10_000.0)
        } else {
            10_000.0
        };
        self.load_kg / rated
    }
}

/// Simulated ADC: counts for given pressures and angle, with one-count dither
/// so every channel is live (as a real converter is).
pub struct SimSensors {
    pub conversion: SensorConversion<f64>,
    pub p1_bar: f64,
    pub p2_bar: f64,
    pub angle_deg: f64,
    tick: u32,
}

impl SimSensors {
    pub fn new(p1_bar: f64, p2_bar: f64, angle_deg: f64) -> Self {
        Self {
            conversion: SensorConversion::standard(),
            p1_bar,
            p2_bar,
            angle_deg,
            tick: 0,
        }
    }
}

impl SensorInputs for SimSensors {
    fn read_counts(&mut self, channel: Channel) -> Result<u16, InputError> {
        self.tick = self.tick.wrapping_add(1);
        let dither = (self.tick / 3 % 2) as u16;
        let c = &self.conversion;
        Ok(match channel {
            Channel::PistonSidePressure => c.counts_for_pressure(&c.p1, self.p1_bar),
            Channel::RodSidePressure => c.counts_for_pressure(&c.p2, self.p2_bar),
            Channel::BoomAngle => c.angle.counts(self.angle_deg),
        } + dither)
    }
}

/// The time of a frame in seconds (tests only: the limiter never needs it).
#[allow(dead_code)]
pub fn seconds(t: Ticks) -> f64 {
    f64::from(t.micros()) * 1e-6
}
