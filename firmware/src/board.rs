//! The real controller (feature `board`): STM32F405RG with an MCP3208 on SPI1
//! and four relay/lamp drivers on GPIOC. Hardware initialisation ([`init`]) is
//! kept apart from the logic ([`run`] only calls the limiter through the
//! `SensorInputs`/`Outputs` seam).
//!
//! Wiring (reference board):
//!
//! | signal                           | pin  | driver                                   |
//! |----------------------------------|------|------------------------------------------|
//! | SPI1 SCK / MISO / MOSI           | PA5 / PA6 / PA7 | MCP3208, mode 0, 1 MHz        |
//! | ADC chip select (active low)     | PA4  | `embedded_hal_bus` `ExclusiveDevice`     |
//! | warning lamp                     | PC0  | high = on                                |
//! | overload alarm (lamp + buzzer)   | PC1  | high = on                                |
//! | permit boom-down relay           | PC2  | high = energised = motion allowed        |
//! | permit hoist-up relay            | PC3  | high = energised = motion allowed        |
//! | fault acknowledge key switch     | PC4  | input, pull-up; pressed = low            |
//!
//! ADC channels: p1 on CH0, p2 on CH1, boom angle on CH2
//! (`ChannelMap::REFERENCE_BOARD`). Clocks: 8 MHz HSE → 168 MHz SYSCLK. TIM2
//! ticks the 100 Hz control loop; the IWDG (50 ms, five missed cycles) resets
//! the MCU if the loop stalls. Relay drivers need pull-downs so a reset MCU
//! (pins floating) leaves the relays de-energised: cut.
//!
//! Start-up ([`run`]), with the outputs cut throughout:
//! 1. read the reset cause (`RCC_CSR`, then cleared with RMVF) and the RAM
//!    fault record the exception handlers leave (`fault`);
//! 2. open the persisted store (`limiter_storage::store`, flash sectors 8–11,
//!    see `memory.x`): count the boot, update the fault latch, log the boot;
//! 3. if the latch is active (a watchdog, fault, low-power or unknown reset,
//!    now or before a power cycle): stay cut, alarm on, until the acknowledge
//!    key is seen released and then held for 3 s (`latch::Acknowledge`);
//! 4. the stored calibration (`limiter_storage::calibration_blob`, written by
//!    the host tool `calibration-image`): decoded, checked against the
//!    calibration schema's bounds and applied; a missing, corrupt, foreign or
//!    out-of-bounds blob is logged (`CalibrationRefused`) and keeps the
//!    outputs cut until the next reset; then room for this run's events is
//!    reserved in the event log (compacting it now if needed);
//! 5. the power-up self-test (`selftest` plus output readback and sensor
//!    plausibility here); a failure keeps the outputs cut until the next reset;
//! 6. only then the watchdog starts and the 100 Hz loop runs. Flash erases
//!    stall the CPU for up to 2 s, so only start-up erases; the loop queues
//!    the limiter's state changes in RAM (`limiter_storage::event_queue`) and
//!    writes at most [`FLUSH_PER_CYCLE`] of them, by programming only, in a
//!    cycle whose outputs grant no motion.
//!
//! None of this runs under QEMU (it models neither the RCC/PLL nor the IWDG).
//! The drivers are tested on the host with embedded-hal-mock
//! (`cargo test -p limiter-drivers`); the limiter code this loop calls is the
//! code the QEMU replay runs; this file is built in CI
//! (`--no-default-features --features board`) so it cannot rot.
#![allow(unsafe_code)] // The panic path writes GPIO registers directly (see SAFETY notes).

