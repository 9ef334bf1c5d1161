/*
** src/core/scene.c -- parse .scene and Wavefront .obj files into a pt_scene
** See LICENSE for copyright and license.
**
** Design.  A file is read as a stream, a window of whole lines at a time
** (fill(): 64 KiB, more for a longer line), and walked once, line by line: the
** parse holds the scene's data, never its text.  Text in memory
** (pt_scene_parse) is walked the same way, all of it one window.
** next_line() finds the end of a line and checks every byte on the way (valid
** UTF-8, no control characters, CR only as part of CRLF), so everything after
** it sees clean text.  pt_sc_next_token() splits a line at spaces and tabs and hands
** out (pointer, length) pairs into the buffer: tokens are never copied, except
** a number that takes strtod()'s path, which needs it NUL-terminated
** (core/numparse.h).
**
** A parser struct holds what spans lines: which once-only directives were seen
** and on which line, and which model is current (always the last one in
** s->models).  A source struct holds one text being read: its name, the read
** position, and the current line.  An `obj` line reads the named file as a
** second source in "OBJ mode", where only v, l and f count and indices are
** relative to the file's own vertices; OBJ mode never opens further files.
**
** Errors.  Every function that can fail returns 0 (or a count) on success and
** -1 on failure.  The first failure writes "FILE:LINE:COL: error: MESSAGE" to
** the caller's buffer; the -1 then travels straight up to the public function,
** which frees the half-built scene.  Nothing here prints or exits.
*/
#define _POSIX_C_SOURCE 200809L        /* open, fstat, fcntl, fdopen: obj files */
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/scene.h"
#include "core/scene_int.h"
#include "core/nameset.h"
#include "core/numparse.h"
#include "core/shapes.h"


/* ---------------------------------------------------------------- messages */


/* ===== errors: FILE:LINE:COL messages ===== */

/* Write "NAME:LINE:COL: error: " and the formatted message to err.  Any control
** byte (say, a newline in a file name) becomes '?', so that the message is
** exactly one line.  Returns -1, so that callers can `return vfail(...)`. */
static int vfail(char *err, size_t errlen, const char *name, size_t line,
                 size_t col, const char *fmt, va_list ap)
{
    int k;
    size_t n, i;

    if (err == NULL || errlen == 0)
        return -1;
    k = snprintf(err, errlen, "%s:%zu:%zu: error: ", name, line, col);
    n = k < 0 ? 0 : (size_t)k;
    if (n < errlen)
        vsnprintf(err + n, errlen - n, fmt, ap);
    for (i = 0; err[i] != '\0'; i++)
        if ((unsigned char)err[i] < 0x20 || err[i] == 0x7f)
            err[i] = '?';
    return -1;
}

/* An error at an explicit file, line and column. */
int pt_sc_fail_at(char *err, size_t errlen, const char *name, size_t line,
                   size_t col, const char *fmt, ...)
{
    va_list ap;

    va_start(ap, fmt);
    vfail(err, errlen, name, line, col, fmt, ap);
    va_end(ap);
    return -1;
}

/* An error at the byte `at` of the current line of src. */
int pt_sc_fail(parser *ps, const source *src, const char *at,
                const char *fmt, ...)
{
    va_list ap;
    size_t col = (size_t)(at - src->line) + 1;

    va_start(ap, fmt);
    vfail(ps->err, ps->errlen, src->name, src->lineno, col, fmt, ap);
    va_end(ap);
    return -1;
}

/* ===== characters and lines: UTF-8, controls, the cursor ===== */

/* Copy p[0..n) into buf (QUOTE_BUF bytes) for a message.  Text longer than
** QUOTE_MAX bytes is cut, at a character boundary, and "..." appended. */
const char *pt_sc_shown(const char *p, size_t n, char *buf)
{
    size_t k = n;

    if (k > QUOTE_MAX) {
        k = QUOTE_MAX;
        while (k > 0 && ((unsigned char)p[k] & 0xC0) == 0x80)
            k--;                        /* p[k] continues a character: back off */
    }
    if (k > 0)
        memcpy(buf, p, k);
    strcpy(buf + k, k < n ? "..." : "");
    return buf;
}

/* -------------------------------------------------- bytes, lines, tokens */

/* The length (2..4) of the valid UTF-8 character at p, given avail >= 1 bytes
** and p[0] >= 0x80; or 0 when it is not valid, with *why naming the reason, or
** NULL when p[0] cannot start a character at all. */
static size_t utf8_len(const unsigned char *p, size_t avail, const char **why)
{
    unsigned c = p[0];
    unsigned lo = 0x80, hi = 0xBF;      /* allowed range of the second byte */
    size_t n, i;

    *why = NULL;
    if (c == 0xC0 || c == 0xC1) {
        *why = "overlong form";
        return 0;
    }
    if (c >= 0xC2 && c <= 0xDF)
        n = 2;
    else if (c >= 0xE0 && c <= 0xEF)
        n = 3;
    else if (c >= 0xF0 && c <= 0xF4)
        n = 4;
    else
        return 0;                       /* a continuation byte, or 0xF5..0xFF */
    for (i = 1; i < n; i++)
        if (i >= avail || (p[i] & 0xC0) != 0x80) {
            *why = "truncated";
            return 0;
        }
    if (c == 0xE0)      { lo = 0xA0; *why = "overlong form"; }
    else if (c == 0xED) { hi = 0x9F; *why = "surrogate"; }
    else if (c == 0xF0) { lo = 0x90; *why = "overlong form"; }
    else if (c == 0xF4) { hi = 0x8F; *why = "beyond U+10FFFF"; }
    if (p[1] < lo || p[1] > hi)
        return 0;
    *why = NULL;
    return n;
}

/* Is the valid UTF-8 character at p (length n) a C1 control, U+0080..U+009F? */
static int is_c1_control(const unsigned char *p, size_t n)
{
    return n == 2 && p[0] == 0xC2 && p[1] < 0xA0;
}

/* Check the character at p, one that is not printable ASCII, tab or LF, and
** return its length; or report why it is not allowed and return 0.  A CR is
** allowed (length 1) only right before an LF. */
static size_t check_char(parser *ps, const source *src, const unsigned char *p,
                         const unsigned char *end)
{
    const char *at = (const char *)p;
    const char *why;
    size_t n;

    if (p[0] == '\r') {
        if (p + 1 < end && p[1] == '\n')
            return 1;
        pt_sc_fail(ps, src, at, "carriage return not followed by a line feed");
    } else if (p[0] == 0) {
        pt_sc_fail(ps, src, at, "NUL byte");
    } else if (p[0] < 0x80) {
        pt_sc_fail(ps, src, at, "control character 0x%02x", p[0]);
    } else if ((n = utf8_len(p, (size_t)(end - p), &why)) == 0) {
        if (why == NULL)
            pt_sc_fail(ps, src, at, "invalid UTF-8 byte 0x%02x", p[0]);
        else
            pt_sc_fail(ps, src, at, "invalid UTF-8 sequence starting with byte 0x%02x (%s)",
                 p[0], why);
    } else if (is_c1_control(p, n)) {
        pt_sc_fail(ps, src, at, "control character U+%04X", (unsigned)p[1]);
    } else {
        return n;
    }
    return 0;
}

/* A stream: move the unread text to the start of the window, grow the window
** when that text fills half of it (a long line), and read what fits after
** it.  After a chunk with a NUL byte nothing more is read: the parser
** reports the byte anyway, and `obj /dev/zero` must not eat all memory.
** Returns 0; -1 on a read error (errno in src->errnum); -2 when out of memory. */

static int fill(source *src)
{
    size_t keep = (size_t)(src->end - src->p), want, got;
    char *p;

    memmove(src->buf, src->p, keep);
    if (keep > src->cap / 2) {
        p = pt_sc_grow(src->buf, &src->cap, 1, SIZE_MAX);
        if (p == NULL)
            return -2;
        src->buf = p;
    }
    src->p = src->line = src->buf;
    src->end = src->buf + keep;
    want = src->cap - keep;
    errno = 0;
    got = fread(src->buf + keep, 1, want, src->f);
    src->end += got;
    if (got > 0 && memchr(src->buf + keep, '\0', got) != NULL)
        src->eof = 1;
    if (got < want) {                   /* end of file, or an error */
        src->eof = 1;
        if (ferror(src->f)) {
            src->errnum = errno != 0 ? errno : EIO;
            return -1;
        }
    }
    return 0;
}

