/*
** src/io/tread.c -- read traces back: names, files, and the dispatch by content
** See LICENSE for copyright and license.
**
** The public reader API: the interned model names, reading the file,
** telling the formats apart by their first bytes, and pt_tread_parse(),
** which splits the buffer into lines and hands each to the reader of its
** format (tread_jsonl.c, tread_text.c; the course's log whole to
** tread_kraft.c).  What the readers share, the reader's records and errors,
** stage names and number tokens, is in tread_util.c (io/tread_int.h).
** Images are read in tread_image.c.  One pass over the buffer, one line at
** a time, no allocation per line.  Numbers go through strtod() only after
** their syntax was checked, so what strtod() reads is exactly the token (and
** buf is NUL-terminated, so it cannot run off the end).  pipetrace never
** calls setlocale(), so '.' is the point.
*/
#define _POSIX_C_SOURCE 200809L         /* fstat(), fileno() */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "io/sbuf.h"
#include "io/tread.h"
#include "io/tread_int.h"

/* ===== interned names ===== */

static uint64_t hash_bytes(const char *s, size_t n)
{
    uint64_t h = 14695981039346656037u;     /* FNV-1a */
    size_t k;

    for (k = 0; k < n; k++) { h ^= (unsigned char)s[k]; h *= 1099511628211u; }
    return h;
}

/* The first empty slot at or after the slot of hash h (linear probing;
** nslot a power of two, the table never full). */
static size_t free_slot(const uint32_t *slot, size_t nslot, uint64_t h)
{
    size_t k = (size_t)h & (nslot - 1);

    while (slot[k]) k = (k + 1) & (nslot - 1);
    return k;
}

/* Rebuild the hash table with nslot slots (a power of two). */
static int names_rehash(pt_names *nm, size_t nslot)
{
    uint32_t *slot = calloc(nslot, sizeof *slot);
    size_t id;

    if (!slot) return -1;
    for (id = 0; id < nm->n; id++) {
        const char *s = pt_names_get(nm, (uint32_t)id);
        slot[free_slot(slot, nslot, hash_bytes(s, strlen(s)))] = (uint32_t)id + 1;
    }
    free(nm->slot);
    nm->slot = slot;
    nm->nslot = nslot;
    return 0;
}

