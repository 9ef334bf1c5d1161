/*
** src/io/explain.c -- each stage's formula with one vertex's numbers put in
** See LICENSE for copyright and license.
**
** No stdio here: the text goes into the caller's buffer through a small
** appender that counts what did not fit.  Numbers are pt_fmt_shortest's, so
** every number shown reads back to the double the stage computed.
*/
#include <math.h>
#include <string.h>
#include "io/explain.h"
#include "io/explain_text.h"
#include "core/pipetrace.h"
#include "io/numfmt.h"

/* ===== vertices ===== */

int pt_vertex_used(const pt_model *m, uint64_t v)
{
    size_t k;

    for (k = 0; k < m->nseg; k++)
        if ((uint64_t)m->seg[k].a + 1 == v || (uint64_t)m->seg[k].b + 1 == v) return 1;
    return 0;
}

/* ===== coordinate names ===== */

int pt_coord_count(pt_stage st)
{
    return pt_stage_nvalues(st);
}

const char *pt_coord_name(pt_stage st, int k)
{
    if ((int)st >= PT_NSTAGES_ALL || k < 0 || k >= pt_coord_count(st)) return "";
    return pt_stage_infos[st].coord[k];
}

/* ===== the text appender ===== */

void pt_xt_init(pt_xt *t, char *buf, size_t cap)
{
    t->buf = buf;
    t->cap = cap;
    t->len = 0;
    if (cap) buf[0] = '\0';
}

void pt_xt_add(pt_xt *t, const char *s)
{
    for (; *s; s++, t->len++)
        if (t->len + 1 < t->cap) t->buf[t->len] = *s;
    if (t->cap) t->buf[t->len < t->cap ? t->len : t->cap - 1] = '\0';
}

void pt_xt_num(pt_xt *t, double x, int paren)
{
    char b[PT_NUMLEN];

    pt_fmt_shortest(b, x);
    if (paren && b[0] == '-') { pt_xt_add(t, "("); pt_xt_add(t, b); pt_xt_add(t, ")"); }
    else pt_xt_add(t, b);
}

void pt_xt_int(pt_xt *t, int64_t x, int paren)
{
    char b[24], *o = b + sizeof b - 1;
    uint64_t u = x < 0 ? 0u - (uint64_t)x : (uint64_t)x;

    *o = '\0';
    do { *--o = (char)('0' + u % 10); u /= 10; } while (u);
    if (x < 0) *--o = '-';
    if (paren && x < 0) { pt_xt_add(t, "("); pt_xt_add(t, o); pt_xt_add(t, ")"); }
    else pt_xt_add(t, o);
}

/* "(a, b)" of two integers */
static void add_pair(pt_xt *t, int64_t a, int64_t b)
{
    pt_xt_add(t, "("); pt_xt_int(t, a, 0); pt_xt_add(t, ", "); pt_xt_int(t, b, 0); pt_xt_add(t, ")");
}

/* "name = " */
static void add_lhs(pt_xt *t, pt_stage st, int k)
{
    pt_xt_add(t, pt_stage_infos[st].coord[k]);
    pt_xt_add(t, " = ");
}

/* Component k of a real-valued record. */
static double comp(const pt_vrec *r, int k)
{
    return k == 0 ? r->x : k == 1 ? r->y : k == 2 ? r->z : r->w;
}

/* The stage before st in j's journey (st itself for the first). */
static pt_stage prev_stage(const pt_journey *j, pt_stage st)
{
    int i;

    for (i = 1; i < j->norder; i++)
        if (j->order[i] == st) return j->order[i - 1];
    return st;
}

static double tcomp(pt_vec3 v, int k)
{
    return k == 0 ? v.x : k == 1 ? v.y : v.z;
}

/* ===== no pixel, and what Java would give ===== */

/* Why pixel-plane coordinate x has no integer pixel. */
static const char *no_pixel_why(double x)
{
    return isfinite(x) ? "it is beyond 2^62" : "it is not finite";
}

int32_t pt_explain_java_int_round(double x)
{
    double r = pt_java_round(x);            /* NaN: 0 */
    uint32_t low;

    if (r >= 9223372036854775808.0) return -1;          /* 2^63 - 1: low bits all 1 */
    if (r < -9223372036854775808.0) return 0;           /* -2^63: low bits all 0 */
    low = (uint32_t)(uint64_t)(int64_t)r;   /* exact: |r| <= 2^63, an integer */
    return low <= INT32_MAX ? (int32_t)low : -(int32_t)(UINT32_MAX - low) - 1;
}

