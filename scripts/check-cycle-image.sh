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
ELF=target/$TARGET/release/firmware
"$(dirname "$0")/install-test-deps.sh" >/dev/null

cargo build -q --release --target $TARGET -p firmware --no-default-features --features board
cp "$ELF" "$ELF-board-check"
python3 scripts/check-cycle-image.py "$ELF-board-check" 5cycle | sed -n '1p;$p'
cargo build -q --release --target $TARGET -p firmware
python3 scripts/check-cycle-image.py "$ELF" 10step_frame | sed -n '1p;$p'
