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
//! `--calibration-blob CAL.bin` (firmware only) takes the calibration in the
//! board's stored form instead (`limiter_storage::calibration_blob`, made by
//! `calibration-image --blob`), decoded and bounds-checked by the code the
//! board runs at start-up: the same replay as with the JSON file it was made
//! from, and a refused blob exits 1 like a refused file.
//!
//! `--budgets` (firmware only, not a crane-sim option) adds one line to stderr:
//! peak stack (paint-stack), and SysTick counts per control cycle (instructions
//! when QEMU runs with `-icount shift=0`).

pub mod budgets;
pub mod semihosting;

use core::fmt::Write;
use moment_limiter::cycle::{Limiter, LimiterConfig};
use moment_limiter::tools::log_format::{LogError, LogErrorKind, LogParser};
use moment_limiter::tools::replay::{self, Replay, ReplayEvent, ReplaySummary};
use semihosting::{FileError, HostFile, HostWriter, LineReader};

/// Exit code: the input (arguments, log or calibration) could not be read.
pub const EXIT_INPUT: u8 = 1;

/// Bytes of one log line the firmware accepts (longer lines are an error).
const LINE_BUF: usize = 512;

/// The command line, as `crane-sim replay` takes it.
#[derive(Debug, Default)]
struct Args<'a> {
    log: Option<&'a str>,
    calibration: Option<&'a str>,
    calibration_blob: Option<&'a str>,
    json: bool,
    budgets: bool,
}

const USAGE: &str =
    "usage: firmware LOG.csv [--calibration CAL.json | --calibration-blob CAL.bin] [--json] [--budgets]";