/* Step src to its next line and check every byte of it, comment included.
** *line gets the line's text up to the first '#' or the line end (LF, CRLF or
** the end of the text).  Returns 1 for a line, 0 at the end, -1 on a bad byte. */
static int next_line(parser *ps, source *src, cursor *line)
{
    const unsigned char *p, *end;
    const unsigned char *hash = NULL;   /* the first '#', if any */
    const unsigned char *stop;          /* where the line's text ends */
    size_t n;
    int r;

    while (!src->eof && memchr(src->p, '\n', (size_t)(src->end - src->p)) == NULL)
        if ((r = fill(src)) < 0)        /* a stream: read on to the line's end */
            return pt_sc_fail_at(ps->err, ps->errlen, src->name, src->lineno + 1, 1, "%s",
                           r == -2 ? "out of memory" : strerror(src->errnum));
    p = (const unsigned char *)src->p;
    end = (const unsigned char *)src->end;
    if (p == end)
        return 0;
    src->line = src->p;
    src->lineno++;
    for (;;) {
        if (p == end || *p == '\n') {
            stop = p;
            break;
        }
        if ((*p >= 0x20 && *p < 0x7f) || *p == '\t') {     /* the common case */
            if (*p == '#' && hash == NULL)
                hash = p;
            p++;
            continue;
        }
        n = check_char(ps, src, p, end);    /* CR, controls, UTF-8 */
        if (n == 0)
            return -1;
        if (*p == '\r') {               /* check_char allowed it: a CRLF */
            stop = p;
            p++;                        /* on the LF, as in the first case */
            break;
        }
        p += n;
    }
    line->p = src->p;
    line->end = (const char *)(hash != NULL ? hash : stop);
    src->p = (const char *)(p == end ? p : p + 1);        /* past the LF */
    return 1;
}

/* ===== tokens and numbers ===== */

/* Take the next token from c into *t.  Returns 1, or 0 when none is left. */
int pt_sc_next_token(cursor *c, token *t)
{
    const char *p = c->p;

    while (p < c->end && (*p == ' ' || *p == '\t'))
        p++;
    if (p == c->end) {
        c->p = p;
        return 0;
    }
    t->p = p;
    while (p < c->end && *p != ' ' && *p != '\t')
        p++;
    t->n = (size_t)(p - t->p);
    c->p = p;
    return 1;
}

/* Is t the word w? */
int pt_sc_tok_is(const token *t, const char *w)
{
    size_t n = strlen(w);

    return t->n == n && memcmp(t->p, w, n) == 0;
}

/* --------------------------------------------------------------- numbers */

static int is_digit(char c)
{
    return c >= '0' && c <= '9';
}

/* Does p[0..n) match [+-]?digits ? */
static int is_integer(const char *p, size_t n)
{
    size_t i = 0;

    if (n > 0 && (p[0] == '+' || p[0] == '-'))
        i = 1;
    if (i == n)
        return 0;
    for (; i < n; i++)
        if (!is_digit(p[i]))
            return 0;
    return 1;
}

/* Convert p[0..n) of the form [+-]?digits to *out.  Magnitudes beyond INT_CAP
** saturate to +-INT_CAP, which is out of every range this file checks, so a
** 40-digit number is reported as out of range without ever overflowing.
** Returns 0, or -1 when the form is wrong. */
static int scan_integer(const char *p, size_t n, int64_t *out)
{
    int64_t v = 0;
    size_t i = 0;

    if (!is_integer(p, n))
        return -1;
    if (p[0] == '+' || p[0] == '-')
        i = 1;
    for (; i < n; i++) {
        if (v < INT_CAP)
            v = v * 10 + (p[i] - '0');  /* v < 1e17, so v*10 + 9 fits */
        if (v > INT_CAP)
            v = INT_CAP;
    }
    *out = p[0] == '-' ? -v : v;
    return 0;
}

/* Parse t as a finite decimal number into *out; what names it in messages.
** pt_parse_decimal() checks the form [+-]?(digits[.digits*]|.digits)
** ([eE][+-]?digits)? (no hex, inf, nan, "1f", "1,5") and converts in one
** pass, exactly as strtod() would (core/numparse.h). */
int pt_sc_number(parser *ps, const source *src, const token *t,
                        const char *what, double *out)
{
    char q[QUOTE_BUF];
    double x;
    int r = pt_parse_decimal(t->p, t->n, &x);

    if (r == -1)
        return pt_sc_fail(ps, src, t->p, "'%s' is not a decimal number",
                    pt_sc_shown(t->p, t->n, q));
    if (r == -2)
        return pt_sc_fail(ps, src, t->p, "out of memory");
    if (!isfinite(x))
        return pt_sc_fail(ps, src, t->p, "%s '%s' is not finite", what,
                    pt_sc_shown(t->p, t->n, q));
    *out = x;
    return 0;
}

/* Parse t as an integer in lo..hi into *out; what names it in messages. */
int pt_sc_int(parser *ps, const source *src, const token *t,
                     const char *what, int lo, int hi, int *out)
{
    char q[QUOTE_BUF];
    int64_t v;

    if (scan_integer(t->p, t->n, &v) < 0)
        return pt_sc_fail(ps, src, t->p, "%s '%s' is not an integer", what,
                    pt_sc_shown(t->p, t->n, q));
    if (v < lo || v > hi)
        return pt_sc_fail(ps, src, t->p, "%s %s is out of range (%d..%d)", what,
                    pt_sc_shown(t->p, t->n, q), lo, hi);
    *out = (int)v;                      /* lo <= v <= hi: the cast is exact */
    return 0;
}

/* ---------------------------------------------------------------- models */

/* ===== the scene being built: models, vertices, segments ===== */

/* Grow the array p of *cap elements of size bytes, doubling (from 16) but
** never beyond max elements nor SIZE_MAX bytes.  Returns the new array and
** updates *cap, or returns NULL, p untouched, when it cannot grow. */
void *pt_sc_grow(void *p, size_t *cap, size_t size, size_t max)
{
    size_t n;

    if (max > SIZE_MAX / size)
        max = SIZE_MAX / size;
    if (*cap >= max)
        return NULL;
    n = *cap == 0 ? 16 : (*cap <= max / 2 ? *cap * 2 : max);
    if (n > max)
        n = max;
    p = realloc(p, n * size);
    if (p != NULL)
        *cap = n;
    return p;
}

/* The current model.  Callers make sure there is one. */
pt_model *pt_sc_model(parser *ps)
{
    return &ps->s->models[ps->s->nmodels - 1];
}

/* Append a white, untranslated model called name[0..n) that began on line
** lineno.  Returns 0, or -1 when out of memory (no message). */
static int new_model(parser *ps, const char *name, size_t n, size_t lineno)
{
    pt_scene *s = ps->s;
    pt_model *m;
    char *copy;
    void *p;

    if (s->nmodels == s->cap_models) {
        p = pt_sc_grow(s->models, &s->cap_models, sizeof *s->models, SIZE_MAX);
        if (p == NULL)
            return -1;
        s->models = p;
    }
    /* model_line keeps pace with models; its elements are smaller than a
    ** pt_model, so the byte count cannot overflow. */
    if (ps->cap_model_line < s->cap_models) {
        p = realloc(ps->model_line, s->cap_models * sizeof *ps->model_line);
        if (p == NULL)
            return -1;
        ps->model_line = p;
        ps->cap_model_line = s->cap_models;
    }
    copy = malloc(n + 1);
    if (copy == NULL)
        return -1;
    if (n > 0)
        memcpy(copy, name, n);
    copy[n] = '\0';
    ps->model_line[s->nmodels] = lineno;
    m = &s->models[s->nmodels++];
    memset(m, 0, sizeof *m);
    m->name = copy;
    m->color[0] = m->color[1] = m->color[2] = 255;
    m->world = pt_mat4_identity();
    ps->translate_line = ps->color_line = 0;
    ps->course.cindex_max = 0;
    ps->course.vcolor_line = ps->course.hidepos_line = ps->course.hidemodel_line = 0;
    return 0;
}

/* Room in *arr (n items of size bytes, room for *cap) for one more, at most
** max of them in one model: `what` names them in the message, at is where
** to point an error.  Returns 0, or -1 after the error. */
int pt_sc_room(parser *ps, const source *src, const char *at, void **arr,
                        size_t n, size_t *cap, size_t size, size_t max, const char *what)
{
    void *p;

    if (n != *cap) return 0;
    if (n >= max)
        return pt_sc_fail(ps, src, at, "more than %lu %s in one model", (unsigned long)max, what);
    p = pt_sc_grow(*arr, cap, size, max);
    if (p == NULL)
        return pt_sc_fail(ps, src, at, "out of memory");
    *arr = p;
    return 0;
}

