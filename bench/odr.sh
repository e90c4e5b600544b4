#!/usr/bin/env bash
# The OpenDRIVE layer's figures: reading each CARLA town against libOpenDRIVE (built from
# ../shared/oracles), four wheels at 1 kHz on a road with an attached CRG file against
# the CRG file alone (in Rust, and through the C API: crgOdrEvalxy against crgEvalxy2z),
# random points over a town. ROUNDS alternating rounds (default 5),
# medians with min and max; the processor's model first.
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=${ROUNDS:-5}
grep -m1 'model name' /proc/cpuinfo | sed 's/^.*: /processor: /'
cargo build -q --release -p opencrg-odr --example odr_bench
cargo build -q --release -p opencrg-capi
bin=target/release/examples/odr_bench
cc -O2 -Iinclude bench/odr_wheels.c target/release/libopencrg.a -lm -lpthread -ldl -o target/release/odr_wheels
lib=target/libopendrive
if [ ! -f "$lib/lib/libOpenDrive.a" ]; then
    ../shared/oracles/build-libopendrive.sh "$PWD/$lib" >/dev/null
fi
g++ -O2 -std=c++17 -I "$lib/include" bench/odr_load.cpp -L "$lib/lib" -lOpenDrive -lpugixml -o "$lib/odr_load"
out=$(mktemp)
for round in $(seq "$rounds"); do
    for town in ../shared/opendrive/carla/Town0*.xodr; do
        "$bin" load "$town" >>"$out"
        "$lib/odr_load" "$town" >>"$out"
    done
    "$bin" wheels target/odr-bench >>"$out"
    target/release/odr_wheels target/odr-bench 1 >>"$out"
    "$bin" random ../shared/opendrive/carla/Town03.xodr >>"$out"
done
python3 - "$out" <<'PY'
import re, statistics, sys
rows = {}
for line in open(sys.argv[1]):
    m = re.match(r"load .*/(Town\d+)\.xodr: read ([\d.]+) ms, index ([\d.]+) ms", line)
    if m:
        rows.setdefault((m[1], "this library: read"), []).append(float(m[2]))
        rows.setdefault((m[1], "this library: read + index"), []).append(float(m[2]) + float(m[3]))
    m = re.match(r"libOpenDRIVE .*/(Town\d+)\.xodr: read ([\d.]+) ms", line)
    if m:
        rows.setdefault((m[1], "libOpenDRIVE: read"), []).append(float(m[2]))
    m = re.match(r"wheels: ([\d.]+) ns per wheel query on the map, ([\d.]+) ns", line)
    if m:
        rows.setdefault(("wheels", "ns per wheel query (map, attached CRG)"), []).append(float(m[1]))
        rows.setdefault(("wheels", "ns per xy_to_z (CRG alone)"), []).append(float(m[2]))
    m = re.match(r"c wheels: ([\d.]+) ns per crgOdrEvalxy, ([\d.]+) ns per crgEvalxy2z", line)
    if m:
        rows.setdefault(("wheels", "C: ns per crgOdrEvalxy"), []).append(float(m[1]))
        rows.setdefault(("wheels", "C: ns per crgEvalxy2z (CRG alone)"), []).append(float(m[2]))
    m = re.match(r"random .*/(Town\d+)\.xodr: (\d+) queries/s", line)
    if m:
        rows.setdefault((m[1], "random points: queries/s"), []).append(float(m[2]))
for (what, how), v in sorted(rows.items()):
    print(f"{what:8} {how:40} median {statistics.median(v):12.2f}  min {min(v):12.2f}  max {max(v):12.2f}  ({len(v)} rounds)")
PY
rm -f "$out"
