/*
** src/tools/journey/journey_classic.c -- the classic camera's panels: model .. pixel array
** See LICENSE for copyright and license.
**
** The seven panels of the classic camera (journey.h), and their layout: the
** two 3-D spaces (model, camera), the image and logical pixel planes, the
** viewport and framebuffer pixel grids with their zoom insets, and the pixel
** array.  The matrix camera shows its model, viewport, framebuffer and pixel
** array with these same panels (its rows point here, jrows.c).
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "tools/journey/journey_classic.h"
#include "tools/journey/jpanel.h"

#define BIG       1e150          /* coordinates beyond this never widen a panel */
#define PIXMAX    1099511627776.0   /* 2^40: pixels beyond get no zoom inset */
#define CELLMAX   20000          /* at most this many pixel cells per view */

/* ===== layout ===== */

/* The stage's own rectangle (data coordinates) of a 2-D panel. */
static void base_rect(const pt_jmodel *jm, pt_stage st, double b[4])
{
    const pt_stage_params *p = &jm->par;

    b[0] = 0; b[1] = 0; b[2] = p->W; b[3] = p->H;    /* the framebuffer's */
    switch (st) {
    case PT_STAGE_IMAGE: b[0] = -1; b[1] = -1; b[2] = 1; b[3] = 1; break;
    case PT_STAGE_PIXEL: b[0] = 0.5; b[1] = 0.5; b[2] = p->w + 0.5; b[3] = p->h + 0.5; break;
    case PT_STAGE_VIEWPORT: b[0] = 0; b[1] = 0; b[2] = p->w; b[3] = p->h; break;
    case PT_STAGE_FRAMEBUFFER:
    case PT_STAGE_MODEL:                     /* not a plane of these panels */
    case PT_STAGE_CAMERA:
    case PT_STAGE_INDEX:
    case PT_STAGE_WORLD:
    case PT_STAGE_VIEW:
    case PT_STAGE_CLIP:
    case PT_STAGE_CVV:
    case PT_STAGE_NDC:
    case PT_STAGE_SCREEN:
        break;
    }
}

/* Grow bbox b to take in (x, y). */
static void grow(double b[4], double x, double y)
{
    if (x < b[0]) b[0] = x;
    if (y < b[1]) b[1] = y;
    if (x > b[2]) b[2] = x;
    if (y > b[3]) b[3] = y;
}

static void pad(double b[4], double frac, double least)
{
    double p = fmax(fmax(b[2] - b[0], b[3] - b[1]) * frac, least);

    b[0] -= p; b[1] -= p; b[2] += p; b[3] += p;
}

void pt_jclassic_absorb(pt_jmodel *jm, const pt_journey *j, size_t k)
{
    pt_jspan *sp = &jm->span;
    double x, y, reach, lim[4];
    int st;

    (void)k;
    /* the 3-D panels' axes and the pyramid's depth */
    for (st = 0; st < 3; st++) {
        double c = fabs(st == 0 ? j->rec[0].x : st == 1 ? j->rec[0].y : j->rec[0].z);
        if (c <= BIG && c > sp->big) sp->big = c;
    }
    if (-j->rec[PT_STAGE_CAMERA].z <= BIG && -j->rec[PT_STAGE_CAMERA].z > sp->deep)
        sp->deep = -j->rec[PT_STAGE_CAMERA].z;
    /* what it adds to the panels' boxes */
    for (st = 0; st < 2; st++)
        if (pt_jstage_xy(j, (pt_stage)st, &x, &y) && fabs(x) <= BIG && fabs(y) <= BIG)
            grow(sp->b[st], x, y);
    for (st = PT_STAGE_IMAGE; st <= PT_STAGE_FRAMEBUFFER; st++) {
        double br[4];
        if (!pt_jstage_xy(j, (pt_stage)st, &x, &y)) continue;
        base_rect(jm, (pt_stage)st, br);
        reach = PT_JOURNEY_REACH * fmax(br[2] - br[0], br[3] - br[1]) / 2;
        lim[0] = br[0] / 2 + br[2] / 2 - reach; lim[2] = br[0] / 2 + br[2] / 2 + reach;
        lim[1] = br[1] / 2 + br[3] / 2 - reach; lim[3] = br[1] / 2 + br[3] / 2 + reach;
        if (x < lim[0] || x > lim[2] || y < lim[1] || y > lim[3]) continue;
        if (st >= PT_STAGE_VIEWPORT) {
            grow(sp->b[st], x - 0.5, y - 0.5);
            grow(sp->b[st], x + 0.5, y + 0.5);
        } else grow(sp->b[st], x, y);
    }
}

int pt_jclassic_layout(pt_jmodel *jm)
{
    const pt_scene *s = jm->s;
    const pt_jspan *sp = &jm->span;
    double b[PT_NSTAGES_ALL][4];
    int st;

    /* 3-D panels: axis lengths and the pyramid's depth from the used vertices */
    jm->axis_m = sp->big > 0 ? 1.25 * sp->big : 1;
    jm->depth = 1.1 * fmax(1, sp->deep);
    jm->axis_c = fmax(1, 0.2 * jm->depth);

    /* the bounding boxes, starting from what every panel shows */
    for (st = 0; st < PT_NSTAGES_ALL; st++) {
        b[st][0] = b[st][1] = (double)INFINITY;
        b[st][2] = b[st][3] = -(double)INFINITY;
    }
    {
        double A = jm->axis_m, D = jm->depth, sx, sy;
        int c;
        grow(b[0], 0, 0);
        pt_jproj(PT_STAGE_MODEL, A, 0, 0, &sx, &sy); grow(b[0], sx, sy);
        pt_jproj(PT_STAGE_MODEL, 0, A, 0, &sx, &sy); grow(b[0], sx, sy);
        pt_jproj(PT_STAGE_MODEL, 0, 0, A, &sx, &sy); grow(b[0], sx, sy);
        (void)D;                             /* the pyramid is clipped, not fitted */
        pt_jproj(PT_STAGE_CAMERA, 0, 0, jm->axis_c, &sx, &sy); grow(b[1], sx, sy);
        pt_jproj(PT_STAGE_CAMERA, jm->axis_c, 0, 0, &sx, &sy); grow(b[1], sx, sy);
        pt_jproj(PT_STAGE_CAMERA, 0, jm->axis_c, 0, &sx, &sy); grow(b[1], sx, sy);
        for (c = 0; c < 4; c++) {            /* the image plane's corners */
            double cx = c & 1 ? 1 : -1, cy = c & 2 ? 1 : -1;
            pt_jproj(PT_STAGE_CAMERA, cx, cy, s->perspective ? -1 : 0, &sx, &sy); grow(b[1], sx, sy);
        }
        grow(b[1], 0, 0);
    }
    for (st = PT_STAGE_IMAGE; st <= PT_STAGE_FRAMEBUFFER; st++) {
        base_rect(jm, (pt_stage)st, b[st]);
        pad(b[st], 0.06, st == PT_STAGE_IMAGE ? 0.1 : 1);
    }
    for (st = 0; st <= PT_STAGE_FRAMEBUFFER; st++)   /* the used vertices */
        pt_jspan_merge(b[st], sp->b[st]);
    pad(b[0], 0.08, 0);
    pad(b[1], 0.06, 0);
    for (st = PT_STAGE_IMAGE; st <= PT_STAGE_FRAMEBUFFER; st++)
        pad(b[st], 0.03, 0);                 /* a vertex on the edge stays in view */
    for (st = 0; st <= PT_STAGE_FRAMEBUFFER; st++)
        pt_jview_fit(&jm->view[st], b[st], st >= PT_STAGE_VIEWPORT, PT_JBOX_X, PT_JBOX_Y,
                     PT_JBOX_W, PT_JBOX_H);
    return 0;
}

