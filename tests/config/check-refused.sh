#!/usr/bin/env bash
# Builds the header refuses must stop with its own #error (not any other failure): the same
# file builds without the refused flag, fails with it, and the first error points at a line of
# the header under test that is an #error directive.
# Usage: check-refused.sh STAMP CC...
#   Each CC is one argument and may carry flags (make test V=2: -iquote v2).
#   CYL_HDR      the header they include (default cylinder_isect.h; under V=2 v2/cylinder_isect.h)
#   CYL_REFUSED  the refused flag sets, separated by '|' (default -ffast-math); under V=2 also
#                the configuration macros v2 dropped (its CONFIGURATION: "Gone in v2")
set -uo pipefail
stamp=$1; shift
hdr=${CYL_HDR:-cylinder_isect.h}
src=tests/config/cfg_refused.c
IFS='|' read -r -a refused <<< "${CYL_REFUSED:--ffast-math}"
for cc in "$@"; do
  if ! $cc -std=c99 -Wall -Werror -I. -c "$src" -o /dev/null; then
    echo "refused-build check: $cc cannot build $src without any refused flag" >&2; exit 1
  fi
  for flags in "${refused[@]}"; do
    if err=$($cc -std=c99 $flags -I. -c "$src" -o /dev/null 2>&1); then
      echo "refused-build check: $cc $flags built $src; $hdr must refuse it" >&2; exit 1
    fi
    loc=$(printf '%s\n' "$err" | grep -m1 -oE '[^[:space:]:]*cylinder_isect\.h:[0-9]+' || true)
    file=${loc%:*}; line=${loc##*:}
    # the #error of $hdr itself, not of another cylinder_isect.h the compiler found first
    if [ -z "$loc" ] || [ "$(realpath -q -- "$file")" != "$(realpath -q -- "$hdr")" ] ||
       ! sed -n "${line}p" "$hdr" | grep -qE '^[[:space:]]*#[[:space:]]*error'; then
      echo "refused-build check: $cc $flags failed, but not on an #error of $hdr:" >&2
      printf '%s\n' "$err" | head -n 5 >&2; exit 1
    fi
    echo "refused-build check: $cc $flags stops at $hdr:$line (#error)"
  done
done
mkdir -p "$(dirname "$stamp")" && touch "$stamp"
