#!/usr/bin/env bash
# make cxx-compat: cylinder_isect.h compiled as C++11 and C++17 by g++ and clang++ with
# -Wall -Wextra -Werror (and the project's strict set), in each precision configuration, then
# embedded/cxx_check.cpp is run. Fails on any warning or wrong answer.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/cross-env.sh
out=$BUILD/cxx; mkdir -p "$out"
# The root Makefile's WARN_CXX set. Not -Wold-style-cast: C casts are the only ones C99 has.
CXXWARN="-pedantic -Wall -Wextra -Werror -Wshadow -Wconversion -Wdouble-promotion -Wfloat-equal"
n=0
for cxx in g++ clang++; do
  command -v $cxx >/dev/null || { echo "cxx-compat: $cxx not found" >&2; exit 1; }
  for std in c++11 c++17; do
    for cfg in "" -DCYL_NO_PRECISE -DCYL_NO_DOUBLE -DCYL_NO_FLOAT; do
      w=$CXXWARN
      exe=$out/cxx_check_${cxx}_${std}${cfg:+_${cfg#-D}}
      $cxx -std=$std $w -O2 $cfg -I"$CYL_INCLUDE" embedded/cxx_check.cpp -lm -o "$exe"
      "$exe" >/dev/null || { "$exe"; echo "cxx-compat: FAIL $cxx -std=$std $cfg" >&2; exit 1; }
      n=$((n + 1))
    done
  done
done
echo "cxx-compat: $n builds (g++, clang++; C++11, C++17; default, CYL_NO_PRECISE, CYL_NO_DOUBLE, CYL_NO_FLOAT) warning-free and passing"
