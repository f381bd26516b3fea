#!/usr/bin/env bash
# Install the Debian packages some features need: OSMesa for offscreen MuJoCo
# rendering (camera perception, videos) and Chromium for the HTML viewer test.
# `system-deps.sh demo` installs only what `make demo` needs (OpenGL for MuJoCo).
set -euo pipefail
pkgs=(libosmesa6 libgl1 libglfw3)
[ "${1:-all}" = "demo" ] || pkgs+=(chromium ffmpeg)
missing=()
for p in "${pkgs[@]}"; do
  dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
if [ "$(id -u)" != "0" ] && ! command -v sudo >/dev/null; then
  echo "system-deps: missing ${missing[*]} and not root; features that need them will be skipped" >&2
  exit 0
fi
SUDO=""; [ "$(id -u)" != "0" ] && SUDO="sudo"
echo "system-deps: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq >/dev/null
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
