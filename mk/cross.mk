# Embedded targets, portability, and paying only for what a scene uses (issue 6).
#   make sizes           code size, stack and ns/call per configuration, lint deviations
#                        -> docs/embedded.md
#   make cross-test      the Unity suite on aarch64, armhf, s390x under qemu user mode
#   make embedded-check  Cortex-M4F / Cortex-M0 / RV32IMAFC builds, disassembly checks,
#                        feature folding, and a smoke run of those objects under qemu
#                        (V=2: on v2's header, as .ci/run does)
#   make cxx-compat      the header as C++11 and C++17 (g++ and clang++, -Wall -Wextra -Werror)
#   make misra-check     cppcheck with its MISRA C 2012 addon (deviations: embedded/misra-deviations.txt)
#   make tidy-check      clang-tidy (checks listed in embedded/tidy-checks.txt)
#   make ci-cross        all of the above except sizes
# All but sizes are steps of `make check`. The shell parts are scripts/cross.sh (targets,
# compilers and flags of the microcontroller builds) and scripts/cross.py.
.PHONY: sizes cross-test embedded-check cxx-compat misra-check tidy-check ci-cross

# V=2: the compiler alone (V=2 adds -iquote to GCC), v2's header, the configurations v2 has.
ifeq ($(V),2)
CROSS_ENV := BUILD=$(BUILD) GCC=$(GCC_ALONE) CYL_INCLUDE=$(V2_DIR) SIZES_SKIP=nofast
else
CROSS_ENV := BUILD=$(BUILD) GCC=$(GCC)
endif
DEPS_GOALS_cross := sizes cross-test embedded-check cxx-compat misra-check tidy-check ci-cross
CROSS_CHECKS := cross-test embedded-check cxx-compat misra-check tidy-check
CHECK_TARGETS += $(CROSS_CHECKS)

# Regenerates the tables of docs/embedded.md: sizes and timing, then the lint deviations with
# their current counts (the check itself is misra-check).
ifeq ($(V),2)
# v2 beside v1: its figures stay in $(BUILD)/sizes (docs/embedded.md describes the product, v1),
# then the limits v2 must meet to replace it (issue 30); it fails when one it met before
# (embedded/gates-held.txt) is no longer met. nofast's macro is gone from v2.
sizes:
	@$(CROSS_ENV) bash scripts/cross.sh sizes --no-doc
	@$(PYTHON) scripts/cross.py gates $(BUILD)/sizes/sizes.csv embedded/gates-held.txt
else
sizes:
	@$(CROSS_ENV) bash scripts/cross.sh sizes
	@$(CROSS_ENV) bash scripts/cross.sh lint misra >/dev/null || echo "sizes: note: misra-check fails, see make misra-check"
	@$(CROSS_ENV) bash scripts/cross.sh lint doc
	@$(MAKE) --no-print-directory readme
endif

embedded-check:
	@$(CROSS_ENV) bash scripts/cross.sh embedded

misra-check:
	@$(CROSS_ENV) bash scripts/cross.sh lint misra

tidy-check:
	@$(CROSS_ENV) bash scripts/cross.sh lint tidy

