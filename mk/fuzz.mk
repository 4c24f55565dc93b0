# Fuzzing with libFuzzer (included by the Makefile). clang builds the library
# and each target with ASan + UBSan under build/fuzz/.
#
#   make fuzz [FUZZ_SECONDS=600]   every target for FUZZ_SECONDS each
#   make fuzz-ci                   every target for its CI budget; any finding fails
#   make fuzz-NAME / fuzz-ci-NAME  one target
#   make fuzz-corpus               regenerate the committed seed corpus of fuzz_load
#
# A target NAME is fuzz/fuzz_NAME.c (defining LLVMFuzzerTestOneInput) with its
# seeds in fuzz/corpus/NAME/ (may be empty). Adding one is one line at the
# end of this file: $(eval $(call MCS_FUZZ_TARGET,NAME,CI_SECONDS)).
# New inputs libFuzzer finds go to build/fuzz/corpus/NAME/ (never into the
# committed seeds); a crashing input is saved as build/fuzz/artifacts/NAME-*
# and reproduced with build/fuzz/fuzz_NAME FILE.

.PHONY: fuzz fuzz-ci fuzz-build fuzz-corpus

# Every finding of fuzz_api is fatal. FUZZ_API_KNOWN=skip (or =<item>) counts
# findings of a numbered open item instead (fuzz/fuzz_api.c), for hunting
# past a known defect; none is open today.
FUZZ_API_KNOWN ?=
export FUZZ_API_KNOWN

FUZZ_CC      ?= $(shell command -v clang-14 || command -v clang)
FUZZ_BUILD   := build/fuzz
FUZZ_SECONDS ?= 60
FUZZ_SAN     := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
FUZZ_OPT     := -O1 -g
# Per input: a timeout well above any honest run, a maximum length above the
# largest seed (records of N up to a few hundred, 2D cutoffs up to 16), and
# libFuzzer's own leak check off (nothing here allocates).
FUZZ_RUN_FLAGS ?= -timeout=10 -max_len=12288 -detect_leaks=0 -print_final_stats=1
FUZZ_TARGETS :=

FUZZ_LIB_OBJ := $(LIB_SRC:%.c=$(FUZZ_BUILD)/obj/%.o) $(KISS_SRC:%.c=$(FUZZ_BUILD)/obj/%.o)
FUZZ_LIB     := $(FUZZ_BUILD)/libmcspec.a

$(FUZZ_BUILD)/obj/src/vendor/%.o: src/vendor/%.c
	@mkdir -p $(@D)
	$(FUZZ_CC) $(VENDOR_WARN) $(FUZZ_OPT) $(FUZZ_SAN) -fsanitize=fuzzer-no-link $(KISS_DEFS) \
	    -MMD -MP -c $< -o $@

$(FUZZ_BUILD)/obj/src/%.o: src/%.c
	@mkdir -p $(@D)
	$(FUZZ_CC) $(WARN) $(FUZZ_OPT) $(FUZZ_SAN) -fsanitize=fuzzer-no-link $(MCS_CPPFLAGS) $(LIB_INC) $(CPPFLAGS) \
	    -isystem src/vendor/kissfft $(KISS_DEFS) -MMD -MP -c $< -o $@

$(FUZZ_LIB): $(FUZZ_LIB_OBJ)
	@rm -f $@
	$(AR) rcs $@ $^

-include $(wildcard $(FUZZ_BUILD)/obj/src/*/*.d $(FUZZ_BUILD)/obj/src/vendor/kissfft/*.d)

# The seed tool is an ordinary program against the ordinary library.
$(FUZZ_BUILD)/make_corpus: fuzz/make_corpus.c $(LIB)
	@mkdir -p $(@D)
	$(CC) $(WARN) $(OPT) $(MCS_CPPFLAGS) $(CPPFLAGS) $< $(LIB) $(LDLIBS) -o $@

fuzz-corpus: $(FUZZ_BUILD)/make_corpus
	@mkdir -p fuzz/corpus/load
	$(FUZZ_BUILD)/make_corpus fuzz/corpus/load
	@echo "fuzz-corpus: $$(ls fuzz/corpus/load | wc -l) records in fuzz/corpus/load"

fuzz-check-cc:
	@test -n "$(FUZZ_CC)" || { echo "fuzz: clang not installed (set FUZZ_CC)"; exit 1; }
.PHONY: fuzz-check-cc

# $(1) name, $(2) seconds in CI.
define MCS_FUZZ_TARGET
FUZZ_TARGETS += $(1)

$(FUZZ_BUILD)/fuzz_$(1): fuzz/fuzz_$(1).c $(FUZZ_LIB) | fuzz-check-cc
	@mkdir -p $$(@D)
	$$(FUZZ_CC) $$(WARN) $$(FUZZ_OPT) $$(FUZZ_SAN) -fsanitize=fuzzer $$(MCS_CPPFLAGS) $$(CPPFLAGS) $$< $$(FUZZ_LIB) \
	    $$(LDLIBS) -o $$@

.PHONY: fuzz-$(1) fuzz-ci-$(1)
fuzz-$(1): $(FUZZ_BUILD)/fuzz_$(1)
	@mkdir -p $(FUZZ_BUILD)/corpus/$(1) $(FUZZ_BUILD)/artifacts fuzz/corpus/$(1)
	$(FUZZ_BUILD)/fuzz_$(1) $$(FUZZ_RUN_FLAGS) -max_total_time=$$(FUZZ_SECONDS) \
	    -artifact_prefix=$(FUZZ_BUILD)/artifacts/$(1)- $(FUZZ_BUILD)/corpus/$(1) fuzz/corpus/$(1)

fuzz-ci-$(1): $(FUZZ_BUILD)/fuzz_$(1)
	@$$(MAKE) --no-print-directory fuzz-$(1) FUZZ_SECONDS=$(2)

fuzz: fuzz-$(1)
fuzz-ci: fuzz-ci-$(1)
fuzz-build: $(FUZZ_BUILD)/fuzz_$(1)
endef

# ------------------------------------------------------------------ targets
$(eval $(call MCS_FUZZ_TARGET,load,30))
$(eval $(call MCS_FUZZ_TARGET,api,30))
# fuzz_api.c includes its second half (one translation unit).
$(FUZZ_BUILD)/fuzz_api: fuzz/fuzz_api_ops.h
