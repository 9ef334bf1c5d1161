/*
** src/io/tread.c -- read traces (JSON Lines or text) and images back into memory
** See LICENSE for copyright and license.
**
** One pass over the buffer, one line at a time, no allocation per line: a
** JSON line is checked in full and its top-level fields are noted as spans of
** the buffer (jfield); only the fields a record needs are then converted.
** Numbers go through strtod() only after their syntax was checked, so what
** strtod() reads is exactly the token (and buf is NUL-terminated, so it cannot
** run off the end).  pipetrace never calls setlocale(), so '.' is the point.
*/
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/tread.h"
#include "io/png.h"

#if defined(__GNUC__)
#define PRINTF_LIKE(f, a) __attribute__((format(printf, f, a)))
#else
#define PRINTF_LIKE(f, a)
#endif

/* The images pt_image_parse() reads, for messages. */
#define IMG_FORMATS "binary PPM (P6), plain PPM (P3), or PNG as pipetrace writes it"

/* ===== interned names ===== */

static uint64_t hash_bytes(const char *s, size_t n)
{
    uint64_t h = 14695981039346656037u;     /* FNV-1a */
    size_t k;

    for (k = 0; k < n; k++) { h ^= (unsigned char)s[k]; h *= 1099511628211u; }
    return h;
}

/* Rebuild the hash table with nslot slots (a power of two). */
static int names_rehash(pt_names *nm, size_t nslot)
{
    uint32_t *slot = calloc(nslot, sizeof *slot);
    size_t id;

    if (!slot) return -1;
    for (id = 0; id < nm->n; id++) {
        const char *s = nm->text + nm->off[id];
        size_t k = (size_t)hash_bytes(s, strlen(s)) & (nslot - 1);
        while (slot[k]) k = (k + 1) & (nslot - 1);
        slot[k] = (uint32_t)id + 1;
    }
    free(nm->slot);
    nm->slot = slot;
    nm->nslot = nslot;
    return 0;
}

int pt_names_intern(pt_names *nm, const char *s, size_t n, uint32_t *id)
{
    size_t k;

    if (2 * (nm->n + 1) >= nm->nslot &&
        names_rehash(nm, nm->nslot ? 2 * nm->nslot : 64) != 0) return -1;
    k = (size_t)hash_bytes(s, n) & (nm->nslot - 1);
    for (; nm->slot[k]; k = (k + 1) & (nm->nslot - 1)) {
        const char *t = nm->text + nm->off[nm->slot[k] - 1];
        if (strncmp(t, s, n) == 0 && t[n] == '\0') { *id = nm->slot[k] - 1; return 0; }
    }
    if (nm->n >= UINT32_MAX - 1) return -1;
    if (nm->len + n + 1 > nm->cap) {
        size_t cap = nm->cap ? nm->cap : 256;
        char *t;
        while (cap < nm->len + n + 1) cap *= 2;
        t = realloc(nm->text, cap);
        if (!t) return -1;
        nm->text = t;
        nm->cap = cap;
    }
    if (nm->n == nm->cap_off) {
        size_t cap = nm->cap_off ? 2 * nm->cap_off : 16;
        size_t *o = realloc(nm->off, cap * sizeof *o);
        if (!o) return -1;
        nm->off = o;
        nm->cap_off = cap;
    }
    memcpy(nm->text + nm->len, s, n);
    nm->text[nm->len + n] = '\0';
    nm->off[nm->n] = nm->len;
    nm->len += n + 1;
    nm->slot[k] = (uint32_t)nm->n + 1;
    *id = (uint32_t)nm->n++;
    return 0;
}

const char *pt_names_get(const pt_names *nm, uint32_t id)
{
    return nm->text + nm->off[id];
}

void pt_names_free(pt_names *nm)
{
    free(nm->text);
    free(nm->off);
    free(nm->slot);
    memset(nm, 0, sizeof *nm);
}

/* ===== stages ===== */

/* The place of stage st in pt_trace_order. */
static int order_pos(int st)
{
    int k;

    for (k = 0; k < PT_NSTAGES_ALL; k++) if ((int)pt_trace_order[k] == st) return k;
    return 0;
}

/* The pt_stage named p[0..n), or -1. */
static int stage_named(const char *p, size_t n)
{
    int k;

    for (k = 0; k < PT_NSTAGES_ALL; k++)
        if (strlen(pt_stage_infos[k].name) == n && memcmp(p, pt_stage_infos[k].name, n) == 0)
            return k;
    return -1;
}

/* ===== files ===== */

int pt_tread_file(const char *path, char **buf, size_t *len, char *err, size_t errlen)
{
    FILE *f = strcmp(path, "-") ? fopen(path, "rb") : stdin;
    size_t n = 0, cap = 1 << 16;
    char *b;

    *buf = NULL;
    *len = 0;
    if (!f) {
        snprintf(err, errlen, "%s:1:1: error: cannot read file: %s", path, strerror(errno));
        return -1;
    }
    b = malloc(cap);
    while (b) {
        size_t got;
        if (cap - n < 2) {                  /* room for one more byte and the NUL */
            char *nb = cap < SIZE_MAX / 2 ? realloc(b, 2 * cap) : NULL;
            if (!nb) { free(b); b = NULL; break; }
            b = nb;
            cap *= 2;
        }
        got = fread(b + n, 1, cap - n - 1, f);
        n += got;
        if (got == 0) break;
    }
    if (!b) {
        snprintf(err, errlen, "%s:1:1: error: out of memory", path);
    } else if (ferror(f)) {
        snprintf(err, errlen, "%s:1:1: error: cannot read file: read error", path);
        free(b);
        b = NULL;
    }
    if (f != stdin) fclose(f);
    if (!b) return -1;
    b[n] = '\0';
    *buf = b;
    *len = n;
    return 0;
}

pt_tkind pt_tread_kind(const char *buf, size_t len)
{
    static const char text[] = "# pipetrace trace";
    static const char csv[] = "model,v,stage,";

    static const char png[] = "\211PNG\r\n\032\n";

    if (len >= 2 && buf[0] == 'P' && buf[1] == '6') return PT_TK_PPM;
    if (len >= 2 && buf[0] == 'P' && buf[1] == '3') return PT_TK_P3;
    if (len >= sizeof png - 1 && memcmp(buf, png, sizeof png - 1) == 0) return PT_TK_PNG;
    if (len >= 1 && buf[0] == '{') return PT_TK_JSONL;
    if (len >= sizeof text - 1 && memcmp(buf, text, sizeof text - 1) == 0) return PT_TK_TEXT;
    if (len >= sizeof csv - 1 && memcmp(buf, csv, sizeof csv - 1) == 0) return PT_TK_CSV;
    return PT_TK_UNKNOWN;
}

/* ===== the reader ===== */

/* The reading position and where errors go. */
typedef struct rd {
    const char *path;            /* file name for messages */
    const char *line;            /* start of the current line */
    const char *eol;             /* its end (before "\r\n" or "\n") */
    size_t lineno;               /* its number, 1-based */
    char *err;                   /* message buffer */
    size_t errlen;
    pt_names *nm;                /* names go here */
    pt_tread *t;                 /* records go here */
    char *sbuf;                  /* a decoded JSON string; owned */
    size_t scap;                 /* room in sbuf */
    int cv_have;                 /* 1: a clip-vertex record was read: */
    uint32_t cv_model;           /*   its model, */
    uint64_t cv_seg;             /*   segment, */
    int cv_pos, cv_end;          /*   stage's place in pt_trace_order, and end */
} rd;

