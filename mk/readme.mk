# The README's usage snippet is compiled (strict warnings, gcc) and run by a Unity runner.
README_DIR := $(BUILD)/readme

$(README_DIR)/snippet.inc: README.md scripts/readme-snippet.py
	@mkdir -p $(@D)
	python3 scripts/readme-snippet.py README.md > $@

$(README_DIR)/test_readme: tests/readme/test_readme.c $(README_DIR)/snippet.inc cylinder_isect.h $(BUILD)/gcc-O0/unity.o
	$(GCC) $(WARN_C) -Wno-format-truncation -O1 $(UNITY_FLAGS) -I. -I$(README_DIR) $< -x none $(BUILD)/gcc-O0/unity.o -lm -o $@

RUNNERS += $(README_DIR)/test_readme
