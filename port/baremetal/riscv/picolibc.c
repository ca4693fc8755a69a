/* What picolibc, the C library of the RISC-V builds (Debian's picolibc-riscv64-unknown-elf),
 * needs from a board: its standard streams and _exit, on semihosting.
 *
 * picolibc's stdio (tinystdio) leaves stdin, stdout and stderr to the application: here each is a
 * stream whose put function hands every character to the host console at once (SYS_WRITE on
 * ":tt", as newlib's _write does on the Cortex-M builds), so output keeps its order across
 * printf, am_port_out and the two streams, and no stream buffer exists. stdin is empty. amorph
 * opens no file through stdio (the port's semihosting calls do that), so picolibc's POSIX
 * open/read/write are not provided. Nothing allocates: tinystdio's printf and strtod take no
 * heap, and the link fails if malloc is pulled in (virt.ld gives no heap). */
#include "boot.h"
#include "semihost.h"

#include <stdio.h>

_Noreturn void _exit(int status);

static int put_out(char c, FILE* f)
{
    (void)f;
    sh_write_console(0, &c, 1);
    return (unsigned char)c;
}

static int put_err(char c, FILE* f)
{
    (void)f;
    sh_write_console(1, &c, 1);
    return (unsigned char)c;
}

static int get_none(FILE* f)
{
    (void)f;
    return EOF;
}

static FILE out_stream = FDEV_SETUP_STREAM(put_out, NULL, NULL, _FDEV_SETUP_WRITE);
static FILE err_stream = FDEV_SETUP_STREAM(put_err, NULL, NULL, _FDEV_SETUP_WRITE);
static FILE in_stream = FDEV_SETUP_STREAM(NULL, get_none, NULL, _FDEV_SETUP_READ);

FILE* const stdin = &in_stream;
FILE* const stdout = &out_stream;
FILE* const stderr = &err_stream;

_Noreturn void _exit(int status)
{
    am_boot_report(0);
    sh_exit(status);
}
