#!/usr/bin/env bash
# Runs every test: formatting, lints and documentation, the Rust tests (unit,
# integration, header freshness, the opencrg command, doctests incl. the README's), the
# crates as published (the rust-version's toolchain, `cargo package`), the contact
# points' owner path under Miri, a short run of every fuzz target, the OpenDRIVE
# geometry against libOpenDRIVE and its CRG records against the reference C library, then
# the instruction guard of the hot calls (callgrind against a kept baseline), through
# CTest the C tests (also under the sanitizers and valgrind), the header and
# symbol checks, the CMake consumer project, the conformance suite in both behaviour
# profiles (.so and .a, and with every binary road read in place), roads read in place
# (a file cut short under an open road, a 2 GB road opened by four processes at once) and
# the differential tester; the same C tests and conformance
# suite on Windows (MinGW-w64 build under wine, with the zip's CMake package and MSVC
# import library) and from the Linux archives (glibc 2.17, zig; the aarch64 one under
# qemu), with CMake and pkg-config consumers, and each platform's FMU binary through a C
# host of the project's own; FMUs driven by FMPy (FMI 2 and 3, co-simulation and model
# exchange), ECOS and libcosim against the C API; the npm package (WebAssembly) in Node
# and its web page in headless Chromium; the .glb export against the Khronos
# glTF validator, the 3D view in headless Chromium; last the Python package: its
# manylinux2014 wheel built with maturin and zig, installed into a fresh virtual
# environment without cargo, and its pytest suite (pickling, multiprocessing, Dask), the
# conformance suite's client on it (the suite, the differential tester's roads); the
# same suite on the package installed from its source distribution.
set -euo pipefail
cd "$(dirname "$0")"
# The shared test data (sample roads, maps, oracles' sources) beside the checkout: a plain
# clone's `cargo test` leaves the tests that need it ignored, saying so; this run needs it.
[ -d ../shared/conformance ] && [ -d ../shared/opendrive ] ||
    { echo "test.sh: needs ../shared beside the checkout (the project's test data)" >&2; exit 1; }
# Each group's time, for the test run's budget (40 minutes on 2 cores, .ci/run included).
step() { echo "test.sh: $SECONDS s: $1"; }
# What the later steps install from the registries (the rust-version's toolchain, Python
# environments, npm packages), fetched in the background while the first steps compile;
# the publishing checks wait for it. The wheel's environment is made where cargo cannot be
# found (the wheel must install without it).
version=$(sed -n 's/^version = "\(.*\)"/\1/p' Cargo.toml | head -1)
msrv=$(sed -n 's/^rust-version = "\(.*\)"/\1/p' Cargo.toml)
# The nightly toolchain of the model tests (Miri), pinned.
nightly=nightly-2026-05-20
no_cargo=$(printf '%s' "$PATH" | tr ':' '\n' | grep -v -e cargo -e rustup | paste -sd: -)
venv() {
    local dir=target/$1
    shift
    rm -rf "$dir"
    python3 -m venv "$dir"
    "$dir/bin/pip" install -q --upgrade pip
    "$dir/bin/pip" install -q "$@"
}
environments() {
    rustup toolchain install "$msrv" --profile minimal >/dev/null
    rustup toolchain install "$nightly" --profile minimal --component miri,rust-src >/dev/null
    venv fmu-venv "fmpy>=0.3.20,<0.4" "ecospy>=0.7,<0.8" "libcosimpy>=0.0.6,<0.1" numpy pytest
    venv python-build "maturin[zig]>=1.7,<2"
    env PATH="$no_cargo" sh -c '! command -v cargo >/dev/null'
    (PATH="$no_cargo" && venv python-venv numpy pytest "dask[distributed]" pyproj matplotlib fmpy)
    venv python-sdist-venv numpy pytest
    npm install --silent --no-save --prefix target/tsc "typescript@5" >/dev/null
    npm install --silent --no-save --prefix target/gltf-validator gltf-validator >/dev/null
}
mkdir -p target
environments >target/environments.log 2>&1 &
environments_job=$!
# The oracles of the OpenDRIVE tests, built outside the project while the checks compile:
# libOpenDRIVE (../shared/oracles/build-libopendrive.sh, for the geometry of every road of
# ../shared/opendrive) and the reference C library (../shared/reference/build-references.sh,
# for the CRG records of every mode), each with the small program the tests ask.
odr_oracle=$PWD/target/libopendrive/answers
crg_reference=$PWD/target/crgref/answers
oracles() {
    ../shared/oracles/build-libopendrive.sh "$PWD/target/libopendrive" >/dev/null
    g++ -O2 -std=c++17 -I target/libopendrive/include crates/opencrg-odr/tests/oracle/libopendrive_answers.cpp \
        -L target/libopendrive/lib -lOpenDrive -lpugixml -o "$odr_oracle"
    ../shared/reference/build-references.sh "$PWD/target/crgref" >/dev/null
    cc -O2 -I target/crgref/up crates/opencrg-odr/tests/oracle/crg_reference_answers.c target/crgref/up/libOpenCRG.so \
        -lm -Wl,-rpath,"$PWD/target/crgref/up" -o "$crg_reference"
}
oracles >target/oracles.log 2>&1 &
oracles_job=$!
cargo fmt --all --check
cargo clippy --workspace --all-targets -- -D warnings
RUSTDOCFLAGS="-D warnings" cargo doc --workspace --no-deps
step "Rust tests"
# Every test, with the ones that read ../shared (ignored in a plain clone) and those that
# ask the oracles, each in its own process and the test programs side by side
# (cargo-nextest; .config/nextest.toml prints what the oracles' tests measured). Then the
# doctests (the README's among them).
wait "$oracles_job" || { cat target/oracles.log; echo "test.sh: building the oracles failed" >&2; exit 1; }
OPENCRG_ODR_ORACLE="$odr_oracle" OPENCRG_CRG_REFERENCE="$crg_reference" \
    cargo nextest run --workspace --run-ignored all --status-level fail --final-status-level slow
