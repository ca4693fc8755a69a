/* Start-up steps every instruction set shares: memory set up from the linker script's symbols,
 * the stack painted for a high-water mark, the host's command line as argv, main().
 *
 * The reset code of the instruction set's folder (cortex-m/startup.c, riscv/startup.c) runs
 * first and calls these; boot.h says in which order. */
#include "boot.h"
#include "semihost.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char** argv);

#define STACK_PAINT 0xa5a5a5a5u /* stack words never written keep this value */

unsigned long am_baremetal_stack_used(void)
{
    const volatile uint32_t* p = __stack_limit;
    while (p < __stack_top && *p == STACK_PAINT) p++;
    return (unsigned long)((uintptr_t)__stack_top - (uintptr_t)p);
}

/* paints the unused stack below the current frame, for am_baremetal_stack_used */
__attribute__((noinline)) static void stack_paint(void)
{
    volatile uint32_t* p = __stack_limit;
    volatile uint32_t* end = (volatile uint32_t*)((uintptr_t)&p - 256);
    while (p < end) *p++ = STACK_PAINT;
}

void am_boot_memory(void)
{
    for (uint32_t *s = __data_load, *d = __data_start; d < __data_end;) *d++ = *s++;
    for (uint32_t* d = __bss_start; d < __bss_end;) *d++ = 0;
    stack_paint();
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

_Noreturn void am_boot_main(void)
{
    int argc = split_cmdline();
    exit(main(argc, argv_buf));
}

void am_boot_report(unsigned long heap_used)
{
#if defined(AM_BAREMETAL_STACK_REPORT)
    char line[96];
    snprintf(line, sizeof line, "baremetal: stack_used=%lu heap_used=%lu\n", am_baremetal_stack_used(), heap_used);
    sh_write_console(1, line, (uint32_t)strlen(line));
#else
    (void)heap_used;
#endif
}
