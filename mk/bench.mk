# Exact reference, stiff/extreme case families, error-vs-time report (issue 3).
#   make test     also runs build/bench/test_accuracy (accuracy targets on a fixed-seed sample)
#   make report   full benchmark: bench/REPORT.md and bench/error_vs_time.png
#                 (BENCH_SEED, BENCH_N change the seed and the cases per family)
#   make insn     instructions per call of each variant under callgrind (INSN_FAMILIES)
#   make ablation the double API with and without its double-word correction (target 2 vs 4)
BENCH_BUILD  := $(BUILD)/bench
BENCH_SRCS   := bench/eval.c bench/cases.c ref/cyl_ref.c
BENCH_HDRS   := cylinder_isect.h bench/eval.h bench/cases.h bench/alt_formulations.h ref/cyl_ref.h
BENCH_INC    := -I. -Ibench -Iref
BENCH_LIBS   := -lmpfr -lgmp -lm
# Timing build: hardware sqrt and FMA, as the header recommends for speed on x86-64.
BENCH_OPT    ?= -O2 -march=native
BENCH_SEED   ?= 20261122
BENCH_N      ?= 6000
REPORT_VENV  := $(BUILD)/report-venv
# Which cylinder_isect.h the report measured (shown in REPORT.md).
BENCH_LIB_REV ?= $(shell git log -1 --format=%h -- cylinder_isect.h 2>/dev/null)$(shell git diff --quiet -- cylinder_isect.h 2>/dev/null || echo ' + uncommitted changes')
MATPLOTLIB   := matplotlib==3.9.2

$(BENCH_BUILD)/unity.o: $(UNITY_C) | unity
	@mkdir -p $(@D)
	$(GCC) -O2 $(UNITY_FLAGS) -w -c $< -o $@

# The accuracy runner: portable flags (no -march), as most users build.
$(BENCH_BUILD)/test_accuracy: bench/test_accuracy.c $(BENCH_SRCS) $(BENCH_HDRS) $(BENCH_BUILD)/unity.o
	@mkdir -p $(@D)
	$(GCC) $(WARN_C) -O2 $(UNITY_FLAGS) $(BENCH_INC) $< $(BENCH_SRCS) -x none $(BENCH_BUILD)/unity.o $(BENCH_LIBS) -o $@

# The measuring tools (bench, probe) show warnings without stopping on them, so that a warning
# in a header under development does not block measuring it; the test runner and the
# alt_check stamp above keep -Werror.
BENCH_WARN   := $(filter-out -Werror,$(WARN_C))

# The timing build; $(1): include directories searched before the project's (make ablation's
# copy of the header).
BENCH_CC      = $(GCC) $(BENCH_WARN) $(BENCH_OPT) -DEV_TIMING -DBENCH_CFLAGS='"$(BENCH_OPT)"' $(1) \
                $(BENCH_INC) bench/bench.c $(BENCH_SRCS) $(BENCH_LIBS)
$(BENCH_BUILD)/bench: bench/bench.c $(BENCH_SRCS) $(BENCH_HDRS)
	@mkdir -p $(@D)
	$(call BENCH_CC,) -o $@

# alt_formulations.h is used by other code (the viewer): strict C with clang and strict C++.
$(BENCH_BUILD)/alt_check.stamp: bench/alt_formulations.h cylinder_isect.h bench/insn.c
	@mkdir -p $(@D)
	echo '#include "bench/alt_formulations.h"' | $(CLANG) -x c $(WARN_C) -I. -fsyntax-only -
	echo '#include "bench/alt_formulations.h"' | $(CXX_GCC) -x c++ $(WARN_CXX) -I. -fsyntax-only -
	echo '#include "cyl_ref.h"' | $(CXX_GCC) -x c++ $(WARN_CXX) -I. -Iref -fsyntax-only -
	$(CLANG) $(WARN_C) $(BENCH_INC) -fsyntax-only $(BENCH_SRCS) bench/bench.c bench/insn.c
	@touch $@

# The same targets for the fast path's other arithmetic: the float API in float, and Kahan's
# FMA products (where this machine has FMA3).
$(BENCH_BUILD)/test_accuracy_narrow: bench/test_accuracy.c $(BENCH_SRCS) $(BENCH_HDRS) $(BENCH_BUILD)/unity.o
	@mkdir -p $(@D)
	$(GCC) $(WARN_C) -O2 -DCYL_FLOAT_WIDE=0 $(UNITY_FLAGS) $(BENCH_INC) $< $(BENCH_SRCS) -x none $(BENCH_BUILD)/unity.o $(BENCH_LIBS) -o $@
