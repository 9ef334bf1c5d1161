/*
** src/io/explain_course.c -- renderers 7 and 9: one vertex's stages with its numbers put in
** See LICENSE for copyright and license.
**
** The numbers come from one render (pt_course_render), heard through its
** listener: the stages' results, the clip stages' cut records (t, the ends,
** the new point and colour as the stage computed them) and the rasterizer's
** pixel lines.  The pixel plane is the rasterizer's own map (the reference
** pixel stage, ptref_image2pixel), its formula the stage table's
** (pt_stage_infos, in the course's names x_p, y_p for its x_ip, y_ip); gamma, anti-aliasing's weight and blend and
** the colour bytes are stages/pt_color.h's functions.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/explain_course.h"
#include "io/explain_text.h"
#include "io/explain.h"
#include "core/pipetrace.h"

/* ===== listening to the render ===== */

/* The camera, and the position being worked on: the one a POSITION
** (Pipeline) or STEP (Pipeline2) mark names. */
static void on_mark(void *ud, pt_course_mark k, const pt_course_cam *cam,
                    const pt_course_pos *pos)
{
    pt_cx_journey *j = ud;

    if (k == PT_CMK_BEGIN) j->cam = *cam;
    if (k != PT_CMK_POSITION && k != PT_CMK_STEP) return;
    j->cur = pos->index;
    j->prim_no = 0;
    if (pos->index == j->mi) {
        j->translate = pos->translate;
        j->matrix = pos->matrix;
    }
}

/* The vertex's viewport pixel: the rasterizer's map of its clipped point. */
static pt_vec2 pixel_plane(const pt_cx_journey *j)
{
    pt_vec3 ip = {j->at[PT_CST_CLIP].x, j->at[PT_CST_CLIP].y, 0.0};
    return ptref_image2pixel(ip, j->par.w, j->par.h, NULL);
}

/* The vertex after the clip as the rasterizer maps it: mapped, px_x, px_y. */
static void map_clipped(pt_cx_journey *j)
{
    pt_vec2 pp = pixel_plane(j);
    pt_vec4 p = j->at[PT_CST_CLIP];
    /* the rasterizer maps only what the clip keeps: |x|, |y| <= 1 (or NaN,
    ** which every comparison lets through), so x_pp is within the
    ** viewport and Math.round fits an int */
    j->mapped = !(fabs(p.x) > 1 || fabs(p.y) > 1);
    if (j->mapped) {
        j->px_x = (int64_t)pt_explain_java_int_round(pp.x) - 1;
        j->px_y = (int64_t)j->par.h - pt_explain_java_int_round(pp.y);
    }
}

static void on_stage(void *ud, pt_course_stage st, const pt_course_pos *pos,
                     const pt_rv_model *m)
{
    pt_cx_journey *j = ud;
    size_t k = (size_t)(j->v - 1);

    j->prim_no = 0;
    if (pos->index != j->mi) return;
    j->nv_last = m->nv;
    if (k >= m->nv) return;
    j->have[st] = 1;
    j->at[st] = m->v[k];
    if (j->born != PT_CST_MODEL) {
        j->has_col[st] = j->cut.c_new < m->nc;
        if (j->has_col[st]) j->col[st] = m->c[j->cut.c_new];
    } else if (k < m->nc) {
        j->has_col[st] = 1;
        j->col[st] = m->c[k];
    }
    if (st == PT_CST_CLIP) map_clipped(j);
}

static void clip_begin(void *ud, const pt_rv_model *m, const pt_rv_prim *p)
{
    pt_cx_journey *j = ud;

    (void)m;
    if (j->cur != j->mi) return;
    j->prim_no++;
    j->clip_prim = *p;
}

static void clip_cut(void *ud, const pt_rv_cut *c)
{
    pt_cx_journey *j = ud;
    pt_course_stage st = c->edge == PT_RV_NEAR ? PT_CST_NEARCLIP : PT_CST_CLIP;

    if (j->cur != j->mi) return;
    if ((uint64_t)c->v_new + 1 == j->v) {
        j->born = st;
        j->cut = *c;
        j->cut_prim = j->prim_no;
    }
    if ((uint64_t)j->clip_prim.v[c->off] + 1 == j->v && j->noff < PT_CX_MAXCUT) {
        j->off[j->noff].stage = st;
        j->off[j->noff].prim = j->prim_no;
        j->off[j->noff].cut = *c;
        j->noff++;
    }
    j->clip_prim.v[c->off] = c->v_new;
    j->clip_prim.c[c->off] = c->c_new;
}

static void on_raster(void *ud, const pt_course_pos *pos, const pt_rv_model *m,
                      const pt_rv_prim *p)
{
    pt_cx_journey *j = ud;
    int e;

    j->end_here = 0;
    if (pos->index != j->mi) return;
    j->raster_no++;
    for (e = 0; e < (p->kind == PT_RV_POINT ? 1 : 2); e++)
        if ((uint64_t)p->v[e] + 1 == j->v) {
            j->end_here = 1;
            j->end_c = m->c[p->c[e]];
        }
    if (j->end_here) j->nends++;
}

/* 1 when pixel line px writes the vertex's pixel. */
static int at_vertex(const pt_cx_journey *j, const pt_rv_pixel *px)
{
    switch (px->kind) {
    case PT_RV_PX_STEP:
    case PT_RV_PX_END:
    case PT_RV_PX_POINT:
        return px->x_vp == j->px_x && px->y_vp == j->px_y;
    case PT_RV_PX_AA:
        return px->transposed ? px->y_vp == j->px_y && (px->lo == j->px_x || px->hi == j->px_x)
                              : px->x_vp == j->px_x && (px->lo == j->px_y || px->hi == j->px_y);
    }
    return 0;
}

static void on_pixel(void *ud, const pt_rv_pixel *px)
{
    pt_cx_journey *j = ud;

    if (!j->end_here || j->npx == PT_CX_MAXPX || !at_vertex(j, px)) return;
    if (px->kind == PT_RV_PX_POINT && px->clipped) return;
    j->px[j->npx].prim = j->raster_no;
    j->px[j->npx].px = *px;
    j->px[j->npx].px.par = NULL;
    j->px[j->npx].end_c = j->end_c;
    j->npx++;
}

/* Start j for scene s: renderer, switches, viewport and framebuffer. */
static void begin(pt_cx_journey *j, const pt_scene *s)
{
    memset(j, 0, sizeof *j);
    j->renderer = s->renderer;
    j->nearclip = s->nearclip;
    j->born = PT_CST_MODEL;
    j->par.w = s->vp_w;  j->par.h = s->vp_h;
    j->par.x_ul = s->vp_x;  j->par.y_ul = s->vp_y;
    j->par.W = s->fb_w;  j->par.H = s->fb_h;
    memcpy(j->par.bg, s->vp_background, 3);
    j->par.antialias = s->antialias;
    j->par.gamma = s->gamma;
    j->cur = (size_t)-1;
}