/* Append vertex v to the current model; at is where to point an error. */
static int add_vertex(parser *ps, const source *src, const char *at, pt_vec3 v)
{
    pt_model *m = pt_sc_model(ps);

    if (pt_sc_room(ps, src, at, (void **)&m->v, m->nv, &m->cap_v, sizeof *m->v,
                     MAX_VERTS, "vertices") != 0)
        return -1;
    m->v[m->nv++] = v;
    return 0;
}

/* Append segment a-b (0-based) to the current model. */
static int add_segment(parser *ps, const source *src, const char *at,
                       uint32_t a, uint32_t b)
{
    pt_model *m = pt_sc_model(ps);

    if (pt_sc_room(ps, src, at, (void **)&m->seg, m->nseg, &m->cap_seg, sizeof *m->seg,
                     MAX_SEGS, "segments") != 0)
        return -1;
    m->seg[m->nseg].a = m->seg[m->nseg].ca = a;
    m->seg[m->nseg].b = m->seg[m->nseg].cb = b;
    m->nseg++;
    return 0;
}

/* The first '/' in p[0..end), or end when there is none. */
static const char *find_slash(const char *p, const char *end)
{
    while (p < end && *p != '/')
        p++;
    return p;
}

/* Split a vertex reference I, I/T, I//N or I/T/N and set *vpart to its I.
** T and N must be integers but are otherwise unused.  Returns 0, or -1 when
** the form is wrong. */
static int vertex_ref(const token *t, token *vpart)
{
    const char *end = t->p + t->n;
    const char *s1, *s2;                /* the first and second '/', or end */

    s1 = find_slash(t->p, end);
    vpart->p = t->p;
    vpart->n = (size_t)(s1 - t->p);
    if (s1 == end)
        return 0;                                           /* I */
    s2 = find_slash(s1 + 1, end);
    if (s2 == end)                                          /* I/T */
        return is_integer(s1 + 1, (size_t)(end - s1 - 1)) ? 0 : -1;
    if (s2 > s1 + 1 && !is_integer(s1 + 1, (size_t)(s2 - s1 - 1)))
        return -1;                                          /* a bad T */
    return is_integer(s2 + 1, (size_t)(end - s2 - 1)) ? 0 : -1;  /* I//N, I/T/N */
}

/* Turn the vertex reference t into a 0-based index into the model's v[].
** In scope are the vertices the model has so far, less those from before the
** source began (an OBJ file counts its own vertices from 1):
**     k > 0:  the k-th vertex in scope          (k <= count)
**     k < 0:  the |k|-th vertex counting back   (|k| <= count, -1 = the last) */
int pt_sc_index(parser *ps, const source *src, const token *t,
                         uint32_t *out)
{
    size_t nv = pt_sc_model(ps)->nv;
    size_t count = nv - src->base;      /* vertices in scope, <= MAX_VERTS */
    const char *scope = src->obj ? " in this file" : "";
    const char *noun = count == 1 ? "vertex" : "vertices";
    char q[QUOTE_BUF];
    token vp;
    int64_t k;

    if (vertex_ref(t, &vp) < 0 || scan_integer(vp.p, vp.n, &k) < 0)
        return pt_sc_fail(ps, src, t->p,
                    "'%s' is not a vertex index (expected I, I/T, I//N or I/T/N)",
                    pt_sc_shown(t->p, t->n, q));
    if (k == 0)
        return pt_sc_fail(ps, src, t->p, "index 0 is not valid (indices start at 1)");
    if (k > 0 && (uint64_t)k > count)
        return pt_sc_fail(ps, src, t->p, "index %s refers past the %zu %s defined so far%s",
                    pt_sc_shown(vp.p, vp.n, q), count, noun, scope);
    if (k < 0 && (uint64_t)-k > count)
        return pt_sc_fail(ps, src, t->p,
                    "index %s refers before the first of the %zu %s defined so far%s",
                    pt_sc_shown(vp.p, vp.n, q), count, noun, scope);
    /* Both results are < nv <= MAX_VERTS, so they fit in a uint32_t. */
    *out = (uint32_t)(k > 0 ? src->base + (size_t)k - 1 : nv - (size_t)-k);
    return 0;
}

/* ------------------------------------------------------------ directives */

/* ===== directives, one handler each ===== */

/* A directive's handler: dir is the directive's token, args the rest of the
** line.  Returns 0 or -1. */
typedef int handler(parser *ps, source *src, const token *dir, cursor *args);

/* Read the arguments of directive dir, which takes lo..hi of them (hi <= 4),
** into arg[] and their number into *count (if not NULL); noun says what they
** are ("numbers").  Missing arguments are reported at the directive, extra
** ones at the first extra argument. */
int pt_sc_take_args(parser *ps, const source *src, const token *dir,
                     cursor *args, token *arg, size_t lo, size_t hi,
                     const char *noun, size_t *count)
{
    const char *extra = NULL;
    char q[QUOTE_BUF];
    size_t n = 0;
    token t;

    while (pt_sc_next_token(args, &t)) {
        if (n < hi)
            arg[n] = t;
        else if (extra == NULL)
            extra = t.p;
        n++;
    }
    if (n < lo)
        return pt_sc_fail(ps, src, dir->p, "expected %zu %s after '%s', found %zu",
                    lo, noun, pt_sc_shown(dir->p, dir->n, q), n);
    if (n > hi && lo == hi)
        return pt_sc_fail(ps, src, extra, "expected %zu %s after '%s', found %zu",
                    lo, noun, pt_sc_shown(dir->p, dir->n, q), n);
    if (n > hi)
        return pt_sc_fail(ps, src, extra, "expected at most %zu %s after '%s', found %zu",
                    hi, noun, pt_sc_shown(dir->p, dir->n, q), n);
    if (count != NULL)
        *count = n;
    return 0;
}

/* A directive allowed once (per scene or per model): remember its line in
** *seen, or fail when *seen already holds one. */
int pt_sc_once(parser *ps, const source *src, const token *dir, size_t *seen)
{
    char q[QUOTE_BUF];

    if (*seen != 0)
        return pt_sc_fail(ps, src, dir->p, "duplicate '%s' (first at line %zu)",
                    pt_sc_shown(dir->p, dir->n, q), *seen);
    *seen = src->lineno;
    return 0;
}

/* Three integers 0..255 into rgb[]: for `background` and `color`. */
int pt_sc_rgb(parser *ps, const source *src, const token *dir,
                     cursor *args, const char *what, unsigned char rgb[3])
{
    token a[3];
    int c[3], i;

    if (pt_sc_take_args(ps, src, dir, args, a, 3, 3, "integers", NULL) < 0)
        return -1;
    for (i = 0; i < 3; i++)
        if (pt_sc_int(ps, src, &a[i], what, 0, 255, &c[i]) < 0)
            return -1;
    for (i = 0; i < 3; i++)
        rgb[i] = (unsigned char)c[i];   /* 0..255: exact */
    return 0;
}

/* framebuffer W H */
static int do_framebuffer(parser *ps, source *src, const token *dir, cursor *args)
{
    token a[2];

    if (pt_sc_once(ps, src, dir, &ps->fb_line) < 0
        || pt_sc_take_args(ps, src, dir, args, a, 2, 2, "integers", NULL) < 0
        || pt_sc_int(ps, src, &a[0], "framebuffer width", 1, PT_MAX_SIZE,
                     &ps->s->fb_w) < 0
        || pt_sc_int(ps, src, &a[1], "framebuffer height", 1, PT_MAX_SIZE,
                     &ps->s->fb_h) < 0)
        return -1;
    return 0;
}

/* background R G B */
static int do_background(parser *ps, source *src, const token *dir, cursor *args)
{
    if (pt_sc_once(ps, src, dir, &ps->bg_line) < 0)
        return -1;
    return pt_sc_rgb(ps, src, dir, args, "background component",
                     ps->s->background);
}

/* viewport X Y W H.  X and Y may put the viewport partly or wholly outside
** the framebuffer, as the course's setViewport allows: -PT_MAX_SIZE ..
** PT_MAX_SIZE, so that y_fb * W + x_fb of any pixel of it stays within an int.
** Whether the matrix camera's fits in the framebuffer is checked once the
** whole file is read (finish_viewport), as `framebuffer` may come later. */
static int do_viewport(parser *ps, source *src, const token *dir, cursor *args)
{
    pt_scene *s = ps->s;
    token a[4];

    if (pt_sc_once(ps, src, dir, &ps->vp_line) < 0
        || pt_sc_take_args(ps, src, dir, args, a, 4, 4, "integers", NULL) < 0
        || pt_sc_int(ps, src, &a[0], "viewport x", -PT_MAX_SIZE, PT_MAX_SIZE, &s->vp_x) < 0
        || pt_sc_int(ps, src, &a[1], "viewport y", -PT_MAX_SIZE, PT_MAX_SIZE, &s->vp_y) < 0
        || pt_sc_int(ps, src, &a[2], "viewport width", 1, PT_MAX_SIZE, &s->vp_w) < 0
        || pt_sc_int(ps, src, &a[3], "viewport height", 1, PT_MAX_SIZE, &s->vp_h) < 0)
        return -1;
    ps->vp_col = (size_t)(dir->p - src->line) + 1;
    return 0;
}

