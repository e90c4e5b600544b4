#!/usr/bin/env bash
# The vehicle workload (bench/vehicle_bench.c) against this project's library and, when
# given, against another library with the same API (for example the reference C library,
# built by you outside this project with gcc -O2), in alternating runs; prints per case
# the median and the range of every figure, and the median and range of the ratios of
# the runs taken in turn.
#
# usage: bench/vehicle_compare.sh [OTHER_LIB OTHER_INCLUDE_DIR]
#   OTHER_LIB           a static library (.a) offering the classic OpenCRG C API
#   OTHER_INCLUDE_DIR   the folder holding its crgBaseLib.h
# Environment: ROADS (default target/bench-roads), RUNS (alternating runs per road,
# default 5), STEPS (steps per pass, default 50000), ROAD_FILES (default: the straight
# 80 MB road and the winding road with slope and banking), CALLS (default: xy2z xy2uv
# xy2pk uv2z), PARTS (single: one thread; threads: 8 and 16; default both), VB_* (passed
# to the program, see bench/vehicle_bench.c), MARKDOWN=1 for Markdown tables, RESULTS=FILE to keep every
# run's lines (bench/vehicle_report.py FILE summarises them again).
set -euo pipefail
cd "$(dirname "$0")/.."
roads=${ROADS:-target/bench-roads}
runs=${RUNS:-5}
steps=${STEPS:-50000}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

source bench/build_programs.sh
build_programs bench/vehicle_bench.c vehicle "$@"
files=${ROAD_FILES:-"track_500m_krbi winding_sloped_banked_2km_krbi"}
# One call at a time (its cases on one thread, then on 8 and 16), the libraries in turn:
# the two runs of a pair are seconds apart, so a slow spell of a shared machine tends to
# hit both.
for f in $files; do
    for r in $(seq "$runs"); do
        for call in ${CALLS:-xy2z xy2uv xy2pk uv2z}; do
            for part in ${PARTS:-single threads}; do
                for l in "${libs[@]}"; do
                    if [ $part = single ]; then sel=(VB_THREADS=none); else sel=(VB_SPEEDS=none); fi
                    env VB_CALLS=$call "${sel[@]}" "$out/vehicle_$l" "$roads/$f.crg" "$steps" |
                        sed "s/^/$f $l $r /" >>"$out/results"
                done
            done
        done
    done
done
[ -n "${RESULTS:-}" ] && cp "$out/results" "$RESULTS"
python3 bench/vehicle_report.py "$out/results"