int pt_names_intern(pt_names *nm, const char *s, size_t n, uint32_t *id)
{
    size_t k;

    if (!pt_sbuf_term_plain(s, n)) {        /* a name diff will print: made safe */
        pt_sbuf safe;
        int rc;

        pt_sbuf_init(&safe);
        pt_sbuf_add_term(&safe, s, n);
        rc = safe.failed || !safe.s ? -1 : pt_names_intern(nm, safe.s, safe.len, id);
        pt_sbuf_free(&safe);
        return rc;
    }

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

/* ===== files ===== */

int pt_tread_file(const char *path, char **buf, size_t *len, char *err, size_t errlen)
{
    return pt_tread_file_max(path, PT_TREAD_MAX_BYTES, buf, len, err, errlen);
}

/* 1 when what buf[0..n) starts with may hold NUL bytes: a binary PPM or a PNG. */
static int binary_kind(const char *buf, size_t n)
{
    pt_tkind k = pt_tread_kind(buf, n);

    return k == PT_TK_PPM || k == PT_TK_PNG;
}

int pt_tread_file_max(const char *path, size_t max, char **buf, size_t *len, char *err,
                      size_t errlen)
{
    FILE *f = strcmp(path, "-") ? fopen(path, "rb") : stdin;
    size_t n = 0, cap = 1 << 16;
    struct stat st;
    char *b;
    int big = 0, text = -1;                 /* text: 1 when NUL ends the reading */

    *buf = NULL;
    *len = 0;
    if (!f) {
        snprintf(err, errlen, "%s:1:1: error: cannot read file: %s", path, strerror(errno));
        return -1;
    }
    if (fstat(fileno(f), &st) == 0 && S_ISREG(st.st_mode) && (uintmax_t)st.st_size > max)
        big = 1;                            /* a regular file: known before reading it */
    b = big ? NULL : malloc(cap);
    while (b) {                             /* invariant: n <= max, n < cap */
        size_t got, from = n;
        if (cap - n < 2) {                  /* room for one more byte and the NUL */
            size_t nc = cap > max / 2 ? max + 2 : 2 * cap;
            char *nb = realloc(b, nc);
            if (!nb) { free(b); b = NULL; break; }
            b = nb;
            cap = nc;
        }
        got = fread(b + n, 1, cap - n - 1, f);
        n += got;
        if (got == 0) break;
        if (n > max) { big = 1; free(b); b = NULL; break; }
        if (text < 0 && n >= 8) { text = !binary_kind(b, n); from = 0; }
        if (text == 1 && memchr(b + from, '\0', n - from)) break;  /* pt_tread_parse() says where */
    }
    if (big) {
        snprintf(err, errlen, "%s:1:1: error: the file is larger than %zu bytes, the most "
                 "pipetrace reads", path, max);
    } else if (!b) {
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

/* A student build's CSV trace starts with a line "# student ...": its length
** with the newline, or 0. */
static size_t student_line(const char *buf, size_t len)
{
    static const char student[] = "# student ";
    const char *nl;

    if (len < sizeof student - 1 || memcmp(buf, student, sizeof student - 1) != 0) return 0;
    nl = memchr(buf, '\n', len);
    return nl ? (size_t)(nl + 1 - buf) : 0;
}

pt_tkind pt_tread_kind(const char *buf, size_t len)
{
    static const char text[] = "# pipetrace trace";
    static const char csv[] = "model,v,stage,";
    static const char kraft[] = "== Begin Rendering of Scene:";
    static const char bad[] = "FrameBuffer: Bad pixel coordinate (";
    size_t k = 0;

    static const char png[] = "\211PNG\r\n\032\n";

    {                                       /* a student build's CSV */
        size_t skip = student_line(buf, len);
        if (skip) return pt_tread_kind(buf + skip, len - skip);
    }
    if (len >= 2 && buf[0] == 'P' && buf[1] == '6') return PT_TK_PPM;
    if (len >= 2 && buf[0] == 'P' && buf[1] == '3') return PT_TK_P3;
    if (len >= sizeof png - 1 && memcmp(buf, png, sizeof png - 1) == 0) return PT_TK_PNG;
    if (len >= 1 && buf[0] == '{') return PT_TK_JSONL;
    if (len >= sizeof text - 1 && memcmp(buf, text, sizeof text - 1) == 0) return PT_TK_TEXT;
    if (len >= sizeof csv - 1 && memcmp(buf, csv, sizeof csv - 1) == 0) return PT_TK_CSV;
    for (;;) {                              /* the viewport's clearing's Bad pixel lines */
        const char *nl;
        if (len - k < sizeof bad - 1 || memcmp(buf + k, bad, sizeof bad - 1) != 0) break;
        if (!(nl = memchr(buf + k, '\n', len - k))) break;
        k = (size_t)(nl + 1 - buf);
    }
    while (k < len && (buf[k] == '\n' || buf[k] == '\r')) k++;    /* its empty line */
    if (len - k >= sizeof kraft - 1 && memcmp(buf + k, kraft, sizeof kraft - 1) == 0)
        return PT_TK_KRAFT;
    return PT_TK_UNKNOWN;
}

/* ===== the trace ===== */

/* The first byte of p[0..e) that does not begin well-formed UTF-8, or NULL.
** p[0..e) holds no NUL and e[0] is '\n', '\r' or the buffer's NUL, so
** pt_sbuf_utf8_len() stays inside. */
static const char *bad_utf8(const char *p, const char *e)
{
    int n;

    for (; p < e; p += n)
        if ((n = (unsigned char)*p < 0x80 ? 1 : pt_sbuf_utf8_len((const unsigned char *)p)) == 0 ||
            n > e - p) return p;
    return NULL;
}

int pt_tread_parse(pt_tread *t, const char *path, const char *buf, size_t len,
                   pt_names *nm, char *err, size_t errlen)
{
    pt_treader r;
    const char *p = buf, *end = buf + len, *bad;
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
    if (t->kind == PT_TK_KRAFT) {          /* the course's log: read whole */
        rc = pt_tr_kraft(&r, buf, len);
        p = end;
    } else if (t->kind != PT_TK_JSONL && t->kind != PT_TK_TEXT) {
        r.eol = buf;
        rc = pt_tr_fail(&r, buf, "not a pipetrace trace (JSON Lines or text) nor an image "
                        "(" PT_TR_IMG_FORMATS ")");
    }
    while (rc == 0 && p < end) {
        const char *nl = memchr(p, '\n', (size_t)(end - p)), *nul;
        size_t n = (size_t)((nl ? nl : end) - p);
        if (n > 0 && p[n - 1] == '\r') n--;
        r.line = p;
        r.eol = p + n;
        if ((nul = memchr(p, '\0', n)) != NULL)
            rc = pt_tr_fail(&r, nul, "NUL byte in a trace");
        else if ((bad = bad_utf8(p, r.eol)) != NULL)
            rc = pt_tr_fail(&r, bad, "invalid UTF-8 sequence starting with byte 0x%02x",
                            (unsigned char)*bad);
        else if (t->kind == PT_TK_JSONL)
            rc = pt_tr_json_line(&r);
        else
            rc = pt_tr_text_line(&r);
        p = nl ? nl + 1 : end;
        r.lineno++;
    }
    if (rc == 0 && t->kind == PT_TK_TEXT) rc = pt_tr_text_end(&r);
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
