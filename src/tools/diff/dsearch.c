/*
** src/tools/diff/dsearch.c -- the separating scenes' search and text, for every renderer
** See LICENSE for copyright and license.
**
** Two mistakes are told apart by a piece whose signatures differ by more
** than a trace's printed digits hide.  Greedily, the piece that tells the
** most pairs apart is kept, until every pair with a listed mistake in it is;
** then each kept piece that others make redundant is dropped again.
*/
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "tools/diff/dsearch.h"

void pt_sep_real(pt_sep_sig *s, double x, int isint)
{
    if (s->n < PT_SEP_MAXV) {
        s->isint[s->n] = (unsigned char)isint;
        s->val[s->n++] = x;
    }
}

/* 1 when a trace tells a from b: an integer that differs, a double that differs
** by more than a text trace's six decimals hide, pixels that differ. */
int pt_sep_differ(const pt_sep_sig *a, const pt_sep_sig *b)
{
    size_t k;

    if (a->n != b->n) return 1;
    for (k = 0; k < a->n; k++) {
        double x = a->val[k], y = b->val[k];
        if (isnan(x) || isnan(y)) { if (isnan(x) != isnan(y)) return 1; continue; }
        if (x == y) continue;
        if (a->isint[k] || isinf(x) || isinf(y)) return 1;
        if (fabs(x - y) > 1e-5 + 1e-6 * fmax(fabs(x), fabs(y))) return 1;
    }
    if (a->has_px && b->has_px && a->px != b->px) return 1;
    if (a->has_cl && b->has_cl && a->cl != b->cl) return 1;
    return 0;
}

/* ===== the search, the same for every renderer ===== */


/* Pairs (i < j) that pieces keep[] (or piece c alone, c < nc) tell apart,
** among those with a listed member, into need (1: not told apart yet);
** returns how many are left. */
static size_t left_pairs(const pt_sep_search *q, const unsigned char *keep, unsigned char need[PT_SEP_MAXH][PT_SEP_MAXH])
{
    size_t i, j, c, left = 0;

    for (i = 0; i < q->nh; i++)
        for (j = i + 1; j < q->nh; j++) {
            need[i][j] = (unsigned char)(q->listed[i] || q->listed[j]);
            for (c = 0; need[i][j] && c < q->nc; c++)
                if (keep[c] && pt_sep_differ(&q->s[c][i], &q->s[c][j])) need[i][j] = 0;
            left += need[i][j];
        }
    return left;
}

/* Keep the fewest pieces the greedy way finds.  Returns 0, or -1 with a pair
** no piece tells apart in q->bad. */
int pt_sep_cover(pt_sep_search *q)
{
    unsigned char need[PT_SEP_MAXH][PT_SEP_MAXH], none[PT_SEP_MAXC];
    size_t i, j, c;

    memset(q->keep, 0, sizeof q->keep);
    memset(none, 0, sizeof none);
    while (left_pairs(q, q->keep, need)) {
        size_t best = q->nc, bestn = 0;
        for (c = 0; c < q->nc; c++) {
            size_t n = 0;
            if (q->keep[c]) continue;
            for (i = 0; i < q->nh; i++)
                for (j = i + 1; j < q->nh; j++)
                    n += need[i][j] && pt_sep_differ(&q->s[c][i], &q->s[c][j]);
            if (n > bestn) { bestn = n; best = c; }
        }
        if (!bestn) {
            for (i = 0; i < q->nh; i++)
                for (j = i + 1; j < q->nh; j++)
                    if (need[i][j]) { q->bad[0] = i; q->bad[1] = j; return -1; }
        }
        q->keep[best] = 1;
    }
    for (c = 0; c < q->nc; c++) {              /* drop what the others cover */
        if (!q->keep[c]) continue;
        q->keep[c] = 0;
        if (left_pairs(q, q->keep, need)) q->keep[c] = 1;
    }
    return 0;
}

/* ===== text ===== */

void pt_sep_put(pt_sep *o, const char *fmt, ...)
{
    va_list ap;
    int n;

    if (o->full) return;
    va_start(ap, fmt);
    n = vsnprintf(o->text + o->n, sizeof o->text - o->n, fmt, ap);
    va_end(ap);
    if (n > 0) o->n += (size_t)n;
    if (o->n >= sizeof o->text) {               /* cut: never half a scene */
        o->ok = 0;
        o->full = 1;
        o->n = (size_t)snprintf(o->text, sizeof o->text, "the scene would be too long.");
    }
}

/* A comment of the scene: "# " lines of at most 78 columns, words kept whole. */
void pt_sep_comment(pt_sep *o, const char *fmt, ...)
{
    char b[2048];
    const char *p = b;
    va_list ap;

    va_start(ap, fmt);
    vsnprintf(b, sizeof b, fmt, ap);
    va_end(ap);
    while (*p) {
        size_t n = strlen(p), cut = n, k;
        if (n > 76) {
            for (cut = 76; cut > 0 && p[cut] != ' '; cut--) {}
            if (!cut) for (cut = 76; p[cut] && p[cut] != ' '; cut++) {}
        }
        pt_sep_put(o, "# %.*s\n", (int)cut, p);
        for (k = cut; p[k] == ' '; k++) {}
        p += k;
    }
}

/* A sentence instead of a scene. */
void pt_sep_none(pt_sep *o, const char *what, const char *a, const char *b)
{
    o->ok = 0;
    o->n = 0;
    pt_sep_put(o, what, a, b);
}

/* "A; B; C" of the listed names, into b (len bytes). */
const char *pt_sep_names(char *b, size_t len, const char *const *names, size_t n)
{
    size_t k, m = 0;

    b[0] = '\0';
    for (k = 0; k < n && m < len; k++)
        m += (size_t)snprintf(b + m, len - m, "%s%s", k ? "; " : "", names[k]);
    return b;
}
