#!/usr/bin/env bash
# Packs the project's demo road and demo map as FMUs with the FMU binaries in BINARIES
# (laid out as PLATFORM/FILE), unpacks each into OUT/NAME, and writes OUT/NAME.points:
# "x y z" lines of points over and beside the road with the heights the native command
# answers (`opencrg eval --xy`, `opencrg odr eval`), for c-tests/fmu/fmu_host.c.
#   c-tests/fmu/expected.sh OPENCRG BINARIES OUT
set -euo pipefail
cd "$(dirname "$0")/../.."
opencrg=${1:?usage: expected.sh OPENCRG BINARIES OUT}
binaries=${2:?usage: expected.sh OPENCRG BINARIES OUT}
out=${3:?usage: expected.sh OPENCRG BINARIES OUT}
mkdir -p "$out"
for road in demo_road.crg demo_map.xodr; do
    name=${road%.*}
    "$opencrg" fmu "examples/data/$road" "$out/$name.fmu" --binaries "$binaries" 2>/dev/null
    rm -rf "${out:?}/$name"
    python3 -m zipfile -e "$out/$name.fmu" "$out/$name"
done
# The road: its u/v grid (and 2 m beyond) to x/y, then x/y to z.
python3 - >"$out/demo_road.uv" <<'PY'
for i in range(61):
    for j in range(9):
        print(-2.0 + i * 2.07, -4.0 + j * 1.0)
PY
"$opencrg" eval examples/data/demo_road.crg <"$out/demo_road.uv" | tail -n +2 | cut -d, -f3,4 | tr , ' ' >"$out/demo_road.xy"
"$opencrg" eval --xy examples/data/demo_road.crg <"$out/demo_road.xy" | tail -n +2 | awk -F, '{print $1, $2, $5}' \
    >"$out/demo_road.points"
# The map: a grid over its extent (many points off its roads).
python3 - >"$out/demo_map.xy" <<'PY'
for i in range(41):
    for j in range(25):
        print(-2.0 + i * 4.0, -8.0 + j * 3.6)
PY
"$opencrg" odr eval examples/data/demo_map.xodr <"$out/demo_map.xy" | paste -d' ' "$out/demo_map.xy" - |
    awk '{print $1, $2, $3}' >"$out/demo_map.points"
wc -l "$out/demo_road.points" "$out/demo_map.points" | tail -1 >/dev/null
