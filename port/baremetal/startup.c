/* Start-up of a Cortex-M board: the vector table, the reset handler (copy .data, clear .bss,
 * switch the FPU on when there is one), the command line from the host, and main().
 *
 * mps2.ld places the table at address 0, where the core reads the initial stack pointer (entry
 * 0) and the reset handler (entry 1) on reset. The stack sits at the bottom of RAM, below .data,
 * so an overflow runs off the RAM instead of into the program's data. */
#include "semihost.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char** argv);
void am_reset(void);

/* symbols of the linker script (mps2.ld) */
extern uint32_t __stack_limit[], __stack_top[];
extern uint32_t __data_start[], __data_end[], __data_load[];
extern uint32_t __bss_start[], __bss_end[];

typedef void (*am_handler)(void);

/* a fault has no way back: say which, and end the run with status 70 */
static void on_fault(const char* what)
{
    sh_write0("amorph: ");
    sh_write0(what);
    sh_write0("\n");
    sh_exit(70);
}
static void on_nmi(void) { on_fault("NMI"); }
static void on_hard_fault(void) { on_fault("hard fault"); }
static void on_mem_fault(void) { on_fault("memory management fault"); }
static void on_bus_fault(void) { on_fault("bus fault"); }
static void on_usage_fault(void) { on_fault("usage fault (an undefined instruction, or the FPU off)"); }
static void on_other(void) { on_fault("unexpected exception"); }

/* the 16 system entries of the ARMv7-M vector table; the port enables no interrupt, so no
 * external entry follows */
typedef struct am_vectors {
    uint32_t* initial_sp;
    am_handler entry[15];
} am_vectors;

__attribute__((section(".vectors"), used)) const am_vectors am_vector_table = {
    __stack_top,
    {
        am_reset,       /* 1 reset */
        on_nmi,         /* 2 NMI */
        on_hard_fault,  /* 3 hard fault */
        on_mem_fault,   /* 4 memory management */
        on_bus_fault,   /* 5 bus fault */
        on_usage_fault, /* 6 usage fault */
        0, 0, 0, 0,     /* 7-10 reserved */
        on_other,       /* 11 SVCall */
        on_other,       /* 12 debug monitor */
        0,              /* 13 reserved */
        on_other,       /* 14 PendSV */
        on_other,       /* 15 SysTick */
    },
};

/* the C library's exit() runs the .fini_array through _fini, which a crt0 would give; amorph
 * has no constructors or destructors, so there is nothing to run at either end */
void _init(void);
void _fini(void);
void _init(void)
{
}
void _fini(void)
{
}

#define STACK_PAINT 0xa5a5a5a5u /* stack words never written keep this value */

/* highest stack use so far, bytes: the painted words the stack has not reached stay painted */
unsigned long am_baremetal_stack_used(void);
unsigned long am_baremetal_stack_used(void)
{
    const volatile uint32_t* p = __stack_limit;
    while (p < __stack_top && *p == STACK_PAINT) p++;
    return (unsigned long)((uintptr_t)__stack_top - (uintptr_t)p);
}

/* the host's command line split at spaces (semihosting passes one string: an argument cannot
 * contain a space) */
#define CMDLINE_MAX 1024
#define ARGV_MAX 64
static char cmdline[CMDLINE_MAX];
static char* argv_buf[ARGV_MAX + 1];

static int split_cmdline(void)
{
    uintptr_t a[2] = {(uintptr_t)cmdline, CMDLINE_MAX};
    int argc = 0;
    if (sh_call(SH_SYS_GET_CMDLINE, (uintptr_t)a) != 0) cmdline[0] = 0;
    cmdline[CMDLINE_MAX - 1] = 0;
    char* p = cmdline;
    while (*p && argc < ARGV_MAX) {
        while (*p == ' ') *p++ = 0;
        if (!*p) break;
        argv_buf[argc++] = p;
        while (*p && *p != ' ') p++;
    }
    if (argc == 0) argv_buf[argc++] = (char*)"amorph"; /* no command line: the program name only */
    argv_buf[argc] = 0;
    return argc;
}

/* the FPU (CP10, CP11) is off after reset; floating-point code before this would fault */
static void fpu_on(void)
{
#if defined(__ARM_FP)
    volatile uint32_t* cpacr = (volatile uint32_t*)0xe000ed88u;
    *cpacr |= 0xfu << 20; /* full access to CP10 and CP11 */
    __asm__ volatile("dsb\n\tisb" ::: "memory");
#endif
}

/* paints the unused stack below the current frame, for am_baremetal_stack_used */
__attribute__((noinline)) static void stack_paint(void)
{
    volatile uint32_t* p = __stack_limit;
    volatile uint32_t* end = (volatile uint32_t*)((uintptr_t)&p - 256);
    while (p < end) *p++ = STACK_PAINT;
}

void am_reset(void)
{
    fpu_on();
    for (uint32_t *s = __data_load, *d = __data_start; d < __data_end;) *d++ = *s++;
    for (uint32_t* d = __bss_start; d < __bss_end;) *d++ = 0;
    stack_paint();
    /* unbuffered standard streams: the C library allocates no stream buffer and output keeps
     * its order across printf, am_port_out and the two streams */
    setvbuf(stdout, 0, _IONBF, 0);
    setvbuf(stderr, 0, _IONBF, 0);
    int argc = split_cmdline();
    exit(main(argc, argv_buf));
}
