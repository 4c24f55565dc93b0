# The mcspec command (cli/), its installation and its figures. Included by
# the Makefile.
#
#   make cli            build/bin/mcspec (part of `make all`)
#   make install-cli    install it as $(DESTDIR)$(BINDIR)/mcspec
#                       (BINDIR defaults to $(PREFIX)/bin, PREFIX to /usr/local)
#   make uninstall-cli  remove it again
#   make plots          render the figures README shows into docs/plots/ (PNG,
#                       by gnuplot through `mcspec ... --plot`); the figures and
#                       their command lines are listed in docs/plots/figures.list
#   make check-plots    render every listed figure as PNG and SVG under
#                       build/plots-check and check each one (valid image of the
#                       expected size, the expected series in its legend), and
#                       that docs/plots holds every figure (tools/check_plots.sh)
#
# Adding a figure: a line in docs/plots/figures.list if `mcspec` draws it;
# otherwise a rule for docs/plots/NAME.png in your own mk/*.mk plus
# `plots: docs/plots/NAME.png` there (the hook for the variance-convergence
# figure of question 6 of the open-questions example).

.PHONY: cli install-cli uninstall-cli plots check-plots

CLI_SRC  := $(sort $(wildcard cli/*.c))
CLI_OBJ  := $(CLI_SRC:%.c=$(BUILD)/obj/%.o)
CLI_BIN  := $(BUILD)/bin/mcspec
# The command is a hosted POSIX program (getline, mkdtemp, posix_spawn, isatty).
CLI_DEFS := -D_POSIX_C_SOURCE=200809L

PREFIX  ?= /usr/local
BINDIR  ?= $(PREFIX)/bin
INSTALL ?= install

all: cli
cli: $(CLI_BIN)
# test/cli_check.sh runs $(CLI_BIN) (given to it as MCSPEC by the test recipe).
test: $(CLI_BIN)

$(BUILD)/obj/cli/%.o: cli/%.c $(FLAGS_STAMP)
	@mkdir -p $(@D)
	@echo "CC $@"
	$(Q)$(MCS_CC) $(CLI_DEFS) $(DEPFLAGS) -c $< -o $@

$(CLI_BIN): $(CLI_OBJ) $(LIB) $(FLAGS_STAMP)
	@mkdir -p $(@D)
	@echo "LD $@"
	$(Q)$(MCS_CC) $(CLI_OBJ) $(LIB) $(LDFLAGS) $(LDLIBS) -o $@

install-cli: $(CLI_BIN)
	$(INSTALL) -d $(DESTDIR)$(BINDIR)
	$(INSTALL) -m 755 $(CLI_BIN) $(DESTDIR)$(BINDIR)/mcspec

uninstall-cli:
	rm -f $(DESTDIR)$(BINDIR)/mcspec

SEC5_BIN := $(BUILD)/examples/sec5_open_questions

plots: $(CLI_BIN) $(SEC5_BIN)
	@sh tools/check_plots.sh -b $(CLI_BIN) -r -o docs/plots
	@sh tools/plot_convergence.sh $(SEC5_BIN) docs/plots/sec5_convergence.png

# The question-6 convergence figure (tools/plot_convergence.sh) is checked
# here: an SVG with a legend entry per pattern and its data drawn.
check-plots: $(CLI_BIN) $(SEC5_BIN)
	@sh tools/check_plots.sh -b $(CLI_BIN) -o $(BUILD)/plots-check
	@sh tools/plot_convergence.sh $(SEC5_BIN) $(BUILD)/plots-check/sec5_convergence.svg && \
	    for p in random stratified jitter homogenized; do \
	        grep -q "<title>$$p exact</title>" $(BUILD)/plots-check/sec5_convergence.svg || \
	            { echo "check-plots: sec5_convergence.svg lacks the $$p series"; exit 1; }; \
	        grep -q "<title>$$p measured" $(BUILD)/plots-check/sec5_convergence.svg || \
	            { echo "check-plots: sec5_convergence.svg has no legend entry for $$p's measured points"; exit 1; }; \
	    done && \
	    test "$$(grep -c '<path' $(BUILD)/plots-check/sec5_convergence.svg)" -ge 16 && \
	    echo "check-plots: sec5_convergence.svg has its four series" || \
	    { echo "check-plots: sec5_convergence.svg failed"; exit 1; }
