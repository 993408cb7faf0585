//! The events of a running limiter, queued in RAM and written to flash only
//! while no motion is granted.
//!
//! A flash write stalls the CPU (a program operation tens of µs per word, a
//! sector erase up to 2 s), which a granted 10 ms cycle cannot afford: an
//! overload must never wait for the event log. So the cycle only *records*
//! (an [`EventQueue::push`], a copy into RAM), and the queue is *flushed*
//! ([`EventQueue::flush`]) only in a cycle whose command cuts both
//! moment-increasing motions (OVERLOAD, FAULT, or any safe point where the
//! limiter grants no motion), at most a few records per cycle and **never
//! with an erase** (the store reserves the room at start-up, before the
//! watchdog runs: [`crate::store::Store::reserve_events`]). A flush asked for
//! while motion is granted writes nothing ([`Flushed::MotionGranted`]).
//!
//! ## When the queue is full
//!
//! It keeps **the first** [`EventQueue::KEEP_FIRST`] events (what started a
//! sequence: the entry into WARNING, OVERLOAD or FAULT) **and the latest**
//! ones (the state the crane is in now), drops the oldest of the latest part
//! to make room, and counts the dropped ones; the count is written as an
//! [`EventKind::EventsDropped`] record after the queue has been emptied.

use crate::event::{EventKind, EventRecord};
use crate::journal::Flash;
use crate::store::{Store, StoreError};
use crane_model::Real;
use moment_limiter::event_log::{self, Event};
use moment_limiter::io::OutputCommand;
use moment_limiter::fault::Fault;
use moment_limiter::state_machine::LimiterState;

/// `items.rotate_left(1)` one swap at a time: the first element goes last,
/// the others one place forward. `rotate_left` moves them with `memmove`,
/// whose code took 1.5 KiB of the board's 64 KiB of flash for this alone.
// Never inlined (push and pop_front both use it): one copy is 0.16 KB
// less of the board's 64 KiB flash than two.
#[inline(never)]
fn rotate_left_one(items: &mut [EventRecord]) {
    let mut rest = items;
    while let [first, tail @ ..] = rest {
        if let Some(next) = tail.first_mut() {
            core::mem::swap(first, next);
        }
        rest = tail;
    }
}

/// `true` when `command` grants a moment-increasing motion (a permit relay
/// energised): no flash write may happen in that cycle.
pub fn motion_granted(command: &OutputCommand) -> bool {
    !(command.cut_boom_down && command.cut_hoist_up)
}

/// The state's code in [`EventKind::StateChanged`] records.
pub fn state_code(state: LimiterState) -> u8 {
    match state {
        LimiterState::Normal => 0,
        LimiterState::Warning => 1,
        LimiterState::Overload => 2,
        LimiterState::Fault => 3,
    }
}

/// The fault's class in [`EventKind::StateChanged`] records: 0 none,
/// 1 sensor, 2 load estimate, 3 capacity, 4 clock, 5 implausible load,
/// 6 outputs, 7 signal chain settling after a fault, 8 switched on while the
/// boom moved.
pub fn fault_code(fault: Option<Fault>) -> u8 {
    match fault {
        None => 0,
        Some(Fault::Sensor(_)) => 1,
        Some(Fault::Estimate(_)) => 2,
        Some(Fault::Capacity(_)) => 3,
        Some(Fault::Clock(_)) => 4,
        Some(Fault::ImplausibleLoad) => 5,
        Some(Fault::Output) => 6,
        Some(Fault::Settling) => 7,
        Some(Fault::StartedMoving) => 8,
    }
}

/// The flash record of one of the limiter's events, `uptime_ms` after boot
/// `boot`; `None` for the kinds the board records otherwise (the self-test).
pub fn record_of<T: Real>(event: &Event<T>, boot: u32, uptime_ms: u32) -> Option<EventRecord> {
    let event_log::EventKind::Entered(state, fault) = event.kind else {
        return None;
    };
    let permille = event.utilization.map_or(0xFFFF, |u| {
        // Saturating: a utilization beyond 65.5 (or negative) is clamped.
        // In `T` (f32 on the board: no soft-float f64 multiply, compare or
        // conversion; through f64 they took 0.4 KB of the board's flash).
        let p = u * T::lit(1000.0);
        let (zero, top) = (T::lit(0.0), T::lit(65_534.0));
        if p >= top {
            65_534
        } else if p > zero {
            p.to_count()
        } else if p <= zero {
            0
        } else {
            0xFFFF // NaN: unknown
        }
    });
    Some(EventRecord {
        boot,
        kind: EventKind::StateChanged,
        detail: state_code(state),
        value: u32::from(fault_code(fault)) | (permille << 16),
        uptime_ms,
    })
}

