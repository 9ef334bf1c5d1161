/*
** src/io/tread_kraft.c -- read the course renderer's debug log (--format kraft) back
** See LICENSE for copyright and license.
**
** What the log says becomes what a text trace would say (io/tread.h):
**   "TITLE: vIndex = N, (x,y,z) = (...)"  a vertex record of the stage whose
**                        course title is TITLE (pt_stage_course), vertex N + 1;
**                        the pixel plane's z (0) is dropped; an image record
**                        under perspective is behind when its camera z > 0
**   "==== Render position" .. "---- Translation vector"  a model of the header,
**                        named by "====== Render model: NAME"; the log has no
**                        viewport, framebuffer or index stage: left out
**   "4. Rasterize: LineSegment"   the next segment (1-based, per model)
**   "      fb_[...] ... (x_vp=X, y_vp=Y)"  a pixel record: its framebuffer
**                        pixel and index from the stages (pt_viewport2fb,
**                        pt_fb2index: -1 outside the framebuffer)
**   "Clip: fb_[...]"     a step of a clip run (consecutive clipped steps)
**   "... x_vp=X {y_low=Y0 ...} {y_hi =Y1 ...}"  an anti-aliased pair: two
**                        pixels (or clipped steps), each tested on its own
**   "3. Pixel-plane: LineSegment" / "Point"  which vertices the primitives
**                        use: the log lists every vertex, a trace only those;
**                        the others' records are dropped
**   "4. Rasterize: Point" and its pixel lines: passed over (a trace has no
**                        record of a point's pixels)
** Its numbers have 5 decimals: prec is 5, so diff allows half a unit of the
** fifth decimal, as for a text trace.  The framebuffer and the viewport are
** known only from pixel lines: without them the header is not there
** (hdr.have 0) and the other trace's is used.  Every other line of the log
** is checked for its form.  A line of a kind the log's reader does not know
** (a student's own output, text after the end)
** is not read, only counted (pt_tread.unread): a log as a student's program
** prints it is never refused for it.
*/
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "io/tread.h"
#include "io/tread_int.h"

#define KRAFT_PREC 5             /* decimals of the log's vertex numbers */

/* What the reader knows between lines. */
typedef struct kstate {
    int have_model;              /* 1: inside "Render model" .. "End model" */
    uint32_t model;              /*   its name id */
    double t[3];                 /* the position's translation, until its model */
    int have_t;                  /* 1: a translation waits for its model */
    uint64_t seg;                /* segments of the model so far */
    size_t cam0;                 /* index in vx of the model's first camera record */
    int have_cam;                /* 1: cam0 is set */
    struct pt_tclip run;         /* the clip run being gathered (count 0: none) */
    int have_fb;                 /* 1: a pixel line gave the framebuffer: */
    int fb_w, fb_h, vp_x, vp_y, vp_w, vp_h;  /*   these */
    int ended;                   /* 1: "== End Rendering of Scene ==" was read */
    size_t vx0;                  /* index in vx of the model's first record */
    int in_point;                /* 1: after "4. Rasterize: Point:", whose pixel
                                 ** lines are not a segment's (not kept) */
    uint64_t *used;              /* vIndex + 1 of each segment end of the model */
    size_t nused, cap_used;      /*   (owned), how many, room */
} kstate;

/* ===== a cursor over one line ===== */

typedef struct cur {
    const char *p, *e;
} cur;

/* Match the literal s at the cursor (after any spaces when s starts with a
** non-space) and move past it; else leave the cursor where it was. */
static int lit(cur *c, const char *s)
{
    size_t n = strlen(s);
    const char *p = c->p;

    if (s[0] != ' ') while (p < c->e && *p == ' ') p++;
    if ((size_t)(c->e - p) < n || memcmp(p, s, n) != 0) return 0;
    c->p = p + n;
    return 1;
}

