# The Unity tests of cylinder_isect.h (tests/README.md lists what each file covers).
# Run one test file in one configuration:
#     make test-one T=tangent CFG=gcc-O0
#   T: a topic of the contract tests, tests/contract/<T>.c (exact tangent errors t_range
#      invariance reference: both precisions, two runners), or a runner tests/test_<T>.c (api,
#      float, double); CFG: gcc-O0 gcc-O2 clang-O0 clang-O2 cxx asan (default gcc-O0).
#
# What make test runs from here:
#   tests/test_float.c, tests/test_double.c  the contract: every tests/contract/<topic>.c, written
#                                            once, in one runner per precision
#   tests/test_api.c                         precision-independent API facts
# in every configuration of the root Makefile (gcc/clang -O0/-O2, g++ as C++11, clang
# ASan+UBSan), and the compile-configuration checks of tests/config:
#   runners   CYL_NO_FLOAT, CYL_NO_DOUBLE, -DCYL_NO_PRECISE, user overrides (CYL_SQRTF/CYL_SQRT/
#             CYL_FMAF/CYL_FMA/CYL_DEF and the tolerance macros), two translation units linked
#             together (the last two also as C++11); the contract suite with CYL_FLOAT_WIDE=0,
#             float-only (CYL_NO_DOUBLE), the double API with CYL_NO_PRECISE, with
#             CYL_NO_FAST_PATH (not under V=2), with a hardware FMA (-mfma, where this
#             machine has one), built for size (-Os, V=2 only), and with every entry point forced inline
#             (tests/config/cfg_forced_inline.h; not under V=2, where that is the default)
#   prereq    -ffast-math (under V=2 also CYL_NO_FAST_PATH, CYL_INTERNAL) must stop the build at
#             the header's #error (gcc and clang)
# The runners that change the arithmetic (float_narrow, float_only, no_precise_double,
# no_dispatch_*, fma_*) build with the entry points out of line (CYL_OUT_OF_LINE, see the
# Makefile): the folding of constant options is gcc-O2's and clang-O2's to test.
# make check also builds and runs every topic alone (tests-topics: proves test-one's builds).

TESTS_CFG_DIR := $(BUILD)/tests-config

