# amorph: one Makefile, several side-by-side builds.
#   make                      build/libamorph.a and build/amorph
#   make check                the fast tier, under a minute: the default build's unit tests and a few
#                             command tests (CHECK_SH), for after each change
#   make test                 every test (the README's test command and CI's; also builds the -O0,
#                             fixed-point and board-profile variants the shell tests compare against)
#   make bench                benchmarks that print figures (bench-board: a board's cost under QEMU;
#                             bench-mpi: MPI ranks against threads; convergence: the default step
#                             against a ten times smaller one on every kind of body)
#   make PORT=mpi             build/mpi/amorph, the MPI build (mpirun -np N build/mpi/amorph ...)
#   make sim-only TARGET=cortex-m4   build/cortex-m4/board_sim: the simulator alone on a board (no port)
#   make check-fixed          the fixed-point step has no floating-point call (Cortex-M3 cross build)
#   make shared               build/libamorph.so (.MAJOR, .MAJOR.MINOR.PATCH), the library for other
#                             languages, exporting the API alone (make check-exports; docs/embedding.md)
#   make install PREFIX=/usr/local   headers, libamorph.a, libamorph.so*, amorph, amorph.pc (DESTDIR honoured)
#   make asan | valgrind      sanitizer / memcheck runs of the test suite
# Options: ARCH= (-march, default native)  BUILD= (output folder)  GATHER=auto|on|off
#          REAL=float|double|fixed  PROFILE=desktop|board  CONFIG= (capacities' header)  OPT= (default -O3)  CC=
ARCH    ?= native
GATHER  ?= auto
BUILD   ?= build
REAL    ?= float
PROFILE ?= desktop
OPT     ?= -O3
PORT    ?= posix
CC      ?= gcc
ifeq ($(origin CC),default)
CC := gcc
endif

# Cross targets: `make TARGET=name` takes the port, the compiler and the CPU flags from the
# name's line below and builds into build/<name>. A new board is a folder port/<port>/ (its
# sources, and a port.mk with its link flags if it needs any) plus one line here.
#   TARGET_<name> := <port> <compiler> <CPU flags...>
TARGET_cortex-m3     := baremetal arm-none-eabi-gcc -mcpu=cortex-m3 -mthumb -mfloat-abi=soft
TARGET_cortex-m4     := baremetal arm-none-eabi-gcc -mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16
TARGET_rv32          := baremetal riscv64-unknown-elf-gcc -march=rv32imafc -mabi=ilp32f
TARGET_aarch64-linux := posix aarch64-linux-gnu-gcc -static
TARGET_armhf-linux   := posix arm-linux-gnueabihf-gcc -static
TARGET_riscv64-linux := posix riscv64-linux-gnu-gcc -static
TARGET_s390x-linux   := posix s390x-linux-gnu-gcc -static -fexcess-precision=fast
TARGET_i686-linux    := posix i686-linux-gnu-gcc -static -msse2 -mfpmath=sse
TARGET_win64         := win32 x86_64-w64-mingw32-gcc -static
TARGET  ?=
TARGET_CFLAGS :=
TARGET_LDFLAGS :=
ifneq ($(TARGET),)
ifeq ($(TARGET_$(TARGET)),)
$(error unknown TARGET '$(TARGET)' (known: $(sort $(filter-out CFLAGS LDFLAGS,$(patsubst TARGET_%,%,$(filter TARGET_%,$(.VARIABLES)))))))
endif
ifneq ($(origin PORT),file)
ifneq ($(PORT),$(word 1,$(TARGET_$(TARGET))))
$(error TARGET=$(TARGET) is a PORT=$(word 1,$(TARGET_$(TARGET))) build, not PORT=$(PORT))
endif
endif
PORT  := $(word 1,$(TARGET_$(TARGET)))
ifneq ($(origin CC),command line)
CC    := $(word 2,$(TARGET_$(TARGET)))
endif
ifneq ($(origin ARCH),command line)
ARCH  :=
endif
ifneq ($(origin BUILD),command line)
BUILD := build/$(TARGET)$(if $(filter-out float,$(REAL)),-$(REAL))
endif
# bare-metal boards optimise for size (flash); results do not depend on the optimisation level
ifeq ($(word 1,$(TARGET_$(TARGET))),baremetal)
ifneq ($(origin OPT),command line)
OPT := -Os
endif
endif
TARGET_CFLAGS := $(wordlist 3,$(words $(TARGET_$(TARGET))),$(TARGET_$(TARGET)))
endif
LDLIBS  := -lm -lpthread
# the port's source folders: port/<port>/, and any its port.mk adds; PORT_FILES: single sources of
# another port's folder it builds on (port/mpi: port/posix/posix.c)
PORT_DIRS := port/$(PORT) port/common
PORT_FILES :=
EXE     :=
-include port/$(PORT)/port.mk

