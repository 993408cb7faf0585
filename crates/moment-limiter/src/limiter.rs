//! The per-cycle step that ties the stages together (SPEC §4, default 100 Hz).
//!
//! One cycle, in order (each stage is a module of this crate):
//! 1. **read and check**: counts → loop current → bar / degrees
//!    ([`crate::conversion`]), instant checks ([`crate::units`]), history
//!    checks ([`crate::checks`]);
//! 2. **piston force** (eq. 4.1, [`crate::piston_force`]) and low-pass filters
//!    on force and angle ([`crate::filter`]); angle rate and direction;
//! 3. **hook load** from the model's piston force ([`crate::load_estimate`]),
//!    the static hook mass whatever the rope ([`crate::static_load`]);
//! 4. **rated load** from the model's affine jack reaction
//!    ([`crate::capacity`]);
//! 5. **utilization and state** ([`crate::state_machine`]), outputs;
//! 6. **event log** ([`crate::event_log`]).
//!
//! Two entries share everything after stage 1: [`Limiter::step_counts`] for
//! the hardware (raw ADC counts through [`SensorInputs`]) and
//! [`Limiter::step_frame`] for recorded logs already in physical units (the
//! replay), which are range-checked exactly as the firmware would: a value out
//! of range in a log is a sensor FAULT (SPEC §5).
//!
//! The first cycle is the **power-up self-test**: it must read all three
//! sensors without a fault; its result is logged. Until that cycle the
//! limiter reports FAULT, and [`Limiter::power_up`] drives the fail-safe
//! command (which doubles as the lamp test).
//!
//! A model or capacity error, a clock that stalls, jumps or goes backwards
//! ([`crate::clock`]), a load estimate no hook can give
//! ([`crate::negative_load`]) and an output failure are faults too: whenever the limiter cannot tell
//! that the crane is safe, it cuts.
//!
//! Time is an integer [`Ticks`] count (µs, wrapping); the float step the
//! filters see is computed from the integer difference ([`crate::clock`]).

use core::fmt;

use crane_model::load_model::{BoomState, CycleQuery, HookLoadModel};
use crane_model::Real;

use crate::capacity::{Capacity, CapacityError};
use crate::checks::{
    channel_name, FaultKind, PlausibilityConfig, PlausibilityMonitor, SensorFault,
};
use crate::clock::{Clock, ClockConfig, ClockFault, Ticks};
use crate::conversion::SensorConversion;
use crate::event_log::{Event, EventKind, EventLog};
use crate::filter::LowPass;
use crate::io::{Channel, OutputCommand, OutputError, Outputs, SensorInputs};
use crate::load_estimate::{
    load_equation, Calibration, Direction, DirectionDetector, DirectionThresholds, EstimateError,
    Friction,
};
use crate::negative_load::{NegativeLoadBound, NegativeLoadMonitor};
use crate::piston_force::piston_force_n;
use crate::state_machine::{CycleInput, LimiterState, StateMachine, Thresholds};
use crate::static_load::{LoadTerms as BankTerms, StaticLoad, StaticLoadBank};
use crate::swing::SwingGeometry;
use crate::units::{BoomAngle, PressureBar};

/// Number of events the limiter's log holds.
pub const EVENT_LOG_LEN: usize = 64;

/// Time after a restart of the signal chain (a fault) during which a moving
/// boom's estimate is no reading (s): three delays of the standard filter
/// and the sensor lag (0.64 s), when its start-up transient has died out.
pub const SETTLE_S: f64 = 2.0;

/// Utilization reported when the rated load is zero, and the ceiling of any
/// reported utilization (keeps logs finite; far above every threshold).
pub const UTILIZATION_CEILING: f64 = 10.0;

/// One sample of a recorded log, in physical units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame<T> {
    /// Time on the limiter's clock ([`crate::clock`]).
    pub t: Ticks,
    /// Piston-side pressure p1 (bar).
    pub p1_bar: T,
    /// Rod-side pressure p2 (bar).
    pub p2_bar: T,
    /// Boom angle (degrees from horizontal).
    pub boom_angle_deg: T,
}

