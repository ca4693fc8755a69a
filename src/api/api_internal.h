/* api_internal.h: what the embedding API's files share (not public). */
#ifndef AMORPH_API_INTERNAL_H
#define AMORPH_API_INTERNAL_H

#include "amorph/api.h"

/* AM_OK when w is a workspace am_api_init prepared, else AM_ERR_ARG with the message */
static inline am_status am_api_ready(const am_api_work* w, char* err, int errsz)
{
    if (!w || w->size != (long)sizeof *w) return am_fail(err, errsz, AM_ERR_ARG, "the workspace is not prepared (am_api_init)");
    return AM_OK;
}

#endif
