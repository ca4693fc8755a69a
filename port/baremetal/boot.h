/* port/baremetal/boot.h: what every instruction set's start-up shares (boot.c).
 *
 * An instruction set's folder (cortex-m/, riscv/) gives the reset code, which sets up the stack
 * pointer and whatever the core needs before C runs (the FPU, a trap vector), then calls
 * am_boot_memory, sets up its C library's standard streams and calls am_boot_main. The linker
 * script of the folder defines the symbols below. */
#ifndef AMORPH_PORT_BOOT_H
#define AMORPH_PORT_BOOT_H

#include <stdint.h>

/* symbols of the linker script: the stack [limit, top), .data's place in RAM and its initial
 * values in the code region, .bss (each a multiple of 4 bytes, 4-aligned) */
extern uint32_t __stack_limit[], __stack_top[];
extern uint32_t __data_start[], __data_end[], __data_load[];
extern uint32_t __bss_start[], __bss_end[];

/* .data copied, .bss cleared, the unused stack painted for am_baremetal_stack_used; call it
 * from a shallow frame (it paints up to 256 bytes below its own) */
void am_boot_memory(void);

/* the host's command line split into arguments, then exit(main(argc, argv)) */
_Noreturn void am_boot_main(void);

/* highest stack use so far, bytes: the painted words the stack has not reached stay painted */
unsigned long am_baremetal_stack_used(void);

/* with -DAM_BAREMETAL_STACK_REPORT, "baremetal: stack_used=N heap_used=N" on stderr (the C
 * library's _exit calls it); heap_used is what the C library's allocator took */
void am_boot_report(unsigned long heap_used);

#endif
