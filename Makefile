# links1: one Makefile builds the firmware (three arithmetics), the host tools
# and the tests.  Each directory adds its sources in its own module.mk; this
# file holds the toolchains, the flags and the rules that turn lists into files.
#
#   make            firmware variants (float, soft, fixed, double) + host tools
#                   + the generated scenes (build/scenes/, from host-tools/gen/)
#   make run        render the default scene (installs missing packages first)
#   make test       every test; last line "N passed, N failed"
#   make bench      benchmarks (speed lives here, never in tests)
#   make fuzz       each libFuzzer harness for FUZZ_SECONDS (default 600)
#   make V=1        show full command lines
#   make LIBC=newlib  link the firmware against newlib instead of picolibc

.DEFAULT_GOAL := all
SHELL := /bin/bash

V ?= 0
# The builds that `make run`, `make test` and friends start use every host
# core (JOBS=-j1 to build one file at a time).
JOBS ?= -j$(shell nproc 2>/dev/null || echo 2)
Q := $(if $(filter 1,$(V)),,@)
# $(call say,TAG,target): one quiet line per step unless V=1
say = $(if $(Q),@printf '  %-6s %s\n' '$(1)' '$(2)';)

B := build
LIBC ?= picolibc
# make run MACHINE=an521: the default scene on the an521 boards.
MACHINE ?= virt
# Firmware goes to build/ with picolibc, build/newlib/ with newlib.
FWB := $(B)$(if $(filter newlib,$(LIBC)),/newlib)

# ---------------------------------------------------------------- host side
HOST_CC ?= cc
HOST_WARN := -Wall -Wextra -Werror
# Debug information: line tables and functions (-g1) by default, enough for
# backtraces, sanitizer reports with file and line, and gdb's breakpoints by
# line, at about two thirds of -g's compile time; `make gdb` builds its own
# copy with full -g (locals and types) in build/gdb/.
DEBUG_INFO ?= -g1
HOST_CFLAGS := -std=gnu11 -O2 $(DEBUG_INFO) $(HOST_WARN) -I. -MMD -MP -ffp-contract=off
# The sanitized builds (the unit tests, the programs board tests run) at -O1,
# as ASan's own documentation advises: they compile in half -O2's time and
# run the suite's checks about as fast.
SAN_FLAGS := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -O1
HOST_LIBS := -lm

# Arithmetic selection for shared code (fixed/ and render/):
#   double: host reference; float: hardware or software float; fixed: fixed point.
ARITH_DEF_double := -DLINKS1_NUM_DOUBLE
ARITH_DEF_float  := -DLINKS1_NUM_FLOAT
ARITH_DEF_fixed  := -DLINKS1_NUM_FIXED
# Modules may add more (HOST_EXTRA_ARITHS, each with its ARITH_DEF_<name>).
HOST_EXTRA_ARITHS :=

