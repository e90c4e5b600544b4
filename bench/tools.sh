#!/usr/bin/env bash
# The road tools on a large road, timed: each command of `opencrg` that makes a road, in
# alternating rounds (every command once per round), and the import of a point cloud
# (points per second). Prints the processor, then per command the median and the range
# of its wall-clock times.
#
# usage: bench/tools.sh
# Environment: ROAD (default: target/bench-roads/winding_sloped_banked_2km_krbi.crg, a
# 2 km winding road with slope and banking, 16.2 M grid nodes, made by
# examples/make_bench_roads.rs), RUNS (rounds, default 3), POINTS (cloud size, default
# 2000000), MARKDOWN=1 for a Markdown table.
set -euo pipefail
cd "$(dirname "$0")/.."
roads=target/bench-roads
road=${ROAD:-$roads/winding_sloped_banked_2km_krbi.crg}
runs=${RUNS:-3}
points=${POINTS:-2000000}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
cargo build --release -q -p opencrg-cli
[ -f "$road" ] || cargo run --release -q -p opencrg-core --example make_bench_roads -- "$roads" >/dev/null
crg=target/release/opencrg
echo "processor: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'), $(nproc) threads"
echo "road: $road ($($crg info --json "$road" | python3 -c 'import json,sys; j=json.load(sys.stdin); print(j["cross_sections"], "x", j["long_sections"], "nodes")'))"

# A cloud sampled from a known surface over a 200 m x 8 m strip, as binary PLY, and a
# line along it.
python3 - "$out" "$points" <<'PY'
import struct, sys, random, math
out, n = sys.argv[1], int(sys.argv[2])
random.seed(1)
with open(f"{out}/cloud.ply", "wb") as f:
    f.write(f"ply\nformat binary_little_endian 1.0\nelement vertex {n}\nproperty double x\nproperty double y\nproperty double z\nend_header\n".encode())
    buf = bytearray()
    for _ in range(n):
        x, y = random.uniform(0, 200), random.uniform(-4, 4)
        buf += struct.pack("<ddd", x, y, 0.05 * math.sin(x / 3) + 0.02 * math.cos(y) + 0.01 * x)
    f.write(buf)
with open(f"{out}/line.csv", "w") as f:
    f.write("x,y\n2,0\n100,0.5\n198,0\n")
with open(f"{out}/line2k.csv", "w") as f:
    f.write("x,y,z\n")
    for i in range(0, 1001):
        x = 2.0 * i
        f.write(f"{x},{50 * math.sin(x / 200)},{0.02 * x}\n")
PY

u_first=$($crg info --json "$road" | python3 -c 'import json,sys; j=json.load(sys.stdin); print(j["u"]["first"])')
half=$(python3 -c "print($u_first + 1000)")
$crg cut "$road" "$out/first.crg" --u "$u_first:$half" 2>/dev/null
$crg cut "$road" "$out/second.crg" --u "$half:1e9" 2>/dev/null
declare -A cmds=(
  [cut]="cut $road $out/o.crg --u $u_first:$half --v -1:1"
  [flip]="flip $road $out/o.crg"
  [append]="append $out/first.crg $out/second.crg $out/o.crg"
  [resample]="resample $road $out/o.crg --u-inc 0.05 --v-inc 0.05"
  [filter_gauss]="filter $road $out/o.crg --gauss 0.05"
  [filter_median]="filter $road $out/o.crg --median 3"
  [slope_extract]="slope $road $out/o.crg --extract"
  [banking_apply]="banking $road $out/o.crg --apply"
  [compare]="compare $road $out/first.crg"
  [generate]="generate $out/o.crg --refline $out/line2k.csv --width 4 --u-inc 0.01 --v-inc 0.05 --surface 0.01*sin(u)*cos(v)"
  [import]="import $out/cloud.ply $out/o.crg --refline $out/line.csv --width 7 --u-inc 0.05 --v-inc 0.05"
)
order="cut flip append resample filter_gauss filter_median slope_extract banking_apply generate compare import"
for r in $(seq "$runs"); do
  for c in $order; do
    s=$(date +%s.%N)
    $crg ${cmds[$c]} >/dev/null 2>"$out/err" || { cat "$out/err"; exit 1; }
    e=$(date +%s.%N)
    echo "$c $(python3 -c "print($e - $s)")" >> "$out/times"
  done
done
python3 - "$out/times" "$points" "${MARKDOWN:-0}" <<'PY'
import sys, statistics
times = {}
for line in open(sys.argv[1]):
    c, t = line.split()
    times.setdefault(c, []).append(float(t))
md = sys.argv[3] == "1"
if md:
    print("| command | median s | min s | max s |\n| --- | --- | --- | --- |")
for c, ts in times.items():
    med, lo, hi = statistics.median(ts), min(ts), max(ts)
    extra = f"  ({int(sys.argv[2]) / med:,.0f} points/s, reading included)" if c == "import" else ""
    print(f"| {c} | {med:.2f} | {lo:.2f} | {hi:.2f} |{extra}" if md else f"{c:15} median {med:6.2f} s  [{lo:.2f} .. {hi:.2f}]{extra}")
PY
