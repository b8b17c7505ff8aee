#!/usr/bin/env bash
# Configures and builds revolve into build/ (Release). Executables land in build/bin/.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release "$@"
cmake --build build
