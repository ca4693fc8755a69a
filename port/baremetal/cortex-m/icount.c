/* The bare-metal clock of `make bench-board` (built with -DAM_BAREMETAL_ICOUNT, which replaces
 * port_baremetal.c's semihosting clock): instructions, read from QEMU's MPS2 boards. */
#include "port.h"

#include <stdint.h>

#if defined(AM_BAREMETAL_ICOUNT)
/* The clock of `make bench-board`: the MPS2 FPGA I/O block's COUNTER (0x40028018), which counts
 * at 25 MHz of the board's time once PRESCALE (0x4002801C) is 0. Under QEMU with -icount shift=0
 * the board's time advances 1 ns per instruction executed, so a second of this clock is 1e9
 * instructions (read to 40 instructions). The 32-bit counter wraps every 171 s of board time;
 * a read after a wrap carries it, so no two reads may be further apart than that. */
#define FPGAIO_COUNTER (*(volatile uint32_t*)0x40028018u)
#define FPGAIO_PRESCALE (*(volatile uint32_t*)0x4002801Cu)
double am_port_now(void)
{
    static int started;
    static uint32_t last;
    static uint64_t high;
    if (!started) {
        FPGAIO_PRESCALE = 0;
        started = 1;
    }
    const uint32_t c = FPGAIO_COUNTER;
    if (c < last) high += (uint64_t)1 << 32;
    last = c;
    return (double)(high + c) / 25e6;
}
#else
typedef int am_baremetal_icount_unused; /* an empty translation unit is not ISO C */
#endif
