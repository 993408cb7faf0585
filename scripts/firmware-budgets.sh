#!/usr/bin/env bash
# Prints the firmware's resource budgets, measured (not estimated):
#   flash and static RAM   arm-none-eabi-size of the release images (board build:
#                          the one that ships; QEMU build: adds the semihosting
#                          replay, log parser and float formatting)
#   peak stack (QEMU)      cortex-m-rt `paint-stack`, scanned by the firmware
#                          after replaying the log under QEMU, text and --json
#   peak stack (board)     the board image cannot run in QEMU (no RCC/PLL model):
#                          static bound from its machine code, the deepest chain
#                          of prologue frames from `main` and from the cycle
#                          (scripts/check-cycle-image.py --stack-only); the same
#                          bound on the QEMU image is printed next to its
#                          measured peak as a check of the method
#   self-test duration     the power-up self-test (RAM March C-, image CRC-32 of a
#                          stamped copy, model reference), SysTick under -icount,
#                          converted to instructions the same way
#   instructions / cycle   SysTick under `qemu-system-arm -icount shift=0`
#                          (1 instruction = 1 ns of virtual time), converted to
#                          instructions with an in-firmware calibration loop of
#                          known length; max and mean over every sample of the log
# Usage: scripts/firmware-budgets.sh [LOG.csv]
#   default: a 100 Hz log synthesized like examples/logs/overload_lowering.csv
#   (8000 kg lowered 75° -> 40°, through WARNING into OVERLOAD), written to
#   target/budgets/ (crane-sim synth --rate-hz 100).
# Exit status 0 even when a target is exceeded: these are reported, not gated.
set -euo pipefail
cd "$(dirname "$0")/.."

TARGET=thumbv7em-none-eabihf
ELF=target/$TARGET/release/firmware
BOARD_ELF=target/$TARGET/release/firmware-board

"$(dirname "$0")/install-test-deps.sh" >/dev/null

log=${1:-}
if [ -z "$log" ]; then
    mkdir -p target/budgets
    log=target/budgets/overload_lowering_100hz.csv
    if [ ! -s "$log" ]; then
        cargo build -q --release -p host-sim
        target/release/crane-sim synth --duration 10 --profile cycloidal --rate-hz 100 --hold-s 1 \
            --load-kg 8000 --direction down --high-deg 75 --seed 2 --out "$log" >/dev/null
    fi
fi
log=$(realpath "$log")

# The board binary (src/bin/board.rs) is `firmware-board`, the QEMU one `firmware`.
cargo build -q --release --target $TARGET -p firmware --no-default-features --features board 2>/dev/null \
    || rm -f "$BOARD_ELF"
cargo build -q --release --target $TARGET -p firmware

size_of() { # ELF -> "flash ram"
    arm-none-eabi-size -B "$1" | awk 'NR==2 { print $1 + $2, $2 + $3 }'
}
read -r flash ram < <(size_of "$ELF")

budgets_line() { # extra firmware args -> the budgets line
    local out
    out=$(QEMU_EXTRA="-icount shift=0" scripts/qemu-runner.sh "$ELF" "$log" --budgets "$@" 2>&1 >/dev/null || true)
    if ! grep '^budgets:' <<<"$out"; then
        echo "firmware-budgets: no budgets line from QEMU; its stderr was:" >&2
        echo "$out" >&2
        exit 1
    fi
}
line=$(budgets_line)
json_line=$(budgets_line --json)
field() { sed -n "s/.* $1=\([0-9]*\).*/\1/p" <<<"${2:-$line}"; }
stack=$(field stack_peak_bytes)
json_stack=$(field stack_peak_bytes "$json_line")
cycles=$(field cycles)
tmax=$(field ticks_per_cycle_max)
tmean=$(field ticks_per_cycle_mean)
ci=$(field calibration_instructions)
ct=$(field calibration_ticks)
imax=$(( tmax * ci / ct ))
imean=$(( tmean * ci / ct ))
res=$(( (ci + ct - 1) / ct ))
static_bound() { # ELF ROOT -> bytes
    python3 scripts/check-cycle-image.py --stack-only "$1" "$2" | sed -n 's/.*: \([0-9]*\) bytes.*/\1/p'
}
qemu_static=$(static_bound "$ELF" main)
cycle_static=$(static_bound "$ELF" 10step_frame)

