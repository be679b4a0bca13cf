#!/usr/bin/env bash
# One- and sixteen-thread ratios on a machine with 16 or more cores, robust to a machine
# whose single-core speed drifts between runs: one and sixteen threads alternate on the same
# points, and one run with MALLOC_ARENA_MAX=2 measures glibc's per-thread arenas. About 2.5
# minutes. Build and run as for scripts/many-core-scaling.sh:
#
#   cargo build --release --example stress
#   bash scripts/many-core-ratios.sh
set -u
log_name=ratios.txt
source "$(dirname "$0")/many-core-common.sh"

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
