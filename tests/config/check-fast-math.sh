#!/usr/bin/env bash
# -ffast-math must stop the build with cylinder_isect.h's own #error (not any other failure):
# the same file builds without the flag, fails with it, and the first error points at a line
# of cylinder_isect.h that is an #error directive. Usage: check-fast-math.sh STAMP CC...
# Each CC is one argument and may carry flags (make test V=2: -iquote v2); CYL_HDR names the
# header they include (default cylinder_isect.h, under V=2 v2/cylinder_isect.h).
set -uo pipefail
stamp=$1; shift
hdr=${CYL_HDR:-cylinder_isect.h}
src=tests/config/cfg_fast_math.c
for cc in "$@"; do
  if ! $cc -std=c99 -Wall -Werror -I. -c "$src" -o /dev/null; then
    echo "fast-math check: $cc cannot build $src even without -ffast-math" >&2; exit 1
  fi
  if err=$($cc -std=c99 -ffast-math -I. -c "$src" -o /dev/null 2>&1); then
    echo "fast-math check: $cc -ffast-math built $src; cylinder_isect.h must refuse it" >&2; exit 1
  fi
  loc=$(printf '%s\n' "$err" | grep -m1 -oE '[^[:space:]:]*cylinder_isect\.h:[0-9]+' || true)
  file=${loc%:*}; line=${loc##*:}
  # the #error of $hdr itself, not of another cylinder_isect.h the compiler found first
  if [ -z "$loc" ] || [ "$(realpath -q -- "$file")" != "$(realpath -q -- "$hdr")" ] ||
     ! sed -n "${line}p" "$hdr" | grep -qE '^[[:space:]]*#[[:space:]]*error'; then
    echo "fast-math check: $cc failed, but not on an #error of $hdr:" >&2
    printf '%s\n' "$err" | head -n 5 >&2; exit 1
  fi
  echo "fast-math check: $cc -ffast-math stops at $hdr:$line (#error)"
done
mkdir -p "$(dirname "$stamp")" && touch "$stamp"
