# Fuzzing (issue 4): libFuzzer harnesses, the corpus replay inside `make test`, coverage.
#   make fuzz             run each harness for FUZZ_SECONDS (default 60), FUZZ_JOBS at once (default:
#                         one per core); fails on any finding
#   make fuzz-seeds       regenerate the seed inputs into build/fuzz/seeds
#   make fuzz-merge       minimise seeds + fuzz/corpus* + what `make fuzz` found into fuzz/corpus*
#   make fuzz-cov         line and branch coverage of cylinder_isect.h reached by the corpus
#   make fuzz-replay      only the replay runners (also part of `make test`)
#   make fuzz-short       each harness for FUZZ_CI_SECONDS (default 35): the step of `make check`
# Recipe and figures: docs/fuzzing.md.
FUZZ_SECONDS  ?= 60
# 35 s per harness in `make check`, starting from the committed corpora.
FUZZ_CI_SECONDS ?= 35
# Harnesses running at once (each one is single-threaded): every core, so that each has one.
FUZZ_JOBS ?= $(shell getconf _NPROCESSORS_ONLN 2>/dev/null || echo 1)
DEPS_GOALS_fuzz := fuzz fuzz-build fuzz-seeds fuzz-merge fuzz-cov fuzz-short
CHECK_TARGETS += fuzz-short
FUZZ_DIR      := $(BUILD)/fuzz
FUZZ_HARNESSES := fuzz_isect fuzz_grid
FUZZ_CORPUS_fuzz_isect := fuzz/corpus
FUZZ_CORPUS_fuzz_grid  := fuzz/corpus_grid
# v2 only: the batch (v2/cylinder_isect_batch.h) against the scalar loops it stands for.
FUZZ_CORPUS_fuzz_batch := fuzz/corpus_batch
# and built float-only (CYL_NO_DOUBLE: the filter and the call both in float, as on a firmware),
# on the same corpus (fuzz-merge merges what it found into fuzz_batch's, by fuzz_batch's coverage)
FUZZ_CORPUS_fuzz_batch_float_only := fuzz/corpus_batch
ifeq ($(V),2)
FUZZ_HARNESSES += fuzz_batch fuzz_batch_float_only
endif
# What fuzz-merge adds to each corpus besides what make fuzz found: the seeds, and for fuzz_batch
# what fuzz_batch_float_only found (which merges into it, not on its own).
FUZZ_SEEDS_fuzz_isect := $(FUZZ_DIR)/seeds
FUZZ_SEEDS_fuzz_grid  := $(FUZZ_DIR)/seeds_grid
FUZZ_SEEDS_fuzz_batch := $(FUZZ_DIR)/work/fuzz_batch_float_only
FUZZ_MERGED := $(filter-out fuzz_batch_float_only,$(FUZZ_HARNESSES))
FUZZ_HDRS     := $(HDR) fuzz/fuzz_check.h fuzz/fuzz_grid.h fuzz/fuzz_ref.h tests/contract/rt_calls.h $(if $(filter 2,$(V)),$(V2_DIR)/cylinder_isect_batch.h)
# The harness runs where it is built: a real FMA makes the library's error-free steps fast.
# The gcc replay is built without it, so libm's fma path is checked too.
FUZZ_ARCH     ?= -march=native
FUZZ_SAN      := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
FUZZ_CFLAGS   := $(WARN_C) -g -O1 $(FUZZ_ARCH) -fsanitize=fuzzer $(FUZZ_SAN) -I. -Ifuzz $(FUZZ_EXTRA)
LLVM_PROFDATA ?= $(firstword $(shell command -v llvm-profdata llvm-profdata-14 2>/dev/null) llvm-profdata)
LLVM_COV      ?= $(firstword $(shell command -v llvm-cov llvm-cov-14 2>/dev/null) llvm-cov)

# The exact reference (ref/, MPFR) plugs in when it is there.
ifneq ($(wildcard ref/cyl_ref.c),)
FUZZ_REF_DEF  := -DFUZZ_HAVE_REF -Iref
FUZZ_REF_LIBS := -lmpfr -lgmp
FUZZ_REF_OBJ_CLANG := $(FUZZ_DIR)/cyl_ref-san.o
FUZZ_REF_OBJ_GCC   := $(FUZZ_DIR)/cyl_ref-gcc.o
FUZZ_REF_OBJ_NOPR  := $(FUZZ_DIR)/cyl_ref-noprecise.o
FUZZ_REF_OBJ_COV   := $(FUZZ_DIR)/cyl_ref-cov.o
endif

