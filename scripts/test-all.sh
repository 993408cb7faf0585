#!/usr/bin/env bash
# Every test of the project, from a fresh machine: installs what the tests need
# (the thumbv7em-none-eabihf target, QEMU, ARM binutils), then runs the host
# tests (model physics, limiter, drivers, CLI), clippy with warnings denied, the
# API docs with broken links denied, the board build of the firmware, and the
# QEMU-vs-host replay of every example log.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install-test-deps.sh

echo "== clippy (warnings denied)"
cargo clippy --workspace --exclude firmware --all-targets -- -D warnings
cargo clippy -p firmware --release --target thumbv7em-none-eabihf -- -D warnings
cargo clippy -p firmware --release --target thumbv7em-none-eabihf --no-default-features --features board -- -D warnings

echo "== API docs (broken or private links denied)"
RUSTDOCFLAGS="-D warnings" cargo doc --workspace --exclude firmware --no-deps

echo "== firmware images (QEMU and board)"
cargo build --release --target thumbv7em-none-eabihf -p firmware
cargo build --release --target thumbv7em-none-eabihf -p firmware --no-default-features --features board

echo "== the control cycle's machine code: no soft float, no f64, no panic"
bash scripts/check-cycle-image.sh

echo "== tests (host, release: the model runs optimised; includes QEMU vs host replay)"
cargo test --release --workspace --exclude firmware
