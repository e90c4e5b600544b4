#!/usr/bin/env bash
# A conformance suite from the differential tester's random roads, in the layout of
# ../shared/conformance (cases.txt, the files under crg-txt/, answers under golden/), for
# the conformance client on every platform and binding: the answers are the Linux
# library's (which the differential tester holds equal to the reference's).
#
#   c-tests/generated/make_suite.sh OUT_DIR LIBRARY [ROADS] [SEED]
#
# Each road is asked twice: with the default options, and with border mode none in v
# and the reference point moved (the search and the refusals at the road's edges).
# CONFORMANCE_PROFILE=2.0.1 writes golden-2.0.1/ instead of golden/.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${1:?usage: make_suite.sh OUT_DIR LIBRARY [ROADS] [SEED]}
library=${2:?usage: make_suite.sh OUT_DIR LIBRARY [ROADS] [SEED]}
roads=${3:-150}
seed=${4:-7}
mkdir -p "$out"
out=$(cd "$out" && pwd)
if [ ! -f "$out/cases.txt" ]; then
    rm -rf "$out/crg-txt" "$out/raw"
    "$root/target/release/crg-difftest" --generate "$out/raw" --roads "$roads" --seed "$seed" >"$out/roads.txt"
    mkdir -p "$out/crg-txt"
    {
        echo "# NAME FILE NU NV [SETTING...]: the differential tester's roads (seed $seed)"
        for dir in "$out"/raw/road*; do
            name=$(basename "$dir")
            mkdir -p "$out/crg-txt/$name"
            cp "$dir"/*.crg "$out/crg-txt/$name/"
            echo "$name.default crg-txt/$name/road.crg 24 8"
            echo "$name.edges crg-txt/$name/road.crg 16 10 opt:BORDER_MODE_V=0 mod:REFPOINT_X=10.0"
        done
    } >"$out/cases.txt"
    rm -rf "$out/raw"
fi
golden=golden
[ "${CONFORMANCE_PROFILE:-current}" = current ] || golden=golden-$CONFORMANCE_PROFILE
rm -rf "$out/$golden"
# The suite's own runner writes the answers (comparing them with themselves).
CONFORMANCE_DATA="$out" sh "$root/../shared/conformance/run.sh" "$root/include" "$library" "$out/$golden" >/dev/null
echo "generated suite: $(grep -vc '^#' "$out/cases.txt") cases in $out ($golden)"