verdict() { if [ "$1" -le "$2" ]; then echo "ok"; else echo "OVER"; fi; }
row() { printf '%-40s %10s %10s  %s\n' "$@"; }
row "budget" "measured" "target" ""
if [ -f "$BOARD_ELF" ]; then
    read -r bflash bram < <(size_of "$BOARD_ELF")
    bstatic=$(static_bound "$BOARD_ELF" main)
    bcycle=$(static_bound "$BOARD_ELF" 5cycle)
    row "board flash (bytes)" "$bflash" $((64 * 1024)) "$(verdict "$bflash" $((64 * 1024)))"
    row "board static RAM (bytes)" "$bram" $((16 * 1024)) "$(verdict "$bram" $((16 * 1024)))"
    row "board peak stack, static bound (bytes)" "$bstatic" $((32 * 1024)) "$(verdict "$bstatic" $((32 * 1024)))"
    row "  of which the cycle (static bound)" "$bcycle" "-" ""
else
    echo "board build: does not build (see firmware/README.md)"
fi
row "instructions/cycle (max)" "$imax" 20000 "$(verdict "$imax" 20000) (stretch 5000: $(verdict "$imax" 5000))"
row "instructions/cycle (mean)" "$imean" "-" ""
row "QEMU image flash (bytes)" "$flash" "-" ""
row "QEMU image static RAM (bytes)" "$ram" "-" ""
row "QEMU replay peak stack (bytes)" "$stack" $((32 * 1024)) "$(verdict "$stack" $((32 * 1024)))"
row "QEMU replay --json peak stack (bytes)" "$json_stack" $((32 * 1024)) "$(verdict "$json_stack" $((32 * 1024)))"
row "QEMU image stack, static bound (bytes)" "$qemu_static" "-" "(panic path included; cycle: $cycle_static)"
# The self-test on a stamped copy of the image (the CRC then covers it all).
STAMPED_ELF=target/$TARGET/release/firmware-stamped
cp "$ELF" "$STAMPED_ELF"
cargo build -q --release -p limiter-storage --bin stamp-image
target/release/stamp-image "$STAMPED_ELF" >/dev/null
st=$(QEMU_EXTRA="-icount shift=0" scripts/qemu-runner.sh "$STAMPED_ELF" "$log" --self-test 2>&1 >/dev/null | grep '^self-test: passed' || true)
if [ -n "$st" ]; then
    sfield() { sed -n "s/.* $1=\([0-9]*\).*/\1/p" <<<"$st"; }
    sinstr=$(( $(sfield ticks) * $(sfield calibration_instructions) / $(sfield calibration_ticks) ))
    row "self-test (instructions)" "$sinstr" "-" "$(sed 's/^self-test: passed //; s/ ticks=.*//' <<<"$st")"
    # Of which the image CRC; the board's image is smaller: scale that part.
    crc_instr=$(( $(sfield image_ticks) * $(sfield calibration_instructions) / $(sfield calibration_ticks) ))
    img_bytes=$(sed -n 's/.*image=crc32:[0-9a-f]*\/\([0-9]*\)B.*/\1/p' <<<"$st")
    row "  of which image CRC-32" "$crc_instr" "-" "$img_bytes bytes of image"
    if [ -f "$BOARD_ELF" ] && [ -n "$img_bytes" ]; then
        read -r bflash _ < <(size_of "$BOARD_ELF")
        board_instr=$(( sinstr - crc_instr + crc_instr * bflash / img_bytes ))
        row "board self-test (est. instr)" "$board_instr" "-" "~$(( board_instr / 168 )) us at 168 MHz, 1 instr/cycle; output readback and 3 ADC reads not included"
    fi
else
    echo "self-test: no report line from QEMU"
fi
echo "log: $log ($cycles lines measured; one SysTick tick = $res instructions, resolution)"
echo "board image sections:"
[ -f "$BOARD_ELF" ] && arm-none-eabi-size -A "$BOARD_ELF" | awk '$2 > 0 && $1 ~ /^\./ { printf "  %-16s %8d\n", $1, $2 }'
echo "qemu image sections:"
arm-none-eabi-size -A "$ELF" | awk '$2 > 0 && $1 ~ /^\./ { printf "  %-16s %8d\n", $1, $2 }'
