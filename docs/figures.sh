#!/usr/bin/env bash
# Draws the guide's pictures with the command, so that they show what it draws:
#   docs/figures.sh [OUT]    (default OUT: docs)
# OPENCRG names the command (default target/release/opencrg). The map picture needs
# CARLA's Town03 from ../shared/opendrive. The test run draws them all again and
# compares them with the ones here (crates/opencrg-cli/tests/figures.rs).
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-docs}
opencrg=${OPENCRG:-target/release/opencrg}
road=examples/data/demo_road.crg
mkdir -p "$out"
"$opencrg" render "$road" "$out/demo_road.png"
"$opencrg" render "$road" "$out/demo_road_profile.png" --profile u=60
"$opencrg" roughness "$road" --plot "$out/demo_roughness.png" >/dev/null
# CARLA's Town03 comes with the project's test data (../shared), not with the project.
if [ -f ../shared/opendrive/carla/Town03.xodr ]; then
    "$opencrg" odr render ../shared/opendrive/carla/Town03.xodr "$out/town03.png" --size 900 2>/dev/null
else
    echo "docs/figures.sh: town03.png not drawn: it needs ../shared beside the checkout" >&2
fi
"$opencrg" odr render examples/data/demo_map.xodr "$out/demo_map.png" --size 900 2>/dev/null
for mode in attached attached0 genuine global; do
    "$opencrg" odr render "examples/data/modes/$mode.xodr" "$out/mode_$mode.png" --size 600 2>/dev/null
done
