#!/usr/bin/env bash
# Builds the npm package `opencrg` (the evaluator and the map crate in WebAssembly) and
# the web page that opens a road or a map in the browser:
#   OUT/opencrg-VERSION.tgz     the package: an ES module (index.js, loading its .wasm
#                               itself: no init call), the .wasm, TypeScript types
#   OUT/package/                the same, unpacked
#   OUT/web/                    the page (index.html and its files, static)
#   packaging/wasm.sh OUT
# Needs: rustup target add wasm32-unknown-unknown; npm; wasm-bindgen's command at the
# version of the crate (installed into target/wasm-bindgen by cargo when missing).
set -euo pipefail
cd "$(dirname "$0")/.."
out=$(realpath -m "${1:?usage: packaging/wasm.sh OUT}")
version=$(sed -n 's/^version = "\([0-9.]*\)"$/\1/p' Cargo.toml | head -1)
bindgen_version=$(sed -n 's/^wasm-bindgen = "=\(.*\)"$/\1/p' crates/opencrg-wasm/Cargo.toml)
bindgen=target/wasm-bindgen/bin/wasm-bindgen
if [ ! -x "$bindgen" ] || [ "$("$bindgen" --version | cut -d' ' -f2)" != "$bindgen_version" ]; then
    # Unoptimised: it builds in well under half the time and writes the same files.
    cargo install -q --debug wasm-bindgen-cli --version "=$bindgen_version" --root target/wasm-bindgen
fi
cargo build -q --release --target wasm32-unknown-unknown -p opencrg-wasm
rm -rf "$out/package" "$out/web" "$out"/opencrg-*.tgz
mkdir -p "$out/package"
"$bindgen" --target web --out-dir "$out/package" --out-name opencrg --no-typescript \
    "${CARGO_TARGET_DIR:-target}/wasm32-unknown-unknown/release/opencrg_wasm.wasm"
cp packaging/npm/index.js packaging/npm/index.d.ts packaging/npm/README.md LICENSE "$out/package/"
sed "s/\"version\": \"0.0.0\"/\"version\": \"$version\"/" packaging/npm/package.json >"$out/package/package.json"
(cd "$out" && npm pack --silent ./package >/dev/null)
# The page: its files and the package beside them.
mkdir -p "$out/web"
cp packaging/web/* "$out/web/"
cp "$out/package/index.js" "$out/package/opencrg.js" "$out/package/opencrg_bg.wasm" "$out/web/"
ls "$out"/opencrg-"$version".tgz
