/*
** src/tools/journey/journey.c -- one vertex's journey drawn: a panel per coordinate system (SVG)
** See LICENSE for copyright and license.
**
** Layout of a panel (PT_JOURNEY_PW x PT_JOURNEY_PH units): a title and the
** stage's formula on top, the plot box (BOX_*) in the middle, the vertex's
** coordinates and a note below.  Each plot is a pt_jview: a window of the
** stage's own coordinates fitted into the box at one scale for x and y.
** Segments are clipped to the window here (Liang-Barsky), so the SVG holds
** only short, finite numbers whatever the scene's coordinates are.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "tools/journey/journey.h"
#include "tools/journey/jplace.h"
#include "io/numfmt.h"
#include "core/pipetrace.h"

/* ===== look ===== */

#define FONT      "DejaVu Sans, Helvetica, Arial, sans-serif"
#define MONO      "DejaVu Sans Mono, Menlo, Consolas, monospace"
#define C_TEXT    "#222"
#define C_NOTE    "#5f6670"
#define C_AXIS    "#6b7280"
#define C_FAINT   "#b9bfc9"
#define C_SEG     "#1f6fd1"
#define C_CELL    "#a8c7ee"
#define C_VTX     "#d62728"        /* PT_JOURNEY_RED_RGB */
#define C_AREA    "#e6eefa"
#define C_EDGE    "#7f9cc6"
#define C_GRID    "#d3d9e3"
#define C_FRAME   "#c9ced6"
#define C_FRAMEPX "#a3abb7"        /* a pixel of the rendered frame */

#define BOX_X     10.0           /* the plot box, panel units */
#define BOX_Y     42.0
#define BOX_W     380.0
#define BOX_H     248.0
#define CAPTION_Y 308.0          /* the coordinates */
#define NOTE_Y    327.0          /* the note */

#define BIG       1e150          /* coordinates beyond this never widen a panel */
#define PIXMAX    1099511627776.0   /* 2^40: pixels beyond get no zoom inset */
#define CELLMAX   20000          /* at most this many pixel cells per view */

/* ===== numbers and elements ===== */

/* A panel coordinate with at most one decimal ("12", "12.5"; never "-0"). */
static void num(pt_sbuf *sb, double x)
{
    double r;

    if (!(x > -1e7)) x = -1e7;           /* callers clip; this is a last guard */
    if (x > 1e7) x = 1e7;
    r = floor(x * 10.0 + 0.5) / 10.0;
    if (r == floor(r)) pt_sbuf_addf(sb, "%.0f", r == 0 ? 0.0 : r);
    else pt_sbuf_addf(sb, "%.1f", r);
}

/* Append ` name="x"` with x a panel coordinate. */
static void attr(pt_sbuf *sb, const char *name, double x)
{
    pt_sbuf_add(sb, " ");
    pt_sbuf_add(sb, name);
    pt_sbuf_add(sb, "=\"");
    num(sb, x);
    pt_sbuf_add(sb, "\"");
}


/* <text> at (x, y): size, anchor ("start", "middle", "end"), more attributes
** (extra, may be ""), the text escaped.  When its estimated width exceeds
** maxw (> 0) it is squeezed to maxw with textLength. */
/* The panel being drawn: while pt_journey_panel_bg() or _fg() runs, the
** lines, circles and texts drawn are recorded in it, and labels that may move
** wait there for their place (jplace.h).  NULL otherwise (the legend, the
** header). */
static pt_jplace *cur;

static void text_raw(pt_sbuf *sb, double x, double y, double size, const char *anchor,
                     const char *extra, const char *t, double maxw)
{
    double est = pt_jtext_width(t, size, pt_jtext_face(extra));

    pt_sbuf_add(sb, "<text");
    attr(sb, "x", x);
    attr(sb, "y", y);
    attr(sb, "font-size", size);
    if (strcmp(anchor, "start") != 0) pt_sbuf_addf(sb, " text-anchor=\"%s\"", anchor);
    if (maxw > 0 && est > maxw) {
        attr(sb, "textLength", maxw);
        pt_sbuf_add(sb, " lengthAdjust=\"spacingAndGlyphs\"");
    }
    if (*extra) { pt_sbuf_add(sb, " "); pt_sbuf_add(sb, extra); }
    pt_sbuf_add(sb, ">");
    pt_sbuf_add_xml(sb, t);
    pt_sbuf_add(sb, "</text>\n");
}

/* A text that stays where it is put; the panel's labels keep clear of it. */
static void text_at(pt_sbuf *sb, double x, double y, double size, const char *anchor,
                    const char *extra, const char *t, double maxw)
{
    if (cur) {
        double b[4];
        pt_jtext_box(b, x, y, size, anchor, pt_jtext_face(extra), t, maxw);
        pt_jplace_box(cur, b[0], b[1], b[2], b[3], PT_JPLACE_TAKEN);
    }
    text_raw(sb, x, y, size, anchor, extra, t, maxw);
}

/* A label that wants to be at (x, y) and may move, most important first
** (prio 0 the vertex's name, 1 axes, 2 the rest): written when the panel's
** foreground ends (pt_jplace_run()), or at once when no panel is drawn. */
enum { LAB_VERTEX, LAB_AXIS, LAB_OTHER };

static void label_at(pt_sbuf *sb, double x, double y, double size, const char *anchor,
                     const char *extra, const char *t, double maxw, int prio)
{
    pt_jlabel l;

    if (!cur) { text_raw(sb, x, y, size, anchor, extra, t, maxw); return; }
    l.x = x; l.y = y; l.size = size; l.maxw = maxw; l.prio = prio;
    snprintf(l.anchor, sizeof l.anchor, "%s", anchor);
    snprintf(l.extra, sizeof l.extra, "%s", extra);
    snprintf(l.text, sizeof l.text, "%s", t);
    pt_jplace_label(cur, &l);
}

/* Many lines or cells as one <path>: open on the first piece, then "M x y"
** and more commands, closed with its attributes by path_end(). */
typedef struct pathw {
    pt_sbuf *sb;
    int open;                    /* 1: "<path d=\"" written */
} pathw;

static void path_start(pathw *p, pt_sbuf *sb)
{
    p->sb = sb;
    p->open = 0;
}

/* Append command c ("M", "L", "h", ...) with n numbers. */
static void path_cmd(pathw *p, const char *c, int n, double a, double b)
{
    if (!p->open) { pt_sbuf_add(p->sb, "<path d=\""); p->open = 1; }
    pt_sbuf_add(p->sb, c);
    num(p->sb, a);
    if (n > 1) { pt_sbuf_add(p->sb, " "); num(p->sb, b); }
}

static void path_end(pathw *p, const char *attrs)
{
    if (!p->open) return;
    pt_sbuf_add(p->sb, "\" ");
    pt_sbuf_add(p->sb, attrs);
    pt_sbuf_add(p->sb, "/>\n");
    p->open = 0;
}

/* A label over drawings: a white halo keeps it legible. */
#define HALO "stroke=\"#fff\" stroke-width=\"3\" paint-order=\"stroke\""

static void line(pt_sbuf *sb, double ax, double ay, double bx, double by,
                 const char *stroke, double width, const char *extra)
{
    if (cur) pt_jplace_seg(cur, ax, ay, bx, by);
    pt_sbuf_add(sb, "<line");
    attr(sb, "x1", ax); attr(sb, "y1", ay); attr(sb, "x2", bx); attr(sb, "y2", by);
    pt_sbuf_addf(sb, " stroke=\"%s\"", stroke);
    attr(sb, "stroke-width", width);
    if (*extra) { pt_sbuf_add(sb, " "); pt_sbuf_add(sb, extra); }
    pt_sbuf_add(sb, "/>\n");
}

static void rect(pt_sbuf *sb, double x, double y, double w, double h, const char *fill,
                 const char *stroke, const char *extra)
{
    pt_sbuf_add(sb, "<rect");
    attr(sb, "x", x); attr(sb, "y", y); attr(sb, "width", w); attr(sb, "height", h);
    pt_sbuf_addf(sb, " fill=\"%s\"", fill);
    if (*stroke) pt_sbuf_addf(sb, " stroke=\"%s\"", stroke);
    if (*extra) { pt_sbuf_add(sb, " "); pt_sbuf_add(sb, extra); }
    pt_sbuf_add(sb, "/>\n");
}

static void circle(pt_sbuf *sb, double x, double y, double r, const char *fill,
                   const char *extra)
{
    if (cur) pt_jplace_box(cur, x - r, y - r, x + r, y + r, r < 4 ? PT_JPLACE_MARK : PT_JPLACE_TAKEN);
    pt_sbuf_add(sb, "<circle");
    attr(sb, "cx", x); attr(sb, "cy", y); attr(sb, "r", r);
    pt_sbuf_addf(sb, " fill=\"%s\"", fill);
    if (*extra) { pt_sbuf_add(sb, " "); pt_sbuf_add(sb, extra); }
    pt_sbuf_add(sb, "/>\n");
}

/* A filled triangle with its tip at (bx, by), pointing from (ax, ay). */
static void arrowhead(pt_sbuf *sb, double ax, double ay, double bx, double by,
                      double size, const char *fill)
{
    double dx = bx - ax, dy = by - ay, d = sqrt(dx * dx + dy * dy);
    double ux, uy;

    if (!(d > 0)) return;
    ux = dx / d; uy = dy / d;
    pt_sbuf_add(sb, "<path d=\"M");
    num(sb, bx); pt_sbuf_add(sb, " "); num(sb, by); pt_sbuf_add(sb, " L");
    num(sb, bx - size * ux - 0.45 * size * uy); pt_sbuf_add(sb, " ");
    num(sb, by - size * uy + 0.45 * size * ux); pt_sbuf_add(sb, " L");
    num(sb, bx - size * ux + 0.45 * size * uy); pt_sbuf_add(sb, " ");
    num(sb, by - size * uy - 0.45 * size * ux);
    pt_sbuf_addf(sb, " Z\" fill=\"%s\"/>\n", fill);
}

/* Integers as text. */
static void fmt_i64(char *b, size_t n, int64_t x)
{
    char t[24], *o = t + sizeof t - 1;
    uint64_t u = x < 0 ? 0u - (uint64_t)x : (uint64_t)x;
    size_t k = 0;

    *o = '\0';
    do { *--o = (char)('0' + u % 10); u /= 10; } while (u);
    if (x < 0) *--o = '-';
    for (; o[k] && k + 1 < n; k++) b[k] = o[k];
    b[k] = '\0';
}

/* ===== views ===== */

static double vx(const pt_jview *v, double x) { return v->bx + (x - v->x0) * v->s; }
static double vy(const pt_jview *v, double y)
{
    return v->ydown ? v->by + (y - v->y0) * v->s : v->by + v->bh - (y - v->y0) * v->s;
}

static int in_view(const pt_jview *v, double x, double y)
{
    return x >= v->x0 && x <= v->x1 && y >= v->y0 && y <= v->y1;
}