/* A number as Java writes it ("-0.50000", "NaN", "Infinity", "-Infinity"),
** after any spaces. */
static int num(pt_treader *r, cur *c, double *x)
{
    int dec;
    size_t n;

    while (c->p < c->e && *c->p == ' ') c->p++;
    if (lit(c, "NaN")) { *x = (double)NAN; return 0; }
    if (lit(c, "Infinity")) { *x = (double)INFINITY; return 0; }
    if (lit(c, "-Infinity")) { *x = -(double)INFINITY; return 0; }
    n = pt_tr_num_len(c->p, c->e, &dec);
    if (n == 0) return pt_tr_fail(r, c->p, "expected a number");
    *x = strtod(c->p, NULL);
    c->p += n;
    return 0;
}

/* An integer, after any spaces. */
static int integer(pt_treader *r, cur *c, int64_t *x)
{
    int dec;
    size_t n;

    while (c->p < c->e && *c->p == ' ') c->p++;
    n = pt_tr_num_len(c->p, c->e, &dec);
    if (n == 0 || !pt_tr_is_int_token(c->p, n) || pt_tr_to_i64(c->p, x) != 0)
        return pt_tr_fail(r, c->p, "expected an integer");
    c->p += n;
    return 0;
}

/* The end of the line must follow. */
static int end(pt_treader *r, cur *c)
{
    if (c->p != c->e) return pt_tr_fail(r, c->p, "unexpected text at the end of the line");
    return 0;
}

/* "(x,y,z) = (A  B  C)" */
static int xyz(pt_treader *r, cur *c, double v[3])
{
    if (!lit(c, "(x,y,z) = (")) return pt_tr_fail(r, c->p, "expected '(x,y,z) = ('");
    if (num(r, c, &v[0]) || num(r, c, &v[1]) || num(r, c, &v[2])) return -1;
    if (!lit(c, ")")) return pt_tr_fail(r, c->p, "expected ')'");
    return 0;
}

/* ===== the lines ===== */

/* Flush the clip run being gathered into the records. */
static int flush_run(pt_treader *r, kstate *k)
{
    int rc = 0;

    if (k->run.count) rc = pt_tr_add_clip(r, &k->run);
    k->run.count = 0;
    return rc;
}

/* "TITLE: vIndex = N, (x,y,z) = (...)", c after "TITLE:". */
static int vertex_line(pt_treader *r, kstate *k, cur *c, int st)
{
    struct pt_tvrec *rec;
    int64_t n;
    double v[3];
    int i;

    if (!k->have_model) return pt_tr_fail(r, r->line, "a vertex outside a model");
    if (!lit(c, "vIndex =")) return pt_tr_fail(r, c->p, "expected 'vIndex ='");
    if (integer(r, c, &n)) return -1;
    if (n < 0 || n >= INT64_MAX) return pt_tr_fail(r, c->p, "vIndex out of range");
    if (!lit(c, ",")) return pt_tr_fail(r, c->p, "expected ','");
    if (xyz(r, c, v) || end(r, c)) return -1;
    if (st == PT_STAGE_CAMERA && !k->have_cam) { k->cam0 = r->t->nvx; k->have_cam = 1; }
    rec = pt_tr_new_vrec(r, k->model, (uint64_t)n + 1, st);
    if (!rec) return -1;
    for (i = 0; i < pt_stage_infos[st].nreal; i++) rec->u.d[i] = v[i];
    if (st == PT_STAGE_IMAGE && r->t->hdr.perspective == 1 && k->have_cam) {
        size_t j = k->cam0 + (size_t)n;              /* vertex n's camera record */
        const struct pt_tvrec *cam = j < r->t->nvx ? &r->t->vx[j] : NULL;
        if (cam && cam->model == k->model && cam->stage == PT_STAGE_CAMERA &&
            cam->v == (uint64_t)n + 1 && cam->u.d[2] > 0)
            rec->flags |= PT_REC_BEHIND;
    }
    return 0;
}