/* Numbers a[0..n) into v[]; what names them in messages. */
int pt_sc_numbers(parser *ps, const source *src, const token *a, size_t n,
                         const char *what, double *v)
{
    size_t i;

    for (i = 0; i < n; i++)
        if (pt_sc_number(ps, src, &a[i], what, &v[i]) < 0)
            return -1;
    return 0;
}

/* camera perspective | orthographic | lookat EX EY EZ DX DY DZ UX UY UZ
** | lookat-target EX EY EZ TX TY TZ UX UY UZ.  A look-at camera is checked
** once the whole file is read (finish_camera). */
static int do_camera(parser *ps, source *src, const token *dir, cursor *args)
{
    char q[QUOTE_BUF];
    token a[10];
    double v[9];
    size_t n;

    if (pt_sc_once(ps, src, dir, &ps->cam_line) < 0
        || pt_sc_take_args(ps, src, dir, args, a, 1, 10, "word", &n) < 0)
        return -1;
    ps->cam_col = (size_t)(a[0].p - src->line) + 1;
    if (pt_sc_tok_is(&a[0], "perspective") || pt_sc_tok_is(&a[0], "orthographic")) {
        ps->s->perspective = pt_sc_tok_is(&a[0], "perspective");
        return n == 1 ? 0 : pt_sc_camera_volume(ps, src, a, n);
    }
    if (pt_sc_tok_is(&a[0], "perspective-fov") || pt_sc_tok_is(&a[0], "orthographic-fov")) {
        ps->s->perspective = pt_sc_tok_is(&a[0], "perspective-fov");
        return pt_sc_camera_volume(ps, src, a, n);
    }
    if (!pt_sc_tok_is(&a[0], "lookat") && !pt_sc_tok_is(&a[0], "lookat-target"))
        return pt_sc_fail(ps, src, a[0].p, "unknown camera '%s' (expected perspective, "
                    "orthographic, perspective-fov, orthographic-fov, lookat or lookat-target)",
                    pt_sc_shown(a[0].p, a[0].n, q));
    if (n != 10)
        return pt_sc_fail(ps, src, a[0].p, "expected 9 numbers after 'camera %s' "
                    "(eye, %s, up), found %zu", pt_sc_shown(a[0].p, a[0].n, q),
                    pt_sc_tok_is(&a[0], "lookat") ? "direction" : "target", n - 1);
    if (pt_sc_numbers(ps, src, a + 1, 9, "camera coordinate", v) < 0)
        return -1;
    ps->s->pipe = PT_PIPE_MATRIX;
    ps->s->eye = (pt_vec3){v[0], v[1], v[2]};
    ps->s->dir = (pt_vec3){v[3], v[4], v[5]};
    ps->s->up = (pt_vec3){v[6], v[7], v[8]};
    ps->s->target = pt_sc_tok_is(&a[0], "lookat-target");
    if (ps->s->target) {
        ps->s->at = ps->s->dir;
        ps->s->dir = pt_lookat_dir(ps->s->eye, ps->s->at);
    }
    return 0;
}

/* projection perspective FOV_DEGREES ASPECT|auto NEAR FAR */
static int do_projection(parser *ps, source *src, const token *dir, cursor *args)
{
    pt_scene *s = ps->s;
    char q[QUOTE_BUF];
    token a[5];
    size_t n;

    if (pt_sc_once(ps, src, dir, &ps->proj_line) < 0
        || pt_sc_take_args(ps, src, dir, args, a, 5, 5, "words", NULL) < 0)
        return -1;
    ps->proj_col[0] = (size_t)(dir->p - src->line) + 1;
    for (n = 1; n < 5; n++)
        ps->proj_col[n] = (size_t)(a[n].p - src->line) + 1;
    if (!pt_sc_tok_is(&a[0], "perspective"))
        return pt_sc_fail(ps, src, a[0].p, "unknown projection '%s' (expected perspective)",
                    pt_sc_shown(a[0].p, a[0].n, q));
    if (pt_sc_number(ps, src, &a[1], "field of view", &s->fov) < 0)
        return -1;
    s->aspect_auto = pt_sc_tok_is(&a[2], "auto");
    if (s->aspect_auto)
        s->aspect = 0;                  /* filled in by finish_camera() */
    else if (pt_sc_number(ps, src, &a[2], "aspect ratio", &s->aspect) < 0)
        return -1;
    else if (!(s->aspect > 0))
        return pt_sc_fail(ps, src, a[2].p, "projection: aspect ratio must be > 0");
    if (pt_sc_number(ps, src, &a[3], "near distance", &s->znear) < 0
        || pt_sc_number(ps, src, &a[4], "far distance", &s->zfar) < 0)
        return -1;
    return 0;
}

/* world translate X Y Z | world scale S | world scale X Y Z
** | world rotate x|y|z DEGREES: appended to the model's world matrix. */
static int do_world(parser *ps, source *src, const token *dir, cursor *args)
{
    pt_model *m = pt_sc_model(ps);
    char q[QUOTE_BUF];
    token a[4];
    double v[3];
    size_t n;
    pt_mat4 t;
    int axis;

    if (pt_sc_take_args(ps, src, dir, args, a, 2, 4, "words", &n) < 0)
        return -1;
    if (pt_sc_tok_is(&a[0], "translate") || pt_sc_tok_is(&a[0], "scale")) {
        int scale = pt_sc_tok_is(&a[0], "scale");
        if (n != 4 && !(scale && n == 2))
            return pt_sc_fail(ps, src, a[0].p, "expected %s after 'world %s', found %zu",
                        scale ? "1 or 3 numbers" : "3 numbers",
                        pt_sc_shown(a[0].p, a[0].n, q), n - 1);
        if (pt_sc_numbers(ps, src, a + 1, n - 1, "world number", v) < 0)
            return -1;
        if (n == 2) v[1] = v[2] = v[0];
        t = scale ? pt_mat4_scale(v[0], v[1], v[2]) : pt_mat4_translate(v[0], v[1], v[2]);
    } else if (pt_sc_tok_is(&a[0], "rotate")) {
        const char *axes = "xyz", *at;
        if (n != 3)
            return pt_sc_fail(ps, src, a[0].p, "expected an axis and an angle after "
                        "'world rotate', found %zu words", n - 1);
        at = a[1].n == 1 ? strchr(axes, a[1].p[0]) : NULL;
        if (at == NULL || *at == '\0')
            return pt_sc_fail(ps, src, a[1].p, "unknown axis '%s' (expected x, y or z)",
                        pt_sc_shown(a[1].p, a[1].n, q));
        if (pt_sc_number(ps, src, &a[2], "angle", &v[0]) < 0)
            return -1;
        axis = (int)(at - axes);
        t = pt_mat4_rotate(axis, v[0]);
    } else {
        return pt_sc_fail(ps, src, a[0].p, "unknown world transformation '%s' "
                    "(expected translate, scale or rotate)", pt_sc_shown(a[0].p, a[0].n, q));
    }
    m->world = pt_mat4_mul(&m->world, &t);  /* row vectors: earlier lines act first */
    for (n = 0; n < 16; n++)
        if (!isfinite(m->world.m[n / 4][n % 4]))
            return pt_sc_fail(ps, src, dir->p, "the world matrix overflows: entry (%zu, %zu) "
                        "is not finite", n / 4 + 1, n % 4 + 1);
    if (ps->world_line == 0) {
        ps->world_line = src->lineno;
        ps->world_col = (size_t)(dir->p - src->line) + 1;
    }
    return 0;
}

