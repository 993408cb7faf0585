//! The QEMU build's entry point (binary `firmware`, feature `qemu`): the
//! power-up self-test with the simulated outputs cut, then the replay of the
//! log named on the semihosting command line ([`firmware::qemu`]).
#![cfg_attr(target_os = "none", no_std)]
#![cfg_attr(target_os = "none", no_main)]
// cortex-m-rt's `#[entry]` expands to an `#[export_name]` item, which the
// unsafe_code lint flags; the attribute is required by the runtime.
#![allow(unsafe_code)]

#[cfg(not(target_os = "none"))]
fn main() {
    eprintln!("the firmware runs on the MCU: build with --target thumbv7em-none-eabihf");
    std::process::exit(1);
}

#[cfg(target_os = "none")]
use firmware::{qemu, qemu_boot};

#[cfg(target_os = "none")]
#[cortex_m_rt::entry]
fn main() -> ! {
    // `take` only fails if called twice; `main` runs once.
    let Some(mut core) = cortex_m::Peripherals::take() else {
        qemu::semihosting::exit(qemu::EXIT_INPUT)
    };
    // Self-test first (outputs cut), then the firmware-only test switches.
    qemu_boot::boot(&mut core.SYST);
    let code = qemu::run(core.SYST);
    qemu::semihosting::exit(code)
}
