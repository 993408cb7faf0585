//! `sequential-storage` speaks the async `embedded-storage-async` traits; the
//! limiter's flash (stm32f4xx-hal's `UnlockedFlash`, the host mocks) is
//! blocking. [`Blocking`] presents a blocking [`NorFlash`] as an async one whose
//! futures complete on their first poll, and [`run`] drives such a future to its
//! end without an executor.

use core::future::Future;
use core::pin::pin;
use core::task::{Context, Poll, Waker};
use embedded_storage::nor_flash::{ErrorType, NorFlash, ReadNorFlash};
use embedded_storage_async::nor_flash as asynch;

/// A blocking flash seen through the async NorFlash traits.
#[derive(Debug)]
pub struct Blocking<F>(pub F);

impl<F: ErrorType> ErrorType for Blocking<F> {
    type Error = F::Error;
}

impl<F: ReadNorFlash> asynch::ReadNorFlash for Blocking<F> {
    const READ_SIZE: usize = F::READ_SIZE;

    async fn read(&mut self, offset: u32, bytes: &mut [u8]) -> Result<(), Self::Error> {
        self.0.read(offset, bytes)
    }

    fn capacity(&self) -> usize {
        self.0.capacity()
    }
}

impl<F: NorFlash> asynch::NorFlash for Blocking<F> {
    const WRITE_SIZE: usize = F::WRITE_SIZE;
    const ERASE_SIZE: usize = F::ERASE_SIZE;

    async fn erase(&mut self, from: u32, to: u32) -> Result<(), Self::Error> {
        self.0.erase(from, to)
    }

    async fn write(&mut self, offset: u32, bytes: &[u8]) -> Result<(), Self::Error> {
        self.0.write(offset, bytes)
    }
}

/// The future was still pending after its poll: impossible with [`Blocking`]
/// (every flash call completes at once); reported instead of spinning.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct WouldBlock;

/// Polls `future` once and returns its output. Futures built only on
/// [`Blocking`] flash never pend, so one poll runs them to completion; a future
/// that would pend gives [`WouldBlock`] rather than a busy loop.
pub fn run<T>(future: impl Future<Output = T>) -> Result<T, WouldBlock> {
    let mut future = pin!(future);
    let mut cx = Context::from_waker(Waker::noop());
    match future.as_mut().poll(&mut cx) {
        Poll::Ready(v) => Ok(v),
        Poll::Pending => Err(WouldBlock),
    }
}