/* Write "FILE:LINE:COL: error: ..." for the byte `at` of the current line.
** Control bytes become '?' so that the message stays one line.  Returns -1. */
static int fail(rd *r, const char *at, const char *fmt, ...) PRINTF_LIKE(3, 4);
static int fail(rd *r, const char *at, const char *fmt, ...)
{
    va_list ap;
    int k;
    size_t n, i;
    size_t col = at && at >= r->line ? (size_t)(at - r->line) + 1 : 1;

    k = snprintf(r->err, r->errlen, "%s:%zu:%zu: error: ", r->path, r->lineno, col);
    n = k < 0 ? 0 : (size_t)k;
    if (n < r->errlen) {
        va_start(ap, fmt);
        vsnprintf(r->err + n, r->errlen - n, fmt, ap);
        va_end(ap);
    }
    for (i = 0; r->err[i]; i++)
        if ((unsigned char)r->err[i] < 0x20 || r->err[i] == 0x7f) r->err[i] = '?';
    return -1;
}

static int oom(rd *r) { return fail(r, NULL, "out of memory"); }

/* Make room for one more element in an array of `size`-byte elements. */
static int grow(rd *r, void **arr, size_t n, size_t *cap, size_t size)
{
    size_t nc;
    void *p;

    if (n < *cap) return 0;
    nc = *cap ? 2 * *cap : 1024;
    if (nc > SIZE_MAX / size) return oom(r);
    p = realloc(*arr, nc * size);
    if (!p) return oom(r);
    *arr = p;
    *cap = nc;
    return 0;
}

static uint32_t line32(const rd *r)
{
    return r->lineno > UINT32_MAX ? UINT32_MAX : (uint32_t)r->lineno;
}

static pt_tvrec *new_vrec(rd *r)
{
    pt_tread *t = r->t;
    pt_tvrec *v;

    if (grow(r, (void **)&t->vx, t->nvx, &t->cap_vx, sizeof *t->vx)) return NULL;
    v = &t->vx[t->nvx++];
    memset(v, 0, sizeof *v);
    v->line = line32(r);
    return v;
}

/* The vertex number of a clip vertex of segment seg at stage st: the records
** of its first end, then of its second, each in stage order, so a stage that
** does not come after the previous one starts the second end. */
static int clipv_number(rd *r, uint32_t model, uint64_t seg, int st, const char *at,
                        uint64_t *v)
{
    int pos = order_pos(st);

    if (seg >= (UINT64_C(1) << 62)) return fail(r, at, "segment number out of range");
    if (!r->cv_have || r->cv_model != model || r->cv_seg != seg) r->cv_end = 0;
    else if (pos <= r->cv_pos) r->cv_end++;
    if (r->cv_end > 1) return fail(r, at, "a third clipped end of one segment");
    r->cv_have = 1;
    r->cv_model = model;
    r->cv_seg = seg;
    r->cv_pos = pos;
    *v = PT_TCLIPV | seg << 1 | (uint64_t)r->cv_end;
    return 0;
}

/* ===== numbers ===== */

/* The length of the number at p (before e): -?D+(.D+)?([eE][+-]?D+)?, or 0.
** *decimals gets the count of digits after the point.  JSON forbids leading
** zeros; the text format never writes them, so both are held to that. */
static size_t num_len(const char *p, const char *e, int *decimals)
{
    const char *s = p;

    *decimals = 0;
    if (s < e && *s == '-') s++;
    if (s >= e || *s < '0' || *s > '9') return 0;
    if (*s == '0') s++;
    else while (s < e && *s >= '0' && *s <= '9') s++;
    if (s < e && *s == '.') {
        const char *d = ++s;
        while (s < e && *s >= '0' && *s <= '9') s++;
        if (s == d) return 0;
        *decimals = (int)(s - d > 99 ? 99 : s - d);
    }
    if (s < e && (*s == 'e' || *s == 'E')) {
        const char *d;
        s++;
        if (s < e && (*s == '+' || *s == '-')) s++;
        d = s;
        while (s < e && *s >= '0' && *s <= '9') s++;
        if (s == d) return 0;
    }
    return (size_t)(s - p);
}

/* 1 when p[0..n) is an integer token: no point, no exponent. */
static int is_int_token(const char *p, size_t n)
{
    size_t k;

    for (k = 0; k < n; k++) if (p[k] == '.' || p[k] == 'e' || p[k] == 'E') return 0;
    return 1;
}

/* The integer p[0..n) (already checked by num_len), or -1 when out of range. */
static int to_i64(const char *p, int64_t *out)
{
    char *end;
    long long v;

    errno = 0;
    v = strtoll(p, &end, 10);
    if (errno) return -1;
    *out = (int64_t)v;
    return 0;
}

/* 1 when p[0..n) spells s. */
static int is(const char *p, size_t n, const char *s)
{
    return strlen(s) == n && memcmp(p, s, n) == 0;
}

/* A non-finite value as the traces spell it: nan, inf, -inf.  1 when it is one. */
static int nonfinite(const char *p, size_t n, double *x)
{
    if (is(p, n, "nan")) { *x = (double)NAN; return 1; }
    if (is(p, n, "inf")) { *x = (double)INFINITY; return 1; }
    if (is(p, n, "-inf")) { *x = -(double)INFINITY; return 1; }
    return 0;
}

/* ===== JSON ===== */

enum { J_STR, J_NUM, J_TRUE, J_FALSE, J_NULL, J_ARR, J_OBJ };

/* A JSON value as a span of the buffer: for a string the text between the
** quotes (escapes not decoded), else the whole token or bracketed span. */
typedef struct jval {
    int kind;                    /* J_* */
    const char *p, *e;           /* the span */
} jval;

typedef struct jfield {
    const char *k;               /* key, between the quotes, not decoded */
    size_t kn;
    jval v;
} jfield;

#define J_MAXFIELDS 32           /* fields noted per object; more are checked only */
#define J_MAXDEPTH 32            /* nesting deeper than this is refused */

static const char *j_ws(const char *p, const char *e)
{
    while (p < e && (*p == ' ' || *p == '\t')) p++;
    return p;
}

