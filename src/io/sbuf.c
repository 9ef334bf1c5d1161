/*
** src/io/sbuf.c -- a growing text buffer, with XML and JSON escaping
** See LICENSE for copyright and license.
*/
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/sbuf.h"

void pt_sbuf_init(pt_sbuf *sb)
{
    sb->s = NULL;
    sb->len = sb->cap = 0;
    sb->failed = 0;
}

void pt_sbuf_free(pt_sbuf *sb)
{
    free(sb->s);
    pt_sbuf_init(sb);
}

/* Make room for n more bytes and the NUL.  Returns 0, or -1 (failed set). */
static int grow(pt_sbuf *sb, size_t n)
{
    size_t want, cap;
    char *p;

    if (sb->failed) return -1;
    if (n >= (size_t)-1 / 2 - sb->len) { sb->failed = 1; return -1; }
    want = sb->len + n + 1;
    if (want <= sb->cap) return 0;
    cap = sb->cap ? sb->cap : 256;
    while (cap < want) cap *= 2;
    p = realloc(sb->s, cap);
    if (!p) { sb->failed = 1; return -1; }
    sb->s = p;
    sb->cap = cap;
    return 0;
}

void pt_sbuf_addn(pt_sbuf *sb, const char *t, size_t n)
{
    if (grow(sb, n) != 0) return;
    memcpy(sb->s + sb->len, t, n);
    sb->len += n;
    sb->s[sb->len] = '\0';
}

void pt_sbuf_add(pt_sbuf *sb, const char *t)
{
    pt_sbuf_addn(sb, t, strlen(t));
}

void pt_sbuf_addf(pt_sbuf *sb, const char *fmt, ...)
{
    va_list ap;
    char small[256];
    int n;

    va_start(ap, fmt);
    n = vsnprintf(small, sizeof small, fmt, ap);
    va_end(ap);
    if (n < 0) { sb->failed = 1; return; }
    if ((size_t)n < sizeof small) { pt_sbuf_addn(sb, small, (size_t)n); return; }
    if (grow(sb, (size_t)n) != 0) return;
    va_start(ap, fmt);
    vsnprintf(sb->s + sb->len, (size_t)n + 1, fmt, ap);
    va_end(ap);
    sb->len += (size_t)n;
}

int pt_sbuf_utf8_len(const unsigned char *p)
{
    int n, k;
    unsigned long c;

    if (*p < 0x80) return 1;
    if (*p >= 0xc2 && *p <= 0xdf) { n = 2; c = *p & 0x1fu; }
    else if (*p >= 0xe0 && *p <= 0xef) { n = 3; c = *p & 0x0fu; }
    else if (*p >= 0xf0 && *p <= 0xf4) { n = 4; c = *p & 0x07u; }
    else return 0;
    for (k = 1; k < n; k++) {
        if ((p[k] & 0xc0u) != 0x80u) return 0;
        c = (c << 6) | (p[k] & 0x3fu);
    }
    if ((n == 3 && (c < 0x800 || (c >= 0xd800 && c <= 0xdfff))) ||
        (n == 4 && (c < 0x10000 || c > 0x10ffff))) return 0;
    return n;
}

#define REPLACEMENT "\xef\xbf\xbd"    /* U+FFFD in UTF-8 */

/* Append the UTF-8 character at *pp (or U+FFFD for a bad byte); advance. */
static void add_utf8(pt_sbuf *sb, const unsigned char **pp)
{
    int n = pt_sbuf_utf8_len(*pp);

    if (n == 0) { pt_sbuf_add(sb, REPLACEMENT); *pp += 1; return; }
    pt_sbuf_addn(sb, (const char *)*pp, (size_t)n);
    *pp += n;
}

void pt_sbuf_add_xml(pt_sbuf *sb, const char *t)
{
    const unsigned char *p = (const unsigned char *)t;

    while (*p) {
        switch (*p) {
        case '&':  pt_sbuf_add(sb, "&amp;"); break;
        case '<':  pt_sbuf_add(sb, "&lt;"); break;
        case '>':  pt_sbuf_add(sb, "&gt;"); break;
        case '"':  pt_sbuf_add(sb, "&quot;"); break;
        case '\'': pt_sbuf_add(sb, "&apos;"); break;
        default:
            if (*p < 0x20 && *p != '\t' && *p != '\n') pt_sbuf_add(sb, REPLACEMENT);
            else { add_utf8(sb, &p); continue; }
        }
        p++;
    }
}

void pt_sbuf_add_json(pt_sbuf *sb, const char *t)
{
    const unsigned char *p = (const unsigned char *)t;

    pt_sbuf_add(sb, "\"");
    while (*p) {
        switch (*p) {
        case '"':  pt_sbuf_add(sb, "\\\""); break;
        case '\\': pt_sbuf_add(sb, "\\\\"); break;
        case '\n': pt_sbuf_add(sb, "\\n"); break;
        case '\t': pt_sbuf_add(sb, "\\t"); break;
        case '<':                /* "</script" or "<!--" would end the element */
            if (p[1] == '/' || p[1] == '!') pt_sbuf_add(sb, "\\u003c");
            else pt_sbuf_add(sb, "<");
            break;
        default:
            if (*p < 0x20) pt_sbuf_addf(sb, "\\u%04x", (unsigned)*p);
            else { add_utf8(sb, &p); continue; }
        }
        p++;
    }
    pt_sbuf_add(sb, "\"");
}
