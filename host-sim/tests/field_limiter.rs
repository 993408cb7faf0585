//! Issue 11's tests: the limiter against the field physics of the simulator
//! (issue 10), in process, f64 (model built here) and f32 (the shipped mode
//! constants the controller and `crane-sim replay` run).
//!
//! Every log is made by the code of `crane-sim synth` (`synth_core.rs`) at
//! 100 Hz: the rope `held` with hanging lengths from 3 m to the tip height at
//! the move's lowest angle (less 0.3 m), or `thesis`; friction constant
//! (12 kN up / 8 kN down) or seal (a + b·|F|: 5 kN + 2.5 % up, 3.5 kN + 2 %
//! down); 2 s at rest before the move and 3 s after. Worlds the limiter was
//! not built on check it from outside: a friction growing with the piston's
//! speed, a seal that breaks away at twice its sliding force (Stribeck),
//! seals that stay stuck at standstill, a friction that turns on over
//! ±0.02 °/s or ±1 °/s of boom rate, logs at 200, 50 and 20 Hz, slower or
//! less damped pendulums, three times the sensor noise, a boom 30 % softer
//! or stiffer or otherwise damped than the limiter's model, a
//! lift-off whose bounce is an ideal one of 1–2 Hz instead of the
//! simulator's, a held load bouncing on its rope at 1–2 Hz after every
//! start and stop, held ropes between the rope bank's lengths, the
//! paid-out rope at another clearance, pressure transducers that lag, and a
//! second formulation of the crane: a rigid mechanism by Lagrange's
//! equation with a pendulum of its own, sharing none of the simulator's
//! dynamics (`second_formulation`).
//! The limiter is calibrated
//! from the same crane's unloaded 10 s up and down runs (thesis rope), as
//! `crane-sim calibrate` does, then replays the log. The truth: u = W_true /
//! rated(θ_true) (the limiter's own rating: quasi-static, safety factor 1.5,
//! 10 t cap).
//!
//! Run: `cargo test --release -p host-sim --test field_limiter -- --nocapture`
//! (prints the measured figures per group).

mod common;
mod second_formulation;

use common::{model, rated_kg};
use second_formulation::{Hanging, RigidCrane};
use host_sim::synth_core;

use std::sync::Mutex;

use crane_model::loads::load_model::HookLoadModel;
use crane_model::data::profile::RampShape;
use crane_model::multibody::rope::RopeChoice;
use crane_model::multibody::ThesisModel;
use crane_model::structure::modal::{MeshRefinement, THESIS_BASIS};
use crane_model::sim::simulation::{Direction, Maneuver, Program, Segment};
use crane_model::loads::thesis_modes::thesis_load_model_f32;
use crane_model::Real;
use moment_limiter::calibration::{CalibrationLearner, SteadyMotion};
use moment_limiter::sensor_lag::{fit_sensor, SensorCandidate};
use moment_limiter::clock::Ticks;
use moment_limiter::cycle::{Limiter, LimiterConfig};
use moment_limiter::io::Frame;
use moment_limiter::load_estimate::Calibration;
use moment_limiter::state_machine::LimiterState;
use synth_core::{options_for_rate, simulate, simulate_program, synthesize, FrictionLaw, SensorModel, SynthRow};

/// The logs' sample rate unless a test sets [`LOG_RATE_HZ`] (Hz).
const RATE_HZ: f64 = 100.0;

/// The sample rate of the logs (Hz): [`RATE_HZ`] unless set.
fn rate_hz() -> f64 {
    LOG_RATE_HZ.with(|r| r.get())
}
const HOLD_BEFORE_S: f64 = 2.0;
const HOLD_AFTER_S: f64 = 3.0;


/// The two cylinders of the tests.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Seals {
    /// 12 kN up, 8 kN down (synth's default).
    Constant,
    /// 5 kN + 2.5 %·|F| up, 3.5 kN + 2 %·|F| down.
    Seal,
    /// A law the limiter does not model, growing with the piston's speed:
    /// 6 kN + 60 kN per m/s up, 4 kN + 40 kN per m/s down (about 11 kN and
    /// 7 kN more at the calibration run's speed than at rest).
    Viscous,
    /// A seal that breaks away at twice the force it slides at (Stribeck,
    /// 12 kN sliding up, 8 kN down, the breakaway under a piston speed of
    /// about 20 mm/s; the moves run the piston at 0.03–0.1 m/s, so the
    /// slowest carry 10 % of the difference more than the calibration's).
    Stribeck,
}

/// The two friction laws the limiter models (and the calibration learns).
const SEALS: [Seals; 2] = [Seals::Constant, Seals::Seal];

fn sensors(seals: Seals, seed: u32) -> SensorModel {
    let (up, down) = match seals {
        Seals::Constant => (FrictionLaw::Constant { force_n: 12_000.0 }, FrictionLaw::Constant { force_n: 8_000.0 }),
        Seals::Seal => (
            FrictionLaw::Seal { base_n: 5_000.0, per_force: 0.025 },
            FrictionLaw::Seal { base_n: 3_500.0, per_force: 0.02 },
        ),
        Seals::Viscous => (
            FrictionLaw::Viscous { base_n: 6_000.0, per_m_s: 60_000.0 },
            FrictionLaw::Viscous { base_n: 4_000.0, per_m_s: 40_000.0 },
        ),
        Seals::Stribeck => (
            FrictionLaw::Stribeck { sliding_n: 12_000.0, breakaway_n: 24_000.0, speed_m_s: 0.02 },
            FrictionLaw::Stribeck { sliding_n: 8_000.0, breakaway_n: 16_000.0, speed_m_s: 0.02 },
        ),
    };
    let standard = SensorModel::standard();
    let pendulum = SENSOR_LAG_S.with(|l| l.get()).map_or(standard.pendulum, |tau_s| synth_core::PendulumSensor::FirstOrder { tau_s });
    let angle_offset_deg = ANGLE_OFFSET_DEG.with(|o| o.get());
    let standstill_release_s = STANDSTILL_RELEASE_S.with(|o| o.get());
    let pendulum = PENDULUM_2ND.with(|p| p.get()).map_or(pendulum, |(hz, damping)| synth_core::PendulumSensor::SecondOrder { hz, damping });
    let noise_bar = NOISE_BAR.with(|n| n.get()).unwrap_or(standard.noise_bar);
    let noise_deg = NOISE_DEG.with(|n| n.get()).unwrap_or(standard.noise_deg);
    let friction_onset_deg_s = FRICTION_ONSET_DEG_S.with(|o| o.get());
    SensorModel { seed, friction_up: up, friction_down: down, pendulum, angle_offset_deg, standstill_release_s, friction_onset_deg_s, noise_bar, noise_deg, ..standard }
}

thread_local! {
    /// The angle sensor as a first-order lag of this time constant (s)
    /// instead of synth's standard pendulum, for the lag measurement.
    static SENSOR_LAG_S: std::cell::Cell<Option<f64>> = const { std::cell::Cell::new(None) };
    /// `false`: the calibration keeps the limiter's default lag (the
    /// calibration before the lag was learned), for comparison.
    static LEARN_LAG: std::cell::Cell<bool> = const { std::cell::Cell::new(true) };
    /// The pendulum's zero error (°), which the calibration cannot observe.
    static ANGLE_OFFSET_DEG: std::cell::Cell<f64> = const { std::cell::Cell::new(0.0) };
    /// The time constant (s) with which the friction a motion leaves in the
    /// cylinder relaxes at standstill (synth's default 0: at once).
    static STANDSTILL_RELEASE_S: std::cell::Cell<f64> = const { std::cell::Cell::new(0.0) };
    /// The boom rate (°/s) over which the friction turns (synth's default 0.2).
    static FRICTION_ONSET_DEG_S: std::cell::Cell<f64> = const { std::cell::Cell::new(0.2) };
    /// The logs' sample rate (Hz).
    static LOG_RATE_HZ: std::cell::Cell<f64> = const { std::cell::Cell::new(RATE_HZ) };
    /// The angle sensor as a pendulum of this natural frequency (Hz) and
    /// damping ratio instead of synth's standard one (2 Hz, 0.7).
    static PENDULUM_2ND: std::cell::Cell<Option<(f64, f64)>> = const { std::cell::Cell::new(None) };
    /// The pressure noise's standard deviation (bar) instead of synth's 0.3.
    static NOISE_BAR: std::cell::Cell<Option<f64>> = const { std::cell::Cell::new(None) };
    /// The angle noise's standard deviation (°) instead of synth's 0.03.
    static NOISE_DEG: std::cell::Cell<Option<f64>> = const { std::cell::Cell::new(None) };
    /// The held load bounces on its rope at this natural frequency (Hz) and
    /// damping ratio ([`bounce_on_the_rope`]), besides the simulator's own
    /// bounce on the boom's bending.
    static ROPE_BOUNCE: std::cell::Cell<Option<(f64, f64)>> = const { std::cell::Cell::new(None) };
    /// The pressure transducers read through a first-order lag of this time
    /// constant (s): a snubber (a restrictor that protects the transducer
    /// from spikes) in front of each.
    static PRESSURE_LAG_S: std::cell::Cell<Option<f64>> = const { std::cell::Cell::new(None) };
    /// The paid-out rope keeps its load this high above the ground (m)
    /// instead of the limiter's 1 m: the operator pays out to another
    /// clearance, and the rope is shorter by the difference at every angle.
    static LOAD_CLEARANCE_M: std::cell::Cell<Option<f64>> = const { std::cell::Cell::new(None) };
    /// The simulated crane's boom differs from the limiter's model: Young's
    /// modulus and damping ratio times these factors.
    static BOOM_FACTORS: std::cell::Cell<(f64, f64)> = const { std::cell::Cell::new((1.0, 1.0)) };
    /// The logs' piston force comes from the second formulation
    /// ([`second_formulation`]: a rigid mechanism by Lagrange's equation,
    /// the load a pendulum integrated there), not from the simulator.
    static SECOND_FORMULATION: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
    /// In the second formulation's world, the winch moves a held rope's
    /// hook by this much (m) while the boom luffs ([`Hanging::Winched`]):
    /// up where the rope stays at least [`SHORTEST_WINCHED_M`] long, else
    /// down; negative, down where the load stays [`WINCHED_CLEARANCE_M`]
    /// above the ground, else up.
    static WINCH_M: std::cell::Cell<Option<f64>> = const { std::cell::Cell::new(None) };
    /// The calibration learns from 30 s unloaded runs up and down besides
    /// the 10 s ones (`crane-sim calibrate` given runs at two speeds), its
    /// lag from the 10 s runs alone, as the command does.
    static TWO_SPEEDS: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// The second formulation's crane, built once.
fn rigid_crane() -> &'static RigidCrane {
    static R: std::sync::OnceLock<RigidCrane> = std::sync::OnceLock::new();
    R.get_or_init(RigidCrane::new)
}

/// In the world of [`SECOND_FORMULATION`], replaces the simulator's piston
/// force by the second formulation's for the same prescribed angle, with
/// `rope` resolved as the simulator resolves it. Nothing otherwise.
fn in_the_second_formulation(samples: &mut [crane_model::sim::simulation::Sample<f64>], rope: RopeChoice) {
    if SECOND_FORMULATION.with(|s| s.get()) {
        second_formulation_of(samples, rope);
    }
}

/// Replaces the simulator's piston force in `samples` by the second
/// formulation's for the same prescribed angle, with `rope` resolved as the
/// simulator resolves it (of the crane of [`crane`]).
fn second_formulation_of(samples: &mut [crane_model::sim::simulation::Sample<f64>], rope: RopeChoice) {
    let crane = crane();
    let start = samples.first().map_or(0.0, |s| s.boom_angle_rad);
    let hanging = match rope {
        RopeChoice::Thesis => Hanging::PaidOut { clearance_m: crane.load_clearance_m },
        RopeChoice::Held { length_m } => {
            let length_m = length_m.unwrap_or_else(|| crane.clearance_length_m(start).expect("reach"));
            match WINCH_M.with(|w| w.get()) {
                None => Hanging::Held { length_m },
                Some(d) => Hanging::Winched { length_m, by_m: winch_travel_m(samples, length_m, d) },
            }
        }
    };
    rigid_crane().replace_forces(samples, hanging);
}

/// The shortest rope the winch takes a hook up to (m).
const SHORTEST_WINCHED_M: f64 = 2.0;

/// The least height of the load above the ground the winch lets it down to (m).
const WINCHED_CLEARANCE_M: f64 = 0.5;

/// The winch's travel on a rope of `length_m` over the move of `samples`
/// for the wish `d` of [`WINCH_M`]: `d` (up) if the rope stays long enough,
/// else −|d|; `d` negative, down if the load stays clear of the ground at
/// the move's lowest tip, else |d| up; 0 where neither way fits.
fn winch_travel_m(samples: &[crane_model::sim::simulation::Sample<f64>], length_m: f64, d: f64) -> f64 {
    let lowest_tip = samples.iter().map(|s| rigid_crane().tip(s.boom_angle_rad)[1]).fold(f64::INFINITY, f64::min);
    let up_ok = length_m - d.abs() >= SHORTEST_WINCHED_M;
    let down_ok = lowest_tip - (length_m + d.abs()) >= WINCHED_CLEARANCE_M;
    match (d >= 0.0, up_ok, down_ok) {
        (true, true, _) | (false, true, false) => d.abs(),
        (_, _, true) => -d.abs(),
        _ => 0.0,
    }
}

/// The crane the logs are simulated on: the limiter's own model unless
/// [`BOOM_FACTORS`] makes its boom stiffer, softer or otherwise damped.
fn crane() -> &'static ThesisModel<f64> {
    type Built = Vec<((u64, u64, u64), &'static ThesisModel<f64>)>;
    static BUILT: Mutex<Built> = Mutex::new(Vec::new());
    let (e, d) = BOOM_FACTORS.with(|b| b.get());
    let clearance = LOAD_CLEARANCE_M.with(|c| c.get());
    if (e, d) == (1.0, 1.0) && clearance.is_none() {
        return model();
    }
    let key = (e.to_bits(), d.to_bits(), clearance.map_or(0, f64::to_bits));
    let mut built = BUILT.lock().unwrap();
    if let Some((_, m)) = built.iter().find(|(k, _)| *k == key) {
        return m;
    }
    let mut data = crane_model::CraneData::coles_mobile_930();
    data.boom.youngs_modulus_pa *= e;
    data.boom.damping_ratio *= d;
    if let Some(c) = clearance {
        data.rope.load_clearance_m = c;
    }
    let m = Box::leak(Box::new(ThesisModel::build(&data, MeshRefinement::THESIS, &THESIS_BASIS).expect("model")));
    built.push((key, m));
    m
}

/// The rope of a scenario.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Rope {
    Thesis,
    /// Held, length as a fraction of the way from 3 m (0.0) to the longest (1.0).
    Held(f64),
}

const ROPES: [Rope; 4] = [Rope::Thesis, Rope::Held(0.0), Rope::Held(0.5), Rope::Held(1.0)];

fn rope_choice(rope: Rope, lowest_deg: f64) -> RopeChoice {
    match rope {
        Rope::Thesis => RopeChoice::Thesis,
        Rope::Held(f) => {
            let m = model();
            let top = m.clearance_length_m(lowest_deg.to_radians()).expect("reach") + m.load_clearance_m - 0.3;
            RopeChoice::Held { length_m: Some(3.0 + (top - 3.0) * f) }
        }
    }
}

/// A scenario: the move (or a lift-off alone) and the crane.
#[derive(Debug, Clone, Copy)]
struct Scenario {
    load_kg: f64,
    from_deg: f64,
    to_deg: f64,
    duration_s: f64,
    ramp_s: f64,
    shape: RampShape,
    rope: Rope,
    seals: Seals,
    lift_off_s: Option<f64>,
    seed: u32,
}

impl Scenario {
    fn name(&self) -> String {
        format!(
            "{:.0}->{:.0} {:.0}s {:?} W={:.0} {:?} {:?}{}",
            self.from_deg,
            self.to_deg,
            self.duration_s,
            self.shape,
            self.load_kg,
            self.rope,
            self.seals,
            self.lift_off_s.map_or(String::new(), |l| format!(" lift {l}s"))
        )
    }

    /// A lift-off alone at `angle_deg`: `load_kg` taken up over
    /// `take_up_s` after [`HOLD_BEFORE_S`] at rest, then 6 s at rest.
    fn lift_off(angle_deg: f64, load_kg: f64, rope: Rope, seals: Seals, take_up_s: f64, seed: u32) -> Self {
        Scenario { load_kg, from_deg: angle_deg, to_deg: angle_deg, duration_s: 6.0, ramp_s: 0.0, shape: RampShape::Linear, rope, seals, lift_off_s: Some(take_up_s), seed }
    }

    fn program(&self) -> Program {
        let lowest = self.from_deg.min(self.to_deg);
        let rope = rope_choice(self.rope, lowest);
        if (self.from_deg - self.to_deg).abs() < 1e-9 {
            // A lift-off alone at a fixed angle.
            let mut p = Program::new(self.from_deg, 0.0, rope).unwrap();
            p.push(Segment::Hold { duration_s: HOLD_BEFORE_S }).unwrap();
            p.push(Segment::LiftOff { duration_s: self.lift_off_s.unwrap_or(2.0), load_kg: self.load_kg }).unwrap();
            p.push(Segment::Hold { duration_s: self.duration_s }).unwrap();
            return p;
        }
        let mut m = Maneuver::luff(self.load_kg, self.from_deg, self.to_deg, self.duration_s, self.ramp_s, self.shape).unwrap();
        m.hold_before_s = HOLD_BEFORE_S;
        m.settle_s = HOLD_AFTER_S;
        m.rope = rope;
        m.program().unwrap()
    }

    /// Start of the move and of its constant-velocity part, its end (log time, s).
    fn times(&self) -> (f64, f64, f64, f64) {
        let t0 = HOLD_BEFORE_S;
        (t0, t0 + self.ramp_s, t0 + self.duration_s - self.ramp_s, t0 + self.duration_s)
    }

    fn rows(&self) -> Vec<SynthRow> {
        program_rows(&self.program(), self.seals, self.seed)
    }
}

fn frame<T: Real>(r: &SynthRow) -> Frame<T> {
    Frame {
        // The limiter's integer µs clock, as `crane-sim campaign` feeds it
        // (whole ms; a negative settle time wraps like the clock).
        t: Ticks::from_micros(((r.t_s * 1e3).round() as i64 * 1000) as u32),
        p1_bar: T::lit(r.p1_bar),
        p2_bar: T::lit(r.p2_bar),
        boom_angle_deg: T::lit(r.boom_angle_deg),
    }
}

/// Rest after each calibration run's stop (s), as the campaign's: the
/// seals' release after the up run shows there
/// (`moment_limiter::seal_release`).
const CALIBRATION_REST_AFTER_S: f64 = 5.0;

/// The calibration `crane-sim calibrate` learns from the crane's unloaded 10 s
/// cycloidal up and down runs ([`CALIBRATION_REST_AFTER_S`] at rest after
/// each): the angle sensor's lag first (unless [`LEARN_LAG`] is off: the
/// limiter's default), then the friction law with it, and the seals'
/// release after the raise.
fn calibration_with<T: Real, M: HookLoadModel<T> + Clone>(model_l: &M, seals: Seals) -> Calibration<T> {
    let mut logs = Vec::new();
    let mut runs = vec![(Direction::Up, 11, 10.0), (Direction::Down, 12, 10.0)];
    if TWO_SPEEDS.with(|t| t.get()) {
        runs.extend([(Direction::Up, 13, 30.0), (Direction::Down, 14, 30.0)]);
    }
    for (dir, seed, duration_s) in runs {
        let mut m = Maneuver::thesis(0.0, duration_s, RampShape::Cycloidal, dir).unwrap();
        m.settle_s = CALIBRATION_REST_AFTER_S;
        let (options, dt) = options_for_rate(rate_hz());
        let mut samples = simulate(crane(), &m, &options).expect("simulation");
        in_the_second_formulation(&mut samples, m.rope);
        lag_the_pressures(&mut samples);
        logs.push(synthesize(&samples, dt, 1.0, 0.0, &sensors(seals, seed)));
    }
    let learn = |sensor: SensorCandidate<T>, steady: SteadyMotion<T>, runs: &[Vec<SynthRow>]| {
        let mut learner = CalibrationLearner::with_steady_motion(steady);
        for rows in runs {
            let config = LimiterConfig { angle_sensor_lag_s: sensor.alignment_lag_s(), ..LimiterConfig::standard() };
            let mut lim = Limiter::new(model_l.clone(), config).unwrap();
            let mut pressure_lag = sensor.pressure_lag();
            for r in rows {
                let rep = lim.step_frame(&pressure_lag.apply(frame::<T>(r)));
                if let (None, Some(me)) = (rep.fault, rep.measurement) {
                    learner.observe(model_l, &me).unwrap();
                }
            }
            learner.end_of_log();
        }
        learner
    };
    let default = LimiterConfig::<T>::standard().angle_sensor_lag_s;
    let lag = if LEARN_LAG.with(|l| l.get()) {
        // The 10 s runs, as `crane-sim calibrate` searches the fastest.
        fit_sensor(default, |sensor| Ok::<_, ()>(learn(sensor, SteadyMotion::lag_search(), &logs[..2]).line_ssr())).unwrap().lag.lag_s
    } else {
        default
    };
    let cal = learn(SensorCandidate::first_order(lag), SteadyMotion::standard(), &logs).finish(50).unwrap();
    println!(
        "calibration ({seals:?} seals, sensor {:?} {:?}): lag {lag:.3} s, up {:.0} N + {:.4}·F + {:.0}·ω, down {:.0} N + {:.4}·F + {:.0}·ω, offset {:.0} N, release after a raise {:?} s",
        SENSOR_LAG_S.with(|l| l.get()),
        PENDULUM_2ND.with(|p| p.get()),
        cal.friction_up_n,
        cal.friction_up_per_force,
        cal.friction_up_per_rate,
        cal.friction_down_n,
        cal.friction_down_per_force,
        cal.friction_down_per_rate,
        cal.force_offset_n,
        cal.seal_release_up_s.map(|s| s.to_f64())
    );
    Calibration { angle_sensor_lag_s: Some(lag), ..cal }
}

/// Which limiter: the host's f64 or the controller's f32.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Precision {
    F64,
    F32,
}

/// One replayed sample: log time, true u, estimated/true load, state.
#[derive(Debug, Clone, Copy)]
struct Point {
    t: f64,
    u: f64,
    ratio: f64,
    state: LimiterState,
}

fn replay_with<T: Real, M: HookLoadModel<T> + Clone>(model_l: &M, cal: Calibration<T>, rows: &[SynthRow]) -> Vec<Point> {
    let config = LimiterConfig { calibration: cal, ..LimiterConfig::standard() };
    let mut lim = Limiter::new(model_l.clone(), config).unwrap();
    rows.iter()
        .map(|r| {
            let rep = lim.step_frame(&frame::<T>(r));
            let est = rep.estimate.map_or(f64::NAN, |e| e.load_kg.to_f64());
            Point {
                t: r.t_s,
                u: r.true_load_kg / rated_kg(r.truth.boom_angle_rad),
                ratio: est / r.true_load_kg,
                state: rep.state,
            }
        })
        .collect()
}

/// The crane a calibration is of: its sensor's lag, whether the lag is
/// learned, its friction law, its pendulum's zero error, its seals' release
/// and friction onset, the logs' sample rate, the pendulum's dynamics and
/// the sensors' noise, the boom's stiffness and damping, the load's clearance on
/// the paid-out rope, the pressure transducers' lag, whether the second
/// formulation makes the force and whether the calibration has runs at two
/// speeds.
type CraneKey = (Option<u64>, bool, Seals, [u64; 14]);

fn replay(sc: &Scenario, precision: Precision) -> Vec<Point> {
    replay_rows(&sc.rows(), sc.seals, precision)
}

/// Replays `rows` of a crane with `seals`, calibrated as `crane-sim calibrate`
/// does (each crane once, by its sensor's lag and friction law).
fn replay_rows(rows: &[SynthRow], seals: Seals, precision: Precision) -> Vec<Point> {
    match precision {
        Precision::F64 => replay_with(model(), calibration_f64(seals), rows),
        Precision::F32 => replay_with(&thesis_load_model_f32(), calibration_f32(seals), rows),
    }
}

/// The crane's calibration (see [`calibration_with`]), learned once per crane.
fn cached<T: Copy>(cache: &Mutex<Vec<(CraneKey, T)>>, seals: Seals, make: impl FnOnce() -> T) -> T {
    let p2 = PENDULUM_2ND.with(|p| p.get()).unwrap_or((0.0, 0.0));
    let noise = [NOISE_BAR.with(|n| n.get()).unwrap_or(-1.0), NOISE_DEG.with(|n| n.get()).unwrap_or(-1.0)];
    let boom = BOOM_FACTORS.with(|b| b.get());
    let clearance = LOAD_CLEARANCE_M.with(|c| c.get()).unwrap_or(-1.0);
    let pressure_lag = PRESSURE_LAG_S.with(|l| l.get()).unwrap_or(-1.0);
    let world = [ANGLE_OFFSET_DEG.with(|o| o.get()), STANDSTILL_RELEASE_S.with(|o| o.get()), FRICTION_ONSET_DEG_S.with(|o| o.get()), rate_hz(), p2.0, p2.1, noise[0], noise[1], boom.0, boom.1, clearance, pressure_lag, f64::from(u8::from(SECOND_FORMULATION.with(|s| s.get()))), f64::from(u8::from(TWO_SPEEDS.with(|t| t.get())))].map(f64::to_bits);
    let key = (SENSOR_LAG_S.with(|l| l.get()).map(f64::to_bits), LEARN_LAG.with(|l| l.get()), seals, world);
    if let Some((_, c)) = cache.lock().unwrap().iter().find(|(k, _)| *k == key) {
        return *c;
    }
    let c = make();
    cache.lock().unwrap().push((key, c));
    c
}

/// The f64 limiter's calibration of the crane with `seals`.
fn calibration_f64(seals: Seals) -> Calibration<f64> {
    static C64: Mutex<Vec<(CraneKey, Calibration<f64>)>> = Mutex::new(Vec::new());
    cached(&C64, seals, || calibration_with(model(), seals))
}

/// The f32 limiter's calibration of the crane with `seals`.
fn calibration_f32(seals: Seals) -> Calibration<f32> {
    static C32: Mutex<Vec<(CraneKey, Calibration<f32>)>> = Mutex::new(Vec::new());
    cached(&C32, seals, || calibration_with(&thesis_load_model_f32(), seals))
}

/// First OVERLOAD onset: (time, true u then).
fn first_overload(points: &[Point]) -> Option<(f64, f64)> {
    let mut prev = LimiterState::Normal;
    for p in points {
        if p.state == LimiterState::Overload && prev != LimiterState::Overload {
            return Some((p.t, p.u));
        }
        prev = p.state;
    }
    None
}

/// Lowest true u at any OVERLOAD onset.
fn lowest_onset_u(points: &[Point]) -> Option<f64> {
    let mut prev = LimiterState::Normal;
    let mut lowest: Option<f64> = None;
    for p in points {
        if p.state == LimiterState::Overload && prev != LimiterState::Overload {
            lowest = Some(lowest.map_or(p.u, |l: f64| l.min(p.u)));
        }
        prev = p.state;
    }
    lowest
}

/// Whether the limiter cuts the moment-increasing motions at `q`: OVERLOAD
/// or FAULT.
fn cut(q: &Point) -> bool {
    matches!(q.state, LimiterState::Overload | LimiterState::Fault)
}

/// The samples at a true u of 1.05 or more that are not [`cut`]: a cut that
/// came late or was released.
fn uncut(points: &[Point]) -> impl Iterator<Item = &Point> {
    points.iter().filter(|q| q.u >= 1.05 && !cut(q))
}

/// The lowering bounds on the replay `points` of case `name`: an OVERLOAD
/// onset before true u = 1/1.1, and the first sample at a true u ≥ 1.05
/// that is not [`cut`] (late or released). Prints the lowest onset.
fn lowering_bound_failures(name: &str, points: &[Point]) -> Vec<String> {
    let onset = lowest_onset_u(points);
    println!("{name:<66} lowest OVERLOAD onset at true u {}", onset.map_or("none".into(), |u| format!("{u:.3}")));
    let early = onset.filter(|&u| u < 1.0 / 1.1).map(|u| format!("{name}: OVERLOAD at true u {u:.3}"));
    let late = uncut(points).next().map(|q| format!("{name}: {:?} at {:.2} s, true u {:.3}", q.state, q.t, q.u));
    early.into_iter().chain(late).collect()
}

/// From when on `ok` holds to the end of `after` (s after `since_s`);
/// `None` when it does not hold at the end.
fn held_from(after: &[&Point], since_s: f64, ok: impl Fn(&Point) -> bool) -> Option<f64> {
    match after.iter().rposition(|q| !ok(q)) {
        None => Some(0.0),
        Some(i) => after.get(i + 1).map(|q| q.t - since_s),
    }
}

/// The log of `program` at [`RATE_HZ`], on the crane with `seals` and the
/// noise draw `seed`.
fn program_rows(program: &Program, seals: Seals, seed: u32) -> Vec<SynthRow> {
    let (options, dt) = options_for_rate(rate_hz());
    let mut samples = simulate_program(crane(), program, &options).expect("simulation");
    in_the_second_formulation(&mut samples, program.rope);
    if let (Some(bounce), RopeChoice::Held { .. }) = (ROPE_BOUNCE.with(|b| b.get()), program.rope) {
        bounce_on_the_rope(&mut samples, bounce);
    }
    lag_the_pressures(&mut samples);
    synthesize(&samples, dt, 0.0, 0.0, &sensors(seals, seed))
}

/// A world whose pressure transducers lag (see [`PRESSURE_LAG_S`]): the
/// piston force they read follows the cylinder's through a first-order lag
/// (exact for a force held over each step). The friction, added after, is
/// not lagged. Nothing when the setting is unset.
fn lag_the_pressures(samples: &mut [crane_model::sim::simulation::Sample<f64>]) {
    let Some(tau_s) = PRESSURE_LAG_S.with(|l| l.get()) else {
        return;
    };
    let mut lagged: Option<(f64, f64)> = None;
    for x in samples.iter_mut() {
        let f = x.reactions.piston_force_n;
        let y = match lagged {
            Some((t, y)) => f + (y - f) * (-(x.t_s - t) / tau_s).exp(),
            None => f,
        };
        lagged = Some((x.t_s, y));
        x.reactions.piston_force_n = y;
    }
}

/// A world whose held load bounces on its rope (see [`ROPE_BOUNCE`]): the
/// load hangs from the tip on a spring of natural frequency `hz` and
/// damping ratio `zeta`, so against the simulator's rigid rope its pull
/// changes by ΔT = −W·ë, where the spring's stretch e answers the tip's
/// vertical acceleration a = L·(cos θ·θ̈ − sin θ·θ̇²) (L the boom's length):
/// ë + 2ζω·ė + ω²·e = a. The piston force changes by ΔT/g times the model's
/// force per kg of hook load at the sample's angle and load. The starts and
/// stops of a move excite it; a still boom does not.
fn bounce_on_the_rope(samples: &mut [crane_model::sim::simulation::Sample<f64>], (hz, zeta): (f64, f64)) {
    let length_m = crane_model::CraneData::coles_mobile_930().boom.length_m();
    let w = 2.0 * std::f64::consts::PI * hz;
    let tip_y: Vec<f64> = samples.iter().map(|x| length_m * x.boom_angle_rad.sin()).collect();
    let (mut e, mut v) = (0.0f64, 0.0f64);
    for i in 1..samples.len().saturating_sub(1) {
        let (t0, t1, t2) = (samples[i - 1].t_s, samples[i].t_s, samples[i + 1].t_s);
        // The tip's vertical acceleration over the step to the next sample,
        // from the rigid boom angle (prescribed, smooth).
        let accel = 2.0 * ((tip_y[i + 1] - tip_y[i]) / (t2 - t1) - (tip_y[i] - tip_y[i - 1]) / (t1 - t0)) / (t2 - t0);
        // Ten semi-implicit Euler steps per sample: ω·h ≤ 0.013 at 2 Hz.
        let steps = 10;
        let h = (t2 - t1) / f64::from(steps);
        let mut e_dd = 0.0;
        for _ in 0..steps {
            e_dd = accel - 2.0 * zeta * w * v - w * w * e;
            v += e_dd * h;
            e += v * h;
        }
        let x = &mut samples[i + 1];
        let load_kg = x.hook_load_kg;
        x.reactions.piston_force_n += force_per_kg(x.boom_angle_rad, load_kg) * load_kg * (-e_dd) / 9.81;
        BOUNCE_PEAK.with(|p| p.set(p.get().max(e_dd.abs() / 9.81)));
    }
}

/// The model's piston force per kg more of hook load (N/kg) at rest at
/// `angle_rad` with `load_kg` on the hook: how a change of the rope's pull
/// reaches the cylinder.
fn force_per_kg(angle_rad: f64, load_kg: f64) -> f64 {
    model()
        .piston_force_n(crane_model::loads::load_model::BoomState { angle_rad, rate_rad_s: 0.0 })
        .map(|q| q.per_kg + 2.0 * q.per_kg2 * load_kg)
        .expect("model")
}

/// A load taken up on a rope that rings: the rope's pull y (kg of hook
/// load) follows the hook load W(t) as a spring-mass of natural frequency
/// `hz` and damping ratio `zeta` does, ÿ + 2ζω·ẏ + ω²·(y − W) = 0, so a
/// load taken up in less than a period overshoots and rings about the new
/// one. The piston force changes by y − W times the model's force per kg
/// of hook load at the sample's angle and load; W, the static hook mass,
/// stays the true load.
fn ring_the_take_up(samples: &mut [crane_model::sim::simulation::Sample<f64>], (hz, zeta): (f64, f64)) {
    let w = 2.0 * std::f64::consts::PI * hz;
    let Some(first) = samples.first() else {
        return;
    };
    let (mut y, mut v, mut t) = (first.hook_load_kg, 0.0f64, first.t_s);
    for x in samples.iter_mut().skip(1) {
        // Ten semi-implicit Euler steps per sample, W held over the step.
        let steps = 10;
        let h = (x.t_s - t) / f64::from(steps);
        for _ in 0..steps {
            v += (-2.0 * zeta * w * v - w * w * (y - x.hook_load_kg)) * h;
            y += v * h;
        }
        t = x.t_s;
        x.reactions.piston_force_n += force_per_kg(x.boom_angle_rad, x.hook_load_kg) * (y - x.hook_load_kg);
    }
}

thread_local! {
    /// The largest |ë|/g [`bounce_on_the_rope`] has added: the bounce's
    /// share of the load's pull.
    static BOUNCE_PEAK: std::cell::Cell<f64> = const { std::cell::Cell::new(0.0) };
}

fn percentile(v: &mut [f64], q: f64) -> f64 {
    v.sort_by(f64::total_cmp);
    if v.is_empty() {
        return f64::NAN;
    }
    v[((v.len() - 1) as f64 * q).round() as usize]
}

fn thesis_moves() -> Vec<(f64, f64, f64, f64, RampShape)> {
    let mut v = Vec::new();
    for (dur, ramp) in [(10.0, 1.0), (30.0, 1.5)] {
        for (a, b) in [(40.0, 80.0), (80.0, 40.0)] {
            for shape in [RampShape::Linear, RampShape::Cycloidal] {
                v.push((a, b, dur, ramp, shape));
            }
        }
    }
    v
}

/// Replays every scenario of `cases` (printing its highest estimated u and
/// OVERLOAD samples) and returns those with an OVERLOAD, and the highest
/// estimated u of all: the check of every "no OVERLOAD at 85 %" test.
fn false_overloads(precision: Precision, cases: impl IntoIterator<Item = Scenario>) -> (Vec<String>, f64) {
    let (mut failures, mut worst) = (Vec::new(), 0.0f64);
    for sc in cases {
        let pts = replay(&sc, precision);
        let peak = pts.iter().map(|p| p.ratio * p.u).fold(0.0, f64::max);
        worst = worst.max(peak);
        let n = pts.iter().filter(|p| p.state == LimiterState::Overload).count();
        println!("{:<60} peak estimated u {peak:.3}, OVERLOAD samples {n}", sc.name());
        if let Some((t, u)) = first_overload(&pts) {
            failures.push(format!("{} OVERLOAD at {t:.2} s, true u {u:.3} (highest estimated u {peak:.3})", sc.name()));
        }
    }
    (failures, worst)
}

/// The 85 % moves of `moves` (from, to, duration, ramp, shape): 85 % of the
/// rated load at 40°, each of `ropes` and `seals_of`.
fn moves_at_85_percent(moves: Vec<(f64, f64, f64, f64, RampShape)>, ropes: &[Rope], seals_of: &[Seals]) -> Vec<Scenario> {
    let w = 0.85 * rated_kg(40f64.to_radians());
    let mut out = Vec::new();
    for (a, b, dur, ramp, shape) in moves {
        for &rope in ropes {
            for &seals in seals_of {
                out.push(Scenario { load_kg: w, from_deg: a, to_deg: b, duration_s: dur, ramp_s: ramp, shape, rope, seals, lift_off_s: None, seed: 7 });
            }
        }
    }
    out
}

/// No OVERLOAD while the true static utilization stays ≤ 0.85: every thesis
/// move (10 s, 30 s; up, down; linear, cycloidal) at 85 % of the rated load
/// at 40°, every rope, both friction laws.
fn no_false_overload(precision: Precision, ropes: &[Rope], seals_of: &[Seals]) {
    let (failures, worst) = false_overloads(precision, moves_at_85_percent(thesis_moves(), ropes, seals_of));
    println!("{precision:?}: {} false OVERLOADs of {}; highest estimated u {worst:.3}", failures.len(), 8 * ropes.len() * seals_of.len());
    assert!(failures.is_empty(), "{failures:#?}");
}

