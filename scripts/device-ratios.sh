#!/usr/bin/env bash
# Issue 14's thread ratios on a many-core machine, robust to a machine whose single-core
# speed drifts (device run 2 of session 11 ran one thread 1.5x slower than run 1 had, on the
# same code): one and sixteen threads alternate on the same points, and glibc's per-thread
# arenas are measured by one run with MALLOC_ARENA_MAX=2. About 2.5 minutes.
#
# Build and carry as for scripts/device-scaling.sh:
#   cargo build --release --example stress
#   mkdir -p .device-bin && cp target/release/examples/stress .device-bin/
#   device run: command "bash scripts/device-ratios.sh", carry [".device-bin"], timeout_s 300
set -u
log_name=ratios.txt
source "$(dirname "$0")/device-common.sh"

for round in 1 2; do
    run 40 1 curve 10000000 points,triangulate
    run 20 16 curve 10000000 points,triangulate
done
run 30 1 uniform 10000000 points,triangulate
run 20 16 uniform 10000000 points,triangulate
run 60 1 even-curve 10000000 reconstruct
run 30 16 even-curve 10000000 reconstruct
echo "## MALLOC_ARENA_MAX=2" | tee -a "$log"
MALLOC_ARENA_MAX=2 run 30 16 even-curve 10000000 reconstruct
run 60 1 curve 10000000 reconstruct
run 30 16 curve 10000000 reconstruct
echo "done" | tee -a "$log"
