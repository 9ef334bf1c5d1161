/*
** src/tools/diff/dprint.c -- pipetrace diff: numbers, wrapped paragraphs, names
** See LICENSE for copyright and license.
**
** What every part of diff prints with: the shortest decimal of a double, a
** paragraph wrapped at 78 columns (built in a pbuf first), a vertex's name.
*/
#include <inttypes.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "tools/diff/diff.h"

const char *const pt_diff_side[2] = {"EXPECTED", "ACTUAL"};

/* A double as the shortest decimal that reads back to it. */
const char *pt_diff_num(double x, char buf[PT_NUMLEN])
{
    pt_fmt_shortest(buf, x);
    return buf;
}

/* Print text as one paragraph wrapped at 78 columns, each line after `lead`. */
void pt_diff_para(const char *lead, const char *text)
{
    size_t col = 0, lead_n = strlen(lead);
    const char *p = text;

    while (*p) {
        const char *w = p;
        size_t n;
        while (*p && *p != ' ') p++;
        n = (size_t)(p - w);
        if (col && col + 1 + n > 78) { putchar('\n'); col = 0; }
        if (!col) { fputs(lead, stdout); col = lead_n; }
        else { putchar(' '); col++; }
        fwrite(w, 1, n, stdout);
        col += n;
        while (*p == ' ') p++;
    }
    if (col) putchar('\n');
}

/* Append to s what printf would print; text past its room is dropped. */
void pt_diff_add(pbuf *s, const char *fmt, ...)
{
    va_list ap;
    int k;

    if (s->n >= sizeof s->b - 1) return;
    va_start(ap, fmt);
    k = vsnprintf(s->b + s->n, sizeof s->b - s->n, fmt, ap);
    va_end(ap);
    if (k > 0) s->n += (size_t)k;
    if (s->n > sizeof s->b - 1) s->n = sizeof s->b - 1;
}

/* "box v3", or for a point where the matrix camera clipped a segment
** "box s2 (clipped end 1)", into buf. */
const char *pt_diff_who(const dctx *c, uint32_t model, uint64_t v, char *buf, size_t len)
{
    if (v & PT_TCLIPV)
        snprintf(buf, len, "%s s%" PRIu64 " (clipped end %d)", pt_names_get(&c->nm, model),
                 (v & ~PT_TCLIPV) >> 1, (int)(v & 1) + 1);
    else
        snprintf(buf, len, "%s v%" PRIu64, pt_names_get(&c->nm, model), v);
    return buf;
}

void pt_diff_no_records(pbuf *s, int side, int st)
{
    pt_diff_add(s, "%s has no %s records: the stage did not report them.", pt_diff_side[side],
                     pt_stage_infos[st].name);
}
