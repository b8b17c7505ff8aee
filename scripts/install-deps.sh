#!/usr/bin/env bash
# Installs the Debian packages revolve needs, skipping those already installed: Debian 12
# (bookworm: Embree 3.13, clang 14) or Debian 13 (trixie: Embree 4.3, clang 19), read from
# /etc/os-release. The names below are the same on both (libclang-rt-dev is each release's
# clang runtime: libclang-rt-14-dev on Debian 12, libclang-rt-19-dev on Debian 13).
# Usage: scripts/install-deps.sh [--test]
#   (none)   what the main job builds and runs: the library and revolve-render
#   --test   also what the whole test suite and the benchmarks need: GoogleTest, Google Benchmark,
#            clang with its sanitizer and libFuzzer runtimes, matplotlib (revolve-lidar --plot,
#            bench/plot_results.py), POV-Ray 3.7 (revolve-bench pov, the export's round-trip test),
#            the DejaVu font (the side-by-side figure's labels), clang-format (scripts/check-format.sh);
#            and the Python package's build and tests: headers, pybind11, numpy, pytest, venv (with
#            pip: `pip install .` into a fresh virtual environment), Dask
#            distributed and Open3D (compared against), Pillow (camera frames read into ROS 2 bags),
#            and on Debian 13 rosbags (revolve.ros2's bags; Debian 12 has no python3-rosbags, and
#            the bag tests skip there saying so), and on Debian 13 OSPRay 3 with its module SDK and
#            ISPC (the OSPRay module, ospray/, and its tests; Debian 12 has no OSPRay 3, and
#            they are left out there saying so)
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
  --test) packages+=(libgtest-dev libgmock-dev libbenchmark-dev clang libclang-rt-dev python3-matplotlib povray fonts-dejavu-core
                     clang-format python3-dev python3-pybind11 python3-numpy python3-pytest python3-venv python3-distributed python3-open3d python3-pil
                     pcl-tools) ;;  # PCL reading the scans revolve-lidar writes
  *) echo "usage: $0 [--test]" >&2; exit 2 ;;
esac

# The releases these names were checked on. Another Debian may well work; anything else needs the
# same libraries installed by its own means.
os_id=$(. /etc/os-release 2>/dev/null && echo "${ID:-unknown}")
os_version=$(. /etc/os-release 2>/dev/null && echo "${VERSION_ID:-unknown}")
case "$os_id $os_version" in
  "debian 12" | "debian 13") ;;
  debian\ *) echo "$0: Debian $os_version is neither 12 nor 13, whose package names this script knows; trying them anyway" >&2 ;;
  *)
    echo "$0: this machine is '$os_id $os_version' (/etc/os-release), not Debian 12 or 13: install Embree 3.13 or 4.x," \
         "TBB, CLI11, nlohmann-json and OpenImageIO by its own means (Debian's names: ${packages[*]})" >&2
    exit 1 ;;
esac

if [[ "${1:-}" == --test && "$os_id $os_version" == "debian 13" ]]; then
  packages+=(python3-rosbags libospray-dev ispc)
fi

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
