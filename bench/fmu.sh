#!/usr/bin/env bash
# The FMI layer's figures: four wheels at 1 kHz through an FMU of `opencrg fmu` (one
# fmi2SetReal and one fmi2GetReal a step, bench/fmu_wheels.c) against the plain C calls
# along the same paths, crgEvalxy2z on a CRG file and crgOdrEvalxy on a map with an
# attached CRG file (the road and map of `odr_bench wheels`). ROUNDS alternating rounds
# (default 7): medians with min and max, and the median ratio of the rounds; the
# processor's model first. Fails where the FMU's answers differ from the plain calls'.
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=${ROUNDS:-7}
grep -m1 'model name' /proc/cpuinfo | sed 's/^.*: /processor: /'
cargo build -q --release -p opencrg-odr --example odr_bench
cargo build -q --release -p opencrg-capi -p opencrg-cli -p opencrg-fmi
dir=target/fmu-bench
mkdir -p "$dir"
target/release/examples/odr_bench wheels target/odr-bench >/dev/null
for road in track.crg track.xodr; do
    name=${road/./_}
    target/release/opencrg fmu "target/odr-bench/$road" "$dir/$name.fmu" 2>/dev/null
    rm -rf "${dir:?}/$name"
    python3 -m zipfile -e "$dir/$name.fmu" "$dir/$name"
done
cc -O2 -Iinclude bench/fmu_wheels.c target/release/libopencrg.a -lm -lpthread -ldl -o "$dir/fmu_wheels"
out=$(mktemp)
trap 'rm -f "$out"' EXIT
for round in $(seq "$rounds"); do
    "$dir/fmu_wheels" "$dir/track_crg/binaries/linux64/track.so" "$dir/track_crg" "$dir/track_xodr" target/odr-bench 1 >>"$out"
done
python3 - "$out" <<'PY'
import re, statistics, sys
rows = [re.match(r"fmu wheels: ([\d.]+) ns .*?, ([\d.]+) ns .*?, ([\d.]+) ns .*?, ([\d.]+) ns .*\(sums (\S+) (\S+) (\S+) (\S+)\)", l)
        for l in open(sys.argv[1])]
assert rows and all(rows), "unexpected output"
for m in rows:
    assert m[5] == m[6] and m[7] == m[8], f"the FMU's heights differ from the plain calls': {m[0]}"
def show(name, values):
    print(f"{name:44s} median {statistics.median(values):7.1f} ns  (min {min(values):.1f}, max {max(values):.1f})")
cols = [[float(m[k]) for m in rows] for k in range(1, 5)]
show("crgEvalxy2z (CRG file)", cols[0])
show("FMU of the CRG file, per wheel", cols[1])
show("crgOdrEvalxy (map, attached CRG)", cols[2])
show("FMU of the map, per wheel", cols[3])
for name, a, b in (("CRG file", cols[1], cols[0]), ("map", cols[3], cols[2])):
    r = [x / y for x, y in zip(a, b)]
    print(f"FMU / plain, {name:31s} median {statistics.median(r):.3f}  (min {min(r):.3f}, max {max(r):.3f})")
print(f"{len(rows)} rounds; the FMU's heights equal the plain calls' in every round")
PY
