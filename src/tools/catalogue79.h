/*
** src/tools/catalogue79.h -- the known mistakes of renderers 7 and 9's stages
** See LICENSE for copyright and license.
**
** What `pipetrace diff` tests a renderer 7 or 9 difference against.  Each
** mistake is the stage's wrong version, computed from EXPECTED's numbers:
**   vertex mistakes  one vertex's values at the stage, from its values at the
**                    stage before (and, where the mistake is "the right
**                    formula, the wrong inputs", the real stage called with
**                    those inputs: stages/r7_view2camera.c, r9_view2camera.c,
**                    r9_world2view.c; no formula is written again here);
**   clip mistakes    the near clip or the rectangle clip run on the model
**                    entering it (EXPECTED's vertices and colours, a log's
**                    primitive list): the real stage (stages/rv_nearclip.c,
**                    rv_clip.c) with the near plane moved, or heard cut by
**                    cut (pt_rv_clip_ls) and each new colour made the wrong way,
**                    or asked segment by segment which end to cut at which
**                    edge while the mistake makes each cut (the student's loop
**                    then goes on from its own wrong point);
**   position mistakes  a position's vertices at once: its matrix found
**                    from EXPECTED's model and world vertices (least
**                    squares), made the wrong way with r9_matrix.c's ops and
**                    applied by the real stage (stages/r9_model2world.c);
**   pixel mistakes   one pixel's colour, from EXPECTED's pixel colours, as an
**                    interval (EXPECTED's colours are rounded: a byte, or 4
**                    decimals), the rasterizer's pixels otherwise the same.
** A mistake is named only when it gives ACTUAL's values at its stage for
** every vertex (or pixel), the ones that differ and the ones that agree.
*/
#ifndef PT_CATALOGUE79_H
#define PT_CATALOGUE79_H

#include <stddef.h>
#include "core/pipetrace.h"

/* The camera as EXPECTED's header gives it. */
typedef struct pt_c79cam {
    int renderer;                /* 7 or 9 */
    int persp;                   /* 1: perspective */
    double l, r, b, t, n;        /* view rectangle, near plane's z */
} pt_c79cam;

/* cam as the stages take it (pt_rv_camera, stages/rv_model.h).  Can't fail. */
pt_rv_camera pt_c79cam_stages(const pt_c79cam *cam);

/* A known mistake of renderer 7 or 9. */
typedef struct pt_mistake79 {
    int stage;                   /* pt_t79_stage it is made in (io/tread79.h) */
    int renderer;                /* 7, 9, or 0: both */
    const char *name;            /* what was done, a few words */
    const char *how;             /* the wrong formula, and why it goes wrong */
    void (*vertex)(const pt_c79cam *cam, const double prev[4], const double right[4], double out[4]);
                                 /* a vertex mistake: the stage's (x, y, z, w)
                                 ** from the stage before (prev) and EXPECTED's
                                 ** own at this stage (right); or NULL */
    int (*clip)(const pt_c79cam *cam, pt_rv_model *m);
                                 /* a clip mistake: the stage on m, the new
                                 ** vertices and colours appended as the stage
                                 ** appends them; 0, or -1 (out of memory, a
                                 ** colour Java refuses); or NULL */
    void (*pixel)(const double rgb[3], const double partner[3], int paired, double tol,
                  double lo[3], double hi[3]);
                                 /* a pixel mistake: the colour's interval from
                                 ** EXPECTED's colour rgb (+- tol) and that of
                                 ** its anti-aliasing partner; or NULL */
    int gamma;                   /* 1: a mistake of the gamma, which leaves a
                                 ** segment's last pixel (written without gamma) be */
    int (*position)(size_t n, const double (*prev)[4], const double (*right)[4], int alt,
                    double (*out)[4]);
                                 /* a position mistake: the stage's (x, y, z, w)
                                 ** of a position's n vertices at once, from
                                 ** the stage before and EXPECTED's own (what
                                 ** the position's matrix is comes from them
                                 ** all); alt 0, 1, .. are the ways the mistake
                                 ** may have gone; 0, or -1 when there is no
                                 ** such alt or the vertices do not fix the
                                 ** matrix (fewer than 4 not in one plane); or NULL */
} pt_mistake79;

#define PT_NMISTAKES79 19
extern const pt_mistake79 pt_mistakes79[PT_NMISTAKES79];

#endif
