//! The events of a running limiter: queued in RAM by the cycle, written to
//! flash only in cycles that grant no motion, never with an erase; they
//! survive a power cut once flushed; a full queue keeps the first and the
//! latest events and counts the rest.

mod common;

use common::{layout, CutFlash};
use limiter_storage::event::{EventKind, EventRecord};
use limiter_storage::event_queue::{
    fault_code, motion_granted, record_of, state_code, EventQueue, Flushed,
};
use limiter_storage::store::Store;
use moment_limiter::clock::Ticks;
use moment_limiter::event_log::{self, Event};
use moment_limiter::io::OutputCommand;
use moment_limiter::fault::Fault;
use moment_limiter::state_machine::LimiterState;

const BOOT: u32 = 3;

fn state_event(n: u32) -> EventRecord {
    EventRecord {
        boot: BOOT,
        kind: EventKind::StateChanged,
        detail: (n % 4) as u8,
        value: n,
        uptime_ms: 10 * n,
    }
}

fn stored(flash: &CutFlash<4>) -> Vec<EventRecord> {
    let mut store = Store::new(flash.reboot(None), layout());
    let mut out = Vec::new();
    store.for_each_event(|e| out.push(e)).unwrap();
    out
}

const GRANTING: [OutputCommand; 4] = [
    // NORMAL
    OutputCommand {
        warning_lamp: false,
        overload_alarm: false,
        cut_boom_down: false,
        cut_hoist_up: false,
    },
    // WARNING
    OutputCommand {
        warning_lamp: true,
        overload_alarm: false,
        cut_boom_down: false,
        cut_hoist_up: false,
    },
    // one motion still permitted (either one)
    OutputCommand {
        warning_lamp: true,
        overload_alarm: true,
        cut_boom_down: true,
        cut_hoist_up: false,
    },
    OutputCommand {
        warning_lamp: true,
        overload_alarm: true,
        cut_boom_down: false,
        cut_hoist_up: true,
    },
];

#[test]
fn a_flush_never_writes_while_any_motion_is_granted() {
    let mut store = Store::new(CutFlash::<4>::new(), layout());
    store.reserve_events(16).unwrap();
    let mut queue = EventQueue::<8>::new();
    let before = store.into_flash();
    let steps = before.steps_done;
    let mut store = Store::new(before, layout());
    for n in 0..6 {
        queue.push(state_event(n));
    }
    for cmd in GRANTING {
        assert!(motion_granted(&cmd));
        for _ in 0..3 {
            assert_eq!(
                queue.flush(&mut store, &cmd, 8, BOOT, 0).unwrap(),
                Flushed::MotionGranted
            );
        }
    }
    assert_eq!(queue.len(), 6, "nothing left the queue");
    let flash = store.into_flash();
    assert_eq!(
        flash.steps_done, steps,
        "a flash write or erase in a granted cycle"
    );
    assert!(stored(&flash).is_empty());
    // The first cycle that grants nothing writes them.
    let mut store = Store::new(flash, layout());
    assert!(!motion_granted(&OutputCommand::FAIL_SAFE));
    assert_eq!(
        queue
            .flush(&mut store, &OutputCommand::FAIL_SAFE, 8, BOOT, 0)
            .unwrap(),
        Flushed::Written(6)
    );
    assert!(queue.is_empty());
    let flash = store.into_flash();
    assert_eq!(stored(&flash), (0..6).map(state_event).collect::<Vec<_>>());
}

#[test]
fn flushed_events_survive_a_power_cut_at_every_step_of_a_flush() {
    // Earlier events already in flash, then a flush of four more, cut at
    // every single write: after the reboot the log holds the earlier events
    // and a prefix of the new ones, each complete, never garbage.
    let mut store = Store::new(CutFlash::<4>::new(), layout());
    store.reserve_events(32).unwrap();
    for n in 0..3 {
        store.append_event(&state_event(n)).unwrap();
    }
    let base = store.into_flash();
    let new: Vec<EventRecord> = (3..7).map(state_event).collect();
    let mut complete = None;
    for cut in 0.. {
        let mut store = Store::new(base.reboot(Some(cut)), layout());
        let mut queue = EventQueue::<8>::new();
        for e in &new {
            queue.push(*e);
        }
        let result = queue.flush(&mut store, &OutputCommand::FAIL_SAFE, 8, BOOT, 0);
        let flash = store.into_flash();
        assert_eq!(flash.erases, 0, "a flush erased");
        let got = stored(&flash);
        assert_eq!(got[..3], (0..3).map(state_event).collect::<Vec<_>>()[..]);
        let tail = &got[3..];
        assert!(
            tail.len() <= new.len() && tail == &new[..tail.len()],
            "cut {cut}: {got:?}"
        );
        // A record that left the queue is in flash.
        assert_eq!(
            queue.len() + tail.len(),
            new.len(),
            "cut {cut}: a record lost from both"
        );
        if result == Ok(Flushed::Written(4)) {
            assert_eq!(tail, &new[..]);
            complete = Some(cut);
            break;
        }
        assert!(result.is_err(), "cut {cut}: {result:?}");
    }
    assert!(complete.unwrap() > 8, "the sweep cut inside the writes");
}

