/*
** tests/fuzz/fuzz_trace.c -- fuzz target: the trace reader (text and JSON Lines)
** See LICENSE for copyright and license.
**
** The bytes, NUL-terminated as pt_tread_file() leaves them, go to
** pt_tread_parse() whatever they hold (images are tests/fuzz/fuzz_image.c's).
** A trace read must keep its promises: every record's line lies in the file,
** every model name id is one of the names.
*/
#include <stdlib.h>
#include <string.h>
#include "fuzz.h"
#include "io/tread.h"

/* 1 when the records of t are within the file's nlines lines and names. */
static int records_ok(const pt_tread *t, const pt_names *nm, size_t nlines)
{
    size_t k;

    for (k = 0; k < t->nvx; k++)
        if (t->vx[k].line < 1 || t->vx[k].line > nlines || t->vx[k].model >= nm->n ||
            t->vx[k].stage >= PT_NSTAGES_ALL) return 0;
    for (k = 0; k < t->npx; k++)
        if (t->px[k].line < 1 || t->px[k].line > nlines || t->px[k].model >= nm->n) return 0;
    for (k = 0; k < t->ncl; k++)
        if (t->cl[k].model >= nm->n || t->cl[k].npix > t->npx || t->cl[k].count < 1) return 0;
    for (k = 0; k < t->hdr.nmodels; k++)
        if (t->hdr.models[k].name >= nm->n) return 0;
    return 1;
}

int pt_fuzz_trace(const uint8_t *data, size_t size)
{
    pt_names nm = PT_NAMES_INIT;
    pt_tread t;
    char err[1024], *buf = malloc(size + 1);
    size_t k, nlines = 1;
    int rc;

    if (!buf) return 0;
    memcpy(buf, data, size);
    buf[size] = '\0';
    for (k = 0; k < size; k++) if (buf[k] == '\n') nlines++;
    err[0] = '\0';
    if (pt_tread_parse(&t, "fuzz", buf, size, &nm, err, sizeof err) != 0)
        rc = pt_fuzz_message_ok(err, "fuzz") && t.nvx == 0 && t.npx == 0 && t.ncl == 0 ? 1 : -1;
    else
        rc = records_ok(&t, &nm, nlines) ? 0 : -1;
    pt_tread_free(&t);
    pt_names_free(&nm);
    free(buf);
    return rc;
}

PT_FUZZ_TARGET(pt_fuzz_trace)
