//! MCP3208-style 12-bit SPI ADC (8 single-ended channels), embedded-hal 1.0.
//!
//! One conversion is one SPI transaction of three bytes (MCP3208 datasheet,
//! "Using the MCP3204/3208 with microcontroller SPI ports", SPI mode 0 or 3,
//! chip select handled by the [`SpiDevice`]):
//!
//! ```text
//! MOSI  byte 0: 0 0 0 0 0 START=1 SGL/DIFF=1 D2      byte 1: D1 D0 x x x x x x   byte 2: x…
//! MISO  byte 0: (high-Z)                             byte 1: ? ? ? NULL=0 B11..B8 byte 2: B7..B0
//! ```
//!
//! The converter drives a null bit (0) just before the MSB of the result; a frame
//! whose null bit reads 1 (a floating or shorted MISO line, a converter that is not
//! there) is rejected as [`InputError::BadFrame`] rather than passed on as a
//! plausible-looking count. A failed bus transaction is [`InputError::Bus`]. Either
//! way the limiter treats the channel as faulted (FAULT state, motions cut).

use embedded_hal::spi::SpiDevice;
use moment_limiter::io::{Channel, InputError, SensorInputs};

/// One single-ended input of the converter, 0..=7. Cannot hold an invalid number.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct AdcChannel(u8);

impl AdcChannel {
    /// The channel `n` of the converter, or `None` if `n > 7`.
    pub const fn new(n: u8) -> Option<Self> {
        if n <= 7 {
            Some(AdcChannel(n))
        } else {
            None
        }
    }

    /// The channel number, 0..=7.
    pub const fn number(self) -> u8 {
        self.0
    }

    /// The three command bytes that start a single-ended conversion on this channel.
    pub const fn command(self) -> [u8; 3] {
        const START: u8 = 0b100;
        const SINGLE_ENDED: u8 = 0b010;
        [
            START | SINGLE_ENDED | (self.0 >> 2),
            (self.0 & 0b11) << 6,
            0x00,
        ]
    }
}

/// Which converter input each limiter channel is wired to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ChannelMap {
    /// Input of p1 (piston-side pressure, 4–20 mA through a shunt).
    pub piston_side_pressure: AdcChannel,
    /// Input of p2 (rod-side pressure, 4–20 mA through a shunt).
    pub rod_side_pressure: AdcChannel,
    /// Input of the pendulum potentiometer (boom angle, ratiometric).
    pub boom_angle: AdcChannel,
}

impl ChannelMap {
    /// The reference board's wiring: p1 on CH0, p2 on CH1, boom angle on CH2.
    pub const REFERENCE_BOARD: ChannelMap = ChannelMap {
        piston_side_pressure: AdcChannel(0),
        rod_side_pressure: AdcChannel(1),
        boom_angle: AdcChannel(2),
    };

    /// The converter input of a limiter channel.
    pub const fn input(&self, channel: Channel) -> AdcChannel {
        match channel {
            Channel::PistonSidePressure => self.piston_side_pressure,
            Channel::RodSidePressure => self.rod_side_pressure,
            Channel::BoomAngle => self.boom_angle,
        }
    }
}

impl Default for ChannelMap {
    fn default() -> Self {
        Self::REFERENCE_BOARD
    }
}

/// Decodes the three bytes clocked in during a conversion into a 12-bit count.
///
/// Returns [`InputError::BadFrame`] if the converter's null bit is not 0.
pub const fn decode_frame(rx: [u8; 3]) -> Result<u16, InputError> {
    const NULL_BIT: u8 = 0b0001_0000;
    if rx[1] & NULL_BIT != 0 {
        return Err(InputError::BadFrame);
    }
    Ok((((rx[1] & 0x0F) as u16) << 8) | rx[2] as u16)
}

/// An MCP3208 (or MCP3204 on channels 0..=3) on an embedded-hal 1.0 SPI device.
#[derive(Debug)]
pub struct Mcp3208<SPI> {
    spi: SPI,
    map: ChannelMap,
}

impl<SPI: SpiDevice> Mcp3208<SPI> {
    /// A converter on `spi` (which owns chip select), wired as `map` says.
    pub fn new(spi: SPI, map: ChannelMap) -> Self {
        Mcp3208 { spi, map }
    }

    /// The wiring this driver uses.
    pub fn channel_map(&self) -> ChannelMap {
        self.map
    }

    /// Gives the SPI device back.
    pub fn release(self) -> SPI {
        self.spi
    }

    /// One single-ended conversion on converter input `input`: 0..=4095.
    pub fn read_input(&mut self, input: AdcChannel) -> Result<u16, InputError> {
        let mut frame = input.command();
        self.spi
            .transfer_in_place(&mut frame)
            .map_err(|_| InputError::Bus)?;
        decode_frame(frame)
    }
}

