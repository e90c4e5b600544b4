#!/usr/bin/env bash
# Tests a 64-bit Arm Linux wheel on an x86-64 machine: Debian's own aarch64 Python
# (bookworm's python3.11, its packages unpacked, not installed) runs under qemu-user with
# the cross C library of Debian's libc6-arm64-cross, numpy, pytest, Dask and pyproj from
# PyPI as aarch64 wheels, and the Python test suite runs on the wheel, but for the three
# tests that start another Python (a multiprocessing pool, a Dask cluster, a child under
# an address-space limit): qemu-user runs one process, and without binfmt_misc the host
# cannot execute the aarch64 interpreter a child would be (Exec format error); and for
# the FMU guide's FMPy example, which test.sh runs on x86-64 (the FMU binary the wheel
# carries is tested by `write_fmu`'s test here and by the C host of the Arm cross run).
#   packaging/test-wheel-aarch64.sh WHEEL
# Needs: root for `dpkg --add-architecture arm64` (once) and apt's index; qemu-user,
# libc6-arm64-cross; pip.
set -euo pipefail
cd "$(dirname "$0")/.."
wheel=$(realpath "$1")
work=target/aarch64-python
rm -rf "$work"
mkdir -p "$work/debs"
if ! dpkg --print-foreign-architectures | grep -qx arm64; then
    dpkg --add-architecture arm64
fi
apt-get update -qq
(
    cd "$work/debs"
    for p in python3.11-minimal libpython3.11-minimal libpython3.11-stdlib libexpat1 zlib1g libffi8 libssl3 \
        libbz2-1.0 liblzma5 libsqlite3-0 libuuid1 libncursesw6 libtinfo6 libreadline8 libdb5.3 libgdbm6 libnsl2 \
        libtirpc3 libcrypt1; do
        apt-get download -qq "$p:arm64" 2>/dev/null
    done
)
for deb in "$work"/debs/*.deb; do
    dpkg -x "$deb" "$work/root"
done
# The C library and its loader from the cross package.
cp -rn /usr/aarch64-linux-gnu/lib/. "$work/root/lib/aarch64-linux-gnu/"
ln -sf aarch64-linux-gnu/ld-linux-aarch64.so.1 "$work/root/lib/ld-linux-aarch64.so.1"
python3 -m pip install -q --target "$work/site" --platform manylinux2014_aarch64 --python-version 3.11 \
    --implementation cp --only-binary=:all: numpy pytest "dask[distributed]" pyproj matplotlib "$wheel"
root=$(realpath "$work/root")
run=(qemu-aarch64 -L "$root" -E "LD_LIBRARY_PATH=$root/lib/aarch64-linux-gnu:$root/usr/lib/aarch64-linux-gnu"
    -E "PYTHONPATH=$(realpath "$work/site")" -E "OPENCRG_CLI=$PWD/target/release/opencrg" "$root/usr/bin/python3.11")
"${run[@]}" -c 'import platform, opencrg; print("aarch64 wheel:", platform.machine(), "Python", platform.python_version(), "opencrg", opencrg.__version__)'
"${run[@]}" -m pytest -q -p no:logging -p no:cacheprovider crates/opencrg-python/tests \
    -k "not with_multiprocessing and not with_dask and not limited_interpreter and not guides_fmpy_example"