/// [`no_false_overload`] over other ranges than the thesis's 40°–80°: for
/// each (lo, hi) of `ranges` 85 % of the load rated at lo, moved lo → hi and
/// back in 10 s and 30 s, linear and cycloidal ramps, every rope, both
/// friction laws (the true u is highest, 0.85, at lo). Returns the cases
/// with an OVERLOAD and the highest estimated u.
fn no_false_overload_over(precision: Precision, ranges: &[(f64, f64)]) -> (Vec<String>, f64) {
    let mut cases = Vec::new();
    for &(lo, hi) in ranges {
        let w = 0.85 * rated_kg(lo.to_radians());
        for (a, b) in [(lo, hi), (hi, lo)] {
            for (dur, ramp) in [(10.0, 1.0), (30.0, 1.5)] {
                for shape in [RampShape::Linear, RampShape::Cycloidal] {
                    for rope in ROPES {
                        for seals in SEALS {
                            cases.push(Scenario { load_kg: w, from_deg: a, to_deg: b, duration_s: dur, ramp_s: ramp, shape, rope, seals, lift_off_s: None, seed: 7 });
                        }
                    }
                }
            }
        }
    }
    let (failures, worst) = false_overloads(precision, cases);
    println!("{precision:?}, ranges {ranges:?}: {} false OVERLOADs of {}; highest estimated u {worst:.3}", failures.len(), ranges.len() * 64);
    (failures, worst)
}

/// No OVERLOAD at 85 % over 20°–60°, 10°–50°, 5°–30° and 30°–85° (f64; the
/// 10 s and 30 s moves, every rope). Measured: highest estimated u 0.931,
/// but for the 3 m rope raised 30° → 85°, whose swing takes p1 out of range:
/// it reads up to 1.538 during that FAULT (which cuts), 0.893 outside it.
#[test]
fn no_false_overload_at_85_percent_over_other_ranges() {
    let (failures, _) = no_false_overload_over(Precision::F64, &[(20.0, 60.0), (10.0, 50.0), (5.0, 30.0), (30.0, 85.0)]);
    assert!(failures.is_empty(), "{failures:#?}");
}

/// 85 % of the load rated at 50° raised to 85° in 10 s and 30 s, every rope,
/// both friction laws (f64 and f32): no OVERLOAD. Stopped at 85° (tan θ =
/// 11.4) on the 3 m held rope the load swings ±24°, its pull on the cylinder
/// runs from −4 to +6 times its weight (the simulator's rigid rope; a real
/// one goes slack, and the load would strike a boom 5° off vertical), and p1
/// leaves its range at the swing's crests (FAULT for 1.4 s). Before the
/// angle's side of the signal chain went on through a pressure's fault
/// (`moment_limiter::cycle`, "A pressure's fault"), the rope bank's
/// pendulums stood still through that gap, and after it every rope read the
/// swing as load: OVERLOAD 2.4–2.6 s after the stop at a true u of 0.62
/// (estimated up to 1.40) in 4 of the 64 cases. Now they swing on with the
/// boom, and the force, restarted after the gap, is no reading until its
/// filters have settled (they would set it beside pendulums of another
/// instant: −1.1 to 1.6 × the load in the first 0.6 s).
fn a_raise_to_85_degrees_on_a_3_m_rope(precision: Precision) {
    let (failures, worst) = no_false_overload_over(precision, &[(50.0, 85.0)]);
    println!("{precision:?}: highest estimated u {worst:.3}");
    assert!(failures.is_empty(), "{failures:#?}");
}

#[test]
fn a_raise_to_85_degrees_on_a_3_m_rope_f64() {
    a_raise_to_85_degrees_on_a_3_m_rope(Precision::F64);
}

#[test]
fn a_raise_to_85_degrees_on_a_3_m_rope_f32() {
    a_raise_to_85_degrees_on_a_3_m_rope(Precision::F32);
}

#[test]
fn no_false_overload_at_85_percent_f64() {
    no_false_overload(Precision::F64, &ROPES, &SEALS);
}

#[test]
fn no_false_overload_at_85_percent_f32() {
    no_false_overload(Precision::F32, &ROPES, &SEALS);
}

/// Lowering past the rated radius: 80° → 20° at the speed of the 10 s and
/// 30 s thesis moves (15 s and 45 s), the loads rated at 45° and at 30°:
/// OVERLOAD never before true u = 1/1.1 and always before 1.05.
fn lowering_past_rated_radius(precision: Precision, ropes: &[Rope], seals_of: &[Seals]) {
    let mut failures = Vec::new();
    for sc in lowering_scenarios(&[(80.0, 20.0, 15.0, 1.0), (80.0, 20.0, 45.0, 1.5)], ropes, seals_of) {
        let pts = replay(&sc, precision);
        let t105 = pts.iter().find(|p| p.u >= 1.05).map(|p| p.t);
        let first = first_overload(&pts);
        let lowest = lowest_onset_u(&pts);
        println!(
            "{:<60} first OVERLOAD at true u {}, lowest onset u {}",
            sc.name(),
            first.map_or("none".into(), |f| format!("{:.3}", f.1)),
            lowest.map_or("none".into(), |l| format!("{l:.3}"))
        );
        match (first, t105) {
            (None, _) => failures.push(format!("{}: no OVERLOAD", sc.name())),
            (Some((t, u)), Some(t105)) if t > t105 => failures.push(format!("{}: OVERLOAD at u {u:.3}, after 1.05", sc.name())),
            _ => {}
        }
        if let Some(l) = lowest {
            if l < 1.0 / 1.1 {
                failures.push(format!("{}: OVERLOAD at true u {l:.3} < 1/1.1", sc.name()));
            }
        }
    }
    println!("{precision:?}: {} failures of {}", failures.len(), 8 * ropes.len() * seals_of.len());
    assert!(failures.is_empty(), "{failures:#?}");
}

/// The lowerings past the rated radius of `moves` (from, to, duration,
/// ramp): the loads rated at 45° and 30°, both ramp shapes, each of `ropes`
/// and `seals_of`.
fn lowering_scenarios(moves: &[(f64, f64, f64, f64)], ropes: &[Rope], seals_of: &[Seals]) -> Vec<Scenario> {
    let mut out = Vec::new();
    for &(from, to, dur, ramp) in moves {
        for rated_at in [45.0f64, 30.0] {
            let w = rated_kg(rated_at.to_radians());
            for shape in [RampShape::Linear, RampShape::Cycloidal] {
                for &rope in ropes {
                    for &seals in seals_of {
                        out.push(Scenario { load_kg: w, from_deg: from, to_deg: to, duration_s: dur, ramp_s: ramp, shape, rope, seals, lift_off_s: None, seed: 9 });
                    }
                }
            }
        }
    }
    out
}

/// [`lowering_past_rated_radius`]'s bounds for lowerings (`moves`: from,
/// to, duration, ramp) other than the thesis's speeds, every rope, both
/// friction laws, both ramp shapes, the loads rated at 45° and 30°. Returns
/// the cases cut before true u = 1/1.1 or with a sample at a true u ≥ 1.05
/// neither OVERLOAD nor FAULT (not cut, late or released); prints every
/// case's lowest onset.
fn lowerings(precision: Precision, moves: &[(f64, f64, f64, f64)]) -> Vec<String> {
    lowerings_on(precision, moves, &ROPES).0
}

/// [`lowerings`] on `ropes`, both friction laws; also returns the lowest
/// true u at an OVERLOAD onset of all of them.
fn lowerings_on(precision: Precision, moves: &[(f64, f64, f64, f64)], ropes: &[Rope]) -> (Vec<String>, f64) {
    let (mut failures, mut lowest) = (Vec::new(), f64::INFINITY);
    for sc in lowering_scenarios(moves, ropes, &SEALS) {
        let pts = replay(&sc, precision);
        lowest = lowest_onset_u(&pts).map_or(lowest, |l| lowest.min(l));
        failures.extend(lowering_bound_failures(&sc.name(), &pts));
    }
    (failures, lowest)
}

/// A logger's dropout in a lowering past the rated radius: the samples of
/// `len` s from `start` s on missing from the 15 s lowerings 80° → 20° of
/// [`lowering_past_rated_radius`] (every rope, both friction laws). The
/// time stamps jump; the jump is a FAULT (which cuts), and the chain
/// bridges it (up to 1 s) or restarts after it. Returns the bound's
/// failures ([`lowering_bound_failures`]) and the highest true u at the
/// first cut (OVERLOAD or FAULT) after the dropout's FAULT has cleared.
/// Replays `rows` of a crane with `seals` without the samples from `start`
/// to `end` (s): a logger's dropout.
fn replay_with_dropout(rows: &[SynthRow], (start, end): (f64, f64), seals: Seals, precision: Precision) -> Vec<Point> {
    let holed: Vec<SynthRow> = rows.iter().filter(|r| !(start..end).contains(&r.t_s)).cloned().collect();
    replay_rows(&holed, seals, precision)
}

fn dropouts_in_lowerings(precision: Precision, dropouts: &[(f64, f64)]) -> (Vec<String>, f64) {
    let (mut failures, mut worst) = (Vec::new(), 0.0f64);
    for sc in lowering_scenarios(&[(80.0, 20.0, 15.0, 1.0)], &ROPES, &SEALS) {
        let rows = sc.rows();
        for &(start, len) in dropouts {
            let pts = replay_with_dropout(&rows, (start, start + len), sc.seals, precision);
            let name = format!("{} without {start}..{:.2} s", sc.name(), start + len);
            failures.extend(lowering_bound_failures(&name, &pts));
            // The first cut after the dropout's FAULT cleared (none while
            // the FAULT holds up to the overload: that cut never lifts).
            let cleared = pts.iter().position(|p| p.t > start && !cut(p));
            if let Some(q) = cleared.and_then(|i| pts[i..].iter().find(|p| cut(p))) {
                worst = worst.max(q.u);
            }
        }
    }
    println!("{precision:?}: dropouts {dropouts:?}: {} failures; after the FAULT cleared, cut at true u {worst:.3} at most", failures.len());
    (failures, worst)
}

/// Dropouts of 0.5 s, 0.98 s (bridged) and 2 s (restarted) at 6 s to 14 s
/// of the lowerings: every cut between true u 1/1.1 and 1.05, and where
/// the dropout's FAULT cleared before the overload, the cut comes before
/// true u 1.0. Measured (f64): the lowest OVERLOAD onset at true u 0.956,
/// after a cleared FAULT the cut at true u 0.995 at most. Before the
/// restarted averages started from the weighing kept over the gap
/// (`moment_limiter::static_load`, `restart_averages`), 15 of the 2 s
/// dropouts at 6 s and 9 s (both loads, the thesis rope and the held
/// ropes) were NORMAL or WARNING at true u 1.05, and a cut came at true u
/// 1.153.
fn a_dropout_in_a_lowering_keeps_the_bounds(precision: Precision) {
    let dropouts: Vec<(f64, f64)> = [6.0, 9.0, 10.5, 12.0, 14.0].iter().flat_map(|&s| [(s, 0.5), (s, 0.98), (s, 2.0)]).collect();
    let (failures, worst) = dropouts_in_lowerings(precision, &dropouts);
    assert!(failures.is_empty(), "{failures:#?}");
    assert!(worst < 1.0, "after a cleared FAULT cut at true u {worst:.3}");
}

#[test]
fn a_dropout_in_a_lowering_keeps_the_bounds_f64() {
    a_dropout_in_a_lowering_keeps_the_bounds(Precision::F64);
}

#[test]
fn a_dropout_in_a_lowering_keeps_the_bounds_f32() {
    a_dropout_in_a_lowering_keeps_the_bounds(Precision::F32);
}

/// A load that leaves the ground during a logger's dropout: the weighing
/// kept over a restart is the part of the load taken up before the gap,
/// and the load read after it must still be the whole one. Lift-offs at
/// 50° and 80°, taken up in 2 s (from 2 s to 4 s), every rope, both
/// friction laws, with 3.0–5.0 s (restarted) or 3.5–4.48 s (bridged)
/// missing. Returns the 110 % cases that are not cut from the dropout's
/// FAULT on (a sample after the gap neither FAULT nor OVERLOAD) and the 90 %
/// cases with an OVERLOAD, with its true u.
fn lift_offs_in_a_dropout(precision: Precision) -> (Vec<String>, Vec<(String, f64)>) {
    let (mut released, mut cut_at_90) = (Vec::new(), Vec::new());
    for (sc, over) in lift_off_scenarios(&[50.0, 80.0], &[2.0], &ROPES) {
        let rows = sc.rows();
        for (start, end) in [(3.0, 5.0), (3.5, 4.48)] {
            let pts = replay_with_dropout(&rows, (start, end), sc.seals, precision);
            let name = format!("{} without {start}..{end} s", sc.name());
            if over {
                if let Some(q) = pts.iter().find(|p| p.t >= end && !cut(p)) {
                    released.push(format!("{name}: {:?} at {:.2} s", q.state, q.t));
                }
            } else if let Some((t, u)) = first_overload(&pts) {
                println!("{name}: OVERLOAD at {t:.2} s, true u {u:.3}");
                cut_at_90.push((name, u));
            }
        }
    }
    println!("{precision:?}: lift-offs in a dropout: 110 % released {}, 90 % cut {}", released.len(), cut_at_90.len());
    (released, cut_at_90)
}

/// [`lift_offs_in_a_dropout`]: 110 % is never released, and 90 % is cut
/// only where measured: the 3 m rope at 80° whose load left the ground in
/// the 2 s gap (both friction laws, f64 and f32), at the FAULT's end
/// (6.01 s) at true u 0.900. There the boom's give swung the load while
/// the chain saw nothing, the rope bank restarted without that swing
/// (`moment_limiter::static_load`, "A lift-off: the boom's give swings the
/// load"), and the swing's crest read as load: an early cut (before
/// 1/1.1), as before the restart kept the bank's weighing.
fn lift_offs_in_a_dropout_stay_as_measured(precision: Precision) {
    let (released, cut_at_90) = lift_offs_in_a_dropout(precision);
    assert!(released.is_empty(), "{released:#?}");
    let unknown: Vec<&(String, f64)> = cut_at_90.iter().filter(|(n, u)| !(n.starts_with("80->80") && n.contains("Held(0.0)") && n.ends_with("without 3..5 s") && *u >= 0.89)).collect();
    assert!(unknown.is_empty(), "{unknown:#?}");
}

#[test]
fn lift_offs_in_a_dropout_stay_as_measured_f64() {
    lift_offs_in_a_dropout_stay_as_measured(Precision::F64);
}

#[test]
fn lift_offs_in_a_dropout_stay_as_measured_f32() {
    lift_offs_in_a_dropout_stay_as_measured(Precision::F32);
}

/// KNOWN GAP (see [`lift_offs_in_a_dropout_stay_as_measured`]): 90 % whose
/// load leaves the ground in a 2 s dropout, on the 3 m rope at 80°, is an
/// OVERLOAD at true u 0.900.
#[test]
#[ignore = "KNOWN GAP: 90 % lifted off on a 3 m rope at 80 deg while 2 s of samples are missing is cut at true u 0.900 as the FAULT ends"]
fn lift_offs_in_a_dropout_known_gap() {
    let (released, cut_at_90) = lift_offs_in_a_dropout(Precision::F64);
    assert!(released.is_empty() && cut_at_90.is_empty(), "{released:#?} {cut_at_90:#?}");
}

/// Lowerings faster than the thesis's 4 °/s: 80° → 20° and 70° → 20° in
/// 10 s (6 and 5 °/s). Cut between true u 1/1.1 and 1.05: measured (f64)
/// at 0.957–0.990 and 0.962–0.990.
#[test]
fn a_faster_lowering_past_the_rated_radius() {
    let failures = lowerings(Precision::F64, &[(80.0, 20.0, 10.0, 1.0), (70.0, 20.0, 10.0, 1.0)]);
    assert!(failures.is_empty(), "{failures:#?}");
}

/// Lowerings over other ranges than 80° → 20°: 60° → 5° in 15 s, 50° → 10°
/// in 30 s, 85° → 30° in 15 s, 75° → 35° in 40 s (there the load rated at
/// 30° never reaches its rating, and is not cut). Cut between true u 1/1.1
/// and 1.05: measured (f64) at 0.954–0.979.
#[test]
fn lowering_past_the_rated_radius_over_other_ranges() {
    let failures = lowerings(Precision::F64, &[(60.0, 5.0, 15.0, 1.0), (50.0, 10.0, 30.0, 1.5), (85.0, 30.0, 15.0, 1.0), (75.0, 35.0, 40.0, 1.5)]);
    assert!(failures.is_empty(), "{failures:#?}");
}

/// A missed overload inside the campaign's own sensor range, found by its
/// wider worlds (`crane-sim campaign --wide --seed 3`, #4653). A lift-off of
/// 6.25 t at 79°, then at once a lowering to 42° in 9.6 s (past the rated
/// radius), on a 9.5 m held rope, behind an angle sensor with 0.05° of noise
/// and a 1.84 Hz, ζ 0.51 pendulum; eight noise draws, both friction laws.
/// Cut between true u 1/1.1 and 1.05.
///
/// Before, the filters' start-up read as a luff (`moment_limiter::static_load`,
/// "Power-up"). At 79° the pendulums' phantom swing then kept the ropes from
/// agreeing, so the lift-off never raised the averages, and the lowering
/// started from half the load. With noise draw 1 (both laws, f64 and f32)
/// the cut came only at true u 1.110; the other 14 at 0.992–0.998.
/// Measured now (f64): all 16 at 0.990–0.998.
fn a_lowering_right_after_a_lift_off_behind_a_noisy_angle_sensor(precision: Precision) {
    let mut failures = Vec::new();
    with_setting(&NOISE_DEG, Some(0.05), || {
        with_setting(&PENDULUM_2ND, Some((1.84, 0.51)), || {
            let mut p = Program::new(78.73, 0.0, RopeChoice::Held { length_m: Some(9.53) }).unwrap();
            p.push(Segment::Hold { duration_s: HOLD_BEFORE_S }).unwrap();
            p.push(Segment::LiftOff { duration_s: 5.83, load_kg: 6252.5 }).unwrap();
            p.push(Segment::Luff { to_deg: 41.94, shape: RampShape::Cycloidal, t1_s: 1.12, t2_s: 8.5, t3_s: 9.62 }).unwrap();
            p.push(Segment::Hold { duration_s: HOLD_AFTER_S }).unwrap();
            for seals in SEALS {
                for seed in 1..=8 {
                    let pts = replay_rows(&program_rows(&p, seals, seed), seals, precision);
                    failures.extend(lowering_bound_failures(&format!("{seals:?} seed {seed}"), &pts));
                }
            }
        });
    });
    assert!(failures.is_empty(), "{failures:#?}");
}

#[test]
fn a_lowering_right_after_a_lift_off_behind_a_noisy_angle_sensor_f64() {
    a_lowering_right_after_a_lift_off_behind_a_noisy_angle_sensor(Precision::F64);
}

#[test]
fn a_lowering_right_after_a_lift_off_behind_a_noisy_angle_sensor_f32() {
    a_lowering_right_after_a_lift_off_behind_a_noisy_angle_sensor(Precision::F32);
}

/// Lowered from 85° to 10° in 10 s (7.5 °/s, nearly twice the thesis's
/// fastest move, from an angle where tan θ = 11.4), every rope, both
/// friction laws, both ramp shapes, the loads rated at 45° and 30° (f64 and
/// f32): cut between true u 1/1.1 and 1.05. The 3 m and the 10 m held ropes
/// swing so far in the start ramp (±30°) that p1 leaves its range for up to
/// 3.3 s. Before the angle's side of the signal chain went on through a
/// pressure's fault (`moment_limiter::cycle`, "A pressure's fault"), the rope
/// bank's pendulums stood still through that gap, every rope read the swing
/// as load after it (1.6 × the load), and 9 of the 32 lowerings were cut
/// early, from true u 0.61 (11 of 32 before the rope that was the weighing
/// restarted at it). Measured (f64): the held ropes are cut at true u
/// 0.961–1.011, the paid-out rope at 1.018–1.027.
fn a_lowering_from_85_degrees_at_7_5_degrees_per_second(precision: Precision) {
    let failures = lowerings(precision, &[(85.0, 10.0, 10.0, 1.0)]);
    assert!(failures.is_empty(), "{} of 32: {failures:#?}", failures.len());
}

#[test]
fn a_lowering_from_85_degrees_at_7_5_degrees_per_second_f64() {
    a_lowering_from_85_degrees_at_7_5_degrees_per_second(Precision::F64);
}

#[test]
fn a_lowering_from_85_degrees_at_7_5_degrees_per_second_f32() {
    a_lowering_from_85_degrees_at_7_5_degrees_per_second(Precision::F32);
}

/// 85 % of the load rated at 60° hanging still at 60°, every rope, both
/// friction laws (f64): p1's loop breaks for 1.5 s, and 0.5 s into that
/// gap the angle reads 20° high for 0.1 s (a loose connector). The angle's
/// side of the chain goes on through a pressure's fault only on angles a
/// boom can follow (the monitor's 60 °/s): the glitch ends that for the
/// gap, which then ends as any gap does. Asserted: from 3 s after the gap
/// no OVERLOAD, and the estimate within 1.00–1.10 of the load for the 10 s
/// after: measured 1.044–1.051. Taken as the boom's, the glitch swung
/// every pendulum and the boom seemed to have luffed: with the check
/// removed, all 8 read 0.908–0.914 of the load 3 s after the gap (low: the
/// direction that misses an overload).
#[test]
fn an_angle_glitch_in_a_pressure_fault_swings_no_pendulum() {
    let mut failures = Vec::new();
    let (mut lo, mut hi) = (f64::INFINITY, 0.0f64);
    for rope in ROPES {
        for seals in SEALS {
            let w = 0.85 * rated_kg(60f64.to_radians());
            let mut p = Program::new(60.0, w, rope_choice(rope, 60.0)).unwrap();
            p.push(Segment::Hold { duration_s: 20.0 }).unwrap();
            let mut rows = program_rows(&p, seals, 3);
            for r in rows.iter_mut().filter(|r| (5.0..6.5).contains(&r.t_s)) {
                r.p1_bar = moment_limiter::units::PRESSURE_MAX_BAR + 20.0;
                if (5.5..5.6).contains(&r.t_s) {
                    r.boom_angle_deg += 20.0;
                }
            }
            let pts = replay_rows(&rows, seals, Precision::F64);
            let after: Vec<&Point> = pts.iter().filter(|q| q.t >= 9.5 && q.t < 19.5).collect();
            let name = format!("{rope:?} {seals:?}");
            if let Some(q) = after.iter().find(|q| q.state == LimiterState::Overload) {
                failures.push(format!("{name}: OVERLOAD at {:.2} s", q.t));
            }
            for q in &after {
                lo = lo.min(q.ratio);
                hi = hi.max(q.ratio);
            }
            if let Some(q) = after.iter().find(|q| !(1.0..=1.10).contains(&q.ratio)) {
                failures.push(format!("{name}: estimate {:.3} of the load at {:.2} s", q.ratio, q.t));
            }
        }
    }
    println!("estimate/true from 3 s after the gap: {lo:.3}–{hi:.3}");
    assert!(failures.is_empty(), "{failures:#?}");
}

#[test]
fn lowering_past_rated_radius_f64() {
    lowering_past_rated_radius(Precision::F64, &ROPES, &SEALS);
}

#[test]
fn lowering_past_rated_radius_f32() {
    lowering_past_rated_radius(Precision::F32, &ROPES, &SEALS);
}

/// [`HOLD_BEFORE_S`] at rest at 60° with `w0` kg on `rope`, raised to 80°
/// in 10 s, `rest` s at rest; if `w1` is more than `w0`, the load taken up
/// to `w1` in 1 s and 5 s more at rest; then lowered 80° → 20° in 15 s
/// (linear ramps of 1 s) and [`HOLD_AFTER_S`] at rest.
fn raise_rest_lower(w0: f64, w1: f64, rope: Rope, rest: f64) -> Program {
    raise_rest_take_up_lower(w0, w1, rope, rest, 5.0)
}

/// [`raise_rest_lower`] with `after` s at rest between the take-up and the
/// lowering.
fn raise_rest_take_up_lower(w0: f64, w1: f64, rope: Rope, rest: f64, after: f64) -> Program {
    let mut p = Program::new(60.0, w0, rope_choice(rope, 20.0)).unwrap();
    p.push(Segment::Hold { duration_s: HOLD_BEFORE_S }).unwrap();
    p.push(Segment::Luff { to_deg: 80.0, shape: RampShape::Cycloidal, t1_s: 1.0, t2_s: 9.0, t3_s: 10.0 }).unwrap();
    p.push(Segment::Hold { duration_s: rest }).unwrap();
    if w1 > w0 {
        p.push(Segment::LiftOff { duration_s: 1.0, load_kg: w1 }).unwrap();
        p.push(Segment::Hold { duration_s: after }).unwrap();
    }
    p.push(Segment::Luff { to_deg: 20.0, shape: RampShape::Linear, t1_s: 1.0, t2_s: 14.0, t3_s: 15.0 }).unwrap();
    p.push(Segment::Hold { duration_s: HOLD_AFTER_S }).unwrap();
    p
}

/// A lowering past the rated radius right after a raise and a rest, the way
/// a crane gets there: the load rated at 45° or 30° raised 60° → 80° in
/// 10 s, `rest` s at rest (3, 8 and 20 s: before, within and after the
/// time the mean over one swing period needs), then lowered 80° → 20° in
/// 15 s; every rope, both friction laws. Asserted: OVERLOAD before true u
/// reaches 1.05, never released while true u ≥ 1.05 (an OVERLOAD may give
/// way to a FAULT), and never before 1/1.1: measured (f64 and f32) at
/// 0.927–1.045. The 3 m rope 3 s after its stop at 80° with the load rated
/// at 45° takes p1 past its range at the swing's crests; it was cut early,
/// at 0.83, until the angle and the pendulums went on through a pressure's
/// fault (now 0.927–0.957), and an 8.9 m rope after 20 s at rest with the
/// same load was once cut at 0.907–0.909. Before the averages carried the
/// rest's weighing into the move (`moment_limiter::static_load`), they sank
/// at rest under the swings of the wrong ropes (to 0.64 of the load after
/// 20 s on the 3 m rope) while the reading held: the lowering read down to
/// 0.67 of the load, 4 cases were cut only past true u 1.05 (1.055–1.064),
/// and 6 released their OVERLOAD at true u over 1.05.
fn lowering_after_a_raise_and_a_rest(precision: Precision) {
    let mut failures = Vec::new();
    let mut lowest_cut: f64 = f64::INFINITY;
    let mut highest_cut: f64 = 0.0;
    let mut lowest_ratio: f64 = f64::INFINITY;
    for rest in [3.0, 8.0, 20.0] {
        for rope in ROPES {
            for seals in SEALS {
                for rated_at in [45.0f64, 30.0] {
                    let w = rated_kg(rated_at.to_radians());
                    let rows = program_rows(&raise_rest_lower(w, w, rope, rest), seals, 9);
                    let pts = replay_rows(&rows, seals, precision);
                    let name = format!("60->80, {rest} s at rest, 80->20 15s {rope:?} {seals:?}, rated at {rated_at}");
                    let first = first_overload(&pts);
                    let t105 = pts.iter().find(|q| q.u >= 1.05).map(|q| q.t);
                    let released = uncut(&pts).next();
                    // The lowering's constant-velocity part, outside FAULTs.
                    let start = HOLD_BEFORE_S + 10.0 + rest;
                    let low = pts.iter().filter(|q| q.t >= start + 1.0 && q.t <= start + 14.0 && q.state != LimiterState::Fault).map(|q| q.ratio).fold(f64::INFINITY, f64::min);
                    lowest_ratio = lowest_ratio.min(low);
                    println!("{name:<66} first OVERLOAD at true u {}, lowest estimate/true in the lowering {low:.3}", first.map_or("none".into(), |f| format!("{:.3}", f.1)));
                    match (first, t105) {
                        (Some((t, u)), Some(t105)) if t <= t105 => {
                            lowest_cut = lowest_cut.min(u);
                            highest_cut = highest_cut.max(u);
                            let floor = 1.0 / 1.1;
                            if u < floor {
                                failures.push(format!("{name}: OVERLOAD at true u {u:.3}, before {floor:.3}"));
                            }
                        }
                        (first, _) => failures.push(format!("{name}: first OVERLOAD {first:?}, true u 1.05 at {t105:?} s")),
                    }
                    if let Some(q) = released {
                        failures.push(format!("{name}: {:?} at {:.2} s, true u {:.3}", q.state, q.t, q.u));
                    }
                }
            }
        }
    }
    println!("{precision:?}: cut at true u {lowest_cut:.3}..{highest_cut:.3}, lowest estimate/true in a lowering {lowest_ratio:.3}; {} failures", failures.len());
    assert!(failures.is_empty(), "{failures:#?}");
}

#[test]
fn a_lowering_after_a_raise_and_a_rest_f64() {
    lowering_after_a_raise_and_a_rest(Precision::F64);
}

#[test]
fn a_lowering_after_a_raise_and_a_rest_f32() {
    lowering_after_a_raise_and_a_rest(Precision::F32);
}

/// A lowering past the rated radius after a load was added at rest: 60 %
/// of the load rated at 45° or 30° raised 60° → 80° in 10 s, `rest` s at
/// rest, the rest of it taken up in 1 s, `after` s more, then lowered 80° →
/// 20° in 15 s; every rope, both friction laws. Returns the cases cut before
/// true u = 1/1.1, or with a sample at a true u ≥ 1.05 that is neither
/// OVERLOAD nor FAULT (cut late or released), the highest true u not cut
/// and the lowest true u at an OVERLOAD's onset.
fn lowering_after_a_load_added_at_rest(precision: Precision, rest: f64, after: f64) -> (Vec<String>, f64, f64) {
    lowering_after_a_load_added_at_rest_on(&ROPES, precision, rest, after)
}

/// [`lowering_after_a_load_added_at_rest`] on the `ropes` given.
fn lowering_after_a_load_added_at_rest_on(ropes: &[Rope], precision: Precision, rest: f64, after: f64) -> (Vec<String>, f64, f64) {
    let (mut failures, mut highest_uncut, mut lowest_onset) = (Vec::new(), 0.0f64, f64::INFINITY);
    for &rope in ropes {
        for seals in SEALS {
            for rated_at in [45.0f64, 30.0] {
                let w1 = rated_kg(rated_at.to_radians());
                let rows = program_rows(&raise_rest_take_up_lower(0.6 * w1, w1, rope, rest, after), seals, 9);
                let pts = replay_rows(&rows, seals, precision);
                let name = format!("60->80, {rest} s at rest, 60 % -> 100 % of rated at {rated_at}, {after} s, 80->20 15s {rope:?} {seals:?}");
                failures.extend(lowering_bound_failures(&name, &pts));
                highest_uncut = uncut(&pts).map(|q| q.u).fold(highest_uncut, f64::max);
                lowest_onset = lowest_onset_u(&pts).map_or(lowest_onset, |u| lowest_onset.min(u));
            }
        }
    }
    (failures, highest_uncut, lowest_onset)
}

/// [`lowering_after_a_load_added_at_rest`] 14 s after the stop, when the
/// swing's period is known and the load added is read from the force's
/// ratio to one period earlier (`moment_limiter::period_mean`): cut between
/// true u 1/1.1 and 1.05 and never released over it. Before the averages
/// took up that reading (`moment_limiter::static_load`, "The averages carry
/// the rest's weighing into the next move"), the lowering started from the
/// averages of the old load, read 0.72–0.9 of the new one, and the 8.9 m
/// rope was cut at true u 1.079–1.085 (at the start of the session also the
/// 3 m rope's cut was released at 1.05).
fn lowering_after_a_load_added_14_s_after_the_stop(precision: Precision) {
    let (failures, _, _) = lowering_after_a_load_added_at_rest(precision, 14.0, 5.0);
    assert!(failures.is_empty(), "{failures:#?}");
}

#[test]
fn a_lowering_after_a_load_added_at_rest_f64() {
    lowering_after_a_load_added_14_s_after_the_stop(Precision::F64);
}

#[test]
fn a_lowering_after_a_load_added_at_rest_f32() {
    lowering_after_a_load_added_14_s_after_the_stop(Precision::F32);
}

/// The same with the load added 3 s after the stop at 80°, before the
/// swing's period is known, and the lowering 5 s after the take-up: cut
/// between true u 1/1.1 and 1.05 and never released over it (measured,
/// f64: OVERLOAD from true u 0.935–1.021; the 8.9 m rope 0.991–1.001). On
/// the 8.9 m rope no rope of the bank follows the swing
/// (`a_load_added_at_rest_after_a_move_known_gap`) and nothing else weighed
/// the new load before the lowering: it was cut only at true u
/// 1.128–1.133, and the 3 m rope (seal friction) released its cut at 1.06.
/// Its first crest came 1.15 s after the swing's midrange began to follow
/// (`moment_limiter::swing_midrange`), and counted once a turning point
/// needed 1.0 s after the one before instead of 1.2 s: the midrange of it
/// and the next trough is read about 0.2 s before the lowering starts. For
/// a while (1e42ddb to the pin this test replaces) the 8.9 m rope was cut
/// only at 1.245–1.249, and the thesis's rope and the 3 m one with constant
/// friction released their cut at 1.05.
fn lowering_5_s_after_a_load_added_at_rest_soon_after_a_stop(precision: Precision) {
    lowering_after_a_load_added_at_rest_keeps_the_bounds(&ROPES, precision, 5.0);
}

/// [`lowering_after_a_load_added_at_rest_on`] the `ropes`, 3 s after the
/// stop and lowered `after` s after the take-up, asserted within the
/// lowering's bounds; prints the highest true u not cut and the lowest at
/// an OVERLOAD's onset.
fn lowering_after_a_load_added_at_rest_keeps_the_bounds(ropes: &[Rope], precision: Precision, after: f64) {
    let (failures, highest_uncut, lowest_onset) = lowering_after_a_load_added_at_rest_on(ropes, precision, 3.0, after);
    println!("{precision:?}: highest true u not cut {highest_uncut:.3}, lowest OVERLOAD onset {lowest_onset:.3}");
    assert!(failures.is_empty(), "{failures:#?}");
}

#[test]
fn a_lowering_5_s_after_a_load_added_at_rest_soon_after_a_stop_f64() {
    lowering_5_s_after_a_load_added_at_rest_soon_after_a_stop(Precision::F64);
}

#[test]
fn a_lowering_5_s_after_a_load_added_at_rest_soon_after_a_stop_f32() {
    lowering_5_s_after_a_load_added_at_rest_soon_after_a_stop(Precision::F32);
}

/// The times from the take-up to the lowering of
/// [`lowering_after_a_load_added_at_rest`] (3 s after the stop) measured
/// besides the 5 s of the test above (s).
const LOWERING_AFTER_S: [f64; 7] = [2.0, 3.0, 4.0, 6.0, 7.0, 8.0, 10.0];

/// The lowering after a load added at rest 3 s after the stop, begun 2–10 s
/// after the take-up ([`LOWERING_AFTER_S`]), f64: the highest true u not
/// cut and the lowest true u at an OVERLOAD's onset over all of them, and
/// the failures.
fn lowerings_2_to_10_s_after_a_load_added_at_rest() -> (Vec<String>, f64, f64) {
    let (mut failures, mut highest_uncut, mut lowest_onset) = (Vec::new(), 0.0f64, f64::INFINITY);
    for after in LOWERING_AFTER_S {
        let (f, uncut_u, onset_u) = lowering_after_a_load_added_at_rest(Precision::F64, 3.0, after);
        println!("lowered {after} s after the take-up: highest true u not cut {uncut_u:.3}, lowest OVERLOAD onset {onset_u:.3}, {} failures", f.len());
        failures.extend(f);
        highest_uncut = highest_uncut.max(uncut_u);
        lowest_onset = lowest_onset.min(onset_u);
    }
    (failures, highest_uncut, lowest_onset)
}

/// KNOWN GAP, measured (f64): [`lowering_5_s_after_a_load_added_at_rest_soon_after_a_stop`]
/// with the lowering begun 2–10 s after the take-up instead of 5 s. Cut
/// late, where nothing has weighed the new load when the lowering starts:
/// 2 s after, up to true u 1.081; 3 s, 1.082 (the 6 m rope, where W_fast at
/// rest never passed the old weighing). Cut early: 6 s after, at 0.887
/// (the 3 m rope); 7 s, 0.893 (the 8.9 m rope). 7 s after, the thesis's
/// rope (seal friction) was cut up to 1.063 until the rescale of a load
/// added at rest raised the stop's W_slow the next move starts from as
/// well (now from 1.023). 4–5.5 s, 8 s and 10 s after, within the bounds
/// ([`lowering_8_or_10_s_after_a_load_added_at_rest`]). 4 s after was cut
/// up to 1.105 (the 3 m and 8.9 m ropes, rated at 45°) until the swing's
/// midrange went on into a lowering that doubts its start
/// (`moment_limiter::static_load::MIDRANGE_CARRY_S`; now from 0.952). Before the averages
/// took up W_fast in a move that starts from a doubted weighing
/// (`moment_limiter::static_load`, "A load added at rest that nothing
/// weighed"), 2–4 s after was cut up to 1.127, 1.116 and 1.164, and 8 s
/// after early at 0.904. When this test was written, 8 s after was cut
/// at 0.813 (19 % early) and 10 s at 0.865: the period mean's step read the
/// load as 1.25 × itself from ratios that climbed bin by bin, a swing out
/// of phase with the period found, until the ratios had to agree
/// (`moment_limiter::period_mean::STEP_AGREE`). With a turning point of the
/// swing's midrange 1.2 s after the one before, as until this test, 4.5–6 s
/// was cut up to 1.13. Tried and not kept: the swing's midrange followed
/// from every loaded stop, one midrange over the held weighing by the
/// rescale's 10 % taken as a load added that doubts the move's start. It
/// cut 3 s after within the bounds (from 0.917) and 2 s after up to 1.060,
/// but an inched lowering on the rope as long as the tip is high (74° → 20°
/// in 6° steps of 2.5 s, 4 s pauses) read W₁'s midrange at rest at 1.4 ×
/// the load (a 0.45 Hz ring that stayed above the load through the pause)
/// and was cut at true u 0.804–0.844 in 4 more of 64 cases
/// ([`inched_lowering`]): the midrange stays a weighing only once W_fast
/// has seen a load added.
#[test]
#[ignore = "KNOWN GAP: a lowering past the rated radius 2-7 s after a load added at rest 3 s after a raise to 80 deg is cut late (true u up to 1.082) or early (from 0.887)"]
fn a_lowering_2_to_10_s_after_a_load_added_at_rest_known_gap() {
    let (failures, _, _) = lowerings_2_to_10_s_after_a_load_added_at_rest();
    assert!(failures.is_empty(), "{failures:#?}");
}

