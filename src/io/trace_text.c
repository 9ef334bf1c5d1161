/*
** src/io/trace_text.c -- the trace as aligned text, a record a line
** See LICENSE for copyright and license.
*/
#include <stdint.h>
#include <string.h>
#include "io/trace.h"
#include "io/trace_int.h"

/* ===== columns ===== */

/* Text: x as "%12.*f" (pt_fmt_fixed: "%.*e" from 1e15 on), right-aligned.
** The number goes over in one fixed-size copy of all of b, the bytes past
** its end included: they land in room that the next piece overwrites. */
static void put_fixed_col(pt_trace *t, double x, int prec)
{
    char b[PT_NUMLEN], *o = room(t, PT_NUMLEN + 12);
    size_t n = pt_fmt_fixed(b, x, prec), pad = n < 12 ? 12 - n : 0;

    memcpy(o, "            ", 12);
    memcpy(o + pad, b, PT_NUMLEN);
    t->len += pad + n;
}
static void put_int_col(pt_trace *t, int64_t x)
{
    t->len = (size_t)(int_at(t, room(t, 32), x, 12) - t->buf);
}

/* Text: "name v12", padded so that the stage names line up: to 14 columns, or
** by one space when longer. */
static void put_who(pt_trace *t, const char *name, char kind, uint64_t n)
{
    size_t nlen = strlen(name), len = nlen + 2 + pt_fmt_ulen(n);
    size_t pad = len < 14 ? 14 - len : 1;
    char *o;

    put(t, name, nlen);
    o = room(t, 40);                                /* 2 + 20 + 13 bytes */
    o[0] = ' ';
    o[1] = kind;
    o += 2 + pt_fmt_u64(o + 2, n);
    memcpy(o, "             ", 13);                 /* pad <= 13 of them */
    t->len = (size_t)(o + pad - t->buf);
}

/* Text: a stage name left-aligned in 13 columns ("%-13s", cut to 13). */
static void put_stage_col(pt_trace *t, const char *name)
{
    size_t n = strlen(name);
    char *o = room(t, 13);

    if (n > 13) n = 13;
    memcpy(o, name, n);
    memset(o + n, ' ', 13 - n);
    t->len += 13;
}

/* ===== header ===== */

/* A point as the text header writes it: "x y z". */
static void put_xyz_text(pt_trace *t, pt_vec3 v)
{
    put_short(t, v.x); put(t, " ", 1); put_short(t, v.y); put(t, " ", 1); put_short(t, v.z);
}

static void header_text(pt_trace *t, const pt_scene *s, const pt_plan *p)
{
    size_t k;
    int st, i;

    puts_(t, "# pipetrace trace, format version 1\nscene        ");
    pt_trace_json_chars(t, s->path);
    puts_(t, "\nframebuffer  "); put_i64(t, s->fb_w); puts_(t, " x "); put_i64(t, s->fb_h);
    puts_(t, ", background "); pt_trace_rgb(t, s->background, " ");
    puts_(t, "\nviewport     "); put_i64(t, s->vp_w); puts_(t, " x "); put_i64(t, s->vp_h);
    puts_(t, " at (x_ul, y_ul) = ("); put_i64(t, s->vp_x); puts_(t, ", ");
    put_i64(t, s->vp_y); puts_(t, ")\ncamera       "); puts_(t, pt_trace_camera_name(s));
    if (p->pipe->matrices) pt_trace_camera(t, s, p, 0);
    if (s->from_obj) { puts_(t, "\nobj placed   translate "); put_xyz_text(t, s->obj_translate); }
    if (t->student && *t->student) {        /* a student build: which stage files */
        puts_(t, "\nstudent      "); puts_(t, t->student);
    }
    put(t, "\n", 1);
    for (k = 0; k < s->nmodels; k++) {
        const pt_model *m = &s->models[k];
        const pt_model_plan *mp = &p->models[k];

        puts_(t, "model        "); puts_(t, m->name);
        puts_(t, ": "); put_u64(t, m->nv); puts_(t, " vertices (");
        put_u64(t, mp->nused); puts_(t, " used), "); put_u64(t, m->nseg);
        puts_(t, " segments, translate "); put_xyz_text(t, m->translate);
        puts_(t, ", color "); pt_trace_rgb(t, m->color, " ");
        if (mp->hidden) puts_(t, m->hidden_position ? ", hidden (hidden-position): not drawn, "
                                  "not traced" : ", hidden (hidden-model): not drawn, not traced");
        else if (!mp->selected) puts_(t, ", not traced (--model)");
        put(t, "\n", 1);
        if (p->pipe->matrices) {
            puts_(t, "  world      "); pt_trace_mat(t, &mp->world, 0); put(t, "\n", 1);
        }
        for (i = 0; i < p->norder; i++) {
            st = p->order[i];
            if (mp->why[st] == PT_WHY_TRACED) continue;
            puts_(t, "  left out   "); puts_(t, pt_stage_infos[st].name);
            puts_(t, ": "); puts_(t, mp->why_text[st]); put(t, "\n", 1);
        }
    }
    put(t, "\n", 1);
}