use crate::selftest::{self, Failure};
use defmt_rtt as _; // defmt transport on the board: RTT, read by probe-rs.
use embedded_hal_bus::spi::ExclusiveDevice;
use limiter_drivers::{AlarmOutputs, ChannelMap, Mcp3208, Polarity};
use limiter_storage::calibration_blob::load_calibration;
use limiter_storage::event::{EventKind, EventRecord};
use limiter_storage::event_queue::{record_of, EventQueue, Flushed};
use limiter_storage::journal::JournalError;
use limiter_storage::latch::{self, Acknowledge, FaultKind, LatchState, ResetCause};
use limiter_storage::store::{Layout, Store};
use moment_limiter::clock::{ClockConfig, Ticks};
use moment_limiter::conversion::SensorConversion;
use moment_limiter::io::{Channel, OutputCommand, Outputs, SensorInputs};
use moment_limiter::cycle::{Limiter, LimiterConfig};
use stm32f4xx_hal::{
    flash::{FlashExt, LockedFlash},
    gpio::{Input, Output, Pin, PinState},
    pac,
    prelude::*,
    rcc::Config,
    spi::{Mode, Phase, Polarity as SpiPolarity, Spi},
    timer::CounterHz,
    watchdog::IndependentWatchdog,
};

/// Control period (µs): 100 Hz, the limiter clock's nominal period.
const PERIOD_US: u32 = ClockConfig::standard().period_us;
/// Events the RAM queue holds between flushes (16 bytes each, on the stack
/// of `run`); when full it keeps the first half and the latest.
const EVENT_QUEUE_LEN: usize = 32;
/// Most events written in one cycle: a record is 24 bytes of flash, about
/// 0.4 ms of byte programming (16 µs a byte), so 4 take ≈ 1.6 ms of the
/// 10 ms period, in a cycle whose motions are cut anyway.
const FLUSH_PER_CYCLE: usize = 4;
/// Events of one run that can be persisted without an erase: start-up makes
/// this much room (compacting the event log then if needed).
const EVENT_RESERVE: u32 = 1024;
/// GPIOC pins of the outputs (see the wiring table).
const WARNING_PIN: u32 = 0;
const ALARM_PIN: u32 = 1;
const PERMIT_DOWN_PIN: u32 = 2;
const PERMIT_HOIST_PIN: u32 = 3;

type Adc =
    Mcp3208<ExclusiveDevice<Spi<pac::SPI1>, Pin<'A', 4, Output>, embedded_hal_bus::spi::NoDelay>>;
type Outs = AlarmOutputs<
    Pin<'C', 0, Output>,
    Pin<'C', 1, Output>,
    Pin<'C', 2, Output>,
    Pin<'C', 3, Output>,
>;

/// The initialised hardware the control loop uses.
struct Hardware {
    adc: Adc,
    outputs: Outs,
    tick: CounterHz<pac::TIM2>,
    /// Not started yet: `run` starts it after the start-up sequence.
    watchdog: IndependentWatchdog,
    /// The fault acknowledge key switch (pressed = low).
    acknowledge: Pin<'C', 4, Input>,
}

/// Why the hardware could not be brought up.
#[derive(Debug, defmt::Format)]
enum InitError {
    Peripherals,
    Outputs,
    ChipSelect,
    Timer,
}

/// Hardware initialisation only: clocks, pins, SPI, outputs (driven to the
/// fail-safe state first), the 100 Hz timer and the watchdog.
fn init() -> Result<(Hardware, LockedFlash), InitError> {
    let dp = pac::Peripherals::take().ok_or(InitError::Peripherals)?;
    let mut rcc = dp.RCC.freeze(Config::hse(8.MHz()).sysclk(168.MHz()));
    let gpioa = dp.GPIOA.split(&mut rcc);
    let gpioc = dp.GPIOC.split(&mut rcc);

    // Outputs first, and in the fail-safe state from the first instant they drive.
    let outputs = AlarmOutputs::new(
        gpioc.pc0.into_push_pull_output_in_state(PinState::High),
        gpioc.pc1.into_push_pull_output_in_state(PinState::High),
        gpioc.pc2.into_push_pull_output_in_state(PinState::Low),
        gpioc.pc3.into_push_pull_output_in_state(PinState::Low),
        Polarity::ActiveHigh,
    )
    .map_err(|_| InitError::Outputs)?;

    let mode = Mode {
        polarity: SpiPolarity::IdleLow,
        phase: Phase::CaptureOnFirstTransition,
    };
    let spi = dp.SPI1.spi(
        (Some(gpioa.pa5), Some(gpioa.pa6), Some(gpioa.pa7)),
        mode,
        1.MHz(),
        &mut rcc,
    );
    let cs = gpioa.pa4.into_push_pull_output_in_state(PinState::High);
    let device = ExclusiveDevice::new_no_delay(spi, cs).map_err(|_| InitError::ChipSelect)?;
    let adc = Mcp3208::new(device, ChannelMap::REFERENCE_BOARD);

    let mut tick = dp.TIM2.counter_hz(&mut rcc);
    tick.start(100.Hz()).map_err(|_| InitError::Timer)?;

    let acknowledge = gpioc.pc4.into_pull_up_input();
    let watchdog = IndependentWatchdog::new(dp.IWDG);

    let hw = Hardware {
        adc,
        outputs,
        tick,
        watchdog,
        acknowledge,
    };
    Ok((hw, LockedFlash::new(dp.FLASH)))
}

