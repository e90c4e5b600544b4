#!/usr/bin/env bash
# Builds the fuzz targets with the stable toolchain (libFuzzer with coverage counters, no
# sanitizer: the code is safe Rust, so a bug shows as a panic or an abort) and runs each
# for SECONDS (default 30), one a processor at a time, under 4 GB of address space, from the seeds of
# examples/make_fuzz_seeds.rs. Prints each target's executions; exits non-zero on the
# first finding, which is left in target/fuzz/findings/. With nightly and cargo-fuzz,
# `cargo +nightly fuzz run TARGET` runs the same targets under AddressSanitizer.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-30}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(header text_reader binary_reader evaluation point_files map_section formula tools odr_map)
host=$(rustc -vV | sed -n 's/^host: //p')
# The coverage instrumentation libFuzzer reads (what cargo-fuzz passes), on the targets
# only (--target keeps it off build scripts); debug assertions and overflow checks on.
export RUSTFLAGS="--cfg fuzzing -Cpasses=sancov-module -Cllvm-args=-sanitizer-coverage-level=4 \
-Cllvm-args=-sanitizer-coverage-inline-8bit-counters -Cllvm-args=-sanitizer-coverage-pc-table \
-Cllvm-args=-sanitizer-coverage-trace-compares -Cdebug-assertions -Coverflow-checks"
# Optimised at level 1: the build takes about half the time it takes at level 3, and the
# runs cover as many paths in their seconds.
(cd fuzz && CARGO_PROFILE_RELEASE_OPT_LEVEL=1 cargo build -q --release --target "$host" --target-dir ../target/fuzz)
bin=target/fuzz/$host/release
corpus=target/fuzz/corpus
mkdir -p "$corpus" target/fuzz/findings
# (The seeds' maker in the development profile: the test run has built its crates so.)
(unset RUSTFLAGS; cargo run -q -p opencrg-tools --example make_fuzz_seeds -- "$corpus")
cpu=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')
echo "fuzzing ${seconds} s per target on $cpu"
# One target a processor at a time (each is one process, single-threaded).
run_target() {
    local t=$1 log=target/fuzz/$1.log
    mkdir -p "$corpus/$t"
    if ! (ulimit -v 4000000; "$bin/$t" "$corpus/$t" -max_total_time="$seconds" -rss_limit_mb=2048 \
            -malloc_limit_mb=1024 -timeout=20 -artifact_prefix=target/fuzz/findings/"$t"- >"$log" 2>&1); then
        echo "fuzz target $t found a problem:"
        grep -E 'panicked|ERROR|SUMMARY' "$log" | head -5
        ls target/fuzz/findings/"$t"-* 2>/dev/null
        return 1
    fi
    runs=$(sed -n 's/^Done \([0-9]*\) runs in \([0-9]*\) second.*/\1 runs in \2 s/p' "$log")
    cover=$(grep -o 'cov: [0-9]*' "$log" | tail -1)
    echo "fuzz target $t: $runs, $cover, no finding"
}
jobs=$(nproc)
failed=0
for ((i = 0; i < ${#targets[@]}; i += jobs)); do
    pids=()
    for t in "${targets[@]:i:jobs}"; do
        run_target "$t" >"target/fuzz/$t.report" &
        pids+=($!)
    done
    for pid in "${pids[@]}"; do
        wait "$pid" || failed=1
    done
    for t in "${targets[@]:i:jobs}"; do
        cat "target/fuzz/$t.report"
    done
    [ $failed = 0 ] || exit 1
done
