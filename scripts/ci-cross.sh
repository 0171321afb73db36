#!/usr/bin/env bash
# What CI runs for issue 6 (embedded targets and portability): the Unity suite under qemu on
# aarch64, armhf and s390x, the microcontroller checks, the C++11/17 builds, MISRA and
# clang-tidy. Every step runs; any failure fails the script (and CI), with a summary at the end.
# Needs the packages of mk/cross.deps (scripts/install-deps.sh) and Unity (make unity).
set -uo pipefail
cd "$(dirname "$0")/.."
: "${BUILD:=build}"
: "${UNITY_SRC:=$BUILD/unity}"
export BUILD
[ -f "$UNITY_SRC/unity.c" ] || make -s unity BUILD="$BUILD"
failed=()
step() {
  local name=$1; shift
  echo "=== $name"
  local t0=$SECONDS
  if "$@"; then echo "=== $name: ok ($((SECONDS - t0)) s)"; else echo "=== $name: FAILED ($((SECONDS - t0)) s)"; failed+=("$name"); fi
}
step cross-test     bash scripts/cross-test.sh "$BUILD" "$UNITY_SRC"
step embedded-check bash scripts/cross-embedded.sh
step cxx-compat     bash scripts/cross-cxx.sh
step misra-check    bash scripts/cross-lint.sh misra
step tidy-check     bash scripts/cross-lint.sh tidy
if [ ${#failed[@]} -ne 0 ]; then echo "ci-cross: FAILED: ${failed[*]}"; exit 1; fi
echo "ci-cross: all passed"