/// Why the limiter is in FAULT.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Fault {
    /// A sensor reading failed a check.
    Sensor(SensorFault),
    /// No load estimate could be made.
    Estimate(EstimateError),
    /// No rated load could be computed.
    Capacity(CapacityError),
    /// The time of the cycle cannot be trusted (stalled, gap, backwards).
    Clock(ClockFault),
    /// The load estimate stayed below [`LimiterConfig::negative_load`]: no
    /// hook load is negative, so the estimate (or a sensor or the
    /// calibration) is wrong.
    ImplausibleLoad,
    /// The signal chain restarted after a fault less than [`SETTLE_S`] ago
    /// with the boom moving: the filters' start-up is no reading yet.
    Settling,
    /// The outputs could not be driven.
    Output,
}

impl fmt::Display for Fault {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Fault::Sensor(s) => write!(f, "{} {}", channel_name(s.channel), s.kind.as_str()),
            Fault::Estimate(EstimateError::Model(e)) => write!(f, "load model: {e}"),
            Fault::Estimate(EstimateError::NotObservable) => f.write_str("load not observable"),
            Fault::Capacity(CapacityError::Model(e)) => write!(f, "capacity model: {e}"),
            Fault::Capacity(CapacityError::NotObservable) => f.write_str("capacity not observable"),
            Fault::Clock(c) => write!(f, "{c}"),
            Fault::ImplausibleLoad => f.write_str("load estimate implausibly negative"),
            Fault::Settling => f.write_str("signal chain settling after a fault"),
            Fault::Output => f.write_str("output driver failed"),
        }
    }
}

/// Why a [`LimiterConfig`] was refused; the name says which part.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ConfigError(pub &'static str);

impl fmt::Display for ConfigError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "invalid limiter configuration: {}", self.0)
    }
}

/// Everything the limiter is configured with (constant while it runs).
#[derive(Debug, Clone, PartialEq)]
pub struct LimiterConfig<T> {
    /// Counts → physical units.
    pub conversion: SensorConversion<T>,
    /// Rate-of-change and stuck limits.
    pub plausibility: PlausibilityConfig<T>,
    /// Cut-off of each stage of the filter on the piston force and the boom
    /// angle (Hz): one filter for both keeps them aligned in time.
    pub filter_hz: T,
    /// Number of first-order stages of that filter (1…[`crate::filter::MAX_STAGES`]).
    pub filter_stages: usize,
    /// Direction-of-motion thresholds.
    pub direction: DirectionThresholds<T>,
    /// Lag of the angle sensor behind the boom for a steady rate (s): for a
    /// pendulum potentiometer of natural frequency ω_n and damping ζ, 2ζ/ω_n
    /// (the sensor's data; see [`Limiter`] "Time alignment"). 0 for a sensor
    /// without lag.
    pub angle_sensor_lag_s: T,
    /// Time constant (s) with which the friction of the last motion is taken
    /// to leave the force once the boom is still (the seals release; see
    /// [`crate::load_estimate`]).
    pub seal_release_s: T,
    /// Crane geometry for the bank of rope hypotheses and their swing
    /// observers ([`crate::static_load`]); `None` turns the rope and swing
    /// corrections off (the load taken hanging straight and still).
    pub swing: Option<SwingGeometry<T>>,
    /// Safety factor and chart.
    pub capacity: Capacity<T>,
    /// State machine thresholds and times.
    pub thresholds: Thresholds<T>,
    /// Friction and offsets.
    pub calibration: Calibration<T>,
    /// The factor the model's load estimate is read with (1.0…1.1). SAE
    /// J376 asks a load indicator to read between 100 % and 110 % of the true
    /// load, never below it: the limiter aims at the middle of that band, so
    /// an estimate within ±5 % of the truth still reads inside it. The
    /// utilization, and so every alarm, uses the load as read.
    pub load_reading_factor: T,
    /// The clock's nominal period and longest allowed step ([`crate::clock`]).
    pub clock: ClockConfig,
    /// How negative a load estimate may be, and for how long, before it is
    /// a FAULT ([`crate::negative_load`]).
    pub negative_load: NegativeLoadBound<T>,
}