/* The code point of the valid UTF-8 character at p (n = 2..4 bytes) when it
** is a format character (Unicode's category Cf: the bidirectional controls
** U+202A .. U+202E and U+2066 .. U+2069, U+200E, U+200F, the invisible
** U+200B .. U+200D, U+2060 .. U+2064, U+FEFF, U+00AD, ...) or a line or
** paragraph separator (U+2028, U+2029); else 0.  Such a character in a name
** turns or hides the text around it, so a name that shows as "cube" need not
** be "cube" (Trojan Source, CVE-2021-42574).  Unicode 15's list. */
static unsigned long name_format_char(const unsigned char *p, size_t n)
{
    static const unsigned long cf[][2] = {
        { 0xAD, 0xAD }, { 0x600, 0x605 }, { 0x61C, 0x61C }, { 0x6DD, 0x6DD },
        { 0x70F, 0x70F }, { 0x890, 0x891 }, { 0x8E2, 0x8E2 }, { 0x180E, 0x180E },
        { 0x200B, 0x200F }, { 0x2028, 0x202E }, { 0x2060, 0x2064 },
        { 0x2066, 0x206F }, { 0xFEFF, 0xFEFF }, { 0xFFF9, 0xFFFB },
        { 0x110BD, 0x110BD }, { 0x110CD, 0x110CD }, { 0x13430, 0x1343F },
        { 0x1BCA0, 0x1BCA3 }, { 0x1D173, 0x1D17A }, { 0xE0001, 0xE0001 },
        { 0xE0020, 0xE007F },
    };
    unsigned long c = p[0] & (n == 2 ? 0x1Fu : n == 3 ? 0x0Fu : 0x07u);
    size_t i;

    for (i = 1; i < n; i++)
        c = (c << 6) | (p[i] & 0x3Fu);
    for (i = 0; i < sizeof cf / sizeof cf[0]; i++)
        if (c >= cf[i][0] && c <= cf[i][1])
            return c;
    return 0;
}

/* Refuse a name t (what: "model", "position") that holds a format character
** (name_format_char()).  Returns 0, or -1 after the error at its column. */
int pt_sc_name_chars(parser *ps, source *src, const token *t, const char *what)
{
    const char *why;
    unsigned long c;
    size_t i, k;

    for (i = 0; i < t->n; i += k) {
        const unsigned char *u = (const unsigned char *)t->p + i;

        k = u[0] < 0x80 ? 1 : utf8_len(u, t->n - i, &why);
        if (k > 1 && (c = name_format_char(u, k)) != 0)
            return pt_sc_fail(ps, src, t->p + i, "a %s name may not contain U+%04lX, a "
                              "format character (it turns or hides text)", what, c);
        if (k == 0)
            k = 1;                      /* cannot be: the line was checked */
    }
    return 0;
}

/* model NAME [POSITION]: a new current model (and its Position's name).
** Names are unique and go into JSON, CSV and text output, so '"', '\' and
** ',' are kept out of them, and onto terminals and pages, so format
** characters are (pt_sc_name_chars()).  (Spaces, '#', control characters and bad
** UTF-8 cannot reach here.)  The duplicate check asks a hash table
** (core/nameset.h): a scene of many models is read in linear time. */
static int do_model(parser *ps, source *src, const token *dir, cursor *args)
{
    pt_scene *s = ps->s;
    char q[QUOTE_BUF];
    size_t i;
    token a, b[2];
    size_t n;

    if (pt_sc_take_args(ps, src, dir, args, b, 0, 2, "names", &n) < 0)
        return -1;
    if (n == 0)
        return pt_sc_fail(ps, src, dir->p, "expected 1 name after 'model', found 0");
    if (s->nmodels > 0 && pt_sc_end_model(ps, src->name) < 0)
        return -1;
    a = b[0];
    for (i = 0; i < a.n; i++)
        if (a.p[i] == '"' || a.p[i] == '\\' || a.p[i] == ',')
            return pt_sc_fail(ps, src, a.p + i, "model name '%s' may not contain '%c'",
                        pt_sc_shown(a.p, a.n, q), a.p[i]);
    if (pt_sc_name_chars(ps, src, &a, "model") < 0
        || (n == 2 && pt_sc_name_chars(ps, src, &b[1], "position") < 0))
        return -1;
    if ((i = pt_nameset_find(&ps->names, a.p, a.n)) != SIZE_MAX)
        return pt_sc_fail(ps, src, a.p, "duplicate model name '%s' (first at line %zu)",
                    pt_sc_shown(a.p, a.n, q), ps->model_line[i]);
    if (new_model(ps, a.p, a.n, src->lineno) < 0
        || pt_nameset_add(&ps->names, pt_sc_model(ps)->name, a.n, s->nmodels - 1) < 0)
        return pt_sc_fail(ps, src, dir->p, "out of memory");
    return n == 2 ? pt_sc_position(ps, src, &b[1]) : 0;
}

/* translate X Y Z */
static int do_translate(parser *ps, source *src, const token *dir, cursor *args)
{
    pt_vec3 t;
    token a[3];

    if (pt_sc_once(ps, src, dir, &ps->translate_line) < 0
        || pt_sc_take_args(ps, src, dir, args, a, 3, 3, "numbers", NULL) < 0
        || pt_sc_number(ps, src, &a[0], "translation", &t.x) < 0
        || pt_sc_number(ps, src, &a[1], "translation", &t.y) < 0
        || pt_sc_number(ps, src, &a[2], "translation", &t.z) < 0)
        return -1;
    pt_sc_model(ps)->translate = t;
    return pt_sc_translate_op(ps, src, dir, t);
}

/* color R G B */
static int do_color(parser *ps, source *src, const token *dir, cursor *args)
{
    if (pt_sc_once(ps, src, dir, &ps->color_line) < 0)
        return -1;
    if (ps->course.vcolor_line != 0)
        return pt_sc_fail(ps, src, dir->p, "a model has 'color' or 'vcolor' lines, not both "
                          "('vcolor' at line %zu)", ps->course.vcolor_line);
    pt_sc_model(ps)->colors_given = 1;
    return pt_sc_rgb(ps, src, dir, args, "color component", pt_sc_model(ps)->color);
}

/* v X Y Z [W]: W is checked like the others, then ignored. */
static int do_vertex(parser *ps, source *src, const token *dir, cursor *args)
{
    pt_vec3 v;
    double w;
    size_t n;
    token a[4];

    if (pt_sc_take_args(ps, src, dir, args, a, 3, 4, "numbers", &n) < 0
        || pt_sc_number(ps, src, &a[0], "coordinate", &v.x) < 0
        || pt_sc_number(ps, src, &a[1], "coordinate", &v.y) < 0
        || pt_sc_number(ps, src, &a[2], "coordinate", &v.z) < 0
        || (n == 4 && pt_sc_number(ps, src, &a[3], "coordinate", &w) < 0))
        return -1;
    return add_vertex(ps, src, dir->p, v);
}

/* l I J ... (an open polyline) or, closed, f I J K ... (a face's outline):
** segments I-J, J-K, ... and for a face also last-first.  Only the previous
** and the first index are kept, so a line of any length needs no memory. */
static int polyline(parser *ps, source *src, const token *dir, cursor *args,
                    int closed)
{
    size_t need = closed ? 3 : 2, count = 0;
    uint32_t first = 0, prev = 0, cur = 0;
    char q[QUOTE_BUF];
    token t;

    while (pt_sc_next_token(args, &t)) {
        if (pt_sc_index(ps, src, &t, &cur) < 0)
            return -1;
        if (count == 0)
            first = cur;
        else if (add_segment(ps, src, t.p, prev, cur) < 0)
            return -1;
        prev = cur;
        count++;
    }
    if (count < need)
        return pt_sc_fail(ps, src, dir->p,
                    "expected at least %zu indices after '%s', found %zu",
                    need, pt_sc_shown(dir->p, dir->n, q), count);
    if (closed)
        return add_segment(ps, src, dir->p, prev, first);
    return 0;
}

static int do_line(parser *ps, source *src, const token *dir, cursor *args)
{
    return polyline(ps, src, dir, args, 0);
}

static int do_face(parser *ps, source *src, const token *dir, cursor *args)
{
    return polyline(ps, src, dir, args, 1);
}

/* ===== files, includes and OBJ ===== */

/* What kind of file mode is, for "not a regular file (a FIFO)". */
static const char *file_kind(mode_t mode)
{
    return S_ISFIFO(mode) ? "a FIFO" : S_ISSOCK(mode) ? "a socket"
         : S_ISCHR(mode) ? "a character device" : S_ISBLK(mode) ? "a block device"
         : S_ISDIR(mode) ? "a directory" : "not a plain file";
}

