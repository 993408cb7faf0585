//! The image checksum: a 16-byte stamp compiled into the firmware and filled in
//! after linking by the `stamp-image` tool, checked by the power-up self-test.
//!
//! Stamp layout (little-endian), somewhere in the flash image:
//!
//! | bytes | field  | unstamped value | stamped value |
//! |-------|--------|-----------------|---------------|
//! | 0..8  | magic  | [`STAMP_MAGIC`] | the same |
//! | 8..12 | length | `0xFFFF_FFFF`   | bytes of the image from the start of flash |
//! | 12..16| crc    | `0xFFFF_FFFF`   | CRC-32 of those bytes, with the length and crc fields read as `0xFF` |
//!
//! The checksum covers the whole flash image (vector table, code, read-only
//! data and the initial values of `.data`), everything but its own 8 bytes, so
//! any flipped bit of the image is found. An image still carrying the unstamped
//! values is reported as [`ImageError::NotStamped`]: the firmware decides what
//! that means (the board refuses to run; a QEMU development image runs).

use crate::crc::Crc32;

/// Marks the stamp in the image (and lets the tool find it).
pub const STAMP_MAGIC: [u8; 8] = *b"LML-CRC\x01";
/// Size of the stamp in bytes.
pub const STAMP_LEN: usize = 16;
/// The value of the length and crc fields before stamping (erased flash).
pub const UNSTAMPED: u32 = 0xFFFF_FFFF;

/// The stamp as the firmware declares it before stamping (`#[used]` static).
pub const UNSTAMPED_STAMP: [u8; STAMP_LEN] = {
    let mut s = [0xFFu8; STAMP_LEN];
    let mut i = 0;
    while i < 8 {
        s[i] = STAMP_MAGIC[i];
        i += 1;
    }
    s
};

/// Why the image check failed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ImageError {
    /// No stamp magic at the stamp's offset (or the offset is outside the image).
    NoStamp,
    /// The stamp still has its unstamped values: the image was never stamped.
    NotStamped,
    /// The stamped length does not fit the flash given, or excludes the stamp.
    BadLength {
        /// Stamped length.
        length: u32,
    },
    /// The image's CRC differs from the stamped one: corrupted image.
    Mismatch {
        /// CRC stamped at build time.
        stamped: u32,
        /// CRC computed now.
        computed: u32,
    },
}

impl core::fmt::Display for ImageError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            ImageError::NoStamp => write!(f, "no checksum stamp found"),
            ImageError::NotStamped => {
                write!(f, "image not stamped (run stamp-image after linking)")
            }
            ImageError::BadLength { length } => {
                write!(f, "stamped image length {length} is impossible")
            }
            ImageError::Mismatch { stamped, computed } => write!(
                f,
                "image checksum mismatch: stamped CRC-32 0x{stamped:08x}, computed 0x{computed:08x}"
            ),
        }
    }
}

/// A verified image: its length and CRC.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Verified {
    /// Image bytes checked.
    pub length: u32,
    /// Their CRC-32.
    pub crc: u32,
}

fn word(bytes: &[u8], at: usize) -> Option<u32> {
    let b = bytes.get(at..)?.first_chunk::<4>()?;
    Some(u32::from_le_bytes(*b))
}

/// CRC-32 of `image[..length]` with the stamp's 8 field bytes at
/// `stamp_offset + 8` read as `0xFF` (what both the tool and the check compute).
pub fn image_crc(image: &[u8], stamp_offset: usize, length: usize) -> Option<u32> {
    let fields = stamp_offset.checked_add(8)?;
    let after = stamp_offset.checked_add(STAMP_LEN)?;
    if after > length {
        return None;
    }
    let mut c = Crc32::new();
    c.update(image.get(..fields)?);
    c.update(&[0xFF; 8]);
    c.update(image.get(after..length)?);
    Some(c.finish())
}

