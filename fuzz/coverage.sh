#!/usr/bin/env bash
# coverage.sh LLVM_COV BINARY PROFDATA OUTDIR: line and branch coverage of cylinder_isect.h
# reached by the replay of the corpora (called by `make fuzz-cov`). Writes the summary, the
# annotated source, and the list of branches the corpus never takes to OUTDIR.
set -euo pipefail
cov=$1; bin=$2; prof=$3; out=$4
"$cov" report "$bin" -instr-profile="$prof" cylinder_isect.h >"$out/cov-report.txt"
"$cov" show "$bin" -instr-profile="$prof" -show-branches=count cylinder_isect.h >"$out/cov-show.txt"
# Missed branch directions: "Branch (L:C): [True: 0, False: n]" (or False: 0), with the source
# line they belong to (the last numbered line printed above them).
awk '
  /^ *[0-9]+\|/ { split($0, p, "|"); ln = p[1] + 0; src = p[3]; sub(/^ +/, "", src); next }
  /Branch \(/ {
    t = ($0 ~ /True: 0,/); f = ($0 ~ /False: 0\]/);
    if (t || f) {
      match($0, /Branch \([0-9]+:[0-9]+\)/); where = substr($0, RSTART + 8, RLENGTH - 9);
      printf "%s  never %s  | %s\n", where, (t && f) ? "reached" : (t ? "true" : "false"), src
    }
  }' "$out/cov-show.txt" | sort -t: -k1,1n -u >"$out/cov-missed-branches.txt"
echo "coverage of cylinder_isect.h by the fuzz corpora:"
head -n 1 "$out/cov-report.txt"
grep -E '^cylinder_isect.h|^TOTAL' "$out/cov-report.txt" | head -n 1
# Lines never executed: "   L|      0|source"
awk -F'|' '/^ *[0-9]+\| +0\|/ { gsub(/^ +/, "", $1); printf "%s: %s\n", $1, $3 }' "$out/cov-show.txt" \
  >"$out/cov-missed-lines.txt"
echo "missed lines: $(wc -l <"$out/cov-missed-lines.txt") (list: $out/cov-missed-lines.txt)"
echo "missed branch directions: $(wc -l <"$out/cov-missed-branches.txt") (list: $out/cov-missed-branches.txt)"
