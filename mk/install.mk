# Install and consume (issue 18).
#   make install    PREFIX=/usr/local DESTDIR= : the header, a pkg-config file and a CMake package
#                   (target cylinder_isect::cylinder_isect), version from the header's
#                   CYL_VERSION_MAJOR/MINOR/PATCH:
#                     $(INCLUDEDIR)/cylinder_isect.h
#                     $(PKGCONFIGDIR)/cylinder_isect.pc
#                     $(CMAKEDIR)/cylinder_isectConfig.cmake, cylinder_isectConfigVersion.cmake
#   make uninstall  removes them (same PREFIX and DESTDIR)
#   make install-check  (a step of make check) a consumer program (tests/consumer/) built and
#                   run through pkg-config and find_package after `make install DESTDIR=<tmp>`,
#                   through add_subdirectory and FetchContent of the source tree; the CMake
#                   install rules (CMakeLists.txt) must install the same files, and make
#                   uninstall must leave nothing behind.
#   make install V=2, make install-check V=2  the same with v2's header ($(HDR)) as the one
#                   installed: the source tree that add_subdirectory, FetchContent and CMake's
#                   install rules read is then a copy of the root's CMakeLists.txt and cmake/
#                   with $(HDR) as its cylinder_isect.h ($(BUILD)/install-check/src), so that
#                   issue 30's swap can be checked to change nothing for a user before it is made.
PREFIX       ?= /usr/local
DESTDIR      ?=
INCLUDEDIR   ?= $(PREFIX)/include
LIBDIR       ?= $(PREFIX)/lib
PKGCONFIGDIR ?= $(LIBDIR)/pkgconfig
CMAKEDIR     ?= $(LIBDIR)/cmake/cylinder_isect
INSTALL      ?= install

CYL_VERSION_PART = $(shell sed -n 's/^\#define CYL_VERSION_$(1) \+\([0-9]\+\).*/\1/p' $(HDR))
CYL_VERSION_MAJOR := $(call CYL_VERSION_PART,MAJOR)
CYL_VERSION  := $(CYL_VERSION_MAJOR).$(call CYL_VERSION_PART,MINOR).$(call CYL_VERSION_PART,PATCH)
CYL_VERSION_NEXT_MAJOR := $(shell echo $$(($(or $(CYL_VERSION_MAJOR),0) + 1)))
INSTALL_GEN  := $(BUILD)/install
# The CMake package finds the header relative to itself (the tree may be moved or staged).
CYL_REL_INCLUDEDIR = $(shell realpath -m --relative-to=$(CMAKEDIR) $(INCLUDEDIR))
# The .pc file's includedir, written relative to its prefix when it is under it.
PC_INCLUDEDIR = $(patsubst $(PREFIX)/%,$${prefix}/%,$(INCLUDEDIR))
INSTALL_FILES = $(INCLUDEDIR)/cylinder_isect.h $(PKGCONFIGDIR)/cylinder_isect.pc \
                $(CMAKEDIR)/cylinder_isectConfig.cmake $(CMAKEDIR)/cylinder_isectConfigVersion.cmake

.PHONY: install uninstall install-check install-files
DEPS_GOALS_install := install-check
CHECK_TARGETS += install-check

# Generated on every install: they depend on PREFIX and the directories, not only on files.
$(INSTALL_GEN)/cylinder_isect.pc $(INSTALL_GEN)/cylinder_isectConfig.cmake $(INSTALL_GEN)/cylinder_isectConfigVersion.cmake: FORCE
	@[ -n "$(CYL_VERSION_MAJOR)" ] && [[ "$(CYL_VERSION)" =~ ^[0-9]+\.[0-9]+\.[0-9]+$$ ]] || \
	  { echo "install: no CYL_VERSION_MAJOR/MINOR/PATCH in $(HDR) (got '$(CYL_VERSION)')" >&2; exit 1; }
	@mkdir -p $(@D)
	@sed -e 's|@PREFIX@|$(PREFIX)|g' -e 's|@INCLUDEDIR@|$(PC_INCLUDEDIR)|g' -e 's|@CYL_VERSION@|$(CYL_VERSION)|g' \
	  -e 's|@CYL_VERSION_MAJOR@|$(CYL_VERSION_MAJOR)|g' -e 's|@CYL_VERSION_NEXT_MAJOR@|$(CYL_VERSION_NEXT_MAJOR)|g' -e 's|@CYL_REL_INCLUDEDIR@|$(CYL_REL_INCLUDEDIR)|g' \
	  cmake/$(@F).in >$@