/* Fit the data rectangle [xa, xb] x [ya, yb] into the box, centred, one scale. */
static void view_fit(pt_jview *v, double xa, double ya, double xb, double yb,
                     double bx, double by, double bw, double bh, int ydown)
{
    double w = xb - xa, h = yb - ya, s, cx = xa / 2 + xb / 2, cy = ya / 2 + yb / 2;

    if (!(w > 0)) w = 0;
    if (!(h > 0)) h = 0;
    if (w == 0 && h == 0) w = h = 1;
    s = w == 0 ? bh / h : h == 0 ? bw / w : fmin(bw / w, bh / h);
    v->s = s;
    v->x0 = cx - bw / (2 * s); v->x1 = cx + bw / (2 * s);
    v->y0 = cy - bh / (2 * s); v->y1 = cy + bh / (2 * s);
    v->bx = bx; v->by = by; v->bw = bw; v->bh = bh;
    v->ydown = ydown;
}

/* Clip the segment a-b to the view's window (Liang-Barsky).  Returns 1 and
** the clipped ends, or 0 when nothing is left or a number is not finite. */
static int clip(const pt_jview *v, double *ax, double *ay, double *bx, double *by)
{
    double dx = *bx - *ax, dy = *by - *ay, t0 = 0, t1 = 1;
    double p[4], q[4];
    int k;

    if (!isfinite(dx) || !isfinite(dy)) return 0;
    p[0] = -dx; q[0] = *ax - v->x0;
    p[1] = dx;  q[1] = v->x1 - *ax;
    p[2] = -dy; q[2] = *ay - v->y0;
    p[3] = dy;  q[3] = v->y1 - *ay;
    for (k = 0; k < 4; k++) {
        if (p[k] == 0) {
            if (q[k] < 0) return 0;
        } else {
            double r = q[k] / p[k];
            if (p[k] < 0) { if (r > t1) return 0; if (r > t0) t0 = r; }
            else          { if (r < t0) return 0; if (r < t1) t1 = r; }
        }
    }
    *bx = *ax + t1 * dx; *by = *ay + t1 * dy;
    *ax = *ax + t0 * dx; *ay = *ay + t0 * dy;
    return 1;
}

/* Draw the data segment a-b clipped to the view.  Returns 1 when drawn. */
static int vline(pt_sbuf *sb, const pt_jview *v, double ax, double ay, double bx,
                 double by, const char *stroke, double width, const char *extra)
{
    if (!clip(v, &ax, &ay, &bx, &by)) return 0;
    line(sb, vx(v, ax), vy(v, ay), vx(v, bx), vy(v, by), stroke, width, extra);
    return 1;
}

/* Draw the data rectangle [x, x + w] x [y, y + h] clipped to the view, at
** least minsize units wide and high (grown about its centre). */
static void vrect(pt_sbuf *sb, const pt_jview *v, double x, double y, double w, double h,
                  const char *fill, const char *stroke, const char *extra, double minsize)
{
    double xa = fmax(x, v->x0), xb = fmin(x + w, v->x1);
    double ya = fmax(y, v->y0), yb = fmin(y + h, v->y1);
    double px, py, pw, ph, t;

    if (!(xa <= xb && ya <= yb)) return;
    px = vx(v, xa); pw = vx(v, xb) - px;
    py = vy(v, ya); ph = vy(v, yb) - py;
    if (ph < 0) { py += ph; ph = -ph; }
    if (pw < minsize) { t = minsize - pw; px -= t / 2; pw = minsize; }
    if (ph < minsize) { t = minsize - ph; py -= t / 2; ph = minsize; }
    rect(sb, px, py, pw, ph, fill, stroke, extra);
}

/* An arrow just inside the box's edge, pointing from the box's centre toward
** the data point (x, y), which lies outside the window (x, y may be
** infinite, not NaN).  Sets (*px, *py) to the arrow's tip. */
static void edge_arrow(pt_sbuf *sb, const pt_jview *v, double x, double y,
                       double *px, double *py)
{
    double cx = v->x0 / 2 + v->x1 / 2, cy = v->y0 / 2 + v->y1 / 2;
    double dx = (x - cx) * v->s, dy = (y - cy) * v->s, m, t, ox, oy, tx, ty;
    double hw = v->bw / 2 - 14, hh = v->bh / 2 - 14;

    *px = *py = (double)NAN;
    if (isnan(dx) || isnan(dy)) return;
    m = fmax(fabs(dx), fabs(dy));
    if (!(m > 0)) return;
    if (isinf(m)) {
        dx = isinf(dx) ? (dx > 0 ? 1 : -1) : 0;
        dy = isinf(dy) ? (dy > 0 ? 1 : -1) : 0;
    } else { dx /= m; dy /= m; }
    if (!v->ydown) dy = -dy;
    t = fmin(dx != 0 ? hw / fabs(dx) : (double)INFINITY,
             dy != 0 ? hh / fabs(dy) : (double)INFINITY);
    ox = v->bx + v->bw / 2; oy = v->by + v->bh / 2;
    tx = ox + t * dx; ty = oy + t * dy;
    m = sqrt(dx * dx + dy * dy);
    line(sb, tx - 26 * dx / m, ty - 26 * dy / m, tx - 6 * dx / m, ty - 6 * dy / m, C_VTX, 2.5, "");
    arrowhead(sb, tx - 26 * dx / m, ty - 26 * dy / m, tx, ty, 11, C_VTX);
    *px = tx - 30 * dx / m;
    *py = ty - 30 * dy / m;
}

/* ===== 3-D views ===== */

/* The screen axes of a 3-D panel seen from direction d (toward the viewer):
** right r = (y x d)/|..|, up u = d x r. */
typedef struct axes3 { double r[3], u[3]; } axes3;

static void axes3_make(axes3 *a, double dx, double dy, double dz)
{
    double n = sqrt(dx * dx + dy * dy + dz * dz), rn;

    dx /= n; dy /= n; dz /= n;
    rn = sqrt(dz * dz + dx * dx);
    a->r[0] = dz / rn; a->r[1] = 0; a->r[2] = -dx / rn;
    a->u[0] = dy * a->r[2] - dz * a->r[1];
    a->u[1] = dz * a->r[0] - dx * a->r[2];
    a->u[2] = dx * a->r[1] - dy * a->r[0];
}

/* Model space: seen from the front right, above.  Camera space: from the
** right side, so -z (the view direction) runs to the right. */
static void axes_of(pt_stage st, axes3 *a)
{
    if (st == PT_STAGE_MODEL || st == PT_STAGE_WORLD) axes3_make(a, 0.55, 0.45, 1.0);
    else if (st == PT_STAGE_VIEW || st == PT_STAGE_NDC) axes3_make(a, -1.0, 0.5, -0.3);
    else axes3_make(a, 1.0, 0.5, 0.3);              /* matrix: view and ndc look down +z */
}

static void proj(const axes3 *a, double x, double y, double z, double *px, double *py)
{
    *px = a->r[0] * x + a->r[1] * y + a->r[2] * z;
    *py = a->u[0] * x + a->u[1] * y + a->u[2] * z;
}

/* Draw the 3-D segment a-b. */
static int vline3(pt_sbuf *sb, const pt_jview *v, const axes3 *ax, const double *a,
                  const double *b, const char *stroke, double width, const char *extra)
{
    double pa[2], pb[2];

    proj(ax, a[0], a[1], a[2], &pa[0], &pa[1]);
    proj(ax, b[0], b[1], b[2], &pb[0], &pb[1]);
    return vline(sb, v, pa[0], pa[1], pb[0], pb[1], stroke, width, extra);
}

/* ===== the journey's numbers ===== */

/* Vertex k + 1's journey, as pt_run() handed it over. */
static void journey_of(const pt_jmodel *jm, size_t k, pt_journey *j)
{
    *j = jm->js[k];
}

/* The journeys of segment s's two ends as stage st sees them: the vertices';
** for the matrix camera's stages after the cvv the points clipping made
** where it cut the segment (journey_matrix.c).  Returns 0 when the stage sees
** no segment (wholly outside the view volume). */
static int seg_ends(const pt_jmodel *jm, size_t s, pt_stage st, pt_journey *ja, pt_journey *jb)
{
    if (pt_scene_pipeline(jm->s)->matrices) return pt_jmatrix_ends(jm, s, st, ja, jb);
    journey_of(jm, jm->m->seg[s].a, ja);
    journey_of(jm, jm->m->seg[s].b, jb);
    return 1;
}

/* The point of stage st in its panel's data coordinates: projected for the
** 3-D panels, the pixel's centre for the pixel grids.  Returns 1, or 0 when
** the stage has no such point (no pixel) or it is not finite; *x, *y are then
** still set where a direction is known (infinite values). */
static int stage_xy(const pt_journey *j, pt_stage st, double *x, double *y)
{
    const pt_vrec *r = &j->rec[st];
    axes3 a;

    *x = *y = (double)NAN;
    if (pt_journey_stopped(j, st)) return 0;        /* stopped at the cvv */
    switch (st) {
    case PT_STAGE_MODEL:
    case PT_STAGE_CAMERA:
    case PT_STAGE_WORLD:
    case PT_STAGE_VIEW:
    case PT_STAGE_NDC:
        if (!isfinite(r->x) || !isfinite(r->y) || !isfinite(r->z)) return 0;
        axes_of(st, &a);
        proj(&a, r->x, r->y, r->z, x, y);
        break;
    case PT_STAGE_IMAGE:
    case PT_STAGE_PIXEL:
    case PT_STAGE_SCREEN:
        *x = r->x; *y = r->y;
        break;
    case PT_STAGE_VIEWPORT:
    case PT_STAGE_FRAMEBUFFER:
        if (r->flags & PT_REC_NULL) return 0;
        *x = (double)r->ix + 0.5; *y = (double)r->iy + 0.5;
        break;
    default:
        return 0;
    }
    return isfinite(*x) && isfinite(*y);
}