/* ===== backgrounds ===== */

static void bg_model(pt_sbuf *sb, const pt_jmodel *jm, pt_stage st)
{
    const pt_jview *v = &jm->view[st];
    double A = jm->axis_m;

    pt_jaxis3(sb, v, st, A, 0, 0, "x_m");
    pt_jaxis3(sb, v, st, 0, A, 0, "y_m");
    pt_jaxis3(sb, v, st, 0, 0, A, "z_m");
    pt_jwireframe(sb, jm, st);
}

static void bg_camera(pt_sbuf *sb, const pt_jmodel *jm, pt_stage st)
{
    const pt_jview *v = &jm->view[PT_STAGE_CAMERA];
    double D = jm->depth, A = jm->axis_c, o[3] = {0, 0, 0}, c[4][3], f[4][3];
    double tx[3] = {0, 0, 0}, ty[3] = {0, 0, 0}, tz[3] = {0, 0, 0}, dz[3] = {0, 0, 0};
    double px, py;
    int k, persp = jm->par.perspective;

    (void)st;
    for (k = 0; k < 4; k++) {                /* image plane and far end */
        double sx = (k == 0 || k == 3) ? -1 : 1, sy = k < 2 ? -1 : 1;
        c[k][0] = sx; c[k][1] = sy; c[k][2] = persp ? -1 : 0;
        f[k][0] = persp ? sx * D : sx; f[k][1] = persp ? sy * D : sy; f[k][2] = -D;
    }
    for (k = 0; k < 4; k++) {                /* the view pyramid (box) */
        pt_jline3(sb, v, PT_STAGE_CAMERA, persp ? o : c[k], f[k], PT_JC_EDGE, 1, "stroke-dasharray=\"5 3\"");
        pt_jline3(sb, v, PT_STAGE_CAMERA, f[k], f[(k + 1) % 4], PT_JC_EDGE, 1, "stroke-dasharray=\"5 3\"");
    }
    pt_sbuf_add(sb, "<path d=\"");
    for (k = 0; k < 4; k++) {
        pt_jproj(PT_STAGE_CAMERA, c[k][0], c[k][1], c[k][2], &px, &py);
        px = fmin(fmax(px, v->x0), v->x1); py = fmin(fmax(py, v->y0), v->y1);
        pt_sbuf_add(sb, k ? " L" : "M"); pt_jnum(sb, pt_jview_x(v, px)); pt_sbuf_add(sb, " "); pt_jnum(sb, pt_jview_y(v, py));
    }
    pt_sbuf_addf(sb, " Z\" fill=\"%s\" fill-opacity=\"0.8\" stroke=\"%s\"/>\n", PT_JC_AREA, PT_JC_EDGE);
    pt_jproj(PT_STAGE_CAMERA, 1, 1, c[0][2], &px, &py);
    if (pt_jview_in(v, px, py) && v->s > 20)
        pt_jlabel_at(sb, pt_jview_x(v, px), pt_jview_y(v, py) - 5, 10, "middle", "fill=\"" PT_JC_NOTE "\"",
                 persp ? "image plane z = -1" : "image plane z = 0", 0, PT_JLAB_OTHER);
    tx[0] = A; ty[1] = A; tz[2] = A; dz[2] = -D;
    pt_jline3(sb, v, PT_STAGE_CAMERA, o, dz, PT_JC_AXIS, 1, "stroke-dasharray=\"1 3\"");
    {                                        /* name the view direction where it leaves */
        double qx, qy;
        pt_jproj(PT_STAGE_CAMERA, 0, 0, 0, &px, &py);
        pt_jproj(PT_STAGE_CAMERA, 0, 0, -D, &qx, &qy);
        if (pt_jview_clip(v, &px, &py, &qx, &qy) && (pt_jview_x(v, qx) - pt_jview_x(v, px)) > 90)
            pt_jlabel_at(sb, pt_jview_x(v, qx) - 4, pt_jview_y(v, qy) + 14, 10, "end", "fill=\"" PT_JC_NOTE "\"",
                     "looking down -z_c", 0, PT_JLAB_OTHER);
    }
    pt_jaxis3(sb, v, PT_STAGE_CAMERA, tx[0], tx[1], tx[2], "x_c");
    pt_jaxis3(sb, v, PT_STAGE_CAMERA, ty[0], ty[1], ty[2], "y_c");
    pt_jaxis3(sb, v, PT_STAGE_CAMERA, tz[0], tz[1], tz[2], "z_c");
    pt_jproj(PT_STAGE_CAMERA, 0, 0, 0, &px, &py);
    if (pt_jview_in(v, px, py)) {
        pt_jcircle(sb, pt_jview_x(v, px), pt_jview_y(v, py), 4, "#333", "");
        pt_jlabel_at(sb, pt_jview_x(v, px) - 7, pt_jview_y(v, py) - 8, 11, "end", "fill=\"#333\"", "camera", 0,
                 PT_JLAB_OTHER);
    }
    pt_jwireframe(sb, jm, PT_STAGE_CAMERA);
}

/* "x_vp ->": the trace's name of value k of stage st and an arrow (UTF-8)
** saying which way it grows. */
static void axis_name(char *t, size_t n, pt_stage st, int k, const char *arrow)
{
    snprintf(t, n, "%s%s", pt_stage_infos[st].coord[k], arrow);
}

/* Is pixel (x, y) of the rendered frame lit (not the scene's background)? */
static int frame_lit(const pt_jmodel *jm, int64_t x, int64_t y)
{
    const unsigned char *c = jm->frame->rgb + 3 * ((size_t)y * (size_t)jm->frame->w + (size_t)x);
    const unsigned char *bg = jm->s->background;

    return c[0] != bg[0] || c[1] != bg[1] || c[2] != bg[2];
}