install: $(INSTALL_GEN)/cylinder_isect.pc $(INSTALL_GEN)/cylinder_isectConfig.cmake $(INSTALL_GEN)/cylinder_isectConfigVersion.cmake
	$(INSTALL) -d $(DESTDIR)$(INCLUDEDIR) $(DESTDIR)$(PKGCONFIGDIR) $(DESTDIR)$(CMAKEDIR)
	$(INSTALL) -m 644 $(HDR) $(DESTDIR)$(INCLUDEDIR)/cylinder_isect.h
	$(INSTALL) -m 644 $(INSTALL_GEN)/cylinder_isect.pc $(DESTDIR)$(PKGCONFIGDIR)/
	$(INSTALL) -m 644 $(INSTALL_GEN)/cylinder_isectConfig.cmake $(INSTALL_GEN)/cylinder_isectConfigVersion.cmake $(DESTDIR)$(CMAKEDIR)/

uninstall:
	rm -f $(addprefix $(DESTDIR),$(INSTALL_FILES))
	-rmdir $(DESTDIR)$(CMAKEDIR) 2>/dev/null

# Prints the installed files, one per line (for the check).
install-files:
	@printf '%s\n' $(INSTALL_FILES)

# ---------------------------------------------------------------- install-check
IC_DIR    := $(BUILD)/install-check
IC_STAGE  := $(CURDIR)/$(IC_DIR)/stage
IC_PREFIX := /usr/local
# The compiler alone (GCC_ALONE): V=2's -iquote v2 would find v2's header before the installed one.
IC_CC     ?= $(GCC_ALONE)
# The source tree the CMake ways read (IC_TREE and the header): the repository, or under V=2 a
# copy with $(HDR) as its header.
IC_TREE   := CMakeLists.txt cmake
IC_SRC    := $(if $(filter 2,$(V)),$(CURDIR)/$(IC_DIR)/src,$(CURDIR))
# $(call ic_expect,OUTPUT FILE): the consumer's output names this version and the hit.
ic_expect = grep -qx 'cylinder_isect $(CYL_VERSION)' $(1) && grep -qx 'hit side t=4.133975' $(1) \
  || { echo "install-check: unexpected consumer output in $(1):"; cat $(1); exit 1; }
# $(call ic_cmake,NAME,ARGS): configure, build and run the consumer's CMake project one way.
ic_cmake = cmake -S tests/consumer -B $(IC_DIR)/$(1) $(2) >$(IC_DIR)/$(1).log 2>&1 \
  && cmake --build $(IC_DIR)/$(1) >>$(IC_DIR)/$(1).log 2>&1 \
  || { tail -n 30 $(IC_DIR)/$(1).log; echo "install-check: $(1) failed (log: $(IC_DIR)/$(1).log)"; exit 1; }; \
  $(IC_DIR)/$(1)/consumer >$(IC_DIR)/$(1).out; $(call ic_expect,$(IC_DIR)/$(1).out); echo "install-check: $(1): ok"

