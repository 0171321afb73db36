# Instructions per call of v1 (./cylinder_isect.h) and v2 ($(COST_V2_DIR)/cylinder_isect.h)
# against the end-point routine, in a program that uses the library as a renderer does:
# bench/cost.c, built as a user builds it (gcc -std=c99 -O2, then -O2 -march=x86-64-v3).
#   make cost        callgrind counts: one table per -march setting, then v2's cost limits (issues
#                    28, 29) met or not and what each part (t_err bound, normal, CYL_PRECISE) adds
#                    to plain, also in build/cost/cost.md; fails when a limit that
#                    bench/cost-held.txt lists as met is no longer met
#   make cost-time   time per call and its ratio, median of COST_RUNS runs (build/cost/cost-time.md)
#   make cost-mix    make cost's counts by kind of instruction (move, convert, arith, decide, ...)
#                    for the loops COST_MIX_LOOPS names (build/cost/cost-mix.md)
# COST_V2_DIR (default v2): where v2's header is; without one the v2 columns say n/a.
# COST_N, COST_SEED: cases generated (those of finite height kept), their seed.
COST_BUILD    := $(BUILD)/cost
COST_V2_DIR   ?= v2
COST_N        ?= 6000
COST_SEED     ?= 20261122
COST_RUNS     ?= 5
COST_SRCS     := bench/cost.c bench/cases.c
COST_DEPS     := $(COST_SRCS) bench/cases.h bench/alt_formulations.h
# The compiler alone (GCC_ALONE, Makefile): cost picks each column's header itself.
COST_GCC      := $(GCC_ALONE)
# The project's warnings without -Werror, as the other measuring tools (a warning in a header
# under development must not block measuring it).
COST_WARN     := $(filter-out -Werror,$(WARN_C))
COST_MARCHES  := base v3
COST_OPT_base := -O2
COST_OPT_v3   := -O2 -march=x86-64-v3
# v2: `#include "cylinder_isect.h"` (in bench/cost.c and bench/alt_formulations.h) finds
# COST_V2_DIR's first; everything else comes from the repository.
COST_INC_v1   := -I.
COST_INC_v2   := -iquote $(abspath $(COST_V2_DIR)) -I.
COST_HDRS_v1  := cylinder_isect.h
COST_HDRS_v2  := $(wildcard $(COST_V2_DIR)/*.h)
COST_VERSIONS := v1 $(if $(wildcard $(COST_V2_DIR)/cylinder_isect.h),v2)
COST_KEYS     := $(foreach v,$(COST_VERSIONS),$(foreach m,$(COST_MARCHES),$(v)-$(m)))
COST_BINS     := $(addprefix $(COST_BUILD)/cost-,$(COST_KEYS))
COST_TSVS     := $(addprefix $(COST_BUILD)/insn-,$(addsuffix .tsv,$(COST_KEYS)))
COST_REPORT   := $(PYTHON) bench/cost_report.py
COST_TABLE_ARGS = --v2-dir $(COST_V2_DIR) --seed $(COST_SEED)
# callgrind counting cost_run alone, one dump per call of it (one per loop)
COST_CG       := valgrind --tool=callgrind --toggle-collect=cost_run --dump-after=cost_run
COST_MIX_LOOPS ?= 24 endpoint,24 intersect:plain,24 intersect:default,24 intersect:precise,$\
                  53 endpoint,53 intersect:plain,53 intersect:default,53 intersect:precise
DEPS_GOALS_cost := cost cost-time cost-mix

# One binary per version and -march setting. Its .flags file holds the command and is
# rewritten only when that changes (another COST_V2_DIR, other flags), which rebuilds it.
define COST_BIN_RULES
COST_CMD_$(1)-$(2) := $$(COST_GCC) $$(COST_WARN) $$(COST_OPT_$(2)) $$(COST_INC_$(1))
$(COST_BUILD)/cost-$(1)-$(2).flags: FORCE
	@mkdir -p $$(@D)
	@$$(call write_if_changed,$$(COST_CMD_$(1)-$(2)))
$(COST_BUILD)/cost-$(1)-$(2): $(COST_BUILD)/cost-$(1)-$(2).flags $(COST_DEPS) $(COST_HDRS_$(1))
	$$(COST_CMD_$(1)-$(2)) $(COST_SRCS) -lm -o $$@
endef
$(foreach v,v1 v2,$(foreach m,$(COST_MARCHES),$(eval $(call COST_BIN_RULES,$(v),$(m)))))

# One callgrind run per binary: the k-th dump counts the k-th loop bench/cost.c announces.
$(COST_BUILD)/insn-%.tsv: $(COST_BUILD)/cost-% bench/cost_report.py
	@rm -rf $(COST_BUILD)/cg-$* && mkdir -p $(COST_BUILD)/cg-$*
	$(COST_CG) --dump-instr=no \
	  --callgrind-out-file=$(COST_BUILD)/cg-$*/out $< --n $(COST_N) --seed $(COST_SEED) \
	  > $(COST_BUILD)/cg-$*/plan.txt 2> $(COST_BUILD)/cg-$*/valgrind.log \
	  || { tail -n 20 $(COST_BUILD)/cg-$*/valgrind.log >&2; exit 1; }
	@$(COST_REPORT) pair --key $* --cflags='$(COST_OPT_$(lastword $(subst -, ,$*)))' \
	  $(COST_BUILD)/cg-$*/plan.txt $(COST_BUILD)/cg-$* > $@.tmp && mv $@.tmp $@

.PHONY: cost cost-time cost-mix

# Counted afresh on every call (a few seconds); the binaries are rebuilt only when needed.
cost: deps
	@rm -f $(COST_BUILD)/insn-*.tsv
	@$(MAKE) --no-print-directory $(COST_TSVS)
	@$(COST_REPORT) insn --out $(COST_BUILD)/cost.md --held bench/cost-held.txt $(COST_TABLE_ARGS) $(COST_TSVS)

# COST_RUNS runs of every binary, interleaved (v1, v2, v1, ...), so that a slow spell of the
# machine falls on all of them.
cost-time: deps $(COST_BINS)
	@set -euo pipefail; rm -f $(COST_BUILD)/time-*.txt; \
	for k in $$(seq 1 $(COST_RUNS)); do \
	  for key in $(COST_KEYS); do \
	    f=$(COST_BUILD)/time-$$key.$$k.txt; echo "# key $$key" > $$f; \
	    $(COST_BUILD)/cost-$$key --time --n $(COST_N) --seed $(COST_SEED) >> $$f; \
	  done; \
	done
	@$(COST_REPORT) time --out $(COST_BUILD)/cost-time.md $(COST_TABLE_ARGS) $(COST_BUILD)/time-*.txt

# The same runs with each instruction's count kept (--dump-instr=yes), read by kind.
cost-mix: deps $(COST_BINS)
	@set -euo pipefail; for key in $(COST_KEYS); do \
	  d=$(COST_BUILD)/mix-$$key; rm -rf $$d && mkdir -p $$d; \
	  $(COST_CG) --dump-instr=yes \
	    --callgrind-out-file=$$d/out $(COST_BUILD)/cost-$$key --n $(COST_N) --seed $(COST_SEED) \
	    > $$d/plan.txt 2> $$d/valgrind.log || { tail -n 20 $$d/valgrind.log >&2; exit 1; }; \
	done
	@set -o pipefail; $(PYTHON) bench/cost_mix.py --loops '$(COST_MIX_LOOPS)' \
	  $(foreach k,$(COST_KEYS),$(k)=$(COST_BUILD)/cost-$(k):$(COST_BUILD)/mix-$(k)) \
	  | tee $(COST_BUILD)/cost-mix.md
