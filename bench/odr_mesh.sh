#!/usr/bin/env bash
# The map mesh's figures: CARLA's Town03 with CRG records of our own (a generated surface
# of cobbles and potholes, 100 m x 7 m at 2 cm, laid `attached` on its 12 longest roads)
# exported with `opencrg odr export` at --max-error 5 mm and 1 mm and without a bound:
# triangles, file size, time and peak memory (GNU time), ROUNDS alternating rounds
# (default 3), medians with min and max; the processor's model first.
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=${ROUNDS:-3}
grep -m1 'model name' /proc/cpuinfo | sed 's/^.*: /processor: /'
cargo build -q --release -p opencrg-cli
bin=target/release/opencrg
work=target/odr-mesh-bench
mkdir -p "$work"
if [ ! -f "$work/cobbles.crg" ]; then
    printf 'x,y\n0,0\n50,0\n100,0\n' >"$work/line.csv"
    "$bin" generate "$work/cobbles.crg" --refline "$work/line.csv" --u-inc 0.02 --v-inc 0.02 --width 7 \
        --surface "0.004*sin(9*u)*cos(7*v) + 0.002*sin(31*u+3*v) - 0.02*exp(-((u-40)^2+(v-1)^2)/0.3)" >/dev/null
fi
python3 - "$work" <<'PY'
import re, sys
work = sys.argv[1]
text = open("../shared/opendrive/carla/Town03.xodr").read()
roads = [(float(m.group(2)), m.group(1)) for m in re.finditer(r'<road[^>]*?id="([^"]+)"[^>]*?length="([^"]+)"', text)]
roads += [(float(m.group(1)), m.group(2)) for m in re.finditer(r'<road[^>]*?length="([^"]+)"[^>]*?id="([^"]+)"', text)]
chosen = {rid for _, rid in sorted(set(roads), reverse=True)[:12]}
def lay(m):
    block = m.group(0)
    rid = re.search(r'\bid="([^"]+)"', block).group(1)
    if rid not in chosen:
        return block
    record = '<surface><CRG file="cobbles.crg" sStart="0" sEnd="100" mode="attached" orientation="same"/></surface>'
    return block.replace("</road>", record + "</road>")
out = re.sub(r"<road\b.*?</road>", lay, text, flags=re.S)
open(f"{work}/Town03_cobbles.xodr", "w").write(out)
print(f"Town03 with CRG records on roads {sorted(chosen)}")
PY
out=$(mktemp)
for round in $(seq "$rounds"); do
    for bound in 0.005 0.001 none; do
        args=()
        [ "$bound" = none ] || args=(--max-error "$bound")
        /usr/bin/time -f "peak %M kB, %e s" "$bin" odr export "$work/Town03_cobbles.xodr" "$work/town_$bound.glb" \
            "${args[@]}" 2>"$work/log"
        triangles=$(sed -n 's/.* \([0-9]*\) triangles.*/\1/p' "$work/log")
        peak=$(sed -n 's/^peak \([0-9]*\) kB, \([0-9.]*\) s/\1 \2/p' "$work/log")
        echo "$bound $triangles $(stat -c %s "$work/town_$bound.glb") $peak" >>"$out"
    done
done
python3 - "$out" <<'PY'
import statistics, sys
rows = {}
for line in open(sys.argv[1]):
    bound, tris, size, peak, secs = line.split()
    rows.setdefault(bound, []).append((int(tris), int(size), int(peak), float(secs)))
for bound, runs in rows.items():
    tris, size = runs[0][0], runs[0][1]
    peak = [r[2] / 1024 for r in runs]
    secs = [r[3] for r in runs]
    name = "no bound (CRG grid, 1 mm elsewhere)" if bound == "none" else f"--max-error {float(bound) * 1000:g} mm"
    print(f"{name:38} {tris:>10} triangles {size / 1e6:8.1f} MB  time median {statistics.median(secs):6.2f} s "
          f"[{min(secs):.2f}, {max(secs):.2f}]  peak memory median {statistics.median(peak):7.0f} MB "
          f"[{min(peak):.0f}, {max(peak):.0f}]  ({len(runs)} rounds)")
PY
rm -f "$out"