fn parse_args(cmdline: &str) -> Result<Args<'_>, &'static str> {
    let mut args = Args::default();
    let mut words = cmdline.split_ascii_whitespace();
    let _program = words.next();
    while let Some(word) = words.next() {
        match word {
            "--json" => args.json = true,
            "--budgets" => args.budgets = true,
            // Handled before the replay by `qemu_boot` (self-test report, fault test).
            "--self-test" | "--trigger-hardfault" => {}
            "--calibration" => {
                args.calibration = Some(words.next().ok_or("--calibration needs a file")?)
            }
            "--calibration-blob" => {
                args.calibration_blob = Some(words.next().ok_or("--calibration-blob needs a file")?)
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
    if args.calibration.is_some() && args.calibration_blob.is_some() {
        return Err("give one of --calibration and --calibration-blob");
    }
    Ok(args)
}

/// What one pass over the log ended with.
struct PassEnd {
    summary: ReplaySummary<f32>,
    /// Why the log was not read to its end, if it was not.
    error: Option<LogError>,
}

/// Opens the log and runs every line through a fresh limiter, calling
/// `on_event` for each state change. Per-cycle counts go to `cycles`.
// Never inlined: `--json` runs two passes, and inlined into `run` each kept
// its own limiter on the stack (the rope bank alone is 2.8 KB in f32); as
// calls, the second pass reuses the first's frame.
#[inline(never)]
fn replay_pass(
    path: &str,
    config: &LimiterConfig<f32>,
    calibrated: bool,
    counter: &mut budgets::CycleCounter,
    cycles: &mut budgets::CycleStats,
    mut on_event: impl FnMut(&ReplayEvent<f32>),
) -> Result<PassEnd, FileError> {
    let limiter = match Limiter::new(crate::model::hook_load_model(), config.clone()) {
        Ok(limiter) => limiter,
        Err(_) => return Err(FileError::Open), // checked by the caller before
    };
    let mut replay = Replay::new(limiter, calibrated);
    let mut parser = LogParser::<f32>::new();
    let mut lines = LineReader::<LINE_BUF>::new(HostFile::open(path)?);
    let error = loop {
        let line = match lines.next_line() {
            Ok(Some(line)) => line,
            Ok(None) => break parser.finish().err(),
            Err(FileError::NotUtf8) => break Some(parser.reject_next_line(LogErrorKind::NotUtf8)),
            Err(_) => break Some(parser.reject_next_line(LogErrorKind::Unreadable)),
        };
        match parser.feed_line(line) {
            Ok(Some(record)) => {
                // One control cycle: the same `Limiter` step the board runs.
                let ((_, event), ticks) = counter.measure(|| replay.feed(&record));
                cycles.add(ticks);
                if let Some(event) = event {
                    on_event(&event);
                }
            }
            Ok(None) => {}
            Err(e) => break Some(e),
        }
    };
    Ok(PassEnd {
        summary: replay.summary(),
        error,
    })
}

/// Writes the JSON object of `crane-sim replay --json` without holding the
/// events: the limiter's `write_json` formats the head (with no events) and
/// then each event on its own, and only the event part of each is kept, so
/// every byte still comes from the limiter's formatter.
struct JsonStream {
    events: u32,
}

const EVENTS_KEY: &str = "\"events\":[";
const JSON_TAIL: &str = "]}\n";

impl JsonStream {
    fn head(out: &mut HostWriter, summary: &ReplaySummary<f32>, error: Option<&LogError>) -> Self {
        let mut buf = heapless::String::<1024>::new();
        let _ = replay::write_json(&mut buf, summary, core::iter::empty(), error);
        match buf.find(EVENTS_KEY) {
            Some(i) => out.write_bytes(&buf.as_bytes()[..i + EVENTS_KEY.len()]),
            None => out.write_bytes(buf.as_bytes()),
        }
        JsonStream { events: 0 }
    }

    fn event(
        &mut self,
        out: &mut HostWriter,
        summary: &ReplaySummary<f32>,
        event: &ReplayEvent<f32>,
    ) {
        let mut buf = heapless::String::<1024>::new();
        let _ = replay::write_json(&mut buf, summary, core::iter::once(event), None);
        let start = buf.find(EVENTS_KEY).map_or(0, |i| i + EVENTS_KEY.len());
        let end = buf.len().saturating_sub(JSON_TAIL.len());
        if self.events > 0 {
            out.write_bytes(b",");
        }
        out.write_bytes(&buf.as_bytes()[start..end.max(start)]);
        self.events += 1;
    }

    fn tail(self, out: &mut HostWriter) {
        out.write_bytes(JSON_TAIL.as_bytes());
    }
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

    let mut config = LimiterConfig::<f32>::standard();
    let calibrated = args.calibration.is_some() || args.calibration_blob.is_some();
    if let Some(path) = args.calibration {
        let mut buf = [0u8; 2048];
        let text = match HostFile::open(path).and_then(|mut f| f.read_to_end(&mut buf)) {
            Ok(bytes) => bytes,
            Err(e) => {
                let _ = writeln!(err, "error: {path}: {e}");
                return EXIT_INPUT;
            }
        };
        match moment_limiter::tools::config_file::parse_calibration(text) {
            Ok(calibration) => config.calibration = calibration,
            Err(e) => {
                let _ = writeln!(err, "error: calibration {path} refused: {e}");
                return EXIT_INPUT;
            }
        }
    } else if let Some(path) = args.calibration_blob {
        let mut buf = [0u8; limiter_storage::calibration_blob::BLOB_LEN + 1];
        let read = HostFile::open(path).and_then(|mut f| f.read_to_end(&mut buf).map(<[u8]>::len));
        let bytes = match read {
            Ok(n) => buf.get(..n).unwrap_or_default(),
            // A file longer than the buffer is not a calibration blob: the
            // decoder refuses it by its length.
            Err(FileError::TooLarge) => &buf[..],
            Err(e) => {
                let _ = writeln!(err, "error: {path}: {e}");
                return EXIT_INPUT;
            }
        };
        match limiter_storage::calibration_blob::decode_calibration(bytes) {
            Ok(calibration) => config.calibration = calibration,
            Err(e) => {
                let _ = writeln!(err, "error: calibration blob {path} refused: {e}");
                return EXIT_INPUT;
            }
        }
    } else {
        let _ = writeln!(err, "{}", replay::UNCALIBRATED_NOTE);
    }
    // The configuration is checked as `Limiter::new` checks it, without a
    // limiter of its own on the stack.
    if let Err(e) = config.validate() {
        let _ = writeln!(err, "error: {e}");
        return EXIT_INPUT;
    }

    let mut out = HostWriter::stdout();
    let mut counter = budgets::CycleCounter::start(syst);
    let mut cycles = budgets::CycleStats::default();

    let end = if args.json {
        // Pass 1 finds the summary that heads the object; pass 2 streams the
        // events (the replay is deterministic: the same events again).
        let first = replay_pass(
            log_path,
            &config,
            calibrated,
            &mut counter,
            &mut cycles,
            |_| {},
        );
        match first {
            Ok(first) => {
                let mut json = JsonStream::head(&mut out, &first.summary, first.error.as_ref());
                let mut ignored = budgets::CycleStats::default();
                let second = replay_pass(
                    log_path,
                    &config,
                    calibrated,
                    &mut counter,
                    &mut ignored,
                    |e| json.event(&mut out, &first.summary, e),
                );
                json.tail(&mut out);
                second.map(|_| first)
            }
            Err(e) => Err(e),
        }
    } else {
        replay_pass(
            log_path,
            &config,
            calibrated,
            &mut counter,
            &mut cycles,
            |e| {
                let _ = replay::write_event_line(&mut out, e);
            },
        )
        .inspect(|end| {
            let _ = replay::write_summary_line(&mut out, &end.summary);
        })
    };
    out.flush();

    let code = match end {
        Err(e) => {
            let _ = writeln!(err, "error: {log_path}: {e}");
            EXIT_INPUT
        }
        Ok(PassEnd { error: Some(e), .. }) => {
            let _ = writeln!(err, "error: {log_path}: {e}");
            EXIT_INPUT
        }
        Ok(PassEnd {
            summary,
            error: None,
        }) => summary.exit_code(),
    };

    if args.budgets {
        // Calibration: `asm::delay(n)` runs a 2-instruction loop n + 1 times, so it
        // executes 2n + 2 instructions. Under `-icount shift=0` each instruction
        // takes 1 ns of virtual time and SysTick ticks at the core clock QEMU
        // models (168 MHz on netduinoplus2): the script converts ticks to
        // instructions with this ratio instead of assuming it.
        let ((), delay_ticks) = counter.measure(|| cortex_m::asm::delay(CALIBRATION_LOOPS));
        report_budgets(&mut err, &cycles, delay_ticks);
    }
    code
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
