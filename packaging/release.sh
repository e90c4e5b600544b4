#!/usr/bin/env bash
# Every artifact of a release into the folder OUT, with SHA256SUMS:
#   opencrg-VERSION-cp39-abi3-manylinux2014_x86_64....whl    the Python wheels (abi3, glibc
#   opencrg-VERSION-cp39-abi3-manylinux2014_aarch64....whl   2.17 and later), linked by zig
#   opencrg-VERSION.tar.gz                                    the Python source distribution
#   opencrg-VERSION-linux-x86_64.tar.gz                       the C library and the command
#   opencrg-VERSION-linux-aarch64.tar.gz                      (glibc 2.17 and later, zig)
#   opencrg-VERSION-windows-x86_64.zip                        the C library and the command
# and tests them: the aarch64 wheel under qemu with Debian's aarch64 Python
# (packaging/test-wheel-aarch64.sh); the Linux archives by c-tests/cross/run.sh linux and
# arm (which build them), the x86-64 wheel and the source distribution by test.sh, the
# Windows zip's tree by c-tests/cross/run.sh windows.
#   packaging/release.sh OUT
# Needs: maturin[zig] (pip), rustup targets aarch64-unknown-linux-gnu and
# x86_64-pc-windows-gnu, Debian's gcc-mingw-w64-x86-64, qemu-user, libc6-arm64-cross.
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
for target in x86_64-unknown-linux-gnu aarch64-unknown-linux-gnu; do
    maturin build -q --release --zig --target "$target" -m crates/opencrg-python/Cargo.toml --out "$out"
done
maturin sdist -m crates/opencrg-python/Cargo.toml --out "$out" >/dev/null
packaging/windows-zip.sh >/dev/null
cp "target/dist/opencrg-$version-windows-x86_64.zip" "$out/"
for platform in linux arm; do
    c-tests/cross/run.sh $platform | tail -1
done
cp "target/dist/opencrg-$version-linux-x86_64.tar.gz" "target/dist/opencrg-$version-linux-aarch64.tar.gz" "$out/"
cargo build -q --release -p opencrg-cli
packaging/test-wheel-aarch64.sh "$(ls "$out"/opencrg-"$version"-cp39-abi3-*aarch64*.whl)"
(cd "$out" && sha256sum opencrg-* >SHA256SUMS)
ls -l "$out"
