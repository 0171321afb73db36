# Embedded targets, portability, and paying only for what a scene uses (issue 6).
#   make sizes           code size, stack and ns/call per configuration, lint deviations
#                        -> docs/embedded.md
#   make cross-test      the Unity suite on aarch64, armhf, s390x under qemu user mode
#   make embedded-check  Cortex-M4F / Cortex-M0 / RV32IMAFC builds, disassembly checks,
#                        feature folding, and a smoke run of those objects under qemu
#   make cxx-compat      the header as C++11 and C++17 (g++ and clang++, -Wall -Wextra -Werror)
#   make misra-check     cppcheck with its MISRA C 2012 addon (deviations: embedded/misra.supp)
#   make tidy-check      clang-tidy (checks listed in scripts/cross-lint.sh)
#   make ci-cross        all of the above except sizes (what CI runs: scripts/ci-cross.sh)
.PHONY: sizes cross-test embedded-check cxx-compat misra-check tidy-check ci-cross

CROSS_ENV := BUILD=$(BUILD) GCC=$(GCC)

# Regenerates the tables of docs/embedded.md: sizes and timing, then the lint deviations with
# their current counts (the check itself is misra-check).
sizes:
	@$(CROSS_ENV) bash scripts/cross-sizes.sh
	@$(CROSS_ENV) bash scripts/cross-lint.sh misra >/dev/null || echo "sizes: note: misra-check fails, see make misra-check"
	@$(CROSS_ENV) bash scripts/cross-lint.sh doc
	@$(MAKE) --no-print-directory readme

cross-test: unity
	@$(CROSS_ENV) bash scripts/cross-test.sh $(BUILD) $(UNITY_SRC)

embedded-check:
	@$(CROSS_ENV) bash scripts/cross-embedded.sh

cxx-compat:
	@$(CROSS_ENV) bash scripts/cross-cxx.sh

misra-check:
	@$(CROSS_ENV) bash scripts/cross-lint.sh misra

tidy-check:
	@$(CROSS_ENV) bash scripts/cross-lint.sh tidy

ci-cross: unity
	@$(CROSS_ENV) UNITY_SRC=$(UNITY_SRC) bash scripts/ci-cross.sh
