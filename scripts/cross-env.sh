# Sourced by scripts/cross-*.sh: the targets, their compilers and flags, in one place.
# Every build of the library uses the project's strict C99 warning set with -Werror.
# shellcheck shell=bash
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
cross_configs() {
  awk '!/^#/ && NF >= 5 { print $1, $2, $3, $4, $5 }' embedded/configs.txt
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
    *) echo "unknown entry $entry" >&2; return 1;;
  esac
  if [ "$opts" = runtime ]; then flags+=" -DCFG_RUNTIME=1"; else flags+=" '-DCFG_OPTS=$opts'"; fi
  if [ "$macros" != - ]; then local m; for m in ${macros//,/ }; do flags+=" -D$m"; done; fi
  echo "$flags"
}