impl<T: Real> LimiterConfig<T> {
    /// The documented defaults of every module; force and angle filtered by
    /// 4 stages at 1.2 Hz (delay 0.53 s; the boom's first bending oscillation,
    /// 3.3–4 Hz, is cut to 0.7–1.4 %, and the angle's second difference is
    /// smooth enough for the inertia correction: 0.09 °/s² of noise, 0.3 %
    /// of a 3.3 t load at 60°, for 0.03° on the angle; a step of load shows
    /// 90 % of its size after 0.88 s); the load read ×1.05 (J376); the angle sensor of the thesis crane's
    /// recorder (pendulum of 2 Hz, ζ = 0.7: lag 2·0.7/(2π·2) = 0.1114 s); the
    /// swing observer with the COLES Mobile 930 geometry; no calibration.
    pub fn standard() -> Self {
        Self {
            conversion: SensorConversion::standard(),
            plausibility: PlausibilityConfig::standard(),
            filter_hz: T::lit(1.2),
            filter_stages: 4,
            direction: DirectionThresholds::standard(),
            angle_sensor_lag_s: T::lit(2.0 * 0.7 / (2.0 * core::f64::consts::PI * 2.0)),
            seal_release_s: T::lit(0.5),
            swing: Some(SwingGeometry::coles_930()),
            capacity: Capacity::standard(),
            thresholds: Thresholds::standard(),
            calibration: Calibration::none(),
            load_reading_factor: T::lit(1.05),
            clock: ClockConfig::standard(),
            negative_load: NegativeLoadBound::standard(),
        }
    }

    /// Checks every part.
    pub fn validate(&self) -> Result<(), ConfigError> {
        let hz = |x: T| x.is_finite() && x > T::lit(0.0);
        let checks = [
            (self.conversion.is_valid(), "conversion"),
            (self.plausibility.is_valid(), "plausibility"),
            (hz(self.filter_hz), "filter_hz"),
            (
                (1..=crate::filter::MAX_STAGES).contains(&self.filter_stages),
                "filter_stages",
            ),
            (self.direction.is_valid(), "direction"),
            (
                self.angle_sensor_lag_s.is_finite() && self.angle_sensor_lag_s >= T::lit(0.0),
                "angle_sensor_lag_s",
            ),
            (hz(self.seal_release_s), "seal_release_s"),
            (self.swing.is_none_or(|g| g.is_valid()), "swing"),
            (self.capacity.is_valid(), "capacity"),
            (self.thresholds.is_valid(), "thresholds"),
            (self.calibration.is_valid(), "calibration"),
            (
                self.load_reading_factor >= T::lit(1.0) && self.load_reading_factor <= T::lit(1.1),
                "load_reading_factor",
            ),
            (self.clock.is_valid(), "clock"),
            (self.negative_load.is_valid(), "negative_load"),
        ];
        match checks.iter().find(|(ok, _)| !ok) {
            Some((_, name)) => Err(ConfigError(name)),
            None => Ok(()),
        }
    }
}

/// The signals after conversion and filtering.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Measurement<T> {
    /// Filtered piston force (N), transducer offsets removed.
    pub piston_force_n: T,
    /// Boom angle now (degrees): the filtered reading, pendulum offset
    /// removed, advanced by rate × (sensor lag + filter delay).
    pub boom_angle_deg: T,
    /// Filtered angle rate (degrees per second).
    pub rate_deg_s: T,
    /// Angular acceleration (degrees per second²): the second difference of
    /// the filtered angle, at the time of the filtered force.
    pub accel_deg_s2: T,
    /// Time the boom has been moving in `direction` without interruption (s);
    /// 0 when still.
    pub moving_for_s: T,
    /// Direction of motion.
    pub direction: Direction,
    /// The friction in the force (see [`crate::load_estimate`]).
    pub friction: Friction,
    /// The share of the last motion's friction still in the force of a
    /// still boom (1 at the stop, decaying as the seals release).
    pub static_friction_share: T,
    /// The boom state at the time of the filtered force (the angle advanced
    /// by rate × sensor lag only): what the load estimate hands to the model.
    pub boom: BoomState<T>,
    /// The boom state now: what the rated load is computed at.
    pub boom_now: BoomState<T>,
    /// tan of the load swing the chosen rope hypothesis predicts at the time
    /// of the filtered force, as of the previous cycle's choice (0 without
    /// the swing geometry).
    pub tan_swing: T,
}

impl<T: Real> Measurement<T> {
    /// The angular acceleration in rad/s², as the model takes it.
    pub fn accel_rad_s2(&self) -> T {
        self.accel_deg_s2 * T::pi() / T::lit(180.0)
    }
}