int pt_cx_run(pt_cx_journey *j, const pt_scene *s, size_t mi, uint64_t v)
{
    pt_rv_raster_ls rls;
    pt_course_ls ls;
    pt_fb fb;
    int rc, i;
    pt_course_stage cs;

    begin(j, s);
    j->mi = mi;
    j->v = v;
    j->nv = s->models[mi].nv;

    memset(&rls, 0, sizeof rls);
    rls.pixel = on_pixel;
    rls.ud = j;
    memset(&ls, 0, sizeof ls);
    ls.mark = on_mark;
    ls.stage = on_stage;
    ls.raster = on_raster;
    ls.nearclip.begin = ls.clip.begin = clip_begin;
    ls.nearclip.cut = ls.clip.cut = clip_cut;
    ls.nearclip.ud = ls.clip.ud = j;
    ls.raster_ls = &rls;
    ls.ud = j;
    if (pt_fb_init(&fb, s->fb_w, s->fb_h, s->background) != 0) return -1;
    rc = pt_course_render(s, &fb, &ls);
    pt_fb_free(&fb);
    if (rc != 0) return -1;
    if (!j->have[PT_CST_CLIP]) return 1;
    for (i = 0; i < PT_NCST; i++) {
        cs = (pt_course_stage)i;
        if (cs == PT_CST_WORLD && j->renderer != 9) continue;
        if (cs < j->born) continue;
        j->steps[j->nsteps++] = pt_cx_step_of(cs);
    }
    j->steps[j->nsteps++] = PT_CXS_PIXEL;
    j->steps[j->nsteps++] = PT_CXS_VIEWPORT;
    j->steps[j->nsteps++] = PT_CXS_RASTER;
    return 0;
}

/* pt_cx_find's listener: the most vertices each position's model had. */
typedef struct finder { size_t *most; } finder;

static void find_stage(void *ud, pt_course_stage st, const pt_course_pos *pos,
                       const pt_rv_model *m)
{
    finder *f = ud;

    (void)st;
    if (m->nv > f->most[pos->index]) f->most[pos->index] = m->nv;
}

int pt_cx_find(const pt_scene *s, uint64_t v, size_t *mi)
{
    pt_course_ls ls;
    finder f;
    pt_fb fb;
    size_t k;
    int rc;

    f.most = calloc(s->nmodels ? s->nmodels : 1, sizeof *f.most);
    if (!f.most) return -1;
    memset(&ls, 0, sizeof ls);
    ls.stage = find_stage;
    ls.ud = &f;
    if (pt_fb_init(&fb, s->fb_w, s->fb_h, s->background) != 0) { free(f.most); return -1; }
    rc = pt_course_render(s, &fb, &ls);
    pt_fb_free(&fb);
    for (k = 0; rc == 0 && k < s->nmodels; k++)
        if (f.most[k] >= v) break;
    free(f.most);
    if (rc != 0) return -1;
    if (k == s->nmodels) return 1;
    *mi = k;
    return 0;
}

/* ===== the rows: each stage's name, spaces, what it does, its formula ===== */

static const pt_cx_row rows[PT_NCXS] = {
    { "model", "scene", "model", "the vertex as the scene gives it, and its colour",
      "(x_m, y_m, z_m) as given", "(x_m, y_m, z_m, w_m = 1) as given" },
    { "world", "model", "world", "the position's matrix M: v_w = M v_m (renderer 9)",
      "", "x_w = (M00*x_m) + (M01*y_m) + (M02*z_m) + (M03*w_m), y_w, z_w, w_w likewise" },
    { "view", "model / world", "view", "r7: add the position's translation; r9: subtract the "
      "camera's translation (its view vector)",
      "x_v = x_t + x_m, y_v = y_t + y_m, z_v = z_t + z_m",
      "x_v = (-1*v_x) + x_w, y_v = (-1*v_y) + y_w, z_v = (-1*v_z) + z_w, w = 1" },
    { "camera", "view", "camera", "normalize the view volume: its rectangle l..r, b..t "
      "becomes -1..1 (perspective: skew, orthographic: shift, then scale)",
      "perspective x = x_v + (z_v*(r+l))/2, orthographic x = x_v - (r+l)/2; "
      "x_c = (2*x)/(r-l) (y with t, b); z_c = z_v",
      "v_c = N v_v, N = m2.times(m1): m1 the skew (perspective) or shift "
      "(orthographic), m2 = diag(2/(r-l), 2/(t-b), 1, 1)" },
    { "nearclip", "camera", "camera", "cut each segment at the near plane z = n: an end "
      "beyond it (z > n) is replaced by the point where the segment crosses it",
      "both z <= n: kept; both z > n: dropped; else t = (n - z1)/(z0 - z1), "
      "x = (1 - t)*x1 + t*x0, y likewise, z = n, colour (1 - t_)*c1 + t_*c0, t_ = (float)t",
      NULL },
    { "image", "camera", "image plane", "project onto the image plane z = -1: divide by the "
      "distance -z_c (orthographic: drop z)",
      "x_p = x_c / -z_c, y_p = y_c / -z_c, z_p = -1 (orthographic: x_p = x_c, y_p = y_c, z_p = 0)",
      NULL },
    { "clip", "image plane", "image plane", "clip each segment to the view rectangle "
      "-1..1, one edge at a time (x = +1, x = -1, y = +1, y = -1)",
      "t = (e - x_o)/(x_i - x_o), x = e, y = (1 - t)*y_o + t*y_i (edge x = e; y = e "
      "likewise), z = 0, colour (1 - t_)*c_o + t_*c_i",
      NULL },
    { "pixel", "image plane", "pixel plane", "stretch the view rectangle over the "
      "viewport's logical pixels (the rasterizer's first step)",
      NULL, NULL },                     /* the stage table's: pixel_formula() */
    { "viewport", "pixel plane", "viewport", "round to the logical pixel with Java's "
      "Math.round, count from 0 and from the top row down, then place in the framebuffer",
      "x_vp = Math.round(x_pp) - 1, y_vp = h - Math.round(y_pp); x_fb = x_ul + x_vp, "
      "y_fb = y_ul + y_vp; index = y_fb*W + x_fb",
      NULL },
    { "raster", "viewport", "framebuffer", "the colour bytes the rasterizer writes at the "
      "vertex's pixel: anti-aliasing's weight and gamma where they apply",
      "c = (float)|c0 + slope*(x - x0)|, slope = (c1 - c0)/(x1 - x0) (x the stepped "
      "coordinate); anti-aliasing: f = (float)(y - floor(y)), low = (1 - f)*c + f*bg, "
      "high = f*c + (1 - f)*bg; gamma: c' = (float)Math.pow(c, 1/2.2); "
      "byte = (int)((double)(c'*255f) + 0.5); the last pixel: byte of c1, no gamma",
      NULL },
};

const pt_cx_row *pt_cx_row_of(pt_cx_step st)
{
    return &rows[st];
}

/* ===== the pixel plane: the stage table's formula ===== */

/* The course's names of the image plane's x and y, as rows[PT_CXS_IMAGE]
** spells them; the stage table (renderer 4's) calls them x_ip, y_ip. */
static const char *const course_ip[2] = {"x_p", "y_p"};