/* A pixel line, c after "Clip: " or the six spaces; clipped: 1 for "Clip: ". */
/* Keep the pixel at (viewport) as a pixel record, or count it into the clip
** run being gathered when clipped. */
static int take_pixel(pt_treader *r, kstate *k, pt_pix at, int clipped)
{
    if (clipped) {
        if (k->run.count == 0) {
            memset(&k->run, 0, sizeof k->run);
            k->run.first[0] = at.x; k->run.first[1] = at.y;
            k->run.seg = k->seg;
            k->run.model = k->model;
            k->run.npix = r->t->npx;
        }
        k->run.count++;
        k->run.last[0] = at.x; k->run.last[1] = at.y;
        return 0;
    } else {
        struct pt_tpix px;
        pt_fb_pixel fb;
        int wrap;
        if (flush_run(r, k)) return -1;
        memset(&px, 0, sizeof px);
        wrap = k->vp_x < 0 || k->vp_y < 0 || (int64_t)k->vp_x + k->vp_w > k->fb_w ||
               (int64_t)k->vp_y + k->vp_h > k->fb_h;   /* it sticks out: the course's index */
        if (k->fb_w >= 1 && k->fb_h >= 1)
            px.i = pt_raster_fb_pixel(at.x, at.y, k->vp_x, k->vp_y, k->fb_w, k->fb_h, wrap, &fb);
        else {
            pt_pix f = pt_viewport2fb(at, k->vp_x, k->vp_y, NULL);
            fb.x_fb = f.x; fb.y_fb = f.y;
            px.i = -1;
        }
        px.x = fb.x_fb;
        px.y = fb.y_fb;
        px.seg = k->seg;
        px.model = k->model;
        px.line = pt_tr_line32(r);
        return pt_tr_add_pixel(r, &px);
    }
}

/* " r=%.4f g=%.4f b=%.4f" */
static int colour(pt_treader *r, cur *c)
{
    double d;

    return !lit(c, "r=") || num(r, c, &d) || !lit(c, "g=") || num(r, c, &d) ||
           !lit(c, "b=") || num(r, c, &d);
}

/* The rest of an anti-aliased pair's line, c after "(x_pp=.., y_pp=..)":
** "x_vp=X {y_low=Y0 r g b} {y_hi =Y1 r g b}" (or y_vp, x_low, x_hi): the
** two pixels in the order the course writes them, each clipped on its own
** (the line's "Clip: " says only that one of them is). */
static int pair_line(pt_treader *r, kstate *k, cur *c)
{
    int64_t at, lo, hi;
    int ymajor;
    pt_pix p;

    if (lit(c, "x_vp=")) ymajor = 0;
    else if (lit(c, "y_vp=")) ymajor = 1;
    else return pt_tr_fail(r, c->p, "expected '(x_vp=', 'x_vp=' or 'y_vp='");
    if (integer(r, c, &at) || !lit(c, ymajor ? "{x_low=" : "{y_low=") || integer(r, c, &lo) ||
        colour(r, c) || !lit(c, "}") || !lit(c, ymajor ? "{x_hi =" : "{y_hi =") ||
        integer(r, c, &hi) || colour(r, c) || !lit(c, "}"))
        return pt_tr_fail(r, c->p, "expected the rest of an anti-aliased pair's line");
    if (end(r, c)) return -1;
    if (at < INT32_MIN || at > INT32_MAX || lo < INT32_MIN || lo > INT32_MAX ||
        hi < INT32_MIN || hi > INT32_MAX)
        return pt_tr_fail(r, r->line, "pixel out of range");
    p.ok = 1;
    p.x = ymajor ? lo : at; p.y = ymajor ? at : lo;
    if (take_pixel(r, k, p, !pt_inside(p.x, p.y, k->vp_w, k->vp_h))) return -1;
    p.x = ymajor ? hi : at; p.y = ymajor ? at : hi;
    return take_pixel(r, k, p, !pt_inside(p.x, p.y, k->vp_w, k->vp_h));
}