/// The known gap above pinned at its measured size, so that it cannot widen
/// unseen: no sample of those lowerings at a true u over 1.09 goes uncut
/// (1.082 measured; 1.105 before the swing's midrange went on into the
/// lowering, 1.164 before the averages took up W_fast in a move that starts
/// from a doubted weighing), and none is cut before true u 0.88 (0.887).
#[test]
fn a_lowering_2_to_10_s_after_a_load_added_at_rest_stays_as_measured() {
    let (_, highest_uncut, lowest_onset) = lowerings_2_to_10_s_after_a_load_added_at_rest();
    assert!(highest_uncut <= 1.09 && lowest_onset >= 0.88, "highest true u not cut {highest_uncut:.3}, lowest OVERLOAD onset {lowest_onset:.3}");
}

/// [`lowering_5_s_after_a_load_added_at_rest_soon_after_a_stop`] with the
/// lowering begun 8 s and 10 s after the take-up, once the swing's midrange
/// or the mean over one swing period has weighed the load added: cut
/// between true u 1/1.1 and 1.05 and never released over it (measured, f64:
/// from 0.933 and 0.963). Before the rest's peak of W_fast was forgotten
/// while those weighed (`moment_limiter::static_load`, "A load added at
/// rest that nothing weighed"), the move started doubting that weighing:
/// 8 s after was cut at 0.904, and with the averages taking up W_fast in
/// such a move, 10 s after at 0.873 (the swing's crest of W_fast on the
/// 3 m rope at 68°, 1.17 × the load, held by the averages).
fn lowering_8_or_10_s_after_a_load_added_at_rest(precision: Precision) {
    let mut failures = Vec::new();
    for after in [8.0, 10.0] {
        let (f, _, onset) = lowering_after_a_load_added_at_rest(precision, 3.0, after);
        println!("{precision:?}, lowered {after} s after the take-up: lowest OVERLOAD onset {onset:.3}, {} failures", f.len());
        failures.extend(f);
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

/// [`lowering_5_s_after_a_load_added_at_rest_soon_after_a_stop`] with the
/// lowering begun 4 s after the take-up, before the swing's midrange has
/// read the new load's first crest with the trough after it: cut between
/// true u 1/1.1 and 1.05 and never released over it (measured, f64 and
/// f32: from 0.947). Until the midrange went on into a lowering that doubts its start
/// (`moment_limiter::static_load::MIDRANGE_CARRY_S`), the 3 m and 8.9 m
/// ropes rated at 45° were cut only at true u 1.076–1.105: the lowering
/// started from the old load's weighing.
fn lowering_4_s_after_a_load_added_at_rest(precision: Precision) {
    lowering_after_a_load_added_at_rest_keeps_the_bounds(&ROPES, precision, 4.0);
}

#[test]
fn a_lowering_4_s_after_a_load_added_at_rest_f64() {
    lowering_4_s_after_a_load_added_at_rest(Precision::F64);
}

#[test]
fn a_lowering_4_s_after_a_load_added_at_rest_f32() {
    lowering_4_s_after_a_load_added_at_rest(Precision::F32);
}

/// [`lowering_5_s_after_a_load_added_at_rest_soon_after_a_stop`] on the
/// paid-out rope with the lowering begun 7 s after the take-up, where the
/// rescale has seen the load added (`moment_limiter::load_jump`): cut
/// between true u 1/1.1 and 1.05 and never released over it (measured, f64
/// and f32: from 0.964). Rated at 45°, it was not cut by true u 1.05 with
/// either friction law (with the seals', up to 1.063) until the rescale raised W_slow at the stop as well as the averages and
/// the held weighing (`moment_limiter::static_load`, "The averages carry
/// the rest's weighing into the next move"): the lowering started from the
/// averages, which had sunk at rest to 0.93 of the new load.
fn lowering_7_s_after_a_load_added_at_rest_on_the_paid_out_rope(precision: Precision) {
    lowering_after_a_load_added_at_rest_keeps_the_bounds(&[Rope::Thesis], precision, 7.0);
}

#[test]
fn a_lowering_7_s_after_a_load_added_at_rest_on_the_paid_out_rope_f64() {
    lowering_7_s_after_a_load_added_at_rest_on_the_paid_out_rope(Precision::F64);
}

#[test]
fn a_lowering_7_s_after_a_load_added_at_rest_on_the_paid_out_rope_f32() {
    lowering_7_s_after_a_load_added_at_rest_on_the_paid_out_rope(Precision::F32);
}

#[test]
fn a_lowering_8_or_10_s_after_a_load_added_at_rest_f64() {
    lowering_8_or_10_s_after_a_load_added_at_rest(Precision::F64);
}

#[test]
fn a_lowering_8_or_10_s_after_a_load_added_at_rest_f32() {
    lowering_8_or_10_s_after_a_load_added_at_rest(Precision::F32);
}

/// A lowering past the rated radius inched, as an operator does near the
/// chart's limit: down to 20° in steps of 5° from 75° (2 s moves, 2 s
/// pauses), of 3° from 65° (2 s, 1 s), of 6° from 74° (2.5 s, 4 s) or of 4°
/// from 72° (2 s, 0.5 s), ramps of a quarter of
/// the move (at most 0.5 s); every rope, both friction laws, loads rated at
/// 45° and 30°. Returns the OVERLOADs set before true u = 1/1.1 (each
/// with the true u at its onset) and the samples at a true u ≥ 1.05 that are neither OVERLOAD nor FAULT (a cut
/// that came late or was released); prints every case. The 3 m rope's
/// swing takes p1 past its range in the short moves: FAULT, which cuts.
fn inched_lowering(precision: Precision) -> (Vec<(String, f64)>, Vec<String>) {
    let (mut early, mut late) = (Vec::new(), Vec::new());
    for (step_deg, move_s, pause_s) in [(5.0, 2.0, 2.0), (3.0, 2.0, 1.0), (6.0, 2.5, 4.0), (4.0, 2.0, 0.5)] {
        for rope in ROPES {
            for seals in SEALS {
                for rated_at in [45.0f64, 30.0] {
                    let w = rated_kg(rated_at.to_radians());
                    // Down to 20° in at most 15 steps (a program holds 32 segments).
                    let steps = ((55.0 / step_deg) as u32).min(15);
                    let mut angle = 20.0 + f64::from(steps) * step_deg;
                    let mut p = Program::new(angle, w, rope_choice(rope, 20.0)).unwrap();
                    p.push(Segment::Hold { duration_s: HOLD_BEFORE_S }).unwrap();
                    let ramp = (move_s / 4.0f64).min(0.5);
                    for _ in 0..steps {
                        angle -= step_deg;
                        p.push(Segment::Luff { to_deg: angle, shape: RampShape::Cycloidal, t1_s: ramp, t2_s: move_s - ramp, t3_s: move_s }).unwrap();
                        p.push(Segment::Hold { duration_s: pause_s }).unwrap();
                    }
                    let rows = program_rows(&p, seals, 9);
                    let pts = replay_rows(&rows, seals, precision);
                    let name = format!("{:.0}->20 in {step_deg} deg steps ({move_s} s, {pause_s} s pauses) {rope:?} {seals:?}, rated at {rated_at}", 20.0 + f64::from(steps) * step_deg);
                    let onset = lowest_onset_u(&pts);
                    let uncut = uncut(&pts).count();
                    println!("{name:<80} first OVERLOAD at true u {}, lowest onset {}, samples over 1.05 not cut {uncut}", first_overload(&pts).map_or("none".into(), |f| format!("{:.3}", f.1)), onset.map_or("none".into(), |u| format!("{u:.3}")));
                    if let Some(u) = onset.filter(|&u| u < 1.0 / 1.1) {
                        early.push((format!("{name}: OVERLOAD at true u {u:.3}"), u));
                    }
                    if uncut > 0 {
                        late.push(format!("{name}: {uncut} samples at true u >= 1.05 not cut"));
                    }
                }
            }
        }
    }
    (early, late)
}

/// [`inched_lowering`]: never a true u of 1.05 or more without the cut
/// (OVERLOAD or FAULT). Early cuts are [`inched_lowering_known_gap`]'s,
/// pinned here at its measured size (3 of 64, from true u 0.883) so that it
/// cannot widen unseen.
fn inched_lowering_is_cut(precision: Precision) {
    let (early, late) = inched_lowering(precision);
    println!("{precision:?}: {} early: {early:#?}", early.len());
    assert!(late.is_empty(), "{late:#?}");
    let lowest = early.iter().map(|&(_, u)| u).fold(f64::INFINITY, f64::min);
    assert!(early.len() <= 3 && lowest >= 0.88, "{} early, from true u {lowest:.3}", early.len());
}

#[test]
fn an_inched_lowering_is_cut_f64() {
    inched_lowering_is_cut(Precision::F64);
}

#[test]
fn an_inched_lowering_is_cut_f32() {
    inched_lowering_is_cut(Precision::F32);
}

/// KNOWN GAP, measured (f64; f32 alike): an inched lowering
/// ([`inched_lowering`]) is cut early, toward safety, in 3 of 64 cases: at
/// true u 0.883–0.889 (the 3 m rope in 3° steps with 1 s pauses, the load
/// rated at 45°, both friction laws; 0.882–0.887 until the rest went on
/// through the angle noise's brief excursions of the rate,
/// `moment_limiter::static_load::UNSETTLED_GRACE_S`) and 0.908 (the 8.9 m rope in 3° steps,
/// constant friction, rated at 30°). Each pause starts a swing the next move
/// meets out of phase. It was 10 of 64 (from 0.804: the 8.9 m rope in 6°
/// steps with 4 s pauses, the 6.0 m rope in 5° steps) until the rope that
/// was the bank's weighing restarted at it in motion (1e42ddb), which closed
/// seven of them unseen here; before the averages carried the rest's
/// weighing into the next move (`moment_limiter::static_load`), 7 of 64.
#[test]
#[ignore = "KNOWN GAP: an inched lowering past the rated radius is cut early (toward safety) in 3 of 64 cases, from true u 0.883"]
fn inched_lowering_known_gap() {
    let (early, _) = inched_lowering(Precision::F64);
    assert!(early.is_empty(), "{early:#?}");
}

/// The limiter switched on while the load swings (a power cut or a watchdog
/// reset right after a move): 85 % of the rated load at the lower angle
/// moved 40° → 80°, 40° → 60° or 80° → 40° in 10 s on every rope, seal
/// friction, the limiter started 0.5 s or 3 s after the stop, 30 s at rest.
/// Returns, per case, its name, the time in OVERLOAD and in FAULT (s), the
/// highest estimate/true and the estimate/true from [`SWING_FOUND_S`] after
/// power-up on (FAULT samples left out).
fn power_up_with_the_load_swinging(precision: Precision) -> Vec<(String, [f64; 2], f64, Vec<f64>)> {
    let mut cases = Vec::new();
    for (from, to) in [(40.0, 80.0), (40.0, 60.0), (80.0, 40.0)] {
        for rope in ROPES {
            let lowest = f64::min(from, to);
            let w = 0.85 * rated_kg(lowest.to_radians());
            let mut p = Program::new(from, w, rope_choice(rope, lowest)).unwrap();
            p.push(Segment::Hold { duration_s: HOLD_BEFORE_S }).unwrap();
            p.push(Segment::Luff { to_deg: to, shape: RampShape::Cycloidal, t1_s: 1.0, t2_s: 9.0, t3_s: 10.0 }).unwrap();
            p.push(Segment::Hold { duration_s: 30.0 }).unwrap();
            let rows = program_rows(&p, Seals::Seal, 9);
            for after_stop in [0.5, 3.0] {
                let on = HOLD_BEFORE_S + 10.0 + after_stop;
                let rows: Vec<SynthRow> = rows.iter().filter(|r| r.t_s >= on).copied().collect();
                let pts = replay_rows(&rows, Seals::Seal, precision);
                let weighing = |q: &&Point| q.state != LimiterState::Fault;
                let high = pts.iter().filter(weighing).map(|q| q.ratio).fold(0.0, f64::max);
                let time_in = |state| pts.iter().filter(|q| q.state == state).count() as f64 / rate_hz();
                let times_s = [time_in(LimiterState::Overload), time_in(LimiterState::Fault)];
                let late: Vec<f64> = pts.iter().filter(weighing).filter(|q| q.t >= on + SWING_FOUND_S).map(|q| q.ratio).collect();
                let name = format!("{from:.0}->{to:.0} {rope:?}, switched on {after_stop} s after the stop");
                cases.push((name, times_s, high, late));
            }
        }
    }
    cases
}

/// Time after power-up by which the mean over one swing period has been
/// found and confirmed on the ropes of [`power_up_with_the_load_swinging`]
/// (s): P·4/3 and 1 s of confirmation is 5.6 s on the 3 m rope, 9.4 s on
/// the 10 m one.
const SWING_FOUND_S: f64 = 12.0;

/// The 40° → 80° cases on the 3 m held rope (its swing takes p1 out of
/// range every period, and each fault starts the mean again) and on the
/// thesis's paid-out rope (at 80° the longest rope here, whose period is
/// found only about 12 s after power-up: p95 1.17–1.23 from 12 s on), where
/// the mean over one swing period is not yet the weighing 12 s after
/// power-up (see `power_up_with_the_load_swinging_known_gap`).
fn swing_not_found_in_time(name: &str) -> bool {
    name.starts_with("40->80 Held(0.0)") || name.starts_with("40->80 Thesis")
}

/// Switched on while the load swings, the ropes hang still (they swing
/// with the moves the bank has seen, and it has seen none) and the swing
/// reads as load. Once the force repeats a swing period, the mean over it
/// is the weighing (`moment_limiter::static_load`, "Switched on while the
/// load swings"): from 12 s after power-up, on 20 of the 24 cases, the
/// estimate reads 1.037–1.049 × the load at p5, 1.038–1.078 at p95 (1.223
/// at most), f64 and f32 alike, and none is an OVERLOAD. Before, every one
/// of the 24 read outside 1.00–1.10 there (p95 up to 2.98 on the 3 m rope at
/// 80°, 2.42 on the 10 m one), and 8 were still an OVERLOAD. All 24 are
/// also held to at most 14 s in OVERLOAD, pinning the known gap at its
/// measured size (13.1 s, the 3 m rope at 80°;
/// `power_up_with_the_load_swinging_known_gap`).
fn power_up_with_the_load_swinging_weighs_the_mean(precision: Precision) {
    let mut failures = Vec::new();
    let mut longest_overload_s = 0.0f64;
    for (name, [overload_s, _], high, mut late) in power_up_with_the_load_swinging(precision) {
        longest_overload_s = longest_overload_s.max(overload_s);
        if swing_not_found_in_time(&name) {
            continue;
        }
        let (p5, p95) = (percentile(&mut late, 0.05), percentile(&mut late, 0.95));
        println!("{precision:?} {name:<56} from {SWING_FOUND_S} s: p5 {p5:.3} p95 {p95:.3}; highest {high:.3}, in OVERLOAD {overload_s:.1} s");
        if !(p5 >= 1.0 && p95 <= 1.1) {
            failures.push(format!("{name}: from {SWING_FOUND_S} s after power-up p5 {p5:.3}, p95 {p95:.3}"));
        }
    }
    // The known gap (`power_up_with_the_load_swinging_known_gap`) pinned at
    // its measured size: at most 13.1 s of OVERLOAD in any case, f64 and f32.
    println!("{precision:?}: longest time in OVERLOAD {longest_overload_s:.1} s");
    if longest_overload_s > 14.0 {
        failures.push(format!("{longest_overload_s:.1} s in OVERLOAD (the known gap measured 13.1 s)"));
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

#[test]
fn power_up_with_the_load_swinging_weighs_the_mean_f64() {
    power_up_with_the_load_swinging_weighs_the_mean(Precision::F64);
}

#[test]
fn power_up_with_the_load_swinging_weighs_the_mean_f32() {
    power_up_with_the_load_swinging_weighs_the_mean(Precision::F32);
}

/// KNOWN GAP, measured (f64, seal friction; the cases of
/// [`power_up_with_the_load_swinging`]): until the mean over one swing
/// period is found (P·4/3 and 1 s of confirmation after power-up) the
/// swing reads as load: up to 3.1 × the load on the 3 m rope at 80° (true
/// u 0.46) and 1.2–1.5 × at 40° (true u 0.85), an OVERLOAD for 4.8–10.6 s
/// of the 30 s at rest on the 10 m rope at 80° and the 3 m and 10 m ropes
/// at 40° (18–30 s before the mean weighed at power-up). On the 3 m rope at
/// 80° the swing's inward pull takes p1 under its range at every trough
/// (FAULT for 15–16 s of the 30), each fault starts the mean again, and it
/// is never the weighing: OVERLOAD for 11–13 s as before. It errs toward
/// cutting: the moment-reducing motions stay free, and setting the load
/// down ends it.
#[test]
#[ignore = "KNOWN GAP: switched on while the load swings, the swing reads as load until a swing period repeats (OVERLOAD for 4.8-10.6 s at true u 0.46-0.85); on a 3 m rope at 80 deg for 11-13 s"]
fn power_up_with_the_load_swinging_known_gap() {
    let mut failures = Vec::new();
    for (name, [overload_s, fault_s], high, _) in power_up_with_the_load_swinging(Precision::F64) {
        println!("{name:<56} highest estimate/true {high:.3}, in OVERLOAD {overload_s:.1} s, in FAULT {fault_s:.1} s");
        if overload_s > 0.0 {
            failures.push(format!("{name}: OVERLOAD for {overload_s:.1} s"));
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

/// Lift-off at 50° (2 s): 90 % of rated → no OVERLOAD; 110 % → OVERLOAD
/// within 1 s of the load leaving the ground (the end of the lift).
fn lift_off(precision: Precision, seals_of: &[Seals]) {
    let angle = 50.0f64;
    let rated = rated_kg(angle.to_radians());
    let mut failures = Vec::new();
    for rope in ROPES {
        for &seals in seals_of {
            for (frac, must) in [(0.9, false), (1.1, true)] {
                let sc = Scenario::lift_off(angle, frac * rated, rope, seals, 2.0, 5);
                let pts = replay(&sc, precision);
                let off = HOLD_BEFORE_S + 2.0;
                let first = first_overload(&pts);
                println!("{:<60} OVERLOAD {}", sc.name(), first.map_or("none".into(), |f| format!("at {:+.2} s from leaving the ground", f.0 - off)));
                match (must, first) {
                    (false, Some((t, _))) => failures.push(format!("{}: OVERLOAD at {t:.2} s", sc.name())),
                    (true, None) => failures.push(format!("{}: no OVERLOAD", sc.name())),
                    (true, Some((t, _))) if t > off + 1.0 => failures.push(format!("{}: OVERLOAD {:.2} s after lift", sc.name(), t - off)),
                    _ => {}
                }
            }
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

/// [`lift_off`] at other angles and take-up times: at each of `angles`,
/// 90 % and 110 % of the rated load taken up in each of `take_ups` (s),
/// every rope, both friction laws. Returns the failures (90 % cut, 110 %
/// not cut or cut more than 1 s after it leaves the ground) and the
/// longest delay of a 110 % cut.
fn lift_offs_over(precision: Precision, angles: &[f64], take_ups: &[f64]) -> (Vec<String>, f64) {
    lift_offs_on(precision, angles, take_ups, &ROPES)
}

/// The lift-offs at `angles` taken up in `take_ups` s on `ropes`, both
/// friction laws, of 90 % and 110 % of the rated load there (noise draw
/// 5), each with whether it is over rated (must be cut).
fn lift_off_scenarios(angles: &[f64], take_ups: &[f64], ropes: &[Rope]) -> Vec<(Scenario, bool)> {
    let mut out = Vec::new();
    for &angle in angles {
        let rated = rated_kg(angle.to_radians());
        for &take_up in take_ups {
            for &rope in ropes {
                for seals in SEALS {
                    for (frac, over) in [(0.9, false), (1.1, true)] {
                        out.push((Scenario::lift_off(angle, frac * rated, rope, seals, take_up, 5), over));
                    }
                }
            }
        }
    }
    out
}

/// [`lift_offs_over`] on `ropes`.
fn lift_offs_on(precision: Precision, angles: &[f64], take_ups: &[f64], ropes: &[Rope]) -> (Vec<String>, f64) {
    let (mut failures, mut worst) = (Vec::new(), 0.0f64);
    for (sc, must) in lift_off_scenarios(angles, take_ups, ropes) {
        let pts = replay(&sc, precision);
        let off = HOLD_BEFORE_S + sc.lift_off_s.unwrap_or(0.0);
        match (must, first_overload(&pts)) {
            (false, Some((t, _))) => failures.push(format!("{}: OVERLOAD at {t:.2} s", sc.name())),
            (true, None) => failures.push(format!("{}: no OVERLOAD", sc.name())),
            (true, Some((t, _))) => {
                worst = worst.max(t - off);
                if t > off + 1.0 {
                    failures.push(format!("{}: OVERLOAD {:.2} s after it leaves the ground", sc.name(), t - off));
                }
            }
            _ => {}
        }
    }
    println!("{precision:?}, lift-offs at {angles:?} taken up in {take_ups:?} s: {} failures, 110 % cut at most {worst:.2} s after leaving the ground", failures.len());
    (failures, worst)
}

/// Lift-offs at 10°, 20°, 35°, 65° and 80°, taken up in 1 s and 2 s: 90 %
/// never cut, 110 % within 1 s of leaving the ground (measured, f64: at
/// most 0.63 s; 0.68 s before the mean of a bouncing lift-off's ring was
/// read, `moment_limiter::static_load`, "A lift-off: the mean of its ring").
#[test]
fn lift_off_at_other_angles() {
    let (failures, _) = lift_offs_over(Precision::F64, &[10.0, 20.0, 35.0, 65.0, 80.0], &[1.0, 2.0]);
    assert!(failures.is_empty(), "{failures:#?}");
}

/// Lift-offs taken up in 0.5 s at 10°–80°, every rope, both friction laws:
/// 90 % never cut, 110 % within 1 s of leaving the ground (measured, f64 and
/// f32: at most 0.76 s; 0.87 s, the 3 m rope at 80°, before the mean of a
/// bouncing lift-off's ring was read, `moment_limiter::static_load`, "A
/// lift-off: the mean of its ring"). The boom bends under the load
/// as it is taken up, its tip moves out, and a 3 m rope at a steep boom is
/// left swinging inward by up to 0.9° (tan 80° · tan 0.9° = 9 % less
/// pull). The rope bank follows that swing (`moment_limiter::static_load`,
/// "A lift-off: the boom's give swings the load"), but it reads the lowest
/// rope, and in the inward half swing that is the least inward, the
/// longest: through the still force's four filter stages that case was cut
/// 1.03 s after (1.05 s before the bank followed the give), through three
/// ("A lift-off: one stage fewer") 0.88 s after, and 0.87 s since a lift-off
/// is also read through a faster stage until it bounces ("A lift-off: read
/// at once until it bounces").
fn lift_off_in_half_a_second_is_cut_within_1_s(precision: Precision) {
    let (failures, worst) = lift_offs_over(precision, &[10.0, 20.0, 35.0, 65.0, 80.0], &[0.5]);
    assert!(failures.is_empty(), "{failures:#?}");
    assert!(worst <= 1.0, "110 % cut {worst:.2} s after it leaves the ground");
}

#[test]
fn lift_off_in_half_a_second_is_cut_within_1_s_f64() {
    lift_off_in_half_a_second_is_cut_within_1_s(Precision::F64);
}

#[test]
fn lift_off_in_half_a_second_is_cut_within_1_s_f32() {
    lift_off_in_half_a_second_is_cut_within_1_s(Precision::F32);
}

/// A lift-off snatched, the load taken up in 0.3 s, at 10°–80°, every
/// rope, both friction laws: for 110 % of rated, the time from leaving the
/// ground to the first cut (OVERLOAD, or FAULT: at 10° the bounce takes p1
/// past its range and the FAULT cuts at once); for 90 %, the cases with an
/// OVERLOAD and the highest estimated u. Returns (the longest 110 % delay,
/// the 90 % cases cut, their highest estimated u, every 110 % case not cut
/// at all).
fn snatched_lift_offs(precision: Precision) -> (f64, Vec<String>, f64, Vec<String>) {
    snatched_in(precision, &[0.3])
}

/// [`snatched_lift_offs`] taken up in each of `take_ups` (s).
fn snatched_in(precision: Precision, take_ups: &[f64]) -> (f64, Vec<String>, f64, Vec<String>) {
    let (mut worst, mut false_cut, mut peak90, mut uncut) = (0.0f64, Vec::new(), 0.0f64, Vec::new());
    for (angle, &take_up) in [10.0f64, 20.0, 35.0, 65.0, 80.0].into_iter().flat_map(|a| take_ups.iter().map(move |t| (a, t))) {
        let rated = rated_kg(angle.to_radians());
        for rope in ROPES {
            for seals in SEALS {
                for frac in [0.9, 1.1] {
                    let sc = Scenario::lift_off(angle, frac * rated, rope, seals, take_up, 5);
                    let pts = replay(&sc, precision);
                    let off = HOLD_BEFORE_S + take_up;
                    if frac > 1.0 {
                        match pts.iter().find(|p| p.t >= HOLD_BEFORE_S && p.state.cuts()) {
                            Some(p) => {
                                println!("{:<60} cut ({:?}) {:+.2} s from leaving the ground", sc.name(), p.state, p.t - off);
                                worst = worst.max(p.t - off);
                            }
                            None => uncut.push(sc.name()),
                        }
                    } else {
                        peak90 = pts.iter().filter(|p| p.u > 0.0).map(|p| p.ratio * p.u).fold(peak90, f64::max);
                        if let Some((t, _)) = first_overload(&pts) {
                            false_cut.push(format!("{}: OVERLOAD at {t:.2} s", sc.name()));
                        }
                    }
                }
            }
        }
    }
    println!("{precision:?}, lift-offs snatched in {take_ups:?} s: 110 % cut at most {worst:.2} s after leaving the ground; 90 % cut in {} cases {false_cut:?}, highest estimated u {peak90:.4}", false_cut.len());
    (worst, false_cut, peak90, uncut)
}

/// Snatched in 0.3 s, 110 % is cut within 1 s of leaving the ground at
/// 20°–80° (at 10° at once, by the FAULT of p1 past its range), and 90 % is
/// never an OVERLOAD and reads at most u 0.98. Measured, f64 and f32: cut at
/// most 0.97 s after, the 3 m rope at 35° the slowest (0.98 s, at 80°,
/// before the mean of the bounce's ring was read: `moment_limiter::static_load`,
/// "A lift-off: the mean of its ring"); 90 % at most u 0.970. Before any move, for 1.2 s after the hook last read empty, the
/// still force's load reads a load rising from an empty hook through three
/// of its filter's four stages (`moment_limiter::static_load`, "A lift-off:
/// one stage fewer"); through all four, 110 % was cut 0.99–1.12 s after it
/// left the ground (90 % the same 0.970): the four-stage filter alone
/// crosses 0.866 of a step 0.68 s after a 0.3 s ramp ends, the 0.7 Hz stage
/// against the bounce (`moment_limiter::static_load`, "A still boom") adds
/// 0.31 s, the 50 ms debounce the rest. Without the 0.7 Hz stage a 1.7 Hz
/// bounce of ±68 % reads 90 % as an OVERLOAD.
///
/// Before the rope bank followed the tip's give in a lift-off
/// (`moment_limiter::static_load`, "A lift-off: the boom's give swings the
/// load"), 90 % on the 3 m rope at 80° was an OVERLOAD: the swing the
/// snatch starts (the tip's deflection grows by 4.6 cm, `crane-sim simulate
/// --from-deg 80 --lift-off-s 0.3 --load-kg 9000 --rope held --rope-length-m
/// 3`, and the load swings ±0.8°) pulls 8 % more at its outward crest at
/// tan 80° = 5.7, and no rope of the bank swung with it (highest u 1.0004
/// here; 1.0004–1.0035 over seven noise seeds with `crane-sim synth`). And
/// 110 % was cut up to 1.14 s after.
fn lift_off_snatched_in_0_3_s_is_cut_within_1_s(precision: Precision) {
    let (worst, false_cut, peak90, uncut) = snatched_lift_offs(precision);
    assert!(uncut.is_empty(), "110 % never cut: {uncut:#?}");
    assert!(worst <= 1.0, "110 % cut {worst:.2} s after it leaves the ground");
    assert!(false_cut.is_empty(), "{false_cut:#?}");
    assert!(peak90 <= 0.98, "90 % read as u {peak90:.4}");
}

#[test]
fn lift_off_snatched_in_0_3_s_is_cut_within_1_s_f64() {
    lift_off_snatched_in_0_3_s_is_cut_within_1_s(Precision::F64);
}

#[test]
fn lift_off_snatched_in_0_3_s_is_cut_within_1_s_f32() {
    lift_off_snatched_in_0_3_s_is_cut_within_1_s(Precision::F32);
}

/// Snatched faster, in 0.02–0.2 s: 110 % is cut within 1 s of leaving the
/// ground (at 10°, and at 20° in 0.02–0.1 s, at once by the FAULT of p1 past
/// its range), and 90 % is never an OVERLOAD and reads at most u 0.99.
/// Measured, f64 and f32: cut at most 0.91 s after (put on in 0.02 s; 0.87 s
/// in 0.1–0.2 s), since the mean of the bounce's ring is read from three of
/// its turning points (`moment_limiter::static_load`, "A lift-off: the mean
/// of its ring"; before, the stage against the bounce carried the ring's
/// troughs into the reading: cut up to 1.14 s after, the 3 m rope at 35°;
/// 1.22 s through the still force's four filter stages throughout). 90 %
/// reads at most u 0.985 (f32 0.986), since the reading is held within 3 %
/// of the ring's highest mean while the ring decays ("A lift-off: no
/// higher than its ring"). Before that, 90 % snatched in 0.1 s at 20° was
/// an OVERLOAD in 4 of 40 cases (u 1.005) and in 0.02 s in 6 of 40 (u
/// 1.008), 1.3 s after it left the ground: the first crest of so fast a
/// snatch's bounce pulls up to twice the load, and the stage against the
/// bounce carried its second crest into the reading, where the ring's means
/// had read it at 0.905 and 0.992 of the load.
fn lift_off_snatched_in_0_02_to_0_2_s(precision: Precision) {
    let (worst, false_cut, peak90, uncut) = snatched_in(precision, &[0.02, 0.1, 0.15, 0.2]);
    assert!(uncut.is_empty(), "110 % never cut: {uncut:#?}");
    assert!(worst <= 1.0, "110 % cut {worst:.2} s after it leaves the ground");
    assert!(false_cut.is_empty() && peak90 <= 0.99, "90 % read as u {peak90:.4}, cut: {false_cut:#?}");
}

#[test]
fn lift_off_snatched_in_0_02_to_0_2_s_is_cut_within_1_s_and_90_percent_never_f64() {
    lift_off_snatched_in_0_02_to_0_2_s(Precision::F64);
}

#[test]
fn lift_off_snatched_in_0_02_to_0_2_s_is_cut_within_1_s_and_90_percent_never_f32() {
    lift_off_snatched_in_0_02_to_0_2_s(Precision::F32);
}

/// A load added at rest after a lift-off, before any move: `w0` of the
/// load rated at `angle` taken up in `lift_s` s (snatched in 0.1 s, its ring
/// still rings for seconds), `gap` s later taken to `w1` of it in `take_up`
/// s, then 5 s at rest; constant friction, noise draw 5.
fn added_after_a_lift_off(angle: f64, (w0, lift_s): (f64, f64), gap: f64, w1: f64, take_up: f64, rope: Rope) -> Program {
    let rated = rated_kg(angle.to_radians());
    let mut p = Program::new(angle, 0.0, rope_choice(rope, angle)).unwrap();
    p.push(Segment::Hold { duration_s: HOLD_BEFORE_S }).unwrap();
    p.push(Segment::LiftOff { duration_s: lift_s, load_kg: w0 * rated }).unwrap();
    p.push(Segment::Hold { duration_s: gap }).unwrap();
    p.push(Segment::LiftOff { duration_s: take_up, load_kg: w1 * rated }).unwrap();
    p.push(Segment::Hold { duration_s: 5.0 }).unwrap();
    p
}

/// [`added_after_a_lift_off`] snatched in 0.1 s, at 20°, 65° and 80°, 0.6 s
/// to 3 s after the snatch, taken up in 0.1 s or 0.5 s, on the thesis's rope and the
/// shortest and longest held ones: 50 % or 90 % taken to 110 % (each cut's
/// delay after the second take-up ends, s; `None` if never cut) and 60 %
/// taken to 90 % (whether cut).
fn loads_added_to_ringing_lift_offs(precision: Precision) -> (Vec<(String, Option<f64>)>, Vec<String>) {
    loads_added_after_lift_offs(precision, "ringing lift-offs", &[0.1], &[0.6, 1.0, 1.5, 2.0, 3.0])
}

/// [`loads_added_to_ringing_lift_offs`] after lift-offs taken up in each of
/// `lifts` s, each of `gaps` s before the load is added.
fn loads_added_after_lift_offs(precision: Precision, what: &str, lifts: &[f64], gaps: &[f64]) -> (Vec<(String, Option<f64>)>, Vec<String>) {
    let (mut over, mut under) = (Vec::new(), Vec::new());
    for angle in [20.0, 65.0, 80.0] {
        for &lift_s in lifts {
            for &gap in gaps {
                for take_up in [0.1, 0.5] {
                    for rope in [Rope::Thesis, Rope::Held(0.0), Rope::Held(1.0)] {
                        for (w0, w1) in [(0.5, 1.1), (0.9, 1.1), (0.6, 0.9)] {
                            let rows = program_rows(&added_after_a_lift_off(angle, (w0, lift_s), gap, w1, take_up, rope), Seals::Constant, 5);
                            let pts = replay_rows(&rows, Seals::Constant, precision);
                            let on = HOLD_BEFORE_S + lift_s + gap + take_up;
                            let name = format!("{angle} deg, {w0} (lifted in {lift_s} s) -> {w1} of rated {gap} s after, in {take_up} s, {rope:?}");
                            let cut = pts.iter().find(|q| q.t >= HOLD_BEFORE_S && q.state.cuts()).map(|q| q.t - on);
                            if w1 > 1.0 {
                                over.push((name, cut));
                            } else if cut.is_some() {
                                under.push(name);
                            }
                        }
                    }
                }
            }
        }
    }
    let worst = over.iter().map(|(_, c)| c.unwrap_or(f64::INFINITY)).fold(f64::NEG_INFINITY, f64::max);
    println!("{precision:?}: loads added to {what}: 110 % cut at most {worst:.2} s after the take-up ends, 90 % cut in {} cases", under.len());
    (over, under)
}

/// A delay (s) of at most 1 s, to the sample: the times are sums of 10 ms
/// steps, and 1 s after can come out a rounding above 1.0.
fn within_a_second(delay_s: f64) -> bool {
    delay_s <= 1.0 + 1e-9
}

/// KNOWN GAP, measured (f64 and f32): 90 % of rated snatched in 0.1 s on
/// the 3 m rope at 80°, before any move, and taken to 110 % in 0.1 s 3 s
/// later is cut 1.05 s after its take-up ends. The force rings from 150
/// to 200 kN, a third of the load's part peak to peak, and the load added
/// lifts it by a fifth of that part: no rise of it passes the ring's
/// crests by the margin a winch's pull asks (`moment_limiter::static_load`,
/// "A load added to one that rings on: a rise over all it did"). Until
/// that rise was read, 50 % taken to 110 % 1.5–3 s after at 65° was cut
/// 1.01–1.14 s after too (the 3 m rope; 1.5 s after, the thesis's and the
/// longest rope). Where the snatch's ring still decays when the load is added, and
/// the lift window has closed, the ring's break reads the load as a lift-off
/// ("A load added while a lift-off rings: a lift-off again" in
/// `moment_limiter::static_load`): 50 % taken to 110 % 3 s after on the 3 m
/// rope at 80°, where the force rang at 3.2 Hz from 99 to 116 kN before the
/// take-up and from 110 to 260 kN after, was cut 1.20 s after, now within
/// the second. On the 3 m rope at 65° the ring rides on the swing that the
/// boom's give starts and breaks within the lift window, so nothing follows
/// it when the load is added (the span's rise reads it now); reading a
/// break within the window as a lift-off too, tried, cut 110 % snatched
/// there 1.04 s after it left the ground (0.91 s) and made 90 % an
/// OVERLOAD in 4 of 40 cases.
#[test]
#[ignore = "KNOWN GAP: 90 % snatched at 80 deg on the 3 m rope and taken to 110 % in 0.1 s 3 s later is cut 1.05 s after its take-up"]
fn a_load_added_to_a_ringing_lift_off_known_gap() {
    cut_within_1_s_but_at_65_to_80_degrees_in_0_1_s(loads_added_to_ringing_lift_offs(Precision::F64), 1.0, Precision::F64);
}

/// Asserts the loads added after lift-offs ([`loads_added_after_lift_offs`]:
/// `over`, each 110 % with its cut's delay; `under`, the 90 % cut): 110 % cut
/// within 1 s of its take-up's end, but within `gap_s` where it is taken up
/// in 0.1 s at 65° or 80° (the known gap; a `gap_s` of 1 asks the second of
/// every case; to the sample, as [`within_a_second`]), and 90 % never cut.
fn cut_within_1_s_but_at_65_to_80_degrees_in_0_1_s((over, under): (Vec<(String, Option<f64>)>, Vec<String>), gap_s: f64, precision: Precision) {
    let gap = |n: &str| (n.starts_with("65 deg") || n.starts_with("80 deg")) && n.contains(", in 0.1 s,");
    let late: Vec<_> = over.iter().filter(|(n, c)| !c.is_some_and(|c| within_a_second(c) || (gap(n) && c <= gap_s + 1e-9))).collect();
    let elsewhere = over.iter().filter(|(n, _)| !gap(n)).map(|(_, c)| c.unwrap_or(f64::INFINITY)).fold(f64::NEG_INFINITY, f64::max);
    println!("{precision:?}: outside the known gap, 110 % cut at most {elsewhere:.2} s after the take-up ends");
    assert!(late.is_empty() && under.is_empty(), "110 % cut late: {late:#?}; 90 % cut: {under:#?}");
}

/// A load added at rest while a lift-off still rings, before any move: the
/// ring's cap ("A lift-off: no higher than its ring") lowers a reading, and
/// must not keep a heavier load waiting. 110 % is cut within 1 s of its
/// take-up's end but in the known gap above (there within 1.05 s, as
/// measured; 1.14 s before a rise over the ring's span was read as a
/// lift-off, 1.20 s before a ring's break was), and 90 % is never cut.
/// Measured (f64 and f32): within 0.90 s elsewhere (0.97 s before the
/// span's rise, 1.00 s before the break). Where the cap held the reading down, 90 % snatched at 20° and
/// taken to 110 % 1 s later is cut 0.76 s after (0.20 s before the cap, when
/// 90 % alone read near the cut: at 20° it was cut before any load was added
/// in 14 of the 30 cases of 90 % taken to 110 %, the known gap of the snatch
/// that the cap closed).
fn loads_added_to_ringing_lift_offs_are_cut(precision: Precision) {
    cut_within_1_s_but_at_65_to_80_degrees_in_0_1_s(loads_added_to_ringing_lift_offs(precision), 1.05, precision);
}

#[test]
fn loads_added_to_ringing_lift_offs_are_cut_f64() {
    loads_added_to_ringing_lift_offs_are_cut(Precision::F64);
}

#[test]
fn loads_added_to_ringing_lift_offs_are_cut_f32() {
    loads_added_to_ringing_lift_offs_are_cut(Precision::F32);
}

/// [`loads_added_after_lift_offs`] 5 s and 12 s after lift-offs snatched in
/// 0.1 s or taken up in 2 s: the load hangs steadily when the next is added
/// (the snatch's ring has died).
fn loads_added_to_hanging_loads(precision: Precision) -> (Vec<(String, Option<f64>)>, Vec<String>) {
    loads_added_after_lift_offs(precision, "loads hanging steadily", &[0.1, 2.0], &[5.0, 12.0])
}

/// A load added at rest to one hanging steadily before any move, 50 % or
/// 90 % taken to 110 % and 60 % to 90 %: 110 % cut within 1 s of its
/// take-up's end, 90 % never. A rise out of the band the load held steadily
/// for a second, or over all the force did since the lift-off's first crest
/// where its ring rings on, is read as a lift-off
/// (`moment_limiter::static_load`, "A load added to one hanging steadily: a
/// lift-off again" and "A load added to one that rings on: a rise over all
/// it did"). Measured (f64 and f32 alike): within 0.73 s. Before the steady
/// band, 11 of the 72 cases of 110 % were cut 1.01–1.11 s after (the
/// longest on the 3 m rope at 80° after a lift-off taken up in 2 s), the
/// load rising through the filter's four stages and the stage against the
/// bounce; before the span, one: 1.02 s after, on the 3 m rope at 65° 5 s
/// after its snatch, whose ring rides on the swing the boom's give starts
/// (nearly half the load's pull peak to peak) and is never steady.
fn loads_added_to_hanging_loads_are_cut(precision: Precision) {
    cut_within_1_s_but_at_65_to_80_degrees_in_0_1_s(loads_added_to_hanging_loads(precision), 1.0, precision);
}

#[test]
fn loads_added_to_hanging_loads_are_cut_f64() {
    loads_added_to_hanging_loads_are_cut(Precision::F64);
}

#[test]
fn loads_added_to_hanging_loads_are_cut_f32() {
    loads_added_to_hanging_loads_are_cut(Precision::F32);
}

/// [`snatched_in`] on a boom 30 % softer than the limiter's model (Young's
/// modulus 0.7 of it: the bounce slower, about 1.2 Hz at 20°, and the ring
/// deeper), with its own calibration.
fn snatched_on_a_softer_boom(take_ups: &[f64]) -> (f64, Vec<String>, f64, Vec<String>) {
    with_setting(&BOOM_FACTORS, (0.7, 1.0), || snatched_in(Precision::F64, take_ups))
}

/// KNOWN GAP, measured (f64): on a boom 30 % softer than the model, 90 %
/// snatched in 0.02–0.1 s on the 3 m rope at 65° is an OVERLOAD (2 of 40
/// cases, both friction laws; highest estimated u 1.023 in 0.1 s, 1.028 in
/// 0.02 s), about 1.8 s after it leaves the ground; and 110 % put on in
/// 0.02 s is cut 1.04 s after (0.99 s in 0.1 s). There the ring rides on
/// the swing that the boom's give starts (the softer boom gives more than
/// the model's, and no rope of the bank predicts the rest), its turning
/// points leave the envelope of a decaying ring, and the reading is no
/// longer held to the ring's mean (`moment_limiter::static_load`, "A
/// lift-off: no higher than its ring"); the stage against the bounce
/// carries a crest into it. Snatched in 0.3 s, taken up in 0.5–2 s: never
/// (at most u 0.990). Before the ring's cap, 90 % snatched in 0.3 s was an
/// OVERLOAD in 24 of 40 cases (every rope at 10°–35°, u up to 1.029) and in
/// 0.1 s in 18 of 40 (u 1.070): the ring is slower (1.2 Hz at 20°) and
/// swings from 0.6 to 1.4 × the load, its mean reads the load at 0.996 of
/// itself 1.1 s after it leaves the ground, and the stage carried the second
/// crest to 1.09 × the load 0.25 s later. How it goes as the boom softens,
/// 90 % snatched in 0.1 s / 0.3 s / 0.02 s (before the cap, 0.1 s / 0.3 s):
/// Young's modulus 1.3 of the model's, none (u 0.972 / 0.956 / 0.973; was
/// none / none); 1.0, none (0.984 / 0.970 / 0.985; 4 of 40 / none); 0.9,
/// none (0.991 / 0.975 / 0.995; 16 of 40 / none); 0.8, 2 of 40 at 65° (1.005
/// / 0.978 / 1.010; 18 / 2 of 40); 0.7, 2 of 40 at 65° (1.023 / 0.990 /
/// 1.028; 18 / 24 of 40). The boom's damping 0.3 of the model's: none
/// (0.984 / 0.974 / 0.990; 12 of 40 / none). 110 % is cut within 0.99 s in
/// all of them but put on in 0.02 s on the softest (1.04 s). Measured with
/// `BOOM_FACTORS` and [`snatched_in`].
#[test]
#[ignore = "KNOWN GAP: on a boom 30 % softer than the model, 90 % snatched in 0.1 s on the 3 m rope at 65 deg is an OVERLOAD (2 of 40 cases, u 1.023)"]
fn lift_off_snatched_on_a_softer_boom_known_gap() {
    let (worst, false_cut, _, uncut) = snatched_on_a_softer_boom(&[0.1, 0.3]);
    assert!(worst <= 1.0 && false_cut.is_empty() && uncut.is_empty(), "110 % cut {worst:.2} s after; 90 % cut: {false_cut:#?}; 110 % never cut: {uncut:#?}");
}

/// The known gap above pinned at its measured size: snatched in 0.1 s or
/// 0.3 s, 110 % is cut within 1 s of leaving the ground (0.99 s measured),
/// and 90 % is an OVERLOAD only on the 3 m rope at 65°, in at most 2 of
/// the 80 cases, reading at most u 1.03 (1.023 measured).
#[test]
fn lift_off_snatched_on_a_softer_boom_stays_as_measured() {
    let (worst, false_cut, peak90, uncut) = snatched_on_a_softer_boom(&[0.1, 0.3]);
    assert!(uncut.is_empty() && worst <= 1.0, "110 % cut {worst:.2} s after; never cut: {uncut:#?}");
    let other: Vec<&String> = false_cut.iter().filter(|f| !(f.starts_with("65->65") && f.contains("Held(0.0)"))).collect();
    assert!(false_cut.len() <= 2 && other.is_empty() && peak90 <= 1.03, "90 % read as u {peak90:.4}, cut: {false_cut:#?}");
}

/// 90 % of rated lifted on the 3 m held rope at 80° (where the swing that
/// the boom's give starts pulls most, see
/// [`lift_off_snatched_in_0_3_s_is_cut_within_1_s`]), taken up in `take_up` s,
/// both friction laws, noise seeds 1–8: the OVERLOADs and the highest
/// estimated u.
fn ninety_percent_on_a_3_m_rope_at_80_degrees(precision: Precision, take_up: f64) -> (usize, f64) {
    let rated = rated_kg(80f64.to_radians());
    let (mut cut, mut peak) = (0usize, 0.0f64);
    for seals in SEALS {
        for seed in 1..=8 {
            let sc = Scenario { duration_s: 8.0, ..Scenario::lift_off(80.0, 0.9 * rated, Rope::Held(0.0), seals, take_up, seed) };
            let pts = replay(&sc, precision);
            peak = pts.iter().filter(|p| p.u > 0.0).map(|p| p.ratio * p.u).fold(peak, f64::max);
            cut += usize::from(first_overload(&pts).is_some());
        }
    }
    println!("{precision:?}, 90 % on the 3 m rope at 80 deg taken up in {take_up} s: {cut} of 16 an OVERLOAD, highest estimated u {peak:.4}");
    (cut, peak)
}

/// 90 % lifted on the 3 m rope at 80°, over 16 noise draws and take-ups of
/// 0.3 s to 2 s, is never an OVERLOAD and reads at most u 0.96 (measured,
/// f64: 0.9504 in 0.3 s, 0.9494 in 0.5 s, 0.9486 in 1 s, 0.9403 in 2 s, f32
/// within 0.0007 (0.9511 in 0.3 s: 0.9506 before a lift-off was read at
/// once until it bounces, `moment_limiter::static_load`); the ×1.05 reading
/// of 90 % is 0.945). Through the still
/// force's four filter stages throughout, before a load rising from an
/// empty hook was read through three for 1.2 s (`moment_limiter::static_load`,
/// "A lift-off: one stage fewer"), 0.9486, 0.9485, 0.9481 and 0.9404; for
/// 2 s, up to 0.9609. Before the rope bank
/// followed the tip's give in a lift-off, the swing the take-up starts read
/// as load at its outward crest: an OVERLOAD in all 16 draws taken up in
/// 0.3 s (highest u 1.0035), in 8 in 0.5 s (1.0028), and 0.9958 in 1 s.
fn ninety_percent_lifted_on_a_3_m_rope_at_80_degrees_is_no_overload(precision: Precision) {
    for take_up in [0.3, 0.5, 1.0, 2.0] {
        let (cut, peak) = ninety_percent_on_a_3_m_rope_at_80_degrees(precision, take_up);
        assert!(cut == 0 && peak <= 0.96, "taken up in {take_up} s: {cut} OVERLOADs, highest u {peak:.4}");
    }
}

#[test]
fn ninety_percent_lifted_on_a_3_m_rope_at_80_degrees_is_no_overload_f64() {
    ninety_percent_lifted_on_a_3_m_rope_at_80_degrees_is_no_overload(Precision::F64);
}

#[test]
fn ninety_percent_lifted_on_a_3_m_rope_at_80_degrees_is_no_overload_f32() {
    ninety_percent_lifted_on_a_3_m_rope_at_80_degrees_is_no_overload(Precision::F32);
}

#[test]
fn lift_off_f64() {
    lift_off(Precision::F64, &SEALS);
}

#[test]
fn lift_off_f32() {
    lift_off(Precision::F32, &SEALS);
}

/// The log of a session after [`HOLD_BEFORE_S`] at rest: a 10 s cycloidal
/// move `from` → `to` with `w0` kg on `rope`, `at_rest_s` at rest, the hook
/// load taken up to `w1` kg over `take_up_s`, then `after_s` at rest.
#[allow(clippy::too_many_arguments)]
fn lift_after_a_move(from: f64, to: f64, rope: Rope, seals: Seals, w0: f64, at_rest_s: f64, take_up_s: f64, w1: f64, after_s: f64) -> Vec<SynthRow> {
    let mut p = Program::new(from, w0, rope_choice(rope, from.min(to))).unwrap();
    p.push(Segment::Hold { duration_s: HOLD_BEFORE_S }).unwrap();
    p.push(Segment::Luff { to_deg: to, shape: RampShape::Cycloidal, t1_s: 1.0, t2_s: 9.0, t3_s: 10.0 }).unwrap();
    p.push(Segment::Hold { duration_s: at_rest_s }).unwrap();
    p.push(Segment::LiftOff { duration_s: take_up_s, load_kg: w1 }).unwrap();
    p.push(Segment::Hold { duration_s: after_s }).unwrap();
    program_rows(&p, seals, 13)
}

/// Lift-off taken up fast on a slow angle sensor (run it
/// [`behind_a_lagging_sensor`]): at 20°, 50° and 80°, on a sensor that lags
/// by 0.3 s (a first-order lag, learned by the
/// calibration), the hoist takes 90 % or 110 % of the rated load up in 1 s
/// or 0.5 s: at 110 % OVERLOAD within 1 s of the load leaving the ground;
/// at 90 % no OVERLOAD. The force of a still boom is read without the
/// sensor's lag (`moment_limiter::static_load`, "A still boom"); through
/// the lag, 110 % taken up in 1 s was cut 1.16–1.20 s after it left the
/// ground, and in 0.5 s 1.33–1.38 s.
fn lift_off_fast_on_a_slow_sensor(precision: Precision) {
    let mut failures = Vec::new();
    for angle in [20.0f64, 50.0, 80.0] {
        let rated = rated_kg(angle.to_radians());
        for seals in SEALS {
            for take_up in [1.0, 0.5] {
                for (frac, must) in [(0.9, false), (1.1, true)] {
                    let sc = Scenario::lift_off(angle, frac * rated, Rope::Thesis, seals, take_up, 5);
                    let pts = replay(&sc, precision);
                    let off = HOLD_BEFORE_S + take_up;
                    let first = first_overload(&pts);
                    println!("{:<60} OVERLOAD {}", sc.name(), first.map_or("none".into(), |f| format!("at {:+.2} s from leaving the ground", f.0 - off)));
                    match (must, first) {
                        (false, Some((t, _))) => failures.push(format!("{}: OVERLOAD at {t:.2} s", sc.name())),
                        (true, None) => failures.push(format!("{}: no OVERLOAD", sc.name())),
                        (true, Some((t, _))) if t > off + 1.0 => failures.push(format!("{}: OVERLOAD {:.2} s after lift", sc.name(), t - off)),
                        _ => {}
                    }
                }
            }
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

/// A lift-off whose bounce is not the simulator's: the piston force of a
/// lift-off at `angle_deg` taken up slowly (2 s, where this crane's bounce
/// at 1.4–1.6 Hz, or 3.2 Hz at 80°, is barely excited), replaced by an ideal
/// one, F_0 + (F_1 − F_0)·y(t): y the response of a mass on a spring of
/// `bounce_hz` and damping ratio `zeta` to the hook's share of the load
/// rising linearly from 0 to 1 over `take_up_s` (ÿ = ω²(s − y) − 2ζω·ẏ), the
/// whole load's pull bouncing (in the simulator about 0.75 of it does);
/// F_0 the force before, F_1 the mean after. Then the same sensors, noise
/// and quantization as every log here.
fn lift_off_with_an_ideal_bounce(angle_deg: f64, load_kg: f64, bounce_hz: f64, zeta: f64, take_up_s: f64) -> Vec<SynthRow> {
    let sc = Scenario::lift_off(angle_deg, load_kg, Rope::Thesis, Seals::Constant, 2.0, 5);
    let (options, dt) = options_for_rate(rate_hz());
    let mut samples = simulate_program(model(), &sc.program(), &options).expect("simulation");
    let f0 = samples[0].reactions.piston_force_n;
    let tail: Vec<f64> = samples.iter().filter(|x| x.t_s >= HOLD_BEFORE_S + 4.0).map(|x| x.reactions.piston_force_n).collect();
    let f1 = tail.iter().sum::<f64>() / tail.len() as f64;
    let w = 2.0 * std::f64::consts::PI * bounce_hz;
    let (mut y, mut v) = (0.0f64, 0.0f64);
    let mut last_t = 0.0;
    for x in &mut samples {
        // Ten semi-implicit Euler steps per sample: ω·h ≤ 0.013 at 2 Hz.
        let steps = 10;
        let h = (x.t_s - last_t) / steps as f64;
        for k in 1..=steps {
            let t = last_t + h * k as f64;
            let share = ((t - HOLD_BEFORE_S) / take_up_s).clamp(0.0, 1.0);
            v += (w * w * (share - y) - 2.0 * zeta * w * v) * h;
            y += v * h;
        }
        last_t = x.t_s;
        x.reactions.piston_force_n = f0 + (f1 - f0) * y;
        x.hook_load_kg = load_kg * ((x.t_s - HOLD_BEFORE_S) / take_up_s).clamp(0.0, 1.0);
    }
    synthesize(&samples, dt, 0.0, load_kg, &sensors(Seals::Constant, 5))
}

/// Lift-off against a bounce of 1–2 Hz that is not this crane's
/// ([`lift_off_with_an_ideal_bounce`]; issue 11 gives 1–2 Hz near the rated
/// load, and the simulator bounces at 1.4–1.6 Hz at 20–45°): at 20°, 50° and
/// 80°, bounces of 1, 1.5 and 2 Hz with damping ratios 0.02 and 0.06, taken
/// up over `take_ups`: 90 % of rated never OVERLOAD, 110 % OVERLOAD within
/// 1 s of leaving the ground. Returns the failures and prints every case.
fn lift_off_against_an_ideal_bounce(precision: Precision, take_ups: &[f64]) -> (Vec<String>, f64) {
    let (mut failures, mut worst) = (Vec::new(), 0.0f64);
    for angle in [20.0f64, 50.0, 80.0] {
        let rated = rated_kg(angle.to_radians());
        for bounce_hz in [1.0, 1.5, 2.0] {
            for zeta in [0.02, 0.06] {
                for &take_up in take_ups {
                    for (frac, must) in [(0.9, false), (1.1, true)] {
                        let rows = lift_off_with_an_ideal_bounce(angle, frac * rated, bounce_hz, zeta, take_up);
                        let pts = replay_rows(&rows, Seals::Constant, precision);
                        let off = HOLD_BEFORE_S + take_up;
                        let first = first_overload(&pts);
                        let peak = pts.iter().filter(|p| p.u > 0.0).map(|p| p.ratio * p.u).fold(0.0, f64::max);
                        let name = format!("{angle:.0} deg, {:.0} % of rated, bounce {bounce_hz} Hz, zeta {zeta}, taken up in {take_up} s", frac * 100.0);
                        println!("{name:<62} peak estimated u {peak:.3}, OVERLOAD {}", first.map_or("none".into(), |f| format!("at {:+.2} s from leaving the ground", f.0 - off)));
                        if let (true, Some((t, _))) = (must, first) {
                            worst = worst.max(t - off);
                        }
                        match (must, first) {
                            (false, Some((t, _))) => failures.push(format!("{name}: OVERLOAD at {t:.2} s (peak estimated u {peak:.3})")),
                            (true, None) => failures.push(format!("{name}: no OVERLOAD")),
                            (true, Some((t, _))) if t > off + 1.0 => failures.push(format!("{name}: OVERLOAD {:.2} s after lift", t - off)),
                            _ => {}
                        }
                    }
                }
            }
        }
    }
    println!("{precision:?}: {} failures, 110 % cut at most {worst:.2} s after leaving the ground", failures.len());
    (failures, worst)
}

#[test]
fn lift_off_against_an_ideal_bounce_f64() {
    let (failures, _) = lift_off_against_an_ideal_bounce(Precision::F64, &[0.8, 1.2, 2.0]);
    assert!(failures.is_empty(), "{failures:#?}");
}

#[test]
fn lift_off_against_an_ideal_bounce_f32() {
    let (failures, _) = lift_off_against_an_ideal_bounce(Precision::F32, &[0.8, 1.2, 2.0]);
    assert!(failures.is_empty(), "{failures:#?}");
}

/// The same taken up in 0.5 s and 0.3 s, where the filters that keep a
/// 1 Hz bounce out cannot also tell 90 % from 110 % within a second. A
/// bounce of 1 Hz reads 90 % as an OVERLOAD in 8 of its 12 cases (peak
/// estimated u up to 1.013 taken up in 0.5 s, 1.069 in 0.3 s: its first
/// crest pulls up to twice the load, and the filters pass a fifth of
/// 1 Hz); 10 of 12 (up to 1.040 and 1.078) before the reading was held to
/// the ring's mean (`moment_limiter::static_load`, "A lift-off: no higher
/// than its ring"); 8 of 12 (up to 1.038 and 1.071) through the still force's four
/// filter stages throughout, before a load rising from an empty hook was
/// read through three (`moment_limiter::static_load`, "A lift-off: one
/// stage fewer"), and all 12 before the rope bank followed the tip's give
/// in a lift-off, whose swing, which this world's force does not have,
/// lowers the lowest rope's reading. At 1.5–2 Hz, 90 % reads at most u
/// 0.977 (0.3 s; 0.992 before the ring's cap) and 0.964 (0.5 s), and 110 % is cut within 0.74 s (0.99 s
/// before the mean of the bounce's ring was read, `moment_limiter::static_load`,
/// "A lift-off: the mean of its ring"; 0.97–1.08 s in 0.3 s through four
/// stages). In the asserted cases (`lift_off_against_an_ideal_bounce_*`,
/// 0.8 s and slower) 90 % reads at most 0.972 (0.977 before the ring's cap) and 110 % is cut within 0.65 s
/// (0.69 s before the ring's mean, 0.84 s through four stages).
#[test]
#[ignore = "KNOWN GAP: a lift-off snatched in 0.5 s or less against a bounce of 1 Hz: 90 % is an OVERLOAD in 8 of 12 cases"]
fn lift_off_snatched_against_an_ideal_bounce_known_gap() {
    let (failures, _) = lift_off_against_an_ideal_bounce(Precision::F64, &[0.3, 0.5]);
    assert!(failures.is_empty(), "{failures:#?}");
}

/// The known gap above pinned at its measured size: snatched in 0.3 s or
/// 0.5 s against an ideal bounce of 1–2 Hz, 110 % is cut within 1 s of
/// leaving the ground (measured, f64: at most 0.74 s; 0.99 s before the
/// ring's mean was read), and 90 % is an OVERLOAD only behind the 1 Hz
/// bounce (the gap).
#[test]
fn lift_off_snatched_against_an_ideal_bounce_is_cut_within_1_s() {
    let (failures, worst) = lift_off_against_an_ideal_bounce(Precision::F64, &[0.3, 0.5]);
    let other: Vec<&String> = failures.iter().filter(|f| !f.contains("90 % of rated, bounce 1 Hz")).collect();
    assert!(other.is_empty(), "{other:#?}");
    assert!(worst <= 1.0, "110 % cut {worst:.2} s after it leaves the ground");
}

/// Runs `f` with this thread's `setting` at `value`, then sets it as
/// before; returns what `f` returns.
fn with_setting<V: Copy, R>(setting: &'static std::thread::LocalKey<std::cell::Cell<V>>, value: V, f: impl FnOnce() -> R) -> R {
    let before = setting.with(|c| c.replace(value));
    let got = f();
    setting.with(|c| c.set(before));
    got
}

/// Runs `f` on this thread with the angle sensor a first-order lag of
/// `tau_s` (see [`SENSOR_LAG_S`]).
fn behind_a_lagging_sensor(tau_s: f64, f: impl FnOnce()) {
    with_setting(&SENSOR_LAG_S, Some(tau_s), f);
}

#[test]
fn lift_off_fast_on_a_slow_sensor_f64() {
    behind_a_lagging_sensor(0.3, || lift_off_fast_on_a_slow_sensor(Precision::F64));
}

#[test]
fn lift_off_fast_on_a_slow_sensor_f32() {
    behind_a_lagging_sensor(0.3, || lift_off_fast_on_a_slow_sensor(Precision::F32));
}

/// A load added at rest while the load still swings from a move (the
/// campaign's lift-offs start with the load hanging still): a 10 s cycloidal
/// move (40° → 60°, 60° → 40°, 40° → 80°) with 60 % of the lower of the two
/// angles' rated loads on a held rope (3 m, a quarter, half and all the way
/// to the tip height at the lowest angle), 3 s at rest, then the hoist takes
/// up more load over 0.5 s, to 90 % or 110 % of the rated load at rest:
/// at 110 % OVERLOAD within 1 s of the end of the take-up; at 90 % no
/// OVERLOAD, and the estimate (×1.05, SAE J376) within 1 s at 1/1.1 of the
/// true load (where a 110 % load reads as an OVERLOAD); the time to reach
/// the true load is printed. Before the common-jump rescale (`moment_limiter::load_jump`) the
/// estimate followed at the slow averages' pace (seen after up to 6 s, or
/// not within 7 s, in the bank's unit test).
fn load_added_at_rest_after_a_move(precision: Precision, cases: &[(f64, f64, Rope)]) {
    let (failures, _) = load_added_at_rest_after_a_move_measured(precision, cases, 4.0);
    assert!(failures.is_empty(), "{failures:#?}");
}

/// The worst of [`load_added_at_rest_after_a_move_measured`]'s cases.
#[derive(Debug, Clone, Copy, Default)]
struct AddedAtRestWorst {
    /// 110 %: its first OVERLOAD (s after its take-up; infinite when none comes).
    slowest_overload_s: f64,
    /// 110 %: the longest time it is not [`cut`] after its take-up (s).
    longest_uncut_s: f64,
    /// 90 %: the true u at its first OVERLOAD (0 when none comes).
    overload_at_90_u: f64,
    /// 90 %: how many cases are cut.
    overloads_at_90: usize,
}

/// [`load_added_at_rest_after_a_move`]'s cases, measured over `after_s` at
/// rest after the take-up (4 s there): the failures and the worst cuts.
fn load_added_at_rest_after_a_move_measured(precision: Precision, cases: &[(f64, f64, Rope)], after_s: f64) -> (Vec<String>, AddedAtRestWorst) {
    load_added_after_a_stop_measured(precision, cases, 3.0, after_s)
}

/// [`load_added_at_rest_after_a_move_measured`] with the take-up begun
/// `at_rest_s` after the stop (3 s there).
fn load_added_after_a_stop_measured(precision: Precision, cases: &[(f64, f64, Rope)], at_rest_s: f64, after_s: f64) -> (Vec<String>, AddedAtRestWorst) {
    const TAKE_UP_S: f64 = 0.5;
    let mut failures = Vec::new();
    let mut worst_seen: f64 = 0.0;
    let mut worst = AddedAtRestWorst::default();
    for &(from, to, rope) in cases {
        let w0 = 0.6 * rated_kg(from.min(to).to_radians());
        {
            for seals in SEALS {
                for (frac, must) in [(0.9, false), (1.1, true)] {
                    let w1 = frac * rated_kg(to.to_radians());
                    let name = format!("{from:.0}->{to:.0} 10s {rope:?} {seals:?}: {w0:.0} kg, +{:.0} kg at rest", w1 - w0);
                    let rows = lift_after_a_move(from, to, rope, seals, w0, at_rest_s, TAKE_UP_S, w1, after_s);
                    let pts = replay_rows(&rows, seals, precision);
                    let lifted = HOLD_BEFORE_S + 10.0 + at_rest_s + TAKE_UP_S;
                    // Seen: the estimate at 1/1.1 of the true load, where a
                    // 110 % load is an OVERLOAD (the lift-off test's bound).
                    let seen = pts.iter().find(|q| q.t >= lifted && q.ratio >= 1.0 / 1.1).map(|q| q.t - lifted);
                    let full = pts.iter().find(|q| q.t >= lifted && q.ratio >= 1.0).map(|q| q.t - lifted);
                    let first = first_overload(&pts);
                    println!(
                        "{name:<62} estimate >= true/1.1 {} s after, >= true {} s, OVERLOAD {}",
                        seen.map_or("never".into(), |s| format!("{s:+.2}")),
                        full.map_or("never".into(), |s| format!("{s:+.2}")),
                        first.map_or("none".into(), |f| format!("at {:+.2} s, true u {:.3}", f.0 - lifted, f.1))
                    );
                    worst_seen = worst_seen.max(seen.unwrap_or(f64::INFINITY));
                    if must {
                        let uncut_s = pts.iter().filter(|q| q.t >= lifted && !cut(q)).count() as f64 / rate_hz();
                        worst.longest_uncut_s = worst.longest_uncut_s.max(uncut_s);
                        worst.slowest_overload_s = worst.slowest_overload_s.max(first.map_or(f64::INFINITY, |f| f.0 - lifted));
                    } else if let Some((_, u)) = first {
                        worst.overload_at_90_u = worst.overload_at_90_u.max(u);
                        worst.overloads_at_90 += 1;
                    }
                    match (must, first, seen) {
                        (false, Some((t, u)), _) => failures.push(format!("{name}: OVERLOAD at {t:.2} s, true u {u:.3}")),
                        (false, None, s) if s.is_none_or(|s| s > 1.0) => failures.push(format!("{name}: estimate below 1/1.1 of the true load 1 s after ({s:?})")),
                        (true, None, _) => failures.push(format!("{name}: no OVERLOAD")),
                        (true, Some((t, u)), _) if t > lifted + 1.0 || u < 1.0 / 1.1 => {
                            failures.push(format!("{name}: OVERLOAD at {:+.2} s, true u {u:.3}", t - lifted))
                        }
                        _ => {}
                    }
                }
            }
        }
    }
    println!("{precision:?}: {} failures of {}; slowest estimate to reach 1/1.1 of the true load {worst_seen:.2} s after the take-up", failures.len(), 4 * cases.len());
    (failures, worst)
}

/// A load lifted after a move with the hook empty (a 10 s cycloidal move,
/// `at_rest_s` at rest, then 110 % or 90 % of the rated load taken up over 2 s):
/// the load swings on as the empty hook did, and the rope bank's averages,
/// which weighed the empty hook, start from nothing. 3–6 s after the load
/// leaves the ground the estimate (×1.05) is at least 1/1.1 of the true
/// load, where a 110 % load reads as an OVERLOAD, and 90 % is never an
/// OVERLOAD. Before the averages were kept no lower than W_fast at rest
/// after a light move (`moment_limiter::static_load`), the estimate read
/// 0.38–0.81 of the load 5 s after (the thesis rope 20° → 70° and
/// 40° → 56°). How soon the 110 % load is cut is printed, not asserted
/// (0.56–2.34 s here): the bank's minimum over the ropes reads the load low
/// while their swings spread (see the module doc).
fn load_lifted_after_an_empty_hook_move(precision: Precision, cases: &[(f64, f64, Rope)], at_rest_s: f64) {
    const TAKE_UP_S: f64 = 2.0;
    let mut failures = Vec::new();
    for &(from, to, rope) in cases {
        for seals in SEALS {
            for frac in [0.9, 1.1] {
                let w = frac * rated_kg(to.to_radians());
                let name = format!("{from:.0}->{to:.0} 10s {rope:?} {seals:?}: empty, then {w:.0} kg lifted at rest");
                let rows = lift_after_a_move(from, to, rope, seals, 0.0, at_rest_s, TAKE_UP_S, w, 7.0);
                let pts = replay_rows(&rows, seals, precision);
                let lifted = HOLD_BEFORE_S + 10.0 + at_rest_s + TAKE_UP_S;
                let low = pts.iter().filter(|q| q.t >= lifted + 3.0 && q.t <= lifted + 6.0).map(|q| q.ratio).fold(f64::INFINITY, f64::min);
                let first = first_overload(&pts);
                println!(
                    "{name:<66} lowest estimate/true 3-6 s after {low:.3}, OVERLOAD {}",
                    first.map_or("none".into(), |f| format!("at {:+.2} s, true u {:.3}", f.0 - lifted, f.1))
                );
                if frac < 1.0 && first.is_some() {
                    failures.push(format!("{name}: OVERLOAD at 90 %"));
                }
                if frac > 1.0 && (!low.is_finite() || low < 1.0 / 1.1) {
                    failures.push(format!("{name}: estimate {low:.3} of the true load 3-6 s after"));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

/// The moves and ropes of [`load_lifted_after_an_empty_hook_move`].
const LIFTED_AFTER_EMPTY: [(f64, f64, Rope); 6] = [
    (40.0, 56.0, Rope::Thesis),
    (20.0, 70.0, Rope::Thesis),
    (60.0, 30.0, Rope::Thesis),
    (40.0, 56.0, Rope::Held(0.0)),
    (60.0, 30.0, Rope::Held(0.0)),
    (40.0, 56.0, Rope::Held(0.5)),
];

/// A load lifted after an empty-hook move where no rope of the bank follows
/// the swing (the moves and ropes of
/// [`a_load_lifted_after_an_empty_hook_move_known_gap`]: the 3 m rope swings
/// 17° at 70°; the load taken up over 2 s after 3 s at rest, 20 s more at
/// rest): once the mean over one swing period is found, it holds the weighing
/// for good. Asserted, from P·4/3 + 3 s after the take-up to the end: for
/// 90 % and 110 % the estimate within [1.00, 1.10] of the true load, and
/// 110 % cut. Before the last period was searched again first
/// (`moment_limiter::period_mean::HINT_SPANS`), on the 3 m rope the mean,
/// found 6.5 s after the take-up, was lost for 1 s of every 3.7 s swing from
/// +10 s on, and the estimate fell to 0.91 of the load (×1.05 included;
/// 1.04 with it).
fn load_lifted_after_an_empty_hook_move_and_weighed(precision: Precision) {
    let cases = [(20.0, 70.0, Rope::Held(0.0)), (20.0, 70.0, Rope::Held(0.5))];
    load_added_and_weighed_by_its_period(precision, &cases, 0.0, 3.0, 2.0, Checks { in_band: true, ninety_clear: false }, |p| p * (1.0 + 1.0 / 3.0) + 3.0);
}

#[test]
fn a_load_lifted_after_an_empty_hook_move_is_weighed_by_its_period_f64() {
    load_lifted_after_an_empty_hook_move_and_weighed(Precision::F64);
}

#[test]
fn a_load_lifted_after_an_empty_hook_move_is_weighed_by_its_period_f32() {
    load_lifted_after_an_empty_hook_move_and_weighed(Precision::F32);
}

#[test]
fn a_load_lifted_after_an_empty_hook_move_f64() {
    load_lifted_after_an_empty_hook_move(Precision::F64, &LIFTED_AFTER_EMPTY, 3.0);
}

#[test]
fn a_load_lifted_after_an_empty_hook_move_f32() {
    load_lifted_after_an_empty_hook_move(Precision::F32, &LIFTED_AFTER_EMPTY, 3.0);
}

/// KNOWN GAP, measured (f64), 20° → 70° (tan θ = 2.75, the empty hook
/// swings hard): on a 3 m rope 110 % reads 0.90 of the load 3–6 s after
/// it left the ground (cut from +0.55 s and held: the reading, 0.99 of
/// rated, is above the OVERLOAD's exit, and at rest after a move a reading
/// that may follow the swing does not clear an OVERLOAD; the period's mean
/// weighs it from +6.5 s); on a 6 m rope (between the bank's 5.9 m and
/// 7.3 m) 90 % is an OVERLOAD 3.37 s after, for 5.25 s, as before the
/// averages were raised: at the swing's crest every rope of the bank reads
/// the load 7 % high, and W_fast, the lowest of them, is then 1.07 × the
/// load.
#[test]
#[ignore = "KNOWN GAP: a load lifted after an empty-hook move at 70 deg: 3 m rope reads 0.90 of 110 %, 6 m rope cuts 90 % (every rope reads 7 % high at the swing's crest)"]
fn a_load_lifted_after_an_empty_hook_move_known_gap() {
    load_lifted_after_an_empty_hook_move(Precision::F64, &[(20.0, 70.0, Rope::Held(0.0)), (20.0, 70.0, Rope::Held(0.5))], 3.0);
}

/// KNOWN GAP, measured (f64): the same with 12 s at rest, the simulator's
/// lifted load inheriting the swing the empty hook still has (its hook is
/// massless and undamped; a real load leaves the ground hanging still, and
/// after [`moment_limiter::static_load::EMPTY_HOOK_S`] with the hook empty
/// the bank takes it so). The ropes hang still, the load swings, and the
/// swing's crests read as load: 90 % is an OVERLOAD in 12 of the 12 cases,
/// 0.24–5.86 s after it leaves the ground; 110 % is cut from −0.05 to
/// +0.96 s. Before the ropes were stilled, 110 % after the thesis rope's
/// 20° → 70° read 0.74 of itself and was never cut, and after 40° → 56°
/// was cut only after 3.26–4.00 s; 90 % was no OVERLOAD.
#[test]
#[ignore = "KNOWN GAP: a load lifted 12 s after an empty-hook move, inheriting the hook's swing (the simulator's massless hook): 90 % is an OVERLOAD (the crests)"]
fn a_load_lifted_long_after_an_empty_hook_move_known_gap() {
    load_lifted_after_an_empty_hook_move(Precision::F64, &LIFTED_AFTER_EMPTY, 12.0);
}

/// The moves and ropes where the bank sees a load added at rest within 1 s
/// (a rope of the bank's grid, or near it, follows the true swing).
const ADDED_SEEN: [(f64, f64, Rope); 8] = [
    (40.0, 60.0, Rope::Held(0.25)),
    (40.0, 60.0, Rope::Held(0.5)),
    (40.0, 60.0, Rope::Held(1.0)),
    (60.0, 40.0, Rope::Held(0.0)),
    (60.0, 40.0, Rope::Held(0.25)),
    (60.0, 40.0, Rope::Held(0.5)),
    (60.0, 40.0, Rope::Held(1.0)),
    (40.0, 80.0, Rope::Held(0.5)),
];

/// Where it does not (yet): no rope of the bank stays consistent with the
/// true swing (see `moment_limiter::load_jump`).
const ADDED_GAP: [(f64, f64, Rope); 4] = [
    (40.0, 60.0, Rope::Held(0.0)),
    (40.0, 80.0, Rope::Held(0.0)),
    (40.0, 80.0, Rope::Held(0.25)),
    (40.0, 80.0, Rope::Held(1.0)),
];

/// [`load_added_at_rest_after_a_move`]'s cases with the load taken up 1 s
/// after the stop instead of 3 s: the failures of its bounds, the slowest
/// first cut of 110 % (s after the take-up) and how many 90 % loads are cut.
fn load_added_one_second_after_a_stop(precision: Precision) -> (Vec<String>, f64, usize) {
    let (failures, worst) = load_added_after_a_stop_measured(precision, &ADDED_SEEN, 1.0, 4.0);
    let ninety_cut = worst.overloads_at_90;
    println!(
        "{precision:?}: {} failures; 110 % first cut {:.2} s after its take-up at the latest; 90 % cut in {ninety_cut} cases",
        failures.len(),
        worst.slowest_overload_s
    );
    (failures, worst.slowest_overload_s, ninety_cut)
}

/// KNOWN GAP, measured (f64): taken up 1 s after the stop, a load added at
/// rest is seen late. 110 % is first cut 1.68–3.75 s after its take-up in 8
/// of the 16 cases (40° → 60° on the ropes a quarter, half and all the way
/// to the tip height, 60° → 40° on the 3 m rope with seal friction, 40° → 80°
/// on the half-way rope), and 90 % is cut at true u 0.900 in 3 of 16 (60° →
/// 40° on the quarter- and half-way ropes, 0.67–2.1 s after its take-up). The
/// load swings hardest in the first seconds after the stop; no rope of the
/// bank reads it consistently yet, so the common jump
/// (`moment_limiter::load_jump`) has no voters, and the fast reading, the
/// lowest rope's, climbs with the swing. 3 s after the stop every case keeps
/// the bounds (`a_load_added_at_rest_after_a_move_*`). Found when measuring
/// what the stop's second stage (`moment_limiter::static_load::BOUNCE_WINDOW_S`)
/// costs a load added within its 2.5 s: the same failures without it, the
/// quarter-way rope's 110 % cut 1.46 s after instead of 1.68 s. A bank of
/// ropes twice as fine (19 held lengths 3–22.4 m, ratio √1.25) was tried and
/// not kept: 18 failures of 32 instead of 19, the slowest 110 % cut 3.76 s
/// after; `a_load_added_at_rest_after_a_move_known_gap` failed 14 of 16 with
/// either bank. A finer grid alone does not close it.
#[test]
#[ignore = "KNOWN GAP: a load added 1 s after a stop is cut up to 3.75 s after its take-up (110 %), and 90 % is cut in 3 of 16 cases"]
fn a_load_added_one_second_after_a_stop_known_gap() {
    let (failures, _, _) = load_added_one_second_after_a_stop(Precision::F64);
    assert!(failures.is_empty(), "{failures:#?}");
}

/// The known gap above pinned at its measured size: every 110 % load cut
/// within 3.8 s of its take-up (3.75 s measured), 90 % cut in no more than 3
/// cases, and no other failure than those two kinds and the reading of
/// 90 % slower than 1 s that goes with a late cut.
#[test]
fn a_load_added_one_second_after_a_stop_stays_as_measured() {
    let (failures, slowest, ninety_cut) = load_added_one_second_after_a_stop(Precision::F64);
    let other: Vec<&String> = failures
        .iter()
        .filter(|f| !f.contains(": OVERLOAD at") && !f.contains("estimate below 1/1.1 of the true load 1 s after"))
        .collect();
    assert!(other.is_empty(), "{other:#?}");
    assert!(slowest <= 3.8, "110 % first cut {slowest:.2} s after its take-up");
    assert!(ninety_cut <= 3, "90 % cut in {ninety_cut} cases");
}

#[test]
fn a_load_added_at_rest_after_a_move_f64() {
    load_added_at_rest_after_a_move(Precision::F64, &ADDED_SEEN);
}

#[test]
fn a_load_added_at_rest_after_a_move_f32() {
    load_added_at_rest_after_a_move(Precision::F32, &ADDED_SEEN);
}

/// The same on an angle sensor that lags 0.3 s (a first-order lag, learned
/// by the calibration), f64: at rest after a move the bank reads the force
/// without the lag, its pendulums' swings with the lag undone
/// (`moment_limiter::static_load`, "At rest after a move: the force without
/// the lag"). Through the lag, 110 % was cut 1.18–1.24 s after the take-up
/// (`crane-sim synth` of 40° → 60°, held ropes of 8.9 and 14.8 m, crane 10
/// of the campaign). Behind this sensor the 5.95 m rope stopped at 60° has
/// no consistent rope in the bank (see the known gap below): the load is
/// seen after 3.8–3.9 s, or 0.85 s with one noise draw of three (4.0 s
/// through the lag).
#[test]
fn a_load_added_at_rest_after_a_move_on_a_slow_sensor() {
    let cases: Vec<_> = ADDED_SEEN.iter().copied().filter(|&c| c != (40.0, 60.0, Rope::Held(0.25))).collect();
    behind_a_lagging_sensor(0.3, || load_added_at_rest_after_a_move(Precision::F64, &cases));
}

/// KNOWN GAP, measured (f64): a 3 m rope stopped at 60° or 80° and the
/// 5.5 m and 13 m ropes stopped at 80° (between the bank's lengths, whose
/// swings drift out of phase with the true one; at 80° the load swung inward
/// barely pulls on the cylinder): the added load is seen after 1.9–2.2 s or
/// not within 4 s: an 110 % load then cuts only when the averages catch up,
/// a crest and a trough of its swing have turned
/// (`moment_limiter::swing_midrange`) or the mean over one swing period
/// weighs it (the 13 m rope at 80°: left uncut for 8.59 s of the 20 s after
/// its take-up, 11.98 s before the midrange), and on the 3 m rope at
/// 80° the swing takes p1 past its range at every crest, whose FAULTs cut
/// with NORMAL between them. (90 % added to the 3 m rope at 80° once cut
/// 3.16 s after the take-up at a true 0.90; re-measured, no more.) Since
/// the pendulums swing longer by the boom's give at rest
/// (`moment_limiter::static_load`), the
/// 3 m rope at 60° with the seals' friction is seen after 0.86–0.91 s (1.88
/// before) and cut at +0.96 s; with constant friction still after 1.88 s.
/// (With the seals' release after a raise learned down to 0.01 s, tried,
/// that case was cut at +0.96 s too, `moment_limiter::seal_release`.)
/// The 13 m rope at 80° and the 3 m one at 60° with constant friction are
/// seen within 1 s when the stop's friction does not count against the
/// ropes' consistency (see
/// [`a_load_added_at_rest_on_the_paid_out_rope_soon_after_a_raise_known_gap`]).
#[test]
#[ignore = "KNOWN GAP: a load added at rest where no rope of the bank follows the true swing (short ropes at 60-80 deg, ropes between the grid's lengths at 80 deg): seen after 1.9-2.2 s or not within 4 s"]
fn a_load_added_at_rest_after_a_move_known_gap() {
    load_added_at_rest_after_a_move(Precision::F64, &ADDED_GAP);
}

/// The known gap above pinned at its measured size, so that it cannot widen
/// unseen: over the 20 s after the take-up, 110 % added at rest on these
/// ropes is left uncut (neither OVERLOAD nor FAULT) for at most 9 s
/// (measured, f64 and f32: 8.59 s, the 13 m rope stopped at 80°, until
/// a crest and a trough of the new load's swing have turned,
/// `moment_limiter::swing_midrange`; 11.98 s before, until the mean over one
/// swing period weighed it), and 90 % is never an OVERLOAD.
fn a_load_added_at_rest_where_no_rope_follows_is_cut_within_9_s(precision: Precision) {
    let (_, worst) = load_added_at_rest_after_a_move_measured(precision, &ADDED_GAP, 20.0);
    let (uncut_s, at_90) = (worst.longest_uncut_s, worst.overload_at_90_u);
    println!("{precision:?}: 110 % uncut for at most {uncut_s:.2} s; 90 % first OVERLOAD at true u {at_90:.3} (0: none)");
    assert!(uncut_s <= 9.0 && at_90 == 0.0, "110 % uncut for {uncut_s:.2} s; 90 % OVERLOAD at true u {at_90:.3}");
}

#[test]
fn a_load_added_at_rest_where_no_rope_follows_is_cut_within_9_s_f64() {
    a_load_added_at_rest_where_no_rope_follows_is_cut_within_9_s(Precision::F64);
}

#[test]
fn a_load_added_at_rest_where_no_rope_follows_is_cut_within_9_s_f32() {
    a_load_added_at_rest_where_no_rope_follows_is_cut_within_9_s(Precision::F32);
}

/// The same behind three times synth's angle noise (0.09°). The filtered
/// rate of the still boom goes over `SETTLED_RAD_S` for 0.07–0.25 s about
/// every second; until the rest's followers went on through such an
/// excursion (`moment_limiter::static_load::UNSETTLED_GRACE_S`), each one
/// started the mean over a period and the swing's midrange again and
/// switched the force and the pendulums between their readings with and
/// without the sensor's lag: the 13 m rope's 110 % at 80° was left uncut
/// for 18.3 s (0.06° alike), and 90 % on the 3 m rope at 60° was an
/// OVERLOAD at true u 0.900 10.3 s after its take-up (17.4 s at 0.06°).
/// Measured now (f64 and f32): 8.59 s, as without the noise; no OVERLOAD.
fn a_load_added_at_rest_where_no_rope_follows_behind_angle_noise(precision: Precision) {
    with_setting(&NOISE_DEG, Some(0.09), || a_load_added_at_rest_where_no_rope_follows_is_cut_within_9_s(precision));
}

#[test]
fn a_load_added_at_rest_where_no_rope_follows_behind_angle_noise_is_cut_within_9_s_f64() {
    a_load_added_at_rest_where_no_rope_follows_behind_angle_noise(Precision::F64);
}

#[test]
fn a_load_added_at_rest_where_no_rope_follows_behind_angle_noise_is_cut_within_9_s_f32() {
    a_load_added_at_rest_where_no_rope_follows_behind_angle_noise(Precision::F32);
}

/// Moves after which a load added at rest on the paid-out rope (the
/// thesis's: the hoist pays out as the boom rises, so the rope is the tip
/// height less the clearance, 9–25 m, its swing period 6–10 s) is seen at
/// once however soon after the stop it is added.
const PAID_OUT_SEEN: [(f64, f64); 5] = [(40.0, 60.0), (60.0, 40.0), (80.0, 40.0), (70.0, 20.0), (60.0, 80.0)];

/// Where it is not seen 3 s after the stop (see
/// [`a_load_added_at_rest_on_the_paid_out_rope_soon_after_a_raise_known_gap`]).
const PAID_OUT_SOON_GAP: [(f64, f64); 4] = [(40.0, 80.0), (20.0, 70.0), (50.0, 80.0), (20.0, 50.0)];

/// A load added at rest on the paid-out rope: a 10 s cycloidal move
/// `from` → `to` with 60 % of the lower angle's rated load, `at_rest_s` at
/// rest, then 90 % or 110 % of the rated load at `to` taken up over 0.5 s,
/// 20 s more at rest; both friction laws. At 110 % OVERLOAD within 1 s of
/// the take-up's end, at a true u of at least 1/1.1, and held to the end; at
/// 90 % no OVERLOAD, and the estimate (×1.05) at 1/1.1 of the true load
/// within 1 s. Before the rescale restarted the hold's 20 s
/// (`moment_limiter::static_load`, "A load added, held"), 110 % added 14 s
/// after a raise to 70° or 80° was cut 0.8 s after the take-up and released
/// 20 s after the stop, at true u 1.10, until the mean over one swing period
/// weighed it 8 s later (cut again from +14 s).
fn load_added_at_rest_on_the_paid_out_rope(precision: Precision, moves: &[(f64, f64)], at_rest_s: f64) {
    let (failures, _) = load_added_at_rest_on_the_paid_out_rope_measured(precision, moves, at_rest_s);
    assert!(failures.is_empty(), "{failures:#?}");
}

/// [`load_added_at_rest_on_the_paid_out_rope`]'s cases, measured: the
/// failures, the slowest first OVERLOAD of 110 % (s after its take-up;
/// infinite when one is never cut) and whether 90 % is ever an OVERLOAD.
fn load_added_at_rest_on_the_paid_out_rope_measured(precision: Precision, moves: &[(f64, f64)], at_rest_s: f64) -> (Vec<String>, (f64, bool)) {
    const TAKE_UP_S: f64 = 0.5;
    let mut failures = Vec::new();
    let (mut slowest_cut, mut cut_at_90) = (0.0f64, false);
    for &(from, to) in moves {
        let w0 = 0.6 * rated_kg(from.min(to).to_radians());
        for seals in SEALS {
            for frac in [0.9, 1.1] {
                let w1 = frac * rated_kg(to.to_radians());
                let name = format!("{from:.0}->{to:.0} 10s paid out {seals:?}, {at_rest_s:.0} s at rest: {w0:.0} kg, then {w1:.0} kg");
                let rows = lift_after_a_move(from, to, Rope::Thesis, seals, w0, at_rest_s, TAKE_UP_S, w1, 20.0);
                let pts = replay_rows(&rows, seals, precision);
                let lifted = HOLD_BEFORE_S + 10.0 + at_rest_s + TAKE_UP_S;
                let after: Vec<&Point> = pts.iter().filter(|q| q.t >= lifted).collect();
                let seen = after.iter().find(|q| q.ratio >= 1.0 / 1.1).map(|q| q.t - lifted);
                let cut_from = held_from(&after, lifted, cut);
                let first = first_overload(&pts);
                println!(
                    "{name:<74} seen {} s, first OVERLOAD {}, cut from {} s to the end",
                    seen.map_or("never".into(), |s| format!("{s:+.2}")),
                    first.map_or("none".into(), |f| format!("at {:+.2} s, true u {:.3}", f.0 - lifted, f.1)),
                    cut_from.map_or("never".into(), |s| format!("{s:+.2}"))
                );
                if frac < 1.0 {
                    cut_at_90 |= first.is_some();
                } else {
                    slowest_cut = slowest_cut.max(first.map_or(f64::INFINITY, |f| f.0 - lifted));
                }
                if frac < 1.0 {
                    if let Some((t, u)) = first {
                        failures.push(format!("{name}: OVERLOAD at {:+.2} s, true u {u:.3}", t - lifted));
                    }
                    if seen.is_none_or(|s| s > 1.0) {
                        failures.push(format!("{name}: estimate at 1/1.1 of the true load from {seen:?} s"));
                    }
                } else {
                    match first {
                        Some((t, u)) if t <= lifted + 1.0 && u >= 1.0 / 1.1 => {
                            if cut_from.is_none_or(|h| h > t - lifted + 0.005) {
                                failures.push(format!("{name}: OVERLOAD at {:+.2} s released, cut to the end only from {cut_from:?} s", t - lifted));
                            }
                        }
                        other => failures.push(format!("{name}: first OVERLOAD {other:?}, take-up ends at {lifted:.2} s")),
                    }
                }
            }
        }
    }
    (failures, (slowest_cut, cut_at_90))
}

#[test]
fn a_load_added_at_rest_on_the_paid_out_rope_f64() {
    let all: Vec<_> = PAID_OUT_SEEN.iter().chain(&PAID_OUT_SOON_GAP).copied().collect();
    load_added_at_rest_on_the_paid_out_rope(Precision::F64, &all, 14.0);
    load_added_at_rest_on_the_paid_out_rope(Precision::F64, &PAID_OUT_SEEN, 3.0);
}

#[test]
fn a_load_added_at_rest_on_the_paid_out_rope_f32() {
    let all: Vec<_> = PAID_OUT_SEEN.iter().chain(&PAID_OUT_SOON_GAP).copied().collect();
    load_added_at_rest_on_the_paid_out_rope(Precision::F32, &all, 14.0);
    load_added_at_rest_on_the_paid_out_rope(Precision::F32, &PAID_OUT_SEEN, 3.0);
}

/// KNOWN GAP, measured (f64): 3 s after a raise 20° → 70° on the paid-out
/// rope with the seals' friction, 110 % is cut only when a crest and a
/// trough of its swing have turned (`moment_limiter::swing_midrange`), 6.07 s
/// after the take-up, and after 20° → 50° 1.01 s after (0.01 s over the
/// bound). Since the calibration learns the seals' release after a raise
/// (`moment_limiter::seal_release`; 0.2 s for these seals, which let go at
/// the stop: the shortest it learns), the raises to 80° and 20° → 70° with constant friction are
/// cut 0.81–0.88 s after the take-up. What follows is what kept them late
/// before (10.1–10.3 s after the take-up; 12.5–14.3 s before the midrange,
/// when the mean over one swing period weighed it). The paid-out
/// hypothesis follows the true swing (in motion it reads the load within
/// 0.3 %), but the stop leaves its weighing up to 16 % low for 1–2 s: the
/// force filter lets the cylinder's friction go as the stop passes through
/// it, while the limiter takes it off in full until the filtered rate falls
/// under 0.05 °/s, up to a second later, and then over `seal_release_up_s`.
/// Its inconsistency (`moment_limiter::load_jump`) takes that dip in and is
/// still 0.037–0.040 at the take-up, over the 0.03 a rope needs to vote, so
/// no rope rescales the load.
///
/// Tried and not kept (measured): holding every rope's inconsistency from
/// the boom's slowing down until the seals are released cuts 40° → 80° and
/// 50° → 80° here at +0.81–0.86 s, the 13 m held rope after 40° → 80° at
/// +0.89 s (never within 4 s) and the 3 m one after 40° → 60° at +0.96 s
/// (1.93 s), but in the campaign (seeds 1 and 2) it made 4 false OVERLOADs
/// at true u 0.70–0.80 after raises to 80–85° on 3.6–7.9 m ropes: ropes
/// consistent in motion voted at rest, where they read the swing's crest.
/// Making every rope prove itself again at rest once the seals are released
/// removed those, but a rope then votes only 2.5–3 s after the stop, and
/// 90 % added 3 s after a stop behind a 0.3 s sensor was seen after 1.8 s.
/// A friction share that leaves the force as the filter lets it go was
/// tried next and not kept (measured): after a raise, from the cycle the
/// stop is seen, no more friction taken off than the force filter's share
/// of a step still to pass, the stop taken its delay n·τ (0.53 s) before it
/// is seen. It cut 40° → 80°, 20° → 70° (constant friction) and 50° → 80°
/// here at +0.81–0.88 s, and every `field_limiter` test passed; but the
/// campaign's seals release over 0–1 s, where this share reads high: over
/// seeds 1–9, 2 early cuts (seed 5 #2572 at true u 0.882, seed 6 #4006 at
/// 0.873) and a false OVERLOAD (seed 7 #4988, true u ≤ 0.818), all at rest
/// after raises to 83–84.5° whose seals released over 0.72–0.99 s. Setting
/// the limiter's release time to 0.01 s gave the same cuts here, so the
/// gap was the seals' release: the limiter assumed seals that hold their
/// friction until the filtered rate shows the stop and release it over
/// 0.5 s, and these logs' seals let it go at the stop. The calibration now
/// learns it, each crane its own (the campaign's seals that release over
/// 0.7–1 s read 0.2–0.4 s). Not yet: 20° → 70° with the seals' friction and
/// 20° → 50°.
#[test]
#[ignore = "KNOWN GAP: a load added 3 s after a raise 20-70 deg on the paid-out rope with seal friction is cut only when a crest and a trough of its swing have turned (6.07 s after; 1.01 s after 20-50 deg)"]
fn a_load_added_at_rest_on_the_paid_out_rope_soon_after_a_raise_known_gap() {
    load_added_at_rest_on_the_paid_out_rope(Precision::F64, &PAID_OUT_SOON_GAP, 3.0);
}

/// The known gap above pinned at its measured size, so that it cannot widen
/// unseen: 110 % added 3 s after those raises is an OVERLOAD within 6.5 s
/// of its take-up (measured, f64 and f32: at most 6.07 s, once a crest and
/// a trough of the new load's swing have turned,
/// `moment_limiter::swing_midrange`; 10.28 s before the calibration learned
/// the seals' release after a raise, 14.26 s before the midrange, when the
/// mean over one swing period weighed it), 90 % never.
fn a_load_added_at_rest_on_the_paid_out_rope_soon_after_a_raise_is_cut_within_6_5_s(precision: Precision) {
    let (_, (slowest_cut, cut_at_90)) = load_added_at_rest_on_the_paid_out_rope_measured(precision, &PAID_OUT_SOON_GAP, 3.0);
    println!("{precision:?}: 110 % cut at most {slowest_cut:.2} s after its take-up; 90 % an OVERLOAD: {cut_at_90}");
    assert!(slowest_cut <= 6.5 && !cut_at_90, "110 % cut {slowest_cut:.2} s after its take-up; 90 % an OVERLOAD: {cut_at_90}");
}

#[test]
fn a_load_added_at_rest_on_the_paid_out_rope_soon_after_a_raise_is_cut_within_6_5_s_f64() {
    a_load_added_at_rest_on_the_paid_out_rope_soon_after_a_raise_is_cut_within_6_5_s(Precision::F64);
}

#[test]
fn a_load_added_at_rest_on_the_paid_out_rope_soon_after_a_raise_is_cut_within_6_5_s_f32() {
    a_load_added_at_rest_on_the_paid_out_rope_soon_after_a_raise_is_cut_within_6_5_s(Precision::F32);
}

/// The cases of [`ADDED_GAP`] but the 3 m rope stopped at 80°: there the
/// swing takes p1 past its range (210 bar) at every crest once the load is
/// added, and each FAULT starts the mean again (see the known gap).
const ADDED_WEIGHED: [(f64, f64, Rope); 3] = [
    (40.0, 60.0, Rope::Held(0.0)),
    (40.0, 80.0, Rope::Held(0.25)),
    (40.0, 80.0, Rope::Held(1.0)),
];

/// A load added at rest where no rope of the bank follows the swing (the
/// moves and ropes of [`ADDED_WEIGHED`]; 60 % of rated, `at_rest_s` at rest,
/// then 90 % or 110 % of the rated load taken up over 0.5 s, 20 s more at
/// rest), weighed by the mean force over one swing period whatever the rope
/// (`moment_limiter::period_mean`). Asserted for 110 %: from at most
/// `bound(P)` after the take-up (P the true rope's swing period) to the end,
/// the limiter cuts (OVERLOAD, or FAULT where the swing takes p1 past its
/// range) and the estimate (×1.05) stays at or above 1/1.1 of the true load
/// wherever it reads; and an OVERLOAD, once set, stands to the end (before
/// `moment_limiter::static_load`'s "At rest after a move: an overload stands", 110 % on
/// the 3 m rope at 60° and the 6 m rope at 80°, added 3 s after the stop,
/// was cut at +1.93 s and +4.52 s and released at the swing's lows).
/// Asserted for 90 %: no OVERLOAD (before the pendulums swung longer by the
/// boom's give at rest, 90 % added 14 s after the stop on the 3 m rope at
/// 60° was an OVERLOAD for 0.95 s at a true 0.90); printed: the highest
/// estimated u.
fn load_added_where_no_rope_follows_the_swing(precision: Precision, at_rest_s: f64, bound: impl Fn(f64) -> f64) {
    load_added_and_weighed_by_its_period(precision, &ADDED_WEIGHED, 0.6, at_rest_s, 0.5, Checks { in_band: false, ninety_clear: true }, bound);
}

/// What [`load_added_and_weighed_by_its_period`] asserts besides the cut.
#[derive(Clone, Copy)]
struct Checks {
    /// For 90 % and 110 % alike every estimate from `bound(P)` on within
    /// [1.00, 1.10] of the true load.
    in_band: bool,
    /// 90 % is never an OVERLOAD.
    ninety_clear: bool,
}

/// [`load_added_where_no_rope_follows_the_swing`] for the moves and ropes
/// `cases`, `w0_frac` of the rated load at the lower angle during the move
/// and a take-up over `take_up_s`, with the [`Checks`] `checks`.
fn load_added_and_weighed_by_its_period(precision: Precision, cases: &[(f64, f64, Rope)], w0_frac: f64, at_rest_s: f64, take_up_s: f64, checks: Checks, bound: impl Fn(f64) -> f64) {
    let Checks { in_band, ninety_clear } = checks;
    const AFTER_S: f64 = 20.0;
    let mut failures = Vec::new();
    for &(from, to, rope) in cases {
        let w0 = w0_frac * rated_kg(from.min(to).to_radians());
        let length = match rope_choice(rope, from.min(to)) {
            RopeChoice::Held { length_m: Some(l) } => l,
            other => panic!("a held rope of known length, not {other:?}"),
        };
        let period = 2.0 * std::f64::consts::PI * (length / 9.81).sqrt();
        let bound = bound(period);
        for seals in SEALS {
            for frac in [0.9, 1.1] {
                let w1 = frac * rated_kg(to.to_radians());
                let name = format!("{from:.0}->{to:.0} 10s {length:.1} m rope {seals:?}, {at_rest_s:.0} s at rest: {w0:.0} kg, then {w1:.0} kg");
                let rows = lift_after_a_move(from, to, rope, seals, w0, at_rest_s, take_up_s, w1, AFTER_S);
                let pts = replay_rows(&rows, seals, precision);
                let lifted = HOLD_BEFORE_S + 10.0 + at_rest_s + take_up_s;
                let after: Vec<&Point> = pts.iter().filter(|q| q.t >= lifted).collect();
                let fault = |q: &Point| q.state == LimiterState::Fault;
                let seen = held_from(&after, lifted, |q| fault(q) || q.ratio >= 1.0 / 1.1);
                let cut_from = held_from(&after, lifted, cut);
                let u_high = after.iter().filter(|q| !fault(q)).map(|q| q.ratio * q.u).fold(0.0, f64::max);
                let (low, high) = after
                    .iter()
                    .filter(|q| !fault(q) && q.t - lifted >= bound)
                    .fold((f64::INFINITY, 0.0f64), |(lo, hi), q| (lo.min(q.ratio), hi.max(q.ratio)));
                if in_band {
                    println!("{name:<78} estimate/true from {bound:.1} s on: {low:.3}..{high:.3}");
                    if !(low >= 1.0 && high <= 1.1) {
                        failures.push(format!("{name}: estimate/true {low:.3}..{high:.3} from {bound:.1} s on"));
                    }
                }
                let first = first_overload(&pts);
                let in_overload_s = after.iter().filter(|q| q.state == LimiterState::Overload).count() as f64 / rate_hz();
                println!(
                    "{name:<78} P {period:.1} s: >= true/1.1 from {} s, cut from {} s (bound {bound:.1} s), first OVERLOAD {}, in OVERLOAD {in_overload_s:.2} s, highest estimated u {u_high:.3}",
                    seen.map_or("never".into(), |s| format!("{s:+.2}")),
                    cut_from.map_or("never".into(), |s| format!("{s:+.2}")),
                    first.map_or("none".into(), |f| format!("at {:+.2} s, true u {:.3}", f.0 - lifted, f.1))
                );
                if let (true, true, Some((t, u))) = (frac < 1.0, ninety_clear, first) {
                    failures.push(format!("{name}: OVERLOAD at {:+.2} s, true u {u:.3}", t - lifted));
                }
                if frac > 1.0 {
                    // An overload at rest stands: once cut, cut to the end.
                    if let (Some((t, _)), Some(c)) = (first.filter(|f| f.0 >= lifted), cut_from) {
                        if c > t - lifted + 0.005 {
                            failures.push(format!("{name}: OVERLOAD at {:+.2} s released, cut again only from {c:+.2} s", t - lifted));
                        }
                    }
                    if seen.is_none_or(|s| s > bound) {
                        failures.push(format!("{name}: estimate at 1/1.1 of the true load from {seen:?} s, bound {bound:.1} s"));
                    }
                    if cut_from.is_none_or(|s| s > bound) {
                        failures.push(format!("{name}: cut from {cut_from:?} s, bound {bound:.1} s"));
                    }
                }
            }
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

/// 3 s at rest (the known gap's cases, where the load is added before the
/// swing's period is known): the mean needs P·(1 + 1/3) of the new load and
/// 1 s of confirmation, and the force filter's delay and step response come
/// on top: bound P·4/3 + 3 s. Before, 110 % on the 6.0 m and 14.8 m ropes
/// stopped at 80° was never held cut in the 20 s (cut at +4.5 s and +18.2 s,
/// released at the next low of the swing), and on the 3 m rope at 60° held
/// cut from +9.3 s; 90 % there cut at a true 0.90 after 10.2 s.
fn load_added_before_the_period_is_known(precision: Precision) {
    load_added_where_no_rope_follows_the_swing(precision, 3.0, |p| p * (1.0 + 1.0 / 3.0) + 3.0);
}

/// 14 s at rest (the swing's period found before the take-up): the load
/// read from the force's ratio to the same phase one period earlier, taken
/// where the swing pulls at least the load (`STEP_PULL`): bound half a
/// period to reach that half, the take-up, the force filter's delay and
/// response and three bins' ratios (P/2 + 2 s). Before, 110 % on the 6.0 m
/// and 14.8 m ropes was never held cut in the 20 s, and on the 3 m rope held
/// cut from +8.9 s. Now cut from +0.99 s on the 3 m rope (1.38 s before its
/// pendulum swung longer by the boom's give at rest), +2.65 s on the 6 m
/// and +0.75 s on the 14.8 m; 90 % on the 3 m rope, an OVERLOAD 6.1 s after
/// the take-up at a true 0.90 before the give, reads at most u 0.993.
fn load_added_to_a_steady_swing(precision: Precision) {
    load_added_where_no_rope_follows_the_swing(precision, 14.0, |p| p / 2.0 + 2.0);
}

#[test]
fn a_load_added_where_no_rope_follows_the_swing_f64() {
    load_added_before_the_period_is_known(Precision::F64);
    load_added_to_a_steady_swing(Precision::F64);
}

#[test]
fn a_load_added_where_no_rope_follows_the_swing_f32() {
    load_added_before_the_period_is_known(Precision::F32);
    load_added_to_a_steady_swing(Precision::F32);
}

/// A long rest after a move (the field tests' other logs rest 3 s, less
/// than the mean over one swing period needs): 10 s cycloidal moves
/// 40° ↔ 80° and 40° ↔ 60°, every rope of [`ROPES`] and a 6.0 m one between
/// the bank's lengths, both friction laws, 30 % and 85 % of the rated load at
/// 40°, then 25 s at rest. No OVERLOAD (true u stays ≤ 0.85), and the
/// estimate/true band at rest, from 1 s after the stop to the end and in its
/// last 10 s, pooled over every case, within [1.00, 1.10] (p5, p95). The
/// mean over one swing period (`moment_limiter::period_mean`) is the
/// weighing for most of that rest. Before it, the last 10 s read p5 0.654
/// (a 3 m rope stopped at 80° read 0.51–1.39 of the load) and the highest
/// estimated u at 85 % was 0.958.
fn long_rest_after_a_move(precision: Precision) {
    const AT_REST_S: f64 = 25.0;
    let mut failures = Vec::new();
    let (mut rest, mut late) = (Vec::new(), Vec::new());
    let mut worst: f64 = 0.0;
    for (from, to) in [(40.0, 80.0), (80.0, 40.0), (40.0, 60.0), (60.0, 40.0)] {
        for rope in [Rope::Thesis, Rope::Held(0.0), Rope::Held(0.25), Rope::Held(0.5), Rope::Held(1.0)] {
            for seals in SEALS {
                for frac in [0.3, 0.85] {
                    let w = frac * rated_kg(40f64.to_radians());
                    let mut p = Program::new(from, w, rope_choice(rope, f64::min(from, to))).unwrap();
                    p.push(Segment::Hold { duration_s: HOLD_BEFORE_S }).unwrap();
                    p.push(Segment::Luff { to_deg: to, shape: RampShape::Cycloidal, t1_s: 1.0, t2_s: 9.0, t3_s: 10.0 }).unwrap();
                    p.push(Segment::Hold { duration_s: AT_REST_S }).unwrap();
                    let rows = program_rows(&p, seals, 17);
                    let pts = replay_rows(&rows, seals, precision);
                    let stop = HOLD_BEFORE_S + 10.0;
                    let at_rest: Vec<f64> = pts.iter().filter(|q| q.t >= stop + 1.0 && q.state != LimiterState::Fault).map(|q| q.ratio).collect();
                    let last: Vec<f64> = pts.iter().filter(|q| q.t >= stop + AT_REST_S - 10.0 && q.state != LimiterState::Fault).map(|q| q.ratio).collect();
                    let peak = pts.iter().map(|q| q.ratio * q.u).fold(0.0, f64::max);
                    let name = format!("{from:.0}->{to:.0} 10s {rope:?} {seals:?} {w:.0} kg, {AT_REST_S:.0} s at rest");
                    let (lo, hi) = (at_rest.iter().copied().fold(f64::INFINITY, f64::min), at_rest.iter().copied().fold(0.0, f64::max));
                    let (llo, lhi) = (last.iter().copied().fold(f64::INFINITY, f64::min), last.iter().copied().fold(0.0, f64::max));
                    println!("{name:<66} at rest estimate/true {lo:.3}-{hi:.3}, last 10 s {llo:.3}-{lhi:.3}, peak estimated u {peak:.3}");
                    if frac > 0.5 {
                        worst = worst.max(peak);
                        if let Some((t, u)) = first_overload(&pts) {
                            failures.push(format!("{name}: OVERLOAD at {t:.2} s, true u {u:.3}"));
                        }
                    }
                    rest.extend(at_rest);
                    late.extend(last);
                }
            }
        }
    }
    let pct = |v: &mut Vec<f64>| [percentile(v, 0.05), percentile(v, 0.5), percentile(v, 0.95)];
    let (r, l) = (pct(&mut rest), pct(&mut late));
    println!("{precision:?}: at rest p5/p50/p95 {:.3}/{:.3}/{:.3}, its last 10 s {:.3}/{:.3}/{:.3}; highest estimated u at 85 % {worst:.3}", r[0], r[1], r[2], l[0], l[1], l[2]);
    if !(r[0] >= 1.0 && r[2] <= 1.1) {
        failures.push(format!("band at rest {r:?}"));
    }
    if !(l[0] >= 1.0 && l[2] <= 1.1) {
        failures.push(format!("band in the last 10 s at rest {l:?}"));
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

#[test]
fn a_long_rest_after_a_move_f64() {
    long_rest_after_a_move(Precision::F64);
}

#[test]
fn a_long_rest_after_a_move_f32() {
    long_rest_after_a_move(Precision::F32);
}

/// The other work cycle of [`a_shift_of_work`]: the empty hook at 40°,
/// `load_kg` lifted in 2 s, raised to 70° in 10 s, 3 s at rest, set down in
/// 2 s, 5 s, the empty hook lowered to 40° in 10 s, 5 s; it ends as it
/// starts.
fn work_cycle_back_empty(rope: RopeChoice, load_kg: f64) -> Program {
    let mut p = Program::new(40.0, 0.0, rope).unwrap();
    p.push(Segment::Hold { duration_s: 3.0 }).unwrap();
    p.push(Segment::LiftOff { duration_s: 2.0, load_kg }).unwrap();
    p.push(Segment::Luff { to_deg: 70.0, shape: RampShape::Cycloidal, t1_s: 1.0, t2_s: 9.0, t3_s: 10.0 }).unwrap();
    p.push(Segment::Hold { duration_s: 3.0 }).unwrap();
    p.push(Segment::LiftOff { duration_s: 2.0, load_kg: 0.0 }).unwrap();
    p.push(Segment::Hold { duration_s: 5.0 }).unwrap();
    p.push(Segment::Luff { to_deg: 40.0, shape: RampShape::Cycloidal, t1_s: 1.0, t2_s: 9.0, t3_s: 10.0 }).unwrap();
    p.push(Segment::Hold { duration_s: 5.0 }).unwrap();
    p
}

/// One work cycle of [`a_shift_of_work`]: the empty hook at 40°, `load_kg`
/// lifted in 2 s, raised to 70° in 10 s, 8 s at rest, lowered to 40°, 5 s,
/// set down in 2 s, 5 s; it ends as it starts.
fn work_cycle(rope: RopeChoice, load_kg: f64) -> Program {
    let mut p = Program::new(40.0, 0.0, rope).unwrap();
    p.push(Segment::Hold { duration_s: 3.0 }).unwrap();
    p.push(Segment::LiftOff { duration_s: 2.0, load_kg }).unwrap();
    p.push(Segment::Luff { to_deg: 70.0, shape: RampShape::Cycloidal, t1_s: 1.0, t2_s: 9.0, t3_s: 10.0 }).unwrap();
    p.push(Segment::Hold { duration_s: 8.0 }).unwrap();
    p.push(Segment::Luff { to_deg: 40.0, shape: RampShape::Cycloidal, t1_s: 1.0, t2_s: 9.0, t3_s: 10.0 }).unwrap();
    p.push(Segment::Hold { duration_s: 5.0 }).unwrap();
    p.push(Segment::LiftOff { duration_s: 2.0, load_kg: 0.0 }).unwrap();
    p.push(Segment::Hold { duration_s: 5.0 }).unwrap();
    p
}

/// What one limiter made of a shift: the highest estimated u of each cycle,
/// the OVERLOADs and FAULTs in the shift (cycle, sample), and for each test
/// lift its first OVERLOAD (sample from its start) and mean estimate over
/// its last 2 s (kg).
struct Shift {
    highest_u: Vec<f64>,
    alarms: Vec<(usize, usize)>,
    lifts: Vec<(Option<usize>, f64)>,
}

/// Runs `n` work cycles (`cycles` in turn, each stamped on from where the
/// previous ended, the µs clock wrapping as it does) on one limiter just
/// switched on, then each of `lifts` on a copy of it.
fn shift_with<T: Real, M: HookLoadModel<T> + Clone>(model_l: &M, cal: Calibration<T>, cycles: &[Vec<SynthRow>], n: usize, lifts: &[Vec<SynthRow>]) -> Shift {
    let config = LimiterConfig { calibration: cal, ..LimiterConfig::standard() };
    let mut lim = Limiter::new(model_l.clone(), config).unwrap();
    let step = |lim: &mut Limiter<T, M>, r: &SynthRow, start_ms: i64| {
        let t = Ticks::from_micros(((start_ms + (r.t_s * 1e3).round() as i64) * 1000) as u32);
        lim.step_frame(&Frame { t, ..frame::<T>(r) })
    };
    let mut out = Shift { highest_u: Vec::new(), alarms: Vec::new(), lifts: Vec::new() };
    let mut start_ms: i64 = 0;
    for k in 0..n {
        let rows = &cycles[k % cycles.len()];
        let mut highest: f64 = 0.0;
        for (i, r) in rows.iter().enumerate() {
            let rep = step(&mut lim, r, start_ms);
            highest = highest.max(rep.estimate.map_or(0.0, |e| e.utilization.to_f64()));
            if matches!(rep.state, LimiterState::Overload | LimiterState::Fault) {
                out.alarms.push((k, i));
            }
        }
        out.highest_u.push(highest);
        start_ms += rows.len() as i64 * 10;
    }
    for lift in lifts {
        let mut lim = lim.clone();
        let last_2s = lift.len().saturating_sub(200);
        let (mut cut, mut sum, mut count) = (None, 0.0, 0.0);
        for (i, r) in lift.iter().enumerate() {
            let rep = step(&mut lim, r, start_ms);
            if rep.state == LimiterState::Overload && cut.is_none() {
                cut = Some(i);
            }
            if let (true, Some(e)) = (i >= last_2s, rep.estimate) {
                sum += e.load_kg.to_f64();
                count += 1.0;
            }
        }
        out.lifts.push((cut, sum / count));
    }
    out
}

/// A working shift on one limiter (SPEC §4 item 7: a crane that has run for
/// a long time alarms exactly as one just switched on). The work cycle
/// `cycle` ([`work_cycle`], or [`work_cycle_back_empty`], which sets the load
/// down at 70° and lowers the empty hook) with 60 % of the rated load at 40°
/// on a held rope of 7.7 m (seal friction; four noise draws in turn) is
/// repeated without a break for `hours`, through the 32-bit µs clock's wrap
/// every 71.6 min; then a test
/// lift at 40°: 110 % of the rated load taken up in 1 s, or 90 %. Asserted:
/// no OVERLOAD or FAULT in the shift; every cycle's highest estimated u
/// within 0.002 of the same noise draw's in the first four cycles; the test
/// lift cut at the same sample (±1) as on a limiter just switched on and
/// within 1 s of leaving the ground, 90 % not cut, and both weighed within
/// 0.1 % of the same lift just switched on. Measured with [`work_cycle`]
/// (f64 8 h, f32 24 h): highest u 0.6222–0.6229 in every cycle, largest
/// change 0.00004; with [`work_cycle_back_empty`] (f64 2 h, f32 8 h)
/// 0.5760–0.5799, 0.00045; 110 % cut 0.77 s after it leaves the ground,
/// weighed 6217.9 kg (6214.1 kg switched on), after either. Before the ropes were stilled under an empty hook
/// (`moment_limiter::static_load`, "A load set down"), the cycles read
/// 0.59–0.91, and the 110 % lift was cut 7.6 s after leaving the ground
/// after four cycles, 1.1 s after 8 h (f64) and never after 24 h (f32),
/// weighed 0.83–0.90 of itself.
fn a_shift_of_work(precision: Precision, hours: f64, cycle: fn(RopeChoice, f64) -> Program) {
    a_shift_of_work_on(Rope::Held(0.4), precision, hours, cycle);
}

/// [`a_shift_of_work`] on the rope `rope`.
fn a_shift_of_work_on(rope: Rope, precision: Precision, hours: f64, cycle: fn(RopeChoice, f64) -> Program) {
    let rope = rope_choice(rope, 40.0);
    let rated = rated_kg(40f64.to_radians());
    let (options, dt) = options_for_rate(rate_hz());
    let samples = simulate_program(model(), &cycle(rope, 0.6 * rated), &options).expect("simulation");
    let cycles: Vec<Vec<SynthRow>> = (0..4).map(|seed| synthesize(&samples, dt, 0.0, 0.0, &sensors(Seals::Seal, 40 + seed))).collect();
    let n = (hours * 3600.0 / (cycles[0].len() as f64 * 0.01)).ceil() as usize;
    let lifts = test_lifts(rope, 0.0);
    let run = |n: usize| match precision {
        Precision::F64 => shift_with(model(), calibration_f64(Seals::Seal), &cycles, n, &lifts),
        Precision::F32 => shift_with(&thesis_load_model_f32(), calibration_f32(Seals::Seal), &cycles, n, &lifts),
    };
    let (fresh, first, long) = (run(0), run(cycles.len()), run(n));
    let range = |v: &[f64]| (v.iter().copied().fold(f64::INFINITY, f64::min), v.iter().copied().fold(0.0, f64::max));
    let name = format!("{precision:?}, {rope:?}, {n} cycles ({hours} h)");
    let (drift, failures) = uptime_failures(&name, "cycle", &fresh, &first, &long);
    println!(
        "{name}: highest estimated u per cycle {:.4?} in the first four, {:.4?} over the shift (largest change {drift:.5})",
        range(&first.highest_u),
        range(&long.highest_u)
    );
    assert!(failures.is_empty(), "{failures:#?}");
}

/// 110 % and 90 % of the load rated at 40°: the test lifts after a shift or
/// a rest ([`test_lifts`]).
const TEST_LIFT_FRACS: [f64; 2] = [1.1, 0.9];

/// The sample at which a test lift's take-up ends (5 s at rest, 1 s up).
const TEST_LIFT_OFF: usize = 600;

/// The test lifts at 40° on `rope` with `hanging` kg on the hook: 5 s at
/// rest, the hook load taken to each of [`TEST_LIFT_FRACS`] of rated in 1 s,
/// 10 s more.
fn test_lifts(rope: RopeChoice, hanging: f64) -> Vec<Vec<SynthRow>> {
    let rated = rated_kg(40f64.to_radians());
    TEST_LIFT_FRACS
        .iter()
        .map(|frac| {
            let mut p = Program::new(40.0, hanging, rope).unwrap();
            p.push(Segment::Hold { duration_s: 5.0 }).unwrap();
            p.push(Segment::LiftOff { duration_s: 1.0, load_kg: frac * rated }).unwrap();
            p.push(Segment::Hold { duration_s: 10.0 }).unwrap();
            program_rows(&p, Seals::Seal, 99)
        })
        .collect()
}

/// What a long uptime (`long`, in `unit`s: cycles or minutes) did that one
/// just switched on (`fresh`) and its first few `unit`s (`first`) did not:
/// an OVERLOAD or FAULT, a `unit`'s highest estimated u more than 0.002 off
/// the same noise draw's in `first`, a 110 % test lift not cut at the same
/// sample (±1) as switched on or later than 1 s, a 90 % one cut, a lift
/// weighed more than 0.1 % off. Returns the largest change of the highest u
/// and the failures; prints each test lift.
fn uptime_failures(name: &str, unit: &str, fresh: &Shift, first: &Shift, long: &Shift) -> (f64, Vec<String>) {
    let period = first.highest_u.len().max(1);
    let drift = long.highest_u.iter().enumerate().map(|(k, u)| (u - first.highest_u[k % period]).abs()).fold(0.0, f64::max);
    let mut failures = Vec::new();
    if let Some(a) = long.alarms.first() {
        failures.push(format!("{name}: {} samples of OVERLOAD or FAULT, first in {unit} {} at sample {}", long.alarms.len(), a.0, a.1));
    }
    if drift > 0.002 {
        failures.push(format!("{name}: a {unit}'s highest estimated u {drift:.4} off the first {period}'s"));
    }
    for ((frac, &(cut0, kg0)), &(cut, kg)) in TEST_LIFT_FRACS.iter().zip(&fresh.lifts).zip(&long.lifts) {
        println!(
            "{name}, then to {:.0} % (taken up by sample {TEST_LIFT_OFF}): cut at sample {cut0:?} switched on, {cut:?} after; weighed {kg0:.1} / {kg:.1} kg",
            frac * 100.0
        );
        let cut_ok = match (*frac > 1.0, cut0, cut) {
            (true, Some(a), Some(b)) => a.abs_diff(b) <= 1 && b <= TEST_LIFT_OFF + 100,
            (false, None, None) => true,
            _ => false,
        };
        if !cut_ok {
            failures.push(format!("{name}, to {frac}: cut at {cut0:?} switched on, {cut:?} after"));
        }
        if (kg / kg0 - 1.0).abs() > 1e-3 {
            failures.push(format!("{name}, to {frac}: weighed {kg0:.1} kg switched on, {kg:.1} kg after"));
        }
    }
    (drift, failures)
}

#[test]
fn a_shift_of_work_f64() {
    a_shift_of_work(Precision::F64, 8.0, work_cycle);
}

#[test]
fn a_shift_of_work_f32() {
    a_shift_of_work(Precision::F32, 24.0, work_cycle);
}

/// The shift on the paid-out rope (the thesis's: its length follows the tip,
/// 9–20 m here), f64 with [`work_cycle`], f32 with [`work_cycle_back_empty`],
/// 8 h each. Measured: highest u 0.6274–0.6277 per cycle (change 0.00000)
/// and 0.5488–0.5565 (0.00045); 110 % cut 0.75 s after it leaves the
/// ground, at the same sample as switched on, weighed 6196.7 kg (6194.9 kg).
#[test]
fn a_shift_of_work_on_the_paid_out_rope_f64() {
    a_shift_of_work_on(Rope::Thesis, Precision::F64, 8.0, work_cycle);
}

#[test]
fn a_shift_of_work_back_empty_on_the_paid_out_rope_f32() {
    a_shift_of_work_on(Rope::Thesis, Precision::F32, 8.0, work_cycle_back_empty);
}

#[test]
fn a_shift_of_work_back_empty_f64() {
    a_shift_of_work(Precision::F64, 2.0, work_cycle_back_empty);
}

#[test]
fn a_shift_of_work_back_empty_f32() {
    a_shift_of_work(Precision::F32, 8.0, work_cycle_back_empty);
}

/// Days at rest on one limiter (SPEC §4 item 7, the uptime without the
/// work): a load hanging still at 40° on a held rope of 7.7 m (seal
/// friction), 80 % of the rated load or the empty hook, for `hours`
/// (60 s logs, four noise draws in turn, through the 32-bit µs clock's
/// wrap every 71.6 min), then the hook load taken to 110 % of rated in 1 s,
/// or to 90 %. Asserted as for [`a_shift_of_work`]: no OVERLOAD or FAULT at
/// rest, every minute's highest estimated u within 0.002 of the first four
/// minutes', 110 % cut at the same sample (±1) as on a limiter switched on
/// with the same load hanging, within 1 s, 90 % not cut, both weighed
/// within 0.1 % of it. Here every counter that only grows at rest (the
/// time the boom has stood still, a sensor's time within its stuck band)
/// grows for the whole test: in f32 one 10 ms step stops adding to it
/// after about 3 days.
fn days_at_rest(precision: Precision, hours: f64) {
    let rope = rope_choice(Rope::Held(0.4), 40.0);
    let rated = rated_kg(40f64.to_radians());
    let (options, dt) = options_for_rate(rate_hz());
    for hanging in [0.8 * rated, 0.0] {
        let mut rest = Program::new(40.0, hanging, rope).unwrap();
        rest.push(Segment::Hold { duration_s: 60.0 }).unwrap();
        let samples = simulate_program(model(), &rest, &options).expect("simulation");
        let minutes: Vec<Vec<SynthRow>> = (0..4).map(|seed| synthesize(&samples, dt, 0.0, 0.0, &sensors(Seals::Seal, 50 + seed))).collect();
        let n = (hours * 60.0).ceil() as usize;
        let lifts = test_lifts(rope, hanging);
        let run = |n: usize| match precision {
            Precision::F64 => shift_with(model(), calibration_f64(Seals::Seal), &minutes, n, &lifts),
            Precision::F32 => shift_with(&thesis_load_model_f32(), calibration_f32(Seals::Seal), &minutes, n, &lifts),
        };
        let (fresh, first, long) = (run(0), run(minutes.len()), run(n));
        let high = long.highest_u.iter().copied().fold(0.0, f64::max);
        let name = format!("{precision:?}, {hanging:.0} kg hanging {hours} h");
        let (drift, failures) = uptime_failures(&name, "minute", &fresh, &first, &long);
        println!("{name}: highest estimated u {high:.4} (largest change over the rest {drift:.5})");
        assert!(failures.is_empty(), "{failures:#?}");
    }
}

#[test]
fn days_at_rest_f64() {
    days_at_rest(Precision::F64, 6.0);
}

#[test]
fn days_at_rest_f32() {
    days_at_rest(Precision::F32, 96.0);
}

/// The estimate/true band (5th–95th percentile) in constant-velocity motion
/// (1 s after the acceleration ramp to the deceleration ramp) and 1 s after
/// stopping (to the end of the log), loads 30 % and 80 % of the rated load at
/// 40°, every thesis move, rope and friction law: within [1.00, 1.10].
fn band(precision: Precision) {
    band_with(precision, &SEALS);
}

/// [`band`] for the friction laws `seals_of`.
fn band_with(precision: Precision, seals_of: &[Seals]) {
    let (m, r) = band_percentiles(precision, seals_of);
    assert!(m[0] >= 1.0 && m[2] <= 1.1 && r[0] >= 1.0 && r[2] <= 1.1, "motion {m:?} rest {r:?}");
}

/// The band's (p5, p50, p95) in motion and at rest (see [`band`]).
fn band_percentiles(precision: Precision, seals_of: &[Seals]) -> ([f64; 3], [f64; 3]) {
    band_percentiles_on(precision, &ROPES, seals_of)
}

/// [`band_percentiles`] on `ropes`.
fn band_percentiles_on(precision: Precision, ropes: &[Rope], seals_of: &[Seals]) -> ([f64; 3], [f64; 3]) {
    let (mut motion, mut rest) = (Vec::new(), Vec::new());
    for (a, b, dur, ramp, shape) in thesis_moves() {
        for frac in [0.3, 0.8] {
            let w = frac * rated_kg(40f64.to_radians());
            for &rope in ropes {
                for &seals in seals_of {
                    let sc = Scenario { load_kg: w, from_deg: a, to_deg: b, duration_s: dur, ramp_s: ramp, shape, rope, seals, lift_off_s: None, seed: 3 };
                    let (_, cv0, cv1, end) = sc.times();
                    let pts = replay(&sc, precision);
                    let (mut m, mut r) = (Vec::new(), Vec::new());
                    for p in &pts {
                        if p.t >= cv0 + 1.0 && p.t <= cv1 {
                            m.push(p.ratio);
                        } else if p.t >= end + 1.0 {
                            r.push(p.ratio);
                        }
                    }
                    let (m5, m95) = (percentile(&mut m.clone(), 0.05), percentile(&mut m.clone(), 0.95));
                    let (r5, r95) = (percentile(&mut r.clone(), 0.05), percentile(&mut r.clone(), 0.95));
                    println!("{:<60} motion {m5:.3}…{m95:.3}  rest {r5:.3}…{r95:.3}", sc.name());
                    motion.extend(m);
                    rest.extend(r);
                }
            }
        }
    }
    let m = [percentile(&mut motion, 0.05), percentile(&mut motion, 0.5), percentile(&mut motion, 0.95)];
    let r = [percentile(&mut rest, 0.05), percentile(&mut rest, 0.5), percentile(&mut rest, 0.95)];
    println!("{precision:?}: band in motion {:.3}/{:.3}/{:.3}, at rest {:.3}/{:.3}/{:.3} (p5/p50/p95)", m[0], m[1], m[2], r[0], r[1], r[2]);
    (m, r)
}

#[test]
fn band_in_motion_and_at_rest_f64() {
    band(Precision::F64);
}

#[test]
fn band_in_motion_and_at_rest_f32() {
    band(Precision::F32);
}

/// A friction law the limiter does not model: one that grows with the
/// piston's speed ([`Seals::Viscous`], 6 kN + 60 kN per m/s up). The
/// calibration, from 10 s runs, learns it as a constant of 16.8 kN up and
/// 11.7 kN down (and 0.114 s of lag, against 0.095 s for this sensor with
/// the modelled laws), so a slower move carries less friction than it
/// corrects for: raising reads low, lowering high. The safety bounds hold
/// anyway: no OVERLOAD at 85 % (highest estimated u 0.937), every lowering
/// past the rated radius cut between true u 1/1.1 and 1.05 (at 0.935–0.967),
/// lift-off as with the modelled laws. With 140 kN per m/s up (100 down) two
/// slow lowerings cut early, at true u 0.89; at 200 kN per m/s all 16 slow
/// ones do. What does not hold at one speed is the band; calibrated at two
/// speeds it does (`band_with_a_speed_dependent_friction_calibrated_at_two_speeds_*`).
fn a_speed_dependent_friction(precision: Precision) {
    no_false_overload(precision, &ROPES, &[Seals::Viscous]);
    lowering_past_rated_radius(precision, &ROPES, &[Seals::Viscous]);
    lift_off(precision, &[Seals::Viscous]);
}

/// The safety bounds in a world the limiter was not built on: no OVERLOAD
/// at 85 % ([`no_false_overload`]), every lowering past the rated radius cut
/// between true u 1/1.1 and 1.05 ([`lowering_past_rated_radius`]), lift-off
/// at 90 % not cut and at 110 % within 1 s ([`lift_off`]), every rope. Returns
/// the band's percentiles in motion and at rest ([`band_percentiles`],
/// printed), for the caller to assert what holds in its world.
fn other_world(precision: Precision, seals: &[Seals]) -> ([f64; 3], [f64; 3]) {
    no_false_overload(precision, &ROPES, seals);
    lowering_past_rated_radius(precision, &ROPES, seals);
    lift_off(precision, seals);
    band_percentiles(precision, seals)
}

/// Whether a band's (p5, p50, p95) lies within [1.00, 1.10].
fn in_band(b: [f64; 3]) -> bool {
    b[0] >= 1.0 && b[2] <= 1.1
}

/// Asserts a world's band (motion `m`, rest `r`) within [1.00, 1.10]; where
/// the rest band's p5 is known to miss (`rest_p5_may_miss`, measured in the
/// caller's doc), only that the miss stays under 1 % and the p95 inside.
fn assert_band(world: &str, m: [f64; 3], r: [f64; 3], rest_p5_may_miss: bool) {
    let rest_ok = if rest_p5_may_miss { r[0] >= 0.99 && r[2] <= 1.1 } else { in_band(r) };
    assert!(in_band(m) && rest_ok, "{world}: motion {m:?} rest {r:?}");
}

/// A seal that breaks away at twice its sliding force (Stribeck,
/// [`Seals::Stribeck`]): the calibration's 10 s runs see the sliding force,
/// every start and stop and the slowest moves some of the breakaway.
/// Measured (f64 and f32 alike): highest estimated u at 85 % 0.932;
/// lowerings cut at true u 0.950–0.981; band in motion p5/p50/p95
/// 1.009/1.038/1.055, at rest 1.005/1.042/1.060. The band holds too.
fn a_stribeck_seal(precision: Precision) {
    let (m, r) = other_world(precision, &[Seals::Stribeck]);
    assert!(in_band(m) && in_band(r), "motion {m:?} rest {r:?}");
}

#[test]
fn a_stribeck_seal_keeps_the_bounds_and_the_band_f64() {
    a_stribeck_seal(Precision::F64);
}

#[test]
fn a_stribeck_seal_keeps_the_bounds_and_the_band_f32() {
    a_stribeck_seal(Precision::F32);
}

/// Seals that stay stuck at standstill (the friction a motion leaves
/// relaxes over 60 s instead of at once; the campaign's cranes take 0–1 s,
/// the limiter takes it off over 0.5 s): after a lowering the force reads
/// low by the lowering friction, after a raise high. The bounds hold, and
/// the band's low side (f64: at rest p5 1.016, in motion 1.008); the high
/// side at rest does not: p95 1.24, up to 1.45 × a 4.3 t load at 80° after
/// a 10 s raise on the 17 m rope (the stuck up-friction read as load, toward
/// cutting; a raise lowers the utilization, so it is high only where the
/// load was higher still before the raise).
fn seals_stuck_at_standstill(precision: Precision) {
    with_setting(&STANDSTILL_RELEASE_S, 60.0, || {
        let (m, r) = other_world(precision, &SEALS);
        assert!(in_band(m) && r[0] >= 1.0, "motion {m:?} rest {r:?}");
        println!("{precision:?}: stuck seals, band at rest p95 {:.3} (reads high after a raise)", r[2]);
    });
}

#[test]
fn seals_stuck_at_standstill_keep_the_bounds_f64() {
    seals_stuck_at_standstill(Precision::F64);
}

#[test]
fn seals_stuck_at_standstill_keep_the_bounds_f32() {
    seals_stuck_at_standstill(Precision::F32);
}

/// The friction turning over ±0.02 °/s (nearly a sign function) or ±1 °/s
/// of boom rate instead of synth's ±0.2 °/s (the friction while moving is
/// its law times tanh(rate / onset)). The bounds hold for both. Measured
/// (f64): at 0.02 °/s the band is 1.008/1.037/1.060 in motion and
/// 1.006/1.040/1.057 at rest; at 1 °/s the 30 s moves (1.3 °/s) carry only
/// 86 % of the friction the calibration's 10 s runs learned, so raising
/// reads low, and the move's weighing held at rest after a slow raise to
/// 80° on the 3 m rope reads 0.957 of a 30 % load: at rest p5 0.997 (in
/// motion 1.009), the speed-dependent friction's miss at one speed
/// (`band_with_a_speed_dependent_friction_calibrated_at_one_speed_measured`) in small;
/// calibrated at two speeds it is within the band
/// ([`a_blunt_friction_onset_calibrated_at_two_speeds_holds_the_band`]).
fn a_sharp_or_blunt_friction_onset(precision: Precision) {
    for (onset, rest_p5_may_miss) in [(0.02, false), (1.0, true)] {
        with_setting(&FRICTION_ONSET_DEG_S, onset, || {
            let (m, r) = other_world(precision, &SEALS);
            assert_band(&format!("onset {onset}"), m, r, rest_p5_may_miss);
            println!("{precision:?}: friction onset {onset} deg/s, band at rest p5 {:.3}", r[0]);
        });
    }
}

#[test]
fn a_sharp_or_blunt_friction_onset_keeps_the_bounds_f64() {
    a_sharp_or_blunt_friction_onset(Precision::F64);
}

#[test]
fn a_sharp_or_blunt_friction_onset_keeps_the_bounds_f32() {
    a_sharp_or_blunt_friction_onset(Precision::F32);
}

/// Logs sampled at 200 Hz, at 50 Hz (the example logs' and `crane-sim
/// synth`'s rate) and at 20 Hz (the slowest the log format takes) instead
/// of 100 Hz, the crane calibrated from runs at the same rate. The bounds
/// hold. Measured (f64): band in motion 1.011/1.037/1.052 at 200 Hz,
/// 1.006/1.031/1.048 at 50 Hz, 1.010/1.038/1.071 at 20 Hz; at rest p5
/// 1.004 at 200 Hz, 0.998 at 50 Hz (the 17 m rope after a 10 s raise to
/// 80°, 0.995: that calibration learns the constant 12 kN up-friction as
/// 10.5 kN + 0.98 % of the force, which reads a raise low; the slope of a
/// calibration from unloaded runs alone scatters with the noise, 0–1.2 %
/// over three seeds at either rate) and 1.004 at 20 Hz. (Until the
/// simulation's step was fitted to the period, "200 Hz" logs were sampled
/// every 6 ms, at 166.7 Hz: rest p5 1.000 there.)
fn logs_at_other_rates(precision: Precision) {
    for (rate, rest_p5_may_miss) in [(200.0, false), (50.0, true), (20.0, false)] {
        with_setting(&LOG_RATE_HZ, rate, || {
            let (m, r) = other_world(precision, &SEALS);
            assert_band(&format!("{rate} Hz"), m, r, rest_p5_may_miss);
            println!("{precision:?}: {rate} Hz, band at rest p5 {:.3}", r[0]);
        });
    }
}

#[test]
fn logs_at_200_50_and_20_hz_keep_the_bounds_f64() {
    logs_at_other_rates(Precision::F64);
}

#[test]
fn logs_at_200_50_and_20_hz_keep_the_bounds_f32() {
    logs_at_other_rates(Precision::F32);
}

/// Angle sensors slower or less damped than synth's 2 Hz, ζ = 0.7 pendulum
/// (the campaign's take 1.5–3 Hz, ζ 0.5–0.9): 1 Hz at ζ 0.5, 0.7 and 0.9,
/// 1.25 and 1.5 Hz at ζ 0.5. The calibration tries a first-order lag and
/// pendulums of ζ 0.5, 0.7 and 0.9 (`moment_limiter::sensor_lag`, "The
/// sensor's shape") and hands the limiter the steady-rate lag of the one
/// that fits best: 0.150, 0.213 and 0.272 s for 0.159, 0.223 and 0.286 s at
/// 1 Hz, 0.125 s for 0.127 s at 1.25 Hz, 0.068 s for 0.106 s at 1.5 Hz (the
/// shapes fit alike there; a first-order lag stays). The bounds and the
/// band hold. Measured (f64): band in motion p5 1.010–1.012, at rest
/// 1.004–1.008; lowerings cut at true u 0.947–0.987; 85 % reads at most u
/// 0.934.
///
/// Behind a 1 Hz pendulum at ζ 0.5 (lag 2ζ/ω_n = 0.159 s on a steady
/// rate) a first-order search alone learned 0.097 s, the force then stood
/// for an instant 0.06 s later than the angle it was read at, and three
/// 15 s lowerings on the 3 m rope were cut at true u 0.901–0.905, before
/// 1/1.1 (a known gap until the search tried the pendulum's own shape: it
/// learns 0.150 s, and every lowering is cut from 0.95).
fn slow_or_underdamped_pendulums(precision: Precision) {
    for p in [(1.0, 0.5), (1.0, 0.7), (1.0, 0.9), (1.25, 0.5), (1.5, 0.5)] {
        with_setting(&PENDULUM_2ND, Some(p), || {
            let (m, r) = other_world(precision, &SEALS);
            println!("{precision:?}: pendulum {p:?}: band in motion {m:.3?}, at rest {r:.3?}");
            assert!(in_band(m) && in_band(r), "pendulum {p:?}: motion {m:?} rest {r:?}");
        });
    }
}

#[test]
fn slow_or_underdamped_pendulums_keep_the_bounds_f64() {
    slow_or_underdamped_pendulums(Precision::F64);
}

#[test]
fn slow_or_underdamped_pendulums_keep_the_bounds_f32() {
    slow_or_underdamped_pendulums(Precision::F32);
}

/// Noisier sensors than synth's 0.3 bar and 0.03° (the campaign's 0.1–0.5
/// bar, 0.01–0.05°): three times either. The bounds hold. Pressure noise
/// of 0.9 bar keeps the band (f64: 1.009/1.039/1.069 in motion,
/// 1.007/1.041/1.064 at rest); angle noise of 0.09° does not in motion
/// (p5 0.979; at rest 1.011/1.037/1.061): the boom's acceleration is the
/// filtered angle differenced twice, its noise enters the boom's inertia
/// term and the rope pendulums' drive, and the bank's lowest rope reads the
/// low side of the noise.
fn noisier_sensors(precision: Precision) {
    with_setting(&NOISE_BAR, Some(0.9), || {
        let (m, r) = other_world(precision, &SEALS);
        assert!(in_band(m) && in_band(r), "0.9 bar: motion {m:?} rest {r:?}");
    });
    with_setting(&NOISE_DEG, Some(0.09), || {
        let (m, r) = other_world(precision, &SEALS);
        // The motion band's p5 misses (0.979); it may not grow.
        assert!(in_band(r) && m[0] >= 0.97 && m[2] <= 1.1, "0.09 deg: motion {m:?} rest {r:?}");
        println!("{precision:?}: angle noise 0.09 deg, band in motion p5 {:.3}", m[0]);
    });
}

/// A crane whose boom is not the limiter's model: the logs simulated with
/// Young's modulus 30 % lower or higher (the static sag and the bounce's
/// frequency differ; the limiter's load model is the nominal boom's), or
/// with the structural damping ratio 0.3 or 3 times the model's 0.02 (the
/// bounce rings longer or dies sooner), the calibration's runs on the same
/// crane. The bounds and the band hold. Measured (f64): band in motion
/// p5/p50/p95 1.011/1.040/1.059 (softer), 1.008/1.036/1.055 (stiffer),
/// 1.009/1.037/1.056 (either damping); at rest p5 1.004–1.009.
fn a_boom_other_than_the_model(precision: Precision, booms: &[(f64, f64)]) {
    for &boom in booms {
        with_setting(&BOOM_FACTORS, boom, || {
            let (m, r) = other_world(precision, &SEALS);
            assert!(in_band(m) && in_band(r), "boom {boom:?}: motion {m:?} rest {r:?}");
        });
    }
}

#[test]
fn a_boom_other_than_the_model_keeps_the_bounds_f64() {
    a_boom_other_than_the_model(Precision::F64, &[(0.7, 1.0), (1.3, 1.0), (1.0, 0.3), (1.0, 3.0)]);
}

#[test]
fn a_boom_other_than_the_model_keeps_the_bounds_f32() {
    a_boom_other_than_the_model(Precision::F32, &[(0.7, 1.0), (1.0, 0.3)]);
}

#[test]
fn noisier_sensors_keep_the_bounds_f64() {
    noisier_sensors(Precision::F64);
}

#[test]
fn noisier_sensors_keep_the_bounds_f32() {
    noisier_sensors(Precision::F32);
}

#[test]
fn a_speed_dependent_friction_f64() {
    a_speed_dependent_friction(Precision::F64);
}

#[test]
fn a_speed_dependent_friction_f32() {
    a_speed_dependent_friction(Precision::F32);
}

/// The band under a friction that grows with the piston's speed
/// ([`Seals::Viscous`]), calibrated from runs at two speeds (10 s and 30 s
/// unloaded luffs up and down, [`TWO_SPEEDS`]): the calibration learns the
/// friction's part per unit boom rate c (`moment_limiter::calibration`),
/// and the band is within [1.00, 1.10] in motion and at rest, f64 and f32.
/// Measured (f64): calibration 5.5 kN + 144 kN·s/rad·|ω| up, 4.0 kN +
/// 98 kN·s/rad·|ω| down (the synthesized 6 kN + 60 kN per m/s and 4 kN +
/// 40 kN per m/s, the piston's speed 2.0–2.5 m/rad of boom rate); band
/// p5/p50/p95 1.011/1.036/1.051 in motion, 1.001/1.039/1.054 at rest.
/// Calibrated from the 10 s runs alone (one speed: c not observable, and
/// `crane-sim calibrate` says so), as before c was learned: the friction
/// is learned as a constant of 17 kN up and 11.5 kN down, the friction at
/// the 10 s runs' speed, and the band is 0.899/1.040/1.143 in motion and
/// 0.804/1.040/1.108 at rest (a 30 s raise reads 0.85 of the load at its
/// end): `band_with_a_speed_dependent_friction_calibrated_at_one_speed_measured`.
fn band_with_a_speed_dependent_friction_calibrated_at_two_speeds(precision: Precision) {
    with_setting(&TWO_SPEEDS, true, || band_with(precision, &[Seals::Viscous]));
}

/// The f64 limiter in that world keeps the safety bounds too, as at one
/// speed ([`other_world`]: no OVERLOAD at 85 %, every lowering past the
/// rated radius cut between true u 1/1.1 and 1.05, lift-off at 90 % not cut
/// and at 110 % within 1 s), and the band.
#[test]
fn band_with_a_speed_dependent_friction_calibrated_at_two_speeds_f64() {
    with_setting(&TWO_SPEEDS, true, || {
        let (m, r) = other_world(Precision::F64, &[Seals::Viscous]);
        assert_band("viscous, two speeds", m, r, false);
    });
}

#[test]
fn band_with_a_speed_dependent_friction_calibrated_at_two_speeds_f32() {
    band_with_a_speed_dependent_friction_calibrated_at_two_speeds(Precision::F32);
}

/// The same band calibrated at one speed, printed (see
/// [`band_with_a_speed_dependent_friction_calibrated_at_two_speeds`]):
/// `cargo test --release -p host-sim --test field_limiter
/// band_with_a_speed_dependent_friction_calibrated_at_one_speed_measured --
/// --ignored --nocapture`.
#[test]
#[ignore = "measurement: a friction that grows with the speed, calibrated at one speed (c not observable), misses the band (p5 0.90 in motion, 0.80 at rest)"]
fn band_with_a_speed_dependent_friction_calibrated_at_one_speed_measured() {
    band_percentiles(Precision::F64, &[Seals::Viscous]);
}

/// The modelled friction laws calibrated from runs at two speeds: the
/// rate's part comes out at nothing to speak of (the law has none), and the
/// band holds as with one speed (`band_in_motion_and_at_rest_f64`).
#[test]
fn band_with_the_modelled_laws_calibrated_at_two_speeds() {
    with_setting(&TWO_SPEEDS, true, || {
        for seals in SEALS {
            let cal = calibration_f64(seals);
            // Under 300 N at 0.07 rad/s (a 10 s luff over 40 degrees).
            let most = cal.friction_up_per_rate.max(cal.friction_down_per_rate) * 0.07;
            assert!(most < 300.0, "{seals:?}: {cal:?}");
        }
        band(Precision::F64);
    });
}

/// The friction turning over ±1 °/s ([`a_sharp_or_blunt_friction_onset`]),
/// calibrated from runs at two speeds ([`TWO_SPEEDS`]): the calibration takes
/// the 30 s runs' smaller friction as a part per unit rate (measured: 22 kN·s/rad
/// up, 15 kN·s/rad down with constant friction; 11 and 9 with the seal law),
/// and the band holds at rest too: p5/p50/p95 1.013/1.038/1.052 in motion and
/// 1.006/1.040/1.060 at rest (at one speed 0.997 at rest, p5).
#[test]
fn a_blunt_friction_onset_calibrated_at_two_speeds_holds_the_band() {
    with_setting(&TWO_SPEEDS, true, || {
        with_setting(&FRICTION_ONSET_DEG_S, 1.0, || {
            let (m, r) = band_percentiles(Precision::F64, &SEALS);
            assert_band("onset 1 deg/s, two speeds", m, r, false);
        });
    });
}

/// A seal that breaks away at twice its sliding force ([`Seals::Stribeck`]),
/// calibrated from runs at two speeds: its friction falls with the speed,
/// which no part per unit rate c ≥ 0 fits, so the calibration learns c = 0
/// (a law fitted over both speeds), and the bounds and the band hold as at
/// one speed ([`a_stribeck_seal`]). Measured (f64): lowerings cut at true u
/// 0.950–0.981, 85 % read at most 0.916, band p5/p50/p95 1.011/1.038/1.056
/// in motion and 1.002/1.041/1.060 at rest.
#[test]
fn a_stribeck_seal_calibrated_at_two_speeds_learns_no_rate_part() {
    with_setting(&TWO_SPEEDS, true, || {
        let cal = calibration_f64(Seals::Stribeck);
        assert_eq!((cal.friction_up_per_rate, cal.friction_down_per_rate), (0.0, 0.0), "{cal:?}");
        let (m, r) = other_world(Precision::F64, &[Seals::Stribeck]);
        assert_band("Stribeck, two speeds", m, r, false);
    });
}

/// Runs `f` with the pendulum reading `offset_deg` off (see
/// [`ANGLE_OFFSET_DEG`]).
fn with_pendulum_off_by(offset_deg: f64, f: impl FnOnce()) {
    with_setting(&ANGLE_OFFSET_DEG, offset_deg, f);
}

/// A pendulum that reads off by a fixed angle: the calibration cannot
/// observe it (docs/calibration.md), so the limiter reads the model at the
/// wrong angle. Zeroed within ±1° the bounds hold (f64, every rope, both
/// friction laws): no OVERLOAD at 85 % (highest estimated u 0.950 at +1°,
/// 0.920 at −1°), every lowering past the rated radius cut between true u
/// 1/1.1 and 1.05 (0.934–0.973 at +1°, 0.945–1.010 at −1°). Beyond, see
/// `pendulum_zero_error_measured`.
#[test]
fn a_pendulum_zeroed_within_one_degree_keeps_the_bounds() {
    for offset in [1.0, -1.0] {
        with_pendulum_off_by(offset, || {
            no_false_overload(Precision::F64, &ROPES, &SEALS);
            lowering_past_rated_radius(Precision::F64, &ROPES, &SEALS);
        });
    }
}

/// The pendulum 2° and 3° off, printed (f64, 64 moves and 64 lowerings
/// each). Reading high errs toward cutting: at +2° 24 lowerings are cut
/// before true u 1/1.1 (from 0.874), at +3° 32 (from 0.817) and 8 of the
/// 85 % moves are cut. Reading low errs the other way but stays inside
/// J159's 1.05: at −2° the lowerings are cut at true u 0.935–1.028, at −3°
/// at 0.928–1.041.
#[test]
#[ignore = "measurement: the pendulum's zero error beyond 1 deg, which the calibration cannot observe"]
fn pendulum_zero_error_measured() {
    for offset in [2.0, -2.0, 3.0, -3.0] {
        with_pendulum_off_by(offset, || {
            println!("== pendulum reads {offset:+} deg off");
            let r = std::panic::catch_unwind(|| no_false_overload(Precision::F64, &ROPES, &SEALS));
            println!("   85 %: {}", if r.is_ok() { "no OVERLOAD" } else { "OVERLOAD (above)" });
            let r = std::panic::catch_unwind(|| lowering_past_rated_radius(Precision::F64, &ROPES, &SEALS));
            println!("   lowering: {}", if r.is_ok() { "every cut between 1/1.1 and 1.05" } else { "failures (above)" });
        });
    }
}

/// The band in motion against the angle sensor's true lag (the campaign's
/// cranes have 0.05–0.3 s; the limiter's default is the pendulum's
/// 0.111 s), each crane calibrated from its own unloaded runs, the lag
/// learned: within [1.00, 1.10] for first-order sensors of 0.05 and 0.3 s
/// (the pendulum's is `band_in_motion_and_at_rest_f64`). With the default
/// lag kept, a 0.3 s sensor read 1.000 at p5 in motion and 0.983 at rest
/// (`band_against_sensor_lag_measured`). At rest within [1.00, 1.10] too
/// (p5 1.005 for both sensors): it read 0.994–0.998 at p5 before the
/// averages stood in motion while a short rope could not weigh, the lowest
/// being light loads at rest at 80° after raising.
#[test]
fn band_in_motion_against_sensor_lag() {
    for tau in [0.05, 0.3] {
        behind_a_lagging_sensor(tau, || {
            println!("first-order lag {tau} s, lag learned:");
            let (m, r) = band_percentiles(Precision::F64, &SEALS);
            println!("  at rest p5/p95 {:.3}/{:.3}", r[0], r[2]);
            assert!(m[0] >= 1.0 && m[2] <= 1.1, "lag {tau} s: motion {m:?}");
            // At rest too, since the averages stand in motion while a short rope
            // cannot weigh (the p5 was 0.994 at 0.3 s before).
            assert!(r[0] >= 1.0 && r[2] <= 1.1, "lag {tau} s: at rest {r:?}");
        });
    }
}

/// The band against the sensor's lag, learned and as before (the default
/// kept), printed, not asserted: `cargo test --release -p host-sim --test
/// field_limiter band_against_sensor_lag_measured -- --ignored --nocapture --test-threads=1`.
#[test]
#[ignore = "measurement"]
fn band_against_sensor_lag_measured() {
    for learn in [true, false] {
        with_setting(&LEARN_LAG, learn, || {
            for tau in [0.05, 0.11, 0.2, 0.3] {
                behind_a_lagging_sensor(tau, || {
                    let (m, r) = band_percentiles(Precision::F64, &SEALS);
                    println!(
                        "sensor {tau} s, lag {}: motion {:.3}/{:.3}/{:.3} rest {:.3}/{:.3}/{:.3}",
                        if learn { "learned" } else { "default 0.111 s" },
                        m[0], m[1], m[2], r[0], r[1], r[2]
                    );
                });
            }
        });
    }
}

/// A trace of one scenario for diagnosis (not a test of requirements):
/// `FIELD_TRACE="rope_fraction from to duration load_fraction" cargo test
/// --release -p host-sim --test field_limiter trace -- --ignored --nocapture`.
#[test]
#[ignore = "diagnostic trace"]
fn trace() {
    let spec = std::env::var("FIELD_TRACE").unwrap_or_else(|_| "0 40 80 10 0.85".into());
    let v: Vec<f64> = spec.split_whitespace().map(|x| x.parse().unwrap()).collect();
    let rope = if v[0] < 0.0 { Rope::Thesis } else { Rope::Held(v[0]) };
    let sc = Scenario { load_kg: if v[4] > 10.0 { v[4] } else { v[4] * rated_kg(40f64.to_radians()) }, from_deg: v[1], to_deg: v[2], duration_s: v[3], ramp_s: 1.0, shape: RampShape::Cycloidal, rope, seals: if v.len() > 5 && v[5] > 0.0 { Seals::Seal } else { Seals::Constant }, lift_off_s: None, seed: 7 };
    let rows = sc.rows();
    let cal = calibration_with(model(), sc.seals);
    let config = LimiterConfig { calibration: cal, ..LimiterConfig::standard() };
    let mut lim = Limiter::new(*model(), config).unwrap();
    for (k, r) in rows.iter().enumerate() {
        let rep = lim.step_frame(&frame::<f64>(r));
        if let Some(f) = rep.fault {
            println!("t {:6.2} fault {f}", r.t_s);
            continue;
        }
        if k % 10 == 0 {
            let (Some(e), Some(m)) = (rep.estimate, rep.measurement) else { continue };
            println!(
                "t {:6.2} th {:6.2} swing {:6.2}deg ratio {:.3} u {:.3} tanphi {:+.3} acc {:+.2} state {:?} {:?}",
                r.t_s, r.truth.boom_angle_rad.to_degrees(), r.truth.swing_rad.to_degrees(), e.load_kg / r.true_load_kg / 1.05,
                r.true_load_kg / rated_kg(r.truth.boom_angle_rad), m.tan_swing, m.accel_deg_s2, rep.state, e.static_load.map(|s| (s.fast_kg / r.true_load_kg, s.slow_kg.map(|w| w / r.true_load_kg)))
            );
        }
    }
}

/// The limiter's cost per cycle on the host (printed, not asserted): the
/// same 10 s held-rope log replayed with the rope-hypothesis bank and
/// without it (`swing: None`), f64 and f32, best of 5.
/// `cargo test --release -p host-sim --test field_limiter cost_per_cycle -- --ignored --nocapture`
#[test]
#[ignore = "measurement"]
fn cost_per_cycle() {
    let sc = Scenario { load_kg: 4000.0, from_deg: 40.0, to_deg: 80.0, duration_s: 10.0, ramp_s: 1.0, shape: RampShape::Cycloidal, rope: Rope::Held(0.5), seals: Seals::Constant, lift_off_s: None, seed: 1 };
    let rows = sc.rows();
    fn time<T: Real, M: HookLoadModel<T> + Clone>(m: &M, rows: &[SynthRow], bank: bool) -> f64 {
        let frames: Vec<Frame<T>> = rows.iter().map(frame::<T>).collect();
        let mut best = f64::INFINITY;
        for _ in 0..5 {
            let config = LimiterConfig { swing: if bank { LimiterConfig::<T>::standard().swing } else { None }, ..LimiterConfig::standard() };
            let mut lim = Limiter::new(m.clone(), config).unwrap();
            let t0 = std::time::Instant::now();
            for f in &frames {
                std::hint::black_box(lim.step_frame(f));
            }
            best = best.min(t0.elapsed().as_secs_f64() / frames.len() as f64);
        }
        best * 1e6
    }
    let m32 = thesis_load_model_f32();
    println!(
        "per cycle: f64 {:.1} µs with the bank, {:.1} µs without; f32 {:.1} µs with, {:.1} µs without",
        time(model(), &rows, true),
        time(model(), &rows, false),
        time(&m32, &rows, true),
        time(&m32, &rows, false)
    );
}




/// Switched on during a lowering past the rated radius (a power cut, a
/// brown-out or a watchdog reset mid-move, or a log whose recording starts
/// mid-move): the rated load at 45° or 30° lowered 80° → 20° in 15 s, every
/// rope of [`ROPES`], both friction laws, the limiter started 3–12 s into
/// the log (1–10 s into the move, at a true u of 0.43–1.14), 8 s at rest at
/// 20° after the stop. Asserted: from 0.3 s after it is switched on
/// (`moment_limiter::cycle::power_up::WATCH_S`) to the end no sample at a
/// true u of 1.05 or more is uncut, the motion is cut (FAULT, or OVERLOAD)
/// from then until the boom stops, and at rest at 20°, where the true u is
/// 1.3–1.5, it is cut to the end. Printed: when the FAULT clears after the
/// stop (3.1 s after it, 4.6 s for the 17 m held rope). Before
/// (`moment_limiter::cycle::power_up`), the limiter weighed from the first
/// reading: as little as −0.11 of the load at first and 0.09 of it 0.3 s
/// later; 24 of the 112 cases left a true u
/// over 1.05 uncut (for up to 0.86 s, first cut at up to 1.157), 47 were cut
/// before 1/1.1 (from 0.62). Switched on 2 s before the move, as every other
/// test does, nothing changes.
#[test]
fn switched_on_during_a_lowering() {
    const STOP_S: f64 = 2.0 + 15.0;
    let mut failures = Vec::new();
    for rope in ROPES {
        for seals in SEALS {
            for rated_at in [45.0f64, 30.0] {
                let w = rated_kg(rated_at.to_radians());
                let mut p = Program::new(80.0, w, rope_choice(rope, 20.0)).unwrap();
                p.push(Segment::Hold { duration_s: 2.0 }).unwrap();
                p.push(Segment::Luff { to_deg: 20.0, shape: RampShape::Linear, t1_s: 1.0, t2_s: 14.0, t3_s: 15.0 }).unwrap();
                p.push(Segment::Hold { duration_s: 8.0 }).unwrap();
                let rows = program_rows(&p, seals, 17);
                for start_s in [3.0, 5.0, 7.0, 9.0, 10.0, 11.0, 12.0] {
                    let on = rows.iter().position(|r| r.t_s >= start_s).unwrap();
                    let pts = replay_rows(&rows[on..], seals, Precision::F64);
                    let name = format!("{rope:?} {seals:?}, rated at {rated_at}, switched on at {start_s} s (true u {:.3})", pts[0].u);
                    let watched = start_s + 0.3;
                    if let Some(q) = uncut(&pts).find(|q| q.t >= watched) {
                        failures.push(format!("{name}: uncut at {:.2} s, true u {:.3}", q.t, q.u));
                    }
                    if let Some(q) = pts.iter().find(|q| q.t >= watched && q.t <= STOP_S && !cut(q)) {
                        failures.push(format!("{name}: moving uncut ({:?}) at {:.2} s", q.state, q.t));
                    }
                    let clears = pts.iter().find(|q| q.t > STOP_S && q.state != LimiterState::Fault).map(|q| (q.t - STOP_S, q.state));
                    if let Some(q) = pts.iter().find(|q| q.t > STOP_S && !cut(q)) {
                        failures.push(format!("{name}: at rest at true u {:.3}, {:?} at {:.2} s", q.u, q.state, q.t));
                    }
                    println!("{name:<70} FAULT clears {} after the stop", clears.map_or("never".into(), |(t, s)| format!("{t:+.2} s, to {s:?}")));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

/// KNOWN GAP, measured (f64): a load added at rest where a rope of the bank
/// follows the swing ([`ADDED_SEEN`], 110 % and 90 % taken up in 0.5 s 3 s
/// after the stop) with seals that stay stuck at standstill (the friction
/// relaxes over 60 s; the campaign's cranes 0–1 s): the rest reading moves
/// from the move's by the stuck friction's share after a lowering (the
/// limiter releases it over its configured 0.5 s there; after a raise the
/// calibration learned 60 s, `moment_limiter::seal_release`), every rope's
/// ratio to its average with it, and the rope that follows the swing is
/// not consistent enough to vote. 4 of 16 cases of 110 % are cut late,
/// all after 60° → 40°: on the 5.95 m rope at +1.04–1.07 s and on the 8.9 m
/// rope at +2.34–2.37 s (the others at +0.69–0.87 s, as with released
/// seals). Before the calibration learned the release after a raise, also
/// 40° → 60° on the 5.95 m rope at +3.61–3.69 s; released over 3 s, one
/// case at +3.86 s.
///
/// What would close it: a consistency test that a change common to every
/// rope (the seals' release) does not disturb, which the previous attempt
/// (freezing the ropes' inconsistency through the stop) did not give
/// without false OVERLOADs; or the release after a lowering learned too,
/// which read the load low where the seals let go at once
/// (`moment_limiter::seal_release`).
#[test]
#[ignore = "KNOWN GAP: with seals stuck at standstill, a load added 3 s after a lowering's stop is cut up to 2.4 s after its take-up where a rope follows the swing"]
fn a_load_added_at_rest_with_stuck_seals_known_gap() {
    with_setting(&STANDSTILL_RELEASE_S, 60.0, || load_added_at_rest_after_a_move(Precision::F64, &ADDED_SEEN));
}

/// The known gap above pinned at its measured size, so that it cannot widen
/// unseen: with seals stuck at standstill 110 % added at rest is cut within
/// 2.5 s of its take-up (measured: at most 2.37 s; 3.69 s before the
/// calibration learned the release after a raise) and 90 % is never an
/// OVERLOAD.
#[test]
fn a_load_added_at_rest_with_stuck_seals_is_cut_within_2_5_s() {
    let worst = with_setting(&STANDSTILL_RELEASE_S, 60.0, || load_added_at_rest_after_a_move_measured(Precision::F64, &ADDED_SEEN, 4.0).1);
    println!("stuck seals: {worst:?}");
    assert!(worst.slowest_overload_s <= 2.5 && worst.overload_at_90_u == 0.0, "{worst:#?}");
}

/// A load added at rest where a rope of the bank follows the swing, behind
/// 0.09° of angle noise (three times synth's): 110 % cut within 1 s of its
/// take-up, 90 % never, as without the noise (measured: the estimate at
/// 1/1.1 of the new load within 0.83 s).
/// Cut up to 3.90 s after (40° → 60° on the 5.95 m rope, constant
/// friction) before the calibration learned the seals' release after a
/// raise (`moment_limiter::seal_release`): the limiter took off for 1–2 s
/// friction the simulator's seals had let go at the stop, and the noisy
/// rest kept the rope that follows the swing from voting.
#[test]
fn a_load_added_at_rest_behind_0_09_deg_of_angle_noise() {
    with_setting(&NOISE_DEG, Some(0.09), || load_added_at_rest_after_a_move(Precision::F64, &ADDED_SEEN));
}

/// The loads added at rest 3 s after a stop, where a rope of the bank
/// follows the swing ([`ADDED_SEEN`], over 6 s) and where none does
/// ([`ADDED_GAP`], over 20 s), behind `noise_deg` of angle noise (f64).
fn loads_added_at_rest_behind_angle_noise(noise_deg: f64) -> (AddedAtRestWorst, AddedAtRestWorst) {
    let (seen, gap) = with_setting(&NOISE_DEG, Some(noise_deg), || {
        let seen = load_added_at_rest_after_a_move_measured(Precision::F64, &ADDED_SEEN, 6.0).1;
        let gap = load_added_at_rest_after_a_move_measured(Precision::F64, &ADDED_GAP, 20.0).1;
        (seen, gap)
    });
    println!("{noise_deg} deg of angle noise: where a rope follows {seen:?}; where none does {gap:?}");
    (seen, gap)
}

/// KNOWN GAP, measured (f64): an angle sensor five times noisier than
/// synth's (0.15°). Up to 0.12° a load added at rest does what it does at
/// 0.09° (where a rope follows, 110 % cut within 3.82 s of its take-up;
/// where none does, within 8.59 s; 90 % never an OVERLOAD). At 0.15°, 90 %
/// added on the 3 m rope stopped at 80° is an OVERLOAD at true u 0.900
/// 3.0 s after its take-up (both friction laws), and where a rope follows
/// 110 % is cut up to 3.80 s after its take-up, with 18 of the 32 cases
/// missing a bound (4 at 0.12°). Not traced further: a pendulum this noisy
/// is outside what the limiter is specified for (docs/limiter.md).
#[test]
#[ignore = "KNOWN GAP: behind 0.15 deg of angle noise, 90 % added at rest on the 3 m rope at 80 deg is an OVERLOAD"]
fn loads_added_at_rest_behind_0_15_deg_of_angle_noise_known_gap() {
    let (seen, gap) = loads_added_at_rest_behind_angle_noise(0.15);
    assert!(seen.slowest_overload_s <= 1.0 && seen.overloads_at_90 + gap.overloads_at_90 == 0, "{seen:?} {gap:?}");
}

/// The known gap above pinned at its measured size: behind 0.15° of angle
/// noise, 110 % added where a rope follows is cut within 3.85 s of its
/// take-up (3.80 s measured), where none does it is left uncut for no more
/// than 9 s (4.60 s), and 90 % is an OVERLOAD in no more than the 2 cases
/// measured (none where a rope follows).
#[test]
fn loads_added_at_rest_behind_0_15_deg_of_angle_noise_stay_as_measured() {
    let (seen, gap) = loads_added_at_rest_behind_angle_noise(0.15);
    assert!(seen.slowest_overload_s <= 3.85 && seen.overloads_at_90 == 0, "{seen:?}");
    assert!(gap.longest_uncut_s <= 9.0 && gap.overloads_at_90 <= 2, "{gap:?}");
}

/// Switched on at a steep boom behind noisy pressure sensors: 80 % of the
/// load rated at 75° hangs at 85°, 82° or 78° (a 20 s raise or lowering of
/// 7° after 2 s at rest; every rope, both friction laws, 8 noise draws) with
/// 0.85 bar of pressure noise (synth's 0.3 × 2.8; the wide campaign's cranes
/// reach 1.5). At 85° the load's arm is a tenth of the boom, so one
/// sample's noise weighs a lot. Until the move nothing WARNs (u ≥ 0.9, where
/// the ×1.05 reading of this load is 0.84), and from 0.1 s after power-up
/// the estimate is within the band's 1.10 of the true load (95th
/// percentile; measured p5/p50/p95 1.029/1.052/1.072 and highest 1.098 in
/// f64, 1.074 and 1.100 in f32).
/// Before the force filters started from the mean of their samples so far
/// and the bank's averages followed the first 0.1 s both ways
/// (`moment_limiter::static_load`, "Power-up"), the averages kept the
/// first sample's noise for seconds: 12 of these 192 WARNed from 0.05 s
/// (p95 1.126, highest 1.142), and 7.7 t at 84° (campaign
/// `--wide --seed 6`, #538) read u 0.92 for a true 0.77, an OVERLOAD with
/// 0.13° of angle noise.
fn switched_on_at_a_steep_boom_behind_noisy_pressure_sensors(precision: Precision) {
    let mut failures = Vec::new();
    let mut ratios = Vec::new();
    with_setting(&NOISE_BAR, Some(0.85), || {
        for (from, to) in [(85.0, 78.0), (82.0, 75.0), (78.0, 85.0)] {
            for rope in ROPES {
                for seals in SEALS {
                    for seed in 1..=8 {
                        let sc = Scenario { load_kg: 0.8 * rated_kg(75f64.to_radians()), from_deg: from, to_deg: to, duration_s: 20.0, ramp_s: 2.0, shape: RampShape::Cycloidal, rope, seals, lift_off_s: None, seed };
                        let pts = replay(&sc, precision);
                        ratios.extend(pts.iter().filter(|q| q.t >= 0.1 && q.t < HOLD_BEFORE_S).map(|q| q.ratio));
                        if let Some(q) = pts.iter().filter(|q| q.t < HOLD_BEFORE_S).find(|q| q.state != LimiterState::Normal) {
                            failures.push(format!("{} seed {seed}: {:?} at {:.2} s", sc.name(), q.state, q.t));
                        }
                    }
                }
            }
        }
    });
    let [p5, p50, p95, highest] = [0.05, 0.5, 0.95, 1.0].map(|q| percentile(&mut ratios, q));
    println!("{precision:?}: estimate/true from 0.1 s to the move p5/p50/p95 {p5:.3}/{p50:.3}/{p95:.3}, highest {highest:.3}; {} of 192 WARN or worse", failures.len());
    assert!(failures.is_empty() && p95 <= 1.1, "p95 {p95:.3}: {failures:#?}");
}

#[test]
fn switched_on_at_a_steep_boom_behind_noisy_pressure_sensors_f64() {
    switched_on_at_a_steep_boom_behind_noisy_pressure_sensors(Precision::F64);
}

#[test]
fn switched_on_at_a_steep_boom_behind_noisy_pressure_sensors_f32() {
    switched_on_at_a_steep_boom_behind_noisy_pressure_sensors(Precision::F32);
}

/// The held ropes of the tests: 3 m, the middle, the longest.
const HELD_ROPES: [Rope; 3] = [Rope::Held(0.0), Rope::Held(0.5), Rope::Held(1.0)];

/// The safety bounds where the held load bounces on its rope at `hz`, `zeta`
/// ([`bounce_on_the_rope`]), printed: the 85 % moves of [`no_false_overload`]
/// (the OVERLOADs and the highest estimated u) and the lowerings of
/// [`lowering_past_rated_radius`] (cut before 1/1.1, or a sample at 1.05 or
/// more not cut), held ropes, both friction laws. Returns (failures of the
/// 85 % moves, highest estimated u there, lowering failures, lowest onset u).
fn bounds_against_a_rope_bounce(precision: Precision, hz: f64, zeta: f64) -> (Vec<String>, f64, Vec<String>, f64) {
    let mut out = with_setting(&ROPE_BOUNCE, Some((hz, zeta)), || {
        // The thesis's moves, and the same with the ramps of a hard start
        // and stop (0.5 s, the campaign's shortest), which excite a 1 Hz
        // bounce most (a 1 s linear ramp does not excite 1 Hz at all).
        let hard = thesis_moves().into_iter().map(|(a, b, dur, _, shape)| (a, b, dur, 0.5, shape));
        let moves = thesis_moves().into_iter().chain(hard).collect();
        let (moved, highest) = false_overloads(precision, moves_at_85_percent(moves, &HELD_ROPES, &SEALS));
        let lowering = [(80.0, 20.0, 15.0, 1.0), (80.0, 20.0, 45.0, 1.5), (80.0, 20.0, 15.0, 0.5), (80.0, 20.0, 45.0, 0.5)];
        let (lowered, lowest) = lowerings_on(precision, &lowering, &HELD_ROPES);
        (moved, highest, lowered, lowest)
    });
    let world = |f: &mut Vec<String>| f.iter_mut().for_each(|x| *x = format!("{hz} Hz zeta {zeta}: {x}"));
    world(&mut out.0);
    world(&mut out.2);
    println!("  largest bounce: {:.1} % of the load's pull", 100.0 * BOUNCE_PEAK.with(|p| p.replace(0.0)));
    println!(
        "{precision:?}, a {hz} Hz zeta {zeta} bounce on the rope: 85 % moves {} OVERLOADs of 96, highest estimated u {:.3}; lowerings {} failures of 48, lowest onset u {:.3}",
        out.0.len(),
        out.1,
        out.2.len(),
        out.3
    );
    out
}

/// A held load that bounces on its rope at 1, 1.5 and 2 Hz (ζ 0.02) besides
/// the simulator's bounce on the boom's bending: the 85 % moves are no
/// OVERLOAD and every lowering past the rated radius is cut between true u
/// 1/1.1 and 1.05, with the thesis's ramps and with 0.5 s ramps (a hard
/// start and stop). Measured (f64 and f32 alike): the bounce reaches 85 %,
/// 94 % and 91 % of the load's pull (1, 1.5, 2 Hz), the highest estimated u
/// at 85 % is 0.976, 0.937 and 0.936 (0.979, 0.944, 0.936 before the second
/// stage after a stop, `moment_limiter::static_load::BOUNCE_WINDOW_S`; 0.933
/// without the bounce; 0.972, 0.945, 0.939 at ζ 0.06, measured before it),
/// and the lowerings are cut from true u 0.937 at every frequency (f64).
fn a_bounce_on_the_rope_keeps_the_bounds(precision: Precision) {
    let mut failures = Vec::new();
    for hz in [1.0, 1.5, 2.0] {
        let (f, _, l, _) = bounds_against_a_rope_bounce(precision, hz, 0.02);
        failures.extend(f.into_iter().chain(l));
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

#[test]
fn a_bounce_on_the_rope_keeps_the_bounds_f64() {
    a_bounce_on_the_rope_keeps_the_bounds(Precision::F64);
}

#[test]
fn a_bounce_on_the_rope_keeps_the_bounds_f32() {
    a_bounce_on_the_rope_keeps_the_bounds(Precision::F32);
}

/// Held ropes at ten lengths spread between the bank's (5 %, 15 %, …, 95 %
/// of the way from 3 m to the longest the move's lowest angle allows), not
/// the three of [`ROPES`]: the issue asks for any hanging length from 3 m to
/// the tip height. The 85 % moves of [`no_false_overload`] are no OVERLOAD
/// and the lowerings of [`lowering_past_rated_radius`] are cut between true
/// u 1/1.1 and 1.05, both friction laws; lifted off at 80° in 1 s and 2 s,
/// 90 % is no OVERLOAD and 110 % is cut within 1 s of leaving the ground.
/// Measured: the highest estimated u at 85 % 0.914 (f64 and f32), the
/// lowerings cut at true u 0.952–0.979 (f32 0.952–0.978); the lift-offs cut
/// within 0.84 s (1 s) and 0.60 s (2 s), 90 % read at most u 0.944 (f64).
/// Taken up in 0.5 s at 65° and 80°, 110 % is cut within 0.72 s (f64 and
/// f32; 0.86 s before the mean of a bouncing lift-off's ring was read), 90 %
/// never; through the still force's four filter stages, before
/// a load rising from an empty hook was read through three
/// (`moment_limiter::static_load`, "A lift-off: one stage fewer"), up to
/// 1.02 s after, as on the bank's own lengths.
fn ropes_between_the_banks_lengths(precision: Precision) {
    let ropes: Vec<Rope> = (0..10).map(|k| Rope::Held(0.05 + 0.1 * f64::from(k))).collect();
    no_false_overload(precision, &ropes, &SEALS);
    lowering_past_rated_radius(precision, &ropes, &SEALS);
    let (mut failures, _) = lift_offs_on(precision, &[80.0], &[1.0, 2.0], &ropes);
    failures.extend(lift_offs_on(precision, &[65.0, 80.0], &[0.5], &ropes).0);
    assert!(failures.is_empty(), "{failures:#?}");
}

#[test]
fn ropes_between_the_banks_lengths_keep_the_bounds_f64() {
    ropes_between_the_banks_lengths(Precision::F64);
}

#[test]
fn ropes_between_the_banks_lengths_keep_the_bounds_f32() {
    ropes_between_the_banks_lengths(Precision::F32);
}

/// The paid-out rope with its load kept 3 m or 5 m above the ground instead
/// of the 1 m the limiter's paid-out hypothesis assumes ([`LOAD_CLEARANCE_M`]):
/// the rope is 2–4 m shorter at every angle, so its swing's period is not the
/// hypothesis's. The 85 % moves of [`no_false_overload`] and the lowerings of
/// [`lowering_past_rated_radius`] keep their bounds, and the band of
/// [`band_percentiles`] on this rope stays within 1.00–1.10, both friction
/// laws. The crane is calibrated at that clearance too (its unloaded runs
/// on the shorter rope). Measured (f64): at 3 m highest estimated u 0.902
/// at 85 %, lowerings cut at true u 0.957–0.975, band in motion
/// 1.036/1.048/1.065 and at rest 1.010/1.053/1.070; at 5 m 0.906,
/// 0.947–0.965, 1.037/1.052/1.072 and 1.011/1.055/1.060.
#[test]
fn paid_out_to_another_clearance_keeps_the_bounds() {
    for clearance in [3.0, 5.0] {
        with_setting(&LOAD_CLEARANCE_M, Some(clearance), || {
            no_false_overload(Precision::F64, &[Rope::Thesis], &SEALS);
            lowering_past_rated_radius(Precision::F64, &[Rope::Thesis], &SEALS);
            let (m, r) = band_percentiles_on(Precision::F64, &[Rope::Thesis], &SEALS);
            println!("paid out at {clearance} m above the ground: band in motion {m:.3?}, at rest {r:.3?}");
            assert_band(&format!("paid out at {clearance} m"), m, r, false);
        });
    }
}

/// Pressure transducers behind snubbers (restrictors that protect them from
/// spikes): p1 and p2 read the cylinder's force through a first-order lag of
/// 0.05 s or 0.2 s ([`PRESSURE_LAG_S`]), which the limiter does not know, on
/// the calibration's runs too. The force then lags the angle it is read
/// against. Asserted for both friction laws (f64): the safety bounds of
/// [`other_world`] (no OVERLOAD at 85 %, lowerings cut between true u
/// 1/1.1 and 1.05, lift-off at 50° in 2 s) and the band within 1.00–1.10.
/// Measured: highest estimated u at 85 % 0.932 (0.05 s) and 0.927 (0.2 s);
/// band in motion p5/p50/p95 1.009–1.012/1.037–1.038/1.054–1.063, at rest
/// 1.005–1.014/1.037–1.044/1.056–1.071 (0.02 s and 0.1 s measured alike).
/// What the lag does cost is a lift-off's time (`lift_offs_over` at 20°, 50°
/// and 80°, every rope, both friction laws): behind 0.05 s, 110 % taken up in
/// 2 s, 1 s and 0.5 s is cut up to 0.64 s, 0.74 s and 0.93 s after it leaves
/// the ground; behind 0.2 s up to 0.84 s, 0.99 s and 1.13 s (all 24 in 0.5 s
/// after 1 s). Through the still force's four filter stages throughout,
/// before a load rising from an empty hook was read through three
/// (`moment_limiter::static_load`, "A lift-off: one stage fewer"): 0.65 s,
/// 0.88 s and 1.08 s (6 of 24 after 1 s), and 0.85 s, 1.07 s (14 of 24) and
/// 1.27 s.
#[test]
fn pressure_transducers_behind_snubbers_keep_the_bounds_and_the_band() {
    for tau_s in [0.05, 0.2] {
        with_setting(&PRESSURE_LAG_S, Some(tau_s), || {
            for seals in SEALS {
                let (m, r) = other_world(Precision::F64, &[seals]);
                println!("pressures lagging {tau_s} s, {seals:?}: band in motion {m:.3?}, at rest {r:.3?}");
                assert_band(&format!("pressures lagging {tau_s} s, {seals:?}"), m, r, false);
            }
        });
    }
}

/// The second formulation ([`second_formulation`]) checked before the
/// limiter is: at rest its Lagrange equation gives the independent
/// reference's quasi-static force of a rigid boom (the same weights,
/// another route: within 1e-6), and that differs from the limiter's model
/// by the boom's static sag alone (the reference with the sag is within
/// 0.2 % of the model; the rigid boom reads up to 1.1 % less force at 70°
/// with 8 t, so the limiter reads this world's loads up to about 1.4 %
/// lower than the simulator's); after
/// a held-rope move the load's swing keeps its energy (a pendulum under a
/// still tip: within 1e-6 of it over 20 s), and swings about as far as
/// the simulator's multibody pendulum on its bending boom (measured 2.3–4.9 %
/// less after the stop; asserted within 10 %, against a gross error such as
/// a wrong length or sign).
#[test]
fn the_second_formulation_agrees_with_the_reference_and_the_model() {
    let rigid = rigid_crane();
    let g = 9.81;
    for deg in [10.0f64, 30.0, 50.0, 70.0, 85.0] {
        let th = deg.to_radians();
        for load in [0.0, 3000.0, 8000.0] {
            let rope_m = rigid.tip(th)[1] - model().load_clearance_m;
            let m = load + rigid.rope_kg_per_m() * rope_m;
            let lagrange = rigid.piston_force(th, 0.0, 0.0, [0.0, -m * g]);
            let reference = rigid.reference_static_force(th, load, false);
            let modelled = model()
                .piston_force_n(crane_model::loads::load_model::BoomState { angle_rad: th, rate_rad_s: 0.0 })
                .expect("model")
                .at(load);
            let sagging = rigid.reference_static_force(th, load, true);
            println!(
                "{deg:>4}° {load:>5} kg: Lagrange {lagrange:.1} N, reference {reference:.1} N; model {modelled:.1} N, {:+.3} % from the rigid boom, {:+.3} % from the sagging one",
                100.0 * (lagrange / modelled - 1.0),
                100.0 * (sagging / modelled - 1.0)
            );
            assert!((lagrange / reference - 1.0).abs() < 1e-6, "{deg}° {load} kg: {lagrange} against {reference}");
            assert!((sagging / modelled - 1.0).abs() < 2e-3, "{deg}° {load} kg: the sagging reference's {sagging} against the model's {modelled}");
        }
    }
    for (from, to, length) in [(40.0, 80.0, 3.0), (80.0, 40.0, 8.0), (20.0, 60.0, 5.0)] {
        let (mut samples, stop) = held_luff_and_rest(from, to, length);
        let peak = |s: &[crane_model::sim::simulation::Sample<f64>]| s.iter().map(|x| x.swing_rad.abs()).fold(0.0, f64::max);
        let simulated = peak(&samples[stop + 1..]);
        rigid.replace_forces(&mut samples, Hanging::Held { length_m: length });
        let rigid_swing = peak(&samples[stop + 1..]);
        let (lo, hi) = swing_energy_range(&samples[stop..], length);
        println!("{from}° -> {to}° on {length} m: swing after the stop {:.3}° (simulator {:.3}°), energy {lo:.7}…{hi:.7} J/kg", rigid_swing.to_degrees(), simulated.to_degrees());
        assert!((rigid_swing / simulated - 1.0).abs() < 0.1, "swing {rigid_swing} against the simulator's {simulated}");
        assert!(hi - lo < 1e-6 * hi, "energy {lo}…{hi}");
    }
}

/// The limiter in the second formulation's world ([`SECOND_FORMULATION`]):
/// the piston force of every log, the calibration's runs too, from a rigid
/// mechanism by Lagrange's equation and a pendulum integrated apart from
/// the simulator ([`second_formulation`]). The safety bounds of
/// [`other_world`] (no OVERLOAD at 85 %, every lowering past the rated
/// radius cut between true u 1/1.1 and 1.05, lift-off at 90 % not cut and
/// at 110 % within 1 s) on every rope, both friction laws, and the band
/// within 1.00–1.10. Measured, f64 and f32 alike: highest estimated u at
/// 85 % 0.910 (0.933 on the simulator's logs); lowerings cut at true u
/// 0.959–0.999; 110 % lifted in 2 s cut within 0.59 s; band in motion
/// p5/p50/p95 1.005/1.029/1.047, at rest 1.000/1.030/1.053 (the rigid boom
/// pushes less for the same load than the sagging one the limiter models,
/// by up to 1.1 % at 70°–85° with 8 t, and every case reads 0.4–1.5 %
/// lower than on the simulator's logs; its lowest at rest, a 3 m rope after
/// a 30 s raise to 80° with 30 % of rated, 0.994).
fn the_second_formulation(precision: Precision) {
    with_setting(&SECOND_FORMULATION, true, || {
        let (m, r) = other_world(precision, &SEALS);
        println!("{precision:?}, the second formulation: band in motion {m:.3?}, at rest {r:.3?}");
        assert_band("the second formulation", m, r, false);
    });
}

/// [`the_second_formulation`], and (f64) over the other ranges of
/// `no_false_overload_at_85_percent_over_other_ranges`,
/// `lowering_past_the_rated_radius_over_other_ranges` and
/// `a_faster_lowering_past_the_rated_radius`, and the lift-offs of
/// `lift_off_at_other_angles`. Measured: no OVERLOAD at 85 %, the highest
/// estimated u 0.920 but on the 3 m rope raised 30° → 85° while its swing
/// takes p1 past its range (1.33–1.40 in that FAULT, which cuts, as on the
/// simulator's logs); lowerings cut at true u 0.939–1.010; 110 % taken up in
/// 1 s or 2 s cut within 0.61 s of leaving the ground. Taken up in 0.5 s
/// and snatched in 0.3 s, 110 % is cut within 0.64 s and 0.71 s here, 90 %
/// never (0.87 s and 0.98 s on the simulator's logs, whose bounce on the
/// boom's bending costs them; `lift_off_in_half_a_second_is_cut_within_1_s_*`,
/// `lift_off_snatched_in_0_3_s_is_cut_within_1_s_*`). Read through the
/// stage against the bounce whatever the force did, before a lift-off was
/// read at once until it bounces (`moment_limiter::static_load`), they were
/// cut within 0.82 s, 0.82 s and 0.90 s; through the still force's four
/// filter stages, before a load rising from an empty hook was read through
/// three (`moment_limiter::static_load`, "A lift-off: one stage fewer"), up
/// to 0.98 s and 1.06 s after here: the filters' step response alone was
/// over the second for a snatch.
#[test]
fn the_second_formulation_keeps_the_bounds_and_the_band_f64() {
    the_second_formulation(Precision::F64);
    with_setting(&SECOND_FORMULATION, true, || {
        let (mut failures, worst) = no_false_overload_over(Precision::F64, &[(20.0, 60.0), (10.0, 50.0), (5.0, 30.0), (30.0, 85.0)]);
        let (lowering, lowest) = lowerings_on(
            Precision::F64,
            &[(60.0, 5.0, 15.0, 1.0), (50.0, 10.0, 30.0, 1.5), (85.0, 30.0, 15.0, 1.0), (75.0, 35.0, 40.0, 1.5), (80.0, 20.0, 10.0, 1.0), (70.0, 20.0, 10.0, 1.0)],
            &ROPES,
        );
        let (lift, slowest) = lift_offs_over(Precision::F64, &[10.0, 20.0, 35.0, 65.0, 80.0], &[1.0, 2.0]);
        println!("the second formulation, other ranges: highest estimated u at 85 % {worst:.3}; lowerings cut from true u {lowest:.3}; lift-offs cut within {slowest:.2} s");
        failures.extend(lowering);
        failures.extend(lift);
        // Without the simulator's bounce on the boom's bending, what the
        // filters alone cost a fast take-up.
        let (half, slowest_half) = lift_offs_over(Precision::F64, &[20.0, 50.0, 65.0, 80.0], &[0.5]);
        let (snatched, slowest_snatched) = lift_offs_over(Precision::F64, &[20.0, 50.0, 65.0, 80.0], &[0.3]);
        println!("the second formulation: 110 % taken up in 0.5 s cut within {slowest_half:.2} s, in 0.3 s within {slowest_snatched:.2} s");
        failures.extend(half);
        failures.extend(snatched);
        assert!(failures.is_empty(), "{failures:#?}");
    });
}

#[test]
fn the_second_formulation_keeps_the_bounds_and_the_band_f32() {
    the_second_formulation(Precision::F32);
}

/// A load that comes on the hook at once, in the second formulation's world
/// (a rigid mechanism: no boom bending, no rope stretch, so no bounce):
/// 110 % of rated taken up in 0.02 s or 0.1 s at 10°–80°, every rope, both
/// friction laws, is cut (OVERLOAD, or FAULT where p1 passes its range at
/// 10°) within 1 s of leaving the ground, and 90 % is never an OVERLOAD.
/// Measured, f64 and f32: cut at most 0.84 s after; 90 % reads at most u
/// 0.945. Read through the stage against the bounce whatever the force did
/// (before `moment_limiter::static_load`'s "A lift-off: read at once until
/// it bounces"), every one of them was cut 1.01–1.02 s after: three filter
/// stages and that stage cross 0.866 of a step 0.97 s after it, the
/// debounce adds 0.05 s.
fn a_load_on_the_hook_at_once_is_cut_within_1_s_where_nothing_bounces(precision: Precision) {
    let (worst, false_cut, peak90, uncut) = with_setting(&SECOND_FORMULATION, true, || snatched_in(precision, &[0.02, 0.1]));
    assert!(uncut.is_empty(), "110 % never cut: {uncut:#?}");
    assert!(worst <= 1.0, "110 % cut {worst:.2} s after it leaves the ground");
    assert!(false_cut.is_empty() && peak90 < 1.0, "90 % cut: {false_cut:#?}, highest u {peak90:.4}");
}

#[test]
fn a_load_on_the_hook_at_once_is_cut_within_1_s_where_nothing_bounces_f64() {
    a_load_on_the_hook_at_once_is_cut_within_1_s_where_nothing_bounces(Precision::F64);
}

#[test]
fn a_load_on_the_hook_at_once_is_cut_within_1_s_where_nothing_bounces_f32() {
    a_load_on_the_hook_at_once_is_cut_within_1_s_where_nothing_bounces(Precision::F32);
}

/// `crane-sim campaign`'s distribution (seed 1; f32 as the CLI runs it,
/// each crane calibrated from its own unloaded runs) with every log's piston
/// force, the calibration runs' too, from the second formulation
/// ([`second_formulation`]): prints the summary's figures, all and per rope
/// mode and friction law, and asserts issue 11's campaign bounds: no missed and no
/// early OVERLOAD, false ones ≤ 0.2 % of the scenarios whose true u stays
/// ≤ 0.85.
fn campaign_in_the_second_formulation(scenarios: usize) {
    let args = host_sim::cmd::campaign::CampaignArgs { scenarios, seed: 1, shard: None, only: Vec::new(), json: true, cranes: 16, step_ms: 2.0, wide: false };
    let world = |s: &mut [crane_model::sim::simulation::Sample<f64>], rope: RopeChoice| second_formulation_of(s, rope);
    let summary = host_sim::cmd::campaign::summary_in_world(&args, &world).expect("campaign");
    let grades = |t: &serde_json::Value| {
        let keys = ["scenarios", "missed_overloads", "early_overloads", "false_overloads", "false_overloads_u_max_le_0_85", "scenarios_u_max_le_0_85", "late_overloads", "band_motion_p5_p50_p95", "band_rest_p5_p50_p95", "detection_delay_s_p5_p50_p95", "detection_delay_s_max", "lift_off_delay_s_p5_p50_p95", "lift_off_delay_s_max"];
        keys.map(|k| format!("{k} {}", t[k])).join(", ")
    };
    println!("all: {}, failed_simulations {}, faults {}, worst {}", grades(&summary), summary["failed_simulations"], summary["faults"], summary["worst"]);
    for g in summary["groups"].as_array().into_iter().flatten() {
        println!("rope {}, friction {}: {}", g["rope"], g["friction"], grades(g));
    }
    let n = |k: &str| summary[k].as_u64().unwrap_or_else(|| panic!("{k} in the summary"));
    let (missed, early, false_, calm) = (n("missed_overloads"), n("early_overloads"), n("false_overloads_u_max_le_0_85"), n("scenarios_u_max_le_0_85"));
    assert!(missed == 0 && early == 0 && false_ as f64 <= 0.002 * calm as f64, "missed {missed}, early {early}, false {false_} of {calm}");
}

/// 1 000 scenarios of [`campaign_in_the_second_formulation`] (19 s).
#[test]
fn a_campaign_in_the_second_formulation() {
    campaign_in_the_second_formulation(1000);
}

/// The same over 10 000 scenarios (measured for the docs; about 3 minutes).
#[test]
#[ignore = "10 000 scenarios: run by hand"]
fn a_full_campaign_in_the_second_formulation() {
    campaign_in_the_second_formulation(10_000);
}





/// The winch's hoists with the boom still (`Segment::Hoist`, a world no luff
/// shows): at 20°, 50° and 80° on held ropes of 3 m, half-way and all the way
/// to the tip, the load lifted off in 2 s, then hoisted by 40 % of its
/// hanging length (the 3 m rope: let down 3 m first) and back, at each
/// (hook speed m/s, linear ramp s) of `hoists`. Returns the OVERLOADs at 85 %
/// and at 90 % of rated, the highest estimated u at 85 %, and the
/// estimate/true of 30 % and 80 % loads in the hoists' constant-speed parts
/// from 1 s after their ramps, and at rest from 1 s after their stops (as the
/// luffs' band).
fn hoists_at_rest(precision: Precision, hoists: &[(f64, f64)]) -> Hoists {
    let mut h = Hoists { cut85: Vec::new(), peak85: 0.0, motion: Vec::new(), rest: Vec::new(), cut90: Vec::new() };
    for angle in [20.0f64, 50.0, 80.0] {
        let rated = rated_kg(angle.to_radians());
        for rope in [Rope::Held(0.0), Rope::Held(0.5), Rope::Held(1.0)] {
            let choice = rope_choice(rope, angle);
            let RopeChoice::Held { length_m: Some(length) } = choice else { unreachable!("a held rope") };
            let first = if length < 5.0 { -3.0 } else { 0.4 * length };
            for &(speed, ramp) in hoists {
                let duration = first.abs() / speed + ramp;
                for frac in [0.3, 0.8, 0.85, 0.9] {
                    let mut p = Program::new(angle, 0.0, choice).unwrap();
                    p.push(Segment::Hold { duration_s: HOLD_BEFORE_S }).unwrap();
                    p.push(Segment::LiftOff { duration_s: 2.0, load_kg: frac * rated }).unwrap();
                    p.push(Segment::Hold { duration_s: 4.0 }).unwrap();
                    let mut starts = Vec::new();
                    let mut t = HOLD_BEFORE_S + 6.0;
                    for by_m in [first, -first] {
                        p.push(Segment::Hoist { by_m, duration_s: duration, ramp_s: ramp, shape: RampShape::Linear }).unwrap();
                        p.push(Segment::Hold { duration_s: 5.0 }).unwrap();
                        starts.push(t);
                        t += duration + 5.0;
                    }
                    let pts = replay_rows(&program_rows(&p, Seals::Constant, 4), Seals::Constant, precision);
                    let name = format!("{angle}° {rope:?} ({length:.1} m) {frac} of rated, hoisted {first:+.1} m and back at {speed} m/s, ramps {ramp} s");
                    if frac > 0.84 {
                        let high = pts.iter().filter(|q| q.u > 0.0).map(|q| q.ratio * q.u).fold(0.0, f64::max);
                        println!("{precision:?} {name}: highest estimated u {high:.3}");
                        let overload = first_overload(&pts).map(|(t, u)| format!("{name}: OVERLOAD at {t:.2} s, true u {u:.3}"));
                        if frac < 0.86 {
                            h.peak85 = h.peak85.max(high);
                            h.cut85.extend(overload);
                        } else {
                            h.cut90.extend(overload);
                        }
                        continue;
                    }
                    let (mut m, mut r) = (Vec::new(), Vec::new());
                    for &start in &starts {
                        let end = start + duration;
                        m.extend(pts.iter().filter(|q| q.t >= start + ramp + 1.0 && q.t <= end - ramp).map(|q| q.ratio));
                        r.extend(pts.iter().filter(|q| q.t >= end + 1.0 && q.t < end + 5.0).map(|q| q.ratio));
                    }
                    let span = |v: &[f64]| (percentile(&mut v.to_vec(), 0.05), percentile(&mut v.to_vec(), 0.95));
                    let ((m5, m95), (r5, r95)) = (span(&m), span(&r));
                    println!("{precision:?} {name}: hoisting {m5:.3}…{m95:.3}, at rest {r5:.3}…{r95:.3}");
                    h.motion.extend(m);
                    h.rest.extend(r);
                }
            }
        }
    }
    let (m, r) = h.bands();
    println!(
        "{precision:?} hoists {hoists:?}: 85 % read at most u {:.3}, cut in {}; 90 % cut in {} of {}; band hoisting {m:.3?}, at rest after {r:.3?}",
        h.peak85,
        h.cut85.len(),
        h.cut90.len(),
        9 * hoists.len(),
    );
    h
}

/// What [`hoists_at_rest`] measures.
struct Hoists {
    /// The OVERLOADs at 85 % of rated.
    cut85: Vec<String>,
    /// The highest estimated u at 85 %.
    peak85: f64,
    /// Estimate/true of 30 % and 80 % while hoisting and at rest after.
    motion: Vec<f64>,
    rest: Vec<f64>,
    /// The OVERLOADs at 90 % of rated.
    cut90: Vec<String>,
}

impl Hoists {
    /// The band's (p5, p50, p95) while hoisting and at rest after.
    fn bands(&self) -> ([f64; 3], [f64; 3]) {
        let band = |v: &[f64]| [0.05, 0.5, 0.95].map(|q| percentile(&mut v.to_vec(), q));
        (band(&self.motion), band(&self.rest))
    }
}

/// Hoists with ramps of 1 s (0.2–0.5 m/s², a winch started and stopped
/// smoothly): at 0.2 m/s and 0.5 m/s.
const SMOOTH_HOISTS: [(f64, f64); 2] = [(0.2, 1.0), (0.5, 1.0)];

/// A hard start and stop: 0.5 m/s in 0.25 s (2 m/s², the rope pulling a
/// fifth more for a quarter of a second, and the load ringing on the boom
/// after it).
const HARD_HOISTS: [(f64, f64); 1] = [(0.5, 0.25)];

/// Hoisting is no load ([`hoists_at_rest`]): started and stopped smoothly,
/// no OVERLOAD at 85 % or 90 % of rated and the estimate within 1.00–1.10
/// of the true load (p5–p95) while hoisting at constant speed and 1 s after a
/// hoist stops; measured: 85 % reads at most u 0.935, the band
/// 1.032/1.045/1.067 hoisting and 1.032/1.047/1.087 at rest after (f32
/// 1.035/1.046/1.069 and 1.035/1.048/1.088). A
/// hard start and stop ([`HARD_HOISTS`]) keeps the requirement at 85 %
/// (read at most u 0.985), but not the band or 90 %: see
/// [`hard_hoist_starts_and_stops_known_gap`].
fn hoisting_is_no_load(precision: Precision) {
    let smooth = hoists_at_rest(precision, &SMOOTH_HOISTS);
    let (m, r) = smooth.bands();
    assert!(smooth.cut85.is_empty() && smooth.cut90.is_empty(), "{:#?} {:#?}", smooth.cut85, smooth.cut90);
    assert!(in_band(m) && in_band(r), "hoisting {m:?}, at rest after {r:?}");
    let hard = hoists_at_rest(precision, &HARD_HOISTS);
    assert!(hard.cut85.is_empty(), "{:#?}", hard.cut85);
}

#[test]
fn hoisting_is_no_load_f64() {
    hoisting_is_no_load(Precision::F64);
}

#[test]
fn hoisting_is_no_load_f32() {
    hoisting_is_no_load(Precision::F32);
}

/// KNOWN GAP, measured (f64; f32 alike): a winch started and stopped hard
/// ([`HARD_HOISTS`], 0.5 m/s in 0.25 s) reads as load. The rope pulls
/// W·(g + 2 m/s²) for a quarter of a second, the load rings on the boom at
/// 1–2 Hz after it, and W_fast passes the crest (one 0.7 Hz stage, against
/// the load's bounce) at up to 1.08 × the load; at rest the bank's averages
/// are raised to W_fast at once (what keeps a lift-off in them), so they
/// take that crest and hold it for seconds. 90 % of rated is cut at true u
/// 0.900 in 6 of 9 cases (20° and 50°; not 80°), the band is
/// 1.029/1.053/1.112 hoisting and 1.031/1.065/1.118 at rest 1–5 s after a
/// stop (single cases up to 1.135), and 85 % reads up to u 0.985 (f32
/// alike). Tried and not kept: raising the averages at rest to W_fast's
/// lower envelope over the last 0.5–1 s (the band at rest after the smooth
/// and hard hoists together, p95 1.104, became 1.075) or its midrange
/// (1.089) instead; both took away the
/// upward bias the crests give every rest, and the band 1–3 s after a stop
/// fell under p5 1.00 in the worlds calibrated at two speeds (0.998–1.000
/// from 1.002–1.006).
#[test]
#[ignore = "KNOWN GAP: a winch started and stopped hard (0.5 m/s in 0.25 s) reads as load: 90 % cut in 6 of 9 cases, band p95 1.112 hoisting, 1.118 at rest after"]
fn hard_hoist_starts_and_stops_known_gap() {
    let hard = hoists_at_rest(Precision::F64, &HARD_HOISTS);
    let (m, r) = hard.bands();
    assert!(hard.cut90.is_empty() && in_band(m) && in_band(r), "90 % cut: {:#?}; hoisting {m:?}, at rest after {r:?}", hard.cut90);
}

/// The known gap above pinned at its measured size: 90 % cut in no more than
/// 6 of the 9 hard hoists, 85 % read at most u 0.99 (0.985 measured), and
/// the band's p95 at most 1.12 (measured 1.112 hoisting, 1.118 at rest
/// after), its p5 at least 1.00.
#[test]
fn hard_hoist_starts_and_stops_stay_as_measured() {
    let hard = hoists_at_rest(Precision::F64, &HARD_HOISTS);
    let (m, r) = hard.bands();
    assert!(hard.cut90.len() <= 6 && hard.peak85 <= 0.99, "90 % cut in {}; 85 % read u {:.3}", hard.cut90.len(), hard.peak85);
    assert!(m[0] >= 1.0 && r[0] >= 1.0 && m[2] <= 1.12 && r[2] <= 1.12, "hoisting {m:?}, at rest after {r:?}");
}


/// The simulator's samples of 4 t luffed `from` → `to` degrees in 10 s
/// (linear ramps of 1 s) on a rope held at `length_m`, and 20 s at rest;
/// with the index of the move's last sample.
fn held_luff_and_rest(from: f64, to: f64, length_m: f64) -> (Vec<crane_model::sim::simulation::Sample<f64>>, usize) {
    let mut m = Maneuver::luff(4000.0, from, to, 10.0, 1.0, RampShape::Linear).unwrap();
    m.settle_s = 20.0;
    m.rope = RopeChoice::Held { length_m: Some(length_m) };
    let (options, _) = options_for_rate(RATE_HZ);
    let samples = simulate(model(), &m, &options).expect("simulation");
    let stop = samples.iter().rposition(|s| (s.boom_angle_rad - to.to_radians()).abs() > 1e-9).expect("a move");
    (samples, stop)
}

/// The lowest and highest energy per kg, ½·l²·φ̇² + g·l·(1 − cos φ), of a
/// pendulum of `length_m` swinging as `after_stop` shows (its first sample
/// the move's last). From the third sample on (the last moving one's
/// angular acceleration reaches into the step after it), the swing's rate
/// by the five-point stencil (error (ωh)⁴/30 ≈ 4e-9 at 3 m).
fn swing_energy_range(after_stop: &[crane_model::sim::simulation::Sample<f64>], length_m: f64) -> (f64, f64) {
    let g = 9.81;
    after_stop
        .get(3..)
        .unwrap_or_default()
        .windows(5)
        .map(|w| {
            let v = (w[0].swing_rad - 8.0 * w[1].swing_rad + 8.0 * w[3].swing_rad - w[4].swing_rad) / (3.0 * (w[4].t_s - w[0].t_s));
            0.5 * length_m * length_m * v * v + g * length_m * (1.0 - w[2].swing_rad.cos())
        })
        .fold((f64::INFINITY, 0.0f64), |(lo, hi), e| (lo.min(e), hi.max(e)))
}

/// The winched rope of the second formulation ([`Hanging::Winched`]) is the
/// pendulum it should be: after the move the winch has stopped at the
/// length it was sent to (the swing's energy ½·l²·φ̇² + g·l·(1 − cos φ) per
/// kg is constant to 1e-6 with that l, and drifts by far more with the
/// length it started at), and the swing's period is 2π·√(l/g)·(1 + φ₀²/16)
/// within 0.5 % (φ₀ its amplitude: hoisting a swinging load pumps its
/// swing, 6 m → 2 m during a raise to 80° leaves 26°, whose period is
/// 1.3 % over the small swing's).
#[test]
fn the_winched_rope_ends_at_its_new_length() {
    let rigid = rigid_crane();
    let g = 9.81;
    for (from, to, length, by) in [(40.0, 80.0, 6.0, 4.0), (80.0, 40.0, 3.0, -3.0), (20.0, 60.0, 8.0, 2.5)] {
        let (mut samples, stop) = held_luff_and_rest(from, to, length);
        rigid.replace_forces(&mut samples, Hanging::Winched { length_m: length, by_m: by });
        let end = length - by;
        let ((lo, hi), (lo0, hi0)) = (swing_energy_range(&samples[stop..], end), swing_energy_range(&samples[stop..], length));
        // Upward zero crossings of the swing after the stop: whole periods.
        let ups: Vec<f64> = samples[stop + 1..].windows(2).filter(|w| w[0].swing_rad < 0.0 && w[1].swing_rad >= 0.0).map(|w| w[0].t_s - w[0].swing_rad * (w[1].t_s - w[0].t_s) / (w[1].swing_rad - w[0].swing_rad)).collect();
        let period = (ups[ups.len() - 1] - ups[0]) / (ups.len() - 1) as f64;
        let peak = samples[stop + 1..].iter().map(|x| x.swing_rad.abs()).fold(0.0, f64::max);
        let expected = 2.0 * std::f64::consts::PI * (end / g).sqrt() * (1.0 + peak * peak / 16.0);
        println!(
            "{from}° -> {to}°, {length} m winched by {by:+} m: period {period:.3} s (2π√(l/g)(1 + φ₀²/16) {expected:.3} s), swing {:.2}°, energy spread {:.1e} at {end} m, {:.1e} at {length} m",
            peak.to_degrees(),
            (hi - lo) / hi,
            (hi0 - lo0) / hi0
        );
        assert!(hi - lo < 1e-6 * hi, "energy at the new length {lo}…{hi}");
        assert!(hi0 - lo0 > 1e-3 * hi0, "energy at the old length {lo0}…{hi0}: the winch did not move");
        assert!((period / expected - 1.0).abs() < 0.005, "period {period} s against {expected} s");
    }
}

/// 85 % of the load rated at 40°, luffed 40° ↔ 80° in 10 s and 30 s
/// (cycloidal) on the held ropes of [`ROPES`], both friction laws, and
/// 20 s at rest after the stop (the tests above rest 3 s): whatever the
/// world's rope does in the move. Returns the cases with an OVERLOAD, the
/// highest estimated u outside FAULT, and the lowest and highest
/// estimate/true from 1 s after the stop.
fn long_rests_at_85_percent(precision: Precision) -> (Vec<String>, f64, f64, f64) {
    let (mut failures, mut peak, mut lo, mut hi) = (Vec::new(), 0.0f64, f64::INFINITY, 0.0f64);
    let w = 0.85 * rated_kg(40f64.to_radians());
    for (a, b) in [(40.0, 80.0), (80.0, 40.0)] {
        for dur in [10.0, 30.0] {
            for rope in [Rope::Held(0.0), Rope::Held(0.5), Rope::Held(1.0)] {
                for seals in SEALS {
                    let mut p = Program::new(a, w, rope_choice(rope, 40.0)).unwrap();
                    p.push(Segment::Hold { duration_s: HOLD_BEFORE_S }).unwrap();
                    p.push(Segment::Luff { to_deg: b, shape: RampShape::Cycloidal, t1_s: 1.0, t2_s: dur - 1.0, t3_s: dur }).unwrap();
                    p.push(Segment::Hold { duration_s: 20.0 }).unwrap();
                    let pts = replay_rows(&program_rows(&p, seals, 7), seals, precision);
                    let name = format!("{a:.0}->{b:.0} {dur:.0}s {rope:?} {seals:?}, 20 s at rest");
                    let case_peak = pts.iter().filter(|q| q.state != LimiterState::Fault).map(|q| q.ratio * q.u).fold(0.0, f64::max);
                    let rest: Vec<f64> = pts.iter().filter(|q| q.t >= HOLD_BEFORE_S + dur + 1.0).map(|q| q.ratio).collect();
                    let (r_lo, r_hi) = rest.iter().fold((f64::INFINITY, 0.0f64), |(l, h), &r| (l.min(r), h.max(r)));
                    println!("{name:<52} highest estimated u {case_peak:.3}, at rest estimate/true {r_lo:.3}…{r_hi:.3}");
                    if let Some((t, u)) = first_overload(&pts) {
                        failures.push(format!("{name}: OVERLOAD at {t:.2} s, true u {u:.3}"));
                    }
                    (peak, lo, hi) = (peak.max(case_peak), lo.min(r_lo), hi.max(r_hi));
                }
            }
        }
    }
    (failures, peak, lo, hi)
}

/// Luffing while hoisting, a world neither of the rope bank's modes is
/// (the hook neither keeps its height nor rides with the tip, and the
/// swing's period changes under the move): in the second formulation's
/// world the winch takes every held rope's hook up or down by `by_m` over
/// each luff ([`WINCH_M`], [`Hanging::Winched`]; 2 m over a 10 s luff is
/// 0.2–0.25 m/s at the hook, 4 m 0.4–0.5 m/s). Asserted: the bounds of
/// [`other_world`] but the lift-off (a lift-off has no luff, so no winch):
/// no OVERLOAD at 85 %, every lowering past the rated radius cut between
/// true u 1/1.1 and 1.05, the band within 1.00–1.10 ([`assert_band`], its
/// rest p5 allowed under 1 % short where `rest_p5_may_miss`, measured in
/// the caller's doc); and no OVERLOAD at 85 % over 20 s at rest after the
/// move ([`long_rests_at_85_percent`]).
fn luffing_while_hoisting(precision: Precision, by_m: f64, rest_p5_may_miss: bool) {
    with_setting(&SECOND_FORMULATION, true, || {
        with_setting(&WINCH_M, Some(by_m), || {
            no_false_overload(precision, &ROPES, &SEALS);
            lowering_past_rated_radius(precision, &ROPES, &SEALS);
            let (m, r) = band_percentiles(precision, &SEALS);
            let (failures, peak, lo, hi) = long_rests_at_85_percent(precision);
            println!("{precision:?}, winch {by_m:+} m: band in motion {m:.3?}, at rest {r:.3?}; 20 s rests at 85 %: highest estimated u {peak:.3}, estimate/true {lo:.3}…{hi:.3}");
            assert_band(&format!("the winch {by_m:+} m"), m, r, rest_p5_may_miss);
            assert!(failures.is_empty(), "{failures:#?}");
        })
    });
}

/// Measured (f64): 4 m up (down where the rope would get shorter than
/// 2 m) and 4 m down (up where the load would come within 0.5 m of the
/// ground): highest estimated u at 85 % 0.927 (0.910 held); every lowering
/// cut; band in motion p5/p50/p95 1.004/1.029/1.053 and 1.004/1.029/1.050,
/// at rest 1.004/1.029/1.066 and 1.004/1.026/1.063 (held 1.005/1.029/1.047
/// and 1.000/1.030/1.053); after 20 s at rest, highest estimated u 0.927
/// (the 3 m rope, lowering 80° → 40° in 10 s), the estimate 1.004–1.234 ×
/// the load (high after a raise to 80° on the longest rope, toward
/// cutting).
#[test]
fn luffing_while_hoisting_keeps_the_bounds_f64() {
    for by_m in [4.0, -4.0] {
        luffing_while_hoisting(Precision::F64, by_m, false);
    }
}

/// The same in the controller's f32, 2 m up and down. Measured: highest
/// estimated u at 85 % 0.922 (f64 alike), 0.922 over 20 s rests (the
/// estimate 1.001–1.146 × the load there); band in motion 1.005/1.029/1.049,
/// at rest p5 0.9985 (f64 0.999 up, 1.000 down): the rest band's low side
/// misses by 0.15 %. The cases that read low are the 30 % load raised to
/// 80° in 30 s on the 3 m and half-way ropes, 0.997–0.999 × the load at
/// rest: the second formulation's rigid boom pushes less at 80° than the
/// sagging one the limiter models (its held world's lowest at rest is that
/// raise on the 3 m rope, 0.994, and its rest p5 1.000), and the winch
/// moves them by 0.1–0.2 %.
#[test]
fn luffing_while_hoisting_keeps_the_bounds_f32() {
    for by_m in [2.0, -2.0] {
        luffing_while_hoisting(Precision::F32, by_m, true);
    }
}

/// What [`load_added_in_motion`] measured.
#[derive(Debug, Default)]
struct InMotion {
    /// The slowest first cut (OVERLOAD or FAULT) of 110 % after its take-up
    /// ends (s), and how many of them came more than 1 s after.
    slowest_110_s: f64,
    late_110: usize,
    /// The cases where 90 % added in a raise was an OVERLOAD.
    cut_90: Vec<String>,
    /// Of the lowerings with 90 % added: the highest true u of a sample
    /// neither OVERLOAD nor FAULT at a true u ≥ 1.05 (0: none), and the
    /// lowest true u at an OVERLOAD's onset.
    highest_uncut_u: f64,
    lowest_onset_u: f64,
}

impl InMotion {
    /// The known gap at its pinned size (`a_load_added_in_motion_*`): 110 %
    /// cut within 3.5 s of its take-up, no lowering uncut over true u 1.15,
    /// none cut before 1/1.1, 90 % added in a raise never an OVERLOAD.
    fn within_the_pinned_gap(&self) -> bool {
        self.slowest_110_s <= 3.5 && self.highest_uncut_u <= 1.15 && self.cut_90.is_empty() && self.lowest_onset_u >= 1.0 / 1.1
    }
}

/// A load added in motion (a second load hooked on, or a hook caught,
/// while the boom luffs): in the second formulation's world, whose hook
/// load may change at any instant (the load keeps its swing), 50 % of the
/// load rated at the lower angle is taken to 90 % or 110 % of the load
/// rated where its take-up ends, over 0.5 s or 2 s from the middle of a
/// cycloidal luff (40° ↔ 80° in 10 s and 30 s, 20° → 60° and 60° → 20° in
/// 30 s), every rope, both friction laws. Measured: the first cut of 110 %
/// after its take-up; 90 % in a raise (the true u falls after it) never an
/// OVERLOAD; in a lowering the true u climbs on past 1, and the lowering's
/// bounds apply.
fn load_added_in_motion(precision: Precision) -> InMotion {
    load_added_in_motion_ringing(precision, None)
}

/// [`load_added_in_motion`], with the held load on a rope that rings
/// (`ring`: natural frequency in Hz and damping ratio) at the luff's starts
/// and stops ([`bounce_on_the_rope`]) and as the load is taken up
/// ([`ring_the_take_up`]); the paid-out rope as before.
fn load_added_in_motion_ringing(precision: Precision, ring: Option<(f64, f64)>) -> InMotion {
    let mut got = InMotion { lowest_onset_u: f64::INFINITY, ..InMotion::default() };
    for (from, to, dur) in [(40.0f64, 80.0f64, 10.0), (40.0, 80.0, 30.0), (80.0, 40.0, 10.0), (80.0, 40.0, 30.0), (20.0, 60.0, 30.0), (60.0, 20.0, 30.0)] {
        for rope in ROPES {
            for seals in SEALS {
                for take_up in [0.5, 2.0] {
                    for frac in [0.9, 1.1] {
                        let w0 = 0.5 * rated_kg(from.min(to).to_radians());
                        let sc = Scenario { load_kg: w0, from_deg: from, to_deg: to, duration_s: dur, ramp_s: 1.0, shape: RampShape::Cycloidal, rope, seals, lift_off_s: None, seed: 5 };
                        let (options, dt) = options_for_rate(rate_hz());
                        let program = sc.program();
                        let mut samples = simulate_program(crane(), &program, &options).expect("simulation");
                        let on = HOLD_BEFORE_S + dur / 2.0;
                        let done = on + take_up;
                        let angle = samples.iter().find(|s| s.t_s >= done).map_or(to.to_radians(), |s| s.boom_angle_rad);
                        let w1 = frac * rated_kg(angle);
                        for s in samples.iter_mut() {
                            s.hook_load_kg = w0 + (w1 - w0) * ((s.t_s - on) / take_up).clamp(0.0, 1.0);
                        }
                        second_formulation_of(&mut samples, program.rope);
                        if let (Some(bounce), RopeChoice::Held { .. }) = (ring, program.rope) {
                            bounce_on_the_rope(&mut samples, bounce);
                            ring_the_take_up(&mut samples, bounce);
                        }
                        lag_the_pressures(&mut samples);
                        let rows = synthesize(&samples, dt, 0.0, 0.0, &sensors(seals, 5));
                        let pts = with_setting(&SECOND_FORMULATION, true, || replay_rows(&rows, seals, precision));
                        let name = format!("{from:.0}->{to:.0} {dur:.0}s {rope:?} {seals:?}: {:.0} % taken up in {take_up} s", frac * 100.0);
                        let first_cut = pts.iter().find(|q| q.t >= on && cut(q)).map(|q| q.t - done);
                        let lowering = to < from;
                        println!(
                            "{name:<58} first cut {}, lowest OVERLOAD onset {}, highest true u uncut {}",
                            first_cut.map_or("none".into(), |c| format!("{c:+.2} s after the take-up")),
                            lowest_onset_u(&pts).map_or("none".into(), |u| format!("at true u {u:.3}")),
                            uncut(&pts).map(|q| q.u).reduce(f64::max).map_or("none".into(), |u| format!("{u:.3}"))
                        );
                        if frac > 1.0 {
                            let c = first_cut.unwrap_or(f64::INFINITY);
                            got.slowest_110_s = got.slowest_110_s.max(c);
                            got.late_110 += usize::from(c > 1.0);
                        } else if lowering {
                            got.highest_uncut_u = uncut(&pts).map(|q| q.u).fold(got.highest_uncut_u, f64::max);
                            got.lowest_onset_u = lowest_onset_u(&pts).map_or(got.lowest_onset_u, |u| got.lowest_onset_u.min(u));
                        } else if let Some((t, u)) = first_overload(&pts) {
                            got.cut_90.push(format!("{name}: OVERLOAD at {t:.2} s, true u {u:.3}"));
                        }
                    }
                }
            }
        }
    }
    println!("{precision:?}: {got:?}");
    got
}

/// KNOWN GAP, measured (f64; f32 alike, below). A load added in motion
/// is read through the lowest rope's reading, W_fast, and through the
/// follower of a rise (`moment_limiter::load_rise`): in a steady luff, a
/// rise every rope sees and the consistent ropes confirm for 0.4 s
/// multiplies the averages by the consistent ropes' lowest rise. Still
/// late:
/// - 110 % is cut within 1 s of its take-up in 61 of 96 cases (f32: 63),
///   half of them within 0.84 s; the slowest are the 10 s raises 40° → 80°,
///   where the consistent ropes that vote include a wrong one whose swing
///   reads low as the boom steepens (3.35 s on the tip-height rope taken up
///   in 2 s, 2.34 s on the half-way rope in 0.5 s), and a take-up of
///   0.5 s, which the force filter's and the fast stages' delay (about 1 s
///   to 95 %) cut 1.0–1.2 s after;
/// - 90 % added in a 10 s lowering 80° → 40° over 0.5 s, whose true u
///   climbs 0.2 a second after the take-up, is cut at true u 1.09–1.11
///   (f32: up to 1.136): in 11 of the 48 lowerings with 90 % added a sample
///   past true u 1.05 is uncut.
///
/// 90 % added in a raise is never an OVERLOAD, and no lowering is cut before
/// true u 0.962. Before the follower: 110 % within 1 s in 43 of 96, the 10 s
/// raises to 80° cut only once the move stopped (2.3–5.8 s after), and 24 of
/// the 48 lowerings uncut past 1.05, up to true u 1.268 (the 10 s lowering
/// on the half-way rope, taken up in 2 s; now cut at 1.042).
///
/// Tried and not kept: the rescale of a load added at rest
/// (`moment_limiter::load_jump`, a ratio to the averages) run in motion.
/// With every rope that weighs voting it raised a light load's reading to
/// 1.395 × itself in a 9 s lowering from 82° on a 3.3 m rope (campaign seed
/// 1 #8831); with the consistent ropes voting it cut 110 % within 1.31 s,
/// but rescaled where the averages held a kept or old weighing below the
/// force (a restart after a logger's dropout, the steps of an inched
/// lowering, a lowering after a load added at rest) and cut early from true
/// u 0.833; only in a luff's steady part it still cut those early from
/// 0.871. The follower measures a rise from what the ropes read before it,
/// which a weighing the averages missed does not make. Its own guards, each
/// found by a test that failed without it: voters must have been consistent
/// before the rise and have read, and averaged, within 10 % of the weighing
/// (a rope just restarted at 80° voted with its starting D_k and was cut at
/// true u 0.689 in `a_lowering_2_to_10_s_after_a_load_added_at_rest_*`);
/// a follow's snapshots are dropped when it ends (its rescale kept its one
/// voter's ratio at 1 while that 7.3 m rope's phantom drifted up, and it
/// followed again: 90 % raised to 80° in 10 s read 1.5 × itself, an
/// OVERLOAD at true u 0.900); the luff must be steady and every rope must
/// rise at the start (the same phantom grew as the raise decelerated);
/// the rise must last 0.4 s (a bounce on the rope at 1–2 Hz, ζ 0.02, was
/// followed and cut at true u 0.89–0.90 in
/// `a_bounce_on_the_rope_keeps_the_bounds_*`); a rise that rings is
/// followed at its lower envelope, and the rest's rescale waits out the
/// stop's bounce after a followed rise
/// (`a_load_added_in_motion_on_a_ringing_rope_stays_as_measured`).
#[test]
#[ignore = "KNOWN GAP: a load added in motion is cut up to 3.35 s after its take-up (110 %, a 10 s raise to 80 deg), and 90 % added in a lowering is cut past true u 1.05 (up to 1.14)"]
fn a_load_added_in_motion_known_gap() {
    let got = load_added_in_motion(Precision::F64);
    assert!(got.slowest_110_s <= 1.0 && got.highest_uncut_u == 0.0 && got.cut_90.is_empty() && got.lowest_onset_u >= 1.0 / 1.1, "{got:?}");
}

/// The known gap above pinned at its measured size, f64 and f32, so that
/// it cannot widen unseen: 110 % cut within 3.5 s of its take-up (3.35 s
/// measured; 6 s before the follower of a rise, 5.80 s measured), no sample
/// of a lowering over true u 1.15 uncut (1.112, f32 1.136; 1.28 before,
/// 1.268), none cut before 1/1.1 (0.962), 90 % added in a raise never an
/// OVERLOAD.
#[test]
fn a_load_added_in_motion_stays_as_measured() {
    for precision in [Precision::F64, Precision::F32] {
        let got = load_added_in_motion(precision);
        assert!(got.within_the_pinned_gap(), "{precision:?}: {got:?}");
    }
}

/// [`load_added_in_motion`] on held ropes that ring (f64): at 1 Hz with a
/// damping ratio of 0.05 and 0.02, at 2 Hz with 0.05, excited by the luff's
/// starts and stops ([`bounce_on_the_rope`]) and by the take-up
/// ([`ring_the_take_up`]: taken up in 0.5 s at 1 Hz, the pull overshoots by
/// about 60 % of the load added). The ring is not load: 90 % added in a raise
/// is never an OVERLOAD and no lowering is cut before 1/1.1 (lowest 0.943);
/// the known gap's sizes hold (110 % within 3.5 s of its take-up, 3.35 s
/// measured; lowerings uncut up to 1.15, 1.110). Before the follower of a
/// rise read a ringing rise at its lower envelope, its crest was taken up:
/// 90 % raised to 80° in 10 s was an OVERLOAD at true u 0.900 in 2–6 of 96
/// cases; and before the rest's rescale waited out the stop's bounce after
/// a followed rise, in 2 (at 1 Hz, ζ 0.05, 1.8 s after the stop).
#[test]
fn a_load_added_in_motion_on_a_ringing_rope_stays_as_measured() {
    for (hz, zeta) in [(1.0, 0.05), (2.0, 0.05), (1.0, 0.02)] {
        let got = load_added_in_motion_ringing(Precision::F64, Some((hz, zeta)));
        println!("a {hz} Hz ring, zeta {zeta}: {got:?}");
        assert!(got.within_the_pinned_gap(), "{hz} Hz, zeta {zeta}: {got:?}");
    }
}
