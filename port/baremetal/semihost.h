/* port/baremetal/semihost.h: semihosting, the debugger's (or QEMU's) services to a board.
 *
 * A semihosting call passes an operation number and one argument (a word, or the address of a
 * block of words) and gets one word back. Only the trap differs between instruction sets
 * (sh_call, in the instruction set's startup.c): BKPT 0xAB with r0 and r1 on M-profile Arm
 * cores, the sequence slli x0,x0,0x1f; ebreak; srai x0,x0,7 with a0 and a1 on RISC-V. The
 * operation numbers are those of Arm's "Semihosting for AArch32 and AArch64" specification,
 * release 2.0, which the RISC-V semihosting specification adopts as they are (words of 32 bits
 * on a 32-bit core). Files are host files, named relative to the host's working directory;
 * ":tt" is the host console. */
#ifndef AMORPH_PORT_SEMIHOST_H
#define AMORPH_PORT_SEMIHOST_H

#include <stdint.h>

enum {
    SH_SYS_OPEN = 0x01,        /* {name, mode, strlen(name)} -> handle or -1 */
    SH_SYS_CLOSE = 0x02,       /* {handle} -> 0 or -1 */
    SH_SYS_WRITE0 = 0x04,      /* NUL-terminated text to the debug console */
    SH_SYS_WRITE = 0x05,       /* {handle, data, n} -> bytes NOT written */
    SH_SYS_READ = 0x06,        /* {handle, buf, n} -> bytes NOT read (n at end of file) */
    SH_SYS_ISTTY = 0x09,       /* {handle} -> 1 for an interactive device */
    SH_SYS_SEEK = 0x0a,        /* {handle, absolute position} -> 0 or negative */
    SH_SYS_FLEN = 0x0c,        /* {handle} -> length in bytes or -1 */
    SH_SYS_REMOVE = 0x0e,      /* {name, strlen(name)} -> 0 or host errno */
    SH_SYS_RENAME = 0x0f,      /* {old, strlen(old), new, strlen(new)} -> 0 or nonzero */
    SH_SYS_CLOCK = 0x10,       /* -> centiseconds since the program started, or -1 */
    SH_SYS_SYSTEM = 0x12,      /* {command, strlen(command)} -> the host shell's status */
    SH_SYS_ERRNO = 0x13,       /* -> the host errno of the last failed call */
    SH_SYS_GET_CMDLINE = 0x15, /* {buf, size} -> 0; buf gets the command line, size its length */
    SH_SYS_EXIT = 0x18,        /* angel_SWIreason_ReportException: r1 is the reason itself */
    SH_SYS_EXIT_EXTENDED = 0x20, /* {reason, subcode}: the exit status reaches the host */
    SH_SYS_ELAPSED = 0x30,     /* {low, high} <- ticks since the program started; -> 0 or -1 */
    SH_SYS_TICKFREQ = 0x31     /* -> ticks per second, or -1 */
};

/* reasons of SYS_EXIT (ADP_Stopped_*) */
#define SH_ADP_APPLICATION_EXIT 0x20026u
#define SH_ADP_RUNTIME_ERROR 0x20023u

/* SYS_OPEN modes: the index of the fopen() mode in r, rb, r+, r+b, w, wb, w+, w+b, a, ab, a+, a+b */
enum { SH_MODE_RB = 1, SH_MODE_WB = 5, SH_MODE_AB = 9 };

/* features a host announces in the ":semihosting-features" file (byte 0) */
#define SH_EXT_EXIT_EXTENDED 0x01
#define SH_EXT_STDOUT_STDERR 0x02

/* one semihosting call: the operation, its argument; the host's answer (the instruction set's
 * startup.c) */
int32_t sh_call(uint32_t op, uintptr_t arg);

/* the port's own helpers (port_baremetal.c) */
int32_t sh_open(const char* name, int mode);          /* handle, or -1 */
int32_t sh_close(int32_t handle);
int32_t sh_write(int32_t handle, const void* data, uint32_t n); /* bytes written */
int32_t sh_read(int32_t handle, void* buf, uint32_t n);         /* bytes read */
int32_t sh_flen(int32_t handle);
int32_t sh_seek(int32_t handle, uint32_t pos);
int sh_features(void);                                /* SH_EXT_* bits, read once */
int32_t sh_console(int err);                          /* handle of stdout (0) or stderr (1), -1 if none */
void sh_write0(const char* text);
void sh_write_console(int err, const char* data, uint32_t n);
_Noreturn void sh_exit(int status);

#endif
