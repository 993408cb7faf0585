//! The sensor model behind `crane-sim synth`, as a function: simulated samples of
//! a maneuver in, recorded-style log rows out, each with the simulated truth it
//! was made from.
//!
//! `crane-sim synth` writes these rows to a file; the acceptance tests
//! (`host-sim/tests/limiter_acceptance.rs`, through the `host_sim` library)
//! feed them to the limiter in-process, so both see the very same
//! log. This file depends only on `crane_model` and `moment_limiter`.
//!
//! What the limiter's sensors would have recorded on the crane: the simulated
//! piston force plus cylinder friction (higher going up than coming down, the
//! hysteresis of the thesis's measured traces, Figs. 4.2–4.3), split into p1 and
//! p2 by eq. 4.1 with a small rod-side back pressure, transducer noise and the
//! 12-bit quantization of the 4–20 mA front end; the boom angle through an
//! oil-damped pendulum potentiometer (second-order lag) or a first-order lag,
//! with noise, offset and quantization; and the true hook load as the last
//! column. Friction per direction: constant, seal (a + b·|F|) or viscous, and
//! friction held at standstill relaxes with a release time.

use crane_model::multibody::ThesisModel;
use crane_model::sim::integrator::NewtonStart;
use crane_model::sim::simulation::{Maneuver, Program, Sample, SimulationOptions};
use moment_limiter::conversion::SensorConversion;
use moment_limiter::testing::fault_injector::Rng;
use moment_limiter::piston_force::p1_bar_for_force;

/// Header line of a synthesized log (SPEC §5 columns and the true load).
pub const LOG_HEADER: &str = "t_s,p1_bar,p2_bar,boom_angle_deg,true_load_kg";

/// Cylinder friction in one direction of motion, as a force opposing the piston
/// (N), given the simulated piston force `F` (N) and piston speed `v` (m/s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FrictionLaw {
    /// A constant force (N).
    Constant {
        /// Friction force (N).
        force_n: f64,
    },
    /// Seal friction growing with the pressure behind the seal: a + b·|F|.
    Seal {
        /// Force at zero load (N).
        base_n: f64,
        /// Fraction of the piston force (–).
        per_force: f64,
    },
    /// Viscous: a + c·|v| (breakaway plus a force per piston speed).
    Viscous {
        /// Force at the slowest motion (N).
        base_n: f64,
        /// Force per piston speed (N·s/m).
        per_m_s: f64,
    },
    /// Stribeck: the seal breaks away at a higher force than it slides at,
    /// F_s + (F_b − F_s)·exp(−(v/v_s)²).
    Stribeck {
        /// Sliding force, at speeds well above `speed_m_s` (N).
        sliding_n: f64,
        /// Breakaway force, at the slowest motion (N).
        breakaway_n: f64,
        /// Stribeck speed of the piston (m/s).
        speed_m_s: f64,
    },
}

impl FrictionLaw {
    /// The magnitude of the friction force (N, ≥ 0).
    pub fn force_n(&self, piston_force_n: f64, piston_speed_m_s: f64) -> f64 {
        match *self {
            FrictionLaw::Constant { force_n } => force_n,
            FrictionLaw::Seal { base_n, per_force } => base_n + per_force * piston_force_n.abs(),
            FrictionLaw::Viscous { base_n, per_m_s } => base_n + per_m_s * piston_speed_m_s.abs(),
            FrictionLaw::Stribeck { sliding_n, breakaway_n, speed_m_s } => {
                let x = piston_speed_m_s / speed_m_s.max(1e-9);
                sliding_n + (breakaway_n - sliding_n) * (-x * x).exp()
            }
        }
        .max(0.0)
    }
}

/// The pendulum (gravity) angle sensor on the boom.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PendulumSensor {
    /// Oil-damped pendulum potentiometer: x'' = ωn²(θ − x) − 2ζωn·x'.
    SecondOrder {
        /// Natural frequency (Hz).
        hz: f64,
        /// Damping ratio (–).
        damping: f64,
    },
    /// First-order lag τ·x' = θ − x (real pendulums: about 0.1–0.3 s).
    FirstOrder {
        /// Time constant (s).
        tau_s: f64,
    },
}

