/*
** src/io/tread_text.c -- read a text trace (pipetrace's default trace format)
** See LICENSE for copyright and license.
**
** A text trace is the line "# pipetrace trace, format version 1", a header
** (framebuffer, viewport, camera, one "model" line per model with its "left
** out" lines), a blank line, the records ("NAME vN STAGE ..." and "NAME sN
** pixel|clipped|skipped ..."), and a summary whose last line starts
** "  rasterized".  Real numbers are read as written; t->prec keeps the fewest
** digits after the point seen.  Indented lines among the records (--explain)
** and the summary's lines are skipped.
*/
#include <stdlib.h>
#include <string.h>
#include "io/tread.h"
#include "io/tread_int.h"

/* Which part of the trace a line is in: r->state. */
enum { HEADER, RECORDS, SUMMARY, END };

/* ===== words and numbers ===== */

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
static int expect(pt_treader *r, cur *c, const char *s)
{
    const char *w;
    size_t n;

    if (!word(c, &w, &n) || !pt_tr_is(w, n, s)) return pt_tr_fail(r, w, "expected '%s'", s);
    return 0;
}

/* A real number as the text format writes it ("%.*f", "%.*e", nan, inf). */
static int text_real(pt_treader *r, cur *c, double *x)
{
    const char *w;
    size_t n;
    int dec;

    if (!word(c, &w, &n)) return pt_tr_fail(r, w, "expected a number");
    if (pt_tr_nonfinite(w, n, x)) return 0;
    if (pt_tr_num_len(w, w + n, &dec) != n) return pt_tr_fail(r, w, "expected a number");
    if (dec < r->t->prec) r->t->prec = dec;
    *x = strtod(w, NULL);
    return 0;
}

/* An integer word; with allow_none, "none" sets *isnull. */
static int text_int(pt_treader *r, cur *c, int64_t *x, int allow_none, int *isnull)
{
    const char *w;
    size_t n;
    int dec;

    if (!word(c, &w, &n)) return pt_tr_fail(r, w, "expected an integer");
    if (allow_none && pt_tr_is(w, n, "none")) { *isnull = 1; *x = 0; return 0; }
    if (pt_tr_num_len(w, w + n, &dec) != n || !pt_tr_is_int_token(w, n))
        return pt_tr_fail(r, w, "expected an integer%s", allow_none ? " or 'none'" : "");
    if (pt_tr_to_i64(w, x) != 0) return pt_tr_fail(r, w, "integer out of range");
    if (isnull) *isnull = 0;
    return 0;
}

/* A count in text: a non-negative integer >= lo. */
static int text_count(pt_treader *r, const char *w, size_t n, uint64_t lo, uint64_t *x)
{
    int64_t v;
    int dec;

    if (n == 0 || pt_tr_num_len(w, w + n, &dec) != n || !pt_tr_is_int_token(w, n) || *w == '-' ||
        pt_tr_to_i64(w, &v) != 0 || (uint64_t)v < lo)
        return pt_tr_fail(r, w, "expected a number >= %llu", (unsigned long long)lo);
    *x = (uint64_t)v;
    return 0;
}

/* ===== records ===== */

/* "NAME vN  STAGE  x_.. = X  y_.. = Y ...", or for a clip vertex "NAME sN
** STAGE ...": c is past the "vN" or "sN" word, sw[0..sn) the stage word. */
static int t_vertex(pt_treader *r, cur *c, uint32_t model, uint64_t vnum, int clipv,
                    const char *sw, size_t sn)
{
    const pt_stage_info *sh;
    pt_tvrec *rec;
    const char *w;
    size_t n;
    int st = pt_tr_stage_named(sw, sn), k, nul = 0;
    unsigned nulls = 0;

    if (st < 0) return pt_tr_fail(r, sw, "unknown stage '%.*s'", (int)(sn > 40 ? 40 : sn), sw);
    if (clipv && pt_tr_clipv_number(r, model, vnum, st, sw, &vnum) != 0) return -1;
    if (!(rec = pt_tr_new_vrec(r, model, vnum, st))) return -1;
    sh = &pt_stage_infos[st];
    for (k = 0; k < sh->nreal + sh->nint; k++) {
        if (expect(r, c, sh->coord[k]) || expect(r, c, "=")) return -1;
        if (sh->nreal) {
            if (text_real(r, c, &rec->u.d[k]) != 0) return -1;
        } else {
            if (text_int(r, c, &rec->u.n[k], (sh->flags & PT_REC_NULL) != 0, &nul) != 0) return -1;
            if (nul) nulls |= 1u << k;      /* null per value */
        }
    }
    rec->flags |= (unsigned char)pt_tr_null_flags(nulls, sh->flags);
    while (word(c, &w, &n)) {               /* flags; then notes and warnings */
        if (pt_tr_is(w, n, "!") || w[0] == '(') break;
        if ((sh->flags & PT_REC_BEHIND) && pt_tr_is(w, n, "behind")) {
            if (expect(r, c, "the") || expect(r, c, "camera")) return -1;
            rec->flags |= PT_REC_BEHIND;
        } else if ((sh->flags & PT_REC_INSIDE) && pt_tr_is(w, n, "inside")) {
            rec->flags |= PT_REC_INSIDE;
        } else if ((sh->flags & PT_REC_INSIDE) && pt_tr_is(w, n, "outside")) {
            ;
        } else {
            return pt_tr_fail(r, w, "unexpected '%.*s'", (int)(n > 40 ? 40 : n), w);
        }
    }
    return 0;
}

