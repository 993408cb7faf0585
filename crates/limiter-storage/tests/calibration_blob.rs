//! The calibration's stored form (`calibration_blob`): JSON → blob → the same
//! calibration; every bound of the schema enforced by the blob decoder too,
//! with the JSON reader's verdict; corrupt, truncated and foreign blobs
//! refused, also through the store the board reads them from.

mod common;

use common::{layout, CutFlash};
use limiter_storage::calibration_blob::{
    decode_calibration, encode_calibration, load_calibration, CalibrationBlobError, BLOB_FORMAT,
    BLOB_FORMAT_1, BLOB_FORMAT_2, BLOB_FORMAT_3, BLOB_FORMAT_4, BLOB_LEN, BLOB_LEN_1, BLOB_LEN_2,
    BLOB_LEN_3, BLOB_LEN_4, BLOB_MAGIC,
};
use limiter_storage::crc::crc32;
use limiter_storage::store::{Key, Store};
use moment_limiter::tools::config_file::{
    calibration_from_values, calibration_values, hostile, parse_calibration,
    CalibrationFileError, CALIBRATION_KEYS, CALIBRATION_VERSION, CALIBRATION_VERSION_1,
    CALIBRATION_VERSION_2, CALIBRATION_VERSION_3, CALIBRATION_VERSION_4, KEY_COUNT, V1_KEYS,
    V2_KEYS, V3_KEYS, V4_KEYS,
};
use moment_limiter::cycle::{DEFAULT_ANGLE_SENSOR_LAG_S, DEFAULT_SEAL_RELEASE_S};
use moment_limiter::load_estimate::Calibration;

/// A blob with any values and versions and a correct CRC: what a buggy or
/// hostile writer could store (the encoder itself refuses bad values).
fn raw_blob(values: &[f64], format: u16, schema: u16) -> Vec<u8> {
    let mut b = Vec::with_capacity(BLOB_LEN);
    b.extend_from_slice(&BLOB_MAGIC);
    b.extend_from_slice(&format.to_le_bytes());
    b.extend_from_slice(&schema.to_le_bytes());
    for v in values {
        b.extend_from_slice(&v.to_le_bytes());
    }
    let crc = crc32(&b);
    b.extend_from_slice(&crc.to_le_bytes());
    b
}

fn values(c: &Calibration<f64>) -> [f64; KEY_COUNT] {
    calibration_values(c)
}

fn good() -> Calibration<f64> {
    parse_calibration(hostile::GOOD.as_bytes()).unwrap()
}

#[test]
fn json_to_blob_to_the_same_calibration_in_f64_and_f32() {
    for text in [
        hostile::GOOD,
        include_str!("../../../examples/logs/cal.json"),
    ] {
        let cal = parse_calibration::<f64>(text.as_bytes()).unwrap();
        let blob = encode_calibration(&cal).unwrap();
        assert_eq!(blob.len(), BLOB_LEN);
        assert_eq!(BLOB_LEN, 108);
        // A file without a lag or a release time (the example is of schema
        // 1) is stored with the standard configuration's, what the limiter
        // used for them.
        let with_lag = |c: Calibration<f64>| Calibration {
            angle_sensor_lag_s: c.angle_sensor_lag_s.or(Some(DEFAULT_ANGLE_SENSOR_LAG_S)),
            seal_release_up_s: c.seal_release_up_s.or(Some(DEFAULT_SEAL_RELEASE_S)),
            ..c
        };
        assert_eq!(decode_calibration::<f64>(&blob).unwrap(), with_lag(cal));
        // The board's f32 calibration is the one the JSON reader gives in f32.
        let c32 = parse_calibration::<f32>(text.as_bytes()).unwrap();
        assert_eq!(
            decode_calibration::<f32>(&blob).unwrap(),
            Calibration {
                angle_sensor_lag_s: c32.angle_sensor_lag_s.or(Some(DEFAULT_ANGLE_SENSOR_LAG_S as f32)),
                seal_release_up_s: c32.seal_release_up_s.or(Some(DEFAULT_SEAL_RELEASE_S as f32)),
                ..c32
            }
        );
        // And the raw writer agrees with the encoder byte for byte.
        let raw = raw_blob(&values(&cal), BLOB_FORMAT, CALIBRATION_VERSION as u16);
        assert_eq!(raw, blob.to_vec());
    }
}