ifeq ($(filter $(REAL),float double fixed),)
$(error REAL must be float, double or fixed, not '$(REAL)')
endif
ifeq ($(filter $(PROFILE),desktop board),)
$(error PROFILE must be desktop or board, not '$(PROFILE)')
endif

# CONFIG=file.h: a project's configuration header of the capacities, over the defaults of
# include/amorph/base.h (docs/porting.md, Capacities); passed as AMORPH_CONFIG_H with its absolute path
CONFIG  ?=
CONFIG_DEF :=
# CHECKS=1: the debug build that checks the model's and the state's invariants after every model
# build and step (-DAM_CHECKS, src/sim/sim_check.c, docs/architecture.md, Invariants)
ifeq ($(CHECKS),1)
CONFIG_DEF += -DAM_CHECKS
endif
ifneq ($(CONFIG),)
ifeq ($(wildcard $(CONFIG)),)
$(error CONFIG=$(CONFIG): no such file)
endif
CONFIG_DEF := -DAMORPH_CONFIG_H=\"$(abspath $(CONFIG))\"
endif

MARCH   := $(if $(ARCH),-march=$(ARCH))
# Vector gathers under -march=native (docs/benchmarks.md, Build flags): GATHER=auto leaves them out
# where the CPU's microcode makes them slow (tools/gather_flags.sh; make gather-why says what it
# decided here), off always, on never. Speed only: the results are the same bit for bit.
ifeq ($(filter $(GATHER),auto on off),)
$(error GATHER must be auto, on or off, not '$(GATHER)')
endif
GATHER_FLAGS := $(if $(and $(filter native,$(ARCH)),$(filter-out on,$(GATHER))),$(shell sh tools/gather_flags.sh '$(CC)' $(GATHER)))
MARCH   += $(if $(GATHER_FLAGS),$(GATHER_FLAGS) -DAM_NO_GATHER)
# make test also builds the other choice and compares its results with this build's (tests/cli_arch.sh)
GATHER_OTHER := $(if $(GATHER_FLAGS),on,off)
DEFS    := -DAM_REAL_$(shell echo $(REAL) | tr a-z A-Z) -DAM_PROFILE_$(shell echo $(PROFILE) | tr a-z A-Z)
WARN    := -Wall -Wextra -Wpedantic -Werror -Wshadow -Wstrict-prototypes -Wmissing-prototypes \
           -Wvla -Wdouble-promotion -Wcast-qual -Wformat=2 -Wundef
CFLAGS  ?=
# fixed point (docs/fixed.md): sums of am_real wrap around instead of being undefined
FIXFLAGS := $(if $(filter fixed,$(REAL)),-fwrapv)
ALLCFLAGS := -std=c11 -pedantic-errors $(WARN) $(OPT) $(MARCH) -ffp-contract=off -fno-fast-math \
           -fno-math-errno -fno-trapping-math -g $(FIXFLAGS) $(DEFS) $(CONFIG_DEF) -Iinclude $(TARGET_CFLAGS) $(CFLAGS)

