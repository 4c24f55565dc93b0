# Cross builds (included by the Makefile; see docs/embedded.md).
#
#   make cross      cross-m4 cross-m7 cross-rv
#   make cross-m4   libmcspec.a for Cortex-M4F (single-precision FPU: doubles in
#                   software), the nm allow-list on it, and the firmware image
#                   of examples/firmware with its arm-none-eabi-size
#   make cross-m7   the same for Cortex-M7 with the double-precision FPU
#   make cross-rv   every library source compiled for RV64 with
#                   riscv64-unknown-elf-gcc -ffreestanding (that toolchain has
#                   no C library: tools/freestanding stands in for the four
#                   headers the sources include), and the allow-list on it
#
# The libraries are built at the default capacities; the firmware links its
# own copy built with FW_DEFS so that its static accumulators fit a small
# part's RAM: MCS_MAX_N=256 for the mcs_spectrum, and a 2D point-set cutoff
# of 8, a 1D one of 32 and 8 x 8 bins for the 2D binned spectrum.
#
# NUFFT=0 (`make cross NUFFT=0`): the same builds without the NUFFT
# (MCS_CONFIG_NUFFT 0, the Makefile's NUFFT_DEFS through MCS_CPPFLAGS), under
# build/nonufft/ instead of build/, so both sets of sizes can be compared.

.PHONY: cross cross-m4 cross-m7 cross-rv sizes cross-m4-lib cross-m7-lib

CROSS_OUT  := build$(NUFFT_DIR)
ARM_PREFIX ?= arm-none-eabi-
RV_PREFIX  ?= riscv64-unknown-elf-
CROSS_OPT  ?= -O2 -g
FW_OPT     ?= -Os -g
FW_DEFS    ?= -DMCS_MAX_N=256 -DMCS_MAX_FREQ=8 -DMCS_MAX_FREQ_1D=32 -DMCS_MAX_SIDE=8
# The smallest configuration the size table shows.
SMALL_DEFS ?= -DMCS_MAX_N=64 -DMCS_MAX_COV_N=16 -DMCS_MAX_FREQ=4 -DMCS_MAX_FREQ_1D=16 -DMCS_MAX_SIDE=4
CROSS_COMMON := -ffreestanding -ffunction-sections -fdata-sections
M4_ARCH := -mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16
M7_ARCH := -mcpu=cortex-m7 -mthumb -mfloat-abi=hard -mfpu=fpv5-d16
RV_ARCH := -march=rv64imafdc -mabi=lp64d -mcmodel=medany
# Names that must not appear in a firmware image: the heap, stdio, exit paths.
FW_FORBIDDEN := malloc|_malloc_r|calloc|_calloc_r|realloc|_realloc_r|free|_free_r|_sbrk|_sbrk_r|\
                abort|exit|_exit|atexit|__call_exitprocs|printf|_printf_r|puts|_puts_r|\
                fprintf|_fprintf_r|__sinit|__sfp|_vfprintf_r|_svfprintf_r

cross: cross-m4 cross-m7 cross-rv sizes

# Compile lines are summarised ("CC build/cross-m4/obj/src/dft.o"); V=1 shows them.
ifeq ($(V),1)
EMB_Q :=
else
EMB_Q := @
endif

# A library build in directory $(1) with compiler prefix $(2) and flags $(3).
# Vendored code keeps its own warnings, but an undeclared function is an error
# there too (with tools/freestanding that is how a stray malloc shows up).
# Like the host build's flags stamp (Makefile), $(1)/flags.txt changes only
# when the flags do, and every object depends on it: `make cross
# FW_DEFS=...` or `CPPFLAGS=-DMCS_MAX_SIDE=...` rebuilds instead of linking
# objects of two capacities together.
define MCS_CROSS_LIB
$(1)/flags.txt: MCS_CROSS_FLAGS_TEXT = $(2)gcc | $(2)ar | $$(WARN) | $$(VENDOR_WARN) | $(3) | \
    $$(MCS_CPPFLAGS) | $$(CPPFLAGS) | $$(KISS_DEFS)
