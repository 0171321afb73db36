#!/usr/bin/env bash
# make sizes: build every configuration of embedded/configs.txt for every target of
# scripts/cross-env.sh, measure code size (text + read-only data of the object: the routine as
# that configuration gets it) and stack use (-fstack-usage), time the configurations side by side
# on this machine (embedded/timing.c), and write the tables into docs/embedded.md between the
# "sizes" markers. Raw figures: $BUILD/sizes/sizes.csv and $BUILD/sizes/timing.csv.
#   scripts/cross-sizes.sh [--no-doc] [--no-timing]
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/cross-env.sh
write_doc=1; timing=1
for a in "$@"; do case $a in --no-doc) write_doc=0;; --no-timing) timing=0;; *) echo "usage: $0 [--no-doc] [--no-timing]" >&2; exit 2;; esac; done

out=${SIZES_OUT:-$BUILD/sizes}
rm -rf "$out"; mkdir -p "$out"
jobs=$out/jobs.txt; : >"$jobs"

# CROSS_ONLY="x86_64 m4f ...": build only these targets (make embedded-check needs no AArch64).
for tgt in "${CROSS_TARGETS[@]}"; do
  t=$(cross_field "$tgt" 0); cc=$(cross_field "$tgt" 1); tflags=$(cross_field "$tgt" 2); tprec=$(cross_field "$tgt" 3)
  if [ -n "${CROSS_ONLY:-}" ]; then case " $CROSS_ONLY " in *" $t "*) ;; *) continue;; esac; fi
  command -v "$cc" >/dev/null || { echo "error: $cc not found (see mk/cross.deps)" >&2; exit 1; }
  mkdir -p "$out/$t"
  while read -r name prec entry opts macros; do
    for p in f d; do
      case $prec in *$p*) ;; *) continue;; esac
      case $tprec in *$p*) ;; *) continue;; esac
      flags=$(cross_cfg_flags "$name" "$p" "$entry" "$opts" "$macros")
      echo "$cc $tflags $CROSS_WARN -fstack-usage -fcallgraph-info=su -I$CYL_INCLUDE $flags -c embedded/configs.c -o $out/$t/${p}_$name.o" >>"$jobs"
    done
  done < <(cross_configs)
done

echo "sizes: $(wc -l <"$jobs") builds"
if ! xargs -P 2 -d '\n' -n 1 bash -c <"$jobs" >"$out/build.log" 2>&1; then
  cat "$out/build.log" >&2; echo "error: a configuration does not build" >&2; exit 1
fi

# Bytes of code and constants in an object: .text*, .rodata*, .srodata*, plus any data or bss
# (there should be none). Unwind tables, notes and attributes are not code.
obj_bytes() {
  size -A "$1" | awk '$1 ~ /^\.(text|rodata|srodata|data|sdata|bss|sbss)(\.|$)/ { s += $2 } END { print s + 0 }'
}
csv=$out/sizes.csv
echo "target,config,precision,bytes,stack,functions" >"$csv"
for tgt in "${CROSS_TARGETS[@]}"; do
  t=$(cross_field "$tgt" 0)
  [ -d "$out/$t" ] || continue
  for o in "$out/$t"/*.o; do
    b=$(basename "$o" .o); p=${b%%_*}; name=${b#*_}
    # Stack: deepest path of the wrapper's call tree, frames as -fstack-usage measures them.
    nf=$(awk -F'\t' 'NF >= 2' "${o%.o}.su" | wc -l)
    echo "$t,$name,$p,$(obj_bytes "$o"),$(python3 scripts/cross-stack.py "${o%.o}.ci" "cfg${p}_$name"),$nf" >>"$csv"
  done
done

tcsv=$out/timing.csv
if [ "$timing" = 1 ]; then
  # Time the x86-64 objects just measured: same code, same flags.
  t0=$(cross_field "${CROSS_TARGETS[0]}" 0); cc0=$(cross_field "${CROSS_TARGETS[0]}" 1); fl0=$(cross_field "${CROSS_TARGETS[0]}" 2)
  list=$out/cfg_list.h; : >"$list"
  while read -r name prec entry opts macros; do
    for p in f d; do
      case $prec in *$p*) ;; *) continue;; esac
      rt=0; [ "$opts" = runtime ] && rt=1
      echo "CFG($p, $name, $rt, \"$entry\")" >>"$list"
    done
  done < <(cross_configs)
  # The driver never includes the header with a configuration's macros: it only needs the
  # public structs, which are the same in every configuration.
  $cc0 $fl0 $CROSS_WARN -I"$CYL_INCLUDE" -I"$out" -c embedded/timing.c -o "$out/timing.o"
  $cc0 "$out/timing.o" "$out/$t0"/*.o -lm -o "$out/timing"
  "$out/timing" >"$tcsv"
  echo "timing: $tcsv"
fi

[ "$write_doc" = 1 ] || { echo "sizes: $csv"; exit 0; }
python3 scripts/cross-table.py "$csv" "$tcsv" embedded/configs.txt docs/embedded.md "$BUILD/bench/results.json"
echo "sizes: $csv, tables written to docs/embedded.md"
