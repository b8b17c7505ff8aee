#!/usr/bin/env bash
# Installs the built library into a fresh prefix, then configures, builds and runs separate
# projects that find it with find_package(revolve), as a user's project does: a program that links
# revolve::core without Embree, an application written in the native API of the Embree the library
# was built with (consumer_embree3 or consumer_embree4), and the README's example program
# (examples/library), so that none of them can rot. When the library was built with its OSPRay
# module, an OSPRay program too (consumer_ospray), run with LD_LIBRARY_PATH on the folder the
# package names, as docs/ospray.md tells a user to.
# Usage: install_and_consume.sh <build-dir> <scratch-dir> <package-tests-dir> <project-dir>...
set -euo pipefail
build=$1 scratch=$2 here=$3
shift 3
rm -rf "$scratch"
cmake --install "$build" --prefix "$scratch/prefix" >/dev/null
major=$(sed -n 's/^#define REVOLVE_EMBREE_MAJOR \([0-9]*\)$/\1/p' "$scratch/prefix/include/revolve/config.h")
if [[ "$major" != 3 && "$major" != 4 ]]; then
  echo "install_and_consume.sh: the installed revolve/config.h names no Embree major version (got '$major')" >&2
  exit 1
fi
echo "== the installed revolve was built against Embree $major"
for project in "$here/consumer_core" "$here/consumer_embree$major" "$@"; do
  name=$(basename "$project")
  cmake -S "$project" -B "$scratch/$name" -G Ninja -DCMAKE_PREFIX_PATH="$scratch/prefix" >/dev/null
  cmake --build "$scratch/$name" >/dev/null
  # Each project builds one executable; run it.
  program=$(find "$scratch/$name" -maxdepth 1 -type f -executable | head -n 1)
  echo "== $name: $program"
  "$program"
done
# Whether the module was installed, as the package itself says (revolve_OSPRAY_MODULE): its folder
# is the install's libdir, lib/x86_64-linux-gnu on Debian, not always lib.
config=$(find "$scratch/prefix" -name revolveConfig.cmake | head -n 1)
module=$(sed -n 's/^set(revolve_OSPRAY_MODULE \(.*\))$/\1/p' "$config")
if [[ "${module^^}" =~ ^(ON|TRUE|1|YES)$ ]]; then
  cmake -S "$here/consumer_ospray" -B "$scratch/consumer_ospray" -G Ninja -DCMAKE_PREFIX_PATH="$scratch/prefix" >/dev/null
  cmake --build "$scratch/consumer_ospray" >/dev/null
  echo "== consumer_ospray: LD_LIBRARY_PATH=$(cat "$scratch/consumer_ospray/module_dir.txt")"
  LD_LIBRARY_PATH="$(cat "$scratch/consumer_ospray/module_dir.txt")" "$scratch/consumer_ospray/consumer_ospray"
else
  echo "== consumer_ospray: not run, the library was built without its OSPRay module"
fi