#[test]
fn a_full_queue_keeps_the_first_and_the_latest_and_counts_the_dropped() {
    let mut queue = EventQueue::<8>::new();
    for n in 0..20 {
        queue.push(state_event(n));
    }
    assert_eq!(EventQueue::<8>::KEEP_FIRST, 4);
    assert_eq!(queue.len(), 8);
    assert_eq!(queue.dropped(), 12);
    let kept: Vec<u32> = queue.iter().map(|e| e.value).collect();
    assert_eq!(kept, [0, 1, 2, 3, 16, 17, 18, 19]);

    // Flushed in order, then the count of the dropped ones.
    let mut store = Store::new(CutFlash::<4>::new(), layout());
    store.reserve_events(16).unwrap();
    // Three per cycle: the dropped record comes once the queue is empty.
    let mut cycles = 0;
    loop {
        let r = queue
            .flush(&mut store, &OutputCommand::FAIL_SAFE, 3, BOOT, 500)
            .unwrap();
        cycles += 1;
        if r == Flushed::Written(0) {
            break;
        }
    }
    assert_eq!(cycles, 4, "9 records at 3 per cycle, then an empty flush");
    assert_eq!(queue.dropped(), 0);
    let got = stored(&store.into_flash());
    assert_eq!(got.len(), 9);
    assert_eq!(
        got[..8].iter().map(|e| e.value).collect::<Vec<_>>(),
        [0, 1, 2, 3, 16, 17, 18, 19]
    );
    assert_eq!(got[8].kind, EventKind::EventsDropped);
    assert_eq!((got[8].value, got[8].uptime_ms), (12, 500));
}

#[test]
fn a_flush_that_would_need_an_erase_waits_for_start_up() {
    // 2 KiB banks: 85 records of 24 bytes. Reserve room for 10, fill the
    // bank, then flush: the records that fit are written, the rest wait.
    let mut store = Store::new(CutFlash::<4>::new(), layout());
    store.reserve_events(10).unwrap();
    for n in 0..80 {
        store.append_event_without_erase(&state_event(n)).unwrap();
    }
    let erases = {
        let f = store.into_flash();
        let e = f.erases;
        store = Store::new(f, layout());
        e
    };
    let mut queue = EventQueue::<16>::new();
    for n in 100..110 {
        queue.push(state_event(n));
    }
    let r = queue
        .flush(&mut store, &OutputCommand::FAIL_SAFE, 16, BOOT, 0)
        .unwrap();
    assert_eq!(r, Flushed::NeedsErase(5));
    assert_eq!(queue.len(), 5, "the unwritten ones stay queued");
    let flash = store.into_flash();
    assert_eq!(flash.erases, erases, "a flush erased");
    assert_eq!(stored(&flash).len(), 85);
    // Start-up (before the watchdog) compacts and reserves room again.
    let mut store = Store::new(flash, layout());
    store.reserve_events(20).unwrap();
    assert_eq!(
        queue
            .flush(&mut store, &OutputCommand::FAIL_SAFE, 16, BOOT, 0)
            .unwrap(),
        Flushed::Written(5)
    );
    let got = stored(&store.into_flash());
    assert_eq!(
        got.last().map(|e| e.value),
        Some(109),
        "the newest survive the compaction"
    );
}