/* The whole rendered frame, every model's pixels, as grey cells over the
** framebuffer: runs of lit pixels along each row; when a pixel is under a
** unit of the panel, blocks of k x k pixels, lit when one of them is.  The
** <path> says how many pixels are lit (data-pixels) and the block (data-k). */
static void frame_cells(pt_sbuf *sb, const pt_jmodel *jm, const pt_jview *v)
{
    int64_t W, H, k = v->s >= 1 ? 1 : (int64_t)ceil(1 / v->s);
    int64_t bx, by, x, y, run, lit = 0;
    pt_jpath pw;
    char attrs[128];

    if (!jm->frame) return;
    W = jm->frame->w; H = jm->frame->h;
    pt_jpath_start(&pw, sb);
    for (by = 0; by * k < H; by++) {
        int64_t y1 = by * k + k < H ? by * k + k : H;
        for (run = -1, bx = 0; ; bx++) {
            int on = 0;
            for (y = by * k; bx * k < W && y < y1; y++)
                for (x = bx * k; x < bx * k + k && x < W; x++)
                    if (frame_lit(jm, x, y)) { on = 1; lit++; }
            if (on && run < 0) run = bx;
            if (!on && run >= 0) {              /* a run of blocks ends */
                double xa = (double)(run * k), xb = (double)(bx * k < W ? bx * k : W);
                pt_jpath_cmd(&pw, "M", 2, pt_jview_x(v, xa), pt_jview_y(v, (double)(by * k)));
                pt_jpath_cmd(&pw, "H", 1, pt_jview_x(v, xb), 0);
                pt_jpath_cmd(&pw, "V", 1, pt_jview_y(v, (double)y1), 0);
                pt_jpath_cmd(&pw, "H", 1, pt_jview_x(v, xa), 0);
                pt_sbuf_add(sb, "z");
                run = -1;
            }
            if (bx * k >= W) break;
        }
    }
    snprintf(attrs, sizeof attrs, "fill=\"" PT_JC_FRAMEPX "\" class=\"frame\" data-pixels=\"%lld\" "
             "data-k=\"%lld\"", (long long)lit, (long long)k);
    pt_jpath_end(&pw, attrs);
}

static void bg_plane(pt_sbuf *sb, const pt_jmodel *jm, pt_stage st)
{
    const pt_jview *v = &jm->view[st];
    const pt_stage_params *p = &jm->par;
    double r[4];
    char a[64], b[64];

    base_rect(jm, st, r);
    if (st == PT_STAGE_FRAMEBUFFER) {
        double vp[4];
        pt_jview_rect(sb, v, r[0], r[1], r[2] - r[0], r[3] - r[1], "#eef0f3", "#9aa1ab", "", 0);
        vp[0] = p->x_ul; vp[1] = p->y_ul; vp[2] = p->x_ul + p->w; vp[3] = p->y_ul + p->h;
        pt_jview_rect(sb, v, vp[0], vp[1], p->w, p->h, PT_JC_AREA, "", "", 0);
        frame_cells(sb, jm, v);
        pt_jgrid(sb, v, r, 0, 5);
        pt_joutline(sb, v, vp, PT_JC_EDGE, 1.5);
        strcpy(a, "viewport at (x_ul, y_ul) = (");
        pt_jfmt_i64(b, sizeof b, p->x_ul); strcat(a, b); strcat(a, ", ");
        pt_jfmt_i64(b, sizeof b, p->y_ul); strcat(a, b); strcat(a, ")");
        if ((vp[2] - vp[0]) * v->s < 150) {
            /* no room for the label */
        } else if ((p->H - vp[3]) * v->s >= 14 && pt_jview_in(v, vp[0], vp[3]))
            pt_jlabel_at(sb, pt_jview_x(v, vp[0]) + 2, pt_jview_y(v, vp[3]) + 12, 10, "start",
                     "fill=\"" PT_JC_EDGE "\"", a, 0, PT_JLAB_OTHER);
        else if (pt_jview_in(v, vp[0], vp[1]))
            pt_jlabel_at(sb, pt_jview_x(v, vp[0]) + 2, pt_jview_y(v, vp[1]) + (vp[1] * v->s >= 14 ? -4 : 13), 10,
                     "start", "fill=\"" PT_JC_EDGE "\"", a, 0, PT_JLAB_OTHER);
    } else {
        pt_jview_rect(sb, v, r[0], r[1], r[2] - r[0], r[3] - r[1], PT_JC_AREA, "", "", 0);
        pt_jgrid(sb, v, r, st == PT_STAGE_PIXEL ? 0.5 : 0, 5);
        pt_joutline(sb, v, r, PT_JC_EDGE, 1.5);
    }
    /* axes through 0 on the image plane; corner labels elsewhere */
    if (st == PT_STAGE_IMAGE) {
        pt_jview_line(sb, v, v->x0, 0, v->x1, 0, PT_JC_AXIS, 0.8, "");
        pt_jview_line(sb, v, 0, v->y0, 0, v->y1, PT_JC_AXIS, 0.8, "");
        pt_jview_label(sb, v, v->x1, 0, -4, -5, "end", "x_ip");
        pt_jview_label(sb, v, 0, v->y1, 5, 12, "start", "y_ip");
        pt_jview_label(sb, v, -1, -1, 0, 13, "middle", "(-1, -1)");
        pt_jview_label(sb, v, 1, 1, 0, -5, "middle", "(1, 1)");
        pt_jview_label(sb, v, -1, 1, 4, 12, "start", "view rectangle");
    } else if (st == PT_STAGE_PIXEL) {
        pt_jfmt_i64(b, sizeof b, p->w); strcpy(a, b); strcat(a, ".5");
        pt_jview_label(sb, v, r[0], r[1], 0, 13, "middle", "0.5");
        pt_jview_label(sb, v, r[2], r[1], 0, 13, "middle", a);
        pt_jfmt_i64(b, sizeof b, p->h); strcpy(a, b); strcat(a, ".5");
        pt_jview_label(sb, v, r[0], r[3], -4, 4, "end", a);
        pt_jview_label(sb, v, r[0], r[1], -4, 0, "end", "0.5");
        axis_name(a, sizeof a, st, 0, " \xe2\x86\x92");              /* x_pp ->, y_pp up */
        pt_jview_label(sb, v, r[2], r[1], 4, -4, "start", a);
        axis_name(a, sizeof a, st, 1, " \xe2\x86\x91");
        pt_jview_label(sb, v, r[0], r[3], 0, -6, "middle", a);
    } else {
        int64_t wd = st == PT_STAGE_VIEWPORT ? p->w : p->W, ht = st == PT_STAGE_VIEWPORT ? p->h : p->H;
        pt_jview_label(sb, v, r[0], r[1], 0, -5, "start", "(0, 0)");
        strcpy(a, "(");
        pt_jfmt_i64(b, sizeof b, wd - 1); strcat(a, b); strcat(a, ", ");
        pt_jfmt_i64(b, sizeof b, ht - 1); strcat(a, b); strcat(a, ")");
        pt_jview_label(sb, v, r[2], r[3], 0, 13, "end", a);
        /* x along the bottom edge's middle (the zoom inset takes the top
        ** right), y at the left edge's middle, its arrow down: rows go down */
        axis_name(a, sizeof a, st, 0, " \xe2\x86\x92");
        pt_jview_label(sb, v, (r[0] + r[2]) / 2, r[3], 0, 13, "middle", a);
        axis_name(a, sizeof a, st, 1, " \xe2\x86\x93");
        pt_jview_label(sb, v, r[0], (r[1] + r[3]) / 2, -4, 4, "end", a);
    }
    pt_jwireframe(sb, jm, st);
}