#[test]
fn a_format_4_blob_still_decodes_without_a_release_time() {
    // What a board calibrated before the seals' release was learned holds:
    // 100 bytes, schema 4.
    let v4 = parse_calibration::<f64>(hostile::GOOD_V4.as_bytes()).unwrap();
    assert_eq!(v4.seal_release_up_s, None);
    assert!(v4.friction_up_per_rate > 0.0);
    let blob = raw_blob(&values(&v4)[..V4_KEYS], BLOB_FORMAT_4, CALIBRATION_VERSION_4 as u16);
    assert_eq!((blob.len(), BLOB_LEN_4), (100, 100));
    assert_eq!(decode_calibration::<f64>(&blob).unwrap(), v4);
    assert_eq!(
        decode_calibration::<f32>(&blob).unwrap(),
        parse_calibration::<f32>(hostile::GOOD_V4.as_bytes()).unwrap()
    );
    // The length and the versions must agree.
    assert_eq!(
        decode_calibration::<f32>(&raw_blob(&values(&v4)[..V4_KEYS], BLOB_FORMAT, 4)),
        Err(CalibrationBlobError::Format(BLOB_FORMAT))
    );
    assert_eq!(
        decode_calibration::<f32>(&raw_blob(&values(&v4)[..V4_KEYS], BLOB_FORMAT_4, 5)),
        Err(CalibrationBlobError::SchemaVersion(5))
    );
    // Stored by the previous firmware under store version 4: the board loads it.
    let mut store = Store::new(CutFlash::<4>::new(), layout());
    store.write_blob(Key::Calibration, BLOB_FORMAT_4, &blob).unwrap();
    let (back, crc) = load_calibration::<f64, _>(&mut store).unwrap();
    assert_eq!(back, v4);
    assert_eq!(crc, crc32(&blob));
}

#[test]
fn a_format_3_blob_still_decodes_with_no_friction_per_rate() {
    // What a board calibrated before the friction per unit rate holds: 84 bytes, schema 3.
    let v3 = parse_calibration::<f64>(hostile::GOOD_V3.as_bytes()).unwrap();
    assert_eq!((v3.friction_up_per_rate, v3.friction_down_per_rate), (0.0, 0.0));
    assert!(v3.angle_sensor_lag_s.is_some());
    let blob = raw_blob(&values(&v3)[..V3_KEYS], BLOB_FORMAT_3, CALIBRATION_VERSION_3 as u16);
    assert_eq!((blob.len(), BLOB_LEN_3), (84, 84));
    assert_eq!(decode_calibration::<f64>(&blob).unwrap(), v3);
    assert_eq!(
        decode_calibration::<f32>(&blob).unwrap(),
        parse_calibration::<f32>(hostile::GOOD_V3.as_bytes()).unwrap()
    );
    // The length and the versions must agree.
    assert_eq!(
        decode_calibration::<f32>(&raw_blob(&values(&v3)[..V3_KEYS], BLOB_FORMAT, 3)),
        Err(CalibrationBlobError::Format(BLOB_FORMAT))
    );
    assert_eq!(
        decode_calibration::<f32>(&raw_blob(&values(&v3)[..V3_KEYS], BLOB_FORMAT_3, 4)),
        Err(CalibrationBlobError::SchemaVersion(4))
    );
    // Stored by the previous firmware under store version 3: the board loads it.
    let mut store = Store::new(CutFlash::<4>::new(), layout());
    store.write_blob(Key::Calibration, BLOB_FORMAT_3, &blob).unwrap();
    let (back, crc) = load_calibration::<f64, _>(&mut store).unwrap();
    assert_eq!(back, v3);
    assert_eq!(crc, crc32(&blob));
}

