#!/bin/bash
# Alternating A/B runs of two builds of examples/stress.rs on the sets and sizes of the
# stress table in benches/README.md (on a shared machine only alternation and ranges mean
# anything). Build each side first, e.g.:
#   git worktree add /tmp/ab-old <commit> && (cd /tmp/ab-old && cargo build --release --example stress)
#   cargo build --release --example stress
#   scripts/ab-stress.sh /tmp/ab-old/target/release/examples/stress target/release/examples/stress > ab.txt
# Each block is headed `== <a|b> threads=<t> <set> <n>`; about 6 minutes on 2 cores.
set -euo pipefail
a=$1
b=$2
run() { # threads set n
  for side in a b; do
    bin=$a
    [ "$side" = b ] && bin=$b
    echo "== $side threads=$1 $2 $3"
    RAYON_NUM_THREADS=$1 "$bin" "$2" "$3" reconstruct 2>&1 | grep -E "phases|peak RSS after|total"
  done
}
for _ in 1 2 3; do
  run 1 even-curve 1000000
  run 1 curve 1000000
done
for _ in 1 2; do
  run 1 even-curve 10000000
  run 2 even-curve 10000000
  run 1 curve 10000000
  run 2 curve 10000000
done
# Oversubscribed on a small machine: for the memory peak of many worker threads only.
run 16 even-curve 10000000
run 16 curve 10000000