/* Where Java parts from pipetrace: " (the Java renderer's (int)Math.round(x_pp)
** gives -1 here)". */
static void add_java(pt_xt *t, double x, int k)
{
    pt_xt_add(t, k == 0 ? " (the Java renderer's (int)Math.round(x_pp) gives "
                  : " (the Java renderer's (int)Math.round(y_pp) gives ");
    pt_xt_int(t, pt_explain_java_int_round(x), 0);
    pt_xt_add(t, " here)");
}

/* ===== one coordinate's formula: a function a stage ===== */

/* Coordinate k of a stage: its formula, the numbers of prev (j's record of
** the stage before, what the stage was handed) put in, and cur's result.
** One function per stage, in stage_rows[] below; a stage's own function
** names its coordinates (add_lhs) and knows its formula. */
typedef void (*coord_fn)(pt_xt *t, const pt_journey *j, const pt_vrec *prev,
                         const pt_vrec *cur, int k);

static void coord_model(pt_xt *t, const pt_journey *j, const pt_vrec *prev,
                        const pt_vrec *cur, int k)      /* as given */
{
    (void)j; (void)prev;
    add_lhs(t, PT_STAGE_MODEL, k);
    pt_xt_num(t, comp(cur, k), 0);
}

static void coord_camera(pt_xt *t, const pt_journey *j, const pt_vrec *prev,
                         const pt_vrec *cur, int k)     /* x_c = x_m + x_t */
{
    add_lhs(t, PT_STAGE_CAMERA, k);
    pt_xt_add(t, pt_stage_infos[PT_STAGE_MODEL].coord[k]);
    pt_xt_add(t, k == 0 ? " + x_t = " : k == 1 ? " + y_t = " : " + z_t = ");
    pt_xt_num(t, comp(prev, k), 0); pt_xt_add(t, " + ");
    pt_xt_num(t, tcomp(j->par.translate, k), 1); pt_xt_add(t, " = ");
    pt_xt_num(t, comp(cur, k), 0);
}

static void coord_image(pt_xt *t, const pt_journey *j, const pt_vrec *prev,
                        const pt_vrec *cur, int k)
{
    add_lhs(t, PT_STAGE_IMAGE, k);
    if (k == 2) {                                       /* z_ip = -1 or 0 */
        pt_xt_num(t, cur->z, 0);
        pt_xt_add(t, j->par.perspective ? " (the image plane)" : " (orthographic)");
    } else if (j->par.perspective) {                    /* x_ip = x_c / -z_c */
        pt_xt_add(t, k == 0 ? "x_c / -z_c = " : "y_c / -z_c = ");
        pt_xt_num(t, comp(prev, k), 0); pt_xt_add(t, " / -");
        pt_xt_num(t, prev->z, 1); pt_xt_add(t, " = ");
        pt_xt_num(t, comp(cur, k), 0);
    } else {                                            /* x_ip = x_c */
        pt_xt_add(t, k == 0 ? "x_c = " : "y_c = ");
        pt_xt_num(t, comp(cur, k), 0);
    }
}

/* s3_image2pixel.h, its divisor PT_PIXEL_DIVISOR */
static void coord_pixel(pt_xt *t, const pt_journey *j, const pt_vrec *prev,
                        const pt_vrec *cur, int k)
{
    add_lhs(t, PT_STAGE_PIXEL, k);
    pt_xt_add(t, k == 0 ? "0.5 + w/" : "0.5 + h/");
    pt_xt_num(t, PT_PIXEL_DIVISOR, 0);
    pt_xt_add(t, k == 0 ? " * (x_ip + 1) = 0.5 + " : " * (y_ip + 1) = 0.5 + ");
    pt_xt_int(t, k == 0 ? j->par.w : j->par.h, 0); pt_xt_add(t, "/");
    pt_xt_num(t, PT_PIXEL_DIVISOR, 0); pt_xt_add(t, " * (");
    pt_xt_num(t, comp(prev, k), 0); pt_xt_add(t, " + 1) = ");
    pt_xt_num(t, comp(cur, k), 0);
}

