#!/usr/bin/env bash
# The C API's tests on another platform: the library built with Rust's cross target, the
# tests with the platform's C compiler, run under its emulator.
#
#   c-tests/cross/run.sh windows   # x86_64-pc-windows-gnu, MinGW-w64, wine; the zip
#   c-tests/cross/run.sh arm       # the linux-aarch64 archive, Debian's cross gcc, qemu
#   c-tests/cross/run.sh linux     # the linux-x86_64 archive (glibc 2.17), natively
#
# Checks: the exported functions against the header; the C tests (API with the shared
# and the static library, threads, extensions, private header, compatibility profile,
# a road read in place whose file is cut short, messages on stderr); the conformance
# suite in both behaviour profiles (../shared) and the differential tester's roads
# (target/generated-suite, when test.sh made it);
# the command's `info` on the project's demo road; the FMU binary through a small FMI
# host (c-tests/fmu); for Windows also the zip's CMake package with MinGW and the MSVC
# import library with lld-link.
set -euo pipefail
# Nothing here reads its input; an emulated program that would waits for nothing.
exec </dev/null
root=$(cd "$(dirname "$0")/../.." && pwd)
platform=${1:?usage: run.sh windows|arm|linux}
cd "$root"
road="$root/examples/data/demo_road.crg"
version=$(sed -n 's/^version = "\([0-9.]*\)"$/\1/p' Cargo.toml | head -1)
work="$root/target/cross-tests/$platform"
rm -rf "$work"
mkdir -p "$work"
strict=(-O2 -Wall -Wextra -Werror -pedantic)
passed=0
ok() {
    passed=$((passed + 1))
    echo "cross $platform: ok ($SECONDS s): $*"
}
need() {
    for tool in "$@"; do
        command -v "$tool" >/dev/null || { echo "cross $platform: $tool not found (.ci/run installs it)" >&2; exit 1; }
    done
}

case "$platform" in
windows)
    need x86_64-w64-mingw32-gcc x86_64-w64-mingw32-objdump wine clang lld-link cmake
    export WINEDEBUG=-all WINEPREFIX="${WINEPREFIX:-$root/target/wineprefix}"
    # A prefix made once, and a server kept up between the many short runs.
    # A prefix made once (waiting until everything its making started has ended), then
    # one server kept up for all the short runs, so that none meets a server on its way
    # out. Its processes get no descriptor of this script's: they outlive single runs.
    if [ ! -d "$WINEPREFIX" ]; then
        wineboot -i </dev/null >/dev/null 2>&1
        wineserver -w </dev/null >/dev/null 2>&1
    fi
    wineserver -k </dev/null >/dev/null 2>&1 || true
    wineserver -p </dev/null >/dev/null 2>&1
    trap 'wineserver -k </dev/null >/dev/null 2>&1 || true' EXIT
    packaging/windows-zip.sh >/dev/null
    tree="$root/target/dist/opencrg-$version-windows-x86_64"
    cc=x86_64-w64-mingw32-gcc
    run=(timeout 600 wine)
    shared="$tree/bin/opencrg.dll"
    link_shared=("$tree/lib/libopencrg.dll.a")
    link_static=("$tree/lib/libopencrg.a" -lkernel32 -lntdll -luserenv -lws2_32 -ldbghelp)
    # winpthreads linked in, so the test programs need no DLL of MinGW's beside them.
    link_threads=(-static -lpthread)
    exe=.exe
    # The command beside a stand-in for a system DLL wine 8 lacks (see bcryptprimitives.c).
    mkdir -p "$work/cli"
    cp "$tree/bin/opencrg.exe" "$work/cli/"
    "$cc" "${strict[@]}" -shared c-tests/cross/bcryptprimitives.c -ladvapi32 -o "$work/cli/bcryptprimitives.dll"
    tool=("${run[@]}" "$work/cli/opencrg.exe")
    cp "$shared" "$work/"
    exported=$(x86_64-w64-mingw32-objdump -p "$shared" | sed -n '/\[Ordinal\/Name Pointer\] Table/,/^$/p' |
        sed -n 's/^\s*\[ *[0-9]*\] \([A-Za-z_0-9]*\)$/\1/p' | sort -u)
    ;;
