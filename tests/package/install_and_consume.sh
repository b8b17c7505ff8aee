#!/usr/bin/env bash
# Installs the built library into a fresh prefix, then configures, builds and runs separate
# projects that find it with find_package(revolve), as a user's project does: the minimal consumer
# here and the README's example program (examples/library), so that neither can rot.
# Usage: install_and_consume.sh <build-dir> <scratch-dir> <project-dir>...
set -euo pipefail
build=$1 scratch=$2
shift 2
rm -rf "$scratch"
cmake --install "$build" --prefix "$scratch/prefix" >/dev/null
for project in "$@"; do
  name=$(basename "$project")
  cmake -S "$project" -B "$scratch/$name" -G Ninja -DCMAKE_PREFIX_PATH="$scratch/prefix" >/dev/null
  cmake --build "$scratch/$name" >/dev/null
  # Each project builds one executable; run it.
  program=$(find "$scratch/$name" -maxdepth 1 -type f -executable | head -n 1)
  echo "== $name: $program"
  "$program"
done
