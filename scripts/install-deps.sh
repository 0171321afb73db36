#!/usr/bin/env bash
# Install what the build needs from Debian's packages when it is missing (as root, or via sudo).
# Areas list their packages in mk/*.deps, one Debian package per line.
set -euo pipefail
cd "$(dirname "$0")/.."
pkgs=(gcc g++ clang make python3 python3-pip)
for f in mk/*.deps; do [ -f "$f" ] && while read -r p _; do [ -n "$p" ] && [ "${p#\#}" = "$p" ] && pkgs+=("$p"); done <"$f"; done
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# python3/pip may come from elsewhere (pyenv); only ask apt for them when no python3 exists.
if command -v python3 >/dev/null; then
  tmp=(); for p in "${missing[@]}"; do case $p in python3|python3-pip) ;; *) tmp+=("$p");; esac; done
  missing=("${tmp[@]+"${tmp[@]}"}")
fi
[ ${#missing[@]} -eq 0 ] && exit 0
echo "installing: ${missing[*]}"
SUDO=; [ "$(id -u)" -ne 0 ] && SUDO=sudo
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