static int pixel_line(pt_treader *r, kstate *k, cur *c, int clipped)
{
    int64_t v[8];
    double d;
    pt_pix at;
    int i;
    static const char *const lead[6] = {"fb_[w=", ",h=", "] vp_[x=", ", y=", ", w=", ",h="};

    if (!k->have_model || k->seg == 0) return pt_tr_fail(r, r->line, "a pixel outside a segment");
    for (i = 0; i < 6; i++)
        if (!lit(c, lead[i]) || integer(r, c, &v[i])) return pt_tr_fail(r, c->p, "expected '%s'", lead[i]);
    if (!lit(c, "]") || !lit(c, "(x_pp=") || num(r, c, &d) || !lit(c, ", y_pp=") ||
        num(r, c, &d) || !lit(c, ")"))
        return pt_tr_fail(r, c->p, "expected the rest of a pixel line");
    for (i = 0; i < 6; i++)                 /* the viewport's corner: either sign */
        if (v[i] < (i == 2 || i == 3 ? INT32_MIN : 0) || v[i] > INT32_MAX)
            return pt_tr_fail(r, r->line, "size out of range");
    if (!k->have_fb) {
        k->have_fb = 1;
        k->fb_w = (int)v[0]; k->fb_h = (int)v[1];
        k->vp_x = (int)v[2]; k->vp_y = (int)v[3]; k->vp_w = (int)v[4]; k->vp_h = (int)v[5];
    } else if (v[0] != k->fb_w || v[1] != k->fb_h || v[2] != k->vp_x || v[3] != k->vp_y ||
               v[4] != k->vp_w || v[5] != k->vp_h) {
        return pt_tr_fail(r, r->line, "another framebuffer or viewport than on the log's "
                          "first pixel line");
    }
    if (!lit(c, "(x_vp=")) return pair_line(r, k, c);
    if (integer(r, c, &v[6]) || !lit(c, ", y_vp=") || integer(r, c, &v[7]) || !lit(c, ")") ||
        colour(r, c))
        return pt_tr_fail(r, c->p, "expected the rest of a pixel line");
    if (end(r, c)) return -1;
    if (v[6] < INT32_MIN || v[6] > INT32_MAX || v[7] < INT32_MIN || v[7] > INT32_MAX)
        return pt_tr_fail(r, r->line, "pixel out of range");
    at.x = v[6]; at.y = v[7]; at.ok = 1;
    return take_pixel(r, k, at, clipped);
}

/* "3. Pixel-plane: LineSegment: ([a, b], [a, b])", c after "LineSegment:":
** note that a and b are used. */
static int segment_line(pt_treader *r, kstate *k, cur *c, int point)
{
    int64_t a, b;
    int e;

    if (!k->have_model) return pt_tr_fail(r, r->line, "a segment outside a model");
    if (point) {                                     /* "Point: ([v], [c]) ...": v */
        if (!lit(c, "([") || integer(r, c, &a) || !lit(c, "]"))
            return pt_tr_fail(r, c->p, "expected '([v]'");
        b = a;
    } else if (!lit(c, "([") || integer(r, c, &a) || !lit(c, ",") || integer(r, c, &b) ||
               !lit(c, "]"))
        return pt_tr_fail(r, c->p, "expected '([a, b]'");
    if (a < 0 || b < 0 || a >= INT64_MAX || b >= INT64_MAX)
        return pt_tr_fail(r, r->line, "vIndex out of range");
    for (e = 0; e < 2; e++) {
        if (pt_tr_grow(r, (void **)&k->used, k->nused, &k->cap_used, sizeof *k->used)) return -1;
        k->used[k->nused++] = (uint64_t)(e ? b : a) + 1;
    }
    return 0;
}

static int cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : x > y;
}

/* At the end of a model: drop the records of its vertices no segment or point uses,
** which a trace does not transform either (the log lists every vertex). */
static void drop_unused(pt_treader *r, kstate *k)
{
    struct pt_tread *t = r->t;
    size_t i, j = k->vx0;

    if (k->nused) qsort(k->used, k->nused, sizeof *k->used, cmp_u64);   /* not on NULL */
    for (i = k->vx0; i < t->nvx; i++)
        if (k->nused && bsearch(&t->vx[i].v, k->used, k->nused, sizeof *k->used, cmp_u64))
            t->vx[j++] = t->vx[i];
    t->nvx = j;
    k->nused = 0;
}

