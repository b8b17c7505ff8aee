#!/usr/bin/env bash
# The main job: install, build, and render the patio scene of Baciu, Jia & Lam (2001)
# (scenes/patio.json: one hundred surfaces of revolution, path traced under a sun and a sky) to
# out/patio.png.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
# Only the renderer and what it links. A new build/ is configured without the tests and the
# benchmark (whose packages the main job does not install); one that configured successfully before
# (it has build.ninja) keeps its options, so running this after scripts/test.sh leaves the test
# build as it was.
if [[ -f build/build.ninja ]]; then
  scripts/build.sh --target revolve-render
else
  scripts/build.sh --target revolve-render -- -DREVOLVE_BUILD_TESTS=OFF -DREVOLVE_BUILD_BENCH=OFF
fi
mkdir -p out
build/bin/revolve-render scenes/patio.json -o out/patio.png --stats out/patio_stats.json
echo "wrote out/patio.png ($(grep -o '"render_seconds": [0-9.]*' out/patio_stats.json | cut -d' ' -f2) s of rendering)"