/// Load, capacity and utilization of one cycle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Estimate<T> {
    /// Estimated hook load (kg).
    pub load_kg: T,
    /// Rated load (kg).
    pub rated_load_kg: T,
    /// Tipping load (kg); `None` when no load can tip the crane here.
    pub tipping_load_kg: Option<T>,
    /// load / rated, capped at [`UTILIZATION_CEILING`].
    pub utilization: T,
    /// Hook radius (m).
    pub radius_m: T,
    /// The rope-hypothesis bank's parts of the load, before the reading
    /// factor ([`crate::static_load`]); `None` without the swing geometry.
    pub static_load: Option<StaticLoad<T>>,
}

/// The result of one cycle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepReport<T> {
    /// Time of the cycle.
    pub t: Ticks,
    /// State after the cycle.
    pub state: LimiterState,
    /// Outputs to drive.
    pub command: OutputCommand,
    /// Filtered signals, when all readings were good.
    pub measurement: Option<Measurement<T>>,
    /// Load and capacity, when they could be computed.
    pub estimate: Option<Estimate<T>>,
    /// The fault found in this cycle, if any.
    pub fault: Option<Fault>,
}

/// Angle and rate `horizon_s` ahead of a filtered (angle, rate,
/// acceleration): constant acceleration, except that a decelerating boom is
/// taken to stop where it would come to rest rather than to turn round (the
/// end of a move: extrapolating the rate alone ran a boom that was stopping
/// at 40° on to 37°, and its rating down by 7 %).
fn extrapolate<T: Real>(angle: T, rate: T, accel: T, horizon_s: T) -> (T, T) {
    let zero = T::lit(0.0);
    let half = T::lit(0.5);
    let rate_end = rate + accel * horizon_s;
    if rate * accel < zero && rate * rate_end <= zero {
        // Stops within the horizon, at rate²/(2·|accel|) from here.
        (angle - rate * rate * half / accel, zero)
    } else {
        (
            angle + (rate + half * accel * horizon_s) * horizon_s,
            rate_end,
        )
    }
}

/// Checked readings of one cycle.
type Readings<T> = (PressureBar<T>, PressureBar<T>, BoomAngle<T>);

/// The load moment limiter: configuration, model and running state.
///
/// ## Time alignment
///
/// The load is W = (F − corrections − F_model,0(θ))/per_kg(θ): the force and
/// the angle must belong to the same instant, or the slope of F_model over θ
/// (≈ 2 kN/° unloaded, ≈ 10 kN/° with 8 t at 60°) turns an angle error into a
/// load error. At a steady rate ω the filtered force lags the boom by the
/// filter's group delay d (≈ 4τ = 0.53 s for 4 stages at 1.2 Hz), and the
/// filtered angle by
/// d plus the angle sensor's own lag (the pendulum's 2ζ/ω_n, 0.111 s): left
/// alone, the model was evaluated 0.111 s × 4.3 °/s ≈ 0.48° away from the
/// force's angle, ≈ 1 kN of error unloaded. Advancing the angle by
/// ω × lag aligned the angle but not the acceleration, whose inertia terms
/// (the boom's J·θ̈ and a held load riding up with the tip) then came 0.11 s
/// late: +13 % on a 90 % load in a 0.5 s start ramp. So the force goes
/// through a first-order lag of the sensor's lag too, and force, angle, rate
/// and acceleration all stand for t − lag − d (0.11 s more delay on a
/// lift-off). The rated load takes the angle advanced by ω × (sensor lag +
/// d) (the present instant: lowering, the rated load falls, and it must not
/// be read late). The same filter on force and angle keeps both delays equal
/// whatever the cut-off.
#[derive(Debug, Clone)]
pub struct Limiter<T, M> {
    model: M,
    config: LimiterConfig<T>,
    monitor: PlausibilityMonitor<T>,
    /// The angle sensor's lag, put on the force too (see "Time alignment").
    force_lag: Option<LowPass<T>>,
    force_filter: LowPass<T>,
    angle_filter: LowPass<T>,
    static_friction_share: T,
    /// Time since the signal chain restarted (s), while under [`SETTLE_S`].
    since_restart_s: Option<T>,
    previous_angle_deg: Option<T>,
    previous_rate_deg_s: Option<T>,
    moving_for_s: T,
    bank: Option<StaticLoadBank<T>>,
    /// Time the bank has not been advanced (s): the faulted cycles since
    /// its last update.
    bank_idle_s: T,
    direction: DirectionDetector<T>,
    machine: StateMachine<T>,
    log: EventLog<T, EVENT_LOG_LEN>,
    clock: Clock<T>,
    negative_load: NegativeLoadMonitor<T>,
    state: Option<LimiterState>,
    output_failed: bool,
}

