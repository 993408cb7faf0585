//! The persisted calibration, fault latch and event log survive a power cut at
//! every single step of an update: after the cut and a reboot, the value read
//! is the old one or the new one, never garbage and never an error, and the
//! store keeps working.
//!
//! The mock flash behaves like NOR flash (writes can only clear bits, erase
//! sets a page to 0xFF) and counts steps: every write of one flash word and
//! every page erase. Cut at step k, the word being written is left half
//! written and the page being erased half erased (what a real cut leaves), and
//! every later operation fails until the "reboot" (a fresh `Store` on the same
//! bytes).

mod common;

use common::{layout, CutFlash, PAGE};
use limiter_storage::event::{EventKind, EventRecord};
use limiter_storage::latch::{LatchState, ResetCause};
use limiter_storage::store::{Key, Store};

/// Calibration number `n`: lengths and contents differ from one to the next.
fn calibration(n: usize) -> (u16, Vec<u8>) {
    let len = 40 + (n * 97) % 300;
    let bytes = (0..len).map(|i| (i * 31 + n * 7 + 1) as u8).collect();
    (n as u16, bytes)
}

fn read_calibration<const W: usize>(flash: CutFlash<W>) -> (Option<(u16, Vec<u8>)>, CutFlash<W>) {
    let mut store = Store::new(flash, layout());
    let mut out = [0u8; 1024];
    let got = store
        .read_blob(Key::Calibration, &mut out)
        .unwrap_or_else(|e| panic!("read after a power cut failed: {e}"))
        .map(|b| (b.version, b.bytes.to_vec()));
    (got, store.into_flash())
}

/// Cuts the power at every step of storing calibration `history` + 1 after
/// `history` earlier updates, and checks old-or-new after each cut.
/// Returns (cuts swept, cuts that read the old value, cuts that read the new
/// value, cuts during an erase).
fn sweep_calibration_update<const W: usize>(history: usize) -> [usize; 4] {
    let mut base = CutFlash::<W>::new();
    for n in 1..=history {
        let (v, b) = calibration(n);
        let mut s = Store::new(base, layout());
        s.write_blob(Key::Calibration, v, &b).expect("setup write");
        base = s.into_flash();
    }
    let old = (history > 0).then(|| calibration(history));
    let new = calibration(history + 1);

    let mut seen = [0; 4];
    for k in 0.. {
        let mut store = Store::new(base.reboot(Some(k)), layout());
        let result = store.write_blob(Key::Calibration, new.0, &new.1);
        let flash = store.into_flash();
        let in_erase = flash.cut_in_erase;
        let (got, flash) = read_calibration(flash.reboot(None));
        if result.is_ok() {
            assert_eq!(
                got,
                Some(new.clone()),
                "completed update must read back the new value"
            );
            seen[0] = k;
            return seen;
        }
        seen[1] += usize::from(got == old);
        seen[2] += usize::from(got.as_ref() == Some(&new));
        seen[3] += usize::from(in_erase);
        assert!(
            got == old || got.as_ref() == Some(&new),
            "history {history}, cut at step {k}/{}: read {:?} bytes of version {:?}, expected old ({:?}) or new ({})",
            flash.steps_done,
            got.as_ref().map(|g| g.1.len()),
            got.as_ref().map(|g| g.0),
            old.as_ref().map(|o| o.0),
            new.0
        );
        // The store still works after the cut: the next update goes through.
        let (v, b) = calibration(history + 2);
        let mut again = Store::new(flash, layout());
        again
            .write_blob(Key::Calibration, v, &b)
            .unwrap_or_else(|e| {
                panic!("history {history}, cut at {k}: write after reboot failed: {e}")
            });
        let (got, _) = read_calibration(again.into_flash());
        assert_eq!(got, Some((v, b)));
    }
    unreachable!()
}

#[test]
fn calibration_survives_a_cut_at_every_step_word_writes() {
    // 0 to 20 earlier updates: page switches and erases happen within the sweep.
    let mut total = [0; 4];
    for history in 0..20 {
        let seen = sweep_calibration_update::<4>(history);
        for (t, s) in total.iter_mut().zip(seen) {
            *t += s;
        }
    }
    let [cuts, old, new, erase] = total;
    assert!(
        cuts > 500,
        "the sweeps cut at only {cuts} steps: the update is not being exercised"
    );
    // Cuts before the commit read the old value (a cut in the last write,
    // the record header, as a rule too: the header is the commit), and some
    // cuts fall in a page erase (the bank switch is exercised).
    assert!(old > 0 && erase > 0, "old {old}, new {new}, erase {erase}");
    assert_eq!(old + new, cuts, "every cut read old or new");
    eprintln!(
        "calibration sweeps: {cuts} cuts, {old} read old, {new} read new, {erase} during an erase"
    );
}

#[test]
fn calibration_survives_a_cut_at_every_step_byte_writes() {
    // WRITE_SIZE 1, as stm32f4xx-hal's flash declares.
    for history in [0, 3, 9, 14] {
        sweep_calibration_update::<1>(history);
    }
}

