# The DFT back end (included by the Makefile; see include/mcspec/dft.h).
#
#   make ...              KissFFT, vendored: the default, and the only back end
#                         of the embedded and cross builds
#   make FFT=fftw ...     FFTW 3 for hosted builds (Debian: libfftw3-dev), in
#                         build/fftw/ (build/san/fftw/ with SAN=1). FFTW is
#                         GPL: a program linked with this library is covered
#                         by the GPL unless it has a commercial FFTW licence.
#                         It allocates once per N, when the first plan for N
#                         is made, never per trial.
#   make spectrum-costs   measures the cost model of the spectrum accumulator's
#                         AUTO path on this machine and fits its constants
#                         (test/bench/spectrum_costs.c); FFT=fftw for FFTW's
#
# Only the host library's compile line gets -DMCS_DFT_FFTW: the cross,
# stack and lint builds compile src/dft/dft_fftw.c as its KissFFT-only stubs.

.PHONY: spectrum-costs

FFT ?= kiss
ifeq ($(FFT),fftw)
LIB_CC += -DMCS_DFT_FFTW
LDLIBS += -lfftw3
LIB_LIBS := -lfftw3
# Before the first object: can $(CC) build and link an FFTW 3 program? If
# not, one line that says what to install, instead of an error deep inside
# src/dft/dft_fftw.c. The stamp is made once per build folder.
FFTW_PROBE := $(BUILD)/fftw-probe.ok
$(FFTW_PROBE):
	@mkdir -p $(@D)
	@[ "$$(sh tools/bench_deps.sh fftw '$(CC)')" = 1 ] || { \
	    echo "make FFT=fftw: $(CC) cannot build a program with <fftw3.h> and -lfftw3: install FFTW 3's development files (Debian: apt-get install libfftw3-dev)"; \
	    exit 2; }
	@touch $@
$(LIB_OBJ) $(PIC_OBJ): | $(FFTW_PROBE)
else ifneq ($(FFT),kiss)
$(error FFT must be kiss (the default) or fftw, not '$(FFT)')
endif

spectrum-costs: $(BUILD)/bench/spectrum_costs
	$(BUILD)/bench/spectrum_costs