# ------------------------------------------------------------- firmware side
# Machines: the virt board (Cortex-A15, the default) and the an521 boards
# (dual Cortex-M33, one QEMU process per board).  What differs between them
# lives in boot/<machine>/, drivers/<machine>/ and linker/<machine>-memory.ld.
ARM_CC := arm-none-eabi-gcc
FW_MACHINES := virt an521
ARM_CPU_virt := -mcpu=cortex-a15 -mthumb
ARM_CPU_an521 := -mthumb
# Each machine's floating-point ABIs, by name (FW_ABI_machine_NAME), and
# the one each variant builds for (FW_ABI_OF_machine_variant).  The
# Cortex-A15's VFPv4 has double precision (32 d-registers); the
# Cortex-M33's FPU is single precision (FPv5-SP), and soft and fixed build
# for an M33 without one (cortex-m33+nofp: picolibc's v8-m.main/nofp).
FW_ABI_virt_vfp := -mfpu=vfpv4 -mfloat-abi=hard
FW_ABI_virt_nofp := -mfloat-abi=soft
FW_ABI_an521_fpv5sp := -mcpu=cortex-m33 -mfpu=fpv5-sp-d16 -mfloat-abi=hard
FW_ABI_an521_nofp := -mcpu=cortex-m33+nofp+nodsp -mfloat-abi=soft
FW_ABI_OF_virt_float := vfp
FW_ABI_OF_virt_soft := nofp
FW_ABI_OF_virt_fixed := nofp
FW_ABI_OF_virt_double := vfp
FW_ABI_OF_an521_float := fpv5sp
FW_ABI_OF_an521_soft := nofp
FW_ABI_OF_an521_fixed := nofp
# The an521 boards' double: the M33's FPU is single precision, so it is
# software (libgcc's, correctly rounded as the VFP's is); float stays on
# the FPU.
FW_ABI_OF_an521_double := fpv5sp
# float-esc and fixed-esc: float and fixed that escalate (--escalate): each
# carries the wide renderer (double, render/wide.h) beside its own, so both
# build for the FPU (on the M33 the wide renderer's double is software).
$(foreach m,virt an521,$(foreach v,float-esc fixed-esc,$(eval FW_ABI_OF_$(m)_$(v) := $(FW_ABI_OF_$(m)_float))))
FW_FLOAT_ABI = $(FW_ABI_$(1)_$(FW_ABI_OF_$(1)_$(2)))
FW_WIDE_float-esc := double
FW_WIDE_fixed-esc := double
# float-esc compiles to float's objects (same arithmetic, same float ABI,
# the wide renderer's entry points weak): it links those, not copies.
FW_OBJS_FROM_float-esc := float
FW_VARIANTS_virt := float soft fixed double float-esc fixed-esc
FW_VARIANTS_an521 := float soft fixed double float-esc fixed-esc
FW_VARIANTS := $(FW_VARIANTS_virt)
FW_MACHINE_DEF_virt := -DLINKS1_MACHINE_VIRT
FW_MACHINE_DEF_an521 := -DLINKS1_MACHINE_AN521
FW_ARITH_float := float
FW_ARITH_soft  := float
FW_ARITH_fixed := fixed
FW_ARITH_double := double
FW_ARITH_float-esc := float
FW_ARITH_fixed-esc := fixed
# The firmware's arithmetic code (proto/arith.h), sent in its LINK_HELLO.
FW_CODE_float := ARITH_FLOAT
FW_CODE_soft  := ARITH_SOFT
FW_CODE_fixed := ARITH_FIXED
FW_CODE_double := ARITH_DOUBLE
FW_CODE_float-esc := ARITH_FLOAT
FW_CODE_fixed-esc := ARITH_FIXED

ifeq ($(LIBC),picolibc)
LIBC_SPECS := --specs=picolibc.specs
else ifeq ($(LIBC),newlib)
LIBC_SPECS := --specs=nano.specs
else
$(error LIBC must be picolibc or newlib, not '$(LIBC)')
endif

FW_CFLAGS := -std=gnu11 -O2 $(DEBUG_INFO) $(HOST_WARN) -I. -MMD -MP \
	-ffreestanding -ffunction-sections -fdata-sections -ffp-contract=off \
	-fno-common -fno-math-errno -DLINKS1_FIRMWARE $(LIBC_SPECS)