/* The pixel array's whole strip, from STRIP_X over STRIP_W units. */
#define STRIP_X 20.0
#define STRIP_W 360.0

static void bg_index(pt_sbuf *sb, const pt_jmodel *jm, pt_stage st)
{
    const pt_stage_params *p = &jm->par;
    pt_jplace *cur = pt_jdraw_place();
    int64_t n = (int64_t)p->W * p->H;
    char a[160], b[32];

    (void)st;
    strcpy(a, "W x H = ");
    pt_jfmt_i64(b, sizeof b, p->W); strcat(a, b); strcat(a, " x ");
    pt_jfmt_i64(b, sizeof b, p->H); strcat(a, b); strcat(a, " = ");
    pt_jfmt_i64(b, sizeof b, n); strcat(a, b); strcat(a, " pixels, one row after another");
    pt_jtext(sb, STRIP_X, 57, 11, "start", "fill=\"" PT_JC_NOTE "\"", a, STRIP_W);
    pt_jrect(sb, STRIP_X, 68, STRIP_W, 18, "#eef0f3", "#9aa1ab", "");
    if (p->H <= 64) {
        int r;
        pt_sbuf_addf(sb, "<g stroke=\"%s\" stroke-width=\"0.7\">\n", "#9aa1ab");
        for (r = 1; r < p->H; r++) {
            double x = STRIP_X + STRIP_W * r / p->H;
            pt_sbuf_add(sb, "<line");
            pt_jattr(sb, "x1", x); pt_jattr(sb, "y1", 68); pt_jattr(sb, "x2", x); pt_jattr(sb, "y2", 86);
            if (cur) pt_jplace_seg(cur, x, 68, x, 86);
            pt_sbuf_add(sb, "/>\n");
        }
        pt_sbuf_add(sb, "</g>\n");
    }
    if (cur) pt_jplace_box(cur, STRIP_X, 68, STRIP_X + STRIP_W, 86, PT_JPLACE_TAKEN);
    pt_jlabel_at(sb, STRIP_X, 98, 10, "start", "fill=\"" PT_JC_NOTE "\"", "0", 0, PT_JLAB_AXIS);
    axis_name(a, sizeof a, PT_STAGE_INDEX, 0, " \xe2\x86\x92");
    pt_jlabel_at(sb, STRIP_X + STRIP_W / 2, 98, 10, "middle", "fill=\"" PT_JC_NOTE "\"", a, 0, PT_JLAB_AXIS);
    pt_jfmt_i64(b, sizeof b, n - 1);
    pt_jlabel_at(sb, STRIP_X + STRIP_W, 98, 10, "end", "fill=\"" PT_JC_NOTE "\"", b, 0, PT_JLAB_AXIS);
}

/* ===== notes: where the vertex stands after each stage ===== */

static void note_model(char *t, size_t n, const pt_jmodel *jm, const pt_journey *j, pt_stage st,
                       int used)
{
    (void)jm; (void)j; (void)st;
    snprintf(t, n, "%s", used ? "the model's own coordinates, as in the scene"
             : "used by no segment: the renderer never transforms it");
}

static void note_camera(char *t, size_t n, const pt_jmodel *jm, const pt_journey *j, pt_stage st,
                        int used)
{
    const pt_vrec *r = &j->rec[st];

    (void)used;
    if (!jm->par.perspective)
        snprintf(t, n, "%s", !isfinite(r->x) || !isfinite(r->y) ? "not finite"
                 : "orthographic: the depth z_c does not move the image point");
    else
        snprintf(t, n, "%s", !isfinite(r->z) ? "not finite"
                 : r->z < 0 ? "in front of the camera (z_c < 0)"
                 : r->z > 0 ? "behind the camera (z_c > 0): projected mirrored"
                 : "on the camera's plane z_c = 0: the projection divides by zero");
}

static void note_image(char *t, size_t n, const pt_jmodel *jm, const pt_journey *j, pt_stage st,
                       int used)
{
    const pt_vrec *r = &j->rec[st];

    (void)jm; (void)used;
    snprintf(t, n, "%s%s", !isfinite(r->x) || !isfinite(r->y) ? "not finite: no image point"
             : fabs(r->x) <= 1 && fabs(r->y) <= 1 ? "inside the view rectangle"
             : "outside the view rectangle",
             r->flags & PT_REC_BEHIND ? " (behind the camera: mirrored)" : "");
}

static void note_pixel(char *t, size_t n, const pt_jmodel *jm, const pt_journey *j, pt_stage st,
                       int used)
{
    char a[32], b[32];

    (void)st; (void)used;
    if (j->rec[PT_STAGE_VIEWPORT].flags & PT_REC_NULL)
        snprintf(t, n, "no integer pixel: not finite or beyond 2^62");
    else {
        pt_jfmt_i64(a, sizeof a, j->rec[PT_STAGE_VIEWPORT].ix + 1);
        pt_jfmt_i64(b, sizeof b, jm->par.h - j->rec[PT_STAGE_VIEWPORT].iy);
        snprintf(t, n, "nearest logical pixel (%s, %s)", a, b);
    }
}

static void note_viewport(char *t, size_t n, const pt_jmodel *jm, const pt_journey *j,
                          pt_stage st, int used)
{
    const pt_vrec *r = &j->rec[st];

    (void)jm;
    snprintf(t, n, "%s", r->flags & PT_REC_NULL ? "no pixel"
             : !(r->flags & PT_REC_INSIDE) ? "outside the viewport: clipped, not drawn"
             : used ? "inside the viewport: drawn"
             : "inside the viewport, but no segment draws it");
}

static void note_framebuffer(char *t, size_t n, const pt_jmodel *jm, const pt_journey *j,
                             pt_stage st, int used)
{
    const pt_vrec *r = &j->rec[st];
    const pt_stage_params *p = &jm->par;

    (void)used;
    snprintf(t, n, "%s", r->flags & PT_REC_NULL ? "no pixel"
             : r->ix >= 0 && r->ix < p->W && r->iy >= 0 && r->iy < p->H
               ? "inside the framebuffer" : "outside the framebuffer");
}

static void note_index(char *t, size_t n, const pt_jmodel *jm, const pt_journey *j, pt_stage st,
                       int used)
{
    (void)jm; (void)used;
    snprintf(t, n, "%s", j->rec[st].flags & PT_REC_NULL
             ? "no index: the pixel is not in the array" : "row-major: the top row first");
}

/* ===== foregrounds ===== */

/* Rasterized pixels of segments, drawn as cells of a view: viewport pixel
** (x, y) is cell (x + dx, y + dy). */
typedef struct cells {
    pt_sbuf *sb;
    const pt_jview *v;
    int64_t dx, dy;              /* viewport -> this view's cells */
    const char *fill;
    pt_jpath pw;                    /* the cells drawn, as one path */
    unsigned long n;             /* cells drawn */
    int64_t row_lo, row_hi;      /* index strip: rows wanted (fb y) */
    double *xs;                  /* index strip: fb x of each cell found */
    int64_t *ys;
    size_t nx, capx;
} cells;