/* The stage's own rectangle (data coordinates) of a 2-D panel. */
static void base_rect(const pt_jmodel *jm, pt_stage st, double b[4])
{
    const pt_stage_params *p = &jm->par;

    switch (st) {
    case PT_STAGE_IMAGE: b[0] = -1; b[1] = -1; b[2] = 1; b[3] = 1; break;
    case PT_STAGE_PIXEL: b[0] = 0.5; b[1] = 0.5; b[2] = p->w + 0.5; b[3] = p->h + 0.5; break;
    case PT_STAGE_VIEWPORT: b[0] = 0; b[1] = 0; b[2] = p->w; b[3] = p->h; break;
    default: b[0] = 0; b[1] = 0; b[2] = p->W; b[3] = p->H; break;
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

/* ===== layout ===== */

int pt_jmodel_init(pt_jmodel *jm, const pt_scene *s, const pt_model *m, const pt_fb *frame)
{
    unsigned char *used = calloc(m->nv ? m->nv : 1, 1);
    double b[PT_NSTAGES_ALL][4], lim[4], reach, big = 0, deep = 0;
    pt_journey j;
    size_t k;
    int st;

    if (!used) return -1;
    memset(jm, 0, sizeof *jm);
    jm->s = s;
    jm->m = m;
    pt_stage_params_of(&jm->par, s, m);
    if (!(jm->js = pt_run_journeys(s, m, 0))) { free(used); return -1; }
    for (k = 0; k < m->nseg; k++) used[m->seg[k].a] = used[m->seg[k].b] = 1;

    /* 3-D panels: axis lengths and the pyramid's depth from the used vertices */
    for (k = 0; k < m->nv; k++) {
        if (!used[k]) continue;
        journey_of(jm, k, &j);
        for (st = 0; st < 3; st++) {
            double c = fabs(st == 0 ? j.rec[0].x : st == 1 ? j.rec[0].y : j.rec[0].z);
            if (c <= BIG && c > big) big = c;
        }
        if (-j.rec[PT_STAGE_CAMERA].z <= BIG && -j.rec[PT_STAGE_CAMERA].z > deep)
            deep = -j.rec[PT_STAGE_CAMERA].z;
    }
    jm->axis_m = big > 0 ? 1.25 * big : 1;
    jm->depth = 1.1 * fmax(1, deep);
    jm->axis_c = fmax(1, 0.2 * jm->depth);

    /* the bounding boxes, starting from what every panel shows */
    for (st = 0; st < PT_NSTAGES_ALL; st++) {
        b[st][0] = b[st][1] = (double)INFINITY;
        b[st][2] = b[st][3] = -(double)INFINITY;
    }
    {
        axes3 am, ac;
        double A = jm->axis_m, D = jm->depth, sx, sy;
        int c;
        axes_of(PT_STAGE_MODEL, &am);
        axes_of(PT_STAGE_CAMERA, &ac);
        grow(b[0], 0, 0);
        proj(&am, A, 0, 0, &sx, &sy); grow(b[0], sx, sy);
        proj(&am, 0, A, 0, &sx, &sy); grow(b[0], sx, sy);
        proj(&am, 0, 0, A, &sx, &sy); grow(b[0], sx, sy);
        (void)D;                             /* the pyramid is clipped, not fitted */
        proj(&ac, 0, 0, jm->axis_c, &sx, &sy); grow(b[1], sx, sy);
        proj(&ac, jm->axis_c, 0, 0, &sx, &sy); grow(b[1], sx, sy);
        proj(&ac, 0, jm->axis_c, 0, &sx, &sy); grow(b[1], sx, sy);
        for (c = 0; c < 4; c++) {            /* the image plane's corners */
            double cx = c & 1 ? 1 : -1, cy = c & 2 ? 1 : -1;
            proj(&ac, cx, cy, s->perspective ? -1 : 0, &sx, &sy); grow(b[1], sx, sy);
        }
        grow(b[1], 0, 0);
    }
    for (st = PT_STAGE_IMAGE; st <= PT_STAGE_FRAMEBUFFER; st++) {
        base_rect(jm, (pt_stage)st, b[st]);
        pad(b[st], 0.06, st == PT_STAGE_IMAGE ? 0.1 : 1);
    }
    for (k = 0; k < m->nv; k++) {
        double x, y;
        if (!used[k]) continue;
        journey_of(jm, k, &j);
        for (st = 0; st < 2; st++)
            if (stage_xy(&j, (pt_stage)st, &x, &y) && fabs(x) <= BIG && fabs(y) <= BIG)
                grow(b[st], x, y);
        for (st = PT_STAGE_IMAGE; st <= PT_STAGE_FRAMEBUFFER; st++) {
            double br[4];
            if (!stage_xy(&j, (pt_stage)st, &x, &y)) continue;
            base_rect(jm, (pt_stage)st, br);
            reach = PT_JOURNEY_REACH * fmax(br[2] - br[0], br[3] - br[1]) / 2;
            lim[0] = br[0] / 2 + br[2] / 2 - reach; lim[2] = br[0] / 2 + br[2] / 2 + reach;
            lim[1] = br[1] / 2 + br[3] / 2 - reach; lim[3] = br[1] / 2 + br[3] / 2 + reach;
            if (x < lim[0] || x > lim[2] || y < lim[1] || y > lim[3]) continue;
            if (st >= PT_STAGE_VIEWPORT) { grow(b[st], x - 0.5, y - 0.5); grow(b[st], x + 0.5, y + 0.5); }
            else grow(b[st], x, y);
        }
    }
    free(used);
    if (!(jm->place = calloc(PT_NSTAGES_ALL, sizeof *jm->place))) { pt_jmodel_free(jm); return -1; }
    {
        double area[4] = { BOX_X, BOX_Y, BOX_X + BOX_W, BOX_Y + BOX_H };
        for (st = 0; st < PT_NSTAGES_ALL; st++) pt_jplace_init(&jm->place[st], area);
    }
    pad(b[0], 0.08, 0);
    pad(b[1], 0.06, 0);
    for (st = PT_STAGE_IMAGE; st <= PT_STAGE_FRAMEBUFFER; st++)
        pad(b[st], 0.03, 0);                 /* a vertex on the edge stays in view */
    for (st = 0; st <= PT_STAGE_FRAMEBUFFER; st++)
        view_fit(&jm->view[st], b[st][0], b[st][1], b[st][2], b[st][3], BOX_X, BOX_Y,
                 BOX_W, BOX_H, st >= PT_STAGE_VIEWPORT);
    if (pt_scene_pipeline(s)->matrices && pt_jmatrix_init(jm) != 0) { pt_jmodel_free(jm); return -1; }
    if ((int64_t)s->fb_w * s->fb_h <= PT_JOURNEY_FRAMEMAX) {
        if (frame) jm->frame = frame;       /* rendered once for every model */
        else {
            if (pt_journey_render(&jm->own_frame, s) != 0) { pt_jmodel_free(jm); return -1; }
            jm->owns_frame = 1;
            jm->frame = &jm->own_frame;
        }
    }
    return 0;
}

int pt_journey_render(pt_fb *fb, const pt_scene *s)
{
    pt_options o;
    pt_plan p;
    pt_summary sum;
    pt_listener quiet;                      /* no trace: every hook NULL */

    memset(&quiet, 0, sizeof quiet);
    pt_options_default(&o);
    if (pt_plan_make(&p, s, &o) != 0) return -1;
    if (pt_fb_init(fb, s->fb_w, s->fb_h, s->background) != 0) { pt_plan_free(&p); return -1; }
    if (pt_run(s, &p, &o, &quiet, fb, &sum) != 0) {
        pt_plan_free(&p);
        pt_fb_free(fb);
        return -1;
    }
    pt_plan_free(&p);
    return 0;
}

void pt_jmodel_free(pt_jmodel *jm)
{
    int st;

    if (jm->owns_frame) pt_fb_free(&jm->own_frame);
    jm->owns_frame = 0;
    jm->frame = NULL;
    if (jm->place)
        for (st = 0; st < PT_NSTAGES_ALL; st++) pt_jplace_free(&jm->place[st]);
    free(jm->place);
    jm->place = NULL;
    free(jm->js);
    jm->js = NULL;
    free(jm->cut);
    free(jm->cutix);
    jm->cut = NULL;
    jm->cutix = NULL;
}

/* ===== titles ===== */

static const char *const titles[PT_NSTAGES_ALL][2] = {
    {"model space", "(x_m, y_m, z_m)"},
    {"camera space", "(x_c, y_c, z_c)"},
    {"image plane", "(x_ip, y_ip)"},
    {"logical pixel plane", "(x_pp, y_pp)"},
    {"viewport pixels", "(x_vp, y_vp)"},
    {"framebuffer", "(x_fb, y_fb)"},
    {"pixel array", "idx"},
    {"world space", "(x_w, y_w, z_w)"},      /* the matrix camera's (journey_matrix.c) */
    {"view space", "(x_v, y_v, z_v)"},
    {"clip space", "(x_k, y_k, z_k, w_k)"},
    {"the six planes", "outcode"},
    {"NDC cube", "(x_n, y_n, z_n)"},
    {"screen", "(x_s, y_s)"},
};

const char *pt_journey_title(pt_stage st)
{
    return (int)st < PT_NSTAGES_ALL ? titles[st][0] : "";
}

/* The formula line under the title. */
static const char *formula_of(const pt_jmodel *jm, pt_stage st)
{
    if (st == PT_STAGE_MODEL) return "(x_m, y_m, z_m): the vertex as the scene gives it";
    if (st == PT_STAGE_IMAGE)
        return jm->par.perspective ? "x_ip = x_c / -z_c, y_ip = y_c / -z_c, z_ip = -1"
                                   : "orthographic: x_ip = x_c, y_ip = y_c, z_ip = 0";
    if (st == PT_STAGE_VIEWPORT) return pt_scene_pipeline(jm->s)->viewport_info->formula;
    return pt_stage_infos[st].formula;
}

/* ===== backgrounds ===== */

/* The faint wireframe of the model in stage st's view. */
static void wireframe(pt_sbuf *sb, const pt_jmodel *jm, pt_stage st)
{
    const pt_model *m = jm->m;
    const pt_jview *v = &jm->view[st];
    size_t k, n = m->nseg < PT_JOURNEY_MAXSEG ? m->nseg : PT_JOURNEY_MAXSEG;
    pt_journey ja, jb;
    double ax, ay, bx, by;
    pathw pw;

    path_start(&pw, sb);
    for (k = 0; k < n; k++) {
        if (!seg_ends(jm, k, st, &ja, &jb)) continue;
        if (!stage_xy(&ja, st, &ax, &ay) || !stage_xy(&jb, st, &bx, &by)) continue;
        if (!clip(v, &ax, &ay, &bx, &by)) continue;
        path_cmd(&pw, "M", 2, vx(v, ax), vy(v, ay));
        path_cmd(&pw, "L", 2, vx(v, bx), vy(v, by));
    }
    path_end(&pw, "fill=\"none\" stroke=\"" C_FAINT "\" stroke-width=\"1\"");
}

/* An arrow-tipped axis of a 3-D panel from the origin to t, labelled. */
static void axis3(pt_sbuf *sb, const pt_jview *v, const axes3 *ax, const double *t,
                  const char *label)
{
    double o[3] = {0, 0, 0}, neg[3] = {-t[0], -t[1], -t[2]};
    double px, py, qx, qy;

    vline3(sb, v, ax, neg, o, C_GRID, 1, "stroke-dasharray=\"3 3\"");
    proj(ax, t[0], t[1], t[2], &qx, &qy);
    proj(ax, 0, 0, 0, &px, &py);
    if (!in_view(v, px, py) || !in_view(v, qx, qy)) { vline3(sb, v, ax, o, t, C_AXIS, 1.2, ""); return; }
    line(sb, vx(v, px), vy(v, py), vx(v, qx), vy(v, qy), C_AXIS, 1.2, "");
    arrowhead(sb, vx(v, px), vy(v, py), vx(v, qx), vy(v, qy), 8, C_AXIS);
    proj(ax, 1.1 * t[0], 1.1 * t[1], 1.1 * t[2], &qx, &qy);
    label_at(sb, vx(v, qx), vy(v, qy) + 4, 12, "middle", "fill=\"" C_AXIS "\" font-style=\"italic\"",
             label, 0, LAB_AXIS);
}

static void bg_model(pt_sbuf *sb, const pt_jmodel *jm)
{
    const pt_jview *v = &jm->view[PT_STAGE_MODEL];
    double A = jm->axis_m, tx[3] = {0, 0, 0}, ty[3] = {0, 0, 0}, tz[3] = {0, 0, 0};
    axes3 ax;

    axes_of(PT_STAGE_MODEL, &ax);
    tx[0] = A; ty[1] = A; tz[2] = A;
    axis3(sb, v, &ax, tx, "x_m");
    axis3(sb, v, &ax, ty, "y_m");
    axis3(sb, v, &ax, tz, "z_m");
    wireframe(sb, jm, PT_STAGE_MODEL);
}

static void bg_camera(pt_sbuf *sb, const pt_jmodel *jm)
{
    const pt_jview *v = &jm->view[PT_STAGE_CAMERA];
    double D = jm->depth, A = jm->axis_c, o[3] = {0, 0, 0}, c[4][3], f[4][3];
    double tx[3] = {0, 0, 0}, ty[3] = {0, 0, 0}, tz[3] = {0, 0, 0}, dz[3] = {0, 0, 0};
    double px, py;
    axes3 ax;
    int k, persp = jm->par.perspective;

    axes_of(PT_STAGE_CAMERA, &ax);
    for (k = 0; k < 4; k++) {                /* image plane and far end */
        double sx = (k == 0 || k == 3) ? -1 : 1, sy = k < 2 ? -1 : 1;
        c[k][0] = sx; c[k][1] = sy; c[k][2] = persp ? -1 : 0;
        f[k][0] = persp ? sx * D : sx; f[k][1] = persp ? sy * D : sy; f[k][2] = -D;
    }
    for (k = 0; k < 4; k++) {                /* the view pyramid (box) */
        vline3(sb, v, &ax, persp ? o : c[k], f[k], C_EDGE, 1, "stroke-dasharray=\"5 3\"");
        vline3(sb, v, &ax, f[k], f[(k + 1) % 4], C_EDGE, 1, "stroke-dasharray=\"5 3\"");
    }
    pt_sbuf_add(sb, "<path d=\"");
    for (k = 0; k < 4; k++) {
        proj(&ax, c[k][0], c[k][1], c[k][2], &px, &py);
        px = fmin(fmax(px, v->x0), v->x1); py = fmin(fmax(py, v->y0), v->y1);
        pt_sbuf_add(sb, k ? " L" : "M"); num(sb, vx(v, px)); pt_sbuf_add(sb, " "); num(sb, vy(v, py));
    }
    pt_sbuf_addf(sb, " Z\" fill=\"%s\" fill-opacity=\"0.8\" stroke=\"%s\"/>\n", C_AREA, C_EDGE);
    proj(&ax, 1, 1, c[0][2], &px, &py);
    if (in_view(v, px, py) && v->s > 20)
        label_at(sb, vx(v, px), vy(v, py) - 5, 10, "middle", "fill=\"" C_NOTE "\"",
                 persp ? "image plane z = -1" : "image plane z = 0", 0, LAB_OTHER);
    tx[0] = A; ty[1] = A; tz[2] = A; dz[2] = -D;
    vline3(sb, v, &ax, o, dz, C_AXIS, 1, "stroke-dasharray=\"1 3\"");
    {                                        /* name the view direction where it leaves */
        double qx, qy;
        proj(&ax, 0, 0, 0, &px, &py);
        proj(&ax, 0, 0, -D, &qx, &qy);
        if (clip(v, &px, &py, &qx, &qy) && (vx(v, qx) - vx(v, px)) > 90)
            label_at(sb, vx(v, qx) - 4, vy(v, qy) + 14, 10, "end", "fill=\"" C_NOTE "\"",
                     "looking down -z_c", 0, LAB_OTHER);
    }
    axis3(sb, v, &ax, tx, "x_c");
    axis3(sb, v, &ax, ty, "y_c");
    axis3(sb, v, &ax, tz, "z_c");
    proj(&ax, 0, 0, 0, &px, &py);
    if (in_view(v, px, py)) {
        circle(sb, vx(v, px), vy(v, py), 4, "#333", "");
        label_at(sb, vx(v, px) - 7, vy(v, py) - 8, 11, "end", "fill=\"#333\"", "camera", 0,
                 LAB_OTHER);
    }
    wireframe(sb, jm, PT_STAGE_CAMERA);
}

/* Lines of a grid with spacing 1 over the data rectangle r, offset off
** (0: cell edges at integers, 0.5: at half-integers), when cells are at least
** mincell units; clipped to the view. */
static void grid(pt_sbuf *sb, const pt_jview *v, const double r[4], double off, double mincell)
{
    double xa = fmax(r[0], v->x0), xb = fmin(r[2], v->x1);
    double ya = fmax(r[1], v->y0), yb = fmin(r[3], v->y1), t;
    pathw pw;

    if (v->s < mincell || !(xa < xb && ya < yb)) return;
    if ((xb - xa) + (yb - ya) > 400) return;
    path_start(&pw, sb);
    for (t = ceil(xa - off) + off; t <= xb; t += 1)
        if (t > r[0] && t < r[2]) {
            path_cmd(&pw, "M", 2, vx(v, t), vy(v, ya));
            path_cmd(&pw, "V", 1, vy(v, yb), 0);
        }
    for (t = ceil(ya - off) + off; t <= yb; t += 1)
        if (t > r[1] && t < r[3]) {
            path_cmd(&pw, "M", 2, vx(v, xa), vy(v, t));
            path_cmd(&pw, "H", 1, vx(v, xb), 0);
        }
    path_end(&pw, "fill=\"none\" stroke=\"" C_GRID "\" stroke-width=\"0.7\"");
}

/* The outline of data rectangle r, clipped, as four lines. */
static void outline(pt_sbuf *sb, const pt_jview *v, const double r[4], const char *stroke,
                    double width)
{
    vline(sb, v, r[0], r[1], r[2], r[1], stroke, width, "");
    vline(sb, v, r[2], r[1], r[2], r[3], stroke, width, "");
    vline(sb, v, r[2], r[3], r[0], r[3], stroke, width, "");
    vline(sb, v, r[0], r[3], r[0], r[1], stroke, width, "");
}

/* A label at data point (x, y) when it is in view, offset (dx, dy) units. */
static void vlabel(pt_sbuf *sb, const pt_jview *v, double x, double y, double dx, double dy,
                   const char *anchor, const char *t)
{
    if (in_view(v, x, y))
        label_at(sb, vx(v, x) + dx, vy(v, y) + dy, 10, anchor, "fill=\"" C_NOTE "\"", t, 0,
                 LAB_AXIS);
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
    pathw pw;
    char attrs[128];

    if (!jm->frame) return;
    W = jm->frame->w; H = jm->frame->h;
    path_start(&pw, sb);
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
                path_cmd(&pw, "M", 2, vx(v, xa), vy(v, (double)(by * k)));
                path_cmd(&pw, "H", 1, vx(v, xb), 0);
                path_cmd(&pw, "V", 1, vy(v, (double)y1), 0);
                path_cmd(&pw, "H", 1, vx(v, xa), 0);
                pt_sbuf_add(sb, "z");
                run = -1;
            }
            if (bx * k >= W) break;
        }
    }
    snprintf(attrs, sizeof attrs, "fill=\"" C_FRAMEPX "\" class=\"frame\" data-pixels=\"%lld\" "
             "data-k=\"%lld\"", (long long)lit, (long long)k);
    path_end(&pw, attrs);
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
        vrect(sb, v, r[0], r[1], r[2] - r[0], r[3] - r[1], "#eef0f3", "#9aa1ab", "", 0);
        vp[0] = p->x_ul; vp[1] = p->y_ul; vp[2] = p->x_ul + p->w; vp[3] = p->y_ul + p->h;
        vrect(sb, v, vp[0], vp[1], p->w, p->h, C_AREA, "", "", 0);
        frame_cells(sb, jm, v);
        grid(sb, v, r, 0, 5);
        outline(sb, v, vp, C_EDGE, 1.5);
        strcpy(a, "viewport at (x_ul, y_ul) = (");
        fmt_i64(b, sizeof b, p->x_ul); strcat(a, b); strcat(a, ", ");
        fmt_i64(b, sizeof b, p->y_ul); strcat(a, b); strcat(a, ")");
        if ((vp[2] - vp[0]) * v->s < 150) {
            /* no room for the label */
        } else if ((p->H - vp[3]) * v->s >= 14 && in_view(v, vp[0], vp[3]))
            label_at(sb, vx(v, vp[0]) + 2, vy(v, vp[3]) + 12, 10, "start",
                     "fill=\"" C_EDGE "\"", a, 0, LAB_OTHER);
        else if (in_view(v, vp[0], vp[1]))
            label_at(sb, vx(v, vp[0]) + 2, vy(v, vp[1]) + (vp[1] * v->s >= 14 ? -4 : 13), 10,
                     "start", "fill=\"" C_EDGE "\"", a, 0, LAB_OTHER);
    } else {
        vrect(sb, v, r[0], r[1], r[2] - r[0], r[3] - r[1], C_AREA, "", "", 0);
        grid(sb, v, r, st == PT_STAGE_PIXEL ? 0.5 : 0, 5);
        outline(sb, v, r, C_EDGE, 1.5);
    }
    /* axes through 0 on the image plane; corner labels elsewhere */
    if (st == PT_STAGE_IMAGE) {
        vline(sb, v, v->x0, 0, v->x1, 0, C_AXIS, 0.8, "");
        vline(sb, v, 0, v->y0, 0, v->y1, C_AXIS, 0.8, "");
        vlabel(sb, v, v->x1, 0, -4, -5, "end", "x_ip");
        vlabel(sb, v, 0, v->y1, 5, 12, "start", "y_ip");
        vlabel(sb, v, -1, -1, 0, 13, "middle", "(-1, -1)");
        vlabel(sb, v, 1, 1, 0, -5, "middle", "(1, 1)");
        vlabel(sb, v, -1, 1, 4, 12, "start", "view rectangle");
    } else if (st == PT_STAGE_PIXEL) {
        fmt_i64(b, sizeof b, p->w); strcpy(a, b); strcat(a, ".5");
        vlabel(sb, v, r[0], r[1], 0, 13, "middle", "0.5");
        vlabel(sb, v, r[2], r[1], 0, 13, "middle", a);
        fmt_i64(b, sizeof b, p->h); strcpy(a, b); strcat(a, ".5");
        vlabel(sb, v, r[0], r[3], -4, 4, "end", a);
        vlabel(sb, v, r[0], r[1], -4, 0, "end", "0.5");
        axis_name(a, sizeof a, st, 0, " \xe2\x86\x92");              /* x_pp ->, y_pp up */
        vlabel(sb, v, r[2], r[1], 4, -4, "start", a);
        axis_name(a, sizeof a, st, 1, " \xe2\x86\x91");
        vlabel(sb, v, r[0], r[3], 0, -6, "middle", a);
    } else {
        int64_t wd = st == PT_STAGE_VIEWPORT ? p->w : p->W, ht = st == PT_STAGE_VIEWPORT ? p->h : p->H;
        vlabel(sb, v, r[0], r[1], 0, -5, "start", "(0, 0)");
        strcpy(a, "(");
        fmt_i64(b, sizeof b, wd - 1); strcat(a, b); strcat(a, ", ");
        fmt_i64(b, sizeof b, ht - 1); strcat(a, b); strcat(a, ")");
        vlabel(sb, v, r[2], r[3], 0, 13, "end", a);
        /* x along the bottom edge's middle (the zoom inset takes the top
        ** right), y at the left edge's middle, its arrow down: rows go down */
        axis_name(a, sizeof a, st, 0, " \xe2\x86\x92");
        vlabel(sb, v, (r[0] + r[2]) / 2, r[3], 0, 13, "middle", a);
        axis_name(a, sizeof a, st, 1, " \xe2\x86\x93");
        vlabel(sb, v, r[0], (r[1] + r[3]) / 2, -4, 4, "end", a);
    }
    wireframe(sb, jm, st);
}

