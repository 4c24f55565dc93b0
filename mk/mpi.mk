# mcspec-mpi, the MPI runner of `mcspec pattern` (mpi/mcspec_mpi.c,
# docs/scaling.md). Included by the Makefile; needs mk/cli.mk (CLI_OBJ).
#
#   make mpi          build/bin/mcspec-mpi (part of `make all` when mpicc exists)
#   make check-mpi    test/mpi_check.sh: P = 1, 2, 4 ranks against
#                     `mcspec pattern --streams P` and the merge of the P
#                     `--stream I` files, and the failure paths
#   make install-mpi  install it as $(DESTDIR)$(BINDIR)/mcspec-mpi (part of
#                     `make install` when mpicc exists)
#   make scaling-figures  the measured figures of docs/scaling.md
#
# MPICC and MPIRUN default to the ones on PATH (Open MPI's mpicc and mpirun
# from Debian's libopenmpi-dev and openmpi-bin); without mpicc, `make all`
# skips mcspec-mpi and `make mpi` says why.

.PHONY: mpi check-mpi install-mpi uninstall-mpi scaling-figures

MPICC   ?= $(shell command -v mpicc)
MPIRUN  ?= $(shell command -v mpirun)
MPI_BIN := $(BUILD)/bin/mcspec-mpi
# Every object of the command but its main().
MPI_CLI_OBJ := $(filter-out $(BUILD)/obj/cli/mcspec.o,$(CLI_OBJ))

ifneq ($(MPICC),)
all: mpi
install: install-mpi
uninstall: uninstall-mpi
endif

mpi: $(MPI_BIN)

# mpicc wraps the C compiler with MPI's include and library flags; the
# command's objects are the ordinary ones (they do not include mpi.h).
$(MPI_BIN): mpi/mcspec_mpi.c $(MPI_CLI_OBJ) $(LIB) $(FLAGS_STAMP)
	@test -n "$(MPICC)" || { echo "mpi: mpicc not found (install libopenmpi-dev)"; exit 1; }
	@mkdir -p $(@D) $(BUILD)/obj/mpi
	@echo "MPICC $@"
	$(Q)$(MPICC) $(WARN) $(OPT) $(SANFLAGS) $(MCS_CPPFLAGS) $(CPPFLAGS) $(CFLAGS) -Icli \
	    $(CLI_DEFS) -MMD -MP -MF $(BUILD)/obj/mpi/mcspec_mpi.d $< $(MPI_CLI_OBJ) $(LIB) \
	    $(LDFLAGS) $(LDLIBS) -o $@

-include $(wildcard $(BUILD)/obj/mpi/*.d)

check-mpi: $(MPI_BIN) $(CLI_BIN)
	@test -n "$(MPIRUN)" || { echo "check-mpi: mpirun not found (install openmpi-bin)"; exit 1; }
	@MCSPEC=$(CLI_BIN) MCSPEC_MPI=$(MPI_BIN) MPIRUN=$(MPIRUN) sh test/mpi_check.sh

install-mpi: $(MPI_BIN)
	$(INSTALL) -d $(DESTDIR)$(BINDIR)
	$(INSTALL) -m 755 $(MPI_BIN) $(DESTDIR)$(BINDIR)/mcspec-mpi

uninstall-mpi:
	rm -f $(DESTDIR)$(BINDIR)/mcspec-mpi

$(BUILD)/tools/io_cost: tools/io_cost.c $(LIB) $(FLAGS_STAMP)
	@mkdir -p $(@D)
	@echo "LD $@"
	$(Q)$(MCS_CC) $< $(LIB) $(LDFLAGS) $(LDLIBS) -o $@

# The figures of docs/scaling.md, measured on this machine (a few seconds).
scaling-figures: $(BUILD)/tools/io_cost $(MPI_BIN) $(CLI_BIN)
	@MCSPEC=$(CLI_BIN) MCSPEC_MPI=$(MPI_BIN) MPIRUN=$(MPIRUN) IO_COST=$(BUILD)/tools/io_cost \
	    sh tools/scaling_figures.sh
