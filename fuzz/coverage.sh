#!/usr/bin/env bash
# coverage.sh LLVM_COV BINARY PROFDATA OUTDIR [HEADER]: line and branch coverage of HEADER
# (default cylinder_isect.h; v2/cylinder_isect.h under V=2) reached by the replay of the corpora
# (called by `make fuzz-cov`). Writes the summary, the annotated source, and the list of
# branches the corpus never takes to OUTDIR.
set -euo pipefail
cov=$1; bin=$2; prof=$3; out=$4; hdr=${5:-cylinder_isect.h}
"$cov" report "$bin" -instr-profile="$prof" "$(realpath "$hdr")" >"$out/cov-report.txt"
"$cov" show "$bin" -instr-profile="$prof" -show-branches=count "$(realpath "$hdr")" >"$out/cov-show.txt"
# Missed branch directions: those no instance of the body takes. The body is compiled once per
# API (and per helper instance), so a source branch is listed once per instance, "Branch (L:C):
# [True: n, False: m]"; a direction counts as missed only where every instance's count is 0.
# Each is printed with its source line (the last numbered line printed above it).
awk '
  /^ *[0-9]+\|/ { split($0, p, "|"); src = p[3]; sub(/^ +/, "", src); next }
  /Branch \(/ {
    match($0, /Branch \([0-9]+:[0-9]+\)/); where = substr($0, RSTART + 8, RLENGTH - 9);
    if (!(where in line)) { line[where] = src; order[++n] = where }
    if ($0 !~ /True: 0,/) taken_t[where] = 1
    if ($0 !~ /False: 0\]/) taken_f[where] = 1
  }
  END {
    for (i = 1; i <= n; i++) {
      w = order[i]; t = !(w in taken_t); f = !(w in taken_f)
      if (t || f) printf "%s  never %s  | %s\n", w, (t && f) ? "reached" : (t ? "true" : "false"), line[w]
    }
  }' "$out/cov-show.txt" | sort -t: -k1,1n -u >"$out/cov-missed-branches.txt"
echo "coverage of $hdr by the fuzz corpora:"
head -n 1 "$out/cov-report.txt"
grep -E 'cylinder_isect.h|^TOTAL' "$out/cov-report.txt" | head -n 1
# Lines never executed: "   L|      0|source"
awk -F'|' '/^ *[0-9]+\| +0\|/ { gsub(/^ +/, "", $1); printf "%s: %s\n", $1, $3 }' "$out/cov-show.txt" \
  >"$out/cov-missed-lines.txt"
echo "missed lines: $(wc -l <"$out/cov-missed-lines.txt") (list: $out/cov-missed-lines.txt)"
echo "missed branch directions: $(wc -l <"$out/cov-missed-branches.txt") (list: $out/cov-missed-branches.txt)"