static void cell_px(void *ud, int64_t x, int64_t y)
{
    cells *c = ud;
    double cx = (double)(x + c->dx), cy = (double)(y + c->dy);

    double xa, xb, ya, yb;

    if (c->n >= CELLMAX) return;
    xa = fmax(cx, c->v->x0); xb = fmin(cx + 1, c->v->x1);
    ya = fmax(cy, c->v->y0); yb = fmin(cy + 1, c->v->y1);
    if (!(xa < xb && ya < yb)) return;
    if (!c->pw.open) pt_jpath_start(&c->pw, c->sb);
    pt_jpath_cmd(&c->pw, "M", 2, pt_jview_x(c->v, xa), pt_jview_y(c->v, ya));
    pt_jpath_cmd(&c->pw, "H", 1, pt_jview_x(c->v, xb), 0);
    pt_jpath_cmd(&c->pw, "V", 1, pt_jview_y(c->v, yb), 0);
    pt_jpath_cmd(&c->pw, "H", 1, pt_jview_x(c->v, xa), 0);
    pt_sbuf_add(c->sb, "z");
    c->n++;
}

/* Close the path of cells drawn by cell_px(). */
static void cells_end(cells *c)
{
    char attrs[64];

    snprintf(attrs, sizeof attrs, "fill=\"%s\"", c->fill);
    pt_jpath_end(&c->pw, attrs);
}

/* Collects the fb pixels of segments that fall in rows row_lo..row_hi. */
static void cell_collect(void *ud, int64_t x, int64_t y)
{
    cells *c = ud;
    int64_t fy = y + c->dy;

    if (fy < c->row_lo || fy > c->row_hi || c->nx >= CELLMAX) return;
    if (c->nx == c->capx) {
        size_t cap = c->capx ? 2 * c->capx : 64;
        double *nx = realloc(c->xs, cap * sizeof *nx);
        int64_t *ny;
        if (!nx) return;
        c->xs = nx;
        ny = realloc(c->ys, cap * sizeof *ny);
        if (!ny) return;
        c->ys = ny;
        c->capx = cap;
    }
    c->xs[c->nx] = (double)(x + c->dx);
    c->ys[c->nx++] = fy;
}

/* The zoom inset of the pixel panels: 9 x 7 pixels around the vertex's pixel,
** where it covers no label and not the marker at (mx, my) (the panel's
** pt_jplace; it may cover lines), a corner far from the marker when several
** places are free. */
static void inset(pt_sbuf *sb, const pt_jmodel *jm, const pt_journey *j, pt_stage st,
                  size_t k, double mx, double my)
{
    const pt_jview *mv = &jm->view[st];
    const pt_stage_params *p = &jm->par;
    const pt_vrec *r = &j->rec[st];
    double iw = 150, ih = 112, cx, cy, best = (double)INFINITY, bx = PT_JBOX_X + 5, by = PT_JBOX_Y + 5;
    double area[4], win[4];
    pt_jplace *cur = pt_jdraw_place();
    pt_jview v;
    int gx, gy;
    char t[80], b[32];

    /* the pixel looked at, as the centre of a cell of this panel's coordinates */
    if (st == PT_STAGE_PIXEL) {
        const pt_vrec *vp = &j->rec[PT_STAGE_VIEWPORT];
        if (vp->flags & PT_REC_NULL) return;
        cx = (double)(vp->ix + 1);           /* logical pixel m = x_vp + 1 */
        cy = (double)(p->h - vp->iy);        /* n = h - y_vp */
    } else {
        if (r->flags & PT_REC_NULL) return;
        cx = (double)r->ix + 0.5; cy = (double)r->iy + 0.5;
    }
    if (!(fabs(cx) < PIXMAX && fabs(cy) < PIXMAX)) return;
    if (isnan(mx)) { mx = PT_JBOX_X; my = PT_JBOX_Y + PT_JBOX_H; }
    for (gy = 0; gy <= 4; gy++)              /* a 9 x 5 grid of places in the box */
        for (gx = 0; gx <= 8; gx++) {
            double x = PT_JBOX_X + 5 + gx * (PT_JBOX_W - iw - 10) / 8;
            double y = PT_JBOX_Y + 5 + gy * (PT_JBOX_H - ih - 10) / 4;
            double q[4], dx = x + iw / 2 - mx, dy = y + ih / 2 - my, c;
            q[0] = x; q[1] = y; q[2] = x + iw; q[3] = y + ih;
            c = (cur ? pt_jplace_cost(cur, q, 0) : 0) - sqrt(dx * dx + dy * dy) / 100;
            if ((gx % 8) || (gy % 4)) c += 5;         /* corners first */
            if (c < best) { best = c; bx = x; by = y; }
        }
    win[0] = cx - 4.5; win[1] = cy - 3.5; win[2] = cx + 4.5; win[3] = cy + 3.5;
    pt_jview_fit(&v, win, st != PT_STAGE_PIXEL, bx, by + 14, iw, ih - 14);
    /* where the inset looks, in the main view */
    pt_jview_rect(sb, mv, v.x0, v.y0, v.x1 - v.x0, v.y1 - v.y0, "none", PT_JC_VTX, "stroke-width=\"1\"", 5);
    if (cur) pt_jplace_box(cur, bx, by, bx + iw, by + ih, PT_JPLACE_TAKEN);
    pt_sbuf_add(sb, "<g class=\"inset\">\n");
    pt_jrect(sb, bx, by, iw, ih, "#fff", "#8a919b", "stroke-width=\"1\"");
    pt_jtext(sb, bx + 4, by + 11, 9.5, "start", "fill=\"" PT_JC_NOTE "\"", "zoom", 0);
    base_rect(jm, st, area);
    pt_jview_rect(sb, &v, area[0], area[1], area[2] - area[0], area[3] - area[1],
          st == PT_STAGE_FRAMEBUFFER ? "#eef0f3" : PT_JC_AREA, "", "", 0);
    if (st == PT_STAGE_FRAMEBUFFER) {
        double vp[4];
        int64_t x, y;
        vp[0] = p->x_ul; vp[1] = p->y_ul; vp[2] = p->x_ul + p->w; vp[3] = p->y_ul + p->h;
        pt_jview_rect(sb, &v, vp[0], vp[1], p->w, p->h, PT_JC_AREA, "", "", 0);
        for (y = (int64_t)floor(v.y0); jm->frame && y < v.y1; y++)     /* the frame */
            for (x = (int64_t)floor(v.x0); x < v.x1; x++)
                if (x >= 0 && y >= 0 && x < p->W && y < p->H && frame_lit(jm, x, y))
                    pt_jview_rect(sb, &v, (double)x, (double)y, 1, 1, PT_JC_FRAMEPX, "", "", 0);
    }
    if (st != PT_STAGE_PIXEL) {
        cells cl;
        memset(&cl, 0, sizeof cl);
        cl.sb = sb; cl.v = &v; cl.fill = PT_JC_CELL;
        if (st == PT_STAGE_FRAMEBUFFER) { cl.dx = p->x_ul; cl.dy = p->y_ul; }
        pt_jraster_segs(jm, k, cell_px, &cl);
        cells_end(&cl);
        pt_jview_rect(sb, &v, cx - 0.5, cy - 0.5, 1, 1, PT_JC_VTX, "", "", 0);
    } else {
        pt_jview_rect(sb, &v, cx - 0.5, cy - 0.5, 1, 1, "none", PT_JC_VTX, "stroke-width=\"2\"", 0);
    }
    {                                        /* the cell grid */
        double g[4];
        g[0] = v.x0 - 1; g[1] = v.y0 - 1; g[2] = v.x1 + 1; g[3] = v.y1 + 1;
        pt_jgrid(sb, &v, g, st == PT_STAGE_PIXEL ? 0.5 : 0, 1);
    }
    if (st == PT_STAGE_FRAMEBUFFER) {
        double vp[4];
        vp[0] = p->x_ul; vp[1] = p->y_ul; vp[2] = p->x_ul + p->w; vp[3] = p->y_ul + p->h;
        pt_joutline(sb, &v, vp, PT_JC_EDGE, 1.5);
        pt_joutline(sb, &v, area, "#9aa1ab", 1.5);
    } else pt_joutline(sb, &v, area, PT_JC_EDGE, 1.5);
    if (st == PT_STAGE_PIXEL) {              /* pixel centres, the segments, the point */
        double x, y;
        pt_jpath pw;
        pt_jpath_start(&pw, sb);                 /* zero-length lines, round caps: dots */
        for (x = ceil(v.x0); x <= v.x1; x += 1)
            for (y = ceil(v.y0); y <= v.y1; y += 1) {
                pt_jpath_cmd(&pw, "M", 2, pt_jview_x(&v, x), pt_jview_y(&v, y));
                pt_sbuf_add(sb, "h0");
            }
        pt_jpath_end(&pw, "stroke=\"" PT_JC_AXIS "\" stroke-width=\"2.4\" stroke-linecap=\"round\"");
        pt_jsegments(sb, jm, &v, st, k, 1.5);
        if (pt_jview_in(&v, r->x, r->y))
            pt_jcircle(sb, pt_jview_x(&v, r->x), pt_jview_y(&v, r->y), 3.5, PT_JC_VTX, "stroke=\"#fff\" stroke-width=\"1\"");
    }
    /* the pixel's name */
    strcpy(t, st == PT_STAGE_PIXEL ? "logical pixel (" : "pixel (");
    pt_jfmt_i64(b, sizeof b, (int64_t)floor(cx)); strcat(t, b); strcat(t, ", ");
    pt_jfmt_i64(b, sizeof b, (int64_t)floor(cy)); strcat(t, b); strcat(t, ")");
    pt_jtext(sb, bx + iw - 4, by + 11, 9.5, "end", "fill=\"" PT_JC_VTX "\"", t, 0);
    pt_sbuf_add(sb, "</g>\n");
}

