#!/usr/bin/env bash
# Cargo runner for thumbv7em-none-eabihf (see .cargo/config.toml):
#   qemu-runner.sh FIRMWARE.elf [ARGS...]
# Boots the image on QEMU's netduinoplus2 (STM32F405, Cortex-M4F) and hands ARGS
# to the firmware as its semihosting command line. Arguments that name existing
# files are made absolute (semihosting opens paths relative to QEMU's working
# directory). The firmware's exit code (semihosting SYS_EXIT_EXTENDED) is QEMU's.
#
# Environment:
#   QEMU_TIMEOUT  seconds before QEMU is killed (default 300; exit code 124)
#   QEMU_EXTRA    extra QEMU options, e.g. "-icount shift=0" (instruction counting)
set -euo pipefail

if [ $# -lt 1 ]; then
    echo "usage: $0 FIRMWARE.elf [ARGS...]" >&2
    exit 1
fi
elf=$1
shift

if ! command -v qemu-system-arm >/dev/null 2>&1; then
    echo "qemu-runner: qemu-system-arm not found (run scripts/install-test-deps.sh)" >&2
    exit 127
fi

semi="enable=on,target=native,arg=firmware"
for a in "$@"; do
    if [ -e "$a" ]; then
        a=$(realpath -- "$a")
    elif [[ "$a" == --*=* && -e "${a#*=}" ]]; then
        a="${a%%=*}=$(realpath -- "${a#*=}")"
    fi
    case "$a" in
        *[[:space:],]*)
            # Semihosting joins the args with spaces, and QEMU splits options on commas.
            echo "qemu-runner: arguments cannot contain spaces or commas: '$a'" >&2
            exit 1
            ;;
    esac
    semi="$semi,arg=$a"
done

# shellcheck disable=SC2086  # QEMU_EXTRA is a list of options
exec timeout --kill-after=5 "${QEMU_TIMEOUT:-300}" \
    qemu-system-arm -machine netduinoplus2 -cpu cortex-m4 \
    -nographic -monitor none -serial null \
    ${QEMU_EXTRA:-} \
    -semihosting-config "$semi" \
    -kernel "$elf"
