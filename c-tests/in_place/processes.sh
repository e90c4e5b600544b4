#!/bin/sh
# A road of gigabytes (generated here, 2.0 GB KRBI: above the size from which binary roads
# are read in place) opened at once by PROCESSES programs of the classic API
# (bench/open_drive.c: read, check, modifiers, a contact point per wheel, a car's four
# wheels driven over 200 m), each on the same stretch: every one must hold at most 256 MiB
# of private memory (RssAnon of /proc/PID/status) and give the answers one program gives
# with the road read into memory.
#
# usage: processes.sh LIBRARY INCLUDE_DIR BENCH_DIR ROADS_DIR OUT_DIR [PROCESSES]
set -eu
lib=$1 inc=$2 bench=$3 roads=$4 out=$5 processes=${6:-4}
mkdir -p "$out"
cc -O2 -I"$inc" -I"$bench" "$bench/open_drive.c" "$lib" -lm -Wl,-rpath,"$(dirname "$lib")" -o "$out/open_drive"
road=$roads/winding_5km_2gb_krbi.crg
[ -f "$road" ] || { echo "processes.sh: $road missing (make_bench_roads makes it)" >&2; exit 1; }
OPENCRG_IN_PLACE=never "$out/open_drive" "$road" 200 30 1000 >"$out/memory"
for i in $(seq "$processes"); do
    "$out/open_drive" "$road" 200 30 1000 >"$out/in_place.$i" &
done
wait
cat "$out/memory" "$out"/in_place.*
sink() { sed -n 's/.* sink \([^ ]*\).*/\1/p' "$1"; }
anon() { sed -n 's/.* rss_anon \([0-9]*\).*/\1/p' "$1"; }
status=0
for f in "$out"/in_place.*; do
    [ "$(sink "$f")" = "$(sink "$out/memory")" ] || { echo "processes.sh: $f answers otherwise than in memory" >&2; status=1; }
    [ "$(anon "$f")" -le 262144 ] || { echo "processes.sh: $f holds more than 256 MiB of private memory" >&2; status=1; }
done
[ "$(anon "$out/memory")" -gt 1048576 ] || { echo "processes.sh: the road in memory should hold its grid" >&2; status=1; }
[ $status = 0 ] && echo "processes.sh: $processes processes read $road in place, each within 256 MiB, with the answers of memory"
exit $status
