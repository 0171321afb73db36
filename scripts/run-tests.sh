#!/usr/bin/env bash
# Run every Unity runner, keep each output in the results folder, and end with one line that sums
# Unity's "N Tests M Failures K Ignored" lines over all runners (ignored ones count as skipped). Exit non-zero on any failure, on a runner
# that crashes, or on a runner that prints no summary.
set -uo pipefail
results=$1; shift
mkdir -p "$results"
passed=0; failed=0; skipped=0; bad=0
for runner in "$@"; do
  name=$(echo "$runner" | tr '/' '_')
  out="$results/$name.txt"
  "$runner" >"$out" 2>&1
  rc=$?
  line=$(grep -E '^[0-9]+ Tests [0-9]+ Failures [0-9]+ Ignored' "$out" | tail -n 1)
  if [ -z "$line" ]; then
    echo "FAIL $runner: no Unity summary (exit $rc)"; tail -n 20 "$out"; bad=$((bad+1)); continue
  fi
  n=$(echo "$line" | awk '{print $1}'); f=$(echo "$line" | awk '{print $3}'); ig=$(echo "$line" | awk '{print $5}')
  passed=$((passed + n - f - ig)); failed=$((failed + f)); skipped=$((skipped + ig))
  if [ "$f" -ne 0 ] || [ "$rc" -ne 0 ]; then
    echo "FAIL $runner ($line, exit $rc)"; grep -E ':FAIL' "$out" | head -n 20
    [ "$f" -eq 0 ] && bad=$((bad+1))
  else
    echo "ok   $runner ($n tests)"
  fi
done
failed=$((failed + bad))
echo "$passed passed, $failed failed, $skipped skipped"
[ "$failed" -eq 0 ]
