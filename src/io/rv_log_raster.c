/*
** src/io/rv_log_raster.c -- renderers 7 and 9: the rasterizer's lines of the course's debug log
** See LICENSE for copyright and license.
**
** The lines are laid at the end of the log's block as renderer 4's trace
** writers lay theirs (io/trace_int.h): room for a whole line, its numbers
** written in place (pt_jnum_f, pt_jnum_dtoa; integers from the block's digit
** table), no printf.  pt_klog_* (renderer 4's log, trace_kraft.c, writes to
** a FILE) lay the same lines into a buffer of their own.
*/
#include <assert.h>
#include <string.h>
#include "io/rv_log_raster.h"
#include "io/jnum.h"
#include "io/trace.h"
#include "io/trace_int.h"

/* The most one call below writes: eight numbers as Java spells them, the
** labels and integers between them. */
#define KLOG_ROOM (8 * PT_JNUM_LEN + 512)

/* ===== the lines, at o (each returns the end) ===== */

/* String.format("%W.Pf", x) at o. */
static char *jf_at(char *o, double x, int width, int prec)
{
    return o + pt_jnum_f(o, x, width, prec, 0);
}

/* Double.toString(x) at o. */
static char *jd_at(char *o, double x)
{
    return o + pt_jnum_dtoa(o, x);
}

/* "(LABEL) = (%9.4f, %9.4f)\n"; label: a short literal (32 bytes at most). */
static char *pair_at(char *o, const char *label, double a, double b)
{
    assert(strlen(label) <= 32);
    o = str_at(str_at(o, "("), label);
    o = jf_at(str_at(o, ") = ("), a, 9, 4);
    o = jf_at(str_at(o, ", "), b, 9, 4);
    return str_at(o, ")\n");
}

/* "r=%.4f g=%.4f b=%.4f", the floats widened as Java does. */
static char *rgb_at(char *o, float r, float g, float b)
{
    o = jf_at(str_at(o, "r="), (double)r, 0, 4);
    o = jf_at(str_at(o, " g="), (double)g, 0, 4);
    return jf_at(str_at(o, " b="), (double)b, 0, 4);
}

static char *slopes_at(char *o, double m, const char *so, const double mc[3],
                       double x0_vp, double y0_vp, double x1_vp, double y1_vp)
{
    static const char *const chan[3] = {"mRed", "mGrn", "mBlu"};
    int i;

    o = jd_at(str_at(o, "Slope m    = "), m);
    if (so) {
        assert(strlen(so) <= 32);
        o = jd_at(str_at(str_at(str_at(o, " ("), so), " 1/m = "), 1 / m);
        o = str_at(o, ")");
    }
    o = str_at(o, "\n");
    for (i = 0; i < 3; i++)
        o = str_at(jd_at(str_at(str_at(str_at(o, "Slope "), chan[i]), " = "), mc[i]), "\n");
    o = pair_at(o, "x0_vp, y0_vp", x0_vp, y0_vp);
    return pair_at(o, "x1_vp, y1_vp", x1_vp, y1_vp);
}

/* x in decimal at o, with its sign. */
static char *dec_at(char *o, long long x)
{
    char d[24];
    unsigned long long u = x < 0 ? 0ULL - (unsigned long long)x : (unsigned long long)x;
    int n = 0;

    do { d[n++] = (char)('0' + u % 10); u /= 10; } while (u);
    if (x < 0) *o++ = '-';
    while (n) *o++ = d[--n];
    return o;
}

/* "FrameBuffer: Bad pixel coordinate (x, y) [w=W, h=H]\n": what the course's
** setPixelFB prints for an index outside the pixel array. */
static char *bad_at(char *o, long long x, long long y, int W, int H)
{
    o = dec_at(str_at(o, "FrameBuffer: Bad pixel coordinate ("), x);
    o = dec_at(str_at(o, ", "), y);
    o = dec_at(str_at(o, ") [w="), W);
    o = dec_at(str_at(o, ", h="), H);
    return str_at(o, "]\n");
}

/* ===== renderer 4's: to a FILE ===== */

void pt_klog_bad(FILE *f, long long x_fb, long long y_fb, int W, int H)
{
    char buf[KLOG_ROOM];
    fwrite(buf, 1, (size_t)(bad_at(buf, x_fb, y_fb, W, H) - buf), f);
}

void pt_klog_pair(FILE *f, const char *label, double a, double b)
{
    char buf[KLOG_ROOM];
    fwrite(buf, 1, (size_t)(pair_at(buf, label, a, b) - buf), f);
}

void pt_klog_rgb(FILE *f, float r, float g, float b)
{
    char buf[KLOG_ROOM];
    fwrite(buf, 1, (size_t)(rgb_at(buf, r, g, b) - buf), f);
}

