#!/usr/bin/env bash
# Installs the built library into a fresh prefix, then configures, builds and runs a separate
# project that finds it with find_package(revolve): what a user's project does.
# Usage: install_and_consume.sh <build-dir> <consumer-source-dir> <scratch-dir>
set -euo pipefail
build=$1 consumer=$2 scratch=$3
rm -rf "$scratch"
cmake --install "$build" --prefix "$scratch/prefix" >/dev/null
cmake -S "$consumer" -B "$scratch/build" -G Ninja -DCMAKE_PREFIX_PATH="$scratch/prefix" >/dev/null
cmake --build "$scratch/build" >/dev/null
"$scratch/build/consumer"
