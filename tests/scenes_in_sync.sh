#!/usr/bin/env bash
# The bundled scenes and robot examples (beam patterns too) are their generators' output: run the generators on a
# scratch copy and compare every file they write with the committed one.
# Usage: scenes_in_sync.sh <source-dir> <scratch-dir>
set -euo pipefail
source=$1 scratch=$2
rm -rf "$scratch"
mkdir -p "$scratch/scenes/profiles" "$scratch/examples/robot"
cp "$source/scenes/make_scenes.py" "$source/scenes/make_robot_world.py" "$scratch/scenes/"
cp "$source/examples/robot/make_beam_patterns.py" "$scratch/examples/robot/"
(cd "$scratch" && python3 scenes/make_scenes.py && python3 scenes/make_robot_world.py &&
  python3 examples/robot/make_beam_patterns.py > /dev/null)
status=0
for file in scenes/patio.json scenes/patio_points.json scenes/still_life.json scenes/spline_still_life.json scenes/vessels.json \
            scenes/many.json scenes/robot_world.json scenes/profiles/wine_bottle.csv \
            examples/robot/lidar_2d.json examples/robot/lidar_3d.json examples/robot/path.csv examples/robot/corner.csv \
            examples/robot/vlp16_pattern.csv examples/robot/rosette_pattern.csv; do
  if ! cmp -s "$scratch/$file" "$source/$file"; then
    echo "$file: differs from what its generator writes; run scenes/make_*.py and commit the output" >&2
    status=1
  fi
done
exit $status
