#!/usr/bin/env bash
# Runs every test: formatting, lints and documentation, the Rust tests (unit,
# integration, header freshness, the opencrg command, doctests incl. the README's), then
# through CTest the C tests (also under the sanitizers and valgrind), the header and
# symbol checks, the CMake consumer project, the conformance suite in both behaviour
# profiles (.so and .a) and the differential tester.
set -euo pipefail
cd "$(dirname "$0")"
cargo fmt --all --check
cargo clippy --workspace --all-targets -- -D warnings
RUSTDOCFLAGS="-D warnings" cargo doc --workspace --no-deps
cargo test --workspace
cargo build --release -p opencrg-sys
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j"$(nproc)"
