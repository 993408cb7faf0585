//! Host I/O for the QEMU build over ARM semihosting: the command line, reading a
//! host file line by line, stdout/stderr, and the exit code.
//!
//! cortex-m-semihosting 0.6 has no public file API, so files go through its
//! `syscall` function (SYS_OPEN/SYS_READ/SYS_CLOSE). Every call here is a
//! `BKPT 0xAB` trap that QEMU (`-semihosting-config enable=on`) answers on the
//! host. Paths resolve against QEMU's working directory; the runner script makes
//! them absolute.
#![allow(unsafe_code)] // Semihosting calls pass raw pointers to the host (see each SAFETY note).

use core::fmt;
use cortex_m_semihosting::{nr, syscall, syscall1};

/// SYS_EXIT_EXTENDED (0x20): exit with a status code (not in cortex-m-semihosting's `nr`).
const SYS_EXIT_EXTENDED: usize = 0x20;
/// ADP_Stopped_ApplicationExit: "the application exited normally".
const ADP_STOPPED_APPLICATION_EXIT: usize = 0x20026;

/// Ends the QEMU run with process exit status `code` (QEMU's own exit status).
pub fn exit(code: u8) -> ! {
    let block = [ADP_STOPPED_APPLICATION_EXIT, code as usize];
    // SAFETY: SYS_EXIT_EXTENDED takes a pointer to a two-word block that lives on
    // the stack for the duration of the call; the host does not return.
    unsafe {
        syscall(SYS_EXIT_EXTENDED, &block);
    }
    // Only reached without a debugger/emulator attached: stop here.
    loop {
        cortex_m::asm::bkpt();
    }
}

/// Copies the semihosting command line (QEMU's `arg=` values joined by spaces)
/// into `buf` and returns it, or `None` if the host refuses or it is not UTF-8.
pub fn command_line(buf: &mut [u8]) -> Option<&str> {
    let mut block = [buf.as_mut_ptr() as usize, buf.len()];
    // SAFETY: SYS_GET_CMDLINE writes at most `block[1]` bytes (including a NUL)
    // into the buffer `block[0]` points to, which we borrow mutably, then stores
    // the length it wrote in `block[1]`.
    let rc = unsafe { syscall1(nr::GET_CMDLINE, core::ptr::addr_of_mut!(block) as usize) };
    if rc != 0 {
        return None;
    }
    let len = block[1].min(buf.len());
    core::str::from_utf8(&buf[..len]).ok()
}

/// Why a host file could not be read.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FileError {
    /// The path is longer than the firmware's path buffer.
    PathTooLong,
    /// The host could not open the file.
    Open,
    /// A read failed on the host.
    Read,
    /// A line is longer than the line buffer.
    LineTooLong,
    /// A line is not UTF-8.
    NotUtf8,
    /// The file is larger than the buffer it must fit in.
    TooLarge,
}

impl fmt::Display for FileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            FileError::PathTooLong => "path too long",
            FileError::Open => "cannot open the file",
            FileError::Read => "read error",
            FileError::LineTooLong => "line too long",
            FileError::NotUtf8 => "not valid UTF-8",
            FileError::TooLarge => "file too large",
        })
    }
}

/// A host file open for reading.
pub struct HostFile {
    handle: usize,
}

impl HostFile {
    /// Opens `path` on the host, read-only, binary.
    pub fn open(path: &str) -> Result<Self, FileError> {
        let mut name = [0u8; 256];
        if path.len() >= name.len() {
            return Err(FileError::PathTooLong);
        }
        name[..path.len()].copy_from_slice(path.as_bytes());
        // SAFETY: SYS_OPEN reads `path.len()` bytes of a NUL-terminated name from
        // `name`, which outlives the call.
        let handle =
            unsafe { syscall!(OPEN, name.as_ptr(), nr::open::R_BINARY, path.len()) } as isize;
        if handle < 0 {
            return Err(FileError::Open);
        }
        Ok(HostFile {
            handle: handle as usize,
        })
    }

    /// Reads up to `buf.len()` bytes; returns how many were read (0 at end of file).
    pub fn read(&mut self, buf: &mut [u8]) -> Result<usize, FileError> {
        if buf.is_empty() {
            return Ok(0);
        }
        // SAFETY: SYS_READ writes at most `buf.len()` bytes into `buf`, which we
        // borrow mutably; it returns the number of bytes NOT read.
        let not_read = unsafe { syscall!(READ, self.handle, buf.as_mut_ptr(), buf.len()) };
        if not_read > buf.len() {
            return Err(FileError::Read);
        }
        Ok(buf.len() - not_read)
    }