# FW_HOT_SRCS: the renderer's inner loops, compiled at -O3 (it inlines and
# unswitches them further: about 4% fewer of a float NC's instructions a
# pixel on demo.scn, the same bits); the rest stays at -O2.
FW_HOT_SRCS := $(wildcard render/*.c fixed/*.c)
# FW_EXTRA_CFLAGS: constants overridden for a measurement (pareto.sh builds
# fixed-point formats into a build directory of its own with B=DIR).
FW_CFLAGS += $(FW_EXTRA_CFLAGS)
FW_LDFLAGS := -nostartfiles -Wl,--gc-sections -Wl,--no-warn-rwx-segments
# -lm: newlib keeps sqrtf and friends there (picolibc has them in libc too).
FW_LIBS := -lm -lc -lgcc

# ----------------------------------------------------------- module lists
# FW_SRCS:     firmware-only sources that use num_t (roles), once a variant
# FW_ARITH_FREE_SRCS[_MACHINE]: firmware-only sources (.c and .S) without
#              num_t (boot, kernel, drivers), once a machine and float ABI
# SHARED_SRCS: sources built for both firmware and host, once per arithmetic
#              (proto/, fixed/, render/): they know nothing of cores or drivers
# HOST_TOOLS:  host programs; for each NAME, NAME_SRCS lists its own sources
#              and NAME_ARITH the arithmetic of the shared code it links
# (The tests are registered in tests/plan.tsv alone; the lists of what runs
# are made from it below.  A C unit test's NAME_SRCS, NAME_ARITH and
# NAME_LIBS stay in the module.mk beside the code it tests.)
# BOARD_PROGS: host programs a board test script runs (same NAME_SRCS and
#              NAME_ARITH; built with ASan+UBSan into build/tests/ by `make`)
# ARITH_FREE_SRCS: host sources without num_t (they never include
#              fixed/num.h): compiled once for the programs of every
#              arithmetic (build/host-any[-san]/, build/fuzz-any/), with no
#              arithmetic defined, so one that does include num.h stops the
#              build at num.h's #error instead of being shared wrongly
# SRC_CFLAGS:  a host source's own extra flags, as the variable <path>_CFLAGS
#              (host-tools/model/module.mk's libassimp soname)
FW_SRCS :=
FW_ARITH_FREE_SRCS :=
FW_ARITH_FREE_SRCS_virt :=
FW_ARITH_FREE_SRCS_an521 :=
SHARED_SRCS :=
ARITH_FREE_SRCS :=
HOST_TOOLS :=

# ------------------------------------------------------------ the test plan
# tests/plan.tsv: one row a test (path, checks, seconds, suite: host, board
# or full; its header says more).  $(call plan_paths,SUITE...): the paths
# of the rows of those suites, in the plan's order.
TEST_PLAN := tests/plan.tsv
plan_paths = $(shell awk -F'\t' 'NF >= 4 && index(" $(1) ", " " $$4 " ") { print $$1 }' $(TEST_PLAN))
PLAN_TEST := $(call plan_paths,host board)
PLAN_FULL := $(call plan_paths,full)
# HOST_TESTS: the C unit tests (rows build/tests/NAME, the path with the
#   default B) that get a build
#   rule: host_prog builds NAME from its NAME_SRCS with ASan+UBSan
# HOST_TEST_BINS: those `make test` builds and runs (`make test-host` too)
# BOARD_TESTS: the scripts of `make test` (and `make test-board`)
# FULL_TESTS: what `make test-full` runs
HOST_TESTS := $(patsubst build/tests/%,%,$(filter build/tests/%,$(PLAN_TEST) $(PLAN_FULL)))
HOST_TEST_BINS := $(filter build/tests/%,$(PLAN_TEST))
BOARD_TESTS := $(filter-out build/tests/%,$(PLAN_TEST))
FULL_TESTS := $(PLAN_FULL)
BOARD_PROGS :=
BENCHES :=
FUZZERS :=
# GEN_SCENES: scenes written by a generator of host-tools/gen/ into build/scenes/
GEN_SCENES :=

include $(wildcard */module.mk */*/module.mk)

# ------------------------------------------------------- the wide renderer
# Escalation (render/wide.h): the renderer once more in the wide arithmetic
# (double), partially linked into one object whose every global symbol is
# renamed wide_NAME, so that it lives beside the program's own renderer.
# Its objects are the double build's (firmware: build/fw-double-LIBC/;
# host: build/host-double[-san]/), render/wide.c among them.
WIDE_SRCS = $(filter-out $(ARITH_FREE_SRCS),$(SHARED_SRCS)) render/wide.c
# $(call wide_object,OBJECT,OBJECT-DIR,CC,BINUTILS-PREFIX)
define wide_object
$(1): $$(patsubst %,$(2)/%.o,$$(WIDE_SRCS))
	$$(call say,WIDE,$$@)
	$(Q)$(3) -r -nostdlib $$^ -o $$@.all
	$(Q)$(4)nm -g --defined-only $$@.all | awk 'NF == 3 { print $$$$3, "wide_" $$$$3 }' > $$@.syms
	$(Q)$(4)objcopy --redefine-syms=$$@.syms $$@.all $$@
	$(Q)rm -f $$@.all
endef

# ------------------------------------------------------------ firmware rules
# $(1) = machine (virt|an521), $(2) = variant (float|soft|fixed|double...).
# The virt board's firmware is build/links1-VARIANT.elf (objects in
# build/fw-VARIANT-LIBC/), an an521 board's build/an521/links1-VARIANT.elf
# (objects in build/fw-an521-VARIANT-LIBC/); both link the arithmetic-free
# objects of build/fw-MACHINE-ABI-LIBC/.
fw_dir = $(B)/fw-$(if $(filter virt,$(1)),,$(1)-)$(2)-$(LIBC)
fw_elf = $(FWB)$(if $(filter virt,$(1)),,/$(1))/links1-$(2).elf
# FW_ARITH_FREE_SRCS (boot, kernel, drivers: no num_t) compile once per
# machine and float ABI $(2) into $(call fw_abi_dir,$(1),$(2)), with no
# arithmetic defined: one that includes fixed/num.h stops the build there.
fw_abi_dir = $(B)/fw-$(1)-$(2)-$(LIBC)
define fw_variant
FW_OBJS_$(1)_$(2) := $$(patsubst %,$(call fw_dir,$(1),$(or $(FW_OBJS_FROM_$(2)),$(2)))/%.o,$$(FW_SRCS) \
	$$(SHARED_SRCS)) $$(patsubst %,$(call fw_abi_dir,$(1),$(FW_ABI_OF_$(1)_$(2)))/%.o,\
	$$(FW_ARITH_FREE_SRCS) $$(FW_ARITH_FREE_SRCS_$(1)))
FW_ELF_$(1)_$(2) := $(call fw_elf,$(1),$(2))
FW_FLAGS_$(1)_$(2) := $(FW_CFLAGS) $(ARM_CPU_$(1)) $(call FW_FLOAT_ABI,$(1),$(2)) $(FW_MACHINE_DEF_$(1)) \
	$(ARITH_DEF_$(FW_ARITH_$(2)))
$(if $(FW_OBJS_FROM_$(2)),,$(call fw_objects,$(call fw_dir,$(1),$(2)),$$(FW_FLAGS_$(1)_$(2)) \
	-DLINKS1_ARITH=$(FW_CODE_$(2))))
FW_LINK_$(1)_$(2) := $$(FW_OBJS_$(1)_$(2)) $(if $(FW_WIDE_$(2)),$(call fw_dir,$(1),$(FW_WIDE_$(2)))/render-wide.o)
$$(FW_ELF_$(1)_$(2)): $$(FW_LINK_$(1)_$(2)) linker/sections.ld $(B)/linker/$(1)-memory.ld
	$$(call say,LD,$$@)
	$(Q)mkdir -p $$(@D)
	$(Q)$(ARM_CC) $$(FW_FLAGS_$(1)_$(2)) $(FW_LDFLAGS) -T$(B)/linker/$(1)-memory.ld \
		-Tlinker/sections.ld $$(FW_LINK_$(1)_$(2)) $(FW_LIBS) -Wl,-Map=$$@.map -o $$@

FIRMWARE_$(1) += $$(FW_ELF_$(1)_$(2))
endef
# The object rules of directory $(1), compiled with flags $(2) (the
# renderer's sources at -O3).
define fw_objects
$(1)/%.c.o: %.c
	$$(call say,CC,$$@)
	$(Q)mkdir -p $$(@D)
	$(Q)$(ARM_CC) $(2) $$(if $$(filter $$<,$(FW_HOT_SRCS)),-O3) -c $$< -o $$@

$(1)/%.S.o: %.S
	$$(call say,AS,$$@)
	$(Q)mkdir -p $$(@D)
	$(Q)$(ARM_CC) $(2) -c $$< -o $$@

-include $$(wildcard $(1)/*/*.d $(1)/*/*/*.d)
endef
# The arithmetic-free objects of machine $(1) for float ABI $(2).
fw_abi_objects = $(call fw_objects,$(call fw_abi_dir,$(1),$(2)),$(FW_CFLAGS) $(ARM_CPU_$(1)) \
	$(FW_ABI_$(1)_$(2)) $(FW_MACHINE_DEF_$(1)))