/* Open path for an `obj` line: only a regular file.  It is opened without
** blocking (O_NONBLOCK: opening a FIFO with no writer returns at once), then
** fstat() tells what was opened, so nothing can swap a FIFO in between a check
** and the open; a regular file gets its blocking mode back.  Returns the
** stream; NULL with *errnum set, or with *errnum 0 and *kind naming what the
** file is when it is not a regular file. */
static FILE *open_regular(const char *path, int *errnum, const char **kind)
{
    struct stat st;
    FILE *f;
    int fd, fl;

    errno = 0;
    fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY);
    if (fd < 0) {
        *errnum = errno;
        return NULL;
    }
    if (fstat(fd, &st) != 0) {
        *errnum = errno != 0 ? errno : EIO;
        close(fd);
        return NULL;
    }
    if (!S_ISREG(st.st_mode)) {
        *errnum = 0;
        *kind = file_kind(st.st_mode);
        close(fd);
        return NULL;
    }
    if ((fl = fcntl(fd, F_GETFL)) < 0 || fcntl(fd, F_SETFL, fl & ~O_NONBLOCK) < 0
        || (f = fdopen(fd, "rb")) == NULL) {
        *errnum = errno != 0 ? errno : EIO;
        close(fd);
        return NULL;
    }
    return f;
}

/* Read the first window of the stream f as src (name, OBJ mode obj, base as in
** init_source; own: close f in close_stream), skipping a UTF-8 byte-order
** mark.  Returns 0; -1 on a read error, errno value in *errnum (0 if none
** was set); -2 when out of memory.  On error f is closed when own. */
static int start_stream(source *src, FILE *f, int own, const char *name, int obj,
                        size_t base, int *errnum)
{
    int r;

    memset(src, 0, sizeof *src);
    src->name = name;
    src->obj = obj;
    src->base = base;
    src->f = f;
    src->own = own;
    src->buf = malloc(CHUNK);
    if (src->buf == NULL) {
        if (own)
            fclose(f);
        return -2;
    }
    src->cap = CHUNK;
    src->p = src->end = src->line = src->buf;
    r = fill(src);
    if (r < 0) {
        *errnum = src->errnum;
        if (own)
            fclose(f);
        free(src->buf);
        return r;
    }
    if (src->end - src->p >= 3 && memcmp(src->p, "\xEF\xBB\xBF", 3) == 0)
        src->p = src->line = src->p + 3;
    return 0;
}

/* Open the file at path as a stream src (name path, OBJ mode obj, base as in
** init_source) and read its first window, skipping a UTF-8 byte-order mark.
** Returns 0 (close it with close_stream); -1 when it cannot be opened or
** read, with the errno value in *errnum (0 if none was set); -2 when out of
** memory. */
static int open_stream(source *src, const char *path, int obj, size_t base, int *errnum)
{
    FILE *f;

    errno = 0;
    f = fopen(path, "rb");
    if (f == NULL) {
        *errnum = errno;
        return -1;
    }
    return start_stream(src, f, 1, path, obj, base, errnum);
}

static void close_stream(source *src)
{
    if (src->own)
        fclose(src->f);
    free(src->buf);
}

static int parse_source(parser *ps, source *src);

/* Set up src to read text[0..len) as file name, skipping a UTF-8 byte-order
** mark (columns on line 1 then count from after it). */
static void init_source(source *src, const char *name, const char *text,
                        size_t len, int obj, size_t base)
{
    static const char empty[1] = "";

    if (text == NULL) {                 /* no text: pointer arithmetic on NULL is UB */
        text = empty;
        len = 0;
    }
    if (len >= 3 && memcmp(text, "\xEF\xBB\xBF", 3) == 0) {
        text += 3;
        len -= 3;
    }
    src->name = name;
    src->p = src->line = text;
    src->end = text + len;
    src->lineno = 0;
    src->obj = obj;
    src->base = base;
    src->f = NULL;
    src->own = 0;
    src->included = 0;
    src->buf = NULL;
    src->cap = 0;
    src->eof = 1;                       /* all of it is in memory */
    src->errnum = 0;
}

/* Add path (malloc'd) to s->objs, which takes it.  Returns 0, or -1 when
** out of memory (path is not taken). */
static int remember_obj(pt_scene *s, char *path)
{
    char **more;

    if (s->nobjs >= SIZE_MAX / sizeof *more - 1)
        return -1;
    more = realloc(s->objs, (s->nobjs + 1) * sizeof *more);
    if (more == NULL)
        return -1;
    s->objs = more;
    s->objs[s->nobjs++] = path;
    return 0;
}

/* obj PATH: the rest of the line, trimmed, names an OBJ file relative to the
** scene's directory (unless it is absolute).  Its v, l and f lines go to the
** current model, and its indices count from the model's vertex count now. */
static int do_obj(parser *ps, source *src, const token *dir, cursor *args)
{
    const char *p = args->p, *e = args->end;
    size_t n, dirlen = ps->dirlen;
    char *path;
    const char *kind = NULL;
    int errnum = 0, r;
    source sub;
    FILE *f;

    while (p < e && (*p == ' ' || *p == '\t'))
        p++;
    while (e > p && (e[-1] == ' ' || e[-1] == '\t'))
        e--;
    if (p == e)
        return pt_sc_fail(ps, src, dir->p, "expected a file name after 'obj'");
    n = (size_t)(e - p);
    if (p[0] == '/')
        dirlen = 0;                     /* absolute: the directory plays no part */
    if (n > SIZE_MAX - dirlen - 1 || (path = malloc(dirlen + n + 1)) == NULL)
        return pt_sc_fail(ps, src, p, "out of memory");
    if (dirlen > 0)
        memcpy(path, ps->dir, dirlen);
    memcpy(path + dirlen, p, n);
    path[dirlen + n] = '\0';
    f = open_regular(path, &errnum, &kind);
    if (f == NULL && errnum == 0)
        r = pt_sc_fail(ps, src, p, "cannot read '%s': it is %s, not a regular file", path, kind);
    else if (f == NULL)
        r = pt_sc_fail(ps, src, p, "cannot read '%s': %s", path, strerror(errnum));
    else if ((r = start_stream(&sub, f, 1, path, 1, pt_sc_model(ps)->nv, &errnum)) == -1)
        r = pt_sc_fail(ps, src, p, "cannot read '%s': %s", path,
                 errnum != 0 ? strerror(errnum) : "read error");
    else if (r == -2)
        r = pt_sc_fail(ps, src, p, "out of memory");
    else {
        sub.included = 1;
        r = parse_source(ps, &sub);     /* OBJ mode: never comes back here */
        close_stream(&sub);
        if (r == 0 && remember_obj(ps->s, path) < 0)
            r = pt_sc_fail(ps, src, p, "out of memory");
        else if (r == 0)
            path = NULL;                /* the scene owns it now */
    }
    free(path);
    return r;
}

/* shape NAME ARGS...: a model of the course's library (src/core/shapes.h),
** appended vertex by vertex, so the model's limits and messages hold. */
static int do_shape(parser *ps, source *src, const token *dir, cursor *args)
{
    const char *at = dir->p;
    char msg[PT_ERRLEN];
    size_t base = pt_sc_model(ps)->nv, i;
    pt_shape sh;
    int r = 0;

    if (pt_shape_make(&sh, args->p, args->end, &at, msg, sizeof msg) < 0)
        return pt_sc_fail(ps, src, at, "%s", msg);
    for (i = 0; i < sh.nv && r == 0; i++)
        r = add_vertex(ps, src, dir->p, sh.v[i]);
    for (i = 0; i < sh.nseg && r == 0; i++)     /* base + index < nv <= MAX_VERTS */
        r = add_segment(ps, src, dir->p, (uint32_t)(base + sh.seg[i][0]),
                        (uint32_t)(base + sh.seg[i][1]));
    pt_shape_free(&sh);
    return r;
}

/* ---------------------------------------------------------- the drivers */

/* The directives of a .scene file; in_model: only after a `model` line.
** The most frequent come first, as the table is searched in order. */
static const struct directive {
    const char *name;
    handler *fn;
    int in_model;
} directives[] = {
    { "v",           do_vertex,      1 },
    { "f",           do_face,        1 },
    { "l",           do_line,        1 },
    { "model",       do_model,       0 },
    { "translate",   do_translate,   1 },
    { "color",       do_color,       1 },
    { "obj",         do_obj,         1 },
    { "shape",       do_shape,       1 },
    { "framebuffer", do_framebuffer, 0 },
    { "background",  do_background,  0 },
    { "viewport",    do_viewport,    0 },
    { "camera",      do_camera,      0 },
    { "projection",  do_projection,  0 },
    { "world",       do_world,       1 },
    /* the course's renderers (scene_course.c) */
    { "segment",     pt_sc_segment,  1 },
    { "point",       pt_sc_point,    1 },
    { "vcolor",      pt_sc_vcolor,   1 },
    { "vcolor-float", pt_sc_vcolor,  1 },
    { "matrix",      pt_sc_matrix,   1 },
    { "matrix-pre",  pt_sc_matrix,   1 },
    { "matrix-set",  pt_sc_matrix,   1 },
    { "hidden-position", pt_sc_hidden, 1 },
    { "hidden-model", pt_sc_hidden,  1 },
    { "renderer",    pt_sc_renderer, 0 },
    { "scene",       pt_sc_scene_name, 0 },
    { "viewport-background", pt_sc_vp_background, 0 },
    { "near",        pt_sc_near,     0 },
    { "view",        pt_sc_view,     0 },
    { "nearclip",    pt_sc_switch,   0 },
    { "antialias",   pt_sc_switch,   0 },
    { "gamma",       pt_sc_switch,   0 },
    { "pipeline2",   pt_sc_pipeline2, 0 },
};