/* src, a formula of the stage table, into t: each of the table's names of
** the image plane's x and y (pt_stage_infos[PT_STAGE_IMAGE].coord) as the
** course names it; with j, that name as j's value there (ip) and w, h as
** j's viewport's width and height. */
static void table_text(pt_xt *t, const char *src, const pt_cx_journey *j, const double ip[2])
{
    while (*src) {
        char id[32];
        size_t n = 0;
        int k;
        if (!(*src == '_' || (*src >= 'a' && *src <= 'z') || (*src >= 'A' && *src <= 'Z'))) {
            id[0] = *src++;
            id[1] = '\0';
            pt_xt_add(t, id);
            continue;
        }
        while ((*src == '_' || (*src >= 'a' && *src <= 'z') || (*src >= 'A' && *src <= 'Z') ||
                (*src >= '0' && *src <= '9')) && n + 1 < sizeof id)
            id[n++] = *src++;
        id[n] = '\0';
        for (k = 0; k < 2 && strcmp(id, pt_stage_infos[PT_STAGE_IMAGE].coord[k]); k++) ;
        if (k < 2 && j) pt_xt_num(t, ip[k], 0);
        else if (k < 2) pt_xt_add(t, course_ip[k]);
        else if (j && !strcmp(id, "w")) pt_xt_int(t, j->par.w, 0);
        else if (j && !strcmp(id, "h")) pt_xt_int(t, j->par.h, 0);
        else pt_xt_add(t, id);
    }
}

/* The pixel plane's formula: the stage table's (stages/pt_stage.c, the map
** of s3_image2pixel.h, which the course's rasterizer makes too), in the
** course's names. */
static const char *pixel_formula(void)
{
    static char f[256];
    pt_xt t;

    if (!f[0]) {
        pt_xt_init(&t, f, sizeof f);
        table_text(&t, pt_stage_infos[PT_STAGE_PIXEL].formula, NULL, NULL);
    }
    return f;
}

const char *pt_cx_formula(int renderer, pt_cx_step st)
{
    const pt_cx_row *r = &rows[st];

    if (st == PT_CXS_PIXEL) return pixel_formula();

    if (st == PT_CXS_WORLD) return renderer == 9 ? r->formula9 : NULL;
    return renderer == 9 && r->formula9 ? r->formula9 : r->formula7;
}

int pt_cx_has_rows(int renderer, pt_cx_step st)
{
    const pt_cx_row *r = &rows[st];
    const char *f = pt_cx_formula(renderer, st);

    return r->name && r->from && r->to && r->what && f && *f;
}

pt_cx_step pt_cx_step_of(pt_course_stage cs)
{
    switch (cs) {
    case PT_CST_MODEL:    return PT_CXS_MODEL;
    case PT_CST_WORLD:    return PT_CXS_WORLD;
    case PT_CST_VIEW:     return PT_CXS_VIEW;
    case PT_CST_CAMERA:   return PT_CXS_CAMERA;
    case PT_CST_NEARCLIP: return PT_CXS_NEARCLIP;
    case PT_CST_IMAGE:    return PT_CXS_IMAGE;
    case PT_CST_CLIP:     return PT_CXS_CLIP;
    }
    return PT_CXS_MODEL;
}

/* ===== the text ===== */

static double vcomp(pt_vec4 v, int k)
{
    return k == 0 ? v.x : k == 1 ? v.y : k == 2 ? v.z : v.w;
}

static double ccomp(pt_rgb c, int k)
{
    return k == 0 ? (double)c.r : k == 1 ? (double)c.g : (double)c.b;
}

static const char *const xyzw = "xyzw";
static const char *const rgb_names[3] = {"r", "g", "b"};

/* "x_w" */
static void name(pt_xt *t, int k, const char *sub)
{
    char b[2] = {xyzw[k], '\0'};
    pt_xt_add(t, b); pt_xt_add(t, "_"); pt_xt_add(t, sub);
}

static void rgb(pt_xt *t, pt_rgb c)
{
    pt_xt_add(t, "(");
    pt_xt_num(t, (double)c.r, 0); pt_xt_add(t, ", ");
    pt_xt_num(t, (double)c.g, 0); pt_xt_add(t, ", ");
    pt_xt_num(t, (double)c.b, 0); pt_xt_add(t, ")");
}

static void bytes(pt_xt *t, pt_rgb c)
{
    pt_xt_add(t, "(");
    pt_xt_int(t, pt_color_byte(c.r), 0); pt_xt_add(t, ", ");
    pt_xt_int(t, pt_color_byte(c.g), 0); pt_xt_add(t, ", ");
    pt_xt_int(t, pt_color_byte(c.b), 0); pt_xt_add(t, ")");
}

/* The rows of matrix m, "M = [a b c d; ...]". */
static void matrix(pt_xt *t, const char *mname, const pt_jmat *m)
{
    int r, c;

    pt_xt_add(t, mname);
    pt_xt_add(t, " = [");
    for (r = 0; r < 4; r++) {
        if (r) pt_xt_add(t, "; ");
        for (c = 0; c < 4; c++) {
            if (c) pt_xt_add(t, " ");
            pt_xt_num(t, vcomp(m->col[c], r), 0);
        }
    }
    pt_xt_add(t, "]");
}

/* Coordinate k of m times in: "x_w = (M00*x_m) + ... = (1*-1) + ... = res". */
static void product(pt_xt *t, const char *mname, const pt_jmat *m, const char *from,
                    pt_vec4 in, const char *to, pt_vec4 out, int k, const char *sep)
{
    int c;
    char ij[8];

    pt_xt_add(t, sep);
    name(t, k, to); pt_xt_add(t, " = ");
    for (c = 0; c < 4; c++) {
        if (c) pt_xt_add(t, " + ");
        ij[0] = (char)('0' + k); ij[1] = (char)('0' + c); ij[2] = '\0';
        pt_xt_add(t, "("); pt_xt_add(t, mname); pt_xt_add(t, ij); pt_xt_add(t, "*");
        name(t, c, from); pt_xt_add(t, ")");
    }
    pt_xt_add(t, " = ");
    for (c = 0; c < 4; c++) {
        if (c) pt_xt_add(t, " + ");
        pt_xt_add(t, "("); pt_xt_num(t, vcomp(m->col[c], k), 0); pt_xt_add(t, "*");
        pt_xt_num(t, vcomp(in, c), 1); pt_xt_add(t, ")");
    }
    pt_xt_add(t, " = ");
    pt_xt_num(t, vcomp(out, k), 0);
}

static const char *edge_name(pt_rv_edge e)
{
    switch (e) {
    case PT_RV_NEAR: return "z = n";
    case PT_RV_XPOS: return "x = +1";
    case PT_RV_XNEG: return "x = -1";
    case PT_RV_YPOS: return "y = +1";
    case PT_RV_YNEG: return "y = -1";
    }
    return "";
}

/* "(1 - t)*a + t*b = (1 - T)*A + T*B = res" */
static void lerp(pt_xt *t, const char *tn, double tv, const char *an, double a,
                 const char *bn, double b, double res)
{
    pt_xt_add(t, "(1 - "); pt_xt_add(t, tn); pt_xt_add(t, ")*"); pt_xt_add(t, an);
    pt_xt_add(t, " + "); pt_xt_add(t, tn); pt_xt_add(t, "*"); pt_xt_add(t, bn);
    pt_xt_add(t, " = (1 - "); pt_xt_num(t, tv, 1); pt_xt_add(t, ")*"); pt_xt_num(t, a, 1);
    pt_xt_add(t, " + "); pt_xt_num(t, tv, 1); pt_xt_add(t, "*"); pt_xt_num(t, b, 1);
    pt_xt_add(t, " = "); pt_xt_num(t, res, 0);
}