impl<T: Real, M: HookLoadModel<T>> Limiter<T, M> {
    /// A limiter that has not run its self-test yet (it reports FAULT).
    pub fn new(model: M, config: LimiterConfig<T>) -> Result<Self, ConfigError> {
        config.validate()?;
        Ok(Self {
            monitor: PlausibilityMonitor::new(config.plausibility),
            force_lag: (config.angle_sensor_lag_s > T::lit(0.0))
                .then(|| LowPass::new(T::lit(1.0) / (T::two_pi() * config.angle_sensor_lag_s), 1)),
            force_filter: LowPass::new(config.filter_hz, config.filter_stages),
            static_friction_share: T::lit(1.0),
            since_restart_s: None,
            angle_filter: LowPass::new(config.filter_hz, config.filter_stages),
            previous_angle_deg: None,
            previous_rate_deg_s: None,
            moving_for_s: T::lit(0.0),
            bank: config.swing.map(StaticLoadBank::new),
            bank_idle_s: T::lit(0.0),
            direction: DirectionDetector::new(config.direction),
            machine: StateMachine::new(config.thresholds),
            log: EventLog::new(),
            clock: Clock::new(config.clock),
            negative_load: NegativeLoadMonitor::new(config.negative_load),
            state: None,
            output_failed: false,
            model,
            config,
        })
    }

    /// The crane model.
    pub fn model(&self) -> &M {
        &self.model
    }

    /// The configuration.
    pub fn config(&self) -> &LimiterConfig<T> {
        &self.config
    }

    /// The event log.
    pub fn events(&self) -> &EventLog<T, EVENT_LOG_LEN> {
        &self.log
    }

    /// Mutable event log (to drain it to storage).
    pub fn events_mut(&mut self) -> &mut EventLog<T, EVENT_LOG_LEN> {
        &mut self.log
    }

    /// Present state (FAULT before the first cycle).
    pub fn state(&self) -> LimiterState {
        self.state.unwrap_or(LimiterState::Fault)
    }

    /// Power-up: drives the fail-safe command (motions cut, lamps on: the lamp
    /// test) until the first cycle decides otherwise.
    pub fn power_up<O: Outputs>(&mut self, outputs: &mut O) -> Result<(), OutputError> {
        let r = outputs.apply(OutputCommand::FAIL_SAFE);
        if r.is_err() {
            self.output_failed = true;
        }
        r
    }

    /// One hardware cycle: reads the counts, steps, drives the outputs. An
    /// output failure makes the next cycles FAULT (the outputs are wired so
    /// that a failed driver leaves the motions cut).
    // A named function in every image: scripts/check-cycle-image.sh walks
    // the call graph from it (no soft float, no panic in the cycle).
    #[inline(never)]
    pub fn cycle<S: SensorInputs, O: Outputs>(
        &mut self,
        now: Ticks,
        inputs: &mut S,
        outputs: &mut O,
    ) -> StepReport<T> {
        let report = self.step_counts(now, inputs);
        self.output_failed = outputs.apply(report.command).is_err();
        report
    }

    /// One cycle from raw ADC counts (the firmware's entry).
    pub fn step_counts<S: SensorInputs>(&mut self, now: Ticks, inputs: &mut S) -> StepReport<T> {
        let readings = self.read_counts(inputs);
        self.step_readings(now, readings)
    }

    /// One cycle from a recorded frame in physical units (the replay's entry).
    // Named in every image, as `cycle` (scripts/check-cycle-image.sh).
    #[inline(never)]
    pub fn step_frame(&mut self, frame: &Frame<T>) -> StepReport<T> {
        let fault = |channel: Channel| move |kind: FaultKind| SensorFault { channel, kind };
        let readings = PressureBar::new(frame.p1_bar)
            .map_err(fault(Channel::PistonSidePressure))
            .and_then(|p1| {
                let p2 = PressureBar::new(frame.p2_bar).map_err(fault(Channel::RodSidePressure))?;
                let a = BoomAngle::new(frame.boom_angle_deg).map_err(fault(Channel::BoomAngle))?;
                Ok((p1, p2, a))
            });
        self.step_readings(frame.t, readings)
    }

