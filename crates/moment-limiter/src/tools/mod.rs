//! Tools around the cycle, not in it: the recorded-log parser and the replay
//! engine (SPEC §5), and the calibration file's schema, reader and writer.
//!
//! All `no_std`: the QEMU firmware replays logs and reads the calibration file
//! with this same code, so the host and the target cannot disagree. The board
//! image's control cycle never calls into this folder; `config_file` lives
//! here rather than beside the cycle because it is parsing, run once at
//! start-up, and shares the text-handling style of the log parser.

pub mod config_file;
pub mod log_format;
pub mod replay;
