#!/usr/bin/env bash
# Builds the library and the command for 64-bit Windows with MinGW-w64 and packs them
# with the header, the import libraries for MinGW and MSVC, a CMake package and the binary
# `opencrg fmu` packs into FMUs (lib/opencrg/fmu/x86_64-windows/opencrg_fmi.dll):
#   target/dist/opencrg-VERSION-windows-x86_64.zip   (and the same tree beside it)
# Needs: rustup target add x86_64-pc-windows-gnu; Debian's gcc-mingw-w64-x86-64 (and
# cmake, for the package's version file).
set -euo pipefail
cd "$(dirname "$0")/.."
target=x86_64-pc-windows-gnu
version=$(sed -n 's/^version = "\([0-9.]*\)"$/\1/p' Cargo.toml | head -1)
cargo build --release --target "$target" -p opencrg-capi -p opencrg-cli -p opencrg-fmi
# (cargo builds where CARGO_TARGET_DIR says, if it says.)
built="${CARGO_TARGET_DIR:-target}/$target/release"
name="opencrg-$version-windows-x86_64"
stage="target/dist/$name"
rm -rf "$stage" "$stage.zip"
mkdir -p "$stage/bin" "$stage/lib/cmake/OpenCRG" "$stage/include"
cp "$built/opencrg.dll" "$built/opencrg.exe" "$stage/bin/"
cp "$built/opencrg.lib" "$built/libopencrg.dll.a" "$built/libopencrg.a" "$built/opencrg.def" "$stage/lib/"
cp include/crgBaseLib.h include/crgBaseLibPrivate.h include/crgOdr.h "$stage/include/"
cp packaging/windows/OpenCRGConfig.cmake "$stage/lib/cmake/OpenCRG/"
cmake -DVERSION="$version" -DCMAKE_SIZEOF_VOID_P=8 -DOUT="$stage/lib/cmake/OpenCRG/OpenCRGConfigVersion.cmake" \
    -P packaging/windows/version.cmake
mkdir -p "$stage/lib/opencrg/fmu/x86_64-windows"
cp "$built/opencrg_fmi.dll" "$stage/lib/opencrg/fmu/x86_64-windows/"
cp LICENSE "$stage/"
(cd target/dist && python3 -m zipfile -c "$name.zip" "$name")
echo "$stage.zip"
