/*
** src/io/tread79.c -- read the traces and logs of the course's renderers 7 and 9 back into memory
** See LICENSE for copyright and license.
**
** A line at a time, whatever the format: the JSON Lines and CSV traces have
** one record a line; the text trace one vertex or pixel a line; the course's
** log one vertex of one stage's list ("1. View : vIndex = 0, (x,y,z) = (..)"),
** one colour ("cIndex = 0, java.awt.Color[r=..,g=..,b=..]") or one step of
** the rasterizer ("fb_[..] vp_[..] (x_pp=.., y_pp=..) (x_vp=.., y_vp=..)
** r=.. g=.. b=..", or with anti-aliasing the step's two pixels) a line.
** Numbers are read with strtod in the "C" locale (pipetrace never calls
** setlocale).  See tread79.h.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/tread79.h"

static const char *const stage_names[PT_T79_NSTAGES] = {
    "model", "world", "view", "camera", "nearclip", "image", "clip"
};

const char *pt_t79_stage_name(int st)
{
    return st >= 0 && st < PT_T79_NSTAGES ? stage_names[st] : "?";
}

/* ===== telling them apart ===== */

/* 1 when s occurs in buf[0..n). */
static int occurs(const char *buf, size_t n, const char *s)
{
    size_t k = strlen(s), i;
    for (i = 0; i + k <= n; i++)
        if (buf[i] == s[0] && !memcmp(buf + i, s, k)) return 1;
    return 0;
}

int pt_t79_renderer(const char *buf, size_t len)
{
    static const char bad[] = "FrameBuffer: Bad pixel coordinate (";
    char head[1024];
    const char *p;
    size_t n;

    while (len >= sizeof bad - 1 && !memcmp(buf, bad, sizeof bad - 1) &&
           (p = memchr(buf, '\n', len)) != NULL) {     /* the viewport's clearing's */
        len -= (size_t)(p + 1 - buf);
        buf = p + 1;
    }
    n = len < sizeof head - 1 ? len : sizeof head - 1;
    memcpy(head, buf, n);
    head[n] = '\0';
    if (head[0] == '{' && (p = strstr(head, "\"renderer\":")) != NULL) return atoi(p + 11);
    if (!strncmp(head, "# pipetrace trace of a course renderer's scene", 46) &&
        (p = strstr(head, "\nrenderer ")) != NULL) return atoi(p + 10);
    if (!strncmp(head, "model,position,v,stage,", 23)) {   /* renderer 9's has a world stage */
        for (p = buf; (size_t)(buf + len - p) >= 7; p++)
            if (*p == ',' && !memcmp(p, ",world,", 7)) return 9;
        return 7;
    }
    if (strstr(head, "Rendering of Scene (Pipeline ")) return 9;
    if (strstr(head, "\n-- Current Camera:\nCamera: \n  perspective = ")) return 7;
    if (!strncmp(head, "==== 1. Render position: ", 25)) return 9;     /* Pipeline2, no scene.debug */
    if (!strncmp(head, "==== Render position: ", 22)) {   /* no scene.debug: renderer 4's too */
        n = len < ((size_t)1 << 16) ? len : (size_t)1 << 16;
        if (occurs(buf, n, "\n1. View ")) return 7;
        if (occurs(buf, n, "\n1. World ")) return 9;
    }
    return 0;
}

/* 1 when x is a whole number in lo .. hi (not NaN). */
static int whole(double x, double lo, double hi)
{
    return x >= lo && x <= hi && x == floor(x);
}

#define PT_T79_BIG 9007199254740992.0   /* 2^53: a pixel's coordinates stay below */

/* ===== growing the arrays ===== */

static pt_t79v *new_vertex(pt_t79 *t)
{
    if (t->nvx == t->cap_vx) {
        size_t cap = t->cap_vx ? 2 * t->cap_vx : 256;
        pt_t79v *p = realloc(t->vx, cap * sizeof *p);
        if (!p) return NULL;
        t->vx = p;
        t->cap_vx = cap;
    }
    memset(&t->vx[t->nvx], 0, sizeof t->vx[0]);
    return &t->vx[t->nvx++];
}

static pt_t79px *new_pixel(pt_t79 *t)
{
    if (t->npx == t->cap_px) {
        size_t cap = t->cap_px ? 2 * t->cap_px : 1024;
        pt_t79px *p = realloc(t->px, cap * sizeof *p);
        if (!p) return NULL;
        t->px = p;
        t->cap_px = cap;
    }
    memset(&t->px[t->npx], 0, sizeof t->px[0]);
    return &t->px[t->npx++];
}

static pt_t79prim *new_prim(pt_t79 *t)
{
    if (t->npr == t->cap_pr) {
        size_t cap = t->cap_pr ? 2 * t->cap_pr : 64;
        pt_t79prim *p = realloc(t->pr, cap * sizeof *p);
        if (!p) return NULL;
        t->pr = p;
        t->cap_pr = cap;
    }
    memset(&t->pr[t->npr], 0, sizeof t->pr[0]);
    t->pr[t->npr].seq = t->npr;
    return &t->pr[t->npr++];
}