LIB_SRC  := $(sort $(wildcard src/*/*.c))
PORT_SRC := $(sort $(foreach d,$(PORT_DIRS),$(wildcard $(d)/*.c)) $(PORT_FILES))
TOOL_SRC := $(sort $(wildcard tools/*.c))
TEST_SRC := $(sort $(wildcard tests/test_*.c))
LIB_OBJ  := $(LIB_SRC:%.c=$(BUILD)/%.o)
PORT_OBJ := $(PORT_SRC:%.c=$(BUILD)/%.o)
TOOL_OBJ := $(TOOL_SRC:%.c=$(BUILD)/%.o)
TEST_BIN := $(TEST_SRC:tests/%.c=$(BUILD)/tests/%)

.PHONY: all shared install sim-only check test unit check-exports check-test-links check-layers bench bench-arch gather-why convergence asan valgrind valgrind-run clean check-alloc check-fma check-tests repro stack stack-peak check-fixed bench-board bench-mpi fuzz fuzz-build fuzz-corpus fuzz-smoke
all: $(BUILD)/libamorph.a $(BUILD)/amorph$(EXE)

# Each object depends on the headers it includes (-MMD -MP: the compiler lists them in a .d file
# beside it) and on $(BUILD)/flags.txt, the compiler and flags of the build, rewritten only when
# they change: another GATHER, CFLAGS or compiler rebuilds every object of that folder instead of
# linking stale ones (not under make -n, which writes nothing).
FLAGS_LINE := $(strip $(CC) $(ALLCFLAGS) $(TARGET_LDFLAGS) $(LDLIBS))
ifneq ($(strip $(shell cat $(BUILD)/flags.txt 2>/dev/null)),$(FLAGS_LINE))
ifeq ($(findstring n,$(firstword -$(MAKEFLAGS))),)
$(shell mkdir -p $(BUILD) && printf '%s\n' '$(FLAGS_LINE)' >$(BUILD)/flags.txt)
else
.PHONY: $(BUILD)/flags.txt
endif
endif
$(BUILD)/flags.txt:
	@mkdir -p $(dir $@) && printf '%s\n' '$(FLAGS_LINE)' >$@

# port/port.h is the program's OS layer, not a library header: the objects of tools/ and port/ (and
# the tests) find it with -Iport, those of src/ (and of tools/board_sim/, which has no port) cannot
# include it
$(BUILD)/%.o: %.c Makefile $(BUILD)/flags.txt
	@mkdir -p $(dir $@)
	$(CC) $(ALLCFLAGS) $(if $(filter $(BUILD)/src/% $(BUILD)/tools/board_sim/%,$@),,-Iport) -MMD -MP -c $< -o $@

$(BUILD)/libamorph.a: $(LIB_OBJ)
	@mkdir -p $(dir $@)
	rm -f $@ && ar rcs $@ $^

$(BUILD)/libamorph_port.a: $(PORT_OBJ)
	@mkdir -p $(dir $@)
	rm -f $@ && ar rcs $@ $^

$(BUILD)/amorph$(EXE): $(TOOL_OBJ) $(BUILD)/libamorph.a $(BUILD)/libamorph_port.a
	$(CC) $(ALLCFLAGS) $(TARGET_LDFLAGS) -o $@ $(TOOL_OBJ) $(BUILD)/libamorph.a $(BUILD)/libamorph_port.a $(LDLIBS)
# a port whose programs have a suffix (EXE, from its port.mk: win32's .exe) builds them for the
# goal $(BUILD)/amorph too, the name tools/repro.sh asks every target for
ifneq ($(EXE),)
.PHONY: $(BUILD)/amorph
$(BUILD)/amorph: $(BUILD)/amorph$(EXE)
endif

# the shared library (docs/embedding.md): the library's sources only, compiled again as
# position-independent code into $(BUILD)/pic/, with the same flags and hidden visibility, so that
# only the functions the public headers mark AM_API are exported (make check-exports). The file is
# libamorph.so.MAJOR.MINOR.PATCH with the SONAME libamorph.so.MAJOR (AM_VERSION_* of
# include/amorph/base.h), and the links libamorph.so.MAJOR and libamorph.so to it
am_version = $(shell awk 'index($$1, "define") && $$2 == "AM_VERSION_$(1)" {print $$3}' include/amorph/base.h)
SO_MAJOR := $(call am_version,MAJOR)
SO_NAME  := libamorph.so.$(SO_MAJOR)
SO_FILE  := $(SO_NAME).$(call am_version,MINOR).$(call am_version,PATCH)
PIC_OBJ := $(LIB_SRC:%.c=$(BUILD)/pic/%.o)
$(BUILD)/pic/%.o: %.c Makefile $(BUILD)/flags.txt
	@mkdir -p $(dir $@)
	$(CC) $(ALLCFLAGS) -fPIC -fvisibility=hidden -MMD -MP -c $< -o $@

$(BUILD)/$(SO_FILE): $(PIC_OBJ)
	$(CC) $(ALLCFLAGS) -shared -Wl,-soname,$(SO_NAME) -o $@ $^ -lm
$(BUILD)/libamorph.so: $(BUILD)/$(SO_FILE)
	ln -sf $(SO_FILE) $(BUILD)/$(SO_NAME) && ln -sf $(SO_NAME) $@
shared: $(BUILD)/libamorph.so

# the shared library exports every function the public headers declare and nothing else: the
# compiler lists the declarations (-aux-info), nm -D the exports (tools/check_exports.sh)
check-exports: $(BUILD)/libamorph.so
	@NM=$(NM) sh tools/check_exports.sh '$(CC)' '-std=c11 $(DEFS) $(TARGET_CFLAGS)' $(BUILD)/libamorph.so

# make install: headers, both libraries, the program and a pkg-config file under PREFIX
# (tools/install.sh; the .pc file carries the build's number type and profile)
PREFIX  ?= /usr/local
DESTDIR ?=
install: all shared
	@sh tools/install.sh $(BUILD) '$(DESTDIR)$(PREFIX)' '$(PREFIX)' '$(DEFS)'
	@echo "install: headers, libamorph.a, libamorph.so, amorph and lib/pkgconfig/amorph.pc in $(DESTDIR)$(PREFIX)"

# the simulator alone on a Cortex-M board (tools/board_sim/; docs/porting.md, The simulator alone):
# the objects of src/base, src/sim and src/geno with board_sim's own start-up, linked with the C
# library and libm only: no src/evo, src/io, tools/ or port. make sim-only TARGET=cortex-m4 (or
# cortex-m3): $(BUILD)/board_sim, run by tools/sim_only.sh (make repro)
SIM_ONLY_OBJ  := $(filter $(BUILD)/src/base/% $(BUILD)/src/sim/% $(BUILD)/src/geno/%,$(LIB_OBJ))
BOARD_SIM_OBJ := $(BUILD)/tools/board_sim/board_sim.o $(BUILD)/tools/board_sim/cortex-m.o
ifneq ($(filter sim-only $(BUILD)/board_sim,$(MAKECMDGOALS)),)
ifeq ($(filter cortex-m3 cortex-m4,$(TARGET)),)
$(error sim-only is a Cortex-M build: make sim-only TARGET=cortex-m4 (or cortex-m3), not TARGET='$(TARGET)')
endif
endif
sim-only: $(BUILD)/board_sim
$(BUILD)/board_sim: $(BOARD_SIM_OBJ) $(SIM_ONLY_OBJ) tools/board_sim/cortex-m.ld
	$(CC) $(ALLCFLAGS) -nostartfiles -Wl,--gc-sections -T tools/board_sim/cortex-m.ld -o $@ $(BOARD_SIM_OBJ) $(SIM_ONLY_OBJ) -lm

# A test links the library archive (the linker takes only the objects it needs), plus the tools/
# objects it tests (TEST_TOOLS_<test>, default none: then it also cannot see tools/'s headers) and
# the port when it calls am_port_* (TEST_PORT_<test> := 1). make check-test-links proves that a
# library-only test holds no symbol of tools/ (nor of the port).
TEST_TOOLS_test_io_png := tools/account.o tools/args.o tools/film.o tools/files.o tools/picture.o \
                          tools/record.o tools/robot.o tools/robot_args.o tools/robot_genome.o tools/run_dir.o
TEST_TOOLS_test_io_vxa := tools/account.o tools/args.o tools/files.o tools/record.o tools/robot.o tools/robot_args.o tools/robot_genome.o tools/run_dir.o
TEST_TOOLS_test_record := tools/record.o
TEST_TOOLS_test_stats  := tools/stats.o
TEST_PORT_test_io_png  := 1
TEST_PORT_test_io_vxa  := 1
TEST_PORT_test_port    := 1
TEST_PORT_test_evo     := 1
test_tools = $(addprefix $(BUILD)/,$(TEST_TOOLS_$(1)))
test_port = $(if $(TEST_PORT_$(1)),$(BUILD)/libamorph_port.a)
.SECONDEXPANSION:
$(BUILD)/tests/%: tests/%.c Makefile $(BUILD)/flags.txt $$(call test_tools,$$*) $$(call test_port,$$*) $(BUILD)/libamorph.a
	@mkdir -p $(dir $@)
	$(CC) $(ALLCFLAGS) $(TARGET_LDFLAGS) -MMD -MP -MF $@.d -MT $@ $(if $(TEST_TOOLS_$*),-Itools)$(if $(TEST_TOOLS_$*)$(TEST_PORT_$*), -Iport) -o $@ $< \
	    $(call test_tools,$*) $(call test_port,$*) $(BUILD)/libamorph.a $(LDLIBS)

-include $(LIB_OBJ:.o=.d) $(PIC_OBJ:.o=.d) $(PORT_OBJ:.o=.d) $(TOOL_OBJ:.o=.d) $(BOARD_SIM_OBJ:.o=.d) $(TEST_BIN:=.d)

# no object of src/ or port/ may reference an allocator
NM ?= nm
check-alloc: $(LIB_OBJ) $(PORT_OBJ)
	@bad=$$(for o in $(LIB_OBJ) $(PORT_OBJ); do $(NM) -u $$o | awk -v o=$$o '$$2 ~ /^(malloc|calloc|realloc|free|aligned_alloc|posix_memalign|alloca|strdup|strndup)$$/ {print o": "$$2}'; done); \
	if [ -n "$$bad" ]; then echo "check-alloc: allocation found:"; echo "$$bad"; echo "check-alloc: 0 passed, 1 failed"; exit 1; fi; \
	echo "check-alloc: no allocator referenced by $(words $(LIB_OBJ) $(PORT_OBJ)) objects of src/ and port/"

# a test without TEST_TOOLS_<test> holds no global symbol that tools/ defines, and one without
# TEST_PORT_<test> none that the port defines (run by make unit)
test_syms = $(NM) -g --defined-only $(1) | awk 'NF == 3 && $$3 != "main" {print $$3}' | sort -u
check-test-links: $(TEST_BIN) $(TOOL_OBJ) $(PORT_OBJ)
	@$(call test_syms,$(TOOL_OBJ)) >$(BUILD)/tests/tools.syms && $(call test_syms,$(PORT_OBJ)) >$(BUILD)/tests/port.syms && \
	test -s $(BUILD)/tests/tools.syms && bad=0 && n=0 && \
	for t in $(foreach t,$(TEST_BIN),$(notdir $(t)):$(if $(TEST_TOOLS_$(notdir $(t))),t)$(if $(TEST_PORT_$(notdir $(t))),p)); do \
	    name=$${t%%:*} && $(call test_syms,$(BUILD)/tests/$$name) >$(BUILD)/tests/$$name.syms || exit 1; \
	    for part in tools port; do case $$part:$${t#*:} in tools:*t*|port:*p*) continue;; esac; n=$$((n + 1)); \
	        s=$$(comm -12 $(BUILD)/tests/$$name.syms $(BUILD)/tests/$$part.syms | head -n 4 | tr '\n' ' '); \
	        if [ -n "$$s" ]; then echo "check-test-links: $$name links $$part/ but does not list it: $$s"; bad=1; fi; done; done; \
	if [ $$bad -ne 0 ]; then echo "check-test-links: 0 passed, 1 failed"; exit 1; fi; \
	echo "check-test-links: $$n checks: no test holds a symbol of tools/ or the port it does not list"

# determinism: -ffp-contract=off forbids fused multiply-adds, but GCC 12's vectoriser still fuses a
# multiply with an alternating add/subtract (vfmaddsub) in some inlining contexts, which rounds
# differently from the -O0 build. No object of the library may hold a fused multiply-add.
OBJDUMP ?= objdump
check-fma: $(LIB_OBJ)
	@bad=$$(for o in $(LIB_OBJ); do $(OBJDUMP) -d --no-show-raw-insn $$o | awk -v o=$$o -F'\t' \
	    'NF >= 2 { split($$2, w, " "); if (w[1] ~ /^(vf(n)?m(add|sub)|vfmaddsub|vfmsubadd|f(n)?m(add|sub)(\.[sd])?|fml[as]|vf(n)?m[as])/) print o": "w[1] }' | sort -u; done); \
	if [ -n "$$bad" ]; then echo "check-fma: fused multiply-add found:"; echo "$$bad"; echo "check-fma: 0 passed, 1 failed"; exit 1; fi; \
	echo "check-fma: no fused multiply-add in $(words $(LIB_OBJ)) objects of src/"

# who may include whom: each layer of src/ only the headers of the layers before it, the ports only
# amorph/base.h and port.h (tools/check_layers.sh, docs/architecture.md)
check-layers:
	@sh tools/check_layers.sh

# a shell test's `check DESC CMD...` judges CMD alone: in `check DESC A && B`, B could never fail
# the suite (tests/lint_checks.awk)
check-tests:
	@if ! bad=$$(awk -f tests/lint_checks.awk tests/*.sh); then echo "check-tests: a check chained outside its command:"; \
	    echo "$$bad"; echo "check-tests: 0 passed, 1 failed"; exit 1; fi; \
	echo "check-tests: no check in tests/*.sh chains a condition it does not judge"

unit: $(TEST_BIN) $(BUILD)/amorph $(BUILD)/libamorph.so check-test-links
	@BUILD=$(BUILD) sh tests/run_all.sh $(TEST_BIN)

# make check: the fast tier, for after each change (under a minute on two cores; README, Layout):
# the default build, its static checks, every unit test (AM_TEST_QUICK=1: the heavy ones shrink)
# and the command tests of CHECK_SH. make test stays the whole suite and CI's command.
CHECK_SH ?= tests/cli_lib.sh tests/cli_build.sh tests/cli_determinism.sh tests/cli_genome.sh tests/cli_lattice.sh
check: all check-alloc check-tests check-layers check-exports $(TEST_BIN) check-test-links
	@AM_TEST_QUICK=1 BUILD=$(BUILD) CLI_TESTS='$(CHECK_SH)' sh tests/run_all.sh $(TEST_BIN)

# the invariants checked after every model build and step, and every AM_ASSERT, while the
# simulator's unit tests run their scenes, then a VXA file's scene and the shipped best robots
# through the checked program, and a false AM_ASSERT through the handler (tests/cli_checks.sh)
CHECKS_TESTS := test_base test_sim_model test_sim_step test_sim_eval test_sim_collide test_api_sim
.PHONY: checks
checks:
	@$(MAKE) --no-print-directory BUILD=$(BUILD)/checks CHECKS=1 $(addprefix $(BUILD)/checks/tests/,$(CHECKS_TESTS)) $(BUILD)/checks/amorph
	@for t in $(CHECKS_TESTS); do $(BUILD)/checks/tests/$$t >/dev/null || { echo "checks: $$t failed"; exit 1; }; done; echo "checks: $(CHECKS_TESTS) pass with the invariants checked after every build and step"
	@CHECKS_BUILD=$(BUILD)/checks BUILD=$(BUILD) sh tests/cli_checks.sh

test: all check-alloc check-fma check-tests check-layers check-exports
	@$(MAKE) --no-print-directory BUILD=$(BUILD)/o0 OPT=-O0 ARCH= all
	@$(MAKE) --no-print-directory BUILD=$(BUILD)/fixed REAL=fixed all
	@$(MAKE) --no-print-directory BUILD=$(BUILD)/board PROFILE=board $(BUILD)/board/amorph
	@$(MAKE) --no-print-directory BUILD=$(BUILD)/small CONFIG=docs/examples/config_small.h $(BUILD)/small/amorph
	@$(MAKE) --no-print-directory checks
	@if command -v x86_64-w64-mingw32-gcc >/dev/null 2>&1 && command -v wine >/dev/null 2>&1; then \
	    $(MAKE) --no-print-directory TARGET=win64 BUILD=$(BUILD)/windows all check-alloc; else echo "test: no mingw-w64 or wine: Windows build skipped"; fi
	@if command -v mpicc >/dev/null 2>&1 && command -v mpirun >/dev/null 2>&1; then \
	    $(MAKE) --no-print-directory PORT=mpi BUILD=$(BUILD)/mpi all check-alloc; else echo "test: no mpicc or mpirun: MPI build skipped"; fi
	@$(if $(filter native,$(ARCH)),$(MAKE) --no-print-directory BUILD=$(BUILD)/gather-$(GATHER_OTHER) GATHER=$(GATHER_OTHER) all)
	@$(MAKE) --no-print-directory unit OTHER_BUILD=$(BUILD)/o0 FIXED_BUILD=$(BUILD)/fixed BOARD_BUILD=$(BUILD)/board SMALL_BUILD=$(BUILD)/small WIN_BUILD=$(BUILD)/windows \
	    MPI_BUILD=$(BUILD)/mpi $(if $(filter native,$(ARCH)),GATHER_BUILD=$(BUILD)/gather-$(GATHER_OTHER))
	@$(MAKE) --no-print-directory check-fixed
	@$(MAKE) --no-print-directory fuzz-smoke
	@$(MAKE) --no-print-directory BUILD=$(BUILD)/fixed REAL=fixed unit check-exports

# the fixed-point hot path is integer-only: the step's sources (sim_step.c, sim_collide.c,
# sim_scale.c with the actuation's scale, base_math.c with its sin and cbrt) cross-compiled for a
# Cortex-M3, which has no FPU, must not call one soft-float helper (__aeabi_f*, __aeabi_d*, libm).
# Skipped without arm-none-eabi-gcc.
FIXED_HOT := src/sim/sim_step.c src/sim/sim_collide.c src/sim/sim_scale.c src/base/base_math.c
M3CC := arm-none-eabi-gcc
M3FLAGS := -std=c11 -pedantic-errors $(WARN) -O2 -mcpu=cortex-m3 -mthumb -ffp-contract=off -fwrapv \
           -DAM_REAL_FIXED -DAM_PROFILE_BOARD -Iinclude
check-fixed:
	@if ! command -v $(M3CC) >/dev/null 2>&1; then echo "check-fixed: $(M3CC) not found: skipped"; exit 0; fi; \
	mkdir -p $(BUILD)/m3 && bad=0 && \
	for f in $(FIXED_HOT); do o=$(BUILD)/m3/$$(basename $$f .c).o; \
	    $(M3CC) $(M3FLAGS) -c $$f -o $$o || exit 1; \
	    calls=$$(arm-none-eabi-nm -u $$o | awk '$$2 ~ /^__aeabi_([fd]|[iu]?[il]2[fd]|[fd]2)|^__(add|sub|mul|div|cmp|eq|lt|gt|le|ge|float|fix|extend|trunc)[sd]f|^(sqrt|floor|fabs|sin|cos|exp|log|pow|cbrt)f?$$/ {printf " %s", $$2}'); \
	    if [ -n "$$calls" ]; then echo "check-fixed: $$f calls floating point:$$calls"; bad=1; fi; \
	    echo "check-fixed: $$f calls:$$(arm-none-eabi-nm -u $$o | awk '{printf " %s", $$2}')"; done; \
	if [ $$bad -ne 0 ]; then echo "check-fixed: 0 passed, 1 failed"; exit 1; fi; \
	echo "check-fixed: no floating-point call in $(FIXED_HOT) (Cortex-M3, REAL=fixed, PROFILE=board)"

bench: all
	$(BUILD)/amorph bench

# voxel-steps per second and instructions per voxel-step of the same code under each -march choice
# (x86-64: x86-64-v2, x86-64-v3, native with and without gathers; aarch64: armv8-a, native), in
# turns, medians, each build's result hash (all must be equal); tools/bench_arch.sh
ARCH_BUILDS_x86_64  := v2:x86-64-v2:on v3:x86-64-v3:on native:native:on native-nogather:native:off
ARCH_BUILDS_aarch64 := armv8-a:armv8-a:on native:native:on
ARCH_BUILDS := $(ARCH_BUILDS_$(shell uname -m))
bench-arch: all
	@for b in $(ARCH_BUILDS); do n=$${b%%:*}; r=$${b#*:}; \
	    $(MAKE) --no-print-directory BUILD=$(BUILD)/arch/$$n ARCH=$${r%%:*} GATHER=$${r#*:} $(BUILD)/arch/$$n/amorph >/dev/null || exit 1; done
	@DEFAULT_DIR=$(BUILD) sh tools/bench_arch.sh $(BUILD) $(foreach b,$(ARCH_BUILDS),$(BUILD)/arch/$(firstword $(subst :, ,$(b))))

gather-why:
	@sh tools/gather_flags.sh '$(CC)' why

# does the default step give the small-step answer? the calibration bars, 30 random bodies (10 per
# representation) and every shipped best robot at 0.9 and 0.1 dt_rec, the period held in seconds,
# plus the margins (friction +-10%, internal damping 0.5 and 1.0, 1.2 times the step): a table and
# a pass/fail line (docs/physics.md, Time step). About half an hour on two cores.
convergence: all
	$(BUILD)/amorph bench --convergence $(sort $(patsubst %/checkpoint.txt,%,$(wildcard results/*/*/checkpoint.txt)))