#[test]
fn limiter_events_become_state_change_records() {
    let e = Event::<f32> {
        t: Ticks(0),
        kind: event_log::EventKind::Entered(LimiterState::Overload, None),
        boom_angle_deg: Some(40.0),
        load_kg: Some(8000.0),
        utilization: Some(1.034),
    };
    let r = record_of(&e, BOOT, 12_340).unwrap();
    assert_eq!(r.kind, EventKind::StateChanged);
    assert_eq!(r.detail, state_code(LimiterState::Overload));
    assert_eq!(r.value, 1034 << 16);
    assert_eq!((r.boot, r.uptime_ms), (BOOT, 12_340));
    let f = Event::<f32> {
        kind: event_log::EventKind::Entered(LimiterState::Fault, Some(Fault::ImplausibleLoad)),
        utilization: None,
        ..e
    };
    let r = record_of(&f, BOOT, 0).unwrap();
    assert_eq!(r.detail, 3);
    assert_eq!(
        r.value,
        u32::from(fault_code(Some(Fault::ImplausibleLoad))) | (0xFFFF << 16)
    );
    assert_eq!(fault_code(Some(Fault::ImplausibleLoad)), 5);
    // Round trip through the record's bytes.
    assert_eq!(EventRecord::decode(&r.encode()), Some(r));
    let s = Event::<f32> {
        kind: event_log::EventKind::SelfTestPassed,
        ..e
    };
    assert_eq!(record_of(&s, BOOT, 0), None);
}

#[test]
fn a_replayed_overload_persists_every_state_change_and_writes_only_in_cut_cycles() {
    use moment_limiter::cycle::{Limiter, LimiterConfig};
    use moment_limiter::tools::log_format::LogParser;

    // The board's loop with the shipped model, fed an example log that goes
    // NORMAL -> WARNING -> OVERLOAD while the boom is lowered.
    let mut limiter = Limiter::new(
        crane_model::loads::thesis_modes::thesis_load_model_f32(),
        LimiterConfig::<f32>::standard(),
    )
    .unwrap();
    let mut parser = LogParser::<f32>::new();
    let mut store = Store::new(CutFlash::<4>::new(), layout());
    store.reserve_events(40).unwrap();
    let mut queue = EventQueue::<8>::new();
    let mut logged = Vec::new();
    let (mut granted_with_events_waiting, mut flushes) = (0, 0);
    let text = include_str!("../../../examples/logs/overload_lowering.csv");
    for (cycle, line) in text.lines().enumerate() {
        let Some(record) = parser.feed_line(line).unwrap() else {
            continue;
        };
        let report = limiter.step_frame(&record.frame);
        let uptime_ms = 20 * cycle as u32;
        while let Some(event) = limiter.events_mut().pop_oldest() {
            if let Some(r) = record_of(&event, BOOT, uptime_ms) {
                logged.push(r);
                queue.push(r);
            }
        }
        let steps = store.flash().steps_done;
        let r = queue
            .flush(&mut store, &report.command, 4, BOOT, uptime_ms)
            .unwrap();
        if motion_granted(&report.command) {
            assert_eq!(r, Flushed::MotionGranted);
            assert_eq!(
                store.flash().steps_done,
                steps,
                "flash written in a granted cycle"
            );
            granted_with_events_waiting += usize::from(!queue.is_empty());
        } else if r != Flushed::Written(0) {
            flushes += 1;
        }
    }
    let states: Vec<u8> = logged.iter().map(|r| r.detail).collect();
    assert!(
        states.contains(&state_code(LimiterState::Warning))
            && states.last() == Some(&state_code(LimiterState::Overload)),
        "the log did not go through WARNING into OVERLOAD: {states:?}"
    );
    assert!(
        granted_with_events_waiting > 0,
        "no event had to wait for a cut cycle"
    );
    assert!(flushes > 0);
    assert!(queue.is_empty(), "the OVERLOAD cycles flushed everything");
    assert_eq!(
        stored(&store.into_flash()),
        logged,
        "every state change, in order"
    );
}

/// The utilization's per mille in the record's top half: truncated toward
/// zero, clamped to 0..=65 534, 0xFFFF for NaN, the same in f32 (the board,
/// converted by the FPU) and f64.
#[test]
fn the_records_per_mille_truncates_clamps_and_marks_nan() {
    fn permille<T: crane_model::Real>(u: T) -> u32 {
        let e = Event::<T> {
            t: Ticks(0),
            kind: event_log::EventKind::Entered(LimiterState::Warning, None),
            boom_angle_deg: None,
            load_kg: None,
            utilization: Some(u),
        };
        record_of(&e, BOOT, 0).unwrap().value >> 16
    }
    for (u, want) in [(0.9999, 999), (0.0004, 0), (-0.5, 0), (65.5339, 65_533), (65.6, 65_534), (1e9, 65_534), (f64::INFINITY, 65_534), (f64::NEG_INFINITY, 0), (f64::NAN, 0xFFFF)] {
        assert_eq!(permille(u), want, "f64 {u}");
        assert_eq!(permille(u as f32), want, "f32 {u}");
    }
}
