#!/usr/bin/env bash
# Instructions per call of the benchmark's variants (callgrind), side by side: `make insn`.
#   scripts/insn.sh BIN [FAMILIES] [N]   BIN: build/bench/insn; FAMILIES: "well grazing huge"
# Prints a markdown table: per precision and family (capped cases), instructions per call of
# each variant, the empty loop subtracted, and lib / quilez, lib / literal.
set -euo pipefail
bin=$1
fams=${2:-"well grazing huge"}
n=${3:-2000}
variants=("lib" "lib+NO_ERRBOUND+NO_NORMAL" "lib+PRECISE" "literal" "quilez")
count() { # prec family variant -> instructions collected inside insn_run
  valgrind --tool=callgrind --toggle-collect=insn_run --callgrind-out-file=/dev/null \
    "$bin" "$1" "$2" 1 "$3" "$n" 2>&1 | awk '/Collected :/ {print $NF}'
}
echo "| precision | family | $(IFS='|'; echo "${variants[*]}" | sed 's/|/ | /g') | lib / quilez | lib / literal |"
echo "|---|---|$(printf -- '--:|%.0s' "${variants[@]}")--:|--:|"
for prec in 24 53; do
  for fam in $fams; do
    base=$(count "$prec" "$fam" none)
    row=()
    for v in "${variants[@]}"; do
      c=$(count "$prec" "$fam" "$v")
      row+=("$(( (c - base) / n ))")
    done
    lib=${row[0]} lit=${row[3]} qz=${row[4]}
    printf '| %s | %s | %s | %s | %s |\n' "$([ "$prec" = 24 ] && echo float || echo double)" "$fam" \
      "$(IFS='|'; echo "${row[*]}" | sed 's/|/ | /g')" \
      "$(awk -v a="$lib" -v b="$qz" 'BEGIN{printf "%.2f", a/b}')" \
      "$(awk -v a="$lib" -v b="$lit" 'BEGIN{printf "%.2f", a/b}')"
  done
done
echo
echo "Capped cases, $n per family, seed 20261122; instructions per call counted by callgrind inside the benchmark's call loop (the empty loop subtracted)."