cargo test --workspace --doc
# The maps' wheel queries, the FMU's answers and the files the toolkit writes once more
# with every binary road read in place (the maps' CRG files are KDBI): the answers they
# check must not change.
OPENCRG_IN_PLACE=always cargo nextest run --workspace --run-ignored all \
    -E 'binary(=ground) | binary(=answers) | binary(=official_rules)' --status-level fail
step "publishing checks"
wait "$environments_job" || { cat target/environments.log; echo "test.sh: fetching the environments failed" >&2; exit 1; }
# Ready to publish: the workspace's crates depended on at the workspace's version; the
# rust-version true (the workspace's libraries and programs check with that toolchain,
# installed by rustup); every
# publishable crate packaged and built from its .crate alone, in dependency order.
if grep -E '^opencrg[-a-z]* = .*version = ' Cargo.toml | grep -v "version = \"$version\""; then
    echo "the workspace's crates must be depended on at version $version" >&2
    exit 1
fi
cargo "+$msrv" check -q --workspace --lib --bins --locked --target-dir target/msrv
# cargo takes a registry crate of a given version to be the same forever: it unpacks each
# packaged crate into CARGO_HOME once per version and reuses what it built from it, so
# the copies and builds an earlier run of the same version left go first.
find "${CARGO_HOME:-$HOME/.cargo}/registry/src" -mindepth 2 -maxdepth 2 -path '*/-*/opencrg-*' -exec rm -rf {} +
cargo clean -q -p opencrg-core -p opencrg-odr -p opencrg-fmu -p opencrg-tools -p opencrg-sys -p opencrg-cli
cargo package -q --locked --allow-dirty -p opencrg-core -p opencrg-odr -p opencrg-fmu -p opencrg-tools -p opencrg-sys -p opencrg-cli
step "model tests"
# The contact points' owner path (opencrg-sys: owner, barrier, thread_id) under Miri, its
# data race detector and weak memory emulation over 4 schedules of the threads (seeds;
# barrier.rs says how the process-wide barrier is modelled). Without the owner's side of
# the barrier, seed 3 finds two threads in one contact point.
MIRIFLAGS="-Zmiri-many-seeds=0..4" cargo "+$nightly" miri test -p opencrg-sys --lib -- owner:: thread_id::
step "fuzzing"
# Every fuzz target for 10 s from its seeds (stable toolchain, under 4 GB of address space).
fuzz/run.sh 10
step "C tests"
# The npm package's build (packaging/wasm.sh, in a target folder of its own) runs from
# here on beside the native builds and tests: it needs none of them.
CARGO_TARGET_DIR="$PWD/target/build-wasm" packaging/wasm.sh target/wasm-dist >target/wasm-build.log 2>&1 &
wasm_build=$!
cargo build --release -p opencrg-capi -p opencrg-cli -p opencrg-fmi
# The instructions of the hot calls (path, u/v, map wheel, loading) against the baseline
# kept in c-tests/instructions: a change that adds work to one fails here.
c-tests/instructions/run.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j"$(nproc)"
# The differential tester's roads as a conformance suite with the Linux library's answers
# (c-tests/generated), for the other platforms and the npm package below.
rm -rf target/generated-suite
for profile in current 2.0.1; do
    CONFORMANCE_PROFILE=$profile c-tests/generated/make_suite.sh target/generated-suite target/release/libopencrg.so