/* ===== the parse loop ===== */

/* One line of a .scene file. */
static int scene_line(parser *ps, source *src, cursor *line)
{
    char q[QUOTE_BUF];
    size_t i;
    token d;

    if (!pt_sc_next_token(line, &d))
        return 0;                       /* blank, or only a comment */
    for (i = 0; i < sizeof directives / sizeof directives[0]; i++) {
        if (!pt_sc_tok_is(&d, directives[i].name))
            continue;
        if (directives[i].in_model && ps->s->nmodels == 0)
            return pt_sc_fail(ps, src, d.p, "'%s' before any 'model'", directives[i].name);
        return directives[i].fn(ps, src, &d, line);
    }
    return pt_sc_fail(ps, src, d.p, "unknown directive '%s'", pt_sc_shown(d.p, d.n, q));
}

/* The statements of the Wavefront OBJ format (its specification, version
** 3.0) that pipetrace has no use for: texture and normal vertices, free-form
** geometry, points, grouping and display attributes.  They are ignored. */
static const char *const obj_unused[] = {
    "vt", "vn", "vp", "cstype", "deg", "bmat", "step", "p", "curv", "curv2",
    "surf", "parm", "trim", "hole", "scrv", "sp", "end", "con", "g", "s", "mg",
    "o", "bevel", "c_interp", "d_interp", "lod", "usemtl", "mtllib",
    "shadow_obj", "trace_obj", "ctech", "stech", "maplib", "usemap", "call", "csh",
};

/* Does t look like an OBJ keyword (1 to 16 lowercase letters, digits and
** '_', a letter first)?  An `obj` line may name any file (`obj /etc/passwd`):
** a message about a line of it quotes only such a word, never other text. */
static int keyword_like(const token *t)
{
    size_t i;

    if (t->n == 0 || t->n > 16 || t->p[0] < 'a' || t->p[0] > 'z')
        return 0;
    for (i = 1; i < t->n; i++)
        if (!((t->p[i] >= 'a' && t->p[i] <= 'z') || (t->p[i] >= '0' && t->p[i] <= '9')
              || t->p[i] == '_'))
            return 0;
    return 1;
}

/* One line of an OBJ file: v, l and f count; the other OBJ statements are
** ignored; anything else is not OBJ, and an error, as in a scene. */
static int obj_line(parser *ps, source *src, cursor *line)
{
    char q[QUOTE_BUF];
    size_t i;
    token d;

    if (!pt_sc_next_token(line, &d))
        return 0;
    if (pt_sc_tok_is(&d, "v"))
        return do_vertex(ps, src, &d, line);
    if (pt_sc_tok_is(&d, "l"))
        return do_line(ps, src, &d, line);
    if (pt_sc_tok_is(&d, "f"))
        return do_face(ps, src, &d, line);
    for (i = 0; i < sizeof obj_unused / sizeof obj_unused[0]; i++)
        if (pt_sc_tok_is(&d, obj_unused[i]))
            return 0;
    if (src->included && !keyword_like(&d))     /* not OBJ: say so, quote none of it */
        return pt_sc_fail(ps, src, d.p, "not an OBJ statement (an OBJ file has v, l and f "
                    "lines; is this an OBJ file?)");
    return pt_sc_fail(ps, src, d.p, "unknown OBJ statement '%s'", pt_sc_shown(d.p, d.n, q));
}

/* Parse every line of src.  Returns 0 or -1. */
static int parse_source(parser *ps, source *src)
{
    cursor line;
    int r;

    while ((r = next_line(ps, src, &line)) > 0)
        if ((src->obj ? obj_line(ps, src, &line) : scene_line(ps, src, &line)) < 0)
            return -1;
    return r;
}

/* ===== checks once the whole scene is read ===== */

/* Fill in the default viewport (the whole framebuffer), or, for the matrix
** camera, check that the given one fits, now that the framebuffer size and
** the camera are final: the course's renderers (the classic camera is
** renderer 4) draw a viewport that sticks out as the course's framebuffer
** does (docs/scene-format.md), the matrix camera has no such rule.  The
** sums are at most 2 * PT_MAX_SIZE in size, so they cannot overflow. */
static int finish_viewport(parser *ps, const char *name)
{
    pt_scene *s = ps->s;

    if (ps->vp_line == 0) {
        s->vp_x = s->vp_y = 0;
        s->vp_w = s->fb_w;
        s->vp_h = s->fb_h;
        return 0;
    }
    if (s->pipe == PT_PIPE_MATRIX && !pt_scene_vp_inside(s))
        return pt_sc_fail_at(ps->err, ps->errlen, name, ps->vp_line, ps->vp_col,
                       "viewport %d %d %d %d does not fit in the %dx%d framebuffer "
                       "(the matrix camera draws only into a viewport inside it)",
                       s->vp_x, s->vp_y, s->vp_w, s->vp_h, s->fb_w, s->fb_h);
    return 0;
}

/* Check the matrix camera now that the viewport (for `auto`) is known:
** `camera lookat` and `projection` come together, and both must give a
** camera that can be built. */
static int finish_camera(parser *ps, const char *name)
{
    pt_scene *s = ps->s;
    pt_mat4 m;
    pt_cam_error e;
    int skewed;

    if ((s->pipe == PT_PIPE_MATRIX) && ps->proj_line == 0)
        return pt_sc_fail_at(ps->err, ps->errlen, name, ps->cam_line, ps->cam_col,
                       "'camera lookat' needs a 'projection perspective' line");
    if (!(s->pipe == PT_PIPE_MATRIX) && ps->proj_line != 0)
        return pt_sc_fail_at(ps->err, ps->errlen, name, ps->proj_line, ps->proj_col[0],
                       "'projection' needs a 'camera lookat' line");
    if (!(s->pipe == PT_PIPE_MATRIX) && ps->world_line != 0)
        return pt_sc_fail_at(ps->err, ps->errlen, name, ps->world_line, ps->world_col,
                       "'world' needs the matrix camera ('camera lookat'); the "
                       "classic camera places a model with 'translate'");
    if (!(s->pipe == PT_PIPE_MATRIX))
        return 0;
    if (s->aspect_auto)
        s->aspect = pt_aspect_auto(s->vp_w, s->vp_h);
    e = pt_lookat(&m, s->eye, s->dir, s->up, 0, &skewed);
    if (e != PT_CAM_OK)
        return pt_sc_fail_at(ps->err, ps->errlen, name, ps->cam_line, ps->cam_col,
                       "camera: %s", pt_cam_error_text(e));
    e = pt_perspective(&m, s->fov, s->aspect, s->znear, s->zfar);
    if (e != PT_CAM_OK)                 /* point at the number at fault */
        return pt_sc_fail_at(ps->err, ps->errlen, name, ps->proj_line,
                       ps->proj_col[e == PT_CAM_FOV || e == PT_CAM_FOV_RANGE ? 1
                                    : e == PT_CAM_ASPECT || e == PT_CAM_ASPECT_RANGE ? 2
                                    : e == PT_CAM_NEAR ? 3 : 4],
                       "projection: %s", pt_cam_error_text(e));
    return 0;
}

/* ===== a whole scene: start, parse, OBJ as a scene ===== */

/* Empty *s, then give it its defaults and a copy of name.  Returns 0, or -1
** when out of memory (*s stays empty). */
static int start_scene(pt_scene *s, const char *name)
{
    size_t n = strlen(name);

    memset(s, 0, sizeof *s);
    s->path = malloc(n + 1);
    if (s->path == NULL)
        return -1;
    memcpy(s->path, name, n + 1);
    s->fb_w = 800;
    s->fb_h = 600;
    s->perspective = 1;
    pt_sc_start_course(s);
    return 0;                           /* the viewport: see finish_viewport() */
}

static void init_parser(parser *ps, pt_scene *s, const char *dir, size_t dirlen,
                        char *err, size_t errlen)
{
    memset(ps, 0, sizeof *ps);
    ps->s = s;
    ps->dir = dir;
    ps->dirlen = dirlen;
    ps->err = err;
    ps->errlen = errlen;
}

