//! # moment-limiter
//!
//! The core of a load moment limiter (LML, rated capacity limiter) for a
//! telescopic-boom hydraulic crane on its jacks: from the two luffing-cylinder
//! pressures and the boom angle to safe-load alarms and the cut-off of the
//! motions that increase the load moment. `no_std`, no heap, no panics in the
//! control path, generic over [`crane_model::Real`] so the controller runs it
//! in `f32` and the host in `f64` from the same source.
//!
//! ## Layers, in the order a cycle runs through them
//!
//! No module imports [`cycle`] except the replay tool, which drives it; the
//! vocabulary the cycle shares with the event log, the log parser, the
//! calibration and the testing aids lives in [`io`] and [`fault`].
//!
//! | layer | module | what it holds |
//! |---|---|---|
//! | time | [`clock`] | integer ticks (µs, wrapping), stalled / gap / backwards faults |
//! | hardware seam | [`io`] | [`io::SensorInputs`] (ADC counts) and [`io::Outputs`] (lamps, cut-off); the shared vocabulary [`io::Frame`] (a logged sample) and [`io::Measurement`] (the filtered signals) |
//! | conversion | [`conversion`] | counts → mA → bar, counts → degrees, per sensor |
//! | valid values | [`units`] | [`units::PressureBar`], [`units::BoomAngle`]: cannot hold a faulted reading |
//! | checks | [`checks`] | NAMUR NE 43, range, stuck, rate of change |
//! | force | [`piston_force`], [`filter`] | eq. 4.1 and the oscillation filter |
//! | load | [`load_estimate`], [`breakaway`], [`static_load`], [`held_pendulum`], [`swing`], [`load_jump`], [`load_rise`], [`period_mean`], [`swing_midrange`] | W from the model's piston force (quadratic in W), friction per direction, boom inertia; the static hook mass from a bank of rope hypotheses (paid out, or held at 3–22 m, each with its swing): the lowest load any rope explains, floored by their averages; a load added at rest after a move, from the consistent ropes' common ratio, the swing's crest and trough, or the mean over one swing period; a load added in motion, from the consistent ropes' common rise; read ×1.05 (SAE J376) |
//! | capacity | [`capacity`] | tipping load from the affine jack reaction, safety factor, chart |
//! | plausibility | [`negative_load`] | a load estimate no hook can give is a FAULT |
//! | decision | [`state_machine`] | NORMAL / WARNING / OVERLOAD / FAULT, hysteresis, outputs |
//! | faults | [`fault`] | [`fault::Fault`]: why the limiter is in FAULT (shared by the cycle, the log and the replay) |
//! | logger | [`event_log`] | EN 13000 event ring buffer |
//! | the cycle | [`cycle`] | [`cycle::Limiter`]: one `step` ties the above together; its config, report and signal chain |
//! | tools (not in the cycle; `no_std`, the QEMU firmware uses them too) | [`tools`] | SPEC §5 CSV parser, replay engine and printed output; the calibration file's schema, its one reader (host and firmware) and writer |
//! | learning | [`calibration`], [`sensor_lag`], [`seal_release`] | friction from unloaded runs (and test weights), the angle sensor's lag, the seals' release after a raise |
//! | testing aids | `testing` (feature `testing`) | sensor fault injection; a rigid stand-in model |
//!
//! ## What a firmware author calls
//!
//! Build a [`cycle::Limiter`] from a crane model implementing
//! [`crane_model::loads::load_model::HookLoadModel`] and a
//! [`cycle::LimiterConfig`]; call [`cycle::Limiter::power_up`] once, then
//! [`cycle::Limiter::cycle`] every 10 ms with the time as a
//! [`clock::Ticks`] (µs, wrapping: the cycle count × 10 000 will do), the
//! sensor inputs and the outputs. Drain [`cycle::Limiter::events_mut`] to storage.
//! The replay tool calls [`cycle::Limiter::step_frame`] through
//! [`tools::replay::Replay`] instead.
#![cfg_attr(not(any(test, feature = "std")), no_std)]
#![forbid(unsafe_code)]

pub mod breakaway;
pub mod calibration;
pub mod capacity;
pub mod checks;
pub mod clock;
pub mod conversion;
pub mod cycle;
pub mod event_log;
pub mod fault;
pub mod filter;
pub mod held_pendulum;
pub mod io;
pub mod load_estimate;
pub mod load_jump;
pub mod load_rise;
pub mod negative_load;
pub mod period_mean;
pub mod piston_force;
pub mod seal_release;
pub mod sensor_lag;
pub mod state_machine;
pub mod static_load;
pub mod swing_midrange;
pub mod swing;
#[cfg(any(test, feature = "testing"))]
pub mod testing;
pub mod tools;
pub mod units;