/* The classic camera's viewport stage, x_vp = round(x_pp) - 1, y_vp = h -
** round(y_pp): the rounding is pt_pix_round()'s, the result cur's, the
** reference stage's record. */
static void coord_round(pt_xt *t, const pt_journey *j, const pt_vrec *pp,
                        const pt_vrec *cur, int k)
{
    double x = comp(pp, k);
    int64_t r;

    add_lhs(t, PT_STAGE_VIEWPORT, k);
    pt_xt_add(t, k == 0 ? "round(x_pp) - 1 = round(" : "h - round(y_pp) = ");
    if (k == 1) { pt_xt_int(t, j->par.h, 0); pt_xt_add(t, " - round("); }
    pt_xt_num(t, x, 0);
    pt_xt_add(t, k == 0 ? ") - 1" : ")");
    if (!pt_pix_round(x, &r) || !pt_rec_has(cur, k)) {
        pt_xt_add(t, ": none, ");
        pt_xt_add(t, no_pixel_why(x));
        add_java(t, x, k);
        return;
    }
    pt_xt_add(t, " = ");
    if (k == 0) { pt_xt_int(t, r, 0); pt_xt_add(t, " - 1 = "); }
    else { pt_xt_int(t, j->par.h, 0); pt_xt_add(t, " - "); pt_xt_int(t, r, 1); pt_xt_add(t, " = "); }
    pt_xt_int(t, k == 0 ? cur->ix : cur->iy, 0);
    if (r != (int64_t)pt_explain_java_int_round(x)) add_java(t, x, k);     /* past 32 bits */
    if (cur->flags & PT_REC_NULL) {         /* the other one has none */
        pt_xt_add(t, ", but the viewport pixel has no value: ");
        pt_xt_add(t, pt_stage_infos[PT_STAGE_VIEWPORT].coord[1 - k]);
        pt_xt_add(t, " has none (");
        pt_xt_add(t, pt_stage_infos[prev_stage(j, PT_STAGE_VIEWPORT)].coord[1 - k]);
        pt_xt_add(t, isfinite(comp(pp, 1 - k)) ? " is beyond 2^62)" : " is not finite)");
    }
}

/* The matrix camera's viewport stage: x_vp = floor(x_s). */
static void coord_floor(pt_xt *t, const pt_journey *j, const pt_vrec *prev,
                        const pt_vrec *cur, int k)
{
    (void)j;
    add_lhs(t, PT_STAGE_VIEWPORT, k);
    pt_xt_add(t, k == 0 ? "floor(x_s) = floor(" : "floor(y_s) = floor(");
    pt_xt_num(t, comp(prev, k), 0); pt_xt_add(t, ")");
    if (cur->flags & PT_REC_NULL) { pt_xt_add(t, ": none, "); pt_xt_add(t, no_pixel_why(comp(prev, k))); return; }
    pt_xt_add(t, " = "); pt_xt_int(t, k == 0 ? cur->ix : cur->iy, 0);
}

static void coord_framebuffer(pt_xt *t, const pt_journey *j, const pt_vrec *prev,
                              const pt_vrec *cur, int k)    /* x_fb = x_ul + x_vp */
{
    add_lhs(t, PT_STAGE_FRAMEBUFFER, k);
    pt_xt_add(t, k == 0 ? "x_ul + x_vp" : "y_ul + y_vp");
    if (prev->flags & PT_REC_NULL) {
        pt_xt_add(t, ": none, the viewport pixel has no value");
        return;
    }
    pt_xt_add(t, " = ");
    pt_xt_int(t, k == 0 ? j->par.x_ul : j->par.y_ul, 0); pt_xt_add(t, " + ");
    pt_xt_int(t, k == 0 ? prev->ix : prev->iy, 1); pt_xt_add(t, " = ");
    pt_xt_int(t, k == 0 ? cur->ix : cur->iy, 0);
}

static void coord_index(pt_xt *t, const pt_journey *j, const pt_vrec *prev,
                        const pt_vrec *cur, int k)          /* idx = y_fb * W + x_fb */
{
    (void)k;
    pt_xt_add(t, "idx = y_fb * W + x_fb");
    if (prev->flags & PT_REC_NULL) {
        pt_xt_add(t, ": none, the pixel has no value");
    } else if (cur->flags & PT_REC_NULL) {
        pt_xt_add(t, ": none, (x_fb, y_fb) = ");
        add_pair(t, prev->ix, prev->iy);
        pt_xt_add(t, " lies outside the ");
        pt_xt_int(t, j->par.W, 0); pt_xt_add(t, " x "); pt_xt_int(t, j->par.H, 0);
        pt_xt_add(t, " framebuffer");
    } else {
        pt_xt_add(t, " = ");
        pt_xt_int(t, prev->iy, 0); pt_xt_add(t, " * "); pt_xt_int(t, j->par.W, 0);
        pt_xt_add(t, " + "); pt_xt_int(t, prev->ix, 0); pt_xt_add(t, " = ");
        pt_xt_int(t, cur->i, 0);
    }
}

