//! Standard output of every subcommand (SPEC §5 exit codes).
//!
//! A reader that stops reading (`crane-sim replay LOG | head -1`) closes the
//! pipe: that is the user's choice, not an error, so the output ends quietly
//! (no "Broken pipe" message) and the command carries on to its own exit
//! code (`replay` still exits 0 or 2 by what the log showed). Any other
//! write error (a full disk, `> /dev/full`) is an error: the command fails
//! with exit 1 and says so.

use std::io::{self, StdoutLock, Write};

/// Standard output that swallows a closed pipe (see the module doc).
pub struct Stdout {
    inner: StdoutLock<'static>,
    closed: bool,
}

/// The locked standard output.
pub fn stdout() -> Stdout {
    Stdout {
        inner: io::stdout().lock(),
        closed: false,
    }
}

impl Stdout {
    fn quiet(&mut self, r: io::Result<()>) -> io::Result<()> {
        match r {
            Err(e) if e.kind() == io::ErrorKind::BrokenPipe => {
                self.closed = true;
                Ok(())
            }
            Err(e) => Err(io::Error::new(
                e.kind(),
                format!("cannot write to standard output: {e}"),
            )),
            Ok(()) => Ok(()),
        }
    }
}

impl Write for Stdout {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        if self.closed {
            return Ok(buf.len());
        }
        let r = self.inner.write_all(buf);
        self.quiet(r).map(|()| buf.len())
    }

    fn flush(&mut self) -> io::Result<()> {
        if self.closed {
            return Ok(());
        }
        let r = self.inner.flush();
        self.quiet(r)
    }
}