# The reference is another area's code: built once per flavour, not instrumented for coverage.
$(FUZZ_DIR)/cyl_ref-san.o: ref/cyl_ref.c ref/cyl_ref.h $(HDR)
	@mkdir -p $(@D)
	$(CLANG) -std=c99 -g -O1 $(FUZZ_SAN) -I. -Iref -c $< -o $@
$(FUZZ_DIR)/cyl_ref-gcc.o: ref/cyl_ref.c ref/cyl_ref.h $(HDR)
	@mkdir -p $(@D)
	$(GCC) -std=c99 -O2 -I. -Iref -c $< -o $@
$(FUZZ_DIR)/cyl_ref-noprecise.o: ref/cyl_ref.c ref/cyl_ref.h $(HDR)
	@mkdir -p $(@D)
	$(GCC) -std=c99 -O2 -DCYL_NO_PRECISE -I. -Iref -c $< -o $@
$(FUZZ_DIR)/cyl_ref-cov.o: ref/cyl_ref.c ref/cyl_ref.h $(HDR)
	@mkdir -p $(@D)
	$(CLANG) -std=c99 -O1 -I. -Iref -c $< -o $@

# ---------------------------------------------------------------- libFuzzer harnesses
# harness.flags holds the compile command and is rewritten only when it changes (another
# FUZZ_ARCH or FUZZ_EXTRA), which rebuilds both harnesses.
FUZZ_CMD := $(CLANG) $(FUZZ_CFLAGS) $(FUZZ_REF_DEF)
$(FUZZ_DIR)/harness.flags: FORCE
	@mkdir -p $(@D)
	@$(call write_if_changed,$(FUZZ_CMD))
$(FUZZ_DIR)/fuzz_%: fuzz/fuzz_%.c $(FUZZ_HDRS) $(FUZZ_REF_OBJ_CLANG) $(FUZZ_DIR)/harness.flags
	$(FUZZ_CMD) $< -x none $(FUZZ_REF_OBJ_CLANG) $(FUZZ_REF_LIBS) -lm -o $@
$(FUZZ_DIR)/fuzz_batch_float_only: fuzz/fuzz_batch.c $(FUZZ_HDRS) $(FUZZ_DIR)/harness.flags
	$(FUZZ_CMD) -DCYL_NO_DOUBLE $< -lm -o $@

.PHONY: fuzz fuzz-build fuzz-seeds fuzz-merge fuzz-cov fuzz-replay fuzz-short
fuzz-build: $(addprefix $(FUZZ_DIR)/,$(FUZZ_HARNESSES))

