#!/usr/bin/env bash
# Every artifact of a release into the folder OUT, with SHA256SUMS:
#   opencrg-VERSION-cp39-abi3-manylinux2014_x86_64....whl    the Python wheels (abi3, glibc
#   opencrg-VERSION-cp39-abi3-manylinux2014_aarch64....whl   2.17 and later), linked by zig
#   opencrg-VERSION.tar.gz                                    the Python source distribution
#   opencrg-VERSION-linux-x86_64.tar.gz                       the C library and the command
#   opencrg-VERSION-linux-aarch64.tar.gz                      (glibc 2.17 and later, zig)
#   opencrg-VERSION-windows-x86_64.zip                        the C library and the command
# (each archive with the FMU binaries of all three platforms, each wheel with its own's)
#   opencrg-VERSION.tgz                                       the npm package (WebAssembly)
#   opencrg-VERSION-web.zip                                   the web page, static
# and tests them: the aarch64 wheel under qemu with Debian's aarch64 Python
# (packaging/test-wheel-aarch64.sh); the Linux archives by c-tests/cross/run.sh linux and
# arm (which build them), the x86-64 wheel and the source distribution by test.sh, the
# Windows zip's tree by c-tests/cross/run.sh windows.
#   packaging/release.sh OUT
# Needs: maturin[zig] (pip), rustup targets aarch64-unknown-linux-gnu,
# x86_64-pc-windows-gnu and wasm32-unknown-unknown, Debian's gcc-mingw-w64-x86-64,
# qemu-user, libc6-arm64-cross, npm.
set -euo pipefail
cd "$(dirname "$0")/.."
out=$(realpath -m "${1:?usage: packaging/release.sh OUT}")
mkdir -p "$out"
version=$(sed -n 's/^version = "\([0-9.]*\)"$/\1/p' Cargo.toml | head -1)
python3 -m venv target/release-build
target/release-build/bin/pip install -q --upgrade pip
target/release-build/bin/pip install -q "maturin[zig]>=1.7,<2"
export PATH="$PWD/target/release-build/bin:$PATH"
rm -f "$out"/opencrg-*
# The native command first: the cross runs pack FMUs with it.
cargo build -q --release -p opencrg-cli
# The archives, each tested on its platform (building them builds their FMU binaries).
packaging/windows-zip.sh >/dev/null
for platform in linux arm; do
    c-tests/cross/run.sh $platform | tail -1
done
# Every archive carries the FMU binaries of all three platforms, so that its `opencrg fmu`
# writes FMUs for all of them.
trees=("opencrg-$version-linux-x86_64" "opencrg-$version-linux-aarch64" "opencrg-$version-windows-x86_64")
fmu_all=target/dist/fmu-binaries
rm -rf "$fmu_all"
mkdir -p "$fmu_all"
for tree in "${trees[@]}"; do
    cp -r "target/dist/$tree/lib/opencrg/fmu/." "$fmu_all/"
done
for tree in "${trees[@]}"; do
    cp -r "$fmu_all/." "target/dist/$tree/lib/opencrg/fmu/"
done
for tree in "${trees[@]:0:2}"; do
    tar -C target/dist -czf "target/dist/$tree.tar.gz" "$tree"
    cp "target/dist/$tree.tar.gz" "$out/"
done
rm -f "target/dist/${trees[2]}.zip"
(cd target/dist && python3 -m zipfile -c "${trees[2]}.zip" "${trees[2]}")
cp "target/dist/${trees[2]}.zip" "$out/"
# The wheels, each with its platform's FMU binary (for write_fmu); the sdist with none.
fmu_binaries=crates/opencrg-python/python/opencrg/fmu
for arch in x86_64 aarch64; do
    rm -rf "$fmu_binaries"
    mkdir -p "$fmu_binaries"
    cp -r "target/dist/opencrg-$version-linux-$arch/lib/opencrg/fmu/$arch-linux" "$fmu_binaries/"
    maturin build -q --release --zig --target "$arch-unknown-linux-gnu" -m crates/opencrg-python/Cargo.toml --out "$out"
done
rm -rf "$fmu_binaries"
maturin sdist -m crates/opencrg-python/Cargo.toml --out "$out" >/dev/null
# The npm package and the page (tested by test.sh).
packaging/wasm.sh target/wasm-release >/dev/null
cp "target/wasm-release/opencrg-$version.tgz" "$out/"
(cd target/wasm-release && rm -f "opencrg-$version-web.zip" && python3 -m zipfile -c "opencrg-$version-web.zip" web)
cp "target/wasm-release/opencrg-$version-web.zip" "$out/"
packaging/test-wheel-aarch64.sh "$(ls "$out"/opencrg-"$version"-cp39-abi3-*aarch64*.whl)"
(cd "$out" && sha256sum opencrg-* >SHA256SUMS)
ls -l "$out"
