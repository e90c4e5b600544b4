#!/usr/bin/env bash
# This project's library against other shared libraries with the same API (for example
# the reference C library as ../shared/reference/build-references.sh builds it, or an
# earlier build of this project's), all loaded into one process and driven in turn
# along the car's path (bench/vehicle_ab.c): the per-round ratios tell builds apart on a
# noisy machine. The first library named is the baseline of the ratios.
#
# usage: bench/vehicle_ab.sh BASELINE.so [OTHER.so ...]
# Environment: ROAD_FILES (default: the straight 80 MB road and the winding road with
# slope and banking), AB_CALLS, AB_SPEEDS, AB_ROUNDS, AB_MODES, AB_IN_PLACE, AB_WARM (see
# bench/vehicle_ab.c). This build in memory against itself read in place, in one process:
#   AB_IN_PLACE=never,always bench/vehicle_ab.sh target/release/libopencrg.so
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -ge 1 ] || { echo "usage: bench/vehicle_ab.sh BASELINE.so [OTHER.so ...]" >&2; exit 2; }
roads=target/bench-roads
cargo build --release -q -p opencrg-capi
cargo run --release -q -p opencrg-core --example make_bench_roads -- "$roads" >/dev/null
cc -O2 -Wall -Wextra -Iinclude bench/vehicle_ab.c -ldl -lm -o target/vehicle_ab
grep -m1 'model name' /proc/cpuinfo | sed 's/.*: /cpu /'
libs=()
for l in "$@"; do libs+=("$(cd "$(dirname "$l")" && pwd)/$(basename "$l")"); done
for f in ${ROAD_FILES:-track_500m_krbi winding_sloped_banked_2km_krbi}; do
    target/vehicle_ab "$roads/$f.crg" "${libs[@]}" "$PWD/target/release/libopencrg.so" | sed "s/^/$f /"
done
