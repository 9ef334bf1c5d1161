/*
** src/io/explain_text.h -- the text appender of the explain modules
** See LICENSE for copyright and license.
**
** explain.c (renderer 4's pipelines) and explain_course.c (renderers 7 and
** 9) write their text into the caller's buffer through it: no stdio, and
** the length counts what did not fit (the buffer stays NUL-terminated).
**   pt_xt t;  pt_xt_init(&t, buf, len);  pt_xt_add(&t, "x = ");
**   pt_xt_num(&t, -1.5, 1);  -> "x = (-1.5)";  t.len is the whole length
*/
#ifndef PT_EXPLAIN_TEXT_H
#define PT_EXPLAIN_TEXT_H

#include <stddef.h>
#include <stdint.h>

/* Text being written into buf[0..cap); len counts what would have been written. */
typedef struct pt_xt {
    char *buf;
    size_t cap, len;
} pt_xt;

/* Start writing into buf (cap bytes; 0 writes nothing).  Can't fail. */
void pt_xt_init(pt_xt *t, char *buf, size_t cap);

/* Append s.  Can't fail. */
void pt_xt_add(pt_xt *t, const char *s);

/* A number as written by pt_fmt_shortest (the shortest decimal that reads
** back to x); in parentheses when paren is set and the number is negative
** ("-1 + (-1.5)").  Can't fail. */
void pt_xt_num(pt_xt *t, double x, int paren);

/* An integer, in parentheses when paren is set and it is negative.  Can't fail. */
void pt_xt_int(pt_xt *t, int64_t x, int paren);

#endif
