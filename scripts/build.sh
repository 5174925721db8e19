#!/usr/bin/env bash
# Configures and builds wetbed in Release into ./build (incremental): the targets named
# as arguments (`bash scripts/build.sh wetbed`: the executable alone), else everything
# (the executable and the test programs).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build build -j "$(nproc)" "${targets[@]}"
