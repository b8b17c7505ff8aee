#!/usr/bin/env bash
# The main job: install, build, and trace the bundled example (a hollow vase seen by a 48 x 48
# camera) through Embree, writing out/vase_hits.csv.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
mkdir -p out
build/bin/revolve-trace --profile examples/vase.csv --rays examples/vase_rays.csv --out out/vase_hits.csv
awk -F, 'NR > 1 { rays++; hits += $1 } END { printf "traced %d rays: %d hits; wrote out/vase_hits.csv\n", rays, hits }' out/vase_hits.csv
