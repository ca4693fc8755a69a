# port/baremetal/port.mk: how the bare-metal port links (included by the Makefile for PORT=baremetal).
# Our own start-up and linker script (no crt0), the toolchain's C library, unused sections dropped.
# The profile is board unless given otherwise, which is refused: the desktop one needs ~9 MiB.
ifeq ($(TARGET),)
$(error PORT=baremetal is a cross build: name the CPU with TARGET=cortex-m3, cortex-m4 or rv32)
endif
ifneq ($(PROFILE),board)
ifeq ($(origin PROFILE),file)
PROFILE := board
else
$(error PORT=baremetal needs PROFILE=board, not '$(PROFILE)')
endif
endif
# the instruction set's folder (start-up, semihosting trap, memory map, the C library's system
# calls), from the TARGET line's compiler: riscv/ for riscv64-unknown-elf-gcc (with picolibc,
# the C library Debian builds for it), cortex-m/ for arm-none-eabi-gcc (with newlib)
ifneq ($(findstring riscv,$(CC)),)
BAREMETAL_ISA := riscv
BAREMETAL_LD  := virt.ld
TARGET_CFLAGS += --specs=picolibc.specs
else
BAREMETAL_ISA := cortex-m
BAREMETAL_LD  := mps2.ld
endif
PORT_DIRS     += port/baremetal/$(BAREMETAL_ISA)
TARGET_CFLAGS  += -ffunction-sections -fdata-sections -Iport/baremetal
TARGET_LDFLAGS += -nostartfiles -Wl,--gc-sections
# the memory map: the folder's linker script unless the TARGET line names another with -T
ifeq ($(filter -T,$(TARGET_CFLAGS)),)
TARGET_LDFLAGS += -T port/baremetal/$(BAREMETAL_ISA)/$(BAREMETAL_LD)
endif
LDLIBS         := -lm
