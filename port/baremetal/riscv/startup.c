/* Start-up of a 32-bit RISC-V board in machine mode: the entry point, the trap handler, the stack
 * guard, and the semihosting trap; then boot.c's steps (.data, .bss, the stack's paint, the
 * command line, main()).
 *
 * QEMU's virt machine started with -bios none jumps to the start of RAM, 0x80000000, where
 * virt.ld places _start. _start sets the stack pointer, the trap vector and the thread pointer
 * (picolibc keeps errno in thread-local storage: tp points at the one thread's block), switches
 * the FPU on when the core has one (mstatus.FS is Off after reset, and any floating-point
 * instruction would trap) and calls am_reset. No interrupt is enabled. */
#include "boot.h"
#include "semihost.h"

void am_reset(void);
void am_trap(void);

/* the entry (first in the image), and the trap vector: a trap resets the stack pointer, which
 * may be what trapped, and reports. CSR instructions need Zicsr by name in the assembler's ISA
 * string; the compiler's -march stays rv32imafc so that its multilib is chosen */
__asm__(".pushsection .text.start, \"ax\", @progbits\n"
        ".globl _start\n"
        "_start:\n"
        ".option push\n"
        ".option arch, +zicsr\n"
        "    la sp, __stack_top\n"
        "    la t0, am_trap_entry\n"
        "    csrw mtvec, t0\n"
        "    la tp, __tls_base\n"
#if defined(__riscv_flen)
        "    li t0, 0x2000\n" /* mstatus.FS = Initial */
        "    csrs mstatus, t0\n"
        "    csrw fcsr, zero\n" /* round to nearest, no flags */
#endif
        ".option pop\n"
        "    call am_reset\n"
        "1:  j 1b\n"
        ".section .text.am_trap_entry, \"ax\", @progbits\n"
        ".balign 4\n" /* mtvec's direct mode: the low two bits are the mode */
        "am_trap_entry:\n"
        "    la sp, __stack_top\n"
        "    call am_trap\n"
        "2:  j 2b\n"
        ".popsection\n");

/* one semihosting call: a0 the operation, a1 its argument, the answer in a0, which is exactly the
 * calling convention of sh_call. The host recognises the three uncompressed instructions around
 * the ebreak; they must not cross a page, which the 16-byte alignment ensures */
__asm__(".pushsection .text.sh_call, \"ax\", @progbits\n"
        ".globl sh_call\n"
        ".balign 16\n"
        "sh_call:\n"
        ".option push\n"
        ".option norvc\n"
        "    slli x0, x0, 0x1f\n"
        "    ebreak\n"
        "    srai x0, x0, 7\n"
        ".option pop\n"
        "    ret\n"
        ".popsection\n");

#define CSR_READ(name, v) __asm__ volatile(".option push\n.option arch, +zicsr\ncsrr %0, " name "\n.option pop" : "=r"(v))
#define CSR_WRITE(name, v) __asm__ volatile(".option push\n.option arch, +zicsr\ncsrw " name ", %0\n.option pop" ::"r"(v))

/* the stack guard: the 4 KiB below __stack_limit (virt.ld aligns it to 4 KiB) neither readable
 * nor writable, in machine mode too (PMP entry 0, NAPOT, locked until reset), so a stack
 * overflow faults (am_trap: "stack overflow", status 70) instead of writing over whatever lies
 * below the RAM region */
#define GUARD 4096u
static void stack_guard(void)
{
    uintptr_t base = (uintptr_t)__stack_limit - GUARD;
    uintptr_t addr = (base >> 2) | (GUARD / 8 - 1); /* NAPOT: base / 4 with the size's low ones */
    uintptr_t cfg = 0x80u | 0x18u;                  /* L (applies to machine mode), A = NAPOT, no R W X */
    CSR_WRITE("pmpaddr0", addr);
    CSR_WRITE("pmpcfg0", cfg);
}

void am_reset(void)
{
    stack_guard();
    am_boot_memory();
    am_boot_main(); /* picolibc's standard streams are unbuffered from the start (picolibc.c) */
}

/* writes text and a number in hex through SYS_WRITE0, without the C library */
static void put_hex(const char* text, uint32_t v)
{
    char s[11] = "0x";
    for (int i = 0; i < 8; i++) s[2 + i] = "0123456789abcdef"[(v >> (28 - 4 * i)) & 15];
    s[10] = 0;
    sh_write0(text);
    sh_write0(s);
}

/* a trap has no way back: say which, where, and end the run with status 70 */
void am_trap(void)
{
    uintptr_t cause, pc, value;
    CSR_READ("mcause", cause);
    CSR_READ("mepc", pc);
    CSR_READ("mtval", value);
    /* an ebreak that is not a semihosting call (or no semihosting host): nobody to tell */
    if (cause == 3)
        for (;;) __asm__ volatile("wfi");
    static const char* const names[16] = {
        "instruction address misaligned", "instruction access fault", "illegal instruction", "breakpoint",
        "load address misaligned",        "load access fault",        "store address misaligned",
        "store access fault",             "environment call",         "environment call",
        "trap 10",                        "environment call",         "instruction page fault",
        "load page fault",                "trap 14",                  "store page fault",
    };
    const uintptr_t limit = (uintptr_t)__stack_limit;
    int overflow = (cause == 5 || cause == 7) && value >= limit - GUARD && value < limit;
    sh_write0("amorph: ");
    sh_write0(overflow ? "stack overflow" : (cause & 0x80000000u) ? "interrupt" : cause < 16 ? names[cause] : "trap");
    put_hex(" (mcause ", (uint32_t)cause);
    put_hex(", mepc ", (uint32_t)pc);
    put_hex(", mtval ", (uint32_t)value);
    sh_write0(")\n");
    sh_exit(70);
}
