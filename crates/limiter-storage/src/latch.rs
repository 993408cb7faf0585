//! Why the controller restarted, and when it may grant motion again.
//!
//! A deterministic fault (a bug hit on every cycle, a stuck interrupt) must not
//! turn into a reset loop that re-grants motion for a few milliseconds on every
//! boot. So a reset caused by a watchdog, a fault handler or an unknown cause
//! *latches*: the outputs stay cut until an operator acknowledges, and the
//! latch is persisted in flash so a power cycle does not clear it either.
//!
//! Pieces, all pure so they test on the host:
//! - [`reset_cause`] reads the STM32F405's `RCC_CSR` flags and the
//!   [`FaultRecord`] the exception handlers leave in non-initialised RAM;
//! - [`ResetCause::latches`] says which causes latch;
//! - [`LatchState`] is the persisted latch (and a count of latched resets);
//! - [`Acknowledge`] is the operator's acknowledgement: the acknowledge input
//!   seen released, then held continuously for [`ACK_HOLD_MS`].

/// `RCC_CSR` reset flags of the STM32F405 (RM0090 §7.3.21).
pub mod csr {
    /// Low-power management reset.
    pub const LPWRRSTF: u32 = 1 << 31;
    /// Window watchdog reset.
    pub const WWDGRSTF: u32 = 1 << 30;
    /// Independent watchdog reset.
    pub const IWDGRSTF: u32 = 1 << 29;
    /// Software reset (SYSRESETREQ).
    pub const SFTRSTF: u32 = 1 << 28;
    /// Power-on / power-down reset.
    pub const PORRSTF: u32 = 1 << 27;
    /// NRST pin reset (also set by every other reset, which drives the pin).
    pub const PINRSTF: u32 = 1 << 26;
    /// Brown-out reset.
    pub const BORRSTF: u32 = 1 << 25;
    /// Write 1 to clear all the flags above.
    pub const RMVF: u32 = 1 << 24;
}

/// Which exception handler stopped the firmware.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[repr(u8)]
pub enum FaultKind {
    /// HardFault (also every escalated MemManage/BusFault/UsageFault).
    HardFault = 1,
    /// Non-maskable interrupt (e.g. the clock security system).
    NonMaskableInt = 2,
    /// An interrupt or exception with no handler (cortex-m-rt `DefaultHandler`).
    UnexpectedInterrupt = 3,
    /// A Rust panic.
    Panic = 4,
}

impl FaultKind {
    /// The kind for a stored code, if it is one.
    pub fn from_code(code: u32) -> Option<Self> {
        Some(match code {
            1 => FaultKind::HardFault,
            2 => FaultKind::NonMaskableInt,
            3 => FaultKind::UnexpectedInterrupt,
            4 => FaultKind::Panic,
            _ => return None,
        })
    }

    /// A short name for logs.
    pub fn as_str(self) -> &'static str {
        match self {
            FaultKind::HardFault => "HardFault",
            FaultKind::NonMaskableInt => "NMI",
            FaultKind::UnexpectedInterrupt => "unexpected interrupt",
            FaultKind::Panic => "panic",
        }
    }
}

/// What an exception handler writes to a RAM word area that start-up code does
/// not initialise (`.uninit`): it survives a watchdog reset but not a power
/// cut. Four words: magic, kind, the faulting PC (or IRQ number), and a check
/// word, so random power-on RAM is not mistaken for a record.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FaultRecord {
    /// Which handler ran.
    pub kind: FaultKind,
    /// Faulting program counter (HardFault), IRQ number (DefaultHandler), or 0.
    pub detail: u32,
}

const RECORD_MAGIC: u32 = 0xFA17_5AFE;

impl FaultRecord {
    /// The four words to store.
    pub const fn encode(&self) -> [u32; 4] {
        let kind = self.kind as u32;
        [
            RECORD_MAGIC,
            kind,
            self.detail,
            !(RECORD_MAGIC ^ kind ^ self.detail),
        ]
    }

    /// The record in `words`, if they hold a valid one.
    pub fn decode(words: [u32; 4]) -> Option<Self> {
        let [magic, kind, detail, check] = words;
        if magic != RECORD_MAGIC || check != !(magic ^ kind ^ detail) {
            return None;
        }
        Some(FaultRecord {
            kind: FaultKind::from_code(kind)?,
            detail,
        })
    }

    /// Words that decode to nothing (what start-up writes after reading).
    pub const CLEARED: [u32; 4] = [0; 4];
}

/// Why the MCU (re)started.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ResetCause {
    /// Power switched on (or a power cut).
    PowerOn,
    /// Supply dipped below the brown-out level.
    BrownOut,
    /// The reset pin (reset button, debugger).
    Pin,
    /// A software reset request (debugger, bootloader). The firmware itself
    /// never requests one.
    Software,
    /// The independent watchdog: the control loop stopped.
    IndependentWatchdog,
    /// The window watchdog.
    WindowWatchdog,
    /// Low-power management reset (entering standby/stop when forbidden).
    LowPower,
    /// An exception handler stopped the firmware and the watchdog reset it.
    Fault(FaultRecord),
    /// No flag set: cannot be told.
    Unknown,
}

