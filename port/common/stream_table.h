/* port/common/stream_table.h: the streams of port.h (am_port_open_write, am_port_write,
 * am_port_open_read, am_port_read, am_port_close) over a fixed table, shared by the ports that
 * keep files (posix, win32, baremetal). What a stream promises is decided here once: a written
 * stream goes to a temporary beside its file and replaces the file only when closed with commit
 * and no write failed; after a failed write every later write is refused; a stream is used by the
 * main thread only.
 *
 * A port's source includes this file once (it defines static tables and the contract's
 * functions, named am_port_open_write ... unless the source defines PORT_FN(name) to name them
 * otherwise: port/posix's are am_posix_open_write ..., which port/posix/port_posix.c and
 * port/mpi/port_mpi.c call), after defining:
 *   PORT_STREAMS   how many streams may be open at once
 *   PORT_TMP_CAP   bytes for a temporary's name with its terminating zero (a stack buffer)
 *   port_handle    the system's handle of an open file
 * and these static functions, each of which reports its own failure through am_fail:
 *   int sys_tmp_name(char* out, size_t cap, const char* path, uint64_t nonce)
 *       the temporary of path named by nonce into out; 0 when it does not fit
 *   am_status sys_create(const char* path, char* tmp, size_t cap, uint64_t* nonce, port_handle* h, char* err, int errsz)
 *       a new temporary for path created for writing, never through a link or a file planted at
 *       its name (where the port can promise it: an unpredictable nonce and an exclusive create,
 *       tried again under a new nonce when the name is taken); its name into tmp and its nonce
 *       into *nonce (the stream keeps the nonce, not the name); a failure names path, the
 *       user's file, not the temporary
 *   am_status sys_open_read(const char* path, port_handle* h, char* err, int errsz)
 *       path opened for reading
 *   am_status sys_write(port_handle h, const void* data, long n, const char* path, char* err, int errsz)
 *       all n bytes written (path names the stream in the message)
 *   am_status sys_read(port_handle h, void* buf, long cap, long* got, const char* path, char* err, int errsz)
 *       up to cap > 0 bytes read, *got 0 at the end
 *   void sys_close(port_handle h)
 *       a read stream closed
 *   void sys_drop(port_handle h, const char* tmp)
 *       a written stream closed and its temporary removed, the file left as it was
 *   am_status sys_commit(port_handle h, const char* tmp, const char* path, char* err, int errsz)
 *       a written stream's bytes made durable, the handle closed and path replaced by tmp; on a
 *       failure the temporary is removed and path is left as it was */
#ifndef AMORPH_PORT_STREAM_TABLE_H
#define AMORPH_PORT_STREAM_TABLE_H

#include <stdint.h>

#ifndef PORT_FN
#define PORT_FN(name) am_port_##name
#endif

static struct {
    port_handle h;
    const char* path; /* the caller's, valid until am_port_close */
    uint64_t nonce;   /* a written stream's temporary: sys_tmp_name(path, nonce) */
    uint8_t used;     /* 1 while the slot is open */
    uint8_t writing;  /* 1: an atomic replace of path through its temporary */
    uint8_t failed;   /* 1 after a failed write: the stream will be dropped */
} streams[PORT_STREAMS];

/* a free slot for a stream of path, or -1 after the message */
static int free_slot(const char* path, char* err, int errsz)
{
    for (int k = 0; k < PORT_STREAMS; k++)
        if (!streams[k].used) return k;
    am_fail(err, errsz, AM_ERR_IO, "%s: more than %d files open at once", path, PORT_STREAMS);
    return -1;
}

static int slot_ok(am_port_stream s)
{
    return s >= 0 && s < PORT_STREAMS && streams[s].used;
}

/* stream slot k from now on for the open file h of path; returns k */
static int claim(int k, port_handle h, const char* path, int writing)
{
    streams[k].h = h;
    streams[k].path = path;
    streams[k].used = 1;
    streams[k].writing = (uint8_t)writing;
    streams[k].failed = 0;
    return k;
}

am_status PORT_FN(open_write)(const char* path, am_port_stream* s, char* err, int errsz)
{
    char tmp[PORT_TMP_CAP];
    *s = -1;
    if (!sys_tmp_name(tmp, sizeof tmp, path, 0)) return am_fail(err, errsz, AM_ERR_IO, "%s: path too long", path);
    const int k = free_slot(path, err, errsz);
    if (k < 0) return AM_ERR_IO;
    port_handle h;
    uint64_t nonce = 0;
    am_status st = sys_create(path, tmp, sizeof tmp, &nonce, &h, err, errsz);
    if (st != AM_OK) return st;
    *s = claim(k, h, path, 1);
    streams[k].nonce = nonce;
    return AM_OK;
}

am_status PORT_FN(write)(am_port_stream s, const void* data, long n, char* err, int errsz)
{
    if (!slot_ok(s) || !streams[s].writing) return am_fail(err, errsz, AM_ERR_ARG, "stream %d: not open for writing", s);
    if (streams[s].failed) return am_fail(err, errsz, AM_ERR_IO, "%s: write error: an earlier write failed", streams[s].path);
    am_status st = sys_write(streams[s].h, data, n, streams[s].path, err, errsz);
    if (st != AM_OK) streams[s].failed = 1;
    return st;
}

am_status PORT_FN(open_read)(const char* path, am_port_stream* s, char* err, int errsz)
{
    *s = -1;
    const int k = free_slot(path, err, errsz);
    if (k < 0) return AM_ERR_IO;
    port_handle h;
    am_status st = sys_open_read(path, &h, err, errsz);
    if (st != AM_OK) return st;
    *s = claim(k, h, path, 0);
    return AM_OK;
}

am_status PORT_FN(read)(am_port_stream s, void* buf, long cap, long* got, char* err, int errsz)
{
    *got = 0;
    if (!slot_ok(s) || streams[s].writing) return am_fail(err, errsz, AM_ERR_ARG, "stream %d: not open for reading", s);
    if (cap <= 0) return AM_OK;
    return sys_read(streams[s].h, buf, cap, got, streams[s].path, err, errsz);
}

am_status PORT_FN(close)(am_port_stream s, int commit, char* err, int errsz)
{
    if (!slot_ok(s)) return am_fail(err, errsz, AM_ERR_ARG, "stream %d: not open", s);
    const char* path = streams[s].path;
    const port_handle h = streams[s].h;
    const int writing = streams[s].writing, failed = streams[s].failed;
    streams[s].used = 0;
    if (!writing) {
        sys_close(h);
        return AM_OK;
    }
    char tmp[PORT_TMP_CAP];
    sys_tmp_name(tmp, sizeof tmp, path, streams[s].nonce); /* fitted at open */
    if (!commit || failed) {
        sys_drop(h, tmp);
        return commit ? am_fail(err, errsz, AM_ERR_IO, "%s: not replaced: a write failed", path) : AM_OK;
    }
    return sys_commit(h, tmp, path, err, errsz);
}

#endif