done
# The other platforms (Windows, Arm) and the Linux archive side by side, each cargo build
# in a target folder of its own (in one folder they would take turns on cargo's lock): a
# release build's link-time optimisation runs on one core, and the emulated tests on one.
CARGO_TARGET_DIR="$PWD/target/build-arm" c-tests/cross/run.sh arm >target/cross-arm.log 2>&1 &
arm=$!
CARGO_TARGET_DIR="$PWD/target/build-linux" c-tests/cross/run.sh linux >target/cross-linux.log 2>&1 &
linux=$!
c-tests/cross/run.sh windows
for platform in arm linux; do
    wait "${!platform}" || { cat "target/cross-$platform.log"; exit 1; }
    cat "target/cross-$platform.log"
done
# The Python wheel (tested in its step below) built from here on, while the FMU and
# WebAssembly steps run on one core: manylinux2014 (glibc 2.17), abi3, linked by zig, in
# a target folder of its own (the WebAssembly step's cargo calls need the workspace's).
# It carries the Linux archive's FMU binary for write_fmu.
wheel_build() {
    rm -f target/wheels/opencrg-*.whl
    local fmu_binaries=crates/opencrg-python/python/opencrg/fmu
    rm -rf "$fmu_binaries"
    mkdir -p "$fmu_binaries/x86_64-linux"
    cp "target/dist/opencrg-$version-linux-x86_64/lib/opencrg/fmu/x86_64-linux/libopencrg_fmi.so" "$fmu_binaries/x86_64-linux/"
    # (maturin finds zig through the `python` first on PATH: the build environment's.)
    env PATH="$PWD/target/python-build/bin:$PATH" CARGO_TARGET_DIR="$PWD/target/build-wheel" \
        maturin build -q --release --zig -m crates/opencrg-python/Cargo.toml --out target/wheels
    rm -rf "$fmu_binaries"
}
wheel_build >target/wheel-build.log 2>&1 &
wheel_job=$!
step "FMU"
# The FMUs as users drive them: FMPy (from PyPI) validates and simulates FMUs of a CRG
# file and of shared maps with CRG records in every mode, FMI 2 and 3, co-simulation and
# model exchange, against the C API and `opencrg odr eval` to the bit; ECOS (FMI 2 and 3)
# and libcosim (FMI 2) run an FMU of a CRG file and one of a map in one system (the C
# host of c-tests/fmu drove each platform's binary in the cross runs above).
OPENCRG_CLI="$PWD/target/release/opencrg" OPENCRG_LIB="$PWD/target/release/libopencrg.so" \
    target/fmu-venv/bin/python -m pytest -q -p no:cacheprovider crates/opencrg-fmi/tests/importers
step "WebAssembly"
# The npm package and the web page (packaging/wasm.sh): the conformance suite's client in
# JavaScript in both profiles, the API, a shared map with CRG records in every mode
# against `opencrg odr eval`, the guide's example, in Node; the page in headless Chromium
# (probes of a road and a map as the command answers, the top view drawn).
cargo clippy -q -p opencrg-wasm --target wasm32-unknown-unknown -- -D warnings
# The WebAssembly build takes the toolkit without its FMU and point-cloud wings.
if cargo tree -q -p opencrg-wasm --target wasm32-unknown-unknown -e normal --prefix none |
    grep -E '^(zip|flate2|las|laz|spade|opencrg-fmu) v'; then
    echo "the WebAssembly build pulls the crates above" >&2
    exit 1
fi
wait "$wasm_build" || { cat target/wasm-build.log; exit 1; }
cat target/wasm-build.log
# Node runs the package's tests without V8's background tasks: Node 20 may wait forever
# at exit for a background task it counts as outstanding (nodejs/node#54918; seen here
# after a test had printed its result), and a hang still fails within the timeout.
js() { timeout 900 node --single-threaded "$@"; }
for profile in current 2.0.1; do
    golden=golden; [ $profile = current ] || golden=golden-$profile
    js packaging/npm/test/conformance.mjs target/wasm-dist/package ../shared/conformance target/wasm-conformance-$profile $profile
    result=$(python3 ../shared/conformance/compare.py ../shared/conformance/$golden target/wasm-conformance-$profile | tail -1)
    echo "npm package, conformance ($profile profile): $result"
    [ "$result" = "232 passed, 0 failed" ]
