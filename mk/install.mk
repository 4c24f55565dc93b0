# Install, uninstall and the consumer tests (included by the Makefile; see
# docs/integrating.md).
#
#   make install PREFIX=/usr/local DESTDIR=   headers, libmcspec.a,
#                  libmcspec.so.X.Y.Z (SONAME libmcspec.so.X, only the API
#                  exported), mcspec.pc, the CMake package, the licences
#   make uninstall PREFIX=... DESTDIR=...     removes what install wrote
#   make check-install   installs into a temporary prefix and builds and runs
#                  consumers against the installed files only
#                  (test/consumers/run.sh), plus the CMake build
#
# The installed mcspec/config.h, mcspec.pc and mcspecConfig.cmake record the
# capacities the library was actually built with: they are read back from the
# capacity tag the archive defines (src/version.c), not from the flags.

.PHONY: install uninstall install-files check-install

PREFIX       ?= /usr/local
LIBDIR       ?= $(PREFIX)/lib
INCLUDEDIR   ?= $(PREFIX)/include
DOCDIR       ?= $(PREFIX)/share/doc/mcspec
PKGCONFIGDIR ?= $(LIBDIR)/pkgconfig
CMAKEDIR     ?= $(LIBDIR)/cmake/mcspec
INSTALL      ?= install
CMAKE        ?= cmake