arm | linux)
    # The Linux archive (packaging/linux-archive.sh: zig, glibc 2.17) as users unpack it.
    if [ "$platform" = arm ]; then
        need aarch64-linux-gnu-gcc aarch64-linux-gnu-nm aarch64-linux-gnu-objdump qemu-aarch64 cmake pkg-config
        arch=aarch64 cc=aarch64-linux-gnu-gcc nm=aarch64-linux-gnu-nm
        run=(timeout 600 qemu-aarch64 -L /usr/aarch64-linux-gnu)
        cmake_cross=(-DCMAKE_SYSTEM_NAME=Linux -DCMAKE_SYSTEM_PROCESSOR=aarch64 -DCMAKE_C_COMPILER=$cc)
    else
        need cc nm objdump cmake pkg-config
        arch=x86_64 cc=cc nm=nm
        run=(timeout 600)
        cmake_cross=()
    fi
    packaging/linux-archive.sh "$arch" | sed "s/^/cross $platform: /"
    tree="$root/target/dist/opencrg-$version-linux-$arch"
    shared="$tree/lib/libopencrg.so.$version"
    link_shared=(-L"$tree/lib" -lopencrg "-Wl,-rpath,$tree/lib")
    link_static=("$tree/lib/libopencrg.a" -lpthread -ldl)
    link_threads=(-lpthread)
    exe=
    tool=("${run[@]}" "$tree/bin/opencrg")
    exported=$("$nm" -D --defined-only "$shared" | awk '{print $3}' | sort -u)
    ;;
*)
    echo "usage: run.sh windows|arm|linux" >&2
    exit 2
    ;;
esac

# The exported functions are exactly the header's.
declared=$(grep -hoE '^[A-Za-z_][A-Za-z_0-9 ]*[ *]+crg[A-Za-z_0-9]*\(' include/crgBaseLib.h include/crgBaseLibPrivate.h include/crgOdr.h | grep -oE 'crg[A-Za-z_0-9]*\($' |
    tr -d '(' | sort -u)
if [ "$exported" != "$declared" ]; then
    diff <(echo "$exported") <(echo "$declared") >&2 || true
    echo "cross $platform: exported functions differ from the header (< exported, > declared)" >&2
    exit 1
fi
ok "exports = the header's $(echo "$declared" | wc -l) functions"

# The C tests.
build() {
    local name=$1 source=$2
    shift 2
    "$cc" "${strict[@]}" -Iinclude -Ic-tests "c-tests/$source" "$@" -lm -o "$work/$name$exe"
}
build test_api test_api.c "${link_shared[@]}"
build test_api_static test_api.c "${link_static[@]}" "${link_threads[@]}"
build test_threads test_threads.c "${link_shared[@]}" "${link_threads[@]}"
build test_extensions test_extensions.c "${link_shared[@]}"
build test_private_header test_private_header.c "${link_shared[@]}"
build test_compat test_compat.c "${link_shared[@]}"
build test_stdout_clean test_stdout_clean.c "${link_shared[@]}"
mkdir -p "$work/out"
(cd "$work" && "${run[@]}" "./test_api$exe" "$road" out "$version") >"$work/api.log" 2>&1 || { cat "$work/api.log"; exit 1; }
ok "$(tail -1 "$work/api.log")"
(cd "$work" && "${run[@]}" "./test_api_static$exe" "$road" out "$version") >"$work/api_static.log" 2>&1 || { cat "$work/api_static.log"; exit 1; }
ok "static library: $(tail -1 "$work/api_static.log")"
for t in threads extensions private_header; do
    (cd "$work" && "${run[@]}" "./test_$t$exe" "$road" out) >"$work/$t.log" 2>&1 || { cat "$work/$t.log"; exit 1; }
    ok "$t: $(tail -1 "$work/$t.log")"
done
(cd "$work" && OPENCRG_COMPAT=2.0 "${run[@]}" "./test_compat$exe" "$road") >"$work/compat.log" 2>&1 || { cat "$work/compat.log"; exit 1; }
ok "$(tail -1 "$work/compat.log")"
# A road read in place whose file is cut short while it is open: the process goes on,
# refusing what was cut off with the file's name. Windows itself refuses to cut short a
# file mapped by a process, so there the file is cut from outside (wine's files are this
# system's), as a device failing to read a page would fail it; elsewhere by the test.
native="$root/target/release/opencrg"
[ -x "$native" ] || { echo "cross $platform: $native not built (cargo build --release -p opencrg-cli)" >&2; exit 1; }
build test_cut_short in_place/test_cut_short.c "${link_shared[@]}"
"$native" resample "$road" "$work/in_place_fine.crg" --u-inc 0.01 --format KRBI >/dev/null
copy="$work/in_place_copy.crg"
rm -f "$copy" "$copy.cut" "${copy}2"
(cd "$work" && "${run[@]}" "./test_cut_short$exe" "$work/in_place_fine.crg" "$copy") >"$work/cut_short.log" 2>&1 &
cut_test=$!
while kill -0 "$cut_test" 2>/dev/null && [ ! -f "$copy.cut" ]; do sleep 0.05; done
if [ -f "$copy.cut" ]; then
    truncate -s $(($(stat -c %s "$copy") / 3)) "$copy"
    rm "$copy.cut"
