/* The system calls newlib's C library makes (printf, fopen, exit...), on semihosting: the C
 * library of the Cortex-M builds (Debian's libnewlib-arm-none-eabi).
 *
 * File descriptors 0, 1, 2 are the host console (stdin is empty); open() hands out descriptors
 * 3 and up for host files, at most SYS_FILES at once. There is no heap growth beyond a fixed
 * static arena: _sbrk serves newlib's malloc from HEAP_ARENA bytes and then fails. Only newlib
 * mallocs, never amorph: its floating-point printf (dtoa's big numbers) and the buffer of a
 * stream opened with fopen (the standard streams are unbuffered, see startup.c). */
#include "boot.h"
#include "semihost.h"

#include <errno.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

/* newlib's names for the system calls (declared here: its headers show them only in part) */
int _open(const char* name, int flags, int mode);
int _close(int fd);
int _read(int fd, char* buf, int n);
int _write(int fd, const char* buf, int n);
int _lseek(int fd, int off, int whence);
int _fstat(int fd, struct stat* st);
int _isatty(int fd);
int _getpid(void);
int _kill(int pid, int sig);
_Noreturn void _exit(int status);
void* _sbrk(ptrdiff_t incr);
unsigned long am_baremetal_heap_used(void);

#define SYS_FILES 8 /* host files open at once */
/* newlib's open() flags (sys/_default_fcntl.h) */
#define NL_O_ACCMODE 3
#define NL_O_WRONLY 1
#define NL_O_RDWR 2
#define NL_O_APPEND 0x0008
#define NL_O_CREAT 0x0200
#define NL_O_TRUNC 0x0400

static struct {
    int32_t handle; /* semihosting handle, -1 when the slot is free */
    long pos;       /* file position, for lseek */
} files[SYS_FILES] = {{-1, 0}, {-1, 0}, {-1, 0}, {-1, 0}, {-1, 0}, {-1, 0}, {-1, 0}, {-1, 0}};

static int slot_of(int fd)
{
    int k = fd - 3;
    return k >= 0 && k < SYS_FILES && files[k].handle >= 0 ? k : -1;
}

int _open(const char* name, int flags, int mode)
{
    (void)mode;
    int acc = flags & NL_O_ACCMODE, sh;
    /* the fopen() mode of the flags: r, r+, w, w+, a, a+ (always binary) */
    if (flags & NL_O_APPEND) sh = acc == NL_O_RDWR ? 11 : 9;
    else if (flags & (NL_O_CREAT | NL_O_TRUNC)) sh = acc == NL_O_RDWR ? 7 : 5;
    else sh = acc == NL_O_RDWR ? 3 : (acc == NL_O_WRONLY ? 5 : 1);
    int k = 0;
    while (k < SYS_FILES && files[k].handle >= 0) k++;
    if (k == SYS_FILES) {
        errno = EMFILE;
        return -1;
    }
    int32_t h = sh_open(name, sh);
    if (h < 0) {
        errno = ENOENT;
        return -1;
    }
    files[k].handle = h;
    files[k].pos = 0;
    if (flags & NL_O_APPEND) {
        /* QEMU 7.2 drops the host's O_APPEND (see am_port_append_file): start at the end */
        int32_t end = sh_flen(h);
        if (end > 0 && sh_seek(h, (uint32_t)end) == 0) files[k].pos = end;
    }
    return k + 3;
}

int _close(int fd)
{
    if (fd >= 0 && fd <= 2) return 0;
    int k = slot_of(fd);
    if (k < 0) {
        errno = EBADF;
        return -1;
    }
    int32_t r = sh_close(files[k].handle);
    files[k].handle = -1;
    return r == 0 ? 0 : -1;
}

int _read(int fd, char* buf, int n)
{
    if (fd == 0) return 0; /* no console input */
    int k = slot_of(fd);
    if (k < 0 || n < 0) {
        errno = EBADF;
        return -1;
    }
    int32_t got = sh_read(files[k].handle, buf, (uint32_t)n);
    if (got < 0) {
        errno = EIO;
        return -1;
    }
    files[k].pos += got;
    return got;
}

int _write(int fd, const char* buf, int n)
{
    if (n < 0) {
        errno = EINVAL;
        return -1;
    }
    if (fd == 1 || fd == 2) {
        sh_write_console(fd == 2, buf, (uint32_t)n);
        return n;
    }
    int k = slot_of(fd);
    if (k < 0) {
        errno = EBADF;
        return -1;
    }
    int32_t put = sh_write(files[k].handle, buf, (uint32_t)n);
    files[k].pos += put;
    if (put == 0 && n > 0) {
        errno = EIO;
        return -1;
    }
    return put;
}

int _lseek(int fd, int off, int whence)
{
    int k = slot_of(fd);
    if (k < 0) {
        errno = EBADF;
        return -1;
    }
    long base = whence == 0 ? 0 : whence == 1 ? files[k].pos : (long)sh_flen(files[k].handle);
    long to = base + off;
    if (base < 0 || to < 0 || sh_seek(files[k].handle, (uint32_t)to) < 0) {
        errno = EINVAL;
        return -1;
    }
    files[k].pos = to;
    return (int)to;
}

int _fstat(int fd, struct stat* st)
{
    memset(st, 0, sizeof *st);
    st->st_mode = fd <= 2 ? S_IFCHR : S_IFREG;
    int k = slot_of(fd);
    if (k >= 0) st->st_size = sh_flen(files[k].handle);
    return 0;
}

int _isatty(int fd)
{
    return fd >= 0 && fd <= 2;
}

int _getpid(void)
{
    return 1;
}

int _kill(int pid, int sig)
{
    (void)pid;
    (void)sig;
    errno = EINVAL;
    return -1;
}

_Noreturn void _exit(int status)
{
    am_boot_report(am_baremetal_heap_used());
    sh_exit(status);
}

/* ---- the heap arena ---- */

/* newlib's malloc grows its pool to the next 4 KiB boundary (its page size) at its first call and
 * asks for whole pages after that. The arena is one page and starts on a page boundary (section
 * .heap, which mps2.ld places there), so the first growth takes exactly the arena and newlib's
 * printf and strtod (the only users) never ask for more (docs/porting.md, Heap). */
#define HEAP_ARENA 4096 /* bytes newlib's malloc may take, in all */
static _Alignas(8) unsigned char heap[HEAP_ARENA] __attribute__((section(".heap")));
static size_t heap_top;

void* _sbrk(ptrdiff_t incr)
{
    if (incr < 0 ? (size_t)(-incr) > heap_top : (size_t)incr > HEAP_ARENA - heap_top) {
        errno = ENOMEM;
        return (void*)-1;
    }
    void* old = heap + heap_top;
    heap_top = (size_t)((ptrdiff_t)heap_top + incr);
    return old;
}

unsigned long am_baremetal_heap_used(void)
{
    return (unsigned long)heap_top;
}