void pt_klog_slopes(FILE *f, double m, const char *so, const double mc[3],
                    double x0_vp, double y0_vp, double x1_vp, double y1_vp)
{
    char buf[KLOG_ROOM];
    fwrite(buf, 1, (size_t)(slopes_at(buf, m, so, mc, x0_vp, y0_vp, x1_vp, y1_vp) - buf), f);
}

/* ===== renderers 7 and 9's: to the log's block ===== */

/* The block's room for a call's lines, and the end of what was written. */
static char *at(pt_trace *t)
{
    return room(t, KLOG_ROOM);
}

static void end_at(pt_trace *t, char *o)
{
    t->len = (size_t)(o - t->buf);
}

static void on_ends(void *ud, double x0, double y0, double x1, double y1)
{
    pt_trace *t = ud;
    end_at(t, pair_at(pair_at(at(t), "x0_pp, y0_pp", x0, y0), "x1_pp, y1_pp", x1, y1));
}

static void on_slopes(void *ud, const pt_rv_slopes *s)
{
    pt_trace *t = ud;
    end_at(t, slopes_at(at(t), s->m, s->transposed ? "transposed, so" : NULL, s->mc,
                        s->x0_vp, s->y0_vp, s->x1_vp, s->y1_vp));
}

static void on_point(void *ud, double x, double y)
{
    pt_trace *t = ud;
    end_at(t, pair_at(at(t), "x_pp, y_pp", x, y));
}

static char *rgb_of(char *o, pt_rgb c)
{
    return rgb_at(o, c.r, c.g, c.b);
}

/* "(x_pp=..., y_pp=...)  ": %4d for the stepped coordinate, else %9.4f. */
static char *pp_at(const pt_trace *t, char *o, double x, int x_int, double y, int y_int)
{
    o = str_at(o, "(x_pp=");
    o = x_int ? int_at(t, o, (int)x, 4) : jf_at(o, x, 9, 4);
    o = str_at(o, ", y_pp=");
    o = y_int ? int_at(t, o, (int)y, 4) : jf_at(o, y, 9, 4);
    return str_at(o, ")  ");
}

static void on_pixel(void *ud, const pt_rv_pixel *px)
{
    pt_trace *t = ud;
    const pt_rv_raster_par *par = px->par;
    int stepped = px->kind == PT_RV_PX_STEP || px->kind == PT_RV_PX_AA;
    char *o = at(t);

    o = int_at(t, str_at(o, "fb_[w="), par->W, 0);
    o = int_at(t, str_at(o, ",h="), par->H, 0);
    o = int_at(t, str_at(o, "] vp_[x="), par->x_ul, 4);
    o = int_at(t, str_at(o, ", y="), par->y_ul, 4);
    o = int_at(t, str_at(o, ", w="), par->w, 0);
    o = int_at(t, str_at(o, ",h="), par->h, 0);
    o = pp_at(t, str_at(o, "]  "), px->x_pp, stepped && !px->transposed, px->y_pp,
              stepped && px->transposed);
    switch (px->kind) {
    case PT_RV_PX_STEP:
    case PT_RV_PX_END:
    case PT_RV_PX_POINT:
        o = int_at(t, str_at(o, "(x_vp="), px->x_vp, 4);
        o = int_at(t, str_at(o, ", y_vp="), px->y_vp, 4);
        o = rgb_of(str_at(o, ")  "), px->c[0]);
        break;
    case PT_RV_PX_AA:
        o = int_at(t, str_at(o, px->transposed ? "y_vp=" : "x_vp="),
                   px->transposed ? px->y_vp : px->x_vp, 4);
        o = int_at(t, str_at(o, px->transposed ? " {x_low=" : " {y_low="), px->lo, 4);
        o = rgb_of(str_at(o, " "), px->c[0]);
        o = int_at(t, str_at(o, px->transposed ? "} {x_hi =" : "} {y_hi ="), px->hi, 4);
        o = str_at(rgb_of(str_at(o, " "), px->c[1]), "}");
        break;
    }
    end_at(t, str_at(o, px->kind == PT_RV_PX_POINT && px->clipped ? " : Clipped\n" : "\n"));
}

static void on_bad(void *ud, int x, int y, int W, int H)
{
    pt_trace *t = ud;
    end_at(t, bad_at(at(t), x, y, W, H));
}

void pt_rv_log_raster_ls(pt_rv_raster_ls *ls, struct pt_trace *t, int debug)
{
    ls->ends = debug ? on_ends : NULL;
    ls->slopes = debug ? on_slopes : NULL;
    ls->point = debug ? on_point : NULL;
    ls->pixel = debug ? on_pixel : NULL;
    ls->bad = on_bad;
    ls->ud = t;
    ls->clipped_points = debug;
    ls->bytes_only = 0;                 /* the log prints the colours in float */
    ls->pixels = NULL;
}