# ---------------------------------------------------------------- the contract tests
CONTRACT_FILES  := $(wildcard tests/contract/*.c tests/contract/*.h)
CONTRACT_TOPICS := $(patsubst tests/contract/%.c,%,$(wildcard tests/contract/*.c))

# test_float and test_double include tests/contract/, which the root TEST_DEPS does not list;
# nor does mk/cross.mk for its cross-compiled copies of the same runners.
$(filter %/test_float %/test_double,$(TEST_BINS)): $(CONTRACT_FILES)
ifneq ($(CROSS_DIR),)
$(foreach a,$(CROSS_ARCHS),$(CROSS_DIR)/$(a)/test_float $(CROSS_DIR)/$(a)/test_double): $(CONTRACT_FILES)
endif

# One topic alone, in configuration $(1): BUILD/$(1)/contract/<topic>_float and _double.
define TESTS_TOPIC_RULES
$(BUILD)/$(1)/contract/%_float: tests/contract/%.c $(CONTRACT_FILES) $(HDR) $(BUILD)/$(1)/unity.o
	@mkdir -p $$(@D)
	$$(CFG_CC_$(1)) $$(CFG_FLAGS_$(1)) $(UNITY_FLAGS) -I. $$< -x none $(BUILD)/$(1)/unity.o -lm -o $$@
$(BUILD)/$(1)/contract/%_double: tests/contract/%.c $(CONTRACT_FILES) $(HDR) $(BUILD)/$(1)/unity.o
	@mkdir -p $$(@D)
	$$(CFG_CC_$(1)) $$(CFG_FLAGS_$(1)) -DT_DOUBLE $(UNITY_FLAGS) -I. $$< -x none $(BUILD)/$(1)/unity.o -lm -o $$@
endef
$(foreach c,$(CONFIGS),$(eval $(call TESTS_TOPIC_RULES,$(c))))

CFG ?= gcc-O0
TEST_ONE_BINS := $(if $(filter $(CFG),$(CONFIGS)),$(strip \
  $(if $(filter $(T),$(CONTRACT_TOPICS)),$(BUILD)/$(CFG)/contract/$(T)_float $(BUILD)/$(CFG)/contract/$(T)_double, \
  $(if $(filter test_$(T),$(TEST_NAMES)),$(BUILD)/$(CFG)/test_$(T)))))

.PHONY: test-one
test-one: $(TEST_ONE_BINS)
	@[ -n "$(TEST_ONE_BINS)" ] || { echo "usage: make test-one T=TOPIC CFG=CONFIGURATION; TOPIC: $(CONTRACT_TOPICS) $(patsubst test_%,%,$(TEST_NAMES)); CONFIGURATION: $(CONFIGS)" >&2; exit 2; }
	@for r in $(TEST_ONE_BINS); do echo "=== $$r"; $$r || exit 1; done

# Every topic alone in gcc-O0, both precisions (a step of make check).
TESTS_TOPIC_BINS := $(foreach t,$(CONTRACT_TOPICS),$(BUILD)/gcc-O0/contract/$(t)_float $(BUILD)/gcc-O0/contract/$(t)_double)
.PHONY: tests-topics
tests-topics: unity $(TESTS_TOPIC_BINS)
	@bash scripts/run-tests.sh $(RESULTS)/topics $(TESTS_TOPIC_BINS)
CHECK_TARGETS += tests-topics

# ---------------------------------------------------------------- compile configurations
TESTS_CFG_HDRS := $(HDR) $(wildcard tests/config/*.h) $(CONTRACT_FILES)

# $(1) runner name, $(2) sources, $(3) extra flags, $(4) c or cxx
define TESTS_CFG_RUNNER
$(TESTS_CFG_DIR)/$(1): $(2) $(TESTS_CFG_HDRS) $(if $(filter cxx,$(4)),$(BUILD)/cxx/unity.o,$(BUILD)/gcc-O0/unity.o)
	@mkdir -p $$(@D)
	$(if $(filter cxx,$(4)),$(CXX_GCC) -x c++ $(WARN_CXX),$(GCC) $(WARN_C)) -O1 $(3) $(UNITY_FLAGS) -I. -Itests/config $(2) -x none $(if $(filter cxx,$(4)),$(BUILD)/cxx/unity.o,$(BUILD)/gcc-O0/unity.o) -lm -o $$@
TESTS_CFG_RUNNERS += $(TESTS_CFG_DIR)/$(1)
endef

TESTS_CFG_RUNNERS :=
$(eval $(call TESTS_CFG_RUNNER,no_float,tests/config/cfg_no_float.c,,c))
$(eval $(call TESTS_CFG_RUNNER,no_double,tests/config/cfg_no_double.c,,c))
$(eval $(call TESTS_CFG_RUNNER,no_precise,tests/config/cfg_no_precise.c,-DCYL_NO_PRECISE,c))
$(eval $(call TESTS_CFG_RUNNER,overrides,tests/config/cfg_overrides.c tests/config/cfg_overrides_ext.c,,c))
$(eval $(call TESTS_CFG_RUNNER,overrides_cxx,tests/config/cfg_overrides.c tests/config/cfg_overrides_ext.c,,cxx))
$(eval $(call TESTS_CFG_RUNNER,two_tu,tests/config/cfg_two_tu_main.c tests/config/cfg_two_tu_other.c,,c))
$(eval $(call TESTS_CFG_RUNNER,two_tu_cxx,tests/config/cfg_two_tu_main.c tests/config/cfg_two_tu_other.c,,cxx))
# The fast path's other arithmetic: the float API computed in float (as on targets without a
# double FPU), and Kahan's FMA products where the FMA is hardware (x86-64 with FMA3 only, so
# that the runner can execute here).
$(eval $(call TESTS_CFG_RUNNER,float_narrow,tests/test_float.c,-DCYL_FLOAT_WIDE=0 $(CYL_OUT_OF_LINE),c))
# The contract suite without the precise tier: as a float-only firmware builds it (CYL_NO_DOUBLE:
# float computed in float; v2 then defines CYL_NO_PRECISE, which also leaves the exact path's
# Newton steps out), and the double API under CYL_NO_PRECISE.
$(eval $(call TESTS_CFG_RUNNER,float_only,tests/test_float.c,-DCYL_NO_DOUBLE $(CYL_OUT_OF_LINE),c))
$(eval $(call TESTS_CFG_RUNNER,no_precise_double,tests/test_double.c,-DCYL_NO_PRECISE $(CYL_OUT_OF_LINE),c))
# v1 only (V=2 leaves these out): the contract suite with every entry point forced inline (the
# header's advice where a caller calls one from several places: each call site folds its own
# constant options), which is v2's default CYL_DEF, so the runner would repeat test_float; and
# without the fast path: the compensated solver answers every call (CYL_NO_FAST_PATH, which v2
# does not have).
ifneq ($(V),2)
$(eval $(call TESTS_CFG_RUNNER,forced_inline,tests/test_float.c,-include tests/config/cfg_forced_inline.h,c))
$(eval $(call TESTS_CFG_RUNNER,no_fast_float,tests/test_float.c,-DCYL_NO_FAST_PATH,c))
$(eval $(call TESTS_CFG_RUNNER,no_fast_double,tests/test_double.c,-DCYL_NO_FAST_PATH,c))
endif
# v2 only: CYL_PRECISE calls without the FMA copy (CYL_FMA_DISPATCH 0, the path of CPUs without
# the FMA), and that copy giving the same bits as that path (at -O2 in GNU C, where gcc contracts
# and vectorizes unless told not to).
ifeq ($(V),2)
$(eval $(call TESTS_CFG_RUNNER,no_dispatch_float,tests/test_float.c,-DCYL_FMA_DISPATCH=0 $(CYL_OUT_OF_LINE),c))
$(eval $(call TESTS_CFG_RUNNER,no_dispatch_double,tests/test_double.c,-DCYL_FMA_DISPATCH=0 $(CYL_OUT_OF_LINE),c))
$(eval $(call TESTS_CFG_RUNNER,dispatch,tests/config/cfg_dispatch_main.c tests/config/cfg_dispatch_other.c bench/cases.c,-Ibench -O2 -std=gnu99,c))
# and the pairs (N1) as structs, as targets without x86-64's or AArch64's vectors form them,
# giving the same bits as the vectors here.
$(eval $(call TESTS_CFG_RUNNER,pair_struct,tests/config/cfg_dispatch_main.c tests/config/cfg_dispatch_other.c bench/cases.c,-Ibench -O2 -std=gnu99 -DCFG_PAIR_STRUCT,c))
# and the other unit built by a C compiler without GNU C (tcc, which defines no __GNUC__): every
# environment hook's portable branch, as MSVC and other compilers take it (<math.h>'s sqrt and
# fma, <string.h>'s memcpy, struct pairs, Dekker's products, no dispatch, nothing forced inline),
# giving the same bits as gcc's builtins. tcc's <float.h> lacks FLT_EVAL_METHOD (0: SSE2 here).
$(TESTS_CFG_DIR)/portable_other.o: tests/config/cfg_dispatch_other.c $(TESTS_CFG_HDRS)
	@mkdir -p $(@D)
	tcc -std=c99 -Wall -Werror -DFLT_EVAL_METHOD=0 -I$(V2_ABS) -Itests/config -c $< -o $@
$(eval $(call TESTS_CFG_RUNNER,portable,tests/config/cfg_dispatch_main.c bench/cases.c $(TESTS_CFG_DIR)/portable_other.o,-Ibench -O2 -std=gnu99 -DCFG_PORTABLE -z noexecstack,c))
# Built for size (-Os, what a firmware uses; the last -O wins): the entry points are then not
# forced inline, and the exact path fills the caller's frame, which the caller answers
# (CYL__HANDBACK). (v1's test_float does not build at -Os with -Werror: gcc 12's
# -Wstringop-overflow in its order2.)
$(eval $(call TESTS_CFG_RUNNER,size_float,tests/test_float.c,-Os,c))
$(eval $(call TESTS_CFG_RUNNER,size_double,tests/test_double.c,-Os,c))
$(eval $(call TESTS_CFG_RUNNER,size_float_narrow,tests/test_float.c,-Os -DCYL_FLOAT_WIDE=0,c))
endif
ifeq ($(HOST_FMA),1)
$(eval $(call TESTS_CFG_RUNNER,fma_float,tests/test_float.c,-mfma $(CYL_OUT_OF_LINE),c))
$(eval $(call TESTS_CFG_RUNNER,fma_double,tests/test_double.c,-mfma $(CYL_OUT_OF_LINE),c))
$(eval $(call TESTS_CFG_RUNNER,fma_float_narrow,tests/test_float.c,-mfma -DCYL_FLOAT_WIDE=0 $(CYL_OUT_OF_LINE),c))
endif

# Each compiler is one argument (under V=2 it carries -iquote); HDR is where the #error must be.
# v1 refuses -ffast-math; v2 also the configuration macros it dropped (its "Gone in v2").
TESTS_REFUSED := -ffast-math$(if $(filter 2,$(V)),|-DCYL_NO_FAST_PATH|-DCYL_INTERNAL)
$(TESTS_CFG_DIR)/refused.stamp: tests/config/cfg_refused.c tests/config/check-refused.sh $(HDR)
	@CYL_HDR='$(HDR)' CYL_REFUSED='$(TESTS_REFUSED)' bash tests/config/check-refused.sh $@ '$(GCC)' '$(CLANG)'

.PHONY: tests-config
tests-config: $(TESTS_CFG_RUNNERS) $(TESTS_CFG_DIR)/refused.stamp

RUNNERS      += $(TESTS_CFG_RUNNERS)
TEST_PREREQS += $(TESTS_CFG_DIR)/refused.stamp

# Mutation check (not part of make test: it rebuilds the suite once per deliberate header bug).
.PHONY: tests-mutants
tests-mutants: unity $(BUILD)/gcc-O2/unity.o
	@$(PYTHON) tests/mutants.py --header $(HDR) $(BUILD)

# ---------------------------------------------------------------- the header's shape
# DESIGN.md's budgets for the rewritten header (v2/, or the root once it has replaced v1): at most
# 1,200 lines in all, a manual of at most 150, no function longer than 80; the batch header beside
# it is reported and its functions held to the same 80 (a step of make check). v1 is not held.
SHAPE_DIR ?= $(if $(wildcard v2/cylinder_isect.h),v2,.)
.PHONY: shape
shape:
	@$(PYTHON) scripts/shape.py --self-test
	@$(PYTHON) scripts/shape.py $(SHAPE_DIR)/cylinder_isect.h $(wildcard $(SHAPE_DIR)/cylinder_isect_batch.h)
CHECK_TARGETS += shape