/* ===== vertex records ===== */

/* "x_pp = ": the name of value k of stage st (stages/pt_stage.h), padded to
** four characters so that the columns line up. */
static void put_lhs(pt_trace *t, pt_stage st, int k)
{
    const char *name = pt_stage_infos[st].coord[k];
    size_t n = strlen(name);

    put(t, name, n);
    for (; n < 4; n++) put(t, " ", 1);
    put(t, " = ", 3);
}

/* --explain: r's formula with this vertex's numbers, from the journey pt_run()
** handed over before the records, so a stage left out still feeds the next
** one its real value: an indented line (trace_jsonl.c: an "explain" field). */
static void put_explain(pt_trace *t, const pt_vrec *r)
{
    char b[PT_EXPLAINLEN];
    size_t n;

    if (!t->journey_made) return;
    n = pt_explain_stage(b, sizeof b, &t->journey, r->stage, "; ");
    if (n >= sizeof b) n = sizeof b - 1;
    put_col(t, "", 0, 14);
    put(t, b, n);
    put(t, "\n", 1);
}

/* Text: "  ! cancellation (9 digits lost)". */
static void put_warnings_text(pt_trace *t, const pt_vrec *r)
{
    int k;

    puts_(t, "  !");
    for (k = 0; k < PT_NWARN; k++) {
        if (!(r->warn & (1u << k))) continue;
        put(t, " ", 1);
        puts_(t, pt_warn_names[k]);
        if ((1u << k) & (PT_WARN_CANCEL | PT_WARN_ILLCOND)) {
            puts_(t, " ("); put_i64(t, r->digits_lost); puts_(t, " digits lost)");
        }
    }
}

/* Text: the rest of "(0b000101: outside near left)", or ": inside ...)". */
static void put_planes_text(pt_trace *t, unsigned code)
{
    int k;

    if (!code) { puts_(t, ": inside the view volume)"); return; }
    puts_(t, ": outside");
    for (k = 0; k < PT_CVV_NPLANES; k++)
        if (code & (1u << k)) { put(t, " ", 1); puts_(t, pt_cvv_names[k]); }
    put(t, ")", 1);
}

/* The stage at which the trace of a point made by clipping begins: the one
** after its pipeline's last segment stage (the matrix camera's ndc, after
** the cvv), or -1 for a pipeline without segment stages.  Asked only for
** such points. */
static int made_first(const pt_trace *t)
{
    const pt_pipeline *pl = pt_scene_pipeline(t->scene);
    int i;

    if (!pl->nsegstages) return -1;
    for (i = 0; i + 1 < pl->norder; i++)
        if (pl->order[i] == pl->segstages[pl->nsegstages - 1].stage) return (int)pl->order[i + 1];
    return -1;
}