/* A name line "PRE NAME POST": the name into *id. */
static int name_line(pt_treader *r, cur *c, const char *post, uint32_t *id)
{
    size_t n = strlen(post);

    if ((size_t)(c->e - c->p) <= n || memcmp(c->e - n, post, n) != 0)
        return pt_tr_fail(r, c->p, "expected a name and '%s'", post);
    if (pt_names_intern(r->nm, c->p, (size_t)(c->e - n - c->p), id) != 0) return pt_tr_oom(r);
    return 0;
}

/* Lines the log has that say nothing a trace keeps: checked for form only. */
static int skipped_line(cur *c)
{
    static const char *const lines[] = {
        "== Begin Rendering of Scene:", "-- Current Camera:", "Camera:",
        "(x0_pp, y0_pp) = (", "(x1_pp, y1_pp) = (", "(x0_vp, y0_vp) = (",
        "(x1_vp, y1_vp) = (", "Slope m", "   vIndex = ", "   cIndex = ",
        "***WARNING:", "FrameBuffer: Bad pixel coordinate", "Incorrect primitive:",
        "Model: ", "This Model's visibility is: ", "Model has ", "(x_pp, y_pp) = (",
        "==== Hidden position: ", "====== Hidden model: "};
    const char *p = c->p;
    size_t i;

    for (i = 0; i < sizeof lines / sizeof lines[0]; i++)
        if (lit(c, lines[i])) return 1;
    while (p < c->e && *p >= '0' && *p <= '9') p++;  /* "N: ..." of Model.toString */
    return p > c->p && c->e - p >= 2 && p[0] == ':' && p[1] == ' ';
}

/* A line not read: counted, and the first one's number kept. */
static int unread(pt_treader *r)
{
    if (r->t->unread++ == 0) r->t->unread_line = r->lineno;
    return 0;
}