/// Reads and clears the reset flags of `RCC_CSR` and the RAM fault record.
fn read_reset_cause() -> ResetCause {
    // SAFETY: RCC_CSR is read, then written with its own value plus RMVF,
    // which only clears the reset flags; nothing else uses RCC_CSR before
    // `init` (which does not touch it).
    let csr = unsafe {
        let rcc = &*pac::RCC::ptr();
        let value = rcc.csr().read().bits();
        rcc.csr().write(|w| w.bits(value | latch::csr::RMVF));
        value
    };
    latch::reset_cause(csr, crate::fault::take_record())
}

/// Offsets of the persisted stores in the flash device (from `memory.x`).
fn storage_layout() -> Layout {
    extern "C" {
        static _settings_flash_start: u8;
        static _settings_flash_end: u8;
        static _events_flash_start: u8;
        static _events_flash_end: u8;
    }
    const FLASH_BASE: usize = 0x0800_0000;
    let offset = |p: *const u8| (p as usize).saturating_sub(FLASH_BASE) as u32;
    Layout {
        settings: offset(core::ptr::addr_of!(_settings_flash_start))
            ..offset(core::ptr::addr_of!(_settings_flash_end)),
        events: offset(core::ptr::addr_of!(_events_flash_start))
            ..offset(core::ptr::addr_of!(_events_flash_end)),
    }
}

/// The MCU's flash for the persisted store: stm32f4xx-hal's `NorFlash`
/// programs and erases, the flash unlocked for each operation only (so it is
/// locked whenever the store is not writing); reads are done here,
/// bounds-checked, because the HAL's read slices the flash with a panicking
/// index.
struct BoardFlash(LockedFlash);

impl limiter_storage::journal::Flash for BoardFlash {
    fn read(&mut self, at: u32, buf: &mut [u8]) -> Result<(), JournalError> {
        const FLASH_BASE: usize = 0x0800_0000;
        const FLASH_LEN: usize = 1024 * 1024;
        let start = at as usize;
        match start.checked_add(buf.len()) {
            Some(end) if end <= FLASH_LEN => {
                // SAFETY: [FLASH_BASE + start, FLASH_BASE + end) lies inside
                // the 1 MiB flash, always mapped and readable; the store only
                // reads ranges it owns, which nothing programs concurrently.
                unsafe {
                    core::ptr::copy_nonoverlapping(
                        (FLASH_BASE + start) as *const u8,
                        buf.as_mut_ptr(),
                        buf.len(),
                    );
                }
                Ok(())
            }
            _ => Err(JournalError::Flash),
        }
    }

    fn write(&mut self, at: u32, buf: &[u8]) -> Result<(), JournalError> {
        // Locked again when `unlocked` is dropped, at the end of the call.
        embedded_storage::nor_flash::NorFlash::write(&mut self.0.unlocked(), at, buf)
            .map_err(|_| JournalError::Flash)
    }

    fn erase(&mut self, from: u32, to: u32) -> Result<(), JournalError> {
        embedded_storage::nor_flash::NorFlash::erase(&mut self.0.unlocked(), from, to)
            .map_err(|_| JournalError::Flash)
    }