void pt_t79_free(pt_t79 *t)
{
    free(t->pr);
    free(t->vx);
    free(t->px);
    memset(t, 0, sizeof *t);
}

/* ===== small readers ===== */

/* The parser's place: the line [p, e), its number. */
typedef struct lctx {
    pt_t79 *t;
    pt_names *nm;
    const char *path;
    char *err;
    size_t errlen;
    uint32_t line;
} lctx;

static int fail(lctx *c, const char *what)
{
    snprintf(c->err, c->errlen, "%s:%lu:1: error: %s", c->path, (unsigned long)c->line, what);
    return -1;
}

/* The stage named s[0..n), or -1. */
static int stage_of(const char *s, size_t n)
{
    int k;
    for (k = 0; k < PT_T79_NSTAGES; k++)
        if (strlen(stage_names[k]) == n && !memcmp(s, stage_names[k], n)) return k;
    return -1;
}

/* A number at *p (blanks first skipped) into *x; *p moves past it.  Returns 0, or -1. */
static int num(const char **p, const char *e, double *x)
{
    char *end;
    while (*p < e && (**p == ' ' || **p == '\t')) (*p)++;
    if (*p >= e) return -1;
    *x = strtod(*p, &end);
    if (end == *p || end > e) return -1;
    *p = end;
    return 0;
}

/* Where key (with its quotes and colon, "\"x\":") starts its value in [p, e), or NULL. */
static const char *jkey(const char *p, const char *e, const char *key)
{
    size_t n = strlen(key);
    for (; p + n <= e; p++)
        if (*p == key[0] && !memcmp(p, key, n)) return p + n;
    return NULL;
}

/* A JSON number after key into *x.  Returns 0, or -1. */
static int jnum(const char *p, const char *e, const char *key, double *x)
{
    const char *v = jkey(p, e, key);
    return v ? num(&v, e, x) : -1;
}

/* A JSON string after key: its raw text [*s, *s + *n).  Returns 0, or -1. */
static int jstr(const char *p, const char *e, const char *key, const char **s, size_t *n)
{
    const char *v = jkey(p, e, key), *q;
    if (!v || v >= e || *v != '"') return -1;
    for (q = v + 1; q < e && *q != '"'; q++)
        if (*q == '\\') q++;
    if (q >= e) return -1;
    *s = v + 1;
    *n = (size_t)(q - v - 1);
    return 0;
}

/* Three numbers of a JSON array after key into x[0..2].  Returns 0, or -1. */
static int jtriple(const char *p, const char *e, const char *key, double *x)
{
    const char *v = jkey(p, e, key);
    int k;
    if (!v || v >= e || *v != '[') return -1;
    v++;
    for (k = 0; k < 3; k++) {
        if (num(&v, e, &x[k]) != 0) return -1;
        if (v < e && *v == ',') v++;
    }
    return 0;
}

static int jbool(const char *p, const char *e, const char *key)
{
    const char *v = jkey(p, e, key);
    if (!v) return -1;
    return v + 4 <= e && !memcmp(v, "true", 4);
}

static void unread(pt_t79 *t, uint32_t line)
{
    if (!t->unread++) t->unread_line = line;
}

/* ===== JSON Lines ===== */

