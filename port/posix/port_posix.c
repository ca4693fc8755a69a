/* POSIX port: clock, files with atomic replace, core count. */
#define _POSIX_C_SOURCE 200809L
#include "amorph/port.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

double am_port_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

am_status am_port_read_file(const char* path, char* buf, long cap, long* len, char* err, int errsz)
{
    int fd = open(path, O_RDONLY);
    if (fd < 0) return am_fail(err, errsz, AM_ERR_IO, "%s: cannot open: %s", path, strerror(errno));
    long n = 0;
    for (;;) {
        if (n >= cap - 1) {
            char extra;
            ssize_t more = read(fd, &extra, 1);
            close(fd);
            if (more > 0)
                return am_fail(err, errsz, AM_ERR_CAPACITY, "%s: file larger than the %ld bytes this build can read", path, cap - 1);
            break;
        }
        ssize_t got = read(fd, buf + n, (size_t)(cap - 1 - n));
        if (got < 0) {
            if (errno == EINTR) continue;
            int e = errno;
            close(fd);
            return am_fail(err, errsz, AM_ERR_IO, "%s: read error: %s", path, strerror(e));
        }
        if (got == 0) {
            close(fd);
            break;
        }
        n += got;
    }
    buf[n] = 0;
    if (len) *len = n;
    return AM_OK;
}

am_status am_port_write_file(const char* path, const void* data, long n, char* err, int errsz)
{
    char tmp[4096];
    if (snprintf(tmp, sizeof tmp, "%s.tmp.%ld", path, (long)getpid()) >= (int)sizeof tmp)
        return am_fail(err, errsz, AM_ERR_IO, "%s: path too long", path);
    int fd = open(tmp, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0) return am_fail(err, errsz, AM_ERR_IO, "%s: cannot create: %s", tmp, strerror(errno));
    const char* p = (const char*)data;
    long done = 0;
    while (done < n) {
        ssize_t put = write(fd, p + done, (size_t)(n - done));
        if (put < 0) {
            if (errno == EINTR) continue;
            int e = errno;
            close(fd);
            unlink(tmp);
            return am_fail(err, errsz, AM_ERR_IO, "%s: write error: %s", path, strerror(e));
        }
        done += put;
    }
    if (fsync(fd) != 0 || close(fd) != 0) {
        int e = errno;
        unlink(tmp);
        return am_fail(err, errsz, AM_ERR_IO, "%s: cannot finish writing: %s", path, strerror(e));
    }
    if (rename(tmp, path) != 0) {
        int e = errno;
        unlink(tmp);
        return am_fail(err, errsz, AM_ERR_IO, "%s: cannot replace: %s", path, strerror(e));
    }
    return AM_OK;
}

int am_port_cores(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n < 1 ? 1 : (int)n;
}
