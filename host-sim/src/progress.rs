//! Progress of a long replay on stderr.
//!
//! The bar counts bytes of the log read. It stays hidden for the first second
//! (a short replay prints nothing extra) and whenever stderr is not a terminal
//! (scripts and CI see only the replay's own output).

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::time::{Duration, Instant};

/// How long a replay runs before its bar appears.
const SHOW_AFTER: Duration = Duration::from_secs(1);

/// The bar of one replay.
pub struct ReplayProgress {
    bar: ProgressBar,
    start: Instant,
    shown: bool,
    pending: u64,
}

impl ReplayProgress {
    /// A hidden bar for a log of `total_bytes`.
    pub fn new(total_bytes: u64) -> Self {
        let bar = ProgressBar::with_draw_target(Some(total_bytes), ProgressDrawTarget::hidden());
        let style = ProgressStyle::with_template("replay {bar:40} {percent:>3}% {binary_bytes}/{binary_total_bytes} eta {eta}")
            .unwrap_or_else(|_| ProgressStyle::default_bar());
        bar.set_style(style);
        Self { bar, start: Instant::now(), shown: false, pending: 0 }
    }

    /// Counts `bytes` more of the log as read.
    pub fn advance(&mut self, bytes: usize) {
        self.pending += bytes as u64;
        // Touch the bar (and the clock) every 64 KiB only: a sample is a few
        // dozen bytes and the replay itself takes about a microsecond.
        if self.pending < 64 * 1024 {
            return;
        }
        self.bar.inc(std::mem::take(&mut self.pending));
        if !self.shown && self.start.elapsed() >= SHOW_AFTER {
            // `stderr()` draws nothing when stderr is not a terminal.
            self.bar.set_draw_target(ProgressDrawTarget::stderr());
            self.shown = true;
        }
    }

    /// Removes the bar.
    pub fn finish(self) {
        self.bar.finish_and_clear();
    }
}