/* The colour of a cut: c[2] = (1 - t_)*c[1] + t_*c[0], t_ = (float)t. */
static void cut_colour(pt_xt *t, const pt_rv_cut *c, const char *c1, const char *c0,
                       const char *sep)
{
    double tf = (double)(float)c->t;
    char a[8], b[8];
    int k;

    pt_xt_add(t, sep); pt_xt_add(t, "t_ = (float)t = "); pt_xt_num(t, tf, 0);
    pt_xt_add(t, " (the colour in float arithmetic)");
    for (k = 0; k < 3; k++) {
        pt_xt_add(t, sep);
        pt_xt_add(t, rgb_names[k]); pt_xt_add(t, " = ");
        strcpy(a, rgb_names[k]); strcat(a, c1);
        strcpy(b, rgb_names[k]); strcat(b, c0);
        lerp(t, "t_", tf, a, ccomp(c->c[1], k), b, ccomp(c->c[0], k), ccomp(c->c[2], k));
    }
}

static void cut_near(pt_xt *t, const pt_cx_journey *j, const char *sep)
{
    const pt_rv_cut *c = &j->cut;
    int k;

    pt_xt_add(t, "made by the near clip of segment "); pt_xt_int(t, (int64_t)j->cut_prim, 0);
    pt_xt_add(t, ": z0 = "); pt_xt_num(t, c->p[0].z, 0);
    pt_xt_add(t, ", z1 = "); pt_xt_num(t, c->p[1].z, 0);
    pt_xt_add(t, ", n = "); pt_xt_num(t, c->plane, 0);
    pt_xt_add(t, c->off ? ": v1 lies beyond the near plane" : ": v0 lies beyond the near plane");
    pt_xt_add(t, sep);
    pt_xt_add(t, "t = (n - z1)/(z0 - z1) = ("); pt_xt_num(t, c->plane, 0); pt_xt_add(t, " - ");
    pt_xt_num(t, c->p[1].z, 1); pt_xt_add(t, ")/("); pt_xt_num(t, c->p[0].z, 0);
    pt_xt_add(t, " - "); pt_xt_num(t, c->p[1].z, 1); pt_xt_add(t, ") = ");
    pt_xt_num(t, c->t, 0);
    for (k = 0; k < 2; k++) {
        char a[4] = {xyzw[k], '1', '\0'}, b[4] = {xyzw[k], '0', '\0'}, n[2] = {xyzw[k], '\0'};
        pt_xt_add(t, sep); pt_xt_add(t, n); pt_xt_add(t, " = ");
        lerp(t, "t", c->t, a, vcomp(c->p[1], k), b, vcomp(c->p[0], k), vcomp(c->p[2], k));
    }
    pt_xt_add(t, sep); pt_xt_add(t, "z = n = "); pt_xt_num(t, c->p[2].z, 0);
    cut_colour(t, c, "1", "0", sep);
}

static void cut_rect(pt_xt *t, const pt_cx_journey *j, const char *sep)
{
    const pt_rv_cut *c = &j->cut;
    int on_x = c->edge == PT_RV_XPOS || c->edge == PT_RV_XNEG, k = on_x ? 0 : 1;
    char a[8], b[8], n[2] = {xyzw[1 - k], '\0'};

    pt_xt_add(t, "made by the clip of segment "); pt_xt_int(t, (int64_t)j->cut_prim, 0);
    pt_xt_add(t, " at the edge "); pt_xt_add(t, edge_name(c->edge));
    pt_xt_add(t, ": the end o = ("); pt_xt_num(t, c->p[1].x, 0); pt_xt_add(t, ", ");
    pt_xt_num(t, c->p[1].y, 0); pt_xt_add(t, ") lies beyond it, i = (");
    pt_xt_num(t, c->p[0].x, 0); pt_xt_add(t, ", "); pt_xt_num(t, c->p[0].y, 0);
    pt_xt_add(t, ") is the other end");
    pt_xt_add(t, sep);
    pt_xt_add(t, on_x ? "t = (e - x_o)/(x_i - x_o) = (" : "t = (e - y_o)/(y_i - y_o) = (");
    pt_xt_num(t, c->plane, 0); pt_xt_add(t, " - "); pt_xt_num(t, vcomp(c->p[1], k), 1);
    pt_xt_add(t, ")/("); pt_xt_num(t, vcomp(c->p[0], k), 0); pt_xt_add(t, " - ");
    pt_xt_num(t, vcomp(c->p[1], k), 1); pt_xt_add(t, ") = "); pt_xt_num(t, c->t, 0);
    pt_xt_add(t, sep); pt_xt_add(t, on_x ? "x = e = " : "y = e = "); pt_xt_num(t, c->plane, 0);
    pt_xt_add(t, sep); pt_xt_add(t, n); pt_xt_add(t, " = ");
    a[0] = b[0] = xyzw[1 - k]; strcpy(a + 1, "_o"); strcpy(b + 1, "_i");
    lerp(t, "t", c->t, a, vcomp(c->p[1], 1 - k), b, vcomp(c->p[0], 1 - k),
         vcomp(c->p[2], 1 - k));
    pt_xt_add(t, sep); pt_xt_add(t, "z = 0");
    cut_colour(t, c, "_o", "_i", sep);
}

/* The cuts that cut the vertex off in stage cs. */
static void cut_offs(pt_xt *t, const pt_cx_journey *j, pt_course_stage cs, const char *sep)
{
    size_t k;

    for (k = 0; k < j->noff; k++) {
        const pt_cx_off *o = &j->off[k];
        if (o->stage != cs) continue;
        pt_xt_add(t, sep); pt_xt_add(t, "segment "); pt_xt_int(t, (int64_t)o->prim, 0);
        pt_xt_add(t, " is cut at "); pt_xt_add(t, edge_name(o->cut.edge));
        pt_xt_add(t, ", t = "); pt_xt_num(t, o->cut.t, 0);
        pt_xt_add(t, ": its end here is replaced by vertex ");
        pt_xt_int(t, (int64_t)o->cut.v_new + 1, 0);
    }
}

static void step_model(pt_xt *t, const pt_cx_journey *j, const char *sep)
{
    int k, n = j->renderer == 9 ? 4 : 3;
    pt_vec4 v = j->at[PT_CST_MODEL];

    for (k = 0; k < n; k++) {
        if (k) pt_xt_add(t, sep);
        name(t, k, "m"); pt_xt_add(t, " = "); pt_xt_num(t, vcomp(v, k), 0);
    }
    if (j->has_col[PT_CST_MODEL]) {
        pt_xt_add(t, sep); pt_xt_add(t, "colour (r, g, b) = "); rgb(t, j->col[PT_CST_MODEL]);
    }
}

static void step_view(pt_xt *t, const pt_cx_journey *j, const char *sep)
{
    int k;
    pt_vec4 in = j->at[j->renderer == 9 ? PT_CST_WORLD : PT_CST_MODEL], out = j->at[PT_CST_VIEW];
    pt_vec3 tv = j->renderer == 9 ? j->cam.cam.view : j->translate;
    pt_vec4 t4 = {tv.x, tv.y, tv.z, 0.0};

    for (k = 0; k < 3; k++) {
        if (k) pt_xt_add(t, sep);
        name(t, k, "v"); pt_xt_add(t, " = ");
        if (j->renderer == 9) {
            pt_xt_add(t, "(-1*"); name(t, k, "view"); pt_xt_add(t, ") + "); name(t, k, "w");
            pt_xt_add(t, " = (-1*"); pt_xt_num(t, vcomp(t4, k), 0); pt_xt_add(t, ") + ");
        } else {
            name(t, k, "t"); pt_xt_add(t, " + "); name(t, k, "m"); pt_xt_add(t, " = ");
            pt_xt_num(t, vcomp(t4, k), 0); pt_xt_add(t, " + ");
        }
        pt_xt_num(t, vcomp(in, k), 1); pt_xt_add(t, " = "); pt_xt_num(t, vcomp(out, k), 0);
    }
}

