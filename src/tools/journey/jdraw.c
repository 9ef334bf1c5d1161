/*
** src/tools/journey/jdraw.c -- the journey's drawing: SVG shapes, texts and labels, views, markers
** See LICENSE for copyright and license.
*/
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "tools/journey/jdraw.h"

/* ===== numbers and elements ===== */

/* A panel coordinate with at most one decimal ("12", "12.5"; never "-0"). */
void pt_jnum(pt_sbuf *sb, double x)
{
    double r;

    if (!(x > -1e7)) x = -1e7;           /* callers clip; this is a last guard */
    if (x > 1e7) x = 1e7;
    r = floor(x * 10.0 + 0.5) / 10.0;
    if (r == floor(r)) pt_sbuf_addf(sb, "%.0f", r == 0 ? 0.0 : r);
    else pt_sbuf_addf(sb, "%.1f", r);
}

/* Append ` name="x"` with x a panel coordinate. */
void pt_jattr(pt_sbuf *sb, const char *name, double x)
{
    pt_sbuf_add(sb, " ");
    pt_sbuf_add(sb, name);
    pt_sbuf_add(sb, "=\"");
    pt_jnum(sb, x);
    pt_sbuf_add(sb, "\"");
}

/* ===== the panel being drawn ===== */

/* While a panel's background or foreground is drawn, the lines, circles and
** texts drawn are recorded in it (jdraw.h); NULL otherwise. */
static pt_jplace *cur;

pt_jplace *pt_jdraw_to(pt_jplace *p)
{
    pt_jplace *was = cur;

    cur = p;
    return was;
}

pt_jplace *pt_jdraw_place(void)
{
    return cur;
}

/* <text> at (x, y), recorded nowhere. */
static void text_raw(pt_sbuf *sb, double x, double y, double size, const char *anchor,
                     const char *extra, const char *t, double maxw)
{
    double est = pt_jtext_width(t, size, pt_jtext_face(extra));

    pt_sbuf_add(sb, "<text");
    pt_jattr(sb, "x", x);
    pt_jattr(sb, "y", y);
    pt_jattr(sb, "font-size", size);
    if (strcmp(anchor, "start") != 0) pt_sbuf_addf(sb, " text-anchor=\"%s\"", anchor);
    if (maxw > 0 && est > maxw) {
        pt_jattr(sb, "textLength", maxw);
        pt_sbuf_add(sb, " lengthAdjust=\"spacingAndGlyphs\"");
    }
    if (*extra) { pt_sbuf_add(sb, " "); pt_sbuf_add(sb, extra); }
    pt_sbuf_add(sb, ">");
    pt_sbuf_add_xml(sb, t);
    pt_sbuf_add(sb, "</text>\n");
}

/* A text that stays where it is put; the panel's labels keep clear of it. */
void pt_jtext(pt_sbuf *sb, double x, double y, double size, const char *anchor,
                    const char *extra, const char *t, double maxw)
{
    if (cur) {
        double b[4];
        pt_jtext_box(b, x, y, size, anchor, pt_jtext_face(extra), t, maxw);
        pt_jplace_box(cur, b[0], b[1], b[2], b[3], PT_JPLACE_TAKEN);
    }
    text_raw(sb, x, y, size, anchor, extra, t, maxw);
}

