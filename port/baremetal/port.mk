# port/baremetal/port.mk: how the bare-metal port links (included by the Makefile for PORT=baremetal).
# Our own start-up and linker script (no crt0), newlib for the C library, unused sections dropped.
# The profile is board unless given otherwise, which is refused: the desktop one needs ~9 MiB.
ifeq ($(TARGET),)
$(error PORT=baremetal is a cross build: name the CPU with TARGET=cortex-m3 or TARGET=cortex-m4)
endif
ifneq ($(PROFILE),board)
ifeq ($(origin PROFILE),file)
PROFILE := board
else
$(error PORT=baremetal needs PROFILE=board, not '$(PROFILE)')
endif
endif
TARGET_CFLAGS  += -ffunction-sections -fdata-sections
TARGET_LDFLAGS += -nostartfiles -Wl,--gc-sections
# the memory map: mps2.ld (QEMU's mps2-an385/an386) unless the TARGET line names another with -T
ifeq ($(filter -T,$(TARGET_CFLAGS)),)
TARGET_LDFLAGS += -T port/baremetal/mps2.ld
endif
LDLIBS         := -lm