    fn geometry(&self) -> (usize, usize, usize) {
        use embedded_storage::nor_flash::{NorFlash, ReadNorFlash};
        use stm32f4xx_hal::flash::UnlockedFlash as U;
        (
            <U as ReadNorFlash>::READ_SIZE,
            <U as NorFlash>::WRITE_SIZE,
            <U as NorFlash>::ERASE_SIZE,
        )
    }
}

/// Appends an event (start-up only: it may erase); a failure is logged, not
/// fatal (the outputs stay cut where the event mattered).
fn log_event(
    store: &mut Store<BoardFlash>,
    boot: u32,
    kind: EventKind,
    detail: u8,
    value: u32,
    uptime_ms: u32,
) {
    let record = EventRecord {
        boot,
        kind,
        detail,
        value,
        uptime_ms,
    };
    if let Err(e) = store.append_event(&record) {
        defmt::error!("event log: {=str}", e.as_str());
    }
}

/// Holds the outputs cut, with the alarm on, until the acknowledge key is
/// seen released and then held for `latch::ACK_HOLD_MS` (100 Hz sampling).
/// Returns the milliseconds waited.
fn wait_for_acknowledgement(hw: &mut Hardware) -> u32 {
    let mut ack = Acknowledge::new();
    let mut waited_ms: u32 = 0;
    loop {
        let _ = hw.outputs.apply(OutputCommand::FAIL_SAFE);
        let _ = nb::block!(hw.tick.wait());
        waited_ms = waited_ms.saturating_add(10);
        if ack.update(hw.acknowledge.is_low(), 10) {
            return waited_ms;
        }
    }
}

/// Output readback: with the fail-safe command applied, GPIOC's output data
/// register and the pins themselves must read warning and alarm high and both
/// permits low. A pin shorted to a rail, or a driver the HAL did not set,
/// shows as a difference.
fn outputs_read_back() -> Result<(), Failure> {
    let expected = (1 << WARNING_PIN) | (1 << ALARM_PIN);
    let mask = expected | (1 << PERMIT_DOWN_PIN) | (1 << PERMIT_HOIST_PIN);
    // SAFETY: reads of GPIOC's ODR and IDR have no side effects.
    let (odr, idr) = unsafe {
        let gpioc = &*pac::GPIOC::ptr();
        (gpioc.odr().read().bits(), gpioc.idr().read().bits())
    };
    let mismatch = ((odr ^ expected) | (idr ^ expected)) & mask;
    if mismatch == 0 {
        Ok(())
    } else {
        Err(Failure::Outputs { mismatch })
    }
}

/// Sensor plausibility: the first reading of each channel converts to a value
/// in its physical range (a broken wire or a short does not).
fn sensors_plausible(adc: &mut Adc, conv: &SensorConversion<f32>) -> Result<(), Failure> {
    for (i, channel) in Channel::ALL.into_iter().enumerate() {
        let counts = adc
            .read_counts(channel)
            .map_err(|_| Failure::Sensors { channel: i as u8 })?;
        let ok = match channel {
            Channel::PistonSidePressure => conv.pressure(&conv.p1, counts).is_ok(),
            Channel::RodSidePressure => conv.pressure(&conv.p2, counts).is_ok(),
            Channel::BoomAngle => conv.boom_angle(counts).is_ok(),
        };
        if !ok {
            return Err(Failure::Sensors { channel: i as u8 });
        }
    }
    Ok(())
}

/// Keeps the outputs cut forever (until a reset), feeding nothing.
fn stay_cut(hw: &mut Hardware) -> ! {
    loop {
        let _ = hw.outputs.apply(OutputCommand::FAIL_SAFE);
        let _ = nb::block!(hw.tick.wait());
    }
}