#[test]
fn a_format_2_blob_still_decodes_without_a_lag() {
    // What a board calibrated before the lag was learned holds: 76 bytes, schema 2.
    let v2 = parse_calibration::<f64>(hostile::GOOD_V2.as_bytes()).unwrap();
    assert_eq!(v2.angle_sensor_lag_s, None);
    assert!(v2.friction_up_per_force > 0.0);
    let blob = raw_blob(&values(&v2)[..V2_KEYS], BLOB_FORMAT_2, CALIBRATION_VERSION_2 as u16);
    assert_eq!((blob.len(), BLOB_LEN_2), (76, 76));
    assert_eq!(decode_calibration::<f64>(&blob).unwrap(), v2);
    assert_eq!(
        decode_calibration::<f32>(&blob).unwrap(),
        parse_calibration::<f32>(hostile::GOOD_V2.as_bytes()).unwrap()
    );
    // Its bounds are enforced as in format 4.
    let mut bad = values(&v2);
    bad[6] = 0.5;
    let e = decode_calibration::<f32>(&raw_blob(&bad[..V2_KEYS], BLOB_FORMAT_2, 2)).unwrap_err();
    assert_eq!((e.code(), e.detail()), (8, 6), "{e:?}");
    // The length and the versions must agree.
    assert_eq!(
        decode_calibration::<f32>(&raw_blob(&values(&v2)[..V2_KEYS], BLOB_FORMAT, 2)),
        Err(CalibrationBlobError::Format(BLOB_FORMAT))
    );
    assert_eq!(
        decode_calibration::<f32>(&raw_blob(&values(&v2)[..V2_KEYS], BLOB_FORMAT_2, 3)),
        Err(CalibrationBlobError::SchemaVersion(3))
    );
    assert_eq!(
        decode_calibration::<f32>(&raw_blob(&values(&v2), BLOB_FORMAT_2, 2)),
        Err(CalibrationBlobError::Format(BLOB_FORMAT_2))
    );
    // Stored by the previous firmware under store version 2: the board loads it.
    let mut store = Store::new(CutFlash::<4>::new(), layout());
    store.write_blob(Key::Calibration, BLOB_FORMAT_2, &blob).unwrap();
    let (back, crc) = load_calibration::<f64, _>(&mut store).unwrap();
    assert_eq!(back, v2);
    assert_eq!(crc, crc32(&blob));
}

#[test]
fn a_format_1_blob_still_decodes_as_constant_friction() {
    // What a board calibrated before the seal law holds: 60 bytes, schema 1.
    let v1 = parse_calibration::<f64>(hostile::GOOD_V1.as_bytes()).unwrap();
    assert_eq!(v1.friction_up_per_force, 0.0);
    let blob = raw_blob(
        &values(&v1)[..V1_KEYS],
        BLOB_FORMAT_1,
        CALIBRATION_VERSION_1 as u16,
    );
    assert_eq!(blob.len(), BLOB_LEN_1);
    assert_eq!(BLOB_LEN_1, 60);
    assert_eq!(decode_calibration::<f64>(&blob).unwrap(), v1);
    assert_eq!(
        decode_calibration::<f32>(&blob).unwrap(),
        parse_calibration::<f32>(hostile::GOOD_V1.as_bytes()).unwrap()
    );
    // Its bounds are enforced as in format 2.
    let mut bad = values(&v1);
    bad[3] = 50.0;
    let e = decode_calibration::<f32>(&raw_blob(
        &bad[..V1_KEYS],
        BLOB_FORMAT_1,
        CALIBRATION_VERSION_1 as u16,
    ))
    .unwrap_err();
    assert_eq!(e.code(), 8, "{e:?}");
    // Every bit flip refused.
    for byte in 0..BLOB_LEN_1 {
        for bit in 0..8 {
            let mut b = blob.clone();
            b[byte] ^= 1 << bit;
            assert!(decode_calibration::<f32>(&b).is_err(), "byte {byte} bit {bit}");
        }
    }
    // The length and the versions must agree: 60 bytes claiming format 2 or
    // schema 2, 76 bytes claiming format 1 or schema 1.
    assert_eq!(
        decode_calibration::<f32>(&raw_blob(&values(&v1)[..V1_KEYS], BLOB_FORMAT, 1)),
        Err(CalibrationBlobError::Format(BLOB_FORMAT))
    );
    assert_eq!(
        decode_calibration::<f32>(&raw_blob(
            &values(&v1)[..V1_KEYS],
            BLOB_FORMAT_1,
            CALIBRATION_VERSION as u16
        )),
        Err(CalibrationBlobError::SchemaVersion(CALIBRATION_VERSION as u16))
    );
    assert_eq!(
        decode_calibration::<f32>(&raw_blob(&values(&v1), BLOB_FORMAT_1, 2)),
        Err(CalibrationBlobError::Format(BLOB_FORMAT_1))
    );
    assert_eq!(
        decode_calibration::<f32>(&raw_blob(&values(&v1), BLOB_FORMAT, 1)),
        Err(CalibrationBlobError::SchemaVersion(1))
    );
    // Stored by an older firmware under store version 1: the board loads it.
    let mut store = Store::new(CutFlash::<4>::new(), layout());
    store
        .write_blob(Key::Calibration, BLOB_FORMAT_1, &blob)
        .unwrap();
    let (back, crc) = load_calibration::<f64, _>(&mut store).unwrap();
    assert_eq!(back, v1);
    assert_eq!(crc, crc32(&blob));
}

