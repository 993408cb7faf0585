//! The limiter driven through the real drivers (embedded-hal-mock underneath):
//! a bus that dies must put the limiter in FAULT with the motions cut, and an
//! output pin that fails must too.

use embedded_hal::digital::{ErrorType as PinErrorType, OutputPin};
use embedded_hal::spi::{ErrorKind, ErrorType, Operation, SpiDevice};
use embedded_hal_mock::eh1::spi::{Mock as SpiMock, Transaction};
use limiter_drivers::{AlarmOutputs, ChannelMap, Mcp3208, Polarity};
use moment_limiter::checks::FaultKind;
use moment_limiter::io::{Channel, InputError, OutputCommand, OutputError, Outputs};
use moment_limiter::clock::Ticks;
use moment_limiter::cycle::{Limiter, LimiterConfig};
use moment_limiter::fault::Fault;
use moment_limiter::testing::rigid_reference::RigidCrane;
use moment_limiter::state_machine::LimiterState;

/// Works for `good` transactions (checked by the mock), then fails them all.
struct DyingBus {
    inner: SpiMock<u8>,
    good: usize,
}

impl ErrorType for DyingBus {
    type Error = ErrorKind;
}

impl SpiDevice for DyingBus {
    fn transaction(&mut self, operations: &mut [Operation<'_, u8>]) -> Result<(), ErrorKind> {
        if self.good == 0 {
            return Err(ErrorKind::Other);
        }
        self.good -= 1;
        self.inner
            .transaction(operations)
            .map_err(|_| ErrorKind::Other)
    }
}

/// Records what the limiter commands.
#[derive(Default)]
struct Recorder(Vec<OutputCommand>);

impl Outputs for Recorder {
    fn apply(&mut self, command: OutputCommand) -> Result<(), OutputError> {
        self.0.push(command);
        Ok(())
    }
}

fn frame(input: u8, counts: u16) -> Vec<Transaction<u8>> {
    let command = limiter_drivers::AdcChannel::new(input).unwrap().command();
    vec![
        Transaction::transaction_start(),
        Transaction::transfer_in_place(
            command.to_vec(),
            vec![0, (counts >> 8) as u8 & 0x0F, counts as u8],
        ),
        Transaction::transaction_end(),
    ]
}

/// Transactions of `cycles` cycles reading p1 = 80 bar, p2 = 5 bar, 45°.
fn steady_cycles(config: &LimiterConfig<f64>, cycles: usize) -> Vec<Transaction<u8>> {
    let conv = &config.conversion;
    let p1 = conv.counts_for_pressure(&conv.p1, 80.0);
    let p2 = conv.counts_for_pressure(&conv.p2, 5.0);
    let angle = conv.angle.counts(45.0);
    let map = ChannelMap::REFERENCE_BOARD;
    let mut t = Vec::new();
    for _ in 0..cycles {
        t.extend(frame(map.piston_side_pressure.number(), p1));
        t.extend(frame(map.rod_side_pressure.number(), p2));
        t.extend(frame(map.boom_angle.number(), angle));
    }
    t
}

#[test]
fn a_dying_spi_bus_puts_the_limiter_in_fault_and_cuts() {
    let config = LimiterConfig::<f64>::standard();
    let good_cycles = 50;
    let bus = DyingBus {
        inner: SpiMock::new(&steady_cycles(&config, good_cycles)),
        good: 3 * good_cycles,
    };
    let mut adc = Mcp3208::new(bus, ChannelMap::REFERENCE_BOARD);
    let mut outputs = Recorder::default();
    let mut limiter = Limiter::new(RigidCrane::coles_930(), config).unwrap();
    limiter.power_up(&mut outputs).unwrap();

    let mut t = Ticks(0);
    for _ in 0..good_cycles {
        let report = limiter.cycle(t, &mut adc, &mut outputs);
        assert_ne!(
            report.state,
            LimiterState::Fault,
            "good readings: {report:?}"
        );
        t = t.wrapping_add_micros(10_000);
    }
    assert!(!outputs.0.last().unwrap().cut_boom_down);

    let report = limiter.cycle(t, &mut adc, &mut outputs);
    assert_eq!(report.state, LimiterState::Fault);
    assert!(matches!(
        report.fault,
        Some(Fault::Sensor(s)) if s.channel == Channel::PistonSidePressure
            && s.kind == FaultKind::Input(InputError::Bus)
    ));
    let last = *outputs.0.last().unwrap();
    assert!(last.cut_boom_down && last.cut_hoist_up && last.overload_alarm);
    adc.release().inner.done();
}

#[derive(Debug)]
struct PinBroke;

impl embedded_hal::digital::Error for PinBroke {
    fn kind(&self) -> embedded_hal::digital::ErrorKind {
        embedded_hal::digital::ErrorKind::Other
    }
}

/// A pin whose writes fail after `good` writes; remembers the last level.
struct BreakingPin {
    good: usize,
    level: Option<bool>,
}

impl PinErrorType for BreakingPin {
    type Error = PinBroke;
}

impl OutputPin for BreakingPin {
    fn set_low(&mut self) -> Result<(), PinBroke> {
        self.set(false)
    }
    fn set_high(&mut self) -> Result<(), PinBroke> {
        self.set(true)
    }
}

impl BreakingPin {
    fn set(&mut self, level: bool) -> Result<(), PinBroke> {
        if self.good == 0 {
            return Err(PinBroke);
        }
        self.good -= 1;
        self.level = Some(level);
        Ok(())
    }
}

#[test]
fn a_failing_output_pin_faults_the_limiter_and_leaves_the_relays_de_energised() {
    let config = LimiterConfig::<f64>::standard();
    let cycles = 30;
    let bus = DyingBus {
        inner: SpiMock::new(&steady_cycles(&config, cycles)),
        good: 3 * cycles,
    };
    let mut adc = Mcp3208::new(bus, ChannelMap::REFERENCE_BOARD);
    // The warning lamp pin breaks after a few writes; the relay pins work.
    let outputs = AlarmOutputs::new(
        BreakingPin {
            good: 12,
            level: None,
        },
        BreakingPin {
            good: usize::MAX,
            level: None,
        },
        BreakingPin {
            good: usize::MAX,
            level: None,
        },
        BreakingPin {
            good: usize::MAX,
            level: None,
        },
        Polarity::ActiveHigh,
    );
    let mut outputs = outputs.map_err(|_| ()).unwrap();
    let mut limiter = Limiter::new(RigidCrane::coles_930(), config).unwrap();
    limiter.power_up(&mut outputs).unwrap();
    let mut states = Vec::new();
    for i in 0..cycles {
        states.push(limiter.cycle(Ticks::from_cycle(i as u32, 10_000), &mut adc, &mut outputs).state);
    }
    assert_eq!(states.last(), Some(&LimiterState::Fault), "{states:?}");
    let (_, _, down, hoist) = outputs.release();
    assert_eq!(
        down.level,
        Some(false),
        "boom-down relay must be de-energised"
    );
    assert_eq!(
        hoist.level,
        Some(false),
        "hoist-up relay must be de-energised"
    );
    adc.release().inner.done();
}