GEN_DIR      := $(BUILD)/install
GEN_CAPS     := $(GEN_DIR)/capacities.sed
GEN_CONFIG_H := $(GEN_DIR)/mcspec/config.h
GEN_PC       := $(GEN_DIR)/mcspec.pc
GEN_CMAKE    := $(GEN_DIR)/mcspecConfig.cmake $(GEN_DIR)/mcspecConfigVersion.cmake
INSTALL_HEADERS := $(filter-out include/mcspec/config.h,$(wildcard include/mcspec/*.h))
INSTALL_DOCS := LICENSE CHANGELOG.md docs/integrating.md
KISS_LICENCES := src/vendor/kissfft/COPYING src/vendor/kissfft/LICENSES/BSD-3-Clause \
                 src/vendor/kissfft/LICENSES/Unlicense

# The capacity macros, in the order config.h's MCS_CONFIG_LINK_TAG names them.
MCS_CAPS := MCS_MAX_N MCS_MAX_COV_N MCS_MAX_FREQ MCS_MAX_FREQ_1D MCS_MAX_SIDE

# A sed script, "s|@NAME@|value|g" per capacity, from the archive's one tag
# mcs_config_requires_libmcspec_built_with_MCS_MAX_N_<N>_..._MCS_MAX_SIDE_<S>:
# each name of MCS_CAPS in turn, then a decimal value, and nothing left over.
$(GEN_CAPS): $(LIB)
	@mkdir -p $(@D)
	@tag=$$($(EMB_NM) -P -g --defined-only $(LIB) | \
	    sed -n 's/^mcs_config_requires_libmcspec_built_with\(_[A-Za-z0-9_]*\) .*/\1/p'); \
	rest=$$tag; : >$@.tmp; \
	for cap in $(MCS_CAPS); do \
	    case $$rest in _$${cap}_[0-9]*) ;; *) rest=bad; break ;; esac; \
	    rest=$${rest#_$${cap}_}; value=$${rest%%_*}; rest=$${rest#"$$value"}; \
	    case $$value in *[!0-9]*) rest=bad; break ;; esac; \
	    echo "s|@$$cap@|$$value|g" >>$@.tmp; \
	done; \
	test -n "$$tag" && test -z "$$rest" || { rm -f $@.tmp; \
	    echo "install: no single capacity tag naming $(MCS_CAPS) in $(LIB)" \
	        "(the capacities must be plain decimal numbers); found: $$tag"; \
	    exit 1; }
	@mv -f $@.tmp $@

# What a static link needs beyond libmcspec.a: the FFTW back end's library
# with FFT=fftw (mk/fft.mk), nothing with KissFFT, then libm. As mcspec.pc's
# Libs.private and as a CMake list for the package.
# -lfftw3 goes before -lm: libfftw3.a calls libm too, and a fully static
# link (-static) resolves only against the libraries after the caller.
LIBS_PRIVATE      := $(strip $(LIB_LIBS) -lm)
STATIC_CMAKE_LIBS := $(patsubst -l%,%,$(LIBS_PRIVATE))

# Substitutes @NAME@ in a template: $(call mcs_subst,template,extra sed args).
mcs_subst = sed -f $(GEN_CAPS) -e 's|@VERSION@|$(VERSION)|g' \
        -e 's|@VERSION_MAJOR@|$(VERSION_MAJOR)|g' -e 's|@VERSION_MINOR@|$(VERSION_MINOR)|g' \
        -e 's|@LIBS_PRIVATE@|$(LIBS_PRIVATE)|g' -e 's|@STATIC_CMAKE_LIBS@|$(STATIC_CMAKE_LIBS)|g' $(2) $(1)

# config.h with the capacities block spliced in after its "mcspec-install:" line.
$(GEN_CONFIG_H): include/mcspec/config.h cmake/capacities.h.in $(GEN_CAPS)
	@mkdir -p $(@D)
	@$(call mcs_subst,cmake/capacities.h.in) >$(GEN_DIR)/capacities.h
	@$(if $(NUFFT_DEFS),printf '%s\n' '/* ... and without the NUFFT (make NUFFT=0: config.h below). */' \
	    '#ifndef MCS_CONFIG_NUFFT' '#define MCS_CONFIG_NUFFT 0' '#endif' >>$(GEN_DIR)/capacities.h,:)
	@grep -q 'mcspec-install:' include/mcspec/config.h || { echo "install: marker missing in config.h"; exit 1; }
	@sed '/mcspec-install:/r $(GEN_DIR)/capacities.h' include/mcspec/config.h >$@

# The paths are the final ones (without DESTDIR); libdir and includedir
# relative to ${prefix} when they are under it.
$(GEN_PC): cmake/mcspec.pc.in $(GEN_CAPS) FORCE
	@mkdir -p $(@D)
	@$(call mcs_subst,cmake/mcspec.pc.in,-e 's|@PREFIX@|$(PREFIX)|' \
	    -e 's|@LIBDIR@|$(patsubst $(PREFIX)/%,$${prefix}/%,$(LIBDIR))|' \
	    -e 's|@INCLUDEDIR@|$(patsubst $(PREFIX)/%,$${prefix}/%,$(INCLUDEDIR))|') >$@

# The size of a pointer of the target, for the version file.
SIZEOF_VOID_P = $$($(CC) $(CFLAGS) -dM -E -x c /dev/null | sed -n 's/^\#define __SIZEOF_POINTER__ //p')

$(GEN_DIR)/mcspecConfig.cmake: cmake/mcspecConfig.cmake.in $(GEN_CAPS) FORCE
	@$(call mcs_subst,$<,-e 's|@CONFIG_PREFIX@|$(PREFIX)|' -e 's|@CONFIG_LIBDIR@|$(LIBDIR)|' \
	    -e 's|@CONFIG_INCLUDEDIR@|$(INCLUDEDIR)|') >$@

$(GEN_DIR)/mcspecConfigVersion.cmake: cmake/mcspecConfigVersion.cmake.in $(GEN_CAPS) FORCE
	@$(call mcs_subst,$<,-e "s|@SIZEOF_VOID_P@|$(SIZEOF_VOID_P)|") >$@

install: $(LIB) $(BUILD)/libmcspec.so $(GEN_CONFIG_H) $(GEN_PC) $(GEN_CMAKE)
	$(INSTALL) -d $(DESTDIR)$(INCLUDEDIR)/mcspec $(DESTDIR)$(LIBDIR) $(DESTDIR)$(PKGCONFIGDIR) \
	    $(DESTDIR)$(CMAKEDIR) $(DESTDIR)$(DOCDIR)/kissfft
	$(INSTALL) -m 644 include/mcspec.h $(DESTDIR)$(INCLUDEDIR)/
	$(INSTALL) -m 644 $(INSTALL_HEADERS) $(GEN_CONFIG_H) $(DESTDIR)$(INCLUDEDIR)/mcspec/
	$(INSTALL) -m 644 $(LIB) $(DESTDIR)$(LIBDIR)/
	$(INSTALL) -m 755 $(SHLIB) $(DESTDIR)$(LIBDIR)/
	ln -sf $(notdir $(SHLIB)) $(DESTDIR)$(LIBDIR)/$(SONAME)
	ln -sf $(SONAME) $(DESTDIR)$(LIBDIR)/libmcspec.so
	$(INSTALL) -m 644 $(GEN_PC) $(DESTDIR)$(PKGCONFIGDIR)/
	$(INSTALL) -m 644 $(GEN_CMAKE) $(DESTDIR)$(CMAKEDIR)/
	$(INSTALL) -m 644 $(INSTALL_DOCS) $(DESTDIR)$(DOCDIR)/
	$(INSTALL) -m 644 $(KISS_LICENCES) $(DESTDIR)$(DOCDIR)/kissfft/

# Removes every file install writes; mcspec's own directories (include/mcspec,
# cmake/mcspec, the doc directory) go whole, shared ones only if left empty.
uninstall:
	rm -f $(DESTDIR)$(INCLUDEDIR)/mcspec.h $(DESTDIR)$(INCLUDEDIR)/mcspec/*.h
	rm -f $(DESTDIR)$(LIBDIR)/libmcspec.a $(DESTDIR)$(LIBDIR)/libmcspec.so \
	    $(DESTDIR)$(LIBDIR)/libmcspec.so.$(VERSION_MAJOR) $(DESTDIR)$(LIBDIR)/libmcspec.so.$(VERSION)
	rm -f $(DESTDIR)$(PKGCONFIGDIR)/mcspec.pc
	rm -f $(DESTDIR)$(CMAKEDIR)/mcspecConfig.cmake $(DESTDIR)$(CMAKEDIR)/mcspecConfigVersion.cmake
	rm -f $(addprefix $(DESTDIR)$(DOCDIR)/,$(notdir $(INSTALL_DOCS))) \
	    $(addprefix $(DESTDIR)$(DOCDIR)/kissfft/,$(notdir $(KISS_LICENCES)))
	-rmdir $(DESTDIR)$(INCLUDEDIR)/mcspec $(DESTDIR)$(CMAKEDIR) $(DESTDIR)$(DOCDIR)/kissfft \
	    $(DESTDIR)$(DOCDIR) 2>/dev/null
	-rmdir $(DESTDIR)$(PKGCONFIGDIR) $(DESTDIR)$(LIBDIR)/cmake 2>/dev/null
	@true

# Consumers of the installed files (test/consumers/run.sh says which). The
# script installs with this Makefile into a temporary prefix itself;
# BUILD_LIB is the build tree's archive, for the link-time capacity check.
check-install: $(LIB) $(BUILD)/libmcspec.so
	@MAKE='$(MAKE)' CC='$(CC)' CXX='$(CXX)' CMAKE='$(CMAKE)' NM='$(EMB_NM)' WERROR='$(WERROR)' \
	    BUILD_LIB='$(LIB)' sh test/consumers/run.sh

# The mcspec command installs with the library (mk/cli.mk).
install: install-cli
uninstall: uninstall-cli
