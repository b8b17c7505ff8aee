#!/usr/bin/env bash
# Checks that every C++ file git tracks is formatted as .clang-format says, with clang-format 14
# (Debian 12's). Other versions format some constructs differently (Debian 13's 19 among them), so
# with any other version the check is skipped, and says so, rather than failing on a formatter's taste.
# Usage: scripts/check-format.sh        (scripts/test.sh runs it)
#        scripts/check-format.sh --fix  (formats the files in place)
set -euo pipefail
cd "$(dirname "$0")/.."
formatter=""
for candidate in clang-format-14 clang-format; do
  if command -v "$candidate" >/dev/null && "$candidate" --version | grep -q 'version 14\.'; then
    formatter=$candidate
    break
  fi
done
if [[ -z "$formatter" ]]; then
  found=$(command -v clang-format >/dev/null && clang-format --version || echo "no clang-format")
  echo "format check skipped: it needs clang-format 14 (Debian 12's), this machine has: $found"
  exit 0
fi
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files '*.cpp' '*.h')
else
  # A copy without git (scripts/fresh-root.sh copies the tracked files into a root without git):
  # every C++ file outside the ignored build and output folders (.gitignore).
  mapfile -t files < <(find . \( -path './build*' -o -path './out' -o -path './.cache' \) -prune -o -type f \
                         \( -name '*.cpp' -o -name '*.h' \) -print | sed 's|^\./||' | sort)
fi
if [[ ${#files[@]} -eq 0 ]]; then
  echo "$0: found no C++ files to check" >&2
  exit 1
fi
if [[ "${1:-}" == --fix ]]; then
  "$formatter" -i "${files[@]}"
  exit 0
fi
if ! "$formatter" --dry-run --Werror "${files[@]}"; then
  echo "the files above are not formatted as .clang-format says; scripts/check-format.sh --fix formats them" >&2
  exit 1
fi
echo "${#files[@]} C++ files formatted as .clang-format says ($formatter)"