/* x' = x*m0k + y*m1k + z*m2k + w*m3k with the numbers, for the matrix
** stages: value k of stage st is column k of matrix m (called mname) times
** prev, a point (w = 1) when prev has no w. */
static void product(pt_xt *t, pt_stage st, const pt_mat4 *m, const char *mname,
                    const pt_vrec *prev, const pt_vrec *cur, int k)
{
    double in[4];
    int r;

    in[0] = prev->x; in[1] = prev->y; in[2] = prev->z;
    in[3] = pt_stage_infos[prev->stage].nreal < 4 ? 1.0 : prev->w;
    add_lhs(t, st, k);
    pt_xt_add(t, "column "); pt_xt_int(t, k, 0); pt_xt_add(t, " of "); pt_xt_add(t, mname); pt_xt_add(t, ": ");
    for (r = 0; r < 4; r++) {
        if (r) pt_xt_add(t, " + ");
        pt_xt_num(t, in[r], r > 0); pt_xt_add(t, "*"); pt_xt_num(t, m->m[r][k], 1);
    }
    pt_xt_add(t, " = ");
    pt_xt_num(t, comp(cur, k), 0);
}

static void coord_world(pt_xt *t, const pt_journey *j, const pt_vrec *prev,
                        const pt_vrec *cur, int k)
{
    product(t, PT_STAGE_WORLD, &j->world, "World", prev, cur, k);
}

static void coord_view(pt_xt *t, const pt_journey *j, const pt_vrec *prev,
                       const pt_vrec *cur, int k)
{
    product(t, PT_STAGE_VIEW, &j->view, "View", prev, cur, k);
}

static void coord_clip(pt_xt *t, const pt_journey *j, const pt_vrec *prev,
                       const pt_vrec *cur, int k)
{
    product(t, PT_STAGE_CLIP, &j->proj, "Projection", prev, cur, k);
}

/* The cvv stage's outcode and the planes it names. */
static void coord_cvv(pt_xt *t, const pt_journey *j, const pt_vrec *prev,
                      const pt_vrec *cur, int k)
{
    int b, first = 1;

    (void)j; (void)prev; (void)k;
    pt_xt_add(t, "code = ");
    pt_xt_int(t, cur->code, 0);
    if (!cur->code) { pt_xt_add(t, ": 0 <= z <= w, -w <= x <= w, -w <= y <= w"); return; }
    pt_xt_add(t, ": outside");
    for (b = 0; b < PT_CVV_NPLANES; b++) {
        if (!(cur->code & (1u << b))) continue;
        pt_xt_add(t, first ? " " : ", ");
        first = 0;
        pt_xt_add(t, pt_cvv_names[b]);
    }
    pt_xt_add(t, " (w_k = "); pt_xt_num(t, cur->w, 0); pt_xt_add(t, ")");
}

static void coord_ndc(pt_xt *t, const pt_journey *j, const pt_vrec *prev,
                      const pt_vrec *cur, int k)            /* x_n = x_k / w_k */
{
    (void)j;
    add_lhs(t, PT_STAGE_NDC, k);
    pt_xt_add(t, k == 0 ? "x_k / w_k = " : k == 1 ? "y_k / w_k = " : "z_k / w_k = ");
    pt_xt_num(t, comp(prev, k), 0); pt_xt_add(t, " / "); pt_xt_num(t, prev->w, 1);
    pt_xt_add(t, " = "); pt_xt_num(t, comp(cur, k), 0);
}

static void coord_screen(pt_xt *t, const pt_journey *j, const pt_vrec *prev,
                         const pt_vrec *cur, int k)
{
    add_lhs(t, PT_STAGE_SCREEN, k);
    if (k == 2) { pt_xt_add(t, "z_n = "); pt_xt_num(t, cur->z, 0); return; }
    pt_xt_add(t, k == 0 ? "(x_n + 1) * w * 0.5 = (" : "(1 - y_n) * h * 0.5 = (1 - ");
    pt_xt_num(t, comp(prev, k), k == 1);
    pt_xt_add(t, k == 0 ? " + 1) * " : ") * ");
    pt_xt_int(t, k == 0 ? j->par.w : j->par.h, 0); pt_xt_add(t, " * 0.5 = ");
    pt_xt_num(t, comp(cur, k), 0);
}

/* The formula of pipeline pl's stage st, or NULL when explain has none
** (defined with the rows, below). */
static coord_fn coord_row(const pt_pipeline *pl, pt_stage st);

