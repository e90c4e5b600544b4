#!/usr/bin/env bash
# Builds the C library and the command for Linux, linked by zig against glibc 2.17 (as
# the manylinux2014 wheels are), and packs them as users unpack them anywhere:
#   target/dist/opencrg-VERSION-linux-ARCH.tar.gz   (and the same tree beside it)
#     lib/libopencrg.so.VERSION, .so.MAJOR, .so (and libOpenCRG.so/.a, the reference
#     library's link names), lib/libopencrg.a, include/ (the three headers),
#     lib/cmake/OpenCRG (find_package) and lib/pkgconfig/opencrg.pc, both relocatable,
#     bin/opencrg, lib/opencrg/fmu/ARCH-linux/libopencrg_fmi.so (the binary `opencrg fmu`
#     packs into FMUs), LICENSE
# and checks that no file asks for a glibc symbol newer than GLIBC_2.17.
#   packaging/linux-archive.sh x86_64|aarch64
# Needs: cmake; pip (cargo-zigbuild and zig are installed into target/zig-build);
# rustup target add aarch64-unknown-linux-gnu; for aarch64, binutils-aarch64-linux-gnu.
set -euo pipefail
cd "$(dirname "$0")/.."
arch=${1:?usage: packaging/linux-archive.sh x86_64|aarch64}
case "$arch" in
x86_64) objdump=objdump ;;
aarch64) objdump=aarch64-linux-gnu-objdump ;;
*) echo "linux-archive: unknown architecture $arch (x86_64 or aarch64)" >&2; exit 2 ;;
esac
glibc=2.17
version=$(sed -n 's/^version = "\([0-9.]*\)"$/\1/p' Cargo.toml | head -1)
# (Made once, under a lock: the two architectures' archives may be built at once.)
mkdir -p target
(
    flock 9
    if [ ! -x target/zig-build/bin/cargo-zigbuild ]; then
        python3 -m venv target/zig-build
        target/zig-build/bin/pip install -q --upgrade pip
        target/zig-build/bin/pip install -q "cargo-zigbuild>=0.19,<1" "ziglang>=0.13,<1"
    fi
) 9>target/zig-build.lock
# (cargo-zigbuild finds zig through the `python` first on PATH: the build environment's.)
env PATH="$PWD/target/zig-build/bin:$PATH" cargo zigbuild -q --release --target "$arch-unknown-linux-gnu.$glibc" \
    -p opencrg-capi -p opencrg-cli -p opencrg-fmi
# (cargo builds where CARGO_TARGET_DIR says, if it says.)
built="$(realpath -m "${CARGO_TARGET_DIR:-target}")/$arch-unknown-linux-gnu/release"
name="opencrg-$version-linux-$arch"
stage="$PWD/target/dist/$name"
rm -rf "$stage" "$stage.tar.gz" "target/dist/$name-cmake"
cmake -S . -B "target/dist/$name-cmake" -DOPENCRG_PREBUILT_DIR="$built" -DBUILD_TESTING=OFF \
    -DCMAKE_INSTALL_LIBDIR=lib >/dev/null
cmake --install "target/dist/$name-cmake" --prefix "$stage" >/dev/null
cp LICENSE "$stage/"
mkdir -p "$stage/lib/opencrg/fmu/$arch-linux"
cp "$built/libopencrg_fmi.so" "$stage/lib/opencrg/fmu/$arch-linux/"

# Nothing newer than glibc 2.17 asked for, by the library, the command or the FMU binary.
for file in "$stage/lib/libopencrg.so.$version" "$stage/bin/opencrg" "$stage/lib/opencrg/fmu/$arch-linux/libopencrg_fmi.so"; do
    newest=$("$objdump" -T "$file" | grep -oE 'GLIBC_[0-9]+(\.[0-9]+)+' | sed 's/GLIBC_//' | sort -uV | tail -1)
    if [ -z "$newest" ] || [ "$(printf '%s\n%s\n' "$newest" "$glibc" | sort -V | tail -1)" != "$glibc" ]; then
        echo "linux-archive: $file needs glibc ${newest:-(none found)}, more than $glibc" >&2
        exit 1
    fi
    if "$objdump" -T "$file" | grep -q GLIBC_PRIVATE; then
        echo "linux-archive: $file uses glibc's private symbols" >&2
        exit 1
    fi
    echo "linux-archive: $(basename "$file"): newest glibc symbol version $newest"
done
tar -C target/dist -czf "$stage.tar.gz" "$name"
echo "$stage.tar.gz"
