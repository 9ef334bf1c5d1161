/*
** stages/rv_raster.h -- renderers 7 and 9: rasterize a clipped primitive into the viewport
** See LICENSE for copyright and license.  (Formula and derivation: to be written by its owner.)
*/
#ifndef PT_RV_RASTER_H
#define PT_RV_RASTER_H
#include "rv_model.h"

/* The viewport and framebuffer a primitive is drawn into, and the switches. */
typedef struct pt_rv_raster_par {
    int w, h;                    /* the viewport's size */
    int x_ul, y_ul;              /* its upper-left corner in the framebuffer */
    int W, H;                    /* the framebuffer's size */
    unsigned char bg[3];         /* the viewport's background (AA blends with it) */
    int antialias, gamma;        /* Rasterize.doAntiAliasing, doGamma */
} pt_rv_raster_par;

/* Who hears the rasterizer (its log lines' numbers; owner defines the records). */
typedef struct pt_rv_raster_ls pt_rv_raster_ls;

/* Draw primitive p of m into rgb (the framebuffer, W x H, 3 bytes a pixel,
** written as FrameBuffer.setPixelVP writes), telling ls (NULL: nobody).
** Returns the number of pixels written. */
uint64_t pt_rv_raster_prim(const pt_rv_model *m, const pt_rv_prim *p,
                           const pt_rv_raster_par *par, unsigned char *rgb,
                           const pt_rv_raster_ls *ls);
#endif
