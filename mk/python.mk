# The Python package python/mcspec (ctypes over libmcspec.so; docs/python.md).
# Included by the Makefile.
#
#   make python-test   its pytest suite against this build's library and
#                      command (also run by `make test`; skipped, with one line
#                      saying why, without a python3 that imports numpy and
#                      pytest)
#   make install       also copies the package to $(PYTHONDIR)/mcspec
#                      (default $(PREFIX)/lib/python3/dist-packages, on the
#                      path of Debian's python3 for PREFIX=/usr only; else
#                      PYTHONPATH=$(PYTHONDIR)); it finds the library in
#                      $(PREFIX)/lib next to it (python/mcspec/_lib.py)
#   make python-bench  the Python route against `mcspec spectrum --dim 2`
#                      (python/bench.py; part of make bench)
#
# The interpreter: $(PYTHON) if set, else python3 on PATH, else /usr/bin/python3,
# the first that imports numpy (python/find_python.sh).

.PHONY: python-test python-bench install-python uninstall-python

PYTHONDIR ?= $(PREFIX)/lib/python3/dist-packages
PY_SRC    := $(wildcard python/mcspec/*.py)

test: $(BUILD)/libmcspec.so

python-test: $(BUILD)/libmcspec.so $(CLI_BIN)
	@sh python/tests/run.sh $(BUILD)/libmcspec.so $(CLI_BIN) $(SAN)

install-python:
	$(INSTALL) -d $(DESTDIR)$(PYTHONDIR)/mcspec
	$(INSTALL) -m 644 $(PY_SRC) $(DESTDIR)$(PYTHONDIR)/mcspec/

uninstall-python:
	rm -rf $(DESTDIR)$(PYTHONDIR)/mcspec
	-rmdir $(DESTDIR)$(PYTHONDIR) $(dir $(DESTDIR)$(PYTHONDIR)) 2>/dev/null
	@true

install: install-python
uninstall: uninstall-python

python-bench: $(BUILD)/libmcspec.so $(CLI_BIN)
	@py=$$(sh python/find_python.sh) || { echo "python-bench: skipped: no python3 that imports numpy"; exit 0; }; \
	MCSPEC_LIBRARY=$(BUILD)/libmcspec.so PYTHONPATH=python $$py python/bench.py --mcspec $(CLI_BIN) \
	    $(if $(filter 1,$(BENCH_QUICK)),--quick)

# make check-install also installs the package into a temporary prefix and
# imports it from there, runs README's Python quick start, and pip-installs
# ./python (python/tests/install_check.sh).
.PHONY: check-install-python
check-install: check-install-python
check-install-python: $(LIB) $(BUILD)/libmcspec.so
	@MAKE='$(MAKE)' sh python/tests/install_check.sh
