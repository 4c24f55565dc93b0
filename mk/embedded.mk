# Checks that prove the embedded claims (included by the Makefile). Each
# target builds in its own directory under build/, so they can run beside
# the ordinary build. See docs/embedded.md.
#
#   make check-alloc   nm allow-list on $(LIB), then tests and examples with
#                      allocator calls from library code counted (must be 0)
#   make cross         library for Cortex-M4F, Cortex-M7 (DP FPU), RV64
#                      (compile only) with the same allow-list, and the
#                      Cortex-M firmware images with their sizes
#   make memcheck      the tests under valgrind, no errors allowed
#   make stack         -fstack-usage report; fails above STACK_LIMIT bytes
#   make lint          cppcheck, clang-tidy, header self-containment, and
#                      check-api: names follow their header, only the
#                      public API is exported
#   make embedded-checks   all of the above but memcheck
#   (make test SAN=1 is the Makefile's own: tests under ASan + UBSan)

.PHONY: check-layout check-alloc check-alloc-nm check-alloc-runtime memcheck stack lint cppcheck clang-tidy \
        check-headers check-api embedded-checks

EMB_NM      ?= nm
EMB_TOOLS_CFLAGS := -std=c11 -O2 -Wall -Wextra $(WERROR_FLAG)

embedded-checks: check-alloc cross stack lint

# ---------------------------------------------------------------- check-alloc
ALLOC_BUILD := build/alloc$(NUFFT_DIR)
ALLOC_SHIM  := $(ALLOC_BUILD)/tools/malloc_count.o
ALLOC_LOG   := $(ALLOC_BUILD)/malloc_count.log
ALLOC_TESTS := $(TEST_SRC:test/%.c=$(ALLOC_BUILD)/test/%)
ALLOC_EXAMPLES := $(EXAMPLE_SRC:examples/%.c=$(ALLOC_BUILD)/examples/%)

check-alloc: check-alloc-nm check-alloc-runtime

# The archive (one partially linked object), then its input objects, so that
# a failure names the module that references the symbol.
check-alloc-nm: $(LIB)
	@sh tools/check_alloc.sh -n $(EMB_NM) $(LIB)
	@sh tools/check_alloc.sh -n $(EMB_NM) -l "the objects of $(LIB)" $(LIB_OBJ) $(KISS_OBJ)

# The runtime build archives the library with tools/ar_counted.sh, which
# renames the library's allocator references to the counters of
# tools/malloc_count.c; every test and example links that object. Then
# tools/check_alloc_run.sh runs them all (the examples also through
# test/examples_check.sh) and requires a zero count from every program.
check-alloc-runtime:
	@$(MAKE) --no-print-directory BUILD=$(ALLOC_BUILD) AR='sh tools/ar_counted.sh' \
	    LDLIBS='$(ALLOC_SHIM) -lm' SAN= tests examples
	@EXAMPLES='$(filter $(ALLOC_BUILD)/examples/sec%,$(ALLOC_EXAMPLES))' \
	    sh tools/check_alloc_run.sh $(ALLOC_LOG) $(ALLOC_TESTS) -- $(ALLOC_EXAMPLES)

ifeq ($(BUILD),$(ALLOC_BUILD))
$(TEST_BIN) $(EXAMPLE_BIN): $(ALLOC_SHIM) tools/ar_counted.sh
endif

$(ALLOC_SHIM): tools/malloc_count.c
	@mkdir -p $(@D)
	$(CC) $(EMB_TOOLS_CFLAGS) -c $< -o $@

# -------------------------------------------------------------------- memcheck
MEMCHECK_BUILD := build/memcheck$(NUFFT_DIR)
MEMCHECK_TESTS := $(TEST_SRC:test/%.c=$(MEMCHECK_BUILD)/test/%)
VALGRIND_FLAGS := -q --error-exitcode=99 --leak-check=full --errors-for-leak-kinds=definite,indirect \
                  --track-origins=yes

