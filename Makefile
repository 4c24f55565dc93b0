# mcspec: one non-recursive Makefile. Outputs under $(BUILD)/.
#   make            library, tests, examples, bench programs
#   make run        build everything and run every section example (the main job)
#   make test       build and run every Unity runner; ends with "N passed, N failed"
#   make bench      build and run the benchmark
#   make SAN=1 ...  the same under AddressSanitizer + UBSan, in build/san/
# More targets (checks for the embedded claims) live in mk/*.mk.

CC      ?= cc
AR      ?= ar
BUILD   ?= build
ifeq ($(SAN),1)
BUILD   := build/san
SANFLAGS := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
endif

OPT      ?= -O2 -g
WARN     := -std=c11 -Wall -Wextra -Wpedantic -Werror -Wshadow -Wstrict-prototypes \
            -Wmissing-prototypes -Wcast-qual -Wdouble-promotion -Wvla -Wundef \
            -Wpointer-arith -Wwrite-strings -Wformat=2
# KissFFT in double precision, no logging, malloc hooks defined away (see
# src/vendor/kissfft/VENDORED.md). Every file that includes a KissFFT header
# must see the same kiss_fft_scalar, so these go to all library objects.
KISS_DEFS := -Dkiss_fft_scalar=double -DNDEBUG '-DKISS_FFT_MALLOC(n)=((void*)0)' \
             '-DKISS_FFT_FREE(p)=((void)0)'
VENDOR_WARN := -std=c11 -Wall -Wno-unused-parameter

CPPFLAGS += -Iinclude
DEPFLAGS := -MMD -MP
LDLIBS   += -lm

LIB_SRC    := $(wildcard src/*.c)
KISS_SRC   := src/vendor/kissfft/kiss_fft.c src/vendor/kissfft/kiss_fftr.c
LIB_OBJ    := $(LIB_SRC:%.c=$(BUILD)/obj/%.o)
KISS_OBJ   := $(KISS_SRC:%.c=$(BUILD)/obj/%.o)
LIB        := $(BUILD)/libmcspec.a

UNITY_OBJ  := $(BUILD)/obj/test/vendor/unity/src/unity.o
TEST_SUPPORT_SRC := $(wildcard test/support/*.c)
TEST_SUPPORT_OBJ := $(TEST_SUPPORT_SRC:%.c=$(BUILD)/obj/%.o)
TEST_SRC   := $(sort $(wildcard test/test_*.c))
TEST_BIN   := $(TEST_SRC:test/%.c=$(BUILD)/test/%)
UNITY_DEFS := -DUNITY_INCLUDE_DOUBLE=

EXAMPLE_SUPPORT_SRC := $(wildcard examples/support/*.c)
EXAMPLE_SUPPORT_OBJ := $(EXAMPLE_SUPPORT_SRC:%.c=$(BUILD)/obj/%.o)
EXAMPLE_SRC := $(sort $(wildcard examples/*.c))
EXAMPLE_BIN := $(EXAMPLE_SRC:examples/%.c=$(BUILD)/examples/%)
SECTION_BIN := $(filter $(BUILD)/examples/sec%,$(EXAMPLE_BIN))

BENCH_SRC  := $(sort $(wildcard test/bench/*.c))
BENCH_BIN  := $(BENCH_SRC:test/bench/%.c=$(BUILD)/bench/%)

.PHONY: all lib tests examples benches run test bench clean
# Keep intermediate objects (test and example support) instead of deleting them.
.SECONDARY:
.DEFAULT_GOAL := all

all: lib tests examples benches
lib: $(LIB)
tests: $(TEST_BIN)
examples: $(EXAMPLE_BIN)
benches: $(BENCH_BIN)

$(LIB): $(LIB_OBJ) $(KISS_OBJ)
	@mkdir -p $(@D)
	rm -f $@
	$(AR) rcs $@ $^

$(BUILD)/obj/src/vendor/%.o: src/vendor/%.c
	@mkdir -p $(@D)
	$(CC) $(VENDOR_WARN) $(OPT) $(SANFLAGS) $(KISS_DEFS) $(DEPFLAGS) -c $< -o $@

$(BUILD)/obj/src/%.o: src/%.c
	@mkdir -p $(@D)
	$(CC) $(WARN) $(OPT) $(SANFLAGS) $(CPPFLAGS) -isystem src/vendor/kissfft $(KISS_DEFS) \
	    $(DEPFLAGS) -c $< -o $@

$(UNITY_OBJ): test/vendor/unity/src/unity.c
	@mkdir -p $(@D)
	$(CC) $(VENDOR_WARN) $(OPT) $(SANFLAGS) $(UNITY_DEFS) $(DEPFLAGS) -c $< -o $@

$(BUILD)/obj/test/support/%.o: test/support/%.c
	@mkdir -p $(@D)
	$(CC) $(WARN) $(OPT) $(SANFLAGS) $(CPPFLAGS) -Itest/support -isystem test/vendor/unity/src \
	    $(UNITY_DEFS) $(DEPFLAGS) -c $< -o $@

$(BUILD)/test/%: test/%.c $(UNITY_OBJ) $(TEST_SUPPORT_OBJ) $(LIB)
	@mkdir -p $(@D) $(BUILD)/obj/test
	$(CC) $(WARN) $(OPT) $(SANFLAGS) $(CPPFLAGS) -Itest/support -isystem test/vendor/unity/src \
	    $(UNITY_DEFS) -MMD -MP -MF $(BUILD)/obj/test/$*.d $< $(UNITY_OBJ) $(TEST_SUPPORT_OBJ) \
	    $(LIB) $(LDLIBS) -o $@

$(BUILD)/obj/examples/support/%.o: examples/support/%.c
	@mkdir -p $(@D)
	$(CC) $(WARN) $(OPT) $(SANFLAGS) $(CPPFLAGS) -Iexamples/support $(DEPFLAGS) -c $< -o $@

$(BUILD)/examples/%: examples/%.c $(EXAMPLE_SUPPORT_OBJ) $(LIB)
	@mkdir -p $(@D) $(BUILD)/obj/examples
	$(CC) $(WARN) $(OPT) $(SANFLAGS) $(CPPFLAGS) -Iexamples/support -MMD -MP \
	    -MF $(BUILD)/obj/examples/$*.d $< $(EXAMPLE_SUPPORT_OBJ) $(LIB) $(LDLIBS) -o $@

$(BUILD)/bench/%: test/bench/%.c $(LIB)
	@mkdir -p $(@D) $(BUILD)/obj/bench
	$(CC) $(WARN) $(OPT) $(SANFLAGS) $(CPPFLAGS) -isystem src/vendor/kissfft $(KISS_DEFS) \
	    -MMD -MP -MF $(BUILD)/obj/bench/$*.d $< $(LIB) $(LDLIBS) -o $@

# The main job: every section example of the note with its defaults.
run: all
	@set -e; for b in $(SECTION_BIN); do echo "== $$b"; $$b; echo; done

# Every Unity runner, then the command-line and CSV checks of the section
# examples (test/examples_check.sh prints a Unity-style summary too).
test: $(TEST_BIN) $(SECTION_BIN)
	@EXAMPLES="$(SECTION_BIN)" sh test/run_tests.sh $(TEST_BIN) test/examples_check.sh

clean:
	rm -rf build

-include $(wildcard $(BUILD)/obj/*/*.d $(BUILD)/obj/*/*/*.d $(BUILD)/obj/*/*/*/*.d)
-include $(wildcard mk/*.mk)