impl ResetCause {
    /// Whether this cause keeps the outputs cut until acknowledged: every
    /// cause that says the firmware stopped working, and any cause that cannot
    /// be told.
    pub fn latches(self) -> bool {
        matches!(
            self,
            ResetCause::IndependentWatchdog
                | ResetCause::WindowWatchdog
                | ResetCause::LowPower
                | ResetCause::Fault(_)
                | ResetCause::Unknown
        )
    }

    /// One-byte code for the event log.
    pub fn code(self) -> u8 {
        match self {
            ResetCause::PowerOn => 1,
            ResetCause::BrownOut => 2,
            ResetCause::Pin => 3,
            ResetCause::Software => 4,
            ResetCause::IndependentWatchdog => 5,
            ResetCause::WindowWatchdog => 6,
            ResetCause::LowPower => 7,
            ResetCause::Fault(r) => 0x10 | r.kind as u8,
            ResetCause::Unknown => 0xFF,
        }
    }

    /// A short name for logs.
    pub fn as_str(self) -> &'static str {
        match self {
            ResetCause::PowerOn => "power-on",
            ResetCause::BrownOut => "brown-out",
            ResetCause::Pin => "reset pin",
            ResetCause::Software => "software reset",
            ResetCause::IndependentWatchdog => "independent watchdog",
            ResetCause::WindowWatchdog => "window watchdog",
            ResetCause::LowPower => "low-power reset",
            ResetCause::Fault(r) => r.kind.as_str(),
            ResetCause::Unknown => "unknown",
        }
    }
}

/// The reset cause from the `RCC_CSR` value read at start-up and the words of
/// the RAM fault record. After a power-on or brown-out the RAM is random and
/// the record is ignored; otherwise a valid record names the fault (the
/// handlers then wait for the watchdog, so `IWDGRSTF` is also set).
pub fn reset_cause(csr_value: u32, record_words: [u32; 4]) -> ResetCause {
    use csr::*;
    let power_lost = csr_value & (PORRSTF | BORRSTF) != 0;
    if !power_lost {
        if let Some(record) = FaultRecord::decode(record_words) {
            return ResetCause::Fault(record);
        }
    }
    // Most specific first: every reset also sets PINRSTF; a power-on also BORRSTF.
    if csr_value & LPWRRSTF != 0 {
        ResetCause::LowPower
    } else if csr_value & WWDGRSTF != 0 {
        ResetCause::WindowWatchdog
    } else if csr_value & IWDGRSTF != 0 {
        ResetCause::IndependentWatchdog
    } else if csr_value & PORRSTF != 0 {
        ResetCause::PowerOn
    } else if csr_value & BORRSTF != 0 {
        ResetCause::BrownOut
    } else if csr_value & SFTRSTF != 0 {
        ResetCause::Software
    } else if csr_value & PINRSTF != 0 {
        ResetCause::Pin
    } else {
        ResetCause::Unknown
    }
}

/// The persisted fault latch.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct LatchState {
    /// Outputs stay cut until acknowledged.
    pub active: bool,
    /// Code of the reset cause that latched ([`ResetCause::code`]).
    pub cause: u8,
    /// Latched resets since the flash was first used (never reset).
    pub count: u32,
}

/// Bytes of an encoded [`LatchState`].
pub const LATCH_LEN: usize = 8;

impl LatchState {
    /// The state after a reset with `cause`: latched if the cause latches,
    /// otherwise unchanged (a power cycle does not clear a latch).
    pub fn after_reset(self, cause: ResetCause) -> Self {
        if cause.latches() {
            LatchState {
                active: true,
                cause: cause.code(),
                count: self.count.saturating_add(1),
            }
        } else {
            self
        }
    }

    /// The state after the operator's acknowledgement.
    pub fn acknowledged(self) -> Self {
        LatchState {
            active: false,
            ..self
        }
    }

    /// Bytes to persist.
    pub fn encode(&self) -> [u8; LATCH_LEN] {
        let mut b = [0u8; LATCH_LEN];
        b[0] = u8::from(self.active);
        b[1] = self.cause;
        crate::put(&mut b, 4, &self.count.to_le_bytes());
        b
    }

    /// From persisted bytes. Anything unreadable decodes as *latched*: the
    /// limiter cannot vouch for a state it cannot read.
    pub fn decode(bytes: &[u8]) -> Self {
        match bytes {
            [active @ (0 | 1), cause, 0, 0, c0, c1, c2, c3] => LatchState {
                active: *active == 1,
                cause: *cause,
                count: u32::from_le_bytes([*c0, *c1, *c2, *c3]),
            },
            _ => LatchState {
                active: true,
                cause: 0xFF,
                count: 0,
            },
        }
    }
}

