/*
** src/io/rv_log_raster.c -- renderers 7 and 9: the rasterizer's lines of the course's debug log
** See LICENSE for copyright and license.
*/
#include "io/rv_log_raster.h"
#include "io/jnum.h"

void pt_klog_pair(FILE *f, const char *label, double a, double b)
{
    char sa[PT_JNUM_LEN], sb[PT_JNUM_LEN];

    pt_jnum_f(sa, a, 9, 4, 0);
    pt_jnum_f(sb, b, 9, 4, 0);
    fprintf(f, "(%s) = (%s, %s)\n", label, sa, sb);
}

void pt_klog_rgb(FILE *f, float r, float g, float b)
{
    char sr[PT_JNUM_LEN], sg[PT_JNUM_LEN], sb[PT_JNUM_LEN];

    pt_jnum_f(sr, (double)r, 0, 4, 0);
    pt_jnum_f(sg, (double)g, 0, 4, 0);
    pt_jnum_f(sb, (double)b, 0, 4, 0);
    fprintf(f, "r=%s g=%s b=%s", sr, sg, sb);
}

void pt_klog_slopes(FILE *f, double m, const char *so, const double mc[3],
                    double x0_vp, double y0_vp, double x1_vp, double y1_vp)
{
    static const char *const chan[3] = {"mRed", "mGrn", "mBlu"};
    char one[PT_JNUM_LEN], two[PT_JNUM_LEN];
    int i;

    pt_jnum_dtoa(one, m);
    if (!so) {
        fprintf(f, "Slope m    = %s\n", one);
    } else {
        pt_jnum_dtoa(two, 1 / m);
        fprintf(f, "Slope m    = %s (%s 1/m = %s)\n", one, so, two);
    }
    for (i = 0; i < 3; i++) {
        pt_jnum_dtoa(one, mc[i]);
        fprintf(f, "Slope %s = %s\n", chan[i], one);
    }
    pt_klog_pair(f, "x0_vp, y0_vp", x0_vp, y0_vp);
    pt_klog_pair(f, "x1_vp, y1_vp", x1_vp, y1_vp);
}

static void on_ends(void *ud, double x0, double y0, double x1, double y1)
{
    pt_klog_pair((FILE *)ud, "x0_pp, y0_pp", x0, y0);
    pt_klog_pair((FILE *)ud, "x1_pp, y1_pp", x1, y1);
}

static void on_slopes(void *ud, const pt_rv_slopes *s)
{
    pt_klog_slopes((FILE *)ud, s->m, s->transposed ? "transposed, so" : NULL, s->mc,
                   s->x0_vp, s->y0_vp, s->x1_vp, s->y1_vp);
}

static void on_point(void *ud, double x, double y)
{
    pt_klog_pair((FILE *)ud, "x_pp, y_pp", x, y);
}

static void put_rgb(FILE *f, pt_rgb c)
{
    pt_klog_rgb(f, c.r, c.g, c.b);
}

/* "(x_pp=..., y_pp=...)": %4d for the stepped coordinate, else %9.4f. */
static void put_pp(FILE *f, double x, int x_int, double y, int y_int)
{
    char s[PT_JNUM_LEN];

    if (x_int) fprintf(f, "(x_pp=%4d, ", (int)x);
    else { pt_jnum_f(s, x, 9, 4, 0); fprintf(f, "(x_pp=%s, ", s); }
    if (y_int) fprintf(f, "y_pp=%4d)  ", (int)y);
    else { pt_jnum_f(s, y, 9, 4, 0); fprintf(f, "y_pp=%s)  ", s); }
}

static void on_pixel(void *ud, const pt_rv_pixel *px)
{
    FILE *f = ud;
    const pt_rv_raster_par *par = px->par;
    int stepped = px->kind == PT_RV_PX_STEP || px->kind == PT_RV_PX_AA;

    fprintf(f, "fb_[w=%d,h=%d] vp_[x=%4d, y=%4d, w=%d,h=%d]  ",
            par->W, par->H, par->x_ul, par->y_ul, par->w, par->h);
    put_pp(f, px->x_pp, stepped && !px->transposed, px->y_pp, stepped && px->transposed);
    switch (px->kind) {
    case PT_RV_PX_STEP:
    case PT_RV_PX_END:
    case PT_RV_PX_POINT:
        fprintf(f, "(x_vp=%4d, y_vp=%4d)  ", px->x_vp, px->y_vp);
        put_rgb(f, px->c[0]);
        break;
    case PT_RV_PX_AA:
        if (!px->transposed) fprintf(f, "x_vp=%4d {y_low=%4d ", px->x_vp, px->lo);
        else fprintf(f, "y_vp=%4d {x_low=%4d ", px->y_vp, px->lo);
        put_rgb(f, px->c[0]);
        fprintf(f, "} {%s =%4d ", px->transposed ? "x_hi" : "y_hi", px->hi);
        put_rgb(f, px->c[1]);
        fputc('}', f);
        break;
    }
    fputs(px->kind == PT_RV_PX_POINT && px->clipped ? " : Clipped\n" : "\n", f);
}

static void on_bad(void *ud, int x, int y, int W, int H)
{
    fprintf((FILE *)ud, "FrameBuffer: Bad pixel coordinate (%d, %d) [w=%d, h=%d]\n", x, y, W, H);
}

void pt_rv_log_raster_ls(pt_rv_raster_ls *ls, FILE *f, int debug)
{
    ls->ends = debug ? on_ends : NULL;
    ls->slopes = debug ? on_slopes : NULL;
    ls->point = debug ? on_point : NULL;
    ls->pixel = debug ? on_pixel : NULL;
    ls->bad = on_bad;
    ls->ud = f;
    ls->clipped_points = debug;
}