# Every step runs; any failure fails the target, with the list at the end.
ci-cross:
	@failed=(); for s in $(CROSS_CHECKS); do echo "=== $$s"; \
	  $(MAKE) --no-print-directory $$s || failed+=("$$s"); done; \
	if [ $${#failed[@]} -ne 0 ]; then echo "ci-cross: FAILED: $${failed[*]}"; exit 1; fi; echo "ci-cross: all passed"

# ---------------------------------------------------------------- cxx-compat
# cylinder_isect.h compiled as C++11 and C++17 by g++ and clang++ with the root Makefile's
# WARN_CXX set (not -Wold-style-cast: C casts are the only ones C99 has), in each precision
# configuration; each build of embedded/cxx_check.cpp must run and pass. Under V=2 on v2's
# header ($(V2_IQUOTE) finds it before the root's).
CXX_COMPAT_DIR  := $(BUILD)/cxx
CXX_COMPAT_WARN := $(filter-out -std=%,$(WARN_CXX))
CXX_COMPAT_CFGS := default CYL_NO_PRECISE CYL_NO_DOUBLE CYL_NO_FLOAT
# $(1) compiler, $(2) standard, $(3) configuration
define CXX_COMPAT_RULE
$(CXX_COMPAT_DIR)/cxx_check_$(1)_$(2)_$(3).ok: embedded/cxx_check.cpp $(HDR)
	@mkdir -p $$(@D)
	$(1) -std=$(2) $(CXX_COMPAT_WARN) -O2 $(if $(filter-out default,$(3)),-D$(3)) $(V2_IQUOTE) -I. $$< -lm -o $$(@:.ok=)
	@$$(@:.ok=) >$$(@:.ok=.txt) 2>&1 || { cat $$(@:.ok=.txt); echo "cxx-compat: FAIL $(1) -std=$(2) $(3)" >&2; exit 1; }
	@touch $$@
CXX_COMPAT_OKS += $(CXX_COMPAT_DIR)/cxx_check_$(1)_$(2)_$(3).ok
endef
CXX_COMPAT_OKS :=
$(foreach x,g++ clang++,$(foreach s,c++11 c++17,$(foreach c,$(CXX_COMPAT_CFGS),$(eval $(call CXX_COMPAT_RULE,$(x),$(s),$(c))))))

cxx-compat: $(CXX_COMPAT_OKS)
	@echo "cxx-compat: $(HDR): $(words $(CXX_COMPAT_OKS)) builds (g++, clang++; C++11, C++17; $(CXX_COMPAT_CFGS)) warning-free and passing"

# ---------------------------------------------------------------- cross-test
# The whole Unity suite (tests/test_*.c, and fuzz/'s replay and regression runners) built with
# Debian's linux-gnu cross compilers and run under qemu user mode, statically linked so that
# qemu needs no sysroot: aarch64, armhf (32-bit, VFPv3 without FMA, so the library's fmaf
# fallback runs) and s390x (big-endian). Same warnings as the native builds; ends with
# run-tests.sh's "N passed, M failed" line. CROSS_ARCHS picks architectures; CROSS_FUZZ=0 leaves
# the fuzz runners out; CROSS_TEST_CFLAGS is appended to the test builds (diagnosis only). With
# V=2 the same on v2's header (.ci/run): its pairs (N1) are vectors on aarch64, structs on the others.
CROSS_ARCHS       ?= aarch64 armhf s390x
CROSS_FUZZ        ?= 1
CROSS_TEST_CFLAGS ?=
CROSS_DIR         := $(BUILD)/cross
CROSS_CC_aarch64    := aarch64-linux-gnu-gcc $(V2_IQUOTE)
CROSS_QEMU_aarch64  := qemu-aarch64-static
CROSS_CC_armhf      := arm-linux-gnueabihf-gcc $(V2_IQUOTE)
CROSS_QEMU_armhf    := qemu-arm-static
# 32-bit glibc on a 64-bit host file system: readdir needs 64-bit offsets under qemu (without
# them the fuzz replay finds no corpus file and runs 0 tests).
CROSS_EXTRA_armhf   := -D_FILE_OFFSET_BITS=64
CROSS_CC_s390x      := s390x-linux-gnu-gcc $(V2_IQUOTE)
CROSS_QEMU_s390x    := qemu-s390x-static
# GCC on s390x in ISO C mode (-std=c99 implies -fexcess-precision=standard) evaluates float
# arithmetic in double (FLT_EVAL_METHOD 1, for glibc's float_t): the header refuses that with
# #error. -fexcess-precision=fast gives native single precision (FLT_EVAL_METHOD 0).
CROSS_EXTRA_s390x   := -fexcess-precision=fast
# The other areas' Unity runners that need nothing but libc: the fuzz corpus replay and the fuzz
# regression tests, without the MPFR reference (no cross build of libmpfr here: the reference
# comparisons run natively in make test; every other invariant runs here too).
CROSS_FUZZ_SRCS   := $(if $(filter-out 0,$(CROSS_FUZZ)),$(wildcard fuzz/replay.c fuzz/test_fuzz_regressions.c))
CROSS_FUZZ_FLAGS  := -Ifuzz -DFUZZ_CORPUS_DIR='"$(CURDIR)/fuzz/corpus"' -DFUZZ_GRID_DIR='"$(CURDIR)/fuzz/corpus_grid"' \
                     -DFUZZ_FINDINGS_DIR='"$(CURDIR)/fuzz/findings"' -DFZ_REF_ALWAYS=1
CROSS_TEST_HDRS   := $(HDR) $(wildcard tests/*.h tests/*.inc)
CROSS_FUZZ_HDRS   := $(HDR) $(wildcard fuzz/*.h) tests/contract/rt_calls.h

# $(1) architecture
define CROSS_ARCH_RULES
$(CROSS_DIR)/$(1)/unity.o: $(UNITY_C) | unity
	@mkdir -p $$(@D)
	$(CROSS_CC_$(1)) -std=c99 -O2 -w $(CROSS_EXTRA_$(1)) $(UNITY_FLAGS) -c $$< -o $$@
$(CROSS_DIR)/$(1)/%: tests/%.c $(CROSS_TEST_HDRS) $(CROSS_DIR)/$(1)/unity.o
	$(CROSS_CC_$(1)) $(WARN_C) -O2 $(CROSS_EXTRA_$(1)) $(CROSS_TEST_CFLAGS) $(UNITY_FLAGS) -I. -Itests $$< -x none $(CROSS_DIR)/$(1)/unity.o -static -lm -o $$@
$(CROSS_DIR)/$(1)/%: fuzz/%.c $(CROSS_FUZZ_HDRS) $(CROSS_DIR)/$(1)/unity.o
	$(CROSS_CC_$(1)) $(WARN_C) -O2 $(CROSS_EXTRA_$(1)) $(CROSS_TEST_CFLAGS) $(UNITY_FLAGS) -I. $(CROSS_FUZZ_FLAGS) $$< -x none $(CROSS_DIR)/$(1)/unity.o -static -lm -o $$@
# The runner run-tests.sh starts: the binary under qemu user mode.
$(CROSS_DIR)/$(1)/run-%: $(CROSS_DIR)/$(1)/%
	@printf '#!/bin/sh\n# %s under qemu user mode (generated by mk/cross.mk)\nexec %s "$$$$(dirname "$$$$0")/%s" "$$$$@"\n' $$* $(CROSS_QEMU_$(1)) $$* >$$@
	@chmod +x $$@
CROSS_RUNNERS += $(addprefix $(CROSS_DIR)/$(1)/run-,$(TEST_NAMES) $(basename $(notdir $(CROSS_FUZZ_SRCS))))
ifeq ($(V),2) # the batch (mk/batch.mk) in its portable form, or SSE2's on none of these: float and double
$(CROSS_DIR)/$(1)/batch_float $(CROSS_DIR)/$(1)/batch_double: $(CROSS_DIR)/$(1)/batch_%: tests/batch/batch.c $(BATCH_HDRS) $(CROSS_DIR)/$(1)/unity.o
	$(CROSS_CC_$(1)) $(WARN_C) -O2 $(CROSS_EXTRA_$(1)) $(CROSS_TEST_CFLAGS) $$(if $$(filter double,$$*),-DT_DOUBLE) $(UNITY_FLAGS) -I. $$< -x none $(CROSS_DIR)/$(1)/unity.o -static -lm -o $$@
CROSS_RUNNERS += $(CROSS_DIR)/$(1)/run-batch_float $(CROSS_DIR)/$(1)/run-batch_double
endif
endef
CROSS_RUNNERS :=
$(foreach a,$(CROSS_ARCHS),$(eval $(call CROSS_ARCH_RULES,$(a))))
# The binaries behind the run- wrappers are kept (not intermediate files make would delete).
.SECONDARY: $(join $(dir $(CROSS_RUNNERS)),$(patsubst run-%,%,$(notdir $(CROSS_RUNNERS))))

cross-test: unity $(CROSS_RUNNERS)
	@rm -rf $(RESULTS)/cross
	@bash scripts/run-tests.sh $(RESULTS)/cross $(CROSS_RUNNERS)
