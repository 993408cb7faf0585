//! The board's entry point (binary `firmware-board`, feature `board`): the
//! start-up sequence and the 100 Hz control loop of [`firmware::board::run`].
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
#[cortex_m_rt::entry]
fn main() -> ! {
    firmware::board::run()
}
