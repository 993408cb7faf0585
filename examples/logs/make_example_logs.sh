#!/usr/bin/env bash
# Regenerates the example logs with `crane-sim synth` (the flexible model).
# Run from the repository root: bash examples/logs/make_example_logs.sh
set -euo pipefail
cd "$(dirname "$0")/../.."
cargo build --release -q -p host-sim
sim=target/release/crane-sim
dir=examples/logs
common=(--duration 10 --profile cycloidal --rate-hz 50 --hold-s 1)
$sim synth "${common[@]}" --load-kg 3000 --direction up --seed 1 --out $dir/safe_lift.csv
$sim synth "${common[@]}" --load-kg 8000 --direction down --high-deg 75 --seed 2 --out $dir/overload_lowering.csv
$sim synth "${common[@]}" --load-kg 3000 --direction up --seed 1 --open-p1-at-s 6.0 --out $dir/wire_break.csv
$sim synth "${common[@]}" --load-kg 0 --direction up --seed 11 --out $dir/unloaded_up.csv
$sim synth "${common[@]}" --load-kg 0 --direction down --seed 12 --out $dir/unloaded_down.csv
# A logger's dropout: the overload lowering with its samples from 5.00 s to 5.48 s missing
# (the time stamps jump 0.52 s in the move).
awk -F, '/^#/ || /^t_s/ { print; next } $1 < 5.0 || $1 >= 5.5 { print }' $dir/overload_lowering.csv > $dir/logger_dropout.csv
# Line 104 (2 comment lines + header + 100 samples before it) gets a non-numeric p1.
awk -F, -v OFS=, 'NR == 104 { $2 = "12.5x" } { print }' $dir/safe_lift.csv > $dir/malformed.csv
$sim calibrate $dir/unloaded_up.csv $dir/unloaded_down.csv --out $dir/cal.json