/* "NAME sN  pixel  x_fb = X  y_fb = Y  idx = I" */
static int t_pixel(pt_treader *r, cur *c, uint32_t model, uint64_t seg)
{
    pt_tpix px;
    const char *w;
    size_t n;

    memset(&px, 0, sizeof px);
    px.model = model;
    px.seg = seg;
    px.line = pt_tr_line32(r);
    if (expect(r, c, "x_fb") || expect(r, c, "=") || text_int(r, c, &px.x, 0, NULL) ||
        expect(r, c, "y_fb") || expect(r, c, "=") || text_int(r, c, &px.y, 0, NULL) ||
        expect(r, c, "idx") || expect(r, c, "=") || text_int(r, c, &px.i, 0, NULL))
        return -1;
    if (word(c, &w, &n)) return pt_tr_fail(r, w, "unexpected text after the pixel");
    return pt_tr_add_pixel(r, &px);
}

/* "NAME sN  clipped  4 steps, (x_vp, y_vp) from (-4, 2) to (-1, 2)" or
** "1 step at (x_vp, y_vp) = (-4, 2)": the count, then the integers after
** "(x_vp, y_vp)". */
static int t_clip(pt_treader *r, cur *c, uint32_t model, uint64_t seg)
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
    if (!word(c, &w, &n)) return pt_tr_fail(r, w, "expected the number of steps clipped");
    if (text_count(r, w, n, 1, &cl.count) != 0) return -1;
    want = cl.count == 1 ? 2 : 4;
    s = c->p;
    while (s < c->e && *s != ')') s++;      /* past "(x_vp, y_vp)" */
    if (s >= c->e) return pt_tr_fail(r, c->p, "expected '(x_vp, y_vp)'");
    for (s++; s < c->e; ) {
        int dec;
        size_t len;
        if ((size_t)(c->e - s) >= 4 && !memcmp(s, "none", 4)) {  /* no such value */
            if (k == want) return pt_tr_fail(r, s, "expected %d integers in the clip record", want);
            v[k++] = PT_PIX_NONE;
            s += 4;
            continue;
        }
        if (*s != '-' && (*s < '0' || *s > '9')) { s++; continue; }
        len = pt_tr_num_len(s, c->e, &dec);
        if (len == 0 || k == want || !pt_tr_is_int_token(s, len) || pt_tr_to_i64(s, &v[k]) != 0)
            return pt_tr_fail(r, s, "expected %d integers in the clip record", want);
        k++;
        s += len;
    }
    if (k != want) return pt_tr_fail(r, c->p, "expected %d integers in the clip record", want);
    cl.first[0] = v[0]; cl.first[1] = v[1];
    cl.last[0] = v[want - 2]; cl.last[1] = v[want - 1];
    return pt_tr_add_clip(r, &cl);
}