# what a board costs: instructions per voxel-step and per evaluation on the Cortex-M3 (fixed and
# soft float) and Cortex-M4F builds under QEMU with -icount (tools/bench_board.sh states the method)
bench-board:
	@sh tools/bench_board.sh

# evaluations per hour on 1 and 2 threads against 1 and 2 MPI ranks, and the map's cost per item
# (tools/bench_mpi.sh; needs Open MPI)
bench-mpi: all
	@$(MAKE) --no-print-directory PORT=mpi BUILD=$(BUILD)/mpi all
	@POSIX=$(BUILD)/amorph MPI=$(BUILD)/mpi/amorph sh tools/bench_mpi.sh

# the parsers under libFuzzer (tests/fuzz_parsers.c): clang, ASan and UBSan, the library built
# with coverage; the seed corpus is tests/data. make fuzz runs FUZZ_SECONDS (60); make test runs a
# fixed count of inputs from a fixed seed (fuzz-smoke) when clang has libFuzzer
FUZZ_SECONDS ?= 60
FUZZ_SAN := -fsanitize=address,undefined -fno-sanitize-recover=all
fuzz-build:
	@$(MAKE) --no-print-directory BUILD=build/fuzz CC=clang OPT=-O1 ARCH= CFLAGS="-fsanitize=fuzzer-no-link $(FUZZ_SAN)" \
	    build/fuzz/libamorph.a build/fuzz/libamorph_port.a
	clang -std=c11 $(WARN) -O1 -g -DAM_REAL_FLOAT -DAM_PROFILE_DESKTOP -Iinclude -fsanitize=fuzzer $(FUZZ_SAN) \
	    -o build/fuzz/fuzz_parsers tests/fuzz_parsers.c build/fuzz/libamorph.a build/fuzz/libamorph_port.a -lm -lpthread