/// The recording chain: friction, transducers, pendulum, noise.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SensorModel {
    /// Seed of the noise.
    pub seed: u32,
    /// Cylinder friction while raising: the piston force reads higher.
    pub friction_up: FrictionLaw,
    /// Cylinder friction while lowering: the piston force reads lower.
    pub friction_down: FrictionLaw,
    /// Time constant with which friction held at standstill relaxes (s): the seal
    /// stays stuck in the state the motion left it; 0 releases it at once.
    pub standstill_release_s: f64,
    /// Boom rate (°/s) over which the friction turns from one direction's to
    /// the other's: the friction while moving is its law times
    /// tanh(rate / this).
    pub friction_onset_deg_s: f64,
    /// Standard deviation of the pressure noise (bar).
    pub noise_bar: f64,
    /// Standard deviation of the angle noise (deg).
    pub noise_deg: f64,
    /// The angle sensor's dynamics.
    pub pendulum: PendulumSensor,
    /// Offset of the angle sensor (deg, added to the reading).
    pub angle_offset_deg: f64,
    /// Offset of both pressure transducers (bar, added to the readings).
    pub pressure_offset_bar: f64,
    /// Back pressure on the rod side (bar).
    pub rod_side_bar: f64,
    /// Break the p1 loop (0 mA, reads −50 bar) from this time on (s).
    pub open_p1_at_s: Option<f64>,
}

impl SensorModel {
    /// The defaults of `crane-sim synth`: 12 kN up / 8 kN down (constant), released
    /// at once at standstill, 0.3 bar, 0.03°, 2 Hz ζ = 0.7 pendulum, no offsets,
    /// 4 bar back pressure, seed 1.
    pub fn standard() -> Self {
        Self {
            seed: 1,
            friction_up: FrictionLaw::Constant { force_n: 12_000.0 },
            friction_down: FrictionLaw::Constant { force_n: 8_000.0 },
            standstill_release_s: 0.0,
            friction_onset_deg_s: 0.2,
            noise_bar: 0.3,
            noise_deg: 0.03,
            pendulum: PendulumSensor::SecondOrder { hz: 2.0, damping: 0.7 },
            angle_offset_deg: 0.0,
            pressure_offset_bar: 0.0,
            rod_side_bar: 4.0,
            open_p1_at_s: None,
        }
    }
}

/// One row of a synthesized log and the truth behind it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SynthRow {
    /// Time in the log (s).
    pub t_s: f64,
    /// Recorded p1 (bar, quantized).
    pub p1_bar: f64,
    /// Recorded p2 (bar, quantized).
    pub p2_bar: f64,
    /// Recorded pendulum angle (deg, quantized).
    pub boom_angle_deg: f64,
    /// True hook load (kg).
    pub true_load_kg: f64,
    /// The simulated sample this row was made from (true angle, piston force, F_A).
    pub truth: Sample<f64>,
    /// True boom rate (deg/s, backward difference) that set the friction.
    pub true_rate_deg_s: f64,
}

impl SynthRow {
    /// The CSV line (no newline) `crane-sim synth` writes for this row: the
    /// time to the millisecond where it is a whole one, else to the
    /// microsecond (a 300 Hz log stamped to the millisecond would step by 3
    /// and 4 ms by turns).
    pub fn csv_line(&self) -> String {
        let ms = self.t_s * 1e3;
        let t = if (ms - ms.round()).abs() < 1e-6 { format!("{:.3}", self.t_s) } else { format!("{:.6}", self.t_s) };
        format!("{t},{:.3},{:.3},{:.3},{}", self.p1_bar, self.p2_bar, self.boom_angle_deg, self.true_load_kg)
    }
}

/// Simulation options for a log sampled at `rate_hz`; returns them and the
/// sample period (s), exactly 1/`rate_hz`: a whole number of integration
/// steps of at most the default 2 ms. Rates whose period is a multiple of
/// 2 ms (20, 25, 50, 100, 125, 250, 500 Hz) keep the 2 ms step; others take
/// the next shorter step that divides the period (200 Hz: three steps of
/// 1.67 ms). Rounding to 2 ms steps instead gave 166.7 Hz for 200 Hz.
pub fn options_for_rate(rate_hz: f64) -> (SimulationOptions, f64) {
    let mut options = SimulationOptions::for_type::<f64>();
    // Logs need the physics, not the reference iterate: the extrapolated start
    // saves about a fifth of the evaluations (the campaign uses the same).
    options.newton_start = NewtonStart::Extrapolated;
    let period_s = 1.0 / rate_hz;
    // The tolerance keeps an exact multiple (0.01 / 0.002 = 5.000000000000001)
    // at its own count.
    let every = (period_s / options.step_s - 1e-9).ceil().max(1.0) as usize;
    options.output_every = every;
    options.step_s = period_s / every as f64;
    (options, period_s)
}

/// Simulates `maneuver` and collects its samples.
pub fn simulate(
    model: &ThesisModel<f64>,
    maneuver: &Maneuver,
    options: &SimulationOptions,
) -> Result<Vec<Sample<f64>>, crane_model::ModelError> {
    let mut samples = Vec::new();
    model.simulate(maneuver, options, |s| {
        samples.push(*s);
        true
    })?;
    Ok(samples)
}

