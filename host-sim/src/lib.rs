//! The library behind `crane-sim`, the desktop tool of the load moment limiter.
//!
//! It runs the same `no_std` crane model and limiter as the firmware, in `f64`
//! (and the controller's `f32` table for the limiter): modes of the boom, the
//! thesis maneuvers, the lifting-capacity chart, synthetic sensor logs,
//! calibration and replay of recorded logs. `src/main.rs` only parses the
//! command line ([`cli::Cli`]) and dispatches.
//!
//! | module | what it holds |
//! |---|---|
//! | [`cli`] | the command line and the dispatch to a command |
//! | [`cmd`] | one module per subcommand: its arguments and its `run` |
//! | [`model`] | the thesis model as the commands build it |
//! | [`rating`] | the limiter's rated load, as the chart and the campaign read it |
//! | [`synth_core`] | sensor models and log synthesis from a simulated maneuver |
//! | [`maneuver_file`] | the maneuver file's schema and reader |
//! | [`replay_report`] | replay recording, its figures and HTML page |
//! | [`plot`] | figures (SVG and PNG) |
//! | [`progress`], [`stdout`] | the progress bar and a stdout that ends quietly on a closed pipe |

pub mod cli;
pub mod cmd;
pub mod maneuver_file;
pub mod model;
pub mod plot;
pub mod progress;
pub mod rating;
pub mod replay_report;
pub mod stdout;
pub mod synth_core;
