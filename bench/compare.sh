#!/usr/bin/env bash
# Runs the benchmark against this project's library and, when given, against
# another library with the same API (for example the reference C library, built
# by you outside this project with gcc -O2), and prints the figures and ratios.
#
# usage: bench/compare.sh [OTHER_LIB OTHER_INCLUDE_DIR]
#   OTHER_LIB           a static library (.a) offering the classic OpenCRG C API
#   OTHER_INCLUDE_DIR   the folder holding its crgBaseLib.h
# Environment: ROADS (default target/bench-roads), N (queries, default 2000000),
# THREADS (default: number of cores), REPEAT (load runs per file, default 3).
set -euo pipefail
cd "$(dirname "$0")/.."
roads=${ROADS:-target/bench-roads}
n=${N:-2000000}
threads=${THREADS:-$(nproc)}
repeat=${REPEAT:-3}
out=$(mktemp -d)

source bench/build_programs.sh
build_programs bench/crg_bench.c bench "$@"

# best (lowest for times, highest otherwise) of several values
best() { sort -g | if [ "$1" = low ]; then head -n1; else tail -n1; fi; }

printf '%-22s %-26s' road figure; for l in "${libs[@]}"; do printf ' %14s' "$l"; done
[ ${#libs[@]} -eq 2 ] && printf ' %8s' ratio; echo
for f in track_500m_krbi track_500m_lrfi winding_10km_krbi; do
    file="$roads/$f.crg"
    declare -A val=()
    # Runs alternate between the libraries, and each figure is the best of its runs:
    # on a shared machine noise only ever makes a run slower.
    for r in $(seq "$repeat"); do
        for l in "${libs[@]}"; do
            "$out/bench_$l" load "$file" >>"$out/load_$l"
            if [ "$f" != track_500m_lrfi ]; then
                "$out/bench_$l" eval "$file" "$n" "$threads" >>"$out/eval_$l"
            fi
        done
    done
    for l in "${libs[@]}"; do
        val[$l,load_s]=$(awk '$1=="load_s"{print $2}' "$out/load_$l" | best low)
        val[$l,peak_rss_mb]=$(awk '$1=="peak_rss_mb"{print $2}' "$out/load_$l" | best low)
        if [ "$f" != track_500m_lrfi ]; then
            for name in $(awk '{print $1}' "$out/eval_$l" | sort -u); do
                val[$l,$name]=$(awk -v k="$name" '$1==k{print $2}' "$out/eval_$l" | best high)
            done
        fi
    done
    names="load_s peak_rss_mb"
    [ "$f" != track_500m_lrfi ] && names="$names $(awk '!seen[$1]++{print $1}' "$out/eval_opencrg" | tr '\n' ' ')"
    for name in $names; do
        printf '%-22s %-26s' "$f" "$name"
        for l in "${libs[@]}"; do printf ' %14s' "${val[$l,$name]}"; done
        if [ ${#libs[@]} -eq 2 ]; then
            case $name in
                load_s|peak_rss_mb) awk -v a="${val[other,$name]}" -v b="${val[opencrg,$name]}" 'BEGIN{printf " %8.2f", (b>0)?a/b:0}' ;;
                *) awk -v a="${val[opencrg,$name]}" -v b="${val[other,$name]}" 'BEGIN{printf " %8.2f", (b>0)?a/b:0}' ;;
            esac
        fi
        echo
    done
    unset val
    rm -f "$out"/load_* "$out"/eval_*
done
echo "ratio: how many times better this project's library is (time, memory: other/ours; rates: ours/other)"
rm -rf "$out"
