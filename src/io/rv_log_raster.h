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

/* Fill *ls to write to f: with debug (Rasterize.debug, and the scene's or
** position's debug on) every line, else only the Bad pixel coordinate lines,
** which the course prints always.  f must outlive ls's use.  This function
** can't fail (write errors show in ferror(f)). */
void pt_rv_log_raster_ls(pt_rv_raster_ls *ls, FILE *f, int debug);
#endif