fuzz-corpus:
	@rm -rf build/fuzz/corpus && mkdir -p build/fuzz/corpus && sh tests/fuzz_corpus.sh build/fuzz/corpus
fuzz: fuzz-build fuzz-corpus
	build/fuzz/fuzz_parsers -max_total_time=$(FUZZ_SECONDS) -max_len=200000 -timeout=10 build/fuzz/corpus
fuzz-smoke:
	@if echo 'int LLVMFuzzerTestOneInput(const unsigned char* d, unsigned long n) { (void)d; (void)n; return 0; }' | \
	    clang -x c -fsanitize=fuzzer -o /dev/null - >/dev/null 2>&1; then \
	    $(MAKE) --no-print-directory fuzz-build fuzz-corpus >/dev/null && \
	    build/fuzz/fuzz_parsers -runs=300000 -seed=1 -max_len=200000 -timeout=10 build/fuzz/corpus 2>build/fuzz/smoke.log && \
	    echo "fuzz-smoke: 300000 inputs from seed 1 (seed corpus: tests/fuzz_corpus.sh): no crash, no sanitizer report, every message one line" || \
	    { tail -n 30 build/fuzz/smoke.log; echo "fuzz-smoke: 0 passed, 1 failed"; exit 1; }; \
	else echo "fuzz-smoke: clang without libFuzzer: skipped"; fi

