# make bench: mcspec against the loops its users would write instead (FFTW,
# numpy) and against plain C floors, from one interleaved run (included by
# the Makefile; the bench itself is test/bench/bench.c and test/bench/src/).
#
#   make bench                 install the peers' packages if missing
#                              (tools/bench_deps.sh), build, run the full grid
#   make bench BENCH_QUICK=1   a subset of the grid with fewer rounds
#   make bench-run             build and run without the package step
#   make bench-pointsets       the point-set jobs of issue 24 alone
#                              (test/bench/pointset_jobs.c: A, B, C, 1D against
#                              the direct path and a numpy direct sum; a few
#                              minutes; BENCH_QUICK=1: 3 rounds)
#
# The FFTW peer is compiled in only when $(CC) can link fftw3; the answer is
# kept in $(BENCH_FFTW_STAMP), rewritten only when it changes, so installing
# FFTW rebuilds the bench and nothing else does.

.PHONY: bench bench-run bench-probe bench-pointsets

BENCH_PROG       := $(BUILD)/bench/bench
BENCH_PART_SRC   := $(sort $(wildcard test/bench/src/*.c))
BENCH_OBJ        := $(BUILD)/obj/test/bench/bench.o $(BENCH_PART_SRC:%.c=$(BUILD)/obj/%.o)
BENCH_FFTW_STAMP := $(BUILD)/bench/fftw.stamp
BENCH_NUMPY_PEER := test/bench/src/peer_numpy.py
BENCH_FLAGS_STR  := $(strip $(OPT) $(SANFLAGS))

bench:
	@sh tools/bench_deps.sh install '$(CC)'
	@$(MAKE) --no-print-directory bench-run
	@$(MAKE) --no-print-directory bench-pointsets
	@$(MAKE) --no-print-directory python-bench

bench-pointsets: $(BUILD)/bench/pointset_jobs
	@$(BUILD)/bench/pointset_jobs $(if $(filter 1,$(BENCH_QUICK)),--quick) \
	    --python "$$(sh tools/bench_deps.sh python)" --numpy-peer test/bench/src/pointset_jobs_numpy.py

bench-run: $(BENCH_PROG)
	@$(BENCH_PROG) $(if $(filter 1,$(BENCH_QUICK)),--quick) \
	    --python "$$(sh tools/bench_deps.sh python)" --numpy-peer $(BENCH_NUMPY_PEER)

bench-probe:

$(BENCH_FFTW_STAMP): bench-probe
	@mkdir -p $(@D)
	@v=$$(sh tools/bench_deps.sh fftw '$(CC)'); \
	[ "$$(cat $@ 2>/dev/null)" = "$$v" ] || echo "$$v" >$@

$(BUILD)/obj/test/bench/%.o: test/bench/%.c $(BENCH_FFTW_STAMP)
	@mkdir -p $(@D)
	@echo "CC $@"
	$(Q)$(CC) $(WARN) $(OPT) $(SANFLAGS) $(MCS_CPPFLAGS) $(CPPFLAGS) $(CFLAGS) -Itest/bench/src -D_POSIX_C_SOURCE=200809L \
	    -DBENCH_HAVE_FFTW=$$(cat $(BENCH_FFTW_STAMP)) '-DBENCH_CC="$(CC)"' \
	    "-DBENCH_CC_VERSION=\"$$($(CC) --version 2>/dev/null | head -n 1)\"" \
	    '-DBENCH_FLAGS="$(BENCH_FLAGS_STR)"' $(DEPFLAGS) -c $< -o $@

# An explicit rule: it takes precedence over the Makefile's one-source
# pattern rule for $(BUILD)/bench/%.
$(BENCH_PROG): $(BENCH_OBJ) $(LIB) $(BENCH_FFTW_STAMP)
	@mkdir -p $(@D)
	@echo "LD $@"
	$(Q)$(CC) $(OPT) $(SANFLAGS) $(CFLAGS) $(LDFLAGS) $(BENCH_OBJ) $(LIB) \
	    $$([ "$$(cat $(BENCH_FFTW_STAMP))" = 1 ] && echo -lfftw3) $(LDLIBS) -o $@

-include $(wildcard $(BUILD)/obj/test/bench/*.d $(BUILD)/obj/test/bench/src/*.d)