install-check: deps tests/consumer/consumer.c tests/consumer/CMakeLists.txt
	@rm -rf $(IC_DIR) && mkdir -p $(IC_DIR)
	@[ "$(IC_SRC)" = "$(CURDIR)" ] || { mkdir -p $(IC_SRC) && cp -R $(IC_TREE) $(IC_SRC)/ && \
	  cp $(HDR) $(IC_SRC)/cylinder_isect.h && echo "install-check: source tree $(IC_SRC) with $(HDR)"; }
	@# make install into an empty staging tree: exactly the listed files.
	@$(MAKE) --no-print-directory -s install PREFIX=$(IC_PREFIX) DESTDIR=$(IC_STAGE) >$(IC_DIR)/install.log
	@(cd $(IC_STAGE) && find . -type f | sed 's|^\.||' | sort) >$(IC_DIR)/make-files.txt
	@$(MAKE) --no-print-directory -s install-files PREFIX=$(IC_PREFIX) | sort >$(IC_DIR)/expected-files.txt
	@diff $(IC_DIR)/expected-files.txt $(IC_DIR)/make-files.txt || { echo "install-check: make install wrote other files"; exit 1; }
	@echo "install-check: make install: $$(wc -l <$(IC_DIR)/make-files.txt) files, version $(CYL_VERSION)"
	@# pkg-config through the staging tree's sysroot.
	@pc="env PKG_CONFIG_PATH= PKG_CONFIG_LIBDIR=$(IC_STAGE)$(IC_PREFIX)/lib/pkgconfig PKG_CONFIG_SYSROOT_DIR=$(IC_STAGE) pkg-config"; \
	  [ "$$($$pc --modversion cylinder_isect)" = $(CYL_VERSION) ] || { echo "install-check: pkg-config --modversion is not $(CYL_VERSION)"; exit 1; }; \
	  flags="$$($$pc --cflags --libs cylinder_isect)" && \
	  $(IC_CC) -std=c99 -pedantic -Wall -Wextra -Werror tests/consumer/consumer.c $$flags -o $(IC_DIR)/pkgconfig-consumer && \
	  echo "install-check: pkg-config: $(IC_CC) ... $$flags"
	@$(IC_DIR)/pkgconfig-consumer >$(IC_DIR)/pkgconfig.out; $(call ic_expect,$(IC_DIR)/pkgconfig.out); echo "install-check: pkg-config: ok"
	@# find_package of the staged package (it is relocatable), with a version range it meets.
	@$(call ic_cmake,package,-DCYL_CONSUME=package -DCMAKE_PREFIX_PATH=$(IC_STAGE)$(IC_PREFIX) \
	  "-DCYL_MIN_VERSION=$(CYL_VERSION_MAJOR).0...<$(CYL_VERSION_NEXT_MAJOR).0")
	@# ... and one it does not (the next major version) must fail.
	@if cmake -S tests/consumer -B $(IC_DIR)/package-next -DCYL_CONSUME=package -DCMAKE_PREFIX_PATH=$(IC_STAGE)$(IC_PREFIX) \
	  -DCYL_MIN_VERSION=$(CYL_VERSION_NEXT_MAJOR).0 >$(IC_DIR)/package-next.log 2>&1; then \
	  echo "install-check: find_package accepted version $(CYL_VERSION_NEXT_MAJOR).0"; exit 1; fi
	@echo "install-check: find_package refuses version $(CYL_VERSION_NEXT_MAJOR).0: ok"
	@# the source tree as a subproject, and as a FetchContent archive.
	@$(call ic_cmake,subdirectory,-DCYL_CONSUME=subdirectory -DCYL_SOURCE_DIR=$(IC_SRC))
	@tar -czf $(IC_DIR)/cylinder_isect.tar.gz -C $(IC_SRC) --transform 's|^|cylinder_isect/|' cylinder_isect.h $(IC_TREE)
	@$(call ic_cmake,fetchcontent,-DCYL_CONSUME=fetchcontent -DCYL_FETCH_URL=file://$(CURDIR)/$(IC_DIR)/cylinder_isect.tar.gz)
	@# CMake's install rules install the same files.
	@cmake -S $(IC_SRC) -B $(IC_DIR)/cmake-install >$(IC_DIR)/cmake-install.log 2>&1 && \
	  DESTDIR=$(CURDIR)/$(IC_DIR)/cmake-stage cmake --install $(IC_DIR)/cmake-install --prefix $(IC_PREFIX) >>$(IC_DIR)/cmake-install.log 2>&1 \
	  || { cat $(IC_DIR)/cmake-install.log; exit 1; }
	@(cd $(IC_DIR)/cmake-stage && find . -type f | sed 's|^\.||' | sort) >$(IC_DIR)/cmake-files.txt
	@diff $(IC_DIR)/make-files.txt $(IC_DIR)/cmake-files.txt || { echo "install-check: CMake installs other files than make install"; exit 1; }
	@diff $(IC_STAGE)$(IC_PREFIX)/lib/pkgconfig/cylinder_isect.pc $(IC_DIR)/cmake-stage$(IC_PREFIX)/lib/pkgconfig/cylinder_isect.pc \
	  || { echo "install-check: the two cylinder_isect.pc differ"; exit 1; }
	@$(call ic_cmake,cmake-package,-DCYL_CONSUME=package -DCMAKE_PREFIX_PATH=$(CURDIR)/$(IC_DIR)/cmake-stage$(IC_PREFIX) \
	  -DCYL_MIN_VERSION=$(CYL_VERSION_MAJOR).0)
	@# make uninstall leaves nothing behind.
	@$(MAKE) --no-print-directory -s uninstall PREFIX=$(IC_PREFIX) DESTDIR=$(IC_STAGE)
	@left=$$(find $(IC_STAGE) -type f -o -name '*cylinder_isect*'); \
	  [ -z "$$left" ] || { echo "install-check: make uninstall left:"; echo "$$left"; exit 1; }
	@echo "install-check: make uninstall removed every file: ok"