$(BENCH_BUILD)/test_accuracy_fma: bench/test_accuracy.c $(BENCH_SRCS) $(BENCH_HDRS) $(BENCH_BUILD)/unity.o
	@mkdir -p $(@D)
	$(GCC) $(WARN_C) -O2 -mfma $(UNITY_FLAGS) $(BENCH_INC) $< $(BENCH_SRCS) -x none $(BENCH_BUILD)/unity.o $(BENCH_LIBS) -o $@

RUNNERS      += $(BENCH_BUILD)/test_accuracy $(BENCH_BUILD)/test_accuracy_narrow
ifeq ($(HOST_FMA),1)
RUNNERS      += $(BENCH_BUILD)/test_accuracy_fma
endif
TEST_PREREQS += $(BENCH_BUILD)/alt_check.stamp $(BENCH_BUILD)/bench

$(REPORT_VENV)/.installed:
	$(PYTHON) -m venv $(REPORT_VENV)
	$(REPORT_VENV)/bin/pip install --quiet --disable-pip-version-check $(MATPLOTLIB)
	@touch $@

.PHONY: report
report: deps $(BENCH_BUILD)/bench $(REPORT_VENV)/.installed
	$(BENCH_BUILD)/bench --seed $(BENCH_SEED) --n $(BENCH_N) --json $(BENCH_BUILD)/results.json | tee $(BENCH_BUILD)/bench.txt
	BENCH_LIB_REV="$(BENCH_LIB_REV)" $(REPORT_VENV)/bin/python bench/report.py $(BENCH_BUILD)/results.json bench/REPORT.md bench/error_vs_time.png docs/accuracy.md
	$(MAKE) --no-print-directory readme

# Instructions per call under callgrind (exact on a shared machine; time is in the report).
# The flags of the callgrind figures quoted in the notes: hardware FMA, inline sqrt.
INSN_OPT     ?= -O2 -march=x86-64-v3 -fno-math-errno
INSN_FAMILIES ?= well grazing huge
$(BENCH_BUILD)/insn: bench/insn.c $(BENCH_SRCS) $(BENCH_HDRS)
	@mkdir -p $(@D)
	$(GCC) $(BENCH_WARN) $(INSN_OPT) -DEV_TIMING $(BENCH_INC) $< $(BENCH_SRCS) $(BENCH_LIBS) -o $@
TEST_PREREQS += $(BENCH_BUILD)/insn

.PHONY: insn
insn: deps $(BENCH_BUILD)/insn
	@bash scripts/insn.sh $(BENCH_BUILD)/insn "$(INSN_FAMILIES)"

$(BENCH_BUILD)/probe: bench/probe.c $(BENCH_SRCS) $(BENCH_HDRS)
	@mkdir -p $(@D)
	$(GCC) $(BENCH_WARN) -O2 $(BENCH_INC) $< $(BENCH_SRCS) $(BENCH_LIBS) -o $@
TEST_PREREQS += $(BENCH_BUILD)/probe

# What the double API's double-word correction costs and buys: the benchmark built a second
# time from a copy of the header without the two correction calls (scripts/ablate-correction.py
# says which), both builds run on the same cases, and their target-2 accuracy and target-4
# time ratios side by side. Minutes, not part of `make test`.
ABL_BUILD    := $(BENCH_BUILD)/ablation
ABL_N        ?= 3000
.PHONY: ablation
ablation: deps $(BENCH_BUILD)/bench
	@mkdir -p $(ABL_BUILD)
	$(PYTHON) scripts/ablate-correction.py patch cylinder_isect.h $(ABL_BUILD)/cylinder_isect.h
	$(call BENCH_CC,-I$(ABL_BUILD)) -o $(ABL_BUILD)/bench
	$(BENCH_BUILD)/bench --seed $(BENCH_SEED) --n $(ABL_N) --json $(ABL_BUILD)/with.json > /dev/null
	$(ABL_BUILD)/bench --seed $(BENCH_SEED) --n $(ABL_N) --json $(ABL_BUILD)/without.json > /dev/null
	@$(PYTHON) scripts/ablate-correction.py compare $(ABL_BUILD)/with.json $(ABL_BUILD)/without.json
