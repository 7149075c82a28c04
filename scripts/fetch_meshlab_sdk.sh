#!/usr/bin/env bash
# Fetches the headers the MeshLab filter (plugin/meshlab/) builds against: src/common, vcglib/vcg and
# vcglib/wrap of Debian's meshlab 2020.09+dfsg1-2 source package — the sources of the libmeshlab-common.so
# that Debian's `meshlab` package ships (../shared/HOSTS.md 2.4). Nothing of MeshLab is committed.
# Idempotent: does nothing when the SDK is already there. Enables deb-src for Debian's archive if needed.
# Usage: scripts/fetch_meshlab_sdk.sh [DEST]   (default: /var/cache/sweepcdt/meshlab-sdk as root,
#                                                ~/.cache/sweepcdt/meshlab-sdk otherwise; CMake looks in both)
set -euo pipefail

version=2020.09+dfsg1-2
if [ "$(id -u)" -eq 0 ]; then sudo_cmd=""; default=/var/cache/sweepcdt/meshlab-sdk
else sudo_cmd="sudo"; default="${HOME}/.cache/sweepcdt/meshlab-sdk"; fi
dest="${1:-$default}"

if [ -f "$dest/src/common/interfaces.h" ] && [ -d "$dest/vcglib/vcg" ] && [ -d "$dest/vcglib/wrap" ]; then
  exit 0
fi

# deb-src entries for Debian's archive (deb822 file of Debian 12), unless some are already enabled.
if ! apt-get indextargets --format '$(IDENTIFIER)' 2>/dev/null | grep -qx 'Sources'; then
  src=/etc/apt/sources.list.d/debian.sources
  if [ ! -f "$src" ]; then
    echo "fetch_meshlab_sdk: no deb-src entry and no $src to derive one from; enable deb-src for Debian 12 and retry" >&2
    exit 1
  fi
  echo "fetch_meshlab_sdk: enabling deb-src (/etc/apt/sources.list.d/sweepcdt-debian-src.sources)"
  sed 's/^Types: deb$/Types: deb-src/' "$src" | $sudo_cmd tee /etc/apt/sources.list.d/sweepcdt-debian-src.sources >/dev/null
  $sudo_cmd apt-get update -qq
fi

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
# (As root apt warns that it downloads "unsandboxed": _apt cannot write to this private folder. Harmless.)
echo "fetch_meshlab_sdk: downloading Debian's meshlab=$version source package"
(cd "$work" && apt-get source --download-only -qq "meshlab=$version" >/dev/null)
orig="$(ls "$work"/meshlab_*.orig.tar.* | head -n 1)"
mkdir -p "$work/x"
tar -xf "$orig" -C "$work/x" --wildcards '*/src/common/*' '*/vcglib/vcg/*' '*/vcglib/wrap/*'
top="$(ls -d "$work"/x/*/ | head -n 1)"
$sudo_cmd mkdir -p "$(dirname "$dest")"
$sudo_cmd rm -rf "$dest.tmp"
$sudo_cmd mkdir -p "$dest.tmp/vcglib"
$sudo_cmd cp -r "$top/src" "$dest.tmp/src"
$sudo_cmd cp -r "$top/vcglib/vcg" "$top/vcglib/wrap" "$dest.tmp/vcglib/"
$sudo_cmd rm -rf "$dest"
$sudo_cmd mv "$dest.tmp" "$dest"
echo "fetch_meshlab_sdk: MeshLab 2020.09 headers in $dest"