    fn read_counts<S: SensorInputs>(&self, inputs: &mut S) -> Result<Readings<T>, SensorFault> {
        let conv = &self.config.conversion;
        let fault = |channel: Channel| move |kind: FaultKind| SensorFault { channel, kind };
        let read = |inputs: &mut S, channel: Channel| {
            inputs.read_counts(channel).map_err(|e| SensorFault {
                channel,
                kind: FaultKind::Input(e),
            })
        };
        let c1 = read(inputs, Channel::PistonSidePressure)?;
        let p1 = conv
            .pressure(&conv.p1, c1)
            .map_err(fault(Channel::PistonSidePressure))?;
        let c2 = read(inputs, Channel::RodSidePressure)?;
        let p2 = conv
            .pressure(&conv.p2, c2)
            .map_err(fault(Channel::RodSidePressure))?;
        let ca = read(inputs, Channel::BoomAngle)?;
        let a = conv.boom_angle(ca).map_err(fault(Channel::BoomAngle))?;
        Ok((p1, p2, a))
    }

    /// Stages 2–6, shared by both entries.
    fn step_readings(
        &mut self,
        t: Ticks,
        readings: Result<Readings<T>, SensorFault>,
    ) -> StepReport<T> {
        // Clock: the step comes from the integer difference; a stalled,
        // jumping or backwards clock is a fault (the step is then 0).
        let clock = self.clock.advance(t);
        let dt_s = *clock.as_ref().unwrap_or(&T::lit(0.0));

        // Stage 1 (history checks) and stages 2–4.
        let mut measurement = None;
        let mut estimate = None;
        let fault = if let Err(c) = clock {
            Some(Fault::Clock(c))
        } else if self.output_failed {
            Some(Fault::Output)
        } else {
            None
        };
        let fault = match (fault, readings) {
            (Some(f), _) => {
                self.restart_signal_chain();
                Some(f)
            }
            (None, Err(sensor)) => {
                self.restart_signal_chain();
                Some(Fault::Sensor(sensor))
            }
            (None, Ok((p1, p2, angle))) => {
                match self
                    .monitor
                    .check([p1.bar(), p2.bar(), angle.degrees()], dt_s)
                {
                    Err(sensor) => {
                        self.restart_signal_chain();
                        Some(Fault::Sensor(sensor))
                    }
                    Ok(()) => {
                        let m = self.measure(p1, p2, angle, dt_s);
                        measurement = Some(m);
                        // After a restart the filters start settled: for a
                        // moving boom their start-up reads as an acceleration
                        // the force never had. Not a reading until it passed.
                        let settling = self.settling(&m, dt_s);
                        match self.assess(&m) {
                            Ok(e) => {
                                estimate = Some(e);
                                // A load no hook can give is no reading.
                                let negative = self.negative_load.implausible(
                                    e.load_kg,
                                    m.boom.angle_rad,
                                    dt_s,
                                );
                                if negative {
                                    Some(Fault::ImplausibleLoad)
                                } else {
                                    settling.then_some(Fault::Settling)
                                }
                            }
                            Err(f) => {
                                self.negative_load.reset();
                                Some(f)
                            }
                        }
                    }
                }
            }
        };

        if measurement.is_none() {
            self.bank_idle_s += dt_s;
        }

        // Stage 5.
        let input = match (&fault, &estimate) {
            (None, Some(e)) => CycleInput::Utilization(e.utilization),
            _ => CycleInput::Fault,
        };
        let state = self.machine.update(dt_s, input);

        // Stage 6: self-test on the first cycle, then every state change.
        let event = |kind| Event {
            t,
            kind,
            boom_angle_deg: measurement.map(|m| m.boom_angle_deg),
            load_kg: estimate.map(|e| e.load_kg),
            utilization: estimate.map(|e| e.utilization),
        };
        if self.state.is_none() {
            self.log.push(event(match fault {
                None => EventKind::SelfTestPassed,
                Some(f) => EventKind::SelfTestFailed(f),
            }));
        }
        if self.state != Some(state) {
            let cause = if state == LimiterState::Fault {
                fault
            } else {
                None
            };
            self.log.push(event(EventKind::Entered(state, cause)));
        }
        self.state = Some(state);

        StepReport {
            t,
            state,
            command: state.command(),
            measurement,
            estimate,
            fault,
        }
    }

