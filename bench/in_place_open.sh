#!/usr/bin/env bash
# Opening a big binary road and driving 200 m of it (bench/open_drive.c through the classic
# API: read, check, modifiers, a contact point per wheel, x/y to z at 1 kHz, 30 m/s), read
# in place and read into memory in alternating runs, then by several processes at once
# reading it in place. Prints the processor, then per case the median and range of the
# time to open, the time to drive and the private memory (RssAnon) each process held.
# The file is read once first, so that every run finds it in the system's cache.
#
# usage: bench/in_place_open.sh ROAD [PROCESSES]   (default 8 processes at once)
# Environment: RUNS (alternating runs, default 5), MEMORY=0 (no runs in memory: a road
# bigger than the machine's memory).
set -euo pipefail
cd "$(dirname "$0")/.."
road=$1
processes=${2:-8}
runs=${RUNS:-5}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
cargo build --release -q -p opencrg-capi
cc -O2 -Iinclude -Ibench bench/open_drive.c target/release/libopencrg.a -lm -lpthread -ldl -o "$out/open_drive"
grep -m1 "model name" /proc/cpuinfo | sed 's/.*: /cpu /'
echo "road $road ($(stat -c %s "$road") bytes)"
cat "$road" >/dev/null
modes="in_place"
[ "${MEMORY:-1}" = 0 ] || modes="in_place memory"
for r in $(seq "$runs"); do
    for mode in $modes; do
        [ $mode = memory ] && setting=never || setting=always
        OPENCRG_IN_PLACE=$setting "$out/open_drive" "$road" 200 30 1000 2>/dev/null | sed "s/^/$mode /" >>"$out/results"
    done
done
for i in $(seq "$processes"); do
    OPENCRG_IN_PLACE=always "$out/open_drive" "$road" 200 30 1000 >"$out/at_once.$i" 2>/dev/null &
done
start=$(date +%s.%N)
wait
end=$(date +%s.%N)
for f in "$out"/at_once.*; do sed "s/^/${processes}_at_once /" "$f" >>"$out/results"; done
python3 - "$out/results" "$start" "$end" <<'EOF'
import statistics
import sys

rows = {}
for line in open(sys.argv[1]):
    f = line.split()
    figures = dict(zip(f[1::2], f[2::2]))
    rows.setdefault(f[0], []).append(figures)
def told(values, unit, scale=1.0):
    v = sorted(float(x) * scale for x in values)
    return f"{statistics.median(v):.2f} ({v[0]:.2f}-{v[-1]:.2f}) {unit}"
for case, runs in rows.items():
    sinks = {r["sink"] for r in runs}
    print(f"{case:>14} x{len(runs)}: open {told([r['open'] for r in runs], 's')}, "
          f"drive {told([r['drive'] for r in runs], 's')}, "
          f"private {told([r['rss_anon'] for r in runs], 'MiB', 1 / 1024)}, sink {' '.join(sorted(sinks))}")
print(f"all processes at once done within {float(sys.argv[3]) - float(sys.argv[2]):.2f} s of their start")
EOF