/// How long the acknowledge input must be held (ms).
pub const ACK_HOLD_MS: u32 = 3000;

/// The operator's acknowledgement of a latched fault: the acknowledge input
/// (a key switch) must first be seen released after boot, so a stuck or
/// shorted input cannot acknowledge on its own, then held without a break for
/// [`ACK_HOLD_MS`].
#[derive(Debug, Clone, Copy, Default)]
pub struct Acknowledge {
    released_seen: bool,
    held_ms: u32,
}

impl Acknowledge {
    /// Not yet acknowledged; the input not yet seen released.
    pub const fn new() -> Self {
        Acknowledge {
            released_seen: false,
            held_ms: 0,
        }
    }

    /// Feeds one sample of the input (`pressed`) taken `elapsed_ms` after the
    /// previous one; returns `true` once the acknowledgement is complete.
    pub fn update(&mut self, pressed: bool, elapsed_ms: u32) -> bool {
        if !pressed {
            self.released_seen = true;
            self.held_ms = 0;
            return false;
        }
        if !self.released_seen {
            return false;
        }
        self.held_ms = self.held_ms.saturating_add(elapsed_ms);
        self.held_ms >= ACK_HOLD_MS
    }
}

#[cfg(test)]
mod tests {
    use super::csr::*;
    use super::*;

    #[test]
    fn flags_give_the_cause_and_only_failures_latch() {
        let none = FaultRecord::CLEARED;
        let cases = [
            (PORRSTF | BORRSTF | PINRSTF, ResetCause::PowerOn, false),
            (BORRSTF | PINRSTF, ResetCause::BrownOut, false),
            (PINRSTF, ResetCause::Pin, false),
            (SFTRSTF | PINRSTF, ResetCause::Software, false),
            (IWDGRSTF | PINRSTF, ResetCause::IndependentWatchdog, true),
            (WWDGRSTF | PINRSTF, ResetCause::WindowWatchdog, true),
            (LPWRRSTF | PINRSTF, ResetCause::LowPower, true),
            (0, ResetCause::Unknown, true),
        ];
        for (flags, cause, latches) in cases {
            assert_eq!(reset_cause(flags, none), cause, "flags {flags:#x}");
            assert_eq!(cause.latches(), latches, "{}", cause.as_str());
        }
    }

    #[test]
    fn a_fault_record_names_the_fault_unless_power_was_lost() {
        let rec = FaultRecord {
            kind: FaultKind::HardFault,
            detail: 0x0800_1234,
        };
        let words = rec.encode();
        assert_eq!(
            reset_cause(IWDGRSTF | PINRSTF, words),
            ResetCause::Fault(rec)
        );
        assert!(ResetCause::Fault(rec).latches());
        // After a power-on the RAM content means nothing.
        assert_eq!(reset_cause(PORRSTF | PINRSTF, words), ResetCause::PowerOn);
        // A corrupted record is not a record.
        let mut bad = words;
        bad[2] ^= 4;
        assert_eq!(reset_cause(IWDGRSTF, bad), ResetCause::IndependentWatchdog);
        assert_eq!(FaultRecord::decode([0xCCCC_CCCC; 4]), None);
        assert_eq!(FaultRecord::decode(FaultRecord::CLEARED), None);
    }

    #[test]
    fn latch_survives_power_cycles_until_acknowledged() {
        let s = LatchState::default();
        let s = s.after_reset(ResetCause::IndependentWatchdog);
        assert!(s.active);
        assert_eq!(s.count, 1);
        // A power cycle does not clear it.
        let s = LatchState::decode(&s.encode()).after_reset(ResetCause::PowerOn);
        assert!(s.active);
        let s = s.acknowledged();
        assert!(!s.active);
        assert_eq!(s.count, 1, "the count of latched resets is kept");
        // Garbage reads as latched.
        assert!(LatchState::decode(&[7; 8]).active);
        assert!(LatchState::decode(&[0; 3]).active);
        assert_eq!(LatchState::decode(&s.encode()), s);
    }

    #[test]
    fn acknowledge_needs_release_then_three_seconds_unbroken() {
        // Held from boot (stuck key): never acknowledges.
        let mut a = Acknowledge::new();
        for _ in 0..1000 {
            assert!(!a.update(true, 10));
        }
        // Released, then held 2.99 s, released: not acknowledged.
        let mut a = Acknowledge::new();
        assert!(!a.update(false, 10));
        for _ in 0..299 {
            assert!(!a.update(true, 10));
        }
        assert!(!a.update(false, 10));
        // Held 3 s without a break: acknowledged on the 300th sample.
        for i in 1..=300 {
            assert_eq!(a.update(true, 10), i == 300, "sample {i}");
        }
    }
}
