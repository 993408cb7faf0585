#!/usr/bin/env bash
# Proves from the release images' machine code that the control cycle reaches
# no soft float (no f64 either: the M4F's FPU is single precision, so every f64
# operation is a __aeabi_d*/__*df3 call) and no panic: builds the QEMU image and
# the board image, and walks the call graph from the limiter's cycle entries
# (`Limiter::step_frame` in the QEMU replay, `Limiter::cycle` on the board; both
# #[inline(never)]) with scripts/check-cycle-image.py. Exit 0 when both are clean.
set -euo pipefail
cd "$(dirname "$0")/.."

TARGET=thumbv7em-none-eabihf
ELF=target/$TARGET/release/firmware        # QEMU build (src/bin/qemu.rs)
"$(dirname "$0")/install-test-deps.sh" >/dev/null

cargo build -q --release --target $TARGET -p firmware --no-default-features --features board
python3 scripts/check-cycle-image.py "$ELF-board" 5cycle | sed -n '1p;$p'
cargo build -q --release --target $TARGET -p firmware
python3 scripts/check-cycle-image.py "$ELF" 10step_frame | sed -n '1p;$p'
# Negative control: the log parser parses f64 (soft float on the M4F) and can
# panic; if the walk from it came out clean, the checker would be blind.
if python3 scripts/check-cycle-image.py "$ELF" 9feed_line >/dev/null 2>&1; then
    echo "check-cycle-image: negative control failed: LogParser::feed_line passed the check" >&2
    exit 1
fi
echo "negative control ok: LogParser::feed_line (f64 parsing) is rejected"
