//! `stamp-image FIRMWARE.elf`: fills the image checksum stamp of a linked
//! firmware ELF in place (see `limiter_storage::image`).
//!
//! The flash image is what `arm-none-eabi-objcopy -O binary` makes of the ELF
//! (every loadable section at its load address, from the start of flash). The
//! stamp is found by its magic, which must occur exactly once in the image and
//! exactly once in the ELF file; the CRC is computed by the same function the
//! firmware's self-test uses, and the two 32-bit fields are written into the
//! ELF at the stamp's file offset. Running it twice is harmless (the fields are
//! read as 0xFF for the CRC either way).
//!
//! Environment: `OBJCOPY` (default `arm-none-eabi-objcopy`).

use limiter_storage::image::{self, STAMP_LEN, STAMP_MAGIC};
use std::process::{Command, ExitCode};

fn find_once(hay: &[u8], what: &str) -> Result<usize, String> {
    let mut hits = hay
        .windows(STAMP_MAGIC.len())
        .enumerate()
        .filter(|(_, w)| *w == STAMP_MAGIC)
        .map(|(i, _)| i);
    match (hits.next(), hits.next()) {
        (Some(i), None) => Ok(i),
        (None, _) => Err(format!("no checksum stamp in the {what}")),
        (Some(_), Some(_)) => Err(format!(
            "the stamp magic occurs more than once in the {what}"
        )),
    }
}

fn stamp(elf_path: &str) -> Result<String, String> {
    let objcopy = std::env::var("OBJCOPY").unwrap_or_else(|_| "arm-none-eabi-objcopy".into());
    let bin_path = format!("{elf_path}.stamp.bin");
    let status = Command::new(&objcopy)
        .args(["-O", "binary", elf_path, &bin_path])
        .status()
        .map_err(|e| format!("cannot run {objcopy}: {e}"))?;
    if !status.success() {
        return Err(format!("{objcopy} failed on {elf_path}"));
    }
    let mut bin = std::fs::read(&bin_path).map_err(|e| format!("{bin_path}: {e}"))?;
    let _ = std::fs::remove_file(&bin_path);
    let in_bin = find_once(&bin, "flash image")?;
    let verified = image::stamp(&mut bin, in_bin).map_err(|e| e.to_string())?;

    let mut elf = std::fs::read(elf_path).map_err(|e| format!("{elf_path}: {e}"))?;
    let in_elf = find_once(&elf, "ELF file")?;
    elf[in_elf..in_elf + STAMP_LEN].copy_from_slice(&bin[in_bin..in_bin + STAMP_LEN]);
    std::fs::write(elf_path, &elf).map_err(|e| format!("{elf_path}: {e}"))?;
    Ok(format!(
        "{elf_path}: stamped {} bytes of flash image, CRC-32 0x{:08x} (stamp at image offset 0x{in_bin:x})",
        verified.length, verified.crc
    ))
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [elf] = args.as_slice() else {
        eprintln!("usage: stamp-image FIRMWARE.elf");
        return ExitCode::from(1);
    };
    match stamp(elf) {
        Ok(msg) => {
            println!("{msg}");
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("stamp-image: {e}");
            ExitCode::from(1)
        }
    }
}
