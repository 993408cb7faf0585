//! The mock NOR flash the store's tests share: it behaves like NOR flash
//! (writes can only clear bits, erase sets a page to 0xFF) and can lose power
//! after a set number of steps (see `power_cut.rs`).
#![allow(dead_code)] // Each test file uses a part.

use embedded_storage::nor_flash::{
    ErrorType, NorFlash, NorFlashError, NorFlashErrorKind, ReadNorFlash,
};
use limiter_storage::store::Layout;

pub const PAGE: usize = 1024;
pub const PAGES: usize = 8;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MockError {
    PowerCut,
    Range,
}

impl NorFlashError for MockError {
    fn kind(&self) -> NorFlashErrorKind {
        match self {
            MockError::PowerCut => NorFlashErrorKind::Other,
            MockError::Range => NorFlashErrorKind::OutOfBounds,
        }
    }
}

/// NOR flash of `PAGES` pages that loses power after a set number of steps.
#[derive(Clone)]
pub struct CutFlash<const W: usize> {
    pub mem: Vec<u8>,
    pub steps_left: Option<usize>,
    pub dead: bool,
    pub steps_done: usize,
    /// The cut happened during a page erase.
    pub cut_in_erase: bool,
    /// Page erases done since power-up.
    pub erases: usize,
}

impl<const W: usize> CutFlash<W> {
    pub fn new() -> Self {
        CutFlash {
            mem: vec![0xFF; PAGE * PAGES],
            steps_left: None,
            dead: false,
            steps_done: 0,
            cut_in_erase: false,
            erases: 0,
        }
    }

    /// The same bytes, powered up again, cutting after `steps` steps (or never).
    pub fn reboot(&self, steps: Option<usize>) -> Self {
        CutFlash {
            mem: self.mem.clone(),
            steps_left: steps,
            dead: false,
            steps_done: 0,
            cut_in_erase: false,
            erases: 0,
        }
    }

    /// One step: `false` if the power goes now.
    pub fn step(&mut self) -> bool {
        self.steps_done += 1;
        match self.steps_left.as_mut() {
            Some(0) => {
                self.dead = true;
                false
            }
            Some(n) => {
                *n -= 1;
                true
            }
            None => true,
        }
    }
}

impl<const W: usize> ErrorType for CutFlash<W> {
    type Error = MockError;
}

impl<const W: usize> ReadNorFlash for CutFlash<W> {
    const READ_SIZE: usize = 1;

    fn read(&mut self, offset: u32, bytes: &mut [u8]) -> Result<(), MockError> {
        if self.dead {
            return Err(MockError::PowerCut);
        }
        let at = offset as usize;
        let src = self.mem.get(at..at + bytes.len()).ok_or(MockError::Range)?;
        bytes.copy_from_slice(src);
        Ok(())
    }

    fn capacity(&self) -> usize {
        self.mem.len()
    }
}

impl<const W: usize> NorFlash for CutFlash<W> {
    const WRITE_SIZE: usize = W;
    const ERASE_SIZE: usize = PAGE;

    fn erase(&mut self, from: u32, to: u32) -> Result<(), MockError> {
        if self.dead {
            return Err(MockError::PowerCut);
        }
        let (from, to) = (from as usize, to as usize);
        assert!(
            from % PAGE == 0 && to % PAGE == 0 && to <= self.mem.len(),
            "bad erase {from}..{to}"
        );
        for page in (from..to).step_by(PAGE) {
            self.erases += 1;
            if !self.step() {
                // Half the page erased when the power went.
                self.cut_in_erase = true;
                self.mem[page..page + PAGE / 2].fill(0xFF);
                return Err(MockError::PowerCut);
            }
            self.mem[page..page + PAGE].fill(0xFF);
        }
        Ok(())
    }

    fn write(&mut self, offset: u32, bytes: &[u8]) -> Result<(), MockError> {
        if self.dead {
            return Err(MockError::PowerCut);
        }
        let at = offset as usize;
        assert!(
            at % W == 0 && bytes.len() % W == 0,
            "unaligned write {at}+{}",
            bytes.len()
        );
        assert!(at + bytes.len() <= self.mem.len(), "write out of range");
        for (i, word) in bytes.chunks(W).enumerate() {
            let base = at + i * W;
            if !self.step() {
                // The word being programmed is torn: only its first half made it.
                for (j, b) in word.iter().enumerate().take(W.div_ceil(2)) {
                    self.mem[base + j] &= b;
                }
                return Err(MockError::PowerCut);
            }
            for (j, b) in word.iter().enumerate() {
                // NOR flash: programming can only clear bits.
                self.mem[base + j] &= b;
            }
        }
        Ok(())
    }
}

pub fn layout() -> Layout {
    Layout {
        settings: 0..(4 * PAGE) as u32,
        events: (4 * PAGE) as u32..(8 * PAGE) as u32,
    }
}
