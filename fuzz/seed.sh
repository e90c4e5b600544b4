#!/usr/bin/env bash
# Seeds the fuzzing corpora with the project's own roads: the demo road and small
# generated roads, whole (header target) and as data sections (reader targets).
set -euo pipefail
cd "$(dirname "$0")/.."
cargo run -q --release -p opencrg-tools --example make_fuzz_seeds -- fuzz/corpus
ls fuzz/corpus/* | head -50