$(1)/flags.txt: FORCE
	@mkdir -p $$(@D)
	@printf '%s\n' '$$(subst ','\'',$$(MCS_CROSS_FLAGS_TEXT))' >$$@.new
	@if cmp -s $$@.new $$@; then rm -f $$@.new; else mv -f $$@.new $$@; fi

$(1)/obj/src/vendor/%.o: src/vendor/%.c $(1)/flags.txt
	@mkdir -p $$(@D)
	@echo "CC $$@"
	$$(EMB_Q)$(2)gcc $$(VENDOR_WARN) -Werror=implicit-function-declaration $(3) $$(KISS_DEFS) \
	    -MMD -MP -c $$< -o $$@

$(1)/obj/src/%.o: src/%.c $(1)/flags.txt
	@mkdir -p $$(@D)
	@echo "CC $$@"
	$$(EMB_Q)$(2)gcc $$(WARN) $(3) $$(MCS_CPPFLAGS) $$(LIB_INC) $$(CPPFLAGS) -isystem src/vendor/kissfft $$(KISS_DEFS) \
	    -MMD -MP -c $$< -o $$@

$(1)/libmcspec.a: $$(LIB_SRC:%.c=$(1)/obj/%.o) $$(KISS_SRC:%.c=$(1)/obj/%.o) $(1)/flags.txt
	@rm -f $$@
	@echo "AR $$@"
	$$(EMB_Q)$(2)ar rcs $$@ $$(filter %.o,$$^)

