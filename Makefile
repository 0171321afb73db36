# cylinder_isect: build, test and check.
#   make test       the unit tests: Unity suites in every configuration (gcc, clang, C++,
#                   ASan+UBSan), the accuracy test against the MPFR reference, the fuzz corpus and
#                   findings replay, the README snippet; ends with one "N passed, M failed" line
#   make test V=2   the same suite on v2/cylinder_isect.h, the rewrite growing beside v1 (below)
#   make check      make test, then every other check (what CI runs: .ci/run): examples and the
#                   viewer under Xvfb, cross and embedded builds under qemu, MISRA and
#                   clang-tidy, C++ compatibility, the install test, a short fuzz run, the
#                   rewritten header's line budgets (make shape, mk/tests.mk)
#   make demo       the examples (see mk/examples.mk)
#   make install    the header, a pkg-config file and a CMake package (see mk/install.mk)
#   make cost       instructions per call of v1 and v2 against the end-point routine (mk/cost.mk)
# Area-specific targets live in mk/*.mk, each owned by one part of the project.
#
# The convention every fragment follows:
#   RUNNERS       Unity runners (programs ending with Unity's summary line) that `make test`
#                 builds and runs; only tests of the library belong here
#   TEST_PREREQS  other files `make test` builds first (a check a stamp stands for)
#   CHECK_PREREQS files `make check` builds (its step check-builds): tools and checks that are
#                 not unit tests, e.g. the benchmark binary
#   CHECK_TARGETS phony targets, each a step of `make check`; every step runs even when an
#                 earlier one failed, and `make check` ends with the list of the failed ones
# Packages: mk/core.deps lists what `make test` needs (and every goal gets); mk/AREA.deps what
# only AREA's goals need. A goal installs what is missing before any rule runs:
#   DEPS_GOALS_<area>  the goals that need mk/<area>.deps (set by the fragment)
# `make check` installs every list; scripts/install-deps.sh TIER|AREA... does the same by hand.
#
# V=2 (`make test V=2`, default V=1): the same `make test` suite on $(V2_DIR)/cylinder_isect.h
# (V2_DIR ?= v2: the rewrite growing beside v1) instead of ./cylinder_isect.h, built apart in
# build/v2 (another V2_DIR: build/v2-<its path>); runners that only make sense for v1
# (-DCYL_NO_FAST_PATH) are left out, and tests that need CYL_PRECISE skip themselves where the
# header defines CYL_NO_PRECISE.
# HDR is the header under test: fragments list $(HDR), never the file name, as a prerequisite.

SHELL    := /bin/bash
CC       ?= cc
GCC      ?= gcc
CLANG    ?= clang
CXX_GCC  ?= g++
PYTHON   ?= python3
# Which header the suite tests. Under V=2 every compiler variable (GCC, CLANG, CXX_GCC, hence
# the CFG_CC_* below) gets -iquote $(V2_DIR): #include "cylinder_isect.h" searches the
# includer's own directory, then the -iquote directories, then -I; no directory but the root
# holds a cylinder_isect.h, so every test, bench, fuzz and ref source finds v2's.
V        ?= 1
ifeq ($(V),2)
V2_DIR   ?= v2
V2_ABS   := $(abspath $(V2_DIR))
# Another V2_DIR's objects go apart too (make compares times, not which header was compiled).
BUILD    ?= build/v2$(if $(filter-out $(abspath v2),$(V2_ABS)),-$(subst /,_,$(V2_ABS:/%=%)))
HDR      := $(V2_DIR)/cylinder_isect.h
V2_IQUOTE := -iquote $(V2_ABS)
override GCC     := $(GCC) $(V2_IQUOTE)
override CLANG   := $(CLANG) $(V2_IQUOTE)
override CXX_GCC := $(CXX_GCC) $(V2_IQUOTE)
else ifeq ($(V),1)
HDR      := cylinder_isect.h
else
$(error V=$(V): use V=1 (./cylinder_isect.h, the default) or V=2 ($$(V2_DIR)/cylinder_isect.h))
endif
BUILD    ?= build
# The C compiler without the -iquote V=2 adds: for builds that choose their header themselves
# (make cost, the cross and size builds, the install test's consumer of the installed header).
GCC_ALONE := $(firstword $(GCC))
RESULTS  := $(BUILD)/results
.DEFAULT_GOAL := test
# `make test` alone uses every core unless a -j is given: the suite is dozens of independent
# builds. Other goals keep make's default (the benchmarks time their runs).
ifeq ($(filter-out test,$(or $(MAKECMDGOALS),test))$(filter -j%,$(MAKEFLAGS)),)
MAKEFLAGS += -j$(shell nproc 2>/dev/null || echo 1)
endif

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
UNITY_SHA256 := b90e735a54cf3b3765ab6caa955d11a1488ee73d9c6152cdc98576c2d17cb871:unity.c \
                9db174d3c2c6424fd35c0980c5941d124c5ebb0f48e8172f997a2aa9554b64ea:unity.h \
                fcd8b3f6b412ac0ab599547eb8a30b6d7f3f0af77aab31f7a1822a2a8fc9a2b2:unity_internals.h