/* "your stage gave x_vp = 2": value k of the run's record r of stage st. */
static void add_yours(pt_xt *t, pt_stage st, const pt_vrec *r, int k)
{
    pt_xt_add(t, "your stage gave ");
    add_lhs(t, st, k);
    if (pt_stage_infos[st].nreal) pt_xt_num(t, comp(r, k), 0);
    else if (!pt_rec_has(r, k)) pt_xt_add(t, "none");
    else pt_xt_int(t, pt_rec_int(r, k), 0);
}

size_t pt_explain_stage(char *buf, size_t len, const pt_journey *j, pt_stage st,
                        const char *sep)
{
    pt_vrec ref;
    unsigned differ;
    coord_fn coord;
    pt_xt t;
    int k;

    pt_xt_init(&t, buf, len);
    if ((int)st >= PT_NSTAGES_ALL) return 0;
    coord = coord_row(j->pipe, st);
    if (!(j->reported & 1u << st)) {        /* a student's stage without pt_emit */
        pt_xt_add(&t, "none: the ");
        pt_xt_add(&t, pt_stage_infos[st].name);
        pt_xt_add(&t, " stage did not report its record (no pt_emit(sink, &r))");
        return t.len;
    }
    if (!(j->reported & 1u << prev_stage(j, st))) {
        pt_xt_add(&t, "the ");
        pt_xt_add(&t, pt_stage_infos[prev_stage(j, st)].name);
        pt_xt_add(&t, " stage did not report its record: the numbers it handed on are not known");
        return t.len;
    }
    if (!pt_pipeline_ref(j->pipe, st)
        || !pt_ref_stage(st, &j->par, &j->rec[prev_stage(j, st)], &ref)) ref = j->rec[st];
    differ = pt_ref_differ(st, &j->rec[st], &ref);
    for (k = 0; k < pt_coord_count(st); k++) {
        if (k) pt_xt_add(&t, sep);
        if (coord) coord(&t, j, &j->rec[prev_stage(j, st)], &ref, k);
        if (differ & 1u << k) { pt_xt_add(&t, sep); add_yours(&t, st, &j->rec[st], k); }
    }
    return t.len;
}

void pt_explain_reference(pt_journey *ref, const pt_journey *j)
{
    int i;

    *ref = *j;
    for (i = 1; i < j->norder; i++) {
        pt_stage st = j->order[i];
        if (!pt_pipeline_ref(j->pipe, st)) continue;
        pt_ref_stage(st, &j->par, &ref->rec[j->order[i - 1]], &ref->rec[st]);
        ref->reported |= 1u << st;
    }
}

/* ===== values as a tuple ===== */

/* The numbers of r (stage st) alone: "(-1, -1, -2)", "144", "none". */
static void add_tuple(pt_xt *t, const pt_vrec *r, pt_stage st)
{
    int k, n = pt_coord_count(st);

    switch (pt_stage_infos[st].kind) {
    case PT_VAL_OUTCODE:
        pt_xt_int(t, r->code, 0);
        break;
    case PT_VAL_PIXEL:                                  /* null per value: */
        if (!pt_rec_has(r, 0) && !pt_rec_has(r, 1)) { pt_xt_add(t, "none"); break; }
        pt_xt_add(t, "(");                                    /* "(none, 7)" */
        if (pt_rec_has(r, 0)) pt_xt_int(t, r->ix, 0); else pt_xt_add(t, "none");
        pt_xt_add(t, ", ");
        if (pt_rec_has(r, 1)) pt_xt_int(t, r->iy, 0); else pt_xt_add(t, "none");
        pt_xt_add(t, ")");
        break;
    case PT_VAL_INDEX:
        if (r->flags & PT_REC_NULL) pt_xt_add(t, "none");
        else pt_xt_int(t, r->i, 0);
        break;
    case PT_VAL_REAL:
        pt_xt_add(t, "(");
        for (k = 0; k < n; k++) {
            if (k) pt_xt_add(t, ", ");
            pt_xt_num(t, comp(r, k), 0);
        }
        pt_xt_add(t, ")");
        break;
    }
}

size_t pt_explain_values(char *buf, size_t len, const pt_journey *j, pt_stage st)
{
    pt_xt t;
    int k, n = pt_coord_count(st);

    pt_xt_init(&t, buf, len);
    if ((int)st >= PT_NSTAGES_ALL) return 0;
    if (n == 1) {                           /* "idx = ", "code = " */
        pt_xt_add(&t, pt_stage_infos[st].coord[0]);
        pt_xt_add(&t, " = ");
    } else {
        pt_xt_add(&t, "(");
        for (k = 0; k < n; k++) {
            if (k) pt_xt_add(&t, ", ");
            pt_xt_add(&t, pt_stage_infos[st].coord[k]);
        }
        pt_xt_add(&t, ") = ");
    }
    add_tuple(&t, &j->rec[st], st);
    return t.len;
}