/* The pixel array's whole strip, from STRIP_X over STRIP_W units. */
#define STRIP_X 20.0
#define STRIP_W 360.0

static void bg_index(pt_sbuf *sb, const pt_jmodel *jm)
{
    const pt_stage_params *p = &jm->par;
    int64_t n = (int64_t)p->W * p->H;
    char a[160], b[32];

    strcpy(a, "W x H = ");
    fmt_i64(b, sizeof b, p->W); strcat(a, b); strcat(a, " x ");
    fmt_i64(b, sizeof b, p->H); strcat(a, b); strcat(a, " = ");
    fmt_i64(b, sizeof b, n); strcat(a, b); strcat(a, " pixels, one row after another");
    text_at(sb, STRIP_X, 57, 11, "start", "fill=\"" C_NOTE "\"", a, STRIP_W);
    rect(sb, STRIP_X, 68, STRIP_W, 18, "#eef0f3", "#9aa1ab", "");
    if (p->H <= 64) {
        int r;
        pt_sbuf_addf(sb, "<g stroke=\"%s\" stroke-width=\"0.7\">\n", "#9aa1ab");
        for (r = 1; r < p->H; r++) {
            double x = STRIP_X + STRIP_W * r / p->H;
            pt_sbuf_add(sb, "<line");
            attr(sb, "x1", x); attr(sb, "y1", 68); attr(sb, "x2", x); attr(sb, "y2", 86);
            if (cur) pt_jplace_seg(cur, x, 68, x, 86);
            pt_sbuf_add(sb, "/>\n");
        }
        pt_sbuf_add(sb, "</g>\n");
    }
    if (cur) pt_jplace_box(cur, STRIP_X, 68, STRIP_X + STRIP_W, 86, PT_JPLACE_TAKEN);
    label_at(sb, STRIP_X, 98, 10, "start", "fill=\"" C_NOTE "\"", "0", 0, LAB_AXIS);
    axis_name(a, sizeof a, PT_STAGE_INDEX, 0, " \xe2\x86\x92");
    label_at(sb, STRIP_X + STRIP_W / 2, 98, 10, "middle", "fill=\"" C_NOTE "\"", a, 0, LAB_AXIS);
    fmt_i64(b, sizeof b, n - 1);
    label_at(sb, STRIP_X + STRIP_W, 98, 10, "end", "fill=\"" C_NOTE "\"", b, 0, LAB_AXIS);
}