fi
wait "$cut_test" || { cat "$work/cut_short.log"; exit 1; }
ok "$(tail -1 "$work/cut_short.log")"
runner=$(IFS=';'; echo "${run[*]}")
cmake -DRUNNER="$runner" -DPROGRAM="$work/test_stdout_clean$exe" -DROAD="$road" -P c-tests/stdout_clean.cmake
ok "messages on stderr, the program's output alone on stdout"

# The conformance suite in both profiles: on Windows its client built by the suite's
# script against the DLL; from a Linux archive the client built as users build theirs,
# by a CMake project with find_package(OpenCRG) and with the flags pkg-config gives
# (the suite's script then runs that client: prebuilt-client.sh stands in for its compiler).
conformance="$root/../shared/conformance/run.sh"
[ -f "$conformance" ] || { echo "cross $platform: $conformance not found" >&2; exit 1; }
clients=(library)
if [ "$platform" != windows ]; then
    oracle="$root/../shared/conformance/oracle.c"
    cmake -S c-tests/consumer -B "$work/consumer" "${cmake_cross[@]}" -DCMAKE_PREFIX_PATH="$tree" \
        -DCMAKE_BUILD_TYPE=Release -DORACLE_SOURCE="$oracle" >/dev/null
    cmake --build "$work/consumer" >/dev/null
    for kind in shared static; do
        (cd "$work/consumer" && "${run[@]}" "./consumer_$kind" "$road") | grep -q '^consumer: z' || exit 1
    done
    ok "find_package(OpenCRG) from the archive: OpenCRG::OpenCRG and OpenCRG::OpenCRG_static build and run"
    read -ra pkg_flags <<<"$(PKG_CONFIG_PATH="$tree/lib/pkgconfig" pkg-config --cflags --libs opencrg)"
    "$cc" -O2 -Wall "$oracle" "${pkg_flags[@]}" -lm "-Wl,-rpath,$tree/lib" -o "$work/oracle_pkgconfig"
    clients=("$work/consumer/conformance_client" "$work/oracle_pkgconfig")
