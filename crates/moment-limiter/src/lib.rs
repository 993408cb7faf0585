//! # moment-limiter
//!
//! Load moment limiter core (being written).
#![cfg_attr(not(any(test, feature = "std")), no_std)]
#![forbid(unsafe_code)]

pub mod io;
