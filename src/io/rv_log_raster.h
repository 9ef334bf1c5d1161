/*
** src/io/rv_log_raster.h -- renderers 7 and 9: the rasterizer's lines of the course's debug log
** See LICENSE for copyright and license.
**
** A listener for stages/rv_raster.h that writes what the course's
** Rasterize_AntiAlias_Line, Rasterize_Clip_Point and PipelineLogger print,
** byte for byte: the ends "(x0_pp, y0_pp) = (%9.4f, %9.4f)", the slopes by
** Double.toString, "(x0_vp, y0_vp)", one line per pixel in the form of its
** kind (a step, an AA pair, the last pixel, a point's pixel with " : Clipped"
** when outside), and "FrameBuffer: Bad pixel coordinate (x, y) [w=W, h=H]"
** after the pixel line it belongs to.  Numbers Java formats go through
** jnum.h.  The "6. Rasterize: P" block header (7. in renderer 9) and its
** vertex and colour lines are the driver's.
*/
#ifndef PT_RV_LOG_RASTER_H
#define PT_RV_LOG_RASTER_H
#include <stdio.h>
#include "core/pipetrace.h"

struct pt_trace;                 /* io/trace.h */

/* Fill *ls to write to the block of t (trace_int.h; the log's FILE is
** t's): with debug (Rasterize.debug, and the scene's or
** position's debug on) every line, else only the Bad pixel coordinate lines,
** which the course prints always.  t must outlive ls's use.  This function
** can't fail (write errors show in ferror() of t's FILE). */
void pt_rv_log_raster_ls(pt_rv_raster_ls *ls, struct pt_trace *t, int debug);

/* The lines every renderer's rasterizer prints alike (renderer 4's log,
** src/io/trace_kraft.c, writes them too).  These functions can't fail.
**   pt_klog_pair    "(LABEL) = (%9.4f, %9.4f)"
**   pt_klog_rgb     "r=%.4f g=%.4f b=%.4f" (floats widened, as Java does)
**   pt_klog_slopes  "Slope m    = M" (with " (SO 1/m = X)" when stepped in y;
**                   SO: renderer 4 "so", renderers 7 and 9 "transposed, so"),
**                   "Slope mRed/mGrn/mBlu = ..." by Double.toString, and the
**                   ends' "(x0_vp, y0_vp)", "(x1_vp, y1_vp)"
**   pt_klog_bad     "FrameBuffer: Bad pixel coordinate (x, y) [w=W, h=H]" (the
**                   framebuffer's own line, which every renderer prints
**                   alike; renderers 7 and 9's "bad" above writes it too) */
void pt_klog_pair(FILE *f, const char *label, double a, double b);
void pt_klog_rgb(FILE *f, float r, float g, float b);
void pt_klog_slopes(FILE *f, double m, const char *so, const double mc[3],
                    double x0_vp, double y0_vp, double x1_vp, double y1_vp);
void pt_klog_bad(FILE *f, long long x_fb, long long y_fb, int W, int H);
#endif
