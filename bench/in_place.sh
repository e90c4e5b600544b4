#!/usr/bin/env bash
# The vehicle workload (bench/vehicle_bench.c) on roads read in place against the same
# roads read into memory (OPENCRG_IN_PLACE=always and never, this project's library), and,
# when given, against another library with the same API (the reference C library, built
# by you outside this project with gcc -O2), in alternating runs; prints per case the
# median and range of every figure and of the ratios of the runs taken in turn (memory /
# in place: at least 0.9 is the goal; other / in place).
#
# usage: bench/in_place.sh [OTHER_LIB OTHER_INCLUDE_DIR]
# Environment: ROADS (default target/bench-roads), ROAD_FILES (names there, without .crg;
# default: the 80 MB road and the winding road with slope and banking), RUNS (alternating
# runs, default 5), STEPS (steps per pass, default 50000), CALLS (default xy2z uv2z; the
# x/y to u/v and heading calls read no grid), VB_* (see bench/vehicle_bench.c),
# OPENCRG_IN_PLACE_CACHE (the tile cache), MARKDOWN=1, RESULTS=FILE (keep every line).
set -euo pipefail
cd "$(dirname "$0")/.."
roads=${ROADS:-target/bench-roads}
runs=${RUNS:-5}
steps=${STEPS:-50000}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

source bench/build_programs.sh
build_programs bench/vehicle_bench.c vehicle "$@"
for f in ${ROAD_FILES:-track_500m_krbi winding_sloped_banked_2km_krbi}; do
    for r in $(seq "$runs"); do
        for call in ${CALLS:-xy2z uv2z}; do
            for part in single threads; do
                if [ $part = single ]; then sel=(VB_THREADS=none); else sel=(VB_SPEEDS=none); fi
                for label in memory in_place ${libs[1]:+reference}; do
                    case $label in
                        memory) program=$out/vehicle_opencrg; mode=never ;;
                        in_place) program=$out/vehicle_opencrg; mode=always ;;
                        reference) program=$out/vehicle_other; mode=never ;;
                    esac
                    env OPENCRG_IN_PLACE=$mode VB_CALLS=$call "${sel[@]}" "$program" "$roads/$f.crg" "$steps" |
                        sed "s/^/$f $label $r /" >>"$out/results"
                done
            done
        done
    done
done
[ -n "${RESULTS:-}" ] && cp "$out/results" "$RESULTS"
echo "== in place against memory (ratio: memory / in place time)"
grep -v " reference " "$out/results" >"$out/memory"
BASE=in_place python3 bench/vehicle_report.py "$out/memory"
if [ ${#libs[@]} -gt 1 ]; then
    echo
    echo "== in place against the other library (ratio: other / in place time)"
    grep -v " memory " "$out/results" >"$out/reference"
    BASE=in_place python3 bench/vehicle_report.py "$out/reference"
fi
