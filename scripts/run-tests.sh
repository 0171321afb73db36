#!/usr/bin/env bash
# Run every Unity runner, keep each output in the results folder, and end with one line that sums
# Unity's "N Tests M Failures K Ignored" lines over all runners (ignored ones count as skipped). Exit non-zero on any failure, on a runner
# that crashes, or on a runner that prints no summary.
#   run-tests.sh RESULTS RUNNER...           runs them, TEST_JOBS at once (default: every core)
#   run-tests.sh --report RESULTS RUNNER...  only the report, of runs already made (the Makefile's
#                                            make test runs each runner as soon as it is built)
# A runner's output is RESULTS/<its path, / as _>.txt, its exit code the same name plus .rc; the
# report lists the runners in the order given.
set -uo pipefail
run=1
if [ "${1:-}" = --report ]; then run=0; shift; fi
results=$1; shift
mkdir -p "$results"
out_of() { echo "$results/$(echo "$1" | tr '/' '_').txt"; }
if [ "$run" = 1 ]; then
  jobs=${TEST_JOBS:-$(getconf _NPROCESSORS_ONLN 2>/dev/null || echo 1)}
  for runner in "$@"; do out=$(out_of "$runner"); rm -f "$out.rc"; printf '%s\0%s\0' "$runner" "$out"; done |
    xargs -0 -r -n 2 -P "$jobs" sh -c '"$1" >"$2" 2>&1; echo $? >"$2.rc"' sh
fi
passed=0; failed=0; skipped=0; bad=0
for runner in "$@"; do
  out=$(out_of "$runner")
  rc=$(cat "$out.rc" 2>/dev/null || echo "none: not run")
  line=$(grep -E '^[0-9]+ Tests [0-9]+ Failures [0-9]+ Ignored' "$out" 2>/dev/null | tail -n 1)
  if [ -z "$line" ]; then
    echo "FAIL $runner: no Unity summary (exit $rc)"; tail -n 20 "$out" 2>/dev/null; bad=$((bad+1)); continue
  fi
  n=$(echo "$line" | awk '{print $1}'); f=$(echo "$line" | awk '{print $3}'); ig=$(echo "$line" | awk '{print $5}')
  passed=$((passed + n - f - ig)); failed=$((failed + f)); skipped=$((skipped + ig))
  if [ "$f" -ne 0 ] || [ "$rc" != 0 ]; then
    echo "FAIL $runner ($line, exit $rc)"; grep -E ':FAIL' "$out" | head -n 20
    [ "$f" -eq 0 ] && bad=$((bad+1))
  else
    echo "ok   $runner ($n tests)"
  fi
done
failed=$((failed + bad))
echo "$passed passed, $failed failed, $skipped skipped"
[ "$failed" -eq 0 ]
