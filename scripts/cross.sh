#!/usr/bin/env bash
# The embedded-target and portability checks of mk/cross.mk (issue 6), one subcommand each:
#   scripts/cross.sh sizes [--no-doc] [--no-timing]   make sizes: build every configuration of
#       embedded/configs.txt for every target below, measure code size (text + read-only data
#       of the object: the routine as that configuration gets it) and stack use
#       (-fstack-usage), time the configurations side by side on this machine
#       (embedded/timing.c), and write the tables into docs/embedded.md between the "sizes"
#       markers. Raw figures: $BUILD/sizes/sizes.csv, $BUILD/sizes/timing.csv and, per symbol,
#       $BUILD/sizes/functions.csv.
#   scripts/cross.sh embedded   make embedded-check: the microcontroller builds of every
#       configuration (the objects of `make sizes`, strict warnings, -Werror) and what they must
#       not contain:
#         Cortex-M4F (-mfpu=fpv4-sp-d16 -mfloat-abi=hard -Os -fno-math-errno -ffreestanding,
#                    CYL_NO_DOUBLE): no double-precision instruction (.f64), no soft-float
#                    helper (__aeabi_*), sqrt as vsqrt.f32, no undefined symbol (no libc call);
#         RV32IMAFC  (-march=rv32imafc -mabi=ilp32f): fsqrt.s, no .d instruction, no undefined
#                    symbol;
#         Cortex-M0  (soft float): builds; its undefined symbols are only libgcc's
#                    single-precision helpers and sqrtf/fmaf, never a double helper;
#       then pay for what you use: every configuration that leaves a feature out is smaller than
#       the one that keeps it, on x86-64 and on Cortex-M4F (a feature that does not fold away
#       fails); and finally runs embedded/mcu_smoke.c, linked with the M4F, M0 and RV32 objects,
#       under qemu.
#   scripts/cross.sh lint misra|tidy|doc   make misra-check / make tidy-check: static analysis of
#       cylinder_isect.h through embedded/lint_tu.c.
#         misra: cppcheck with its MISRA C 2012 addon, once per precision; every finding must be
#                one of the deviations of embedded/misra-deviations.txt (reasons there and in
#                docs/embedded.md).
#         tidy:  clang-tidy with the checks of embedded/tidy-checks.txt; must be clean.
#         doc:   write both lists into docs/embedded.md between the "lint" markers.
# Every build of the library uses the project's strict C99 warning set with -Werror.
set -euo pipefail
cd "$(dirname "$0")/.."

# ---------------------------------------------------------------- targets, compilers, flags
: "${GCC:=gcc}"
: "${BUILD:=build}"
# Where cylinder_isect.h is (the repository root unless told otherwise).
: "${CYL_INCLUDE:=.}"

CROSS_WARN="-std=c99 -pedantic -Wall -Wextra -Werror -Wshadow -Wconversion -Wdouble-promotion \
-Wfloat-equal -Wstrict-prototypes"

# Microcontroller builds: what a firmware would use (freestanding, sqrt as an instruction, float
# only). -fno-math-errno lets GCC emit vsqrt.f32 / fsqrt.s instead of a call to sqrtf at -Os.
MCU_COMMON="-Os -fno-math-errno -ffreestanding -DCYL_NO_DOUBLE"

# name|compiler|flags|precisions measured (f, fd)|description
CROSS_TARGETS=(
  "x86_64|$GCC|-O2 -mfma -fno-asynchronous-unwind-tables|fd|x86-64, gcc -O2 -mfma"
  "aarch64|aarch64-linux-gnu-gcc|-O2 -fno-asynchronous-unwind-tables|fd|AArch64, gcc -O2"
  "m4f|arm-none-eabi-gcc|-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard $MCU_COMMON|f|Cortex-M4F, gcc -Os, hard float"
  "m0|arm-none-eabi-gcc|-mcpu=cortex-m0 -mthumb -mfloat-abi=soft $MCU_COMMON|f|Cortex-M0, gcc -Os, soft float"
  "rv32|riscv64-unknown-elf-gcc|--specs=picolibc.specs -march=rv32imafc -mabi=ilp32f -mcmodel=medlow $MCU_COMMON|f|RV32IMAFC, gcc -Os"
)