static void step_camera(pt_xt *t, const pt_cx_journey *j, const char *sep)
{
    const pt_rv_camera *c = &j->cam.cam;
    pt_vec4 in = j->at[PT_CST_VIEW], out = j->at[PT_CST_CAMERA];
    int k;

    pt_xt_add(t, c->perspective ? "perspective" : "orthographic");
    pt_xt_add(t, ", l = "); pt_xt_num(t, c->l, 0); pt_xt_add(t, ", r = "); pt_xt_num(t, c->r, 0);
    pt_xt_add(t, ", b = "); pt_xt_num(t, c->b, 0); pt_xt_add(t, ", t = "); pt_xt_num(t, c->t, 0);
    pt_xt_add(t, ", n = "); pt_xt_num(t, c->n, 0);
    if (j->renderer == 9) {
        pt_xt_add(t, sep);
        matrix(t, "N", &j->cam.norm);
        for (k = 0; k < 3; k++) product(t, "N", &j->cam.norm, "v", in, "c", out, k, sep);
        return;
    }
    {
        pt_vec4 mid = pt_r7_view2camera_shift(in, c);
        for (k = 0; k < 2; k++) {
            double lo = k ? c->b : c->l, hi = k ? c->t : c->r;
            const char *ls = k ? "t+b" : "r+l", *ds = k ? "t-b" : "r-l";
            char nm[2] = {xyzw[k], '\0'};
            pt_xt_add(t, sep); pt_xt_add(t, nm); pt_xt_add(t, " = "); name(t, k, "v");
            if (c->perspective) {
                pt_xt_add(t, " + (z_v*("); pt_xt_add(t, ls); pt_xt_add(t, "))/2 = ");
                pt_xt_num(t, vcomp(in, k), 0); pt_xt_add(t, " + ("); pt_xt_num(t, in.z, 0);
                pt_xt_add(t, "*("); pt_xt_num(t, hi, 0); pt_xt_add(t, " + "); pt_xt_num(t, lo, 1);
                pt_xt_add(t, "))/2 = ");
            } else {
                pt_xt_add(t, " - ("); pt_xt_add(t, ls); pt_xt_add(t, ")/2 = ");
                pt_xt_num(t, vcomp(in, k), 0); pt_xt_add(t, " - ("); pt_xt_num(t, hi, 0);
                pt_xt_add(t, " + "); pt_xt_num(t, lo, 1); pt_xt_add(t, ")/2 = ");
            }
            pt_xt_num(t, vcomp(mid, k), 0);
            pt_xt_add(t, sep); name(t, k, "c"); pt_xt_add(t, " = (2*"); pt_xt_add(t, nm);
            pt_xt_add(t, ")/("); pt_xt_add(t, ds); pt_xt_add(t, ") = (2*");
            pt_xt_num(t, vcomp(mid, k), 1); pt_xt_add(t, ")/("); pt_xt_num(t, hi, 0);
            pt_xt_add(t, " - "); pt_xt_num(t, lo, 1); pt_xt_add(t, ") = ");
            pt_xt_num(t, vcomp(out, k), 0);
        }
        pt_xt_add(t, sep); pt_xt_add(t, "z_c = z_v = "); pt_xt_num(t, out.z, 0);
    }
}

static void step_nearclip(pt_xt *t, const pt_cx_journey *j, const char *sep)
{
    double z = j->at[PT_CST_CAMERA].z, n = j->cam.cam.n;

    if (j->born == PT_CST_NEARCLIP) { cut_near(t, j, sep); return; }
    if (!j->nearclip) {
        pt_xt_add(t, "nearclip off: the stage does not run, the vertex goes on as it is");
        return;
    }
    pt_xt_add(t, "z_c = "); pt_xt_num(t, z, 0);
    if (z <= n) {
        pt_xt_add(t, " <= n = "); pt_xt_num(t, n, 0);
        pt_xt_add(t, ": on the visible side of the near plane (on it counts as visible)");
    } else {
        pt_xt_add(t, " > n = "); pt_xt_num(t, n, 0);
        pt_xt_add(t, ": beyond the near plane: a segment with both ends beyond it is "
                     "dropped, one with the other end visible is cut");
    }
    cut_offs(t, j, PT_CST_NEARCLIP, sep);
}

static void step_image(pt_xt *t, const pt_cx_journey *j, const char *sep)
{
    pt_vec4 in = j->at[PT_CST_NEARCLIP], out = j->at[PT_CST_IMAGE];
    int k;

    for (k = 0; k < 2; k++) {
        if (k) pt_xt_add(t, sep);
        name(t, k, "p"); pt_xt_add(t, " = "); name(t, k, "c");
        if (j->cam.cam.perspective) {
            pt_xt_add(t, " / -z_c = "); pt_xt_num(t, vcomp(in, k), 0);
            pt_xt_add(t, " / -"); pt_xt_num(t, in.z, 1);
        }
        pt_xt_add(t, " = "); pt_xt_num(t, vcomp(out, k), 0);
    }
    pt_xt_add(t, sep); pt_xt_add(t, "z_p = "); pt_xt_num(t, out.z, 0);
    pt_xt_add(t, j->cam.cam.perspective ? " (the image plane)" : " (orthographic)");
}

static void step_clip(pt_xt *t, const pt_cx_journey *j, const char *sep)
{
    pt_vec4 p = j->at[PT_CST_IMAGE];

    if (j->born == PT_CST_CLIP) { cut_rect(t, j, sep); return; }
    pt_xt_add(t, "(x_p, y_p) = ("); pt_xt_num(t, p.x, 0); pt_xt_add(t, ", ");
    pt_xt_num(t, p.y, 0); pt_xt_add(t, ")");
    if (!(fabs(p.x) > 1 || fabs(p.y) > 1))
        pt_xt_add(t, ": |x_p| <= 1 and |y_p| <= 1, inside the view rectangle: the clip keeps it");
    else
        pt_xt_add(t, ": outside the view rectangle -1..1: a segment ending here is cut at "
                     "its edge or dropped");
    cut_offs(t, j, PT_CST_CLIP, sep);
}

/* The stage table's pixel formula (x's, then y's, split at ", "), each with
** j's numbers put in. */
static void step_pixel(pt_xt *t, const pt_cx_journey *j, const char *sep)
{
    const char *f = pt_stage_infos[PT_STAGE_PIXEL].formula, *cut = strstr(f, ", ");
    const double ip[2] = {j->at[PT_CST_CLIP].x, j->at[PT_CST_CLIP].y};
    pt_vec2 pp = pixel_plane(j);
    char part[2][128];
    int k;

    snprintf(part[0], sizeof part[0], "%.*s", cut ? (int)(cut - f) : (int)strlen(f), f);
    snprintf(part[1], sizeof part[1], "%s", cut ? cut + 2 : "");
    for (k = 0; k < 2; k++) {
        const char *rhs = strstr(part[k], " = ");
        if (k) pt_xt_add(t, sep);
        table_text(t, part[k], NULL, NULL);
        pt_xt_add(t, " = ");
        table_text(t, rhs ? rhs + 3 : "", j, ip);
        pt_xt_add(t, " = ");
        pt_xt_num(t, k ? pp.y : pp.x, 0);
    }
}

