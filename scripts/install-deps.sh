#!/usr/bin/env bash
# Installs the Debian 12 packages revolve needs, skipping those already installed.
# Usage: scripts/install-deps.sh [--test]
#   (none)   what the main job builds and runs: the library and revolve-render
#   --test   also what the whole test suite and the benchmarks need: GoogleTest, Google Benchmark,
#            clang with its sanitizer and libFuzzer runtimes, matplotlib (revolve-lidar --plot,
#            bench/plot_results.py), POV-Ray 3.7 (revolve-bench pov, the export's round-trip test)
#            and the DejaVu font (the side-by-side figure's labels)
set -euo pipefail

packages=(
  cmake ninja-build g++
  libembree-dev libtbb-dev libcli11-dev nlohmann-json3-dev
  # Debian's libopenimageio-dev exports CMake targets for OpenImageIO's command-line tools, which
  # live in openimageio-tools: without it find_package(OpenImageIO) fails at configure time
  # ("imported target OpenImageIO::iconvert references the file /usr/bin/iconvert").
  libopenimageio-dev openimageio-tools
)
case "${1:-}" in
  "") ;;
  --test) packages+=(libgtest-dev libgmock-dev libbenchmark-dev clang libclang-rt-14-dev python3-matplotlib povray fonts-dejavu-core) ;;
  *) echo "usage: $0 [--test]" >&2; exit 2 ;;
esac

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done
if [[ ${#missing[@]} -eq 0 ]]; then
  exit 0
fi

sudo=()
if [[ "$(id -u)" -ne 0 ]]; then
  if ! command -v sudo >/dev/null; then
    echo "$0: these Debian packages are missing and installing them needs root (or sudo): ${missing[*]}" >&2
    exit 1
  fi
  sudo=(sudo)
fi
echo "Installing: ${missing[*]}"
"${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -qq
"${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
