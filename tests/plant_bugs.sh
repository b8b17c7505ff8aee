#!/usr/bin/env bash
# Plants small, plausible bugs in the kernel's exact boundary rules, one at a time, into a copy of
# the source tree, rebuilds the Release tests there and runs the suite (ctest), reporting which
# tests fail for each plant. A plant that no test catches is a blind spot of the suite: the script
# then exits with status 1. The working tree itself is never modified.
#
# Each plant is a file, an exact code fragment and its replacement. The fragment must occur exactly
# once in the file; otherwise the script stops and says so (the code has moved: update the plant).
#
#   tests/plant_bugs.sh [ctest arguments...]     e.g. tests/plant_bugs.sh -R 'BoundaryRules'
#
# The copy and its build directory persist between runs (REVOLVE_PLANT_DIR, default
# ${TMPDIR:-/tmp}/revolve-plants), so that a run rebuilds only what each plant touches. Tests run
# with their default seeds (REVOLVE_TEST_SEED is unset), so the report is deterministic.
set -euo pipefail

source_dir=$(cd "$(dirname "$0")/.." && pwd)
work=${REVOLVE_PLANT_DIR:-${TMPDIR:-/tmp}/revolve-plants}
copy=$work/src
build=$work/build
jobs=${REVOLVE_PLANT_JOBS:-2}
ctest_args=("$@")
unset REVOLVE_TEST_SEED

# name | file | fragment | replacement
plants=(
  "half-open height rule: a vertex height belongs to no segment|plugin/src/kernel/segment_hits.h|zMin <= ray.oz|zMin < ray.oz"
  "tfar exclusive: a far end exactly on the surface is no hit|plugin/src/kernel/bracketed_roots.h|  if (on.at1) inside1 = !(eInside ? insideE : inside0);|"
  "tnear exclusive: a near end exactly on the surface is no hit|plugin/src/kernel/bracketed_roots.h|  if (on.at0) inside0 = !(eInside ? insideE : inside1);|"
  "apex touch clamped to the bracket as computed|plugin/src/kernel/segment_hits.h|std::max(sLow - widen, lo), std::min(sHigh + widen, hi)|sLow, sHigh"
  "a tangent touch (discriminant 0) misses|plugin/src/kernel/bracketed_roots.h|D >= 0.0 : D < 0.0|D > 0.0 : D < 0.0"
  "a touch from inside (A < 0, discriminant 0) misses|plugin/src/kernel/bracketed_roots.h|D >= 0.0 : D < 0.0|D >= 0.0 : D <= 0.0"
  "curve leaf, horizontal rays: an end exactly on the wall is no hit|plugin/src/kernel/curve_hits.h|EndsOnSurface{rho2Lo == R2, rho2Hi == R2}|EndsOnSurface{}"
  "packet u not wrapped below 1|plugin/src/util/azimuth.h|  for (int lane = 0; lane < kLanes; ++lane) u[lane] = u[lane] < 1.0f ? u[lane] : 0.0f;|"
  "single-ray set-up: tfar not scaled by the direction's length|plugin/src/kernel/meridian_ray.h|std::min((double(ray.tfar) - tCentre) * length, w)|std::min(double(ray.tfar) - tCentre, w)"
  "packet set-up: tfar not scaled by the direction's length|plugin/src/kernel/meridian_rays.h|minOf((tfar - tCentre) * length, w)|minOf(tfar - tCentre, w)"
)

fail() {
  echo "plant_bugs.sh: $*" >&2
  exit 1
}

# Lists the tree's files (not its builds, outputs or git data), NUL-separated, relative to $1.
tree_files() {
  (cd "$1" && find . \( -path ./.git -o -path './build*' -o -path ./out -o -path ./.cache \) -prune -o -type f -print0)
}

# Brings the copy to the working tree's files. Only files that differ are rewritten, and they get a
# new modification time (never the original's, which may be older than the copy's objects built
# from a plant), so the build stays incremental and never stale.
sync_copy() {
  local file
  mkdir -p "$copy"
  while IFS= read -r -d '' file; do
    if ! cmp -s "$source_dir/$file" "$copy/$file"; then
      mkdir -p "$(dirname "$copy/$file")"
      cp "$source_dir/$file" "$copy/$file"
    fi
  done < <(tree_files "$source_dir")
  while IFS= read -r -d '' file; do
    [[ -e "$source_dir/$file" ]] || rm "$copy/$file"
  done < <(tree_files "$copy")
}

# replace FILE FRAGMENT REPLACEMENT: the one occurrence of FRAGMENT in FILE, literally.
replace() {
  local file=$1 fragment=$2 replacement=$3 content rest count
  [[ -f "$file" ]] || fail "$file does not exist"
  IFS= read -r -d '' content <"$file" || true
  rest=${content//"$fragment"/}
  count=$(((${#content} - ${#rest}) / ${#fragment}))
  [[ $count == 1 ]] || fail "'$fragment' occurs $count times in ${file#"$copy"/} (expected exactly once): update the plant"
  printf '%s' "${content/"$fragment"/"$replacement"}" >"$file"
}

# Builds the copy and runs ctest; prints the names of the failing tests, one a line.
build_and_test() {
  local log=$1
  cmake --build "$build" -j"$jobs" >"$log.build" 2>&1 || fail "the build failed: see $log.build"
  (cd "$build" && ctest --no-tests=error -j"$jobs" "${ctest_args[@]}" >"$log" 2>&1) || true
  grep -q "tests passed" "$log" || fail "ctest did not finish: see $log"
  sed -n '/The following tests FAILED:/,$p' "$log" | sed -nE 's/^[[:space:]]*[0-9]+ - (.*) \([^()]*\)$/\1/p' |
    sed -E 's/ +# GetParam\(\) = .*//'
}

# Every fragment is checked before anything is built.
sync_copy
for plant in "${plants[@]}"; do
  IFS='|' read -r name file fragment replacement <<<"$plant"
  cp "$copy/$file" "$work/check"
  replace "$work/check" "$fragment" "$replacement"
done
rm -f "$work/check"

cmake -S "$copy" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DREVOLVE_BUILD_TESTS=ON -DREVOLVE_BUILD_BENCH=ON \
  -DREVOLVE_BUILD_TOOLS=ON >"$work/configure.log" 2>&1 || fail "configuring failed: see $work/configure.log"

echo "== unplanted: every test must pass"
failed=$(build_and_test "$work/unplanted.log")
[[ -z "$failed" ]] || fail "the unplanted copy fails: $failed (see $work/unplanted.log)"
echo "   all pass"

uncaught=0
index=0
for plant in "${plants[@]}"; do
  index=$((index + 1))
  IFS='|' read -r name file fragment replacement <<<"$plant"
  sync_copy
  replace "$copy/$file" "$fragment" "$replacement"
  echo "== plant $index: $name"
  echo "   $file: '$fragment' -> '$replacement'"
  failed=$(build_and_test "$work/plant-$index.log")
  if [[ -z "$failed" ]]; then
    echo "   NOT CAUGHT: every test passes"
    uncaught=$((uncaught + 1))
  else
    echo "   caught by $(wc -l <<<"$failed") tests:"
    sed 's/^/     /' <<<"$failed"
  fi
done
sync_copy  # leave the copy unplanted

if ((uncaught > 0)); then
  echo "$uncaught of ${#plants[@]} plants were not caught" >&2
  exit 1
fi
echo "all ${#plants[@]} plants caught"
