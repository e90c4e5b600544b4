#!/usr/bin/env bash
# The instruction guard: callgrind counts the instructions each hot call of the C library
# executes (c-tests/instructions/hot_calls.c: the car of bench/car.h on the benchmark roads,
# read into memory and, on the warm path of their tiles, read in place,
# a map's wheel query, loading a KRBI road) and compares them with the baseline kept beside
# this script. Instruction counts are the same for the same program and input however
# busy the machine is, so a few per cent more means more work in the call, not noise.
# Fails when a case grows by more than TOLERANCE per cent (default 3), naming it.
#
# usage: c-tests/instructions/run.sh [LIB.so]           compare with the baseline
#        c-tests/instructions/run.sh --bless [LIB.so]   write the baseline anew; commit it
#                                                       saying why the counts changed
#        c-tests/instructions/run.sh --against OTHER.so [LIB.so]
#                                      compare with another build of the library (an
#                                      earlier commit's, the reference's) instead of the
#                                      baseline, on the cases both offer
# LIB.so defaults to target/release/libopencrg.so (built here when missing).
set -euo pipefail
cd "$(dirname "$0")/../.."
here=c-tests/instructions
baseline=$here/baseline.txt
bless=0
against=
if [ "${1:-}" = --bless ]; then
    bless=1
    shift
elif [ "${1:-}" = --against ]; then
    against=$(cd "$(dirname "$2")" && pwd)/$(basename "$2")
    shift 2
fi
lib=${1:-target/release/libopencrg.so}
tolerance=${TOLERANCE:-3}
[ "$(uname -m)" = x86_64 ] || { echo "instruction guard: the baseline is for x86_64, not $(uname -m)" >&2; exit 1; }
command -v valgrind >/dev/null || { echo "instruction guard: needs valgrind" >&2; exit 1; }
[ -f "$lib" ] || cargo build --release -q -p opencrg-capi
lib=$(cd "$(dirname "$lib")" && pwd)/$(basename "$lib")
out=target/instructions
roads=target/bench-roads
mkdir -p "$out"
cc -O2 -Wall -Wextra -Ibench $here/hot_calls.c -ldl -lm -o "$out/hot_calls"
cargo run --release -q -p opencrg-core --example make_bench_roads -- "$roads" \
    track_500m_krbi winding_sloped_banked_2km_krbi >/dev/null

# The cases: a name, the case of hot_calls and its file.
straight=$roads/track_500m_krbi.crg
winding=$roads/winding_sloped_banked_2km_krbi.crg
cases=(
    "xy2z-own-straight xy2z-own $straight"
    "xy2z-own-winding xy2z-own $winding"
    "xy2z-shared-straight xy2z-shared $straight"
    "xy2z-shared-winding xy2z-shared $winding"
    "xy2uv-own-straight xy2uv-own $straight"
    "xy2uv-own-winding xy2uv-own $winding"
    "xy2uv-shared-straight xy2uv-shared $straight"
    "xy2uv-shared-winding xy2uv-shared $winding"
    "xy2pk-own-winding xy2pk-own $winding"
    "uv2z-own-straight uv2z-own $straight"
    "uv2z-own-winding uv2z-own $winding"
    "uv2pk-own-winding uv2pk-own $winding"
    "xy2z-own-in-place-winding xy2z-own-in-place $winding"
    "uv2z-own-in-place-straight uv2z-own-in-place $straight"
    "uv2z-shared-in-place-straight uv2z-shared-in-place $straight"
    "odr-wheels-attached odr-wheels examples/data/modes/attached.xodr"
    "load-krbi-80mb load $straight"
)

# One case of one library: its instructions per call, into DIR/NAME.count (with
# --against, a case the other library lacks is left out, and "-" written).
count() {
    local lib=$1 dir=$2 name=$3 case=$4 file=$5
    if ! valgrind --tool=callgrind --toggle-collect=measured --callgrind-out-file="$dir/$name.callgrind" \
        "$out/hot_calls" "$lib" "$case" "$file" >"$dir/$name.stdout" 2>"$dir/$name.stderr"; then
        if [ -n "$against" ] && grep -q 'undefined symbol' "$dir/$name.stderr"; then
            echo - >"$dir/$name.count"
            return 0
        fi
        echo "instruction guard: $name failed:" >&2
        cat "$dir/$name.stderr" >&2
        return 1
    fi
    local calls total
    calls=$(sed -n 's/^calls //p' "$dir/$name.stdout")
    total=$(sed -n 's/^summary: //p' "$dir/$name.callgrind")
    awk -v t="$total" -v c="$calls" 'BEGIN { printf "%.1f\n", t / c }' >"$dir/$name.count"
}
export -f count
export out against
mkdir -p "$out/this" "$out/other"
{
    printf "$lib $out/this %s\n" "${cases[@]}"
    [ -z "$against" ] || printf "$against $out/other %s\n" "${cases[@]}"
} | xargs -P "$(nproc)" -L 1 bash -c 'count "$@"' _

toolchain="$(rustc --version), $(cc --version | head -1), $(valgrind --version)"
if [ $bless = 1 ]; then
    {
        echo "# Instructions per call of the hot calls, counted by c-tests/instructions/run.sh"
        echo "# (callgrind; x86_64). Written by run.sh --bless with: $toolchain"
        for c in "${cases[@]}"; do
            name=${c%% *}
            echo "$name $(cat "$out/this/$name.count")"
        done
    } >"$baseline"
    echo "instruction guard: baseline written to $baseline"
    cat "$baseline"
    exit 0
fi

echo "instruction guard: $toolchain; tolerance $tolerance %"
if [ -n "$against" ]; then
    echo "against $against"
    printf '%-30s %14s %14s %8s\n' case other this change
else
    printf '%-30s %14s %14s %8s\n' case baseline now change
fi
failed=()
for c in "${cases[@]}"; do
    name=${c%% *}
    now=$(cat "$out/this/$name.count")
    if [ -n "$against" ]; then
        was=$(cat "$out/other/$name.count")
        [ "$was" != - ] || continue
    else
        was=$(awk -v n="$name" '$1 == n { print $2 }' "$baseline")
    fi
    if [ -z "$was" ]; then
        printf '%-30s %14s %14s\n' "$name" "(none)" "$now"
        failed+=("$name (not in the baseline)")
        continue
    fi
    change=$(awk -v a="$now" -v b="$was" 'BEGIN { printf "%+.2f", 100 * (a - b) / b }')
    printf '%-30s %14s %14s %7s%%\n' "$name" "$was" "$now" "$change"
    if awk -v c="$change" -v t="$tolerance" 'BEGIN { exit !(c > t) }'; then
        failed+=("$name ($change %)")
    fi
done
if [ ${#failed[@]} -gt 0 ]; then
    if [ -n "$against" ]; then
        echo "instruction guard: more work than $against in: ${failed[*]}" >&2
    else
        echo "instruction guard: more work than the baseline in: ${failed[*]}" >&2
        echo "(a deliberate change: run $0 --bless and commit the baseline with the reason)" >&2
    fi
    exit 1
fi
echo "instruction guard: every case within $tolerance % of the ${against:-baseline}"
