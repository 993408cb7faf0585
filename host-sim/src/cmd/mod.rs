//! One module per `crane-sim` subcommand; each has its `clap` arguments and a
//! `run` that returns the process exit code.
pub mod calibrate;
pub mod campaign;
pub mod chart;
pub mod modes;
pub mod replay;
pub mod report;
pub mod simulate;
pub mod synth;
