#!/usr/bin/env bash
# Configures and builds revolve into build/ (Release). Executables land in build/bin/.
# Usage: scripts/build.sh [--target NAME...] [-- CMAKE-OPTION...]
#   With no --target everything configured is built. CMake options given after -- are passed to the
#   configure step (e.g. -DREVOLVE_BUILD_TESTS=ON); without any, an existing build/ keeps the options
#   it was configured with and a new one gets the project's defaults.
set -euo pipefail
cd "$(dirname "$0")/.."
targets=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --target) targets+=(--target "$2"); shift 2 ;;
    --) shift; break ;;
    *) echo "usage: $0 [--target NAME...] [-- CMAKE-OPTION...]" >&2; exit 2 ;;
  esac
done
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release "$@"
cmake --build build "${targets[@]}"