    /// `true` while the signal chain restarted less than [`SETTLE_S`] ago
    /// and the boom moves (a still boom's start is its true history).
    fn settling(&mut self, m: &Measurement<T>, dt_s: T) -> bool {
        let Some(t) = self.since_restart_s else {
            return false;
        };
        let t = t + dt_s;
        self.since_restart_s = (t < T::lit(SETTLE_S)).then_some(t);
        self.since_restart_s.is_some() && m.direction != Direction::Still
    }

    /// After a bad cycle the filters restart settled on the next good sample,
    /// so no faulty value ever reaches them.
    fn restart_signal_chain(&mut self) {
        self.since_restart_s = Some(T::lit(0.0));
        self.negative_load.reset();
        self.monitor.break_rate_history();
        if let Some(l) = self.force_lag.as_mut() {
            l.reset();
        }
        self.force_filter.reset();
        self.angle_filter.reset();
        self.previous_angle_deg = None;
        self.previous_rate_deg_s = None;
        self.moving_for_s = T::lit(0.0);
        // The load keeps swinging through a fault (a pressure out of range
        // when a short rope swings inward at a steep boom): the swing
        // observers run on over the gap, only the averages start afresh.
        if let Some(b) = self.bank.as_mut() {
            b.restart_averages();
        }
    }

    /// Stage 2: force, filters, rate and direction.
    fn measure(
        &mut self,
        p1: PressureBar<T>,
        p2: PressureBar<T>,
        angle: BoomAngle<T>,
        dt_s: T,
    ) -> Measurement<T> {
        let cal = &self.config.calibration;
        let force = piston_force_n(p1, p2, cal.p1_offset_bar, cal.p2_offset_bar);
        // The force through the angle sensor's lag too: force, angle, rate
        // and acceleration then share one delay (see "Time alignment").
        let force = match self.force_lag.as_mut() {
            Some(l) => l.update(force, dt_s),
            None => force,
        };
        let force_f = self.force_filter.update(force, dt_s);
        let angle_f = self
            .angle_filter
            .update(angle.degrees() - cal.angle_offset_deg, dt_s);
        // Rate and acceleration as differences of the filtered angle: the
        // filter already removed the noise, and no further filter may delay
        // them behind the force (their inertia term is in the force now).
        let rate_f = match self.previous_angle_deg {
            Some(prev) if dt_s > T::lit(0.0) => (angle_f - prev) / dt_s,
            _ => self.previous_rate_deg_s.unwrap_or(T::lit(0.0)),
        };
        self.previous_angle_deg = Some(angle_f);
        let accel_f = match self.previous_rate_deg_s {
            Some(prev) if dt_s > T::lit(0.0) => (rate_f - prev) / dt_s,
            _ => T::lit(0.0),
        };
        self.previous_rate_deg_s = Some(rate_f);
        let previous_direction = self.direction.current();
        let direction = self.direction.update(rate_f);
        self.moving_for_s = if direction == Direction::Still {
            T::lit(0.0)
        } else if direction == previous_direction {
            self.moving_for_s + dt_s
        } else {
            T::lit(0.0)
        };
        // The seals release at standstill (see crate::load_estimate).
        self.static_friction_share = if direction == Direction::Still {
            let x = dt_s / self.config.seal_release_s;
            // e^(−x) ≈ 1/(1 + x + x²/2 + x³/6): no libm exp in the cycle.
            self.static_friction_share
                / (T::lit(1.0) + x * (T::lit(1.0) + x * (T::lit(0.5) + x / T::lit(6.0))))
        } else {
            T::lit(1.0)
        };
        // Time alignment (see the type's doc): the filtered force and the
        // filtered angle both stand for t − d − lag.
        let at_force = angle_f;
        let (now, rate_now) = extrapolate(
            angle_f,
            rate_f,
            accel_f,
            self.config.angle_sensor_lag_s + self.force_filter.delay_s(dt_s),
        );
        let to_rad = T::pi() / T::lit(180.0);
        let boom = BoomState {
            angle_rad: at_force * to_rad,
            rate_rad_s: rate_f * to_rad,
        };
        let settling = self.since_restart_s.is_some();
        let tan_swing = match self.bank.as_mut() {
            Some(b) => {
                if settling {
                    // The filters restarted at this reading: the swing is
                    // carried over relative to the tip (no jump of the
                    // filtered angle kicks it), the filters' start-up
                    // acceleration is not the boom's, and no average
                    // starts from a reading that is none yet.
                    if self.since_restart_s == Some(T::lit(0.0)) {
                        b.rebase(boom.angle_rad);
                    }
                    b.restart_averages();
                }
                let accel = if settling {
                    T::lit(0.0)
                } else {
                    accel_f * to_rad
                };
                b.advance(
                    boom.angle_rad,
                    boom.rate_rad_s,
                    accel,
                    dt_s + core::mem::replace(&mut self.bank_idle_s, T::lit(0.0)),
                )
            }
            None => T::lit(0.0),
        };
        Measurement {
            piston_force_n: force_f,
            boom_angle_deg: now,
            rate_deg_s: rate_f,
            accel_deg_s2: accel_f,
            moving_for_s: self.moving_for_s,
            direction,
            friction: self.direction.friction(),
            static_friction_share: self.static_friction_share,
            boom,
            boom_now: BoomState {
                angle_rad: now * to_rad,
                rate_rad_s: rate_now * to_rad,
            },
            tan_swing,
        }
    }

