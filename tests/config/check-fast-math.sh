#!/usr/bin/env bash
# -ffast-math must stop the build with cylinder_isect.h's own #error (not any other failure):
# the same file builds without the flag, fails with it, and the first error points at a line
# of cylinder_isect.h that is an #error directive. Usage: check-fast-math.sh STAMP CC...
set -uo pipefail
stamp=$1; shift
src=tests/config/cfg_fast_math.c
for cc in "$@"; do
  if ! $cc -std=c99 -Wall -Werror -I. -c "$src" -o /dev/null; then
    echo "fast-math check: $cc cannot build $src even without -ffast-math" >&2; exit 1
  fi
  if err=$($cc -std=c99 -ffast-math -I. -c "$src" -o /dev/null 2>&1); then
    echo "fast-math check: $cc -ffast-math built $src; cylinder_isect.h must refuse it" >&2; exit 1
  fi
  loc=$(printf '%s\n' "$err" | grep -m1 -oE 'cylinder_isect\.h:[0-9]+' || true)
  line=${loc#*:}
  if [ -z "$loc" ] || ! sed -n "${line}p" cylinder_isect.h | grep -qE '^[[:space:]]*#[[:space:]]*error'; then
    echo "fast-math check: $cc failed, but not on an #error of cylinder_isect.h:" >&2
    printf '%s\n' "$err" | head -n 5 >&2; exit 1
  fi
  echo "fast-math check: $cc -ffast-math stops at cylinder_isect.h:$line (#error)"
done
mkdir -p "$(dirname "$stamp")" && touch "$stamp"