static void step_viewport(pt_xt *t, const pt_cx_journey *j, const char *sep)
{
    pt_vec2 pp = pixel_plane(j);
    double rx = pt_java_round(pp.x), ry = pt_java_round(pp.y);
    int64_t x_fb = (int64_t)j->par.x_ul + j->px_x, y_fb = (int64_t)j->par.y_ul + j->px_y;

    if (!j->mapped) {
        pt_xt_add(t, "none: the vertex lies outside the view rectangle, and the rasterizer "
                     "maps only what the clip keeps (the clipped segments' ends)");
        return;
    }

    pt_xt_add(t, "x_vp = Math.round(x_pp) - 1 = Math.round("); pt_xt_num(t, pp.x, 0);
    pt_xt_add(t, ") - 1 = "); pt_xt_num(t, rx, 0); pt_xt_add(t, " - 1 = ");
    pt_xt_int(t, j->px_x, 0);
    pt_xt_add(t, sep);
    pt_xt_add(t, "y_vp = h - Math.round(y_pp) = "); pt_xt_int(t, j->par.h, 0);
    pt_xt_add(t, " - Math.round("); pt_xt_num(t, pp.y, 0); pt_xt_add(t, ") = ");
    pt_xt_int(t, j->par.h, 0); pt_xt_add(t, " - "); pt_xt_num(t, ry, 1); pt_xt_add(t, " = ");
    pt_xt_int(t, j->px_y, 0);
    pt_xt_add(t, sep);
    pt_xt_add(t, "(x_fb, y_fb) = (x_ul + x_vp, y_ul + y_vp) = (");
    pt_xt_int(t, j->par.x_ul, 0); pt_xt_add(t, " + "); pt_xt_int(t, j->px_x, 1);
    pt_xt_add(t, ", "); pt_xt_int(t, j->par.y_ul, 0); pt_xt_add(t, " + ");
    pt_xt_int(t, j->px_y, 1); pt_xt_add(t, ") = (");
    pt_xt_int(t, x_fb, 0); pt_xt_add(t, ", "); pt_xt_int(t, y_fb, 0); pt_xt_add(t, ")");
    pt_xt_add(t, sep);
    if (x_fb < 0 || x_fb >= j->par.W || y_fb < 0 || y_fb >= j->par.H) {
        int xf, yf;                         /* the viewport sticks out: the course's index */
        int64_t idx = pt_rv_fb_index(&j->par, (int)j->px_x, (int)j->px_y, &xf, &yf);
        pt_xt_add(t, "outside the framebuffer; the course's index y_fb*W + x_fb = ");
        pt_xt_int(t, y_fb, 0); pt_xt_add(t, "*"); pt_xt_int(t, j->par.W, 0);
        pt_xt_add(t, " + "); pt_xt_int(t, x_fb, 1); pt_xt_add(t, " = ");
        pt_xt_int(t, y_fb * j->par.W + x_fb, 0);
        if (idx < 0) {
            pt_xt_add(t, " lies outside the pixel array: the write is dropped "
                         "(FrameBuffer: Bad pixel coordinate)");
        } else {
            pt_xt_add(t, " wraps past the edge: the pixel written is (");
            pt_xt_int(t, idx % j->par.W, 0); pt_xt_add(t, ", ");
            pt_xt_int(t, idx / j->par.W, 0); pt_xt_add(t, ") of the array");
        }
        return;
    }
    pt_xt_add(t, "index = y_fb*W + x_fb = "); pt_xt_int(t, y_fb, 0); pt_xt_add(t, "*");
    pt_xt_int(t, j->par.W, 0); pt_xt_add(t, " + "); pt_xt_int(t, x_fb, 0);
    pt_xt_add(t, " = "); pt_xt_int(t, y_fb * j->par.W + x_fb, 0);
}

/* g = gamma(c) per component, and the bytes: the encoding of colour c. */
static pt_rgb gamma_text(pt_xt *t, pt_rgb c, int on, const char *sep)
{
    pt_rgb g = c;
    int k;

    if (!on) {
        pt_xt_add(t, sep); pt_xt_add(t, "gamma off: the colour is written as it is");
        return c;
    }
    g.r = pt_gamma(c.r); g.g = pt_gamma(c.g); g.b = pt_gamma(c.b);
    for (k = 0; k < 3; k++) {
        pt_xt_add(t, sep); pt_xt_add(t, "gamma: ");
        pt_xt_add(t, rgb_names[k]); pt_xt_add(t, "' = (float)Math.pow(");
        pt_xt_add(t, rgb_names[k]); pt_xt_add(t, ", 1/2.2) = (float)Math.pow(");
        pt_xt_num(t, ccomp(c, k), 0); pt_xt_add(t, ", "); pt_xt_num(t, PT_GAMMA_INV, 0);
        pt_xt_add(t, ") = "); pt_xt_num(t, ccomp(g, k), 0);
    }
    return g;
}

/* "bytes = (int)((double)(c*255f) + 0.5) of (...) = (a, b, c)", the colour
** called cn, and the check against what the rasterizer wrote. */
static void bytes_text(pt_xt *t, const char *cn, pt_rgb c, pt_rgb written, const char *sep)
{
    pt_xt_add(t, sep); pt_xt_add(t, "bytes = (int)((double)(");
    pt_xt_add(t, cn); pt_xt_add(t, "*255f) + 0.5) of ");
    rgb(t, c); pt_xt_add(t, " = "); bytes(t, c);
    if (memcmp(&c, &written, sizeof c) != 0) {
        pt_xt_add(t, " (the rasterizer wrote "); bytes(t, written); pt_xt_add(t, ")");
    }
}