done
# The differential tester's roads (150 of them: loops, arcs, border mode none, moved
# reference points) in the conformance client's order against the Linux library's
# answers, to the last bit. The WebAssembly build computes sines, cosines and arc
# tangents with the portable functions (base/portable_math.rs), which glibc rounds
# otherwise at about one argument in 700: the cases this leaves differing are counted in
# c-tests/generated/allowed.txt; more fail.
for profile in current 2.0.1; do
    golden=golden; [ $profile = current ] || golden=golden-$profile
    allowed=$(sed -n "s/^$profile //p" c-tests/generated/allowed.txt)
    js packaging/npm/test/conformance.mjs target/wasm-dist/package target/generated-suite target/wasm-generated-$profile $profile
    echo "npm package, generated roads ($profile profile): $(python3 ../shared/conformance/compare.py \
        target/generated-suite/$golden target/wasm-generated-$profile | tail -1) within the suite's tolerance;" \
        "to the bit: $(python3 c-tests/generated/same_bits.py target/generated-suite/$golden target/wasm-generated-$profile $allowed | tail -1)"
    python3 c-tests/generated/same_bits.py target/generated-suite/$golden target/wasm-generated-$profile $allowed >/dev/null
done
OPENCRG_CLI="$PWD/target/release/opencrg" js packaging/npm/test/api.mjs target/wasm-dist/package examples/data
# The package's types against a program using every documented call (TypeScript from the
# npm registry), compiled beside the package's index.d.ts.
cp packaging/npm/test/types.ts target/wasm-dist/package/types_check.ts
(cd target/wasm-dist/package && ../../tsc/node_modules/.bin/tsc --strict --noEmit --module nodenext \
    --moduleResolution nodenext --target es2022 types_check.ts && rm types_check.ts)
echo "npm package types: every documented call type-checks (tsc --strict)"
OPENCRG_CLI="$PWD/target/release/opencrg" js packaging/npm/test/map.mjs target/wasm-dist/package ../shared/opendrive target/wasm-maps
js packaging/npm/test/guide.mjs target/wasm-dist/package . target/wasm-guide
python3 packaging/web/test_page.py target/wasm-dist/web target/release/opencrg examples/data
step "glTF and views"
# The .glb export of the demo road (curved, sloped, banked), whole, a part and simplified,
# and of the demo map (the demo road laid on a road of an OpenDRIVE map), against the
# Khronos glTF validator, from the npm registry.
target/release/opencrg export examples/data/demo_road.crg target/demo_road.glb
target/release/opencrg export examples/data/demo_road.crg target/demo_part.glb --u 30:60 --v -1:2
target/release/opencrg export examples/data/demo_road.crg target/demo_simple.glb --max-error 0.002
target/release/opencrg odr export examples/data/demo_map.xodr target/demo_map.glb
target/release/opencrg odr export examples/data/demo_map.xodr target/demo_map_simple.glb --max-error 0.005
NODE_PATH=target/gltf-validator/node_modules node crates/opencrg-cli/tests/validate_glb.js target/demo_road.glb \
    target/demo_part.glb target/demo_simple.glb target/demo_map.glb target/demo_map_simple.glb
# The README's georeferenced road: its start in WGS 84 and its GeoJSON (valid JSON, the
# reference line's first position that start).
target/release/opencrg info examples/data/demo_road_utm.crg --json >target/demo_road_utm.json
target/release/opencrg export examples/data/demo_road_utm.crg target/demo_road_utm.geojson
python3 - <<'PY'
import json
start = json.load(open("target/demo_road_utm.json"))["wgs84"]["start"]
line = json.load(open("target/demo_road_utm.geojson"))["features"][0]["geometry"]["coordinates"]
assert start["from"] == "map projection" and abs(start["lat"] - 48.02331) < 1e-4, start
assert abs(line[0][0] - start["lon"]) < 1e-12 and abs(line[0][1] - start["lat"]) < 1e-12, line[0]
print("georeferenced demo road: start", start["lat"], start["lon"])
PY
# The 3D view of the demo road in headless Chromium (software WebGL), checked on a screenshot.
target/release/opencrg view examples/data/demo_road.crg target/demo_view.html
rm -rf target/chromium-profile target/demo_view.png
timeout 120 chromium --headless --no-sandbox --disable-gpu --use-angle=swiftshader --enable-unsafe-swiftshader \
    --disable-background-networking --disable-component-update --disable-sync --no-first-run \
    --user-data-dir="$PWD/target/chromium-profile" --window-size=900,600 --virtual-time-budget=3000 \
    --screenshot="$PWD/target/demo_view.png" "file://$PWD/target/demo_view.html" >/dev/null 2>&1
