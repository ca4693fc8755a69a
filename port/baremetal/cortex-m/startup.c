/* Start-up of a Cortex-M board: the vector table, the reset handler (switch the FPU on when
 * there is one, then boot.c's steps: .data, .bss, the stack's paint, the command line, main()),
 * and the semihosting trap.
 *
 * mps2.ld places the table at address 0, where the core reads the initial stack pointer (entry
 * 0) and the reset handler (entry 1) on reset. The stack sits at the bottom of RAM, below .data,
 * so an overflow runs off the RAM instead of into the program's data. */
#include "boot.h"
#include "semihost.h"

#include <stdio.h>

void am_reset(void);

/* one semihosting call: BKPT 0xAB with the operation in r0 and its argument in r1, the answer
 * back in r0 (M-profile cores) */
int32_t sh_call(uint32_t op, uintptr_t arg)
{
    register uint32_t r0 __asm__("r0") = op;
    register uintptr_t r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
    return (int32_t)r0;
}

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

/* the FPU (CP10, CP11) is off after reset; floating-point code before this would fault */
static void fpu_on(void)
{
#if defined(__ARM_FP)
    volatile uint32_t* cpacr = (volatile uint32_t*)0xe000ed88u;
    *cpacr |= 0xfu << 20; /* full access to CP10 and CP11 */
    __asm__ volatile("dsb\n\tisb" ::: "memory");
#endif
}

void am_reset(void)
{
    fpu_on();
    am_boot_memory();
    /* unbuffered standard streams: the C library allocates no stream buffer and output keeps
     * its order across printf, am_port_out and the two streams */
    setvbuf(stdout, 0, _IONBF, 0);
    setvbuf(stderr, 0, _IONBF, 0);
    am_boot_main();
}
