# Examples (issue 5): examples/minimal.c, the viewer, their tests and `make demo`.
#   make examples      build build/examples/{minimal,viewer,pngcmp}
#   make demo          open the viewer on the default scene (headless PNG without a display)
#   make examples-ref  re-render the reference PNGs (after a reviewed, intended change)
#   make examples-img  re-render the README images (docs/img/*.png)
#   make examples-bench  the frames-per-second figures of docs/examples.md
#   make examples-test the examples' Unity runner (renders against examples/ref, minimal.c)
#   make ci-viewer     the windowed viewer under Xvfb against the headless render
# The last two are steps of `make check` (not of `make test`: they need GLFW, libpng, Xvfb).
EX_DIR      := $(BUILD)/examples
EX_SCENES   := $(wildcard examples/scenes/*.txt)
EX_PKGS     := glfw3 gl libpng
EX_CFLAGS    = $(WARN_C) -O2 $(EX_ARCH) -D_POSIX_C_SOURCE=200809L \
               $(shell pkg-config --cflags $(EX_PKGS) 2>/dev/null)
EX_LIBS      = $(shell pkg-config --libs $(EX_PKGS) 2>/dev/null) -lpthread -lm
# The viewer is built for the machine it runs on (FMA for the library's error-free steps).
# Images do not depend on it: GCC's ISO C mode contracts no a*b+c, and fma() is exact anyway.
EX_ARCH     ?= -march=native
EX_INC      ?= -I. -Iexamples
EX_HDRS     := $(HDR) bench/alt_formulations.h examples/png_io.h
EX_DEMO_PNG := $(EX_DIR)/demo.png
EX_DEFAULT  := examples/scenes/molecule.txt

$(EX_DIR)/viewer: examples/viewer.c $(EX_HDRS)
	@mkdir -p $(@D)
	$(GCC) $(EX_CFLAGS) $(EX_INC) $< $(EX_LIBS) -o $@

# The viewer also has to pass clang's warnings.
$(EX_DIR)/viewer.clang.ok: examples/viewer.c $(EX_HDRS)
	@mkdir -p $(@D)
	$(CLANG) $(WARN_C) -O2 -D_POSIX_C_SOURCE=200809L $(shell pkg-config --cflags $(EX_PKGS) 2>/dev/null) $(EX_INC) -fsyntax-only $<
	@touch $@

$(EX_DIR)/pngcmp: examples/pngcmp.c examples/png_io.h
	@mkdir -p $(@D)
	$(GCC) $(EX_CFLAGS) $(EX_INC) $< $(shell pkg-config --libs libpng 2>/dev/null) -o $@

# minimal.c is what users copy: gcc, clang and C++ must all take it with the strict warnings.
$(EX_DIR)/minimal: examples/minimal.c $(HDR)
	@mkdir -p $(@D)
	$(GCC) $(WARN_C) -O2 -I. $< -lm -o $@
$(EX_DIR)/minimal-clang: examples/minimal.c $(HDR)
	@mkdir -p $(@D)
	$(CLANG) $(WARN_C) -O2 -I. $< -lm -o $@
$(EX_DIR)/minimal-cxx: examples/minimal.c $(HDR)
	@mkdir -p $(@D)
	$(CXX_GCC) -x c++ $(WARN_CXX) -O2 -I. $< -lm -o $@

$(EX_DIR)/test_examples: examples/test_examples.c examples/png_io.h $(BUILD)/gcc-O2/unity.o
	@mkdir -p $(@D)
	$(GCC) $(EX_CFLAGS) $(UNITY_FLAGS) $(EX_INC) -DVIEWER_BIN='"$(EX_DIR)/viewer"' \
	  -DMINIMAL_BIN='"$(EX_DIR)/minimal"' -DOUT_DIR='"$(EX_DIR)/test"' \
	  $< -x none $(BUILD)/gcc-O2/unity.o $(shell pkg-config --libs libpng 2>/dev/null) -lm -o $@

EX_PROGS := $(EX_DIR)/viewer $(EX_DIR)/viewer.clang.ok $(EX_DIR)/pngcmp $(EX_DIR)/minimal \
            $(EX_DIR)/minimal-clang $(EX_DIR)/minimal-cxx
.PHONY: examples demo examples-ref examples-img ci-viewer examples-bench examples-test
examples: $(EX_PROGS)

DEPS_GOALS_examples := demo examples examples-ref examples-img examples-bench examples-test ci-viewer
CHECK_TARGETS += examples-test ci-viewer

examples-test: unity $(EX_PROGS) $(EX_DIR)/test_examples
	@bash scripts/run-tests.sh $(RESULTS)/examples $(EX_DIR)/test_examples

# Opens the window when a display is there and the window opens (exit code 2 means it did
# not); otherwise renders headless and says where the PNG is. DEMO_ARGS go to the windowed
# viewer, e.g. `make demo DEMO_ARGS="--frames 30"` quits after 30 frames (for scripts).
DEMO_ARGS ?=
demo: deps examples
	@if [ -n "$${DISPLAY:-}$${WAYLAND_DISPLAY:-}" ]; then \
	  $(EX_DIR)/viewer $(DEMO_ARGS) $(EX_DEFAULT); rc=$$?; [ $$rc -ne 2 ] && exit $$rc; \
	fi; \
	$(EX_DIR)/viewer --headless --size 640x480 --out $(EX_DEMO_PNG) $(EX_DEFAULT) && \
	echo "no display: the default scene is rendered in $(EX_DEMO_PNG)"

examples-ref: $(EX_DIR)/viewer
	@mkdir -p examples/ref
	@for s in $(EX_SCENES); do n=$$(basename $$s .txt); \
	  $(EX_DIR)/viewer --headless --size 160x120 --out examples/ref/$$n.png $$s || exit 1; done

examples-img: $(EX_DIR)/viewer
	@mkdir -p docs/img
	@for s in $(EX_SCENES); do n=$$(basename $$s .txt); \
	  $(EX_DIR)/viewer --headless --size 640x480 --out docs/img/$$n.png $$s || exit 1; done
	@$(EX_DIR)/viewer --headless --size 640x480 --view error --split \
	  --out docs/img/pipes-error-split.png examples/scenes/pipes.txt

ci-viewer: $(EX_DIR)/viewer $(EX_DIR)/pngcmp
	@BUILD=$(BUILD) bash scripts/viewer-check.sh

# The figures of docs/examples.md: every scene at 640x480 with shadows (the viewer's default
# settings), frames and rays per second over a full orbit, plus CPU time per frame.
EX_BENCH_FRAMES ?= 60
examples-bench: $(EX_DIR)/viewer
	@for s in $(EX_SCENES); do $(EX_DIR)/viewer --bench $(EX_BENCH_FRAMES) $$s || exit 1; done
	@$(EX_DIR)/viewer --bench $(EX_BENCH_FRAMES) --double $(EX_DEFAULT)
	@$(EX_DIR)/viewer --bench $(EX_BENCH_FRAMES) --threads 1 $(EX_DEFAULT)