/// Simulates a program of segments and collects its samples.
pub fn simulate_program(
    model: &ThesisModel<f64>,
    program: &Program,
    options: &SimulationOptions,
) -> Result<Vec<Sample<f64>>, crane_model::ModelError> {
    let mut samples = Vec::new();
    model.simulate_program(program, options, |s| {
        samples.push(*s);
        true
    })?;
    Ok(samples)
}

/// Gaussian-like noise with unit standard deviation (sum of 12 uniforms − 6).
fn gauss(rng: &mut Rng) -> f64 {
    (0..12).map(|_| 0.5 * (rng.symmetric_unit() + 1.0)).sum::<f64>() - 6.0
}

/// The log rows of simulated `samples` (period `dt_s`), preceded by `hold_s`
/// of standstill at the first sample. The true load of every row is the
/// sample's hook load (it grows during a lift-off); `_load_kg` is kept for callers.
pub fn synthesize(
    samples: &[Sample<f64>],
    dt_s: f64,
    hold_s: f64,
    _load_kg: f64,
    sensors: &SensorModel,
) -> Vec<SynthRow> {
    let conv = SensorConversion::<f64>::standard();
    let mut rng = Rng::new(sensors.seed);
    let (mut pend, mut pend_rate) = (
        samples
            .first()
            .map(|s| s.boom_angle_rad.to_degrees())
            .unwrap_or(0.0),
        0.0,
    );
    let hold = (hold_s / dt_s).round() as usize;
    let first = samples.first().copied();
    let rows = first
        .into_iter()
        .cycle()
        .take(hold)
        .map(|s| (s, 0.0))
        .chain(samples.iter().enumerate().map(|(i, s)| {
            let prev = if i == 0 { s } else { &samples[i - 1] };
            (*s, (s.boom_angle_rad - prev.boom_angle_rad).to_degrees() / dt_s)
        }));
    let release = if sensors.standstill_release_s > 0.0 { (-dt_s / sensors.standstill_release_s).exp() } else { 0.0 };
    let mut friction = 0.0f64;
    let mut out = Vec::with_capacity(hold + samples.len());
    for (k, (s, rate_deg_s)) in rows.enumerate() {
        let t = k as f64 * dt_s;
        // Friction while moving follows its law, smoothed over ±onset; what
        // the motion leaves at standstill relaxes with the seal's release time.
        let motion = (rate_deg_s / sensors.friction_onset_deg_s.max(1e-6)).tanh();
        let moving = if motion >= 0.0 {
            sensors.friction_up.force_n(s.reactions.piston_force_n, s.actuator_rate_m_s) * motion
        } else {
            sensors.friction_down.force_n(s.reactions.piston_force_n, s.actuator_rate_m_s) * motion
        };
        friction = moving + (1.0 - motion.abs()) * friction * release;
        let force = s.reactions.piston_force_n + friction;
        let p2 = sensors.rod_side_bar + sensors.noise_bar * gauss(&mut rng);
        let p1 = p1_bar_for_force(force, sensors.rod_side_bar) + sensors.noise_bar * gauss(&mut rng);
        let (p1, p2) = (p1 + sensors.pressure_offset_bar, p2 + sensors.pressure_offset_bar);
        let mut p1q = conv.raw_pressure_bar(&conv.p1, conv.counts_for_pressure(&conv.p1, p1));
        if sensors.open_p1_at_s.is_some_and(|at| t >= at - 1e-9) {
            p1q = conv.p1.bar(0.0);
        }
        let p2q = conv.raw_pressure_bar(&conv.p2, conv.counts_for_pressure(&conv.p2, p2));
        // The angle sensor, 20 sub-steps per sample.
        let truth = s.boom_angle_rad.to_degrees();
        let sub = dt_s / 20.0;
        match sensors.pendulum {
            PendulumSensor::SecondOrder { hz, damping } => {
                let wn = 2.0 * std::f64::consts::PI * hz;
                for _ in 0..20 {
                    let acc = wn * wn * (truth - pend) - 2.0 * damping * wn * pend_rate;
                    pend_rate += acc * sub;
                    pend += pend_rate * sub;
                }
            }
            PendulumSensor::FirstOrder { tau_s } => {
                // Exact discretization of τ·x' = θ − x with θ held over the sample.
                pend = truth + (pend - truth) * (-dt_s / tau_s.max(1e-6)).exp();
            }
        }
        let angle = pend + sensors.angle_offset_deg + sensors.noise_deg * gauss(&mut rng);
        let angle_q = conv.angle.degrees(conv.angle.counts(angle));
        out.push(SynthRow {
            t_s: t,
            p1_bar: p1q,
            p2_bar: p2q,
            boom_angle_deg: angle_q,
            true_load_kg: s.hook_load_kg,
            truth: s,
            true_rate_deg_s: rate_deg_s,
        });
    }
    out
}
