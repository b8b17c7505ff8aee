#!/usr/bin/env bash
# Runs a command in a fresh, minimal Debian 12 or 13 root holding a copy of this checkout, so that
# the README's commands are tried as a newcomer's machine would run them: no compilers, no -dev
# packages, no sudo, nothing installed by hand. Run it whenever the dependencies change.
#
# Usage: scripts/fresh-root.sh [--release bookworm|trixie] [--export DIR] COMMAND...
#   (as root; e.g. scripts/fresh-root.sh --release trixie bash scripts/main.sh)
#   --release  Debian 12 (bookworm, the default) or Debian 13 (trixie)
#   --export   DIR (made if missing) is bound at /export inside the root: results to keep, or to
#              hand to a run in the other release's root
#
# The root is `mmdebstrap --variant=minbase RELEASE`, made with this machine's own Debian mirrors
# (the URIs apt already uses for Debian's archive here, with the release's name in place of this
# machine's), with /proc and /dev bound in. The checkout is copied without its ignored files (no
# build/, no out/). COMMAND runs in the copy's top folder; its exit status is this script's. The
# root is deleted afterwards, also on SIGINT/SIGTERM.
#
# The bootstrap tarball is cached in ${REVOLVE_ROOT_CACHE:-~/.cache/revolve} for a day, purely to
# save its 20 s to 2 min: a missing or unreadable cache is simply made again.
set -euo pipefail

usage="usage: $0 [--release bookworm|trixie] [--export DIR] COMMAND..."
release=bookworm
export_dir=
while [[ $# -gt 0 ]]; do
  case "$1" in
    --release)
      [[ $# -ge 2 ]] || { echo "$usage" >&2; exit 2; }
      release=$2
      shift 2 ;;
    --export)
      [[ $# -ge 2 && -n "$2" ]] || { echo "$usage" >&2; exit 2; }
      export_dir=$2
      shift 2 ;;
    *) break ;;
  esac
done
case "$release" in
  bookworm | trixie) ;;
  *) echo "$0: --release is '$release': it must be bookworm (Debian 12) or trixie (Debian 13)" >&2; exit 2 ;;
esac
if [[ $# -eq 0 ]]; then
  echo "$usage" >&2
  exit 2
fi
if [[ "$(id -u)" -ne 0 ]]; then
  echo "$0: must run as root (it bootstraps a Debian root and chroots into it)" >&2
  exit 2
fi
checkout=$(cd "$(dirname "$0")/.." && pwd)

if ! command -v mmdebstrap >/dev/null; then
  echo "Installing: mmdebstrap"
  DEBIAN_FRONTEND=noninteractive apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends mmdebstrap
fi

# This machine's Debian mirrors, as apt sees them: every package index whose release file says
# o=Debian, one "deb URI SUITE COMPONENT" line each (third-party sources are left out), with this
# machine's release name (bookworm in bookworm-updates, bookworm-security) replaced by $release.
debian_sources() {
  local here
  here=$(. /etc/os-release && echo "${VERSION_CODENAME:-}")
  apt-cache policy | awk -v here="$here" -v release="$release" '
    /^ *[0-9]+ [a-z]+:\/\// { uri = $2; split($3, sc, "/"); suite = sc[1]; component = sc[2]; next }
    /release .*o=Debian,/ && uri != "" { if (here != "") sub("^" here, release, suite)
                                         line = "deb " uri " " suite " " component
                                         if (!(line in seen)) { seen[line] = 1; print line } uri = "" }'
}
sources=$(debian_sources)
if [[ -z "$sources" ]]; then  # no package lists yet on this machine
  DEBIAN_FRONTEND=noninteractive apt-get update -qq
  sources=$(debian_sources)
fi
if [[ -z "$sources" ]]; then
  echo "$0: apt on this machine names no Debian archive (apt-cache policy shows no o=Debian source)" >&2
  exit 1
fi

cache=${REVOLVE_ROOT_CACHE:-$HOME/.cache/revolve}
tarball="$cache/$release-minbase.tar"
work=$(mktemp -d "${TMPDIR:-/tmp}/revolve-fresh-root.XXXXXX")
root="$work/root"
cleanup() {
  local status=$?
  trap - EXIT INT TERM
  for mount in "$root/export" "$root/dev/pts" "$root/dev" "$root/proc"; do
    mountpoint -q "$mount" 2>/dev/null && umount -l "$mount"
  done
  rm -rf --one-file-system "$work"
  exit "$status"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

# The cached tarball is used only when it is a day old at most, made from the same sources, and
# reads back as a tar; anything else makes a new one.
stamp="$cache/$release-minbase.sources"
if [[ -f "$tarball" && -f "$stamp" && "$(cat "$stamp")" == "$sources" ]] \
    && [[ -n "$(find "$tarball" -mmin -1440)" ]] && tar -tf "$tarball" >/dev/null 2>&1; then
  echo "== fresh root: cached $tarball"
else
  echo "== fresh root: mmdebstrap --variant=minbase $release"
  mkdir -p "$cache"
  printf '%s\n' "$sources" > "$work/sources.list"
  mmdebstrap --quiet --variant=minbase "$release" "$work/$release-minbase.tar" "$work/sources.list"
  mv "$work/$release-minbase.tar" "$tarball.tmp.$$"
  mv "$tarball.tmp.$$" "$tarball"
  printf '%s\n' "$sources" > "$stamp"
fi

mkdir "$root"
tar -xf "$tarball" -C "$root"
cp /etc/resolv.conf "$root/etc/resolv.conf" 2>/dev/null || true
mount --bind /proc "$root/proc"
mount --bind /dev "$root/dev"
mount --bind /dev/pts "$root/dev/pts" 2>/dev/null || true
if [[ -n "$export_dir" ]]; then
  mkdir -p "$export_dir" "$root/export"
  mount --bind "$export_dir" "$root/export"
fi

# The checkout as git would clone it, plus uncommitted and untracked (not ignored) files.
mkdir -p "$root/root/revolve"
(cd "$checkout" && git ls-files -z --cached --others --exclude-standard \
   | while IFS= read -r -d '' file; do if [[ -e "$file" ]]; then printf '%s\0' "$file"; fi; done \
   | tar --null -T - -cf -) | tar -xf - -C "$root/root/revolve"

echo "== fresh root ($release): $*"
quoted=$(printf ' %q' "$@")
chroot "$root" /usr/bin/env -i HOME=/root PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
  LANG=C.UTF-8 TERM=dumb /bin/bash -c "cd /root/revolve &&${quoted}"