static void vertex_text(pt_trace *t, const pt_vrec *r)
{
    const pt_stage_info *in = &pt_stage_infos[r->stage];

    if (t->clipv) put_who(t, t->model->name, 's', t->seg);
    else put_who(t, t->model->name, 'v', t->v);
    put_stage_col(t, in->name);
    switch (in->kind) {
    case PT_VAL_OUTCODE: {                  /* "code = 61 = 0b111101" */
        char bits[PT_CVV_NPLANES + 1];
        int k;
        for (k = 0; k < PT_CVV_NPLANES; k++)
            bits[k] = r->code & (1u << (PT_CVV_NPLANES - 1 - k)) ? '1' : '0';
        bits[PT_CVV_NPLANES] = '\0';
        put_lhs(t, r->stage, 0); put_i64(t, r->code); puts_(t, "  (0b"); puts_(t, bits);
        put_planes_text(t, r->code);
        break;
    }
    case PT_VAL_INDEX:
        put_lhs(t, r->stage, 0);
        if (r->flags & PT_REC_NULL) put_col(t, "none", 4, 12);
        else put_int_col(t, r->i);
        break;
    case PT_VAL_REAL: {
        const double v[4] = {r->x, r->y, r->z, r->w};
        int k;
        for (k = 0; k < in->nreal; k++) {
            if (k) puts_(t, "  ");
            put_lhs(t, r->stage, k); put_fixed_col(t, v[k], t->precision);
        }
        break;
    }
    case PT_VAL_PIXEL:                      /* null per value */
        put_lhs(t, r->stage, 0);
        if (pt_rec_has(r, 0)) put_int_col(t, r->ix); else put_col(t, "none", 4, 12);
        puts_(t, "  "); put_lhs(t, r->stage, 1);
        if (pt_rec_has(r, 1)) put_int_col(t, r->iy); else put_col(t, "none", 4, 12);
        break;
    }
    if (r->flags & PT_REC_BEHIND) puts_(t, "  behind the camera");
    if (in->flags & PT_REC_INSIDE)          /* a stage that says inside or not */
        puts_(t, r->flags & PT_REC_INSIDE ? "  inside" : "  outside");
    if (t->clipv && (int)r->stage == made_first(t)) {
        puts_(t, "  (clipped v"); put_u64(t, t->from); puts_(t, "-v"); put_u64(t, t->to);
        puts_(t, " at t = "); put_short(t, t->t_clip); put(t, ")", 1);
    }
    if (r->warn) put_warnings_text(t, r);
    put(t, "\n", 1);
    if (t->explain) put_explain(t, r);
}

static void on_vertex(void *ud, const pt_vrec *r)
{
    vertex_text(ud, r);
}

/* ===== raster records ===== */

/* "m1 s7          pixel        x_fb = ": how the pixel records of segment
** seg of m begin (pt_trace_pixel_prefix). */
static size_t pixel_opening(pt_trace *t, const pt_model *m, uint64_t seg)
{
    put_who(t, m->name, 's', seg);
    puts_(t, "pixel        x_fb = ");
    return 0;
}

static void pixel_prefix(pt_trace *t, const pt_model *m, uint64_t seg)
{
    pt_trace_pixel_prefix(t, m, seg, pixel_opening);
}

/* One pixel record of segment or point ('s', 'p') n, the long way. */
static void pixel_line(pt_trace *t, const pt_model *m, char kind, uint64_t n,
                       const pt_fb_pixel *p)
{
    put_who(t, m->name, kind, n);
    puts_(t, "pixel        x_fb = "); put_int_col(t, p->x_fb);
    puts_(t, "  y_fb = "); put_int_col(t, p->y_fb);
    puts_(t, "  idx = "); put_i64(t, p->idx);
    put(t, "\n", 1);
}

/* A segment's pixel record, the long way: for a model whose name is too long
** to keep its opening. */
static void pixel_long(pt_trace *t, const pt_model *m, uint64_t seg, const pt_fb_pixel *p)
{
    pixel_line(t, m, 's', seg, p);
}

