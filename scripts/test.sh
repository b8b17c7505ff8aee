#!/usr/bin/env bash
# Installs, builds and runs the whole test suite: the Release build, the same suite under
# AddressSanitizer and UndefinedBehaviorSanitizer, and a short libFuzzer run of every fuzz target.
# REVOLVE_FUZZ_SECONDS sets the fuzzing time per target (default 45; 0 skips fuzzing).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --test
jobs=$(nproc)

echo "== Release build and tests"
scripts/build.sh
ctest --test-dir build --output-on-failure -j"$jobs"

echo "== AddressSanitizer + UndefinedBehaviorSanitizer build and tests"
cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DREVOLVE_SANITIZE=ON -DREVOLVE_BUILD_BENCH=OFF
cmake --build build-sanitize
ctest --test-dir build-sanitize --output-on-failure -j"$jobs"

seconds=${REVOLVE_FUZZ_SECONDS:-45}
if [[ "$seconds" != 0 ]]; then
  echo "== libFuzzer, ${seconds} s per target"
  tests/fuzz/run.sh "$seconds" build-fuzz
fi