/// What a [`EventQueue::flush`] did.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Flushed {
    /// Nothing written: this cycle grants motion.
    MotionGranted,
    /// This many records written (0 if the queue was empty); the queue holds
    /// more if the per-call limit was reached.
    Written(usize),
    /// Stopped after this many records: the next one needs a flash erase,
    /// which only start-up does; the rest stay queued.
    NeedsErase(usize),
}

/// A bounded queue of event records, `N` of them (N ≥ 2).
#[derive(Debug, Clone)]
pub struct EventQueue<const N: usize> {
    items: [EventRecord; N],
    len: usize,
    dropped: u32,
}

const EMPTY: EventRecord = EventRecord {
    boot: 0,
    kind: EventKind::EventsDropped,
    detail: 0,
    value: 0,
    uptime_ms: 0,
};

impl<const N: usize> Default for EventQueue<N> {
    fn default() -> Self {
        Self::new()
    }
}

impl<const N: usize> EventQueue<N> {
    /// Events kept from the start of a full queue: half of it.
    pub const KEEP_FIRST: usize = N / 2;

    /// An empty queue.
    pub const fn new() -> Self {
        EventQueue {
            items: [EMPTY; N],
            len: 0,
            dropped: 0,
        }
    }

    /// Number of events queued.
    pub fn len(&self) -> usize {
        self.len
    }

    /// `true` when nothing is queued.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Events dropped since the last flush that emptied the queue.
    pub fn dropped(&self) -> u32 {
        self.dropped
    }

    /// The queued events, oldest first.
    pub fn iter(&self) -> impl Iterator<Item = &EventRecord> {
        self.items.iter().take(self.len)
    }

    /// Queues an event (RAM only, bounded time: at most N moves). When full,
    /// the oldest event after the first [`Self::KEEP_FIRST`] is dropped and
    /// counted.
    pub fn push(&mut self, record: EventRecord) {
        if self.len < N {
            if let Some(slot) = self.items.get_mut(self.len) {
                *slot = record;
                self.len += 1;
            }
            return;
        }
        // Full: close the gap at KEEP_FIRST, put the new one last.
        let tail = self.items.get_mut(Self::KEEP_FIRST..).unwrap_or_default();
        rotate_left_one(tail);
        if let Some(last) = tail.last_mut() {
            *last = record;
        }
        self.dropped = self.dropped.saturating_add(1);
    }

    fn pop_front(&mut self) {
        if self.len > 0 {
            if let Some(live) = self.items.get_mut(..self.len) {
                rotate_left_one(live);
            }
            self.len -= 1;
        }
    }

    /// Writes up to `max_records` queued events to `store`, oldest first,
    /// only if `command` grants no motion, and never with an erase. A record
    /// leaves the queue only once written; when the queue is empty and
    /// events were dropped, an [`EventKind::EventsDropped`] record (`boot`,
    /// `uptime_ms`) with their count follows.
    pub fn flush<F: Flash>(
        &mut self,
        store: &mut Store<F>,
        command: &OutputCommand,
        max_records: usize,
        boot: u32,
        uptime_ms: u32,
    ) -> Result<Flushed, StoreError> {
        if motion_granted(command) {
            return Ok(Flushed::MotionGranted);
        }
        let mut written = 0;
        while written < max_records {
            let record = match self.items.first() {
                Some(r) if self.len > 0 => *r,
                _ if self.dropped > 0 => EventRecord {
                    boot,
                    kind: EventKind::EventsDropped,
                    detail: 0,
                    value: self.dropped,
                    uptime_ms,
                },
                _ => break,
            };
            match store.append_event_without_erase(&record) {
                Ok(()) => {}
                Err(StoreError::NeedsErase) => return Ok(Flushed::NeedsErase(written)),
                Err(e) => return Err(e),
            }
            if self.len > 0 {
                self.pop_front();
            } else {
                self.dropped = 0;
            }
            written += 1;
        }
        Ok(Flushed::Written(written))
    }
}
