/*
** src/io/tread_jsonl.c -- read a JSON Lines trace (--format jsonl)
** See LICENSE for copyright and license.
**
** One JSON object a line, its "type" saying what it is: "header", "vertex",
** "clipvertex", "pixel", "clip" (kept), "skip", "note" and "summary" (checked and
** ignored).  A line is checked in full and its top-level fields are noted as
** spans of the buffer (jfield), with no allocation per line; only the fields
** a record needs are then converted.  Numbers are exact: strtod() of a token
** already checked.
*/
#include <stdlib.h>
#include <string.h>
#include "io/tread.h"
#include "io/tread_int.h"

/* ===== JSON values ===== */

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
static const char *j_string(pt_treader *r, const char *p, const char *e, jval *v)
{
    const char *s = p + 1;

    v->kind = J_STR;
    v->p = s;
    while (s < e && *s != '"') {
        unsigned char c = (unsigned char)*s;
        if (c < 0x20) { pt_tr_fail(r, s, "control character in a string"); return NULL; }
        if (c == '\\') {
            s++;
            if (s >= e) break;
            if (*s == 'u') {
                int k;
                for (k = 1; k <= 4; k++)
                    if (s + k >= e || hexval(s[k]) < 0) {
                        pt_tr_fail(r, s - 1, "bad \\u escape in a string");
                        return NULL;
                    }
                s += 4;
            } else if (!strchr("\"\\/bfnrt", *s)) {
                pt_tr_fail(r, s - 1, "bad escape in a string");
                return NULL;
            }
        }
        s++;
    }
    if (s >= e) { pt_tr_fail(r, p, "string without its closing quote"); return NULL; }
    v->e = s;
    return s + 1;
}

static const char *j_value(pt_treader *r, const char *p, const char *e, jval *v, int depth);

/* The array or object starting at p; checks every item. */
static const char *j_nested(pt_treader *r, const char *p, const char *e, jval *v, int depth)
{
    char close = *p == '[' ? ']' : '}';
    const char *s = j_ws(p + 1, e);
    jval item;

    v->kind = *p == '[' ? J_ARR : J_OBJ;
    v->p = p;
    if (depth > J_MAXDEPTH) { pt_tr_fail(r, p, "nested too deeply"); return NULL; }
    if (s < e && *s == close) { v->e = s + 1; return s + 1; }
    for (;;) {
        if (close == '}') {
            if (s >= e || *s != '"') { pt_tr_fail(r, s, "expected a key in quotes"); return NULL; }
            if (!(s = j_string(r, s, e, &item))) return NULL;
            s = j_ws(s, e);
            if (s >= e || *s != ':') { pt_tr_fail(r, s, "expected ':' after the key"); return NULL; }
            s = j_ws(s + 1, e);
        }
        if (!(s = j_value(r, s, e, &item, depth + 1))) return NULL;
        s = j_ws(s, e);
        if (s < e && *s == ',') { s = j_ws(s + 1, e); continue; }
        if (s < e && *s == close) { v->e = s + 1; return s + 1; }
        pt_tr_fail(r, s, "expected ',' or '%c'", close);
        return NULL;
    }
}

/* Any JSON value at p.  Returns the byte after it, or NULL after the error. */
static const char *j_value(pt_treader *r, const char *p, const char *e, jval *v, int depth)
{
    int dec;
    size_t n;

    if (p >= e) { pt_tr_fail(r, p, "expected a value"); return NULL; }
    if (*p == '"') return j_string(r, p, e, v);
    if (*p == '[' || *p == '{') return j_nested(r, p, e, v, depth);
    v->p = p;
    if ((size_t)(e - p) >= 4 && memcmp(p, "true", 4) == 0) { v->kind = J_TRUE; n = 4; }
    else if ((size_t)(e - p) >= 5 && memcmp(p, "false", 5) == 0) { v->kind = J_FALSE; n = 5; }
    else if ((size_t)(e - p) >= 4 && memcmp(p, "null", 4) == 0) { v->kind = J_NULL; n = 4; }
    else if ((n = pt_tr_num_len(p, e, &dec)) > 0) v->kind = J_NUM;
    else { pt_tr_fail(r, p, "expected a value"); return NULL; }
    v->e = p + n;
    return p + n;
}