void pt_journey_panel_bg(pt_sbuf *sb, const pt_jmodel *jm, pt_stage st)
{
    char t[160];

    if ((int)st >= PT_NSTAGES_ALL) return;
    cur = &jm->place[st];
    pt_jplace_clear(cur);
    rect(sb, 0.5, 0.5, PT_JOURNEY_PW - 1, PT_JOURNEY_PH - 1, "#fff", C_FRAME, "rx=\"6\"");
    snprintf(t, sizeof t, "%d  %s  %s", pt_jmatrix_number(jm, st), titles[st][0], titles[st][1]);
    text_at(sb, 12, 21, 15, "start", "font-weight=\"bold\" fill=\"" C_TEXT "\"", t, 376);
    text_at(sb, 12, 36, 10.5, "start", "font-family=\"" MONO "\" fill=\"" C_NOTE "\"",
            formula_of(jm, st), 376);
    rect(sb, BOX_X, BOX_Y, BOX_W, BOX_H, "#fbfcfe", "#e3e6eb", "");
    switch (st) {
    case PT_STAGE_MODEL: bg_model(sb, jm); break;
    case PT_STAGE_CAMERA: bg_camera(sb, jm); break;
    case PT_STAGE_INDEX: bg_index(sb, jm); break;
    case PT_STAGE_VIEWPORT: case PT_STAGE_FRAMEBUFFER: bg_plane(sb, jm, st); break;
    default:
        if (!pt_pipeline_has(&pt_pipe_classic, st)) pt_jmatrix_bg(sb, jm, st);  /* journey_matrix.c */
        else bg_plane(sb, jm, st);
        break;
    }
    cur->ready = 1;
    if (cur->failed) sb->failed = 1;
    cur = NULL;
}

/* ===== foregrounds ===== */

/* Rasterized pixels of segments, drawn as cells of a view: viewport pixel
** (x, y) is cell (x + dx, y + dy). */
typedef struct cells {
    pt_sbuf *sb;
    const pt_jview *v;
    int64_t dx, dy;              /* viewport -> this view's cells */
    const char *fill;
    pathw pw;                    /* the cells drawn, as one path */
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
    if (!c->pw.open) path_start(&c->pw, c->sb);
    path_cmd(&c->pw, "M", 2, vx(c->v, xa), vy(c->v, ya));
    path_cmd(&c->pw, "H", 1, vx(c->v, xb), 0);
    path_cmd(&c->pw, "V", 1, vy(c->v, yb), 0);
    path_cmd(&c->pw, "H", 1, vx(c->v, xa), 0);
    pt_sbuf_add(c->sb, "z");
    c->n++;
}

