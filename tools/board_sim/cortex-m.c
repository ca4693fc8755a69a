/* tools/board_sim/cortex-m.c: the start-up of board_sim on a Cortex-M board (QEMU's mps2-an385 and
 * mps2-an386 models; cortex-m.ld): the vector table, the reset handler (FPU on where there is one,
 * .data copied, .bss cleared, the stack painted, main) and the host console and exit through
 * semihosting (Arm's "Semihosting for AArch32 and AArch64": BKPT 0xAB, SYS_WRITE0, SYS_EXIT).
 * Written for this program alone, apart from the amorph port (port/baremetal), which it does not
 * link: a board that runs only the simulator needs no files, command line, clock or threads. */
#include "board.h"

#include <errno.h>
#include <stddef.h>
#include <stdint.h>

int main(void);
void board_reset(void);

/* the linker script's symbols */
extern uint32_t __stack_limit[], __stack_top[];
extern uint32_t __data_start[], __data_end[], __data_load[];
extern uint32_t __bss_start[], __bss_end[];

#define PAINT 0x5a5aa5a5u

/* one semihosting call: the operation in r0, its argument in r1, the answer in r0 */
static int32_t sh_call(uint32_t op, uintptr_t arg)
{
    register uint32_t r0 __asm__("r0") = op;
    register uintptr_t r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
    return (int32_t)r0;
}

void board_out(const char* text)
{
    sh_call(0x04u, (uintptr_t)text); /* SYS_WRITE0 */
}

_Noreturn void board_exit(int status)
{
    /* SYS_EXIT: ADP_Stopped_ApplicationExit for 0, ADP_Stopped_RunTimeErrorUnknown otherwise */
    for (;;) sh_call(0x18u, status == 0 ? 0x20026u : 0x20023u);
}

unsigned long board_stack_used(void)
{
    const uint32_t* w = __stack_limit;
    while (w < __stack_top && *w == PAINT) w++;
    return (unsigned long)((uintptr_t)__stack_top - (uintptr_t)w);
}

/* a fault has no way back */
static void on_fault(void)
{
    board_out("board_sim: fault\n");
    board_exit(70);
}

typedef void (*board_handler)(void);
typedef struct board_vectors {
    uint32_t* initial_sp;
    board_handler entry[15];
} board_vectors;

/* the 16 system entries of the ARMv7-M vector table; no interrupt is enabled */
__attribute__((section(".vectors"), used)) const board_vectors board_vector_table = {
    __stack_top,
    {board_reset, on_fault, on_fault, on_fault, on_fault, on_fault, 0, 0, 0, 0, on_fault, on_fault, 0, on_fault, on_fault},
};

/* the stack from its limit up to 256 bytes below this frame painted for board_stack_used */
__attribute__((noinline)) static void paint_stack(void)
{
    volatile uint32_t here = 0;
    uint32_t* end = (uint32_t*)((uintptr_t)&here - 256);
    for (uint32_t* w = __stack_limit; w < end; w++) *w = PAINT;
}

void board_reset(void)
{
#if defined(__ARM_FP)
    volatile uint32_t* cpacr = (volatile uint32_t*)0xe000ed88u;
    *cpacr |= 0xfu << 20; /* full access to CP10 and CP11: the FPU on */
    __asm__ volatile("dsb\n\tisb" ::: "memory");
#endif
    for (uint32_t *s = __data_load, *d = __data_start; d < __data_end;) *d++ = *s++;
    for (uint32_t* d = __bss_start; d < __bss_end;) *d++ = 0;
    paint_stack();
    board_exit(main());
}

/* The C library's system calls. The library calls snprintf, vsnprintf and strtod (its messages and
 * its number parsing), and newlib's formatted printing refers to the standard streams, the
 * allocator (numbers' conversions) and abort, so these must exist; none is reached by this
 * program: nothing allocates, and no stream is read or written. They refuse (ENOSYS, ENOMEM), but
 * _exit, which ends the program. */
struct stat;
void* _sbrk(ptrdiff_t incr);
int _write(int fd, const void* buf, size_t n);
int _read(int fd, void* buf, size_t n);
int _close(int fd);
long _lseek(int fd, long off, int whence);
int _fstat(int fd, struct stat* st);
int _isatty(int fd);
int _kill(int pid, int sig);
int _getpid(void);
_Noreturn void _exit(int status);

void* _sbrk(ptrdiff_t incr)
{
    (void)incr;
    errno = ENOMEM;
    return (void*)-1;
}
static int refused(void)
{
    errno = ENOSYS;
    return -1;
}
int _write(int fd, const void* buf, size_t n) { return (void)fd, (void)buf, (void)n, refused(); }
int _read(int fd, void* buf, size_t n) { return (void)fd, (void)buf, (void)n, refused(); }
int _close(int fd) { return (void)fd, refused(); }
long _lseek(int fd, long off, int whence) { return (void)fd, (void)off, (void)whence, refused(); }
int _fstat(int fd, struct stat* st) { return (void)fd, (void)st, refused(); }
int _isatty(int fd) { return (void)fd, 0; }
int _kill(int pid, int sig) { return (void)pid, (void)sig, refused(); }
int _getpid(void) { return 1; }
_Noreturn void _exit(int status) { board_exit(status); }