static int jsonl_line(lctx *c, const char *p, const char *e)
{
    pt_t79 *t = c->t;
    const char *s;
    size_t n;
    double x;

    if (jstr(p, e, "\"type\":", &s, &n) != 0) { unread(t, c->line); return 0; }
    if (n == 6 && !memcmp(s, "header", 6)) {
        const char *cam = jkey(p, e, "\"camera\":");
        if (jnum(p, e, "\"renderer\":", &x) == 0 && whole(x, 0, 99)) t->renderer = (int)x;
        if (cam) {
            const char *ps;
            size_t pn;
            t->have_cam = jnum(cam, e, "\"l\":", &t->l) == 0 && jnum(cam, e, "\"r\":", &t->r) == 0 &&
                          jnum(cam, e, "\"b\":", &t->b) == 0 && jnum(cam, e, "\"t\":", &t->t) == 0 &&
                          jnum(cam, e, "\"n\":", &t->n) == 0 &&
                          jstr(cam, e, "\"projection\":", &ps, &pn) == 0;
            if (t->have_cam) t->persp = pn == 11 && !memcmp(ps, "perspective", 11);
        }
        t->aa = jbool(p, e, "\"antialias\":");
        t->gamma = jbool(p, e, "\"gamma\":");
        return 0;
    }
    if (n == 6 && !memcmp(s, "vertex", 6)) {
        pt_t79v *v;
        const char *ss;
        size_t sn;
        int st;
        uint32_t id;
        if (jstr(p, e, "\"stage\":", &ss, &sn) != 0 || (st = stage_of(ss, sn)) < 0)
            return fail(c, "a vertex record without a stage of renderer 7 or 9");
        if (jstr(p, e, "\"position\":", &s, &n) != 0 && jstr(p, e, "\"model\":", &s, &n) != 0)
            return fail(c, "a vertex record without a position");
        if (pt_names_intern(c->nm, s, n, &id) != 0 || !(v = new_vertex(t))) return -2;
        v->pos = id;
        v->st = (unsigned char)st;
        v->line = c->line;
        if (jnum(p, e, "\"v\":", &x) != 0 || x < 1 || x > 4e9 || x != floor(x))
            return fail(c, "a vertex record without its number v");
        v->v = (uint32_t)x;
        if (jnum(p, e, "\"x\":", &v->x[0]) || jnum(p, e, "\"y\":", &v->x[1]) ||
            jnum(p, e, "\"z\":", &v->x[2]))
            return fail(c, "a vertex record without x, y and z");
        v->has_w = jnum(p, e, "\"w\":", &v->x[3]) == 0;
        v->has_rgb = jtriple(p, e, "\"color\":", v->rgb) == 0;
        return 0;
    }
    if (n == 5 && !memcmp(s, "pixel", 5)) {
        pt_t79px *q;
        double px, py, rgb[3];
        if (jnum(p, e, "\"x\":", &px) || jnum(p, e, "\"y\":", &py) || jtriple(p, e, "\"rgb\":", rgb) ||
            !whole(px, -PT_T79_BIG, PT_T79_BIG) || !whole(py, -PT_T79_BIG, PT_T79_BIG))
            return fail(c, "a pixel record without x, y and rgb");
        if (!(q = new_pixel(t))) return -2;
        q->x = (int64_t)px;
        q->y = (int64_t)py;
        for (n = 0; n < 3; n++) q->rgb[n] = rgb[n] / 255.0;
        q->line = c->line;
        if (jnum(p, e, "\"coverage\":", &q->cov) != 0) q->cov = -1;
        if (jnum(p, e, "\"primitive\":", &x) == 0 && whole(x, 0, 4e9)) q->prim = (uint32_t)x;
        if (jstr(p, e, "\"position\":", &s, &n) == 0 && pt_names_intern(c->nm, s, n, &q->pos) != 0)
            return -2;
        t->raster = 1;
        return 0;
    }
    if (n == 9 && !memcmp(s, "primitive", 9)) {   /* after its pixels: a line's last one */
        const char *k;
        size_t kn;
        uint32_t id;
        if (t->npx && jstr(p, e, "\"kind\":", &k, &kn) == 0 && kn == 4 && !memcmp(k, "line", 4) &&
            jnum(p, e, "\"primitive\":", &x) == 0 && whole(x, 0, 4e9) &&
            jstr(p, e, "\"position\":", &s, &n) == 0) {
            if (pt_names_intern(c->nm, s, n, &id) != 0) return -2;
            if (t->px[t->npx - 1].prim == (uint32_t)x && t->px[t->npx - 1].pos == id)
                t->px[t->npx - 1].seg_end = 1;
        }
        return 0;
    }
    return 0;                   /* summary, warnings: not compared */
}

/* ===== the text trace ===== */

/* The next blank-separated word of [*p, e) into [*s, *s + *n).  Returns 0, or -1 at the end. */
static int word(const char **p, const char *e, const char **s, size_t *n)
{
    while (*p < e && (**p == ' ' || **p == '\t')) (*p)++;
    if (*p >= e) return -1;
    *s = *p;
    while (*p < e && **p != ' ' && **p != '\t') (*p)++;
    *n = (size_t)(*p - *s);
    return 0;
}

/* After "key =" in [p, e), a number into *x.  Returns 0, or -1. */
static int tval(const char *p, const char *e, const char *key, double *x)
{
    const char *v = jkey(p, e, key);
    return v ? num(&v, e, x) : -1;
}

/* The number of a text trace's "pN" (0 when it is none). */
static uint32_t prim_number(const char *w)
{
    double x = strtod(w + 1, NULL);
    return whole(x, 0, 4e9) ? (uint32_t)x : 0;
}

