#!/usr/bin/env bash
# Runs every test: formatting and lints, the Rust tests (unit, integration, header
# freshness), then through CTest the C tests, the same under valgrind, the CMake
# consumer project and the conformance suite (.so and .a).
set -euo pipefail
cd "$(dirname "$0")"
cargo fmt --all --check
cargo clippy --workspace --all-targets -- -D warnings
cargo test --workspace
cargo build --release -p opencrg-sys
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j"$(nproc)"