#[test]
fn every_bound_of_the_schema_is_enforced_by_the_blob_decoder_as_by_the_json_reader() {
    let base = values(&good());
    let mut checked = 0;
    for (k, spec) in CALIBRATION_KEYS.iter().enumerate() {
        let candidates = [
            (spec.min, true),
            (spec.max, true),
            ((spec.min + spec.max) / 2.0, true),
            (spec.max.next_up(), false),
            (spec.min.next_down(), false),
            (spec.max + 1.0, false),
            (spec.min - 1.0, false),
            (f64::NAN, false),
            (f64::INFINITY, false),
            (f64::NEG_INFINITY, false),
        ];
        for (v, ok) in candidates {
            let mut vals = base;
            vals[k] = v;
            let blob = raw_blob(&vals, BLOB_FORMAT, CALIBRATION_VERSION as u16);
            let got = decode_calibration::<f32>(&blob);
            assert_eq!(got.is_ok(), ok, "{} = {v}: {got:?}", spec.key);
            if let Err(e) = &got {
                match e {
                    CalibrationBlobError::OutOfBounds(CalibrationFileError::OutOfBounds {
                        spec: s,
                        ..
                    }) => assert_eq!(s.key, spec.key),
                    other => panic!(
                        "{} = {v}: refused for the wrong reason: {other:?}",
                        spec.key
                    ),
                }
                assert_eq!(e.code(), 8);
                assert_eq!(e.detail(), k as u32, "the event names the key's index");
                assert!(e.to_string().contains(&format!("`{}`", spec.key)), "{e}");
                // The encoder refuses to write it in the first place.
                let mut cv = values(&good());
                cv[k] = v;
                let cal: Calibration<f64> = calibration_from_values(&cv, KEY_COUNT);
                assert!(
                    encode_calibration(&cal).is_err(),
                    "{} = {v} encoded",
                    spec.key
                );
            }
            // The same verdict as the JSON reader, where JSON can spell the value.
            if v.is_finite() {
                let text = hostile::with(spec.key, Some(&format!("{v:?}")));
                assert_eq!(
                    parse_calibration::<f32>(text.as_bytes()).is_ok(),
                    ok,
                    "JSON and blob disagree on {} = {v}",
                    spec.key
                );
            }
            checked += 1;
        }
    }
    assert_eq!(checked, 10 * CALIBRATION_KEYS.len());
}

