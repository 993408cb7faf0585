//! The data logger (EN 13000): a bounded ring buffer of what happened.
//!
//! Every state change, every fault (with its cause) and the power-up
//! self-test are recorded with time, boom angle, load and utilization. When
//! the buffer is full the oldest entry is dropped and counted, so the log
//! always holds the most recent `N` events and says how many were lost. The
//! firmware drains it to non-volatile memory; the host prints it.

use crate::clock::Ticks;
use crate::fault::Fault;
use crate::state_machine::LimiterState;

/// What an event records.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum EventKind {
    /// The power-up self-test passed.
    SelfTestPassed,
    /// The power-up self-test failed for this reason.
    SelfTestFailed(Fault),
    /// The limiter entered this state; for FAULT, with its cause.
    Entered(LimiterState, Option<Fault>),
}

/// One logged event.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Event<T> {
    /// Time of the cycle on the limiter's clock ([`crate::clock`]).
    pub t: Ticks,
    /// What happened.
    pub kind: EventKind,
    /// Boom angle (degrees), if it was read correctly.
    pub boom_angle_deg: Option<T>,
    /// Estimated hook load (kg), if it could be estimated.
    pub load_kg: Option<T>,
    /// Utilization (fraction of rated load), if known.
    pub utilization: Option<T>,
}

/// A ring buffer of the last `N` events.
#[derive(Debug, Clone)]
pub struct EventLog<T, const N: usize> {
    events: heapless::Deque<Event<T>, N>,
    dropped: u32,
}

impl<T: Copy, const N: usize> Default for EventLog<T, N> {
    fn default() -> Self {
        Self::new()
    }
}

impl<T: Copy, const N: usize> EventLog<T, N> {
    /// An empty log.
    pub fn new() -> Self {
        Self {
            events: heapless::Deque::new(),
            dropped: 0,
        }
    }

    /// Records an event, dropping the oldest if the log is full.
    // Never inlined (runs on a state change only): its inlined copies took
    // 0.26 KB more of the board's 64 KiB flash than one function.
    #[inline(never)]
    pub fn push(&mut self, event: Event<T>) {
        if self.events.is_full() {
            let _ = self.events.pop_front();
            self.dropped = self.dropped.saturating_add(1);
        }
        // Cannot fail: there is room after the pop above (unless N == 0, in
        // which case the event is counted as dropped).
        if self.events.push_back(event).is_err() {
            self.dropped = self.dropped.saturating_add(1);
        }
    }

    /// The events held, oldest first.
    pub fn iter(&self) -> impl Iterator<Item = &Event<T>> {
        self.events.iter()
    }

    /// Number of events held.
    pub fn len(&self) -> usize {
        self.events.len()
    }

    /// `true` when no event is held.
    pub fn is_empty(&self) -> bool {
        self.events.is_empty()
    }

    /// How many events were dropped because the log was full.
    pub fn dropped(&self) -> u32 {
        self.dropped
    }

    /// Removes and returns the oldest event (for draining to storage).
    pub fn pop_oldest(&mut self) -> Option<Event<T>> {
        self.events.pop_front()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ring_keeps_the_newest_and_counts_drops() {
        let mut log: EventLog<f64, 3> = EventLog::new();
        for k in 0..5 {
            log.push(Event {
                t: Ticks::from_millis(k),
                kind: EventKind::SelfTestPassed,
                boom_angle_deg: None,
                load_kg: None,
                utilization: None,
            });
        }
        let times: Vec<u32> = log.iter().map(|e| e.t.micros()).collect();
        assert_eq!(times, vec![2000, 3000, 4000]);
        assert_eq!(log.dropped(), 2);
    }
}