/* The camera panel's projection ray and image point. */
static void fg_ray(pt_sbuf *sb, const pt_jmodel *jm, const pt_journey *j)
{
    const pt_jview *v = &jm->view[PT_STAGE_CAMERA];
    const pt_vrec *c = &j->rec[PT_STAGE_CAMERA], *ip = &j->rec[PT_STAGE_IMAGE];
    double o[3] = {0, 0, 0}, pc[3], pi[3], px, py;

    pc[0] = c->x; pc[1] = c->y; pc[2] = c->z;
    pi[0] = ip->x; pi[1] = ip->y; pi[2] = ip->z;
    if (!isfinite(pi[0]) || !isfinite(pi[1])) return;
    if (jm->par.perspective) {
        pt_jline3(sb, v, PT_STAGE_CAMERA, o, pc, PT_JC_VTX, 1, "stroke-dasharray=\"4 3\"");
        pt_jline3(sb, v, PT_STAGE_CAMERA, o, pi, PT_JC_VTX, 1, "stroke-dasharray=\"4 3\"");
    } else pt_jline3(sb, v, PT_STAGE_CAMERA, pc, pi, PT_JC_VTX, 1, "stroke-dasharray=\"4 3\"");
    pt_jproj(PT_STAGE_CAMERA, pi[0], pi[1], pi[2], &px, &py);
    if (pt_jview_in(v, px, py))
        pt_jcircle(sb, pt_jview_x(v, px), pt_jview_y(v, py), 3.5, "#fff", "stroke=\"" PT_JC_VTX "\" stroke-width=\"1.5\"");
}

/* The index stage's formula without its bounds test (pt_fb2index() gives -1
** off the frame; the panel shows where the formula would point): written
** again here on purpose, and tied to pt_fb2index() on the frame by
** tests/unit/test_journey.c. */
int64_t pt_jclassic_would_index(int64_t x, int64_t y, int64_t W)
{
    return y * W + x;                        /* idx = y_fb * W + x_fb */
}

/* The first and the last element of row y (0 <= y < H) of the pixel array,
** as the index stage gives them. */
static int64_t row_start(const pt_stage_params *p, int64_t y)
{
    pt_pix fb = {0, 0, 1};

    fb.y = y;
    return pt_fb2index(fb, p->W, p->H, NULL);
}

static int64_t row_end(const pt_stage_params *p, int64_t y)
{
    pt_pix fb = {0, 0, 1};

    fb.x = p->W - 1;
    fb.y = y;
    return pt_fb2index(fb, p->W, p->H, NULL);
}

