#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (ASan + UBSan) and fuzzes each for a while.
#
# Usage: tests/fuzz/run.sh <seconds-per-target> [build-dir]   (build-dir defaults to build-fuzz/)
#
# Each target starts from a scratch copy of its committed seed corpus (corpus/<target>), so runs
# never grow the committed corpus. Exits non-zero if any target finds a crash, a sanitizer report,
# a broken check, a timeout or an out-of-memory; the input is saved as
# <build-dir>/fuzz-artifacts/<target>/crash-* (or timeout-*, oom-*) and the log beside it.
set -euo pipefail

if [[ $# -lt 1 || ! $1 =~ ^[0-9]+$ ]]; then
  echo "usage: $0 <seconds-per-target> [build-dir]" >&2
  exit 2
fi
seconds=$1
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=$(realpath -m "${2:-$root/build-fuzz}")

# Line tables only, as the sanitizer build of scripts/test.sh: reports still name file and line, and
# a library file compiled in 7.4 CPU seconds instead of 9.7 with full debug information.
cmake -S "$root" -B "$build" -G Ninja \
  -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG" -DREVOLVE_FUZZ=ON -DREVOLVE_BUILD_TESTS=OFF -DREVOLVE_BUILD_BENCH=OFF -DREVOLVE_BUILD_TOOLS=ON
cmake --build "$build" --target fuzz_profile_csv fuzz_rays_csv fuzz_profile_points fuzz_spline_points fuzz_scene_json fuzz_sensor_json \
  fuzz_poses_csv
# Regressions first: every seed and every saved finding, once each.
ctest --test-dir "$build" --output-on-failure
if [[ $seconds -eq 0 ]]; then  # build and replay only (libFuzzer reads -max_total_time=0 as "no limit")
  exit 0
fi

# Input caps: a profile CSV line is at least 4 bytes ("1,2\n"), so 2048 bytes is at most ~500
# points (and 128 raw double points); 1024 bytes of spline points, at most 63 raw or 511 grid
# points (the curve's self-intersection check subdivides parts); rays are parsed only; a scene of 4096 bytes holds profiles of
# at most ~500 points; sensor files and poses are parsed only (beam angles up to 4096). Any input
# taking over 10 s or 2 GB is
# itself a finding (the work per input is O(n log n) in the points).
declare -A max_len=([fuzz_profile_csv]=2048 [fuzz_rays_csv]=4096 [fuzz_profile_points]=2048 [fuzz_spline_points]=1024
                   [fuzz_scene_json]=4096
                   [fuzz_sensor_json]=4096 [fuzz_poses_csv]=4096)

# The robot inputs' readers only parse, and their coverage stops growing within seconds (measured:
# the sensor file 1,345 edges after 15 s and 1,363 after 40 s; poses 283 after both), so they get
# a third of the time each.
declare -A time_share=([fuzz_sensor_json]=3 [fuzz_poses_csv]=3)

export ASAN_OPTIONS=${ASAN_OPTIONS:-abort_on_error=0:detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# One target: a scratch copy of its corpus, its time, its own log; the verdict in $scratch/<target>.ok.
fuzz_target() {
  local target=$1
  local corpus="$scratch/$target" artifacts="$build/fuzz-artifacts/$target"
  mkdir -p "$corpus" "$artifacts"
  cp "$here/corpus/$target/"* "$corpus/"
  local dictionary=()
  [[ -f "$here/$target.dict" ]] && dictionary=(-dict="$here/$target.dict")
  local target_seconds=$(( seconds / ${time_share[$target]:-1} ))
  (( target_seconds >= 1 )) || target_seconds=1
  if "$build/bin/$target" "$corpus" "${dictionary[@]}" \
      -max_total_time="$target_seconds" -max_len="${max_len[$target]}" -timeout=10 -rss_limit_mb=2048 \
      -artifact_prefix="$artifacts/" -print_final_stats=1 2> "$artifacts/log.txt"; then
    touch "$scratch/$target.ok"
  fi
}

# Each libFuzzer process uses one core: as many targets at a time as there are cores, so that the
# stage takes the time of one target per core rather than the sum (each still gets its full time).
targets=(fuzz_profile_csv fuzz_rays_csv fuzz_profile_points fuzz_spline_points fuzz_scene_json fuzz_sensor_json fuzz_poses_csv)
parallel=$(nproc)
running=0
for target in "${targets[@]}"; do
  if (( running >= parallel )); then
    wait -n || true  # a target's verdict is its .ok file
    running=$((running - 1))
  fi
  echo "== $target: $(( seconds / ${time_share[$target]:-1} ))s, max_len ${max_len[$target]}"
  fuzz_target "$target" &
  running=$((running + 1))
done
wait

failed=()
for target in "${targets[@]}"; do
  log="$build/fuzz-artifacts/$target/log.txt"
  echo "== $target"
  if [[ -f "$scratch/$target.ok" ]]; then
    grep -E "DONE +cov:|^stat::(number_of_executed_units|average_exec_per_sec|peak_rss_mb)" "$log" || true
  else
    failed+=("$target")
    echo "!! $target failed; last lines of $log:"
    tail -n 40 "$log"
  fi
done

if [[ ${#failed[@]} -gt 0 ]]; then
  echo "findings in: ${failed[*]} (inputs under $build/fuzz-artifacts/)" >&2
  exit 1
fi
echo "no findings"