#[test]
fn corrupt_truncated_and_foreign_blobs_are_refused() {
    let blob = encode_calibration(&good()).unwrap();
    // Every single bit flip anywhere.
    for byte in 0..BLOB_LEN {
        for bit in 0..8 {
            let mut bad = blob;
            bad[byte] ^= 1 << bit;
            let e = decode_calibration::<f32>(&bad).expect_err("a flipped bit decoded");
            assert!(
                matches!(e, CalibrationBlobError::Crc | CalibrationBlobError::Magic),
                "byte {byte} bit {bit}: {e:?}"
            );
        }
    }
    // Wrong lengths.
    for n in [0, 4, BLOB_LEN_1 - 1, BLOB_LEN_1 + 1, BLOB_LEN_2 - 1, BLOB_LEN_2 + 1, BLOB_LEN_3 - 1, BLOB_LEN_3 + 1, BLOB_LEN_4 - 1, BLOB_LEN_4 + 1, BLOB_LEN - 1] {
        assert_eq!(
            decode_calibration::<f32>(&blob[..n]),
            Err(CalibrationBlobError::Length(n))
        );
    }
    let mut long = blob.to_vec();
    long.push(0);
    assert_eq!(
        decode_calibration::<f32>(&long),
        Err(CalibrationBlobError::Length(BLOB_LEN + 1))
    );
    // Erased flash, and a blob of something else.
    assert_eq!(
        decode_calibration::<f32>(&[0xFF; BLOB_LEN]),
        Err(CalibrationBlobError::Magic)
    );
    // Versions this firmware does not know, with a correct CRC.
    let v = values(&good());
    assert_eq!(
        decode_calibration::<f32>(&raw_blob(&v, BLOB_FORMAT + 1, CALIBRATION_VERSION as u16)),
        Err(CalibrationBlobError::Format(BLOB_FORMAT + 1))
    );
    for schema in [0, CALIBRATION_VERSION as u16 + 1] {
        let e = decode_calibration::<f32>(&raw_blob(&v, BLOB_FORMAT, schema)).unwrap_err();
        assert_eq!(e, CalibrationBlobError::SchemaVersion(schema));
        assert_eq!((e.code(), e.detail()), (7, u32::from(schema)));
    }
}

#[test]
fn the_board_loads_only_a_good_stored_blob() {
    let cal = good();
    // Nothing stored.
    let mut store = Store::new(CutFlash::<4>::new(), layout());
    assert_eq!(
        load_calibration::<f32, _>(&mut store),
        Err(CalibrationBlobError::Missing)
    );
    // Stored by the host tool's path.
    limiter_storage::calibration_blob::store_calibration(&mut store, &cal).unwrap();
    let (back, crc) = load_calibration::<f64, _>(&mut store).unwrap();
    assert_eq!(back, cal, "read back through the store");
    // The CRC the board logs with `CalibrationApplied` identifies the blob.
    assert_eq!(crc, crc32(&encode_calibration(&cal).unwrap()));
    // A blob under another store version, a foreign blob, one out of bounds.
    let blob = encode_calibration(&cal).unwrap();
    store.write_blob(Key::Calibration, 7, &blob).unwrap();
    assert_eq!(
        load_calibration::<f32, _>(&mut store),
        Err(CalibrationBlobError::Format(7))
    );
    store
        .write_blob(Key::Calibration, BLOB_FORMAT, b"{\"version\": 1}")
        .unwrap();
    assert_eq!(
        load_calibration::<f32, _>(&mut store),
        Err(CalibrationBlobError::Length(14))
    );
    let mut v = values(&cal);
    v[3] = 50.0; // p1_offset_bar = 50 bar: the case
    store
        .write_blob(
            Key::Calibration,
            BLOB_FORMAT,
            &raw_blob(&v, BLOB_FORMAT, CALIBRATION_VERSION as u16),
        )
        .unwrap();
    let e = load_calibration::<f32, _>(&mut store).unwrap_err();
    assert!(
        e.to_string().contains("`p1_offset_bar` = 50 is outside"),
        "{e}"
    );
    // Bit rot in the stored record: the store's CRC refuses it, the previous
    // record of the key is not resurrected as a calibration either.
    let mut flash = store.into_flash();
    let at = flash
        .mem
        .windows(4)
        .rposition(|w| w == BLOB_MAGIC)
        .expect("blob in flash");
    flash.mem[at + 20] ^= 0x10;
    let mut store = Store::new(flash.reboot(None), layout());
    let got = load_calibration::<f32, _>(&mut store);
    assert!(got.is_err(), "a rotten blob was applied: {got:?}");
}

/// A refusal names every length, format and schema version the decoder
/// reads (the ones before format 5 left out format 4, which it reads).
#[test]
fn refusals_name_every_format_the_decoder_reads() {
    let format = CalibrationBlobError::Format(9).to_string();
    assert!(format.ends_with(" 9 (this firmware reads 1, 2, 3, 4 and 5)"), "{format}");
    let schema = CalibrationBlobError::SchemaVersion(9).to_string();
    assert!(schema.ends_with(" 9 (this firmware reads 1, 2, 3, 4 and 5)"), "{schema}");
    let length = CalibrationBlobError::Length(7).to_string();
    assert!(length.ends_with("(7 bytes, not 108, 100, 84, 76 nor 60)"), "{length}");
}
