#!/usr/bin/env bash
# Installs, builds and runs the whole test suite: the Release build (with the Python package and its
# pytest suite), the same suite under AddressSanitizer and UndefinedBehaviorSanitizer (the Python
# package too, its interpreter started with the sanitizers' runtime preloaded: python/CMakeLists.txt),
# and a short libFuzzer run of every fuzz target.
# REVOLVE_FUZZ_SECONDS sets the fuzzing time per target (default 15; 0 skips fuzzing).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --test
jobs=$(nproc)

echo "== documentation links"
# Every relative link and image of README.md and docs/ names a file (and heading) that exists.
/usr/bin/python3 scripts/check-links.py

echo "== formatting"
scripts/check-format.sh

echo "== Release build and tests (the Python package's pytest suite among them)"
# Tests and benchmark on explicitly: build/ may have been configured by scripts/main.sh without them.
# The Python package too, so that a missing dependency fails here instead of skipping its tests.
# The test executables' own files are compiled at -O1 with GoogleTest precompiled
# (cmake/TestCode.cmake): 283 CPU-seconds instead of 406 for them under GCC 12 (measured with -j2).
scripts/build.sh -- -DREVOLVE_BUILD_TESTS=ON -DREVOLVE_BUILD_BENCH=ON -DREVOLVE_BUILD_TOOLS=ON -DREVOLVE_BUILD_PYTHON=ON
ctest --test-dir build --output-on-failure --no-tests=error -j"$jobs"
echo "== Release build and tests: ${SECONDS} s so far"

echo "== AddressSanitizer + UndefinedBehaviorSanitizer build and tests"
# clang, with line tables only: the same build under GCC with -O2 -g took 525 s of CI's time, this
# one 190 s (measured on 2 cores); sanitizer reports still name file and line. Its test files get
# -O1 and precompiled GoogleTest too: 30% less compile time (clang 14, five test files sampled).
# Without precompiled headers (cmake/TestCode.cmake): a header a test includes first is compiled
# here as the user's compiler sees it, so a missing #include fails on both Debian releases.
cmake -S . -B build-sanitize -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG" -DREVOLVE_SANITIZE=ON -DREVOLVE_BUILD_BENCH=OFF \
  -DREVOLVE_BUILD_PYTHON=ON -DCMAKE_DISABLE_PRECOMPILE_HEADERS=ON
cmake --build build-sanitize
ctest --test-dir build-sanitize --output-on-failure --no-tests=error -j"$jobs"
echo "== sanitizer build and tests: ${SECONDS} s so far"

seconds=${REVOLVE_FUZZ_SECONDS:-15}
if [[ "$seconds" != 0 ]]; then
  echo "== libFuzzer, ${seconds} s per target"
  tests/fuzz/run.sh "$seconds" build-fuzz
  echo "== fuzzing: ${SECONDS} s so far"
fi