/* Close the path of cells drawn by cell_px(). */
static void cells_end(cells *c)
{
    char attrs[64];

    snprintf(attrs, sizeof attrs, "fill=\"%s\"", c->fill);
    path_end(&c->pw, attrs);
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

static void no_clip(void *ud, uint64_t count, pt_pix first, pt_pix last)
{
    (void)ud; (void)count; (void)first; (void)last;
}

/* Rasterize every segment of the model that uses vertex k into the callback. */
static void raster_segs(const pt_jmodel *jm, size_t k, void (*px)(void *, int64_t, int64_t),
                        void *ud)
{
    const pt_model *m = jm->m;
    pt_raster_out out;
    pt_journey ja, jb;
    size_t s;

    out.pixel = px;
    out.clip = no_clip;
    out.ud = ud;
    for (s = 0; s < m->nseg; s++) {
        pt_vec2 a, b;
        if (m->seg[s].a != k && m->seg[s].b != k) continue;
        if (!seg_ends(jm, s, PT_STAGE_VIEWPORT, &ja, &jb)) continue;
        if (pt_scene_pipeline(jm->s)->matrices) {   /* the rasterizer's points, as pt_run's */
            if (pt_jmatrix_pixelplane(&ja, jm->par.h, &a) != 0) continue;
            if (pt_jmatrix_pixelplane(&jb, jm->par.h, &b) != 0) continue;
            pt_raster_segment(a, b, jm->par.w, jm->par.h, pt_pixelplane2viewport, &out);
            continue;
        }
        a.x = ja.rec[PT_STAGE_PIXEL].x; a.y = ja.rec[PT_STAGE_PIXEL].y;
        b.x = jb.rec[PT_STAGE_PIXEL].x; b.y = jb.rec[PT_STAGE_PIXEL].y;
        pt_raster_segment(a, b, jm->par.w, jm->par.h, pt_pixel2viewport, &out);
    }
}

/* The segments that use vertex k, in view v, in the segment color. */
static void fg_segments(pt_sbuf *sb, const pt_jmodel *jm, const pt_jview *v, pt_stage st,
                        size_t k, double width)
{
    const pt_model *m = jm->m;
    pt_journey ja, jb;
    size_t s;

    for (s = 0; s < m->nseg; s++) {
        double ax, ay, bx, by;
        if (m->seg[s].a != k && m->seg[s].b != k) continue;
        if (!seg_ends(jm, s, st, &ja, &jb)) continue;
        if (!stage_xy(&ja, st, &ax, &ay) || !stage_xy(&jb, st, &bx, &by)) continue;
        vline(sb, v, ax, ay, bx, by, C_SEG, width, "stroke-linecap=\"round\"");
        if (m->seg[s].a == k) { ax = bx; ay = by; }       /* the other end */
        if (in_view(v, ax, ay)) circle(sb, vx(v, ax), vy(v, ay), 2.5, C_SEG, "");
    }
}

/* The vertex marker (or an arrow toward it) and its name; returns its
** position in panel units in (*px, *py), NaN when there is none.  ring: 0 a
** dot, 1 a ring (around a tiny filled pixel), 2 nothing (the pixel is big). */
static void marker(pt_sbuf *sb, const pt_jview *v, int ok, double x, double y,
                   uint64_t vn, int ring, double *px, double *py)
{
    char name[32];

    name[0] = 'v';
    fmt_i64(name + 1, sizeof name - 1, (int64_t)vn);
    if (ok && in_view(v, x, y)) {
        *px = vx(v, x); *py = vy(v, y);
        if (ring == 1) circle(sb, *px, *py, 7, "none", "stroke=\"" C_VTX "\" stroke-width=\"2\"");
        else if (ring == 0) circle(sb, *px, *py, 5, C_VTX, "stroke=\"#fff\" stroke-width=\"1.5\" class=\"vertex\"");
        label_at(sb, *px + 8, *py - 8, 13, "start",
                 "font-weight=\"bold\" fill=\"" C_VTX "\" " HALO, name, 0, LAB_VERTEX);
        return;
    }
    edge_arrow(sb, v, x, y, px, py);
    if (!isnan(*px)) {                      /* its name, and "off the panel" under it */
        const char *anchor = *px < v->bx + v->bw / 3 ? "start"
                           : *px > v->bx + 2 * v->bw / 3 ? "end" : "middle";
        double ly = *py + (*py < v->by + v->bh / 2 ? 14 : -18);
        label_at(sb, *px, ly, 11, anchor, "font-weight=\"bold\" fill=\"" C_VTX "\" " HALO, name, 0,
                 LAB_VERTEX);
        label_at(sb, *px, ly + 12, 9.5, anchor, "fill=\"" C_VTX "\" " HALO, "off the panel", 0,
                 LAB_VERTEX);
    }
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
    double iw = 150, ih = 112, cx, cy, best = (double)INFINITY, bx = BOX_X + 5, by = BOX_Y + 5;
    double area[4];
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
    if (isnan(mx)) { mx = BOX_X; my = BOX_Y + BOX_H; }
    for (gy = 0; gy <= 4; gy++)              /* a 9 x 5 grid of places in the box */
        for (gx = 0; gx <= 8; gx++) {
            double x = BOX_X + 5 + gx * (BOX_W - iw - 10) / 8;
            double y = BOX_Y + 5 + gy * (BOX_H - ih - 10) / 4;
            double q[4], dx = x + iw / 2 - mx, dy = y + ih / 2 - my, c;
            q[0] = x; q[1] = y; q[2] = x + iw; q[3] = y + ih;
            c = (cur ? pt_jplace_cost(cur, q, 0) : 0) - sqrt(dx * dx + dy * dy) / 100;
            if ((gx % 8) || (gy % 4)) c += 5;         /* corners first */
            if (c < best) { best = c; bx = x; by = y; }
        }
    view_fit(&v, cx - 4.5, cy - 3.5, cx + 4.5, cy + 3.5, bx, by + 14, iw, ih - 14,
             st != PT_STAGE_PIXEL);
    /* where the inset looks, in the main view */
    vrect(sb, mv, v.x0, v.y0, v.x1 - v.x0, v.y1 - v.y0, "none", C_VTX, "stroke-width=\"1\"", 5);
    if (cur) pt_jplace_box(cur, bx, by, bx + iw, by + ih, PT_JPLACE_TAKEN);
    pt_sbuf_add(sb, "<g class=\"inset\">\n");
    rect(sb, bx, by, iw, ih, "#fff", "#8a919b", "stroke-width=\"1\"");
    text_at(sb, bx + 4, by + 11, 9.5, "start", "fill=\"" C_NOTE "\"", "zoom", 0);
    base_rect(jm, st, area);
    vrect(sb, &v, area[0], area[1], area[2] - area[0], area[3] - area[1],
          st == PT_STAGE_FRAMEBUFFER ? "#eef0f3" : C_AREA, "", "", 0);
    if (st == PT_STAGE_FRAMEBUFFER) {
        double vp[4];
        int64_t x, y;
        vp[0] = p->x_ul; vp[1] = p->y_ul; vp[2] = p->x_ul + p->w; vp[3] = p->y_ul + p->h;
        vrect(sb, &v, vp[0], vp[1], p->w, p->h, C_AREA, "", "", 0);
        for (y = (int64_t)floor(v.y0); jm->frame && y < v.y1; y++)     /* the frame */
            for (x = (int64_t)floor(v.x0); x < v.x1; x++)
                if (x >= 0 && y >= 0 && x < p->W && y < p->H && frame_lit(jm, x, y))
                    vrect(sb, &v, (double)x, (double)y, 1, 1, C_FRAMEPX, "", "", 0);
    }
    if (st != PT_STAGE_PIXEL) {
        cells cl;
        memset(&cl, 0, sizeof cl);
        cl.sb = sb; cl.v = &v; cl.fill = C_CELL;
        if (st == PT_STAGE_FRAMEBUFFER) { cl.dx = p->x_ul; cl.dy = p->y_ul; }
        raster_segs(jm, k, cell_px, &cl);
        cells_end(&cl);
        vrect(sb, &v, cx - 0.5, cy - 0.5, 1, 1, C_VTX, "", "", 0);
    } else {
        vrect(sb, &v, cx - 0.5, cy - 0.5, 1, 1, "none", C_VTX, "stroke-width=\"2\"", 0);
    }
    {                                        /* the cell grid */
        double g[4];
        g[0] = v.x0 - 1; g[1] = v.y0 - 1; g[2] = v.x1 + 1; g[3] = v.y1 + 1;
        grid(sb, &v, g, st == PT_STAGE_PIXEL ? 0.5 : 0, 1);
    }
    if (st == PT_STAGE_FRAMEBUFFER) {
        double vp[4];
        vp[0] = p->x_ul; vp[1] = p->y_ul; vp[2] = p->x_ul + p->w; vp[3] = p->y_ul + p->h;
        outline(sb, &v, vp, C_EDGE, 1.5);
        outline(sb, &v, area, "#9aa1ab", 1.5);
    } else outline(sb, &v, area, C_EDGE, 1.5);
    if (st == PT_STAGE_PIXEL) {              /* pixel centres, the segments, the point */
        double x, y;
        pathw pw;
        path_start(&pw, sb);                 /* zero-length lines, round caps: dots */
        for (x = ceil(v.x0); x <= v.x1; x += 1)
            for (y = ceil(v.y0); y <= v.y1; y += 1) {
                path_cmd(&pw, "M", 2, vx(&v, x), vy(&v, y));
                pt_sbuf_add(sb, "h0");
            }
        path_end(&pw, "stroke=\"" C_AXIS "\" stroke-width=\"2.4\" stroke-linecap=\"round\"");
        fg_segments(sb, jm, &v, st, k, 1.5);
        if (in_view(&v, r->x, r->y))
            circle(sb, vx(&v, r->x), vy(&v, r->y), 3.5, C_VTX, "stroke=\"#fff\" stroke-width=\"1\"");
    }
    /* the pixel's name */
    strcpy(t, st == PT_STAGE_PIXEL ? "logical pixel (" : "pixel (");
    fmt_i64(b, sizeof b, (int64_t)floor(cx)); strcat(t, b); strcat(t, ", ");
    fmt_i64(b, sizeof b, (int64_t)floor(cy)); strcat(t, b); strcat(t, ")");
    text_at(sb, bx + iw - 4, by + 11, 9.5, "end", "fill=\"" C_VTX "\"", t, 0);
    pt_sbuf_add(sb, "</g>\n");
}

/* The camera panel's projection ray and image point. */
static void fg_ray(pt_sbuf *sb, const pt_jmodel *jm, const pt_journey *j)
{
    const pt_jview *v = &jm->view[PT_STAGE_CAMERA];
    const pt_vrec *c = &j->rec[PT_STAGE_CAMERA], *ip = &j->rec[PT_STAGE_IMAGE];
    double o[3] = {0, 0, 0}, pc[3], pi[3], px, py;
    axes3 ax;

    axes_of(PT_STAGE_CAMERA, &ax);
    pc[0] = c->x; pc[1] = c->y; pc[2] = c->z;
    pi[0] = ip->x; pi[1] = ip->y; pi[2] = ip->z;
    if (!isfinite(pi[0]) || !isfinite(pi[1])) return;
    if (jm->par.perspective) {
        vline3(sb, v, &ax, o, pc, C_VTX, 1, "stroke-dasharray=\"4 3\"");
        vline3(sb, v, &ax, o, pi, C_VTX, 1, "stroke-dasharray=\"4 3\"");
    } else vline3(sb, v, &ax, pc, pi, C_VTX, 1, "stroke-dasharray=\"4 3\"");
    proj(&ax, pi[0], pi[1], pi[2], &px, &py);
    if (in_view(v, px, py))
        circle(sb, vx(v, px), vy(v, py), 3.5, "#fff", "stroke=\"" C_VTX "\" stroke-width=\"1.5\"");
}

/* The model panel's path from the origin along x, then y, then z. */
static void fg_path(pt_sbuf *sb, const pt_jmodel *jm, const pt_journey *j, pt_stage st)
{
    const pt_jview *v = &jm->view[st];
    const pt_vrec *r = &j->rec[st];
    double p0[3] = {0, 0, 0}, p1[3], p2[3], p3[3];
    axes3 ax;

    axes_of(st, &ax);
    p1[0] = r->x; p1[1] = 0; p1[2] = 0;
    p2[0] = r->x; p2[1] = r->y; p2[2] = 0;
    p3[0] = r->x; p3[1] = r->y; p3[2] = r->z;
    vline3(sb, v, &ax, p0, p1, C_VTX, 1, "stroke-dasharray=\"3 3\"");
    vline3(sb, v, &ax, p1, p2, C_VTX, 1, "stroke-dasharray=\"3 3\"");
    vline3(sb, v, &ax, p2, p3, C_VTX, 1, "stroke-dasharray=\"3 3\"");
}

/* The note under a panel: where the vertex stands after this stage. */
static void note_of(char *t, size_t n, const pt_jmodel *jm, const pt_journey *j, pt_stage st,
                    int used)
{
    const pt_vrec *r = &j->rec[st];
    const pt_stage_params *p = &jm->par;
    char a[32], b[32];

    t[0] = '\0';
    if (j->pipe->matrices && pt_jmatrix_note(t, n, j, st)) return;
    switch (st) {
    case PT_STAGE_MODEL:
        snprintf(t, n, "%s", used ? "the model's own coordinates, as in the scene"
                 : "used by no segment: the renderer never transforms it");
        break;
    case PT_STAGE_CAMERA:
        if (!p->perspective)
            snprintf(t, n, "%s", !isfinite(r->x) || !isfinite(r->y) ? "not finite"
                     : "orthographic: the depth z_c does not move the image point");
        else
            snprintf(t, n, "%s", !isfinite(r->z) ? "not finite"
                     : r->z < 0 ? "in front of the camera (z_c < 0)"
                     : r->z > 0 ? "behind the camera (z_c > 0): projected mirrored"
                     : "on the camera's plane z_c = 0: the projection divides by zero");
        break;
    case PT_STAGE_IMAGE:
        snprintf(t, n, "%s%s", !isfinite(r->x) || !isfinite(r->y) ? "not finite: no image point"
                 : fabs(r->x) <= 1 && fabs(r->y) <= 1 ? "inside the view rectangle"
                 : "outside the view rectangle",
                 r->flags & PT_REC_BEHIND ? " (behind the camera: mirrored)" : "");
        break;
    case PT_STAGE_PIXEL:
        if (j->rec[PT_STAGE_VIEWPORT].flags & PT_REC_NULL)
            snprintf(t, n, "no integer pixel: not finite or beyond 2^62");
        else {
            fmt_i64(a, sizeof a, j->rec[PT_STAGE_VIEWPORT].ix + 1);
            fmt_i64(b, sizeof b, p->h - j->rec[PT_STAGE_VIEWPORT].iy);
            snprintf(t, n, "nearest logical pixel (%s, %s)", a, b);
        }
        break;
    case PT_STAGE_VIEWPORT:
        snprintf(t, n, "%s", r->flags & PT_REC_NULL ? "no pixel"
                 : !(r->flags & PT_REC_INSIDE) ? "outside the viewport: clipped, not drawn"
                 : used ? "inside the viewport: drawn"
                 : "inside the viewport, but no segment draws it");
        break;
    case PT_STAGE_FRAMEBUFFER:
        snprintf(t, n, "%s", r->flags & PT_REC_NULL ? "no pixel"
                 : r->ix >= 0 && r->ix < p->W && r->iy >= 0 && r->iy < p->H
                   ? "inside the framebuffer" : "outside the framebuffer");
        break;
    default:
        snprintf(t, n, "%s", r->flags & PT_REC_NULL ? "no index: the pixel is not in the array"
                 : "row-major: the top row first");
        break;
    }
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
        text_at(sb, 200, 150, 12, "middle", "fill=\"" C_VTX "\"",
                "no pixel, so no place in the array", 0);
        return;
    }
    x = fb->ix; y = fb->iy;
    if (ix->flags & PT_REC_NULL) {           /* outside: where the formula would point */
        fmt_i64(a, sizeof a, x); fmt_i64(b, sizeof b, y);
        snprintf(t, sizeof t, "(x_fb, y_fb) = (%s, %s) lies outside the framebuffer", a, b);
        text_at(sb, 200, 140, 11.5, "middle", "fill=\"" C_VTX "\"", t, 370);
        if (fabs((double)x) < PIXMAX && fabs((double)y) < PIXMAX) {
            int64_t would = y * W + x;      /* the formula without the stage's
                                             ** bounds: written again on purpose */
            fmt_i64(a, sizeof a, would);
            if (would >= 0 && would < n) {
                double wx = STRIP_X + STRIP_W * ((double)would + 0.5) / (double)n;
                snprintf(t, sizeof t, "y_fb * W + x_fb would be %s: another pixel's element", a);
                line(sb, wx, 62, wx, 92, C_VTX, 1.5, "stroke-dasharray=\"3 2\"");
                circle(sb, wx, 77, 5, "none", "stroke=\"" C_VTX "\" stroke-width=\"1.5\"");
            } else {
                double ax0 = would < 0 ? STRIP_X + 30 : STRIP_X + STRIP_W - 30;
                double ax1 = would < 0 ? STRIP_X - 12 : STRIP_X + STRIP_W + 12;
                snprintf(t, sizeof t, "y_fb * W + x_fb would be %s: outside the array", a);
                line(sb, ax0, 77, ax1 + (would < 0 ? 8 : -8), 77, C_VTX, 2.5, "");
                arrowhead(sb, ax0, 77, ax1, 77, 10, C_VTX);
            }
            text_at(sb, 200, 160, 11.5, "middle", "fill=\"" C_VTX "\"", t, 370);
        }
        text_at(sb, 200, 190, 11, "middle", "fill=\"" C_NOTE "\"",
                "so the index stage gives none, and nothing is written", 370);
        return;
    }
    i = ix->i;
    /* the whole strip: the vertex's row, and its element */
    sx = STRIP_X + STRIP_W * (double)row_start(p, y) / (double)n;
    rect(sb, sx, 68, fmax(STRIP_W / (double)H, 1.5), 18, C_CELL, "", "");
    ex = STRIP_X + STRIP_W * ((double)i + 0.5) / (double)n;
    line(sb, ex, 64, ex, 90, C_VTX, 2, "");
    arrowhead(sb, ex, 58, ex, 67, 8, C_VTX);

    /* the rows around it, laid end to end */
    r0 = y > 0 ? y - 1 : y;
    r1 = y + 1 < H ? y + 1 : y;
    nr = (int)(r1 - r0 + 1);
    bw = STRIP_W / nr;
    line(sb, STRIP_X + STRIP_W * (double)row_start(p, r0) / (double)n, 87, STRIP_X, 111,
         C_GRID, 1, "");                     /* the fan stops above the rows' names */
    line(sb, STRIP_X + STRIP_W * (double)(row_end(p, r1) + 1) / (double)n, 87,
         STRIP_X + STRIP_W, 111, C_GRID, 1, "");
    for (r = r0; r <= r1; r++) {
        double bx = STRIP_X + bw * (double)(r - r0);
        rect(sb, bx, 128, bw, 20, r == y ? C_AREA : "#eef0f3", "#9aa1ab", "");
        fmt_i64(a, sizeof a, r);
        snprintf(t, sizeof t, "row %s%s", a, r == y ? " = y_fb" : "");
        text_at(sb, bx + bw / 2, 123, 10, "middle", "fill=\"" C_NOTE "\"", t, bw - 4);
        fmt_i64(a, sizeof a, row_start(p, r));
        text_at(sb, bx + 1, 160, 9, "start", "fill=\"" C_NOTE "\"", a, 0);
    }
    fmt_i64(a, sizeof a, row_end(p, r1));
    text_at(sb, STRIP_X + STRIP_W, 160, 9, "end", "fill=\"" C_NOTE "\"", a, 0);
    /* the segments' pixels in these rows */
    memset(&cl, 0, sizeof cl);
    cl.dx = p->x_ul; cl.dy = p->y_ul; cl.row_lo = r0; cl.row_hi = r1;
    raster_segs(jm, k, cell_collect, &cl);
    pt_sbuf_addf(sb, "<g stroke=\"%s\" stroke-width=\"1\">\n", C_SEG);
    for (c = 0; c < (int64_t)cl.nx; c++) {
        double cxp = STRIP_X + bw * ((double)(cl.ys[c] - r0) + (cl.xs[c] + 0.5) / (double)W);
        pt_sbuf_add(sb, "<line");
        attr(sb, "x1", cxp); attr(sb, "y1", 131); attr(sb, "x2", cxp); attr(sb, "y2", 145);
        pt_sbuf_add(sb, "/>\n");
    }
    pt_sbuf_add(sb, "</g>\n");
    rowx = STRIP_X + bw * ((double)(y - r0) + ((double)x + 0.5) / (double)W);
    line(sb, rowx, 127, rowx, 152, C_VTX, 2, "");

    /* eleven elements around idx */
    nc = n < 11 ? (int)n : 11;
    c0 = i - 5;
    if (c0 > n - nc) c0 = n - nc;
    if (c0 < 0) c0 = 0;
    bw = STRIP_W / 11;
    {                                        /* a fan to them, from below the rows' numbers */
        double xa = STRIP_X + bw * (double)(i - c0), xb = xa + bw, f = 13.0 / 44;
        line(sb, rowx + (xa - rowx) * f, 165, xa, 196, C_GRID, 1, "");
        line(sb, rowx + (xb - rowx) * f, 165, xb, 196, C_GRID, 1, "");
    }
    fmt_i64(a, sizeof a, y); fmt_i64(b, sizeof b, W); fmt_i64(d, sizeof d, x);
    {
        char e[32];
        fmt_i64(e, sizeof e, i);
        snprintf(t, sizeof t, "idx = y_fb * W + x_fb = %s * %s + %s = %s", a, b, d, e);
    }
    text_at(sb, 200, 258, 11, "middle", "font-family=\"" MONO "\" fill=\"" C_TEXT "\" " HALO, t, 370);
    for (c = 0; c < nc; c++) {
        int64_t e = c0 + c;
        double cxp = STRIP_X + bw * (double)c;
        int seg = 0;
        size_t q;
        for (q = 0; q < cl.nx; q++)         /* where the formula puts a pixel of the
                                             ** rows (x may be off the frame: again
                                             ** without the stage's bounds, on purpose) */
            if (cl.ys[q] * W + (int64_t)cl.xs[q] == e) seg = 1;
        rect(sb, cxp, 196, bw, 26, e == i ? C_VTX : seg ? C_CELL : "#fff", "#9aa1ab", "");
        fmt_i64(a, sizeof a, e % W);
        text_at(sb, cxp + bw / 2, 213, 9, "middle", e == i ? "fill=\"#fff\"" : "fill=\"" C_NOTE "\"",
                a, bw - 3);
        if (e % W == 0 && c > 0) line(sb, cxp, 190, cxp, 228, C_TEXT, 2, "");
        if (e == i || c == 0 || c == nc - 1) {
            fmt_i64(a, sizeof a, e);
            text_at(sb, cxp + bw / 2, 236, e == i ? 11 : 9, "middle",
                    e == i ? "font-weight=\"bold\" fill=\"" C_VTX "\"" : "fill=\"" C_NOTE "\"", a, 0);
        }
    }
    text_at(sb, STRIP_X, 276, 9.5, "start", "fill=\"" C_NOTE "\"",
            "cells: x_fb within the row; below: the element's index", 0);
    free(cl.xs);
    free(cl.ys);
}