# Each memory map takes the sizes C also needs from kernel/param.h and
# proto/board_map.h.
$(B)/linker/%-memory.ld: linker/%-memory.ld kernel/param.h proto/units.h proto/board_map.h \
		proto/board_map_an521.h
	$(call say,CPP,$@)
	$(Q)mkdir -p $(@D)
	$(Q)$(ARM_CC) -E -P -x c -I. $(FW_MACHINE_DEF_$*) $< -o $@

FIRMWARE_virt :=
FIRMWARE_an521 :=
ifneq ($(strip $(FW_SRCS)),)
$(foreach m,$(FW_MACHINES),$(foreach v,$(FW_VARIANTS_$(m)),$(eval $(call fw_variant,$(m),$(v)))))
$(foreach m,$(FW_MACHINES),$(foreach a,$(sort $(foreach v,$(FW_VARIANTS_$(m)),$(FW_ABI_OF_$(m)_$(v)))),\
	$(eval $(call fw_abi_objects,$(m),$(a)))))
endif
FIRMWARE := $(FIRMWARE_virt) $(FIRMWARE_an521)
$(foreach m,$(FW_MACHINES),$(eval $(call wide_object,$(call fw_dir,$(m),double)/render-wide.o,$(call fw_dir,$(m),double),$(ARM_CC),arm-none-eabi-)))
-include $(foreach m,$(FW_MACHINES),$(call fw_dir,$(m),double)/render/wide.c.d)