static int text_line(lctx *c, const char *p, const char *e)
{
    pt_t79 *t = c->t;
    const char *s, *q = p, *w2, *w3;
    size_t n, n2, n3;
    double x;
    int st;

    if (p == e || *p == '#') return 0;
    if (word(&q, e, &s, &n) != 0) return 0;
    if (n == 8 && !memcmp(s, "renderer", 8)) {
        if (num(&q, e, &x) == 0 && whole(x, 0, 99)) t->renderer = (int)x;
        return 0;
    }
    if (n == 6 && !memcmp(s, "camera", 6)) {
        const char *v = jkey(q, e, "l r b t = ");
        t->persp = jkey(q, e, "perspective") != NULL;
        t->have_cam = v && num(&v, e, &t->l) == 0 && num(&v, e, &t->r) == 0 &&
                      num(&v, e, &t->b) == 0 && num(&v, e, &t->t) == 0 &&
                      tval(q, e, "n = ", &t->n) == 0;
        return 0;
    }
    if (n == 8 && !memcmp(s, "switches", 8)) {
        t->aa = jkey(q, e, "antialias on") != NULL;
        t->gamma = jkey(q, e, "gamma on") != NULL;
        return 0;
    }
    if ((n == 5 && !memcmp(s, "scene", 5)) || (n == 11 && !memcmp(s, "framebuffer", 11)) ||
        (n == 8 && !memcmp(s, "viewport", 8)) || (n == 7 && !memcmp(s, "summary", 7)) ||
        (n == 6 && !memcmp(s, "models", 6)))
        return 0;
    if (word(&q, e, &w2, &n2) != 0 || word(&q, e, &w3, &n3) != 0 || n2 < 2 ||
        (w2[0] != 'v' && w2[0] != 'p')) {
        unread(t, c->line);
        return 0;
    }
    if (w2[0] == 'v' && (st = stage_of(w3, n3)) >= 0) {
        pt_t79v *v;
        uint32_t id;
        x = strtod(w2 + 1, NULL);
        if (!whole(x, 1, 4e9)) return fail(c, "a vertex line without its number");
        if (pt_names_intern(c->nm, s, n, &id) != 0 || !(v = new_vertex(t))) return -2;
        v->pos = id;
        v->v = (uint32_t)x;
        v->st = (unsigned char)st;
        v->line = c->line;
        if (tval(q, e, " x = ", &v->x[0]) || tval(q, e, " y = ", &v->x[1]) ||
            tval(q, e, " z = ", &v->x[2]))
            return fail(c, "a vertex line without x, y and z");
        v->has_w = tval(q, e, " w = ", &v->x[3]) == 0;
        {
            const char *r = jkey(q, e, "rgb = ");
            v->has_rgb = r && num(&r, e, &v->rgb[0]) == 0 && num(&r, e, &v->rgb[1]) == 0 &&
                         num(&r, e, &v->rgb[2]) == 0;
        }
        return 0;
    }
    if (w2[0] == 'p' && n3 == 5 && !memcmp(w3, "pixel", 5)) {
        pt_t79px *px;
        double fx, fy, rgb[3];
        int k;
        const char *r = jkey(q, e, "rgb = ");
        if (tval(q, e, "x_fb = ", &fx) || tval(q, e, "y_fb = ", &fy) || !r ||
            num(&r, e, &rgb[0]) || num(&r, e, &rgb[1]) || num(&r, e, &rgb[2]) ||
            !whole(fx, -PT_T79_BIG, PT_T79_BIG) || !whole(fy, -PT_T79_BIG, PT_T79_BIG))
            return fail(c, "a pixel line without x_fb, y_fb and rgb");
        if (!(px = new_pixel(t))) return -2;
        px->x = (int64_t)fx;
        px->y = (int64_t)fy;
        for (k = 0; k < 3; k++) px->rgb[k] = rgb[k] / 255.0;
        px->line = c->line;
        if (tval(q, e, "coverage ", &px->cov) != 0) px->cov = -1;
        px->prim = prim_number(w2);
        if (pt_names_intern(c->nm, s, n, &px->pos) != 0) return -2;
        t->raster = 1;
        return 0;
    }
    if (w2[0] == 'p' && n3 == 5 && !memcmp(w3, "drawn", 5) && t->npx) {  /* a line's last pixel */
        const char *k;
        size_t kn;
        uint32_t id;
        if (pt_names_intern(c->nm, s, n, &id) != 0) return -2;
        if (word(&q, e, &k, &kn) == 0 && kn == 4 && !memcmp(k, "line", 4) &&
            t->px[t->npx - 1].pos == id && t->px[t->npx - 1].prim == prim_number(w2))
            t->px[t->npx - 1].seg_end = 1;
        return 0;
    }
    if (w2[0] == 'p') return 0;     /* skipped, clipped: the pixels say it */
    unread(t, c->line);
    return 0;
}

/* ===== the CSV trace ===== */

