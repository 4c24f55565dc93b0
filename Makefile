# mcspec: one non-recursive Makefile. Outputs under $(BUILD)/.
#   make            library (static and shared), tests, examples, bench programs
#   make run        build everything and run every section example (the main job)
#   make test       build and run every Unity runner; ends with "N passed, N failed"
#   make bench      build and run the benchmark
#   make SAN=1 ...  the same under AddressSanitizer + UBSan, in build/san/
#   make install PREFIX=... DESTDIR=...   (and uninstall; see mk/install.mk)
# More targets (checks for the embedded claims, install) live in mk/*.mk.
#
# Your CPPFLAGS, CFLAGS and LDFLAGS are added after the project's own flags,
# never instead of them: `make CPPFLAGS=-DMCS_MAX_N=256 lib` still finds
# include/. Warnings are errors only with WERROR=1 (.ci/run sets it).

# Builds run one job per core unless the command line says how many (-j N,
# or -j1 for one): `make test` from a clean clone builds in parallel.
ifeq ($(filter -j% j%,$(MAKEFLAGS)),)
MAKEFLAGS += -j$(shell nproc 2>/dev/null || echo 2)
endif

CC      ?= cc
AR      ?= ar
OBJCOPY ?= objcopy
BUILD   ?= build
ifeq ($(SAN),1)
BUILD   := build/san
SANFLAGS := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
endif
# FFT=fftw: the FFTW back end (mk/fft.mk), built apart from the default.
ifeq ($(FFT),fftw)
BUILD   := $(BUILD)/fftw
endif
# NUFFT=0: the library without the NUFFT (MCS_CONFIG_NUFFT 0 in
# include/mcspec/config.h), built apart, as are its cross, stack and
# check-alloc builds (mk/cross.mk, mk/embedded.mk); make test-nonufft tests it.
ifeq ($(NUFFT),0)
NUFFT_DEFS := -DMCS_CONFIG_NUFFT=0
NUFFT_DIR  := /nonufft
BUILD   := $(BUILD)/nonufft
endif

OPT      ?= -O2 -g
WARN     := -std=c11 -Wall -Wextra -Wpedantic -Wshadow -Wstrict-prototypes \
            -Wmissing-prototypes -Wcast-qual -Wdouble-promotion -Wvla -Wundef \
            -Wpointer-arith -Wwrite-strings -Wformat=2
VENDOR_WARN := -std=c11 -Wall -Wno-unused-parameter
ifeq ($(WERROR),1)
WARN     += -Werror
WERROR_FLAG := -Werror
endif

# KissFFT as mcspec needs it (src/vendor/kissfft/VENDORED.md): double
# precision, no logging, malloc hooks defined away. Every file that includes a
# KissFFT header must see the same configuration, so it goes to all library
# objects; src/core/version.c stops the build with #error if it is missing.
KISS_CONFIG := -Dkiss_fft_scalar=double -DNDEBUG '-DKISS_FFT_MALLOC(n)=((void*)0)' \
               '-DKISS_FFT_FREE(p)=((void)0)'
# KissFFT's external names get the mcs_ prefix, so mcspec's double build can
# never meet a renderer's own (float) KissFFT at link time, whatever the build
# system (these are plain -D flags: the CMake build and a copy of the sources
# use the same ones). The archive and the shared library then keep only the
# public API global (see LIB below).
KISS_RENAME := -Dkiss_fft=mcs_kiss_fft -Dkiss_fft_alloc=mcs_kiss_fft_alloc \
               -Dkiss_fft_stride=mcs_kiss_fft_stride -Dkiss_fft_cleanup=mcs_kiss_fft_cleanup \
               -Dkiss_fft_next_fast_size=mcs_kiss_fft_next_fast_size
KISS_DEFS := $(KISS_CONFIG) $(KISS_RENAME)

# Compile and link lines are summarised ("CC build/obj/src/dft.o"); V=1 shows them.
ifeq ($(V),1)
Q :=
else
Q := @
endif

# The project's preprocessor flags; the user's CPPFLAGS follow them.
MCS_CPPFLAGS := -Iinclude $(NUFFT_DEFS)
# The library's own sources also see src/ (a family's private header is
# included as "family/name.h"; tools/check_layout.sh checks the direction).
LIB_INC := -Isrc
DEPFLAGS := -MMD -MP
LDLIBS   += -lm

