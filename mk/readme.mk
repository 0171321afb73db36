# The README's usage snippet is compiled (strict warnings, gcc) and run by a Unity runner.
README_DIR := $(BUILD)/readme

$(README_DIR)/snippet.inc: README.md scripts/readme-snippet.py
	@mkdir -p $(@D)
	python3 scripts/readme-snippet.py README.md > $@

$(README_DIR)/test_readme: tests/readme/test_readme.c $(README_DIR)/snippet.inc cylinder_isect.h $(BUILD)/gcc-O0/unity.o
	$(GCC) $(WARN_C) -Wno-format-truncation -O1 $(UNITY_FLAGS) -I. -I$(README_DIR) $< -x none $(BUILD)/gcc-O0/unity.o -lm -o $@

RUNNERS += $(README_DIR)/test_readme

# The README's generated blocks (accuracy headline, fuzzing figures, sizes, scene recipes) are
# copies of the documents the commands write; `make readme` refreshes them, `make test` checks.
README_SYNC := headline=docs/accuracy.md fuzzfig=docs/fuzzing.md sizes=docs/embedded.md \
               recipes=docs/embedded.md
.PHONY: readme
readme:
	python3 scripts/sync-readme.py README.md $(README_SYNC)

$(README_DIR)/sync.stamp: README.md docs/accuracy.md docs/fuzzing.md docs/embedded.md scripts/sync-readme.py
	@mkdir -p $(@D)
	python3 scripts/sync-readme.py --check README.md $(README_SYNC)
	@touch $@
TEST_PREREQS += $(README_DIR)/sync.stamp
