# port/baremetal/port.mk: how the bare-metal port links (included by the Makefile for PORT=baremetal).
# Our own start-up and linker script (no crt0), newlib for the C library, unused sections dropped.
ifneq ($(PROFILE),board)
ifeq ($(origin PROFILE),file)
PROFILE := board
else
$(error PORT=baremetal needs PROFILE=board, not '$(PROFILE)')
endif
endif
TARGET_CFLAGS  += -ffunction-sections -fdata-sections
TARGET_LDFLAGS += -nostartfiles -T port/baremetal/mps2.ld -Wl,--gc-sections
LDLIBS         := -lm