/* The pixel array: the vertex's rows and its neighbours in the array. */
static void fg_index(pt_sbuf *sb, const pt_jmodel *jm, const pt_journey *j, size_t k)
{
    const pt_stage_params *p = &jm->par;
    const pt_vrec *fb = &j->rec[PT_STAGE_FRAMEBUFFER], *ix = &j->rec[PT_STAGE_INDEX];
    int64_t W = p->W, H = p->H, n = W * H, x, y, i, r0, r1, r, c0, c;
    double bw, sx, ex, rowx;
    int nr, nc;
    char t[160], a[32], b[32], d[32];
    cells cl;

    if (fb->flags & PT_REC_NULL) {
        pt_jtext(sb, 200, 150, 12, "middle", "fill=\"" PT_JC_VTX "\"",
                "no pixel, so no place in the array", 0);
        return;
    }
    x = fb->ix; y = fb->iy;
    if (ix->flags & PT_REC_NULL) {           /* outside: where the formula would point */
        const char *why = "so the index stage gives none, and nothing is written";
        pt_jfmt_i64(a, sizeof a, x); pt_jfmt_i64(b, sizeof b, y);
        snprintf(t, sizeof t, "(x_fb, y_fb) = (%s, %s) lies outside the framebuffer", a, b);
        pt_jtext(sb, 200, 140, 11.5, "middle", "fill=\"" PT_JC_VTX "\"", t, 370);
        if (fabs((double)x) < PIXMAX && fabs((double)y) < PIXMAX) {
            int64_t would = pt_jclassic_would_index(x, y, W);
            pt_jfmt_i64(a, sizeof a, would);
            if (would >= 0 && would < n) {
                double wx = STRIP_X + STRIP_W * ((double)would + 0.5) / (double)n;
                snprintf(t, sizeof t, "y_fb * W + x_fb would be %s: another pixel's element", a);
                if (!pt_scene_vp_inside(jm->s))     /* the course's setPixelFB wraps */
                    why = "the index stage gives none; a pixel drawn here lands there "
                          "(the viewport sticks out: rows wrap)";
                pt_jline(sb, wx, 62, wx, 92, PT_JC_VTX, 1.5, "stroke-dasharray=\"3 2\"");
                pt_jcircle(sb, wx, 77, 5, "none", "stroke=\"" PT_JC_VTX "\" stroke-width=\"1.5\"");
            } else {
                double ax0 = would < 0 ? STRIP_X + 30 : STRIP_X + STRIP_W - 30;
                double ax1 = would < 0 ? STRIP_X - 12 : STRIP_X + STRIP_W + 12;
                snprintf(t, sizeof t, "y_fb * W + x_fb would be %s: outside the array", a);
                pt_jline(sb, ax0, 77, ax1 + (would < 0 ? 8 : -8), 77, PT_JC_VTX, 2.5, "");
                pt_jarrow(sb, ax0, 77, ax1, 77, 10, PT_JC_VTX);
            }
            pt_jtext(sb, 200, 160, 11.5, "middle", "fill=\"" PT_JC_VTX "\"", t, 370);
        }
        pt_jtext(sb, 200, 190, 11, "middle", "fill=\"" PT_JC_NOTE "\"", why, 370);
        return;
    }
    i = ix->i;
    /* the whole strip: the vertex's row, and its element */
    sx = STRIP_X + STRIP_W * (double)row_start(p, y) / (double)n;
    pt_jrect(sb, sx, 68, fmax(STRIP_W / (double)H, 1.5), 18, PT_JC_CELL, "", "");
    ex = STRIP_X + STRIP_W * ((double)i + 0.5) / (double)n;
    pt_jline(sb, ex, 64, ex, 90, PT_JC_VTX, 2, "");
    pt_jarrow(sb, ex, 58, ex, 67, 8, PT_JC_VTX);

    /* the rows around it, laid end to end */
    r0 = y > 0 ? y - 1 : y;
    r1 = y + 1 < H ? y + 1 : y;
    nr = (int)(r1 - r0 + 1);
    bw = STRIP_W / nr;
    pt_jline(sb, STRIP_X + STRIP_W * (double)row_start(p, r0) / (double)n, 87, STRIP_X, 111,
         PT_JC_GRID, 1, "");                     /* the fan stops above the rows' names */
    pt_jline(sb, STRIP_X + STRIP_W * (double)(row_end(p, r1) + 1) / (double)n, 87,
         STRIP_X + STRIP_W, 111, PT_JC_GRID, 1, "");
    for (r = r0; r <= r1; r++) {
        double bx = STRIP_X + bw * (double)(r - r0);
        pt_jrect(sb, bx, 128, bw, 20, r == y ? PT_JC_AREA : "#eef0f3", "#9aa1ab", "");
        pt_jfmt_i64(a, sizeof a, r);
        snprintf(t, sizeof t, "row %s%s", a, r == y ? " = y_fb" : "");
        pt_jtext(sb, bx + bw / 2, 123, 10, "middle", "fill=\"" PT_JC_NOTE "\"", t, bw - 4);
        pt_jfmt_i64(a, sizeof a, row_start(p, r));
        pt_jtext(sb, bx + 1, 160, 9, "start", "fill=\"" PT_JC_NOTE "\"", a, 0);
    }
    pt_jfmt_i64(a, sizeof a, row_end(p, r1));
    pt_jtext(sb, STRIP_X + STRIP_W, 160, 9, "end", "fill=\"" PT_JC_NOTE "\"", a, 0);
    /* the segments' pixels in these rows */
    memset(&cl, 0, sizeof cl);
    cl.dx = p->x_ul; cl.dy = p->y_ul; cl.row_lo = r0; cl.row_hi = r1;
    pt_jraster_segs(jm, k, cell_collect, &cl);
    pt_sbuf_addf(sb, "<g stroke=\"%s\" stroke-width=\"1\">\n", PT_JC_SEG);
    for (c = 0; c < (int64_t)cl.nx; c++) {
        double cxp = STRIP_X + bw * ((double)(cl.ys[c] - r0) + (cl.xs[c] + 0.5) / (double)W);
        pt_sbuf_add(sb, "<line");
        pt_jattr(sb, "x1", cxp); pt_jattr(sb, "y1", 131); pt_jattr(sb, "x2", cxp); pt_jattr(sb, "y2", 145);
        pt_sbuf_add(sb, "/>\n");
    }
    pt_sbuf_add(sb, "</g>\n");
    rowx = STRIP_X + bw * ((double)(y - r0) + ((double)x + 0.5) / (double)W);
    pt_jline(sb, rowx, 127, rowx, 152, PT_JC_VTX, 2, "");

    /* eleven elements around idx */
    nc = n < 11 ? (int)n : 11;
    c0 = i - 5;
    if (c0 > n - nc) c0 = n - nc;
    if (c0 < 0) c0 = 0;
    bw = STRIP_W / 11;
    {                                        /* a fan to them, from below the rows' numbers */
        double xa = STRIP_X + bw * (double)(i - c0), xb = xa + bw, f = 13.0 / 44;
        pt_jline(sb, rowx + (xa - rowx) * f, 165, xa, 196, PT_JC_GRID, 1, "");
        pt_jline(sb, rowx + (xb - rowx) * f, 165, xb, 196, PT_JC_GRID, 1, "");
    }
    pt_jfmt_i64(a, sizeof a, y); pt_jfmt_i64(b, sizeof b, W); pt_jfmt_i64(d, sizeof d, x);
    {
        char e[32];
        pt_jfmt_i64(e, sizeof e, i);
        snprintf(t, sizeof t, "idx = y_fb * W + x_fb = %s * %s + %s = %s", a, b, d, e);
    }
    pt_jtext(sb, 200, 258, 11, "middle", "font-family=\"" PT_JMONO "\" fill=\"" PT_JC_TEXT "\" " PT_JHALO, t, 370);
    for (c = 0; c < nc; c++) {
        int64_t e = c0 + c;
        double cxp = STRIP_X + bw * (double)c;
        int seg = 0;
        size_t q;
        for (q = 0; q < cl.nx; q++)         /* where the formula puts a pixel of the
                                             ** rows (x may be off the frame: again
                                             ** without the stage's bounds, on purpose) */
            if (pt_jclassic_would_index((int64_t)cl.xs[q], cl.ys[q], W) == e) seg = 1;
        pt_jrect(sb, cxp, 196, bw, 26, e == i ? PT_JC_VTX : seg ? PT_JC_CELL : "#fff", "#9aa1ab", "");
        pt_jfmt_i64(a, sizeof a, e % W);
        pt_jtext(sb, cxp + bw / 2, 213, 9, "middle", e == i ? "fill=\"#fff\"" : "fill=\"" PT_JC_NOTE "\"",
                a, bw - 3);
        if (e % W == 0 && c > 0) pt_jline(sb, cxp, 190, cxp, 228, PT_JC_TEXT, 2, "");
        if (e == i || c == 0 || c == nc - 1) {
            pt_jfmt_i64(a, sizeof a, e);
            pt_jtext(sb, cxp + bw / 2, 236, e == i ? 11 : 9, "middle",
                    e == i ? "font-weight=\"bold\" fill=\"" PT_JC_VTX "\"" : "fill=\"" PT_JC_NOTE "\"", a, 0);
        }
    }
    pt_jtext(sb, STRIP_X, 276, 9.5, "start", "fill=\"" PT_JC_NOTE "\"",
            "cells: x_fb within the row; below: the element's index", 0);
    free(cl.xs);
    free(cl.ys);
}