static int csv_line(lctx *c, const char *p, const char *e)
{
    const char *f[11];
    size_t fn[11];
    int k, st;
    pt_t79v *v;
    uint32_t id;
    double x;

    if (c->line == 1) return 0;
    for (k = 0; k < 11; k++) {
        f[k] = p;
        while (p < e && *p != ',') p++;
        fn[k] = (size_t)(p - f[k]);
        if (p < e) p++;
        else if (k < 10) return fail(c, "a CSV row of fewer than 11 fields");
    }
    if ((st = stage_of(f[3], fn[3])) < 0) return fail(c, "a CSV row without a stage");
    if (pt_names_intern(c->nm, f[1], fn[1], &id) != 0 || !(v = new_vertex(c->t))) return -2;
    v->pos = id;
    v->st = (unsigned char)st;
    v->line = c->line;
    x = strtod(f[2], NULL);
    if (!whole(x, 1, 4e9)) return fail(c, "a CSV row without its vertex number");
    v->v = (uint32_t)x;
    for (k = 0; k < 4; k++) {
        const char *q = f[4 + k];
        if (fn[4 + k] == 0) { if (k < 3) return fail(c, "a CSV row without x, y and z"); continue; }
        if (num(&q, f[4 + k] + fn[4 + k], &v->x[k]) != 0) return fail(c, "a CSV number unread");
        if (k == 3) v->has_w = 1;
    }
    v->has_rgb = 1;
    for (k = 0; k < 3; k++) {
        const char *q = f[8 + k];
        if (!fn[8 + k] || num(&q, f[8 + k] + fn[8 + k], &v->rgb[k]) != 0) v->has_rgb = 0;
    }
    return 0;
}

/* ===== the course's log ===== */

/* Where the log is: the stage list being read, and how many each stage listed. */
typedef struct logst {
    uint32_t pos;                /* the position being rendered */
    int have_pos;
    int line_prim;               /* 1: the pixels since line_px are a segment's */
    size_t line_px;              /* pixels read when its Rasterize line came */
} logst;

static int starts(const char *p, const char *e, const char *s)
{
    size_t n = strlen(s);
    return (size_t)(e - p) >= n && !memcmp(p, s, n);
}

/* 1 when [w, e) starts with the word s, then a blank or a colon. */
static int word_is(const char *w, const char *e, const char *s)
{
    size_t n = strlen(s);
    return (size_t)(e - w) > n && !memcmp(w, s, n) && (w[n] == ' ' || w[n] == ':');
}

/* The stage a log's "N. Word" names, with its list's vIndex/cIndex lines, or
** -1 (the clip stages' "Near_Clipping", "Clipped (accept)" blocks). */
static int log_stage(const char *w, const char *e)
{
    static const char *const word[PT_T79_NSTAGES] = {
        "Model", "World", "View", "Camera", "Near_Clipped", "Projected", "Clipped"
    };
    int st;
    for (st = 0; st < PT_T79_NSTAGES; st++)
        if (word_is(w, e, word[st]) && !starts(w + strlen(word[st]), e, " (")) return st;
    return -1;
}

/* -1, 0, 1 as a sorts before, with, after b by (position, stage, vertex). */
static int key_order(const pt_t79v *a, const pt_t79v *b)
{
    if (a->pos != b->pos) return a->pos < b->pos ? -1 : 1;
    if (a->st != b->st) return a->st < b->st ? -1 : 1;
    return a->v < b->v ? -1 : a->v > b->v;
}

static const pt_t79 *sort_t;     /* qsort's comparison has no context argument */

static int cmp_key(const void *a, const void *b)
{
    return key_order(&sort_t->vx[*(const size_t *)a], &sort_t->vx[*(const size_t *)b]);
}

/* The stage whose list the clip stage st extends (its old vertices), or -1. */
static int before(int st)
{
    return st == PT_T79_NEARCLIP ? PT_T79_CAMERA : st == PT_T79_CLIP ? PT_T79_IMAGE : -1;
}

static int log_vertex(lctx *c, logst *g, int st, const char *p, const char *e)
{
    pt_t79 *t = c->t;
    const char *q = jkey(p, e, "vIndex =");
    double k, x[4];
    int n = 0;
    pt_t79v *v;

    if (!q || num(&q, e, &k) != 0 || !whole(k, 0, 4e9)) return fail(c, "a vIndex line unread");
    q = jkey(q, e, "=");
    if (!q) return fail(c, "a vIndex line without its coordinates");
    while (q < e && (*q == ' ' || *q == '(')) q++;
    while (n < 4 && num(&q, e, &x[n]) == 0) n++;
    if (n < 3) return fail(c, "a vIndex line without x, y and z");
    if (!(v = new_vertex(t))) return -2;       /* an old one listed again: old_again() */
    v->pos = g->pos;
    v->v = (uint32_t)k + 1;
    v->st = (unsigned char)st;
    v->line = c->line;
    memcpy(v->x, x, sizeof x);
    v->has_w = n == 4;
    return 0;
}

/* A colour byte after key ("r=") into *x (0 .. 1).  Returns 0, or -1. */
static int log_byte(const char *p, const char *e, const char *key, double *x)
{
    double b;
    if (jnum(p, e, key, &b) != 0) return -1;
    *x = b / 255.0;
    return 0;
}

