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
//!
//! ADC channels: p1 on CH0, p2 on CH1, boom angle on CH2
//! (`ChannelMap::REFERENCE_BOARD`). Clocks: 8 MHz HSE → 168 MHz SYSCLK. TIM2
//! ticks the 100 Hz control loop; the IWDG (50 ms, five missed cycles) resets
//! the MCU if the loop stalls. Relay drivers need pull-downs so a reset MCU
//! (pins floating) leaves the relays de-energised: cut.
//!
//! None of this runs under QEMU (it models neither the RCC/PLL nor the IWDG).
//! The drivers are tested on the host with embedded-hal-mock
//! (`cargo test -p limiter-drivers`); the limiter code this loop calls is the
//! code the QEMU replay runs; this file is built in CI
//! (`--no-default-features --features board`) so it cannot rot.
#![allow(unsafe_code)] // The panic path writes GPIO registers directly (see SAFETY notes).

use defmt_rtt as _; // defmt transport on the board: RTT, read by probe-rs.
use embedded_hal_bus::spi::ExclusiveDevice;
use limiter_drivers::{AlarmOutputs, ChannelMap, Mcp3208, Polarity};
use moment_limiter::clock::{ClockConfig, Ticks};
use moment_limiter::io::{OutputCommand, Outputs};
use moment_limiter::limiter::{Limiter, LimiterConfig};
use stm32f4xx_hal::{
    gpio::{Output, Pin, PinState},
    pac,
    prelude::*,
    rcc::Config,
    spi::{Mode, Phase, Polarity as SpiPolarity, Spi},
    timer::CounterHz,
    watchdog::IndependentWatchdog,
};

/// Control period (µs): 100 Hz, the limiter clock's nominal period.
const PERIOD_US: u32 = ClockConfig::standard().period_us;
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
    watchdog: IndependentWatchdog,
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
fn init() -> Result<Hardware, InitError> {
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

    let mut watchdog = IndependentWatchdog::new(dp.IWDG);
    watchdog.start(50.millis());

    Ok(Hardware {
        adc,
        outputs,
        tick,
        watchdog,
    })
}

/// Boots and runs the 100 Hz control loop forever.
pub fn run() -> ! {
    let mut hw = match init() {
        Ok(hw) => hw,
        Err(e) => {
            defmt::error!("hardware init failed: {}", e);
            cut_outputs_now();
            // Let the watchdog (if it was started) reset us; outputs stay cut.
            loop {
                cortex_m::asm::wfi();
            }
        }
    };

    let mut limiter = match Limiter::new(crate::model::hook_load_model(), LimiterConfig::standard())
    {
        Ok(limiter) => limiter,
        Err(e) => {
            defmt::error!(
                "limiter configuration refused: {}",
                defmt::Display2Format(&e)
            );
            // Stay cut with the alarm on; keep feeding the watchdog so the
            // lamps do not flicker through reset cycles.
            loop {
                let _ = hw.outputs.apply(OutputCommand::FAIL_SAFE);
                let _ = nb::block!(hw.tick.wait());
                hw.watchdog.feed();
            }
        }
    };
    // Lamp test and fail-safe until the first cycle (the power-up self-test).
    let _ = limiter.power_up(&mut hw.outputs);
    defmt::info!("limiter up, 100 Hz");

    let mut cycle: u32 = 0;
    let mut previous = limiter.state();
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

/// After a panic: make sure the watchdog runs (start key; harmless if it
/// already does) and wait for it to reset the MCU. Outputs stay cut.
pub fn halt_after_panic(_info: &core::panic::PanicInfo) -> ! {
    const KR_START: u16 = 0xCCCC;
    // SAFETY: writing the start key to IWDG_KR only starts the independent
    // watchdog (it cannot be stopped again); no other state is touched.
    unsafe {
        (*pac::IWDG::ptr()).kr().write(|w| w.bits(KR_START));
    }
    loop {
        cortex_m::asm::nop();
    }
}