/* The object starting at the '{' p, checked in full in one pass; its first
** J_MAXFIELDS top-level fields go into f (later ones are checked only).
** Returns the byte after its '}', or NULL after reporting the error. */
static const char *j_object(pt_treader *r, const char *p, const char *e, jfield *f, int *nf)
{
    const char *s = j_ws(p + 1, e);

    *nf = 0;
    if (s < e && *s == '}') return s + 1;
    for (;;) {
        jval key, val;
        if (s >= e || *s != '"') { pt_tr_fail(r, s, "expected a key in quotes"); return NULL; }
        if (!(s = j_string(r, s, e, &key))) return NULL;
        s = j_ws(s, e);
        if (s >= e || *s != ':') { pt_tr_fail(r, s, "expected ':' after the key"); return NULL; }
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
        pt_tr_fail(r, s, "expected ',' or '}'");
        return NULL;
    }
}

/* The fields of the object v (already checked). */
static int j_fields(pt_treader *r, const jval *v, jfield *f, int *nf)
{
    return j_object(r, v->p, v->e, f, nf) ? 0 : -1;
}

/* The field named key, or NULL. */
static const jval *j_get(const jfield *f, int nf, const char *key)
{
    int k;

    for (k = 0; k < nf; k++) if (pt_tr_is(f[k].k, f[k].kn, key)) return &f[k].v;
    return NULL;
}

