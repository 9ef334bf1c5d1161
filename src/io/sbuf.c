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

/* The code point of the well-formed UTF-8 character of n bytes at p. */
static unsigned long utf8_code(const unsigned char *p, int n)
{
    static const unsigned char lead[5] = { 0, 0x7f, 0x1f, 0x0f, 0x07 };
    unsigned long c = p[0] & lead[n];
    int k;

    for (k = 1; k < n; k++) c = (c << 6) | (p[k] & 0x3fu);
    return c;
}

/* Is c a character no XML or HTML document may hold raw?  XML 1.0 (section
** 2.2) forbids C0 controls but tab, LF and CR, and U+FFFE, U+FFFF; HTML
** (13.2.3.5) calls DEL, the C1 controls and every noncharacter (U+FDD0 ..
** U+FDEF, the last two of each plane) parse errors.  CR is refused too: a
** parser turns it into LF. */
static int markup_refused(unsigned long c)
{
    return (c < 0x20 && c != '\t' && c != '\n') || (c >= 0x7f && c <= 0x9f) ||
           (c >= 0xfdd0 && c <= 0xfdef) || (c & 0xfffeu) == 0xfffeu;
}

/* What an escaper writes for the character c that begins at p: its
** replacement, or NULL to copy it.  buf has room for one made on the spot. */
typedef const char *escaper(const unsigned char *p, unsigned long c, char buf[16]);

static const char *xml_escape(const unsigned char *p, unsigned long c, char buf[16])
{
    (void)p; (void)buf;
    switch (c) {
    case '&':  return "&amp;";
    case '<':  return "&lt;";
    case '>':  return "&gt;";
    case '"':  return "&quot;";
    case '\'': return "&apos;";
    default:   return markup_refused(c) ? REPLACEMENT : NULL;
    }
}

static const char *json_escape(const unsigned char *p, unsigned long c, char buf[16])
{
    switch (c) {
    case '"':  return "\\\"";
    case '\\': return "\\\\";
    case '\n': return "\\n";
    case '\t': return "\\t";
    case '<':                /* "</script" or "<!--" would end the element */
        return p[1] == '/' || p[1] == '!' ? "\\u003c" : "<";
    default:
        if (!markup_refused(c)) return NULL;
        if (c < 0x10000) snprintf(buf, 16, "\\u%04x", (unsigned)c);  /* the same */
        else snprintf(buf, 16, "\\u%04x\\u%04x",      /* character; a surrogate pair */
                      (unsigned)(0xd800 + ((c - 0x10000) >> 10)),
                      (unsigned)(0xdc00 + ((c - 0x10000) & 0x3ff)));
        return buf;
    }
}

/* Append t with each character escaped as esc says; a byte that does not
** begin a well-formed UTF-8 character becomes U+FFFD. */
static void add_escaped(pt_sbuf *sb, const char *t, escaper *esc)
{
    const unsigned char *p = (const unsigned char *)t;
    char buf[16];
    const char *r;
    int n;

    while (*p) {
        if ((n = pt_sbuf_utf8_len(p)) == 0) { pt_sbuf_add(sb, REPLACEMENT); p++; continue; }
        if ((r = esc(p, utf8_code(p, n), buf)) != NULL) pt_sbuf_add(sb, r);
        else pt_sbuf_addn(sb, (const char *)p, (size_t)n);
        p += n;
    }
}

void pt_sbuf_add_xml(pt_sbuf *sb, const char *t)
{
    add_escaped(sb, t, xml_escape);
}

/* 0, or the code point of the UTF-8 character of len bytes at p when a
** terminal must not get it raw (C1, bidirectional and invisible marks). */
static unsigned long term_hidden(const unsigned char *p, int len)
{
    unsigned long c = utf8_code(p, len);

    if ((c >= 0x80 && c <= 0x9f) || c == 0x200e || c == 0x200f ||
        (c >= 0x202a && c <= 0x202e) || (c >= 0x2066 && c <= 0x2069) || c == 0xfeff)
        return c;
    return 0;
}

int pt_sbuf_term_plain(const char *t, size_t n)
{
    const unsigned char *p = (const unsigned char *)t, *e = p + n;

    while (p < e) {
        int len = *p < 0x80 ? 1 : pt_sbuf_utf8_len(p);
        if (len == 0 || len > e - p) return 0;
        if (len == 1 && (*p < 0x20 || *p == 0x7f)) return 0;
        if (len > 1 && term_hidden(p, len)) return 0;
        p += len;
    }
    return 1;
}

void pt_sbuf_add_term(pt_sbuf *sb, const char *t, size_t n)
{
    const unsigned char *p = (const unsigned char *)t, *e = p + n;

    if (pt_sbuf_term_plain(t, n)) { pt_sbuf_addn(sb, t, n); return; }
    while (p < e) {
        int len = *p < 0x80 ? 1 : pt_sbuf_utf8_len(p);
        unsigned long c;

        if (len == 0 || len > e - p || (len == 1 && (*p < 0x20 || *p == 0x7f))) {
            pt_sbuf_addf(sb, "\\x%02x", *p);          /* a byte */
            p++;
        } else if (len > 1 && (c = term_hidden(p, len)) != 0) {
            pt_sbuf_addf(sb, "\\u%04lx", c);          /* a character */
            p += len;
        } else {
            if (*p == '\\') pt_sbuf_add(sb, "\\");  /* reads back */
            pt_sbuf_addn(sb, (const char *)p, (size_t)len);
            p += len;
        }
    }
}

int pt_sbuf_csv_plain(const char *t)
{
    return (*t == 0 || !strchr("=+-@\t\r", *t)) && !t[strcspn(t, ",\"\r\n")];
}

void pt_sbuf_add_csv(pt_sbuf *sb, const char *t)
{
    const char *q;

    if (pt_sbuf_csv_plain(t)) { pt_sbuf_add(sb, t); return; }
    pt_sbuf_add(sb, strchr("=+-@\t\r", *t) ? "\"'" : "\"");
    while ((q = strchr(t, '"')) != NULL) {  /* "" for each " */
        pt_sbuf_addn(sb, t, (size_t)(q - t) + 1);
        pt_sbuf_add(sb, "\"");
        t = q + 1;
    }
    pt_sbuf_add(sb, t);
    pt_sbuf_add(sb, "\"");
}

void pt_sbuf_add_csv_untrusted(pt_sbuf *sb, const char *t)
{
    pt_sbuf safe;

    if (pt_sbuf_term_plain(t, strlen(t))) { pt_sbuf_add_csv(sb, t); return; }
    pt_sbuf_init(&safe);
    pt_sbuf_add_term(&safe, t, strlen(t));
    if (safe.failed) sb->failed = 1;
    else pt_sbuf_add_csv(sb, safe.s ? safe.s : "");
    pt_sbuf_free(&safe);
}

void pt_sbuf_add_json(pt_sbuf *sb, const char *t)
{
    pt_sbuf_add(sb, "\"");
    add_escaped(sb, t, json_escape);
    pt_sbuf_add(sb, "\"");
}