static int hexval(char c)
{
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

/* The string starting at the quote p.  Returns the byte after its closing
** quote, or NULL after reporting the error. */
static const char *j_string(rd *r, const char *p, const char *e, jval *v)
{
    const char *s = p + 1;

    v->kind = J_STR;
    v->p = s;
    while (s < e && *s != '"') {
        unsigned char c = (unsigned char)*s;
        if (c < 0x20) { fail(r, s, "control character in a string"); return NULL; }
        if (c == '\\') {
            s++;
            if (s >= e) break;
            if (*s == 'u') {
                int k;
                for (k = 1; k <= 4; k++)
                    if (s + k >= e || hexval(s[k]) < 0) {
                        fail(r, s - 1, "bad \\u escape in a string");
                        return NULL;
                    }
                s += 4;
            } else if (!strchr("\"\\/bfnrt", *s)) {
                fail(r, s - 1, "bad escape in a string");
                return NULL;
            }
        }
        s++;
    }
    if (s >= e) { fail(r, p, "string without its closing quote"); return NULL; }
    v->e = s;
    return s + 1;
}

static const char *j_value(rd *r, const char *p, const char *e, jval *v, int depth);

/* The array or object starting at p; checks every item. */
static const char *j_nested(rd *r, const char *p, const char *e, jval *v, int depth)
{
    char close = *p == '[' ? ']' : '}';
    const char *s = j_ws(p + 1, e);
    jval item;

    v->kind = *p == '[' ? J_ARR : J_OBJ;
    v->p = p;
    if (depth > J_MAXDEPTH) { fail(r, p, "nested too deeply"); return NULL; }
    if (s < e && *s == close) { v->e = s + 1; return s + 1; }
    for (;;) {
        if (close == '}') {
            if (s >= e || *s != '"') { fail(r, s, "expected a key in quotes"); return NULL; }
            if (!(s = j_string(r, s, e, &item))) return NULL;
            s = j_ws(s, e);
            if (s >= e || *s != ':') { fail(r, s, "expected ':' after the key"); return NULL; }
            s = j_ws(s + 1, e);
        }
        if (!(s = j_value(r, s, e, &item, depth + 1))) return NULL;
        s = j_ws(s, e);
        if (s < e && *s == ',') { s = j_ws(s + 1, e); continue; }
        if (s < e && *s == close) { v->e = s + 1; return s + 1; }
        fail(r, s, "expected ',' or '%c'", close);
        return NULL;
    }
}

/* Any JSON value at p.  Returns the byte after it, or NULL after the error. */
static const char *j_value(rd *r, const char *p, const char *e, jval *v, int depth)
{
    int dec;
    size_t n;

    if (p >= e) { fail(r, p, "expected a value"); return NULL; }
    if (*p == '"') return j_string(r, p, e, v);
    if (*p == '[' || *p == '{') return j_nested(r, p, e, v, depth);
    v->p = p;
    if ((size_t)(e - p) >= 4 && memcmp(p, "true", 4) == 0) { v->kind = J_TRUE; n = 4; }
    else if ((size_t)(e - p) >= 5 && memcmp(p, "false", 5) == 0) { v->kind = J_FALSE; n = 5; }
    else if ((size_t)(e - p) >= 4 && memcmp(p, "null", 4) == 0) { v->kind = J_NULL; n = 4; }
    else if ((n = num_len(p, e, &dec)) > 0) v->kind = J_NUM;
    else { fail(r, p, "expected a value"); return NULL; }
    v->e = p + n;
    return p + n;
}

/* The object starting at the '{' p, checked in full in one pass; its first
** J_MAXFIELDS top-level fields go into f (later ones are checked only).
** Returns the byte after its '}', or NULL after reporting the error. */
static const char *j_object(rd *r, const char *p, const char *e, jfield *f, int *nf)
{
    const char *s = j_ws(p + 1, e);

    *nf = 0;
    if (s < e && *s == '}') return s + 1;
    for (;;) {
        jval key, val;
        if (s >= e || *s != '"') { fail(r, s, "expected a key in quotes"); return NULL; }
        if (!(s = j_string(r, s, e, &key))) return NULL;
        s = j_ws(s, e);
        if (s >= e || *s != ':') { fail(r, s, "expected ':' after the key"); return NULL; }
        s = j_ws(s + 1, e);
        if (!(s = j_value(r, s, e, &val, 2))) return NULL;
        if (*nf < J_MAXFIELDS) {
            f[*nf].k = key.p;
            f[*nf].kn = (size_t)(key.e - key.p);
            f[*nf].v = val;
            ++*nf;
        }
        s = j_ws(s, e);
        if (s < e && *s == ',') { s = j_ws(s + 1, e); continue; }
        if (s < e && *s == '}') return s + 1;
        fail(r, s, "expected ',' or '}'");
        return NULL;
    }
}

/* The fields of the object v (already checked). */
static int j_fields(rd *r, const jval *v, jfield *f, int *nf)
{
    return j_object(r, v->p, v->e, f, nf) ? 0 : -1;
}

/* The field named key, or NULL. */
static const jval *j_get(const jfield *f, int nf, const char *key)
{
    int k;

    for (k = 0; k < nf; k++) if (is(f[k].k, f[k].kn, key)) return &f[k].v;
    return NULL;
}

/* The next item of the array a (already checked): *pos starts at NULL.
** Returns 1 with *item, or 0 after the last. */
static int j_item(rd *r, const jval *a, const char **pos, jval *item)
{
    const char *s = *pos ? *pos : a->p + 1;

    s = j_ws(s, a->e);
    if (*s == ',') s = j_ws(s + 1, a->e);
    if (*s == ']') return 0;
    s = j_value(r, s, a->e, item, 1);
    *pos = s;
    return s != NULL;
}

/* Decode the string v into r->sbuf (NUL-terminated); *n gets its length.
** \u0000 and unpaired surrogates are refused: names hold neither. */
static int j_decode(rd *r, const jval *v, size_t *n)
{
    size_t need = (size_t)(v->e - v->p) + 1, k = 0;
    const char *s;

    if (need > r->scap) {
        char *b = realloc(r->sbuf, need);
        if (!b) return oom(r);
        r->sbuf = b;
        r->scap = need;
    }
    for (s = v->p; s < v->e; s++) {
        unsigned long c;
        if (*s != '\\') { r->sbuf[k++] = *s; continue; }
        s++;
        switch (*s) {
        case 'b': r->sbuf[k++] = '\b'; continue;
        case 'f': r->sbuf[k++] = '\f'; continue;
        case 'n': r->sbuf[k++] = '\n'; continue;
        case 'r': r->sbuf[k++] = '\r'; continue;
        case 't': r->sbuf[k++] = '\t'; continue;
        case 'u': break;
        default: r->sbuf[k++] = *s; continue;
        }
        c = (unsigned long)(hexval(s[1]) << 12 | hexval(s[2]) << 8 | hexval(s[3]) << 4 | hexval(s[4]));
        s += 4;
        if (c >= 0xD800 && c < 0xDC00 && s + 6 < v->e && s[1] == '\\' && s[2] == 'u') {
            unsigned long lo = (unsigned long)(hexval(s[3]) << 12 | hexval(s[4]) << 8 |
                                               hexval(s[5]) << 4 | hexval(s[6]));
            if (lo >= 0xDC00 && lo < 0xE000) {
                c = 0x10000 + ((c - 0xD800) << 10) + (lo - 0xDC00);
                s += 6;
            }
        }
        if (c == 0 || (c >= 0xD800 && c < 0xE000))
            return fail(r, v->p - 1, "string holds \\u%04lx, which no name holds", c);
        /* UTF-8 never takes more bytes than the 6 of the escape it replaces */
        if (c < 0x80) r->sbuf[k++] = (char)c;
        else if (c < 0x800) {
            r->sbuf[k++] = (char)(0xC0 | c >> 6);
            r->sbuf[k++] = (char)(0x80 | (c & 0x3F));
        } else if (c < 0x10000) {
            r->sbuf[k++] = (char)(0xE0 | c >> 12);
            r->sbuf[k++] = (char)(0x80 | (c >> 6 & 0x3F));
            r->sbuf[k++] = (char)(0x80 | (c & 0x3F));
        } else {
            r->sbuf[k++] = (char)(0xF0 | c >> 18);
            r->sbuf[k++] = (char)(0x80 | (c >> 12 & 0x3F));
            r->sbuf[k++] = (char)(0x80 | (c >> 6 & 0x3F));
            r->sbuf[k++] = (char)(0x80 | (c & 0x3F));
        }
    }
    r->sbuf[k] = '\0';
    *n = k;
    return 0;
}

/* ===== JSON records ===== */

/* Field `key` of a record: must be there. */
static const jval *need(rd *r, const jfield *f, int nf, const char *key, const char *what)
{
    const jval *v = j_get(f, nf, key);

    if (!v) fail(r, r->line, "%s record without \"%s\"", what, key);
    return v;
}

/* A double: a number, or "nan", "inf", "-inf". */
static int jnum(rd *r, const jval *v, double *x)
{
    if (v->kind == J_NUM) { *x = strtod(v->p, NULL); return 0; }
    if (v->kind == J_STR && nonfinite(v->p, (size_t)(v->e - v->p), x)) return 0;
    return fail(r, v->p, "expected a number");
}

/* An integer; with allow_null, null sets *isnull. */
static int jint(rd *r, const jval *v, int64_t *x, int allow_null, int *isnull)
{
    if (allow_null && v->kind == J_NULL) { *isnull = 1; *x = 0; return 0; }
    if (v->kind != J_NUM || !is_int_token(v->p, (size_t)(v->e - v->p)))
        return fail(r, v->p, "expected an integer%s", allow_null ? " or null" : "");
    if (to_i64(v->p, x) != 0) return fail(r, v->p, "integer out of range");
    if (isnull) *isnull = 0;
    return 0;
}

/* A count: an integer >= lo. */
static int jcount(rd *r, const jval *v, uint64_t lo, uint64_t *x)
{
    int64_t n;

    if (jint(r, v, &n, 0, NULL) != 0) return -1;
    if (n < 0 || (uint64_t)n < lo) return fail(r, v->p, "expected an integer >= %llu", (unsigned long long)lo);
    *x = (uint64_t)n;
    return 0;
}

/* The model name of a record (field "model"; in the header "name"): a
** string, interned. */
static int jmodel(rd *r, const jfield *f, int nf, const char *what, uint32_t *id)
{
    const jval *v = need(r, f, nf, strcmp(what, "header model") ? "model" : "name", what);
    size_t n = 0;

    if (!v) return -1;
    if (v->kind != J_STR) return fail(r, v->p, "expected the model name in quotes");
    if (j_decode(r, v, &n) != 0) return -1;
    if (pt_names_intern(r->nm, r->sbuf, n, id) != 0) return oom(r);
    return 0;
}

/* A vertex record, or with clipv a clip-vertex record (the matrix camera's
** clipped end of a segment: "segment" instead of "v"). */
static int j_vertex(rd *r, const jfield *f, int nf, int clipv)
{
    const char *what = clipv ? "clipvertex" : "vertex";
    const pt_stage_info *sh;
    const jval *v, *sv;
    pt_tvrec *rec;
    int st, k, isnull = 0, nul;
    uint32_t model;
    uint64_t vnum;

    if (jmodel(r, f, nf, what, &model) != 0) return -1;
    if (!(v = need(r, f, nf, clipv ? "segment" : "v", what)) || jcount(r, v, 1, &vnum) != 0)
        return -1;
    if (!(sv = need(r, f, nf, "stage", what))) return -1;
    st = sv->kind == J_STR ? stage_named(sv->p, (size_t)(sv->e - sv->p)) : -1;
    if (st < 0) return fail(r, sv->p, "unknown stage");
    if (clipv && clipv_number(r, model, vnum, st, sv->p, &vnum) != 0) return -1;
    if (!(rec = new_vrec(r))) return -1;
    rec->model = model;
    rec->v = vnum;
    rec->stage = (unsigned char)st;
    sh = &pt_stage_infos[st];
    for (k = 0; k < sh->nreal; k++) {
        if (!(v = need(r, f, nf, sh->key[k], what))) return -1;
        if (jnum(r, v, &rec->u.d[k]) != 0) return -1;
    }
    for (k = 0; k < sh->nint; k++) {
        if (!(v = need(r, f, nf, sh->key[k], what))) return -1;
        if (jint(r, v, &rec->u.n[k], st != PT_STAGE_CVV, &nul) != 0) return -1;
        if (k && nul != isnull) return fail(r, v->p, "one coordinate null, the other not");
        isnull = nul;
    }
    if (isnull) rec->flags |= PT_REC_NULL;
    if (st == PT_STAGE_IMAGE && (v = j_get(f, nf, "behind")) != NULL) {
        if (v->kind != J_TRUE && v->kind != J_FALSE) return fail(r, v->p, "expected true or false");
        if (v->kind == J_TRUE) rec->flags |= PT_REC_BEHIND;
    }
    if (st == PT_STAGE_VIEWPORT) {
        if (!(v = need(r, f, nf, "inside", "viewport"))) return -1;
        if (v->kind != J_TRUE && v->kind != J_FALSE) return fail(r, v->p, "expected true or false");
        if (v->kind == J_TRUE) rec->flags |= PT_REC_INSIDE;
    }
    return 0;
}

static int j_pixel(rd *r, const jfield *f, int nf)
{
    pt_tread *t = r->t;
    const jval *v;
    pt_tpix px;

    memset(&px, 0, sizeof px);
    if (jmodel(r, f, nf, "pixel", &px.model) != 0) return -1;
    if (!(v = need(r, f, nf, "segment", "pixel")) || jcount(r, v, 1, &px.seg) != 0) return -1;
    if (!(v = need(r, f, nf, "x", "pixel")) || jint(r, v, &px.x, 0, NULL) != 0) return -1;
    if (!(v = need(r, f, nf, "y", "pixel")) || jint(r, v, &px.y, 0, NULL) != 0) return -1;
    if (!(v = need(r, f, nf, "i", "pixel")) || jint(r, v, &px.i, 0, NULL) != 0) return -1;
    px.line = line32(r);
    if (grow(r, (void **)&t->px, t->npx, &t->cap_px, sizeof *t->px)) return -1;
    t->px[t->npx++] = px;
    return 0;
}

/* A pair [x,y] of integers. */
static int jpair(rd *r, const jval *v, int64_t out[2])
{
    const char *pos = NULL;
    jval item;
    int k;

    if (v->kind != J_ARR) return fail(r, v->p, "expected [x,y]");
    for (k = 0; k < 2; k++) {
        if (!j_item(r, v, &pos, &item)) return fail(r, v->p, "expected [x,y]");
        if (jint(r, &item, &out[k], 0, NULL) != 0) return -1;
    }
    if (j_item(r, v, &pos, &item)) return fail(r, item.p, "expected [x,y]");
    return 0;
}

static int j_clip(rd *r, const jfield *f, int nf)
{
    pt_tread *t = r->t;
    const jval *v;
    pt_tclip c;

    memset(&c, 0, sizeof c);
    if (jmodel(r, f, nf, "clip", &c.model) != 0) return -1;
    if (!(v = need(r, f, nf, "segment", "clip")) || jcount(r, v, 1, &c.seg) != 0) return -1;
    if (!(v = need(r, f, nf, "count", "clip")) || jcount(r, v, 1, &c.count) != 0) return -1;
    if (!(v = need(r, f, nf, "first", "clip")) || jpair(r, v, c.first) != 0) return -1;
    if (!(v = need(r, f, nf, "last", "clip")) || jpair(r, v, c.last) != 0) return -1;
    c.npix = t->npx;
    if (grow(r, (void **)&t->cl, t->ncl, &t->cap_cl, sizeof *t->cl)) return -1;
    t->cl[t->ncl++] = c;
    return 0;
}

/* An int field of a header object, 0 <= x <= 1e9. */
static int jsize(rd *r, const jfield *f, int nf, const char *key, int *x)
{
    const jval *v = need(r, f, nf, key, "header");
    int64_t n;

    if (!v || jint(r, v, &n, 0, NULL) != 0) return -1;
    if (n < 0 || n > 1000000000) return fail(r, v->p, "size out of range");
    *x = (int)n;
    return 0;
}

static int j_header(rd *r, const jfield *f, int nf)
{
    pt_thdr *h = &r->t->hdr;
    jfield g[J_MAXFIELDS];
    const jval *v;
    const char *pos = NULL;
    jval item;
    int ng;

    if (h->have) return fail(r, r->line, "a second header");
    if (!(v = need(r, f, nf, "version", "header"))) return -1;
    if (v->kind != J_NUM || !is(v->p, (size_t)(v->e - v->p), "1"))
        return fail(r, v->p, "trace format version %.*s; this pipetrace reads version 1",
                    (int)(v->e - v->p > 20 ? 20 : v->e - v->p), v->p);
    if (!(v = need(r, f, nf, "framebuffer", "header"))) return -1;
    if (v->kind != J_OBJ) return fail(r, v->p, "expected {\"w\":W,\"h\":H}");
    if (j_fields(r, v, g, &ng) || jsize(r, g, ng, "w", &h->fb_w) || jsize(r, g, ng, "h", &h->fb_h))
        return -1;
    if (!(v = need(r, f, nf, "viewport", "header"))) return -1;
    if (v->kind != J_OBJ) return fail(r, v->p, "expected {\"x\":..,\"y\":..,\"w\":..,\"h\":..}");
    if (j_fields(r, v, g, &ng) || jsize(r, g, ng, "x", &h->vp_x) || jsize(r, g, ng, "y", &h->vp_y) ||
        jsize(r, g, ng, "w", &h->vp_w) || jsize(r, g, ng, "h", &h->vp_h))
        return -1;
    if (!(v = need(r, f, nf, "camera", "header"))) return -1;
    if (v->kind == J_STR && is(v->p, (size_t)(v->e - v->p), "perspective")) h->perspective = 1;
    else if (v->kind == J_STR && is(v->p, (size_t)(v->e - v->p), "orthographic")) h->perspective = 0;
    else if (v->kind == J_STR && is(v->p, (size_t)(v->e - v->p), "lookat")) h->perspective = -1;
    else return fail(r, v->p, "expected \"perspective\", \"orthographic\" or \"lookat\"");
    if (!(v = need(r, f, nf, "models", "header"))) return -1;
    if (v->kind != J_ARR) return fail(r, v->p, "expected a list of models");
    while (j_item(r, v, &pos, &item)) {
        const jval *tr;
        const char *tpos = NULL;
        jval x;
        pt_tmodel *m;
        int k;

        if (item.kind != J_OBJ) return fail(r, item.p, "expected a model object");
        if (j_fields(r, &item, g, &ng) != 0) return -1;
        if (grow(r, (void **)&h->models, h->nmodels, &h->cap, sizeof *h->models)) return -1;
        m = &h->models[h->nmodels++];
        memset(m, 0, sizeof *m);
        if (jmodel(r, g, ng, "header model", &m->name) != 0) return -1;
        if ((tr = j_get(g, ng, "left_out")) != NULL) {  /* [{"stage":..,"why":..}, ..] */
            const char *lpos = NULL;
            jfield lf[J_MAXFIELDS];
            int nlf, st;
            if (tr->kind != J_ARR) return fail(r, tr->p, "expected a list of stages left out");
            while (j_item(r, tr, &lpos, &x)) {
                const jval *sv;
                if (x.kind != J_OBJ || j_fields(r, &x, lf, &nlf) != 0 ||
                    !(sv = j_get(lf, nlf, "stage")) || sv->kind != J_STR ||
                    (st = stage_named(sv->p, (size_t)(sv->e - sv->p))) < 0)
                    return fail(r, x.p, "expected {\"stage\":NAME,\"why\":..}");
                m->left_out |= 1u << st;
            }
            m->left_known = 1;
        }
        if (!(tr = need(r, g, ng, "translate", "header model"))) return -1;
        if (tr->kind != J_ARR) return fail(r, tr->p, "expected [x,y,z]");
        for (k = 0; k < 3; k++) {
            if (!j_item(r, tr, &tpos, &x)) return fail(r, tr->p, "expected [x,y,z]");
            if (jnum(r, &x, &m->t[k]) != 0) return -1;
        }
    }
    h->have = 1;
    return 0;
}

static int json_line(rd *r)
{
    jfield f[J_MAXFIELDS];
    const jval *type;
    const char *s = j_ws(r->line, r->eol), *end;
    int nf;
    size_t n;

    if (s == r->eol) return 0;              /* a blank line */
    if (*s != '{') return fail(r, s, "expected a JSON object");
    if (!(end = j_object(r, s, r->eol, f, &nf))) return -1;
    end = j_ws(end, r->eol);
    if (end != r->eol) return fail(r, end, "text after the object");
    if (!(type = need(r, f, nf, "type", "a"))) return -1;
    if (type->kind != J_STR) return fail(r, type->p, "expected the record type in quotes");
    n = (size_t)(type->e - type->p);
    if (is(type->p, n, "vertex")) return j_vertex(r, f, nf, 0);
    if (is(type->p, n, "clipvertex")) return j_vertex(r, f, nf, 1);
    if (is(type->p, n, "pixel")) return j_pixel(r, f, nf);
    if (is(type->p, n, "clip")) return j_clip(r, f, nf);
    if (is(type->p, n, "header")) return j_header(r, f, nf);
    if (is(type->p, n, "skip") || is(type->p, n, "summary")) return 0;
    return fail(r, type->p, "unknown record type '%.*s'", (int)(n > 40 ? 40 : n), type->p);
}

/* ===== text ===== */

/* A cursor over the current line. */
typedef struct cur {
    const char *p, *e;
} cur;

/* The next word (a run of bytes other than space and tab); 0 at the end. */
static int word(cur *c, const char **w, size_t *n)
{
    while (c->p < c->e && (*c->p == ' ' || *c->p == '\t')) c->p++;
    if (c->p >= c->e) { *w = c->e; *n = 0; return 0; }
    *w = c->p;
    while (c->p < c->e && *c->p != ' ' && *c->p != '\t') c->p++;
    *n = (size_t)(c->p - *w);
    return 1;
}

/* The next word must be s. */
static int expect(rd *r, cur *c, const char *s)
{
    const char *w;
    size_t n;

    if (!word(c, &w, &n) || !is(w, n, s)) return fail(r, w, "expected '%s'", s);
    return 0;
}

/* A real number as the text format writes it ("%.*f", "%.*e", nan, inf). */
static int text_real(rd *r, cur *c, double *x)
{
    const char *w;
    size_t n;
    int dec;

    if (!word(c, &w, &n)) return fail(r, w, "expected a number");
    if (nonfinite(w, n, x)) return 0;
    if (num_len(w, w + n, &dec) != n) return fail(r, w, "expected a number");
    if (dec < r->t->prec) r->t->prec = dec;
    *x = strtod(w, NULL);
    return 0;
}

/* An integer word; with allow_none, "none" sets *isnull. */
static int text_int(rd *r, cur *c, int64_t *x, int allow_none, int *isnull)
{
    const char *w;
    size_t n;
    int dec;

    if (!word(c, &w, &n)) return fail(r, w, "expected an integer");
    if (allow_none && is(w, n, "none")) { *isnull = 1; *x = 0; return 0; }
    if (num_len(w, w + n, &dec) != n || !is_int_token(w, n))
        return fail(r, w, "expected an integer%s", allow_none ? " or 'none'" : "");
    if (to_i64(w, x) != 0) return fail(r, w, "integer out of range");
    if (isnull) *isnull = 0;
    return 0;
}

/* A count in text: a non-negative integer >= lo. */
static int text_count(rd *r, const char *w, size_t n, uint64_t lo, uint64_t *x)
{
    int64_t v;
    int dec;

    if (n == 0 || num_len(w, w + n, &dec) != n || !is_int_token(w, n) || *w == '-' ||
        to_i64(w, &v) != 0 || (uint64_t)v < lo)
        return fail(r, w, "expected a number >= %llu", (unsigned long long)lo);
    *x = (uint64_t)v;
    return 0;
}

/* "NAME vN  STAGE  x_.. = X  y_.. = Y ...", or for a clip vertex "NAME sN
** STAGE ...": c is past the "vN" or "sN" word, sw[0..sn) the stage word. */
static int t_vertex(rd *r, cur *c, uint32_t model, uint64_t vnum, int clipv,
                    const char *sw, size_t sn)
{
    const pt_stage_info *sh;
    pt_tvrec *rec;
    const char *w;
    size_t n;
    int st = stage_named(sw, sn), k, isnull = 0, nul;

    if (st < 0) return fail(r, sw, "unknown stage '%.*s'", (int)(sn > 40 ? 40 : sn), sw);
    if (clipv && clipv_number(r, model, vnum, st, sw, &vnum) != 0) return -1;
    if (!(rec = new_vrec(r))) return -1;
    rec->model = model;
    rec->v = vnum;
    rec->stage = (unsigned char)st;
    sh = &pt_stage_infos[st];
    for (k = 0; k < sh->nreal + sh->nint; k++) {
        if (expect(r, c, sh->coord[k]) || expect(r, c, "=")) return -1;
        if (sh->nreal) {
            if (text_real(r, c, &rec->u.d[k]) != 0) return -1;
        } else {
            if (text_int(r, c, &rec->u.n[k], st != PT_STAGE_CVV, &nul) != 0) return -1;
            if (k && nul != isnull) return fail(r, c->p, "one coordinate none, the other not");
            isnull = nul;
        }
    }
    if (isnull) rec->flags |= PT_REC_NULL;
    while (word(c, &w, &n)) {               /* flags; then notes and warnings */
        if (is(w, n, "!") || w[0] == '(') break;
        if (st == PT_STAGE_IMAGE && is(w, n, "behind")) {
            if (expect(r, c, "the") || expect(r, c, "camera")) return -1;
            rec->flags |= PT_REC_BEHIND;
        } else if (st == PT_STAGE_VIEWPORT && is(w, n, "inside")) {
            rec->flags |= PT_REC_INSIDE;
        } else if (st == PT_STAGE_VIEWPORT && is(w, n, "outside")) {
            ;
        } else {
            return fail(r, w, "unexpected '%.*s'", (int)(n > 40 ? 40 : n), w);
        }
    }
    return 0;
}

/* "NAME sN  pixel  x_fb = X  y_fb = Y  idx = I" */
static int t_pixel(rd *r, cur *c, uint32_t model, uint64_t seg)
{
    pt_tread *t = r->t;
    pt_tpix px;
    const char *w;
    size_t n;

    memset(&px, 0, sizeof px);
    px.model = model;
    px.seg = seg;
    px.line = line32(r);
    if (expect(r, c, "x_fb") || expect(r, c, "=") || text_int(r, c, &px.x, 0, NULL) ||
        expect(r, c, "y_fb") || expect(r, c, "=") || text_int(r, c, &px.y, 0, NULL) ||
        expect(r, c, "idx") || expect(r, c, "=") || text_int(r, c, &px.i, 0, NULL))
        return -1;
    if (word(c, &w, &n)) return fail(r, w, "unexpected text after the pixel");
    if (grow(r, (void **)&t->px, t->npx, &t->cap_px, sizeof *t->px)) return -1;
    t->px[t->npx++] = px;
    return 0;
}

/* "NAME sN  clipped  4 steps, (x_vp, y_vp) from (-4, 2) to (-1, 2)" or
** "1 step at (x_vp, y_vp) = (-4, 2)": the count, then the integers after
** "(x_vp, y_vp)". */
static int t_clip(rd *r, cur *c, uint32_t model, uint64_t seg)
{
    pt_tread *t = r->t;
    pt_tclip cl;
    int64_t v[4];
    const char *w, *s;
    size_t n;
    int k = 0, want;

    memset(&cl, 0, sizeof cl);
    cl.model = model;
    cl.seg = seg;
    cl.npix = t->npx;
    if (!word(c, &w, &n) || text_count(r, w, n, 1, &cl.count) != 0) return -1;
    want = cl.count == 1 ? 2 : 4;
    s = c->p;
    while (s < c->e && *s != ')') s++;      /* past "(x_vp, y_vp)" */
    if (s >= c->e) return fail(r, c->p, "expected '(x_vp, y_vp)'");
    for (s++; s < c->e; ) {
        int dec;
        size_t len;
        if (*s != '-' && (*s < '0' || *s > '9')) { s++; continue; }
        len = num_len(s, c->e, &dec);
        if (len == 0 || k == want || !is_int_token(s, len) || to_i64(s, &v[k]) != 0)
            return fail(r, s, "expected %d integers in the clip record", want);
        k++;
        s += len;
    }
    if (k != want) return fail(r, c->p, "expected %d integers in the clip record", want);
    cl.first[0] = v[0]; cl.first[1] = v[1];
    cl.last[0] = v[want - 2]; cl.last[1] = v[want - 1];
    if (grow(r, (void **)&t->cl, t->ncl, &t->cap_cl, sizeof *t->cl)) return -1;
    t->cl[t->ncl++] = cl;
    return 0;
}

/* A record line: "NAME vN STAGE ..." or "NAME sN pixel|clipped|skipped ...". */
static int text_record(rd *r)
{
    cur c = {r->line, r->eol};
    const char *name, *id, *kind;
    size_t nn, ni, nk;
    uint64_t num;
    uint32_t model;

    if (!word(&c, &name, &nn)) return 0;
    if (!word(&c, &id, &ni) || ni < 2 || (id[0] != 'v' && id[0] != 's'))
        return fail(r, id, "expected 'vN' or 'sN' after the model name");
    if (text_count(r, id + 1, ni - 1, 1, &num) != 0) return -1;
    if (!word(&c, &kind, &nk)) return fail(r, kind, "expected a stage or record kind");
    if (pt_names_intern(r->nm, name, nn, &model) != 0) return oom(r);
    if (id[0] == 'v') return t_vertex(r, &c, model, num, 0, kind, nk);
    if (is(kind, nk, "pixel")) return t_pixel(r, &c, model, num);
    if (is(kind, nk, "clipped")) return t_clip(r, &c, model, num);
    if (is(kind, nk, "skipped")) return 0;
    if (stage_named(kind, nk) >= 0) return t_vertex(r, &c, model, num, 1, kind, nk);
    return fail(r, kind, "unknown record '%.*s'", (int)(nk > 40 ? 40 : nk), kind);
}

/* 1 when the line starts with s. */
static int starts(const rd *r, const char *s)
{
    size_t n = strlen(s);
    return (size_t)(r->eol - r->line) >= n && memcmp(r->line, s, n) == 0;
}

/* "framebuffer  W x H, ..." and "viewport     w x h at (x_ul, y_ul) = (x, y)" */
static int t_size(rd *r, cur *c, int *w, int *h)
{
    int64_t a, b;
    const char *s;
    size_t n;

    if (text_int(r, c, &a, 0, NULL) || expect(r, c, "x")) return -1;
    s = c->p;
    while (s < c->e && *s == ' ') s++;
    n = 0;
    while (s + n < c->e && s[n] >= '0' && s[n] <= '9') n++;
    if (n == 0 || n > 10) return fail(r, s, "expected a size");
    b = strtoll(s, NULL, 10);
    c->p = s + n;
    if (a < 0 || a > 1000000000 || b > 1000000000) return fail(r, s, "size out of range");
    *w = (int)a;
    *h = (int)b;
    return 0;
}

static int text_header_line(rd *r)
{
    pt_thdr *h = &r->t->hdr;
    cur c = {r->line, r->eol};
    const char *w;
    size_t n;

    word(&c, &w, &n);
    if (starts(r, "  left out ")) {         /* "  left out   STAGE: why", of the last model */
        int st;
        if (!word(&c, &w, &n) || !word(&c, &w, &n) || n < 2 || w[n - 1] != ':' ||
            (st = stage_named(w, n - 1)) < 0)
            return fail(r, w, "expected 'left out   STAGE: why'");
        if (!h->nmodels) return fail(r, r->line, "'left out' before any 'model' line");
        h->models[h->nmodels - 1].left_out |= 1u << st;
        return 0;
    }
    if (starts(r, "scene ") || starts(r, "obj placed ") || starts(r, "  ") ||
        starts(r, "projection ") || starts(r, "view ")) return 0;  /* nothing diff needs */
    if (is(w, n, "framebuffer")) return t_size(r, &c, &h->fb_w, &h->fb_h);
    if (is(w, n, "viewport")) {
        const char *s;
        char *end;
        long long x, y;

        if (t_size(r, &c, &h->vp_w, &h->vp_h) != 0) return -1;
        for (s = c.p; s < c.e && *s != '='; s++) ;
        while (s < c.e && (*s == '=' || *s == ' ' || *s == '(')) s++;
        x = strtoll(s, &end, 10);           /* buf is NUL-terminated */
        if (end == s || end >= c.e || *end != ',') return fail(r, s, "expected (x_ul, y_ul)");
        s = end + 1;
        y = strtoll(s, &end, 10);
        if (end == s || end >= c.e || *end != ')' || x < 0 || y < 0 ||
            x > 1000000000 || y > 1000000000)
            return fail(r, s, "expected (x_ul, y_ul)");
        h->vp_x = (int)x;
        h->vp_y = (int)y;
        return 0;
    }
    if (is(w, n, "camera")) {
        if (!word(&c, &w, &n)) return fail(r, w, "expected the camera");
        if (is(w, n, "perspective")) h->perspective = 1;
        else if (is(w, n, "orthographic")) h->perspective = 0;
        else if (is(w, n, "lookat")) h->perspective = -1;
        else return fail(r, w, "expected 'perspective', 'orthographic' or 'lookat'");
        return 0;
    }
    if (is(w, n, "model")) {
        pt_tmodel *m;
        const char *name;
        int k;

        if (!word(&c, &name, &n) || n < 2 || name[n - 1] != ':')
            return fail(r, name, "expected 'NAME:' after 'model'");
        if (grow(r, (void **)&h->models, h->nmodels, &h->cap, sizeof *h->models)) return -1;
        m = &h->models[h->nmodels++];
        memset(m, 0, sizeof *m);
        m->left_known = 1;                  /* its "left out" lines follow */
        if (pt_names_intern(r->nm, name, n - 1, &m->name) != 0) return oom(r);
        while (word(&c, &w, &n) && !is(w, n, "translate")) ;
        if (n == 0) return fail(r, w, "expected 'translate X Y Z'");
        for (k = 0; k < 3; k++) {
            int dec;
            size_t len;
            if (!word(&c, &w, &n)) return fail(r, w, "expected 'translate X Y Z'");
            if (k == 2 && n > 0 && w[n - 1] == ',') n--;
            len = num_len(w, w + n, &dec);
            if (!nonfinite(w, n, &m->t[k])) {
                if (len != n) return fail(r, w, "expected a number");
                m->t[k] = strtod(w, NULL);
            }
        }
        return 0;
    }
    return fail(r, w, "unknown header line");
}

/* ===== the trace ===== */

int pt_tread_parse(pt_tread *t, const char *path, const char *buf, size_t len,
                   pt_names *nm, char *err, size_t errlen)
{
    rd r;
    const char *p = buf, *end = buf + len;
    enum { HEADER, RECORDS, SUMMARY, END } state = HEADER;
    int rc = 0;

    memset(t, 0, sizeof *t);
    memset(&r, 0, sizeof r);
    t->kind = pt_tread_kind(buf, len);
    t->prec = t->kind == PT_TK_TEXT ? 17 : -1;
    r.path = path;
    r.err = err;
    r.errlen = errlen;
    r.nm = nm;
    r.t = t;
    r.line = buf;
    r.lineno = 1;
    if (t->kind != PT_TK_JSONL && t->kind != PT_TK_TEXT) {
        r.eol = buf;
        rc = fail(&r, buf, "not a pipetrace trace (JSON Lines or text) nor an image "
                  "(" IMG_FORMATS ")");
    }
    while (rc == 0 && p < end) {
        const char *nl = memchr(p, '\n', (size_t)(end - p));
        r.line = p;
        r.eol = nl ? nl : end;
        if (r.eol > p && r.eol[-1] == '\r') r.eol--;
        if (memchr(p, '\0', (size_t)(r.eol - p)) != NULL)
            rc = fail(&r, memchr(p, '\0', (size_t)(r.eol - p)), "NUL byte in a trace");
        else if (t->kind == PT_TK_JSONL)
            rc = json_line(&r);
        else if (r.lineno == 1) {
            if (!starts(&r, "# pipetrace trace, format version 1") ||
                r.eol - p != (ptrdiff_t)strlen("# pipetrace trace, format version 1"))
                rc = fail(&r, p + 18, "trace format version other than 1");
            t->hdr.have = 1;
        } else if (r.eol == p) {
            if (state == HEADER) state = RECORDS;   /* the blank line after the header */
        } else if (state == HEADER) {
            rc = text_header_line(&r);
        } else if (starts(&r, "summary") && r.eol - p == 7) {
            state = SUMMARY;
        } else if (state == SUMMARY && starts(&r, "  rasterized ")) {
            state = END;                    /* the summary's last line */
        } else if (state == RECORDS && *p != ' ') {
            rc = text_record(&r);
        }                                   /* else: summary lines, --explain lines */
        p = nl ? nl + 1 : end;
        r.lineno++;
    }
    if (rc == 0 && t->kind == PT_TK_TEXT && state != END) {  /* a text trace ends with */
        r.lineno--;                                          /* its summary: cut short */
        rc = fail(&r, r.eol, "the trace ends %s: it was cut short (a text trace ends "
                  "with its summary)", state == HEADER ? "inside its header"
                  : state == RECORDS ? "before its summary" : "inside its summary");
    }
    free(r.sbuf);
    if (rc != 0) {
        pt_tread_free(t);
        return -1;
    }
    return 0;
}

void pt_tread_free(pt_tread *t)
{
    free(t->vx);
    free(t->px);
    free(t->cl);
    free(t->hdr.models);
    memset(t, 0, sizeof *t);
}

/* ===== images ===== */

/* Write "FILE:1:1: error: ..." to err; returns -1. */
static int img_fail(char *err, size_t errlen, const char *path, const char *fmt, ...)
    PRINTF_LIKE(4, 5);
static int img_fail(char *err, size_t errlen, const char *path, const char *fmt, ...)
{
    va_list ap;
    int k = snprintf(err, errlen, "%s:1:1: error: ", path);
    size_t n = k < 0 ? 0 : (size_t)k;

    if (n < errlen) {
        va_start(ap, fmt);
        vsnprintf(err + n, errlen - n, fmt, ap);
        va_end(ap);
    }
    return -1;
}

/* Skip whitespace and '#' comments in a PPM header. */
static size_t ppm_ws(const char *b, size_t k, size_t len)
{
    while (k < len) {
        if (b[k] == '#') while (k < len && b[k] != '\n') k++;
        else if (b[k] == ' ' || b[k] == '\t' || b[k] == '\n' || b[k] == '\r') k++;
        else break;
    }
    return k;
}

/* A decimal number of a PPM header at b[*k], at most 65535. */
static int ppm_num(const char *b, size_t *k, size_t len, int *out)
{
    long v = 0;
    size_t s = *k = ppm_ws(b, *k, len);

    while (*k < len && b[*k] >= '0' && b[*k] <= '9' && v <= 65535) v = v * 10 + (b[(*k)++] - '0');
    if (*k == s || v > 65535 || (*k < len && b[*k] >= '0' && b[*k] <= '9')) return -1;
    *out = (int)v;
    return 0;
}

/* "P6 W H MAXVAL" or "P3 ...": the header of either PPM, up to the pixels. */
static int ppm_header(pt_ppm *img, const char *path, const char *buf, size_t len, size_t *k,
                      char *err, size_t errlen)
{
    *k = 2;
    if (ppm_num(buf, k, len, &img->w) || ppm_num(buf, k, len, &img->h) ||
        ppm_num(buf, k, len, &img->maxval) || img->w < 1 || img->h < 1 ||
        img->maxval < 1 || img->maxval > 255 || *k >= len ||
        (buf[*k] != ' ' && buf[*k] != '\t' && buf[*k] != '\n' && buf[*k] != '\r'))
        return img_fail(err, errlen, path, "bad %s header: expected '%s W H MAXVAL' with "
                        "sizes 1..65535 and MAXVAL 1..255", img->format, img->format);
    ++*k;                                   /* the one whitespace byte */
    return 0;
}

static int p6_parse(pt_ppm *img, const char *path, const char *buf, size_t len,
                    char *err, size_t errlen)
{
    size_t k;

    if (ppm_header(img, path, buf, len, &k, err, errlen) != 0) return -1;
    if ((len - k) / 3 / (size_t)img->w < (size_t)img->h)
        return img_fail(err, errlen, path, "the image is cut short: %d x %d pixels need "
                        "%zu bytes, the file has %zu", img->w, img->h,
                        3 * (size_t)img->w * (size_t)img->h, len - k);
    img->rgb = (const unsigned char *)buf + k;
    return 0;
}

/* Plain PPM: the samples as decimal numbers separated by whitespace. */
static int p3_parse(pt_ppm *img, const char *path, const char *buf, size_t len,
                    char *err, size_t errlen)
{
    size_t k, i, n;
    int v;

    if (ppm_header(img, path, buf, len, &k, err, errlen) != 0) return -1;
    n = 3 * (size_t)img->w * (size_t)img->h;
    if (n > (len - k + 1) / 2)              /* each sample takes a digit and a space */
        return img_fail(err, errlen, path, "%zu samples cannot fit in the %zu bytes "
                        "left: the image is cut short", n, len - k);
    if (!(img->owned = malloc(n))) return img_fail(err, errlen, path, "out of memory");
    for (i = 0; i < n; i++) {
        if (ppm_num(buf, &k, len, &v) != 0 || v > img->maxval) {
            pt_image_free(img);
            return img_fail(err, errlen, path, "sample %zu of %zu: expected a number "
                            "0..%d%s", i + 1, n, img->maxval,
                            ppm_ws(buf, k, len) >= len ? " (the image is cut short)" : "");
        }
        img->owned[i] = (unsigned char)v;
    }
    img->rgb = img->owned;
    return 0;
}

static uint32_t rd32(const unsigned char *p)
{
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

/* The Paeth predictor of the PNG specification, section 9.4. */
static int paeth(int a, int b, int c)
{
    int p = a + b - c, pa = abs(p - a), pb = abs(p - b), pc = abs(p - c);

    return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

/* Undo each row's filter in place (raw: h rows of 1 + 3w bytes) into rgb. */
static int png_unfilter(const unsigned char *raw, unsigned char *rgb, int w, int h)
{
    size_t stride = 3 * (size_t)w, x;
    int y;

    for (y = 0; y < h; y++) {
        const unsigned char *in = raw + (size_t)y * (stride + 1);
        unsigned char *out = rgb + (size_t)y * stride;
        const unsigned char *up = y ? out - stride : NULL;
        int f = in[0];

        if (f > 4) return -1;
        for (x = 0; x < stride; x++) {
            int a = x >= 3 ? out[x - 3] : 0, b = up ? up[x] : 0, c = up && x >= 3 ? up[x - 3] : 0;
            int pred = f == 1 ? a : f == 2 ? b : f == 3 ? (a + b) / 2 : f == 4 ? paeth(a, b, c) : 0;
            out[x] = (unsigned char)(in[1 + x] + pred);
        }
    }
    return 0;
}

/* A PNG as png.h describes what pipetrace writes; stored deflate blocks only
** (a compressed stream is refused: decoding Huffman codes is not worth its
** size here), every filter type. */
static int png_parse(pt_ppm *img, const char *path, const char *buf, size_t len,
                     char *err, size_t errlen)
{
    const unsigned char *b = (const unsigned char *)buf;
    unsigned char *z = NULL, *raw = NULL;
    size_t k = 8, nz = 0, nraw = 0, want = 0, zk;
    int have_ihdr = 0, ended = 0;
    const char *why = NULL;

    img->maxval = 255;
    while (!why && !ended) {                /* the chunks; IDAT data gathered in z */
        uint32_t n;
        const unsigned char *type, *data;

        if (len - k < 12) { why = "the file is cut short (no IEND chunk)"; break; }
        n = rd32(b + k);
        type = b + k + 4;
        data = b + k + 8;
        if (n > len - k - 12) { why = "a chunk runs past the end of the file"; break; }
        if (pt_crc32(pt_crc32(0, type, 4), data, n) != rd32(data + n)) {
            why = "a chunk's CRC does not match: the file is damaged";
            break;
        }
        if (!memcmp(type, "IHDR", 4)) {
            if (n != 13) { why = "bad IHDR chunk"; break; }
            if (rd32(data) < 1 || rd32(data) > 65535 || rd32(data + 4) < 1 ||
                rd32(data + 4) > 65535) { why = "sizes outside 1..65535"; break; }
            img->w = (int)rd32(data);
            img->h = (int)rd32(data + 4);
            if (data[8] != 8 || data[9] != 2 || data[10] != 0 || data[11] != 0 || data[12] != 0)
                why = "not 8-bit RGB without interlace, as pipetrace writes it";
            want = (1 + 3 * (size_t)img->w) * (size_t)img->h;
            have_ihdr = 1;
        } else if (!memcmp(type, "IDAT", 4)) {
            unsigned char *nzb;
            if (!have_ihdr) { why = "IDAT before IHDR"; break; }
            if (!(nzb = realloc(z, nz + n + 1))) { why = "out of memory"; break; }
            z = nzb;
            memcpy(z + nz, data, n);
            nz += n;
        } else if (!memcmp(type, "IEND", 4)) {
            ended = 1;
        } else if (!(type[0] & 0x20)) {
            why = "a critical chunk other than IHDR, IDAT, IEND";
        }
        k += 12 + (size_t)n;
    }
    if (!why && !have_ihdr) why = "no IHDR chunk";
    if (!why && want > nz) why = "the image data is cut short";  /* stored: raw <= nz */
    if (!why && !(raw = malloc(want))) why = "out of memory";
    /* the zlib stream: CMF FLG, then stored blocks BFINAL|BTYPE, LEN, NLEN, bytes */
    if (!why && (nz < 2 || (z[0] & 0x0f) != 8 || (z[0] << 8 | z[1]) % 31 != 0 || (z[1] & 0x20)))
        why = "bad zlib header in IDAT";
    for (zk = 2; !why; ) {
        unsigned blen;
        int final;
        if (nz - zk < 5) { why = "the image data is cut short"; break; }
        if ((z[zk] >> 1 & 3) != 0) {
            why = "its image data is compressed; pipetrace diff reads only the uncompressed "
                  "PNG that pipetrace writes (convert the image to P6 PPM, e.g. "
                  "'pngtopnm A.png > A.ppm')";
            break;
        }
        final = z[zk] & 1;
        blen = (unsigned)z[zk + 1] | (unsigned)z[zk + 2] << 8;
        if ((blen ^ ((unsigned)z[zk + 3] | (unsigned)z[zk + 4] << 8)) != 0xffffu) {
            why = "bad stored block in the image data (LEN and NLEN disagree)";
            break;
        }
        zk += 5;
        if (blen > nz - zk || blen > want - nraw) {
            why = blen > nz - zk ? "the image data is cut short"
                                 : "more image data than the size needs";
            break;
        }
        memcpy(raw + nraw, z + zk, blen);
        nraw += blen;
        zk += blen;
        if (final) break;
    }
    if (!why && nraw != want) why = "the image data is cut short";
    if (!why && (nz - zk < 4 || rd32(z + zk) != pt_adler32(1, raw, nraw)))
        why = "the image data's Adler-32 does not match: the file is damaged";
    if (!why && !(img->owned = malloc(3 * (size_t)img->w * (size_t)img->h))) why = "out of memory";
    if (!why && png_unfilter(raw, img->owned, img->w, img->h) != 0) why = "unknown row filter";
    free(z);
    free(raw);
    if (why) {
        pt_image_free(img);
        return img_fail(err, errlen, path, "PNG: %s", why);
    }
    img->rgb = img->owned;
    return 0;
}

int pt_image_parse(pt_ppm *img, const char *path, const char *buf, size_t len,
                   char *err, size_t errlen)
{
    pt_tkind kind = pt_tread_kind(buf, len);

    memset(img, 0, sizeof *img);
    img->format = kind == PT_TK_PNG ? "PNG" : kind == PT_TK_P3 ? "P3" : "P6";
    if (kind == PT_TK_PPM) return p6_parse(img, path, buf, len, err, errlen);
    if (kind == PT_TK_P3) return p3_parse(img, path, buf, len, err, errlen);
    if (kind == PT_TK_PNG) return png_parse(img, path, buf, len, err, errlen);
    return img_fail(err, errlen, path, "not an image pipetrace diff reads: "
                    "%s", IMG_FORMATS);
}

void pt_image_free(pt_ppm *img)
{
    free(img->owned);
    img->owned = NULL;
    img->rgb = NULL;
}