-include $$(wildcard $(1)/obj/src/*/*.d $(1)/obj/src/vendor/kissfft/*.d)
endef

# A Cortex-M target $(1) (m4, m7) with arch flags $(2): library, firmware, checks.
define MCS_CORTEX_M
$(call MCS_CROSS_LIB,$(CROSS_OUT)/cross-$(1),$(ARM_PREFIX),$(2) $(CROSS_COMMON) $(CROSS_OPT))
$(call MCS_CROSS_LIB,$(CROSS_OUT)/cross-$(1)/fw,$(ARM_PREFIX),$(2) $(CROSS_COMMON) $(FW_OPT) $(FW_DEFS) -fstack-usage -fcallgraph-info=su)

# The firmware's own objects share the stamp of its library (same flags).
$(CROSS_OUT)/cross-$(1)/fw/obj/examples/firmware/%.o: examples/firmware/%.c $(CROSS_OUT)/cross-$(1)/fw/flags.txt
	@mkdir -p $$(@D)
	@echo "CC $$@"
	$$(EMB_Q)$(ARM_PREFIX)gcc $$(WARN) $(2) $(CROSS_COMMON) $(FW_OPT) $(FW_DEFS) -fstack-usage \
	    -fcallgraph-info=su $$(MCS_CPPFLAGS) $$(CPPFLAGS) -MMD -MP -c $$< -o $$@

-include $$(wildcard $(CROSS_OUT)/cross-$(1)/fw/obj/examples/firmware/*.d)

# Our own startup replaces crt0 (-nostartfiles); nano.specs and nosys.specs
# give newlib-nano's libc and libm and stub syscalls. The linker script has no
# heap, so anything that reached malloc would not link.
$(CROSS_OUT)/cross-$(1)/fw/firmware.elf: $(CROSS_OUT)/cross-$(1)/fw/obj/examples/firmware/main.o \
        $(CROSS_OUT)/cross-$(1)/fw/obj/examples/firmware/startup.o $(CROSS_OUT)/cross-$(1)/fw/libmcspec.a \
        examples/firmware/$(1).ld examples/firmware/sections.ld
	@echo "LD $$@"
	$$(EMB_Q)$(ARM_PREFIX)gcc $(2) --specs=nano.specs --specs=nosys.specs -nostartfiles \
	    -Wl,--gc-sections -Wl,-Map=$(CROSS_OUT)/cross-$(1)/fw/firmware.map -Lexamples/firmware \
	    -T $(1).ld $$(filter %.o,$$^) $(CROSS_OUT)/cross-$(1)/fw/libmcspec.a -lm -o $$@

# The allow-list check runs before the firmware link, whose failure on a
# stray malloc ("undefined reference to `end'") is less telling.
cross-$(1)-lib: $(CROSS_OUT)/cross-$(1)/libmcspec.a
	@sh tools/check_alloc.sh -n $(ARM_PREFIX)nm -l "Cortex-$(1) libmcspec.a ($(2))" \
	    -r "$$$$($(ARM_PREFIX)gcc $(2) -print-libgcc-file-name)" $(CROSS_OUT)/cross-$(1)/libmcspec.a

$(CROSS_OUT)/cross-$(1)/fw/firmware.elf: | cross-$(1)-lib

cross-$(1): cross-$(1)-lib $(CROSS_OUT)/cross-$(1)/fw/firmware.elf
	@bad=$$$$($(ARM_PREFIX)nm $(CROSS_OUT)/cross-$(1)/fw/firmware.elf | \
	    grep -E ' ($(strip $(FW_FORBIDDEN)))$$$$' || true); \
	if [ -n "$$$$bad" ]; then echo "cross-$(1): firmware image contains:"; echo "$$$$bad"; exit 1; fi; \
	echo "cross-$(1): firmware image has no heap, stdio or exit symbols"
	@echo "cross-$(1): arm-none-eabi-size $(CROSS_OUT)/cross-$(1)/fw/firmware.elf" \
	    "(flash = text + data; RAM = data + bss, bss including the 8 KiB stack reservation)"
	@$(ARM_PREFIX)size $(CROSS_OUT)/cross-$(1)/fw/firmware.elf
	@echo "cross-$(1): firmware stack from Reset_Handler, against the 8 KiB reservation:"
	@sh tools/stack_report.sh -n 1 -l 8192 -e Reset_Handler $(CROSS_OUT)/cross-$(1)/fw/obj | sed 1,2d
endef

$(eval $(call MCS_CORTEX_M,m4,$(M4_ARCH)))
$(eval $(call MCS_CORTEX_M,m7,$(M7_ARCH)))
$(eval $(call MCS_CROSS_LIB,$(CROSS_OUT)/rv,$(RV_PREFIX),$(RV_ARCH) $(CROSS_COMMON) $(CROSS_OPT) -isystem tools/freestanding))

cross-rv: $(CROSS_OUT)/rv/libmcspec.a
	@sh tools/check_alloc.sh -n $(RV_PREFIX)nm -l "RV64 libmcspec.a ($(RV_ARCH), compile only)" \
	    -r "$$($(RV_PREFIX)gcc $(RV_ARCH) -print-libgcc-file-name)" $(CROSS_OUT)/rv/libmcspec.a

# sizeof each public struct: on the host, on Cortex-M (32-bit size_t) at the
# default capacities, at the firmware's, and at a small configuration.
sizes:
	@echo "sizeof, bytes (tools/sizes.sh); firmware: $(FW_DEFS); small: $(SMALL_DEFS)"
	@sh tools/sizes.sh $(CROSS_OUT)/sizes "x86-64|$(CC)|$(EMB_NM)|" \
	    "Cortex-M|$(ARM_PREFIX)gcc|$(ARM_PREFIX)nm|$(M4_ARCH)" \
	    "Cortex-M firmware|$(ARM_PREFIX)gcc|$(ARM_PREFIX)nm|$(M4_ARCH) $(FW_DEFS)" \
	    "Cortex-M small|$(ARM_PREFIX)gcc|$(ARM_PREFIX)nm|$(M4_ARCH) $(SMALL_DEFS)"