# Library sources by wildcard, one folder per family (src/<family>/*.c; the
# families and their order are drawn in CONTRIBUTING.md): a new source in a
# family's folder is picked up without edits. kiss_fftr.c is not built:
# nothing calls the real transform (dft/dft.c untangles it itself); the file
# stays in the tree as shipped.
LIB_SRC    := $(sort $(filter-out src/vendor/%,$(wildcard src/*/*.c)))
KISS_SRC   := src/vendor/kissfft/kiss_fft.c
LIB_OBJ    := $(LIB_SRC:%.c=$(BUILD)/obj/%.o)
KISS_OBJ   := $(KISS_SRC:%.c=$(BUILD)/obj/%.o)
LIB        := $(BUILD)/libmcspec.a
PUBLIC_HEADERS := include/mcspec.h $(wildcard include/mcspec/*.h)

# Version, from include/mcspec/version.h (the one place it is written).
mcs_version_part = $(shell sed -n 's/^\#define MCS_VERSION_$(1) \([0-9][0-9]*\).*/\1/p' include/mcspec/version.h)
VERSION_MAJOR := $(call mcs_version_part,MAJOR)
VERSION_MINOR := $(call mcs_version_part,MINOR)
VERSION_PATCH := $(call mcs_version_part,PATCH)
VERSION    := $(VERSION_MAJOR).$(VERSION_MINOR).$(VERSION_PATCH)
SONAME     := libmcspec.so.$(VERSION_MAJOR)
SHLIB      := $(BUILD)/libmcspec.so.$(VERSION)
PIC_OBJ    := $(LIB_SRC:%.c=$(BUILD)/pic/%.o) $(KISS_SRC:%.c=$(BUILD)/pic/%.o)
# The public API, one name per line, read from the public headers with the
# library's own flags (tools/api.sh): what the archive and the shared library
# keep global, and nothing else.
API_LIST   := $(BUILD)/mcspec.api
API_MAP    := $(BUILD)/mcspec.map

UNITY_OBJ  := $(BUILD)/obj/test/vendor/unity/src/unity.o
TEST_SUPPORT_SRC := $(wildcard test/support/*.c)
TEST_SUPPORT_OBJ := $(TEST_SUPPORT_SRC:%.c=$(BUILD)/obj/%.o)
# Unity runners, one folder per library family (test/<family>/test_*.c) and
# test/api/ for the whole-API adversarial table.
TEST_SRC   := $(sort $(wildcard test/*/test_*.c))
TEST_BIN   := $(TEST_SRC:test/%.c=$(BUILD)/test/%)
UNITY_DEFS := -DUNITY_INCLUDE_DOUBLE=

EXAMPLE_SUPPORT_SRC := $(wildcard examples/support/*.c)
EXAMPLE_SUPPORT_OBJ := $(EXAMPLE_SUPPORT_SRC:%.c=$(BUILD)/obj/%.o)
EXAMPLE_SRC := $(sort $(wildcard examples/*.c))
EXAMPLE_BIN := $(EXAMPLE_SRC:examples/%.c=$(BUILD)/examples/%)
SECTION_BIN := $(filter $(BUILD)/examples/sec%,$(EXAMPLE_BIN))

BENCH_SRC  := $(sort $(wildcard test/bench/*.c))
BENCH_BIN  := $(BENCH_SRC:test/bench/%.c=$(BUILD)/bench/%)

.PHONY: all lib tests examples benches run test bench clean FORCE
# Keep intermediate objects (test and example support) instead of deleting them.
.SECONDARY:
.DEFAULT_GOAL := all

all: lib tests examples benches
lib: $(LIB) $(BUILD)/libmcspec.so
tests: $(TEST_BIN)
examples: $(EXAMPLE_BIN)
benches: $(BENCH_BIN)

# Compile lines for our own C, the vendored C and links; user flags come last.
MCS_CC  = $(CC) $(WARN) $(OPT) $(SANFLAGS) $(MCS_CPPFLAGS) $(CPPFLAGS) $(CFLAGS)
VEND_CC = $(CC) $(VENDOR_WARN) $(OPT) $(SANFLAGS) $(CPPFLAGS) $(CFLAGS)
LIB_CC  = $(MCS_CC) $(LIB_INC) -isystem src/vendor/kissfft $(KISS_DEFS)

# Every object depends on this stamp, which changes only when the flags do:
# `make CPPFLAGS=-DMCS_MAX_N=256` after a default build rebuilds everything
# instead of mixing objects of two capacities.
FLAGS_STAMP := $(BUILD)/flags.txt
FLAGS_TEXT = $(CC) | $(WARN) | $(OPT) | $(SANFLAGS) | $(CPPFLAGS) | $(CFLAGS) | $(LDFLAGS) | \
             $(KISS_DEFS) | $(AR) | $(LDLIBS) | $(NUFFT_DEFS)
$(FLAGS_STAMP): FORCE
	@mkdir -p $(@D)
	@printf '%s\n' '$(subst ','\'',$(FLAGS_TEXT))' >$@.new
	@if cmp -s $@.new $@; then rm -f $@.new; else mv -f $@.new $@; fi

# The archive holds one object: every library object partially linked
# (cc -r), then every global symbol not in the public API made local
# (objcopy --keep-global-symbols). Internal references are resolved by then,
# so KissFFT and any cross-module helper stay inside; only the API is global.
$(BUILD)/obj/libmcspec.o: $(LIB_OBJ) $(KISS_OBJ) $(API_LIST)
	@echo "LD $@"
	$(Q)$(CC) -r -nostdlib -o $@.all $(LIB_OBJ) $(KISS_OBJ)
	$(Q)$(OBJCOPY) --keep-global-symbols=$(API_LIST) $@.all $@
	@rm -f $@.all

$(LIB): $(BUILD)/obj/libmcspec.o
	@mkdir -p $(@D)
	@echo "AR $@"
	$(Q)rm -f $@
	$(Q)$(AR) rcs $@ $^

# The public API (tools/api.sh reads the headers through the preprocessor
# with the library's flags, so the capacity tag of config.h has its values).
$(API_LIST): $(PUBLIC_HEADERS) tools/api.sh $(FLAGS_STAMP)
	@mkdir -p $(@D)
	@echo "GEN $@"
	$(Q)sh tools/api.sh -c '$(CC) $(MCS_CPPFLAGS) $(CPPFLAGS)' names >$@.tmp && mv -f $@.tmp $@

# Version script of the shared library: the API global, everything else local.
$(API_MAP): $(API_LIST)
	@echo "GEN $@"
	$(Q){ echo '{ global:'; sed 's/.*/  &;/' $<; echo 'local: *; };'; } >$@

# Shared library: position-independent objects of the same sources,
# SONAME libmcspec.so.MAJOR, only the API exported (the version script).
$(SHLIB): $(PIC_OBJ) $(API_MAP)
	@echo "LD $@"
	$(Q)$(CC) $(SANFLAGS) -shared -Wl,-soname,$(SONAME) -Wl,--version-script=$(API_MAP) \
	    -Wl,--no-undefined $(LDFLAGS) -o $@ $(PIC_OBJ) $(LIB_LIBS) -lm

$(BUILD)/libmcspec.so: $(SHLIB)
	@echo "LN $@"
	$(Q)ln -sf $(notdir $(SHLIB)) $(BUILD)/$(SONAME)
	$(Q)ln -sf $(SONAME) $@

$(BUILD)/pic/src/vendor/%.o: src/vendor/%.c $(FLAGS_STAMP)
	@mkdir -p $(@D)
	@echo "CC $@"
	$(Q)$(VEND_CC) -fPIC $(KISS_DEFS) $(DEPFLAGS) -c $< -o $@

$(BUILD)/pic/src/%.o: src/%.c $(FLAGS_STAMP)
	@mkdir -p $(@D)
	@echo "CC $@"
	$(Q)$(LIB_CC) -fPIC $(DEPFLAGS) -c $< -o $@

$(BUILD)/obj/src/vendor/%.o: src/vendor/%.c $(FLAGS_STAMP)
	@mkdir -p $(@D)
	@echo "CC $@"
	$(Q)$(VEND_CC) $(KISS_DEFS) $(DEPFLAGS) -c $< -o $@

$(BUILD)/obj/src/%.o: src/%.c $(FLAGS_STAMP)
	@mkdir -p $(@D)
	@echo "CC $@"
	$(Q)$(LIB_CC) $(DEPFLAGS) -c $< -o $@

$(UNITY_OBJ): test/vendor/unity/src/unity.c $(FLAGS_STAMP)
	@mkdir -p $(@D)
	@echo "CC $@"
	$(Q)$(VEND_CC) $(UNITY_DEFS) $(DEPFLAGS) -c $< -o $@

$(BUILD)/obj/test/support/%.o: test/support/%.c $(FLAGS_STAMP)
	@mkdir -p $(@D)
	@echo "CC $@"
	$(Q)$(MCS_CC) -Itest/support -isystem test/vendor/unity/src $(UNITY_DEFS) $(DEPFLAGS) -c $< -o $@

$(BUILD)/test/%: test/%.c $(UNITY_OBJ) $(TEST_SUPPORT_OBJ) $(LIB) $(FLAGS_STAMP)
	@mkdir -p $(@D) $(dir $(BUILD)/obj/test/$*)
	@echo "LD $@"
	$(Q)$(MCS_CC) -Itest/support -isystem test/vendor/unity/src $(UNITY_DEFS) \
	    -MMD -MP -MF $(BUILD)/obj/test/$*.d $< $(UNITY_OBJ) $(TEST_SUPPORT_OBJ) \
	    $(LIB) $(LDFLAGS) $(LDLIBS) -o $@

$(BUILD)/obj/examples/support/%.o: examples/support/%.c $(FLAGS_STAMP)
	@mkdir -p $(@D)
	@echo "CC $@"
	$(Q)$(MCS_CC) -Iexamples/support $(DEPFLAGS) -c $< -o $@

$(BUILD)/examples/%: examples/%.c $(EXAMPLE_SUPPORT_OBJ) $(LIB) $(FLAGS_STAMP)
	@mkdir -p $(@D) $(BUILD)/obj/examples
	@echo "LD $@"
	$(Q)$(MCS_CC) -Iexamples/support -MMD -MP -MF $(BUILD)/obj/examples/$*.d $< \
	    $(EXAMPLE_SUPPORT_OBJ) $(LIB) $(LDFLAGS) $(LDLIBS) -o $@

$(BUILD)/bench/%: test/bench/%.c $(LIB) $(FLAGS_STAMP)
	@mkdir -p $(@D) $(BUILD)/obj/bench
	@echo "LD $@"
	$(Q)$(MCS_CC) -MMD -MP -MF $(BUILD)/obj/bench/$*.d $< $(LIB) $(LDFLAGS) $(LDLIBS) -o $@

# The main job: every section example of the note with its defaults. It
# builds what it runs (the library and the section examples), not the tests
# or the bench.
run: $(SECTION_BIN)
	@set -e; for b in $(SECTION_BIN); do echo "== $$b"; $$b; echo; done

# ADVERSARIAL_KNOWN=skip excuses the rows test/test_adversarial.c lists as
# known-open findings (none today: every row runs and must pass).
ADVERSARIAL_KNOWN ?=
export ADVERSARIAL_KNOWN

# Every Unity runner, then the command-line and CSV checks of the section
# examples (test/examples_check.sh prints a Unity-style summary too).
test: $(TEST_BIN) $(SECTION_BIN) $(BUILD)/examples/renderer_sampler $(BUILD)/examples/sampler_check
	@ADVERSARIAL_KNOWN=$(ADVERSARIAL_KNOWN) SAMPLER_CHECK=$(BUILD)/examples/sampler_check \
	    MCSPEC_LIBRARY=$(BUILD)/libmcspec.so SAN=$(SAN) \
	    EXAMPLES="$(SECTION_BIN) $(BUILD)/examples/renderer_sampler" MCSPEC="$(CLI_BIN)" RENDERER="$(BUILD)/examples/renderer_sampler" \
	    sh test/run_tests.sh $(TEST_BIN) test/examples_check.sh test/cli_check.sh test/measures_check.sh \
	    test/record_check.sh test/measure_records_check.sh test/renderer_check.sh \
	    test/spectrum_check.sh test/sample_check.sh \
	    test/integrate_check.sh test/pcf_check.sh python/tests/run.sh

clean:
	rm -rf build

-include $(wildcard $(BUILD)/obj/*/*.d $(BUILD)/obj/*/*/*.d $(BUILD)/obj/*/*/*/*.d \
    $(BUILD)/pic/*/*/*.d $(BUILD)/pic/*/*/*/*.d)
-include $(wildcard mk/*.mk)
