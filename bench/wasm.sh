#!/usr/bin/env bash
# The npm package's figures: the .wasm's size (and gzipped); uvToZ and map.ground per
# point in Node (the second call over the points, and the first) against crgEvaluv2z and
# crgOdrEvalxy natively, at the same points (a 67 MB KRBI road of make_bench_roads and
# CARLA's Town03), in ROUNDS alternating rounds (default 5); opening the 80 MB KRBI road
# and Town03 in the web page in headless Chromium (fetching, reading, drawing, in real
# time: bench/page_timing.py). Medians with min and max; the processor's model first.
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=${ROUNDS:-5}
grep -m1 'model name' /proc/cpuinfo | sed 's/^.*: /processor: /'
dir=target/wasm-bench
mkdir -p "$dir"
packaging/wasm.sh "$dir/dist" >/dev/null
wasm="$dir/dist/package/opencrg_bg.wasm"
echo "wasm: $(stat -c %s "$wasm") bytes, $(gzip -9 -c "$wasm" | wc -c) gzipped"
cargo build -q --release -p opencrg-capi
cargo run -q --release -p opencrg-core --example make_bench_roads -- target/bench-roads winding_sloped_banked_2km_krbi track_500m_krbi >/dev/null
road=target/bench-roads/winding_sloped_banked_2km_krbi.crg
town=../shared/opendrive/carla/Town03.xodr
cc -O2 -Iinclude bench/wasm_native.c target/release/libopencrg.a -lm -lpthread -ldl -o "$dir/wasm_native"
out=$(mktemp)
trap 'rm -f "$out"' EXIT
for r in $(seq "$rounds"); do
    node bench/wasm_speed.mjs "$dir/dist/package" "$road" "$town" "$dir" >>"$out"
    "$dir/wasm_native" "$road" "$town" "$dir" >>"$out"
done
# The page, served on loopback, opening a big road and a town.
site=$(mktemp -d)
cp -r "$dir/dist/web" "$site/web"
ln -s "$PWD/target/bench-roads/track_500m_krbi.crg" "$site/big.crg"
ln -s "$PWD/$town" "$site/Town03.xodr"
(cd "$site" && exec python3 -m http.server 8791 --bind 127.0.0.1 >/dev/null 2>&1) &
server=$!
sleep 1
for r in $(seq "$rounds"); do
    for file in big.crg Town03.xodr; do
        timing=$(python3 bench/page_timing.py "http://127.0.0.1:8791/web/index.html?road=../$file" 300)
        echo "page $file: $timing" >>"$out"
    done
done
kill $server
rm -rf "$site"
python3 - "$out" <<'PY'
import re, statistics, sys
rows = {}
for line in open(sys.argv[1]):
    m = re.match(r"wasm: ([\d.]+) ns per uvToZ point, ([\d.]+) ns per map.ground point \(sums (\S+) (\S+)\); first calls ([\d.]+), ([\d.]+)", line)
    if m:
        rows.setdefault("uvToZ (Node, wasm)", []).append(float(m[1]))
        rows.setdefault("map.ground (Node, wasm)", []).append(float(m[2]))
        rows.setdefault("uvToZ (Node, wasm), first call", []).append(float(m[5]))
        rows.setdefault("map.ground (Node, wasm), first call", []).append(float(m[6]))
    m = re.match(r"native: ([\d.]+) ns per crgEvaluv2z point, ([\d.]+) ns per crgOdrEvalxy point", line)
    if m:
        rows.setdefault("crgEvaluv2z (native)", []).append(float(m[1]))
        rows.setdefault("crgOdrEvalxy (native)", []).append(float(m[2]))
    m = re.match(r"page (\S+): fetched (\d+) ms, read (\d+) ms, drawn (\d+) ms", line)
    if m:
        rows.setdefault(f"page {m[1]}: fetch + read + draw (ms)", []).append(int(m[2]) + int(m[3]) + int(m[4]))
        rows.setdefault(f"page {m[1]}: read (ms)", []).append(int(m[3]))
for name, v in rows.items():
    print(f"{name:44s} median {statistics.median(v):9.1f}  (min {min(v):.1f}, max {max(v):.1f}, {len(v)} rounds)")
for a, b in (("uvToZ (Node, wasm)", "crgEvaluv2z (native)"), ("map.ground (Node, wasm)", "crgOdrEvalxy (native)"),
             ("uvToZ (Node, wasm), first call", "crgEvaluv2z (native)"), ("map.ground (Node, wasm), first call", "crgOdrEvalxy (native)")):
    r = [x / y for x, y in zip(rows[a], rows[b])]
    print(f"{a} / native: median {statistics.median(r):.2f} (min {min(r):.2f}, max {max(r):.2f})")
PY
