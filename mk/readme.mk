# README.md (part of `make test`):
#   build/readme/test_readme  the usage snippet, compiled (strict warnings, gcc) and run by a
#                             Unity runner that also checks the output line the README states
#   build/readme/sync.stamp   the generated blocks match their sources, and every relative link
#                             and image names a file that exists
#   make readme               copy the generated blocks in (after `make report`)
README_DIR := $(BUILD)/readme

$(README_DIR)/snippet.inc: README.md scripts/sync-readme.py
	@mkdir -p $(@D)
	$(PYTHON) scripts/sync-readme.py --snippet README.md > $@.tmp && mv $@.tmp $@

$(README_DIR)/test_readme: tests/readme/test_readme.c $(README_DIR)/snippet.inc $(HDR) $(BUILD)/gcc-O0/unity.o
	$(GCC) $(WARN_C) -Wno-format-truncation -O1 $(UNITY_FLAGS) -I. -I$(README_DIR) $< -x none $(BUILD)/gcc-O0/unity.o -lm -o $@

RUNNERS += $(README_DIR)/test_readme

# The accuracy-and-cost table is written into docs/accuracy.md by `make report` (bench/report.py)
# and copied into README.md between the same `headline` markers; the batch's, into docs/batch.md by
# `make bench-batch`, between `batch` markers.
README_SYNC := headline=docs/accuracy.md batch=docs/batch.md
.PHONY: readme
readme:
	$(PYTHON) scripts/sync-readme.py README.md $(README_SYNC)

$(README_DIR)/sync.stamp: README.md docs/accuracy.md scripts/sync-readme.py $(wildcard docs/*.md)
	@mkdir -p $(@D)
	$(PYTHON) scripts/sync-readme.py --check README.md $(README_SYNC)
	@touch $@
TEST_PREREQS += $(README_DIR)/sync.stamp