/* The numbers of a write from c, the colour of its step (a segment's last
** pixel: its end's; a point's: its own): anti-aliasing's weight and blend
** for the pair's lower or upper pixel, gamma and the bytes, checked against
** the colour px says the rasterizer wrote there. */
static void colour_text(pt_xt *t, const pt_rv_raster_par *par, const pt_rv_pixel *px,
                        int upper, pt_rgb c, const char *sep)
{
    pt_rgb g;

    switch (px->kind) {
    case PT_RV_PX_END:
        bytes_text(t, "c", c, px->c[0], sep);
        return;
    case PT_RV_PX_POINT:
    case PT_RV_PX_STEP:
        g = gamma_text(t, c, par->gamma, sep);
        bytes_text(t, par->gamma ? "c'" : "c", g, px->c[0], sep);
        return;
    case PT_RV_PX_AA: {
        double a = px->transposed ? px->x_pp : px->y_pp;
        double a_low = floor(a);
        float f = pt_aa_weight(a, a_low), lo[3], hi[3];
        int k;
        pt_rgb mix;

        pt_xt_add(t, sep);
        pt_xt_add(t, px->transposed ? "weight f = (float)(x - floor(x)) = (float)("
                                    : "weight f = (float)(y - floor(y)) = (float)(");
        pt_xt_num(t, a, 0); pt_xt_add(t, " - "); pt_xt_num(t, a_low, 1); pt_xt_add(t, ") = ");
        pt_xt_num(t, (double)f, 0);
        pt_xt_add(t, !upper ? "; this pixel is the lower of the pair, coverage 1 - f = "
                            : "; this pixel is the upper of the pair, coverage f = ");
        pt_xt_num(t, !upper ? (double)(1.0f - f) : (double)f, 0);
        pt_xt_add(t, " (the blend in float arithmetic, bg the viewport's background)");
        for (k = 0; k < 3; k++) {
            float bg = pt_color_float(par->bg[k]);
            pt_aa_blend((float)ccomp(c, k), bg, f, &lo[k], &hi[k]);
            pt_xt_add(t, sep); pt_xt_add(t, rgb_names[k]);
            if (!upper) {
                pt_xt_add(t, " = (1 - f)*c + f*bg = (1 - "); pt_xt_num(t, (double)f, 0);
                pt_xt_add(t, ")*"); pt_xt_num(t, ccomp(c, k), 0); pt_xt_add(t, " + ");
                pt_xt_num(t, (double)f, 0); pt_xt_add(t, "*"); pt_xt_num(t, (double)bg, 0);
            } else {
                pt_xt_add(t, " = f*c + (1 - f)*bg = "); pt_xt_num(t, (double)f, 0);
                pt_xt_add(t, "*"); pt_xt_num(t, ccomp(c, k), 0); pt_xt_add(t, " + (1 - ");
                pt_xt_num(t, (double)f, 0); pt_xt_add(t, ")*"); pt_xt_num(t, (double)bg, 0);
            }
            pt_xt_add(t, " = "); pt_xt_num(t, (double)(!upper ? lo[k] : hi[k]), 0);
        }
        mix.r = !upper ? lo[0] : hi[0]; mix.g = !upper ? lo[1] : hi[1];
        mix.b = !upper ? lo[2] : hi[2];
        g = gamma_text(t, mix, par->gamma, sep);
        bytes_text(t, par->gamma ? "c'" : "c", g, px->c[upper], sep);
        return;
    }
    }
}

static void pixel_line(pt_xt *t, const pt_cx_journey *j, const pt_cx_px *p, const char *sep)
{
    const pt_rv_pixel *px = &p->px;
    pt_rgb c = p->end_c;

    pt_xt_add(t, px->kind == PT_RV_PX_POINT ? "point " : "segment ");
    pt_xt_int(t, (int64_t)p->prim, 0);
    switch (px->kind) {
    case PT_RV_PX_END:
        pt_xt_add(t, " (rasterized): its last pixel, coverage 1, in the end's colour as it is "
                     "(no gamma, no anti-aliasing): c = ");
        break;
    case PT_RV_PX_POINT:
    case PT_RV_PX_STEP:
        pt_xt_add(t, px->kind == PT_RV_PX_POINT ? ": a pixel of its disc, coverage 1, c = "
                  : " (rasterized): its first step, coverage 1 (anti-aliasing off), its colour "
                    "the end's, c = (float)|c0 + slope*0| = ");
        break;
    case PT_RV_PX_AA:
        pt_xt_add(t, " (rasterized): its first step, anti-aliased, its colour the end's, "
                     "c = (float)|c0 + slope*0| = ");
        break;
    }
    rgb(t, c);
    colour_text(t, &j->par, px, px->kind == PT_RV_PX_AA &&
                (px->transposed ? j->px_x : j->px_y) != px->lo, c, sep);
}

static void step_raster(pt_xt *t, const pt_cx_journey *j, const char *sep)
{
    size_t k;

    if (!j->mapped) {
        pt_xt_add(t, "no pixel: the vertex lies outside the view rectangle");
        return;
    }
    if (!j->nends) {
        pt_xt_add(t, "no primitive the rasterizer draws has an end at vertex ");
        pt_xt_int(t, (int64_t)j->v, 0);
        pt_xt_add(t, ": the clips dropped or cut every segment from it, or none uses it");
        return;
    }
    if (!j->npx) {
        pt_xt_add(t, "no pixel line of its primitives lands on the vertex's pixel");
        return;
    }
    for (k = 0; k < j->npx; k++) {
        if (k) pt_xt_add(t, sep);
        pixel_line(t, j, &j->px[k], sep);
    }
}

/* The primitive of w: "a segment from vertex 1 to vertex 2", "a point at vertex 3 (radius 0)". */
static void ends_text(pt_xt *t, const pt_cx_write *w)
{
    if (w->p.kind == PT_RV_POINT) {
        pt_xt_add(t, "a point at vertex "); pt_xt_int(t, (int64_t)w->v[0], 0);
        pt_xt_add(t, " (radius "); pt_xt_int(t, w->p.radius, 0); pt_xt_add(t, ")");
        return;
    }
    pt_xt_add(t, "a segment from vertex "); pt_xt_int(t, (int64_t)w->v[0], 0);
    pt_xt_add(t, " to vertex "); pt_xt_int(t, (int64_t)w->v[1], 0);
}

/* A loop step of w's segment: which step, and the colour it interpolates
** between the ends in stepping order (the rasterizer's slopes), into *c. */
static void step_colour(pt_xt *t, const pt_cx_write *w, pt_rgb *c, const char *sep)
{
    const pt_rv_slopes *sl = &w->sl;
    int tr = sl->transposed, k;
    double x = tr ? w->px.y_pp : w->px.x_pp;   /* the stepped coordinate */
    double x0 = sl->x0_vp + 1.0, x1 = sl->x1_vp + 1.0;
    int e0 = pt_java_round(tr ? w->ends[1] : w->ends[0]) == x0 ? 0 : 1;
    pt_rgb c0 = w->c[e0], c1 = w->c[1 - e0];
    const char *xn = tr ? "y" : "x";

    pt_xt_add(t, ", its step k = "); pt_xt_add(t, xn); pt_xt_add(t, " - ");
    pt_xt_add(t, xn); pt_xt_add(t, "0 = "); pt_xt_num(t, x, 0); pt_xt_add(t, " - ");
    pt_xt_num(t, x0, 1); pt_xt_add(t, " = "); pt_xt_num(t, x - x0, 0);
    pt_xt_add(t, tr ? " (transposed: steep, the DDA steps y_pp" : " (the DDA steps x_pp");
    pt_xt_add(t, " from vertex "); pt_xt_int(t, (int64_t)w->v[e0], 0); pt_xt_add(t, "'s end ");
    pt_xt_num(t, x0, 0); pt_xt_add(t, " to vertex "); pt_xt_int(t, (int64_t)w->v[1 - e0], 0);
    pt_xt_add(t, "'s "); pt_xt_num(t, x1, 0); pt_xt_add(t, ", c0 and c1 their colours)");
    for (k = 0; k < 3; k++) {
        pt_xt_add(t, sep); pt_xt_add(t, "slope_"); pt_xt_add(t, rgb_names[k]);
        pt_xt_add(t, " = ("); pt_xt_add(t, rgb_names[k]); pt_xt_add(t, "1 - ");
        pt_xt_add(t, rgb_names[k]); pt_xt_add(t, "0)/("); pt_xt_add(t, xn); pt_xt_add(t, "1 - ");
        pt_xt_add(t, xn); pt_xt_add(t, "0) = (");
        pt_xt_num(t, ccomp(c1, k), 0); pt_xt_add(t, " - "); pt_xt_num(t, ccomp(c0, k), 1);
        pt_xt_add(t, ")/("); pt_xt_num(t, x1, 0); pt_xt_add(t, " - "); pt_xt_num(t, x0, 1);
        pt_xt_add(t, ") = "); pt_xt_num(t, sl->mc[k], 0);
    }
    c->r = pt_color_at(c0.r, sl->mc[0], x, x0);
    c->g = pt_color_at(c0.g, sl->mc[1], x, x0);
    c->b = pt_color_at(c0.b, sl->mc[2], x, x0);
    for (k = 0; k < 3; k++) {
        pt_xt_add(t, sep); pt_xt_add(t, rgb_names[k]); pt_xt_add(t, " = (float)|");
        pt_xt_add(t, rgb_names[k]); pt_xt_add(t, "0 + slope_"); pt_xt_add(t, rgb_names[k]);
        pt_xt_add(t, "*("); pt_xt_add(t, xn); pt_xt_add(t, " - "); pt_xt_add(t, xn);
        pt_xt_add(t, "0)| = (float)|"); pt_xt_num(t, ccomp(c0, k), 0); pt_xt_add(t, " + ");
        pt_xt_num(t, sl->mc[k], 1); pt_xt_add(t, "*("); pt_xt_num(t, x, 0);
        pt_xt_add(t, " - "); pt_xt_num(t, x0, 1); pt_xt_add(t, ")| = ");
        pt_xt_num(t, ccomp(*c, k), 0);
    }
}

