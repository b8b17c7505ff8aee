#!/usr/bin/env bash
# The main job: install, build, and render the paper's patio scene (scenes/patio.json: one hundred
# surfaces of revolution, path traced under a sun and a sky) to out/patio.png.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
mkdir -p out
build/bin/revolve-render scenes/patio.json -o out/patio.png --stats out/patio_stats.json
echo "wrote out/patio.png ($(grep -o '"render_seconds": [0-9.]*' out/patio_stats.json | cut -d' ' -f2) s of rendering)"