/// Boots (see the module notes) and runs the 100 Hz control loop forever.
pub fn run() -> ! {
    // Before anything else: whatever the pins did, cut (GPIOC may still be
    // unclocked after reset, then the pins float and the relays drop anyway).
    cut_outputs_now();
    let cause = read_reset_cause();
    let (mut hw, locked_flash) = match init() {
        Ok(parts) => parts,
        Err(e) => {
            defmt::error!("hardware init failed: {}", e);
            cut_outputs_now();
            halt_waiting_for_watchdog()
        }
    };
    let Some(mut core) = cortex_m::Peripherals::take() else {
        cut_outputs_now();
        halt_waiting_for_watchdog()
    };
    defmt::warn!("reset cause: {}", cause.as_str());

    let mut config = LimiterConfig::<f32>::standard();
    // Kept for the whole run: the loop appends the queued events (programs
    // only, never an erase) while no motion is granted.
    let mut store = Store::new(BoardFlash(locked_flash), storage_layout());
    let boot = store.next_boot().unwrap_or(0);
    {
        log_event(&mut store, boot, EventKind::Boot, cause.code(), 0, 0);
        // An unreadable latch is a latched one: the limiter cannot vouch for it.
        let before = store.latch().unwrap_or_else(|e| {
            defmt::error!("fault latch unreadable: {=str}", e.as_str());
            LatchState {
                active: true,
                cause: 0xFE,
                count: 0,
            }
        });
        let latch = before.after_reset(cause);
        if latch != before {
            if let Err(e) = store.set_latch(latch) {
                defmt::error!("fault latch not persisted: {=str}", e.as_str());
            }
        }
        if latch.active {
            log_event(
                &mut store,
                boot,
                EventKind::FaultLatched,
                latch.cause,
                latch.count,
                0,
            );
            defmt::error!(
                "outputs latched cut after a fault reset (cause code {}, {} so far): hold the acknowledge key 3 s",
                latch.cause,
                latch.count
            );
            let waited_ms = wait_for_acknowledgement(&mut hw);
            if let Err(e) = store.set_latch(latch.acknowledged()) {
                defmt::error!("acknowledgement not persisted: {=str}", e.as_str());
            }
            log_event(
                &mut store,
                boot,
                EventKind::Acknowledged,
                latch.cause,
                latch.count,
                waited_ms,
            );
            defmt::warn!("fault acknowledged");
        }
        // The stored calibration (`calibration-image` makes it from a
        // validated CAL.json), checked against the schema's bounds. Without
        // a good one the limiter cannot vouch for its load estimate: no
        // motion is granted, and the reason is in the event log.
        match load_calibration::<f32, _>(&mut store) {
            Ok((calibration, crc)) => {
                config.calibration = calibration;
                log_event(&mut store, boot, EventKind::CalibrationApplied, 0, crc, 0);
                defmt::info!("calibration applied (blob crc32 {=u32:08x})", crc);
            }
            Err(e) => {
                log_event(
                    &mut store,
                    boot,
                    EventKind::CalibrationRefused,
                    e.code(),
                    e.detail(),
                    0,
                );
                defmt::error!(
                    "calibration refused ({=str}, detail {=u32}): no motion granted",
                    e.as_str(),
                    e.detail()
                );
                stay_cut(&mut hw)
            }
        }
        // Room for this run's events, so that no flush during operation
        // ever needs an erase (made now, before the watchdog runs).
        if let Err(e) = store.reserve_events(EVENT_RESERVE) {
            defmt::error!("event log: {=str}", e.as_str());
        }

        // Power-up self-test, outputs cut.
        let (result, cycles) = selftest::measure(&mut core.SYST, || {
            selftest::run_common(false)?;
            outputs_read_back()?;
            sensors_plausible(&mut hw.adc, &config.conversion)
        });
        match result {
            Ok(()) => {
                log_event(&mut store, boot, EventKind::SelfTestPassed, 0, cycles, 0);
                defmt::info!("self-test passed in {} cycles", cycles);
            }
            Err(failure) => {
                log_event(
                    &mut store,
                    boot,
                    EventKind::SelfTestFailed,
                    failure.code(),
                    0,
                    0,
                );
                defmt::error!(
                    "self-test failed: check {} (1 RAM, 2 image, 3 model, 4 outputs, 5 sensors), detail 0x{:x}",
                    failure.code(),
                    failure.detail()
                );
                stay_cut(&mut hw)
            }
        }
    }

    let mut limiter = match Limiter::new(crate::model::hook_load_model(), config) {
        Ok(limiter) => limiter,
        Err(e) => {
            // Not `Display2Format`: core::fmt's padding code costs 2 KB of
            // the board's flash budget; the reason is in the debug build's logs.
            let _ = e;
            defmt::error!("limiter configuration refused");
            stay_cut(&mut hw)
        }
    };
    // Fail-safe until the first cycle decides otherwise.
    let _ = limiter.power_up(&mut hw.outputs);
    hw.watchdog.start(50.millis());
    defmt::info!("limiter up, 100 Hz");

    let mut cycle: u32 = 0;
    let mut previous = limiter.state();
    let mut queue = EventQueue::<EVENT_QUEUE_LEN>::new();
    loop {
        let _ = nb::block!(hw.tick.wait());
        // Integer time (moment_limiter::clock): the cycle count in µs,
        // wrapping every 71.6 min, which the limiter's wrap-safe differences
        // make harmless; never an absolute float.
        let now = Ticks::from_cycle(cycle, PERIOD_US);
        let report = limiter.cycle(now, &mut hw.adc, &mut hw.outputs);
        if report.state != previous {
            defmt::warn!("cycle {} state {}", cycle, report.state.as_str());
            previous = report.state;
        }
        // The cycle's events into the RAM queue; to flash only in a cycle
        // whose outputs grant no motion, a few records at a time, never an
        // erase (`limiter_storage::event_queue`).
        let uptime_ms = cycle.wrapping_mul(PERIOD_US / 1000);
        while let Some(event) = limiter.events_mut().pop_oldest() {
            if let Some(record) = record_of(&event, boot, uptime_ms) {
                queue.push(record);
            }
        }
        if !queue.is_empty() || queue.dropped() > 0 {
            match queue.flush(
                &mut store,
                &report.command,
                FLUSH_PER_CYCLE,
                boot,
                uptime_ms,
            ) {
                Ok(Flushed::NeedsErase(_)) => {
                    defmt::warn!("event log full until the next start-up")
                }
                Ok(_) => {}
                Err(e) => defmt::error!("event log: {=str}", e.as_str()),
            }
        }
        // Overrun: the next tick already came while we were working.
        if hw.tick.wait().is_ok() {
            defmt::error!("control cycle overran 10 ms at cycle {}", cycle);
        }
        hw.watchdog.feed();
        cycle = cycle.wrapping_add(1);
    }
}