#[test]
fn latch_survives_a_cut_at_every_step() {
    let mut base = CutFlash::<4>::new();
    // Fill the map with other traffic so the latch update moves pages too.
    for n in 1..12 {
        let (v, b) = calibration(n);
        let mut s = Store::new(base, layout());
        s.write_blob(Key::Calibration, v, &b).unwrap();
        base = s.into_flash();
    }
    let mut s = Store::new(base, layout());
    let old = LatchState::default().after_reset(ResetCause::IndependentWatchdog);
    s.set_latch(old).unwrap();
    let base = s.into_flash();
    let new = old.acknowledged();
    for k in 0.. {
        let mut s = Store::new(base.reboot(Some(k)), layout());
        let r = s.set_latch(new);
        let mut s = Store::new(s.into_flash().reboot(None), layout());
        let got = s.latch().expect("latch readable after a cut");
        if r.is_ok() {
            assert_eq!(got, new);
            break;
        }
        assert!(got == old || got == new, "cut at {k}: latch read {got:?}");
    }
}

fn events<const W: usize>(flash: CutFlash<W>) -> (Vec<EventRecord>, CutFlash<W>) {
    let mut s = Store::new(flash, layout());
    let mut v = Vec::new();
    s.for_each_event(|e| v.push(e)).expect("events readable");
    (v, s.into_flash())
}

fn event(n: u32) -> EventRecord {
    EventRecord {
        boot: n,
        kind: EventKind::Boot,
        detail: (n % 200) as u8,
        value: n * 1000,
        uptime_ms: n,
    }
}

#[test]
fn event_log_keeps_every_complete_record_through_a_cut() {
    // 4 pages of 1 KiB hold fewer than 4 * 1024 / 24 records: 300 appends
    // wrap the queue several times, so appends that erase the oldest page are swept too.
    let mut base = CutFlash::<4>::new();
    let mut appended = Vec::new();
    for n in 0..300u32 {
        let e = event(n);
        // Cut at every step of this append.
        for k in 0.. {
            let mut s = Store::new(base.reboot(Some(k)), layout());
            let r = s.append_event(&e);
            let (got, _) = events(s.into_flash().reboot(None));
            // Whatever is read is a run of consecutive complete records ending
            // with the previous or the new one.
            let last = got.last().map(|r| r.boot);
            assert!(
                last == appended.last().map(|r: &EventRecord| r.boot) || last == Some(n),
                "append {n}, cut at {k}: last record {last:?}"
            );
            for w in got.windows(2) {
                assert_eq!(
                    w[1].boot,
                    w[0].boot + 1,
                    "append {n}, cut at {k}: gap or garbage"
                );
            }
            for r in &got {
                assert_eq!(*r, event(r.boot), "append {n}, cut at {k}: altered record");
            }
            if r.is_ok() {
                break;
            }
            if n % 50 != 7 {
                break; // sweep every step only for some appends: the test stays fast
            }
        }
        let mut s = Store::new(base, layout());
        s.append_event(&e).unwrap();
        base = s.into_flash();
        appended.push(e);
    }
    let (got, _) = events(base);
    // 4 KiB = two banks of 2 KiB, 24 bytes a record: a bank holds 85, and a
    // compaction keeps the newest 42.
    assert!(got.len() >= 42, "only {} events kept", got.len());
    assert_eq!(got.last(), appended.last(), "the newest event is kept");
    assert!(
        got.len() < appended.len(),
        "the queue should have dropped old pages"
    );
}

#[test]
fn a_flipped_bit_in_flash_never_reads_as_a_value() {
    let mut s = Store::new(CutFlash::<4>::new(), layout());
    let stored: Vec<(u16, Vec<u8>)> = (1..=3).map(calibration).collect();
    for (v, b) in &stored {
        s.write_blob(Key::Calibration, *v, b).unwrap();
    }
    let clean = s.into_flash();
    let used = clean.mem[..4 * PAGE]
        .iter()
        .rposition(|&b| b != 0xFF)
        .unwrap();
    for at in (0..=used).step_by(3) {
        let mut bad = clean.reboot(None);
        bad.mem[at] ^= 0x04;
        let mut s = Store::new(bad, layout());
        let mut out = [0u8; 1024];
        // None or an error is acceptable; a value must be one that was stored.
        if let Ok(Some(b)) = s.read_blob(Key::Calibration, &mut out) {
            assert!(
                stored
                    .iter()
                    .any(|(v, s)| *v == b.version && s[..] == *b.bytes),
                "bit flip at {at} read as a value never stored"
            );
        }
    }
}

#[test]
fn blobs_round_trip_and_oversized_ones_are_refused() {
    let mut s = Store::new(CutFlash::<4>::new(), layout());
    let mut out = [0u8; 1024];
    assert_eq!(s.read_blob(Key::Configuration, &mut out), Ok(None));
    s.write_blob(Key::Configuration, 3, b"{\"version\":3}")
        .unwrap();
    s.write_blob(Key::Calibration, 1, b"cal").unwrap();
    let b = s.read_blob(Key::Configuration, &mut out).unwrap().unwrap();
    assert_eq!((b.version, b.bytes), (3, &b"{\"version\":3}"[..]));
    assert_eq!(
        s.write_blob(Key::Calibration, 1, &[0u8; 1025]),
        Err(limiter_storage::store::StoreError::TooBig)
    );
    let mut small = [0u8; 2];
    assert_eq!(
        s.read_blob(Key::Calibration, &mut small),
        Err(limiter_storage::store::StoreError::TooBig)
    );
    assert_eq!(s.next_boot(), Ok(1));
    assert_eq!(s.next_boot(), Ok(2));
}
