#!/usr/bin/env bash
# Times the MIBIT kernel of an earlier revision against this checkout's, side by side on the
# benchmark's rays: both builds run revolve-kernel-timing (bench/kernel_timing.cpp) alternately,
# ROUNDS times on every test shape, one ray at a time (incoherent rays, rtcIntersect1) and in
# packets (camera rays, rtcIntersect8), and the table gives each configuration's median ns a ray
# and the ratio. CPU time of the timing thread, not wall time, so that a shared machine's waits
# are not charged; still, run it on an otherwise quiet machine.
#
# Usage: scripts/compare-kernels.sh REVISION [ROUNDS] [POINTS]
#   REVISION  any git revision (e.g. b3f246d); it is built in a temporary worktree
#   ROUNDS    alternations (default 3); POINTS  profile points, comma-separated (default 16,64,256,1024,4096)
# Writes the table to stdout and, with the raw timings, to out/compare-kernels-REVISION.txt.
set -euo pipefail
cd "$(dirname "$0")/.."
if [[ $# -lt 1 ]]; then
  echo "usage: $0 REVISION [ROUNDS] [POINTS]" >&2
  exit 2
fi
revision=$1
rounds=${2:-3}
points=${3:-16,64,256,1024,4096}
git rev-parse --verify --quiet "$revision^{commit}" >/dev/null || { echo "$0: $revision: not a revision of this repository" >&2; exit 2; }

work=$(mktemp -d "${TMPDIR:-/tmp}/revolve-compare.XXXXXX")
cleanup() {
  git worktree remove --force "$work/old" >/dev/null 2>&1 || true
  rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

echo "== building $revision (the kernel and the benchmark's library)"
git worktree add -q --detach "$work/old" "$revision"
cmake -S "$work/old" -B "$work/old-build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DREVOLVE_BUILD_TESTS=OFF >/dev/null
cmake --build "$work/old-build" --target revolve revolve_io revolve_bench_lib >/dev/null
# Revisions since the Embree 4 port split the library in two and generate revolve/config.h.
old_libraries=("$work/old-build/plugin/librevolve.a")
[[ -f "$work/old-build/plugin/librevolve_core.a" ]] && old_libraries+=("$work/old-build/plugin/librevolve_core.a")
# Revisions since the platform/ layout keep its geometry (placements) in a library of its own.
[[ -f "$work/old-build/platform/librevolve_geometry.a" ]] &&
  old_libraries=("$work/old-build/platform/librevolve_geometry.a" "${old_libraries[@]}")
embree_major=$(grep -o 'REVOLVE_EMBREE_MAJOR [0-9]' "$work/old-build/plugin/include/revolve/config.h" 2>/dev/null | cut -d' ' -f2)
# This checkout's timing program against the old libraries and headers (copied beside them, since a
# quoted include looks in the source's own folder first): it uses only what every revision's
# benchmark library has.
cp bench/kernel_timing.cpp "$work/old/bench/kernel_timing.cpp"
# The applications' shared code lay in demo/ before it became platform/.
platform=platform
[[ -d "$work/old/platform" ]] || platform=demo
g++ -O2 -std=c++20 -I "$work/old/bench" -I "$work/old/$platform" -I "$work/old/plugin/include" \
  -I "$work/old-build/plugin/include" "$work/old/bench/kernel_timing.cpp" \
  -o "$work/old-timing" "$work/old-build/bench/librevolve_bench_lib.a" "$work/old-build/$platform/librevolve_io.a" \
  "${old_libraries[@]}" "-lembree${embree_major:-3}" -ltbb -lbenchmark -lpthread
echo "== building this checkout"
scripts/build.sh --target revolve-kernel-timing >/dev/null

mkdir -p out
raw="$work/raw.txt"
for ((round = 1; round <= rounds; ++round)); do
  for shape in sphere torus vase goblet bottle; do
    for mode in incoherent camera8; do
      echo "== round $round/$rounds: $shape, $mode" >&2
      "$work/old-timing" "$shape" "$points" "$mode" 5 | sed "s/^/old $mode /" >> "$raw"
      build/bin/revolve-kernel-timing "$shape" "$points" "$mode" 5 | sed "s/^/new $mode /" >> "$raw"
    done
  done
done

report="out/compare-kernels-$revision.txt"
python3 - "$raw" "$revision" "$(git rev-parse --short HEAD)" "$rounds" > "$report" <<'PY'
import collections, statistics, sys
raw, old_name, new_name, rounds = sys.argv[1:5]
times = collections.defaultdict(list)
for line in open(raw):
    build, mode, shape, config, ns = line.split()
    times[(mode, shape, config, build)].append(float(ns))
print(f"MIBIT ns a ray, {old_name} (old) against {new_name} (new): medians of {rounds} alternating runs, "
      "each the median of 5 passes over the benchmark's rays (CPU time, one thread)")
for mode in ("incoherent", "camera8"):
    title = "incoherent rays, rtcIntersect1" if mode == "incoherent" else "camera rays (512 x 512), rtcIntersect8"
    print(f"\n{title}\n{'shape':8} {'config':18} {'old ns':>9} {'new ns':>9} {'old/new':>8}")
    keys = sorted({(s, c) for (m, s, c, b) in times if m == mode},
                  key=lambda k: (k[0], k[1] != "sphere_primitive", int(k[1].split("_")[1]) if k[1].startswith("mibit") else 0))
    for shape, config in keys:
        old = statistics.median(times[(mode, shape, config, "old")])
        new = statistics.median(times[(mode, shape, config, "new")])
        print(f"{shape:8} {config:18} {old:9.1f} {new:9.1f} {old / new:8.2f}")
PY
cat "$report"
echo
echo "raw timings:" >> "$report"
cat "$raw" >> "$report"
echo "wrote $report"
