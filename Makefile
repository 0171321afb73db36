# cylinder_isect: build, test and report.
#   make test    every test build (gcc, clang, C++, sanitizers) and one pass line
#   make demo    the examples (see mk/examples.mk)
# Area-specific targets live in mk/*.mk, each owned by one part of the project.

SHELL    := /bin/bash
CC       ?= cc
GCC      ?= gcc
CLANG    ?= clang
CXX_GCC  ?= g++
PYTHON   ?= python3
BUILD    ?= build
RESULTS  := $(BUILD)/results

# The warning set every build of the library must pass (issue 2).
WARN_C   := -std=c99 -pedantic -Wall -Wextra -Werror -Wshadow -Wconversion \
            -Wdouble-promotion -Wfloat-equal -Wstrict-prototypes
WARN_CXX := -std=c++11 -pedantic -Wall -Wextra -Werror -Wshadow -Wconversion \
            -Wdouble-promotion -Wfloat-equal

# ---------------------------------------------------------------- Unity
# Unity v2.6.1 comes from a registry package whose copies of the three files are byte-identical
# to the release; the hashes below are the release's, so any other content stops the build.
UNITY_PKG     := vyperling==0.0.4
UNITY_FETCHED := $(BUILD)/unity
ifdef UNITY_DIR
UNITY_SRC := $(UNITY_DIR)
else
UNITY_SRC := $(UNITY_FETCHED)
endif
UNITY_C    := $(UNITY_SRC)/unity.c
UNITY_FLAGS := -I$(UNITY_SRC) -DUNITY_INCLUDE_DOUBLE -DUNITY_SUPPORT_64

$(UNITY_FETCHED)/unity.c:
	@bash scripts/fetch-unity.sh "$(UNITY_PKG)" "$(UNITY_FETCHED)"

.PHONY: unity
unity: $(UNITY_C)
	@bash scripts/check-unity.sh "$(UNITY_SRC)"

# ---------------------------------------------------------------- test builds
# Each configuration builds every tests/test_*.c into its own runner.
TEST_SRCS  := $(wildcard tests/test_*.c)
TEST_NAMES := $(patsubst tests/%.c,%,$(TEST_SRCS))
TEST_DEPS  := cylinder_isect.h $(wildcard tests/*.h)
CONFIGS    := gcc-O0 gcc-O2 clang-O0 clang-O2 cxx asan

CFG_CC_gcc-O0    := $(GCC)
CFG_FLAGS_gcc-O0 := $(WARN_C) -O0 -g
CFG_CC_gcc-O2    := $(GCC)
CFG_FLAGS_gcc-O2 := $(WARN_C) -O2
CFG_CC_clang-O0    := $(CLANG)
CFG_FLAGS_clang-O0 := $(WARN_C) -O0 -g
CFG_CC_clang-O2    := $(CLANG)
CFG_FLAGS_clang-O2 := $(WARN_C) -O2
CFG_CC_cxx       := $(CXX_GCC) -x c++
CFG_FLAGS_cxx    := $(WARN_CXX) -O2
CFG_CC_asan      := $(CLANG)
CFG_FLAGS_asan   := $(WARN_C) -O1 -g -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer

# Unity itself is third-party C: it is built once per configuration with relaxed warnings.
define CONFIG_RULES
$(BUILD)/$(1)/unity.o: $(UNITY_C) | unity
	@mkdir -p $$(@D)
	$$(CFG_CC_$(1)) $$(filter-out -Werror -Wconversion -Wdouble-promotion -Wfloat-equal -Wshadow -pedantic,$$(CFG_FLAGS_$(1))) $(UNITY_FLAGS) -w -c $$< -o $$@
$(BUILD)/$(1)/%: tests/%.c $(TEST_DEPS) $(BUILD)/$(1)/unity.o
	@mkdir -p $$(@D)
	$$(CFG_CC_$(1)) $$(CFG_FLAGS_$(1)) $(UNITY_FLAGS) -I. -Itests $$< -x none $(BUILD)/$(1)/unity.o -lm -o $$@
endef
$(foreach c,$(CONFIGS),$(eval $(call CONFIG_RULES,$(c))))

TEST_BINS := $(foreach c,$(CONFIGS),$(foreach t,$(TEST_NAMES),$(BUILD)/$(c)/$(t)))

# Area fragments add runners to RUNNERS (programs whose output has Unity's summary line)
# and prerequisites to TEST_PREREQS.
RUNNERS      := $(TEST_BINS)
TEST_PREREQS :=

# The packages must be there before any rule runs: with -j, make starts the compilers beside
# the `deps` prerequisite, before it has installed them (seen with `make test -j2` on a fresh
# machine: clang not found). So the goals that build install first, once, while this file is
# read; sub-makes inherit CYL_DEPS_DONE and skip it.
ifneq ($(filter test demo report insn,$(MAKECMDGOALS)),)
ifneq ($(CYL_DEPS_DONE),1)
DEPS_RC := $(shell bash scripts/install-deps.sh >&2; echo $$?)
ifneq ($(DEPS_RC),0)
$(error scripts/install-deps.sh failed with exit code $(DEPS_RC))
endif
export CYL_DEPS_DONE := 1
endif
endif
# Runners built with -mfma run only where this machine executes FMA3 (x86-64): mk/bench.mk,
# mk/fuzz.mk and mk/tests.mk add them when HOST_FMA is 1.
HOST_FMA := $(shell grep -qw fma /proc/cpuinfo 2>/dev/null && test "$$(uname -m)" = x86_64 && echo 1)
-include mk/*.mk

.PHONY: test deps
deps:
	@[ "$(CYL_DEPS_DONE)" = 1 ] || bash scripts/install-deps.sh

test: deps unity $(TEST_PREREQS) $(RUNNERS)
	@bash scripts/run-tests.sh $(RESULTS) $(RUNNERS)

.PHONY: clean
clean:
	rm -rf $(BUILD)