# --------------------------------------------------------------- host rules
# Shared and host sources compile once per (arithmetic, plain|san) into
# build/host-<arith>[-san]/; those of ARITH_FREE_SRCS once into
# build/host-any[-san]/ (ARITH_DEF_any is empty).
define host_objdir
$(B)/host-$(1)$(2)/%.c.o: %.c
	$$(call say,HOSTCC,$$@)
	$(Q)mkdir -p $$(@D)
	$(Q)$(HOST_CC) $(HOST_CFLAGS) $$($$<_CFLAGS) $(ARITH_DEF_$(1)) $(if $(2),$(SAN_FLAGS)) -c $$< -o $$@
endef
$(foreach a,any double float fixed $(HOST_EXTRA_ARITHS),$(eval $(call host_objdir,$(a),))$(eval $(call host_objdir,$(a),-san)))

# $(call arith_objs,DIR-PREFIX,ARITH,SUFFIX,SOURCES): the objects of SOURCES,
# DIR-PREFIX-any SUFFIX/ for those of ARITH_FREE_SRCS, DIR-PREFIX-ARITH SUFFIX/
# for the others
arith_objs = $(foreach s,$(4),$(1)-$(if $(filter $(s),$(ARITH_FREE_SRCS)),any,$(2))$(3)/$(s).o)

# The wide renderer of the host programs that escalate (NAME_WIDE = 1).
$(eval $(call wide_object,$(B)/host-double/render-wide.o,$(B)/host-double,$(HOST_CC),))
$(eval $(call wide_object,$(B)/host-double-san/render-wide.o,$(B)/host-double-san,$(HOST_CC),))
-include $(B)/host-double/render/wide.c.d $(B)/host-double-san/render/wide.c.d

# $(1) = program name, $(2) = output dir suffix ('' or -san), $(3) = output path.
# A program links every shared source, or only its NAME_SHARED when set (a
# test of one part then builds no renderer in its arithmetic).
define host_prog
$(1)_OBJS := $$(call arith_objs,$(B)/host,$$($(1)_ARITH),$(2),$$($(1)_SRCS) \
	$$(or $$($(1)_SHARED),$$(SHARED_SRCS))) \
	$(if $($(1)_WIDE),$(B)/host-double$(2)/render-wide.o)
$(3): $$($(1)_OBJS)
	$$(call say,HOSTLD,$$@)
	$(Q)mkdir -p $$(@D)
	$(Q)$(HOST_CC) $(HOST_CFLAGS) $(if $(2),$(SAN_FLAGS)) $$($(1)_OBJS) $$($(1)_LIBS) $(HOST_LIBS) -o $$@
-include $$($(1)_OBJS:.o=.d)
endef
$(foreach t,$(HOST_TOOLS),$(eval $(call host_prog,$(t),,$(B)/$(t))))
$(foreach t,$(HOST_TESTS),$(eval $(call host_prog,$(t),-san,$(B)/tests/$(t))))
$(foreach t,$(BOARD_PROGS),$(eval $(call host_prog,$(t),-san,$(B)/tests/$(t))))

# ---------------------------------------------------------------- fuzzing
# libFuzzer harnesses (tests/fuzz/): Debian's clang, with ASan and UBSan.
# Their objects go to build/fuzz-<arith>/ (fuzz-any/ for ARITH_FREE_SRCS),
# the harnesses to build/fuzz/.
FUZZ_CC ?= clang
FUZZ_SAN := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
FUZZ_SECONDS ?= 600
define fuzz_objdir
$(B)/fuzz-$(1)/%.c.o: %.c
	$$(call say,FUZZCC,$$@)
	$(Q)mkdir -p $$(@D)
	$(Q)$(FUZZ_CC) $(HOST_CFLAGS) $$($$<_CFLAGS) $(ARITH_DEF_$(1)) $(FUZZ_SAN) -fsanitize=fuzzer-no-link \
		-c $$< -o $$@
endef
$(foreach a,any double float fixed,$(eval $(call fuzz_objdir,$(a))))
define fuzz_prog
$(1)_OBJS := $$(call arith_objs,$(B)/fuzz,$$($(1)_ARITH),,$$($(1)_SRCS) $$(SHARED_SRCS))
$(B)/fuzz/$(1): $$($(1)_OBJS)
	$$(call say,FUZZLD,$$@)
	$(Q)mkdir -p $$(@D)
	$(Q)$(FUZZ_CC) $(FUZZ_SAN) -fsanitize=fuzzer $$($(1)_OBJS) $$($(1)_LIBS) $(HOST_LIBS) -o $$@
