#!/usr/bin/env bash
# Installs what the firmware tests need, only when it is missing (idempotent):
#   - the Rust target thumbv7em-none-eabihf (Cortex-M4F, hard float);
#   - qemu-system-arm (runs the firmware's QEMU build, machine netduinoplus2);
#   - binutils-arm-none-eabi (arm-none-eabi-size/nm/objdump for the budgets);
#   - python3 (scripts/check-cycle-image.py walks the image's call graph);
#   - flip-link (cargo install; the firmware's linker, stack-overflow guard).
# Safe to run on every CI run and on a developer machine: each step is skipped
# when its tool is already there. apt-get runs non-interactively and only when a
# package is missing (with `apt-get update` first); it needs root or sudo.
set -euo pipefail

TARGET=thumbv7em-none-eabihf

if command -v rustup >/dev/null 2>&1; then
    if ! rustup target list --installed | grep -qx "$TARGET"; then
        echo "install-test-deps: rustup target add $TARGET"
        rustup target add "$TARGET"
    fi
else
    echo "install-test-deps: rustup not found; make sure the $TARGET target is installed" >&2
fi

# flip-link: the firmware's linker wrapper (stack-overflow guard, see
# .cargo/config.toml); a cargo binary, about 30 s to build.
if ! command -v flip-link >/dev/null 2>&1; then
    echo "install-test-deps: cargo install flip-link"
    cargo install --locked flip-link
fi

missing=()
command -v qemu-system-arm >/dev/null 2>&1 || missing+=(qemu-system-arm)
command -v arm-none-eabi-size >/dev/null 2>&1 || missing+=(binutils-arm-none-eabi)
command -v python3 >/dev/null 2>&1 || missing+=(python3)

if ((${#missing[@]})); then
    SUDO=""
    if [ "$(id -u)" -ne 0 ]; then
        if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
            echo "install-test-deps: need root to install ${missing[*]}" >&2
            exit 1
        fi
    fi
    echo "install-test-deps: apt-get install ${missing[*]}"
    export DEBIAN_FRONTEND=noninteractive
    $SUDO apt-get update -q
    $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

echo "install-test-deps: $TARGET, qemu-system-arm ($(command -v qemu-system-arm)), arm-none-eabi-size ($(command -v arm-none-eabi-size)) ready"