# Each harness runs on a scratch corpus in build/ plus the committed one (new inputs never land in
# git); a violation aborts that harness, libFuzzer writes the input to build/fuzz/artifacts/, the
# other harnesses still run, and make fails at the end.
fuzz: fuzz-build
	@mkdir -p $(FUZZ_DIR)/artifacts
	@one() { h=$$1; c=$$2; rm -f $(FUZZ_DIR)/$$h.rc; mkdir -p $(FUZZ_DIR)/work/$$h; \
	  $(FUZZ_DIR)/$$h -max_total_time=$(FUZZ_SECONDS) -print_final_stats=1 -max_len=512 \
	    -artifact_prefix=$(FUZZ_DIR)/artifacts/$$h- $(FUZZ_DIR)/work/$$h $$c >$(FUZZ_DIR)/$$h.log 2>&1; \
	  echo $$? >$(FUZZ_DIR)/$$h.rc; }; \
	for hc in $(foreach h,$(FUZZ_HARNESSES),$(h):$(FUZZ_CORPUS_$(h))); do h=$${hc%%:*}; c=$${hc#*:}; \
	  while [ "$$(jobs -rp | wc -l)" -ge $(FUZZ_JOBS) ]; do wait -n; done; \
	  echo "== $$h: $(FUZZ_SECONDS) s on $$c"; one $$h $$c & \
	done; wait; \
	bad=0; for h in $(FUZZ_HARNESSES); do \
	  if [ "$$(cat $(FUZZ_DIR)/$$h.rc 2>/dev/null)" = 0 ]; then \
	    echo "$$h:"; grep -E 'stat::number_of_executed_units|stat::average_exec_per_sec' $(FUZZ_DIR)/$$h.log; \
	  else \
	    grep -m1 -B1 'ERROR: libFuzzer' $(FUZZ_DIR)/$$h.log | head -n 1 | cut -c1-400; \
	    grep 'Test unit written' $(FUZZ_DIR)/$$h.log; \
	    echo "FINDING in $$h (log: $(FUZZ_DIR)/$$h.log; replay: $(FUZZ_DIR)/replay-gcc -v FILE)"; bad=1; \
	  fi; \
	done; exit $$bad

fuzz-short:
	@$(MAKE) --no-print-directory fuzz FUZZ_SECONDS=$(FUZZ_CI_SECONDS)

$(FUZZ_DIR)/gen_seeds: fuzz/gen_seeds.c fuzz/fuzz_check.h $(HDR)
	@mkdir -p $(@D)
	$(GCC) $(WARN_C) -O1 -I. -Ifuzz $< -lm -o $@
fuzz-seeds: $(FUZZ_DIR)/gen_seeds
	rm -rf $(FUZZ_DIR)/seeds $(FUZZ_DIR)/seeds_grid && mkdir -p $(FUZZ_DIR)/seeds $(FUZZ_DIR)/seeds_grid
	$(FUZZ_DIR)/gen_seeds $(FUZZ_DIR)/seeds $(FUZZ_DIR)/seeds_grid

# Keep only inputs that add coverage (libFuzzer -merge=1), then replace the committed corpora.
fuzz-merge: fuzz-build fuzz-seeds
	@set -e; for t in $(foreach h,$(FUZZ_MERGED),$(h):$(FUZZ_CORPUS_$(h)):$(FUZZ_SEEDS_$(h))); do \
	  h=$${t%%:*}; c=$${t#*:}; extra=$${c#*:}; c=$${c%%:*}; \
	  rm -rf $(FUZZ_DIR)/merged/$$h && mkdir -p $(FUZZ_DIR)/merged/$$h $(FUZZ_DIR)/work/$$h $(FUZZ_DIR)/artifacts $$c $$extra; \
	  $(FUZZ_DIR)/$$h -merge=1 -use_counters=0 -artifact_prefix=$(FUZZ_DIR)/artifacts/merge-$$h- $(FUZZ_DIR)/merged/$$h $$c $$extra $(FUZZ_DIR)/work/$$h >$(FUZZ_DIR)/$$h-merge.log 2>&1 \
	    || { tail -n 20 $(FUZZ_DIR)/$$h-merge.log; exit 1; }; \
	  rm -f $$c/* && cp $(FUZZ_DIR)/merged/$$h/* $$c/; \
	  echo "$$c: $$(ls $$c | wc -l) inputs"; \
	done

# ---------------------------------------------------------------- replay inside `make test`
FUZZ_REPLAY_DEFS := -DFUZZ_CORPUS_DIR='"$(CURDIR)/fuzz/corpus"' -DFUZZ_GRID_DIR='"$(CURDIR)/fuzz/corpus_grid"' \
                    -DFZ_REF_ALWAYS=1 $(FUZZ_REF_DEF)
FUZZ_FINDINGS_DEF := -DFUZZ_FINDINGS_DIR='"$(CURDIR)/fuzz/findings"'

$(FUZZ_DIR)/replay-gcc: fuzz/replay.c $(FUZZ_HDRS) $(BUILD)/gcc-O2/unity.o $(FUZZ_REF_OBJ_GCC)
	@mkdir -p $(@D)
	$(GCC) $(WARN_C) -O2 $(UNITY_FLAGS) -I. -Ifuzz $(FUZZ_REPLAY_DEFS) $< -x none $(BUILD)/gcc-O2/unity.o \
	  $(FUZZ_REF_OBJ_GCC) $(FUZZ_REF_LIBS) -lm -o $@
# The same corpus with the precise tier compiled out: CYL_PRECISE must then be CYL_E_OPTION.
$(FUZZ_DIR)/replay-noprecise: fuzz/replay.c $(FUZZ_HDRS) $(BUILD)/gcc-O2/unity.o $(FUZZ_REF_OBJ_NOPR)
	@mkdir -p $(@D)
	$(GCC) $(WARN_C) -O2 -DCYL_NO_PRECISE $(UNITY_FLAGS) -I. -Ifuzz $(FUZZ_REPLAY_DEFS) $< -x none \
	  $(BUILD)/gcc-O2/unity.o $(FUZZ_REF_OBJ_NOPR) $(FUZZ_REF_LIBS) -lm -o $@
# At -O0, as the asan configuration (Makefile): every load keeps its check, and it builds in a
# ninth of -O1's time (v2: 1.4 s, not 11.9); the harnesses run -O1 code under the sanitizers.
$(FUZZ_DIR)/replay-asan: fuzz/replay.c $(FUZZ_HDRS) $(BUILD)/asan/unity.o $(FUZZ_REF_OBJ_CLANG)
	@mkdir -p $(@D)
	$(CLANG) $(WARN_C) -g -O0 $(FUZZ_SAN) $(UNITY_FLAGS) -I. -Ifuzz $(FUZZ_REPLAY_DEFS) $< -x none \
	  $(BUILD)/asan/unity.o $(FUZZ_REF_OBJ_CLANG) $(FUZZ_REF_LIBS) -lm -o $@
# One named Unity test per finding (fuzz/findings/), see docs/fuzzing.md.
$(FUZZ_DIR)/test_fuzz_regressions: fuzz/test_fuzz_regressions.c $(FUZZ_HDRS) $(BUILD)/gcc-O2/unity.o $(FUZZ_REF_OBJ_GCC)
	@mkdir -p $(@D)
	$(GCC) $(WARN_C) -O2 $(UNITY_FLAGS) -I. -Ifuzz $(FUZZ_REPLAY_DEFS) $(FUZZ_FINDINGS_DEF) $< -x none \
	  $(BUILD)/gcc-O2/unity.o $(FUZZ_REF_OBJ_GCC) $(FUZZ_REF_LIBS) -lm -o $@

# The same in GNU C mode with a hardware FMA, where gcc contracts products into sums across
# statements by default (-ffp-contract=fast): the header must keep its error-free
# transformations apart there too (finding 33).
$(FUZZ_DIR)/test_fuzz_regressions_gnu: fuzz/test_fuzz_regressions.c $(FUZZ_HDRS) $(BUILD)/gcc-O2/unity.o $(FUZZ_REF_OBJ_GCC)
	@mkdir -p $(@D)
	$(GCC) $(filter-out -std=c99,$(WARN_C)) -std=gnu99 -mfma -O2 $(UNITY_FLAGS) -I. -Ifuzz $(FUZZ_REPLAY_DEFS) \
	  $(FUZZ_FINDINGS_DEF) $< -x none $(BUILD)/gcc-O2/unity.o $(FUZZ_REF_OBJ_GCC) $(FUZZ_REF_LIBS) -lm -o $@

FUZZ_RUNNERS := $(FUZZ_DIR)/replay-gcc $(FUZZ_DIR)/replay-noprecise $(FUZZ_DIR)/replay-asan \
                $(FUZZ_DIR)/test_fuzz_regressions
ifeq ($(HOST_FMA),1)
FUZZ_RUNNERS += $(FUZZ_DIR)/test_fuzz_regressions_gnu
endif
RUNNERS += $(FUZZ_RUNNERS)

fuzz-replay: unity $(FUZZ_RUNNERS)
	@bash scripts/run-tests.sh $(RESULTS)/fuzz $(FUZZ_RUNNERS)

# ---------------------------------------------------------------- coverage
# The replay driver built with clang's source-based coverage, run over both corpora and the
# findings; the report covers the header under test ($(HDR)) only.
$(FUZZ_DIR)/replay-cov: fuzz/replay.c $(FUZZ_HDRS) $(UNITY_C) $(FUZZ_REF_OBJ_COV)
	@mkdir -p $(@D)
	$(CLANG) $(WARN_C) -O0 -fprofile-instr-generate -fcoverage-mapping $(UNITY_FLAGS) -I. -Ifuzz \
	  $(FUZZ_REPLAY_DEFS) $< -x none $(FUZZ_DIR)/unity-cov.o $(FUZZ_REF_OBJ_COV) $(FUZZ_REF_LIBS) -lm -o $@
$(FUZZ_DIR)/replay-cov: $(FUZZ_DIR)/unity-cov.o
$(FUZZ_DIR)/unity-cov.o: $(UNITY_C) | unity
	@mkdir -p $(@D)
	$(CLANG) -O0 $(UNITY_FLAGS) -w -c $< -o $@

# The findings (fuzz/findings/) count too; an open one may fail there without stopping the report.
fuzz-cov: unity $(FUZZ_DIR)/replay-cov
	@rm -f $(FUZZ_DIR)/cov*.profraw
	LLVM_PROFILE_FILE=$(FUZZ_DIR)/cov-corpus.profraw $(FUZZ_DIR)/replay-cov >$(FUZZ_DIR)/cov-replay.txt 2>&1 || \
	  { tail -n 20 $(FUZZ_DIR)/cov-replay.txt; exit 1; }
	-LLVM_PROFILE_FILE=$(FUZZ_DIR)/cov-findings.profraw $(FUZZ_DIR)/replay-cov -v fuzz/findings/* \
	  >$(FUZZ_DIR)/cov-findings.txt 2>&1
	$(LLVM_PROFDATA) merge -sparse $(FUZZ_DIR)/cov-corpus.profraw $(FUZZ_DIR)/cov-findings.profraw -o $(FUZZ_DIR)/cov.profdata
	@bash fuzz/coverage.sh "$(LLVM_COV)" $(FUZZ_DIR)/replay-cov $(FUZZ_DIR)/cov.profdata $(FUZZ_DIR) $(HDR)
