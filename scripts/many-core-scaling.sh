#!/usr/bin/env bash
# Thread scaling on a machine with 16 or more cores: the triangulation and the whole
# reconstruction at 10^7 points on 1 and 16 threads, the noisy curve on 1, 2, 4, 8 and 16
# threads, and 10^8 points reconstructed on 16 threads; about 5 minutes. Results:
# benches/README.md, "examples/stress.rs".
#
#   cargo build --release --example stress
#   bash scripts/many-core-scaling.sh          # or STRESS_BIN=path/to/stress OUT=dir bash …
#
# The binary can be built elsewhere and copied (set STRESS_BIN). Everything goes to standard
# output and to $OUT/scaling.txt (see many-core-common.sh). Compare thread counts within one
# run only: on a shared machine absolute times drift.
set -u
log_name=scaling.txt
source "$(dirname "$0")/many-core-common.sh"

# The triangulation on 1 and 16 threads, the same points each time.
for set in curve uniform; do
    run 60 1 "$set" 10000000 points,triangulate
    run 60 16 "$set" 10000000 points,triangulate
done

# The whole reconstruction, both curve sets; the noisy curve on every thread count, for the
# shape of the scaling curve.
run 90 1 curve 10000000 reconstruct
run 60 16 curve 10000000 reconstruct
for threads in 1 2 4 8 16; do
    run 90 "$threads" even-curve 10000000 reconstruct
done

# 10^8 points reconstructed with the default pruned axis on all cores (time, peak memory per
# point). (The one-thread triangulation of 10^8 points, for the n log n flatness, takes
# another 100 s: `run 150 1 curve 100000000 points,triangulate`.)
run 170 16 curve 100000000 reconstruct
echo "done" | tee -a "$log"
