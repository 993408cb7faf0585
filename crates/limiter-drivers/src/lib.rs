//! # limiter-drivers
//!
//! embedded-hal 1.0 adapters between real hardware and the limiter's seam
//! ([`moment_limiter::io`]):
//!
//! - [`adc::Mcp3208`]: an MCP3208-style 12-bit SPI ADC (three 4–20 mA / ratiometric
//!   inputs of the limiter on configurable converter channels) implementing
//!   [`moment_limiter::io::SensorInputs`];
//! - [`outputs::AlarmOutputs`]: the warning lamp, overload alarm and the two
//!   cut-off relays over four [`embedded_hal::digital::OutputPin`]s, implementing
//!   [`moment_limiter::io::Outputs`] with fail-safe polarity (a de-energised
//!   cut-off relay blocks the motion).
//!
//! The layering follows the embedded-hal ecosystem: the limiter depends only on its
//! own small traits, these adapters implement them over any embedded-hal 1.0 bus
//! and pins, and the firmware wires a concrete HAL (stm32f4xx-hal) underneath.
//! Everything here is `no_std`, allocation-free and panic-free; the host tests
//! drive it with `embedded-hal-mock` transactions.
#![cfg_attr(not(test), no_std)]
#![forbid(unsafe_code)]

pub mod adc;
pub mod outputs;

pub use adc::{AdcChannel, ChannelMap, Mcp3208};
pub use outputs::{AlarmOutputs, Polarity};