# Field $2 of a "|"-separated record.
cross_field() { local IFS='|'; set -f; local a; read -r -a a <<<"$1"; set +f; echo "${a[$2]}"; }

# Read embedded/configs.txt: prints "name prec entry opts macros" lines (no comments).
# SIZES_SKIP="name ...": configurations left out (make sizes V=2: those of macros v2 dropped).
cross_configs() {
  awk -v skip=" ${SIZES_SKIP:-} " '!/^#/ && NF >= 5 && index(skip, " " $1 " ") == 0 { print $1, $2, $3, $4, $5 }' embedded/configs.txt
}

# The -D flags that make embedded/configs.c one configuration.
#   cross_cfg_flags <name> <f|d> <entry> <opts> <macros>
cross_cfg_flags() {
  local name=$1 p=$2 entry=$3 opts=$4 macros=$5 flags
  local dbl=0; [ "$p" = d ] && dbl=1
  flags="-DCFG_NAME=cfg${p}_$name -DCFG_DOUBLE=$dbl"
  case $entry in
    intersect) flags+=" -DCFG_ENTRY=CFG_INTERSECT";;
    all)       flags+=" -DCFG_ENTRY=CFG_ALL";;
    occluded)  flags+=" -DCFG_ENTRY=CFG_OCCLUDED";;
    every)     flags+=" -DCFG_ENTRY=CFG_EVERY";;
    pair)      flags+=" -DCFG_ENTRY=CFG_PAIR";;
    mixed)     flags+=" -DCFG_ENTRY=CFG_MIXED";;
    *) echo "unknown entry $entry" >&2; return 1;;
  esac
  if [ "$opts" = runtime ]; then flags+=" -DCFG_RUNTIME=1"; else flags+=" '-DCFG_OPTS=$opts'"; fi
  if [ "$macros" != - ]; then local m; for m in ${macros//,/ }; do flags+=" -D$m"; done; fi
  echo "$flags"
}

# ---------------------------------------------------------------- sizes
cmd_sizes() {
  write_doc=1; timing=1
  for a in "$@"; do case $a in --no-doc) write_doc=0;; --no-timing) timing=0;; *) echo "usage: $0 sizes [--no-doc] [--no-timing]" >&2; exit 2;; esac; done

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
        # the mixed unit holds the double API too: only where double is compiled in
        if [ "$entry" = mixed ]; then case $tprec in *d*) ;; *) continue;; esac; fi
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
  fcsv=$out/functions.csv
  echo "target,config,precision,symbol,bytes" >"$fcsv"
  for tgt in "${CROSS_TARGETS[@]}"; do
    t=$(cross_field "$tgt" 0); cc=$(cross_field "$tgt" 1)
    [ -d "$out/$t" ] || continue
    for o in "$out/$t"/*.o; do
      b=$(basename "$o" .o); p=${b%%_*}; name=${b#*_}
      # Stack: deepest path of the wrapper's call tree, frames as -fstack-usage measures them.
      nf=$(awk -F'\t' 'NF >= 2' "${o%.o}.su" | wc -l)
      echo "$t,$name,$p,$(obj_bytes "$o"),$(python3 scripts/cross.py stack "${o%.o}.ci" "cfg${p}_$name"),$nf" >>"$csv"
      # Where its bytes go: every sized symbol, largest first, by the target's own nm
      # (gcc -> nm, arm-none-eabi-gcc -> arm-none-eabi-nm).
      "${cc/%gcc*/nm}" -S --size-sort -r -t d "$o" | awk -v pre="$t,$name,$p" 'NF == 4 { print pre "," $4 "," $2 + 0 }' >>"$fcsv"
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
  python3 scripts/cross.py table "$csv" "$tcsv" embedded/configs.txt docs/embedded.md "$BUILD/bench/results.json"
  echo "sizes: $csv, tables written to docs/embedded.md"
}