size_t pt_explain_tuple(char *buf, size_t len, const pt_journey *j, pt_stage st)
{
    pt_xt t;

    pt_xt_init(&t, buf, len);
    if ((int)st < PT_NSTAGES_ALL) add_tuple(&t, &j->rec[st], st);
    return t.len;
}

/* ===== what comes next ===== */

/* "1..w x 1..h"-style range */
static void add_range(pt_xt *t, int lo_x, int hi_x, int lo_y, int hi_y)
{
    pt_xt_int(t, lo_x, 0); pt_xt_add(t, ".."); pt_xt_int(t, hi_x, 0); pt_xt_add(t, " x ");
    pt_xt_int(t, lo_y, 0); pt_xt_add(t, ".."); pt_xt_int(t, hi_y, 0);
}

/* What the result of a stage means for the stages after it: one function a
** stage, in next_rows[] below.  r is j's record of the stage. */
typedef void (*next_fn)(pt_xt *t, const pt_journey *j, const pt_vrec *r);

/* What a pipeline's second stage does with the model's values (the model's
** "next"), by that stage: in first_rows[] below. */
typedef void (*first_fn)(pt_xt *t, const pt_journey *j);

static void first_camera(pt_xt *t, const pt_journey *j)
{
    pt_vec3 tr = j->par.translate;

    if (tr.x == 0 && tr.y == 0 && tr.z == 0)
        pt_xt_add(t, "the translation is (0, 0, 0): the camera stage changes nothing");
    else {
        pt_xt_add(t, "the camera stage adds the model's translation (x_t, y_t, z_t) = (");
        pt_xt_num(t, tr.x, 0); pt_xt_add(t, ", "); pt_xt_num(t, tr.y, 0); pt_xt_add(t, ", ");
        pt_xt_num(t, tr.z, 0); pt_xt_add(t, ")");
    }
}

static void first_world(pt_xt *t, const pt_journey *j)
{
    (void)j;
    pt_xt_add(t, "the world stage multiplies (x_m, y_m, z_m, 1) by the model's world matrix");
}

/* The stages a pipeline may have second, after the model.  A pipeline whose
** second stage is new adds a row. */
static const first_fn first_rows[PT_NSTAGES_ALL] = {
    [PT_STAGE_CAMERA] = first_camera,
    [PT_STAGE_WORLD] = first_world,
};

static void next_model(pt_xt *t, const pt_journey *j, const pt_vrec *r)
{
    (void)r;
    if (j->norder > 1 && first_rows[j->order[1]]) first_rows[j->order[1]](t, j);
}

static void next_camera(pt_xt *t, const pt_journey *j, const pt_vrec *r)
{
    double z = r->z;

    if (!j->par.perspective)
        pt_xt_add(t, "orthographic camera: the image stage keeps x_c and y_c and drops the depth");
    else if (z < 0) {
        pt_xt_add(t, "in front of the camera (z_c < 0): the image stage divides by its distance -z_c = ");
        pt_xt_num(t, -z, 0);
    } else if (z > 0)
        pt_xt_add(t, "behind the camera (z_c > 0): the image stage projects it mirrored through the origin");
    else if (z == 0)
        pt_xt_add(t, "in the camera's plane (z_c = 0): the image stage divides by zero");
    else
        pt_xt_add(t, "z_c is not a number: so is its projection");
}

static void next_image(pt_xt *t, const pt_journey *j, const pt_vrec *ip)
{
    int vp_inside = (j->rec[PT_STAGE_VIEWPORT].flags & PT_REC_INSIDE) != 0;
    int rect = fabs(ip->x) <= 1 && fabs(ip->y) <= 1;

    if (ip->flags & PT_REC_BEHIND)
        pt_xt_add(t, "behind the camera (z_c > 0): projected mirrored through the origin; ");
    if (!isfinite(ip->x) || !isfinite(ip->y))
        pt_xt_add(t, "not finite: it will have no pixel, and segments using it are skipped");
    else if (rect)
        pt_xt_add(t, "inside the view rectangle [-1, 1] x [-1, 1]: the point lies inside the viewport");
    else if (vp_inside) {
        pt_xt_add(t, "just outside the view rectangle [-1, 1] x [-1, 1], but the pixel stage's ");
        pt_xt_num(t, PT_PIXEL_DIVISOR, 0);
        pt_xt_add(t, " leaves room: it still rounds to a pixel inside the viewport");
    }
    else
        pt_xt_add(t, "outside the view rectangle [-1, 1] x [-1, 1]: the point lies outside the viewport");
}

