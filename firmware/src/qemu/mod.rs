//! The QEMU build: `crane-sim replay` on the emulated MCU.
//!
//! `cargo run --release --target thumbv7em-none-eabihf -p firmware -- LOG.csv
//! [--calibration CAL.json] [--json]` boots this image in `qemu-system-arm
//! -machine netduinoplus2` (scripts/qemu-runner.sh). It reads the arguments and
//! the files through semihosting, runs every sample of the log through the same
//! limiter code the board runs each 100 Hz cycle, prints the same timeline (or
//! JSON summary) as `crane-sim replay` with the limiter's own formatting
//! functions, and exits with the replay exit codes: 0 never OVERLOAD/FAULT, 2
//! entered OVERLOAD or FAULT, 1 the input could not be read.
//!
//! The replay is driven by the log's samples, not by the 100 Hz timer: it runs
//! as fast as QEMU can. No STM32 clock, SPI, GPIO or watchdog is initialised here
//! (QEMU does not model the RCC/PLL; see `board` for that part).
//!
//! `--budgets` (firmware only, not a crane-sim option) adds one line to stderr:
//! peak stack (paint-stack), and SysTick counts per control cycle (instructions
//! when QEMU runs with `-icount shift=0`).

pub mod budgets;
mod engine_placeholder;
pub mod semihosting;

use core::fmt::Write;
use semihosting::{FileError, HostFile, HostWriter, LineReader};

/// Exit code: the log was read and never entered OVERLOAD or FAULT.
pub const EXIT_OK: u8 = 0;
/// Exit code: the input (arguments, log or calibration) could not be read.
pub const EXIT_INPUT: u8 = 1;

/// The command line, as `crane-sim replay` takes it.
#[derive(Debug, Default)]
struct Args<'a> {
    log: Option<&'a str>,
    calibration: Option<&'a str>,
    json: bool,
    budgets: bool,
}

const USAGE: &str = "usage: firmware LOG.csv [--calibration CAL.json] [--json] [--budgets]";

fn parse_args(cmdline: &str) -> Result<Args<'_>, &'static str> {
    let mut args = Args::default();
    let mut words = cmdline.split_ascii_whitespace();
    let _program = words.next();
    while let Some(word) = words.next() {
        match word {
            "--json" => args.json = true,
            "--budgets" => args.budgets = true,
            "--calibration" => {
                args.calibration = Some(words.next().ok_or("--calibration needs a file")?)
            }
            "--trace" => return Err("--trace is not supported by the firmware (use crane-sim)"),
            w if w.starts_with("--calibration=") => {
                args.calibration = Some(&w["--calibration=".len()..])
            }
            w if w.starts_with('-') => return Err("unknown option"),
            w if args.log.is_none() => args.log = Some(w),
            _ => return Err("more than one log file"),
        }
    }
    if args.log.is_none() {
        return Err("missing LOG.csv");
    }
    Ok(args)
}

/// Runs the replay and returns the process exit code.
pub fn run(syst: cortex_m::peripheral::SYST) -> u8 {
    let mut err = HostWriter::stderr();
    let mut cmdline_buf = [0u8; 512];
    let Some(cmdline) = semihosting::command_line(&mut cmdline_buf) else {
        let _ = writeln!(err, "error: cannot read the semihosting command line");
        return EXIT_INPUT;
    };
    let args = match parse_args(cmdline) {
        Ok(args) => args,
        Err(why) => {
            let _ = writeln!(err, "error: {why}\n{USAGE}");
            return EXIT_INPUT;
        }
    };
    let log_path = args.log.unwrap_or_default();

    let mut calibration_buf = [0u8; 2048];
    let _calibration: Option<&[u8]> = match args.calibration {
        None => None,
        Some(path) => {
            match HostFile::open(path).and_then(|mut f| f.read_to_end(&mut calibration_buf)) {
                Ok(bytes) => Some(bytes),
                Err(e) => {
                    let _ = writeln!(err, "error: {path}: {e}");
                    return EXIT_INPUT;
                }
            }
        }
    };

    let file = match HostFile::open(log_path) {
        Ok(f) => f,
        Err(e) => {
            let _ = writeln!(err, "error: {log_path}: {e}");
            return EXIT_INPUT;
        }
    };
    let mut lines = LineReader::<512>::new(file);
    let mut out = HostWriter::stdout();
    let mut counter = budgets::CycleCounter::start(syst);
    let mut cycles = budgets::CycleStats::default();

    let mut replay = engine_placeholder::Replay::new();
    loop {
        let line = match lines.next_line() {
            Ok(Some(line)) => line,
            Ok(None) => break,
            Err(e) => {
                out.flush();
                let _ = writeln!(err, "error: {log_path}: {e}");
                return EXIT_INPUT;
            }
        };
        let (result, ticks) = counter.measure(|| replay.push_line(line));
        match result {
            Ok(Some(event)) => {
                cycles.add(ticks);
                if !args.json {
                    let _ = engine_placeholder::Replay::write_event(&mut out, &event);
                }
            }
            Ok(None) => cycles.add(ticks),
            Err(e) => {
                out.flush();
                let _ = writeln!(err, "error: {log_path}: {e}");
                return EXIT_INPUT;
            }
        }
    }
    let _ = replay.write_summary(&mut out, args.json);
    out.flush();

    if args.budgets {
        // Calibration: `asm::delay(n)` runs a 2-instruction loop n + 1 times, so it
        // executes 2n + 2 instructions. Under `-icount shift=0` each instruction
        // takes 1 ns of virtual time and SysTick ticks at the core clock QEMU
        // models (168 MHz on netduinoplus2): the script converts ticks to
        // instructions with this ratio instead of assuming it.
        let ((), delay_ticks) = counter.measure(|| cortex_m::asm::delay(CALIBRATION_LOOPS));
        report_budgets(&mut err, &cycles, delay_ticks);
    }
    replay.exit_code()
}

/// Loops of the calibration delay (see `run`).
const CALIBRATION_LOOPS: u32 = 500_000;

/// One machine-readable line on stderr for scripts/firmware-budgets.sh.
fn report_budgets(err: &mut HostWriter, cycles: &budgets::CycleStats, delay_ticks: u32) {
    let (_, stack_size) = budgets::stack_region();
    let _ = writeln!(
        err,
        "budgets: stack_peak_bytes={} stack_region_bytes={} cycles={} ticks_per_cycle_max={} ticks_per_cycle_mean={} calibration_instructions={} calibration_ticks={}",
        budgets::peak_stack_bytes(),
        stack_size,
        cycles.count,
        cycles.max,
        cycles.mean(),
        2 * CALIBRATION_LOOPS + 2,
        delay_ticks,
    );
}

#[allow(dead_code)]
fn _assert_error_display(e: FileError) -> impl core::fmt::Display {
    e
}