/* A record line: "NAME vN STAGE ..." or "NAME sN pixel|clipped|skipped|note ...", "NAME pN pixel ...". */
static int text_record(pt_treader *r)
{
    cur c = {r->line, r->eol};
    const char *name, *id, *kind;
    size_t nn, ni, nk;
    uint64_t num = 0;
    uint32_t model;

    if (!word(&c, &name, &nn)) return 0;
    if (!word(&c, &id, &ni) || ni < 2 || (id[0] != 'v' && id[0] != 's' && id[0] != 'p'))
        return pt_tr_fail(r, id, "expected 'vN', 'sN' or 'pN' after the model name");
    if (text_count(r, id + 1, ni - 1, 1, &num) != 0) return -1;
    if (!word(&c, &kind, &nk)) return pt_tr_fail(r, kind, "expected a stage or record kind");
    if (pt_names_intern(r->nm, name, nn, &model) != 0) return pt_tr_oom(r);
    if (id[0] == 'v') return t_vertex(r, &c, model, num, 0, kind, nk);
    if (id[0] == 'p') {                     /* a point's pixel: passed over, as the
                                            ** course's log's are (tread_kraft.c) */
        if (pt_tr_is(kind, nk, "pixel")) return 0;
        return pt_tr_fail(r, kind, "expected 'pixel' after a point's 'pN'");
    }
    if (pt_tr_is(kind, nk, "pixel")) return t_pixel(r, &c, model, num);
    if (pt_tr_is(kind, nk, "clipped")) return t_clip(r, &c, model, num);
    if (pt_tr_is(kind, nk, "skipped") || pt_tr_is(kind, nk, "note")) return 0;
    if (pt_tr_stage_named(kind, nk) >= 0) return t_vertex(r, &c, model, num, 1, kind, nk);
    return pt_tr_fail(r, kind, "unknown record '%.*s'", (int)(nk > 40 ? 40 : nk), kind);
}

/* ===== the header ===== */

/* 1 when the line starts with s. */
static int starts(const pt_treader *r, const char *s)
{
    size_t n = strlen(s);
    return (size_t)(r->eol - r->line) >= n && memcmp(r->line, s, n) == 0;
}

/* "framebuffer  W x H, ..." and "viewport     w x h at (x_ul, y_ul) = (x, y)" */
static int t_size(pt_treader *r, cur *c, int *w, int *h)
{
    int64_t a, b;
    const char *s;
    size_t n;

    if (text_int(r, c, &a, 0, NULL) || expect(r, c, "x")) return -1;
    s = c->p;
    while (s < c->e && *s == ' ') s++;
    n = 0;
    while (s + n < c->e && s[n] >= '0' && s[n] <= '9') n++;
    if (n == 0 || n > 10) return pt_tr_fail(r, s, "expected a size");
    b = strtoll(s, NULL, 10);
    c->p = s + n;
    if (a < 0 || a > 1000000000 || b > 1000000000) return pt_tr_fail(r, s, "size out of range");
    *w = (int)a;
    *h = (int)b;
    return 0;
}

/* "scene        PATH": the path escaped as in a JSON string, without the
** quotes (trace.c), which a raw control character or a bad escape breaks. */
static int text_scene(pt_treader *r)
{
    const char *s = r->line + 6;
    int k;

    while (s < r->eol && *s == ' ') s++;
    for (; s < r->eol; s++) {
        if ((unsigned char)*s < 0x20) return pt_tr_fail(r, s, "control character in the scene path");
        if (*s != '\\') continue;
        if (s + 1 < r->eol && s[1] && strchr("\"\\/bfnrt", s[1])) { s++; continue; }
        for (k = 2; k < 6 && s + k < r->eol && s[k] && strchr("0123456789abcdefABCDEF", s[k]); k++) ;
        if (s + 1 >= r->eol || s[1] != 'u' || k < 6)
            return pt_tr_fail(r, s, "bad escape in the scene path");
        s += 5;
    }
    return 0;
}