/// Checks `image` (the flash from its first byte; may be longer than the
/// image) against the stamp at `stamp_offset`.
pub fn verify(image: &[u8], stamp_offset: usize) -> Result<Verified, ImageError> {
    let magic = image
        .get(stamp_offset..stamp_offset.saturating_add(8))
        .ok_or(ImageError::NoStamp)?;
    if magic != STAMP_MAGIC {
        return Err(ImageError::NoStamp);
    }
    let length = word(image, stamp_offset + 8).ok_or(ImageError::NoStamp)?;
    let stamped = word(image, stamp_offset + 12).ok_or(ImageError::NoStamp)?;
    if length == UNSTAMPED && stamped == UNSTAMPED {
        return Err(ImageError::NotStamped);
    }
    let computed = usize::try_from(length)
        .ok()
        .filter(|&l| l <= image.len())
        .and_then(|l| image_crc(image, stamp_offset, l))
        .ok_or(ImageError::BadLength { length })?;
    if computed != stamped {
        return Err(ImageError::Mismatch { stamped, computed });
    }
    Ok(Verified {
        length,
        crc: computed,
    })
}

/// Fills the stamp at `stamp_offset` of `image` (all of which is the flash
/// image): what the `stamp-image` tool does to the linked binary.
pub fn stamp(image: &mut [u8], stamp_offset: usize) -> Result<Verified, ImageError> {
    let length = image.len();
    let length32 =
        u32::try_from(length).map_err(|_| ImageError::BadLength { length: UNSTAMPED })?;
    if image.get(stamp_offset..stamp_offset.saturating_add(8)) != Some(&STAMP_MAGIC[..]) {
        return Err(ImageError::NoStamp);
    }
    let crc =
        image_crc(image, stamp_offset, length).ok_or(ImageError::BadLength { length: length32 })?;
    let fields = image
        .get_mut(stamp_offset + 8..stamp_offset + STAMP_LEN)
        .ok_or(ImageError::NoStamp)?;
    crate::put(fields, 0, &length32.to_le_bytes());
    crate::put(fields, 4, &crc.to_le_bytes());
    Ok(Verified {
        length: length32,
        crc,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unstamped_image() -> (Vec<u8>, usize) {
        let mut img: Vec<u8> = (0..4096u32)
            .map(|i| (i.wrapping_mul(2654435761) >> 13) as u8)
            .collect();
        let at = 1000;
        img[at..at + STAMP_LEN].copy_from_slice(&UNSTAMPED_STAMP);
        (img, at)
    }

    #[test]
    fn stamped_image_verifies_and_flash_beyond_it_is_ignored() {
        let (mut img, at) = unstamped_image();
        let v = stamp(&mut img, at).unwrap();
        assert_eq!(v.length, 4096);
        // The flash after the image (erased) is not part of it.
        let mut flash = img.clone();
        flash.extend_from_slice(&[0xFF; 512]);
        assert_eq!(verify(&flash, at), Ok(v));
    }

    #[test]
    fn unstamped_image_is_reported_as_such() {
        let (img, at) = unstamped_image();
        assert_eq!(verify(&img, at), Err(ImageError::NotStamped));
        assert_eq!(verify(&img, at + 1), Err(ImageError::NoStamp));
        assert_eq!(verify(&img, img.len() - 4), Err(ImageError::NoStamp));
    }

    #[test]
    fn any_corrupted_byte_fails_the_check() {
        let (mut img, at) = unstamped_image();
        let v = stamp(&mut img, at).unwrap();
        for i in (0..img.len()).step_by(7) {
            let mut bad = img.clone();
            bad[i] ^= 0x10;
            let r = verify(&bad, at);
            assert!(r.is_err(), "corruption of byte {i} passed the check");
            if !(at..at + STAMP_LEN).contains(&i) {
                assert_eq!(
                    r,
                    Err(ImageError::Mismatch {
                        stamped: v.crc,
                        computed: image_crc(&bad, at, bad.len()).unwrap()
                    })
                );
            }
        }
    }

    #[test]
    fn corrupted_stamped_crc_fails() {
        let (mut img, at) = unstamped_image();
        let v = stamp(&mut img, at).unwrap();
        img[at + 12] ^= 1;
        assert_eq!(
            verify(&img, at),
            Err(ImageError::Mismatch {
                stamped: v.crc ^ 1,
                computed: v.crc
            })
        );
    }

    #[test]
    fn impossible_length_is_refused_not_read() {
        let (mut img, at) = unstamped_image();
        stamp(&mut img, at).unwrap();
        img[at + 8..at + 12].copy_from_slice(&100_000u32.to_le_bytes());
        assert_eq!(
            verify(&img, at),
            Err(ImageError::BadLength { length: 100_000 })
        );
        img[at + 8..at + 12].copy_from_slice(&((at + 4) as u32).to_le_bytes());
        assert!(matches!(
            verify(&img, at),
            Err(ImageError::BadLength { .. })
        ));
    }
}