# ---------------------------------------------------------------- embedded
cmd_embedded() {
  S=$BUILD/embedded/objs
  ( SIZES_OUT=$S CROSS_ONLY="x86_64 m4f m0 rv32" cmd_sizes --no-doc --no-timing ) >/dev/null

  fail=0
  bad() { echo "FAIL $*"; fail=$((fail + 1)); }
  # GCC lowers a struct assignment to a call to memcpy when it does not expand it inline (RV32 at
  # -Os does so for 16 bytes): say where such a call comes from.
  memcpy_hint() {
    case " $* " in *" memcpy "*|*" memset "*) echo "     (a struct assignment or initialisation in the library that GCC turned into a libc call: assign the fields one by one)";; esac
  }

  # The runtime configurations read their options from these two variables, defined by the caller.
  ALLOWED_UNDEF='^(cfg_runtime_opts|cfg_runtime_entry)$'

  # ---- Cortex-M4F
  n=0
  for o in "$S"/m4f/*.o; do
    n=$((n + 1)); b=$(basename "$o" .o)
    dis=$(arm-none-eabi-objdump -d "$o")
    if grep -qE '\.f64|__aeabi_d' <<<"$dis"; then bad "m4f $b: double-precision instruction or helper:"; grep -E '\.f64|__aeabi_d' <<<"$dis" | head -5; fi
    und=$(arm-none-eabi-nm -u "$o" | awk '{print $2}' | grep -vE "$ALLOWED_UNDEF" || true)
    [ -z "$und" ] || { bad "m4f $b: undefined symbols (library or helper calls): $(echo $und)"; memcpy_hint $und; }
    case $b in f_occluded|f_occl_caps) ;; *)
      grep -q 'vsqrt\.f32' <<<"$dis" || bad "m4f $b: no vsqrt.f32 (sqrt not inlined?)";;
    esac
  done
  echo "m4f: $n configurations checked (no .f64, no __aeabi_*, no undefined symbol, vsqrt.f32)"

  # ---- RV32IMAFC
  n=0
  for o in "$S"/rv32/*.o; do
    n=$((n + 1)); b=$(basename "$o" .o)
    dis=$(riscv64-unknown-elf-objdump -d "$o")
    # Any double-precision instruction: f*.d, fcvt.*.d / fcvt.d.*, fld, fsd, fmv.x.d ...
    dops=$(awk -F'\t' 'NF >= 3 { print $3 }' <<<"$dis" | grep -E '^(f[a-z.]*\.d(\.[a-z]+)?|fld|fsd|fcvt\.d\.[a-z]+|fcvt\.[a-z]+\.d)$' || true)
    [ -z "$dops" ] || bad "rv32 $b: double-precision instructions: $(echo $dops | head -c 200)"
    und=$(riscv64-unknown-elf-nm -u "$o" | awk '{print $2}' | grep -vE "$ALLOWED_UNDEF" || true)
    [ -z "$und" ] || { bad "rv32 $b: undefined symbols (library or helper calls): $(echo $und)"; memcpy_hint $und; }
    case $b in f_occluded|f_occl_caps) ;; *)
      grep -q 'fsqrt\.s' <<<"$dis" || bad "rv32 $b: no fsqrt.s";;
    esac
  done
  echo "rv32: $n configurations checked (no .d instruction, no undefined symbol, fsqrt.s)"

  # ---- Cortex-M0 (soft float): single-precision helpers only
  n=0; helpers=""
  for o in "$S"/m0/*.o; do
    n=$((n + 1)); b=$(basename "$o" .o)
    und=$(arm-none-eabi-nm -u "$o" | awk '{print $2}' | grep -vE "$ALLOWED_UNDEF" || true)
    other=$(grep -vE '^(__aeabi_f[a-z0-9]*|__aeabi_[iu]i?2f|__aeabi_f2[iu]*z|__aeabi_[lu]*i?div(mod)?|__aeabi_[lu]*l?2f|__aeabi_f2[u]?lz|__aeabi_[lu]?lsl|__aeabi_[lu]?l[sa]r|__aeabi_llsl|__aeabi_lmul|__aeabi_uidiv|__aeabi_idiv|__(lt|gt|le|ge|eq|ne|un)sf2|sqrtf|fmaf)$' <<<"$und" || true)
    [ -z "$other" ] || bad "m0 $b: unexpected undefined symbols (double helper or libc?): $(echo $other)"
    helpers="$helpers $und"
  done
  echo "m0: $n configurations build; external calls: $(tr ' ' '\n' <<<"$helpers" | sort -u | grep . | tr '\n' ' ')"

  # ---- pay for what you use: leaving a feature out must make the code smaller
  size_of() { awk -F, -v t="$1" -v c="$2" -v p="$3" '$1 == t && $2 == c && $3 == p { print $4 }' "$S/sizes.csv"; }
  smaller() { # target prec lean full why
    local a b
    case " ${SIZES_SKIP:-} " in *" $3 "*|*" $4 "*) echo "skip $1 $2: $3 < $4 ($5: a configuration this header does not have)"; return;; esac
    a=$(size_of "$1" "$3" "$2"); b=$(size_of "$1" "$4" "$2")
    if [ -z "$a" ] || [ -z "$b" ]; then bad "sizes: missing $1 $2 $3 or $4"; return; fi
    if [ "$a" -lt "$b" ]; then echo "ok   $1 $2: $3 $a B < $4 $b B ($5)"; else bad "$1 $2: $3 is $a B, not smaller than $4 $b B: $5 does not fold away"; fi
  }
  # Does the header compile the precise tier out of a float-only build (v2: CYL_NO_DOUBLE defines
  # CYL_NO_PRECISE)? Then the microcontroller's precise and runtime objects refuse the bit.
  # (the header by its path: a quoted include from standard input would find ./cylinder_isect.h)
  major=$(printf '#include "%s/cylinder_isect.h"\nCYL_VERSION_MAJOR\n' "$CYL_INCLUDE" | $GCC -E -P -x c - | tail -n 1)
  mcu_noprec=$(printf '#include "%s/cylinder_isect.h"\n#ifdef CYL_NO_PRECISE\nnoprec\n#endif\n' "$CYL_INCLUDE" |
    $GCC -E -P -DCYL_NO_DOUBLE -x c - | grep -c '^noprec$' || true)
  for tp in x86_64:f x86_64:d m4f:f; do
    t=${tp%:*}; p=${tp#*:}
    smaller "$t" "$p" open capped "the caps"
    # intersect vs intersect_all is not a fold: both solve for both crossings (the nearest one in
    # range needs both); only the output of the second differs. Reported, not asserted.
    echo "info $t $p: open (intersect) $(size_of "$t" open "$p") B, all (intersect_all) $(size_of "$t" all "$p") B"
    smaller "$t" "$p" no_terr open "t_err"
    smaller "$t" "$p" no_normal open "the normal"
    # Validation is checked directly (below): its size saving is small enough for GCC's code
    # layout to hide it (x86-64 float: the trusted object has been larger than the open one).
    echo "info $t $p: trusted $(size_of "$t" trusted "$p") B, open $(size_of "$t" open "$p") B"
    smaller "$t" "$p" minimal no_terr "normal and validation, given no t_err"
    smaller "$t" "$p" occluded open "everything a shadow ray does not need"
    smaller "$t" "$p" occl_caps capped "everything a shadow ray does not need, capped"
    # v1: the default path carries the compensated solver as its fallback, so the precise tier
    # folds into it only where the precise tier also starts on the fast path (the float API
    # computed in double); the double API's precise tier is the solver alone, smaller than the
    # default. v2: the precise tier adds its certificates to the default path everywhere.
    if [ "$t" = m4f ] && [ "$mcu_noprec" -gt 0 ]; then
      smaller "$t" "$p" precise open "the whole call where CYL_PRECISE is compiled out (CYL_E_OPTION)"
      echo "info $t $p: rt_noprec $(size_of "$t" rt_noprec "$p") B, runtime $(size_of "$t" runtime "$p") B (CYL_NO_DOUBLE defines CYL_NO_PRECISE: the same)"
    else
      if [ "$tp" = x86_64:d ] && [ "$major" -lt 2 ]; then
        echo "info $t $p: open $(size_of "$t" open "$p") B (fast path + solver), precise $(size_of "$t" precise "$p") B (solver alone)"
      else
        smaller "$t" "$p" open precise "the precise tier"
      fi
      smaller "$t" "$p" rt_noprec runtime "the precise tier (CYL_NO_PRECISE)"
    fi
    smaller "$t" "$p" open runtime "options not passed as constants"
    smaller "$t" "$p" nofast open "the fast path (CYL_NO_FAST_PATH)"
  done

  # Input validation, directly: its six return codes CYL_E_NONFINITE..CYL_E_TRANGE (-2..-7) are
  # immediates in the code of a validating configuration and must all be gone with CYL_TRUSTED
  # (CYL_E_NULL and CYL_E_OPTION remain by contract). gcc may form CYL_E_ZERO_DIR and
  # CYL_E_ZERO_AXIS (-3, -4) arithmetically from one comparison (v2 on x86-64: sbb; sub $3), so a
  # validating object shows at least the other four.
  codes() { # target object -> number of distinct immediates -2..-7
    case $1 in
      x86_64) objdump -d "$2" | grep -oE '\$0xffffff(fe|fd|fc|fb|fa|f9)\b' || true;;
      m4f)    arm-none-eabi-objdump -d "$2" | { grep -oE 'mvn[a-z]*(\.w)?\s+r[0-9]+, #[1-6]$' || true; } | grep -oE '#[1-6]$' || true;; # mvn, mvns, and conditional forms (mvnhi.w) in IT blocks
    esac | sort -u | wc -l || true
  }
  for tp in x86_64:f x86_64:d m4f:f; do
    t=${tp%:*}; p=${tp#*:}
    with=$(codes "$t" "$S/$t/${p}_open.o"); without=$(codes "$t" "$S/$t/${p}_trusted.o"); lean=$(codes "$t" "$S/$t/${p}_minimal.o")
    if [ "$with" -ge 4 ] && [ "$without" -eq 0 ] && [ "$lean" -eq 0 ]; then
      echo "ok   $t $p: validation folds away: $with of its 6 return codes are in open, none in trusted or minimal"
    else
      bad "$t $p: validation return codes: open $with of 6, trusted $without, minimal $lean (want 4 to 6, 0, 0)"
    fi
  done

  # ---- run the M4F, M0 and RV32 objects on emulated cores
  smoke=$BUILD/embedded; mkdir -p "$smoke"
  objs() { local d=$1 c; for c in open capped all occluded occl_caps no_terr no_normal trusted minimal precise runtime rt_noprec every_f; do echo "$S/$d/f_$c.o"; done; }
  HARNESS_FLAGS="$CROSS_WARN -Wno-missing-prototypes -fno-builtin -fno-tree-loop-distribute-patterns -I$CYL_INCLUDE"
  for tgt in "${CROSS_TARGETS[@]}"; do
    t=$(cross_field "$tgt" 0); cc=$(cross_field "$tgt" 1); fl=$(cross_field "$tgt" 2)
    case $t in
      m4f|m0) run="qemu-arm-static -cpu max"; libs="-lm -lc -lgcc"; ldextra=;;
      rv32)   run="qemu-riscv32-static";    libs="-lc -lgcc"; ldextra=-Wl,--defsym=__flash_size=0x100000;;
      *) continue;;
    esac
    $cc $fl $HARNESS_FLAGS -c embedded/mcu_smoke.c -o "$smoke/mcu_smoke_$t.o"
    # Without libc start-up code (the harness has its own _start). All thirteen configurations
    # together exceed the 64 KiB flash region of picolibc's default memory map: give it 1 MiB.
    $cc $fl -nostdlib -static $ldextra "$smoke/mcu_smoke_$t.o" $(objs "$t") $libs -o "$smoke/mcu_smoke_$t"
    printf '#!/bin/sh\nexec %s "$(dirname "$0")/mcu_smoke_%s" "$@"\n' "$run" "$t" >"$smoke/run-mcu_smoke_$t"
    chmod +x "$smoke/run-mcu_smoke_$t"
  done
  bash scripts/run-tests.sh "$BUILD/results/embedded" "$smoke"/run-mcu_smoke_* || fail=$((fail + 1))

  if [ "$fail" -ne 0 ]; then echo "embedded-check: $fail failure(s)"; exit 1; fi
  echo "embedded-check: all passed"
}

# ---------------------------------------------------------------- lint
lint_misra() {
  command -v cppcheck >/dev/null || { echo "misra-check: cppcheck not found (see mk/cross.deps)" >&2; exit 1; }
  local raw=$BUILD/lint/misra.txt p
  : >"$raw"
  # cppcheck does not read the system headers: it is told what they would say.
  for p in CYL_NO_DOUBLE CYL_NO_FLOAT; do
    cppcheck --addon=misra --std=c99 --language=c --enable=style,warning,portability,performance \
      --inline-suppr -I"$CYL_INCLUDE" -D__GNUC__ -DFLT_EVAL_METHOD=0 -D$p \
      --template='{file}:{line}:{id}:{message}' --quiet embedded/lint_tu.c >>"$raw" 2>&1
  done
  sort -u -o "$raw" "$raw"
  local allowed bad
  allowed=$(awk '!/^#/ && NF { print $1 }' embedded/misra-deviations.txt)
  # Findings outside the header, and findings in it that are not listed deviations.
  bad=$(awk -F: -v allowed="$allowed" 'BEGIN { n = split(allowed, a, "\n"); for (i = 1; i <= n; i++) ok[a[i]] = 1 }
        { f = $1; sub(/^.*\//, "", f) } !(f == "cylinder_isect.h" && ($3 in ok))' "$raw")
  echo "misra-check: $(wc -l <"$raw") findings in $BUILD/lint/misra.txt; by id:"
  awk -F: '{ print $3 }' "$raw" | sort | uniq -c | sort -rn | sed 's/^/  /'
  if [ -n "$bad" ]; then
    echo "misra-check: FAIL, not a listed deviation (embedded/misra-deviations.txt):"; echo "$bad"; exit 1
  fi
  echo "misra-check: every finding is a listed deviation"
}

lint_tidy() {
  command -v clang-tidy >/dev/null || { echo "tidy-check: clang-tidy not found (see mk/cross.deps)" >&2; exit 1; }
  local checks raw=$BUILD/lint/tidy.txt
  checks=$(awk '!/^#/ && NF { c = $1; sub(/^\+/, "", c); printf "%s%s", sep, c; sep = "," }' embedded/tidy-checks.txt)
  checks="-*,$checks"
  if ! clang-tidy embedded/lint_tu.c --quiet --checks="$checks" --warnings-as-errors='*' \
      --header-filter='cylinder_isect\.h' -- -std=c99 -I"$CYL_INCLUDE" >"$raw" 2>&1; then
    grep -E 'warning|error' "$raw" | head -40
    echo "tidy-check: FAIL ($(grep -cE 'warning:|error:' "$raw") findings, all in $raw)"; exit 1
  fi
  echo "tidy-check: clean ($checks)"
}

lint_doc() {
  python3 scripts/cross.py lint-doc embedded/misra-deviations.txt embedded/tidy-checks.txt docs/embedded.md "$BUILD/lint/misra.txt"
  echo "lint tables written to docs/embedded.md"
}

cmd_lint() {
  mkdir -p "$BUILD/lint"
  case ${1:-} in
    misra) lint_misra;;
    tidy) lint_tidy;;
    doc) lint_doc;;
    *) echo "usage: $0 lint misra|tidy|doc" >&2; exit 2;;
  esac
}

cmd=${1:-}; [ $# -gt 0 ] && shift
case $cmd in
  sizes) cmd_sizes "$@";;
  embedded) cmd_embedded "$@";;
  lint) cmd_lint "$@";;
  *) echo "usage: $0 sizes [--no-doc] [--no-timing] | embedded | lint misra|tidy|doc" >&2; exit 2;;
esac
