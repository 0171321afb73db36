#!/usr/bin/env bash
# Installs the Debian packages a tier of the build needs, when missing (as root, or via sudo).
#   scripts/install-deps.sh test       mk/core.deps: what `make test` needs
#   scripts/install-deps.sh check      every mk/*.deps: what `make check` (and CI) needs
#   scripts/install-deps.sh AREA...    mk/core.deps and mk/AREA.deps (e.g. examples for make demo)
# The root Makefile calls it with the tier of the goals it is given. One package per line.
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -ne 0 ] || set -- test
lists=(mk/core.deps)
for tier in "$@"; do
  case $tier in
    test) ;;
    check) for f in mk/*.deps; do lists+=("$f"); done;;
    *) [ -f "mk/$tier.deps" ] || { echo "install-deps: no mk/$tier.deps (tiers: test, check, or an area of mk/*.deps)" >&2; exit 2; }
       lists+=("mk/$tier.deps");;
  esac
done
pkgs=()
for f in "${lists[@]}"; do
  while read -r p _; do [ -n "$p" ] && [ "${p#\#}" = "$p" ] && pkgs+=("$p"); done <"$f"
done
mapfile -t pkgs < <(printf '%s\n' "${pkgs[@]}" | sort -u)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# python3/pip may come from elsewhere (pyenv); only ask apt for them when no python3 exists.
if command -v python3 >/dev/null; then
  tmp=(); for p in "${missing[@]+"${missing[@]}"}"; do case $p in python3|python3-pip) ;; *) tmp+=("$p");; esac; done
  missing=("${tmp[@]+"${tmp[@]}"}")
fi
[ ${#missing[@]} -eq 0 ] && exit 0
echo "installing ($*): ${missing[*]}"
SUDO=; [ "$(id -u)" -ne 0 ] && SUDO=sudo
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