static int log_color(lctx *c, logst *g, int st, const char *p, const char *e)
{
    pt_t79 *t = c->t;
    const char *q = jkey(p, e, "cIndex =");
    double k, rgb[3];
    size_t i;

    if (!q || num(&q, e, &k) != 0 || !whole(k, 0, 4e9)) return fail(c, "a cIndex line unread");
    if (log_byte(q, e, "r=", &rgb[0]) || log_byte(q, e, "g=", &rgb[1]) || log_byte(q, e, "b=", &rgb[2]))
        return fail(c, "a cIndex line without its colour");
    for (i = t->nvx; i-- > 0 && t->vx[i].st == st && t->vx[i].pos == g->pos;) {
        pt_t79v *v = &t->vx[i];                 /* the stage's list, just read */
        if (v->v == (uint32_t)k + 1) {
            memcpy(v->rgb, rgb, sizeof rgb);
            v->has_rgb = 1;
            return 0;
        }
    }
    return 0;
}

/* A primitive of the list entering a clip stage: "LineSegment: ([0, 1], [0, 1])"
** or "Point: ([0], [0]) radius = 2". */
static int log_prim(lctx *c, logst *g, int st, const char *p, const char *e)
{
    const char *q;
    double a[4], r = 0;
    pt_t79prim *pr;
    int point, k, n;

    if ((q = jkey(p, e, "LineSegment: ([")) != NULL) point = 0;
    else if ((q = jkey(p, e, "Point: ([")) != NULL) point = 1;
    else return 0;
    n = point ? 2 : 4;
    for (k = 0; k < n; k++) {
        while (q < e && (*q == ',' || *q == ' ' || *q == ']' || *q == '[')) q++;
        if (num(&q, e, &a[k]) != 0 || !whole(a[k], 0, 4e9)) return fail(c, "a primitive unread");
    }
    if (point && (jnum(q, e, "radius =", &r) != 0 || !whole(r, 0, 1e9)))
        return fail(c, "a point without its radius");
    if (!(pr = new_prim(c->t))) return -2;
    pr->pos = g->pos;
    pr->st = (unsigned char)st;
    pr->point = (unsigned char)point;
    pr->v[0] = (uint32_t)a[0];
    pr->v[1] = point ? pr->v[0] : (uint32_t)a[1];
    pr->c[0] = (uint32_t)a[point ? 1 : 2];
    pr->c[1] = point ? pr->c[0] : (uint32_t)a[3];
    pr->radius = (int)r;
    return 0;
}

/* One pixel of a log's pixel line. */
static int log_pixel(lctx *c, int64_t x, int64_t y, const char *p, const char *e, int pair)
{
    pt_t79px *q;

    if (!(q = new_pixel(c->t))) return -2;
    q->x = x;
    q->y = y;
    q->cov = -1;
    q->line = c->line;
    if (jnum(p, e, "r=", &q->rgb[0]) || jnum(p, e, "g=", &q->rgb[1]) || jnum(p, e, "b=", &q->rgb[2]))
        return fail(c, "a pixel line without its colour");
    if (pair) {                 /* the second of a step's two */
        q->pair = (uint32_t)(c->t->npx - 1);
        c->t->px[c->t->npx - 2].pair = (uint32_t)c->t->npx;
    }
    c->t->raster = 1;
    return 0;
}

/* 1 when a log's three pixel coordinates are whole and far from overflowing. */
static int in_range(double a, double b, double b2)
{
    double m = PT_T79_BIG / 2;
    return whole(a, -m, m) && whole(b, -m, m) && whole(b2, -m, m);
}

static int log_pixel_line(lctx *c, const char *p, const char *e)
{
    double vx, vy, a, b, b2;
    const char *q, *lo, *hi;
    int rc;

    if ((size_t)(e - p) > 9 && !memcmp(e - 9, ": Clipped", 9))
        return 0;                               /* a point's pixel outside: not written */
    if (jnum(p, e, "vp_[x=", &vx) || jnum(p, e, ", y=", &vy) || !whole(vx, -1e9, 1e9) ||
        !whole(vy, -1e9, 1e9))
        return fail(c, "a pixel line without its viewport");
    if ((q = jkey(p, e, "(x_vp=")) != NULL) {
        if (num(&q, e, &a) || !(q = jkey(q, e, "y_vp=")) || num(&q, e, &b) ||
            !whole(a, -PT_T79_BIG / 2, PT_T79_BIG / 2) || !whole(b, -PT_T79_BIG / 2, PT_T79_BIG / 2))
            return fail(c, "a pixel line without x_vp and y_vp");
        return log_pixel(c, (int64_t)(vx + a), (int64_t)(vy + b), q, e, 0);
    }
    if ((q = jkey(p, e, "  x_vp=")) != NULL && (lo = jkey(q, e, "{y_low=")) != NULL &&
        (hi = jkey(q, e, "{y_hi =")) != NULL) {
        if (num(&q, e, &a) || num(&lo, e, &b) || num(&hi, e, &b2) || !in_range(a, b, b2))
            return fail(c, "an anti-aliased pixel line unread");
        rc = log_pixel(c, (int64_t)(vx + a), (int64_t)(vy + b), lo, hi, 0);
        return rc ? rc : log_pixel(c, (int64_t)(vx + a), (int64_t)(vy + b2), hi, e, 1);
    }
    if ((q = jkey(p, e, "  y_vp=")) != NULL && (lo = jkey(q, e, "{x_low=")) != NULL &&
        (hi = jkey(q, e, "{x_hi =")) != NULL) {
        if (num(&q, e, &b) || num(&lo, e, &a) || num(&hi, e, &b2) || !in_range(a, b, b2))
            return fail(c, "an anti-aliased pixel line unread");
        rc = log_pixel(c, (int64_t)(vx + a), (int64_t)(vy + b), lo, hi, 0);
        return rc ? rc : log_pixel(c, (int64_t)(vx + b2), (int64_t)(vy + b), hi, e, 1);
    }
    return fail(c, "a pixel line of no form read here");
}