void pt_jlabel_at(pt_sbuf *sb, double x, double y, double size, const char *anchor,
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

void pt_jpath_start(pt_jpath *p, pt_sbuf *sb)
{
    p->sb = sb;
    p->open = 0;
}

/* Append command c ("M", "L", "h", ...) with n numbers. */
void pt_jpath_cmd(pt_jpath *p, const char *c, int n, double a, double b)
{
    if (!p->open) { pt_sbuf_add(p->sb, "<path d=\""); p->open = 1; }
    pt_sbuf_add(p->sb, c);
    pt_jnum(p->sb, a);
    if (n > 1) { pt_sbuf_add(p->sb, " "); pt_jnum(p->sb, b); }
}

void pt_jpath_end(pt_jpath *p, const char *attrs)
{
    if (!p->open) return;
    pt_sbuf_add(p->sb, "\" ");
    pt_sbuf_add(p->sb, attrs);
    pt_sbuf_add(p->sb, "/>\n");
    p->open = 0;
}

void pt_jline(pt_sbuf *sb, double ax, double ay, double bx, double by,
                 const char *stroke, double width, const char *extra)
{
    if (cur) pt_jplace_seg(cur, ax, ay, bx, by);
    pt_sbuf_add(sb, "<line");
    pt_jattr(sb, "x1", ax); pt_jattr(sb, "y1", ay); pt_jattr(sb, "x2", bx); pt_jattr(sb, "y2", by);
    pt_sbuf_addf(sb, " stroke=\"%s\"", stroke);
    pt_jattr(sb, "stroke-width", width);
    if (*extra) { pt_sbuf_add(sb, " "); pt_sbuf_add(sb, extra); }
    pt_sbuf_add(sb, "/>\n");
}

void pt_jrect(pt_sbuf *sb, double x, double y, double w, double h, const char *fill,
                 const char *stroke, const char *extra)
{
    pt_sbuf_add(sb, "<rect");
    pt_jattr(sb, "x", x); pt_jattr(sb, "y", y); pt_jattr(sb, "width", w); pt_jattr(sb, "height", h);
    pt_sbuf_addf(sb, " fill=\"%s\"", fill);
    if (*stroke) pt_sbuf_addf(sb, " stroke=\"%s\"", stroke);
    if (*extra) { pt_sbuf_add(sb, " "); pt_sbuf_add(sb, extra); }
    pt_sbuf_add(sb, "/>\n");
}

void pt_jcircle(pt_sbuf *sb, double x, double y, double r, const char *fill,
                   const char *extra)
{
    if (cur) pt_jplace_box(cur, x - r, y - r, x + r, y + r, r < 4 ? PT_JPLACE_MARK : PT_JPLACE_TAKEN);
    pt_sbuf_add(sb, "<circle");
    pt_jattr(sb, "cx", x); pt_jattr(sb, "cy", y); pt_jattr(sb, "r", r);
    pt_sbuf_addf(sb, " fill=\"%s\"", fill);
    if (*extra) { pt_sbuf_add(sb, " "); pt_sbuf_add(sb, extra); }
    pt_sbuf_add(sb, "/>\n");
}

/* A filled triangle with its tip at (bx, by), pointing from (ax, ay). */
void pt_jarrow(pt_sbuf *sb, double ax, double ay, double bx, double by,
                      double size, const char *fill)
{
    double dx = bx - ax, dy = by - ay, d = sqrt(dx * dx + dy * dy);
    double ux, uy;

    if (!(d > 0)) return;
    ux = dx / d; uy = dy / d;
    pt_sbuf_add(sb, "<path d=\"M");
    pt_jnum(sb, bx); pt_sbuf_add(sb, " "); pt_jnum(sb, by); pt_sbuf_add(sb, " L");
    pt_jnum(sb, bx - size * ux - 0.45 * size * uy); pt_sbuf_add(sb, " ");
    pt_jnum(sb, by - size * uy + 0.45 * size * ux); pt_sbuf_add(sb, " L");
    pt_jnum(sb, bx - size * ux + 0.45 * size * uy); pt_sbuf_add(sb, " ");
    pt_jnum(sb, by - size * uy - 0.45 * size * ux);
    pt_sbuf_addf(sb, " Z\" fill=\"%s\"/>\n", fill);
}

/* Integers as text. */
void pt_jfmt_i64(char *b, size_t n, int64_t x)
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

double pt_jview_x(const pt_jview *v, double x) { return v->bx + (x - v->x0) * v->s; }
double pt_jview_y(const pt_jview *v, double y)
{
    return v->ydown ? v->by + (y - v->y0) * v->s : v->by + v->bh - (y - v->y0) * v->s;
}

int pt_jview_in(const pt_jview *v, double x, double y)
{
    return x >= v->x0 && x <= v->x1 && y >= v->y0 && y <= v->y1;
}

void pt_jview_fit(pt_jview *v, const double r[4], int ydown, double bx, double by, double bw,
                  double bh)
{
    double xa = r[0], ya = r[1], xb = r[2], yb = r[3];
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
int pt_jview_clip(const pt_jview *v, double *ax, double *ay, double *bx, double *by)
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
int pt_jview_line(pt_sbuf *sb, const pt_jview *v, double ax, double ay, double bx,
                 double by, const char *stroke, double width, const char *extra)
{
    if (!pt_jview_clip(v, &ax, &ay, &bx, &by)) return 0;
    pt_jline(sb, pt_jview_x(v, ax), pt_jview_y(v, ay), pt_jview_x(v, bx), pt_jview_y(v, by), stroke, width, extra);
    return 1;
}

/* Draw the data rectangle [x, x + w] x [y, y + h] clipped to the view, at
** least minsize units wide and high (grown about its centre). */
void pt_jview_rect(pt_sbuf *sb, const pt_jview *v, double x, double y, double w, double h,
                  const char *fill, const char *stroke, const char *extra, double minsize)
{
    double xa = fmax(x, v->x0), xb = fmin(x + w, v->x1);
    double ya = fmax(y, v->y0), yb = fmin(y + h, v->y1);
    double px, py, pw, ph, t;

    if (!(xa <= xb && ya <= yb)) return;
    px = pt_jview_x(v, xa); pw = pt_jview_x(v, xb) - px;
    py = pt_jview_y(v, ya); ph = pt_jview_y(v, yb) - py;
    if (ph < 0) { py += ph; ph = -ph; }
    if (pw < minsize) { t = minsize - pw; px -= t / 2; pw = minsize; }
    if (ph < minsize) { t = minsize - ph; py -= t / 2; ph = minsize; }
    pt_jrect(sb, px, py, pw, ph, fill, stroke, extra);
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
    pt_jline(sb, tx - 26 * dx / m, ty - 26 * dy / m, tx - 6 * dx / m, ty - 6 * dy / m, PT_JC_VTX, 2.5, "");
    pt_jarrow(sb, tx - 26 * dx / m, ty - 26 * dy / m, tx, ty, 11, PT_JC_VTX);
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

/* Model and world space are seen from the front right, above; camera space
** from the right side, so -z (the view direction) runs to the right; view
** space and the NDC cube, which look down +z, from the left. */
#define EYE_MODEL  { 0.55, 0.45, 1.0 }
#define EYE_CAMERA { 1.0, 0.5, 0.3 }
#define EYE_VIEW   { -1.0, 0.5, -0.3 }
#define FLAT       { 1.0, 0.5, 0.3 }    /* not a space: never projected */

const pt_jlook pt_jlooks[PT_NSTAGES_ALL] = {
    [PT_STAGE_MODEL]       = { PT_JKIND_SPACE, EYE_MODEL },
    [PT_STAGE_CAMERA]      = { PT_JKIND_SPACE, EYE_CAMERA },
    [PT_STAGE_IMAGE]       = { PT_JKIND_PLANE, FLAT },
    [PT_STAGE_PIXEL]       = { PT_JKIND_PLANE, FLAT },
    [PT_STAGE_VIEWPORT]    = { PT_JKIND_PIXELS, FLAT },
    [PT_STAGE_FRAMEBUFFER] = { PT_JKIND_PIXELS, FLAT },
    [PT_STAGE_INDEX]       = { PT_JKIND_NONE, FLAT },
    [PT_STAGE_WORLD]       = { PT_JKIND_SPACE, EYE_MODEL },
    [PT_STAGE_VIEW]        = { PT_JKIND_SPACE, EYE_VIEW },
    [PT_STAGE_CLIP]        = { PT_JKIND_NONE, FLAT },     /* its own plots: w_k against each */
    [PT_STAGE_CVV]         = { PT_JKIND_NONE, FLAT },
    [PT_STAGE_NDC]         = { PT_JKIND_SPACE, EYE_VIEW },
    [PT_STAGE_SCREEN]      = { PT_JKIND_PLANE, FLAT },
};

/* The screen axes of stage st's panel. */
static void axes_of(pt_stage st, axes3 *a)
{
    const double *e = pt_jlooks[st].eye;

    axes3_make(a, e[0], e[1], e[2]);
}

void pt_jproj(pt_stage st, double x, double y, double z, double *px, double *py)
{
    axes3 a;

    axes_of(st, &a);
    *px = a.r[0] * x + a.r[1] * y + a.r[2] * z;
    *py = a.u[0] * x + a.u[1] * y + a.u[2] * z;
}

int pt_jline3(pt_sbuf *sb, const pt_jview *v, pt_stage st, const double *a, const double *b,
              const char *stroke, double width, const char *extra)
{
    double pa[2], pb[2];

    pt_jproj(st, a[0], a[1], a[2], &pa[0], &pa[1]);
    pt_jproj(st, b[0], b[1], b[2], &pb[0], &pb[1]);
    return pt_jview_line(sb, v, pa[0], pa[1], pb[0], pb[1], stroke, width, extra);
}

void pt_jaxis3(pt_sbuf *sb, const pt_jview *v, pt_stage st, double x, double y, double z,
               const char *label)
{
    double o[3] = {0, 0, 0}, t[3], neg[3];
    double px, py, qx, qy;

    t[0] = x; t[1] = y; t[2] = z;
    neg[0] = -x; neg[1] = -y; neg[2] = -z;
    pt_jline3(sb, v, st, neg, o, PT_JC_GRID, 1, "stroke-dasharray=\"3 3\"");
    pt_jproj(st, t[0], t[1], t[2], &qx, &qy);
    pt_jproj(st, 0, 0, 0, &px, &py);
    if (!pt_jview_in(v, px, py) || !pt_jview_in(v, qx, qy)) {
        pt_jline3(sb, v, st, o, t, PT_JC_AXIS, 1.2, "");
        return;
    }
    pt_jline(sb, pt_jview_x(v, px), pt_jview_y(v, py), pt_jview_x(v, qx), pt_jview_y(v, qy),
             PT_JC_AXIS, 1.2, "");
    pt_jarrow(sb, pt_jview_x(v, px), pt_jview_y(v, py), pt_jview_x(v, qx), pt_jview_y(v, qy), 8,
              PT_JC_AXIS);
    pt_jproj(st, 1.1 * t[0], 1.1 * t[1], 1.1 * t[2], &qx, &qy);
    pt_jlabel_at(sb, pt_jview_x(v, qx), pt_jview_y(v, qy) + 4, 12, "middle",
                 "fill=\"" PT_JC_AXIS "\" font-style=\"italic\"", label, 0, PT_JLAB_AXIS);
}

/* Lines of a grid with spacing 1 over the data rectangle r, offset off
** (0: cell edges at integers, 0.5: at half-integers), when cells are at least
** mincell units; clipped to the view. */
void pt_jgrid(pt_sbuf *sb, const pt_jview *v, const double r[4], double off, double mincell)
{
    double xa = fmax(r[0], v->x0), xb = fmin(r[2], v->x1);
    double ya = fmax(r[1], v->y0), yb = fmin(r[3], v->y1), t;
    pt_jpath pw;

    if (v->s < mincell || !(xa < xb && ya < yb)) return;
    if ((xb - xa) + (yb - ya) > 400) return;
    pt_jpath_start(&pw, sb);
    for (t = ceil(xa - off) + off; t <= xb; t += 1)
        if (t > r[0] && t < r[2]) {
            pt_jpath_cmd(&pw, "M", 2, pt_jview_x(v, t), pt_jview_y(v, ya));
            pt_jpath_cmd(&pw, "V", 1, pt_jview_y(v, yb), 0);
        }
    for (t = ceil(ya - off) + off; t <= yb; t += 1)
        if (t > r[1] && t < r[3]) {
            pt_jpath_cmd(&pw, "M", 2, pt_jview_x(v, xa), pt_jview_y(v, t));
            pt_jpath_cmd(&pw, "H", 1, pt_jview_x(v, xb), 0);
        }
    pt_jpath_end(&pw, "fill=\"none\" stroke=\"" PT_JC_GRID "\" stroke-width=\"0.7\"");
}

/* The outline of data rectangle r, clipped, as four lines. */
void pt_joutline(pt_sbuf *sb, const pt_jview *v, const double r[4], const char *stroke,
                    double width)
{
    pt_jview_line(sb, v, r[0], r[1], r[2], r[1], stroke, width, "");
    pt_jview_line(sb, v, r[2], r[1], r[2], r[3], stroke, width, "");
    pt_jview_line(sb, v, r[2], r[3], r[0], r[3], stroke, width, "");
    pt_jview_line(sb, v, r[0], r[3], r[0], r[1], stroke, width, "");
}

/* A label at data point (x, y) when it is in view, offset (dx, dy) units. */
void pt_jview_label(pt_sbuf *sb, const pt_jview *v, double x, double y, double dx, double dy,
                   const char *anchor, const char *t)
{
    if (pt_jview_in(v, x, y))
        pt_jlabel_at(sb, pt_jview_x(v, x) + dx, pt_jview_y(v, y) + dy, 10, anchor, "fill=\"" PT_JC_NOTE "\"", t, 0,
                 PT_JLAB_AXIS);
}

/* The vertex marker (or an arrow toward it) and its name; returns its
** position in panel units in (*px, *py), NaN when there is none.  ring: 0 a
** dot, 1 a ring (around a tiny filled pixel), 2 nothing (the pixel is big). */
void pt_jmarker(pt_sbuf *sb, const pt_jview *v, int ok, double x, double y,
                   uint64_t vn, int ring, double *px, double *py)
{
    char name[32];
    double ox, oy;

    if (!px) px = &ox;
    if (!py) py = &oy;
    name[0] = 'v';
    pt_jfmt_i64(name + 1, sizeof name - 1, (int64_t)vn);
    if (ok && pt_jview_in(v, x, y)) {
        *px = pt_jview_x(v, x); *py = pt_jview_y(v, y);
        if (ring == 1) pt_jcircle(sb, *px, *py, 7, "none", "stroke=\"" PT_JC_VTX "\" stroke-width=\"2\"");
        else if (ring == 0) pt_jcircle(sb, *px, *py, 5, PT_JC_VTX, "stroke=\"#fff\" stroke-width=\"1.5\" class=\"vertex\"");
        pt_jlabel_at(sb, *px + 8, *py - 8, 13, "start",
                 "font-weight=\"bold\" fill=\"" PT_JC_VTX "\" " PT_JHALO, name, 0, PT_JLAB_VERTEX);
        return;
    }
    edge_arrow(sb, v, x, y, px, py);
    if (!isnan(*px)) {                      /* its name, and "off the panel" under it */
        const char *anchor = *px < v->bx + v->bw / 3 ? "start"
                           : *px > v->bx + 2 * v->bw / 3 ? "end" : "middle";
        double ly = *py + (*py < v->by + v->bh / 2 ? 14 : -18);
        pt_jlabel_at(sb, *px, ly, 11, anchor, "font-weight=\"bold\" fill=\"" PT_JC_VTX "\" " PT_JHALO, name, 0,
                 PT_JLAB_VERTEX);
        pt_jlabel_at(sb, *px, ly + 12, 9.5, anchor, "fill=\"" PT_JC_VTX "\" " PT_JHALO, "off the panel", 0,
                 PT_JLAB_VERTEX);
    }
}

/* pt_jplace_run()'s hand: a label in its place. */
static void put_label(void *ud, const pt_jlabel *l, double x, double y)
{
    text_raw(ud, x, y, l->size, l->anchor, l->extra, l->text, l->maxw);
}


void pt_jdraw_labels(pt_sbuf *sb, pt_jplace *p)
{
    pt_jplace_run(p, put_label, sb);
}
