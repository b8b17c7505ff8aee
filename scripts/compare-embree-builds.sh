#!/usr/bin/env bash
# Compares this build's answers with another build's, against another Embree (.ci/run: Debian 12's
# Embree 3.13 and Debian 13's Embree 4.3): every hit of the benchmark's rays (revolve-embree-answers)
# and the patio image scripts/main.sh rendered.
#
# Usage: scripts/compare-embree-builds.sh DIR [OTHER-DIR]
#   Writes this build's answers and out/patio.png into DIR; with OTHER-DIR (another build's DIR),
#   also compares: revolve's hits must agree bit for bit, and the two patio images must differ by
#   less than a tenth of the renderer's own noise (the mean difference between two seeds).
# Needs build/ (or $REVOLVE_BUILD_DIR) with revolve-embree-answers and revolve-render, and
# out/patio.png (scripts/main.sh and scripts/test.sh make them).
set -euo pipefail
cd "$(dirname "$0")/.."
if [[ $# -lt 1 || $# -gt 2 ]]; then
  echo "usage: $0 DIR [OTHER-DIR]" >&2
  exit 2
fi
here=$1 other=${2:-}
bin=${REVOLVE_BUILD_DIR:-build}/bin
mkdir -p "$here"
"$bin"/revolve-embree-answers write "$here/answers.csv"
cp out/patio.png "$here/patio.png"
[[ -z "$other" ]] && exit 0

echo "== revolve's answers: $other against $here"
"$bin"/revolve-embree-answers compare "$other/answers.csv" "$here/answers.csv"

echo "== the patio image: $other against $here"
# idiff -v prints the mean error even of identical images (and fails on any difference: ignored).
mean_error() { { idiff -v -a "$1" "$2" 2>&1 || true; } | sed -n 's/.*Mean error = \([0-9.e+-]*\).*/\1/p' | head -n 1; }
between_builds=$(mean_error "$other/patio.png" "$here/patio.png")
"$bin"/revolve-render scenes/patio.json -o out/patio-seed2.png --seed 2 >/dev/null
between_seeds=$(mean_error "$here/patio.png" out/patio-seed2.png)
if [[ -z "$between_builds" || -z "$between_seeds" ]]; then
  echo "$0: idiff gave no mean error" >&2
  exit 1
fi
echo "mean difference between the builds: $between_builds; between seeds 1 and 2 (the noise): $between_seeds"
if ! awk -v b="$between_builds" -v s="$between_seeds" 'BEGIN { exit !(b <= s / 10) }'; then
  echo "$0: the two builds' patio images differ by more than a tenth of the renderer's noise" >&2
  exit 1
fi