python3 crates/opencrg-cli/tests/check_view.py target/demo_view.png
# The demo map's view: drawn (its CRG record outlined), and the point it reads agrees
# with odr eval.
target/release/opencrg odr view examples/data/demo_map.xodr target/demo_map_view.html
for shot in --screenshot="$PWD/target/demo_map_view.png" --dump-dom; do
    rm -rf target/chromium-profile
    timeout 120 chromium --headless --no-sandbox --disable-gpu --use-angle=swiftshader --enable-unsafe-swiftshader \
        --disable-background-networking --disable-component-update --disable-sync --no-first-run \
        --user-data-dir="$PWD/target/chromium-profile" --window-size=900,600 --virtual-time-budget=3000 \
        "$shot" "file://$PWD/target/demo_map_view.html#probe" >target/demo_map_view.dom 2>/dev/null
done
python3 crates/opencrg-cli/tests/check_view.py target/demo_map_view.png
python3 crates/opencrg-cli/tests/check_odr_view.py target/demo_map_view.dom examples/data/demo_map.xodr target/release/opencrg
step "Python wheel"
# The wheel wheel_build made in the background (see there).
wait "$wheel_job" || { cat target/wheel-build.log; exit 1; }
cat target/wheel-build.log
wheel=$(ls target/wheels/opencrg-*-cp39-abi3-*manylinux_2_17_x86_64*.whl)
# Installed into a fresh environment where cargo cannot be found, and tested there.
env PATH="$no_cargo" target/python-venv/bin/pip install -q "$wheel"
env PATH="$no_cargo" OPENCRG_CLI="$PWD/target/release/opencrg" target/python-venv/bin/python -m pytest -q -p no:logging crates/opencrg-python/tests
# The conformance suite's client on the package (crates/opencrg-python/tests/conformance.py,
# the C client's calls in its order): the suite in both profiles, and the differential
# tester's roads to the last bit (the package computes with glibc, as the Linux library
# does: no case may differ).
for profile in current 2.0.1; do
    golden=golden; [ $profile = current ] || golden=golden-$profile
    env PATH="$no_cargo" target/python-venv/bin/python crates/opencrg-python/tests/conformance.py \
        ../shared/conformance target/python-conformance-$profile $profile
    result=$(python3 ../shared/conformance/compare.py ../shared/conformance/$golden target/python-conformance-$profile | tail -1)
    echo "Python package, conformance ($profile profile): $result"
    [ "$result" = "232 passed, 0 failed" ]
    env PATH="$no_cargo" target/python-venv/bin/python crates/opencrg-python/tests/conformance.py \
        target/generated-suite target/python-generated-$profile $profile
    echo "Python package, generated roads ($profile profile), to the bit:" \
        "$(python3 c-tests/generated/same_bits.py target/generated-suite/$golden target/python-generated-$profile 0 | tail -1)"
    python3 c-tests/generated/same_bits.py target/generated-suite/$golden target/python-generated-$profile 0 >/dev/null
done
step "Python sdist"
# The source distribution as PyPI would serve it: installed into a fresh environment that
# has cargo (a development build, to keep the run short), and the suite's core, toolkit
# and type stub tests run there (the wheel ran the whole suite on the same sources).
rm -f target/sdist/opencrg-*.tar.gz
target/python-build/bin/maturin sdist -m crates/opencrg-python/Cargo.toml --out target/sdist >/dev/null
# (Built where the workspace's development builds are, so the registry crates built for
# them are not built again.)
CARGO_TARGET_DIR="$PWD/target" target/python-sdist-venv/bin/pip install -q --config-settings=build-args="--profile=dev" \
    target/sdist/opencrg-*.tar.gz
# (A package built from source carries no FMU binary: write_fmu takes the archive's.)
OPENCRG_CLI="$PWD/target/release/opencrg" OPENCRG_FMU_BINARIES="$PWD/target/dist/opencrg-$version-linux-x86_64/lib/opencrg/fmu" \
    target/python-sdist-venv/bin/python -m pytest -q -p no:logging crates/opencrg-python/tests/test_opencrg.py \
    crates/opencrg-python/tests/test_tools.py crates/opencrg-python/tests/test_stubs.py
step "done"
