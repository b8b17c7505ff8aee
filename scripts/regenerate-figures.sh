#!/usr/bin/env bash
# Regenerates the figures README.md shows (docs/*.png) from the scenes and the committed benchmark
# results (bench/results/). These are the only commands that write into the repository's tracked
# files; README's examples write under out/.
# Usage: scripts/regenerate-figures.sh [--benchmarks]
#   --benchmarks  first measure again: revolve-bench (about 14 minutes on 2 cores), revolve-lidar-bench
#                 (about 5), the paper's table and POV-Ray (about 4), replacing bench/results/; README's tables quote
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
targets=(--target revolve-render --target revolve-lidar --target _revolve)
# The OSPRay example where OSPRay 3 is installed (Debian 13: install-deps.sh --test installs it).
ospray=no
if dpkg-query -W -f='${Status}' libospray-dev 2>/dev/null | grep -q "install ok installed"; then
  ospray=yes
  targets+=(--target revolve-ospray-scene)
fi
[[ $benchmarks == yes ]] && targets+=(--target revolve-bench --target revolve-lidar-bench)
scripts/build.sh "${targets[@]}" -- -DREVOLVE_BUILD_TOOLS=ON -DREVOLVE_BUILD_BENCH=ON -DREVOLVE_BUILD_PYTHON=ON
mkdir -p out

if [[ $benchmarks == yes ]]; then
  build/bin/revolve-bench --json bench/results/revolve-bench.json --csv bench/results/revolve-bench.csv \
    | tee bench/results/revolve-bench.txt
  build/bin/revolve-lidar-bench scenes/robot_world.json --poses examples/robot/path.csv \
    --out bench/results/robot/lidar_bench.json
  build/bin/revolve-bench paper-table --json bench/results/paper-table.json | tee bench/results/paper-table.txt
  # POV-Ray beside revolve (README, "Against POV-Ray"); these also draw docs/pov_*.png.
  build/bin/revolve-bench pov --json bench/results/pov-patio.json --figure docs/pov_patio.png | tee bench/results/pov-patio.txt
  build/bin/revolve-bench pov --scene scenes/vessels.json --json bench/results/pov-vessels.json \
    --figure docs/pov_vessels.png | tee bench/results/pov-vessels.txt
  build/bin/revolve-bench pov-scaling --json bench/results/pov-scaling.json | tee bench/results/pov-scaling.txt
  # Scenes of many distinct objects (docs/performance.md): one process a run, about 15 minutes; the
  # million objects built by the library alone need about 10 GB.
  bench/python/scale_ladder.py build/bin/revolve-bench bench/results/scale/scale.json \
    --counts 100,1000,10000,100000,1000000 --runs 3 --mesh-limit-gb 8 --scene-max 100000
fi

# The patio as scripts/main.sh renders it (README, "revolve-render").
build/bin/revolve-render scenes/patio.json -o docs/patio.png
# The still life of spline profiles (README, "revolve-render", "Smooth profiles").
build/bin/revolve-render scenes/spline_still_life.json -o docs/spline_still_life.png
# A 2-D scan at the corridor's corner (README, "Robot range-finding"); the scan itself goes to out/.
build/bin/revolve-lidar scenes/robot_world.json --sensor examples/robot/lidar_2d.json \
  --poses examples/robot/corner.csv -o out/scan.csv --plot docs/robot_scan.png
# The lidar's intensity across a pole and a barrel, exact against meshes (docs/robot.md, "Intensity").
PYTHONPATH=build/python /usr/bin/python3 bench/python/plot_lidar_intensity.py docs/lidar_intensity.png
# A moving sensor's sweep of the corridor beside the same sweep at rest (docs/robot.md, "Time and motion").
PYTHONPATH=build/python /usr/bin/python3 bench/python/plot_lidar_motion.py docs/lidar_motion.png
# A dual-return scan of a pole in front of a wall: two returns where a beam straddles the pole's edge (docs/robot.md).
PYTHONPATH=build/python /usr/bin/python3 bench/python/plot_lidar_returns.py docs/lidar_returns.png
# A robot's camera along the path (docs/robot.md, "Cameras along a path"): its frame at pose 3.
mkdir -p out/frames
build/bin/revolve-render scenes/robot_world.json --camera examples/robot/camera_front.json \
  --poses examples/robot/path.csv -o out/frames/front.png --spp 64
cp out/frames/front_0003.png docs/camera_frame.png
# A ring of 8 sonars along the path, read exactly (docs/robot.md, "Range sensors").
PYTHONPATH=build/python /usr/bin/python3 bench/python/plot_sonar_ring.py docs/sonar_ring.png
# Speed, memory and scaling against error (README, "Performance"), from the committed results.
bench/plot_results.py bench/results/revolve-bench.json docs/
bench/plot_pov_scaling.py bench/results/pov-scaling.json docs/pov_scaling.png
bench/python/plot_scale.py bench/results/scale/scale.json docs/scale_objects.png | tee bench/results/scale/scale.txt
# revolve beside Open3D from Python (docs/python.md), from its committed results; measuring them
# again needs Debian 13's Open3D (bench/python/open3d_compare.py says how).
bench/python/plot_open3d_compare.py bench/results/python/open3d_compare.json docs/open3d_comparison.png
# The patio through OSPRay's scivis renderer with the revolve module, beside docs/patio.png
# (docs/ospray.md); OSPRay finds the module beside libospray as loaded from build/lib.
if [[ $ospray == yes ]]; then
  LD_LIBRARY_PATH="$PWD/build/lib" build/bin/revolve-ospray-scene scenes/patio.json -o docs/ospray_patio.png
else
  echo "docs/ospray_patio.png not regenerated: OSPRay 3 is not installed (Debian 13's libospray-dev)"
fi
echo "regenerated docs/*.png; look at them before committing"