# $(call unity_verify,DIR): fails unless DIR holds exactly Unity v2.6.1's three files.
unity_verify = printf '%s\n' $(foreach s,$(UNITY_SHA256),'$(word 1,$(subst :, ,$(s)))  $(1)/$(word 2,$(subst :, ,$(s)))') \
  | sha256sum --quiet -c - || { echo "error: Unity sources in $(1) do not match the sha256 of Unity v2.6.1; refusing to build." >&2; exit 1; }

# Fetched from the pinned registry package (never vendored), unpacked, verified.
$(UNITY_FETCHED)/unity.c:
	@rm -rf $(UNITY_FETCHED).download && mkdir -p $(UNITY_FETCHED).download $(UNITY_FETCHED)
	@$(PYTHON) -m pip download --quiet --no-deps --disable-pip-version-check "$(UNITY_PKG)" -d $(UNITY_FETCHED).download
	@$(PYTHON) -m zipfile -e $(UNITY_FETCHED).download/*.whl $(UNITY_FETCHED).download/whl
	@cp $(addprefix $(UNITY_FETCHED).download/whl/vyperling/c/,unity.c unity.h unity_internals.h) $(UNITY_FETCHED)/
	@$(call unity_verify,$(UNITY_FETCHED)) || { rm -f $(UNITY_FETCHED)/unity*; exit 1; }

# $(call write_if_changed,TEXT): a recipe line that writes TEXT into $@ only when it differs, so
# that a file holding a build command (its rule depends on FORCE) is newer only when the command changed.
write_if_changed = printf '%s\n' '$(1)' | cmp -s - $@ || printf '%s\n' '$(1)' > $@
.PHONY: FORCE
FORCE:

.PHONY: unity
unity: $(UNITY_C)
	@$(call unity_verify,$(UNITY_SRC))

# ---------------------------------------------------------------- test builds
# Each configuration builds every tests/test_*.c into its own runner.
TEST_SRCS  := $(wildcard tests/test_*.c)
TEST_NAMES := $(patsubst tests/%.c,%,$(TEST_SRCS))
TEST_DEPS  := $(HDR) $(wildcard tests/*.h)
CONFIGS    := gcc-O0 gcc-O2 clang-O0 clang-O2 cxx asan

CFG_CC_gcc-O0    := $(GCC)
CFG_FLAGS_gcc-O0 := $(WARN_C) -O0 -g
CFG_CC_gcc-O2    := $(GCC)
CFG_FLAGS_gcc-O2 := $(WARN_C) -O2
CFG_CC_clang-O0    := $(CLANG)
CFG_FLAGS_clang-O0 := $(WARN_C) -O0 -g
CFG_CC_clang-O2    := $(CLANG)
CFG_FLAGS_clang-O2 := $(WARN_C) -O2
# Entry points out of line (CYL_DEF as `static inline`, the manual's way to let calls share
# code; v1's default): one copy of the body per runner instead of one per call site. The
# builds that change the language or the arithmetic (C++, the configuration runners of
# mk/tests.mk) use it, which takes v2's C++ runner from about 14 s to 3 s of compiling; the
# default, every call site folding its own options, is what gcc-O2 and clang-O2 test.
CYL_OUT_OF_LINE := -D'CYL_DEF=static inline'
CFG_CC_cxx       := $(CXX_GCC) -x c++
CFG_FLAGS_cxx    := $(WARN_CXX) -O2 $(CYL_OUT_OF_LINE)
# ASan+UBSan at -O0: every load and every operation keeps its check, and the build is quick
# (v2 inlines nothing at -O0, v1 only what gcc chooses); the runners take under a second.
CFG_CC_asan      := $(CLANG)
CFG_FLAGS_asan   := $(WARN_C) -O0 -g -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer

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

RUNNERS       := $(TEST_BINS)
TEST_PREREQS  :=
CHECK_PREREQS :=
CHECK_TARGETS :=

# Runners built with -mfma run only where this machine executes FMA3 (x86-64): mk/bench.mk,
# mk/fuzz.mk and mk/tests.mk add them when HOST_FMA is 1.
HOST_FMA := $(shell grep -qw fma /proc/cpuinfo 2>/dev/null && test "$$(uname -m)" = x86_64 && echo 1)

-include mk/*.mk

# ---------------------------------------------------------------- packages
# They must be there before any rule runs: with -j, make starts the compilers beside a `deps`
# prerequisite, before it has installed them (seen with `make test -j2` on a fresh machine:
# clang not found). So the goals named on the command line install first, once, while this file
# is read (not for `make -n`); sub-makes inherit CYL_DEPS_DONE and skip it.
DEPS_AREAS_ALL := $(patsubst mk/%.deps,%,$(wildcard mk/*.deps))
GOALS          := $(or $(MAKECMDGOALS),$(.DEFAULT_GOAL))
ifneq ($(filter check,$(GOALS)),)
DEPS_TIER := check
else ifneq ($(filter test deps $(foreach a,$(DEPS_AREAS_ALL),$(DEPS_GOALS_$(a))),$(GOALS)),)
DEPS_TIER := $(or $(strip $(foreach a,$(DEPS_AREAS_ALL),$(if $(filter $(DEPS_GOALS_$(a)),$(GOALS)),$(a)))),test)
endif
ifneq ($(DEPS_TIER),)
ifneq ($(CYL_DEPS_DONE),1)
ifeq ($(findstring n,$(firstword -$(MAKEFLAGS))),)
DEPS_RC := $(shell bash scripts/install-deps.sh $(DEPS_TIER) >&2; echo $$?)
ifneq ($(DEPS_RC),0)
$(error scripts/install-deps.sh $(DEPS_TIER) failed with exit code $(DEPS_RC))
endif
export CYL_DEPS_DONE := 1
endif
endif
endif

.PHONY: deps
deps:
	@[ "$(CYL_DEPS_DONE)" = 1 ] || bash scripts/install-deps.sh $(or $(DEPS_TIER),test)

# ---------------------------------------------------------------- the two tiers
.PHONY: test check check-builds
# Each runner runs as soon as it is built, beside the builds still going (make -j): its output
# and exit code go to $(RESULTS)/<its path, / as _>.txt and .rc, and run-tests.sh --report sums
# them in RUNNERS' order. Every make test runs every runner (FORCE: what one reads, the fuzz
# corpus for one, may have changed since).
run_out = $(RESULTS)/$(subst /,_,$(1)).txt
define RUN_RULE
$(call run_out,$(1)): $(1) FORCE
	@mkdir -p $$(@D); rm -f $$@.rc; $(1) >$$@ 2>&1; echo $$$$? >$$@.rc
endef
$(foreach r,$(RUNNERS),$(eval $(call RUN_RULE,$(r))))
test: deps unity $(TEST_PREREQS) $(foreach r,$(RUNNERS),$(call run_out,$(r)))
	@bash scripts/run-tests.sh --report $(RESULTS) $(RUNNERS)

check-builds: deps unity $(CHECK_PREREQS)

# Each step is its own sub-make (parallel inside with -j); every step runs, the failed ones are
# listed at the end. CHECK_STEPS="a b" runs only those steps.
CHECK_STEPS ?= test check-builds $(CHECK_TARGETS)
check: deps
	@failed=(); t00=$$SECONDS; \
	for s in $(CHECK_STEPS); do \
	  echo "=== $$s"; t0=$$SECONDS; \
	  if $(MAKE) --no-print-directory $$s; then echo "=== $$s: ok ($$((SECONDS - t0)) s)"; \
	  else echo "=== $$s: FAILED ($$((SECONDS - t0)) s)"; failed+=("$$s"); fi; \
	done; \
	if [ $${#failed[@]} -ne 0 ]; then echo "check: FAILED: $${failed[*]} ($$((SECONDS - t00)) s)"; exit 1; fi; \
	echo "check: all $(words $(CHECK_STEPS)) steps passed ($$((SECONDS - t00)) s)"

.PHONY: clean
clean:
	rm -rf $(BUILD)