# Each test runs through a one-line wrapper so that test/run_tests.sh still
# sums the Unity results; valgrind's exit status 99 marks any memory error.
memcheck:
	@command -v valgrind >/dev/null || { echo "memcheck: valgrind not installed"; exit 1; }
	@$(MAKE) --no-print-directory BUILD=$(MEMCHECK_BUILD) SAN= OPT='-O1 -g' tests
	@mkdir -p $(MEMCHECK_BUILD)/vg
	@set -e; for t in $(MEMCHECK_TESTS); do \
	    w=$(MEMCHECK_BUILD)/vg/$${t##*/}; \
	    printf '#!/bin/sh\nexec valgrind %s %s "$$@"\n' '$(VALGRIND_FLAGS)' "$$t" >$$w; chmod +x $$w; \
	done
	@sh test/run_tests.sh $(addprefix $(MEMCHECK_BUILD)/vg/,$(notdir $(MEMCHECK_TESTS)))

# ----------------------------------------------------------------------- stack
STACK_BUILD := build/stack$(NUFFT_DIR)
STACK_LIMIT ?= 1024
STACK_DEPTH ?= 8
STACK_FLAGS := -fstack-usage -fcallgraph-info=su -Wstack-usage=$(STACK_LIMIT) -Walloca -Wvla
STACK_OBJ   := $(LIB_SRC:%.c=$(STACK_BUILD)/obj/%.o) $(KISS_SRC:%.c=$(STACK_BUILD)/obj/%.o)

stack: $(STACK_OBJ)
	@sh tools/stack_report.sh -l $(STACK_LIMIT) -d $(STACK_DEPTH) $(STACK_BUILD)/obj

# Same flags as the library build; -Wstack-usage and -Walloca are errors in our
# code and warnings in the vendored code (the report still fails on its frames).
$(STACK_BUILD)/obj/src/vendor/%.o: src/vendor/%.c
	@mkdir -p $(@D)
	@echo "CC $@"
	$(EMB_Q)$(CC) $(VENDOR_WARN) $(OPT) $(STACK_FLAGS) $(KISS_DEFS) -MMD -MP -c $< -o $@

$(STACK_BUILD)/obj/src/%.o: src/%.c
	@mkdir -p $(@D)
	@echo "CC $@"
	$(EMB_Q)$(CC) $(WARN) $(OPT) $(STACK_FLAGS) $(MCS_CPPFLAGS) $(LIB_INC) $(CPPFLAGS) -isystem src/vendor/kissfft $(KISS_DEFS) \
	    -MMD -MP -c $< -o $@

-include $(wildcard $(STACK_BUILD)/obj/src/*/*.d $(STACK_BUILD)/obj/src/vendor/kissfft/*.d)

# ------------------------------------------------------------------------ lint
# Our sources and public headers, plus the firmware and the counting shim;
# the vendored code stays as shipped.
LINT_SRC     := $(filter-out src/vendor/%,$(LIB_SRC)) $(wildcard examples/firmware/*.c) \
                tools/malloc_count.c
LINT_HEADERS := $(wildcard include/*.h include/mcspec/*.h)
CLANG_TIDY   ?= $(shell command -v clang-tidy || command -v clang-tidy-14)
CPPCHECK     ?= cppcheck
LINT_BUILD   := build/lint

lint: check-layout check-headers check-api cppcheck clang-tidy

# The tree is the architecture (CONTRIBUTING.md): sources in family folders,
# includes and calls only downward, no cycle (tools/check_layout.sh).
check-layout: $(LIB_OBJ)
	@sh tools/check_layout.sh -n $(EMB_NM) $(LIB_OBJ)

# Every public function is named mcs_<header>_..., every global of the
# library's objects is prefixed mcs_, and libmcspec.a and libmcspec.so export
# exactly the functions the public headers declare (tools/check_api.sh).
check-api: $(LIB) $(BUILD)/libmcspec.so $(BUILD)/test/api/test_adversarial
	@sh tools/check_api.sh -c '$(CC) $(MCS_CPPFLAGS) $(CPPFLAGS)' -n $(EMB_NM) \
	    -o '$(LIB_OBJ) $(KISS_OBJ)' -t $(BUILD)/test/api/test_adversarial $(LIB) $(BUILD)/libmcspec.so

$(LINT_BUILD):
	@mkdir -p $@

clang-tidy: | $(LINT_BUILD)

# cppcheck's exit code is 1 on any finding; --inline-suppr honours
# "// cppcheck-suppress <id>" comments, each of which carries its reason.
cppcheck:
	@echo "cppcheck $(LINT_SRC) $(LINT_HEADERS)"
	@$(CPPCHECK) --quiet --std=c11 --enable=warning,performance,portability --inline-suppr \
	    --error-exitcode=1 -Iinclude $(NUFFT_DEFS) $(LIB_INC) -Isrc/vendor/kissfft $(KISS_DEFS) \
	    -i src/vendor --suppress='*:src/vendor/*' --suppress=missingIncludeSystem \
	    $(LINT_SRC) $(LINT_HEADERS) && echo "cppcheck OK"

# .clang-tidy holds the checks; WarningsAsErrors makes any finding fatal.
# Its "N warnings generated" lines count suppressed system-header notes: dropped.
clang-tidy:
	@test -n "$(CLANG_TIDY)" || { echo "clang-tidy not installed"; exit 1; }
	@echo "clang-tidy $(LINT_SRC)"
	@$(CLANG_TIDY) --quiet $(LINT_SRC) -- $(filter-out -Werror,$(WARN)) $(MCS_CPPFLAGS) $(LIB_INC) $(CPPFLAGS) \
	    -isystem src/vendor/kissfft $(KISS_DEFS) >$(LINT_BUILD)/clang-tidy.out 2>&1; rc=$$?; \
	grep -v '^[0-9][0-9]* warnings\{0,1\} generated\.$$' $(LINT_BUILD)/clang-tidy.out; \
	[ $$rc -eq 0 ] && echo "clang-tidy OK"; exit $$rc

# Every public header compiles on its own, as C11 and as C++.
check-headers:
	@mkdir -p $(LINT_BUILD)
	@set -e; for h in $(LINT_HEADERS); do \
	    inc=$${h#include/}; \
	    printf '#include "%s"\n#include "%s"\ntypedef int mcs_header_check;\n' "$$inc" "$$inc" | \
	        $(CC) $(WARN) $(MCS_CPPFLAGS) $(CPPFLAGS) -x c -fsyntax-only - || { echo "check-headers: $$h (C)"; exit 1; }; \
	    printf '#include "%s"\n' "$$inc" | \
	        $(CXX) -std=c++11 -Wall -Wextra $(WERROR_FLAG) -pedantic $(MCS_CPPFLAGS) $(CPPFLAGS) -x c++ -fsyntax-only - || \
	        { echo "check-headers: $$h (C++)"; exit 1; }; \
	done; echo "check-headers OK: $(words $(LINT_HEADERS)) headers self-contained in C11 and C++11"

# ---------------------------------------------------------------- test-nonufft
# The library without the NUFFT (NUFFT=0: MCS_CONFIG_NUFFT 0, config.h) in
# build/nonufft/: the point-set runners and the NUFFT's own (whose tests skip
# there with a printed reason), then test_pointset_direct_bits from both
# builds, whose digests must be equal: the build without the NUFFT gives the
# default build's direct-path bits.
.PHONY: test-nonufft
NONUFFT_RUNNERS := $(filter test/pointsets/% test/dft/test_nufft.c,$(TEST_SRC))
NONUFFT_BITS    := test/pointsets/test_pointset_direct_bits

test-nonufft: build/$(NONUFFT_BITS)
	@$(MAKE) --no-print-directory NUFFT=0 SAN= $(NONUFFT_RUNNERS:test/%.c=build/nonufft/test/%)
	@sh test/run_tests.sh $(NONUFFT_RUNNERS:test/%.c=build/nonufft/test/%)
	@rm -f build/nonufft/digest-default.txt build/nonufft/digest-nonufft.txt
	@MCS_DIGEST_OUT=build/nonufft/digest-default.txt build/$(NONUFFT_BITS) >/dev/null
	@MCS_DIGEST_OUT=build/nonufft/digest-nonufft.txt build/nonufft/$(NONUFFT_BITS) >/dev/null
	@cmp build/nonufft/digest-default.txt build/nonufft/digest-nonufft.txt && \
	    echo "test-nonufft: direct-path digests equal in both builds:" && \
	    cat build/nonufft/digest-nonufft.txt