    /// Stages 3–4: load, rating, utilization, from one query of the model.
    fn assess(&mut self, m: &Measurement<T>) -> Result<Estimate<T>, Fault> {
        let terms = self.model.cycle_terms(CycleQuery {
            force_angle_rad: m.boom.angle_rad,
            now: m.boom_now,
        });
        let load_terms = terms
            .load
            .map_err(|e| Fault::Estimate(EstimateError::Model(e)))?;
        let (at_rest, force_n) = load_equation(
            &load_terms,
            m.accel_rad_s2(),
            m.piston_force_n,
            &self.config.calibration,
            m.friction,
            m.static_friction_share,
        )
        .map_err(Fault::Estimate)?;
        // The static hook mass: the rope-hypothesis bank when the swing
        // geometry is known, else the load hanging straight and still.
        let static_load = match self.bank.as_mut() {
            Some(bank) => Some(
                bank.update(&BankTerms {
                    at_rest,
                    force_n,
                    angle_rad: m.boom.angle_rad,
                })
                .ok_or(Fault::Estimate(EstimateError::NotObservable))?,
            ),
            None => None,
        };
        let load_kg = match static_load {
            Some(s) => Some(s.load_kg),
            None => at_rest.solve(force_n),
        }
        .ok_or(Fault::Estimate(EstimateError::NotObservable))?
            * self.config.load_reading_factor;
        let capacity_terms = terms
            .capacity
            .map_err(|e| Fault::Capacity(CapacityError::Model(e)))?;
        let rating = self
            .config
            .capacity
            .rating_from(&capacity_terms)
            .map_err(Fault::Capacity)?;
        let ceiling = T::lit(UTILIZATION_CEILING);
        let utilization = if rating.rated_load_kg > T::lit(0.0) {
            (load_kg / rating.rated_load_kg).min(ceiling)
        } else {
            ceiling
        };
        Ok(Estimate {
            load_kg,
            rated_load_kg: rating.rated_load_kg,
            tipping_load_kg: rating.tipping_load_kg,
            utilization,
            radius_m: rating.radius_m,
            static_load,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::extrapolate;

    #[test]
    fn extrapolation_follows_the_acceleration_and_stops_a_stopping_boom() {
        // Steady lowering: a straight line.
        assert_eq!(extrapolate(50.0_f64, -5.0, 0.0, 0.5), (47.5, -5.0));
        // Speeding up: the parabola.
        let (a, r) = extrapolate(50.0_f64, -1.0, -2.0, 0.5);
        assert!((a - (50.0 - 0.5 - 0.25)).abs() < 1e-12 && (r + 2.0).abs() < 1e-12);
        // Slowing down, still moving at the horizon: the parabola.
        let (a, r) = extrapolate(50.0_f64, -5.0, 4.0, 0.5);
        assert!((a - (50.0 - 2.5 + 0.5)).abs() < 1e-12 && (r + 3.0).abs() < 1e-12);
        // Slowing down, stopped before the horizon: where it comes to rest
        // (−5 °/s at 8 °/s² stops in 0.625 s, 1.5625° further), not beyond.
        let (a, r) = extrapolate(50.0_f64, -5.0, 8.0, 1.0);
        assert!((a - (50.0 - 1.5625)).abs() < 1e-12 && r == 0.0);
        // The same raising.
        let (a, r) = extrapolate(50.0_f64, 5.0, -8.0, 1.0);
        assert!((a - (50.0 + 1.5625)).abs() < 1e-12 && r == 0.0);
    }
}