static int text_header_line(pt_treader *r)
{
    pt_thdr *h = &r->t->hdr;
    cur c = {r->line, r->eol};
    const char *w;
    size_t n;

    word(&c, &w, &n);
    if (starts(r, "  left out ")) {         /* "  left out   STAGE: why", of the last model */
        int st;
        if (!word(&c, &w, &n) || !word(&c, &w, &n) || n < 2 || w[n - 1] != ':' ||
            (st = pt_tr_stage_named(w, n - 1)) < 0)
            return pt_tr_fail(r, w, "expected 'left out   STAGE: why'");
        if (!h->nmodels) return pt_tr_fail(r, r->line, "'left out' before any 'model' line");
        h->models[h->nmodels - 1].left_out |= 1u << st;
        return 0;
    }
    if (starts(r, "scene ")) return text_scene(r);
    if (starts(r, "obj placed ") || starts(r, "  ") ||
        starts(r, "projection ") || starts(r, "view ")) return 0;  /* nothing diff needs */
    if (pt_tr_is(w, n, "framebuffer")) return t_size(r, &c, &h->fb_w, &h->fb_h);
    if (pt_tr_is(w, n, "viewport")) {
        const char *s;
        char *end;
        long long x, y;

        if (t_size(r, &c, &h->vp_w, &h->vp_h) != 0) return -1;
        for (s = c.p; s < c.e && *s != '='; s++) ;
        while (s < c.e && (*s == '=' || *s == ' ' || *s == '(')) s++;
        x = strtoll(s, &end, 10);           /* buf is NUL-terminated */
        if (end == s || end >= c.e || *end != ',') return pt_tr_fail(r, s, "expected (x_ul, y_ul)");
        s = end + 1;
        y = strtoll(s, &end, 10);
        if (end == s || end >= c.e || *end != ')' || x < -1000000000 || y < -1000000000 ||
            x > 1000000000 || y > 1000000000)
            return pt_tr_fail(r, s, "expected (x_ul, y_ul)");
        h->vp_x = (int)x;
        h->vp_y = (int)y;
        return 0;
    }
    if (pt_tr_is(w, n, "camera")) {
        if (!word(&c, &w, &n)) return pt_tr_fail(r, w, "expected the camera");
        if (pt_tr_camera(h, w, n) != 0)
            return pt_tr_fail(r, w, "expected 'perspective', 'orthographic' or 'lookat'");
        return 0;
    }
    if (pt_tr_is(w, n, "student")) {        /* a student build's stage files */
        size_t len;
        while (c.p < c.e && *c.p == ' ') c.p++;
        len = (size_t)(c.e - c.p);
        if (len >= sizeof h->student) len = sizeof h->student - 1;
        memcpy(h->student, c.p, len);
        h->student[len] = '\0';
        return 0;
    }
    if (pt_tr_is(w, n, "model")) {
        pt_tmodel *m;
        const char *name;
        int k;

        if (!word(&c, &name, &n) || n < 2 || name[n - 1] != ':')
            return pt_tr_fail(r, name, "expected 'NAME:' after 'model'");
        if (!(m = pt_tr_new_model(r))) return -1;
        m->left_known = 1;                  /* its "left out" lines follow */
        if (pt_names_intern(r->nm, name, n - 1, &m->name) != 0) return pt_tr_oom(r);
        while (word(&c, &w, &n) && !pt_tr_is(w, n, "translate")) ;
        if (n == 0) return pt_tr_fail(r, w, "expected 'translate X Y Z'");
        for (k = 0; k < 3; k++) {
            int dec;
            size_t len;
            if (!word(&c, &w, &n)) return pt_tr_fail(r, w, "expected 'translate X Y Z'");
            if (k == 2 && n > 0 && w[n - 1] == ',') n--;
            len = pt_tr_num_len(w, w + n, &dec);
            if (!pt_tr_nonfinite(w, n, &m->t[k])) {
                if (len != n) return pt_tr_fail(r, w, "expected a number");
                m->t[k] = strtod(w, NULL);
            }
        }
        return 0;
    }
    return pt_tr_fail(r, w, "unknown header line");
}

/* ===== the trace, line by line ===== */

int pt_tr_text_line(pt_treader *r)
{
    const char *p = r->line;

    if (r->lineno == 1) {
        if (!starts(r, "# pipetrace trace, format version 1") ||
            r->eol - p != (ptrdiff_t)strlen("# pipetrace trace, format version 1"))
            return pt_tr_fail(r, p + 18, "trace format version other than 1");
        r->t->hdr.have = 1;
    } else if (r->eol == p) {
        if (r->state == HEADER) r->state = RECORDS;     /* the blank line after the header */
    } else if (r->state == HEADER) {
        return text_header_line(r);
    } else if (starts(r, "summary") && r->eol - p == 7) {
        r->state = SUMMARY;
    } else if (r->state == SUMMARY && starts(r, "  rasterized ")) {
        r->state = END;                     /* the summary's last line */
    } else if (r->state == RECORDS && *p != ' ') {
        return text_record(r);
    }                                       /* else: summary lines, --explain lines */
    return 0;
}

int pt_tr_text_end(pt_treader *r)
{
    if (r->state == END) return 0;          /* a text trace ends with its summary */
    r->lineno--;                            /* cut short: point at its last line */
    return pt_tr_fail(r, r->eol, "the trace ends %s: it was cut short (a text trace ends "
                      "with its summary)", r->state == HEADER ? "inside its header"
                      : r->state == RECORDS ? "before its summary" : "inside its summary");
}