/* The next item of the array a (already checked): *pos starts at NULL.
** Returns 1 with *item, or 0 after the last. */
static int j_item(pt_treader *r, const jval *a, const char **pos, jval *item)
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
static int j_decode(pt_treader *r, const jval *v, size_t *n)
{
    size_t need = (size_t)(v->e - v->p) + 1, k = 0;
    const char *s;

    if (need > r->scap) {
        char *b = realloc(r->sbuf, need);
        if (!b) return pt_tr_oom(r);
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
            return pt_tr_fail(r, v->p - 1, "string holds \\u%04lx, which no name holds", c);
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

/* ===== records ===== */

/* Field `key` of a record: must be there. */
static const jval *need(pt_treader *r, const jfield *f, int nf, const char *key, const char *what)
{
    const jval *v = j_get(f, nf, key);

    if (!v) pt_tr_fail(r, r->line, "%s record without \"%s\"", what, key);
    return v;
}

/* A double: a number, or "nan", "inf", "-inf". */
static int jnum(pt_treader *r, const jval *v, double *x)
{
    if (v->kind == J_NUM) { *x = strtod(v->p, NULL); return 0; }
    if (v->kind == J_STR && pt_tr_nonfinite(v->p, (size_t)(v->e - v->p), x)) return 0;
    return pt_tr_fail(r, v->p, "expected a number");
}

/* An integer; with allow_null, null sets *isnull. */
static int jint(pt_treader *r, const jval *v, int64_t *x, int allow_null, int *isnull)
{
    if (allow_null && v->kind == J_NULL) { *isnull = 1; *x = 0; return 0; }
    if (v->kind != J_NUM || !pt_tr_is_int_token(v->p, (size_t)(v->e - v->p)))
        return pt_tr_fail(r, v->p, "expected an integer%s", allow_null ? " or null" : "");
    if (pt_tr_to_i64(v->p, x) != 0) return pt_tr_fail(r, v->p, "integer out of range");
    if (isnull) *isnull = 0;
    return 0;
}

/* A count: an integer >= lo. */
static int jcount(pt_treader *r, const jval *v, uint64_t lo, uint64_t *x)
{
    int64_t n;

    if (jint(r, v, &n, 0, NULL) != 0) return -1;
    if (n < 0 || (uint64_t)n < lo) return pt_tr_fail(r, v->p, "expected an integer >= %llu", (unsigned long long)lo);
    *x = (uint64_t)n;
    return 0;
}

/* The model name of a record (field "model"; in the header "name"): a
** string, interned. */
static int jmodel(pt_treader *r, const jfield *f, int nf, const char *what, uint32_t *id)
{
    const jval *v = need(r, f, nf, strcmp(what, "header model") ? "model" : "name", what);
    size_t n = 0;

    if (!v) return -1;
    if (v->kind != J_STR) return pt_tr_fail(r, v->p, "expected the model name in quotes");
    if (j_decode(r, v, &n) != 0) return -1;
    if (pt_names_intern(r->nm, r->sbuf, n, id) != 0) return pt_tr_oom(r);
    return 0;
}

/* A vertex record, or with clipv a clip-vertex record (the matrix camera's
** clipped end of a segment: "segment" instead of "v"). */
static int j_vertex(pt_treader *r, const jfield *f, int nf, int clipv)
{
    const char *what = clipv ? "clipvertex" : "vertex";
    const pt_stage_info *sh;
    const jval *v, *sv;
    pt_tvrec *rec;
    int st, k, nul = 0;
    unsigned nulls = 0;
    uint32_t model;
    uint64_t vnum;

    if (jmodel(r, f, nf, what, &model) != 0) return -1;
    if (!(v = need(r, f, nf, clipv ? "segment" : "v", what)) || jcount(r, v, 1, &vnum) != 0)
        return -1;
    if (!(sv = need(r, f, nf, "stage", what))) return -1;
    st = sv->kind == J_STR ? pt_tr_stage_named(sv->p, (size_t)(sv->e - sv->p)) : -1;
    if (st < 0) return pt_tr_fail(r, sv->p, "unknown stage");
    if (clipv && pt_tr_clipv_number(r, model, vnum, st, sv->p, &vnum) != 0) return -1;
    if (!(rec = pt_tr_new_vrec(r, model, vnum, st))) return -1;
    sh = &pt_stage_infos[st];
    for (k = 0; k < sh->nreal; k++) {
        if (!(v = need(r, f, nf, sh->key[k], what))) return -1;
        if (jnum(r, v, &rec->u.d[k]) != 0) return -1;
    }
    for (k = 0; k < sh->nint; k++) {
        if (!(v = need(r, f, nf, sh->key[k], what))) return -1;
        if (jint(r, v, &rec->u.n[k], (sh->flags & PT_REC_NULL) != 0, &nul) != 0) return -1;
        if (nul) nulls |= 1u << k;          /* null per value */
    }
    rec->flags |= (unsigned char)pt_tr_null_flags(nulls, sh->flags);
    if ((sh->flags & PT_REC_BEHIND) && (v = j_get(f, nf, "behind")) != NULL) {
        if (v->kind != J_TRUE && v->kind != J_FALSE) return pt_tr_fail(r, v->p, "expected true or false");
        if (v->kind == J_TRUE) rec->flags |= PT_REC_BEHIND;
    }
    if (sh->flags & PT_REC_INSIDE) {           /* "inside": true or false */
        if (!(v = need(r, f, nf, "inside", sh->name))) return -1;
        if (v->kind != J_TRUE && v->kind != J_FALSE) return pt_tr_fail(r, v->p, "expected true or false");
        if (v->kind == J_TRUE) rec->flags |= PT_REC_INSIDE;
    }
    return 0;
}

/* Field `key` of a `what` record, an integer, into *x.  0, or 1 after the
** error. */
static int need_int(pt_treader *r, const jfield *f, int nf, const char *key, const char *what,
                    int64_t *x)
{
    const jval *v = need(r, f, nf, key, what);

    return !v || jint(r, v, x, 0, NULL) != 0;
}

/* Field `key` of a `what` record, a count >= 1, into *x.  0, or 1 after the
** error. */
static int need_count(pt_treader *r, const jfield *f, int nf, const char *key, const char *what,
                      uint64_t *x)
{
    const jval *v = need(r, f, nf, key, what);

    return !v || jcount(r, v, 1, x) != 0;
}

static int j_pixel(pt_treader *r, const jfield *f, int nf)
{
    pt_tpix px;

    memset(&px, 0, sizeof px);
    if (!j_get(f, nf, "segment") && j_get(f, nf, "point"))
        return 0;                           /* a point's: passed over, as the course's
                                            ** log's are (tread_kraft.c) */
    if (jmodel(r, f, nf, "pixel", &px.model) != 0 ||
        need_count(r, f, nf, "segment", "pixel", &px.seg) || need_int(r, f, nf, "x", "pixel", &px.x) ||
        need_int(r, f, nf, "y", "pixel", &px.y) || need_int(r, f, nf, "i", "pixel", &px.i))
        return -1;
    px.line = pt_tr_line32(r);
    return pt_tr_add_pixel(r, &px);
}

/* A pair [x,y] of integers. */
static int jpair(pt_treader *r, const jval *v, int64_t out[2])
{
    const char *pos = NULL;
    jval item;
    int k;

    if (v->kind != J_ARR) return pt_tr_fail(r, v->p, "expected [x,y]");
    for (k = 0; k < 2; k++) {
        if (!j_item(r, v, &pos, &item)) return pt_tr_fail(r, v->p, "expected [x,y]");
        if (item.kind == J_NULL) { out[k] = PT_PIX_NONE; continue; }  /* no such value */
        if (jint(r, &item, &out[k], 0, NULL) != 0) return -1;
    }
    if (j_item(r, v, &pos, &item)) return pt_tr_fail(r, item.p, "expected [x,y]");
    return 0;
}

static int j_clip(pt_treader *r, const jfield *f, int nf)
{
    const jval *first, *last;
    pt_tclip c;

    memset(&c, 0, sizeof c);
    if (jmodel(r, f, nf, "clip", &c.model) != 0 ||
        need_count(r, f, nf, "segment", "clip", &c.seg) ||
        need_count(r, f, nf, "count", "clip", &c.count) ||
        !(first = need(r, f, nf, "first", "clip")) || jpair(r, first, c.first) != 0 ||
        !(last = need(r, f, nf, "last", "clip")) || jpair(r, last, c.last) != 0)
        return -1;
    c.npix = r->t->npx;
    return pt_tr_add_clip(r, &c);
}

/* An int field of a header object, 0 <= x <= 1e9. */
static int jsize(pt_treader *r, const jfield *f, int nf, const char *key, int *x)
{
    const jval *v = need(r, f, nf, key, "header");
    int64_t n;

    if (!v || jint(r, v, &n, 0, NULL) != 0) return -1;
    if (n < 0 || n > 1000000000) return pt_tr_fail(r, v->p, "size out of range");
    *x = (int)n;
    return 0;
}

/* The viewport's corner x or y: an int of either sign (it may lie outside
** the framebuffer). */
static int jcorner(pt_treader *r, const jfield *f, int nf, const char *key, int *x)
{
    const jval *v = need(r, f, nf, key, "header");
    int64_t n;

    if (!v || jint(r, v, &n, 0, NULL) != 0) return -1;
    if (n < -1000000000 || n > 1000000000) return pt_tr_fail(r, v->p, "corner out of range");
    *x = (int)n;
    return 0;
}

static int j_header(pt_treader *r, const jfield *f, int nf)
{
    pt_thdr *h = &r->t->hdr;
    jfield g[J_MAXFIELDS];
    const jval *v;
    const char *pos = NULL;
    jval item;
    int ng;

    if (h->have) return pt_tr_fail(r, r->line, "a second header");
    if (!(v = need(r, f, nf, "version", "header"))) return -1;
    if (v->kind != J_NUM || !pt_tr_is(v->p, (size_t)(v->e - v->p), "1"))
        return pt_tr_fail(r, v->p, "trace format version %.*s; this pipetrace reads version 1",
                          (int)(v->e - v->p > 20 ? 20 : v->e - v->p), v->p);
    if ((v = j_get(f, nf, "student")) != NULL) {   /* a student build's stage files */
        size_t len = (size_t)(v->e - v->p);
        if (v->kind != J_STR) return pt_tr_fail(r, v->p, "expected the student's files in quotes");
        if (len >= sizeof h->student) len = sizeof h->student - 1;
        memcpy(h->student, v->p, len);      /* as written: not decoded */
        h->student[len] = '\0';
    }
    if (!(v = need(r, f, nf, "framebuffer", "header"))) return -1;
    if (v->kind != J_OBJ) return pt_tr_fail(r, v->p, "expected {\"w\":W,\"h\":H}");
    if (j_fields(r, v, g, &ng) || jsize(r, g, ng, "w", &h->fb_w) || jsize(r, g, ng, "h", &h->fb_h))
        return -1;
    if (!(v = need(r, f, nf, "viewport", "header"))) return -1;
    if (v->kind != J_OBJ) return pt_tr_fail(r, v->p, "expected {\"x\":..,\"y\":..,\"w\":..,\"h\":..}");
    if (j_fields(r, v, g, &ng) || jcorner(r, g, ng, "x", &h->vp_x) || jcorner(r, g, ng, "y", &h->vp_y) ||
        jsize(r, g, ng, "w", &h->vp_w) || jsize(r, g, ng, "h", &h->vp_h))
        return -1;
    if (!(v = need(r, f, nf, "camera", "header"))) return -1;
    if (v->kind != J_STR || pt_tr_camera(h, v->p, (size_t)(v->e - v->p)) != 0)
        return pt_tr_fail(r, v->p, "expected \"perspective\", \"orthographic\" or \"lookat\"");
    if (!(v = need(r, f, nf, "models", "header"))) return -1;
    if (v->kind != J_ARR) return pt_tr_fail(r, v->p, "expected a list of models");
    while (j_item(r, v, &pos, &item)) {
        const jval *tr;
        const char *tpos = NULL;
        jval x;
        pt_tmodel *m;
        int k;

        if (item.kind != J_OBJ) return pt_tr_fail(r, item.p, "expected a model object");
        if (j_fields(r, &item, g, &ng) != 0) return -1;
        if (!(m = pt_tr_new_model(r))) return -1;
        if (jmodel(r, g, ng, "header model", &m->name) != 0) return -1;
        if ((tr = j_get(g, ng, "left_out")) != NULL) {  /* [{"stage":..,"why":..}, ..] */
            const char *lpos = NULL;
            jfield lf[J_MAXFIELDS];
            int nlf, st;
            if (tr->kind != J_ARR) return pt_tr_fail(r, tr->p, "expected a list of stages left out");
            while (j_item(r, tr, &lpos, &x)) {
                const jval *sv;
                if (x.kind != J_OBJ || j_fields(r, &x, lf, &nlf) != 0 ||
                    !(sv = j_get(lf, nlf, "stage")) || sv->kind != J_STR ||
                    (st = pt_tr_stage_named(sv->p, (size_t)(sv->e - sv->p))) < 0)
                    return pt_tr_fail(r, x.p, "expected {\"stage\":NAME,\"why\":..}");
                m->left_out |= 1u << st;
            }
            m->left_known = 1;
        }
        if (!(tr = need(r, g, ng, "translate", "header model"))) return -1;
        if (tr->kind != J_ARR) return pt_tr_fail(r, tr->p, "expected [x,y,z]");
        for (k = 0; k < 3; k++) {
            if (!j_item(r, tr, &tpos, &x)) return pt_tr_fail(r, tr->p, "expected [x,y,z]");
            if (jnum(r, &x, &m->t[k]) != 0) return -1;
        }
    }
    h->have = 1;
    return 0;
}

/* ===== the trace, line by line ===== */

int pt_tr_json_line(pt_treader *r)
{
    jfield f[J_MAXFIELDS];
    const jval *type;
    const char *s = j_ws(r->line, r->eol), *end;
    int nf;
    size_t n;

    if (s == r->eol) return 0;              /* a blank line */
    if (*s != '{') return pt_tr_fail(r, s, "expected a JSON object");
    if (!(end = j_object(r, s, r->eol, f, &nf))) return -1;
    end = j_ws(end, r->eol);
    if (end != r->eol) return pt_tr_fail(r, end, "text after the object");
    if (!(type = need(r, f, nf, "type", "a"))) return -1;
    if (type->kind != J_STR) return pt_tr_fail(r, type->p, "expected the record type in quotes");
    n = (size_t)(type->e - type->p);
    if (pt_tr_is(type->p, n, "vertex")) return j_vertex(r, f, nf, 0);
    if (pt_tr_is(type->p, n, "clipvertex")) return j_vertex(r, f, nf, 1);
    if (pt_tr_is(type->p, n, "pixel")) return j_pixel(r, f, nf);
    if (pt_tr_is(type->p, n, "clip")) return j_clip(r, f, nf);
    if (pt_tr_is(type->p, n, "header")) return j_header(r, f, nf);
    if (pt_tr_is(type->p, n, "skip") || pt_tr_is(type->p, n, "note") ||
        pt_tr_is(type->p, n, "summary"))
        return 0;
    return pt_tr_fail(r, type->p, "unknown record type '%.*s'", (int)(n > 40 ? 40 : n), type->p);
}