fi
# Under an emulator a client now and then dies without answering (seen under wine: no
# output, exit status 1, once in some dozen runs of 464 clients). A profile whose only
# failures are such runs is run once more, saying so; different answers fail at once.
conformance_run() {
    local out="$work/conformance-$1-$2" compiler=$cc
    [ "$3" = library ] || compiler="$root/c-tests/cross/prebuilt-client.sh"
    rm -rf "$out"
    CC=$compiler PREBUILT_CLIENT=$3 CONFORMANCE_RUNNER="${run[*]}" CONFORMANCE_PROFILE=$1 \
        sh "$conformance" include "$shared" "$out" >"$out.log" 2>&1 || true
    grep -q '^232 passed, 0 failed$' "$out.log"
}
# Both profiles with the first client; the second (the same client built the other way)
# in the current profile.
for client in "${clients[@]}"; do
    how=$(basename "$client")
    profiles=(current)
    [ "$client" != "${clients[0]}" ] || profiles+=(2.0.1)
    for profile in "${profiles[@]}"; do
        out="$work/conformance-$profile-$how"
        if ! conformance_run $profile "$how" "$client"; then
            died=$(grep -l 'the client exited with status' "$out"/*.err 2>/dev/null | wc -l)
            failed=$(grep -c '^FAIL ' "$out.log" || true)
            if [ "$died" -eq 0 ] || [ "$died" -ne "$failed" ]; then
                tail -20 "$out.log"
                exit 1
            fi
            echo "cross $platform: $died client(s) of the $profile profile died under the emulator without answering:" \
                "$(grep -h 'the client exited' "$out"/*.err | head -3 | tr '\n' ' ')- running the profile again"
            conformance_run $profile "$how" "$client" || { tail -20 "$out.log"; exit 1; }
        fi
        ok "conformance ($profile profile, client: $how): $(tail -1 "$out.log")"
    done
done

# The differential tester's roads (c-tests/generated, made by test.sh before these runs),
# current profile, against the Linux library's answers to the bit: with glibc (Linux on
# either processor) in every case, elsewhere but for the cases allowed.txt counts (where
# glibc rounds a sine, cosine or arc tangent otherwise than the portable functions).
generated="$root/target/generated-suite"
if [ -f "$generated/cases.txt" ]; then
    allowed=0
    [ "$platform" != windows ] || allowed=$(sed -n 's/^current //p' c-tests/generated/allowed.txt)
    generated_run() {
        rm -rf "$work/generated"
        CC=$cc CONFORMANCE_RUNNER="${run[*]}" CONFORMANCE_DATA="$generated" \
            sh "$conformance" include "$shared" "$work/generated" >"$work/generated.log" 2>&1 || true
        python3 c-tests/generated/same_bits.py "$generated/golden" "$work/generated" "$allowed" >"$work/generated.bits"
    }
    if ! generated_run; then
        died=$(grep -l 'the client exited with status' "$work/generated"/*.err 2>/dev/null | wc -l)
        [ "$died" -gt 0 ] || { tail -5 "$work/generated.bits"; exit 1; }
        echo "cross $platform: $died client(s) died under the emulator without answering - running the generated roads again"
        generated_run || { tail -5 "$work/generated.bits"; exit 1; }
    fi
    ok "the differential tester's roads: $(tail -1 "$work/generated.bits") (at most $allowed may)"
fi

# The command.
"${tool[@]}" info "$road" >"$work/info.log" 2>&1 || { cat "$work/info.log"; exit 1; }
grep -q 'demo_road' "$work/info.log" || { cat "$work/info.log"; exit 1; }
ok "opencrg info: $(grep -c . "$work/info.log") lines"

if [ "$platform" = windows ]; then
    # The zip's CMake package, found and used by a MinGW project.
    cmake -S c-tests/consumer -B "$work/consumer" -DCMAKE_SYSTEM_NAME=Windows -DCMAKE_C_COMPILER=x86_64-w64-mingw32-gcc \
        -DCMAKE_PREFIX_PATH="$tree" -DCMAKE_BUILD_TYPE=Release >/dev/null
    cmake --build "$work/consumer" >/dev/null
    cp "$tree/bin/opencrg.dll" "$work/consumer/"
    for kind in shared static; do
        (cd "$work/consumer" && "${run[@]}" "./consumer_$kind.exe" "$road") | grep -q '^consumer: z' || exit 1
    done
    ok "find_package(OpenCRG) with MinGW: OpenCRG::OpenCRG and OpenCRG::OpenCRG_static"
    # MSVC's import library, used the way MSVC's linker uses it.
    mkdir -p "$work/msvc"
    clang --target=x86_64-pc-windows-msvc "${strict[@]}" -isystem c-tests/cross/msvc-stub -I"$tree/include" \
        -c c-tests/cross/msvc_link.c -o "$work/msvc/msvc_link.obj"
    lld-link /nologo /entry:opencrg_entry /subsystem:console /nodefaultlib "$work/msvc/msvc_link.obj" "$tree/lib/opencrg.lib" \
        /out:"$work/msvc/msvc_link.exe"
    cp "$tree/bin/opencrg.dll" "$work/msvc/"
    cp "$road" "$work/msvc/road.crg"
    (cd "$work/msvc" && "${run[@]}" ./msvc_link.exe) || { echo "cross windows: msvc_link exited with $?" >&2; exit 1; }
    ok "opencrg.lib linked by lld-link (MSVC's format), the program runs"
fi
# The archive's FMU binary: FMUs of the demo road and the demo map packed with it by the
# native command, unpacked, driven by fmu_host (a small FMI host of the project's own)
# against the native command's answers, to the bit.
c-tests/fmu/expected.sh "$native" "$tree/lib/opencrg/fmu" "$work/fmu"
case "$platform" in
windows) fmu_folder=win64 fmu_ext=dll host_libs=() ;;
arm) fmu_folder=aarch64-linux fmu_ext=so host_libs=(-ldl) ;;
linux) fmu_folder=linux64 fmu_ext=so host_libs=(-ldl) ;;
esac
"$cc" "${strict[@]}" -Ibench c-tests/fmu/fmu_host.c "${link_threads[@]}" "${host_libs[@]}" -lm -o "$work/fmu_host$exe"
"${run[@]}" "$work/fmu_host$exe" "$work/fmu/demo_road/binaries/$fmu_folder/demo_road.$fmu_ext" \
    "$work/fmu/demo_road" "$work/fmu/demo_road.points" "$work/fmu/demo_map" "$work/fmu/demo_map.points" \
    >"$work/fmu.log" 2>&1 || { cat "$work/fmu.log"; exit 1; }
ok "FMU binary: $(tail -1 "$work/fmu.log")"

echo "cross $platform: $passed checks passed"