impl<SPI: SpiDevice> SensorInputs for Mcp3208<SPI> {
    fn read_counts(&mut self, channel: Channel) -> Result<u16, InputError> {
        self.read_input(self.map.input(channel))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use embedded_hal::spi::ErrorKind;
    use embedded_hal_mock::eh1::spi::{Mock as SpiMock, Transaction};

    /// The transactions of one conversion on `input` answered with `rx`.
    fn conversion(input: u8, rx: [u8; 3]) -> Vec<Transaction<u8>> {
        vec![
            Transaction::transaction_start(),
            Transaction::transfer_in_place(
                AdcChannel::new(input).unwrap().command().to_vec(),
                rx.to_vec(),
            ),
            Transaction::transaction_end(),
        ]
    }

    #[test]
    fn command_bytes_follow_the_datasheet() {
        assert_eq!(AdcChannel::new(0).unwrap().command(), [0x06, 0x00, 0x00]);
        assert_eq!(AdcChannel::new(1).unwrap().command(), [0x06, 0x40, 0x00]);
        assert_eq!(AdcChannel::new(3).unwrap().command(), [0x06, 0xC0, 0x00]);
        assert_eq!(AdcChannel::new(4).unwrap().command(), [0x07, 0x00, 0x00]);
        assert_eq!(AdcChannel::new(7).unwrap().command(), [0x07, 0xC0, 0x00]);
        assert_eq!(AdcChannel::new(8), None);
    }

    #[test]
    fn decodes_twelve_bits_and_ignores_undriven_bits() {
        assert_eq!(decode_frame([0xFF, 0x0A, 0xBC]), Ok(0xABC));
        assert_eq!(decode_frame([0x00, 0xE0, 0x00]), Ok(0));
        assert_eq!(decode_frame([0x00, 0x0F, 0xFF]), Ok(4095));
        assert_eq!(decode_frame([0x00, 0x1F, 0xFF]), Err(InputError::BadFrame));
    }

    #[test]
    fn reads_each_limiter_channel_from_its_mapped_input() {
        let map = ChannelMap {
            piston_side_pressure: AdcChannel::new(5).unwrap(),
            rod_side_pressure: AdcChannel::new(2).unwrap(),
            boom_angle: AdcChannel::new(7).unwrap(),
        };
        let mut expected = Vec::new();
        expected.extend(conversion(5, [0, 0x08, 0x00])); // 2048
        expected.extend(conversion(2, [0, 0x03, 0x33])); // 819 (4 mA on 250 Ω / 5 V)
        expected.extend(conversion(7, [0, 0x0F, 0xFF])); // 4095
        let mut adc = Mcp3208::new(SpiMock::new(&expected), map);
        assert_eq!(adc.read_counts(Channel::PistonSidePressure), Ok(2048));
        assert_eq!(adc.read_counts(Channel::RodSidePressure), Ok(819));
        assert_eq!(adc.read_counts(Channel::BoomAngle), Ok(4095));
        adc.release().done();
    }

    /// A bus that works for `good` transactions (checked by the wrapped mock) and
    /// then fails every transaction, like a broken SCK wire or a dead converter.
    /// embedded-hal-mock 0.11's SPI mock cannot inject errors itself.
    struct DyingBus<S> {
        inner: S,
        good: usize,
    }

    impl<S: embedded_hal::spi::ErrorType> embedded_hal::spi::ErrorType for DyingBus<S> {
        type Error = ErrorKind;
    }

    impl<S: SpiDevice> SpiDevice for DyingBus<S> {
        fn transaction(
            &mut self,
            operations: &mut [embedded_hal::spi::Operation<'_, u8>],
        ) -> Result<(), ErrorKind> {
            if self.good == 0 {
                return Err(ErrorKind::Other);
            }
            self.good -= 1;
            self.inner
                .transaction(operations)
                .map_err(|_| ErrorKind::Other)
        }
    }

    #[test]
    fn a_failing_bus_is_reported_as_bus_error() {
        let expected = conversion(0, [0, 0x04, 0xD2]); // 1234, then the bus dies
        let mut adc = Mcp3208::new(
            DyingBus {
                inner: SpiMock::new(&expected),
                good: 1,
            },
            ChannelMap::REFERENCE_BOARD,
        );
        assert_eq!(adc.read_counts(Channel::PistonSidePressure), Ok(1234));
        for channel in Channel::ALL {
            assert_eq!(adc.read_counts(channel), Err(InputError::Bus));
        }
        adc.release().inner.done();
    }

    #[test]
    fn a_floating_miso_line_is_a_bad_frame_not_a_reading() {
        let expected = conversion(1, [0xFF, 0xFF, 0xFF]);
        let mut adc = Mcp3208::new(SpiMock::new(&expected), ChannelMap::REFERENCE_BOARD);
        assert_eq!(
            adc.read_counts(Channel::RodSidePressure),
            Err(InputError::BadFrame)
        );
        adc.release().done();
    }
}
