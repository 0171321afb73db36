#!/usr/bin/env bash
# CI: libFuzzer on cylinder_isect.h. Each harness (fuzz_isect, fuzz_grid) runs FUZZ_CI_SECONDS
# (default 35, so 70 s of fuzzing in total, within CI's 2-minute budget) starting from the
# committed corpora; any violated invariant or sanitizer report fails the job, and the input is
# left in build/fuzz/artifacts/ (replay it with build/fuzz/replay-gcc -v FILE).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
secs=${FUZZ_CI_SECONDS:-35}
make --no-print-directory fuzz FUZZ_SECONDS="$secs"