/* Parse the scene src called name; obj paths are relative to
** name[0..dirlen). */
static int parse_scene(pt_scene *s, const char *name, size_t dirlen, source *src,
                       char *err, size_t errlen)
{
    parser ps;
    int r;

    if (start_scene(s, name) < 0)
        return pt_sc_fail_at(err, errlen, name, 1, 1, "out of memory");
    init_parser(&ps, s, name, dirlen, err, errlen);
    r = parse_source(&ps, src);
    if (r == 0 && s->nmodels > 0)
        r = pt_sc_end_model(&ps, name);
    if (r == 0)
        r = finish_viewport(&ps, name);
    if (r == 0)
        r = pt_sc_finish_course(&ps, name);
    if (r == 0)
        r = finish_camera(&ps, name);
    free(ps.model_line);
    pt_nameset_free(&ps.names);
    if (r < 0)
        pt_scene_free(s);
    return r;
}

/* The model name for a plain OBJ file: its base name without ".obj"; or "obj"
** when that is empty or would not be a valid model name (a file name may hold
** any byte; a model name is one token of valid UTF-8 without control or
** format characters, '"', '\', ',' or '#').  path ends in ".obj", any case. */
static void obj_model_name(const char *path, const char **name, size_t *n)
{
    const char *base = strrchr(path, '/');
    const unsigned char *p, *e;
    const char *why;
    size_t k;

    base = base != NULL ? base + 1 : path;
    k = strlen(base) - 4;               /* base ends in ".obj" too */
    *name = "obj";
    *n = 3;
    p = (const unsigned char *)base;
    e = p + k;
    if (k == 0)
        return;
    while (p < e) {
        if (*p >= 0x80) {
            k = utf8_len(p, (size_t)(e - p), &why);
            if (k == 0 || is_c1_control(p, k) || name_format_char(p, k) != 0)
                return;
            p += k;
        } else if (*p <= ' ' || *p == 0x7f || strchr("\"\\,#", *p) != NULL) {
            return;
        } else {
            p++;
        }
    }
    *name = base;
    *n = (size_t)(e - (const unsigned char *)base);
}

/* The translation that puts a plain OBJ model in front of the default
** perspective camera (which looks down -z onto the image plane z = -1).
** With the bounding box centre (cx,cy,cz), half extents (rx,ry,rz) and
** R = max(rx, ry), or 1 when that is 0:
**
**     translation = (-cx, -cy, -cz - rz - 2R)
**
** Afterwards the box has |x| <= rx <= R, |y| <= ry <= R, and its nearest face
** at z = -2R, so every vertex projects to x_c / -z_c, y_c / -z_c in
** [-0.5, 0.5]: centred, at most half the view.  No vertices: (0, 0, 0).
** Returns 0, or -1 when the result is not finite (coordinates near DBL_MAX). */
static int frame_obj(const pt_model *m, pt_vec3 *t)
{
    pt_vec3 lo, hi, c, r;
    double big;
    size_t i;

    t->x = t->y = t->z = 0.0;
    if (m->nv == 0)
        return 0;
    lo = hi = m->v[0];
    for (i = 1; i < m->nv; i++) {
        const pt_vec3 *v = &m->v[i];
        if (v->x < lo.x) lo.x = v->x;
        if (v->x > hi.x) hi.x = v->x;
        if (v->y < lo.y) lo.y = v->y;
        if (v->y > hi.y) hi.y = v->y;
        if (v->z < lo.z) lo.z = v->z;
        if (v->z > hi.z) hi.z = v->z;
    }
    /* Halve first: lo + hi and hi - lo may overflow, lo/2 + hi/2 cannot. */
    c.x = lo.x / 2 + hi.x / 2;
    c.y = lo.y / 2 + hi.y / 2;
    c.z = lo.z / 2 + hi.z / 2;
    r.x = hi.x / 2 - lo.x / 2;
    r.y = hi.y / 2 - lo.y / 2;
    r.z = hi.z / 2 - lo.z / 2;
    big = r.x > r.y ? r.x : r.y;
    if (!(big > 0))                     /* a point, or a segment along z */
        big = 1;
    t->x = 0.0 - c.x;                   /* 0 - c rather than -c: +0, never -0 */
    t->y = 0.0 - c.y;
    t->z = 0.0 - c.z - r.z - 2 * big;
    return isfinite(t->z) ? 0 : -1;     /* x and y are finite: c is */
}

/* Wrap the OBJ file src from path in a default scene (see frame_obj). */
static int load_obj(pt_scene *s, const char *path, source *src, char *err, size_t errlen)
{
    const char *name;
    parser ps;
    pt_vec3 t = { 0.0, 0.0, 0.0 };
    size_t n;
    int r;

    if (start_scene(s, path) < 0)
        return pt_sc_fail_at(err, errlen, path, 1, 1, "out of memory");
    init_parser(&ps, s, "", 0, err, errlen);
    obj_model_name(path, &name, &n);
    if (new_model(&ps, name, n, 1) < 0) {
        r = pt_sc_fail_at(err, errlen, path, 1, 1, "out of memory");
    } else {
        r = parse_source(&ps, src);
    }
    if (r == 0 && frame_obj(&s->models[0], &t) < 0)
        r = pt_sc_fail_at(err, errlen, path, 1, 1,
                    "coordinates too large to place the model in view");
    if (r == 0) {
        s->from_obj = 1;
        s->obj_translate = t;
        s->models[0].translate = t;
        r = finish_viewport(&ps, path);
    }
    free(ps.model_line);
    pt_nameset_free(&ps.names);
    if (r < 0)
        pt_scene_free(s);
    return r;
}

/* Does path end in ".obj", in any case? */
static int ends_with_obj(const char *path)
{
    size_t n = strlen(path);

    return n >= 4 && path[n - 4] == '.'
        && (path[n - 3] == 'o' || path[n - 3] == 'O')
        && (path[n - 2] == 'b' || path[n - 2] == 'B')
        && (path[n - 1] == 'j' || path[n - 1] == 'J');
}

/* ----------------------------------------------------------- public API */

/* ===== the public functions ===== */

int pt_scene_load(pt_scene *s, const char *path, char *err, size_t errlen)
{
    const char *slash;
    size_t dirlen;
    int errnum = 0, r;
    source src;

    memset(s, 0, sizeof *s);
    r = open_stream(&src, path, ends_with_obj(path), 0, &errnum);
    if (r == -1)
        return pt_sc_fail_at(err, errlen, path, 1, 1, "cannot read file: %s",
                       errnum != 0 ? strerror(errnum) : "read error");
    if (r == -2)
        return pt_sc_fail_at(err, errlen, path, 1, 1, "out of memory");
    if (src.obj) {
        r = load_obj(s, path, &src, err, errlen);
    } else {
        slash = strrchr(path, '/');
        dirlen = slash != NULL ? (size_t)(slash - path) + 1 : 0;
        r = parse_scene(s, path, dirlen, &src, err, errlen);
    }
    close_stream(&src);
    return r;
}

int pt_scene_read(pt_scene *s, FILE *f, const char *name, char *err, size_t errlen)
{
    int errnum = 0, r;
    source src;

    memset(s, 0, sizeof *s);
    r = start_stream(&src, f, 0, name, 0, 0, &errnum);
    if (r == -1)
        return pt_sc_fail_at(err, errlen, name, 1, 1, "cannot read: %s",
                       errnum != 0 ? strerror(errnum) : "read error");
    if (r == -2)
        return pt_sc_fail_at(err, errlen, name, 1, 1, "out of memory");
    r = parse_scene(s, name, 0, &src, err, errlen);
    close_stream(&src);
    return r;
}

int pt_scene_parse(pt_scene *s, const char *name, const char *text, size_t len,
                   char *err, size_t errlen)
{
    source src;

    if (name == NULL)
        name = "<builtin>";
    init_source(&src, name, text, len, 0, 0);
    return parse_scene(s, name, 0, &src, err, errlen);
}

int pt_scene_vp_inside(const pt_scene *s)
{
    return s->vp_x >= 0 && s->vp_y >= 0 && s->vp_x + s->vp_w <= s->fb_w &&
           s->vp_y + s->vp_h <= s->fb_h;
}

void pt_scene_free(pt_scene *s)
{
    size_t i;

    if (s == NULL)
        return;
    for (i = 0; i < s->nmodels; i++) {
        free(s->models[i].name);
        free(s->models[i].v);
        free(s->models[i].seg);
        pt_sc_free_model(&s->models[i]);
    }
    free(s->scene_name);
    free(s->models);
    for (i = 0; i < s->nobjs; i++)
        free(s->objs[i]);
    free(s->objs);
    free(s->path);
    memset(s, 0, sizeof *s);
}