-include $$($(1)_OBJS:.o=.d)
endef
$(foreach t,$(FUZZERS),$(eval $(call fuzz_prog,$(t))))
FUZZ_BINS := $(addprefix $(B)/fuzz/,$(FUZZERS))

HOST_TOOL_BINS := $(addprefix $(B)/,$(HOST_TOOLS))
BOARD_PROG_BINS := $(addprefix $(B)/tests/,$(BOARD_PROGS))

# ---------------------------------------------------------------- targets
.PHONY: all firmware host-tools gen-scenes deps run gdb test test-host test-board test-full bench \
	clean fuzz fuzz-build

all: firmware host-tools gen-scenes
firmware: $(FIRMWARE)
host-tools: $(HOST_TOOL_BINS) $(BOARD_PROG_BINS)
gen-scenes: $(GEN_SCENES) $(GEN_MAPS)

deps:
	$(Q)bash host-tools/scripts/install-deps.sh

# make run builds and installs only what rendering the demo needs: links1
# and the machine's float firmware that escalates (what render boots by
# default).
run:
	$(Q)$(if $(filter $(MACHINE),$(FW_MACHINES)),true,echo "make run: MACHINE=$(MACHINE): the machines are $(FW_MACHINES)" >&2; exit 2)
	$(Q)bash host-tools/scripts/install-deps.sh run
	$(Q)$(MAKE) $(JOBS) --no-print-directory $(B)/links1 $(call fw_elf,$(MACHINE),float-esc)
	$(Q)MACHINE=$(MACHINE) bash host-tools/scripts/make-run.sh

# The board halted under QEMU's gdb stub, gdb-multiarch attached with the
# firmware's symbols (GDB_NCS, GDB_ARITH, GDB_ARGS; docs/firmware.md).
GDB_ARITH ?= float
gdb: deps
	$(Q)$(MAKE) $(JOBS) --no-print-directory B=$(B)/gdb DEBUG_INFO=-g \
		$(B)/gdb/links1 $(B)/gdb/links1-$(GDB_ARITH).elf
	$(Q)LINKS1=$(B)/gdb/links1 FW_DIR=$(B)/gdb GDB_ARITH=$(GDB_ARITH) bash host-tools/scripts/make-gdb.sh

test: deps
	$(Q)$(MAKE) $(JOBS) --no-print-directory all $(HOST_TEST_BINS) $(FUZZ_BINS)
	$(Q)HOST_TESTS="$(HOST_TEST_BINS)" BOARD_TESTS="$(BOARD_TESTS)" FW_DIR=$(FWB) \
		bash tests/run.sh

# Host tests only: no emulator needed (some read the generated scenes).
test-host: $(HOST_TEST_BINS) gen-scenes
	$(Q)HOST_TESTS="$(HOST_TEST_BINS)" BOARD_TESTS= bash tests/run.sh

# Board tests only, against the already built firmware.
test-board: all $(FUZZ_BINS)
	$(Q)HOST_TESTS= BOARD_TESTS="$(BOARD_TESTS)" FW_DIR=$(FWB) bash tests/run.sh

# The longest tests (suite full: 64-NC grids, farms on two hosts, Slurm).
test-full: deps
	$(Q)$(MAKE) $(JOBS) --no-print-directory all $(filter build/tests/%,$(FULL_TESTS))
	$(Q)HOST_TESTS="$(filter build/tests/%,$(FULL_TESTS))" \
		BOARD_TESTS="$(filter-out build/tests/%,$(FULL_TESTS))" FW_DIR=$(FWB) bash tests/run.sh

bench: deps
	$(Q)$(MAKE) $(JOBS) --no-print-directory all
	$(Q)for b in $(BENCHES); do bash $$b || exit 1; done

# The fuzz harnesses; `make fuzz` runs each for FUZZ_SECONDS (tests/fuzz/run.sh).
fuzz-build: $(FUZZ_BINS)
fuzz: deps
	$(Q)$(MAKE) $(JOBS) --no-print-directory fuzz-build
	$(Q)rc=0; for f in $(FUZZERS); do bash tests/fuzz/run.sh $$f $(FUZZ_SECONDS) || rc=1; done; exit $$rc

clean:
	rm -rf $(B)
