#!/usr/bin/env bash
# Runs every test: formatting, lints and documentation, the Rust tests (unit,
# integration, header freshness, the opencrg command, doctests incl. the README's), then
# through CTest the C tests (also under the sanitizers and valgrind), the header and
# symbol checks, the CMake consumer project, the conformance suite in both behaviour
# profiles (.so and .a) and the differential tester; last the Python package, installed
# with pip into a virtual environment under target/, and its pytest suite.
set -euo pipefail
cd "$(dirname "$0")"
cargo fmt --all --check
cargo clippy --workspace --all-targets -- -D warnings
RUSTDOCFLAGS="-D warnings" cargo doc --workspace --no-deps
cargo test --workspace
cargo build --release -p opencrg-capi -p opencrg-cli
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j"$(nproc)"
python3 -m venv target/python-venv
target/python-venv/bin/pip install -q --upgrade pip
target/python-venv/bin/pip install -q numpy pytest
target/python-venv/bin/pip install -q crates/opencrg-python
OPENCRG_CLI="$PWD/target/release/opencrg" target/python-venv/bin/python -m pytest -q crates/opencrg-python/tests