static void next_pixel(pt_xt *t, const pt_journey *j, const pt_vrec *pp)
{
    const pt_vrec *vp = &j->rec[PT_STAGE_VIEWPORT];
    int64_t m, n;

    if (vp->flags & PT_REC_NULL) {
        pt_xt_add(t, "no integer pixel (not finite, or beyond 2^62): segments using it are skipped");
        return;
    }
    pt_pix_round(pp->x, &m);
    pt_pix_round(pp->y, &n);
    pt_xt_add(t, "the viewport stage rounds it to the logical pixel ");
    add_pair(t, m, n);
    pt_xt_add(t, vp->flags & PT_REC_INSIDE ? ", inside " : ", outside ");
    add_range(t, 1, j->par.w, 1, j->par.h);
    if (!(vp->flags & PT_REC_INSIDE))
        pt_xt_add(t, " (the view rectangle's pixels): the point lies outside the viewport");
}

static void next_viewport(pt_xt *t, const pt_journey *j, const pt_vrec *r)
{
    (void)j;
    if (r->flags & PT_REC_NULL)
        pt_xt_add(t, "no pixel: segments using this vertex are skipped");
    else if (r->flags & PT_REC_INSIDE)
        pt_xt_add(t, "inside the viewport: the rasterizer writes the pixels of its segments here");
    else
        pt_xt_add(t, "outside the viewport: its pixel is clipped (the rasterizer steps "
               "there but writes nothing)");
}

static void next_framebuffer(pt_xt *t, const pt_journey *j, const pt_vrec *fb)
{
    if (fb->flags & PT_REC_NULL) pt_xt_add(t, "no pixel: no index");
    else if (j->rec[PT_STAGE_INDEX].flags & PT_REC_NULL)
        pt_xt_add(t, "outside the framebuffer: no index");
    else if (!(j->rec[PT_STAGE_VIEWPORT].flags & PT_REC_INSIDE))
        pt_xt_add(t, "inside the framebuffer but outside the viewport: it has an index, "
               "but the rasterizer never writes there");
    else pt_xt_add(t, "inside the framebuffer: the index stage numbers it");
}

static void next_index(pt_xt *t, const pt_journey *j, const pt_vrec *r)
{
    const pt_stage_params *p = &j->par;
    int sticks_out = p->x_ul < 0 || p->y_ul < 0 || (int64_t)p->x_ul + p->w > p->W ||
                     (int64_t)p->y_ul + p->h > p->H;

    if ((r->flags & PT_REC_NULL) && sticks_out &&
        (j->rec[PT_STAGE_VIEWPORT].flags & PT_REC_INSIDE))
        pt_xt_add(t, "outside the framebuffer: no index; the viewport sticks out, and a "
               "pixel drawn here lands where the course's framebuffer puts y_fb * W + x_fb "
               "(rows wrap), or is dropped when that lies outside the array");
    else if (r->flags & PT_REC_NULL)
        pt_xt_add(t, "outside the framebuffer: no index, nothing is stored for this point");
    else {
        pt_xt_add(t, "the end of the journey: the pixel's color is element ");
        pt_xt_int(t, r->i, 0);
        pt_xt_add(t, " of the pixel array");
        if (!(j->rec[PT_STAGE_VIEWPORT].flags & PT_REC_INSIDE))
            pt_xt_add(t, " (never written: outside the viewport)");
    }
}

static void next_world(pt_xt *t, const pt_journey *j, const pt_vrec *r)
{
    (void)j; (void)r;
    pt_xt_add(t, "the view stage moves the eye to the origin and turns the camera's axes onto x, y, z");
}

static void next_view(pt_xt *t, const pt_journey *j, const pt_vrec *r)
{
    (void)j;
    if (r->z > 0) {
        pt_xt_add(t, "in front of the eye (z_v > 0): the clip stage sets w_k = z_v = ");
        pt_xt_num(t, r->z, 0);
    } else
        pt_xt_add(t, "not in front of the eye (z_v <= 0): w_k will be <= 0, "
               "outside the near plane");
}

static void next_clip(pt_xt *t, const pt_journey *j, const pt_vrec *r)
{
    (void)j;
    pt_xt_add(t, "the cvv stage compares x_k, y_k, z_k with w_k = ");
    pt_xt_num(t, r->w, 0);
    pt_xt_add(t, ", before any division");
}

