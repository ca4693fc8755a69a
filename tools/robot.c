/* Loading robots for the commands: scenes, lattice files, genome files, VXA files. */
#include "cmd.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

char tool_file_buf[TOOL_FILE_MAX];
am_evo_work tool_work[AM_MAX_WORKERS];

int tool_usage_error(const char* fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fputs("amorph: ", stderr);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
    return 2;
}

int tool_write_output(const char* out, const char* text, long len)
{
    char err[AM_ERR_MAX];
    if (!out) {
        if (fwrite(text, 1, (size_t)len, stdout) != (size_t)len || fflush(stdout) != 0) {
            fprintf(stderr, "amorph: cannot write to the standard output\n");
            return 1;
        }
        return 0;
    }
    if (am_port_write_file(out, text, len, err, sizeof err) != AM_OK) {
        fprintf(stderr, "amorph: %s\n", err);
        return 1;
    }
    return 0;
}

am_status tool_load_robot(const char* name, int is_scene, am_lattice* lat, char* err, int errsz)
{
    tool_vxa_loaded = 0;
    if (is_scene) return am_scene_build(lat, name, err, errsz);
    long len = 0;
    am_status st = am_port_read_file(name, tool_file_buf, TOOL_FILE_MAX, &len, err, errsz);
    if (st != AM_OK) return st;
    if (strlen(tool_file_buf) != (size_t)len)
        return am_fail(err, errsz, AM_ERR_PARSE, "%s:1: binary data (a NUL byte) in a text file", name);
    st = tool_vxa_text_to_lattice(tool_file_buf, name, lat, err, errsz);
    if (st != AM_ERR_ARG) return st;
    st = tool_genome_text_to_lattice(tool_file_buf, name, lat, err, errsz);
    if (st != AM_ERR_ARG) return st;
    return am_lattice_parse(lat, tool_file_buf, name, err, errsz);
}
