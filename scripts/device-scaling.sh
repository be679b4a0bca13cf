#!/usr/bin/env bash
# Issue 14's checks for a many-core machine (the `device` tool's 16-core machine; see
# ../.library/device/README.md): parallel scaling of the triangulation and the whole
# reconstruction at 10^7, and 10^8 points, in one run of about 5 minutes.
#
# The machine has no network and no Rust toolchain is assumed there: build here, carry the
# binary in an ignored folder, then run this script there.
#
#   cargo build --release --example stress
#   mkdir -p .device-bin && cp target/release/examples/stress .device-bin/
#   grep -qx '/.device-bin/' .git/info/exclude || echo /.device-bin/ >> .git/info/exclude
#   device run: command "bash scripts/device-scaling.sh", carry [".device-bin"], timeout_s 600
#
# Everything goes to standard output and to $OUT/scaling.txt (see device-common.sh).
# Compare thread counts within this one run: the machine is shared.
set -u
log_name=scaling.txt
source "$(dirname "$0")/device-common.sh"

# Item 2: the triangulation on 1 and 16 threads (target >= 6x at 16), same points each time.
for set in curve uniform; do
    run 60 1 "$set" 10000000 points,triangulate
    run 60 16 "$set" 10000000 points,triangulate
done

# Item 2: the whole reconstruction (target >= 4x at 16), both curve sets; the even curve on
# every thread count, for the shape of the scaling curve.
run 90 1 curve 10000000 reconstruct
run 60 16 curve 10000000 reconstruct
for threads in 1 2 4 8 16; do
    run 90 "$threads" even-curve 10000000 reconstruct
done

# Item 3: 10^8 points reconstructed with the default pruned axis on all cores (time, peak
# memory per point). (The one-thread triangulation of 10^8 points, for the n log n
# flatness, takes another 100 s: `run 150 1 curve 100000000 points,triangulate`.)
run 170 16 curve 100000000 reconstruct
echo "done" | tee -a "$log"
