#!/usr/bin/env bash
# Prints the firmware's resource budgets, measured (not estimated):
#   flash and static RAM   arm-none-eabi-size of the release image (qemu build,
#                          and the board build when it builds)
#   peak stack             cortex-m-rt `paint-stack`, scanned by the firmware
#                          after replaying a log under QEMU
#   self-test duration     the power-up self-test (RAM March C-, image CRC-32 of a
#                          stamped copy, model reference), SysTick under -icount,
#                          converted to instructions the same way
#   instructions / cycle   SysTick under `qemu-system-arm -icount shift=0`
#                          (1 instruction = 1 ns of virtual time), converted to
#                          instructions with an in-firmware calibration loop of
#                          known length; max and mean over every sample of the log
# Usage: scripts/firmware-budgets.sh [LOG.csv]   (default: the largest example log)
# Exit status 0 even when a target is exceeded: these are reported, not gated.
set -euo pipefail
cd "$(dirname "$0")/.."

TARGET=thumbv7em-none-eabihf
ELF=target/$TARGET/release/firmware
BOARD_ELF=target/$TARGET/release/firmware-board

"$(dirname "$0")/install-test-deps.sh" >/dev/null

log=${1:-}
if [ -z "$log" ]; then
    log=$(ls -S examples/logs/*.csv 2>/dev/null | head -n1 || true)
    [ -n "$log" ] || log=$(ls -S tests/data/*.csv | head -n1)
fi
log=$(realpath "$log")

cargo build -q --release --target $TARGET -p firmware --no-default-features --features board 2>/dev/null \
    && cp "$ELF" "$BOARD_ELF" || rm -f "$BOARD_ELF"
cargo build -q --release --target $TARGET -p firmware

size_of() { # ELF -> "flash ram"
    arm-none-eabi-size -B "$1" | awk 'NR==2 { print $1 + $2, $2 + $3 }'
}
read -r flash ram < <(size_of "$ELF")

out=$(QEMU_EXTRA="-icount shift=0" scripts/qemu-runner.sh "$ELF" "$log" --budgets 2>&1 >/dev/null || true)
line=$(grep '^budgets:' <<<"$out" || true)
if [ -z "$line" ]; then
    echo "firmware-budgets: no budgets line from QEMU; its stderr was:" >&2
    echo "$out" >&2
    exit 1
fi
field() { sed -n "s/.* $1=\([0-9]*\).*/\1/p" <<<"$line"; }
stack=$(field stack_peak_bytes)
cycles=$(field cycles)
tmax=$(field ticks_per_cycle_max)
tmean=$(field ticks_per_cycle_mean)
ci=$(field calibration_instructions)
ct=$(field calibration_ticks)
imax=$(( tmax * ci / ct ))
imean=$(( tmean * ci / ct ))
res=$(( (ci + ct - 1) / ct ))

verdict() { if [ "$1" -le "$2" ]; then echo "ok"; else echo "OVER"; fi; }
printf '%-28s %10s %10s  %s\n' "budget" "measured" "target" ""
printf '%-28s %10d %10d  %s\n' "flash (bytes)" "$flash" $((64 * 1024)) "$(verdict "$flash" $((64 * 1024)))"
printf '%-28s %10d %10d  %s\n' "static RAM (bytes)" "$ram" $((16 * 1024)) "$(verdict "$ram" $((16 * 1024)))"
printf '%-28s %10d %10d  %s\n' "peak stack (bytes)" "$stack" $((32 * 1024)) "$(verdict "$stack" $((32 * 1024)))"
printf '%-28s %10d %10d  %s\n' "instructions/cycle (max)" "$imax" 100000 "$(verdict "$imax" 100000)"
printf '%-28s %10d %10s\n' "instructions/cycle (mean)" "$imean" "-"
# The self-test on a stamped copy of the image (the CRC then covers it all).
STAMPED_ELF=target/$TARGET/release/firmware-stamped
cp "$ELF" "$STAMPED_ELF"
cargo build -q --release -p limiter-storage --bin stamp-image
target/release/stamp-image "$STAMPED_ELF" >/dev/null
st=$(QEMU_EXTRA="-icount shift=0" scripts/qemu-runner.sh "$STAMPED_ELF" "$log" --self-test 2>&1 >/dev/null | grep '^self-test: passed' || true)
if [ -n "$st" ]; then
    sfield() { sed -n "s/.* $1=\([0-9]*\).*/\1/p" <<<"$st"; }
    sinstr=$(( $(sfield ticks) * $(sfield calibration_instructions) / $(sfield calibration_ticks) ))
    printf '%-28s %10d %10s  %s\n' "self-test (instructions)" "$sinstr" "-" "$(sed 's/^self-test: passed //; s/ ticks=.*//' <<<"$st")"
    # Of which the image CRC; the board's image is smaller: scale that part.
    crc_instr=$(( $(sfield image_ticks) * $(sfield calibration_instructions) / $(sfield calibration_ticks) ))
    img_bytes=$(sed -n 's/.*image=crc32:[0-9a-f]*\/\([0-9]*\)B.*/\1/p' <<<"$st")
    printf '%-28s %10d %10s  %s\n' "  of which image CRC-32" "$crc_instr" "-" "$img_bytes bytes of image"
    if [ -f "$BOARD_ELF" ] && [ -n "$img_bytes" ]; then
        read -r bflash _ < <(size_of "$BOARD_ELF")
        board_instr=$(( sinstr - crc_instr + crc_instr * bflash / img_bytes ))
        printf '%-28s %10d %10s  %s\n' "board self-test (est. instr)" "$board_instr" "-" "~$(( board_instr / 168 )) us at 168 MHz, 1 instr/cycle; output readback and 3 ADC reads not included"
    fi
else
    echo "self-test: no report line from QEMU"
fi
if [ -f "$BOARD_ELF" ]; then
    read -r bflash bram < <(size_of "$BOARD_ELF")
    printf '%-28s %10d %10d  %s\n' "board build flash (bytes)" "$bflash" $((64 * 1024)) "$(verdict "$bflash" $((64 * 1024)))"
    printf '%-28s %10d %10d  %s\n' "board build static RAM" "$bram" $((16 * 1024)) "$(verdict "$bram" $((16 * 1024)))"
else
    echo "board build: does not build yet (see firmware/README.md)"
fi
echo "log: $log ($cycles lines measured; one SysTick tick = $res instructions, resolution)"
echo "qemu build sections:"
arm-none-eabi-size -A "$ELF" | awk '$2 > 0 && $1 ~ /^\./ { printf "  %-16s %8d\n", $1, $2 }'
