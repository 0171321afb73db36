#!/usr/bin/env bash
# make embedded-check: the microcontroller builds of every configuration (the objects of
# `make sizes`, strict warnings, -Werror) and what they must not contain:
#   Cortex-M4F (-mfpu=fpv4-sp-d16 -mfloat-abi=hard -Os -fno-math-errno -ffreestanding,
#              CYL_NO_DOUBLE): no double-precision instruction (.f64), no soft-float helper
#              (__aeabi_*), sqrt as vsqrt.f32, no undefined symbol at all (no libc call);
#   RV32IMAFC  (-march=rv32imafc -mabi=ilp32f): fsqrt.s, no .d instruction, no undefined symbol;
#   Cortex-M0  (soft float): builds; its undefined symbols are only libgcc's single-precision
#              helpers and sqrtf/fmaf, never a double helper;
# then pay for what you use: every configuration that leaves a feature out is smaller than the
# one that keeps it, on x86-64 and on Cortex-M4F (a feature that does not fold away fails);
# and finally runs embedded/mcu_smoke.c, linked with the M4F, M0 and RV32 objects, under qemu.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/cross-env.sh
S=$BUILD/embedded/objs
SIZES_OUT=$S CROSS_ONLY="x86_64 m4f m0 rv32" bash scripts/cross-sizes.sh --no-doc --no-timing >/dev/null

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
  local a b; a=$(size_of "$1" "$3" "$2"); b=$(size_of "$1" "$4" "$2")
  if [ -z "$a" ] || [ -z "$b" ]; then bad "sizes: missing $1 $2 $3 or $4"; return; fi
  if [ "$a" -lt "$b" ]; then echo "ok   $1 $2: $3 $a B < $4 $b B ($5)"; else bad "$1 $2: $3 is $a B, not smaller than $4 $b B: $5 does not fold away"; fi
}
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
  # The default path carries the compensated solver as its fallback, so the precise tier folds
  # into it only where the precise tier also starts on the fast path (the float API computed
  # in double); the double API's precise tier is the solver alone, smaller than the default.
  if [ "$tp" = x86_64:d ]; then
    echo "info $t $p: open $(size_of "$t" open "$p") B (fast path + solver), precise $(size_of "$t" precise "$p") B (solver alone)"
  else
    smaller "$t" "$p" open precise "the precise tier"
  fi
  smaller "$t" "$p" open runtime "options not passed as constants"
  smaller "$t" "$p" rt_noprec runtime "the precise tier (CYL_NO_PRECISE)"
  smaller "$t" "$p" nofast open "the fast path (CYL_NO_FAST_PATH)"
done

# Input validation, directly: its six return codes CYL_E_NONFINITE..CYL_E_TRANGE (-2..-7) are
# immediates in the code of a validating configuration and must all be gone with CYL_TRUSTED
# (CYL_E_NULL and CYL_E_OPTION remain by contract).
codes() { # target object -> number of distinct immediates -2..-7
  case $1 in
    x86_64) objdump -d "$2" | grep -oE '\$0xffffff(fe|fd|fc|fb|fa|f9)\b' || true;;
    m4f)    arm-none-eabi-objdump -d "$2" | { grep -oE 'mvn[a-z]*(\.w)?\s+r[0-9]+, #[1-6]$' || true; } | grep -oE '#[1-6]$' || true;; # mvn, mvns, and conditional forms (mvnhi.w) in IT blocks
  esac | sort -u | wc -l || true
}
for tp in x86_64:f x86_64:d m4f:f; do
  t=${tp%:*}; p=${tp#*:}
  with=$(codes "$t" "$S/$t/${p}_open.o"); without=$(codes "$t" "$S/$t/${p}_trusted.o"); lean=$(codes "$t" "$S/$t/${p}_minimal.o")
  if [ "$with" -eq 6 ] && [ "$without" -eq 0 ] && [ "$lean" -eq 0 ]; then
    echo "ok   $t $p: validation folds away: its 6 return codes are in open, none in trusted or minimal"
  else
    bad "$t $p: validation return codes: open $with of 6, trusted $without, minimal $lean (want 6, 0, 0)"
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