/* The rest of a pixel record after its kept opening, at o:
** '  X  y_fb = Y  idx = I\n'. */
static char *pixel_text_at(const pt_trace *t, char *o, const pt_fb_pixel *p)
{
    o = int_at(t, o, p->x_fb, 12);
    o = int_at(t, str_at(o, "  y_fb = "), p->y_fb, 12);
    o = int_at(t, str_at(o, "  idx = "), p->idx, 0);
    *o++ = '\n';
    return o;
}

static void on_pixels(void *ud, const pt_model *m, uint64_t seg, const pt_fb_pixel *px,
                      size_t n)
{
    pixels_put(ud, m, seg, px, n, pixel_prefix, pixel_long, pixel_text_at);
}

/* A point's pixels: "NAME pN pixel        x_fb = X  y_fb = Y  idx = I", the
** plain way (a point has few pixels inside the viewport). */
static void on_point_pixels(void *ud, const pt_model *m, uint64_t pt, const pt_fb_pixel *px,
                            size_t n)
{
    size_t k;

    for (k = 0; k < n; k++) pixel_line(ud, m, 'p', pt, &px[k]);
}

/* One coordinate of a clipped step: "none" where the step has none (a
** value beyond what the rasterizer rounds, PT_PIX_NONE). */
static void put_clip_coord(pt_trace *t, int64_t x)
{
    if (x == PT_PIX_NONE) puts_(t, "none");
    else put_i64(t, x);
}

static void put_pair_text(pt_trace *t, pt_pix p)
{
    put(t, "(", 1); put_clip_coord(t, p.x); puts_(t, ", "); put_clip_coord(t, p.y); put(t, ")", 1);
}

static void on_clip(void *ud, const pt_model *m, uint64_t seg, uint64_t count,
                    pt_pix first, pt_pix last)
{
    pt_trace *t = ud;

    put_who(t, m->name, 's', seg);
    puts_(t, "clipped      "); put_u64(t, count);
    puts_(t, count == 1 ? " step at (x_vp, y_vp) = " : " steps, (x_vp, y_vp) from ");
    put_pair_text(t, first);
    if (count > 1) { puts_(t, " to "); put_pair_text(t, last); }
    put(t, "\n", 1);
}

/* A segment's remark, KIND ("skipped     ", "note        "): "NAME sN KIND vV: TEXT". */
static void remark(pt_trace *t, const pt_model *m, uint64_t seg, const char *kind,
                   uint64_t v, const char *text)
{
    put_who(t, m->name, 's', seg);
    puts_(t, kind);
    if (v) { put(t, "v", 1); put_u64(t, v); puts_(t, ": "); }
    puts_(t, text); put(t, "\n", 1);
}

static void on_skip(void *ud, const pt_model *m, uint64_t seg, uint64_t v, const char *why)
{
    remark(ud, m, seg, "skipped      ", v, why);
}

static void on_note(void *ud, const pt_model *m, uint64_t seg, uint64_t v, const char *what)
{
    remark(ud, m, seg, "note         ", v, what);
}

/* ===== summary ===== */

static void on_summary(void *ud, const pt_summary *sum)
{
    pt_trace *t = ud;
    pt_trace_count c[PT_TRACE_NCOUNTS];
    size_t k;

    pt_trace_counts(sum, c);
    puts_(t, "\nsummary");
    for (k = 0; k < PT_TRACE_NCOUNTS; k++) {
        puts_(t, k % 4 == 0 ? "\n  " : "  ");
        puts_(t, c[k].name); put(t, " ", 1);
        pt_trace_put_u128(t, c[k].hi, c[k].lo);
    }
    puts_(t, "\n  warnings");
    for (k = 0; k < PT_NWARN; k++) {
        put(t, " ", 1); puts_(t, pt_warn_names[k]); put(t, " ", 1);
        put_u64(t, sum->warnings[k]);
    }
    puts_(t, sum->rasterized ? "\n  rasterized yes\n" : "\n  rasterized no (--vertex without --image)\n");
}

const pt_trace_writer pt_trace_text = {
    header_text, on_vertex, on_pixels, on_clip, on_point_pixels, on_skip, on_note, on_summary
};
