/*
** src/tools/diff/dsearch.h -- the separating scenes' search and text, for every renderer
** See LICENSE for copyright and license.
**
** A piece's signature under a hypothesis, the greedy search for the fewest
** pieces that tell the listed mistakes apart, and the scene's text, shared by
** renderer 4's candidates (dseparate.c) and renderers 7 and 9's
** (dseparate79.c); dseparate.h says what the scenes are for.
*/
#ifndef PT_DSEARCH_H
#define PT_DSEARCH_H

#include <stddef.h>
#include <stdint.h>
#include "tools/cli.h"

#define PT_SEP_TEXT 12288

/* A separating scene, or why there is none. */
typedef struct pt_sep {
    int ok;                      /* 1: text is the scene; 0: text is one sentence
                                 ** saying why there is none */
    int full;                    /* 1: the scene did not fit (text says so) */
    size_t n;                    /* bytes of text */
    char text[PT_SEP_TEXT];      /* the scene's lines, each ending in '\n' */
} pt_sep;

#define PT_SEP_MAXH 24                  /* hypotheses, the right stages (0) included */
#define PT_SEP_MAXC 24                  /* candidate pieces */
#define PT_SEP_MAXV 48                  /* values in a signature (a position's: 33) */

/* What a trace of one piece holds under one hypothesis. */
typedef struct pt_sep_sig {
    double val[PT_SEP_MAXV];            /* values, in a fixed order */
    unsigned char isint[PT_SEP_MAXV];   /* 1: compared exactly */
    size_t n;
    uint64_t px, cl;             /* renderer 4's replayed pixels and clip records */
    int has_px, has_cl;
    int fragile;                 /* 1: a colour a trace's printed digits leave
                                 ** between two bytes (renderers 7 and 9) */
} pt_sep_sig;

/* The search: every piece under every hypothesis, and what it keeps. */
typedef struct pt_sep_search {
    pt_sep_sig s[PT_SEP_MAXC][PT_SEP_MAXH];           /* s[piece][hypothesis] */
    size_t nc, nh;
    unsigned char listed[PT_SEP_MAXH];  /* 1: must be told from every other */
    unsigned char keep[PT_SEP_MAXC];    /* the pieces kept */
    size_t bad[2];               /* a pair no piece tells apart */
} pt_sep_search;

/* Append x to s's values (isint: compared exactly). */
void pt_sep_real(pt_sep_sig *s, double x, int isint);

/* 1 when a trace tells a from b (pt_sep_cover's test of a pair). */
int pt_sep_differ(const pt_sep_sig *a, const pt_sep_sig *b);

/* Keep in q->keep the fewest pieces the greedy way finds that tell every
** pair with a listed member apart.  Returns 0, or -1 with a pair no piece
** tells apart in q->bad. */
int pt_sep_cover(pt_sep_search *q);

/* printf to the scene's text (cut whole, with a sentence, when it is full). */
void pt_sep_put(pt_sep *o, const char *fmt, ...) PT_PRINTF_LIKE(2, 3);

/* A comment of the scene: "# " lines of at most 78 columns, words kept whole. */
void pt_sep_comment(pt_sep *o, const char *fmt, ...) PT_PRINTF_LIKE(2, 3);

/* A sentence instead of a scene: what, with a and b put in (two %s). */
void pt_sep_none(pt_sep *o, const char *what, const char *a, const char *b);

/* "A; B; C" of the n names, into b (len bytes); returns b. */
const char *pt_sep_names(char *b, size_t len, const char *const *names, size_t n);

#endif