/* ===== foregrounds by stage ===== */

static void fg_model(pt_sbuf *sb, const pt_jmodel *jm, const pt_journey *j, size_t k, pt_stage st)
{
    pt_jfg_path(sb, jm, j, st);
    pt_jfg_point(sb, jm, j, k, st);
}

static void fg_camera(pt_sbuf *sb, const pt_jmodel *jm, const pt_journey *j, size_t k, pt_stage st)
{
    fg_ray(sb, jm, j);
    pt_jfg_point(sb, jm, j, k, st);
}

/* The logical pixel plane: the nearest logical pixel outlined, a zoom inset
** when pixels are small. */
static void fg_pixel(pt_sbuf *sb, const pt_jmodel *jm, const pt_journey *j, size_t k, pt_stage st)
{
    const pt_jview *v = &jm->view[st];
    double x, y, mx, my;
    int ok = pt_jstage_xy(j, st, &x, &y);

    pt_jsegments(sb, jm, v, st, k, 2);
    if (!(j->rec[PT_STAGE_VIEWPORT].flags & PT_REC_NULL) && v->s >= 3) {
        double m = (double)j->rec[PT_STAGE_VIEWPORT].ix + 1;
        double n = (double)(jm->par.h - j->rec[PT_STAGE_VIEWPORT].iy);
        pt_jview_rect(sb, v, m - 0.5, n - 0.5, 1, 1, "none", PT_JC_VTX, "stroke-width=\"1.5\"", 0);
    }
    pt_jmarker(sb, v, ok, x, y, (uint64_t)k + 1, 0, &mx, &my);
    if (v->s < 6) inset(sb, jm, j, st, k, mx, my);
}

/* The viewport and the framebuffer: the pixels the vertex's segments light,
** its own pixel filled, a zoom inset when pixels are small. */
static void fg_pixels(pt_sbuf *sb, const pt_jmodel *jm, const pt_journey *j, size_t k, pt_stage st)
{
    const pt_jview *v = &jm->view[st];
    double x, y, mx, my;
    int ok = pt_jstage_xy(j, st, &x, &y);

    if (v->s >= 3) {
        cells cl;
        memset(&cl, 0, sizeof cl);
        cl.sb = sb; cl.v = v; cl.fill = PT_JC_CELL;
        if (st == PT_STAGE_FRAMEBUFFER) { cl.dx = jm->par.x_ul; cl.dy = jm->par.y_ul; }
        pt_jraster_segs(jm, k, cell_px, &cl);
        cells_end(&cl);
    }
    pt_jsegments(sb, jm, v, st, k, v->s >= 3 ? 1 : 2);
    if (ok) pt_jview_rect(sb, v, x - 0.5, y - 0.5, 1, 1, PT_JC_VTX, "", "", 4);
    pt_jmarker(sb, v, ok, x, y, (uint64_t)k + 1, v->s < 6 ? 1 : 2, &mx, &my);
    if (!ok) {
        pt_jlabel_at(sb, PT_JBOX_X + PT_JBOX_W / 2, PT_JBOX_Y + PT_JBOX_H / 2, 12, "middle",
                     "fill=\"" PT_JC_VTX "\" " PT_JHALO, "no pixel", 0, PT_JLAB_VERTEX);
        pt_jlabel_at(sb, PT_JBOX_X + PT_JBOX_W / 2, PT_JBOX_Y + PT_JBOX_H / 2 + 16, 10.5, "middle",
                     "fill=\"" PT_JC_VTX "\" " PT_JHALO, "the pixel-plane point", 0,
                     PT_JLAB_VERTEX);
        pt_jlabel_at(sb, PT_JBOX_X + PT_JBOX_W / 2, PT_JBOX_Y + PT_JBOX_H / 2 + 30, 10.5, "middle",
                     "fill=\"" PT_JC_VTX "\" " PT_JHALO, "is not finite or beyond 2^62", 0,
                     PT_JLAB_VERTEX);
    }
    if (v->s < 6) inset(sb, jm, j, st, k, mx, my);
}

static void fg_array(pt_sbuf *sb, const pt_jmodel *jm, const pt_journey *j, size_t k, pt_stage st)
{
    (void)st;
    fg_index(sb, jm, j, k);
}

/* ===== the rows (jrows.c) ===== */

const pt_jstage_row pt_jclassic_rows[PT_NSTAGES_ALL] = {
    [PT_STAGE_MODEL]       = { bg_model, fg_model, note_model },
    [PT_STAGE_CAMERA]      = { bg_camera, fg_camera, note_camera },
    [PT_STAGE_IMAGE]       = { bg_plane, pt_jfg_point, note_image },
    [PT_STAGE_PIXEL]       = { bg_plane, fg_pixel, note_pixel },
    [PT_STAGE_VIEWPORT]    = { bg_plane, fg_pixels, note_viewport },
    [PT_STAGE_FRAMEBUFFER] = { bg_plane, fg_pixels, note_framebuffer },
    [PT_STAGE_INDEX]       = { bg_index, fg_array, note_index },
};

int pt_jclassic_ends(const pt_jmodel *jm, size_t s, pt_stage st, pt_journey *ja, pt_journey *jb)
{
    (void)st;
    *ja = *pt_jmodel_journey(jm, jm->m->seg[s].a);
    *jb = *pt_jmodel_journey(jm, jm->m->seg[s].b);
    return 1;
}

int pt_jclassic_pixelplane(const pt_jmodel *jm, const pt_journey *j, pt_vec2 *pp)
{
    (void)jm;
    pp->x = j->rec[PT_STAGE_PIXEL].x;
    pp->y = j->rec[PT_STAGE_PIXEL].y;
    return 0;
}
