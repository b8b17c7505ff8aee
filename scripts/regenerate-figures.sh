#!/usr/bin/env bash
# Regenerates the figures README.md shows (docs/*.png) from the scenes and the committed benchmark
# results (bench/results/). These are the only commands that write into the repository's tracked
# files; README's examples write under out/.
# Usage: scripts/regenerate-figures.sh [--benchmarks]
#   --benchmarks  first measure again: revolve-bench (about 10 minutes on 2 cores) and
#                 revolve-lidar-bench (about 5), replacing bench/results/; README's tables quote
#                 those files and are then updated by hand. Run it on an otherwise idle machine.
set -euo pipefail
cd "$(dirname "$0")/.."
benchmarks=no
case "${1:-}" in
  "") ;;
  --benchmarks) benchmarks=yes ;;
  *) echo "usage: $0 [--benchmarks]" >&2; exit 2 ;;
esac

scripts/install-deps.sh --test
targets=(--target revolve-render --target revolve-lidar)
[[ $benchmarks == yes ]] && targets+=(--target revolve-bench --target revolve-lidar-bench)
scripts/build.sh "${targets[@]}" -- -DREVOLVE_BUILD_DEMOS=ON -DREVOLVE_BUILD_BENCH=ON
mkdir -p out

if [[ $benchmarks == yes ]]; then
  build/bin/revolve-bench --json bench/results/revolve-bench.json --csv bench/results/revolve-bench.csv \
    | tee bench/results/revolve-bench.txt
  build/bin/revolve-lidar-bench scenes/robot_world.json --poses examples/robot/path.csv \
    --out bench/results/robot/lidar_bench.json
fi

# The patio as scripts/main.sh renders it (README, "revolve-render").
build/bin/revolve-render scenes/patio.json -o docs/patio.png
# A 2-D scan at the corridor's corner (README, "Robot range-finding"); the scan itself goes to out/.
build/bin/revolve-lidar scenes/robot_world.json --sensor examples/robot/lidar_2d.json \
  --poses examples/robot/corner.csv -o out/scan.csv --plot docs/robot_scan.png
# Speed, memory and scaling against error (README, "Performance"), from the committed results.
bench/plot_results.py bench/results/revolve-bench.json docs/
echo "regenerated docs/*.png; look at them before committing"