/// Drives the outputs to the cut-off state by writing GPIOC directly, without
/// the HAL objects (which the panicking code may own): permit relays
/// de-energised (motions cut), warning lamp and overload alarm on.
pub fn cut_outputs_now() {
    let set = (1 << WARNING_PIN) | (1 << ALARM_PIN);
    let reset = (1 << PERMIT_DOWN_PIN) | (1 << PERMIT_HOIST_PIN);
    // SAFETY: BSRR is a write-only set/reset register: one write changes only
    // the four named pins, atomically, whatever the HAL believes their state is.
    // Called with interrupts disabled from the panic handler or before the
    // limiter runs, so nothing else drives these pins concurrently.
    unsafe {
        (*pac::GPIOC::ptr())
            .bsrr()
            .write(|w| w.bits(set | (reset << 16)));
    }
}

/// Makes sure the watchdog runs (start key; harmless if it already does) and
/// waits for it to reset the MCU, re-cutting the outputs meanwhile.
fn halt_waiting_for_watchdog() -> ! {
    const KR_START: u16 = 0xCCCC;
    // SAFETY: writing the start key to IWDG_KR only starts the independent
    // watchdog (it cannot be stopped again); no other state is touched.
    unsafe {
        (*pac::IWDG::ptr()).kr().write(|w| w.bits(KR_START));
    }
    loop {
        cut_outputs_now();
        cortex_m::asm::nop();
    }
}

/// After a panic (outputs already cut): wait for the watchdog reset.
pub fn halt_after_panic(_info: &core::panic::PanicInfo) -> ! {
    halt_waiting_for_watchdog()
}

/// After a fault exception (outputs already cut, record written): log, then
/// wait for the watchdog reset; start-up will latch the outputs cut.
pub fn halt_after_fault(kind: FaultKind, detail: u32) -> ! {
    defmt::error!("fault: {} at 0x{:08x}; outputs cut", kind.as_str(), detail);
    halt_waiting_for_watchdog()
}