static void next_cvv(pt_xt *t, const pt_journey *j, const pt_vrec *r)
{
    (void)j;
    if (r->code == 0)
        pt_xt_add(t, "inside the view volume: the ndc stage divides by w_k");
    else
        pt_xt_add(t, "outside the view volume: this vertex is not divided (for w_k <= 0 that "
               "would flip it into view); its segments are clipped at the planes in clip "
               "space, and the points that makes go on from there");
}

static void next_ndc(pt_xt *t, const pt_journey *j, const pt_vrec *r)
{
    (void)j;
    pt_xt_add(t, fabs(r->x) <= 1 && fabs(r->y) <= 1 && r->z >= 0 && r->z <= 1
           ? "inside the cube [-1, 1] x [-1, 1] x [0, 1]: the screen stage stretches it over the viewport"
           : "on the cube's border (rounding): the screen stage stretches it over the viewport");
}

static void next_screen(pt_xt *t, const pt_journey *j, const pt_vrec *r)
{
    (void)j; (void)r;
    pt_xt_add(t, "the viewport stage takes the pixel whose square contains (x_s, y_s): floor of each");
}

/* Explain's row of each stage: its formula with the numbers put in, and
** what its result means for the stages after it.  A new stage adds its row
** here (tests/unit/test_explain.c fails until it has one); the viewport stage's
** formula is its pipeline's (viewport_rows[]). */
static const struct stage_row {
    coord_fn coord;              /* one coordinate's formula */
    next_fn next;                /* what comes next */
} stage_rows[PT_NSTAGES_ALL] = {
    [PT_STAGE_MODEL] = { coord_model, next_model },
    [PT_STAGE_CAMERA] = { coord_camera, next_camera },
    [PT_STAGE_IMAGE] = { coord_image, next_image },
    [PT_STAGE_PIXEL] = { coord_pixel, next_pixel },
    [PT_STAGE_VIEWPORT] = { NULL, next_viewport },          /* formula: viewport_rows[] */
    [PT_STAGE_FRAMEBUFFER] = { coord_framebuffer, next_framebuffer },
    [PT_STAGE_INDEX] = { coord_index, next_index },
    [PT_STAGE_WORLD] = { coord_world, next_world },
    [PT_STAGE_VIEW] = { coord_view, next_view },
    [PT_STAGE_CLIP] = { coord_clip, next_clip },
    [PT_STAGE_CVV] = { coord_cvv, next_cvv },
    [PT_STAGE_NDC] = { coord_ndc, next_ndc },
    [PT_STAGE_SCREEN] = { coord_screen, next_screen },
};

/* The viewport stages, keyed by a pipeline's viewport row (pt_pipeline.
** viewport_info): a pipeline with a viewport stage of its own adds a row. */
static const struct viewport_row {
    const pt_stage_info *info;   /* the pipeline's viewport row */
    coord_fn coord;              /* its formula */
} viewport_rows[] = {
    { &pt_stage_infos[PT_STAGE_VIEWPORT], coord_round },    /* classic */
    { &pt_matrix_viewport_info, coord_floor },              /* matrix */
};

/* The formula of pl's stage st, or NULL when explain has none. */
static coord_fn coord_row(const pt_pipeline *pl, pt_stage st)
{
    size_t i;

    if (st != PT_STAGE_VIEWPORT) return stage_rows[st].coord;
    for (i = 0; i < sizeof viewport_rows / sizeof viewport_rows[0]; i++)
        if (viewport_rows[i].info == pt_pipeline_info(pl, st)) return viewport_rows[i].coord;
    return NULL;
}

size_t pt_explain_next(char *buf, size_t len, const pt_journey *j, pt_stage st)
{
    pt_xt t;

    pt_xt_init(&t, buf, len);
    if ((int)st >= PT_NSTAGES_ALL) return 0;
    if (!(j->reported & 1u << st)) {
        pt_xt_add(&t, "the next stage computes from numbers this stage did not report");
        return t.len;
    }
    if (stage_rows[st].next) stage_rows[st].next(&t, j, &j->rec[st]);
    return t.len;
}

int pt_explain_has_rows(const pt_pipeline *pl, pt_stage st)
{
    if ((int)st >= PT_NSTAGES_ALL || !coord_row(pl, st) || !stage_rows[st].next) return 0;
    return st != pl->order[0] || pl->norder < 2 || first_rows[pl->order[1]] != NULL;
}