    /// Reads the whole file into `buf`; fails if it does not fit.
    pub fn read_to_end<'b>(&mut self, buf: &'b mut [u8]) -> Result<&'b [u8], FileError> {
        let mut len = 0;
        loop {
            if len == buf.len() {
                let mut probe = [0u8; 1];
                return match self.read(&mut probe)? {
                    0 => Ok(&buf[..len]),
                    _ => Err(FileError::TooLarge),
                };
            }
            match self.read(&mut buf[len..])? {
                0 => return Ok(&buf[..len]),
                n => len += n,
            }
        }
    }
}

impl Drop for HostFile {
    fn drop(&mut self) {
        // SAFETY: SYS_CLOSE takes the handle SYS_OPEN gave us, closed only here.
        unsafe {
            syscall!(CLOSE, self.handle);
        }
    }
}

/// Reads a host file line by line through a fixed buffer (no heap): memory use
/// does not grow with the file. `\n` and `\r\n` line ends.
pub struct LineReader<const N: usize> {
    file: HostFile,
    buf: [u8; N],
    start: usize,
    end: usize,
    eof: bool,
}

impl<const N: usize> LineReader<N> {
    /// Wraps an open file.
    pub fn new(file: HostFile) -> Self {
        LineReader {
            file,
            buf: [0; N],
            start: 0,
            end: 0,
            eof: false,
        }
    }

    /// The next line without its line end, or `None` at the end of the file.
    pub fn next_line(&mut self) -> Result<Option<&str>, FileError> {
        loop {
            if let Some(pos) = self.buf[self.start..self.end]
                .iter()
                .position(|&b| b == b'\n')
            {
                let line_start = self.start;
                let mut line_end = self.start + pos;
                self.start = line_end + 1;
                if line_end > line_start && self.buf[line_end - 1] == b'\r' {
                    line_end -= 1;
                }
                return core::str::from_utf8(&self.buf[line_start..line_end])
                    .map(Some)
                    .map_err(|_| FileError::NotUtf8);
            }
            if self.eof {
                if self.start == self.end {
                    return Ok(None);
                }
                let (line_start, mut line_end) = (self.start, self.end);
                self.start = self.end;
                if self.buf[line_end - 1] == b'\r' {
                    line_end -= 1;
                }
                return core::str::from_utf8(&self.buf[line_start..line_end])
                    .map(Some)
                    .map_err(|_| FileError::NotUtf8);
            }
            if self.start > 0 {
                self.buf.copy_within(self.start..self.end, 0);
                self.end -= self.start;
                self.start = 0;
            }
            if self.end == N {
                return Err(FileError::LineTooLong);
            }
            let n = self.file.read(&mut self.buf[self.end..])?;
            if n == 0 {
                self.eof = true;
            }
            self.end += n;
        }
    }
}

/// A buffered writer to the host's stdout or stderr (`fmt::Write`).
pub struct HostWriter {
    handle: Option<usize>,
    buf: [u8; 256],
    len: usize,
}

impl HostWriter {
    fn open(mode: usize) -> Self {
        const TT: &[u8] = b":tt\0";
        // SAFETY: SYS_OPEN reads the NUL-terminated name ":tt" (the console).
        let handle = unsafe { syscall!(OPEN, TT.as_ptr(), mode, TT.len() - 1) } as isize;
        HostWriter {
            handle: (handle >= 0).then_some(handle as usize),
            buf: [0; 256],
            len: 0,
        }
    }

    /// The host's standard output (":tt" opened for writing).
    pub fn stdout() -> Self {
        Self::open(nr::open::W_TRUNC)
    }

    /// The host's standard error (":tt" opened for appending, libgloss's convention).
    pub fn stderr() -> Self {
        Self::open(nr::open::W_APPEND)
    }

    /// Writes out what is buffered.
    pub fn flush(&mut self) {
        if let Some(handle) = self.handle {
            let mut data = &self.buf[..self.len];
            while !data.is_empty() {
                // SAFETY: SYS_WRITE reads `data.len()` bytes from `data`; it
                // returns the number of bytes NOT written.
                let not_written = unsafe { syscall!(WRITE, handle, data.as_ptr(), data.len()) };
                if not_written == 0 || not_written > data.len() {
                    break;
                }
                data = &data[data.len() - not_written..];
            }
        }
        self.len = 0;
    }

    /// Writes raw bytes.
    pub fn write_bytes(&mut self, mut bytes: &[u8]) {
        while !bytes.is_empty() {
            if self.len == self.buf.len() {
                self.flush();
            }
            let n = bytes.len().min(self.buf.len() - self.len);
            self.buf[self.len..self.len + n].copy_from_slice(&bytes[..n]);
            self.len += n;
            bytes = &bytes[n..];
        }
    }
}

impl fmt::Write for HostWriter {
    fn write_str(&mut self, s: &str) -> fmt::Result {
        self.write_bytes(s.as_bytes());
        Ok(())
    }
}

impl Drop for HostWriter {
    fn drop(&mut self) {
        self.flush();
    }
}
