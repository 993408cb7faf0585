//! `calibration-image CAL.json OUT.bin [--blob]`: makes what the board loads
//! its calibration from, out of a calibration file.
//!
//! The file is read with the one calibration reader
//! (`moment_limiter::tools::config_file`: schema version 4, 3, 2 or 1, every key required and
//! bounded); a refused file exits 1 with the reader's message, which names
//! the key. Then:
//!
//! - default: `OUT.bin` is an image of the board's whole **settings flash
//!   range** (sectors 8–9, 256 KiB at [`SETTINGS_BASE`], see `memory.x`):
//!   a fresh two-bank journal holding the calibration blob
//!   (`limiter_storage::calibration_blob`), written through the very
//!   `Store` the board reads it with. Flash it with
//!   `probe-rs download --chip STM32F405RGTx --binary-format bin
//!   --base-address 0x08080000 OUT.bin`. It replaces the whole range: the
//!   fault latch and the boot counter start afresh (a service action).
//! - `--blob`: `OUT.bin` is the 100-byte blob alone (format 4).
//!
//! Exit codes: 0 written, 1 refused file or usage or I/O error.

use embedded_storage::nor_flash::{
    ErrorType, NorFlash, NorFlashError, NorFlashErrorKind, ReadNorFlash,
};
use limiter_storage::calibration_blob::{encode_calibration, store_calibration, BLOB_LEN};
use limiter_storage::store::{Layout, Store};
use moment_limiter::tools::config_file::parse_calibration;
use std::process::ExitCode;

/// Address of the settings range on the STM32F405 (`_settings_flash_start`).
const SETTINGS_BASE: u32 = 0x0808_0000;
/// Length of the settings range (`_settings_flash_end` − start): two banks.
const SETTINGS_LEN: usize = 256 * 1024;
/// Erase unit of stm32f4xx-hal's `NorFlash` (the board's geometry).
const ERASE: usize = 128 * 1024;

/// The settings range in RAM, with the board's flash geometry.
struct RamFlash(Vec<u8>);

#[derive(Debug)]
struct OutOfRange;

impl NorFlashError for OutOfRange {
    fn kind(&self) -> NorFlashErrorKind {
        NorFlashErrorKind::OutOfBounds
    }
}

impl ErrorType for RamFlash {
    type Error = OutOfRange;
}

impl ReadNorFlash for RamFlash {
    const READ_SIZE: usize = 1;
    fn read(&mut self, offset: u32, bytes: &mut [u8]) -> Result<(), OutOfRange> {
        let at = offset as usize;
        let src = self.0.get(at..at + bytes.len()).ok_or(OutOfRange)?;
        bytes.copy_from_slice(src);
        Ok(())
    }
    fn capacity(&self) -> usize {
        self.0.len()
    }
}

impl NorFlash for RamFlash {
    const WRITE_SIZE: usize = 1;
    const ERASE_SIZE: usize = ERASE;
    fn erase(&mut self, from: u32, to: u32) -> Result<(), OutOfRange> {
        self.0
            .get_mut(from as usize..to as usize)
            .ok_or(OutOfRange)?
            .fill(0xFF);
        Ok(())
    }
    fn write(&mut self, offset: u32, bytes: &[u8]) -> Result<(), OutOfRange> {
        let at = offset as usize;
        let dst = self.0.get_mut(at..at + bytes.len()).ok_or(OutOfRange)?;
        for (d, s) in dst.iter_mut().zip(bytes) {
            *d &= s; // NOR flash: programming only clears bits
        }
        Ok(())
    }
}

fn settings_image(
    cal: &moment_limiter::load_estimate::Calibration<f64>,
) -> Result<Vec<u8>, String> {
    let layout = Layout {
        settings: 0..SETTINGS_LEN as u32,
        events: 0..0,
    };
    let mut store = Store::new(RamFlash(vec![0xFF; SETTINGS_LEN]), layout);
    store_calibration(&mut store, cal).map_err(|e| format!("{e:?}"))?;
    Ok(store.into_flash().0)
}

fn run(args: &[String]) -> Result<String, String> {
    let usage = "usage: calibration-image CAL.json OUT.bin [--blob]";
    let blob_only = args.iter().any(|a| a == "--blob");
    let paths: Vec<&String> = args.iter().filter(|a| *a != "--blob").collect();
    let [cal_path, out_path] = paths.as_slice() else {
        return Err(usage.into());
    };
    if let Some(flag) = paths.iter().find(|p| p.starts_with("--")) {
        return Err(format!("unknown option `{flag}`\n{usage}"));
    }
    let text = std::fs::read(cal_path).map_err(|e| format!("{cal_path}: {e}"))?;
    let cal = parse_calibration::<f64>(&text).map_err(|e| format!("{cal_path}: {e}"))?;
    let bytes = if blob_only {
        encode_calibration(&cal)
            .map_err(|e| format!("{cal_path}: {e}"))?
            .to_vec()
    } else {
        settings_image(&cal)?
    };
    std::fs::write(out_path, &bytes).map_err(|e| format!("{out_path}: {e}"))?;
    Ok(if blob_only {
        format!("{out_path}: calibration blob, {BLOB_LEN} bytes")
    } else {
        format!(
            "{out_path}: settings flash image, {} bytes; flash at 0x{SETTINGS_BASE:08x}",
            bytes.len()
        )
    })
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match run(&args) {
        Ok(msg) => {
            println!("{msg}");
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("calibration-image: {e}");
            ExitCode::from(1)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use limiter_storage::calibration_blob::load_calibration;

    #[test]
    fn the_constants_match_memory_x() {
        let memory_x = include_str!("../../../../memory.x");
        let start = format!("_settings_flash_start = 0x{SETTINGS_BASE:08X};");
        let end = format!(
            "_settings_flash_end = 0x{:08X};",
            SETTINGS_BASE + SETTINGS_LEN as u32
        );
        assert!(memory_x.contains(&start), "memory.x lacks `{start}`");
        assert!(memory_x.contains(&end), "memory.x lacks `{end}`");
    }

    #[test]
    fn the_image_reads_back_through_the_boards_store() {
        let text = include_str!("../../../../examples/logs/cal.json");
        let cal = parse_calibration::<f64>(text.as_bytes()).unwrap();
        let image = settings_image(&cal).unwrap();
        assert_eq!(image.len(), SETTINGS_LEN);
        let layout = Layout {
            settings: 0..SETTINGS_LEN as u32,
            events: 0..0,
        };
        let mut store = Store::new(RamFlash(image), layout);
        // The example is of schema 1 (no lag, no release time): stored with
        // the standard configuration's, what the limiter used for them.
        let lag = moment_limiter::cycle::DEFAULT_ANGLE_SENSOR_LAG_S;
        let release = moment_limiter::cycle::DEFAULT_SEAL_RELEASE_S;
        assert_eq!((cal.angle_sensor_lag_s, cal.seal_release_up_s), (None, None));
        let stored = moment_limiter::load_estimate::Calibration { angle_sensor_lag_s: Some(lag), seal_release_up_s: Some(release), ..cal };
        assert_eq!(load_calibration::<f64, _>(&mut store).unwrap().0, stored);
        let cal32 = parse_calibration::<f32>(text.as_bytes()).unwrap();
        assert_eq!(
            load_calibration::<f32, _>(&mut store).unwrap().0,
            moment_limiter::load_estimate::Calibration { angle_sensor_lag_s: Some(lag as f32), seal_release_up_s: Some(release as f32), ..cal32 }
        );
    }
}