/* pt_jplace_run()'s hand: a label in its place. */
static void put_label(void *ud, const pt_jlabel *l, double x, double y)
{
    text_raw(ud, x, y, l->size, l->anchor, l->extra, l->text, l->maxw);
}

void pt_journey_panel_fg(pt_sbuf *sb, const pt_jmodel *jm, uint64_t vn, pt_stage st)
{
    const pt_jview *v = &jm->view[st];
    size_t k = (size_t)(vn - 1), s;
    int used = 0, ok;
    pt_journey j;
    double x, y, mx = (double)NAN, my = (double)NAN;
    char t[PT_EXPLAINLEN];
    pt_jplace_mark mark;

    if ((int)st >= PT_NSTAGES_ALL || vn < 1 || vn > jm->m->nv) return;
    if (!jm->place[st].ready) {              /* the background's lines and labels */
        pt_sbuf bg;
        pt_sbuf_init(&bg);
        pt_journey_panel_bg(&bg, jm, st);
        if (bg.failed) sb->failed = 1;
        pt_sbuf_free(&bg);
    }
    mark = pt_jplace_save(&jm->place[st]);
    cur = &jm->place[st];
    for (s = 0; s < jm->m->nseg && !used; s++)
        used = jm->m->seg[s].a == k || jm->m->seg[s].b == k;
    journey_of(jm, k, &j);
    ok = stage_xy(&j, st, &x, &y);
    if (pt_journey_stopped(&j, st))          /* the matrix camera's own drawings */
        pt_jmatrix_fg(sb, jm, &j, k, st);
    else switch (st) {
    case PT_STAGE_CLIP:
    case PT_STAGE_CVV:
        pt_jmatrix_fg(sb, jm, &j, k, st);
        break;
    case PT_STAGE_INDEX:
        fg_index(sb, jm, &j, k);
        break;
    case PT_STAGE_VIEWPORT:
    case PT_STAGE_FRAMEBUFFER:
        if (v->s >= 3) {
            cells cl;
            memset(&cl, 0, sizeof cl);
            cl.sb = sb; cl.v = v; cl.fill = C_CELL;
            if (st == PT_STAGE_FRAMEBUFFER) { cl.dx = jm->par.x_ul; cl.dy = jm->par.y_ul; }
            raster_segs(jm, k, cell_px, &cl);
            cells_end(&cl);
        }
        fg_segments(sb, jm, v, st, k, v->s >= 3 ? 1 : 2);
        if (ok) vrect(sb, v, x - 0.5, y - 0.5, 1, 1, C_VTX, "", "", 4);
        marker(sb, v, ok, x, y, vn, v->s < 6 ? 1 : 2, &mx, &my);
        if (!ok) {
            label_at(sb, BOX_X + BOX_W / 2, BOX_Y + BOX_H / 2, 12, "middle",
                     "fill=\"" C_VTX "\" " HALO, "no pixel", 0, LAB_VERTEX);
            label_at(sb, BOX_X + BOX_W / 2, BOX_Y + BOX_H / 2 + 16, 10.5, "middle",
                     "fill=\"" C_VTX "\" " HALO, "the pixel-plane point", 0, LAB_VERTEX);
            label_at(sb, BOX_X + BOX_W / 2, BOX_Y + BOX_H / 2 + 30, 10.5, "middle",
                     "fill=\"" C_VTX "\" " HALO, "is not finite or beyond 2^62", 0, LAB_VERTEX);
        }
        if (v->s < 6) inset(sb, jm, &j, st, k, mx, my);
        break;
    case PT_STAGE_PIXEL:
        fg_segments(sb, jm, v, st, k, 2);
        if (!(j.rec[PT_STAGE_VIEWPORT].flags & PT_REC_NULL) && v->s >= 3) {
            double m = (double)j.rec[PT_STAGE_VIEWPORT].ix + 1;
            double n = (double)(jm->par.h - j.rec[PT_STAGE_VIEWPORT].iy);
            vrect(sb, v, m - 0.5, n - 0.5, 1, 1, "none", C_VTX, "stroke-width=\"1.5\"", 0);
        }
        marker(sb, v, ok, x, y, vn, 0, &mx, &my);
        if (v->s < 6) inset(sb, jm, &j, st, k, mx, my);
        break;
    default:
        if (st == PT_STAGE_MODEL || st == PT_STAGE_WORLD) fg_path(sb, jm, &j, st);
        if (st == PT_STAGE_CAMERA) fg_ray(sb, jm, &j);
        fg_segments(sb, jm, v, st, k, 2);
        if (st == PT_STAGE_NDC || st == PT_STAGE_SCREEN) pt_jmatrix_cuts(sb, jm, k, st);
        marker(sb, v, ok, x, y, vn, 0, &mx, &my);
        break;
    }
    cur = NULL;
    pt_jplace_run(&jm->place[st], put_label, sb);   /* the background's labels and ours */
    if (jm->place[st].failed) sb->failed = 1;
    pt_jplace_back(&jm->place[st], mark);
    if (pt_journey_stopped(&j, st))
        pt_jmatrix_unreached(t, sizeof t, st);
    else pt_explain_values(t, sizeof t, &j, st);
    pt_sbuf_addf(sb, "<g data-stage=\"%s\">\n", pt_stage_infos[st].name);
    text_at(sb, 12, CAPTION_Y, 12, "start", "class=\"coords\" font-family=\"" MONO
            "\" font-weight=\"bold\" fill=\"" C_TEXT "\"", t, 376);
    note_of(t, sizeof t, jm, &j, st, used);
    text_at(sb, 12, NOTE_Y, 11, "start", "class=\"note\" fill=\"" C_NOTE "\"", t, 376);
    pt_sbuf_add(sb, "</g>\n");
}