/* The log's words that start lines diff reads past (their numbers follow
** from the lines it compares). */
static const char *const log_known[] = {
    "==", "--", "Camera: ", "  perspective", "  left", "  bottom", "  near", "  (fovy",
    "   vIndex", "   cIndex", "Slope", "(x", "Normalization Matrix", "Translation Vector",
    "[[", " [", "  [x,y,z,w]", "Clip", "Near_Clip", "\t", "    ", "= Begin Rendering",
    "= End Rendering", "- Current Camera:", "FrameBuffer: Bad pixel coordinate ("
};

/* The clip stages' lists in a log repeat the old vertices: drop a record at
** the near clip (the rectangle clip) that the camera (image) stage has too. */
static int old_again(pt_t79 *t)
{
    size_t *ix = malloc((t->nvx + 1) * sizeof *ix), i, j = 0;
    if (!ix) return -2;
    for (i = 0; i < t->nvx; i++) ix[i] = i;
    sort_t = t;
    qsort(ix, t->nvx, sizeof *ix, cmp_key);
    for (i = 0; i < t->nvx; i++) {
        const pt_t79v *v = &t->vx[i];
        pt_t79v key = *v;
        size_t lo = 0, hi = t->nvx;
        int b = before(v->st), found = 0;
        if (b >= 0) {
            key.st = (unsigned char)b;
            while (lo < hi && !found) {
                size_t mid = lo + (hi - lo) / 2;
                int r = key_order(&t->vx[ix[mid]], &key);
                if (r == 0) found = 1; else if (r < 0) lo = mid + 1; else hi = mid;
            }
        }
        if (!found) t->vx[j++] = *v;
    }
    t->nvx = j;
    free(ix);
    return 0;
}

/* The segment being rasterized is done: its last pixel has no gamma. */
static void end_segment(pt_t79 *t, logst *g)
{
    if (g->line_prim && t->npx > g->line_px) t->px[t->npx - 1].seg_end = 1;
    g->line_prim = 0;
}

static int log_line(lctx *c, logst *g, const char *p, const char *e)
{
    pt_t79 *t = c->t;
    const char *q;
    size_t k;

    if (p == e) return 0;
    if (starts(p, e, "====")) {                 /* whose vertices follow */
        /* "Render position: P", Pipeline 1's "Render model: M" under it, and
        ** Pipeline 2's "Transform model: P::M" (Near_Clip, Project, Clip,
        ** Rasterize: each stage for every position in turn) */
        int w = (q = jkey(p, e, "Render position: ")) != NULL ? 0 :
                (q = jkey(p, e, "Render model: ")) != NULL ? 2 :
                (q = jkey(p, e, " model: ")) != NULL ? 1 : 3;
        if (w < 3 && !(w == 2 && g->have_pos)) {        /* a model: its position's name */
            const char *f = e, *m;
            uint32_t id;
            while (f > q && (f[-1] == '=' || f[-1] == ' ')) f--;
            for (m = q; m + 1 < f; m++)         /* Pipeline2's "POSITION::MODEL" */
                if (m[0] == ':' && m[1] == ':') { f = m; break; }
            if (pt_names_intern(c->nm, q, (size_t)(f - q), &id) != 0) return -2;
            g->pos = id;
            g->have_pos = w < 2;
            return 0;
        }
        if (w < 3) return 0;
    }
    if (starts(p, e, "====") && jkey(p, e, "End position:")) { g->have_pos = 0; return 0; }
    if (starts(p, e, "  perspective = ")) { t->persp = p[16] == 't'; t->have_cam = 1; return 0; }
    if (starts(p, e, "  left = ")) {
        if (jnum(p, e, "left = ", &t->l) || jnum(p, e, "right = ", &t->r)) return fail(c, "left, right unread");
        return 0;
    }
    if (starts(p, e, "  bottom = ")) {
        if (jnum(p, e, "bottom = ", &t->b) || jnum(p, e, "top = ", &t->t)) return fail(c, "bottom, top unread");
        return 0;
    }
    if (starts(p, e, "  near = ")) {
        if (jnum(p, e, "near = ", &t->n)) return fail(c, "near unread");
        t->n = -t->n;
        return 0;
    }
    if (starts(p, e, "fb_[")) return log_pixel_line(c, p, e);
    if (p[0] >= '0' && p[0] <= '9' && (q = memchr(p, '.', (size_t)(e - p))) != NULL && q + 2 <= e &&
        q[1] == ' ') {
        int st = log_stage(q + 2, e);
        if (starts(q + 2, e, "Rasterize: ")) {
            end_segment(t, g);
            g->line_prim = starts(q + 2, e, "Rasterize: LineSegment");
            g->line_px = t->npx;
            return 0;
        }
        if (st < 0) return 0;                   /* the clip stages' segment blocks */
        if (jkey(q, e, "vIndex =")) return log_vertex(c, g, st, q, e);
        if (jkey(q, e, "cIndex =")) return log_color(c, g, st, q, e);
        if (st == PT_T79_CAMERA || st == PT_T79_NEARCLIP) return log_prim(c, g, st, q, e);
        return 0;
    }
    for (k = 0; k < sizeof log_known / sizeof log_known[0]; k++)
        if (starts(p, e, log_known[k])) return 0;
    unread(t, c->line);
    return 0;
}