static int kraft_line(pt_treader *r, kstate *k)
{
    cur c;
    uint32_t id;
    int st;

    c.p = r->line;
    c.e = r->eol;
    if (c.p == c.e) return 0;                        /* the empty first line */
    if (k->ended) return unread(r);
    for (st = 0; st < PT_NSTAGES_ALL; st++) {        /* "0. Model      : ..." */
        const char *title = pt_stage_course[st];
        size_t n = title ? strlen(title) : 0;
        cur d = c;

        if (!title || (size_t)(d.e - d.p) < n || memcmp(d.p, title, n) != 0) continue;
        d.p += n;
        while (d.p < d.e && *d.p == ' ') d.p++;
        if (!lit(&d, ":")) continue;
        {
            cur peek = d;
            if (lit(&peek, "vIndex")) return vertex_line(r, k, &d, st);
        }
        if (st == PT_STAGE_PIXEL && lit(&d, "LineSegment:")) return segment_line(r, k, &d, 0);
        if (st == PT_STAGE_PIXEL && lit(&d, "Point:")) return segment_line(r, k, &d, 1);
        if (st == PT_STAGE_PIXEL) return 0;           /* its colours, "[]" */
        return pt_tr_fail(r, d.p, "expected 'vIndex ='");
    }
    if (lit(&c, "perspective = ")) {
        if (lit(&c, "true")) r->t->hdr.perspective = 1;
        else if (lit(&c, "false")) r->t->hdr.perspective = 0;
        else return pt_tr_fail(r, c.p, "expected 'true' or 'false'");
        return end(r, &c);
    }
    if (lit(&c, "==== Render position: ")) return 0;
    if (lit(&c, "---- Translation vector = [x,y,z] = [")) {
        if (num(r, &c, &k->t[0]) || num(r, &c, &k->t[1]) || num(r, &c, &k->t[2])) return -1;
        if (!lit(&c, "]")) return pt_tr_fail(r, c.p, "expected ']'");
        k->have_t = 1;
        return end(r, &c);
    }
    if (lit(&c, "====== Render model: ")) {
        struct pt_tmodel *m;
        if (k->have_model) return pt_tr_fail(r, r->line, "a model inside a model");
        if (name_line(r, &c, " ======", &id)) return -1;
        m = pt_tr_new_model(r);
        if (!m) return -1;
        m->name = id;
        if (k->have_t) memcpy(m->t, k->t, sizeof m->t);
        m->left_known = 1;                           /* the log has no stage after */
        m->left_out = 1u << PT_STAGE_VIEWPORT | 1u << PT_STAGE_FRAMEBUFFER |
                      1u << PT_STAGE_INDEX;          /* the pixel plane */
        k->have_model = 1;
        k->model = id;
        k->have_t = 0;
        k->seg = 0;
        k->have_cam = 0;
        k->vx0 = r->t->nvx;
        return 0;
    }
    if (lit(&c, "4. Rasterize: LineSegment:")) {
        if (!k->have_model) return pt_tr_fail(r, r->line, "a segment outside a model");
        if (flush_run(r, k)) return -1;
        k->seg++;
        k->in_point = 0;
        return 0;
    }
    if (lit(&c, "4. Rasterize: Point:")) {
        if (!k->have_model) return pt_tr_fail(r, r->line, "a point outside a model");
        if (flush_run(r, k)) return -1;
        k->in_point = 1;
        return 0;
    }
    {   /* a point's pixels are not kept: a trace has none (docs/renderer4.md) */
        cur d = c;
        if ((lit(&d, "Clip: ") || lit(&d, "      fb_[")) && k->in_point) return 0;
    }
    if (lit(&c, "Clip: ")) return pixel_line(r, k, &c, 1);
    if (lit(&c, "      fb_[")) { c.p -= 4; return pixel_line(r, k, &c, 0); }
    if (lit(&c, "====== End model: ")) {
        if (!k->have_model) return pt_tr_fail(r, r->line, "'End model' without a model");
        if (flush_run(r, k)) return -1;
        drop_unused(r, k);
        k->have_model = 0;
        k->in_point = 0;
        return 0;
    }
    if (lit(&c, "==== End position: ")) return 0;
    if (lit(&c, "== End Rendering of Scene ==")) {
        if (k->have_model) return pt_tr_fail(r, r->line, "the scene ends inside a model");
        k->ended = 1;
        return end(r, &c);
    }
    if (skipped_line(&c)) return 0;
    return unread(r);
}

int pt_tr_kraft(pt_treader *r, const char *buf, size_t len)
{
    const char *p = buf, *e = buf + len;
    kstate k;
    int rc = 0;

    memset(&k, 0, sizeof k);
    r->t->prec = KRAFT_PREC;
    r->t->hdr.perspective = 1;
    while (rc == 0 && p < e) {
        const char *nl = memchr(p, '\n', (size_t)(e - p));
        r->line = p;
        r->eol = nl ? nl : e;
        if (r->eol > p && r->eol[-1] == '\r') r->eol--;
        if (memchr(p, '\0', (size_t)(r->eol - p)) != NULL)
            rc = pt_tr_fail(r, memchr(p, '\0', (size_t)(r->eol - p)), "NUL byte in a log");
        else
            rc = kraft_line(r, &k);
        p = nl ? nl + 1 : e;
        r->lineno++;
    }
    free(k.used);
    if (rc == 0 && !k.ended) {
        r->line = r->eol = e;
        rc = pt_tr_fail(r, NULL, "the log ends before '== End Rendering of Scene =='");
    }
    if (rc == 0 && k.have_fb) {
        pt_thdr *h = &r->t->hdr;
        h->have = 1;
        h->fb_w = k.fb_w; h->fb_h = k.fb_h;
        h->vp_x = k.vp_x; h->vp_y = k.vp_y; h->vp_w = k.vp_w; h->vp_h = k.vp_h;
    }
    return rc;
}
