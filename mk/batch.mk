# The batch (one ray against many cylinders, v2/cylinder_isect_batch.h; issue 31), staged beside
# v2's header until v2 replaces v1.
#   make test V=2      also runs tests/batch/batch.c (float and double) in every configuration of
#                      the root Makefile, and built for x86-64-v3 (AVX2), for x86-64-v4 (AVX-512,
#                      where this machine has it), in the batch's portable form, and the float API
#                      computed in float (CYL_FLOAT_WIDE=0; CYL_NO_DOUBLE at -Os); make cross-test
#                      V=2 runs it on each architecture it builds for
#   make bench-batch   ns per test of the batch against the scalar loop, float and double, N = 1024,
#                      4096, 65536 and 2^20, for each form this machine runs: -O2 (SSE2), the
#                      portable form, x86-64-v3 (AVX2), x86-64-v4 (AVX-512, with 256-bit vectors,
#                      the default, and 512-bit ones); the median of
#                      BENCH_BATCH_RUNS timings, in one run (build/bench-batch/bench-batch.md), and
#                      issue 31's limits at N = 4096 met or not; docs/batch.md gets the N = 4096
#                      rows, which `make readme` copies into README.md
BATCH_HDRS := v2/cylinder_isect.h v2/cylinder_isect_batch.h
HOST_AVX512 := $(shell grep -qw avx512f /proc/cpuinfo 2>/dev/null && test "$$(uname -m)" = x86_64 && echo 1)
DEPS_GOALS_batch := bench-batch

ifeq ($(V),2)
# $(1) configuration, $(2) runner name, $(3) extra flags (the configuration's own flags first),
# $(4) the APIs: float double, or float alone
define BATCH_RUNNER
$(BUILD)/$(1)/$(2)_float $(BUILD)/$(1)/$(2)_double: $(BUILD)/$(1)/$(2)_%: tests/batch/batch.c $(BATCH_HDRS) $(BUILD)/$(1)/unity.o
	@mkdir -p $$(@D)
	$$(CFG_CC_$(1)) $$(CFG_FLAGS_$(1)) $(3) $$(if $$(filter double,$$*),-DT_DOUBLE) $(UNITY_FLAGS) -I. $$< -x none $(BUILD)/$(1)/unity.o -lm -o $$@
RUNNERS += $(foreach p,$(or $(4),float double),$(BUILD)/$(1)/$(2)_$(p))
endef
$(foreach c,$(CONFIGS),$(eval $(call BATCH_RUNNER,$(c),batch)))
# The forms below change the batch's arithmetic (vectors, working type), not how calls inline:
# their entry points out of line (CYL_OUT_OF_LINE, as the root Makefile's configuration runners),
# which halves their compiling; gcc-O2's and clang-O2's batch runners keep every call site folding.
$(eval $(call BATCH_RUNNER,gcc-O2,batch_portable,-DCYL_BATCH_PORTABLE $(CYL_OUT_OF_LINE)))
# The float API's filter and call both in float (CYL_FLOAT_WIDE 0: its own bound factor and range),
# and as a float-only firmware builds it (CYL_NO_DOUBLE, no vectors, for size).
$(eval $(call BATCH_RUNNER,gcc-O2,batch_narrow,-DCYL_FLOAT_WIDE=0 $(CYL_OUT_OF_LINE),float))
$(eval $(call BATCH_RUNNER,gcc-O2,batch_float_only,-DCYL_NO_DOUBLE -DCYL_BATCH_PORTABLE -Os,float))
ifeq ($(shell uname -m),x86_64)
$(eval $(call BATCH_RUNNER,gcc-O2,batch_avx2,-march=x86-64-v3 $(CYL_OUT_OF_LINE)))
$(eval $(call BATCH_RUNNER,clang-O2,batch_avx2,-march=x86-64-v3 $(CYL_OUT_OF_LINE)))
$(eval $(call BATCH_RUNNER,gcc-O2,batch_avx2_narrow,-march=x86-64-v3 -DCYL_FLOAT_WIDE=0 $(CYL_OUT_OF_LINE),float))
endif
ifeq ($(HOST_AVX512),1)
$(eval $(call BATCH_RUNNER,gcc-O2,batch_avx512,-march=x86-64-v4 $(CYL_OUT_OF_LINE)))
$(eval $(call BATCH_RUNNER,gcc-O2,batch_avx512_zmm,-march=x86-64-v4 -DCYL_BATCH_VECTOR_BYTES=64 $(CYL_OUT_OF_LINE)))
endif
endif

# ---------------------------------------------------------------- make bench-batch
BENCH_BATCH_DIR   := build/bench-batch
BENCH_BATCH_RUNS  ?= 5
BENCH_BATCH_TESTS ?= 4e6
BENCH_BATCH_KEYS  := sse2 portable $(if $(filter x86_64,$(shell uname -m)),avx2) $(if $(HOST_AVX512),avx512 avx512zmm)
BENCH_BATCH_FLAGS_sse2     := -O2
BENCH_BATCH_FLAGS_portable := -O2 -DCYL_BATCH_PORTABLE
BENCH_BATCH_FLAGS_avx2     := -O2 -march=x86-64-v3
BENCH_BATCH_FLAGS_avx512   := -O2 -march=x86-64-v4
BENCH_BATCH_FLAGS_avx512zmm := -O2 -march=x86-64-v4 -DCYL_BATCH_VECTOR_BYTES=64
$(BENCH_BATCH_DIR)/batch-%: bench/batch.c $(BATCH_HDRS)
	@mkdir -p $(@D)
	$(GCC_ALONE) $(WARN_C) $(BENCH_BATCH_FLAGS_$*) -iquote $(abspath v2) $< -lm -o $@

.PHONY: bench-batch
bench-batch: deps $(addprefix $(BENCH_BATCH_DIR)/batch-,$(BENCH_BATCH_KEYS))
	@set -euo pipefail; { \
	  $(foreach k,$(BENCH_BATCH_KEYS),$(BENCH_BATCH_DIR)/batch-$(k) --key "$(k): $(BENCH_BATCH_FLAGS_$(k))" --runs $(BENCH_BATCH_RUNS) --tests $(BENCH_BATCH_TESTS);) \
	} | $(PYTHON) bench/batch_report.py --cpu "$$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//')" \
	  --gcc "$$($(GCC_ALONE) -dumpfullversion)" --runs $(BENCH_BATCH_RUNS) --tests $(BENCH_BATCH_TESTS) \
	  --out $(BENCH_BATCH_DIR)/bench-batch.md --doc docs/batch.md