size_t pt_cx_explain_write(char *buf, size_t len, const pt_scene *s, const pt_cx_write *w,
                           uint64_t nwrites, const char *sep)
{
    const pt_rv_pixel *px = &w->px;
    pt_cx_journey j;
    pt_xt t;
    pt_rgb c = px->c[0];

    begin(&j, s);
    pt_xt_init(&t, buf, len);
    pt_xt_add(&t, nwrites > 1 ? "the last of " : "the only write");
    if (nwrites > 1) { pt_xt_int(&t, (int64_t)nwrites, 0); pt_xt_add(&t, " writes"); }
    pt_xt_add(&t, " at (x_fb, y_fb) = ("); pt_xt_int(&t, w->at.x_fb, 0); pt_xt_add(&t, ", ");
    pt_xt_int(&t, w->at.y_fb, 0); pt_xt_add(&t, "), index = y_fb*W + x_fb = ");
    pt_xt_int(&t, w->at.y_fb, 0); pt_xt_add(&t, "*"); pt_xt_int(&t, s->fb_w, 0);
    pt_xt_add(&t, " + "); pt_xt_int(&t, w->at.x_fb, 1); pt_xt_add(&t, " = ");
    pt_xt_int(&t, w->at.idx, 0);
    if (w->at.x_fb < 0 || w->at.x_fb >= s->fb_w || w->at.y_fb < 0 || w->at.y_fb >= s->fb_h) {
        pt_xt_add(&t, " (outside the framebuffer, the course's index wraps past its edge: "
                      "the pixel written is (");
        pt_xt_int(&t, w->at.idx % s->fb_w, 0); pt_xt_add(&t, ", ");
        pt_xt_int(&t, w->at.idx / s->fb_w, 0); pt_xt_add(&t, ") of the array)");
    }
    pt_xt_add(&t, ": model "); pt_xt_add(&t, w->model);
    if (strcmp(w->position, w->model)) {
        pt_xt_add(&t, " (position "); pt_xt_add(&t, w->position); pt_xt_add(&t, ")");
    }
    pt_xt_add(&t, ", primitive "); pt_xt_int(&t, (int64_t)w->prim, 0);
    pt_xt_add(&t, " of the rasterizer, ");
    ends_text(&t, w);
    switch (px->kind) {
    case PT_RV_PX_END:
        pt_xt_add(&t, w->has_slopes ? ": its last pixel, coverage 1, in that end's colour as "
                                      "it is (no gamma, no anti-aliasing): c = "
                                    : ", one pixel long: coverage 1, in its first end's colour "
                                      "as it is (no gamma, no anti-aliasing): c = ");
        rgb(&t, c);
        break;
    case PT_RV_PX_POINT:
        c = w->c[0];
        pt_xt_add(&t, ": a pixel of its disc, coverage 1, in its colour c = ");
        rgb(&t, c);
        break;
    case PT_RV_PX_STEP:
    case PT_RV_PX_AA:
        step_colour(&t, w, &c, sep);
        if (px->kind == PT_RV_PX_STEP) {
            pt_xt_add(&t, sep);
            pt_xt_add(&t, "anti-aliasing off: the pixel Math.round of the other coordinate, "
                          "coverage 1");
        }
        break;
    }
    colour_text(&t, &j.par, px, w->upper, c, sep);
    if (px->kind == PT_RV_PX_AA && w->coverage == 0.0f) {
        pt_xt_add(&t, sep);
        pt_xt_add(&t, "coverage 0: the write leaves the viewport's background there");
    }
    return t.len;
}

size_t pt_cx_stage(char *buf, size_t len, const pt_cx_journey *j, pt_cx_step st,
                   const char *sep)
{
    pt_xt t;
    int k;

    pt_xt_init(&t, buf, len);
    switch (st) {
    case PT_CXS_MODEL:    step_model(&t, j, sep); break;
    case PT_CXS_WORLD:
        matrix(&t, "M", &j->matrix);
        for (k = 0; k < 4; k++)
            product(&t, "M", &j->matrix, "m", j->at[PT_CST_MODEL], "w", j->at[PT_CST_WORLD], k, sep);
        break;
    case PT_CXS_VIEW:     step_view(&t, j, sep); break;
    case PT_CXS_CAMERA:   step_camera(&t, j, sep); break;
    case PT_CXS_NEARCLIP: step_nearclip(&t, j, sep); break;
    case PT_CXS_IMAGE:    step_image(&t, j, sep); break;
    case PT_CXS_CLIP:     step_clip(&t, j, sep); break;
    case PT_CXS_PIXEL:    step_pixel(&t, j, sep); break;
    case PT_CXS_VIEWPORT: step_viewport(&t, j, sep); break;
    case PT_CXS_RASTER:   step_raster(&t, j, sep); break;
    }
    return t.len;
}

size_t pt_cx_explain_rec(char *buf, size_t len, const pt_scene *s, const pt_course_cam *cam,
                         const pt_cx_rec *r, const char *sep)
{
    return pt_cx_explain_step(buf, len, s, cam, r, pt_cx_step_of(r->st), sep);
}

size_t pt_cx_explain_step(char *buf, size_t len, const pt_scene *s, const pt_course_cam *cam,
                          const pt_cx_rec *r, pt_cx_step step, const char *sep)
{
    static const pt_course_stage before[PT_NCST] = {PT_CST_MODEL, PT_CST_MODEL, PT_CST_WORLD,
        PT_CST_VIEW, PT_CST_CAMERA, PT_CST_NEARCLIP, PT_CST_IMAGE};
    pt_course_stage pre = r->st == PT_CST_VIEW && s->renderer != 9 ? PT_CST_MODEL : before[r->st];
    pt_cx_journey j;

    begin(&j, s);
    j.cam = *cam;
    j.translate = r->pos->translate;
    j.matrix = r->pos->matrix;
    j.at[pre] = r->prev;
    j.at[r->st] = r->cur;
    if (r->color) { j.has_col[r->st] = 1; j.col[r->st] = *r->color; }
    if (r->cut) {
        j.born = r->st;
        j.cut = *r->cut;
        j.cut_prim = r->cut_prim;
    }
    if (r->st == PT_CST_CLIP) map_clipped(&j);
    return pt_cx_stage(buf, len, &j, step, sep);
}