/* ===== the SVG document ===== */

#define GAP      16              /* between panels */
#define HEAD     62              /* the header band */
#define DOC_W    (GAP + 4 * (PT_JOURNEY_PW + GAP))
#define DOC_H(n) (HEAD + ((n) + 4) / 4 * (PT_JOURNEY_PH + GAP))  /* n panels, legend */

/* The eighth cell: what the scene is and what the colors mean. */
static void legend(pt_sbuf *sb, const pt_jmodel *jm)
{
    const pt_stage_params *p = &jm->par;
    double y = 28;
    char t[200], a[PT_NUMLEN], b[PT_NUMLEN], c[PT_NUMLEN];
    pt_sbuf u;

    rect(sb, 0.5, 0.5, PT_JOURNEY_PW - 1, PT_JOURNEY_PH - 1, "#fff", C_FRAME, "rx=\"6\"");
    text_at(sb, 12, 21, 15, "start", "font-weight=\"bold\" fill=\"" C_TEXT "\"", "how to read it", 0);
    circle(sb, 22, y + 14, 5, C_VTX, "stroke=\"#fff\" stroke-width=\"1.5\"");
    text_at(sb, 36, y + 18, 12, "start", "fill=\"" C_TEXT "\"", "the vertex, labelled with its number", 0);
    line(sb, 14, y + 36, 30, y + 36, C_SEG, 2.5, "");
    text_at(sb, 36, y + 40, 12, "start", "fill=\"" C_TEXT "\"", "the segments that use it", 0);
    line(sb, 14, y + 58, 30, y + 58, C_FAINT, 1.5, "");
    text_at(sb, 36, y + 62, 12, "start", "fill=\"" C_TEXT "\"", "the rest of its model", 0);
    rect(sb, 15, y + 73, 14, 10, C_CELL, "", "");
    text_at(sb, 36, y + 83, 12, "start", "fill=\"" C_TEXT "\"", "pixels its segments light", 0);
    rect(sb, 15, y + 95, 14, 10, C_FRAMEPX, "", "");
    text_at(sb, 36, y + 105, 12, "start", "fill=\"" C_TEXT "\"",
            "the whole frame: every model's pixels", 0);
    rect(sb, 15, y + 117, 14, 10, C_AREA, C_EDGE, "");
    text_at(sb, 36, y + 127, 12, "start", "fill=\"" C_TEXT "\"",
            "what reaches the viewport", 0);
    line(sb, 13, y + 146, 22, y + 146, C_VTX, 2.5, "");
    arrowhead(sb, 13, y + 146, 31, y + 146, 10, C_VTX);
    text_at(sb, 36, y + 150, 12, "start", "fill=\"" C_TEXT "\"",
            "the vertex lies off the panel that way", 0);
    y += 176;
    pt_fmt_shortest(a, p->translate.x); pt_fmt_shortest(b, p->translate.y);
    pt_fmt_shortest(c, p->translate.z);
    pt_sbuf_init(&u);
    pt_sbuf_add(&u, "model ");
    pt_sbuf_add(&u, jm->m->name);
    pt_sbuf_addf(&u, ": translate (x_t, y_t, z_t) = (%s, %s, %s)", a, b, c);
    text_at(sb, 12, y, 11, "start", "fill=\"" C_NOTE "\"", u.s ? u.s : "", 376);
    pt_sbuf_free(&u);
    snprintf(t, sizeof t, "camera %s; viewport w x h = %d x %d at (x_ul, y_ul) = (%d, %d)",
             pt_scene_camera_word(jm->s),
             p->w, p->h, p->x_ul, p->y_ul);
    text_at(sb, 12, y + 17, 11, "start", "fill=\"" C_NOTE "\"", t, 376);
    snprintf(t, sizeof t, "framebuffer W x H = %d x %d; round() is Java's Math.round", p->W, p->H);
    text_at(sb, 12, y + 34, 11, "start", "fill=\"" C_NOTE "\"", t, 376);
    text_at(sb, 12, y + 51, 11, "start", "fill=\"" C_NOTE "\"",
            "numbers: shortest decimals that read back exactly, as in the trace", 376);
    text_at(sb, 12, y + 68, 11, "start", "fill=\"" C_NOTE "\"",
            "pipetrace step shows each formula with its numbers put in", 376);
}

int pt_journey_svg(pt_sbuf *sb, const pt_scene *s, const pt_model *m, uint64_t vn)
{
    pt_jmodel jm;
    pt_sbuf t;
    int i, n = pt_scene_pipeline(s)->norder;
    const pt_stage *ord = pt_scene_pipeline(s)->order;

    if (pt_jmodel_init(&jm, s, m, NULL) != 0) return -1;
    pt_sbuf_add(sb, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    pt_sbuf_addf(sb, "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 %d %d\" "
                 "width=\"100%%\" font-family=\"%s\">\n", DOC_W, DOC_H(n), FONT);
    pt_sbuf_add(sb, "<title>pipetrace journey: vertex ");
    pt_sbuf_addf(sb, "%llu of model ", (unsigned long long)vn);
    pt_sbuf_add_xml(sb, m->name);
    pt_sbuf_add(sb, " in ");
    pt_sbuf_add_xml(sb, s->path);
    pt_sbuf_add(sb, "</title>\n");
    pt_sbuf_addf(sb, "<rect width=\"%d\" height=\"%d\" fill=\"#f3f4f6\"/>\n", DOC_W, DOC_H(n));
    pt_sbuf_init(&t);
    pt_sbuf_addf(&t, "pipetrace journey: vertex %llu of model ", (unsigned long long)vn);
    pt_sbuf_add(&t, m->name);
    text_at(sb, GAP, 30, 22, "start", "font-weight=\"bold\" fill=\"" C_TEXT "\"",
            t.s ? t.s : "", DOC_W - 2 * GAP);
    pt_sbuf_free(&t);
    pt_sbuf_add(&t, "scene ");
    pt_sbuf_add(&t, s->path);
    pt_sbuf_add(&t, ": from model coordinates to its element of the pixel array, "
                "one panel per coordinate system");
    text_at(sb, GAP, 50, 13, "start", "fill=\"" C_NOTE "\"", t.s ? t.s : "", DOC_W - 2 * GAP);
    if (t.failed) sb->failed = 1;
    pt_sbuf_free(&t);
    for (i = 0; i <= n; i++) {
        int col = i % 4, row = i / 4, st = i < n ? (int)ord[i] : -1;
        int px = GAP + col * (PT_JOURNEY_PW + GAP), py = HEAD + row * (PT_JOURNEY_PH + GAP);
        if (i == n) {
            pt_sbuf_addf(sb, "<g class=\"legend\" transform=\"translate(%d %d)\">\n", px, py);
            legend(sb, &jm);
        } else {
            pt_sbuf_addf(sb, "<g class=\"panel\" data-stage=\"%s\" transform=\"translate(%d %d)\">\n",
                         pt_stage_infos[st].name, px, py);
            pt_journey_panel_bg(sb, &jm, (pt_stage)st);
            pt_journey_panel_fg(sb, &jm, vn, (pt_stage)st);
        }
        pt_sbuf_add(sb, "</g>\n");
        if (col < 3 && i < n - 1)            /* an arrow to the next panel */
            arrowhead(sb, px + PT_JOURNEY_PW + 1, py + PT_JOURNEY_PH / 2.0,
                      px + PT_JOURNEY_PW + GAP - 2, py + PT_JOURNEY_PH / 2.0, 12, "#8a919b");
    }
    pt_sbuf_add(sb, "</svg>\n");
    pt_jmodel_free(&jm);
    return sb->failed ? -1 : 0;
}

/* ===== for the matrix camera's panels (journey_matrix.c) ===== */

void pt_jtext(pt_sbuf *sb, double x, double y, double size, const char *anchor,
              const char *extra, const char *t, double maxw)
{
    text_at(sb, x, y, size, anchor, extra, t, maxw);
}

void pt_jtext_label(pt_sbuf *sb, double x, double y, double size, const char *anchor,
               const char *extra, const char *t, double maxw)
{
    label_at(sb, x, y, size, anchor, extra, t, maxw, LAB_OTHER);
}

void pt_jline(pt_sbuf *sb, double ax, double ay, double bx, double by, const char *stroke,
              double width, const char *extra)
{
    line(sb, ax, ay, bx, by, stroke, width, extra);
}

void pt_jcircle(pt_sbuf *sb, double x, double y, double r, const char *fill, const char *extra)
{
    circle(sb, x, y, r, fill, extra);
}

void pt_jrect(pt_sbuf *sb, double x, double y, double w, double h, const char *fill,
              const char *stroke, const char *extra)
{
    rect(sb, x, y, w, h, fill, stroke, extra);
}

void pt_jview_fit(pt_jview *v, const double b[4], int ydown, double bx, double by, double bw,
                  double bh)
{
    view_fit(v, b[0], b[1], b[2], b[3], bx, by, bw, bh, ydown);
}

int pt_jview_line(pt_sbuf *sb, const pt_jview *v, double ax, double ay, double bx, double by,
                  const char *stroke, double width, const char *extra)
{
    return vline(sb, v, ax, ay, bx, by, stroke, width, extra);
}

double pt_jview_x(const pt_jview *v, double x) { return vx(v, x); }
double pt_jview_y(const pt_jview *v, double y) { return vy(v, y); }
int pt_jview_in(const pt_jview *v, double x, double y) { return in_view(v, x, y); }

void pt_jview_label(pt_sbuf *sb, const pt_jview *v, double x, double y, double dx, double dy,
                    const char *anchor, const char *t)
{
    vlabel(sb, v, x, y, dx, dy, anchor, t);
}

int pt_jstage_xy(const pt_journey *j, pt_stage st, double *x, double *y)
{
    return stage_xy(j, st, x, y);
}

void pt_jproj(pt_stage st, double x, double y, double z, double *px, double *py)
{
    axes3 a;

    axes_of(st, &a);
    proj(&a, x, y, z, px, py);
}

void pt_jaxis3(pt_sbuf *sb, const pt_jmodel *jm, pt_stage st, double x, double y, double z,
               const char *label)
{
    axes3 a;
    double t[3];

    t[0] = x; t[1] = y; t[2] = z;
    axes_of(st, &a);
    axis3(sb, &jm->view[st], &a, t, label);
}

int pt_jline3(pt_sbuf *sb, const pt_jmodel *jm, pt_stage st, const double *a, const double *b,
              const char *stroke, double width, const char *extra)
{
    axes3 ax;

    axes_of(st, &ax);
    return vline3(sb, &jm->view[st], &ax, a, b, stroke, width, extra);
}

void pt_jwireframe(pt_sbuf *sb, const pt_jmodel *jm, pt_stage st)
{
    wireframe(sb, jm, st);
}

void pt_jsegments(pt_sbuf *sb, const pt_jmodel *jm, const pt_jview *v, pt_stage st, size_t k)
{
    fg_segments(sb, jm, v, st, k, 2);
}

void pt_jmarker(pt_sbuf *sb, const pt_jview *v, int ok, double x, double y, uint64_t vn)
{
    double px, py;

    marker(sb, v, ok, x, y, vn, 0, &px, &py);
}