asan:
	$(MAKE) --no-print-directory BUILD=build/asan OPT="-O1" CFLAGS="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer" unit

# valgrind 3.19 cannot decode AVX-512, so memcheck runs on a baseline x86-64 build of its own
valgrind:
	$(MAKE) --no-print-directory BUILD=build/valgrind ARCH= OPT=-O2 valgrind-run

valgrind-run: $(TEST_BIN) $(BUILD)/amorph
	@VALGRIND=1 BUILD=$(BUILD) sh tests/run_all.sh $(TEST_BIN)

# one reference computation on every target (x86-64 compilers, Linux under qemu-user, Cortex-M
# under qemu-system-arm) must print the same pinned hash (docs/porting.md)
repro:
	@sh tools/repro.sh float
	@sh tools/repro.sh fixed

# worst-case stack depth from GCC's frame sizes and call graph: the board builds (Cortex-M4, and
# rv32 when its compiler is installed), then the desktop build (tools/stack.sh states the method)
stack:
	@$(MAKE) --no-print-directory TARGET=cortex-m4 PROFILE=board BUILD=build/stack/cortex-m4 CFLAGS="-fstack-usage -fcallgraph-info=su" build/stack/cortex-m4/amorph >/dev/null
	@echo "== board (cortex-m4, PROFILE=board)"; sh tools/stack.sh build/stack/cortex-m4
	@if command -v riscv64-unknown-elf-gcc >/dev/null 2>&1; then \
	    $(MAKE) --no-print-directory TARGET=rv32 PROFILE=board BUILD=build/stack/rv32 CFLAGS="-fstack-usage -fcallgraph-info=su" build/stack/rv32/amorph >/dev/null && \
	    echo && echo "== board (rv32, PROFILE=board)" && sh tools/stack.sh build/stack/rv32; fi
	@$(MAKE) --no-print-directory PROFILE=desktop ARCH= BUILD=build/stack/desktop CFLAGS="-fstack-usage -fcallgraph-info=su" build/stack/desktop/amorph >/dev/null
	@echo; echo "== desktop (x86-64, PROFILE=desktop)"; sh tools/stack.sh build/stack/desktop

# the stack each board command really takes: the board builds with the port's stack report, each
# command of a list under QEMU (tools/stack_peak.sh states the method; docs/porting.md, Stack)
stack-peak:
	@sh tools/stack_peak.sh

clean:
	rm -rf build