/* ===== the driver ===== */

/* Pair the anti-aliased pixels of a trace: two in a row, next to each other,
** whose coverages add up to 1. */
static void pair_trace_pixels(pt_t79 *t)
{
    size_t k;

    if (t->aa != 1) return;
    for (k = 0; k + 1 < t->npx; k++) {
        pt_t79px *a = &t->px[k], *b = &t->px[k + 1];
        int64_t dx = a->x - b->x, dy = a->y - b->y;
        if (a->pair || b->pair || a->cov < 0 || b->cov < 0 || fabs(a->cov + b->cov - 1) > 1e-6)
            continue;
        if ((dx == 0 && (dy == 1 || dy == -1)) || (dy == 0 && (dx == 1 || dx == -1))) {
            a->pair = (uint32_t)(k + 2);
            b->pair = (uint32_t)(k + 1);
            k++;
        }
    }
}

int pt_t79_parse(pt_t79 *t, const char *path, const char *buf, size_t len, pt_names *nm,
                 char *err, size_t errlen)
{
    lctx c;
    logst g;
    const char *p = buf, *end = buf + len;
    int rc = 0;

    memset(t, 0, sizeof *t);
    memset(&g, 0, sizeof g);
    t->aa = t->gamma = -1;
    t->renderer = pt_t79_renderer(buf, len);
    if (buf[0] == '{') t->kind = PT_T79_JSONL;
    else if (!strncmp(buf, "# pipetrace", 11)) t->kind = PT_T79_TEXT;
    else if (!strncmp(buf, "model,position,", 15)) t->kind = PT_T79_CSV;
    else t->kind = PT_T79_LOG;
    switch (t->kind) {             /* half a unit in the last digit printed */
    case PT_T79_JSONL: case PT_T79_CSV:
        t->vtol = 0; t->ctol = 0; t->ptol = 0.5 / 255; break;
    case PT_T79_TEXT:
        t->vtol = 5e-7; t->ctol = 5e-7; t->ptol = 0.5 / 255; break;
    case PT_T79_LOG:
        t->vtol = 5e-6; t->ctol = 0.5 / 255; t->cbytes = 1; t->ptol = 5e-5; break;
    }
    c.t = t; c.nm = nm; c.path = path; c.err = err; c.errlen = errlen; c.line = 0;
    while (p < end && rc == 0) {
        const char *e = memchr(p, '\n', (size_t)(end - p));
        if (!e) e = end;
        if (c.line < UINT32_MAX) c.line++;
        {
            const char *f = e > p && e[-1] == '\r' ? e - 1 : e;
            switch (t->kind) {
            case PT_T79_JSONL: rc = jsonl_line(&c, p, f); break;
            case PT_T79_TEXT: rc = text_line(&c, p, f); break;
            case PT_T79_CSV: rc = csv_line(&c, p, f); break;
            case PT_T79_LOG: rc = log_line(&c, &g, p, f); break;
            }
        }
        p = e + 1;
    }
    if (rc == -2) {
        snprintf(err, errlen, "%s: error: out of memory", path);
        return -1;
    }
    if (rc) return -1;
    if (t->kind == PT_T79_LOG) {
        end_segment(t, &g);
        if (old_again(t) != 0) {
            snprintf(err, errlen, "%s: error: out of memory", path);
            return -1;
        }
    }
    if (t->kind != PT_T79_LOG) pair_trace_pixels(t);
    else if (t->npx && t->aa < 0) {
        size_t k;
        for (k = 0; k < t->npx && !t->px[k].pair; k++) {}
        t->aa = k < t->npx;
    }
    return 0;
}
