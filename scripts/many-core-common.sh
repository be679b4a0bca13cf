# Sourced by scripts/many-core-*.sh with `log_name` set: the stress binary, the log file, and
# `run`. The binary is $STRESS_BIN (default target/release/examples/stress); the log goes to
# $OUT/$log_name, $OUT defaulting to a new temporary folder. Each run has its own time limit,
# so one slow run cannot take the rest with it.
bin=${STRESS_BIN:-target/release/examples/stress}
out=${OUT:-$(mktemp -d)}
mkdir -p "$out"
log="$out/$log_name"
: >"$log"
echo "log: $log"

# `run LIMIT THREADS ARGS…`: one stress run with RAYON_NUM_THREADS=THREADS.
run() {
    local limit=$1 threads=$2
    shift 2
    echo "## threads $threads: stress $*" | tee -a "$log"
    RAYON_NUM_THREADS=$threads timeout "$limit" "$bin" "$@" 2>&1 | tee -a "$log"
    echo "(exit ${PIPESTATUS[0]})" | tee -a "$log"
}

{ nproc; grep -m1 'model name' /proc/cpuinfo; free -g | head -2; } 2>&1 | tee -a "$log"
